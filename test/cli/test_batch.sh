# Batch use: decks from standard input and pipes, --set overrides.

# expect_bytes NAME EXPECTED ACTUAL: the two files are identical byte for byte.
expect_bytes() {
  if cmp -s "$2" "$3"; then pass; else fail "$1" "$3 differs from $2: $(diff "$2" "$3" | head -6)"; fi
}

# expect_one_line_error NAME CODE PATTERN: the last run exited CODE with one stderr line
# "kinetostat: error: ..." matching PATTERN (grep -E) and nothing on stdout.
expect_one_line_error() {
  local name="$1" code="$2" pattern="$3"
  if [ "$rc" -ne "$code" ]; then fail "$name" "exit code $rc, expected $code: $(head -c 300 "$err")"; return; fi
  if [ "$(wc -l <"$err")" -ne 1 ]; then fail "$name" "stderr is not one line: $(head -c 300 "$err")"; return; fi
  if ! grep -Eq "^kinetostat: error: .*$pattern" "$err"; then fail "$name" "message does not match /$pattern/: $(cat "$err")"; return; fi
  if [ -s "$out" ]; then fail "$name" "something was written to stdout"; return; fi
  pass
}

# --- decks from standard input: `-` (redirect and pipe) and /dev/stdin on a pipe give the
# file run's output byte for byte; the table's DECK line names the deck as given
for deck in data/pr3207.nml data/assur_slider_crank.nml data/cam_flat.nml; do
  name=$(basename "$deck" .nml)
  "$KINETOSTAT" - --format csv <"$deck" >"$cli_tmp/stdin.csv" 2>"$cli_tmp/stdin.err"
  expect_bytes "stdin-dash-redirect-csv-$name" "data/expected/$name.csv" "$cli_tmp/stdin.csv"
  cat "$deck" | "$KINETOSTAT" - --format csv >"$cli_tmp/pipe.csv" 2>"$cli_tmp/stdin.err"
  expect_bytes "stdin-dash-pipe-csv-$name" "data/expected/$name.csv" "$cli_tmp/pipe.csv"
  cat "$deck" | "$KINETOSTAT" /dev/stdin --format csv >"$cli_tmp/devstdin.csv" 2>"$cli_tmp/stdin.err"
  expect_bytes "stdin-dev-stdin-pipe-csv-$name" "data/expected/$name.csv" "$cli_tmp/devstdin.csv"
  cat "$deck" | "$KINETOSTAT" - >"$cli_tmp/pipe.table" 2>"$cli_tmp/stdin.err"
  sed "s|^ DECK: $deck\$| DECK: <stdin>|" "data/expected/$name.table" >"$cli_tmp/expected_stdin.table"
  expect_bytes "stdin-dash-pipe-table-$name" "$cli_tmp/expected_stdin.table" "$cli_tmp/pipe.table"
done
grep -q '^ DECK: <stdin>$' "$cli_tmp/pipe.table" && pass || fail stdin-deck-name "the table does not name the deck <stdin>"
# an input error in a piped deck names <stdin>
run_ks - <"$(deck_with stdin_bad data/pr3207.nml 's/l_ab = 0.11/l_ab = -0.11/')"
expect_one_line_error stdin-error-names-stdin 2 '<stdin>: &pr3207: l_ab: must be > 0'
# an empty standard input is an input error, not a hang or a crash
run_ks - </dev/null
expect_one_line_error stdin-empty 2 '<stdin>: no namelist group'

# --- --set equals the sed-edited deck byte for byte (CSV), in both option forms
# set_equals_sed NAME DECK SED_EXPR SET_ARGS...: CSV of DECK with SET_ARGS = CSV of the edited deck.
set_equals_sed() {
  local name="$1" deck="$2" expr="$3"; shift 3
  local edited; edited=$(deck_with "set_$name" "$deck" "$expr")
  if cmp -s "$deck" "$edited"; then fail "set-$name" "the sed expression changed nothing"; return; fi
  "$KINETOSTAT" "$edited" --format csv >"$cli_tmp/sed.csv" 2>/dev/null
  "$KINETOSTAT" "$deck" --format csv "$@" >"$cli_tmp/set.csv" 2>/dev/null
  if cmp -s "$deck" "$edited" || cmp -s "data/expected/$(basename "$deck" .nml).csv" "$cli_tmp/set.csv"; then
    fail "set-$name" "--set changed nothing in the output"; return
  fi
  expect_bytes "set-$name" "$cli_tmp/sed.csv" "$cli_tmp/set.csv"
}
set_equals_sed pr3207-l_ab data/pr3207.nml 's/l_ab = 0.11/l_ab = 0.12/' --set l_ab=0.12
set_equals_sed pr3207-equals-form data/pr3207.nml 's/dphi = 30/dphi = 15/' --set=dphi=15
set_equals_sed pr3207-two data/pr3207.nml 's/m5 = 60/m5 = 80/; s/f5c_work = 3000/f5c_work = 2500/' \
  --set m5=80 --set f5c_work=2500
set_equals_sed pr3207-later-wins data/pr3207.nml 's/m5 = 60/m5 = 80/' --set m5=70 --set m5=80
set_equals_sed assur-member data/assur_slider_crank.nml 's/dyad(1)%l2 = 0.35/dyad(1)%l2 = 0.36/' \
  --set 'dyad(1)%l2=0.36'
set_equals_sed assur-member-force data/assur_slider_crank.nml 's/force(1)%value = 500/force(1)%value = 650/' \
  --set 'force(1)%value = 650'
set_equals_sed sixbar-element data/sixbar.nml 's/f5 = 7\*1000, 6\*0/f5 = 1000, 1500, 5*1000, 6*0/' --set 'f5(2)=1500'
set_equals_sed cam-string data/cam_flat.nml "s/f_cam     = 0.1 /f_cam = 0.2/" --set f_cam=0.2
# a variable the deck does not set is added (pr3207's n, optional)
set_equals_sed pr3207-added data/pr3207.nml 's/^\//  n = 7\n\//' --set n=7

# --- the INPUT DATA echo shows the overrides and marks the overridden records
run_ks data/pr3207.nml --set l_ab=0.12 --set 'dphi = 15'
grep -q '^   --set l_ab=0.12$' "$out" && grep -q '^   --set dphi=15$' "$out" && pass \
  || fail set-echo-lines "the overrides are not listed in INPUT DATA"
grep -q '^   L_AB            =   1.200000000E-01  m (--set)$' "$out" && pass || fail set-echo-mark "L_AB is not marked (--set)"
[ "$(grep -c '(--set)' "$out")" -eq 2 ] && pass || fail set-echo-mark-count "expected 2 marked records: $(grep '(--set)' "$out")"
run_ks data/assur_slider_crank.nml --set 'dyad(1)%l2=0.36' --format json
run_py -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["overrides"] == ["dyad(1)%l2=0.36"], d["overrides"]' "$out" \
  && pass || fail set-json-overrides "JSON has no overrides list"
run_ks data/pr3207.nml --set l_ab=0.12 --format json
run_py -c 'import json,sys; d=json.load(open(sys.argv[1])); assert [e["name"] for e in d["input"] if e.get("overridden")] == ["L_AB"]' "$out" \
  && pass || fail set-json-mark "JSON does not mark L_AB overridden"
# without --set nothing changes (the goldens cover this byte for byte)

# --- bad --set: exit 2, one line, naming --set
run_ks data/pr3207.nml --set l_abx=1
expect_one_line_error set-unknown-name 2 "--set l_abx=1: &pr3207: l_abx = 1: unknown variable 'l_abx'"
run_ks data/pr3207.nml --set 'l_ab=0,11'
expect_one_line_error set-decimal-comma 2 "--set l_ab=0,11: &pr3207: l_ab = 0,11: decimal comma\? write 0.11$"
run_ks data/pr3207.nml --set l_ab=abc
expect_one_line_error set-bad-value 2 "--set l_ab=abc: &pr3207: "
grep -q "^kinetostat: error: --set l_ab=abc: &pr3207: l_ab = abc: " "$err" && pass || fail set-bad-value-start "$(cat "$err")"
# no line number of the deck is given for an override's own line (the file has no such line)
grep -q 'pr3207.nml:[0-9]' "$err" && fail set-no-deck-line "$(cat "$err")" || pass
run_ks data/pr3207.nml --set l_ab=-1
expect_one_line_error set-invalid-value 2 "&pr3207: l_ab: must be > 0 .*\(from --set l_ab=-1\)$"
run_ks data/pr3207.nml --set n=2147483648
expect_one_line_error set-overflow 2 "n: must be a whole number .*\(from --set n=2147483648\)$"
run_ks data/pr3207.nml --set l_ab
expect_one_line_error set-no-equals 2 "--set 'l_ab': expected NAME=VALUE"
run_ks data/pr3207.nml --set l_ab=
expect_one_line_error set-no-value 2 "--set 'l_ab=': no value after '='"
run_ks data/pr3207.nml --set '=3'
expect_one_line_error set-no-name 2 "--set '=3': '' is not a deck variable name"
run_ks data/pr3207.nml --set 'l_ab=0.1 / &pr3207 m5=1'
expect_one_line_error set-injection 2 "--set 'l_ab=0.1 / &pr3207 m5=1': the value must be one namelist value list"
run_ks data/pr3207.nml --set 'l_ab=0.1, m5=1'
expect_one_line_error set-second-assignment 2 "the value must be one namelist value list"
run_ks data/pr3207.nml --set
expect_exit set-missing-argument 1 data/pr3207.nml --set
# a mistake of the deck itself is not blamed on a --set that is fine
run_ks "$(deck_with set_deck_bad data/pr3207.nml 's/m1 = 12/m1 = -12/')" --set l_ab=0.12
expect_one_line_error set-deck-own-error 2 "&pr3207: m1: must be >= 0 \(got -12[.0]*\)$"
# ... and a --set may repair it
run_ks "$(deck_with set_deck_bad2 data/pr3207.nml 's/m1 = 12/m1 = -12/')" --set m1=12 --format csv
expect_bytes set-repairs-deck data/expected/pr3207.csv "$out"

# --- the true error: with several --set the message is the full run's own; "(from --set ...)"
# only when that override alone gives the same error
run_ks data/pr3207.nml --set "dynamics='steady'" --set delta=5
expect_one_line_error set-true-error-delta 2 "data/pr3207.nml: &pr3207: delta: must be > 0 and < 1 \(got 5[.0]*\): "
grep -q "from --set" "$err" && fail set-true-error-delta-blame "blamed on one --set: $(cat "$err")" || pass
run_ks docs/examples/engine.nml --set "dynamics='steady'" --set delta=0.02
expect_one_line_error set-true-error-cycle 2 "docs/examples/engine.nml: &assur: cycle: the steady cycle is one turn \\(cycle = 360, the default\\) but force\\(1\\)%table spans 720"
grep -q "from --set\|missing" "$err" && fail set-true-error-cycle-blame "blamed or 'missing': $(cat "$err")" || pass
run_ks data/pr3207_flywheel.nml --set m5=70 --set delta=5
expect_one_line_error set-true-error-alone 2 "&pr3207: delta: must be > 0 and < 1 \(got 5[.0]*\): .* \(from --set delta=5\)$"
run_ks data/pr3207.nml --set m5=70 --set l_ab=-1 --set m3=30
expect_one_line_error set-true-error-middle 2 "&pr3207: l_ab: must be > 0 .*\(from --set l_ab=-1\)$"
run_ks data/pr3207.nml --set m5=70 --set 'l_ab=0,11'
expect_one_line_error set-true-error-line 2 "--set l_ab=0,11: &pr3207: l_ab = 0,11: decimal comma\? write 0.11$"
