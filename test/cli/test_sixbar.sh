# Command-line tests of T.FTN (&sixbar) (sourced by tools/test with test/cli/lib.sh).
sx_ref=data/sixbar.nml

# --- golden outputs (data/expected/), compared with numdiff, and proof the comparison can fail
run_ks "$sx_ref"; cp "$out" "$cli_tmp/sixbar.table"
[ "$rc" -eq 0 ] && pass || fail sixbar-table-exit "exit $rc: $(cat "$err")"
expect_same sixbar-golden-table data/expected/sixbar.table "$cli_tmp/sixbar.table"
expect_no_nan sixbar-table-no-nan "$cli_tmp/sixbar.table"
run_ks "$sx_ref" --format csv; cp "$out" "$cli_tmp/sixbar.csv"
expect_same sixbar-golden-csv data/expected/sixbar.csv "$cli_tmp/sixbar.csv"
expect_no_nan sixbar-csv-no-nan "$cli_tmp/sixbar.csv"
sx_header="phi1,F21,F21G,F32,F32G,F43,F43G,F45,F45G,F36,F36G,F16,F16G,F56,M1"
if [ "$(head -1 "$cli_tmp/sixbar.csv")" = "$sx_header" ]; then pass
else fail sixbar-csv-header "header is '$(head -1 "$cli_tmp/sixbar.csv")'"; fi
if [ "$(wc -l <"$cli_tmp/sixbar.csv")" -eq 14 ]; then pass
else fail sixbar-csv-rows "expected 13 steps + header, got $(wc -l <"$cli_tmp/sixbar.csv") lines"; fi
# angles as ATAN2 gives them: every *G column in (-180, 180]
if awk -F, 'NR>1{for(i=3;i<=13;i+=2) if ($i+0 <= -180 || $i+0 > 180) bad=1} END{exit bad}' "$cli_tmp/sixbar.csv"; then pass
else fail sixbar-angles-range "an angle column is outside (-180, 180]"; fi
# perturb one value (M1 at step 2) by 1e-6 relative: the comparison must fail
awk -F, 'BEGIN{OFS=","} NR==3{$15=sprintf("%.12E",$15*(1+1e-6))} {print}' data/expected/sixbar.csv >"$cli_tmp/sx_perturbed.csv"
expect_differ sixbar-golden-csv-can-fail data/expected/sixbar.csv "$cli_tmp/sx_perturbed.csv"
sed '0,/901.929/s//901.930/' data/expected/sixbar.table >"$cli_tmp/sx_perturbed.table"
expect_differ sixbar-golden-table-can-fail data/expected/sixbar.table "$cli_tmp/sx_perturbed.table"

# --- template: a valid deck giving the reference results
run_ks template sixbar; cp "$out" "$cli_tmp/sx_template.nml"
[ "$rc" -eq 0 ] && grep -q '^&sixbar' "$cli_tmp/sx_template.nml" && pass || fail sixbar-template "rc=$rc"
run_ks "$cli_tmp/sx_template.nml" --format csv; cp "$out" "$cli_tmp/sx_template.csv"
expect_same sixbar-template-runs data/expected/sixbar.csv "$cli_tmp/sx_template.csv"

# --- phi_start = the extreme angle written out gives the same as start_at_extreme
run_ks "$(deck_with sx_phi_start "$sx_ref" 's/start_at_extreme = .true., /phi_start = 36.770616366652, /')" --format csv
cp "$out" "$cli_tmp/sx_phi_start.csv"
expect_same sixbar-phi-start-form data/expected/sixbar.csv "$cli_tmp/sx_phi_start.csv"

# --- legacy_eq2: group 2-3 and the crank change, group 4-5 (F43, F45, F56) does not
run_ks "$(deck_with sx_legacy "$sx_ref" 's/^\//  legacy_eq2 = .true.\n\//')" --format csv
cp "$out" "$cli_tmp/sx_legacy.csv"
[ "$rc" -eq 0 ] && pass || fail sixbar-legacy-exit "exit $rc: $(cat "$err")"
expect_differ sixbar-legacy-differs data/expected/sixbar.csv "$cli_tmp/sx_legacy.csv"
cut -d, -f1,6-9,14 data/expected/sixbar.csv >"$cli_tmp/sx_g45.csv"
cut -d, -f1,6-9,14 "$cli_tmp/sx_legacy.csv" >"$cli_tmp/sx_g45_legacy.csv"
expect_same sixbar-legacy-keeps-group-45 "$cli_tmp/sx_g45.csv" "$cli_tmp/sx_g45_legacy.csv"
run_ks "$(deck_with sx_legacy_tab "$sx_ref" 's/^\//  legacy_eq2 = .true.\n\//')"
if grep -Eq 'LEGACY_EQ2 += +T' "$out"; then pass; else fail sixbar-legacy-echo "LEGACY_EQ2 = T not echoed"; fi

# --- geometry errors: exit 3, one line naming the step and its angle, nothing written
expect_input_error sixbar-open-contour1 '&sixbar: step 6 \(phi1 = 150\.0* deg\): contour A-B-C-D cannot be assembled' \
  "$(deck_with sx_open1 "$sx_ref" 's/lam2 = 4/lam2 = 1.6/; s/start_at_extreme = .true., /phi_start = 0, /')" 3
expect_input_error sixbar-open-contour2 '&sixbar: step 1 \(phi1 = 36\.77.* deg\): contour D-E-H cannot be assembled' \
  "$(deck_with sx_open2 "$sx_ref" 's/lam_e = 2.5/lam_e = 5.5/')" 3
expect_input_error sixbar-l1-too-long '&sixbar: start_at_extreme: step 1 \(extreme position\) cannot be assembled' \
  "$(deck_with sx_l1_long "$sx_ref" 's/l1 = 0.100/l1 = 0.2/')" 3
expect_input_error sixbar-l1-too-long-phi-start '&sixbar: step [0-9]+ \(phi1 = [0-9.]+ deg\): contour' \
  "$(deck_with sx_l1_long2 "$sx_ref" 's/l1 = 0.100/l1 = 0.2/; s/start_at_extreme = .true., /phi_start = 0, /')" 3

# --- input errors: exit 2, one line naming deck, group, variable and reason
expect_input_error sixbar-unknown-variable "&sixbar: foo = 1: unknown variable 'foo'" "$(deck_with sx_unknown "$sx_ref" 's/m1 = 50/m1 = 50, foo = 1/')"
expect_input_error sixbar-wrong-type "&sixbar: l1 = abc: 'abc' is not a number" "$(deck_with sx_type "$sx_ref" 's/l1 = 0.100/l1 = abc/')"
expect_input_error sixbar-missing-a '&sixbar: a: missing' "$(deck_with sx_no_a "$sx_ref" 's/a = 0.170, //')"
expect_input_error sixbar-missing-b '&sixbar: b: missing' "$(deck_with sx_no_b "$sx_ref" 's/b = 0.340, //')"
expect_input_error sixbar-d-at-a '&sixbar: b: a and b must not both be 0' "$(deck_with sx_d0 "$sx_ref" 's/a = 0.170, b = 0.340/a = 0, b = 0/')"
expect_input_error sixbar-nan-a '&sixbar: a: must be a finite number' "$(deck_with sx_nan "$sx_ref" 's/a = 0.170/a = NaN/')"
expect_input_error sixbar-zero-l1 '&sixbar: l1: must be > 0' "$(deck_with sx_l1 "$sx_ref" 's/l1 = 0.100/l1 = 0/')"
expect_input_error sixbar-negative-lam2 '&sixbar: lam2: must be > 0' "$(deck_with sx_lam2 "$sx_ref" 's/lam2 = 4/lam2 = -4/')"
expect_input_error sixbar-negative-lam_s2 '&sixbar: lam_s2: must be >= 0' "$(deck_with sx_lams2 "$sx_ref" 's/lam_s2 = 0.5/lam_s2 = -0.5/')"
expect_input_error sixbar-zero-lam3 '&sixbar: lam3: must be > 0' "$(deck_with sx_lam3 "$sx_ref" 's/lam3 = 3/lam3 = 0/')"
expect_input_error sixbar-zero-lam_de '&sixbar: lam_de: must be > 0' "$(deck_with sx_lamde "$sx_ref" 's/lam_de = 3/lam_de = 0/')"
expect_input_error sixbar-zero-lam4 '&sixbar: lam4: must be > 0' "$(deck_with sx_lam4 "$sx_ref" 's/lam4 = 2/lam4 = 0/')"
expect_input_error sixbar-negative-lam_s4 '&sixbar: lam_s4: must be >= 0' "$(deck_with sx_lams4 "$sx_ref" 's/lam_s4 = 0.5/lam_s4 = -1/')"
expect_input_error sixbar-missing-lam_e '&sixbar: lam_e: missing' "$(deck_with sx_lame "$sx_ref" 's/, lam_e = 2.5//')"
expect_input_error sixbar-negative-m2 '&sixbar: m2: must be >= 0' "$(deck_with sx_m2 "$sx_ref" 's/m2 = 5/m2 = -5/')"
expect_input_error sixbar-missing-m5 '&sixbar: m5: missing' "$(deck_with sx_m5 "$sx_ref" 's/, m5 = 6//')"
expect_input_error sixbar-negative-j4 '&sixbar: j4: must be >= 0' "$(deck_with sx_j4 "$sx_ref" 's/j4 = 0.007/j4 = -0.007/')"
expect_input_error sixbar-missing-j1 '&sixbar: j1: missing' "$(deck_with sx_j1 "$sx_ref" 's/j1 = 20, //')"
expect_input_error sixbar-missing-omega1 '&sixbar: omega1: missing' "$(deck_with sx_w "$sx_ref" '/omega1/d')"
expect_input_error sixbar-inf-omega1 '&sixbar: omega1: must be a finite number' "$(deck_with sx_winf "$sx_ref" 's/omega1 = 100/omega1 = Infinity/')"
expect_input_error sixbar-negative-g '&sixbar: g: must be >= 0' "$(deck_with sx_g "$sx_ref" 's/g = 9.81/g = -9.81/')"
expect_input_error sixbar-zero-step '&sixbar: dphi: must be > 0' "$(deck_with sx_dphi "$sx_ref" 's/dphi = 30/dphi = 0/')"
expect_input_error sixbar-no-positions '&sixbar: n: must be a whole number from 1 to 1000000' "$(deck_with sx_n "$sx_ref" 's/n = 13/n = 0/')"
expect_input_error sixbar-both-starts '&sixbar: phi_start: give either' "$(deck_with sx_both "$sx_ref" 's/dphi = 30/phi_start = 10, dphi = 30/')"
expect_input_error sixbar-f5-wrong-length '&sixbar: f5: expected 13 values' "$(deck_with sx_f5len "$sx_ref" 's/f5 = 7\*1000, 6\*0/f5 = 1, 2, 3/')"
expect_input_error sixbar-f5-missing '&sixbar: f5: missing' "$(deck_with sx_f5none "$sx_ref" '/f5 =/d')"
expect_input_error sixbar-f5-gap '&sixbar: f5: values must be given without gaps' "$(deck_with sx_f5gap "$sx_ref" 's/f5 = 7\*1000, 6\*0/f5(1) = 1, f5(3) = 2/')"
expect_input_error sixbar-f5-nan '&sixbar: f5\(2\): must be a finite number' "$(deck_with sx_f5nan "$sx_ref" 's/f5 = 7\*1000, 6\*0/f5 = 1, NaN, 11*0/')"
expect_input_error sixbar-legacy-not-logical '&sixbar: legacy_eq2 = 2.5: 2.5 is not a logical value' "$(deck_with sx_legbad "$sx_ref" 's/^\//  legacy_eq2 = 2.5\n\//')"
expect_input_error sixbar-unterminated '&sixbar: namelist' "$(deck_with sx_unterminated "$sx_ref" '/^\//d')"

# --- the manual's worked example (one position, phi1 = 66.8 deg, g = 10): golden CSV; with
# legacy_eq2 the group 2-3 values move, group 4-5 stays
run_ks data/sixbar_example.nml --format csv; cp "$out" "$cli_tmp/sx_example.csv"
expect_same sixbar-example-golden data/expected/sixbar_example.csv "$cli_tmp/sx_example.csv"
run_ks "$(deck_with sx_example_legacy data/sixbar_example.nml 's/^\//  legacy_eq2 = .true.\n\//')" --format csv
cp "$out" "$cli_tmp/sx_example_legacy.csv"
expect_differ sixbar-example-legacy-differs data/expected/sixbar_example.csv "$cli_tmp/sx_example_legacy.csv"

# --- very large forces print in exponent form (never '*'); overflow is exit 3 naming the quantity
run_ks "$(deck_with sx_big "$sx_ref" 's/m5 = 6 /m5 = 6e6/')"; cp "$out" "$cli_tmp/sx_big.table"
[ "$rc" -eq 0 ] && grep -q 'E+10' "$cli_tmp/sx_big.table" && pass || fail sixbar-big-forces "rc=$rc or no exponent form"
expect_no_nan sixbar-big-forces-no-stars "$cli_tmp/sx_big.table"
expect_input_error sixbar-overflow '&sixbar: step [0-9]+ \(phi1 = .* deg\): M1 is not finite' \
  "$(deck_with sx_overflow "$sx_ref" 's/m5 = 6 /m5 = 1e305/')" 3
