# --format npy: the CSV's columns as a NumPy .npy file. tools/npy_check.py (a reader of the
# format in Python's standard library; numpy and pandas too when installed) compares every
# file with the CSV of the same run: header, field names and order, record count, and every
# value rounded to 13 significant digits against the CSV's text (an empty cell: NaN). A heavy
# deck (lib.sh) with tools/test --long only: its twin (pr3207_flywheel, assur_engine_flywheel) runs.

# every bundled deck that runs, with the kinematics columns
npy_pairs=()
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  heavy_deck "$name" && continue
  run_ks_cached "$name.kin.csv" "$deck" --format csv --kinematics
  [ "$rc" -eq 0 ] || continue
  cp "$out" "$cli_tmp/npy_$name.csv"
  run_ks "$deck" --format npy --kinematics --quiet -o "$cli_tmp/npy_$name.npy"
  if [ "$rc" -ne 0 ]; then fail "npy-$name" "exit $rc: $(head -c 300 "$err")"; continue; fi
  npy_pairs+=("$cli_tmp/npy_$name.npy" "$cli_tmp/npy_$name.csv")
done
if [ "${#npy_pairs[@]}" -lt 40 ]; then fail npy-decks "only $((${#npy_pairs[@]} / 2)) decks ran"; fi
run_py tools/npy_check.py "${npy_pairs[@]}" >"$cli_tmp/npy_check.out" 2>&1 && pass ||
  fail npy-decks-against-csv "$(head -20 "$cli_tmp/npy_check.out")"

# more rows than a block (8192): the header's count and the rows of every block; a cam deck
# with jammed and lost-contact steps (empty CSV cells, NaN); two threads write the same bytes
sed 's/dphi = 30 /dphi = 0.018, n = 20000 /' data/pr3207.nml >"$cli_tmp/npy_long.nml"
# (steps 4001-8000 past the critical pressure angle: jammed; 10001-12000 lose contact)
sed 's/dphi = 30, n = 13/dphi = 0.03, n = 12000/; s/^  theta = .*/  theta = 4000*0, 4000*45, 4000*-15/;
     s/^  vdir  = .*/  vdir = 4000*1, 4000*1, 4000*-1/; s/^  f2    = .*/  f2 = 10000*300, 2000*-20/' \
  data/cam_translating.nml >"$cli_tmp/npy_cam.nml"
for deck in npy_long npy_cam; do
  if ! grep -q "000" "$cli_tmp/$deck.nml"; then fail "$deck" "the deck was not scaled"; continue; fi
  "$KINETOSTAT" "$cli_tmp/$deck.nml" --format csv --quiet -o "$cli_tmp/$deck.csv"
  OMP_NUM_THREADS=1 "$KINETOSTAT" "$cli_tmp/$deck.nml" --format npy --quiet -o "$cli_tmp/$deck.npy"
  OMP_NUM_THREADS=2 "$KINETOSTAT" "$cli_tmp/$deck.nml" --format npy --quiet >"$cli_tmp/${deck}_2.npy"
  run_py tools/npy_check.py "$cli_tmp/$deck.npy" "$cli_tmp/$deck.csv" >"$cli_tmp/npy_check.out" 2>&1 && pass ||
    fail "$deck-against-csv" "$(head -20 "$cli_tmp/npy_check.out")"
  cmp -s "$cli_tmp/$deck.npy" "$cli_tmp/${deck}_2.npy" && pass ||
    fail "$deck-threads" "2 threads (stdout) differ from 1 (-o): $(cmp "$cli_tmp/$deck.npy" "$cli_tmp/${deck}_2.npy")"
done
run_py - "$cli_tmp/npy_cam.npy" <<'PY' && pass || fail npy-cam-nan "not NaN exactly in the jammed and lost steps"
import math, sys
sys.path.insert(0, "tools")
from npy_check import read_npy
_, names, records = read_npy(sys.argv[1])
void = [k for k, r in enumerate(records) if any(math.isnan(v) for v in r)]
assert len(void) == 6000 and void[0] == 4000 and void[-1] == 11999, "void rows"
PY

# a Cyrillic joint name: header version 3.0 (UTF-8), the field named as in the CSV
sed "s/dyad(1)%joints = 'B'/dyad(1)%joints = 'Б'/" data/assur_fourbar.nml >"$cli_tmp/npy_cyr.nml"
"$KINETOSTAT" "$cli_tmp/npy_cyr.nml" --format csv --kinematics --quiet -o "$cli_tmp/npy_cyr.csv"
"$KINETOSTAT" "$cli_tmp/npy_cyr.nml" --format npy --kinematics --quiet -o "$cli_tmp/npy_cyr.npy"
if ! head -1 "$cli_tmp/npy_cyr.csv" | grep -q "x_Б"; then fail npy-cyrillic "the deck's joint is not named Б"
elif run_py tools/npy_check.py "$cli_tmp/npy_cyr.npy" "$cli_tmp/npy_cyr.csv" >"$cli_tmp/npy_check.out" 2>&1 &&
  [ "$(od -An -tu1 -j6 -N1 "$cli_tmp/npy_cyr.npy" | tr -d ' ')" = 3 ]; then pass
else fail npy-cyrillic "not version 3.0 or not the CSV: $(head -5 "$cli_tmp/npy_check.out")"; fi

# the checker can fail: one value of the last record changed
cp "$cli_tmp/npy_long.npy" "$cli_tmp/npy_bad.npy"
printf '\x01' | dd of="$cli_tmp/npy_bad.npy" bs=1 seek=$(($(stat -c %s "$cli_tmp/npy_bad.npy") - 3)) conv=notrunc 2>/dev/null
if run_py tools/npy_check.py "$cli_tmp/npy_bad.npy" "$cli_tmp/npy_long.csv" >"$cli_tmp/npy_check.out" 2>&1; then
  fail npy-check-must-fail "a changed value was accepted"
elif grep -q "row 20000, M1: npy" "$cli_tmp/npy_check.out"; then pass; else
  fail npy-check-must-fail "the report does not name row 20000, M1: $(head -5 "$cli_tmp/npy_check.out")"
fi

# a sweep: the summary CSV's columns (the --set of a text left out), --jobs and --part
sweep_args=(sweep data/assur_fourbar.nml --vary crank_m=0.4:0.6:3 --vary omega1=10:20:2 --set "title='a, \"b\"'" --quiet)
"$KINETOSTAT" "${sweep_args[@]}" -o "$cli_tmp/npy_sweep.csv"
run_ks "${sweep_args[@]}" --format npy --jobs 1 -o "$cli_tmp/npy_sweep.npy"
if [ "$rc" -eq 0 ]; then
  run_py tools/npy_check.py "$cli_tmp/npy_sweep.npy" "$cli_tmp/npy_sweep.csv" >"$cli_tmp/npy_check.out" 2>&1 && pass ||
    fail npy-sweep-against-csv "$(head -20 "$cli_tmp/npy_check.out")"
else
  fail npy-sweep "exit $rc: $(head -c 300 "$err")"
fi
"$KINETOSTAT" "${sweep_args[@]}" --format npy --jobs 2 -o "$cli_tmp/npy_sweep_2.npy"
cmp -s "$cli_tmp/npy_sweep.npy" "$cli_tmp/npy_sweep_2.npy" && pass || fail npy-sweep-jobs "--jobs 2 differs from --jobs 1"
"$KINETOSTAT" "${sweep_args[@]}" --format npy --part 1/2 -o "$cli_tmp/npy_part1.npy"
"$KINETOSTAT" "${sweep_args[@]}" --format npy --part 2/2 -o "$cli_tmp/npy_part2.npy"
run_py - "$cli_tmp/npy_sweep.npy" "$cli_tmp/npy_part1.npy" "$cli_tmp/npy_part2.npy" <<'PY' && pass || fail npy-sweep-parts "the parts' records (3 and 3) are not the whole sweep's"
import sys
sys.path.insert(0, "tools")
from npy_check import read_npy
_, names, whole = read_npy(sys.argv[1])
_, names1, part1 = read_npy(sys.argv[2])
_, names2, part2 = read_npy(sys.argv[3])
assert names1 == names and names2 == names, "other fields"
assert len(part1) == 3 and part1 + part2 == whole, "the parts' records are not the whole sweep's"
PY

# a variable set twice is one column (the later value's), as in the CSV
twice_args=(sweep data/pr3207.nml --vary l_ab=0.08:0.1:2 --set m5=60 --set m5=61 --quiet)
"$KINETOSTAT" "${twice_args[@]}" -o "$cli_tmp/npy_twice.csv"
run_ks "${twice_args[@]}" --format npy -o "$cli_tmp/npy_twice.npy"
if [ "$rc" -eq 0 ]; then
  run_py tools/npy_check.py "$cli_tmp/npy_twice.npy" "$cli_tmp/npy_twice.csv" >"$cli_tmp/npy_check.out" 2>&1 && pass ||
    fail npy-sweep-set-twice "$(head -20 "$cli_tmp/npy_check.out")"
else
  fail npy-sweep-set-twice "exit $rc: $(head -c 300 "$err")"
fi
# --keep-going: the variants that ran (l_ab = 0.3; 0.4 and 0.5 fail), exit 2
run_ks sweep data/pr3207.nml --vary l_ab=0.3:0.5:3 --keep-going --format npy --quiet -o "$cli_tmp/npy_kept.npy"
run_py - "$cli_tmp/npy_kept.npy" <<'PY' && [ "$rc" -eq 2 ] && pass || fail npy-sweep-keep-going "exit $rc (expected 2) or not the one variant that ran"
import sys
sys.path.insert(0, "tools")
from npy_check import read_npy
_, names, rows = read_npy(sys.argv[1])
assert len(rows) == 1 and rows[0][names.index("l_ab")] == 0.3, (len(rows), rows[:1])
PY

# binary data is never written to a terminal (usage error); to a file or a pipe it is
if command -v script >/dev/null 2>&1; then
  script -qec "$KINETOSTAT data/pr3207.nml --format npy" /dev/null >"$cli_tmp/npy_tty.out" 2>&1
  grep -q "kinetostat: error: --format npy writes binary data, not for a terminal" "$cli_tmp/npy_tty.out" && pass ||
    fail npy-terminal "not refused on a terminal: $(head -c 300 "$cli_tmp/npy_tty.out")"
  script -qec "$KINETOSTAT data/pr3207.nml --format npy -o /dev/tty" /dev/null >"$cli_tmp/npy_tty.out" 2>&1
  grep -q "not for a terminal" "$cli_tmp/npy_tty.out" && pass ||
    fail npy-terminal-o "-o /dev/tty not refused: $(head -c 300 "$cli_tmp/npy_tty.out")"
else
  echo "note: npy-terminal skipped (no script(1) to make a terminal)"
fi
run_ks data/pr3207.nml --format npy --quiet
if [ "$rc" -eq 0 ] && [ "$(head -c 6 "$out" | od -An -c | tr -d ' ')" = "223NUMPY" ]; then pass; else
  fail npy-stdout "exit $rc, or stdout is not an npy file"
fi
# a failing run leaves no file
rm -f "$cli_tmp/npy_fail.npy"
expect_exit npy-fail-exit 3 data/assur_toggle.nml --format npy -o "$cli_tmp/npy_fail.npy"
if ls "$cli_tmp/npy_fail.npy"* >/dev/null 2>&1; then fail npy-fail-nothing-left "a file was left"; else pass; fi
