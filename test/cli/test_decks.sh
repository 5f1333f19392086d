# Command-line tests of the deck layer shared by every mechanism (sourced by tools/test with
# test/cli/lib.sh): how a deck file may end and be encoded, and values that used to collide
# with the "not given" sentinels or overflow an integer.
dk_ref=data/pr3207.nml

# run_in DIR ARGS...: run_ks from directory DIR (so a relative deck path prints the same).
run_in() {
  local dir="$1"; shift
  out="$cli_tmp/stdout"; err="$cli_tmp/stderr"
  (cd "$dir" && "$KINETOSTAT" "$@") >"$out" 2>"$err"; rc=$?
}

# --- every bundled deck with its final newline removed gives the same output (the table, and
# with tools/test --long the CSV too; stdout, stderr, exit code): the same relative path
# data/NAME.nml, run from another directory (a heavy deck, lib.sh, with --long only: the
# other &linkage decks go through the same reader)
mkdir -p "$cli_tmp/no_newline/data"
for deck in data/*.nml; do
  name="$(basename "$deck" .nml)"
  heavy_deck "$name" && continue
  if [ "$(tail -c1 "$deck" | od -An -c | tr -d ' ')" != '\n' ]; then
    fail "decks-no-newline-$name" "$deck itself has no final newline: the test would prove nothing"; continue
  fi
  printf '%s' "$(cat "$deck")" >"$cli_tmp/no_newline/data/$name.nml"
  if [ "$(tail -c1 "$cli_tmp/no_newline/data/$name.nml" | od -An -c | tr -d ' ')" = '\n' ]; then
    fail "decks-no-newline-$name" "the copy still ends with a newline"; continue
  fi
  # the table holds what the CSV does and more; the CSV too with tools/test --long
  dk_formats="table"; [ "${KINETOSTAT_LONG:-0}" = 1 ] && dk_formats="table csv"
  for fmt in $dk_formats; do
    run_in . "data/$name.nml" --format "$fmt"
    cp "$out" "$cli_tmp/dk_ref.out"; cp "$err" "$cli_tmp/dk_ref.err"; ref_rc=$rc
    run_in "$cli_tmp/no_newline" "data/$name.nml" --format "$fmt"
    if [ "$rc" -eq "$ref_rc" ] && cmp -s "$out" "$cli_tmp/dk_ref.out" && cmp -s "$err" "$cli_tmp/dk_ref.err"; then pass
    else fail "decks-no-newline-$name-$fmt" "exit $rc (original $ref_rc) or output differs: $(head -c 300 "$err")"; fi
  done
done

# --- a UTF-8 byte-order mark, CRLF line ends, both together without a final newline
printf '\357\273\277' >"$cli_tmp/bom.nml"; cat "$dk_ref" >>"$cli_tmp/bom.nml"
run_ks "$cli_tmp/bom.nml" --format csv
if [ "$rc" -eq 0 ] && cmp -s "$out" data/expected/pr3207.csv; then pass
else fail decks-bom "exit $rc or CSV differs from data/expected/pr3207.csv: $(head -c 300 "$err")"; fi
sed 's/$/\r/' "$dk_ref" >"$cli_tmp/crlf.nml"
run_ks "$cli_tmp/crlf.nml" --format csv
if [ "$rc" -eq 0 ] && cmp -s "$out" data/expected/pr3207.csv; then pass
else fail decks-crlf "exit $rc or CSV differs from data/expected/pr3207.csv: $(head -c 300 "$err")"; fi
printf '\357\273\277%s' "$(sed 's/$/\r/' data/assur_slider_crank.nml)" >"$cli_tmp/bom_crlf.nml"
run_ks "$cli_tmp/bom_crlf.nml" --format csv
if [ "$rc" -eq 0 ] && cmp -s "$out" data/expected/assur_slider_crank.csv; then pass
else fail decks-bom-crlf-no-newline "exit $rc or CSV differs from data/expected/assur_slider_crank.csv: $(head -c 300 "$err")"; fi
# a deck read from a pipe (size unknown): the deck is read once, so this works
cat "$dk_ref" | "$KINETOSTAT" /dev/stdin --format csv >"$cli_tmp/pipe.csv" 2>"$cli_tmp/pipe.err"; rc=$?
if [ "$rc" -eq 0 ] && cmp -s "$cli_tmp/pipe.csv" data/expected/pr3207.csv; then pass
else fail decks-pipe "exit $rc or CSV differs: $(head -c 300 "$cli_tmp/pipe.err")"; fi
# a line longer than any fixed buffer (4000 blanks before the value)
sed "s/l_ab = 0.11/l_ab = $(printf '%4000s' '')0.11/" "$dk_ref" >"$cli_tmp/long_line.nml"
run_ks "$cli_tmp/long_line.nml" --format csv
if [ "$rc" -eq 0 ] && cmp -s "$out" data/expected/pr3207.csv; then pass
else fail decks-long-line "exit $rc or CSV differs: $(head -c 300 "$err")"; fi

# --- the old "not given" sentinels typed in a deck are ordinary (invalid) values now
expect_input_error decks-n-old-sentinel '&pr3207: n: must be a whole number from 1 to 1000000 \(got -2147483647\)' \
  "$(deck_with n_sentinel "$dk_ref" 's/dphi = 30/dphi = 30, n = -2147483647/')"
expect_input_error decks-g-old-sentinel '&pr3207: g: must be >= 0' \
  "$(deck_with g_sentinel "$dk_ref" 's/g = 9.81/g = -1.7976931348623157e308/')"
expect_input_error decks-kind-old-sentinel '&assur: dyad\(1\)%kind: must be 1\.\.5 .*got -2147483647' \
  "$(deck_with kind_sentinel data/assur_slider_crank.nml 's/dyad(1)%kind = 2/dyad(1)%kind = -2147483647/')"
expect_input_error decks-z3-old-sentinel "&gears: z3\\(1\\): only for a 'planetary' stage" \
  "$(deck_with z3_sentinel data/gears_reducer.nml 's/m1      = 50/m1 = 50, z3 = -2147483647/')"

# --- integer variables: out of the default integer range, or not whole
expect_input_error decks-n-too-big '&pr3207: n: must be a whole number from 1 to 1000000 \(got 2147483648\)' \
  "$(deck_with n_big "$dk_ref" 's/dphi = 30/dphi = 30, n = 2147483648/')"
expect_input_error decks-n-fraction '&pr3207: n: must be a whole number from 1 to 1000000 \(got 1\.5' \
  "$(deck_with n_frac "$dk_ref" 's/dphi = 30/dphi = 30, n = 1.5/')"
expect_input_error decks-sixbar-n-fraction '&sixbar: n: must be a whole number' \
  "$(deck_with sx_n_frac data/sixbar.nml 's/n = 13/n = 13.5/')"
expect_input_error decks-cam-n-too-big '&cam: n: must be a whole number' \
  "$(deck_with cam_n_big data/cam_translating.nml 's/n = 13/n = 1e10/')"
expect_input_error decks-gears-z1-fraction '&gears: z1\(1\): must be a whole number from 1 to 100000 \(got 20\.5' \
  "$(deck_with z1_frac data/gears_reducer.nml 's/z1      = 20, 18/z1 = 20.5, 18/')"
expect_input_error decks-gears-k-fraction '&gears: k\(1\): must be a whole number' \
  "$(deck_with k_frac data/gears_planetary.nml 's/k       = 3 /k = 3.5 /')"
expect_input_error decks-assur-link2-fraction '&assur: dyad\(1\)%link2: must be a whole number from 0' \
  "$(deck_with link2_frac data/assur_slider_crank.nml 's/dyad(1)%link2 = 2/dyad(1)%link2 = 2.5/')"
expect_input_error decks-assur-on2-too-big '&assur: dyad\(1\)%on2: must be a whole number from 0 to 2147483647' \
  "$(deck_with on2_big data/assur_slider_crank.nml 's/dyad(1)%on2 = 1/dyad(1)%on2 = 4294967297/')"
expect_input_error decks-assur-mode-fraction '&assur: dyad\(1\)%mode: must be \+1 or -1 \(assembly mode\), got 1\.5' \
  "$(deck_with mode_frac data/assur_slider_crank.nml 's/dyad(1)%mode = 1/dyad(1)%mode = 1.5/')"
expect_input_error decks-assur-force-link-fraction '&assur: force\(1\)%link: must be a whole number' \
  "$(deck_with flink_frac data/assur_slider_crank.nml 's/force(1)%link = 3/force(1)%link = 3.25/')"
expect_input_error decks-assur-frame-id-negative '&assur: frame_id: must be a whole number from 0' \
  "$(deck_with frame_neg data/assur_slider_crank.nml 's/frame_id = 0/frame_id = -1/')"
expect_input_error decks-assur-column-huge '&assur: force\(1\)%column: must be a whole number from 1 to 1000000' \
  "$(deck_with col_huge data/assur_slider_crank.nml 's/force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180/force(1)%column = 2147483647, step_values = 13*5/')"

# --- a step so small that 360/dphi overflows an integer: an error naming dphi, not an empty run
expect_input_error decks-dphi-tiny '&pr3207: dphi: too small' "$(deck_with dphi_tiny "$dk_ref" 's/dphi = 30/dphi = 1e-12/')"
expect_input_error decks-assur-dphi-tiny '&assur: dphi: too small' \
  "$(deck_with a_dphi_tiny data/assur_slider_crank.nml 's/dphi = 30/dphi = 1e-300/')"

# --- a NaN typed in the deck is a value (not "not given"), rejected as not finite
expect_input_error decks-nan-optional-g '&pr3207: g: must be a finite number' \
  "$(deck_with g_nan "$dk_ref" 's/g = 9.81/g = nan/')"
expect_input_error decks-nan-payload '&pr3207: phi_start: must be a finite number' \
  "$(deck_with phi_nan "$dk_ref" 's/phi_start = 0/phi_start = NaN(0x1)/')"
expect_input_error decks-nan-n '&pr3207: n: must be a whole number from 1 to 1000000 \(got NaN\)' \
  "$(deck_with n_nan "$dk_ref" 's/dphi = 30/dphi = 30, n = nan/')"
