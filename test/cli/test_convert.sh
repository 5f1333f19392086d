# kinetostat convert DECK --to linkage (docs/linkage.md, "One model: the &linkage
# translation"): every bundled linkage deck of data/ and docs/examples/ (found by listing the
# folders) is converted and both decks are run; every column both CSVs have agrees within
# rtol 1e-9, atol 1e-9 (kinetostat diff --common), but the columns the two kinds report in
# different frames (listed per deck below, with why); a deck that fails at a step fails the
# same way converted (exit code and step); the converted deck converts to itself, byte for
# byte. A perturbed translation (one mass 1e-6 relative off) must fail the comparison. By
# default a sample of the decks (one of each kind and of each feature: a few seconds of CPU);
# KINETOSTAT_LONG=1: every deck. Refusals: one line, exit 2, naming the variable.

cv_dir="$cli_tmp/convert"
mkdir -p "$cv_dir"

# The columns a kind reports in its own frames, which the &linkage form reports globally:
# &sixbar gives the forces of group 4-5 in its frame 2 and F56 signed; an &assur dyad with a
# frame_angle gives its three pairs in its reporting frame; the efficiency of an actuator-driven
# &assur deck has no &linkage value.
cv_skip() {  # DECK -> a regex of the columns left out (empty: none)
  case "$1" in
    data/sixbar*.nml) echo '^(F43G|F45G|F56)$' ;;
    data/assur_sixbar*.nml) echo '^(F43|F45|F56)[GxyN]$' ;;
    # a &linkage deck driven by a sliding pair leaves its efficiency undefined (eta_defined = 0)
    data/assur_pr3050_friction.nml) echo '^(eta|eta_defined)$' ;;
    *) echo '' ;;
  esac
}

# The rows a kind gives a value the &linkage form cannot: data/sixbar_flywheel.nml's slider
# load is a table over the crank angle whose two ends differ (f5 = 1000 N at step 1, 0 at step
# 361, one turn later); a &linkage table is periodic and gives step 361 the value of step 1.
cv_drop_last() {  # DECK -> 1 when its last row is left out
  case "$1" in
    data/sixbar_flywheel.nml) echo 1 ;;
    *) echo 0 ;;
  esac
}

# cv_csv_without IN OUT REGEX [DROP-LAST]: the CSV without the columns matching REGEX (and
# without its last row when DROP-LAST is 1).
cv_csv_without() {
  run_py - "$1" "$2" "$3" "${4:-0}" <<'PY'
import csv, re, sys
src, dst, pattern, drop_last = sys.argv[1:5]
with open(src, newline="") as f:
    rows = list(csv.reader(f))
if drop_last == "1":
    rows = rows[:-1]
keep = [i for i, name in enumerate(rows[0]) if not (pattern and re.search(pattern, name))]
with open(dst, "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    for r in rows:
        w.writerow([r[i] for i in keep])
PY
}

# cv_check NAME DECK [PERTURB-SED]: convert, run both, compare, idempotence.
cv_check() {
  local name="$1" deck="$2" perturb="${3:-}"
  local conv="$cv_dir/$name.nml" a="$cv_dir/$name.a.csv" b="$cv_dir/$name.b.csv"
  "$KINETOSTAT" convert "$deck" --to linkage -o "$conv" 2>"$cv_dir/err"
  local rc=$?
  if [ "$rc" -ne 0 ]; then fail "$name" "convert exit $rc: $(head -c 300 "$cv_dir/err")"; return; fi
  if [ -n "$perturb" ]; then sed -i "$perturb" "$conv"; fi
  local ra rb
  "$KINETOSTAT" "$deck" --format csv --quiet -o "$a" 2>"$cv_dir/erra"; ra=$?
  "$KINETOSTAT" "$conv" --format csv --quiet -o "$b" 2>"$cv_dir/errb"; rb=$?
  if [ "$ra" -ne "$rb" ]; then
    fail "$name" "exit $ra for the deck, $rb for its translation: $(head -c 200 "$cv_dir/erra") / $(head -c 200 "$cv_dir/errb")"
    return
  fi
  if [ "$ra" -ne 0 ]; then
    # both refused at a step: the same step
    local sa sb
    sa=$(grep -o 'step [0-9]*' "$cv_dir/erra" | head -1); sb=$(grep -o 'step [0-9]*' "$cv_dir/errb" | head -1)
    if [ -n "$sa" ] && [ "$sa" = "$sb" ]; then pass; else fail "$name" "both exit $ra but at '$sa' and '$sb'"; fi
    return
  fi
  local skip; skip=$(cv_skip "$deck")
  local drop; drop=$(cv_drop_last "$deck")
  cv_csv_without "$a" "$a.kept" "$skip" "$drop"; cv_csv_without "$b" "$b.kept" "$skip" "$drop"
  "$KINETOSTAT" diff --common --rtol 1e-9 --atol 1e-9 "$a.kept" "$b.kept" >"$cv_dir/diff" 2>&1
  if [ -n "$perturb" ]; then
    if grep -q '^different:' "$cv_dir/diff"; then pass; else fail "$name" "a perturbed translation passed: $(tail -1 "$cv_dir/diff")"; fi
    return
  fi
  if ! grep -q '^same:' "$cv_dir/diff"; then fail "$name" "$(head -c 600 "$cv_dir/diff")"; return; fi
  "$KINETOSTAT" convert "$conv" --to linkage -o "$conv.again" 2>"$cv_dir/err"
  if ! cmp -s "$conv" "$conv.again"; then
    fail "$name" "not idempotent: $(diff "$conv" "$conv.again" | head -5)"; return
  fi
  pass
}

# the decks of the linkage kinds: every one (--long) or the sample
cv_sample=" data/pr3207.nml data/pr3050.nml data/sixbar.nml data/assur_fourbar.nml \
data/assur_sixbar.nml data/assur_slider_crank.nml data/assur_pr3050.nml data/friction_slider_crank.nml \
data/class3.nml docs/examples/engine.nml "
for deck in data/*.nml docs/examples/*.nml; do
  group=$(grep -m1 -o '^[[:space:]]*&[A-Za-z0-9_]*' "$deck" | tr -d ' \t&')
  case "$group" in pr3207|pr3050|sixbar|assur|linkage) ;; *) continue ;; esac
  if [ "${KINETOSTAT_LONG:-0}" != 1 ] && [[ "$cv_sample" != *" $deck "* ]]; then continue; fi
  # kinds the translation refuses (one line, exit 2, naming the variable)
  run_ks convert "$deck" --to linkage
  if [ "$rc" -eq 2 ] && grep -q 'convert: .* has no &linkage translation yet' "$err"; then
    if [ "$(wc -l <"$err")" -eq 1 ] && [ ! -s "$out" ]; then pass; else fail "convert-refusal-$deck" "$(cat "$err")"; fi
    continue
  fi
  cv_check "convert-$(basename "$deck" .nml)" "$deck"
done

# the checks can fail: a translation with the lever 1e-6 heavier differs
cv_check convert-perturbed-pr3207 data/pr3207.nml 's/link(3)%m = 22,/link(3)%m = 22.000022,/'
cv_check convert-perturbed-assur data/assur_fourbar.nml 's/link(2)%m = 1,/link(2)%m = 1.000001,/'

# the hand-written twin and the translation of data/pr3207_flywheel.nml: the same deck
run_ks convert data/pr3207_flywheel.nml --to linkage
if grep -qx "  frame = 6" "$out" && grep -q "pair(2)%name = 'B', pair(2)%kind = 'R', pair(2)%links = 2, 1" "$out" \
   && grep -q "dynamics = 'steady', delta = 0.04, j_rotor = 0.6" "$out" \
   && grep -qx "! PR 3207 (spec pr3207.md) with its machine dynamics: the reference deck at a crank step of" "$out"; then
  pass
else
  fail convert-pr3207-twin "$(head -c 600 "$out")"
fi

# refusals and usage
expect_exit convert-needs-to 1 convert data/pr3207.nml
grep -q "convert needs --to linkage" "$err" && pass || fail convert-needs-to-message "$(cat "$err")"
expect_exit convert-to-other 1 convert data/pr3207.nml --to assur
run_ks convert data/gears_reducer.nml --to linkage
if [ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "^kinetostat: error: data/gears_reducer.nml: &gears: convert: not a linkage of lower pairs" "$err" && [ ! -s "$out" ]; then
  pass
else
  fail convert-gears "exit $rc: $(cat "$err")"
fi
# all or nothing: a refused deck leaves no file
rm -f "$cv_dir/none.nml"
run_ks convert data/gears_reducer.nml --to linkage -o "$cv_dir/none.nml"
if [ -e "$cv_dir/none.nml" ]; then fail convert-no-partial "a file was written"; else pass; fi

# kinetostat balance of a &pr3207 deck balances its &linkage translation: full balance refused
# with the figure of the &assur twin (7.65 % of the centre of mass's travel left), the crank
# alone written as a &linkage deck that runs
run_ks balance data/pr3207.nml
if [ "$rc" -eq 3 ] && grep -q "&pr3207 (its &linkage translation): full balance is impossible: .* leave 7.65 % " "$err"; then
  pass
else
  fail convert-balance-pr3207-full "exit $rc: $(head -c 300 "$err")"
fi
"$KINETOSTAT" balance data/pr3207.nml --method crank -o "$cv_dir/balanced.nml" 2>/dev/null
if grep -q '^&linkage' "$cv_dir/balanced.nml" && "$KINETOSTAT" "$cv_dir/balanced.nml" --quiet -o /dev/null; then
  pass
else
  fail convert-balance-pr3207-crank "the balanced deck is no running &linkage deck: $(head -c 300 "$cv_dir/balanced.nml")"
fi

# comments go before what their variable became: the engine's gas-force comment before force(1)
run_ks convert docs/examples/engine.nml --to linkage
if run_py - "$out" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
i = lines.index("  ! gas force on the piston, towards the crank (-x), N, over the crank angle (deg):")
assert lines[i + 2].startswith("  force(1)%link = 3"), lines[i + 2]
assert lines[0].startswith("! A four-stroke engine slider-crank"), lines[0]
assert lines.index("&linkage") > 0
PY
then pass; else fail convert-comments "$(head -c 600 "$out")"; fi

# a title with a quote comes back through the namelist escaper (the quote doubled), idempotent
sed "s/^  title = .*/  title = 'it''s a \"test\"'/" data/linkage_fourbar.nml >"$cv_dir/quote.nml"
"$KINETOSTAT" convert "$cv_dir/quote.nml" --to linkage -o "$cv_dir/quote2.nml"
"$KINETOSTAT" convert "$cv_dir/quote2.nml" --to linkage -o "$cv_dir/quote3.nml"
if grep -qxF "  title = 'it''s a \"test\"'" "$cv_dir/quote2.nml" && cmp -s "$cv_dir/quote2.nml" "$cv_dir/quote3.nml"; then
  pass
else
  fail convert-title-quote "$(grep title "$cv_dir/quote2.nml")"
fi
