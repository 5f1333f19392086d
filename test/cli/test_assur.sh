# Command-line tests of the generic Assur-group engine (sourced by tools/test with test/cli/lib.sh).

# assur_cols FILE NAME...: the named columns of a CSV file (header + rows), in the given order.
assur_cols() {
  local file="$1"; shift
  awk -F, -v want="$*" 'BEGIN{n=split(want,w," ")}
    NR==1{for(i=1;i<=NF;i++) idx[$i]=i; for(j=1;j<=n;j++) if(!(w[j] in idx)) {print "missing column " w[j] > "/dev/stderr"; exit 1}}
    {line=""; for(j=1;j<=n;j++){ line = line (j>1?",":"") (NR==1? w[j] : $(idx[w[j]])) } print line}' "$file"
}

# --- golden outputs of the three generic decks, and proof the comparison can fail
for d in sixbar pr3207 slider_crank; do
  run_ks "data/assur_$d.nml"; cp "$out" "$cli_tmp/assur_$d.table"
  [ "$rc" -eq 0 ] && pass || fail "assur-$d-table-exit" "exit $rc: $(cat "$err")"
  expect_same "assur-$d-golden-table" "data/expected/assur_$d.table" "$cli_tmp/assur_$d.table"
  expect_no_nan "assur-$d-table-no-nan" "$cli_tmp/assur_$d.table"
  run_ks "data/assur_$d.nml" --format csv; cp "$out" "$cli_tmp/assur_$d.csv"
  expect_same "assur-$d-golden-csv" "data/expected/assur_$d.csv" "$cli_tmp/assur_$d.csv"
  expect_no_nan "assur-$d-csv-no-nan" "$cli_tmp/assur_$d.csv"
  header="$(head -1 "$cli_tmp/assur_$d.csv")"
  case "$header" in phi1,*,M1) pass ;; *) fail "assur-$d-csv-phi1-M1" "header is '$header'" ;; esac
done
awk -F, 'BEGIN{OFS=","} NR==3{$NF=sprintf("%.12E",$NF*(1+1e-6))} {print}' data/expected/assur_sixbar.csv >"$cli_tmp/assur_perturbed.csv"
expect_differ assur-golden-csv-can-fail data/expected/assur_sixbar.csv "$cli_tmp/assur_perturbed.csv"
sed '0,/26767.95/s//26767.96/' data/expected/assur_sixbar.table >"$cli_tmp/assur_perturbed.table"
expect_differ assur-golden-table-can-fail data/expected/assur_sixbar.table "$cli_tmp/assur_perturbed.table"

# --- cross-mechanism: the generic PR 3207 deck reproduces the dedicated program at every step.
# Generic pair F43 (on block 4 from the lever) is -F34 of pr3207.md: same magnitude, angle + 180.
to_pr3207_columns() {
  assur_cols "$1" phi1 F16 F16G F21 F21G F36 F36G F43 F43G F56 F56G M1 |
    awk -F, 'BEGIN{OFS=","} NR==1{$8="F34"; $9="F34G"; print; next}
      {g = $9 + 180; if (g >= 360) g -= 360; if ($8 + 0 == 0) g = 0; $9 = sprintf("%.12E", g); print}'
}
to_pr3207_columns "$cli_tmp/assur_pr3207.csv" >"$cli_tmp/assur_as_pr3207.csv"
run_ks data/pr3207.nml --format csv; cp "$out" "$cli_tmp/dedicated_pr3207.csv"
expect_same assur-pr3207-vs-dedicated-program "$cli_tmp/dedicated_pr3207.csv" "$cli_tmp/assur_as_pr3207.csv"
expect_same assur-pr3207-vs-dedicated-golden data/expected/pr3207.csv "$cli_tmp/assur_as_pr3207.csv"
if [ "$(wc -l <"$cli_tmp/assur_as_pr3207.csv")" -eq 14 ]; then pass; else fail assur-pr3207-rows "expected 13 steps"; fi
# and the comparison can fail: a generic deck with a different lever mass must differ
run_ks "$(deck_with pr_m3 data/assur_pr3207.nml 's/dyad(1)%m3 = 22/dyad(1)%m3 = 22.001/')" --format csv
to_pr3207_columns "$out" >"$cli_tmp/assur_as_pr3207_m3.csv"
expect_differ assur-pr3207-comparison-can-fail "$cli_tmp/dedicated_pr3207.csv" "$cli_tmp/assur_as_pr3207_m3.csv"

# --- cross-mechanism: the generic six-bar deck reproduces the dedicated T.FTN program at every
# step (same pair names and angle frames as sixbar.md; the signed slider force is column F56N).
to_sixbar_columns() {
  assur_cols "$1" phi1 F21 F21G F32 F32G F43 F43G F45 F45G F36 F36G F16 F16G F56N M1 | sed '1s/F56N/F56/'
}
to_sixbar_columns "$cli_tmp/assur_sixbar.csv" >"$cli_tmp/assur_as_sixbar.csv"
run_ks data/sixbar.nml --format csv; cp "$out" "$cli_tmp/dedicated_sixbar.csv"
expect_same assur-sixbar-vs-dedicated-program "$cli_tmp/dedicated_sixbar.csv" "$cli_tmp/assur_as_sixbar.csv"
expect_same assur-sixbar-vs-dedicated-golden data/expected/sixbar.csv "$cli_tmp/assur_as_sixbar.csv"
if [ "$(wc -l <"$cli_tmp/assur_as_sixbar.csv")" -eq 14 ]; then pass; else fail assur-sixbar-rows "expected 13 steps"; fi
# and the comparison can fail: a generic deck with a heavier slider must differ
run_ks "$(deck_with sb_m5 data/assur_sixbar.nml 's/dyad(2)%m3 = 6,/dyad(2)%m3 = 6.001,/')" --format csv
to_sixbar_columns "$out" >"$cli_tmp/assur_as_sixbar_m5.csv"
expect_differ assur-sixbar-comparison-can-fail "$cli_tmp/dedicated_sixbar.csv" "$cli_tmp/assur_as_sixbar_m5.csv"

# --- template: a valid deck (the slider-crank) giving the golden results
run_ks template assur; cp "$out" "$cli_tmp/assur_template.nml"
[ "$rc" -eq 0 ] && grep -q '^&assur' "$cli_tmp/assur_template.nml" && pass || fail assur-template "rc=$rc"
run_ks "$cli_tmp/assur_template.nml" --format csv; cp "$out" "$cli_tmp/assur_template.csv"
expect_same assur-template-runs data/expected/assur_slider_crank.csv "$cli_tmp/assur_template.csv"

# --- the per-step table form of a force equals the window form (sixbar: 7 x 1000 N, 6 x 0)
run_ks "$(deck_with six_window data/assur_sixbar.nml 's/force(1)%column = 1/force(1)%value = 1000, force(1)%phi_on = 0, force(1)%phi_off = 220/; /step_values/d')" --format csv
cp "$out" "$cli_tmp/six_window.csv"
expect_same assur-window-equals-table data/expected/assur_sixbar.csv "$cli_tmp/six_window.csv"
# -o FILE works and leaves no temporary
rm -f "$cli_tmp/assur_o.csv"
run_ks data/assur_sixbar.nml --format csv -o "$cli_tmp/assur_o.csv"
if [ "$rc" -eq 0 ] && cmp -s "$cli_tmp/assur_o.csv" "$cli_tmp/assur_sixbar.csv" && ! ls "$cli_tmp"/assur_o.csv.tmp.* >/dev/null 2>&1; then pass
else fail assur-output-file "rc=$rc or file differs or temporary left"; fi

# --- geometry errors: exit 3, one line naming the step and the input angle, no file, no NaN
expect_input_error assur-toggle 'step 2 \(phi1 = 0\.0+ deg\): dyad 1 \(RRR, links 2-3\): dead \(toggle\) position' \
  data/assur_toggle.nml 3
expect_input_error assur-cannot-assemble 'step 3 \(phi1 = 60\.0+ deg\): dyad 1 \(RRP, links 2-3\): cannot be assembled' \
  "$(deck_with short_rod data/assur_slider_crank.nml 's/dyad(1)%l2 = 0.35/dyad(1)%l2 = 0.05/')" 3
expect_input_error assur-rpp-parallel-slot '&assur: dyad\(2\)%slot_angle: must not be parallel' \
  "$(deck_with slot_par data/assur_pr3207.nml 's/slot_angle = -90/slot_angle = 180/')"

# --- input errors: exit 2, one line naming deck, group, variable and reason
sc=data/assur_slider_crank.nml
expect_input_error assur-unknown-variable "&assur: dyad\(1\)%foo = 1: unknown variable 'dyad\(1\)%foo'" "$(deck_with a_unk "$sc" 's/dyad(1)%mode = 1/dyad(1)%mode = 1, dyad(1)%foo = 1/')"
expect_input_error assur-wrong-type "&assur: dyad\(1\)%l2 = abc: 'abc' is not a number" "$(deck_with a_type "$sc" 's/dyad(1)%l2 = 0.35/dyad(1)%l2 = abc/')"
expect_input_error assur-too-many-dyads '&assur: dyad\(17\): at most 16 dyads$' "$(deck_with a_many "$sc" 's/dyad(1)%mode = 1/dyad(1)%mode = 1, dyad(17)%kind = 1/')"
expect_input_error assur-kind '&assur: dyad\(1\)%kind: must be 1\.\.5' "$(deck_with a_kind "$sc" 's/dyad(1)%kind = 2/dyad(1)%kind = 7/')"
# a kind given by a name that is none of the kinds: the names are listed (not "a number is expected")
expect_input_error assur-kind-name-unknown "^kinetostat: error: [^ ]*:[0-9]+: &assur: dyad\(1\)%kind = 'RRS': unknown kind 'RRS' \(a dyad's kind is RRR, RRP, RPR, PRP or RPP, or its number 1 to 5\)$" "$(deck_with a_rrs "$sc" "s/dyad(1)%kind = 2/dyad(1)%kind = 'RRS'/")"
expect_input_error assur-kind-word-unknown "&assur: dyad\(1\)%kind = rrx: unknown kind 'rrx' \(a dyad's kind is RRR" "$(deck_with a_rrx "$sc" "s/dyad(1)%kind = 2/dyad(1)%kind = rrx/")"
run_ks "$sc" --set "dyad(1)%kind='RRS'"
if [ "$rc" -eq 2 ] && grep -q "^kinetostat: error: --set dyad(1)%kind='RRS': &assur: dyad(1)%kind = 'RRS': unknown kind 'RRS' (a dyad's kind is RRR, RRP, RPR, PRP or RPP" "$err"; then pass
else fail assur-kind-name-set "exit $rc: $(cat "$err")"; fi
# a crank_id or frame_id that no dyad hangs on is blamed on crank_id / frame_id, not on the dyad
expect_input_error assur-crank-id-unused "&assur: crank_id: no dyad hangs on link 1000 \(the crank\), and dyad\(1\)%on2 names link 1, which no one defines: is the crank link 1\?" "$(deck_with a_c1000 "$sc" "s/crank_id = 1 /crank_id = 1000 /")"
expect_input_error assur-frame-id-unused "&assur: frame_id: no dyad hangs on link 7 \(the frame\), and dyad\(1\)%on3 names link 6, which no one defines" "$(deck_with a_f7 data/assur_pr3207.nml "s/frame_id = 6,/frame_id = 7,/")"
expect_input_error assur-no-dyad '&assur: dyad: at least one dyad' "$(deck_with a_nod "$sc" 's/dyad(1)%kind = 2, //')"
expect_input_error assur-dyad-gap '&assur: dyad\(3\): dyads must be numbered' "$(deck_with a_gap "$sc" 's/dyad(1)%mode = 1/dyad(1)%mode = 1, dyad(3)%l2 = 1/')"
expect_input_error assur-missing-l2 '&assur: dyad\(1\)%l2: missing' "$(deck_with a_l2 "$sc" 's/dyad(1)%l2 = 0.35, //')"
expect_input_error assur-negative-l2 '&assur: dyad\(1\)%l2: must be > 0' "$(deck_with a_l2n "$sc" 's/dyad(1)%l2 = 0.35/dyad(1)%l2 = -0.35/')"
expect_input_error assur-nan-l2 '&assur: dyad\(1\)%l2: must be a finite number' "$(deck_with a_l2nan "$sc" 's/dyad(1)%l2 = 0.35/dyad(1)%l2 = NaN/')"
expect_input_error assur-unused-l3 '&assur: dyad\(1\)%l3: not used by this dyad \(kind RRP\)' "$(deck_with a_l3 "$sc" 's/dyad(1)%l2 = 0.35/dyad(1)%l2 = 0.35, dyad(1)%l3 = 0.2/')"
expect_input_error assur-mode '&assur: dyad\(1\)%mode: must be \+1 or -1' "$(deck_with a_mode "$sc" 's/dyad(1)%mode = 1/dyad(1)%mode = 2/')"
expect_input_error assur-on-later-link '&assur: dyad\(1\)%on2: link 3 is not the frame, the crank or a link of an earlier dyad' "$(deck_with a_on "$sc" 's/dyad(1)%on2 = 1/dyad(1)%on2 = 3/')"
expect_input_error assur-duplicate-id '&assur: dyad\(1\)%link2: link number 1 must be' "$(deck_with a_dup "$sc" 's/dyad(1)%link2 = 2/dyad(1)%link2 = 1/')"
expect_input_error assur-missing-at3 '&assur: dyad\(1\)%at3: missing' "$(deck_with a_at3 "$sc" 's/dyad(1)%at3 = 0, 0.02 //')"
expect_input_error assur-at2-one-value '&assur: dyad\(1\)%at2: needs two values' "$(deck_with a_at2 "$sc" 's/dyad(1)%at2 = 0.1, 0 /dyad(1)%at2 = 0.1 /')"
expect_input_error assur-missing-angle3 '&assur: dyad\(1\)%angle3: missing' "$(deck_with a_ang "$sc" '/dyad(1)%angle3/d')"
expect_input_error assur-negative-mass '&assur: dyad\(1\)%m2: must be >= 0' "$(deck_with a_m2 "$sc" 's/dyad(1)%m2 = 1.5/dyad(1)%m2 = -1.5/')"
expect_input_error assur-negative-j '&assur: dyad\(1\)%j3: must be >= 0' "$(deck_with a_j3 "$sc" 's/dyad(1)%j3 = 0/dyad(1)%j3 = -1/')"
expect_input_error assur-negative-crank-mass '&assur: crank_m: must be >= 0' "$(deck_with a_cm "$sc" 's/crank_m = 2.0/crank_m = -2.0/')"
expect_input_error assur-missing-omega1 '&assur: omega1: missing' "$(deck_with a_w "$sc" '/omega1 = 50/d')"
expect_input_error assur-omega-both '&assur: omega1: give either omega1' "$(deck_with a_wb "$sc" 's/omega1 = 50 /omega1 = 50, omega1_step = 13*50, eps1_step = 13*0 /')"
expect_input_error assur-omega-step-length '&assur: omega1_step: expected 13 values' "$(deck_with a_wl "$sc" 's/omega1 = 50 /omega1_step = 12*50, eps1_step = 13*0 /')"
expect_input_error assur-eps-step-missing '&assur: eps1_step: expected 13 values \(one per step\), got 0' "$(deck_with a_el "$sc" 's/omega1 = 50 /omega1_step = 13*50 /')"
expect_input_error assur-zero-step '&assur: dphi: must be > 0' "$(deck_with a_dphi "$sc" 's/dphi = 30/dphi = 0/')"
expect_input_error assur-negative-g '&assur: g: must be >= 0' "$(deck_with a_g "$sc" 's/g = 9.81/g = -9.81/')"
expect_input_error assur-crank-id '&assur: crank_id: must be >= 0 and differ from frame_id' "$(deck_with a_cid "$sc" 's/crank_id = 1/crank_id = 0/')"
expect_input_error assur-force-link '&assur: force\(1\)%link: link 7 is not a moving link' "$(deck_with a_fl "$sc" 's/force(1)%link = 3/force(1)%link = 7/')"
expect_input_error assur-force-frame '&assur: force\(1\)%link: link 0 is not a moving link' "$(deck_with a_ff "$sc" 's/force(1)%link = 3/force(1)%link = 0/')"
expect_input_error assur-force-angle '&assur: force\(1\)%angle: missing' "$(deck_with a_fa "$sc" 's/, force(1)%angle = 180//')"
expect_input_error assur-force-value '&assur: force\(1\)%value: missing' "$(deck_with a_fv "$sc" 's/force(1)%value = 500, //')"
expect_input_error assur-force-window '&assur: force\(1\)%phi_off: must be >= phi_on' "$(deck_with a_fw "$sc" 's/force(1)%phi_off = 180/force(1)%phi_off = -10/')"
expect_input_error assur-force-window-half '&assur: force\(1\)%phi_off: missing' "$(deck_with a_fh "$sc" 's/, force(1)%phi_off = 180//')"
expect_input_error assur-force-column-and-value '&assur: force\(1\)%column: give either column' "$(deck_with a_fc "$sc" 's/force(1)%value = 500/force(1)%column = 1, force(1)%value = 500/')"
expect_input_error assur-force-column-short '&assur: force\(1\)%column: step_values has 12 values' "$(deck_with a_fs "$sc" 's/force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180/force(1)%column = 1, step_values = 12*5/')"
expect_input_error assur-force-gap '&assur: force\(2\)%link: missing \(forces must be numbered without gaps\)$' "$(deck_with a_fg "$sc" 's/force(1)%link = 3/force(2)%value = 1, force(2)%angle = 0, force(1)%link = 3/')"
expect_input_error assur-moment-link '&assur: moment\(1\)%link: link 9 is not a moving link' "$(deck_with a_ml "$sc" 's/force(1)%link = 3/moment(1)%link = 9, moment(1)%value = 1, force(1)%link = 3/')"
expect_input_error assur-unterminated '&assur: namelist' "$(deck_with a_unt "$sc" '/^\//d')"

# --- prescribed speed law: omega1_step/eps1_step with constant values equal the constant form
run_ks "$(deck_with a_law "$sc" 's/omega1 = 50 /omega1_step = 13*50, eps1_step = 13*0 /')" --format csv
cp "$out" "$cli_tmp/assur_law.csv"
expect_same assur-prescribed-constant-law data/expected/assur_slider_crank.csv "$cli_tmp/assur_law.csv"
run_ks "$(deck_with a_law2 "$sc" 's/omega1 = 50 /omega1_step = 13*50, eps1_step = 13*400 /')"
if [ "$rc" -eq 0 ] && grep -q 'MISMATCH VS POWER BALANCE .*OK' "$out"; then pass
else fail assur-prescribed-eps-selfcheck "rc=$rc, self-check not OK"; fi

# --- inner_on: which link the reported inner-pair force acts on (names F32 instead of F23)
expect_input_error assur-inner-on '&assur: dyad\(1\)%inner_on: must be link2 \(2\) or link3 \(3\), got 5' "$(deck_with a_in "$sc" 's/dyad(1)%mode = 1/dyad(1)%mode = 1, dyad(1)%inner_on = 5/')"
run_ks "$(deck_with a_in23 data/assur_sixbar.nml '/inner_on/d')" --format csv
cp "$out" "$cli_tmp/six_f23.csv"
# F23 = -F32: same magnitude, opposite components
paste -d, <(assur_cols "$cli_tmp/six_f23.csv" F23 F23x F23y | tail -n +2) \
          <(assur_cols data/expected/assur_sixbar.csv F32 F32x F32y | tail -n +2) |
  awk -F, '{ if ($1 != $4 || $2 + $5 != 0 || $3 + $6 != 0) bad = 1 } END { exit bad }' && pass ||
  fail assur-inner-on-sense "F23 is not -F32"
