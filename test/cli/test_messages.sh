# Deck mistakes a newcomer makes: a missing '=' names its own line and variable; the dyads'
# kinds by name (RRR, 'RRP', any case) read as their codes; a variable given twice warns.

# `omega1 20` without '=': line 6, omega1 (not the array of the line above)
sed 's/^  omega1 = 20 /  omega1 20 /' docs/examples/fourbar.nml >"$cli_tmp/msg_no_equals.nml"
expect_input_error msg-missing-equals ":6: &assur: omega1 20: missing '=' after omega1 \(write omega1 = 20\)" \
  "$cli_tmp/msg_no_equals.nml"

# kinds by name: the same CSV as the codes, byte for byte
run_ks docs/examples/fourbar.nml --format csv; cp "$out" "$cli_tmp/msg_kind_code.csv"
for spelling in "RRR" "'RRR'" "rrr" '"Rrr"'; do
  sed "s/dyad(1)%kind = 1,/dyad(1)%kind = $spelling,/" docs/examples/fourbar.nml >"$cli_tmp/msg_kind.nml"
  run_ks "$cli_tmp/msg_kind.nml" --format csv
  if [ "$rc" -eq 0 ] && cmp -s "$out" "$cli_tmp/msg_kind_code.csv"; then pass
  else fail "msg-kind-name-$spelling" "rc=$rc $(head -c 300 "$err")"; fi
done
# RRP by name asks for what an RRP needs (its guide angle), as kind = 2 does
sed "s/dyad(1)%kind = 1,/dyad(1)%kind = 'RRP',/" docs/examples/fourbar.nml >"$cli_tmp/msg_kind_rrp.nml"
expect_input_error msg-kind-rrp "dyad\(1\)%angle3: missing" "$cli_tmp/msg_kind_rrp.nml"
# an unknown name is named as one, with the names the kinds have
sed "s/dyad(1)%kind = 1,/dyad(1)%kind = RRRP,/" docs/examples/fourbar.nml >"$cli_tmp/msg_kind_bad.nml"
expect_input_error msg-kind-unknown "dyad\(1\)%kind = RRRP: unknown kind 'RRRP' \(a dyad's kind is RRR, RRP, RPR, PRP or RPP, or its number 1 to 5\)" "$cli_tmp/msg_kind_bad.nml"

# a variable given twice: a warning naming both lines (the last value counts), exit 4 with
# --strict; --set is not a repeat
sed 's/^  omega1 = 20 .*/  omega1 = 20\n  omega1 = 30/' docs/examples/fourbar.nml >"$cli_tmp/msg_twice.nml"
run_ks "$cli_tmp/msg_twice.nml"
if [ "$rc" -eq 0 ] && grep -qx "kinetostat: warning: $cli_tmp/msg_twice.nml: omega1 is given twice (lines 6 and 7); the last value counts" "$err"
then pass; else fail msg-given-twice "rc=$rc $(cat "$err")"; fi
expect_exit msg-given-twice-strict 4 "$cli_tmp/msg_twice.nml" --strict
run_ks docs/examples/fourbar.nml --set omega1=25
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail msg-set-not-twice "rc=$rc $(cat "$err")"
