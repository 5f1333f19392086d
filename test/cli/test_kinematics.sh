# --kinematics: the kinematics columns come only when asked, after the ordinary
# columns (so every default row is a prefix of the kinematics row); the legacy table ignores
# the option; the JSON with them loads and names them with their units and frames. The runs
# without --kinematics are the goldens of data/expected (the golden check proves them the
# binary's output). A heavy deck (lib.sh) with tools/test --long only: its twin
# (pr3207_flywheel, assur_engine_flywheel) runs.

for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  [ "$name" = assur_toggle ] && continue
  # the design kinds have no kinematics columns (--kinematics changes nothing there)
  case "$name" in gear_geometry_*|planetary_synthesis*|cam_profile_*) continue ;; esac
  heavy_deck "$name" && continue
  # the run without --kinematics: its golden (the golden check proves it the binary's output);
  # the CSVs are compared after the loop, every deck in one Python process
  run_ks_cached "$name.kin.csv" "$deck" --format csv --kinematics
  printf '%s\t%s\t%s\n' "$name" "data/expected/$name.csv" "$out" >>"$cli_tmp/k_pairs.tsv"
  cp "data/expected/$name.table" "$cli_tmp/k_plain.table"
  run_ks "$deck" --kinematics
  if cmp -s "$out" "$cli_tmp/k_plain.table"; then pass; else fail "kinematics-table-$name" "--kinematics changed the legacy table"; fi
done
# every deck's CSV with --kinematics is its default CSV plus columns: a line "ok NAME" or
# "FAIL NAME: why" per deck (a deck with no line fails too)
run_py - "$cli_tmp/k_pairs.tsv" >"$cli_tmp/k_pairs.out" 2>&1 <<'PY'
import sys
for line in open(sys.argv[1]):
    name, plain_path, kin_path = line.rstrip("\n").split("\t")
    try:
        plain = open(plain_path).read().splitlines()
        kin_text = open(kin_path).read()
        kin = kin_text.splitlines()
        assert len(plain) == len(kin) and len(plain) > 1, (len(plain), len(kin))
        for p, k in zip(plain, kin):
            assert k.startswith(p + ","), (p[:60], k[:60])
        extra = kin[0][len(plain[0]) + 1:].split(",")
        assert any(c.startswith("x_") for c in extra), extra
        assert any(c.endswith("_x") for c in extra), extra
        assert "nan" not in kin_text.lower()
        print("ok", name)
    except Exception as exc:  # noqa: BLE001 - the deck's verdict, whatever went wrong
        print("FAIL %s: %r" % (name, exc))
PY
while IFS=$'\t' read -r name _ _; do
  if grep -qx "ok $name" "$cli_tmp/k_pairs.out"; then pass
  else fail "kinematics-csv-$name" "kinematics CSV is not the default CSV plus columns: $(grep -m1 "^FAIL $name:" "$cli_tmp/k_pairs.out" || tail -3 "$cli_tmp/k_pairs.out")"; fi
done <"$cli_tmp/k_pairs.tsv"
rm -f "$cli_tmp/k_pairs.tsv"

run_ks data/sixbar.nml --format json --kinematics
run_py - "$out" <<'PY' && pass || fail kinematics-json "JSON with --kinematics does not load or lacks the columns"
import json, sys
d = json.load(open(sys.argv[1]))
cols = {c["name"]: c for c in d["columns"]}
assert cols["x_H"]["unit"] == "m" and cols["x_H"]["kinematic"] is True
assert cols["omega3"]["unit"] == "rad/s" and cols["eps4"]["unit"] == "rad/s^2"
assert cols["ax_S4"]["unit"] == "m/s^2"
# F43 is given in frame 2 (x2 at beta - 180 deg in frame 1), F21 in frame 1
assert abs(cols["F43_x"]["frame_angle"] - (-153.43494882292202)) < 1e-9, cols["F43_x"]
assert cols["F21_x"]["frame_angle"] == 0
assert all(len(r) == len(d["columns"]) for r in d["rows"])
PY
run_ks data/sixbar.nml --format json
if [ "$rc" -ne 0 ] || ! grep -q '"columns"' "$out"; then fail kinematics-json-default "rc=$rc: $(head -c 300 "$err")"
elif grep -q '"kinematic"' "$out"; then fail kinematics-json-default "default JSON lists kinematics columns"
else pass; fi

# the points' velocities vx_P, vy_P and accelerations ax_P, ay_P against central differences
# of the positions over the input angle (tools/motion_check.py, 4th-order stencils at 0.5 deg,
# relative 1e-6 of the largest speed or acceleration): every linkage kind, a class-III group,
# the true motion of a steady cycle (omega1, eps1 varying)
motion_case() {
  local name="$1"; shift
  run_ks "$@" --kinematics --format csv
  if [ "$rc" -ne 0 ]; then fail "kinematics-motion-$name" "exit $rc: $(head -c 300 "$err")"; return; fi
  cp "$out" "$cli_tmp/motion.csv"
  if run_py tools/motion_check.py "$cli_tmp/motion.csv" >"$cli_tmp/motion.out" 2>&1 && grep -q "^motion: OK" "$cli_tmp/motion.out"; then
    pass
  else
    fail "kinematics-motion-$name" "$(tail -4 "$cli_tmp/motion.out")"
  fi
}
motion_case pr3207 data/pr3207.nml --set phi_start=100 --set dphi=0.5 --set n=7
motion_case sixbar data/sixbar_example.nml --set dphi=0.5 --set n=7 --set "f5=7*5000"
motion_case assur-sixbar data/assur_sixbar.nml --set phi_start=100 --set dphi=0.5 --set n=7
motion_case assur-pr3050 data/assur_slider_crank.nml --set phi_start=100 --set dphi=0.5 --set n=7
motion_case linkage-slider-crank data/linkage_slider_crank.nml --set "drive(1)%start=40" --set "drive(1)%step=0.5" --set n=7
motion_case class3 data/class3.nml --set "drive(1)%start=30" --set "drive(1)%step=0.5" --set n=7
motion_case pr3207-flywheel data/pr3207_flywheel.nml --set dphi=0.5 --set n=721
# the check must fail on a changed velocity and a changed acceleration
run_ks data/class3.nml --set "drive(1)%start=30" --set "drive(1)%step=0.5" --set n=7 --kinematics --format csv
for col in vx_T1 ay_B; do
  run_py - "$out" "$col" "$cli_tmp/motion_bad.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
c = rows[0].index(sys.argv[2])
rows[3][c] = repr(float(rows[3][c]) * (1 + 1e-4) + 1e-3)
csv.writer(open(sys.argv[3], "w", newline=""), lineterminator="\n").writerows(rows)
PY
  if run_py tools/motion_check.py "$cli_tmp/motion_bad.csv" >"$cli_tmp/motion.out" 2>&1; then
    fail "kinematics-motion-must-fail-$col" "a changed $col passed: $(tail -2 "$cli_tmp/motion.out")"
  elif grep -q "^motion: FAIL" "$cli_tmp/motion.out"; then pass
  else fail "kinematics-motion-must-fail-$col" "no verdict: $(tail -2 "$cli_tmp/motion.out")"; fi
done

# the points' velocities and accelerations (closed form, link by link) against the plans of
# velocities and accelerations of the same step (--plans --format json: the least-squares
# solve of every pair equation, an independent solver): every point the plan and the CSV
# share, within 1e-9 of the plan's largest vector; a slider pair (pr3207: the ram from two
# guides), dyads, a class-III group, the general engine's slider-crank
plans_compare() {
  run_py - "$1" "$2" "$3" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
plans = json.load(open(sys.argv[2]))
row = rows[int(sys.argv[3]) - 1]
bad = []
for plan, (cx, cy) in (("velocity_plan", ("vx_", "vy_")), ("acceleration_plan", ("ax_", "ay_"))):
    pts = plans[plan]["points"]
    scale = max(max(abs(p["x"]), abs(p["y"])) for p in pts)
    n = 0
    for p in pts:
        if cx + p["name"] not in row:
            continue
        n += 1
        for key, col in (("x", cx), ("y", cy)):
            got = float(row[col + p["name"]])
            if abs(got - p[key]) > 1e-9 * scale:
                bad.append(f"{col}{p['name']}: csv {got!r} vs plan {p[key]!r} (tolerance {1e-9 * scale:.2e})")
    if n == 0:
        bad.append(f"{plan}: no point in common with the CSV")
print("plans: FAIL " + "; ".join(bad[:4]) if bad else "plans: OK")
PY
}
plans_case() {
  local name="$1" at="$2"; shift 2
  run_ks "$@" --kinematics --format csv
  if [ "$rc" -ne 0 ]; then fail "kinematics-plans-$name" "exit $rc: $(head -c 300 "$err")"; return; fi
  cp "$out" "$cli_tmp/plans.csv"
  run_ks "$@" --plans --at "$at" --format json
  if [ "$rc" -ne 0 ]; then fail "kinematics-plans-$name" "plans exit $rc: $(head -c 300 "$err")"; return; fi
  cp "$out" "$cli_tmp/plans.json"
  plans_compare "$cli_tmp/plans.csv" "$cli_tmp/plans.json" "$at" >"$cli_tmp/plans.out" 2>&1
  if grep -q "^plans: OK" "$cli_tmp/plans.out"; then pass; else fail "kinematics-plans-$name" "$(tail -2 "$cli_tmp/plans.out")"; fi
}
plans_case pr3207 5 data/pr3207.nml
plans_case assur-sixbar 4 data/assur_sixbar.nml
plans_case assur-slider-crank 3 data/assur_slider_crank.nml
plans_case linkage-slider-crank 3 data/linkage_slider_crank.nml
plans_case class3 7 data/class3.nml
plans_case sixbar 4 data/sixbar.nml
plans_case assur-pr3050 3 data/assur_pr3050.nml
# the comparison must fail on a changed velocity
run_py - "$cli_tmp/plans.csv" "$cli_tmp/plans_bad.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
c = next(j for j, n in enumerate(rows[0]) if n.startswith("vx_") and abs(float(rows[3][j])) > 1e-3)
rows[3][c] = repr(float(rows[3][c]) * (1 + 1e-6))
csv.writer(open(sys.argv[2], "w", newline=""), lineterminator="\n").writerows(rows)
PY
plans_compare "$cli_tmp/plans_bad.csv" "$cli_tmp/plans.json" 3 >"$cli_tmp/plans.out" 2>&1
if grep -q "^plans: FAIL" "$cli_tmp/plans.out"; then pass
else fail kinematics-plans-must-fail "a changed velocity passed: $(tail -2 "$cli_tmp/plans.out")"; fi
