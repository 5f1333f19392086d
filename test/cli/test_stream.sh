# Streaming (issue 14, item 3): a run is solved and written in blocks of rows, and text beyond
# the spool's memory bound (4 MiB) goes to a temporary file that becomes the output only when
# the run succeeded. Checked on runs big enough to spill (2*10^5 steps, ~50 MB of CSV): -o and
# stdout give the same bytes, nothing is left in $TMPDIR or beside the target, and a run that
# fails at its last step (after the spool took most of the text) leaves no output file and
# writes nothing to stdout. The byte-for-byte equality of blocked and whole runs for every
# deck and format is `fpm test -- blocks`.

stream_tmp="$cli_tmp/stream"
mkdir -p "$stream_tmp/tmpdir" "$stream_tmp/out"
sed 's/dphi = 30 /dphi = 0.0018, n = 200000 /' data/pr3207.nml > "$stream_tmp/big.nml"
for format in csv table json; do
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/big.nml" --format $format \
    -o "$stream_tmp/out/big.$format" 2>"$stream_tmp/err"; rc1=$?
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/big.nml" --format $format \
    >"$stream_tmp/big.stdout.$format" 2>>"$stream_tmp/err"; rc2=$?
  size=$(wc -c <"$stream_tmp/big.stdout.$format")
  if [ "$rc1" -ne 0 ] || [ "$rc2" -ne 0 ]; then
    fail "stream-$format" "exit codes $rc1 (-o) and $rc2 (stdout); stderr: $(head -c 300 "$stream_tmp/err")"
  elif [ "$size" -le 4194304 ]; then
    fail "stream-$format" "output of $size bytes does not exceed the 4 MiB spool bound: the test checks nothing"
  elif ! cmp -s "$stream_tmp/out/big.$format" "$stream_tmp/big.stdout.$format"; then
    fail "stream-$format" "-o and stdout differ: $(cmp "$stream_tmp/out/big.$format" "$stream_tmp/big.stdout.$format")"
  elif [ -n "$(ls -A "$stream_tmp/tmpdir")" ] || [ -n "$(ls "$stream_tmp/out" | grep tmp)" ]; then
    fail "stream-$format" "temporary files left: $(ls "$stream_tmp/tmpdir" "$stream_tmp/out")"
  else
    pass
  fi
done
# a run failing at its last step: f5c overflows there (exit 3), after ~50 MB of rows
sed 's/dphi = 30 /dphi = 0.0018, n = 200000 /; s/f5c_work = 3000, f5c_idle = 0/f5c = 199999*0, 1e308/; /phi_cut_start/d' \
  data/pr3207.nml > "$stream_tmp/late.nml"
for format in csv table; do
  rm -f "$stream_tmp/out/late.$format"
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/late.nml" --format $format -o "$stream_tmp/out/late.$format" \
    >"$stream_tmp/late.stdout" 2>"$stream_tmp/late.err"; rc1=$?
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/late.nml" --format $format \
    >"$stream_tmp/late.stdout2" 2>"$stream_tmp/late.err2"; rc2=$?
  if [ "$rc1" -ne 3 ] || [ "$rc2" -ne 3 ]; then
    fail "stream-late-error-$format" "exit codes $rc1 (-o) and $rc2 (stdout), expected 3; stderr: $(head -c 300 "$stream_tmp/late.err")"
  elif ! grep -q "step 200000" "$stream_tmp/late.err"; then
    fail "stream-late-error-$format" "the error does not name step 200000: $(head -c 300 "$stream_tmp/late.err")"
  elif [ -e "$stream_tmp/out/late.$format" ] || [ -s "$stream_tmp/late.stdout" ] || [ -s "$stream_tmp/late.stdout2" ]; then
    fail "stream-late-error-$format" "a failed run wrote output ($(ls -la "$stream_tmp/out"), stdout $(wc -c <"$stream_tmp/late.stdout2") bytes)"
  elif [ -n "$(ls -A "$stream_tmp/tmpdir")" ] || [ -n "$(ls "$stream_tmp/out" | grep tmp)" ]; then
    fail "stream-late-error-$format" "temporary files left: $(ls "$stream_tmp/tmpdir" "$stream_tmp/out")"
  else
    pass
  fi
done
rm -rf "$stream_tmp"
