# Self-check scale floor (sourced by tools/test with test/cli/lib.sh): zero-gravity and
# zero-mass variants of every bundled deck (one variable at a time, then all at once; the
# gear torque m1 and the cam load f2 for the massless mechanisms) run with exit 0, no
# self-check warning, and a footer equilibrium residual <= 1e-9 (a link whose loads are all
# roundoff, e.g. the two-force rocker of PR 3050 with g = 0, is judged against the step's
# load level, not against its own roundoff). assur_toggle stops at a toggle (exit 3): skipped.
floor_limit=1e-9
for deck in data/*.nml; do
  base=$(basename "$deck" .nml)
  [ "$base" = assur_toggle ] && continue
  # the design kinds (a gear pair's geometry, a train's teeth, a cam's profile) have no loads
  case "$base" in gear_geometry_*|planetary_synthesis*|cam_profile_*) continue ;; esac
  vars=$(grep -v '^ *!' "$deck" | grep -oE '(^|[ ,])(g|m[0-9]|crank_m|dyad\([0-9]\)%m[23]|f2) *=' \
         | sed -E 's/^[ ,]*//; s/ *=$//' | sort -u)
  case "$base" in gears_*) vars=$(echo "$vars" | grep -x 'm1') ;; cam_*) vars=$(echo "$vars" | grep -x 'f2') ;; esac
  all_expr=""
  for v in $vars all; do
    if [ "$v" = all ]; then expr="$all_expr"; else
      ve="$v"  # ( ) % are literal in a sed BRE
      # the first value of VAR becomes 0 (whole arrays for cam f2: every step's load)
      case "$v" in f2) expr="s/^\( *f2 *= *\).*/\10/" ;; *) expr="s/\(^\|[ ,]\)\($ve *= *\)[-+0-9.eEdD]*/\1\20/" ;; esac
      all_expr="$all_expr;$expr"
    fi
    [ -z "$expr" ] && continue
    # a heavy deck (lib.sh) with every load at 0 only
    heavy_deck "$base" && [ "$v" != all ] && continue
    name="floor-$base-${v//[()%]/_}=0"
    variant=$(deck_with "floor_${base}_${v//[()%]/_}" "$deck" "${expr#;}")
    # a variable already 0 in the deck gives no variant; the all-at-once edit must change the deck
    if cmp -s "$deck" "$variant"; then
      [ "$v" = all ] && fail "$name" "the edit '$expr' changed nothing"
      continue
    fi
    run_ks "$variant"
    # the footer's first residual against the limit, in one awk: "ok", "none" or the residual
    residual=$(awk -v l="$floor_limit" '/MAX EQUILIBRIUM RESIDUAL/ { r = $(NF - 1); found = 1; exit }
      END { if (!found) print "none"; else if (r + 0 <= l + 0) print "ok"; else print r }' "$out")
    if [ "$rc" -ne 0 ]; then fail "$name" "exit $rc: $(head -c 300 "$err")"
    elif [ -s "$err" ] && grep -q 'self-check' "$err"; then fail "$name" "self-check warning: $(cat "$err")"
    elif [ "$residual" = none ]; then fail "$name" "no residual in the footer"
    elif [ "$residual" = ok ]; then pass
    else fail "$name" "footer residual $residual, expected <= $floor_limit"; fi
  done
done
