# Deterministic mutation test, sourced by tools/test with test/cli/lib.sh.
# tools/mutate_decks.py derives >= 500 broken or extreme decks from data/*.nml (fixed seed) and
# runs $KINETOSTAT on each (table, CSV, -o FILE; the decks with hostile strings in every
# output format, checked by tools/output_check.py). The default suite's gate runs a fixed ninth
# of them (--every 9: every ninth deck in the fixed order, so that every class runs on a ninth
# of the bundled decks, each way - the table, the CSV with -o: --every 9 --modes lists them - a
# twenty-seventh of the decks whose runs take over a second, the &linkage steady cycles - every
# deck of the classes of strings with outputs to check (hostile file names, titles and fields) and of the endless inputs, and of the classes with an expected
# error (fraction, text after the group, CP1251, capacity) the first deck of each namelist group
# and of each capacity row drawn and every ninth of the others; the CSV written with -o only),
# with no time limit: the same decks and the same verdict every run;
# tools/test --long runs them all, the CSV to standard output too. It reports one verdict per assertion category
# ("check NAME: ok" / "check NAME: FAIL (n decks)"); each category counts as ONE check here, so
# that 500+ decks do not swamp the counters of the rest of the suite. The failing decks are
# listed one per line (mutation, failed check, reproducer in a temporary directory that the
# tool makes at the first failure and prints: "mutation: the failing decks are written to DIR").
# A run's limit is processor time (10 s; 60 s for the long texts and the heavy decks), not wall
# time: the machine's load does not change the verdict.
mutation_log="$cli_tmp/mutation.log"
mutation_every=9
[ "${KINETOSTAT_LONG:-0}" = 1 ] && mutation_every=1
if python3 "$root/tools/mutate_decks.py" --bin "$KINETOSTAT" --every "$mutation_every" \
  >"$mutation_log" 2>&1; then :; fi
for category in exit-code non-finite error-shape no-leftover warning-shape runtime-text valid-output expected-error; do
  if grep -qx "check $category: ok" "$mutation_log"; then
    pass
  else
    fail "mutation-$category" "$(grep -m1 "^check $category:" "$mutation_log" || echo "no verdict (script failed: $(tail -3 "$mutation_log"))")
$(grep "^FAIL .* $category (" "$mutation_log" | head -100)
$(grep '^mutation: the failing decks are written to' "$mutation_log")"
  fi
done
grep -E '^(mutation|named): ' "$mutation_log"

# The mutation checks can fail: a fake binary that prints a NaN and exits 0, and one that
# exits 1 with two stderr lines, must be caught.
fake="$cli_tmp/fake_kinetostat"
printf '#!/bin/sh\necho "  1.00  NaN"\nexit 0\n' >"$fake"; chmod +x "$fake"
python3 "$root/tools/mutate_decks.py" --bin "$fake" --deck pr3050 --only pr3050_001 --out "$cli_tmp/mut_fake" >"$cli_tmp/mut_fake.log" 2>&1
if grep -q '^check non-finite: FAIL' "$cli_tmp/mut_fake.log"; then pass
else fail mutation-can-fail-nan "a binary printing NaN passed: $(tail -2 "$cli_tmp/mut_fake.log")"; fi
printf '#!/bin/sh\necho one >&2\necho two >&2\nexit 1\n' >"$fake"
python3 "$root/tools/mutate_decks.py" --bin "$fake" --deck pr3050 --only pr3050_001 --out "$cli_tmp/mut_fake" >"$cli_tmp/mut_fake.log" 2>&1
if grep -q '^check exit-code: FAIL' "$cli_tmp/mut_fake.log" && grep -q '^check error-shape: FAIL' "$cli_tmp/mut_fake.log"; then pass
else fail mutation-can-fail-exit "a binary exiting 1 with two stderr lines passed: $(tail -2 "$cli_tmp/mut_fake.log")"; fi
# ... and so can the classes of strings: a binary writing a JSON with an added key and a CSV row
# over two lines for a deck with hostile strings, and one that accepts a fraction
printf '#!/bin/sh\necho "{\\"injected\\": true}"\necho "a,b"\necho "1"\nexit 0\n' >"$fake"
python3 "$root/tools/mutate_decks.py" --bin "$fake" --deck pr3207 --only pr3207_s01_user_strings --out "$cli_tmp/mut_fake" >"$cli_tmp/mut_fake.log" 2>&1
if grep -q '^check valid-output: FAIL' "$cli_tmp/mut_fake.log"; then pass
else fail mutation-can-fail-valid-output "an invalid output passed: $(tail -2 "$cli_tmp/mut_fake.log")"; fi
printf '#!/bin/sh\necho " ok"\nexit 0\n' >"$fake"
python3 "$root/tools/mutate_decks.py" --bin "$fake" --deck pr3207 --only pr3207_s02_fraction --out "$cli_tmp/mut_fake" >"$cli_tmp/mut_fake.log" 2>&1
if grep -q '^check expected-error: FAIL' "$cli_tmp/mut_fake.log"; then pass
else fail mutation-can-fail-expected-error "an accepted fraction passed: $(tail -2 "$cli_tmp/mut_fake.log")"; fi

# ... and so can the limit of processor time, with --long (it spends the limit, a second, on each
# of its three runs): a binary that computes for ever is stopped and reported
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  printf '#!/bin/sh\nwhile :; do :; done\n' >"$fake"
  python3 "$root/tools/mutate_decks.py" --bin "$fake" --deck assur_pr3050 --only assur_pr3050_001_delete --cpu-limit 1 \
    --out "$cli_tmp/mut_fake" >"$cli_tmp/mut_fake.log" 2>&1
  if grep -q '^check exit-code: FAIL' "$cli_tmp/mut_fake.log" && grep -q 'over 1 s of processor time (stopped)' "$cli_tmp/mut_fake.log"
  then pass; else fail mutation-can-fail-cpu-limit "a binary that never ends passed: $(tail -2 "$cli_tmp/mut_fake.log")"; fi
fi

# With tools/test --long, a second, randomized run of the whole mutation set (every class above,
# new random choices from a seed of the date, printed: `python3 tools/mutate_decks.py --seed N`
# reproduces it), in random order within 60 s of starting decks; the decks the budget leaves
# are skipped. It is not in the default suite: its verdict would change by day and load.
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  seed=$(date +%Y%m%d)
  python3 "$root/tools/mutate_decks.py" --bin "$KINETOSTAT" --seed "$seed" --budget 60 \
    >"$cli_tmp/mutation_random.log" 2>&1
  if grep -q "^mutation: .* 0 decks failed" "$cli_tmp/mutation_random.log"; then pass
  else fail mutation-random "seed $seed: $(grep -E '^(FAIL|check .*FAIL|mutation: the failing)' "$cli_tmp/mutation_random.log" | head -20)
  $(tail -2 "$cli_tmp/mutation_random.log")"; fi
  grep -E '^mutation: ' "$cli_tmp/mutation_random.log"
fi
