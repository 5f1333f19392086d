# Parallel steps: with OMP_NUM_THREADS=2 every output is byte for byte the
# one of OMP_NUM_THREADS=1 (stdout, stderr and exit code), for every bundled deck in every
# format, for decks scaled to thousands of steps (the writers then format rows in parallel
# blocks) and for a deck failing at many steps (the first failing step in step order is the
# one reported).

# expect_same_threads NAME ARGS...: the run with 2 threads gives the bytes and exit code of
# the run with 1 thread.
expect_same_threads() {
  local name="$1"; shift
  local rc1 rc2
  OMP_NUM_THREADS=1 "$KINETOSTAT" "$@" >"$cli_tmp/par1.out" 2>"$cli_tmp/par1.err"; rc1=$?
  OMP_NUM_THREADS=2 "$KINETOSTAT" "$@" >"$cli_tmp/par2.out" 2>"$cli_tmp/par2.err"; rc2=$?
  if [ "$rc1" -ne "$rc2" ]; then fail "$name" "exit code $rc2 with 2 threads, $rc1 with 1"; return; fi
  if ! cmp -s "$cli_tmp/par1.out" "$cli_tmp/par2.out"; then
    fail "$name" "stdout differs with 2 threads: $(cmp "$cli_tmp/par1.out" "$cli_tmp/par2.out")"; return
  fi
  if ! cmp -s "$cli_tmp/par1.err" "$cli_tmp/par2.err"; then
    fail "$name" "stderr differs with 2 threads: $(diff "$cli_tmp/par1.err" "$cli_tmp/par2.err" | head -4)"; return
  fi
  pass
}

# The bundled decks: one of the five forms (table, CSV, JSON, SVG, CSV with --kinematics) in
# turn, so that every form runs on a fifth of the decks; all five with tools/test --long.
# The decks scaled to thousands of steps below run every form.
par_forms=("--format table" "--format csv" "--format json" "--format svg" "--format csv --kinematics")
par_i=0
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  # the heavy deck (lib.sh) with --long only: the &linkage engine's threads are the other
  # &linkage decks', the dynamics stage's the other flywheel decks'
  if heavy_deck "$name"; then par_i=$((par_i + 1)); continue; fi
  for j in 0 1 2 3 4; do
    if [ "${KINETOSTAT_LONG:-0}" != 1 ] && [ $((par_i % 5)) -ne "$j" ]; then continue; fi
    # shellcheck disable=SC2086 # the form is words
    expect_same_threads "threads-$name-$(echo ${par_forms[$j]} | sed 's/--format //; s/ --/-/')" "$deck" ${par_forms[$j]}
  done
  par_i=$((par_i + 1))
done

# decks scaled to 3000 steps (more than the writers' threshold of 256 rows per thread)
sed 's/dphi = 30 /dphi = 0.1, n = 3000 /' data/pr3207.nml >"$cli_tmp/par_pr3207.nml"
sed 's/dphi = 30, n = 13/dphi = 0.1, n = 3000/; s/f5 = 7\*1000, 6\*0/f5 = 1500*1000, 1500*0/' \
  data/sixbar.nml >"$cli_tmp/par_sixbar.nml"
sed 's/dphi = 30, n = 13/dphi = 0.1, n = 3000/; s/step_values = 7\*1000, 6\*0/step_values = 1500*1000, 1500*0/' \
  data/assur_sixbar.nml >"$cli_tmp/par_assur_sixbar.nml"
sed 's/dphi = 30, n = 13/dphi = 0.1, n = 3000/; s/^  theta = .*/  theta = 1000*0, 1000*20, 1000*-15/;
     s/^  vdir  = .*/  vdir = 1000*1, 1000*1, 1000*-1/; s/^  f2    = .*/  f2 = 3000*300/' \
  data/cam_translating.nml >"$cli_tmp/par_cam.nml"
# PR 3050 (its prismatic pair's second section) and T.FTN in Russian (its moment section):
# the legacy table's two sections of each block are formatted in parallel parts
sed 's/dphi3 = 5 /dphi3 = 0.015 /; s/^  omega3 = .*/  omega3 = 1500*0.3, 1501*0.5/; s/^  eps3 = .*/  eps3 = 3001*0.1/' \
  data/pr3050.nml >"$cli_tmp/par_pr3050.nml"
expect_same_threads "threads-par_pr3050-table" "$cli_tmp/par_pr3050.nml"
expect_same_threads "threads-par_pr3050-table-ru" "$cli_tmp/par_pr3050.nml" --lang ru
expect_same_threads "threads-par_sixbar-table-ru" "$cli_tmp/par_sixbar.nml" --lang ru
expect_same_threads "threads-par_assur_sixbar-table-link" "$cli_tmp/par_assur_sixbar.nml" --frame link
OMP_NUM_THREADS=2 run_ks "$cli_tmp/par_pr3050.nml"
if [ "$rc" -eq 0 ] && [ "$(grep -c '^ *45\.00 ' "$out")" -eq 2 ]; then pass; else
  fail "threads-par_pr3050-both-sections" "expected exit 0 and the last step (45.00) in both sections, got $rc, \
$(grep -c '^ *45\.00 ' "$out") lines"
fi
# the toggle is singular every 180 deg: steps 2, 8, 14, ... fail (exit 3, step 2 named)
sed 's/n = 3$/n = 3000/' data/assur_toggle.nml >"$cli_tmp/par_toggle.nml"
for deck in par_pr3207 par_sixbar par_assur_sixbar par_cam par_toggle; do
  if ! grep -q "3000" "$cli_tmp/$deck.nml"; then fail "threads-$deck" "the deck was not scaled"; continue; fi
  for format in table csv json; do
    expect_same_threads "threads-$deck-$format" "$cli_tmp/$deck.nml" --format "$format"
  done
  expect_same_threads "threads-$deck-csv-kinematics" "$cli_tmp/$deck.nml" --format csv --kinematics
done
OMP_NUM_THREADS=2 run_ks "$cli_tmp/par_toggle.nml"
if [ "$rc" -eq 3 ] && grep -q "step 2 (phi1 = 0.000000000 deg)" "$err"; then pass; else
  fail "threads-toggle-first-step" "expected exit 3 naming step 2 (phi1 = 0.000000000 deg), got $rc: $(head -c 300 "$err")"
fi
for deck in par_pr3207 par_sixbar par_assur_sixbar par_cam; do
  OMP_NUM_THREADS=2 run_ks "$cli_tmp/$deck.nml" --format csv
  if [ "$rc" -eq 0 ] && [ "$(wc -l <"$out")" -eq 3001 ]; then pass; else
    fail "threads-$deck-rows" "expected exit 0 and 3001 CSV lines, got $rc and $(wc -l <"$out")"
  fi
done
