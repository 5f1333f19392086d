# Command-line tests of PR 3207 (sourced by tools/test with test/cli/lib.sh).
ref=data/pr3207.nml

# --- golden outputs (data/expected/), compared with numdiff, and proof the comparison can fail
run_ks "$ref"; cp "$out" "$cli_tmp/pr3207.table"
[ "$rc" -eq 0 ] && pass || fail pr3207-table-exit "exit $rc: $(cat "$err")"
expect_same pr3207-golden-table data/expected/pr3207.table "$cli_tmp/pr3207.table"
expect_no_nan pr3207-table-no-nan "$cli_tmp/pr3207.table"
run_ks "$ref" --format csv; cp "$out" "$cli_tmp/pr3207.csv"
expect_same pr3207-golden-csv data/expected/pr3207.csv "$cli_tmp/pr3207.csv"
expect_no_nan pr3207-csv-no-nan "$cli_tmp/pr3207.csv"
if [ "$(head -1 "$cli_tmp/pr3207.csv")" = "phi1,F16,F16G,F21,F21G,F36,F36G,F34,F34G,F56,F56G,M1" ]; then pass
else fail pr3207-csv-header "header is '$(head -1 "$cli_tmp/pr3207.csv")'"; fi
# perturb one value (M1 at phi1 = 30 deg) by 1e-6 relative: the comparison must fail
awk -F, 'BEGIN{OFS=","} NR==3{$12=sprintf("%.12E",$12*(1+1e-6))} {print}' data/expected/pr3207.csv >"$cli_tmp/perturbed.csv"
expect_differ pr3207-golden-csv-can-fail data/expected/pr3207.csv "$cli_tmp/perturbed.csv"
sed '0,/588.60/s//588.61/' data/expected/pr3207.table >"$cli_tmp/perturbed.table"
expect_differ pr3207-golden-table-can-fail data/expected/pr3207.table "$cli_tmp/perturbed.table"

# --- -o FILE: same bytes as stdout, no temporary left behind
rm -f "$cli_tmp/o.csv"
run_ks "$ref" --format csv -o "$cli_tmp/o.csv"
if [ "$rc" -eq 0 ] && cmp -s "$cli_tmp/o.csv" "$cli_tmp/pr3207.csv" && ! ls "$cli_tmp"/o.csv.tmp.* >/dev/null 2>&1; then pass
else fail pr3207-output-file "rc=$rc or file differs from stdout or temporary left"; fi
# an error never replaces an existing output file
echo "previous" >"$cli_tmp/keep.out"
run_ks "$(deck_with bad_keep "$ref" 's/l_ab = 0.11/l_ab = -1/')" -o "$cli_tmp/keep.out"
if [ "$rc" -eq 2 ] && [ "$(cat "$cli_tmp/keep.out")" = "previous" ]; then pass
else fail pr3207-error-keeps-old-file "rc=$rc, file now: $(head -c 100 "$cli_tmp/keep.out")"; fi

# --- template: valid deck giving the reference results
run_ks template pr3207; cp "$out" "$cli_tmp/template.nml"
[ "$rc" -eq 0 ] && grep -q '^&pr3207' "$cli_tmp/template.nml" && pass || fail pr3207-template "rc=$rc"
run_ks "$cli_tmp/template.nml" --format csv; cp "$out" "$cli_tmp/template.csv"
expect_same pr3207-template-runs data/expected/pr3207.csv "$cli_tmp/template.csv"

# --- per-step f5c array form gives the same as the equivalent two-value form
f5c_list="0, 0, 0, 0, 3000, 3000, 3000, 3000, 3000, 0, 0, 0, 0"
run_ks "$(deck_with array_form "$ref" "s/f5c_work = 3000, f5c_idle = 0/f5c = $f5c_list/; /phi_cut_start/d")" --format csv
cp "$out" "$cli_tmp/array.csv"
expect_same pr3207-array-form data/expected/pr3207.csv "$cli_tmp/array.csv"

# --- usage errors: exit 1
expect_exit usage-no-args 1
expect_exit usage-bad-option 1 "$ref" --bogus
expect_exit usage-bad-format 1 "$ref" --format xml
expect_exit usage-template-unknown 1 template nosuch
expect_exit usage-two-decks 1 "$ref" "$ref"
expect_exit help 0 --help
expect_exit version 0 --version

# --- input errors: exit 2, one line naming deck, group, variable and reason
expect_input_error deck-missing-file 'cannot open deck' "$cli_tmp/no_such.nml"
printf '&nosuch\n x = 1\n/\n' >"$cli_tmp/unknown_group.nml"
expect_input_error unknown-mechanism '&nosuch: unknown mechanism' "$cli_tmp/unknown_group.nml"
expect_input_error unknown-variable "&pr3207: foo = 1: unknown variable 'foo'" "$(deck_with unknown_var "$ref" 's/m1 = 12/m1 = 12, foo = 1/')"
expect_input_error wrong-type "&pr3207: l_ab = abc: 'abc' is not a number" "$(deck_with wrong_type "$ref" 's/l_ab = 0.11/l_ab = abc/')"
expect_input_error missing-l_ab '&pr3207: l_ab: missing' "$(deck_with missing "$ref" 's/l_ab = 0.11, //')"
expect_input_error missing-omega1 '&pr3207: omega1: missing' "$(deck_with missing_w "$ref" '/omega1/d')"
expect_input_error nan-l_ac '&pr3207: l_ac: must be a finite number' "$(deck_with nan "$ref" 's/l_ac = 0.38/l_ac = NaN/')"
expect_input_error inf-omega1 '&pr3207: omega1: must be a finite number' "$(deck_with inf "$ref" 's/omega1 = 7.5/omega1 = Infinity/')"
expect_input_error zero-l_ab '&pr3207: l_ab: must be > 0' "$(deck_with zero_ab "$ref" 's/l_ab = 0.11/l_ab = 0/')"
expect_input_error negative-l_cd '&pr3207: l_cd: must be > 0' "$(deck_with neg_cd "$ref" 's/l_cd = 0.72/l_cd = -0.72/')"
expect_input_error negative-l_cs3 '&pr3207: l_cs3: must be >= 0' "$(deck_with neg_cs3 "$ref" 's/l_cs3 = 0.36/l_cs3 = -0.1/')"
expect_input_error negative-m3 '&pr3207: m3: must be >= 0' "$(deck_with neg_m3 "$ref" 's/m3 = 22/m3 = -22/')"
expect_input_error negative-j3 '&pr3207: j3: must be >= 0' "$(deck_with neg_j3 "$ref" 's/j3 = 1.1/j3 = -1.1/')"
expect_input_error negative-g '&pr3207: g: must be >= 0' "$(deck_with neg_g "$ref" 's/g = 9.81/g = -9.81/')"
expect_input_error l_ab-ge-l_ac '&pr3207: l_ab: must be < l_ac' "$(deck_with ab_ac "$ref" 's/l_ab = 0.11/l_ab = 0.38/')"
expect_input_error l_cd-too-short '&pr3207: l_cd: must be > l_ac \+ l_ab' "$(deck_with cd_short "$ref" 's/l_cd = 0.72/l_cd = 0.49/')"
expect_input_error zero-step '&pr3207: dphi: must be > 0' "$(deck_with zero_step "$ref" 's/dphi = 30/dphi = 0/')"
expect_input_error no-positions '&pr3207: n: must be a whole number from 1 to 1000000' "$(deck_with no_pos "$ref" 's/dphi = 30/dphi = 30, n = 0/')"
expect_input_error f5c-wrong-length '&pr3207: f5c: expected 13 values' "$(deck_with f5c_len "$ref" 's/f5c_work = 3000, f5c_idle = 0/f5c = 1, 2, 3/; /phi_cut_start/d')"
expect_input_error f5c-gap '&pr3207: f5c: values must be given without gaps' "$(deck_with f5c_gap "$ref" 's/f5c_work = 3000, f5c_idle = 0/f5c(1) = 1, f5c(3) = 2/; /phi_cut_start/d')"
expect_input_error f5c-both-forms '&pr3207: f5c: give either' "$(deck_with f5c_both "$ref" 's/f5c_idle = 0/f5c_idle = 0, f5c = 1/')"
expect_input_error f5c-neither '&pr3207: f5c: missing' "$(deck_with f5c_none "$ref" '/f5c_work/d; /phi_cut_start/d')"
expect_input_error f5c-cut-missing '&pr3207: phi_cut_end: missing' "$(deck_with cut_missing "$ref" 's/, phi_cut_end = 265//')"
expect_input_error unterminated '&pr3207: namelist' "$(deck_with unterminated "$ref" '/^\//d')"

# --- success prints no self-check warning on the reference deck; its only remark is the
# coarse step (30 deg) next to the cutting force's switch, gone at dphi = 1
run_ks "$ref"
if [ "$rc" -eq 0 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q 'input step 30 deg is coarser than 5 deg' "$err"; then pass
else fail pr3207-quiet-success "rc=$rc stderr: $(head -c 200 "$err")"; fi
run_ks "$ref" --set dphi=1
if [ "$rc" -eq 0 ] && [ ! -s "$err" ]; then pass; else fail pr3207-quiet-success-fine "rc=$rc stderr: $(head -c 200 "$err")"; fi
