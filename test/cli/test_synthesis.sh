# Command-line tests of the design kinds: &gear_geometry, &planetary_synthesis, &cam_profile
# (sourced by tools/test with lib.sh): the output names, the one-record summary and a sweep
# of it, the analysis decks (--format deck) that run and agree, the blocking contour, the
# design sheets (SVG and DXF: the involutes, the cam's profile polyline), the independent
# re-computation (tools/verify_synthesis.py), the signs of the pressure angle, the templates,
# and one deck per input rule.

gg=data/gear_geometry_shift.nml
ga=data/gear_geometry_auto.nml
ps=data/planetary_synthesis.nml
cr=data/cam_profile_roller.nml
cf=data/cam_profile_flat.nml
co=data/cam_profile_oscillating.nml

# --- every bundled deck runs with a clean self-check, no NaN
for d in $gg $ga $ps $cr $cf $co; do
  name=$(basename "$d" .nml)
  run_ks "$d"
  [ "$rc" -eq 0 ] && pass || fail "$name-runs" "rc=$rc: $(head -c 300 "$err")"
  expect_no_nan "$name-no-nan" "$out"
  grep -q '!!' "$out" && fail "$name-selfcheck" "a self-check line is !!" || pass
done

# --- the output names the course uses, exactly
run_ks $gg --format csv
gear_header="x1,x2,a_w,alpha_w,y,delta_y,d1,d2,db1,db2,dw1,dw2,da1,da2,df1,df2,s1,s2,sa1,sa2,x1_min,x2_min,\
eps_alpha,lambda1,lambda2,undercut1,undercut2,pointed1,pointed2,interference1,interference2"
[ "$(head -1 "$out")" = "$gear_header" ] && pass || fail gear-csv-header "$(head -1 "$out")"
run_ks $ps --format json
run_py - "$out" <<'PY' && pass || fail planetary-json "JSON lacks z1, z2, z3, u_actual or they do not satisfy z3 = z1 + 2 z2"
import json, sys
d = json.load(open(sys.argv[1]))
names = [c["name"] for c in d["columns"]]
row = dict(zip(names, d["rows"][0]))
assert {"z1", "z2", "z3", "u_actual"} <= set(names), names
assert row["z3"] == row["z1"] + 2 * row["z2"] and abs(row["u_actual"] - (1 + row["z3"] / row["z1"])) < 1e-12
PY
run_ks $cr --format json
run_py - "$out" <<'PY' && pass || fail cam-json "the summary lacks r_base, r_prime or r_base != r_prime - roller_radius"
import json, sys
d = json.load(open(sys.argv[1]))
s = {e["name"]: e["value"] for e in d["summary"]}
assert abs(s["r_base"] - (s["r_prime"] - 0.008)) < 1e-14, s
assert abs(s["theta_rise_max"] - 30) < 1e-9 and s["theta_return_max"] <= 45 + 1e-9, s
PY
run_ks $cf --format json
run_py - "$out" <<'PY' && pass || fail cam-flat-json "the flat face's summary lacks face_width or rho_min"
import json, sys
d = json.load(open(sys.argv[1]))
s = {e["name"]: e["value"] for e in d["summary"]}
assert abs(s["face_width"] - 0.05) < 1e-12 and abs(s["r_base"] - 0.025) < 1e-12 and abs(s["rho_min"] - 0.05) < 1e-12, s
PY

# --- z = 12 without shift: flagged undercut, a warning naming it, exit 4 with --strict
run_ks $gg --set x1=0 --set x2=0 --format csv
awk -F, 'NR==2{exit !($26 == 1 && $27 == 0)}' "$out" && pass || fail gear-undercut-z12 "undercut1/2 = $(cut -d, -f26,27 "$out" | tail -1)"
grep -q "gear 1 is undercut: x1 = 0 < x1_min = 0.298" "$err" && pass || fail gear-undercut-warning "$(cat "$err")"
expect_exit gear-undercut-strict 4 $gg --set x1=0 --set x2=0 --strict

# --- --format summary of a one-record kind: its values; a sweep of it is a study
run_ks $gg --format csv; cp "$out" "$cli_tmp/gear.csv"
run_ks $gg --format summary
cmp -s "$out" "$cli_tmp/gear.csv" && pass || fail gear-summary-values "summary differs from the CSV: $(head -c 300 "$out")"
run_ks sweep $gg --vary x1=0:1:11 --jobs 1
run_py - "$out" <<'PY' && pass || fail gear-sweep-study "the sweep over x1 is not a study of the pair: $(head -c 300 "$out")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
header = open(sys.argv[1]).readline().strip().split(",")
assert len(rows) == 11 and header.count("x1") == 1 and header[0] == "x1", header
x = [float(r["x1"]) for r in rows]
assert all(abs(x[k] - k / 10) < 1e-12 for k in range(11)), x
assert all(float(rows[k + 1]["a_w"]) > float(rows[k]["a_w"]) for k in range(10))   # a_w grows with x1
assert [int(r["undercut1"]) for r in rows][:3] == [1, 1, 1] and int(rows[3]["undercut1"]) == 0
PY

# --- the analysis decks: written, they run, and they carry the design's numbers
run_ks $gg --format deck; cp "$out" "$cli_tmp/gg_gears.nml"
[ "$rc" -eq 0 ] && grep -q '^&gears' "$cli_tmp/gg_gears.nml" && pass || fail gear-deck-written "rc=$rc: $(cat "$err")"
run_ks "$cli_tmp/gg_gears.nml" --format csv
awk -F, 'NR==2{exit !($7 > 37.6665 && $7 < 37.6666)}' "$out" && [ "$rc" -eq 0 ] && pass \
  || fail gear-deck-runs "rc=$rc, dw1 = $(cut -d, -f7 "$out" | tail -1): $(head -c 200 "$err")"
run_ks $ps --format deck; cp "$out" "$cli_tmp/ps_gears.nml"
run_ks "$cli_tmp/ps_gears.nml" --format csv
[ "$rc" -eq 0 ] && awk -F, 'NR==2{exit !($3 == 22 && $4 == 32 && $5 == 86 && $6 == 3)}' "$out" && pass \
  || fail planetary-deck-runs "rc=$rc: $(head -2 "$out" | tail -1) $(head -c 200 "$err")"
for d in $cr $cf; do
  name=$(basename "$d" .nml)
  run_ks "$d" --format deck; cp "$out" "$cli_tmp/${name}_cam.nml"
  run_ks "$cli_tmp/${name}_cam.nml" --format csv --quiet; cp "$out" "$cli_tmp/${name}_cam.csv"
  [ "$rc" -eq 0 ] && pass || fail "$name-deck-runs" "rc=$rc: $(head -c 300 "$err")"
  run_ks "$d" --format csv; cp "$out" "$cli_tmp/${name}_profile.csv"
  run_py - "$cli_tmp/${name}_profile.csv" "$cli_tmp/${name}_cam.csv" <<'PY' && pass || fail "$name-deck-agrees" "the &cam run does not take the profile's angles"
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(b)
for p, q in zip(a, b):
    assert abs(float(p["phi"]) - float(q["phi"])) < 1e-9
    assert abs(float(p["theta"]) - float(q["theta"])) < 1e-9            # the pressure angle
    if "rho_pitch" not in p:                                              # flat: x_B = omega_dir*ds/dphi
        assert abs(float(q["xB"]) - float(p["ds"])) < 1e-12
PY
done
expect_exit cam-deck-oscillating 1 $co --format deck
run_ks "$(deck_with no_m1b $gg '/m1 = 20/d')" --format deck
[ "$rc" -eq 2 ] && grep -q "&gear_geometry: m1: missing" "$err" && [ ! -s "$out" ] && pass || fail gear-deck-needs-m1 "rc=$rc: $(cat "$err")"
run_ks "$(deck_with no_guide $cr 's/^  l = .*//')" --format deck
[ "$rc" -eq 2 ] && grep -q "l, l_over, f, f2: missing" "$err" && pass || fail cam-deck-needs-guide "rc=$rc: $(cat "$err")"
expect_exit deck-of-an-analysis-kind 1 data/gears_reducer.nml --format deck

# --- the blocking contour: long-format CSV of the eight curves
run_ks contour $ga; cp "$out" "$cli_tmp/contour.csv"
[ "$rc" -eq 0 ] && [ "$(head -1 "$out")" = "curve,x1,x2" ] && pass || fail contour-runs "rc=$rc: $(head -c 200 "$err")"
[ "$(tail -n +2 "$out" | cut -d, -f1 | uniq | tr '\n' ' ')" = \
  "undercut1 undercut2 pointed1 pointed2 eps1 eps1_2 interference1 interference2 " ] && pass \
  || fail contour-curves "$(tail -n +2 "$out" | cut -d, -f1 | uniq | tr '\n' ' ')"
run_ks contour $ga --set z1=20 --set z2=40
cmp -s "$out" "$cli_tmp/contour.csv" && fail contour-set "--set z1=20 did not change the contour" || pass
expect_exit contour-needs-gear-deck 2 contour $cr
expect_exit contour-no-format 1 contour $ga --format csv

# --- the design sheets (--format svg / dxf): the same drawing model as every sheet; the
# labels, notation, formats and frames of the SVGs are checked with every deck's sheet by
# test_legible.sh, the goldens by tools/test. Here: they parse, the DXFs read back, the meshing
# drawing's flanks lie on involutes of the base circles, the cam's profile is one closed
# POLYLINE through the CSV's points, and the options the sheets take or refuse.
synth_check="$root/tools/synthesis_check.py"
for d in $gg $ga $ps $cr $cf $co; do
  name=$(basename "$d" .nml)
  for lang in en ru; do
    run_ks "$d" --format svg --lang "$lang"; cp "$out" "$cli_tmp/$name.$lang.svg"
    [ "$rc" -eq 0 ] && xmllint --noout "$cli_tmp/$name.$lang.svg" 2>"$cli_tmp/xml.err" && pass \
      || fail "$name-sheet-svg-$lang" "rc=$rc $(head -c 300 "$err") $(head -3 "$cli_tmp/xml.err")"
  done
  run_ks "$d" --format dxf --lang ru; cp "$out" "$cli_tmp/$name.dxf"
  [ "$rc" -eq 0 ] && run_py tools/dxf_check.py "$cli_tmp/$name.dxf" >"$cli_tmp/check.out" 2>&1 && pass \
    || fail "$name-sheet-dxf" "rc=$rc $(head -c 300 "$err") $(head -5 "$cli_tmp/check.out")"
  run_ks "$d" --format csv; cp "$out" "$cli_tmp/$name.csv"
done
for name in gear_geometry_shift gear_geometry_auto; do
  run_py "$synth_check" involutes "$cli_tmp/$name.en.svg" "$cli_tmp/$name.csv" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "$name-involutes" "$(head -5 "$cli_tmp/check.out")"
done
echo "synthesis: $(cat "$cli_tmp/check.out")"
# an undercut pinion (z = 8 unshifted) is drawn as the rack cuts it, its flanks still involutes
run_ks "$(deck_with undercut $gg 's/z1 = 12/z1 = 8/; s/x1 = 0.6/x1 = 0/; s/x2 = 0.36/x2 = 0/')" --format svg
cp "$out" "$cli_tmp/undercut.svg"
run_ks "$(deck_with undercut $gg 's/z1 = 12/z1 = 8/; s/x1 = 0.6/x1 = 0/; s/x2 = 0.36/x2 = 0/')" --format csv
run_py "$synth_check" involutes "$cli_tmp/undercut.svg" "$out" >"$cli_tmp/check.out" 2>&1 \
  && pass || fail gear-undercut-involutes "$(head -5 "$cli_tmp/check.out")"
# the check can fail: two points of a flank moved 0.2 mm, across and along the sheet
run_py - "$cli_tmp/gear_geometry_shift.en.svg" "$cli_tmp/moved.svg" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
m = re.search(r'<path d="([^"]*)"[^>]*data-flank="1"', text)
pts = m.group(1).split(" L ")
x, y = pts[5].split()
pts[5] = f"{float(x) + 0.2:.2f} {y}"
x, y = pts[15].split()
pts[15] = f"{x} {float(y) + 0.2:.2f}"
open(sys.argv[2], "w", encoding="utf-8").write(text.replace(m.group(1), " L ".join(pts), 1))
PY
run_py "$synth_check" involutes "$cli_tmp/moved.svg" "$cli_tmp/gear_geometry_shift.csv" >"$cli_tmp/check.out" 2>&1
grep -q "off an involute" "$cli_tmp/check.out" && pass || fail involutes-check-can-fail "$(head -3 "$cli_tmp/check.out")"
for name in cam_profile_roller cam_profile_flat cam_profile_oscillating; do
  run_py "$synth_check" cam-profile "$cli_tmp/$name.dxf" "$cli_tmp/$name.csv" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "$name-profile-polyline" "$(head -5 "$cli_tmp/check.out")"
done
# ... and so can the profile's: a vertex moved by 1 um on the paper
run_py - "$cli_tmp/cam_profile_roller.dxf" "$cli_tmp/moved.dxf" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
# the POLYLINE on layer PROFILE; its first VERTEX's x follows
i = next(k for k in range(len(lines) - 2) if lines[k] == "POLYLINE" and lines[k + 2] == "PROFILE")
i = lines.index("VERTEX", i)
i = lines.index("10", i) + 1
lines[i] = f"{float(lines[i]) + 0.001:.6f}"
open(sys.argv[2], "w").write("\n".join(lines))
PY
run_py "$synth_check" cam-profile "$cli_tmp/moved.dxf" "$cli_tmp/cam_profile_roller.csv" >"$cli_tmp/check.out" 2>&1
grep -q "phi = 0" "$cli_tmp/check.out" && pass || fail cam-profile-check-can-fail "$(head -3 "$cli_tmp/check.out")"
# the follower where --at puts it (else at the largest pressure angle: 260 deg on this cam)
grep -q 'follower at φ = 260.0 deg' "$cli_tmp/cam_profile_roller.en.svg" && pass \
  || fail cam-sheet-follower "$(grep -o 'follower at[^;]*' "$cli_tmp/cam_profile_roller.en.svg" | head -1)"
run_ks $cr --format svg --at 13
[ "$rc" -eq 0 ] && grep -q 'follower at φ = 60.0 deg' "$out" && pass || fail cam-sheet-at "rc=$rc $(head -c 200 "$err")"
expect_exit cam-sheet-at-beyond 1 $cr --format svg --at 74
expect_exit gear-sheet-no-at 1 $ga --format svg --at 1
expect_exit planetary-sheet-no-at 1 $ps --format dxf --at 1
expect_exit design-sheet-no-pairs 1 $ga --format svg --pairs F12
expect_exit design-no-plans 1 $cr --format plans --at 1

# --- the signs: a mirrored cam (clockwise, offset on the other side) has the opposite
# pressure angle and the mirrored profile
run_ks $cr --format csv; cp "$out" "$cli_tmp/ccw.csv"
run_ks $cr --format csv --set omega=-10 --set offset=-0.005; cp "$out" "$cli_tmp/cw.csv"
run_py - "$cli_tmp/ccw.csv" "$cli_tmp/cw.csv" <<'PY' && pass || fail cam-mirror "the mirrored cam's angle or profile is not mirrored"
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
for p, q in zip(a, b):
    assert abs(float(p["theta"]) + float(q["theta"])) < 1e-9, (p["phi"], p["theta"], q["theta"])
    assert abs(float(p["x_profile"]) + float(q["x_profile"])) < 1e-12 and abs(float(p["y_profile"]) - float(q["y_profile"])) < 1e-12
PY
# a positive offset lowers the rise's pressure angle of a counter-clockwise cam
run_ks $cr --format json --set offset=0
r0=$(run_py -c 'import json,sys; print({e["name"]: e["value"] for e in json.load(open(sys.argv[1]))["summary"]}["r_prime"])' "$out")
run_ks $cr --format json
r5=$(run_py -c 'import json,sys; print({e["name"]: e["value"] for e in json.load(open(sys.argv[1]))["summary"]}["r_prime"])' "$out")
run_py -c "import sys; sys.exit(not $r5 < $r0)" && pass || fail cam-offset-sense "offset 5 mm: r_prime $r5 not below $r0 without offset"

# --- the independent re-computation
if run_py tools/verify_synthesis.py "$KINETOSTAT" >"$cli_tmp/verify_synthesis.out" 2>&1; then pass
else fail verify-synthesis "$(tail -20 "$cli_tmp/verify_synthesis.out")"; fi
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  if run_py tools/verify_synthesis.py "$KINETOSTAT" --long >"$cli_tmp/verify_synthesis.out" 2>&1; then pass
  else fail verify-synthesis-long "$(tail -20 "$cli_tmp/verify_synthesis.out")"; fi
fi

# --- templates: valid decks that run
for kind in gear_geometry planetary_synthesis cam_profile; do
  run_ks template $kind; cp "$out" "$cli_tmp/template_$kind.nml"
  [ "$rc" -eq 0 ] && grep -q "^&$kind" "$cli_tmp/template_$kind.nml" && pass || fail "$kind-template" "rc=$rc"
  run_ks "$cli_tmp/template_$kind.nml"
  [ "$rc" -eq 0 ] && pass || fail "$kind-template-runs" "rc=$rc: $(cat "$err")"
done

# --- input errors: exit 2, one line naming deck, group, variable and reason
expect_input_error gear-m-missing '&gear_geometry: m: missing' "$(deck_with e1 $gg '/^  m  = 3/d')"
expect_input_error gear-z1-zero '&gear_geometry: z1: must be >= 1 teeth' "$(deck_with e2 $gg 's/z1 = 12/z1 = 0/')"
expect_input_error gear-z2-fraction '&gear_geometry: z2: must be a whole number' "$(deck_with e3 $gg 's/z2 = 24/z2 = 24.5/')"
expect_input_error gear-alpha-range '&gear_geometry: alpha: must be in \(0, 45\)' "$(deck_with e4 $gg 's/x2 = 0.36/x2 = 0.36, alpha = 50/')"
expect_input_error gear-shift-word "&gear_geometry: shift: must be 'auto' or 'given'" "$(deck_with e5 $ga "s/shift = 'auto'/shift = 'best'/")"
expect_input_error gear-auto-with-x1 "&gear_geometry: x1: not with shift = 'auto'" "$(deck_with e6 $ga "s/shift = 'auto'/shift = 'auto', x1 = 0.2/")"
expect_input_error gear-a_w-small '&gear_geometry: a_w: must exceed a\*cos\(alpha\)' "$(deck_with e7 $ga "s/shift = 'auto'/shift = 'auto', a_w = 70/")"
expect_input_error gear-a_w-unsplit '&gear_geometry: a_w: gives x1 \+ x2 = ' "$(deck_with e8 $ga "s/shift = 'auto'/a_w = 82/")"
expect_input_error gear-a_w-both '&gear_geometry: a_w: with x1 and x2 both given' "$(deck_with e9 $ga "s/shift = 'auto'/a_w = 82, x1 = 0.1, x2 = 0.2/")"
expect_input_error gear-ha-star '&gear_geometry: ha_star: must be > 0' "$(deck_with e10 $gg 's/x2 = 0.36/x2 = 0.36, ha_star = 0/')"
expect_input_error gear-x-huge '&gear_geometry: x1: must be within -100 .. 100' "$(deck_with e11 $gg 's/x1 = 0.6/x1 = 1e300/')"
expect_input_error gear-no-flank 'a tip circle lies inside its base circle' "$(deck_with e12 $gg 's/x1 = 0.6/x1 = -1.4/; s/x2 = 0.36/x2 = 2/')"
expect_input_error planetary-u-small '&planetary_synthesis: u: must be in \(2, 1000\]' "$(deck_with p1 $ps 's/u  = 5 /u = 1.5/')"
expect_input_error planetary-k-zero '&planetary_synthesis: k: must be a whole number from 1 to 100' "$(deck_with p2 $ps 's/k  = 3 /k = 0/')"
expect_input_error planetary-tolerance '&planetary_synthesis: u_tolerance: must be in \[0, 0.5\)' "$(deck_with p3 $ps 's/u_tolerance = 0.04/u_tolerance = 0.6/')"
expect_input_error planetary-scheme "&planetary_synthesis: scheme: must be 'single_row'" "$(deck_with p4 $ps "s/k  = 3 /k = 3, scheme = 'double_row'/")"
expect_input_error planetary-none 'no single-row train' "$(deck_with p5 $ps 's/k  = 3 /k = 4/; s/u  = 5 /u = 7.1/; s/u_tolerance = 0.04/u_tolerance = 0.02/')" 3
expect_input_error cam-follower "&cam_profile: follower: must be 'flat', 'roller' or 'oscillating'" "$(deck_with c1 $cr "s/follower = 'roller'/follower = 'knife'/")"
expect_input_error cam-law "&cam_profile: law\(2\): must be 'dwell'" "$(deck_with c2 $cr "s/'cycloidal', 'dwell'/'cycloidal', 'stop'/")"
expect_input_error cam-beta-count '&cam_profile: beta: expected 4 values' "$(deck_with c3 $cr 's/beta  = 120, 60, 120, 60/beta = 120, 60, 180/')"
expect_input_error cam-beta-sum '&cam_profile: beta: must add up to 360' "$(deck_with c4 $cr 's/beta  = 120, 60, 120, 60/beta = 120, 60, 120, 50/')"
expect_input_error cam-lift-sum '&cam_profile: lift: must add up to 0' "$(deck_with c5 $cr 's/lift  = 0.02, 0, -0.02, 0/lift = 0.02, 0, -0.01, 0/')"
expect_input_error cam-dwell-lift "&cam_profile: lift\(2\): must be 0 for a 'dwell'" "$(deck_with c6 $cr 's/lift  = 0.02, 0, -0.02, 0/lift = 0.02, 0.01, -0.03, 0/')"
expect_input_error cam-fall-first '&cam_profile: lift: the follower must start at its lowest position' "$(deck_with c7 $cr 's/lift  = 0.02, 0, -0.02, 0/lift = -0.02, 0, 0.02, 0/')"
expect_input_error cam-step '&cam_profile: step: must divide 360' "$(deck_with c8 $cr 's/step  = 5 /step = 7 /')"
expect_input_error cam-omega '&cam_profile: omega: must be non-zero' "$(deck_with c9 $cr 's/omega = 10 /omega = 0 /')"
expect_input_error cam-pressure-limit '&cam_profile: pressure_angle_max: must be in \(0, 90\)' "$(deck_with c10 $cr 's/pressure_angle_max = 30 /pressure_angle_max = 90 /')"
expect_input_error cam-rho-min-roller '&cam_profile: rho_min: not for this follower' "$(deck_with c11 $cr 's/omega = 10 /omega = 10, rho_min = 0.01 /')"
expect_input_error cam-flat-offset '&cam_profile: offset: not for this follower' "$(deck_with c12 $cf 's/rho_min = 0.05 /rho_min = 0.05, offset = 0.01 /')"
expect_input_error cam-flat-rho-min '&cam_profile: rho_min: missing' "$(deck_with c13 $cf '/rho_min = 0.05/d')"
expect_input_error cam-arm '&cam_profile: arm: missing' "$(deck_with c14 $co '/^  arm /d')"
expect_input_error cam-pivot-origin '&cam_profile: pivot: must not be the cam' "$(deck_with c15 $co 's/pivot = 0.09, 0.06/pivot = 0, 0/')"
expect_input_error cam-roller-too-big 'not larger than the roller' "$(deck_with c16 $cr 's/roller_radius = 0.008/roller_radius = 0.5/')" 3
expect_input_error cam-f-cam-roller '&cam_profile: f_cam: only for a flat face' "$(deck_with c17 $cr 's/f2 = 200/f2 = 200, f_cam = 0.1/')"
expect_input_error cam-rho-min-tiny 'rho_min is so small' "$(deck_with c18 $cf 's/rho_min = 0.05 /rho_min = 1e-9 /')" 3
