# Command-line tests of PR 3050 (sourced by tools/test with test/cli/lib.sh).
ref3050=data/pr3050.nml

# --- golden outputs (data/expected/), compared with numdiff, and proof the comparison can fail
run_ks "$ref3050"; cp "$out" "$cli_tmp/pr3050.table"
[ "$rc" -eq 0 ] && pass || fail pr3050-table-exit "exit $rc: $(cat "$err")"
expect_same pr3050-golden-table data/expected/pr3050.table "$cli_tmp/pr3050.table"
expect_no_nan pr3050-table-no-nan "$cli_tmp/pr3050.table"
run_ks "$ref3050" --format csv; cp "$out" "$cli_tmp/pr3050.csv"
expect_same pr3050-golden-csv data/expected/pr3050.csv "$cli_tmp/pr3050.csv"
expect_no_nan pr3050-csv-no-nan "$cli_tmp/pr3050.csv"
if [ "$(head -1 "$cli_tmp/pr3050.csv")" = "phi3rel,F14,F14G,F34,F34G,F32,F32G,F2" ]; then pass
else fail pr3050-csv-header "header is '$(head -1 "$cli_tmp/pr3050.csv")'"; fi
if [ "$(wc -l <"$cli_tmp/pr3050.csv")" -eq 11 ]; then pass
else fail pr3050-csv-rows "expected header + 10 rows, got $(wc -l <"$cli_tmp/pr3050.csv") lines"; fi
# one line per step in the table's RESULTS block, forces in the original's E format (0.222E+05)
n_lines=$(grep -cE '^ +[0-9]+\.[0-9]{2} +-?0\.[0-9]{3}E[+-][0-9]{2} +[0-9]+\.[0-9]{2}( +-?0\.[0-9]{3}E[+-][0-9]{2} +[0-9]+\.[0-9]{2}){2} +-?0\.[0-9]{3}E[+-][0-9]{2}$' "$cli_tmp/pr3050.table")
[ "$n_lines" -eq 10 ] && pass || fail pr3050-table-e-format "expected 10 E-format step lines, got $n_lines"
# the self-check footer says OK for both checks
[ "$(grep -c ' OK$' "$cli_tmp/pr3050.table")" -eq 2 ] && pass || fail pr3050-selfcheck-ok "footer not OK"
# perturb one value (F2 at the 5th step) by 1e-6 relative: the comparison must fail
awk -F, 'BEGIN{OFS=","} NR==6{$8=sprintf("%.12E",$8*(1+1e-6))} {print}' data/expected/pr3050.csv >"$cli_tmp/perturbed3050.csv"
expect_differ pr3050-golden-csv-can-fail data/expected/pr3050.csv "$cli_tmp/perturbed3050.csv"
sed '0,/0.221E+05/s//0.222E+05/' data/expected/pr3050.table >"$cli_tmp/perturbed3050.table"
expect_differ pr3050-golden-table-can-fail data/expected/pr3050.table "$cli_tmp/perturbed3050.table"

# --- -o FILE: same bytes as stdout
rm -f "$cli_tmp/o3050.csv"
run_ks "$ref3050" --format csv -o "$cli_tmp/o3050.csv"
if [ "$rc" -eq 0 ] && cmp -s "$cli_tmp/o3050.csv" "$cli_tmp/pr3050.csv"; then pass
else fail pr3050-output-file "rc=$rc or file differs from stdout"; fi

# --- template: a valid deck giving the reference results
run_ks template pr3050; cp "$out" "$cli_tmp/template3050.nml"
[ "$rc" -eq 0 ] && grep -q '^&pr3050' "$cli_tmp/template3050.nml" && pass || fail pr3050-template "rc=$rc"
run_ks "$cli_tmp/template3050.nml" --format csv; cp "$out" "$cli_tmp/template3050.csv"
expect_same pr3050-template-runs data/expected/pr3050.csv "$cli_tmp/template3050.csv"

# --- a static deck (all omega3 = eps3 = 0) runs, with gravity only, self-check OK
zeros10="0, 0, 0, 0, 0, 0, 0, 0, 0, 0"
static=$(deck_with static3050 "$ref3050" "s/^  omega3 = .*/  omega3 = $zeros10/; s/^  eps3 = .*/  eps3 = $zeros10/")
run_ks "$static"; cp "$out" "$cli_tmp/static3050.table"
[ "$rc" -eq 0 ] && pass || fail pr3050-static-runs "rc=$rc: $(cat "$err")"
expect_no_nan pr3050-static-no-nan "$cli_tmp/static3050.table"
[ "$(grep -c ' OK$' "$cli_tmp/static3050.table")" -eq 2 ] && pass || fail pr3050-static-selfcheck "footer not OK"
# with g = 0 as well nothing loads the mechanism: every force prints as 0, angle 0
run_ks "$(deck_with unloaded3050 "$static" 's/g = 9.81/g = 0/')" --format csv; cp "$out" "$cli_tmp/unloaded3050.csv"
if [ "$rc" -eq 0 ] && [ "$(tail -n +2 "$cli_tmp/unloaded3050.csv" | cut -d, -f2- | tr ',' '\n' | sort -u)" = "0.000000000000E+000" ]; then pass
else fail pr3050-unloaded-zero "rc=$rc or a nonzero force with no loads: $(head -3 "$cli_tmp/unloaded3050.csv")"; fi

# --- input errors: exit 2, one line naming deck, group, variable and reason, no output
e() { expect_input_error "pr3050-$1" "&pr3050: $2" "$(deck_with "p3050_$1" "$ref3050" "$3")"; }
e unknown-variable "n = 10: unknown variable 'n'" 's/dphi3 = 5/dphi3 = 5, n = 10/'
e wrong-type "l_cb = abc: 'abc' is not a number" 's/l_cb = 1.222/l_cb = abc/'
e missing-l_ca 'l_ca: missing' 's/l_ca = 1.667, //'
e missing-l_cb 'l_cb: missing' 's/, l_cb = 1.222//'
e missing-l_cs3 'l_cs3: missing' 's/l_cs3 = 2.31, //'
e missing-delta 'delta: missing' 's/, delta = 10.5//'
e missing-l_bs2 'l_bs2: missing' 's/l_bs2 = 0.48, //'
e missing-l_s1a 'l_s1a: missing' 's/, l_s1a = 0.42//'
e missing-gamma 'gamma: missing' 's/gamma = 313.72, //'
e missing-m2 'm2: missing' 's/m2 = 28, //'
e missing-j3 'j3: missing' 's/, j3 = 622//'
e missing-phi3_start 'phi3_start: missing' 's/phi3_start = 43.72, //'
e missing-phi3_end 'phi3_end: missing' 's/phi3_end = 88.72, //'
e missing-dphi3 'dphi3: missing' 's/, dphi3 = 5//'
e missing-omega3 'omega3: missing' '/^  omega3/d'
e missing-eps3 'eps3: missing' '/^  eps3/d'
e nan-l_ca 'l_ca: must be a finite number' 's/l_ca = 1.667/l_ca = NaN/'
e inf-gamma 'gamma: must be a finite number' 's/gamma = 313.72/gamma = Infinity/'
e nan-delta 'delta: must be a finite number' 's/delta = 10.5/delta = NaN/'
e zero-l_ca 'l_ca: must be > 0' 's/l_ca = 1.667/l_ca = 0/'
e negative-l_cb 'l_cb: must be > 0' 's/l_cb = 1.222/l_cb = -1.222/'
e negative-l_cs3 'l_cs3: must be >= 0' 's/l_cs3 = 2.31/l_cs3 = -2.31/'
e negative-l_bs2 'l_bs2: must be >= 0' 's/l_bs2 = 0.48/l_bs2 = -0.48/'
e negative-l_s1a 'l_s1a: must be >= 0' 's/l_s1a = 0.42/l_s1a = -0.42/'
e negative-g 'g: must be >= 0' 's/g = 9.81/g = -9.81/'
e negative-m1 'm1: must be >= 0' 's/m1 = 15/m1 = -15/'
e negative-m2 'm2: must be >= 0' 's/m2 = 28/m2 = -28/'
e negative-m3 'm3: must be >= 0' 's/m3 = 1056/m3 = -1056/'
e negative-j1 'j1: must be >= 0' 's/j1 = 1.5/j1 = -1.5/'
e negative-j2 'j2: must be >= 0' 's/j2 = 1.5/j2 = -1.5/'
e negative-j3 'j3: must be >= 0' 's/j3 = 622/j3 = -622/'
e end-equals-start 'phi3_end: must be > phi3_start' 's/phi3_end = 88.72/phi3_end = 43.72/'
e end-before-start 'phi3_end: must be > phi3_start' 's/phi3_end = 88.72/phi3_end = 0/'
e zero-step 'dphi3: must be > 0' 's/dphi3 = 5/dphi3 = 0/'
e negative-step 'dphi3: must be > 0' 's/dphi3 = 5/dphi3 = -5/'
e step-not-whole 'dphi3: phi3_end - phi3_start = 45.* is not a whole number of steps' 's/dphi3 = 5/dphi3 = 4/'
e step-too-small 'dphi3: too small' 's/dphi3 = 5/dphi3 = 1e-9/'
e omega3-short 'omega3: expected 10 values \(one per step\), got 9' 's/0.28868, 0 /0.28868 /'
e omega3-long 'omega3: expected 10 values \(one per step\), got 11' 's/0.28868, 0 /0.28868, 0, 0 /'
e eps3-short 'eps3: expected 10 values \(one per step\), got 9' 's/-0.47746, -0.47746, -0.47746/-0.47746, -0.47746/'
e eps3-for-other-n 'eps3: expected 19 values' 's/dphi3 = 5/dphi3 = 2.5/; s/^  omega3 = .*/  omega3 = 19*0.5/'
e omega3-gap 'omega3: values must be given without gaps' 's/^  omega3 = .*/  omega3(1) = 1, omega3(3) = 2/'
e omega3-nan 'omega3\(4\): must be a finite number' 's/0.40825, 0.5,/0.40825, NaN,/'
e eps3-inf 'eps3\(5\): must be a finite number' 's/0.47746, 0, 0,/0.47746, 0, Infinity,/'
e unterminated 'namelist' '/^\//d'

# --- geometry errors: exit 3, the step and its angle named, no output, no NaN
# s = 0: l_cb = l_ca and the range passes phi3 = 0 at step 3
expect_input_error pr3050-s-zero '&pr3050: step 3 \(phi3 = 0\.0+ deg\): cannot be assembled: cylinder length s = 0' \
  "$(deck_with p3050_s0 "$ref3050" 's/l_cb = 1.222/l_cb = 1.667/; s/phi3_start = 43.72, phi3_end = 88.72/phi3_start = -10, phi3_end = 10/;
     s/^  omega3 = .*/  omega3 = 5*0.5/; s/^  eps3 = .*/  eps3 = 5*0/')" 3
# dead position: the cylinder axis passes through C at phi3 = 180 (step 2)
expect_input_error pr3050-dead '&pr3050: step 2 \(phi3 = 180\.0+ deg\): dead position' \
  "$(deck_with p3050_dead "$ref3050" 's/phi3_start = 43.72, phi3_end = 88.72/phi3_start = 175, phi3_end = 185/;
     s/^  omega3 = .*/  omega3 = 3*0.5/; s/^  eps3 = .*/  eps3 = 3*0/')" 3
# the same range without the dead step (170 and 190) is fine
run_ks "$(deck_with p3050_around "$ref3050" 's/phi3_start = 43.72, phi3_end = 88.72, dphi3 = 5/phi3_start = 170, phi3_end = 190, dphi3 = 20/;
     s/^  omega3 = .*/  omega3 = 2*0.5/; s/^  eps3 = .*/  eps3 = 2*0/')" --format csv
[ "$rc" -eq 0 ] && pass || fail pr3050-around-dead "rc=$rc: $(cat "$err")"
expect_no_nan pr3050-around-dead-no-nan "$out"
# ... but the user is told that the dead position lies between steps 1 and 2 (--quiet silences it)
if grep -Eq '^kinetostat: warning: .*between step 1 \(phi3 = 170(\.0*)? deg\) and step 2 \(phi3 = 190(\.0*)? deg\).*dead position phi3 = 180(\.0*)? deg' "$err" \
   && [ "$(wc -l <"$err")" -eq 1 ]; then pass; else fail pr3050-around-dead-warning "stderr: $(cat "$err")"; fi
run_ks "$cli_tmp/p3050_around.nml" --format csv --quiet
if [ "$rc" -eq 0 ] && [ ! -s "$err" ]; then pass; else fail pr3050-around-dead-quiet "rc=$rc stderr: $(cat "$err")"; fi
# the reference range (43.72..88.72 deg) stays clear: no warning
run_ks "$ref3050"
if [ "$rc" -eq 0 ] && [ ! -s "$err" ]; then pass; else fail pr3050-reference-no-warning "stderr: $(cat "$err")"; fi

# --- constant speed: omega3 = 10*0.5, eps3 = 10*0 (repeat counts) reproduces the cruise steps
# 4..7 of the reference law (omega3 = 0.5, eps3 = 0 there) exactly
run_ks "$(deck_with const3050 "$ref3050" 's/^  omega3 = .*/  omega3 = 10*0.5/; s/^  eps3 = .*/  eps3 = 10*0/')" --format csv
sed -n '5,8p' "$out" >"$cli_tmp/const3050.rows"
sed -n '5,8p' data/expected/pr3050.csv >"$cli_tmp/cruise3050.rows"
if [ "$rc" -eq 0 ] && [ "$(wc -l <"$cli_tmp/const3050.rows")" -eq 4 ]; then pass
else fail pr3050-constant-speed-runs "rc=$rc: $(cat "$err")"; fi
expect_same pr3050-constant-speed-equals-cruise "$cli_tmp/cruise3050.rows" "$cli_tmp/const3050.rows"
# ... while its acceleration steps differ from the reference law's (eps3 /= 0 there)
sed -n '2,4p' "$out" >"$cli_tmp/const3050.start"
sed -n '2,4p' data/expected/pr3050.csv >"$cli_tmp/accel3050.start"
expect_differ pr3050-constant-speed-differs-in-ramp "$cli_tmp/accel3050.start" "$cli_tmp/const3050.start"
