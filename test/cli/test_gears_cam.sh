# Command-line tests of the gear (&gears) and cam (&cam) decks (sourced by tools/test with lib.sh).

# --- golden outputs (data/expected/), compared with numdiff, and proof the comparison can fail
for d in gears_reducer gears_planetary gears_bevel cam_translating cam_flat; do
  run_ks "data/$d.nml"; cp "$out" "$cli_tmp/$d.table"
  [ "$rc" -eq 0 ] && pass || fail "$d-table-exit" "exit $rc: $(cat "$err")"
  expect_same "$d-golden-table" "data/expected/$d.table" "$cli_tmp/$d.table"
  expect_no_nan "$d-table-no-nan" "$cli_tmp/$d.table"
  run_ks "data/$d.nml" --format csv; cp "$out" "$cli_tmp/$d.csv"
  [ "$rc" -eq 0 ] && pass || fail "$d-csv-exit" "exit $rc: $(cat "$err")"
  expect_same "$d-golden-csv" "data/expected/$d.csv" "$cli_tmp/$d.csv"
  expect_no_nan "$d-csv-no-nan" "$cli_tmp/$d.csv"
done
gears_header="stage,kind,z1,z2,z3,k,dw1,dw2,u,M1,M2,M2P,Ft,Fr1,Fa1,Fr2,Fa2,Fn,F12,F12G,FS1,FS1G,FS2,FS2G,F23,F23G,F2H,F2HG,M3,M3P"
cam_header="phi,theta,xB,F2,vdir,N,F21,F21G,F23C,F23CG,F23D,F23DG,KF,KF2,JAM,LOST"
[ "$(head -1 "$cli_tmp/gears_reducer.csv")" = "$gears_header" ] && pass || fail gears-csv-header "$(head -1 "$cli_tmp/gears_reducer.csv")"
[ "$(head -1 "$cli_tmp/cam_flat.csv")" = "$cam_header" ] && pass || fail cam-csv-header "$(head -1 "$cli_tmp/cam_flat.csv")"
# perturb one value by 1e-6 relative: the comparison must fail (M_out of the reducer; N of the cam)
awk -F, 'BEGIN{OFS=","} NR==3{$11=sprintf("%.12E",$11*(1+1e-6))} {print}' data/expected/gears_reducer.csv >"$cli_tmp/p1.csv"
expect_differ gears-golden-csv-can-fail data/expected/gears_reducer.csv "$cli_tmp/p1.csv"
awk -F, 'BEGIN{OFS=","} NR==3{$6=sprintf("%.12E",$6*(1+1e-6))} {print}' data/expected/cam_translating.csv >"$cli_tmp/p2.csv"
expect_differ cam-golden-csv-can-fail data/expected/cam_translating.csv "$cli_tmp/p2.csv"
sed '0,/4.800000000E+02/s//4.800000100E+02/' data/expected/gears_planetary.table >"$cli_tmp/p3.table"
expect_differ gears-golden-table-can-fail data/expected/gears_planetary.table "$cli_tmp/p3.table"
sed '0,/551.181/s//551.182/' data/expected/cam_translating.table >"$cli_tmp/p4.table"
expect_differ cam-golden-table-can-fail data/expected/cam_translating.table "$cli_tmp/p4.table"

# --- physics visible on the command line
# reducer: output torque from forces (M2) equals the power balance (M2P) on the last stage
awk -F, 'NR==3{d=$11-$12; if (d<0) d=-d; exit !(d <= 1e-9*($12<0?-$12:$12))}' "$cli_tmp/gears_reducer.csv" && pass \
  || fail gears-reducer-torque "M_out from forces differs from the power balance"
# spur = helical with beta = 0: same forces (rows 3 and 4 of the bevel deck, with beta 0 for the helical)
run_ks "$(deck_with helical0 data/gears_bevel.nml "s/beta    = 0, 0, 12/beta    = 0, 0, 0/")" --format csv
awk -F, 'NR==3{for(i=7;i<=30;i++)s[i]=$i} NR==4{for(i=7;i<=30;i++) if (s[i]!=$i) bad=1} END{exit bad}' "$out" && pass \
  || fail gears-spur-is-helical-beta0 "spur and helical(beta=0) rows differ"
# cam flags: step 4 jammed, step 11 lost contact, steps 3 and 5 K_F > 2
grep -q ' 90.00  45.000 .*JAMMED' "$cli_tmp/cam_translating.table" && pass || fail cam-jam-flag "no JAMMED at 90 deg"
grep -q '300.00 -25.000 .*LOST CONTACT' "$cli_tmp/cam_translating.table" && pass || fail cam-lost-flag "no LOST at 300 deg"
[ "$(awk -F, 'NR>1 && $14==1' "$cli_tmp/cam_translating.csv" | wc -l)" -eq 3 ] && pass || fail cam-kf-flags "expected 3 rows with KF2 = 1"
# jamming exactly at the analytic critical pressure angle: atan(l/(f(l+2a))) = 43.60281897 deg
run_ks "$(deck_with crit data/cam_translating.nml 's/^  theta = .*/  theta = 43.6028, 43.6029/; s/^  vdir  = .*/  vdir = 1/; s/^  f2    = .*/  f2 = 100/; s/n = 13/n = 2/')" --format csv
[ "$rc" -eq 0 ] && [ "$(awk -F, 'NR==2{print $15} NR==3{print $15}' "$out" | tr '\n' ' ')" = "0 1 " ] \
  && pass || fail cam-critical-angle "rc=$rc; JAM column: $(cut -d, -f15 "$out" | tr '\n' ' ')"

# --- templates: valid decks that run
for kind in gears cam; do
  run_ks template $kind; cp "$out" "$cli_tmp/template_$kind.nml"
  [ "$rc" -eq 0 ] && grep -q "^&$kind" "$cli_tmp/template_$kind.nml" && pass || fail "$kind-template" "rc=$rc"
  run_ks "$cli_tmp/template_$kind.nml"
  [ "$rc" -eq 0 ] && grep -q 'MAX EQUILIBRIUM RESIDUAL.* OK' "$out" && pass || fail "$kind-template-runs" "rc=$rc: $(cat "$err")"
  expect_no_nan "$kind-template-no-nan" "$out"
done

# --- input errors, gears: exit 2, one line naming deck, group, variable and reason
g=data/gears_reducer.nml
p=data/gears_planetary.nml
b=data/gears_bevel.nml
expect_input_error gears-unknown-variable "&gears: foo = 1: unknown variable 'foo'" "$(deck_with g_unknown "$g" 's/m1      = 50/m1 = 50, foo = 1/')"
expect_input_error gears-z1-zero '&gears: z1\(2\): must be >= 1 teeth' "$(deck_with g_z0 "$g" 's/z1      = 20, 18/z1 = 20, 0/')"
expect_input_error gears-z2-negative '&gears: z2\(1\): must be >= 1 teeth' "$(deck_with g_zneg "$g" 's/z2      = 40, 54/z2 = -40, 54/')"
expect_input_error gears-z1-missing '&gears: z1\(2\): missing' "$(deck_with g_zmiss "$g" 's/z1      = 20, 18/z1 = 20/')"
expect_input_error gears-alpha-zero '&gears: alpha_w\(1\): must be in \(0, 45\)' "$(deck_with g_a0 "$g" 's/alpha_w = 20, 20/alpha_w = 0, 20/')"
expect_input_error gears-alpha-45 '&gears: alpha_w\(2\): must be in \(0, 45\)' "$(deck_with g_a45 "$g" 's/alpha_w = 20, 20/alpha_w = 20, 45/')"
expect_input_error gears-alpha-negative '&gears: alpha_w\(1\): must be in \(0, 45\)' "$(deck_with g_aneg "$g" 's/alpha_w = 20, 20/alpha_w = -20, 20/')"
expect_input_error gears-alpha-nan '&gears: alpha_w\(1\): must be a finite number' "$(deck_with g_anan "$g" 's/alpha_w = 20, 20/alpha_w = NaN, 20/')"
expect_input_error gears-module-zero '&gears: m\(1\): must be > 0' "$(deck_with g_m0 "$g" 's/m       = 3, 4/m = 0, 4/')"
expect_input_error gears-module-missing '&gears: m\(2\): missing' "$(deck_with g_mmiss "$g" 's/m       = 3, 4/m = 3/')"
expect_input_error gears-m-and-dw1 '&gears: m\(1\): give either m or dw1' "$(deck_with g_mdw "$g" 's/m       = 3, 4/m = 3, 4, dw1 = 60/')"
expect_input_error gears-dw1-negative '&gears: dw1\(1\): must be > 0' "$(deck_with g_dw "$g" 's/m       = 3, 4/m(2) = 4, dw1(1) = -60/')"
expect_input_error gears-torque-missing '&gears: m1\(1\): missing' "$(deck_with g_t "$g" '/m1      = 50/d')"
expect_input_error gears-series-torque-2 '&gears: m1\(2\): not allowed in layout .series.' "$(deck_with g_t2 "$g" 's/m1      = 50 /m1 = 50, 10/')"
expect_input_error gears-series-bevel '&gears: stage\(2\): .bevel. cannot be a stage of layout .series.' "$(deck_with g_sb "$g" "s/stage   = 'spur', 'spur'/stage = 'spur', 'bevel'/")"
expect_input_error gears-bad-stage '&gears: stage\(1\): must be' "$(deck_with g_bs "$g" "s/stage   = 'spur', 'spur'/stage = 'worm', 'spur'/")"
expect_input_error gears-bad-layout '&gears: layout: must be' "$(deck_with g_bl "$g" "s/layout  = 'series'/layout = 'parallel'/")"
expect_input_error gears-no-stage '&gears: stage: missing' "$(deck_with g_ns "$g" "/stage   =/d")"
expect_input_error gears-extra-value '&gears: z1\(3\): given for stage 3' "$(deck_with g_ex "$g" 's/z1      = 20, 18/z1 = 20, 18, 30/')"
expect_input_error gears-beta-spur '&gears: beta\(2\): only for a .helical. stage' "$(deck_with g_bsp "$b" 's/beta    = 0, 0, 12/beta = 0, 5, 12/')"
expect_input_error gears-beta-45 '&gears: beta\(3\): must be in \(-45, 45\)' "$(deck_with g_b45 "$b" 's/beta    = 0, 0, 12/beta = 0, 0, 45/')"
expect_input_error gears-z3-coaxial '&gears: z3\(1\): must be z1 \+ 2\*z2 = 72' "$(deck_with g_z3 "$p" 's/z3      = 72/z3 = 70/')"
expect_input_error gears-z3-zero '&gears: z3\(1\): must be >= 1 teeth' "$(deck_with g_z30 "$p" 's/z3      = 72/z3 = 0/')"
expect_input_error gears-k-zero '&gears: k\(1\): must be >= 1' "$(deck_with g_k0 "$p" 's/k       = 3 /k = 0 /')"
expect_input_error gears-k-missing '&gears: k\(1\): missing' "$(deck_with g_km "$p" '/k       = 3/d')"
expect_input_error gears-k-assembly '&gears: k\(1\): \(z1 \+ z3\)/k must be an integer' "$(deck_with g_ka "$p" 's/k       = 3 /k = 5 /')"
expect_input_error gears-k-neighbours '&gears: k\(1\): too many satellites' "$(deck_with g_kn "$p" 's/k       = 3 /k = 6 /')"
expect_input_error gears-z3-on-spur '&gears: z3\(1\): only for a .planetary. stage' "$(deck_with g_z3s "$g" 's/m1      = 50/m1 = 50, z3 = 60/')"
expect_input_error gears-alpha23-range '&gears: alpha_w23\(1\): must be in \(0, 45\)' "$(deck_with g_a23 "$p" 's/k       = 3 /k = 3, alpha_w23 = 50 /')"

# --- input errors, cam
c=data/cam_translating.nml
fl=data/cam_flat.nml
expect_input_error cam-unknown-variable "&cam: foo = 1: unknown variable 'foo'" "$(deck_with c_unknown "$c" 's/f         = 0.3 /f = 0.3, foo = 1 /')"
expect_input_error cam-f-negative '&cam: f: must be >= 0' "$(deck_with c_fneg "$c" 's/f         = 0.3 /f = -0.3 /')"
expect_input_error cam-f-missing '&cam: f: missing' "$(deck_with c_fmiss "$c" '/f         = 0.3/d')"
expect_input_error cam-l-zero '&cam: l: must be > 0' "$(deck_with c_l0 "$c" 's/l         = 0.04 /l = 0 /')"
expect_input_error cam-l-negative '&cam: l: must be > 0' "$(deck_with c_lneg "$c" 's/l         = 0.04 /l = -0.04 /')"
expect_input_error cam-l-missing '&cam: l: missing' "$(deck_with c_lmiss "$c" '/l         = 0.04/d')"
expect_input_error cam-overhang-negative '&cam: l_over: must be >= 0' "$(deck_with c_a "$c" 's/l_over    = 0.05/l_over = -0.05/')"
expect_input_error cam-theta-90 '&cam: theta\(2\): must be in \(-90, 90\)' "$(deck_with c_t90 "$c" 's/theta = 0, 20,/theta = 0, 90,/')"
expect_input_error cam-theta-length '&cam: theta: expected 13 values' "$(deck_with c_tl "$c" 's/^  theta = .*/  theta = 1, 2/')"
expect_input_error cam-theta-missing '&cam: theta: missing' "$(deck_with c_tm "$c" '/^  theta = /d')"
expect_input_error cam-f2-missing '&cam: f2: missing' "$(deck_with c_f2 "$c" '/^  f2    = /d')"
expect_input_error cam-vdir-bad '&cam: vdir\(1\): must be \+1' "$(deck_with c_v "$c" 's/^  vdir  = 1,/  vdir  = 2,/')"
expect_input_error cam-fcam-translating '&cam: f_cam: only for follower = .flat.' "$(deck_with c_fc "$c" 's/f         = 0.3 /f = 0.3, f_cam = 0.1 /')"
expect_input_error cam-bad-follower '&cam: follower: must be' "$(deck_with c_fo "$c" "s/follower  = 'translating'/follower = 'oscillating'/")"
expect_input_error cam-zero-step '&cam: dphi: must be > 0' "$(deck_with c_dp "$c" 's/dphi = 30/dphi = 0/')"
expect_input_error cam-flat-theta '&cam: theta: not for follower = .flat.' "$(deck_with c_ft "$fl" 's/f2      = 500 /f2 = 500, theta = 10 /')"
expect_input_error cam-flat-fcam-negative '&cam: f_cam: must be >= 0' "$(deck_with c_ffc "$fl" 's/f_cam     = 0.1 /f_cam = -0.1 /')"
expect_input_error cam-flat-omega '&cam: omega_dir: must be \+1' "$(deck_with c_fo2 "$fl" 's/omega_dir = 1 /omega_dir = 0 /')"
expect_input_error cam-flat-ds-missing '&cam: ds_dphi: missing' "$(deck_with c_fds "$fl" '/ds_dphi = /,/0.02     !/d')"
expect_input_error gears-z-too-many '&gears: z2\(1\): must be <= 100000 teeth' "$(deck_with g_zbig "$g" 's/z2      = 40, 54/z2 = 2000000000, 54/')"
expect_input_error gears-overflow 'stage 1: M2 is not finite' "$(deck_with g_ovf "$g" 's/m1      = 50 /m1 = 1e308 /')" 3
expect_input_error cam-overflow 'step 3 \(phi = 60 deg\): N is not finite' "$(deck_with c_ovf "$c" 's/^  f2    = .*/  f2 = 1e308/')" 3
run_ks "$(deck_with g_a23zero "$b" 's/beta    = 0, 0, 12/beta = 0, 0, 12, alpha_w23 = 0, 0, 0/')" --format csv
expect_same gears-alpha_w23-zero-accepted data/expected/gears_bevel.csv "$out"
