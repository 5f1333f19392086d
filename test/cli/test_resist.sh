# Technological resistance (force(i)%resist, moment(i)%resist in &assur): the load always
# opposes its link's motion, so over a turn it does the useful work 2 * size * swing (or
# stroke), checked against the hand geometry; the cycle efficiency of a four-bar with a
# resisting rocker moment is ~0.96, not 0 as with a constant moment.

# sizes by hand: the rocker's swing (law of cosines at the extreme positions, crank and
# coupler in line) and the offset slider-crank's stroke
resist_hand() {
  run_py -c "
import math
swing = math.acos((0.3**2 + 0.25**2 - 0.45**2) / (2*0.3*0.25)) - math.acos((0.3**2 + 0.25**2 - 0.25**2) / (2*0.3*0.25))
stroke = math.sqrt(0.45**2 - 0.02**2) - math.sqrt(0.25**2 - 0.02**2)
print(2 * 40 * swing, 2 * 500 * stroke)"
}
read -r useful_rocker useful_slider <<<"$(resist_hand)"

# 1. the bundled deck: driver's work - friction losses = useful work (rel 1e-4: trapezoidal
#    rule over 2 deg steps, ~1.4e-5 here); cycle efficiency 0.959 (not 0)
run_ks data/friction_fourbar_resist.nml
run_py - "$out" "$useful_rocker" <<'PY' && pass || fail resist-fourbar-work "useful work or efficiency off"
import re, sys
text = open(sys.argv[1]).read()
get = lambda k: float(re.search(r"^\s*" + k + r"\s*=\s*(\S+)", text, re.M).group(1))
a_driver, a_loss, eta = get("A_DRIVER"), get("A_LOSS"), get("ETA")
useful = float(sys.argv[2])
if abs(a_driver - a_loss - useful) > 1e-4 * useful or not 0.955 < eta < 0.965:
    print(f"A_driver - A_loss = {a_driver - a_loss:.6f} J, by hand 2*40*swing = {useful:.6f} J; eta = {eta:.6f}")
    sys.exit(1)
PY

# 2. the moment's sign at every step is against the rocker's angular velocity, its size 40
#    N*m, 0 only where the rocker stops (the echoed VALUE list against omega3 of --kinematics)
run_ks data/friction_fourbar_resist.nml --format csv --kinematics; cp "$out" "$cli_tmp/resist_kin.csv"
run_ks data/friction_fourbar_resist.nml
run_py - "$out" "$cli_tmp/resist_kin.csv" <<'PY' && pass || fail resist-fourbar-sign "a resisting moment helps the motion"
import csv, re, sys
text = open(sys.argv[1]).read()
block = text.split("RESIST", 1)[1].split("VALUE(", 1)[1]
values = []
for line in block.splitlines()[1:]:
    nums = re.findall(r"-?\d\.\d+E[+-]\d+", line)
    if not nums or "=" in line:
        break
    values += [float(v) for v in nums]
rows = list(csv.DictReader(open(sys.argv[2])))
bad = [(r["phi1"], v, r["omega3"]) for r, v in zip(rows, values)
       if not ((abs(float(r["omega3"])) > 1e-9 and abs(abs(v) - 40) < 1e-9 and v * float(r["omega3"]) < 0)
               or (abs(float(r["omega3"])) <= 1e-9 and v == 0))]
if len(values) != len(rows) or bad:
    print(f"{len(values)} values, {len(rows)} rows; first bad (phi1, value, omega3): {bad[:3]}"); sys.exit(1)
PY

# 3. a resisting force on the slider of the offset slider-crank, frictionless: the driver's
#    work per turn (summary work_M1) = 2 * 500 N * stroke (rel 1e-4, 1 deg steps)
sed -e 's/force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180/force(1)%value = 500, force(1)%resist = .true./' \
    -e 's/dphi = 30 /dphi = 1 /' data/assur_slider_crank.nml >"$cli_tmp/resist_slider.nml"
run_ks "$cli_tmp/resist_slider.nml" --format summary
run_py - "$out" "$useful_slider" <<'PY' && pass || fail resist-slider-work "work of the resisting force off"
import csv, sys
row = list(csv.DictReader(open(sys.argv[1])))[0]
work, useful = float(row["work_M1"]), float(sys.argv[2])
if abs(work - useful) > 1e-4 * useful:
    print(f"work_M1 = {work}, by hand 2*500*stroke = {useful}"); sys.exit(1)
PY

# 4. its size must not be negative (the motion gives the sign)
printf '%s\n' "$(sed 's/moment(1)%value = 40,/moment(1)%value = -40,/' data/friction_fourbar_resist.nml)" >"$cli_tmp/resist_negative.nml"
expect_input_error resist-negative 'moment\(1\)%value: must be >= 0 with resist' "$cli_tmp/resist_negative.nml"
