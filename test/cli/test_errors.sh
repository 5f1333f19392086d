# Errors that point at the mistake: a namelist that does not read names the
# line, the assignment and the reason; all missing required variables in one message; a
# generic-engine dyad that cannot be assembled gives the numbers.
ref="data/pr3207.nml"   # line 3: l_ab ..., line 4: m1 ..., line 6: omega1, line 8: phi_start, dphi

# expect_error_line NAME EXACT_MESSAGE DECK: the one stderr line is exactly
# "kinetostat: error: EXACT_MESSAGE" (and expect_input_error's other checks hold).
expect_error_line() {
  local name="$1" message="$2" deck="$3"
  expect_input_error "$name" "" "$deck"
  if [ "$(cat "$err")" != "kinetostat: error: $message" ]; then
    fail "$name-text" "expected 'kinetostat: error: $message', got '$(cat "$err")'"
  else pass; fi
}

d="$(deck_with comma "$ref" 's/l_ab = 0.11/l_ab = 0,11/')"
expect_error_line err-decimal-comma "$d:3: &pr3207: l_ab = 0,11: decimal comma? write 0.11" "$d"
d="$(deck_with comma2 "$ref" 's/m3 = 22/m3 = 22,5/')"
expect_error_line err-decimal-comma-mid-line "$d:4: &pr3207: m3 = 22,5: decimal comma? write 22.5" "$d"
d="$(deck_with text "$ref" "s/omega1 = 7.5/omega1 = 'abc'/")"
expect_error_line err-text-for-number "$d:6: &pr3207: omega1 = 'abc': 'abc' is text; a number is expected" "$d"
d="$(deck_with logical "$ref" 's/j3 = 1.1/j3 = .true./')"
expect_error_line err-logical-for-number "$d:5: &pr3207: j3 = .true.: .true. is a logical value; a number is expected" "$d"
d="$(deck_with unknown "$ref" 's/m5 = 60/m_5 = 60/')"
expect_error_line err-unknown-variable "$d:4: &pr3207: m_5 = 60: unknown variable 'm_5' in this group (a typing error?)" "$d"
d="$(deck_with toomany "$ref" 's/m1 = 12,/m1 = 12, 13,/')"
expect_error_line err-too-many-values \
  "$d:4: &pr3207: m1 = 12, 13: too many values (one value, or an array's size, expected)" "$d"
# an integer too large for the program: the variable and the range are named
d="$(deck_with overflow "$ref" 's/dphi = 30 /dphi = 30, n = 2147483648 /')"
expect_error_line err-integer-overflow "$d: &pr3207: n: must be a whole number from 1 to 1000000 (got 2147483648)" "$d"
# the first of two broken lines is reported (the bisection finds the first line that fails)
d="$(deck_with two "$ref" 's/l_ab = 0.11/l_ab = 0,11/; s/omega1 = 7.5/omega1 = abc/')"
expect_error_line err-first-of-two "$d:3: &pr3207: l_ab = 0,11: decimal comma? write 0.11" "$d"
# a wrong type on a continuation line of an array names the array
d="$cli_tmp/cont.nml"
printf '&pr3207\n  l_ab = 0.11, l_ac = 0.38, l_cd = 0.72, l_cs3 = 0.36\n  m1 = 12, m3 = 22, m5 = 60, j3 = 1.1\n  omega1 = 7.5, dphi = 90\n  f5c = 1, 2,\n        3, .true., 5\n/\n' >"$d"
expect_error_line err-continuation-line "$d:6: &pr3207: 3, .true., 5: f5c: .true. is a logical value; a number is expected" "$d"

# --- all missing required variables in one message
d="$(deck_with missing3 "$ref" 's/l_ab = 0.11, //; s/m3 = 22, //; s/omega1 = 7.5//')"
expect_error_line err-missing-all "$d: &pr3207: missing required variables: l_ab, m3, omega1" "$d"
d="$(deck_with missing1 "$ref" 's/m3 = 22, //')"
expect_error_line err-missing-one "$d: &pr3207: m3: missing (required variable)" "$d"
d="$(deck_with missing_sixbar data/sixbar.nml 's/^ *lam2 *=.*//; s/^ *omega1 *=.*//')"
expect_input_error err-missing-sixbar 'missing required variables: lam2, lam_s2, lam3, lam_de, omega1$' "$d"

d="$(deck_with missing_gears data/gears_reducer.nml 's/^  z1 .*//; s/^  m  .*//')"
expect_input_error err-missing-gears 'missing required variables: z1\(1\), m\(1\), z1\(2\), m\(2\)$' "$d"
d="$(deck_with missing_gears1 data/gears_reducer.nml 's/^  z1 .*/  z1 = 20/')"
expect_input_error err-missing-gears-one '&gears: z1\(2\): missing \(number of teeth\)$' "$d"
# --- generic engine (&assur): the missing variables of the deck and of its dyads and loads in
# one line, in the order the checks meet them; one missing variable keeps its own message
sc=data/assur_slider_crank.nml
d="$(deck_with assur_missing3 "$sc" 's/omega1 = 50 //; s/dyad(1)%on3 = 0, //; s/dyad(1)%l2 = 0.35, //')"
expect_error_line err-assur-missing-all "$d: &assur: missing required variables: omega1, dyad(1)%on3, dyad(1)%l2" "$d"
d="$(deck_with assur_missing1 "$sc" 's/dyad(1)%l2 = 0.35, //')"
expect_error_line err-assur-missing-one "$d: &assur: dyad(1)%l2: missing (required variable)" "$d"
# two dyads (RPR, RPP), a load's value and its window's end
d="$(deck_with assur_missing_pr "data/assur_pr3207.nml" 's/, dyad(2)%slot_angle = -90//; s/dyad(1)%link3 = 3//;
  s/force(1)%value = 3000, //; s/, force(1)%phi_off = 265//; s/phi_start = 0, dphi = 30/phi_start = 0/')"
expect_error_line err-assur-missing-dyads \
  "$d: &assur: missing required variables: dphi, dyad(1)%link3, dyad(2)%slot_angle, force(1)%value, force(1)%phi_off" "$d"
# a load without its link: the link and the load's other missing members
d="$(deck_with assur_missing_load "$sc" 's/force(1)%link = 3/moment(1)%value = 1, force(1)%link = 3/; s/, force(1)%angle = 180//')"
expect_error_line err-assur-missing-load "$d: &assur: missing required variables: force(1)%angle, moment(1)%link" "$d"
# the global form: phi_ref and the inner joint b are required, the lengths are not
d="$(deck_with assur_missing_gl data/assur_fourbar_global.nml 's/, phi_ref = 40//; /dyad(1)%b =/d; s/, dyad(1)%link3 = 3//')"
expect_error_line err-assur-missing-global "$d: &assur: missing required variables: phi_ref, dyad(1)%link3, dyad(1)%b" "$d"
# without coordinates = 'global' the same deck misses the lengths, but its phi_ref is reported
# first: an error that is not a missing variable keeps its place
d="$(deck_with assur_missing_form data/assur_fourbar_global.nml "s/coordinates = 'global', //")"
expect_error_line err-assur-missing-form "$d: &assur: phi_ref: only used with coordinates = 'global'" "$d"
d="$(deck_with assur_missing_local data/assur_fourbar_global.nml "s/coordinates = 'global', phi_ref = 40//; /dyad(1)%b =/d")"
expect_error_line err-assur-missing-local "$d: &assur: missing required variables: dyad(1)%l2, dyad(1)%l3" "$d"

# --- generic engine: a dyad that cannot be assembled gives the numbers
d="$(deck_with assur_far data/assur_slider_crank.nml 's/dyad(1)%at3 = 0, 0.02 /dyad(1)%at3 = 0, 0.5 /')"
expect_input_error err-assur-reach 'dyad 1 \(RRP, links 2-3\): cannot be assembled: distance from its joint to the guide 0\.50* m exceeds l2 = 0\.350* m' "$d" 3
# a derived-type member (line 25 of the generic PR 3207 deck) and a text variable
d="$(deck_with member data/assur_pr3207.nml "s/dyad(2)%slot_at = 0, 0,/dyad(2)%slot_at = 0, 'abc',/")"
expect_error_line err-member-text "$d:25: &assur: dyad(2)%slot_at = 0, 'abc': 'abc' is text; a number is expected" "$d"
d="$(deck_with unquoted data/assur_slider_crank.nml "s/title = 'offset slider-crank'/title = offset/")"
expect_error_line err-text-unquoted "$d:4: &assur: title = offset: offset is not a text in quotes ('...')" "$d"
d="$(deck_with twovalues data/assur_slider_crank.nml 's/crank_m = 2.0/crank_m = 2.0, 3.0/')"
expect_error_line err-member-too-many "$d:7: &assur: crank_m = 2.0, 3.0: too many values (one value, or an array's size, expected)" "$d"
