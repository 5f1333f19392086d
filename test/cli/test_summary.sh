# Summaries and sweeps: --format summary, the legacy table's
# SUMMARY block, the coarse-step warning, kinetostat sweep.

# --- --format summary: every figure recomputed from the run's own CSV (max, min, the input
# angle of each, the mean over the input angle, the work of M1 over the input angle in rad)
for deck in data/pr3207.nml data/assur_slider_crank.nml data/sixbar.nml data/pr3050.nml data/cam_flat.nml \
            data/gears_reducer.nml; do
  name=$(basename "$deck" .nml)
  run_ks "$deck" --format csv --quiet; cp "$out" "$cli_tmp/sum_$name.csv"
  run_ks "$deck" --format summary --quiet; cp "$out" "$cli_tmp/sum_$name.summary"
  run_py - "$cli_tmp/sum_$name.csv" "$cli_tmp/sum_$name.summary" "$name" <<'PY' && pass || fail "summary-recomputed-$name" "see above"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
summary = list(csv.DictReader(open(sys.argv[2])))
name = sys.argv[3]
assert len(summary) == 1, "expected one summary row"
s = summary[0]
cols = list(rows[0].keys())
has_input = name not in ("gears_reducer",)
x = [float(r[cols[0]]) for r in rows] if has_input else None
def close(a, b, what):
    if abs(a - b) > 1e-11 * max(1.0, abs(b)):
        print(f"{name} {what}: summary {a!r} vs recomputed {b!r}"); sys.exit(1)
assert int(s["rows"]) == len(rows)
checked = 0
for c in cols[1:] if has_input else cols:
    if c + "_max" not in s:
        continue
    v = [float(r[c]) for r in rows]
    tie = 1e-12 * max(abs(t) for t in v)  # first row within 1e-12 of the largest magnitude
    kmax = next(k for k in range(len(v)) if v[k] >= max(v) - tie)
    kmin = next(k for k in range(len(v)) if v[k] <= min(v) + tie)
    close(float(s[c + "_max"]), v[kmax], c + "_max"); close(float(s[c + "_min"]), v[kmin], c + "_min")
    at = (lambda k: x[k]) if has_input else (lambda k: k + 1)
    close(float(s[c + "_max_at"]), at(kmax), c + "_max_at"); close(float(s[c + "_min_at"]), at(kmin), c + "_min_at")
    if has_input and x[-1] != x[0]:
        mean = sum((v[k] + v[k + 1]) / 2 * (x[k + 1] - x[k]) for k in range(len(v) - 1)) / (x[-1] - x[0])
    else:
        mean = sum(v) / len(v)
    close(float(s[c + "_mean"]), mean, c + "_mean")
    checked += 1
assert checked >= 4, f"only {checked} columns summarized"
# force angles are not summarized (directions modulo 360 deg)
assert not any(k.endswith("G_max") for k in s), "a force angle column was summarized"
if "M1" in cols and has_input:
    m = [float(r["M1"]) for r in rows]
    work = sum((m[k] + m[k + 1]) / 2 * math.radians(x[k + 1] - x[k]) for k in range(len(m) - 1))
    close(float(s["work_M1"]), work, "work_M1")
    close(float(s["M1_mean"]) * math.radians(x[-1] - x[0]), float(s["work_M1"]), "M1_mean * span = work_M1")
elif name == "pr3050":
    assert "work_F2" in s, "pr3050 has no work of F2"
else:
    assert not any(k.startswith("work_") for k in s), "work for a mechanism without a driving coordinate"
PY
done

# --- the work per cycle is the energy the loads take: offset slider-crank, a force R on the
# slider along -x, 500 N for crank angles 0..180 deg and 100 N elsewhere. Over a turn at
# constant speed gravity and inertia give back what they take, so the drive's work W(M1)
# balances the force's work, integral -R dx: W(M1) = integral R(phi) dx(phi) (geometry from
# the deck: crank 0.1 m, rod 0.35 m, guide y = 0.02 m). Here W < 0: from 0 to 180 deg the
# slider moves along -x with the larger force, which then drives. dphi = 0.05 deg: the
# trapezoid's error at the two load steps is below 1e-3 of W.
run_ks data/assur_slider_crank.nml --set dphi=0.05 --format summary --quiet
run_py - "$out" <<'PY' && pass || fail summary-work-energy "work of M1 is not the resistance's energy"
import csv, math, sys
s = next(csv.DictReader(open(sys.argv[1])))
r, l, e = 0.1, 0.35, 0.02
def x(p):
    yb = r * math.sin(p)
    return r * math.cos(p) + math.sqrt(l * l - (e - yb) ** 2)
# integral R dx with R constant on each half turn: R times the slider's travel over it
w = 500.0 * (x(math.pi) - x(0.0)) + 100.0 * (x(2 * math.pi) - x(math.pi))
work = float(s["work_M1"])
print("work_M1", work, "expected", w)
assert abs(work - w) <= 1e-3 * abs(w), (work, w)
PY

# --- overrides come first in the summary, as given (a value with a comma quoted)
run_ks data/pr3207.nml --set l_ab=0.12 --set 'f5c_work = 2500' --format summary --quiet
head -1 "$out" | grep -q '^l_ab,f5c_work,rows,phi1_first,phi1_last,F16_max,F16_max_at,F16_min,F16_min_at,F16_mean,' \
  && sed -n 2p "$out" | grep -q '^0.12,2500,13,' && pass || fail summary-overrides "$(head -c 300 "$out")"
run_ks data/sixbar.nml --set 'f5=2*900, 5*1000, 6*0' --format summary --quiet
sed -n 2p "$out" | grep -q '^"2\*900, 5\*1000, 6\*0",13,' && pass || fail summary-csv-quoting "$(sed -n 2p "$out" | head -c 100)"

# --- the legacy table's SUMMARY block carries the same figures
run_ks data/pr3207.nml --quiet
grep -q '^ SUMMARY (PHI1 0.00 ... 360.00 deg)$' "$out" \
  && grep -q '^   F16 MAX         =   5.342165581E+03  N    AT PHI1 =   120.00 deg$' "$out" \
  && grep -q '^   M1 MIN          =  -2.257429062E+02  N\*m  AT PHI1 =    30.00 deg$' "$out" \
  && grep -q '^   WORK OF M1      =   1.095725074E+03  J$' "$out" && pass || fail summary-table-block "$(grep -A10 '^ SUMMARY' "$out")"
run_ks data/pr3207.nml --format summary --quiet
run_py -c 'import csv,sys; s=next(csv.DictReader(open(sys.argv[1]))); assert "%.9E" % float(s["F16_max"]) == "5.342165581E+03" and float(s["F16_max_at"]) == 120' "$out" \
  && pass || fail summary-table-equals-csv "the block and the summary disagree"
# no block without an input angle (the gears' stages)
run_ks data/gears_reducer.nml
if [ "$rc" -ne 0 ] || [ ! -s "$out" ]; then fail summary-no-block-gears "rc=$rc: $(head -c 300 "$err")"
elif grep -q 'SUMMARY' "$out"; then fail summary-no-block-gears "gears table has a SUMMARY block"
else pass; fi

# --- the coarse-step warning: dphi above 5 deg with a load switching next to a force peak
run_ks data/pr3207.nml --format csv
grep -q '^kinetostat: warning: data/pr3207.nml: the input step 30 deg is coarser than 5 deg and a load switches on or off within one step of the peak of F16.*(the peak of F16 = 5342.17 N at phi1 = 120 deg, the load switches between phi1 = 90 deg and phi1 = 120 deg).*--set dphi=0.5' "$err" \
  && pass || fail coarse-warning-text "$(cat "$err")"
expect_exit coarse-warning-strict 4 data/pr3207.nml --strict
expect_exit coarse-warning-quiet-strict 4 data/pr3207.nml --strict --quiet
run_ks data/pr3207.nml --set dphi=5 --strict
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail coarse-warning-5-deg "5 deg is not coarser than 5 deg: rc=$rc $(cat "$err")"
# no switching load: no warning however coarse (the engine's gas force is a curve)
run_ks data/pr3207.nml --set f5c_work=0 --strict
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail coarse-warning-no-switch "rc=$rc $(cat "$err")"
# the 30 deg step misses the peak: F16's true peak (dphi = 0.5) is higher
run_ks data/pr3207.nml --set dphi=0.5 --format summary --quiet; cp "$out" "$cli_tmp/fine.summary"
run_ks data/pr3207.nml --format summary --quiet
run_py - "$out" "$cli_tmp/fine.summary" <<'PY' && pass || fail coarse-peak-missed "the fine run's F16 peak is not above the coarse one"
import csv, sys
coarse = float(next(csv.DictReader(open(sys.argv[1])))["F16_max"])
fine = next(csv.DictReader(open(sys.argv[2])))
assert float(fine["F16_max"]) > 1.1 * coarse and float(fine["F16_max_at"]) == 95.0, (coarse, fine["F16_max"])
PY

# --- the table-peak warning: a load table's local extreme strictly between two steps, the load
# there more than 5 % of the table's range from both steps' values. The engine's gas force peaks
# at 375 deg: at 30 deg steps (360, 390) the steps miss it, and the rod force's peak with it
# (F21: 10355 N against 17450 N at 0.5 deg, 41 % low)
run_ks docs/examples/engine.nml --set dphi=30 --set n=25 --format csv
[ "$rc" -eq 0 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "^kinetostat: warning: docs/examples/engine.nml: force(1)%table: its point at phi1 = 375 deg (27143 N, a local maximum) lies between the steps at phi1 = 360 deg and phi1 = 390 deg, where the load is 8282 N and 17019 N: the steps miss the load's peak and the forces it causes; rerun with a finer step (e.g. --set dphi=0.5) or put a step on the point$" "$err" \
  && pass || fail table-peak-warning-text "rc=$rc $(cat "$err")"
run_ks docs/examples/engine.nml --set dphi=30 --set n=25 --format json --quiet
run_py -c "import json,sys; w=json.load(open(sys.argv[1]))['warnings']; sys.exit(0 if len(w) == 1 and 'force(1)%table: its point at phi1 = 375 deg' in str(w[0]) else 1)" "$out" \
  && pass || fail table-peak-warning-json "$(head -c 300 "$out")"
expect_exit table-peak-warning-strict 4 docs/examples/engine.nml --set dphi=30 --set n=25 --strict --quiet
run_ks docs/examples/engine.nml --set dphi=30 --set n=25 --format summary --quiet; cp "$out" "$cli_tmp/eng30.summary"
run_ks docs/examples/engine.nml --set dphi=0.5 --set n=1441 --format summary --strict; cp "$out" "$cli_tmp/eng05.summary"
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && run_py - "$cli_tmp/eng30.summary" "$cli_tmp/eng05.summary" <<'PY' && pass || fail table-peak-missed "rc=$rc $(cat "$err")"
import csv, sys
coarse, fine = (float(next(csv.DictReader(open(f)))["F21_max"]) for f in sys.argv[1:3])
assert abs(coarse - 10355.0) < 1 and abs(fine - 17450.0) < 1 and 0.40 < 1 - coarse / fine < 0.42, (coarse, fine)
PY
# a step on the point (15 deg: 375 is a step), or steps close enough (2 deg: 374 and 376, the
# load there within 5 % of the range of the peak), or a table without an extreme between two
# steps: no warning
for set in "dphi=15" "dphi=2 --set n=361" "dphi=7.5 --set n=97"; do
  run_ks docs/examples/engine.nml --set $set --strict --quiet --format csv
  [ "$rc" -eq 0 ] && pass || fail "table-peak-no-warning-$set" "rc=$rc"
done
# the warning names a table over a link's position with that link (the piston's stroke)
run_ks "$(deck_with stroke_table docs/examples/engine.nml "s/force(1)%over = 1/force(1)%over = 3/; /force(1)%table/,/720, -50/c\\  force(1)%table = 0.15, 0, 0.17, 100, 0.181, 5000, 0.19, 100, 0.25, 0")" --set dphi=30 --set n=25 --format csv
grep -q "^kinetostat: warning: .*: force(1)%table: its point at the stroke of link 3 = 0.18 m (5000 N, a local maximum) lies between the steps at phi1 = " "$err" \
  && pass || fail table-peak-warning-stroke "rc=$rc $(cat "$err")"

# --- sweep: one row per variant in grid order, each equal to the single run with --set
run_ks sweep data/pr3207.nml --vary l_ab=0.08:0.14:4 --vary m5=50:70:3 --quiet
cp "$out" "$cli_tmp/sweep.csv"
[ "$rc" -eq 0 ] && [ "$(wc -l <"$cli_tmp/sweep.csv")" -eq 13 ] && pass || fail sweep-rows "rc=$rc, $(wc -l <"$cli_tmp/sweep.csv") lines"
cut -d, -f1,2 "$cli_tmp/sweep.csv" | tr '\n' ' ' | grep -q '^l_ab,m5 0.08,50 0.08,60 0.08,70 0.1,50 0.1,60 0.1,70 0.12,50 0.12,60 0.12,70 0.14,50 0.14,60 0.14,70 $' \
  && pass || fail sweep-grid-order "$(cut -d, -f1,2 "$cli_tmp/sweep.csv" | tr '\n' ' ')"
bad=0
for line in 2 7 13; do
  vals=$(sed -n "${line}p" "$cli_tmp/sweep.csv" | cut -d, -f1,2)
  "$KINETOSTAT" data/pr3207.nml --set "l_ab=${vals%,*}" --set "m5=${vals#*,}" --format summary --quiet >"$cli_tmp/single.csv"
  { head -1 "$cli_tmp/sweep.csv"; sed -n "${line}p" "$cli_tmp/sweep.csv"; } | cmp -s - "$cli_tmp/single.csv" || bad=1
done
[ "$bad" -eq 0 ] && pass || fail sweep-equals-single "a sweep row differs from the single run with --set"
# --set applies to every variant and comes first
run_ks sweep data/assur_slider_crank.nml --set dphi=10 --vary 'dyad(1)%l2=0.3:0.4:2' --quiet
sed -n 1,3p "$out" | cut -d, -f1-3 | tr '\n' ' ' | grep -q '^dphi,dyad(1)%l2,rows 10,0.3,37 10,0.4,37 $' \
  && pass || fail sweep-set-and-member "$(sed -n 1,3p "$out" | cut -d, -f1-3)"
# --part K/N: the parts concatenated in order are the whole sweep, byte for byte
for k in 1 2 3 4 5; do
  "$KINETOSTAT" sweep data/pr3207.nml --vary l_ab=0.08:0.14:4 --vary m5=50:70:3 --quiet --part "$k/5" -o "$cli_tmp/part$k.csv"
done
cat "$cli_tmp"/part{1,2,3,4,5}.csv | cmp -s - "$cli_tmp/sweep.csv" && pass || fail sweep-parts "parts do not concatenate to the sweep"
# warnings name the variant; --strict exits 4
run_ks sweep data/pr3207.nml --vary l_ab=0.1:0.12:2
[ "$rc" -eq 0 ] && [ "$(grep -c '^kinetostat: warning: data/pr3207.nml (l_ab=0.1): the input step 30 deg' "$err")" -eq 1 ] \
  && pass || fail sweep-warning-names-variant "$(head -c 300 "$err")"
expect_exit sweep-strict 4 sweep data/pr3207.nml --vary l_ab=0.1:0.12:2 --strict
run_ks sweep data/pr3207.nml --vary l_ab=0.1:0.12:2 --set dphi=1 --strict
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail sweep-strict-clean "rc=$rc $(cat "$err")"
# errors
expect_exit sweep-no-vary 1 sweep data/pr3207.nml
expect_exit sweep-format-csv 1 sweep data/pr3207.nml --vary l_ab=0.1:0.12:2 --format csv
expect_exit vary-without-sweep 1 data/pr3207.nml --vary l_ab=0.1:0.12:2
expect_exit sweep-bad-part 1 sweep data/pr3207.nml --vary l_ab=0.1:0.12:2 --part 3/2
run_ks sweep data/pr3207.nml --vary l_ab=0.1:0.12
[ "$rc" -eq 2 ] && grep -q "^kinetostat: error: --vary 'l_ab=0.1:0.12': expected NAME=FROM:TO:COUNT" "$err" && pass \
  || fail sweep-bad-vary "rc=$rc $(cat "$err")"
run_ks sweep data/pr3207.nml --vary l_ab=0.1:0.12:2.5
[ "$rc" -eq 2 ] && grep -q "COUNT must be a whole number" "$err" && pass || fail sweep-bad-count "rc=$rc $(cat "$err")"
run_ks sweep data/pr3207.nml --vary l_ab=0.3:0.5:3 --quiet
[ "$rc" -eq 2 ] && [ ! -s "$out" ] && [ "$(wc -l <"$err")" -eq 1 ] \
  && grep -q "l_ab: .*(sweep variant 2: l_ab=0.4)$" "$err" && pass || fail sweep-variant-error "rc=$rc $(cat "$err")"

# --- progress: only when stderr is a terminal and the run has gone on for a
# second (KINETOSTAT_PROGRESS_DELAY=0: from the first block on, so that the test does not
# depend on the machine's speed), overwritten in place and erased at the end; never in a pipe
# or a file, never with --quiet
if command -v script >/dev/null 2>&1; then
  script -qec "'$KINETOSTAT' data/pr3050.nml -o '$cli_tmp/progress.table'" /dev/null >"$cli_tmp/pty.txt" 2>&1
  if [ ! -s "$cli_tmp/pty.txt" ] && cmp -s "$cli_tmp/progress.table" data/expected/pr3050.table; then
    pass; else fail progress-short-run "a 13-step run showed: $(od -c "$cli_tmp/pty.txt" | head -5)"; fi
  sed 's/dphi = 30 /dphi = 0.018, n = 20000 /' data/pr3207.nml > "$cli_tmp/progress.nml"
  KINETOSTAT_PROGRESS_DELAY=0 script -qec "'$KINETOSTAT' '$cli_tmp/progress.nml' --format csv -o '$cli_tmp/progress.csv'" \
    /dev/null >"$cli_tmp/pty.txt" 2>&1
  "$KINETOSTAT" "$cli_tmp/progress.nml" --format csv >"$cli_tmp/progress2.csv" 2>/dev/null
  if grep -q $'\rkinetostat: '"$cli_tmp"'/progress.nml: step 8192 of 20000' "$cli_tmp/pty.txt" \
     && grep -q $'step 20000 of 20000\r *\r$' "$cli_tmp/pty.txt" && cmp -s "$cli_tmp/progress.csv" "$cli_tmp/progress2.csv"; then
    pass; else fail progress-terminal "$(od -c "$cli_tmp/pty.txt" | head -8)"; fi
  script -qec "'$KINETOSTAT' data/pr3050.nml --quiet -o /dev/null" /dev/null >"$cli_tmp/pty.txt" 2>&1
  [ ! -s "$cli_tmp/pty.txt" ] && pass || fail progress-quiet "$(od -c "$cli_tmp/pty.txt" | head -3)"
fi
run_ks data/pr3050.nml
[ ! -s "$err" ] && pass || fail progress-not-in-pipes "$(od -c "$err" | head -3)"
run_ks sweep data/pr3050.nml --vary m3=1000:1100:3
[ ! -s "$err" ] && pass || fail progress-not-in-pipes-sweep "$(od -c "$err" | head -3)"

# --- sweep --jobs: variants in child processes give the serial run's bytes (stdout, stderr,
# exit code), also when a variant fails; no temporary file is left behind
for args in "--vary l_ab=0.08:0.14:7 --vary m5=50:70:3" "--vary l_ab=0.05:0.5:6"; do
  # shellcheck disable=SC2086
  "$KINETOSTAT" sweep data/pr3207.nml $args --jobs 1 >"$cli_tmp/j1.out" 2>"$cli_tmp/j1.err"; rc1=$?
  # shellcheck disable=SC2086
  TMPDIR="$cli_tmp" "$KINETOSTAT" sweep data/pr3207.nml $args --jobs 3 >"$cli_tmp/j3.out" 2>"$cli_tmp/j3.err"; rc3=$?
  if [ "$rc1" -eq "$rc3" ] && cmp -s "$cli_tmp/j1.out" "$cli_tmp/j3.out" && cmp -s "$cli_tmp/j1.err" "$cli_tmp/j3.err"; then
    pass
  else
    fail "sweep-jobs ($args)" "exit $rc1 vs $rc3; $(diff "$cli_tmp/j1.out" "$cli_tmp/j3.out" | head -3) $(diff "$cli_tmp/j1.err" "$cli_tmp/j3.err" | head -3)"
  fi
  if ls "$cli_tmp"/kinetostat-sweep-* >/dev/null 2>&1; then fail sweep-jobs-tmp "temporary files left: $(ls "$cli_tmp"/kinetostat-sweep-*)"; else pass; fi
done
expect_exit sweep-jobs-bad 1 sweep data/pr3207.nml --vary l_ab=0.1:0.12:2 --jobs 0
expect_exit sweep-jobs-not-sweep 1 data/pr3207.nml --jobs 2

# --- summary and sweep headers: every name once; the --vary/--set columns keep their names
# and the dynamics figures carry the prefix dyn_ (a sweep of delta had delta, J_red_max and
# J_red_min twice)
run_ks sweep data/pr3207_flywheel.nml --vary delta=0.03:0.05:2 --set j_rotor=0.6 --set j_rotor=0.7 --quiet
cp "$out" "$cli_tmp/sweep_delta.csv"
if [ "$rc" -eq 0 ] && run_py - "$cli_tmp/sweep_delta.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
h = rows[0]
dup = sorted({n for n in h if h.count(n) > 1})
assert not dup, f"names twice: {dup}"
assert h[:2] == ["j_rotor", "delta"], h[:3]
for n in ["dyn_M_d", "dyn_J_flywheel", "dyn_delta", "dyn_delta_asked", "dyn_J_red_max", "J_red_max", "delta"]:
    assert n in h, n
r = dict(zip(h, rows[1]))
assert r["j_rotor"] == "0.7" and r["delta"] == "0.03" and abs(float(r["dyn_delta"]) - 0.03) < 1e-9, r
PY
then pass; else fail sweep-header-unique "exit $rc: $(head -1 "$cli_tmp/sweep_delta.csv" | head -c 300)"; fi
# every bundled deck's --format summary (with --kinematics, and --shaking where a linkage)
# (each header noted as "DECK OPTS|HEADER"; one awk finds the names twice)
: >"$cli_tmp/hdrs"
for deck in data/*.nml; do
  case "$deck" in data/assur_toggle.nml) continue ;; esac
  name="${deck##*/}"
  for opts in "" "--kinematics" "--shaking --kinematics"; do
    # a heavy deck (lib.sh) with the most columns only
    heavy_deck "${name%.nml}" && [ "$opts" != "--shaking --kinematics" ] && continue
    # shellcheck disable=SC2086
    "$KINETOSTAT" "$deck" --format summary --quiet $opts >"$cli_tmp/hdr.csv" 2>/dev/null || continue
    read -r header <"$cli_tmp/hdr.csv"
    printf '%s %s|%s\n' "$deck" "$opts" "$header" >>"$cli_tmp/hdrs"
  done
done
bad=$(awk -F'|' '{ n = split($2, names, ","); split("", seen); twice = ""
  for (i = 1; i <= n; i++) if (seen[names[i]]++ == 1) twice = twice " " names[i]
  if (twice != "") printf " %s:%s;", $1, twice }' "$cli_tmp/hdrs")
[ -s "$cli_tmp/hdrs" ] && [ -z "$bad" ] && pass || fail summary-header-unique "names twice:$bad (headers: $(wc -l <"$cli_tmp/hdrs"))"

# --- sweep --keep-going: every variant written, an error column last (empty on good rows),
# exit 2 when any failed; the header does not depend on a variant succeeding, and --part
# parts agree (concatenated, the whole sweep, byte for byte)
run_ks sweep data/pr3207.nml --vary l_ab=0.3:0.5:3 --vary m5=50:60:2 --keep-going --quiet
cp "$out" "$cli_tmp/keep.csv"
if [ "$rc" -eq 2 ] && run_py - "$cli_tmp/keep.csv" "$err" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
h = rows[0]
assert h[-1] == "error" and h[:2] == ["l_ab", "m5"], h
assert len(rows) == 7 and all(len(r) == len(h) for r in rows), [len(r) for r in rows]
good = [r for r in rows[1:] if r[-1] == ""]
failed = [r for r in rows[1:] if r[-1] != ""]
assert [r[:2] for r in good] == [["0.3", "50"], ["0.3", "60"]], good
assert all(r[0] in ("0.4", "0.5") for r in failed) and len(failed) == 4, failed
assert all("l_ab" in r[-1] for r in failed), failed
assert all(all(v == "" for v in r[2:-1]) for r in failed), "a failed variant has figures"
assert all(all(v != "" for v in r[2:-1]) for r in good), "a good variant has empty figures"
err = open(sys.argv[2]).read().splitlines()
assert len(err) == 4 and all(l.startswith("kinetostat: error: ") and "(sweep variant " in l for l in err), err
PY
then pass; else fail sweep-keep-going "exit $rc: $(head -3 "$cli_tmp/keep.csv" | cut -c1-200) / $(head -c 300 "$err")"; fi
# the same figures as a sweep without --keep-going, where that one succeeds
run_ks sweep data/pr3207.nml --vary l_ab=0.3:0.3:1 --vary m5=50:60:2 --quiet
if cmp -s <(cut -d, -f1-$(($(head -1 "$out" | tr ',' '\n' | wc -l))) "$cli_tmp/keep.csv" | head -3) "$out"; then pass
else fail sweep-keep-going-rows "the good rows differ from the plain sweep's"; fi
# every variant fails (the first too): the header is still the full one
run_ks sweep data/pr3207.nml --vary l_ab=0.3:0.3:1 --keep-going --quiet; head -1 "$out" >"$cli_tmp/keep_header"
run_ks sweep data/pr3207.nml --vary l_ab=0.4:0.5:2 --keep-going --quiet
if [ "$rc" -eq 2 ] && [ "$(head -1 "$out")" = "$(cat "$cli_tmp/keep_header")" ] && [ "$(wc -l <"$out")" -eq 3 ] && \
   grep -q ',error$' "$cli_tmp/keep_header"; then pass
else fail sweep-keep-going-all-fail "exit $rc, header: $(head -1 "$out" | cut -c1-200)"; fi
# --part: every part the same header (part 1 writes it), the parts concatenated are the sweep,
# also when part 1's variants all fail
for n in 2 3; do
  for k in $(seq 1 $n); do
    "$KINETOSTAT" sweep data/pr3207.nml --vary l_ab=0.5:0.3:3 --vary m5=50:60:2 --keep-going --quiet --part "$k/$n" \
      -o "$cli_tmp/kpart$k.csv" 2>/dev/null
  done
  run_ks sweep data/pr3207.nml --vary l_ab=0.5:0.3:3 --vary m5=50:60:2 --keep-going --quiet
  if cat $(seq -f "$cli_tmp/kpart%g.csv" 1 $n) | cmp -s - "$out" && head -1 "$cli_tmp/kpart1.csv" | grep -q ',error$'; then pass
  else fail "sweep-keep-going-parts-$n" "the $n parts do not make the sweep: $(cat $(seq -f "$cli_tmp/kpart%g.csv" 1 $n) | cut -c1-60)"; fi
done
# --jobs: the children's rows, the same bytes
run_ks sweep data/pr3207.nml --vary l_ab=0.3:0.5:3 --vary m5=50:60:2 --keep-going --quiet --jobs 3
cmp -s "$out" "$cli_tmp/keep.csv" && [ "$rc" -eq 2 ] && pass || fail sweep-keep-going-jobs "exit $rc; $(diff "$out" "$cli_tmp/keep.csv" | head -3)"
