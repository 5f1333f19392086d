# Command-line tests of friction in the pairs of the generic engine (sourced by
# tools/test with test/cli/lib.sh).

fr_deck=data/friction_slider_crank.nml

# --- the friction slider-crank: golden outputs, CSV columns, footer
run_ks "$fr_deck" --format csv; cp "$out" "$cli_tmp/friction.csv"
[ "$rc" -eq 0 ] && pass || fail friction-csv-exit "exit $rc: $(cat "$err")"
expect_same friction-golden-csv data/expected/friction_slider_crank.csv "$cli_tmp/friction.csv"
header="$(head -1 "$cli_tmp/friction.csv")"
case ",$header," in
  *,phi1,*,M1,*,P_loss,*) pass ;;
  *) fail friction-csv-columns "header lacks phi1, M1, P_loss: $header" ;;
esac
if [ "$(wc -l <"$cli_tmp/friction.csv")" -eq 38 ]; then pass; else fail friction-csv-rows "expected 37 steps"; fi
# P_loss >= 0 and M1 > M1_0 (omega1 > 0) on every row
awk -F, 'NR==1{for(i=1;i<=NF;i++) c[$i]=i; next}
  { if ($c["P_loss"] < 0 || !($c["M1"] - $c["M1_0"] > 0)) { print "row " NR ": P_loss " $c["P_loss"] ", M1 " $c["M1"] ", M1_0 " $c["M1_0"]; bad=1 } }
  END{exit bad}' "$cli_tmp/friction.csv" >"$cli_tmp/friction_rows.log" && pass ||
  fail friction-csv-ploss-and-m1-sign "$(head -5 "$cli_tmp/friction_rows.log")"
run_ks "$fr_deck"; cp "$out" "$cli_tmp/friction.table"
expect_same friction-golden-table data/expected/friction_slider_crank.table "$cli_tmp/friction.table"
expect_no_nan friction-table-no-nan "$cli_tmp/friction.table"
grep -q "^   ETA = 1 - A_LOSS/A_DRIVER OVER A WHOLE TURN OF THE INPUT: THE CYCLE EFFICIENCY$" "$cli_tmp/friction.table" && pass ||
  fail friction-table-cycle-line "no cycle-efficiency line in the footer"
grep -Eq "^   MAX M1 MISMATCH, POWER BALANCE WITH FRICTION +[0-9.E+-]+  OK$" "$cli_tmp/friction.table" && pass ||
  fail friction-table-power-balance "no OK power balance line with friction"
# a partial run says that its efficiency is not the cycle efficiency
run_ks "$(deck_with fr_half "$fr_deck" 's/phi_start = 0, dphi = 10 /phi_start = 180, dphi = 10, n = 19/')"
[ "$rc" -eq 0 ] && grep -q "LESS THAN A WHOLE TURN: NOT THE CYCLE EFFICIENCY" "$out" && pass ||
  fail friction-partial-run-note "exit $rc, or no partial-run note: $(tail -8 "$out")"
run_ks "$fr_deck" --format json
run_py -c 'import json,sys; d=json.load(open(sys.argv[1])); s={r.get("name"): r.get("value") for r in d["summary"]};
assert s["A_DRIVER"] > 0 and abs(s["ETA"]) < 1e-9, s' "$out" 2>"$cli_tmp/json.log" && pass ||
  fail friction-json-summary "$(tail -3 "$cli_tmp/json.log")"

# --- all coefficients 0: the frictionless outputs, byte for byte (CSV; table but for the deck line)
zero="$(deck_with fr_zero data/assur_slider_crank.nml 's|^/$|  crank_f = 0, crank_r = 0.01, dyad(1)%f2 = 0, dyad(1)%r2 = 0.01, dyad(1)%f23 = 0\n  dyad(1)%f3 = 0, dyad(1)%guide3 = 0.3, dyad(1)%block3 = 0.05\n/|')"
grep -q "crank_f = 0" "$zero" && pass || fail friction-zero-deck "sed did not add the variables"
run_ks "$zero" --format csv
cmp -s "$out" data/expected/assur_slider_crank.csv && pass || fail friction-zero-csv-identical "CSV differs from the frictionless golden"
run_ks "$zero"
sed "s|^ DECK: .*| DECK: data/assur_slider_crank.nml|" "$out" >"$cli_tmp/fr_zero.table"
cmp -s "$cli_tmp/fr_zero.table" data/expected/assur_slider_crank.table && pass ||
  fail friction-zero-table-identical "table differs from the frictionless golden: $(diff "$cli_tmp/fr_zero.table" data/expected/assur_slider_crank.table | head -5)"
for d in pr3207 sixbar; do
  run_ks "$(deck_with "fr_zero_$d" "data/assur_$d.nml" 's|^/$|  crank_f = 0, dyad(1)%f2 = 0, dyad(2)%f3 = 0\n/|')" --format csv
  cmp -s "$out" "data/expected/assur_$d.csv" && pass || fail "friction-zero-$d-csv-identical" "CSV differs from the golden"
done

# --- failures: jamming (no convergence) and self-locking at rest are exit 3 naming step, angle, pair
expect_input_error friction-jamming-exit3 'step [0-9]+ \(phi1 = [0-9.]+ deg\): friction: .*not converge.* pair F[0-9]+' \
  "$(deck_with fr_jam "$fr_deck" 's/dyad(1)%f3 = 0.15/dyad(1)%f3 = 20/')" 3
expect_input_error friction-self-locking-exit3 'step 19 \(phi1 = 180[.0]* deg\): friction: self-locking .* pair F[0-9]+' \
  "$(deck_with fr_lock "$fr_deck" 's/omega1 = 100 /omega1 = 0 /')" 3

# --- deck errors: exit 2 naming the variable
expect_input_error friction-negative-f 'crank_f: must be >= 0' "$(deck_with fr_neg_f "$fr_deck" 's/crank_f = 0.1/crank_f = -0.1/')"
expect_input_error friction-negative-r 'dyad\(1\)%r23: must be >= 0' \
  "$(deck_with fr_neg_r "$fr_deck" 's/dyad(1)%r23 = 0.01/dyad(1)%r23 = -0.01/')"
expect_input_error friction-negative-f3 'dyad\(1\)%f3: must be >= 0' "$(deck_with fr_neg_f3 "$fr_deck" 's/dyad(1)%f3 = 0.15/dyad(1)%f3 = -0.15/')"
expect_input_error friction-negative-block 'dyad\(1\)%block3: must be >= 0' \
  "$(deck_with fr_neg_b "$fr_deck" 's/dyad(1)%f3 = 0.15/dyad(1)%f3 = 0.15, dyad(1)%block3 = -0.05/')"
expect_input_error friction-radius-on-slide 'dyad\(1\)%r3: not used by this pair \(a sliding pair' \
  "$(deck_with fr_r3 "$fr_deck" 's/dyad(1)%f3 = 0.15/dyad(1)%f3 = 0.15, dyad(1)%r3 = 0.01/')"
expect_input_error friction-guide-on-pin 'dyad\(1\)%guide2: not used by this pair \(a turning pair' \
  "$(deck_with fr_g2 "$fr_deck" 's/dyad(1)%f2 = 0.1,/dyad(1)%f2 = 0.1, dyad(1)%guide2 = 0.1,/')"
expect_input_error friction-no-radius 'crank_r: the journal radius must be > 0' \
  "$(deck_with fr_r0 "$fr_deck" 's/crank_r = 0.01/crank_r = 0/')"
expect_input_error friction-infinite-f 'dyad\(1\)%f2: must be a finite number' \
  "$(deck_with fr_inf "$fr_deck" 's/dyad(1)%f2 = 0.1,/dyad(1)%f2 = Inf,/')"

# --- a sliding pair's reported reaction is the whole reaction (normal + friction force), its
# normal part the F30N column: on every step of the friction slider-crank (--kinematics CSV)
# the slider's force balance closes with F30 (F30 - F23 + 500 N along -x + G3 - m3*a_S3 = 0,
# relative to the 500 N load, limit 1e-9), |F30| = |F30N|*sqrt(1 + f^2) (f = 0.15, limit
# 1e-12 relative) and the friction part F30x opposes the slider's motion (the sign of
# dx_S3/dphi1 from the neighbouring steps). With the normal force alone the balance misses
# f*|N| (up to 19 N).
run_ks "$fr_deck" --format csv --kinematics
run_py - "$out" >"$cli_tmp/fr_whole.log" 2>&1 <<'PY' && pass || fail friction-whole-reaction "$(head -5 "$cli_tmp/fr_whole.log")"
import csv, math, sys
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
m3, g, f, load = 1.5, 9.81, 0.15, 500.0
bad = []
for k, r in enumerate(rows):
    rx = r["F30_x"] - r["F23_x"] - load - m3 * r["ax_S3"]
    ry = r["F30_y"] - r["F23_y"] - m3 * g - m3 * r["ay_S3"]
    if math.hypot(rx, ry) > 1e-9 * load:
        bad.append("step %d: slider balance off by %.3e N" % (k + 1, math.hypot(rx, ry)))
    whole = abs(r["F30N"]) * math.sqrt(1 + f * f)
    if 0 < k < len(rows) - 1:
        dx = rows[k + 1]["x_S3"] - rows[k - 1]["x_S3"]
        if abs(dx) > 1e-9 and abs(r["F30"] - whole) > 1e-12 * whole:
            bad.append("step %d: |F30| %.12g vs |F30N|*sqrt(1+f^2) %.12g" % (k + 1, r["F30"], whole))
        if abs(dx) > 1e-9 and r["F30_x"] * dx > 0:
            bad.append("step %d: F30x %.6g does not oppose the sliding (dx %.3g)" % (k + 1, r["F30_x"], dx))
print("\n".join(bad) or "ok")
sys.exit(1 if bad else 0)
PY

# &linkage friction: the twin of data/friction_slider_crank.nml agrees in every column both
# have (M1, M1_0, P_loss_<pair>, P_loss, eta, the forces) within 1e-9
run_ks data/linkage_friction_slider_crank.nml --format csv; cp "$out" "$cli_tmp/lf_l.csv"; rc_l=$rc
run_ks data/friction_slider_crank.nml --format csv; cp "$out" "$cli_tmp/lf_a.csv"
run_ks diff --common --rtol 1e-9 --atol 1e-9 "$cli_tmp/lf_a.csv" "$cli_tmp/lf_l.csv"
if [ "$rc_l$rc" = 00 ] && grep -q "^same: [0-9]* values agree" "$out" && head -1 "$cli_tmp/lf_l.csv" | grep -q "M1,M1_0,P_loss_F21,P_loss_F23,P_loss_F30,P_loss_F10,P_loss,eta_defined,eta"; then pass
else fail linkage-friction-twin "exit $rc_l/$rc: $(head -c 300 "$out") $(head -c 300 "$err")"; fi
# friction on the class-III deck by the power balance at every step: M1*omega1 = the power the
# loads absorb (gravity, the force, the moment, inertia: dT/dt) + sum P_loss, within 1e-9 of the
# step's largest term; the same check with one pair's loss left out must fail
fr_set=""
for k in 1 2 3 4 5 6 7; do fr_set="$fr_set --set pair($k)%f=0.15 --set pair($k)%r=0.02"; done
run_ks data/class3.nml --kinematics --format csv $fr_set; cp "$out" "$cli_tmp/c3f.csv"; rc_c=$rc
cat >"$cli_tmp/c3_balance.py" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
drop = sys.argv[2] if len(sys.argv) > 2 else ""
m = {1: 2, 2: 3, 3: 2, 4: 2, 5: 5}; J = {1: 0.010, 2: 0.040, 3: 0.020, 4: 0.020, 5: 0.050}
losses = [c for c in rows[0] if c.startswith("P_loss_")]
assert len(losses) == 7, losses
d = (math.cos(math.radians(-120)), math.sin(math.radians(-120)))
worst = 0.0
for r in rows:
    f = lambda c: float(r[c])
    p_in = f("M1") * f("omega1")
    terms = [abs(p_in)]
    p_abs = 0.0
    for i in m:
        v = (f(f"vx_S{i}"), f(f"vy_S{i}")); a = (f(f"ax_S{i}"), f(f"ay_S{i}"))
        grav = -m[i] * 9.81 * v[1]
        kin = m[i] * (a[0] * v[0] + a[1] * v[1]) + J[i] * f(f"eps{i}") * f(f"omega{i}")
        p_abs += -grav + kin
        terms += [abs(grav), abs(kin)]
    pf = 200 * (d[0] * f("vx_T2") + d[1] * f("vy_T2")); pm = -30 * f("omega3")
    p_abs += -pf - pm
    loss = sum(f(c) for c in losses if c != drop)
    assert abs(f("P_loss") - sum(f(c) for c in losses)) <= 1e-9 * max(1, f("P_loss"))
    terms += [abs(pf), abs(pm), loss]
    worst = max(worst, abs(p_in - p_abs - loss) / max(terms))
print("worst power-balance mismatch", worst)
sys.exit(0 if worst <= 1e-9 else 1)
PY
if [ "$rc_c" -eq 0 ] && run_py "$cli_tmp/c3_balance.py" "$cli_tmp/c3f.csv" >"$cli_tmp/c3.out" 2>&1; then pass
else fail linkage-friction-class3-power "exit $rc_c: $(cat "$cli_tmp/c3.out") $(head -c 300 "$err")"; fi
if ! run_py "$cli_tmp/c3_balance.py" "$cli_tmp/c3f.csv" P_loss_F53 >"$cli_tmp/c3.out" 2>&1 && \
   grep -q "^worst power-balance mismatch" "$cli_tmp/c3.out"; then pass
else fail linkage-friction-class3-power-can-fail "$(cat "$cli_tmp/c3.out")"; fi
# a turning pair's friction needs its journal radius; a sliding pair has none
run_ks data/class3.nml --set 'pair(2)%f=0.1'
[ "$rc" -eq 2 ] && grep -q "&linkage: pair(2)%r: must be > 0 with friction" "$err" && pass \
  || fail linkage-friction-needs-r "exit $rc: $(cat "$err")"
run_ks data/linkage_friction_slider_crank.nml --set 'pair(3)%r=0.01'
[ "$rc" -eq 2 ] && grep -q "&linkage: pair(3)%r: not used by this pair" "$err" && pass \
  || fail linkage-friction-r-on-p "exit $rc: $(cat "$err")"
