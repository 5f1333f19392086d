# --strict: a run that warns exits 4 with its output written; cam jamming
# and lost contact are warnings (stderr, silenced by --quiet).

# strict_case NAME DECK PATTERN...: DECK warns: without --strict exit 0 and one stderr
# warning line per PATTERN (grep -E, in order); with --strict exit 4, the same stdout and the
# same stderr; with -o the file is written; with --quiet --strict exit 4 and stderr empty.
strict_case() {
  local name="$1" deck="$2"; shift 2
  run_ks "$deck"
  cp "$out" "$cli_tmp/plain.out"; cp "$err" "$cli_tmp/plain.err"
  if [ "$rc" -ne 0 ]; then fail "strict-$name-plain" "exit $rc without --strict: $(head -c 300 "$err")"; return; fi
  if [ "$(wc -l <"$err")" -ne $# ]; then fail "strict-$name-lines" "expected $# warning lines: $(cat "$err")"; return; fi
  local i=1 p
  for p in "$@"; do
    if sed -n "${i}p" "$err" | grep -Eq "^kinetostat: warning: $deck: $p"; then pass
    else fail "strict-$name-warning-$i" "line $i does not match /$p/: $(cat "$err")"; fi
    i=$((i + 1))
  done
  run_ks "$deck" --strict
  [ "$rc" -eq 4 ] && pass || fail "strict-$name-exit" "exit $rc with --strict, expected 4"
  cmp -s "$out" "$cli_tmp/plain.out" && cmp -s "$err" "$cli_tmp/plain.err" && pass \
    || fail "strict-$name-same-output" "--strict changed stdout or stderr"
  rm -f "$cli_tmp/strict.out"
  run_ks "$deck" --strict -o "$cli_tmp/strict.out"
  [ "$rc" -eq 4 ] && cmp -s "$cli_tmp/strict.out" "$cli_tmp/plain.out" && pass \
    || fail "strict-$name-file" "exit $rc or -o FILE not written in full"
  run_ks "$deck" --strict --quiet
  [ "$rc" -eq 4 ] && [ ! -s "$err" ] && pass || fail "strict-$name-quiet" "exit $rc, stderr: $(cat "$err")"
  run_ks "$deck" --quiet
  [ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail "strict-$name-quiet-only" "exit $rc, stderr: $(cat "$err")"
}

# the bundled translating-follower deck jams at 90 deg and loses contact at 300 deg
strict_case cam-translating data/cam_translating.nml \
  'the follower jams \(self-locking.* at 1 step, the first at step 4 \(phi = 90 deg\)' \
  'contact is lost \(F2 <= 0.* at 1 step, the first at step 11 \(phi = 300 deg\)'
# crafted: jamming only (every load holds the follower on the cam), at two steps
strict_case cam-jam-only "$(deck_with cam_jam data/cam_translating.nml \
  's/^  f2 .*/  f2 = 13*300/; s/^  theta = .*/  theta = 0, 20, 35, 45, 30, 10, 0, -15, -30, -38, -25, -10, 45/; s/^  vdir .*/  vdir = 12*1, 1/')" \
  'the follower jams .* at 2 steps, the first at step 4 \(phi = 90 deg\)'
# crafted: lost contact only, on the flat-faced follower (f2 <= 0 at two steps)
strict_case cam-lost-only "$(deck_with cam_lost data/cam_flat.nml 's/^  f2 .*/  f2 = 500, 500, 0, -100, 9*500/')" \
  'contact is lost .* at 2 steps, the first at step 3 \(phi = 60 deg\)'
# PR 3050: the rocker passes its dead position between two steps
strict_case pr3050-dead-between "$(deck_with strict_3050 data/pr3050.nml 's/phi3_start = 43.72, phi3_end = 88.72, dphi3 = 5/phi3_start = 170, phi3_end = 190, dphi3 = 20/;
     s/^  omega3 = .*/  omega3 = 2*0.5/; s/^  eps3 = .*/  eps3 = 2*0/')" \
  'between step 1 \(phi3 = 170(\.0*)? deg\) and step 2 .*dead position'

# a run without warnings exits 0 with --strict; an error keeps its own code
run_ks data/cam_flat.nml --strict
[ "$rc" -eq 0 ] && [ ! -s "$err" ] && pass || fail strict-clean-deck "exit $rc, stderr: $(cat "$err")"
run_ks "$(deck_with strict_bad data/cam_flat.nml 's/^  l  .*/  l = -1/')" --strict
[ "$rc" -eq 2 ] && pass || fail strict-error-code "exit $rc for an input error with --strict, expected 2"
# the JSON lists the warnings
run_ks data/cam_translating.nml --format json
run_py -c 'import json,sys; w=json.load(open(sys.argv[1]))["warnings"]; assert len(w) == 2 and "jams" in w[0] and "lost" in w[1], w' "$out" \
  && pass || fail strict-json-warnings "JSON warnings list is not the two cam warnings"
