# `kinetostat diff A B`: exit 0 same, 1 different, 2 unreadable or not
# comparable; angles modulo 360, angles of vanishing forces ignored, deck lines ignored.
dexp=data/expected

# expect_diff NAME CODE PATTERN ARGS...: `kinetostat diff ARGS` exits CODE and its stdout+stderr
# matches PATTERN (grep -E; "" for any).
expect_diff() {
  local name="$1" code="$2" pattern="$3"; shift 3
  run_ks diff "$@"
  if [ "$rc" -ne "$code" ]; then fail "$name" "exit $rc, expected $code: $(head -c 400 "$out" "$err")"; return; fi
  if [ -n "$pattern" ] && ! cat "$out" "$err" | grep -Eq -- "$pattern"; then
    fail "$name" "output does not match /$pattern/: $(head -c 400 "$out" "$err")"; return
  fi
  pass
}

# --- same: every golden against itself (by default every deck's table but the steady cycles'
# (the flywheel decks: tables of 20 to 80 kB, 0.2-0.8 s each) of the first deck of each kind
# only, and the Russian table and the CSV of the first deck of each kind, its namelist group;
# tools/test --long every golden), and the table of a run from another directory
diff_kinds_seen=" "
for f in "$dexp"/*.table "$dexp"/*.csv; do
  case "$f" in
    *.ru.table | *.csv | *_flywheel.table)
      kind=$(sed -n 's/^[[:space:]]*&\([A-Za-z0-9_]*\).*/\1/p' "data/$(basename "${f%%.*}").nml" | head -1)
      case "$f" in *.ru.table) kind="ru:$kind" ;; *.csv) kind="csv:$kind" ;; *) kind="flywheel:$kind" ;; esac
      case "${KINETOSTAT_LONG:-0}:$diff_kinds_seen" in
        0:*" $kind "*) continue ;;
      esac
      diff_kinds_seen="$diff_kinds_seen$kind " ;;
  esac
  expect_diff "diff-self-$(basename "$f")" 0 '^same: [0-9]+ values agree' "$f" "$f"
done
mkdir -p "$cli_tmp/elsewhere"; cp data/pr3207.nml "$cli_tmp/elsewhere/renamed.nml"
(cd "$cli_tmp/elsewhere" && "$KINETOSTAT" renamed.nml >pr3207.table)
grep -q 'DECK: renamed.nml' "$cli_tmp/elsewhere/pr3207.table" && pass || fail diff-deck-line-differs "deck line unchanged"
expect_diff diff-deck-path-ignored 0 '^same' "$dexp/pr3207.table" "$cli_tmp/elsewhere/pr3207.table"
sed 's/^\//  title = "a title"\n\//' data/pr3207.nml >"$cli_tmp/titled.nml"
run_ks "$cli_tmp/titled.nml"; cp "$out" "$cli_tmp/titled.table"
if grep -q 'TITLE: a title' "$cli_tmp/titled.table"; then
  expect_diff diff-deck-title-ignored 0 '^same' "$dexp/pr3207.table" "$cli_tmp/titled.table"
fi

# --- a real difference: exit 1, the step, the column, both values and the relative difference
sed '0,/2741.19/s//2741.25/' "$dexp/pr3207.table" >"$cli_tmp/d_f16.table"
expect_diff diff-table-f16 1 '^step 2, column F16: 2741.19 vs 2741.25 \(rel 2.2e-05\)$' "$dexp/pr3207.table" "$cli_tmp/d_f16.table"
expect_diff diff-table-summary 1 '^different: 1 of [0-9]+ values differ' "$dexp/pr3207.table" "$cli_tmp/d_f16.table"
expect_diff diff-rtol-loosens 0 '^same' --rtol 1e-4 "$dexp/pr3207.table" "$cli_tmp/d_f16.table"
expect_diff diff-rtol-equals-form 0 '^same' "$dexp/pr3207.table" "$cli_tmp/d_f16.table" --rtol=1e-4
run_ks diff --quiet "$dexp/pr3207.table" "$cli_tmp/d_f16.table"
[ "$rc" -eq 1 ] && [ ! -s "$out" ] && pass || fail diff-quiet "rc=$rc, stdout: $(head -c 200 "$out")"
# second-line (angle) and N/M lines of the generic engine, an INPUT DATA value, a Russian table
sed '0,/  253.66/s//  253.70/' "$dexp/pr3207.table" >"$cli_tmp/d_ang.table"
expect_diff diff-table-angle-line 1 '^step 3, column F21G: 253.66 vs 253.70 \(diff 4.0e-02 deg\)$' \
  "$dexp/pr3207.table" "$cli_tmp/d_ang.table"
sed '0,/-317.32/s//-317.30/' "$dexp/assur_pr3207.table" >"$cli_tmp/d_m.table"
expect_diff diff-table-assur-m-line 1 '^step 2, column F56M: -317.32 vs -317.30' "$dexp/assur_pr3207.table" "$cli_tmp/d_m.table"
sed 's/F5C_WORK        =   3.000000000E+03/F5C_WORK        =   3.100000000E+03/' "$dexp/pr3207.table" >"$cli_tmp/d_in.table"
expect_diff diff-table-input 1 '^INPUT DATA, F5C_WORK: 3.000000000E\+03 vs 3.100000000E\+03' "$dexp/pr3207.table" "$cli_tmp/d_in.table"
sed '0,/ 901.929/s// 901.939/' "$dexp/sixbar.ru.table" >"$cli_tmp/d_ru.table"
expect_diff diff-table-ru 1 'step 2, column M1: 901.929 vs 901.939' "$dexp/sixbar.ru.table" "$cli_tmp/d_ru.table"
sed 's/ OK$/ FAILED/' "$dexp/pr3207.table" >"$cli_tmp/d_ok.table"
expect_diff diff-table-verdict 1 'MAX EQUILIBRIUM RESIDUAL, ALL LINKS AND STEPS: OK vs FAILED' "$dexp/pr3207.table" "$cli_tmp/d_ok.table"
sed 's/  1     1567.566   55.00     2112.092  196.70     1173.385  343.30    4.6105  KF>2/  1  JAMMED (SELF-LOCKING)/' \
  "$dexp/cam_translating.table" >"$cli_tmp/d_jam.table"
expect_diff diff-table-remark 1 '^step 3: KF>2 vs JAMMED \(SELF-LOCKING\)$' "$dexp/cam_translating.table" "$cli_tmp/d_jam.table"
sed '0,/250.0000/s//250.0100/' "$dexp/gears_reducer.table" >"$cli_tmp/d_g.table"
expect_diff diff-table-gears 1 '^STAGE 1: SPUR, F12 ANGLE: 250.0000 vs 250.0100' "$dexp/gears_reducer.table" "$cli_tmp/d_g.table"
awk -F, 'BEGIN{OFS=","} NR==3{$12=sprintf("%.12E",$12*(1+1e-5))} {print}' "$dexp/pr3207.csv" >"$cli_tmp/d_m1.csv"
expect_diff diff-csv-m1 1 '^step 2, column M1: -2.257429061813E\+002 vs -2.257451636[0-9]*E\+0*2 \(rel 1.0e-05\)$' \
  "$dexp/pr3207.csv" "$cli_tmp/d_m1.csv"
awk -F, 'BEGIN{OFS=","} NR==2{$3=sprintf("%.12E",$3*(1+1e-5))} {print}' "$dexp/gears_reducer.csv" >"$cli_tmp/d_stage.csv"
expect_diff diff-csv-stage 1 '^stage 1, column z1: 20 vs 2.000020000000E\+01' "$dexp/gears_reducer.csv" "$cli_tmp/d_stage.csv"
# another number of steps: reported first
sed 's/dphi = 30 /dphi = 60 /' data/pr3207.nml >"$cli_tmp/dphi60.nml"
run_ks "$cli_tmp/dphi60.nml" --format csv; cp "$out" "$cli_tmp/dphi60.csv"
expect_diff diff-steps 1 '^steps: 13 vs 7$' "$dexp/pr3207.csv" "$cli_tmp/dphi60.csv"

# --- angles modulo 360: 359.999 vs 0.001 is a difference of 0.002 deg
awk -F, 'BEGIN{OFS=","} NR==3{$3="3.599990000000E+002"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/a359.csv"
awk -F, 'BEGIN{OFS=","} NR==3{$3="1.000000000000E-003"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/a0.csv"
expect_diff diff-angle-wraps 0 '^same' --atol 0.005 "$cli_tmp/a359.csv" "$cli_tmp/a0.csv"
expect_diff diff-angle-wrap-measured 1 '^step 2, column F16G: 3.599990000000E\+002 vs 1.000000000000E-003 \(diff 2.0e-03 deg\)$' \
  "$cli_tmp/a359.csv" "$cli_tmp/a0.csv"
awk -F, 'BEGIN{OFS=","} NR==3{$3="3.599999999990E+002"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/a359b.csv"
awk -F, 'BEGIN{OFS=","} NR==3{$3="1.000000000000E-009"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/a0b.csv"
expect_diff diff-angle-wraps-default 0 '^same' "$cli_tmp/a359b.csv" "$cli_tmp/a0b.csv"
# ... only for angles: the same numbers in a force column differ
awk -F, 'BEGIN{OFS=","} NR==3{$2="3.599990000000E+002"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/f359.csv"
awk -F, 'BEGIN{OFS=","} NR==3{$2="1.000000000000E-003"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/f0.csv"
expect_diff diff-force-no-wrap 1 '^step 2, column F16: ' --atol 0.005 "$cli_tmp/f359.csv" "$cli_tmp/f0.csv"
# in a table too (PHI1, F16G: units deg)
sed '0,/   256.65/s//   359.99/' "$dexp/pr3207.table" >"$cli_tmp/t359.table"
sed '0,/   256.65/s//     0.01/' "$dexp/pr3207.table" >"$cli_tmp/t0.table"
expect_diff diff-table-angle-wraps 0 '^same' --atol 0.05 "$cli_tmp/t359.table" "$cli_tmp/t0.table"
expect_diff diff-table-angle-wrap-measured 1 'column F16G: 359.99 vs 0.01 \(diff 2.0e-02 deg\)' "$cli_tmp/t359.table" "$cli_tmp/t0.table"

# --- the angle of a vanishing force is arbitrary: F21 = 0 at step 1 of PR 3207
awk -F, 'BEGIN{OFS=","} NR==2{$5="1.234567890000E+002"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/v.csv"
expect_diff diff-vanishing-angle-ignored 0 'angles of vanishing forces not compared' "$dexp/pr3207.csv" "$cli_tmp/v.csv"
# a force just above the floor (1e-12 of the step's largest force, 588.6 N here): its angle counts
awk -F, 'BEGIN{OFS=","} NR==2{$4="1.000000000000E-005"; $5="1.234567890000E+002"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/v1.csv"
awk -F, 'BEGIN{OFS=","} NR==2{$4="1.000000000000E-005"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/v0.csv"
expect_diff diff-small-force-angle-counts 1 '^step 1, column F21G: 0.000000000000E\+000 vs 1.234567890000E\+002' \
  "$cli_tmp/v0.csv" "$cli_tmp/v1.csv"
# the same in a table: F21 = 0.00 at step 1, its angle any
sed '0,/       180.00        0.00      180.00/s//       180.00      123.45      180.00/' "$dexp/pr3207.table" >"$cli_tmp/v.table"
if ! cmp -s "$dexp/pr3207.table" "$cli_tmp/v.table"; then
  expect_diff diff-table-vanishing-angle-ignored 0 '^same' "$dexp/pr3207.table" "$cli_tmp/v.table"
else fail diff-table-vanishing-angle-ignored "the sed did not change the table"; fi
# a random angle on a force that does not vanish is a difference
awk -F, 'BEGIN{OFS=","} NR==2{$3="1.234567890000E+002"} {print}' "$dexp/pr3207.csv" >"$cli_tmp/nv.csv"
expect_diff diff-angle-of-real-force 1 '^step 1, column F16G' "$dexp/pr3207.csv" "$cli_tmp/nv.csv"

# --- exit 2: unreadable, or not the same mechanism, columns, format or language
printf 'garbage\n1 2 3\n' >"$cli_tmp/garbage.txt"
expect_diff diff-garbage 2 'not an output of kinetostat' "$dexp/pr3207.csv" "$cli_tmp/garbage.txt"
: >"$cli_tmp/empty.txt"
expect_diff diff-empty 2 'empty file' "$cli_tmp/empty.txt" "$dexp/pr3207.csv"
expect_diff diff-missing 2 'no-such.csv: no such file' "$dexp/pr3207.csv" "$cli_tmp/no-such.csv"
expect_diff diff-other-mechanism-table 2 'not the same mechanism' "$dexp/pr3207.table" "$dexp/sixbar.table"
# two CSV files share only some columns (phi1, M1): the others are listed, exit 1
expect_diff diff-other-mechanism-csv 1 '^columns only in data/expected/sixbar.csv: F32, F32G, F43, F43G, F45, F45G$' "$dexp/pr3207.csv" "$dexp/sixbar.csv"
expect_diff diff-other-assur-columns 2 'not the same columns' "$dexp/assur_pr3207.table" "$dexp/assur_sixbar.table"
expect_diff diff-table-vs-csv 2 'not comparable \(compare outputs of the same --format\)' "$dexp/pr3207.table" "$dexp/pr3207.csv"
expect_diff diff-en-vs-ru 2 'same --lang' "$dexp/pr3207.table" "$dexp/pr3207.ru.table"
expect_diff diff-json 2 'JSON' "$dexp/pr3207.json" "$dexp/pr3207.json"
head -5 "$dexp/pr3207.csv" | sed '3s/,[^,]*$//' >"$cli_tmp/short_row.csv"
expect_diff diff-csv-short-row 2 'short_row.csv:3: 11 fields, the header has 12' "$dexp/pr3207.csv" "$cli_tmp/short_row.csv"
sed '3s/^[^,]*/abc/' "$dexp/pr3207.csv" >"$cli_tmp/word.csv"
expect_diff diff-csv-word 2 "word.csv:3: column phi1: 'abc' is not a number" "$dexp/pr3207.csv" "$cli_tmp/word.csv"
expect_diff diff-one-file 2 'needs two files' "$dexp/pr3207.csv"
expect_diff diff-bad-rtol 2 'rtol must be a number >= 0' --rtol -1 "$dexp/pr3207.csv" "$dexp/pr3207.csv"
expect_diff diff-unknown-option 2 "unknown option '--frob'" --frob "$dexp/pr3207.csv" "$dexp/pr3207.csv"

# --- CSV columns are matched by name: another order is the same file; a column on one side
# only is a difference (exit 1, listed); --common compares the shared columns only
run_py - "$dexp/assur_fourbar.csv" "$cli_tmp/reordered.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
order = list(range(len(rows[0])))[::-1]
with open(sys.argv[2], "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    for r in rows:
        w.writerow([r[i] for i in order])
PY
expect_diff diff-csv-reordered 0 '^same: [0-9]+ values agree' "$dexp/assur_fourbar.csv" "$cli_tmp/reordered.csv"
sed '4s/^\([^,]*\),[^,]*/\1,9.99E+02/' "$cli_tmp/reordered.csv" >"$cli_tmp/reordered_changed.csv"
expect_diff diff-csv-reordered-changed 1 '^step 3, column ' "$dexp/assur_fourbar.csv" "$cli_tmp/reordered_changed.csv"
run_ks data/assur_fourbar.nml --format csv --shaking; cp "$out" "$cli_tmp/fourbar_shaking.csv"
expect_diff diff-csv-extra-columns 1 '^columns only in .*fourbar_shaking.csv: F_shake, F_shakeG, F_shake_x, F_shake_y, M_shake, F_frame_x, F_frame_y, M_frame$' \
  "$dexp/assur_fourbar.csv" "$cli_tmp/fourbar_shaking.csv"
expect_diff diff-csv-missing-columns 1 '^columns only in .*fourbar_shaking.csv: F_shake' "$cli_tmp/fourbar_shaking.csv" "$dexp/assur_fourbar.csv"
expect_diff diff-csv-common 0 '^same: [0-9]+ values agree .*8 columns only in .*fourbar_shaking.csv not compared' \
  --common "$dexp/assur_fourbar.csv" "$cli_tmp/fourbar_shaking.csv"
sed '3s/^\([^,]*\),[^,]*/\1,1.5E+02/' "$cli_tmp/fourbar_shaking.csv" >"$cli_tmp/fourbar_shaking_changed.csv"
expect_diff diff-csv-common-differs 1 '^step 2, column ' --common "$dexp/assur_fourbar.csv" "$cli_tmp/fourbar_shaking_changed.csv"
printf 'a_col,b_col\n1,2\n' >"$cli_tmp/nothing_shared.csv"
expect_diff diff-csv-nothing-shared 2 'no column in common' "$dexp/assur_fourbar.csv" "$cli_tmp/nothing_shared.csv"
