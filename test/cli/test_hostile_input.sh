# Hostile and malformed input, the finite guard of every printed number, and the self-check's
# verdict (sourced by tools/test with test/cli/lib.sh).

# --- syntax pre-check: an unclosed '(' after an array or type name made gfortran's namelist
# reader crash (SIGSEGV); now one line, exit 2, naming deck, line, group, variable, reason
printf '&assur dyad(\n' >"$cli_tmp/paren_assur.nml"
expect_input_error syntax-assur-dyad-paren "paren_assur.nml:1: &assur: dyad\(: unclosed '\('" "$cli_tmp/paren_assur.nml"
printf '&gears stage(' >"$cli_tmp/paren_gears.nml"
expect_input_error syntax-gears-stage-paren "paren_gears.nml:1: &gears: stage\(: unclosed '\('" "$cli_tmp/paren_gears.nml"
for body in "dyad(1)%kind = 1 dyad(" "title = 'x' dyad(" "dyad(1)%kind = (1,2"; do
  printf '&assur\n  %s\n/\n' "$body" >"$cli_tmp/paren_value.nml"
  expect_input_error "syntax-paren-in-values-${body%% *}" "paren_value.nml:2: &assur: .*unclosed '\('" "$cli_tmp/paren_value.nml"
done
printf '&assur\n  ) x\n/\n' >"$cli_tmp/stray.nml"
expect_input_error syntax-stray-close "stray.nml:2: &assur: .*'\)' without '\('" "$cli_tmp/stray.nml"
printf '&cam\n  = 3\n/\n' >"$cli_tmp/bare_eq.nml"
expect_input_error syntax-bare-equals "bare_eq.nml:2: &cam: .*'=' without a variable name" "$cli_tmp/bare_eq.nml"
run_ks data/assur_fourbar.nml --set 'title=dyad('
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "^kinetostat: error: --set title=dyad(: &assur: dyad(: unclosed '('" "$err" \
  && pass || fail syntax-set-paren "exit $rc: $(head -c 300 "$err")"

# --- strings of any length: a 400 000-character title is refused (80 at most), no stack overflow
run_py -c "
import re, sys
s = open('data/assur_fourbar.nml').read()
open(sys.argv[1], 'w').write(re.sub(r\"title\s*=\s*'[^']*'\", \"title = '\" + 'x' * 400000 + \"'\", s))
" "$cli_tmp/long_title.nml"
(ulimit -s 8192; expect_input_error long-title-400k '&assur: title: longer than 80 characters' "$cli_tmp/long_title.nml"
 echo "$cli_passed $cli_failed" >"$cli_tmp/sub_counts")
read -r cli_passed cli_failed <"$cli_tmp/sub_counts"

# --- deck size limit: /dev/zero and endless standard input stop at the limit (within 20 s of
# processor time - bash's time, user + sys, which the machine's load does not stretch - one
# line, exit 2); a file over --max-deck-size names both sizes; a bad value is a usage error
# hi_cpu_s FILE: whole seconds of processor time in bash's time report FILE (TIMEFORMAT below)
hi_cpu_s() { awk '{ printf "%d", $1 + $2 }' "$1"; }
TIMEFORMAT='%3U %3S'
{ time run_ks /dev/zero; } 2>"$cli_tmp/hi_time"
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "^kinetostat: error: /dev/zero: the deck is longer than the limit of 268435456 bytes" "$err" \
  && [ "$(hi_cpu_s "$cli_tmp/hi_time")" -le 20 ] && pass \
  || fail deck-limit-dev-zero "exit $rc after $(cat "$cli_tmp/hi_time") s (user, sys): $(head -c 300 "$err")"
{ time { yes | "$KINETOSTAT" - --max-deck-size 1000000 >"$cli_tmp/yes.out" 2>"$cli_tmp/yes.err"; rc=$?; }; } 2>"$cli_tmp/hi_time"
[ "$rc" -eq 2 ] && grep -q "^kinetostat: error: <stdin>: the deck is longer than the limit of 1000000 bytes" "$cli_tmp/yes.err" \
  && [ "$(hi_cpu_s "$cli_tmp/hi_time")" -le 20 ] && pass \
  || fail deck-limit-yes "exit $rc after $(cat "$cli_tmp/hi_time") s (user, sys): $(head -c 300 "$cli_tmp/yes.err")"
unset TIMEFORMAT
run_ks data/pr3207.nml --max-deck-size 100
[ "$rc" -eq 2 ] && grep -q "data/pr3207.nml: the deck is [0-9]* bytes, more than the limit of 100 bytes" "$err" \
  && pass || fail deck-limit-file "exit $rc: $(cat "$err")"
run_ks data/pr3207.nml --max-deck-size=100000 --format csv
[ "$rc" -eq 0 ] && cmp -s "$out" data/expected/pr3207.csv && pass || fail deck-limit-raised "exit $rc: $(head -c 300 "$err")"
expect_exit deck-limit-bad-value 1 data/pr3207.nml --max-deck-size 0
expect_exit deck-limit-not-a-number 1 data/pr3207.nml --max-deck-size 1e9

# --- 8-bit comments: a CP1251 comment in the group ("! данные для расчёта", with byte 0xFF)
# and before it: the deck is CP1251, decoded, and the comments are ignored as ever
{ printf '! \xe7\xe0\xe3\xee\xeb\xee\xe2\xee\xea \xff\n'; sed -n '1,/^&cam/p' data/cam_flat.nml
  printf '  ! \xe4\xe0\xed\xed\xfb\xe5 \xe4\xeb\xff \xf0\xe0\xf1\xf7\xb8\xf2\xe0\n'
  sed -n '/^&cam/,$p' data/cam_flat.nml | tail -n +2; } >"$cli_tmp/cp1251.nml"
run_ks "$cli_tmp/cp1251.nml" --format csv
[ "$rc" -eq 0 ] && cmp -s "$out" data/expected/cam_flat.csv && pass || fail cp1251-comment "exit $rc: $(head -c 300 "$err")"
# (a byte 0xFF in a title, a Latin-1 title, a deck in two encodings: test/cli/test_strings.sh)
# a deck path or --set value with a newline or a stray byte: the message stays one line, escaped
run_ks "$cli_tmp/no
such"$'\xff'.nml
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q 'no\\nsuch\\xFF.nml: cannot open deck' "$err" && pass \
  || fail path-newline-one-line "exit $rc, $(wc -l <"$err") lines: $(cat "$err")"
run_ks data/pr3207.nml --set $'l_ab=0.1\n2'
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "l_ab=0.1\\\\n2" "$err" && pass \
  || fail set-newline-one-line "exit $rc, $(wc -l <"$err") lines: $(cat "$err")"

# --- misreads: the line at fault is named, not the next one; gaps in dyads and forces
expect_input_error misread-logical-for-real 'l_over.nml:7: &cam: l_over += F: F is a logical value' \
  "$(deck_with l_over data/cam_translating.nml 's/^\( *l_over *=\) *[0-9.]*/\1 F/')"
expect_input_error misread-dyad-gap '&assur: dyad\(5\): dyads must be numbered 1..2 without gaps' \
  "$(deck_with dyad_gap data/assur_fourbar.nml 's/^\/$/  dyad(5)%kind = 1\n\//')"
expect_input_error misread-force-gap '&assur: force\(1\): missing: force\(2\) is given' \
  "$(deck_with force_gap data/assur_fourbar.nml 's/force(1)/force(2)/g')"

# --- finite guard: huge finite loads give finite means and works (the sums are kept in range),
# in the table, --format summary and CSV; the SVG refuses values it cannot draw (exit 3)
for args in "data/cam_flat.nml --set f2(1)=1e308" "data/assur_fourbar.nml --set force(1)%value=1.7976931348623157e308"; do
  for format in table summary csv json; do
    # shellcheck disable=SC2086
    run_ks $args --format "$format"
    if [ "$rc" -eq 0 ] && ! grep -qiE '(^|[^a-z])(nan|inf|infinity)([^a-z]|$)' "$out"; then pass
    else fail "finite-${args%%.nml*}-$format" "exit $rc or NaN/Infinity: $(grep -m1 -iE 'nan|inf' "$out" | head -c 200) $(head -c 200 "$err")"; fi
  done
  # shellcheck disable=SC2086
  run_ks $args --format svg
  [ "$rc" -eq 3 ] && grep -q "is too large to draw" "$err" && [ ! -s "$out" ] && pass || fail "finite-${args%%.nml*}-svg" "exit $rc: $(head -c 200 "$err")"
done
# the mean by the scaled sums equals the plain mean scaled (cam_flat: N MEAN at f2(1)=1e300 times 1e8)
m300=$("$KINETOSTAT" data/cam_flat.nml --set 'f2(1)=1e300' | awk '/N MEAN/ {print $4}')
m308=$("$KINETOSTAT" data/cam_flat.nml --set 'f2(1)=1e308' | awk '/N MEAN/ {print $4}')
awk -v a="$m300" -v b="$m308" 'BEGIN { r = b / (a * 1e8); exit !(r > 1 - 1e-9 && r < 1 + 1e-9) }' && pass \
  || fail finite-mean-scaled "N MEAN $m308 at 1e308 vs $m300 at 1e300"

# --- the self-check judges against the loads: a massless slider-crank with a load across its
# guide (no load does work, M1 = 0) passes, frictionless and in statics with friction (M1 at
# roundoff is not a sign change: no self-locking)
cat >"$cli_tmp/transverse.nml" <<'NML'
&assur
  title = 'massless slider-crank, transverse load on the slider'
  frame_id = 0, crank_id = 1, crank_at = 0, 0
  omega1 = 10, g = 0
  phi_start = 0, dphi = 5, n = 71
  dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3
  dyad(1)%on2 = 1, dyad(1)%at2 = 0.05, 0
  dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0, dyad(1)%angle3 = 0
  dyad(1)%l2 = 0.2, dyad(1)%mode = 1
  force(1)%link = 3, force(1)%at = 0, 0, force(1)%angle = 90, force(1)%value = 100
/
NML
run_ks "$cli_tmp/transverse.nml"
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && [ "$(grep -c '  OK$' "$out")" -eq 2 ] && pass \
  || fail selfcheck-transverse-load "exit $rc: $(head -c 300 "$err") $(grep -A2 SELF-CHECK "$out")"
run_ks "$(deck_with transverse_static "$cli_tmp/transverse.nml" 's/omega1 = 10/omega1 = 0/; s/dyad(1)%mode = 1/dyad(1)%mode = 1, dyad(1)%f3 = 0.15, dyad(1)%f2 = 0.1, dyad(1)%r2 = 0.01/')"
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail selfcheck-static-no-self-locking "exit $rc: $(head -c 300 "$err")"
# with guide friction f = 0.2 the guide's reaction is the whole one: |F30| = |F30N|*sqrt(1.04),
# turned atan(0.2) = 11.31 deg from the normal (the shape of PMKS+'s published case:
# 99.23 N at 90 deg normal, 101.19 N at 78.7 deg whole)
run_ks "$(deck_with transverse_f "$cli_tmp/transverse.nml" 's/dyad(1)%mode = 1/dyad(1)%mode = 1, dyad(1)%f3 = 0.2/')" --format csv
run_py - "$out" <<'PY' >"$cli_tmp/transverse_f.log" 2>&1 && pass || fail friction-transverse-whole "$(head -3 "$cli_tmp/transverse_f.log")"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = []
for r in rows[1:35] + rows[37:70]:   # away from the dead centres (no sliding there)
    f30, fn, g = float(r["F30"]), abs(float(r["F30N"])), float(r["F30G"])
    if abs(f30 - fn * math.sqrt(1.04)) > 1e-12 * f30:
        bad.append("phi1 %s: F30 %.12g, F30N %.12g" % (r["phi1"], f30, fn))
    if abs(abs(g - 270.0) - math.degrees(math.atan(0.2))) > 1e-9:
        bad.append("phi1 %s: F30G %.10g, expected 270 +- 11.3099" % (r["phi1"], g))
print("\n".join(bad) or "ok")
sys.exit(1 if bad else 0)
PY

# --- a failed self-check is a computation error (exit 3, the figure and the step named,
# nothing written); --allow-selfcheck-failure writes the output with a warning (also in the
# JSON's warnings), and --strict then exits 4
rm -f "$cli_tmp/never.out"
run_ks data/pr3207.nml --set phi_start=1e20 -o "$cli_tmp/never.out"
[ "$rc" -eq 3 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "&pr3207: self-check failed at step [0-9]*: M1 mismatch" "$err" \
  && [ ! -e "$cli_tmp/never.out" ] && pass || fail selfcheck-failure-exit-3 "exit $rc: $(cat "$err")"
run_ks data/pr3207.nml --set phi_start=1e20 --allow-selfcheck-failure --format json
[ "$rc" -eq 0 ] && grep -q "^kinetostat: warning: data/pr3207.nml: self-check failed at step" "$err" \
  && run_py -c 'import json,sys; w=json.load(open(sys.argv[1]))["warnings"]; assert any("self-check failed" in x for x in w), w' "$out" \
  && pass || fail selfcheck-allowed-warning "exit $rc: $(head -c 300 "$err")"
expect_exit selfcheck-allowed-strict 4 data/pr3207.nml --set phi_start=1e20 --allow-selfcheck-failure --strict
