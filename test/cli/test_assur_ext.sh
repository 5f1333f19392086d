# Command-line tests of the generic engine's extensions (sourced by tools/test with
# test/cli/lib.sh): linear actuator as driver, crank angle lists (rocking inputs), start at the
# extreme position, loads by components and tables over a link's position, the global
# coordinates deck form.

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

# --- crank angle lists: a rocking input (up 0..180, down 150..0) equals two monotonic runs,
# with a prescribed law where the speed's sign matters (eps1 = 40 rad/s^2 everywhere)
sc=data/assur_slider_crank.nml
up='phi1 = 0, 30, 60, 90, 120, 150, 180, omega1_step = 7*10, eps1_step = 7*40'
down='phi1 = 150, 120, 90, 60, 30, 0, omega1_step = 6*-10, eps1_step = 6*40'
rock='phi1 = 0, 30, 60, 90, 120, 150, 180, 150, 120, 90, 60, 30, 0, omega1_step = 7*10, 6*-10, eps1_step = 13*40'
no_steps='s/phi_start = 0, dphi = 30 /'
run_ks "$(deck_with rk_up "$sc" "${no_steps}$up/; s/omega1 = 50 //")" --format csv; cp "$out" "$cli_tmp/rk_up.csv"
[ "$rc" -eq 0 ] && pass || fail assur-list-up "exit $rc: $(cat "$err")"
run_ks "$(deck_with rk_down "$sc" "${no_steps}$down/; s/omega1 = 50 //")" --format csv; cp "$out" "$cli_tmp/rk_down.csv"
run_ks "$(deck_with rk_rock "$sc" "${no_steps}$rock/; s/omega1 = 50 //")" --format csv; cp "$out" "$cli_tmp/rk_rock.csv"
{ cat "$cli_tmp/rk_up.csv"; tail -n +2 "$cli_tmp/rk_down.csv"; } >"$cli_tmp/rk_two_runs.csv"
if [ "$(wc -l <"$cli_tmp/rk_rock.csv")" -eq 14 ]; then pass; else fail assur-rocking-rows "expected 13 steps"; fi
expect_same assur-rocking-equals-two-runs "$cli_tmp/rk_two_runs.csv" "$cli_tmp/rk_rock.csv"
# the comparison can fail: the down run with eps1 = -40 differs
run_ks "$(deck_with rk_wrong "$sc" "${no_steps}${down/6\*40/6*-40}/; s/omega1 = 50 //")" --format csv
{ cat "$cli_tmp/rk_up.csv"; tail -n +2 "$out"; } >"$cli_tmp/rk_wrong.csv"
expect_differ assur-rocking-comparison-can-fail "$cli_tmp/rk_wrong.csv" "$cli_tmp/rk_rock.csv"
# (the sign of omega1 itself changes no frictionless force: accelerations go with omega1^2
# and eps1; it shows in velocities, e.g. an actuator's stroke speed:) the PR 3050 deck rocked
# up and down at constant omega1 = 0.5 equals its two monotonic runs, stroke_v < 0 going down (from the first step after the turning point)
p50=data/assur_pr3050.nml
p50_steps='s/phi_start = 43.72, dphi = 5, n = 10/'
p50_law='/omega1_step/d; /eps1_step/d'
run_ks "$(deck_with pk_up "$p50" "${p50_steps}phi1 = 43.72, 53.72, 63.72, omega1 = 0.5/; $p50_law")" --format csv
cp "$out" "$cli_tmp/pk_up.csv"
run_ks "$(deck_with pk_down "$p50" "${p50_steps}phi1 = 58.72, 48.72, omega1 = 0.5/; $p50_law")" --format csv
cp "$out" "$cli_tmp/pk_down.csv"
run_ks "$(deck_with pk_rock "$p50" "${p50_steps}phi1 = 43.72, 53.72, 63.72, 58.72, 48.72, omega1 = 0.5/; $p50_law")" --format csv
cp "$out" "$cli_tmp/pk_rock.csv"
{ cat "$cli_tmp/pk_up.csv"; tail -n +2 "$cli_tmp/pk_down.csv"; } >"$cli_tmp/pk_two_runs.csv"
expect_same assur-actuator-rocking-equals-two-runs "$cli_tmp/pk_two_runs.csv" "$cli_tmp/pk_rock.csv"
drive_cols "$cli_tmp/pk_rock.csv" stroke_v | tail -n +2 | tr '\n' ' ' |
  awk '{ exit !($1 > 0 && $2 > 0 && $3 > 0 && $4 < 0 && $5 < 0) }' && pass ||
  fail assur-actuator-rocking-stroke-speed "stroke_v signs are not + + + - - (the turning point is reached going up): $(drive_cols "$cli_tmp/pk_rock.csv" stroke_v | tr '\n' ' ')"
# the monotonic list equals phi_start/dphi: the up run against steps 1-7 of the golden form
run_ks "$(deck_with rk_up2 "$sc" 's/phi_start = 0, dphi = 30 /phi_start = 0, dphi = 30, n = 7 /; s/omega1 = 50 /omega1_step = 7*10, eps1_step = 7*40 /')" --format csv
expect_same assur-list-equals-start-step "$out" "$cli_tmp/rk_up.csv"
# a list with constant omega1: the speed's sign is that of the move that reached the step
# (+ up to the turning point 180, - after it)
run_ks "$(deck_with rk_const "$sc" "${no_steps}phi1 = 0, 30, 60, 90, 120, 150, 180, 150, 120, 90, 60, 30, 0 /")"
grep -A3 'OMEGA1_STEP(13)' "$out" | tr -s ' ' '\n' | grep -E '^-?[0-9]' >"$cli_tmp/rk_signs.txt"
if [ "$(grep -c '^5' "$cli_tmp/rk_signs.txt")" -eq 7 ] && [ "$(grep -c '^-5' "$cli_tmp/rk_signs.txt")" -eq 6 ]; then pass
else fail assur-list-omega-sign "OMEGA1_STEP echo is not 7 x 50, 6 x -50: $(tr '\n' ' ' <"$cli_tmp/rk_signs.txt")"; fi
expect_input_error assur-list-and-step '&assur: phi1: give either phi1\(:\)' "$(deck_with rk_both "$sc" 's/dphi = 30 /dphi = 30, phi1 = 0, 10 /')"
expect_input_error assur-list-gap '&assur: phi1: values must be given without gaps' "$(deck_with rk_gap "$sc" "${no_steps}phi1(1) = 0, phi1(3) = 10 /")"
expect_input_error assur-list-omega-steps '&assur: omega1_step: expected 3 values' \
  "$(deck_with rk_wn "$sc" "${no_steps}phi1 = 0, 10, 20, omega1_step = 13*50, eps1_step = 3*0 /; s/omega1 = 50 //")"

# --- start_at = 'extreme': the generic six-bar finds T.FTN's extreme position itself
six=data/assur_sixbar.nml
run_ks "$(deck_with six_ext "$six" "s/phi_start = 36.77061636665199, dphi = 30/start_at = 'extreme', dphi = 30/")" --format csv
cp "$out" "$cli_tmp/six_ext.csv"
expect_same assur-start-at-extreme-sixbar data/expected/assur_sixbar.csv "$cli_tmp/six_ext.csv"
# the rocker 3 as output link has the same extreme position
run_ks "$(deck_with six_ext3 "$six" "s/phi_start = 36.77061636665199, dphi = 30/start_at = 'extreme', output_link = 3, dphi = 30/")" --format csv
expect_same assur-start-at-extreme-rocker data/expected/assur_sixbar.csv "$out"
# and the comparison can fail: starting the search past it finds the other extreme
run_ks "$(deck_with six_ext2 "$six" "s/phi_start = 36.77061636665199, dphi = 30/start_at = 'extreme', phi_start = 40, dphi = 30/")" --format csv
expect_differ assur-start-at-extreme-can-fail data/expected/assur_sixbar.csv "$out"
expect_input_error assur-start-at-value "&assur: start_at: must be 'extreme'" "$(deck_with se_bad "$six" "s/dphi = 30/start_at = 'outer', dphi = 30/")"
expect_input_error assur-start-at-and-list '&assur: phi1: give either phi1' "$(deck_with se_list "$six" "s/phi_start = 36.77061636665199, dphi = 30, n = 13/start_at = 'extreme', phi1 = 0, 30/; s/step_values = 7\*1000, 6\*0/step_values = 2*1000/")"
expect_input_error assur-output-link '&assur: output_link: link 9 is not a moving link' "$(deck_with se_ol "$six" "s/dphi = 30/output_link = 9, dphi = 30/")"
# the crank as output link has no extreme position: geometry error, exit 3
expect_input_error assur-no-extreme "&assur: start_at: no extreme position of link 1 \(the output link\)" \
  "$(deck_with se_none "$six" "s/phi_start = 36.77061636665199, dphi = 30/start_at = 'extreme', output_link = 1, dphi = 30/")" 3

# --- loads: components, tables over a link's position (slider-crank: slider 3 on the guide)
win='force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180'
# a constant table equals the constant load, over the slider's stroke (m) and over the crank's
# angle (deg, modulo 360 into the table's range)
run_ks "$(deck_with ld_const "$sc" "s/$win/force(1)%value = 300/")" --format csv; cp "$out" "$cli_tmp/ld_const.csv"
run_ks "$(deck_with ld_tab "$sc" "s/$win/force(1)%table = 0.2, 300, 0.5, 300/")" --format csv
[ "$rc" -eq 0 ] && pass || fail assur-table-runs "exit $rc: $(cat "$err")"
expect_same assur-constant-table-equals-constant "$cli_tmp/ld_const.csv" "$out"
run_ks "$(deck_with ld_tab1 "$sc" "s/$win/force(1)%table = -180, 300, 180, 300, force(1)%over = 1/")" --format csv
expect_same assur-constant-table-over-angle "$cli_tmp/ld_const.csv" "$out"
run_ks "$(deck_with ld_tab2 "$sc" "s/$win/force(1)%table = 0.2, 300, 0.5, 300.001/")" --format csv
expect_differ assur-table-comparison-can-fail "$cli_tmp/ld_const.csv" "$out"
# a moment table equals a constant moment
run_ks "$(deck_with ld_m "$sc" "s/$win/force(1)%value = 300, moment(1)%link = 2, moment(1)%value = 4/")" --format csv
cp "$out" "$cli_tmp/ld_m.csv"
run_ks "$(deck_with ld_mt "$sc" "s/$win/force(1)%value = 300, moment(1)%link = 2, moment(1)%table = 0.2, 4, 0.5, 4/")" --format csv
expect_same assur-constant-moment-table "$cli_tmp/ld_m.csv" "$out"
# components equal angle + value: global (with a window), and in the link's axes (follow)
run_ks "$(deck_with ld_ang "$sc" "s/$win/force(1)%value = 500, force(1)%phi_on = 0, force(1)%phi_off = 180/")" --format csv
cp "$out" "$cli_tmp/ld_ang.csv"
run_ks "$(deck_with ld_fx "$sc" "s/$win/force(1)%fx = -500, force(1)%phi_on = 0, force(1)%phi_off = 180/; s/, force(1)%angle = 180//")" --format csv
expect_same assur-components-equal-angle-value "$cli_tmp/ld_ang.csv" "$out"
run_ks "$(deck_with ld_fol "$sc" "s/$win/force(1)%value = 300, force(2)%link = 2, force(2)%at = 0.2, 0, force(2)%angle = 90, force(2)%follow = .true., force(2)%value = 40/")" --format csv
cp "$out" "$cli_tmp/ld_fol.csv"
run_ks "$(deck_with ld_folc "$sc" "s/$win/force(1)%value = 300, force(2)%link = 2, force(2)%at = 0.2, 0, force(2)%fy = 40, force(2)%follow = .true./")" --format csv
expect_same assur-components-in-link-axes "$cli_tmp/ld_fol.csv" "$out"
expect_differ assur-components-in-link-axes-can-fail "$cli_tmp/ld_const.csv" "$out"
# deck errors
expect_input_error assur-table-not-increasing '&assur: force\(1\)%table: positions must be strictly increasing: point 2' \
  "$(deck_with le_inc "$sc" "s/$win/force(1)%table = 0.5, 0, 0.2, 600/")"
expect_input_error assur-table-odd '&assur: force\(1\)%table: needs pairs \(position, value\), got 3 numbers' \
  "$(deck_with le_odd "$sc" "s/$win/force(1)%table = 0.2, 0, 0.5/")"
expect_input_error assur-table-range '&assur: force\(1\)%table: at step 1 \(phi1 = 0\.0+ deg\) link 3 is at 0\.44.* m, outside the table \[0\.20*, 0\.40*\] m' \
  "$(deck_with le_rng "$sc" "s/$win/force(1)%table = 0.2, 0, 0.4, 600/")"
expect_input_error assur-table-and-value '&assur: force\(1\)%table: give either table' \
  "$(deck_with le_tv "$sc" "s/$win/force(1)%value = 1, force(1)%table = 0.2, 0, 0.5, 600/")"
expect_input_error assur-table-moment '&assur: moment\(1\)%table: positions must be strictly increasing' \
  "$(deck_with le_mi "$sc" "s/$win/force(1)%value = 1, moment(1)%link = 2, moment(1)%table = 0.2, 0, 0.2, 6/")"
expect_input_error assur-over-without-table '&assur: force\(1\)%over: only used with table' \
  "$(deck_with le_ov "$sc" "s/$win/force(1)%value = 1, force(1)%over = 2/")"
expect_input_error assur-over-link '&assur: force\(1\)%over: link 8 is not a moving link' \
  "$(deck_with le_ol "$sc" "s/$win/force(1)%table = 0.2, 0, 0.5, 600, force(1)%over = 8/")"
expect_input_error assur-components-and-angle '&assur: force\(1\)%fx: give the force either by components' \
  "$(deck_with le_fa "$sc" "s/$win/force(1)%fx = 1/")"

# --- global coordinates: a four-bar and the generic six-bar written both ways give identical
# output (CSV to 1e-12: the global deck's link coordinates differ from the local ones in their
# last bits; the table's RESULTS except the self-check's roundoff figures)
for d in fourbar sixbar; do
  run_ks "data/assur_$d.nml" --format csv; cp "$out" "$cli_tmp/gl_local_$d.csv"
  run_ks "data/assur_${d}_global.nml" --format csv; cp "$out" "$cli_tmp/gl_global_$d.csv"
  [ "$rc" -eq 0 ] && pass || fail "assur-global-$d-exit" "exit $rc: $(cat "$err")"
  if "$KINETOSTAT" diff --rtol 1e-12 --atol 1e-12 --quiet "$cli_tmp/gl_local_$d.csv" "$cli_tmp/gl_global_$d.csv"; then pass
  else fail "assur-global-$d-identical" "CSV differs: $(diff "$cli_tmp/gl_local_$d.csv" "$cli_tmp/gl_global_$d.csv" | head -4)"; fi
  run_ks "data/assur_$d.nml"; sed -n '/RESULTS/,/SELF-CHECK/p' "$out" >"$cli_tmp/gl_local_$d.table"
  run_ks "data/assur_${d}_global.nml"; sed -n '/RESULTS/,/SELF-CHECK/p' "$out" >"$cli_tmp/gl_global_$d.table"
  if cmp -s "$cli_tmp/gl_local_$d.table" "$cli_tmp/gl_global_$d.table"; then pass
  else fail "assur-global-$d-table-identical" "table RESULTS differ"; fi
done
# the comparison can fail: the coupler's joint C 0.1 mm off gives another four-bar
run_ks "$(deck_with gl_c data/assur_fourbar_global.nml 's/dyad(1)%b = 0.38136313809986955/dyad(1)%b = 0.38146313809986955/')" --format csv
expect_differ assur-global-comparison-can-fail "$cli_tmp/gl_local_fourbar.csv" "$out"
# misfits of the reference position: exit 2 naming the joint and the misfit
expect_input_error assur-global-misfit-rrp '&assur: dyad\(2\)%b: the reference position is not assembled: joint B is 0\.1007[0-9]*E-2 m from where the links put it' \
  "$(deck_with gl_h data/assur_sixbar_global.nml 's/dyad(2)%b = 0.2066768052997261, -0.36623587262509272/dyad(2)%b = 0.2071240188952261, -0.36713029981609263/')"
expect_input_error assur-global-misfit-mode '&assur: dyad\(1\)%b: the reference position is not assembled: joint B is 0\.499[0-9]* m' \
  "$(deck_with gl_m data/assur_fourbar_global.nml 's/dyad(1)%kind = 1,/dyad(1)%kind = 1, dyad(1)%mode = -1,/')"
expect_input_error assur-global-unassembled '&assur: dyad\(1\): cannot be assembled at the reference position \(phi_ref = 0\.0+ deg\)' \
  "$(deck_with gl_ua data/assur_pr3050.nml "s/dyad(1)%e = 0/dyad(1)%e = 5/; s/frame_id = 4/coordinates = 'global', phi_ref = 0, frame_id = 4/")"
expect_input_error assur-global-phi-ref '&assur: phi_ref: missing' "$(deck_with gl_pr data/assur_fourbar_global.nml 's/, phi_ref = 40//')"
expect_input_error assur-local-phi-ref "&assur: phi_ref: only used with coordinates = 'global'" "$(deck_with gl_lp data/assur_fourbar.nml 's/omega1 = 20 /omega1 = 20, phi_ref = 3 /')"
expect_input_error assur-coordinates "&assur: coordinates: must be 'local'" "$(deck_with gl_co data/assur_fourbar_global.nml "s/coordinates = 'global'/coordinates = 'world'/")"
expect_input_error assur-global-no-b '&assur: dyad\(1\)%b: missing: the global form gives the inner joint B' "$(deck_with gl_nb data/assur_fourbar_global.nml '/dyad(1)%b =/d')"
expect_input_error assur-global-l2 '&assur: dyad\(1\)%l2: derived from at2 and b in the global form' "$(deck_with gl_l2 data/assur_fourbar_global.nml 's/dyad(1)%kind = 1,/dyad(1)%kind = 1, dyad(1)%l2 = 0.35,/')"
expect_input_error assur-global-b-rpr '&assur: dyad\(1\)%b: not used by this dyad \(kind RPR\)' "$(deck_with gl_br data/assur_pr3050.nml "s/dyad(1)%e = 0/dyad(1)%e = 0, dyad(1)%b = 1, 1/; s/frame_id = 4/coordinates = 'global', phi_ref = 0, frame_id = 4/")"

# --- a title longer than 80 characters is an input error; an unterminated quote (a truncated
# deck) is a syntax error on one line naming the line and the variable, without gfortran's
# runtime warning
expect_input_error assur-title-long '&assur: title: longer than 80 characters' \
  "$(deck_with tl_long data/assur_fourbar.nml "s/title = '[^']*'/title = '$(printf 'x%.0s' {1..81})'/")"
head -c 286 data/assur_fourbar.nml >"$cli_tmp/tl_cut.nml"
expect_input_error assur-title-unterminated "tl_cut.nml:5: &assur: title: unclosed quote '" "$cli_tmp/tl_cut.nml"

# --- --frame link: pair forces in the axes of the link each acts on
sc=data/assur_slider_crank.nml
run_ks "$sc" --format csv --frame link; cp "$out" "$cli_tmp/frame_link.csv"
# (the deck's only remark is the coarse step next to its force window)
[ "$rc" -eq 0 ] && ! grep -qv 'the input step 30 deg is coarser than 5 deg' "$err" && pass \
  || fail frame-link-csv-exit "exit $rc: $(cat "$err")"
header="$(head -1 "$cli_tmp/frame_link.csv")"
case "$header" in *,M1,F21_along,F21_across,F23_along,F23_across,F30_along,F30_across,F10_along,F10_across) pass ;;
  *) fail frame-link-csv-columns "header is '$header'" ;; esac
# the default columns unchanged, in front; without --frame link no link-axes columns
run_ks "$sc" --format csv; cp "$out" "$cli_tmp/frame_global.csv"
cut -d, -f1-20 "$cli_tmp/frame_link.csv" | cmp -s - "$cli_tmp/frame_global.csv" && pass ||
  fail frame-link-csv-prefix "the first 20 columns differ from the default CSV"
run_ks "$sc" --format csv --frame global
cmp -s "$out" "$cli_tmp/frame_global.csv" && pass || fail frame-global-is-default "--frame global differs from the default"
# the slider's frame pair F30 (guide along x): along 0, across = F30N; the crank pin F10 at
# phi1 = 0 in crank axes = its global components; phi1 = 90: along = F10y, across = -F10x
run_py - "$cli_tmp/frame_link.csv" <<'PY' && pass || fail frame-link-csv-values "link-axes values wrong"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = []
for r in rows:
    f = {k: float(v) for k, v in r.items()}
    s = max(f[k] for k in ("F21", "F23", "F30", "F10"))
    checks = [(f["F30_along"], 0.0), (f["F30_across"], f["F30N"])]
    if abs(f["phi1"]) < 1e-12:
        checks += [(f["F10_along"], f["F10x"]), (f["F10_across"], f["F10y"])]
    if abs(f["phi1"] - 90) < 1e-12:
        checks += [(f["F10_along"], f["F10y"]), (f["F10_across"], -f["F10x"])]
    bad += [(f["phi1"], a, b) for a, b in checks if abs(a - b) > 1e-12 * s]
if bad or len(rows) < 2:
    print(bad[:5], len(rows)); sys.exit(1)
PY
# table: a heading naming the frame, ALONG/ACROSS labels, the values of the CSV (2 decimals)
run_ks "$sc" --frame link; cp "$out" "$cli_tmp/frame_link.table"
grep -q '^ REACTIONS IN THE AXES OF THE LINK EACH ACTS ON (LINE 1 ALONG ITS X AXIS, LINE 2 ACROSS), N' "$out" && pass ||
  fail frame-link-table-heading "no link-axes heading"
grep -Eq '^ +PHI1 +F21_ALONG +F23_ALONG +F30_ALONG +F10_ALONG +M1$' "$out" && pass ||
  fail frame-link-table-labels "$(grep PHI1 "$out")"
v="$(awk -F, 'NR==3{printf "%.2f %.2f", $21, $22}' "$cli_tmp/frame_link.csv")"
line1="$(grep -A1 '^    30\.00 ' "$out" | sed -n 1p)"
line2="$(grep -A1 '^    30\.00 ' "$out" | sed -n 2p)"
[ "$(echo "$line1" | awk '{print $2}')" = "${v% *}" ] && [ "$(echo "$line2" | awk '{print $1}')" = "${v#* }" ] && pass ||
  fail frame-link-table-values "step 2: table '$line1' / '$line2', CSV F21_along, F21_across $v"
run_ks "$sc" --frame link --lang ru
grep -q '^ РЕАКЦИИ В ОСЯХ ЗВЕНА' "$out" && pass || fail frame-link-table-ru "no Russian heading"
# JSON: the link-axes columns carry their frame and link
run_ks "$sc" --format json --frame link
run_py - "$out" <<'PY' && pass || fail frame-link-json "link-axes columns without frame/link"
import json, sys
d = json.load(open(sys.argv[1]))
cols = {c["name"]: c for c in d["columns"]}
ok = cols["F21_along"].get("frame") == "link" and cols["F21_along"].get("link") == "2" \
    and cols["F30_across"].get("link") == "3" and cols["F10_along"].get("link") == "1" \
    and all(len(r) == len(d["columns"]) for r in d["rows"])
sys.exit(0 if ok else 1)
PY
run_ks "$sc" --format json
if [ "$rc" -ne 0 ] || ! grep -q '"columns"' "$out"; then fail frame-default-json "rc=$rc: $(head -c 300 "$err")"
elif grep -q '_along' "$out"; then fail frame-default-json "link-axes columns without --frame link"
else pass; fi
# other mechanisms: exit 1 naming the option; a bad value: exit 1
expect_exit frame-link-not-assur 1 data/pr3207.nml --frame link
grep -q '^kinetostat: error: --frame link: only the generic engine (&assur)' "$err" && pass ||
  fail frame-link-not-assur-message "$(cat "$err")"
expect_exit frame-bad-value 1 "$sc" --frame body
grep -q "^kinetostat: error: --frame must be global or link (got 'body')" "$err" && pass ||
  fail frame-bad-value-message "$(cat "$err")"

# --- joint names (crank_joint, dyad(i)%joints): the sheets' letters and the kinematics columns;
# a bad name is one line naming deck, line, group and variable
fb=data/assur_fourbar.nml
run_ks "$fb" --format csv --kinematics
head -1 "$out" | grep -q ',x_B,y_B,x_C,y_C,x_D,y_D,x_A,y_A,' && pass || fail joint-names-columns "$(head -1 "$out")"
run_ks "$fb"
grep -q '^   JOINTS          =  B (F21), C (F23), D (F30), A (F10)$' "$out" && pass || fail joint-names-echo "$(grep JOINTS "$out")"
run_ks "$fb" --format plans --at 4
grep -q '>c</text>' "$out" && pass || fail joint-names-plans "no image c on the plans sheet"
run_ks "$(deck_with jn_blank "$fb" "s/dyad(1)%joints = 'B', 'C', 'D'/dyad(1)%joints = 'B', '', 'D'/")" --format csv --kinematics
head -1 "$out" | grep -q ',x_B,y_B,x_J23,y_J23,x_D,' && pass || fail joint-names-blank-default "$(head -1 "$out")"
expect_input_error joint-names-duplicate \
  ":1[0-9]: &assur: crank_joint: 'A' names two joints \(also dyad\(1\)%joints\)" \
  "$(deck_with jn_dup "$fb" "s/dyad(1)%joints = 'B', 'C', 'D'/dyad(1)%joints = 'B', 'C', 'a'/")"
expect_input_error joint-names-long ':1[0-9]: &assur: crank_joint: longer than 8 characters' \
  "$(deck_with jn_long "$fb" "s/crank_joint = 'A'/crank_joint = 'ABCDEFGHI'/")"
expect_input_error joint-names-chars "&assur: dyad\(1\)%joints: a joint's name is a letter followed by letters" \
  "$(deck_with jn_chars "$fb" "s/dyad(1)%joints = 'B', 'C', 'D'/dyad(1)%joints = 'B', '2C', 'D'/")"
expect_input_error joint-names-com "&assur: dyad\(1\)%joints: 'S2' is the name of a centre of mass" \
  "$(deck_with jn_com "$fb" "s/dyad(1)%joints = 'B', 'C', 'D'/dyad(1)%joints = 'B', 'S2', 'D'/")"
