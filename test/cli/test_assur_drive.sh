# Command-line tests of the generic engine's extensions (sourced by tools/test with
# test/cli/lib.sh): linear actuator as driver.

# drive_cols FILE NAME...: the named columns of a CSV file (header + rows), in the given order.
drive_cols() {
  local file="$1"; shift
  awk -F, -v want="$*" 'BEGIN{n=split(want,w," ")}
    NR==1{for(i=1;i<=NF;i++) idx[$i]=i; for(j=1;j<=n;j++) if(!(w[j] in idx)) {print "missing column " w[j] > "/dev/stderr"; exit 1}}
    {line=""; for(j=1;j<=n;j++){ line = line (j>1?",":"") (NR==1? w[j] : $(idx[w[j]])) } print line}' "$file"
}

# --- golden outputs of the PR 3050 generic deck
run_ks data/assur_pr3050.nml; cp "$out" "$cli_tmp/assur_pr3050.table"
[ "$rc" -eq 0 ] && pass || fail assur-pr3050-table-exit "exit $rc: $(cat "$err")"
expect_same assur-pr3050-golden-table data/expected/assur_pr3050.table "$cli_tmp/assur_pr3050.table"
run_ks data/assur_pr3050.nml --format csv; cp "$out" "$cli_tmp/assur_pr3050.csv"
expect_same assur-pr3050-golden-csv data/expected/assur_pr3050.csv "$cli_tmp/assur_pr3050.csv"
expect_no_nan assur-pr3050-csv-no-nan "$cli_tmp/assur_pr3050.csv"
header="$(head -1 "$cli_tmp/assur_pr3050.csv")"
case "$header" in phi1,*,F_drive,stroke,stroke_v,stroke_a) pass ;; *) fail assur-pr3050-csv-drive-columns "header is '$header'" ;; esac
grep -q 'MAX F_drive MISMATCH VS POWER BALANCE .*OK' "$cli_tmp/assur_pr3050.table" && pass ||
  fail assur-pr3050-selfcheck "no F_drive power-balance line with OK"

# --- cross-mechanism: the generic PR 3050 deck reproduces the dedicated program at every step.
# Generic F23 (on rod 2 from rocker 3) is -F32 of pr3050.md: same magnitude, angle + 180;
# phi3rel = phi1 - 43.72; F2 = F_drive. Compared to relative 1e-9 (numdiff, golden tolerances).
to_pr3050_columns() {
  drive_cols "$1" phi1 F14 F14G F34 F34G F23 F23G F_drive |
    awk -F, 'BEGIN{OFS=","} NR==1{print "phi3rel,F14,F14G,F34,F34G,F32,F32G,F2"; next}
      {$1 = sprintf("%.12E", $1 - 43.72); g = $7 + 180; if (g >= 360) g -= 360; $7 = sprintf("%.12E", g); print}'
}
to_pr3050_columns "$cli_tmp/assur_pr3050.csv" >"$cli_tmp/assur_as_pr3050.csv"
run_ks data/pr3050.nml --format csv; cp "$out" "$cli_tmp/dedicated_pr3050.csv"
expect_same assur-pr3050-vs-dedicated-program "$cli_tmp/dedicated_pr3050.csv" "$cli_tmp/assur_as_pr3050.csv"
if [ "$(wc -l <"$cli_tmp/assur_as_pr3050.csv")" -eq 11 ]; then pass; else fail assur-pr3050-rows "expected 10 steps"; fi
# and the comparison can fail: the rod's centre of mass 1 mm further from B must differ
run_ks "$(deck_with pr50_s2 data/assur_pr3050.nml 's/dyad(1)%s3 = 0.48, 0/dyad(1)%s3 = 0.481, 0/')" --format csv
to_pr3050_columns "$out" >"$cli_tmp/assur_as_pr3050_s2.csv"
expect_differ assur-pr3050-comparison-can-fail "$cli_tmp/dedicated_pr3050.csv" "$cli_tmp/assur_as_pr3050_s2.csv"

# --- deck errors of the driver: exit 2, one line naming the variable
p50=data/assur_pr3050.nml
expect_input_error assur-drive-not-prismatic '&assur: drive_pair: pair 1 of dyad 1 \(RPR\) is revolute: a linear actuator drives a prismatic pair; its prismatic pairs: 2' \
  "$(deck_with dr_rev "$p50" 's/drive_pair = 2/drive_pair = 1/')"
expect_input_error assur-drive-rrr '&assur: drive_pair: pair 2 of dyad 1 \(RRR\) is revolute.*has none' \
  "$(deck_with dr_rrr data/assur_sixbar.nml 's/^\//  drive_dyad = 1, drive_pair = 2\n\//')"
expect_input_error assur-drive-pair-missing '&assur: drive_pair: missing' "$(deck_with dr_nop "$p50" 's/, drive_pair = 2//')"
expect_input_error assur-drive-dyad-missing '&assur: drive_dyad: missing' "$(deck_with dr_nod "$p50" 's/drive_dyad = 1, //')"
expect_input_error assur-drive-dyad-range '&assur: drive_dyad: must be a whole number from 1 to 1' \
  "$(deck_with dr_rng "$p50" 's/drive_dyad = 1/drive_dyad = 2/')"
expect_input_error assur-drive-pair-range '&assur: drive_pair: must be a whole number from 1 to 3' \
  "$(deck_with dr_p4 "$p50" 's/drive_pair = 2/drive_pair = 4/')"
# a dead position of the actuator (rocker arm along C-A: stroke' = 0) is a geometry error, exit 3
expect_input_error assur-drive-dead 'step 1 \(phi1 = 0\.0+ deg\): dyad 1 \(RPR, links 1-2\): the actuator \(pair 2\) cannot move the input link' \
  "$(deck_with dr_dead "$p50" 's/phi_start = 43.72/phi_start = 0/')" 3
