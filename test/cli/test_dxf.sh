# --format dxf --at K: the --at sheet as an ASCII DXF (R12 entities, the drawing model's
# layers), read back by tools/dxf_check.py against the CSV's positions on every linkage deck
# at three steps (English and Russian; a heavy deck, lib.sh, with tools/test --long only: its
# twin, pr3207_flywheel or assur_engine_flywheel, runs);
# --format dxf: the sheet of a run; the check can fail;
# usage errors.
dxf_check="$root/tools/dxf_check.py"
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  case "$name" in gears_*|cam_*|gear_geometry_*|planetary_synthesis*|assur_toggle) continue ;; esac
  heavy_deck "$name" && continue
  run_ks_cached "$name.kin.csv" "$deck" --format csv --kinematics
  cp "$out" "$cli_tmp/$name.kin.csv"
  steps=$(($(wc -l <"$out") - 1))
  dxf_steps="1 $(((steps + 1) / 2)) $steps"
  for k in $dxf_steps; do
    lang=en; [ "$k" = 1 ] && lang=ru
    run_ks "$deck" --format dxf --at "$k" --lang "$lang"
    if [ "$rc" -ne 0 ]; then fail "dxf-runs-$name-$k" "rc=$rc: $(head -c 300 "$err")"; continue; fi
    cp "$out" "$cli_tmp/$name.$k.dxf"
    check_job dxf_check "dxf-$name-$k" "$cli_tmp/$name.$k.dxf" "$cli_tmp/$name.kin.csv" "$k"
  done
done
check_batch dxf_check
# the check can fail: joint A moved by 1 mm (the first circle's x)
awk 'BEGIN{c=0} {print} /^CIRCLE$/ {c=1} c==1 && /^ *10$/ {getline; printf "%.6f\n", $1 + 1; c=2}' \
  "$cli_tmp/sixbar.1.dxf" >"$cli_tmp/moved.dxf"
run_py "$dxf_check" "$cli_tmp/moved.dxf" "$cli_tmp/sixbar.kin.csv" 1 >"$cli_tmp/check.out" 2>&1
grep -q '^point A: no circle on JOINTS' "$cli_tmp/check.out" && pass \
  || fail dxf-check-can-fail "a moved joint was not reported as such: $(head -3 "$cli_tmp/check.out")"
# ... and so can it in a batch (tools/batch_check.py, as the decks' checks above run)
printf 'moved\t%s\t%s\t1\n' "$cli_tmp/moved.dxf" "$cli_tmp/sixbar.kin.csv" >"$cli_tmp/moved.tsv"
run_py "$root/tools/batch_check.py" dxf_check "$cli_tmp/moved.tsv" "$cli_tmp/moved" >"$cli_tmp/moved.status" 2>&1
grep -qx "$(printf 'moved\t1')" "$cli_tmp/moved.status" && grep -q '^point A: no circle on JOINTS' "$cli_tmp/moved/moved.out" \
  && pass || fail dxf-batch-can-fail "a moved joint passed in a batch: $(cat "$cli_tmp/moved.status")"
# without --at: the sheet of the run (hodographs, diagrams) as DXF, read back; --pairs selects
for deck in data/pr3207_flywheel.nml data/gears_reducer.nml; do
  name=$(basename "$deck" .nml)
  run_ks "$deck" --format dxf --lang ru
  cp "$out" "$cli_tmp/$name.sheet.dxf"
  [ "$rc" -eq 0 ] && run_py "$dxf_check" "$cli_tmp/$name.sheet.dxf" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "dxf-sheet-$name" "rc=$rc $(head -10 "$cli_tmp/check.out")"
done
run_ks data/pr3207.nml --format dxf --pairs F16
[ "$rc" -eq 0 ] && grep -q '^F16$' "$out" && ! grep -q '^F36$' "$out" && pass || fail dxf-sheet-pairs "rc=$rc"
expect_exit dxf-not-gears 1 data/gears_reducer.nml --format dxf --at 1
