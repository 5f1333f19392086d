# What the output shows is what the deck means: INPUT DATA of the generic engine lists only
# the fields a dyad's kind uses; an interpolated zero is 0; the SVG legend's mean of a
# conservative cycle is 0 (-0.00 in fixed fields: test/test_io.f90).

# an RRP (slider-crank): L2 and ANGLE3, no L3, E, ANGLE2, SLOT_AT, SLOT_ANGLE
run_ks data/assur_slider_crank.nml
if grep -q '^   L2  ' "$out" && grep -q '^   ANGLE3  ' "$out" && ! grep -Eq '^   (L3|E|ANGLE2|SLOT_AT\(2\)|SLOT_ANGLE) ' "$out"
then pass; else fail cosmetics-echo-rrp "$(sed -n '/DYAD 1/,/M2 /p' "$out")"; fi
# an RRR (four-bar): L2 and L3 only
run_ks data/assur_fourbar.nml
if grep -q '^   L2  ' "$out" && grep -q '^   L3  ' "$out" && ! grep -Eq '^   (E|ANGLE2|ANGLE3|SLOT_AT\(2\)|SLOT_ANGLE) ' "$out"
then pass; else fail cosmetics-echo-rrr "$(sed -n '/DYAD 1/,/M2 /p' "$out")"; fi

# a table over the crank angle, -0.7 N at 0 deg to 0.4 N at 330 deg: at 210 deg the
# interpolation's roundoff (2.2e-16) is echoed as 0
sed -e 's/force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180/force(1)%over = 1, force(1)%table = 0, -0.7, 330, 0.4/' \
    -e 's/dphi = 30 /dphi = 10, n = 34 /' data/assur_slider_crank.nml >"$cli_tmp/cosmetics_interp.nml"
run_ks "$cli_tmp/cosmetics_interp.nml"
if grep -A6 'VALUE(34)' "$out" | grep -q -- '-3.333333E-02  0.000000E+00  3.333333E-02'; then pass
else fail cosmetics-interpolated-zero "$(grep -A6 'VALUE(34)' "$out")"; fi

# the friction slider-crank without friction: every load is conservative, M1's mean over the
# cycle is roundoff (-7.2e-15 N*m in --format summary's work); the legend says 0
grep -v '_f = \|%f2 = \|%f23 = \|%f3 = ' data/friction_slider_crank.nml >"$cli_tmp/cosmetics_conservative.nml"
run_ks "$cli_tmp/cosmetics_conservative.nml" --format svg
grep -q '>mean 0 N·m<' "$out" && pass || fail cosmetics-svg-mean-zero "$(grep -o 'mean [^<]*' "$out" | tail -1)"
