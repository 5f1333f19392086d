# --format dxf --at K: the mechanism at step K as an ASCII DXF (R12 entities, layers LINKS,
# JOINTS, GUIDES, FORCES, TEXT), read back by tools/dxf_check.py against the CSV's positions
# on every linkage deck at three steps; the check can fail; usage errors.
dxf_check="$root/tools/dxf_check.py"
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  case "$name" in gears_*|cam_*|gear_geometry_*|planetary_synthesis*|assur_toggle) continue ;; esac
  run_ks "$deck" --format csv --kinematics
  cp "$out" "$cli_tmp/$name.kin.csv"
  steps=$(($(wc -l <"$out") - 1))
  for k in 1 $(((steps + 1) / 2)) "$steps"; do
    run_ks "$deck" --format dxf --at "$k"
    if [ "$rc" -ne 0 ]; then fail "dxf-runs-$name-$k" "rc=$rc: $(head -c 300 "$err")"; continue; fi
    cp "$out" "$cli_tmp/$name.$k.dxf"
    python3 "$dxf_check" "$cli_tmp/$name.$k.dxf" "$cli_tmp/$name.kin.csv" "$k" >"$cli_tmp/check.out" 2>&1 \
      && pass || fail "dxf-$name-$k" "$(head -10 "$cli_tmp/check.out")"
  done
done
# the check can fail: joint A moved by 1 mm (the first circle's x)
awk 'BEGIN{c=0} {print} /^CIRCLE$/ {c=1} c==1 && /^ *10$/ {getline; printf "%.6f\n", $1 + 1; c=2}' \
  "$cli_tmp/sixbar.1.dxf" >"$cli_tmp/moved.dxf"
python3 "$dxf_check" "$cli_tmp/moved.dxf" "$cli_tmp/sixbar.kin.csv" 1 >/dev/null 2>&1 \
  && fail dxf-check-can-fail "a moved joint was accepted" || pass
expect_exit dxf-needs-at 1 data/sixbar.nml --format dxf
expect_exit dxf-not-gears 1 data/gears_reducer.nml --format dxf --at 1
