# Command-line tests of the machine dynamics stage (sourced by tools/test with test/cli/lib.sh).
fw=data/pr3207_flywheel.nml

# --- the bundled deck: delta reached, M1 = M_d in the footer, the columns, ru labels
run_ks "$fw" --format json; cp "$out" "$cli_tmp/fw.json"
[ "$rc" -eq 0 ] && pass || fail dynamics-json-exit "exit $rc: $(cat "$err")"
if run_py - "$cli_tmp/fw.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
dy, cols = d["dynamics"], [c["name"] for c in d["columns"]]
assert abs(dy["delta"] - 0.04) <= 1e-9 * 0.04, dy["delta"]
assert abs((dy["omega_max"] + dy["omega_min"]) / 2 - 7.5) <= 1e-12 * 7.5
assert d["selfcheck"]["max_drive_deviation"] <= 1e-9 and d["selfcheck"]["ok"]
for c in ["J_red", "dJ_red", "M_red", "dT", "omega1", "eps1", "t"]:
    assert c in cols, c
i, m = cols.index("omega1"), cols.index("M1")
rows = d["rows"]
assert abs(rows[0][i] - rows[-1][i]) <= 1e-12 * 7.5          # periodic
assert all(abs(r[m] - dy["M_d"]) <= 1e-9 * dy["M_d"] for r in rows)
assert max(r[i] for r in rows) <= dy["omega_max"] * (1 + 1e-14)
PY
then pass; else fail dynamics-json-laws "delta, periodicity or M1 = M_d do not hold in $cli_tmp/fw.json"; fi
run_ks "$fw" --lang ru
if grep -q "ДИНАМИЧЕСКИЙ РАСЧЕТ" "$out" && grep -q "ПРИВЕДЕННЫЙ МОМЕНТ ИНЕРЦИИ" "$out" && grep -q "МАХОВИК" "$out"; then pass
else fail dynamics-ru-labels "Russian DYNAMICS block missing"; fi
run_ks "$fw"
if grep -Eq "MAX \|M1 - M_d\|/\|M_d\| WITH THE TRUE MOTION +[0-9.E+-]+  OK" "$out"; then pass
else fail dynamics-footer "no M1 = M_d footer line: $(tail -4 "$out")"; fi

# --- 'given' with the flywheel found gives back delta; a huge flywheel gives the constant-speed
# force magnitudes (angles of forces near zero are undefined)
jfw=$(run_py -c "import json; print(repr(json.load(open('$cli_tmp/fw.json'))['dynamics']['J_flywheel']))")
given=$(deck_with fw_given "$fw" "s/dynamics = 'steady', delta = 0.04/dynamics = 'given', j_flywheel = $jfw/")
run_ks "$given" --format json
if run_py -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if abs(d['dynamics']['delta']-0.04) <= 4e-11 else 1)" /dev/stdin <"$out"
then pass; else fail dynamics-given-delta "delta with the found flywheel: $(grep -o '"delta": [^,]*' "$out")"; fi
huge=$(deck_with fw_huge data/pr3207.nml "s/phi_start = 0, dphi = 30/phi_start = 0, dphi = 30, dynamics = 'given', j_flywheel = 1e12/")
run_ks "$huge" --format csv
cut -d, -f1,2,4,6,8,10 "$out" >"$cli_tmp/huge_forces.csv"
cut -d, -f1,2,4,6,8,10 data/expected/pr3207.csv >"$cli_tmp/golden_forces.csv"
if numdiff -q -s ' \t\n,' -r 1e-6 -a 1e-6 "$cli_tmp/golden_forces.csv" "$cli_tmp/huge_forces.csv" >/dev/null 2>&1; then pass
else fail dynamics-huge-flywheel "forces with j_flywheel = 1e12 differ from the constant-speed golden"; fi
red=$(deck_with fw_reduced data/pr3207.nml "s/phi_start = 0, dphi = 30/phi_start = 0, dphi = 30, dynamics = 'reduced'/")
run_ks "$red" --format csv
if [ "$(head -1 "$out")" = "phi1,F16,F16G,F21,F21G,F36,F36G,F34,F34G,F56,F56G,M1,J_red,dJ_red,M_red" ] && \
   cmp -s <(cut -d, -f1-12 "$out") data/expected/pr3207.csv; then pass
else fail dynamics-reduced-columns "dynamics = 'reduced': header '$(head -1 "$out")' or forces changed"; fi

# --- every error of the stage, from a deck
expect_input_error dynamics-unknown "dynamics: unknown value 'wobbly'" "$(deck_with dyn_unknown "$fw" "s/'steady'/'wobbly'/")"
expect_input_error dynamics-delta-zero "delta: must be > 0 and < 1" "$(deck_with dyn_d0 "$fw" "s/delta = 0.04/delta = 0/")"
expect_input_error dynamics-delta-negative "delta: must be > 0 and < 1" "$(deck_with dyn_dneg "$fw" "s/delta = 0.04/delta = -0.1/")"
expect_input_error dynamics-delta-missing "delta: missing" "$(deck_with dyn_dmiss "$fw" "s/, delta = 0.04//")"
expect_input_error dynamics-no-flywheel-needed "no flywheel is needed" "$(deck_with dyn_big_rotor "$fw" "s/j_rotor = 0.6/j_rotor = 5000/")"
expect_input_error dynamics-not-one-turn "exactly one turn" "$(deck_with dyn_turn "$fw" "s/dphi = 1 /dphi = 1, n = 181 /")"
# loads that do net positive work (an engine's case): M_d < 0 is the consumer's moment, M1 = M_d
run_ks "$(deck_with dyn_engine "$fw" "s/f5c_work = 3000/f5c_work = -3000/")" --format json
if [ "$rc" -eq 0 ] && run_py -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d['dynamics']['M_d'] < 0 and d['selfcheck']['ok'] else 1)" "$out"
then pass; else fail dynamics-negative-md "loads driving the machine: exit $rc, $(head -c 300 "$err")"; fi
expect_input_error dynamics-machine-stops "the speed would fall to zero" "$(deck_with dyn_stop "$fw" "s/dynamics = 'steady', delta = 0.04/dynamics = 'given', j_flywheel = 0/")"
expect_input_error dynamics-omega-positive "omega1: must be > 0" "$(deck_with dyn_w0 "$fw" "s/omega1 = 7.5 /omega1 = -7.5 /")"
expect_input_error dynamics-per-step-load "two-value form" "$(deck_with dyn_array data/pr3207.nml "s/f5c_work = 3000, f5c_idle = 0/f5c = 13*100, dynamics = 'steady', delta = 0.1/; /phi_cut_/d")"
expect_input_error dynamics-delta-without "need dynamics" "$(deck_with dyn_stray data/pr3207.nml "s/dphi = 30/dphi = 30, delta = 0.1/")"
expect_input_error dynamics-given-delta "is found with dynamics = 'given'" "$(deck_with dyn_gd "$fw" "s/dynamics = 'steady'/dynamics = 'given', j_flywheel = 300/")"

# --- the generic twin gives the same numbers (relative 1e-9)
run_ks "$fw" --format json; cp "$out" "$cli_tmp/twin_a.json"
run_ks data/assur_pr3207_flywheel.nml --format json; cp "$out" "$cli_tmp/twin_b.json"
if run_py - "$cli_tmp/twin_a.json" "$cli_tmp/twin_b.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
def close(x, y, scale): return abs(x - y) <= 1e-9 * max(abs(x), abs(y), scale)
for k, v in a["dynamics"].items():        # the peaks are named by each deck's pairs
    if k in b["dynamics"] and isinstance(v, float):
        assert close(v, b["dynamics"][k], 1e-12), (k, v, b["dynamics"][k])
    elif k in b["dynamics"]:
        assert v == b["dynamics"][k], (k, v, b["dynamics"][k])
assert close(a["dynamics"]["F21_peak"], b["dynamics"]["F21_peak"], 1e-12)
ca, cb = [c["name"] for c in a["columns"]], [c["name"] for c in b["columns"]]
for name in ["phi1", "M1", "J_red", "dJ_red", "M_red", "dT", "omega1", "eps1", "t", "A_Md", "A_red", "T_I"]:
    i, j = ca.index(name), cb.index(name)
    scale = max(abs(r[i]) for r in a["rows"])
    for ra, rb in zip(a["rows"], b["rows"]):
        assert close(ra[i], rb[j], scale), (name, ra[i], rb[j])
PY
then pass; else fail dynamics-generic-twin "data/assur_pr3207_flywheel.nml differs from data/pr3207_flywheel.nml"; fi
expect_input_error dynamics-assur-actuator "no turn to make a cycle of" "$(deck_with dyn_act data/assur_pr3050.nml "s/^\/$/  dynamics = 'steady', delta = 0.05\n\//")"
expect_input_error dynamics-dead-position "dynamics: the cycle at phi1 = 0.000000000 deg: dyad 1 \(RRR, links 2-3\): dead \(toggle\) position" "$(deck_with dyn_dead data/assur_toggle.nml "s/, n = 3//; s/^\/$/  dynamics = 'steady', delta = 0.05\n\//")" 3
expect_input_error dynamics-assur-friction "friction in the pairs" "$(deck_with dyn_fr data/assur_pr3207_flywheel.nml "s/crank_s = 0, 0 /crank_s = 0, 0, crank_f = 0.1, crank_r = 0.02 /")"

# --- --format summary carries the figures of the DYNAMICS block
run_ks "$fw" --format summary
if run_py - "$out" "$cli_tmp/fw.json" <<'PY'
import csv, json, sys
h, v = list(csv.reader(open(sys.argv[1])))
d = json.load(open(sys.argv[2]))["dynamics"]
for k in ["M_d", "J_flywheel", "J_flywheel_textbook", "omega_max", "omega_min", "delta", "F16_peak_difference"]:
    assert abs(float(v[h.index("dyn_" + k)]) - d[k]) <= 1e-12 * abs(d[k]), k
PY
then pass; else fail dynamics-summary "--format summary lacks the dynamics figures: $(head -c 300 "$out")"; fi

# --- the T.FTN six-bar: the reduced quantities; its steady cycle with f5 as a load table
run_ks "$(deck_with six_red data/sixbar.nml "s/^\/$/  dynamics = 'reduced', j_rotor = 0.5\n\//")" --format csv
if [ "$rc" -eq 0 ] && head -1 "$out" | grep -q ",M1,J_red,dJ_red,M_red$" && \
   cmp -s <(cut -d, -f1-15 "$out") data/expected/sixbar.csv; then pass
else fail dynamics-sixbar-reduced "exit $rc, header '$(head -1 "$out")' or the forces changed"; fi
expect_input_error dynamics-sixbar-not-one-turn "exactly one turn" "$(deck_with six_turn data/sixbar_flywheel.nml "s/dphi = 1 /dphi = 1, n = 300 /; s/f5 = 181\*1000, 180\*0/f5 = 150*1000, 150*0/")"
expect_input_error dynamics-sixbar-no-flywheel-needed "no flywheel is needed" "$(deck_with six_nofw data/sixbar_flywheel.nml "s/delta = 0.001/delta = 0.05/")"
run_ks data/sixbar_flywheel.nml --format json; cp "$out" "$cli_tmp/six_a.json"
# the generic twin: data/assur_sixbar.nml at 1 deg over one turn, F5 as a 4-point table over the
# crank angle (the dedicated deck's per-step table, linear between its steps)
six_twin=$(deck_with six_twin data/assur_sixbar.nml "s/dphi = 30, n = 13/dphi = 1, n = 361, dynamics = 'steady', delta = 0.001/; s/, force(1)%column = 1/\n  force(1)%over = 1, force(1)%table = 36.77061636665199, 1000, 216.77061636665199, 1000, 217.77061636665199, 0, 396.77061636665199, 0/; /step_values/d")
run_ks "$six_twin" --format json; cp "$out" "$cli_tmp/six_b.json"
if run_py - "$cli_tmp/six_a.json" "$cli_tmp/six_b.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
def close(x, y, scale): return abs(x - y) <= 1e-9 * max(abs(x), abs(y), scale)
dy = a["dynamics"]
assert abs(dy["delta"] - 0.001) <= 1e-9 * 0.001 and a["selfcheck"]["max_drive_deviation"] <= 1e-9
for k in ["M_d", "J_red_min", "J_red_max", "J_flywheel", "J_flywheel_textbook", "omega_max", "phi_omega_max",
          "omega_min", "phi_omega_min", "delta", "period"]:
    assert close(dy[k], b["dynamics"][k], 1e-12), (k, dy[k], b["dynamics"][k])
ca, cb = [c["name"] for c in a["columns"]], [c["name"] for c in b["columns"]]
for name in ["M1", "J_red", "dJ_red", "M_red", "dT", "omega1", "eps1", "t"]:
    i, j = ca.index(name), cb.index(name)
    scale = max(abs(r[i]) for r in a["rows"])
    for ra, rb in zip(a["rows"], b["rows"]):
        assert close(ra[i], rb[j], scale), (name, ra[i], rb[j])
m, w = ca.index("M1"), ca.index("omega1")
assert all(abs(r[m] - dy["M_d"]) <= 1e-9 * dy["M_d"] for r in a["rows"])
assert abs(a["rows"][0][w] - a["rows"][-1][w]) <= 1e-12 * 100
PY
then pass; else fail dynamics-sixbar-twin "data/sixbar_flywheel.nml: delta, M1 = M_d or its generic twin (from data/assur_sixbar.nml) differ"; fi

# --- PR 3050: the reduced quantities reduced to the cylinder's stroke (mass kg, force N)
run_ks "$(deck_with p50_red data/pr3050.nml "s/^\/$/  dynamics = 'reduced'\n\//")" --format json
if [ "$rc" -eq 0 ] && run_py - "$out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
units = {c["name"]: c["unit"] for c in d["columns"]}
assert units["J_red"] == "kg" and units["dJ_red"] == "kg/m" and units["M_red"] == "N", units
assert any(r["name"] == "REDUCED_TO" and "stroke" in r["value"] for r in d["input"]), "no REDUCED_TO echo"
PY
then pass; else fail dynamics-pr3050-units "exit $rc: the stroke's units or the REDUCED_TO echo missing"; fi
run_ks "$(deck_with p50_csv data/pr3050.nml "s/^\/$/  dynamics = 'reduced'\n\//")" --format csv
if [ "$(head -1 "$out")" = "phi3rel,F14,F14G,F34,F34G,F32,F32G,F2,J_red,dJ_red,M_red" ] && \
   cmp -s <(cut -d, -f1-8 "$out") data/expected/pr3050.csv; then pass
else fail dynamics-pr3050-columns "header '$(head -1 "$out")' or the forces changed"; fi
expect_input_error dynamics-pr3050-steady "PR 3050's input is the cylinder's stroke" "$(deck_with p50_st data/pr3050.nml "s/^\/$/  dynamics = 'steady'\n\//")"
expect_input_error dynamics-pr3050-given "needs a crank" "$(deck_with p50_gv data/pr3050.nml "s/^\/$/  dynamics = 'given'\n\//")"

# --- a driving-moment table (a motor characteristic over the crank angle), scaled to zero net
# work: the dedicated and the generic deck give the same cycle; M1 follows the table
mdt="md_table = 0, 1, 90, 1.5, 180, 1, 270, 0.5"
run_ks "$(deck_with md_a "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, $mdt /")" --format json; cp "$out" "$cli_tmp/md_a.json"
run_ks "$(deck_with md_b data/assur_pr3207_flywheel.nml "s/j_rotor = 0.6 /j_rotor = 0.6, $mdt /")" --format json; cp "$out" "$cli_tmp/md_b.json"
if run_py - "$cli_tmp/md_a.json" "$cli_tmp/md_b.json" "$cli_tmp/fw.json" <<'PY'
import json, math, sys
a, b, c = (json.load(open(f)) for f in sys.argv[1:4])
def close(x, y, scale): return abs(x - y) <= 1e-9 * max(abs(x), abs(y), scale)
da = a["dynamics"]
assert close(da["M_d"], c["dynamics"]["M_d"], 1e-12), "mean differs from the constant M_d"
assert close(da["M_d_max"], 1.5 * da["M_d_scale"], 1) and close(da["M_d_min"], 0.5 * da["M_d_scale"], 1)
assert abs(da["delta"] - 0.04) <= 4e-11 and a["selfcheck"]["max_drive_deviation"] <= 1e-9
for k in ["M_d", "M_d_scale", "J_flywheel", "omega_max", "omega_min", "phi_omega_min", "period"]:
    assert close(da[k], b["dynamics"][k], 1e-12), (k, da[k], b["dynamics"][k])
cols = [x["name"] for x in a["columns"]]
p, m = cols.index("phi1"), cols.index("M1")
for r in a["rows"]:
    phi = r[p] % 360
    i = min(int(phi // 90), 3)
    shape = [1, 1.5, 1, 0.5, 1][i] + ([1, 1.5, 1, 0.5, 1][i + 1] - [1, 1.5, 1, 0.5, 1][i]) * (phi - 90 * i) / 90
    assert close(r[m], shape * da["M_d_scale"], 1), (phi, r[m])
PY
then pass; else fail dynamics-md-table "the driving-moment table: mean, shape, M1 = M_d(phi) or the generic twin differ"; fi
expect_input_error dynamics-md-table-sign "md_table: the table's work" "$(deck_with md_neg "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, md_table = 0, -1, 180, -2 /")"
expect_input_error dynamics-md-table-zero "md_table: the driving-moment table does no net work" "$(deck_with md_zero "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, md_table = 0, 1, 180, -1 /")"
expect_input_error dynamics-md-table-pairs "md_table: give pairs" "$(deck_with md_odd "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, md_table = 0, 1, 180 /")"
expect_input_error dynamics-md-table-order "md_table: the angles must increase" "$(deck_with md_ord "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, md_table = 90, 1, 0, 2 /")"
expect_input_error dynamics-md-table-turn "md_table: the angles must lie within one turn" "$(deck_with md_turn "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, md_table = 0, 1, 360, 2 /")"
expect_input_error dynamics-md-table-mode "md_table: a driving-moment table needs" "$(deck_with md_mode data/pr3207.nml "s/dphi = 30/dphi = 30, md_table = 0, 1, 180, 2/")"

# --- --shaking with a steady cycle: the flywheel's and rotor's couple -(J_fw + j_rotor) eps1 is
# part of M_shake, so d'Alembert's M_frame = M_shake holds for a free machine (no loads, g = 0)
run_ks "$(deck_with sh_free data/assur_pr3207_flywheel.nml "s/g = 9.81, /g = 0, /; s/force(1)%value = 3000/force(1)%value = 0/; s/dynamics = 'steady', delta = 0.04/dynamics = 'given', j_flywheel = 2/")" --shaking --format csv
if [ "$rc" -eq 0 ] && run_py - "$out" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
scale = max(abs(float(r["M_shake"])) for r in rows)
assert scale > 10, scale
worst = max(abs(float(r["M_frame"]) - float(r["M_shake"])) for r in rows)
assert worst <= 1e-9 * scale, (worst, scale)
PY
then pass; else fail dynamics-shaking-flywheel "free machine with a flywheel: M_frame differs from M_shake (exit $rc)"; fi
# the SVG sheet draws M_d(phi) of the table (a dashed curve, not the constant level)
run_ks "$(deck_with md_svg "$fw" "s/j_rotor = 0.6 /j_rotor = 0.6, $mdt /")" --format svg
if [ "$rc" -eq 0 ] && grep -q 'stroke="#333333" stroke-width="0.4" fill="none" stroke-dasharray="2,1"' "$out"; then pass
else fail dynamics-md-table-svg "exit $rc; no dashed M_d(phi) curve on the SVG sheet"; fi

# --- a linear actuator's generic deck reduced to its stroke equals the dedicated PR 3050
run_ks data/assur_pr3050.nml --set "dynamics='reduced'" --format csv; cp "$out" "$cli_tmp/act_generic.csv"
run_ks data/pr3050.nml --set "dynamics='reduced'" --format csv; cp "$out" "$cli_tmp/act_pr3050.csv"
if run_py - "$cli_tmp/act_generic.csv" "$cli_tmp/act_pr3050.csv" <<'PY'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1]))); d = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(d) > 0, (len(a), len(d))
for k, (ra, rd) in enumerate(zip(a, d)):
    for c in ("J_red", "dJ_red", "M_red"):
        x, y = float(ra[c]), float(rd[c])
        if abs(x - y) > 1e-9 * max(abs(y), 1.0):
            sys.exit(f"row {k + 1} {c}: generic {x!r} vs PR 3050 {y!r} (rel 1e-9)")
PY
then pass; else fail dynamics-actuator-stroke "the generic actuator deck's J_red, dJ_red, M_red differ from PR 3050's"; fi
grep -q "REDUCED_TO" <("$KINETOSTAT" data/assur_pr3050.nml --set "dynamics='reduced'" 2>&1) && pass \
  || fail dynamics-actuator-echo "no REDUCED_TO line in the actuator deck's INPUT DATA"
"$KINETOSTAT" data/assur_pr3050.nml --set "dynamics='steady'" --set delta=0.05 >"$cli_tmp/act.out" 2>"$cli_tmp/act.err"
rc=$?
[ "$rc" -eq 2 ] && grep -q "dynamics.*no turn to make a cycle of" "$cli_tmp/act.err" && [ ! -s "$cli_tmp/act.out" ] && pass \
  || fail dynamics-actuator-steady "exit $rc: $(cat "$cli_tmp/act.err")"

# --- delta in (0, 1) is solved on every deck kind (the flywheel found gives back the delta
# asked, the dedicated deck and its generic twin agree), delta >= 1 is refused with one reason
# everywhere (before, delta near 1 or 2 failed erratically or came back as 0.89)
for d in 0.5 0.9 0.99; do
  run_ks "$fw" --set delta=$d --format json; cp "$out" "$cli_tmp/fw_d.json"; rc_a=$rc
  run_ks data/assur_pr3207_flywheel.nml --set delta=$d --format json; cp "$out" "$cli_tmp/twin_d.json"; rc_b=$rc
  # the engine alone runs with delta = 0.978 over its cycle of two turns: a quarter of d needs a flywheel
  run_ks docs/examples/engine.nml --set "dynamics='steady'" --set cycle=720 --set delta="$(run_py -c "print($d / 4)")" --format json
  rc_c=$rc
  if [ "$rc_a$rc_b$rc_c" = 000 ] && run_py - "$cli_tmp/fw_d.json" "$cli_tmp/twin_d.json" "$out" "$d" <<'PY'
import json, sys
a, b, c = (json.load(open(f)) for f in sys.argv[1:4])
for x, d in ((a, float(sys.argv[4])), (b, float(sys.argv[4])), (c, float(sys.argv[4]) / 4)):
    dy = x["dynamics"]
    assert abs(dy["delta"] - d) <= 1e-9 * d, (dy["delta"], d)
    assert abs((dy["omega_max"] - dy["omega_min"]) / dy["omega_mean"] - d) <= 1e-9 * d
    assert x["selfcheck"]["ok"], x["selfcheck"]
fa, fb = a["dynamics"]["J_flywheel"], b["dynamics"]["J_flywheel"]
assert abs(fa - fb) <= 1e-9 * fa, (fa, fb)
PY
  then pass; else fail "dynamics-delta-$d" "exit $rc_a $rc_b $rc_c, or delta not reached: $(head -c 300 "$err")"; fi
done
for d in 1 1.5 1.99 5; do
  for deck in "$fw" data/assur_pr3207_flywheel.nml data/sixbar_flywheel.nml; do
    run_ks "$deck" --set delta=$d
    if [ "$rc" -eq 2 ] && grep -q "^kinetostat: error: $deck: &[a-z0-9]*: delta: must be > 0 and < 1 (got " "$err" && \
       grep -q "(from --set delta=$d)$" "$err"; then pass
    else fail "dynamics-delta-refused-$d" "$deck: exit $rc: $(head -c 300 "$err")"; fi
  done
done
# --- every refusal names the variable and the reason: a kinetic energy beyond the arithmetic's
# range is blamed on the value that makes it so (not "no flywheel gives delta" or "the speed
# would fall to zero")
expect_input_error dynamics-omega-huge "&pr3207: omega1: .*kinetic energy.*out of the range" "$(deck_with dyn_whuge "$fw" "s/omega1 = 7.5 /omega1 = 1e300 /")"
expect_input_error dynamics-rotor-huge "&pr3207: j_rotor: .*kinetic energy.*out of the range" "$(deck_with dyn_rhuge "$fw" "s/j_rotor = 0.6/j_rotor = 1e308/")"
expect_input_error dynamics-flywheel-huge "&pr3207: j_flywheel: .*kinetic energy.*out of the range" "$(deck_with dyn_fhuge "$fw" "s/dynamics = 'steady', delta = 0.04/dynamics = 'given', j_flywheel = 1e308/")"
expect_input_error dynamics-assur-omega-huge "&assur: omega1: .*kinetic energy.*out of the range" "$(deck_with dyn_awhuge data/assur_pr3207_flywheel.nml "s/omega1 = 7.5 /omega1 = 1e300 /")"
expect_input_error dynamics-delta-tiny "&pr3207: delta: 0.1000000000E-13 is below what the arithmetic of the speed resolves" "$(deck_with dyn_dtiny "$fw" "s/delta = 0.04/delta = 1e-14/")"
expect_input_error dynamics-delta-tinier "&pr3207: delta: with the loads' work over the cycle changing the kinetic energy by 617.3523108 J, the flywheel for delta = 0.1000000000E-299 would hold about .*out of the range" "$(deck_with dyn_dtinier "$fw" "s/delta = 0.04/delta = 1e-300/")"
expect_input_error dynamics-loads-huge "&pr3207: delta: with the loads' work over the cycle changing the kinetic energy by 0.2057841036E\+300 J" "$(deck_with dyn_lhuge "$fw" "s/f5c_work = 3000/f5c_work = 1e300/")"
# a geometry error met by the cycle names the dyad, its lengths and the angle, as the plain run
# does (a rod shorter than the crank)
expect_input_error dynamics-cycle-geometry "&assur: dynamics: the cycle at phi1 = [0-9.]+ deg: dyad 1 \(RRP, links 2-3\): cannot be assembled: distance from its joint to the guide [0-9.E-]+ m exceeds l2 = 0.2000000000E-1 m" \
  "$(deck_with dyn_short docs/examples/engine.nml "s/dyad(1)%l2 = 0.2,/dyad(1)%l2 = 0.02,/; s/phi_start = 0, dphi = 15, n = 49/phi_start = 0, dphi = 15, n = 49, dynamics = 'steady', delta = 0.05, cycle = 720/")" 3

# --- a machine whose only inertia is its flywheel (every link massless, j_rotor = 0, J_red = 0):
# J_fw = dE_max / (delta omega_m^2) exactly, checked by its own law: the true motion's delta is
# the delta asked, 1/2 J_fw omega^2 - dT is the same at every step, and J_fw from the largest
# change of kinetic energy (a fine step's dT) over delta omega_m^2
massless=$(deck_with dyn_massless "$fw" "s/m1 = 12, m3 = 22, m5 = 60/m1 = 0, m3 = 0, m5 = 0/; s/j3 = 1.1/j3 = 0/; s/j_rotor = 0.6/j_rotor = 0/")
for d in 0.04 0.5; do
  run_ks "$massless" --set delta=$d --set dphi=0.1 --set n=3601 --format json
  if [ "$rc" -eq 0 ] && run_py - "$out" "$d" <<'PY'
import json, sys
x = json.load(open(sys.argv[1])); d = float(sys.argv[2]); dy = x["dynamics"]
cols = [c["name"] for c in x["columns"]]; rows = x["rows"]
w, dt, jr = cols.index("omega1"), cols.index("dT"), cols.index("J_red")
assert all(r[jr] == 0 for r in rows), "J_red is not 0"
jfw, wm = dy["J_flywheel"], dy["omega_mean"]
# the law of motion with J = J_fw: 1/2 J_fw omega^2 - dT constant (the energy E0)
e = [0.5 * jfw * r[w] ** 2 - r[dt] for r in rows]
assert max(e) - min(e) <= 1e-9 * max(abs(v) for v in e), (min(e), max(e))
# the true motion's delta: from its extremes, and from the steps' omega (0.1 deg apart)
assert abs((dy["omega_max"] - dy["omega_min"]) / wm - d) <= 1e-12 * d, dy
ws = [r[w] for r in rows]
assert abs((max(ws) - min(ws)) / wm - d) <= 1e-5 * d, ((max(ws) - min(ws)) / wm, d)
# J_fw = dE_max / (delta omega_m^2), dE_max from the steps' dT
de = max(r[dt] for r in rows) - min(r[dt] for r in rows)
assert abs(de / (d * wm ** 2) - jfw) <= 1e-5 * jfw, (de / (d * wm ** 2), jfw)
assert x["selfcheck"]["ok"]
PY
  then pass; else fail "dynamics-massless-$d" "exit $rc: $(head -c 300 "$err")"; fi
done
expect_input_error dynamics-phi-start-huge "&pr3207: phi_start: 0.1000000000E\+21 deg is too large" "$(deck_with dyn_phuge "$fw" "s/phi_start = 0/phi_start = 1e20/")"

# --- a cycle of two turns (cycle = 720: the four-stroke engine): checked by its own law at 0.5 deg
# steps (tools/cycle_check.py: M1 = M_d at every step, M_d = -(1/4 pi) of the loads' work over
# both turns, dT closes over 720 deg and is the integral of M_d + M_red, the energy equation,
# (omega_max - omega_min)/omega_m = delta, the second turn's M_red not the first's)
eng=data/assur_engine_flywheel.nml
run_ks "$eng" --set dphi=0.5 --set n=1441 --format json; cp "$out" "$cli_tmp/eng720.json"
if [ "$rc" -eq 0 ] && run_py tools/cycle_check.py "$cli_tmp/eng720.json" 720 0.02 >"$cli_tmp/cycle_check.out" 2>&1; then pass
else fail dynamics-cycle-720-law "exit $rc: $(cat "$cli_tmp/cycle_check.out") $(head -c 300 "$err")"; fi
# the checker must fail on a run whose M_d is not its cycle's (M_d of one turn: 1 % off here)
run_py - "$cli_tmp/eng720.json" "$cli_tmp/eng720_bad.json" <<'PY'
import json, sys
x = json.load(open(sys.argv[1])); x["dynamics"]["M_d"] *= 1.01
json.dump(x, open(sys.argv[2], "w"))
PY
if ! run_py tools/cycle_check.py "$cli_tmp/eng720_bad.json" 720 0.02 >"$cli_tmp/cycle_check.out" 2>&1 && \
   grep -q "max |M1 - M_d|" "$cli_tmp/cycle_check.out"; then pass
else fail dynamics-cycle-720-law-must-fail "a wrong M_d passed: $(cat "$cli_tmp/cycle_check.out")"; fi
# 'given' with the flywheel found gives back delta over the two turns; a driving-moment table
# of constant shape over the cycle of 720 deg is the constant M_d (same flywheel, 1e-9)
jfw=$(run_py -c "import json; print(repr(json.load(open('$cli_tmp/eng720.json'))['dynamics']['J_flywheel']))")
run_ks "$(deck_with eng_given "$eng" "s/dynamics = 'steady', delta = 0.02/dynamics = 'given', j_flywheel = $jfw/")" --format json
if [ "$rc" -eq 0 ] && run_py -c "import json,sys; d=json.load(open(sys.argv[1]))['dynamics']; sys.exit(0 if abs(d['delta']-0.02) <= 1e-9*0.02 else 1)" "$out"
then pass; else fail dynamics-cycle-720-given "exit $rc: $(head -c 300 "$err")"; fi
run_ks "$(deck_with eng_md "$eng" "s/cycle = 720/cycle = 720, md_table = 0, -1, 400, -1/")" --format json
if [ "$rc" -eq 0 ] && run_py - "$out" "$jfw" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))["dynamics"]; jfw = float(sys.argv[2])
assert abs(d["J_flywheel"] - jfw) <= 1e-9 * jfw, (d["J_flywheel"], jfw)
assert abs(d["M_d_scale"] - 38.97702985) <= 1e-6, d["M_d_scale"]
PY
then pass; else fail dynamics-cycle-720-md-table "exit $rc: $(head -c 300 "$err")"; fi
expect_input_error dynamics-cycle-table-longer "&assur: cycle: the steady cycle is one turn \(cycle = 360, the default\) but force\(1\)%table spans 720.0000000 deg of the crank angle: give cycle = 720" \
  "$(deck_with eng_360 "$eng" "s/, cycle = 720//; s/dphi = 5, n = 145/dphi = 5, n = 73/")"
expect_input_error dynamics-cycle-steps "&assur: dphi: the steps must cover exactly the cycle of two turns with cycle = 720: \(n - 1\)\*dphi = 360.0000000 deg, not 720" \
  "$(deck_with eng_73 "$eng" "s/dphi = 5, n = 145/dphi = 5, n = 73/")"
expect_input_error dynamics-cycle-value "&assur: cycle: must be 360 \(one turn\) or 720" "$(deck_with eng_540 "$eng" "s/cycle = 720/cycle = 540/")"
expect_input_error dynamics-cycle-without "&assur: cycle: the cycle of the steady motion needs dynamics = 'steady' or 'given'" \
  "$(deck_with eng_none "$eng" "s/dynamics = 'steady', delta = 0.02, //")"
expect_input_error dynamics-cycle-md-table "&assur: md_table: the angles must lie within one cycle \(last - first < 720" \
  "$(deck_with eng_md2 "$eng" "s/cycle = 720/cycle = 720, md_table = 0, 1, 720, 1/")"
# --- a gas table of 1441 points (every 0.5 deg over 720 deg, the linear interpolant of the
# engine's own table) is read and gives the engine's figures: the steady cycle's M_d and
# flywheel, and every force of the 5 deg steps, within 1e-9
run_py - "$eng" "$cli_tmp/eng1441.nml" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
body = re.search(r"force\(1\)%table = (.*?)\n/", text, re.S).group(1)
nums = [float(v) for v in re.findall(r"-?[0-9.]+", body)]
xs, vs = nums[0::2], nums[1::2]
def at(x):
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            return vs[i] + (vs[i + 1] - vs[i]) * (x - xs[i]) / (xs[i + 1] - xs[i])
pairs = ", ".join(f"{k / 2:g}, {at(k / 2)!r}" for k in range(1441))
open(sys.argv[2], "w").write(re.sub(r"force\(1\)%table = .*?\n/", "force(1)%table = " + pairs + "\n/", text, flags=re.S))
PY
run_ks "$cli_tmp/eng1441.nml" --format json; cp "$out" "$cli_tmp/eng1441.json"; rc_a=$rc
run_ks "$eng" --format json
if [ "$rc_a$rc" = 00 ] && run_py - "$out" "$cli_tmp/eng1441.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for key in ("M_d", "J_flywheel", "omega_min", "phi_omega_min"):
    assert abs(a["dynamics"][key] - b["dynamics"][key]) <= 1e-9 * abs(a["dynamics"][key]), (key, a["dynamics"][key], b["dynamics"][key])
assert [c["name"] for c in a["columns"]] == [c["name"] for c in b["columns"]]
for ra, rb in zip(a["rows"], b["rows"]):
    big = max(abs(v) for v in ra if v is not None)
    for va, vb in zip(ra, rb):
        assert abs(va - vb) <= 1e-9 * big, (ra[0], va, vb)
PY
then pass; else fail dynamics-table-1441-points "exit $rc_a $rc: $(head -c 300 "$err")"; fi

# --- &linkage decks: the machine dynamics of a linkage with one drive. The twin of
# data/pr3207_flywheel.nml in PR 3207's frame, links numbered as PR 3207's: every column both
# have (the forces, M1, the reduced quantities, dT, omega1, eps1, t) within 1e-9 (kinetostat
# diff --common), and the flywheel's figures; the comparison must fail with the ram 1 kg heavier
run_ks data/linkage_pr3207_flywheel.nml --format json; cp "$out" "$cli_tmp/lk_fw.json"; rc_a=$rc
# (the CSV files are the goldens: lib.sh from_golden)
from_golden linkage_pr3207_flywheel csv --format csv; cp "$out" "$cli_tmp/lk_fw.csv"
from_golden pr3207_flywheel csv --format csv; cp "$out" "$cli_tmp/pr_fw.csv"
"$KINETOSTAT" diff --common --rtol 1e-9 --atol 1e-9 "$cli_tmp/pr_fw.csv" "$cli_tmp/lk_fw.csv" >"$cli_tmp/lk_diff.out" 2>&1
if [ "$rc_a" -eq 0 ] && [ $? -eq 0 ] && grep -q "^same: 7942 values agree" "$cli_tmp/lk_diff.out" && \
   run_py - "$cli_tmp/lk_fw.json" "$cli_tmp/fw.json" <<'PY'
import json, sys
a, b = (json.load(open(f))["dynamics"] for f in sys.argv[1:3])
for key in ("M_d", "J_red_max", "J_flywheel", "J_flywheel_textbook", "omega_max", "phi_omega_min", "delta", "period"):
    assert abs(a[key] - b[key]) <= 1e-9 * abs(b[key]), (key, a[key], b[key])
PY
then pass; else fail dynamics-linkage-twin-pr3207 "exit $rc_a: $(head -3 "$cli_tmp/lk_diff.out")"; fi
run_ks data/linkage_pr3207_flywheel.nml --set 'link(5)%m=61' --format csv
if ! "$KINETOSTAT" diff --common --rtol 1e-9 --atol 1e-9 "$cli_tmp/pr_fw.csv" "$out" >"$cli_tmp/lk_diff.out" 2>&1; then pass
else fail dynamics-linkage-twin-must-fail "a 1 kg heavier ram agreed: $(head -3 "$cli_tmp/lk_diff.out")"; fi
# 'reduced' and 'steady' of the four-bar and the slider-crank equal their &assur twins'
for twin in fourbar slider_crank; do
  for mode in reduced steady; do
    set_args=(--set "dynamics='$mode'"); [ "$mode" = steady ] && set_args+=(--set delta=0.05)
    run_ks "data/linkage_$twin.nml" "${set_args[@]}" --format csv; cp "$out" "$cli_tmp/lk_t.csv"; rc_a=$rc
    run_ks "data/assur_$twin.nml" "${set_args[@]}" --format csv --quiet
    if [ "$rc_a$rc" = 00 ] && head -1 "$cli_tmp/lk_t.csv" | grep -q ",J_red,dJ_red,M_red" && \
       "$KINETOSTAT" diff --common --rtol 1e-9 --atol 1e-9 "$out" "$cli_tmp/lk_t.csv" >"$cli_tmp/lk_diff.out" 2>&1; then pass
    else fail "dynamics-linkage-twin-$twin-$mode" "exit $rc_a $rc: $(head -3 "$cli_tmp/lk_diff.out")"; fi
  done
done
# the refusals: one line each, naming the variable
lk=data/linkage_pr3207_flywheel.nml
expect_input_error dynamics-linkage-two-drives "&linkage: drive\(2\): the machine dynamics reduces the machine to one input: a linkage of 2 drives" \
  "$(deck_with lk_five data/fivebar.nml "s|^/$|  dynamics = 'reduced'\n/|")"
expect_input_error dynamics-linkage-sliding-drive "&linkage: dynamics: a sliding drive's stroke goes out and back" \
  "$(deck_with lk_slide data/linkage_slider_crank.nml "s|drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 30, drive(1)%omega = 50|drive(1)%pair = 'D', drive(1)%start = 0, drive(1)%step = 0.001, drive(1)%omega = 1|; s|^/$|  dynamics = 'steady', delta = 0.1\n/|")"
expect_input_error dynamics-linkage-steps "&linkage: drive\(1\)%step: the steps must cover exactly the cycle \(360 deg\)" "$(deck_with lk_n "$lk" "s/n = 361/n = 181/")"
expect_input_error dynamics-linkage-eps "&linkage: drive\(1\)%eps: a steady cycle finds the acceleration" "$(deck_with lk_eps "$lk" "s/drive(1)%omega = 7.5/drive(1)%omega = 7.5, drive(1)%eps = 1/")"
expect_input_error dynamics-linkage-delta "&linkage: delta: must be > 0 and < 1" "$(deck_with lk_d "$lk" "s/delta = 0.04/delta = 2/")"
expect_input_error dynamics-linkage-unknown "&linkage: dynamics: unknown value 'wobbly'" "$(deck_with lk_u "$lk" "s/'steady'/'wobbly'/")"
# the numbers behind the dynamics sheet: A_Md = int M_d dphi and A_red = int M_red dphi from the
# first step (their increments over two 1-deg steps against Simpson's rule over the CSV's M_red
# and M1 = M_d, relative 1e-6 of dT's range; pairs of steps at a load switch or a point of the
# driving-moment table - the angles after the deck - left out), dT = A_Md + A_red, A_Md = M_d (phi - phi0) for a constant M_d and the Simpson
# integral of M1 = M_d(phi) for a driving-moment table, T_I = dT - (J_red - J_c) omega_m^2/2
# (Merzalov, J_c = J_rotor for PR 3207), the textbook flywheel from T_I's range, and the
# flywheel as a steel disc: J = m D^2/8, b = 0.2 D, m = 7800 pi D^2 b/4 (1e-12)
dyn_work_check() {
  local name="$1" jc="$2" skip="$3"; shift 3
  run_ks "$@" --format json
  if [ "$rc" -ne 0 ]; then fail "dynamics-work-$name" "exit $rc: $(head -c 300 "$err")"; return; fi
  run_py - "$out" "$jc" "$skip" <<'PY' && pass || fail "dynamics-work-$name" "A_Md, A_red, T_I or the disc wrong (above)"
import json, math, sys
d = json.load(open(sys.argv[1]))
jc = float(sys.argv[2])
skip = [float(x) for x in sys.argv[3].split(",") if x]
names = [c["name"] for c in d["columns"]]
col = lambda n: [r[names.index(n)] for r in d["rows"]]
assert names[names.index("t") + 1:names.index("t") + 4] == ["A_Md", "A_red", "T_I"], names
phi = [math.radians(x) for x in col("phi1")]
dT, amd, ared, ti = col("dT"), col("A_Md"), col("A_red"), col("T_I")
jred, mred, m1 = col("J_red"), col("M_red"), col("M1")
dyn = d["dynamics"]
h = phi[1] - phi[0]
def simpson(f, k):  # int over rows k .. k + 2
    return h / 3 * (f[k] + 4 * f[k + 1] + f[k + 2])
def at_switch(k):
    return any(abs(((math.degrees(phi[j]) - a) + 180) % 360 - 180) < 1e-6 for j in range(k, k + 3) for a in skip)
scale = max(dT) - min(dT)
const = "M_d_scale" not in dyn
checked = 0
for k in range(0, len(phi) - 2):
    # the CSV's 13 digits of the three
    assert abs(dT[k] - amd[k] - ared[k]) <= 1e-11 * (abs(amd[k]) + abs(ared[k]) + scale), (k, dT[k], amd[k], ared[k])
    if at_switch(k):
        continue
    checked += 1
    s = simpson(mred, k)
    assert abs(ared[k + 2] - ared[k] - s) <= 1e-6 * scale, ("A_red", k, ared[k + 2] - ared[k], s)
    s = simpson(m1, k)
    assert abs(amd[k + 2] - amd[k] - s) <= 1e-6 * scale, ("A_Md vs M1", k, amd[k + 2] - amd[k], s)
assert checked > 0.9 * len(phi), checked
for k in range(len(phi)):
    if const:
        assert abs(amd[k] - dyn["M_d"] * (phi[k] - phi[0])) <= 1e-11 * (abs(amd[k]) + scale), ("A_Md", k, amd[k])
wm = dyn["omega_mean"]
for k in range(len(phi)):
    e = dT[k] - (jred[k] - jc) * wm ** 2 / 2
    assert abs(ti[k] - e) <= 1e-11 * (abs(dT[k]) + abs(jred[k]) * wm ** 2), ("T_I", k, ti[k], e)
jt = (max(ti) - min(ti)) / (dyn["delta_asked"] * wm ** 2) - jc
assert abs(jt - dyn["J_flywheel_textbook"]) <= 2e-3 * dyn["J_flywheel_textbook"], (jt, dyn["J_flywheel_textbook"])
J, D, b, m = dyn["J_flywheel"], dyn["flywheel_D"], dyn["flywheel_b"], dyn["flywheel_m"]
rho, psi = dyn["flywheel_density"], dyn["flywheel_width_ratio"]
assert abs(m * D ** 2 / 8 - J) <= 1e-12 * J and abs(b - psi * D) <= 1e-12 * D
assert abs(m - rho * math.pi * D ** 2 * b / 4) <= 1e-12 * m
assert abs(D - (32 * J / (math.pi * rho * psi)) ** 0.2) <= 1e-12 * D
PY
}
dyn_work_check pr3207 0.6 95,265 data/pr3207_flywheel.nml
dyn_work_check pr3207-md-table 0.6 0,90,95,180,265,270 data/pr3207_flywheel.nml --set "md_table=0,1,90,1.5,180,1,270,0.5"
dyn_work_check pr3207-aluminium 0.6 95,265 data/pr3207_flywheel.nml --set flywheel_density=2700 --set flywheel_width_ratio=0.1
dyn_work_check sixbar 20 216.77061636665199,217.77061636665199,36.77061636665199 data/sixbar_flywheel.nml
# with no flywheel the disc is null and the note says so; the summary's columns stay the same
sed "s/dynamics = 'steady', delta = 0.001/dynamics = 'given', j_flywheel = 0/" data/sixbar_flywheel.nml > "$cli_tmp/dyn_nofw.nml"
run_ks "$cli_tmp/dyn_nofw.nml" --format json
run_py - "$out" <<'PY' && pass || fail dynamics-disc-null "the disc of no flywheel is not null with a note"
import json, sys
d = json.load(open(sys.argv[1]))["dynamics"]
assert d["J_flywheel"] == 0 and d["flywheel_D"] is None and d["flywheel_b"] is None and d["flywheel_m"] is None
assert d["flywheel_note"].startswith("no flywheel"), d["flywheel_note"]
PY
run_ks "$cli_tmp/dyn_nofw.nml" --format summary; head -1 "$out" | tr , '\n' | grep flywheel > "$cli_tmp/dyn_nofw.head"
sed "s/dynamics = 'steady', delta = 0.001/dynamics = 'given', j_flywheel = 50/" data/sixbar_flywheel.nml > "$cli_tmp/dyn_fw50.nml"
run_ks "$cli_tmp/dyn_fw50.nml" --format summary
if head -1 "$out" | tr , '\n' | grep flywheel | cmp -s - "$cli_tmp/dyn_nofw.head" && grep -q "dyn_flywheel_D" "$cli_tmp/dyn_nofw.head" \
  && ! grep -q "flywheel_note" "$cli_tmp/dyn_nofw.head"; then pass
else fail dynamics-disc-summary "the summary's flywheel columns differ with and without a flywheel"; fi
run_ks "$cli_tmp/dyn_nofw.nml" --lang ru
if grep -q "МАХОВИК: ДИАМЕТР D *= НЕТ" "$out"; then pass; else fail dynamics-disc-ru "no 'НЕТ' for the disc in Russian"; fi
expect_input_error dynamics-disc-density "&pr3207: flywheel_density: must be > 0" \
  "$(deck_with dyn_rho "$fw" "s/delta = 0.04/delta = 0.04, flywheel_density = -1/")"
expect_input_error dynamics-disc-ratio "&pr3207: flywheel_width_ratio: must be > 0 and <= 10" \
  "$(deck_with dyn_psi "$fw" "s/delta = 0.04/delta = 0.04, flywheel_width_ratio = 0/")"
expect_input_error dynamics-disc-without-cycle "&pr3207: flywheel_density: .*need dynamics = 'steady' or 'given'" \
  "$(deck_with dyn_rho2 data/pr3207.nml "s/omega1 = 7.5/omega1 = 7.5, flywheel_density = 7800/")"
