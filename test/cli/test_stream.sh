# Streaming: a run is solved and written in blocks of rows, and text beyond
# the spool's memory bound (4 MiB) goes to a temporary file that becomes the output only when
# the run succeeded. Checked on runs big enough to spill (4*10^4 steps, ~10 MB of CSV and 6 MB
# of table; 2*10^5 steps, ~50 MB of CSV, with tools/test --long): -o and
# stdout give the same bytes, nothing is left in $TMPDIR or beside the target, and a run that
# fails at its last step (after the spool took most of the text) leaves no output file and
# writes nothing to stdout. The byte-for-byte equality of blocked and whole runs for every
# deck and format is `fpm test -- blocks`.

stream_tmp="$cli_tmp/stream"
mkdir -p "$stream_tmp/tmpdir" "$stream_tmp/out"
stream_n=40000 stream_dphi=0.009
[ "${KINETOSTAT_LONG:-0}" = 1 ] && stream_n=200000 stream_dphi=0.0018
sed "s/dphi = 30 /dphi = $stream_dphi, n = $stream_n /" data/pr3207.nml > "$stream_tmp/big.nml"
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
# a run failing at its last step: f5c overflows there (exit 3), after ~10 MB (--long: ~50 MB) of rows
sed "s/dphi = 30 /dphi = $stream_dphi, n = $stream_n /; s/f5c_work = 3000, f5c_idle = 0/f5c = $((stream_n - 1))*0, 1e308/; /phi_cut_start/d" \
  data/pr3207.nml > "$stream_tmp/late.nml"
for format in csv table; do
  rm -f "$stream_tmp/out/late.$format"
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/late.nml" --format $format -o "$stream_tmp/out/late.$format" \
    >"$stream_tmp/late.stdout" 2>"$stream_tmp/late.err"; rc1=$?
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/late.nml" --format $format \
    >"$stream_tmp/late.stdout2" 2>"$stream_tmp/late.err2"; rc2=$?
  if [ "$rc1" -ne 3 ] || [ "$rc2" -ne 3 ]; then
    fail "stream-late-error-$format" "exit codes $rc1 (-o) and $rc2 (stdout), expected 3; stderr: $(head -c 300 "$stream_tmp/late.err")"
  elif ! grep -q "step $stream_n" "$stream_tmp/late.err"; then
    fail "stream-late-error-$format" "the error does not name step $stream_n: $(head -c 300 "$stream_tmp/late.err")"
  elif [ -e "$stream_tmp/out/late.$format" ] || [ -s "$stream_tmp/late.stdout" ] || [ -s "$stream_tmp/late.stdout2" ]; then
    fail "stream-late-error-$format" "a failed run wrote output ($(ls -la "$stream_tmp/out"), stdout $(wc -c <"$stream_tmp/late.stdout2") bytes)"
  elif [ -n "$(ls -A "$stream_tmp/tmpdir")" ] || [ -n "$(ls "$stream_tmp/out" | grep tmp)" ]; then
    fail "stream-late-error-$format" "temporary files left: $(ls "$stream_tmp/tmpdir" "$stream_tmp/out")"
  else
    pass
  fi
done
# the INPUT DATA echo of 131 073 different omega3 values (tools/scale-decks --distinct, five
# to a line; with tools/test --long 2*10^5): the heads written a chunk of at most 65 536 values
# at a time through the spool, two whole chunks and a last one of one value, a chunk's end in
# the middle of a table line; every value echoed once and in order (-o; with --long stdout too,
# the same bytes)
echo_n=131073 echo_last=4.999985E-01
[ "${KINETOSTAT_LONG:-0}" = 1 ] && echo_n=200000 echo_last=4.999990E-01
tools/scale-decks "$echo_n" "$stream_tmp" --distinct
# (the same run to standard output, compared with -o's, with tools/test --long: the runs above
# compare the two sinks of the spool on 6-10 MB outputs; each of these runs 0.5 s)
for format in table json; do
  TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/pr3050_lines.nml" --format $format \
    -o "$stream_tmp/out/lines.$format" 2>"$stream_tmp/err"; rc1=$?
  rc2=0
  if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
    TMPDIR="$stream_tmp/tmpdir" "$KINETOSTAT" "$stream_tmp/pr3050_lines.nml" --format $format \
      >"$stream_tmp/lines.stdout.$format" 2>>"$stream_tmp/err"; rc2=$?
  fi
  if [ "$format" = table ]; then
    # the OMEGA3 echo: lines of five values (the last of what is left), the first 3.000000E-01
    echoed=$(awk '/OMEGA3\('"$echo_n"'\)/{on=1; next} on && /^      /{n++; last=$NF; if (n==1) first=$1; next} on{exit}
      END{print n, first, last}' "$stream_tmp/out/lines.table")
    expected="$(((echo_n + 4) / 5)) 3.000000E-01 $echo_last"
  else
    echoed=$(grep -o '"name": "OMEGA3", "value": \[[^]]*\]' "$stream_tmp/out/lines.json" | sed 's/.*\[//' |
      tr ',' '\n' | wc -l)
    expected=$echo_n
  fi
  if [ "$rc1" -ne 0 ] || [ "$rc2" -ne 0 ]; then
    fail "stream-echo-$format" "exit codes $rc1 (-o) and $rc2 (stdout); stderr: $(head -c 300 "$stream_tmp/err")"
  elif [ "${KINETOSTAT_LONG:-0}" = 1 ] && ! cmp -s "$stream_tmp/out/lines.$format" "$stream_tmp/lines.stdout.$format"; then
    fail "stream-echo-$format" "-o and stdout differ: $(cmp "$stream_tmp/out/lines.$format" "$stream_tmp/lines.stdout.$format")"
  elif [ "$echoed" != "$expected" ]; then
    fail "stream-echo-$format" "echo of OMEGA3: expected $expected, got $echoed"
  elif [ "$format" = json ] && ! python3 -c 'import json, sys; json.load(open(sys.argv[1]))' \
      "$stream_tmp/out/lines.json" 2>"$stream_tmp/json.err"; then
    fail "stream-echo-$format" "not valid JSON: $(tail -1 "$stream_tmp/json.err")"
  else
    pass
  fi
done
# every deck tools/scale-decks writes runs (the decks of the benchmark and of docs/performance.md)
tools/scale-decks 20 "$stream_tmp" --distinct
for deck in pr3207 pr3050 sixbar assur cam pr3050_distinct pr3050_lines; do
  expect_exit "scale-decks-$deck" 0 "$stream_tmp/$deck.nml" --format summary
done

# --- bounded memory of a drawing (tools/test --long: 10^6 steps): --at 2 of a 10^6-step
# &linkage run solves every block but keeps only the rows it draws (below 300 MiB; every step
# kept took 1.58 GB), and its numbers are those of a 3-step run of the same steps; the SVG sheet
# keeps each bucket's extremes. Run with the release build (tools/kinetostat's), as a user
# would; the debug build takes ten times as long.
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  mem_bin="$KINETOSTAT"
  if declare -p release_build >/dev/null 2>&1 && fpm build "${release_build[@]}" >"$stream_tmp/release.log" 2>&1; then
    mem_bin="$(pwd)/$(fpm run "${release_build[@]}" --runner echo 2>/dev/null | tail -1)"
  fi
  mkdir -p "$stream_tmp/big" "$stream_tmp/small"
  sed 's/  n = 13/  n = 1000000/; s/drive(1)%step = 30/drive(1)%step = 0.00036/' data/linkage_slider_crank.nml \
    >"$stream_tmp/big/deck.nml"
  sed 's/  n = 13/  n = 3/; s/drive(1)%step = 30/drive(1)%step = 0.00036/' data/linkage_slider_crank.nml \
    >"$stream_tmp/small/deck.nml"
  for args in "--format json --at 2 --plans" "--format plans --at 2" "--format dxf --at 2" "--format svg"; do
    # shellcheck disable=SC2086
    peak=$(cd "$stream_tmp/big" && python3 - "$mem_bin" deck.nml $args <<'PY'
import resource, subprocess, sys
with open("out", "wb") as out:
    rc = subprocess.call(sys.argv[1:], stdout=out, stderr=subprocess.DEVNULL)
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
if sys.platform == "darwin":
    peak //= 1024
print(rc, peak)
PY
)
    rc=${peak% *}; kib=${peak#* }
    if [ "$rc" -ne 0 ] || [ "$kib" -ge $((300 * 1024)) ]; then
      fail "stream-at-memory ($args)" "exit $rc, peak $((kib / 1024)) MiB of memory (limit 300 MiB)"
      continue
    fi
    case "$args" in
      *--plans*)
        # shellcheck disable=SC2086
        (cd "$stream_tmp/small" && "$mem_bin" deck.nml $args >out)
        # the run's own figures (its self-check over every step) apart, the step's plans agree
        if cmp -s <(grep -v '"selfcheck"' "$stream_tmp/big/out") <(grep -v '"selfcheck"' "$stream_tmp/small/out"); then pass
        else fail "stream-at-memory-numbers" "--at 2 of 10^6 steps differs from that of 3 steps: $(diff "$stream_tmp/big/out" "$stream_tmp/small/out" | head -4)"; fi ;;
      "--format svg")
        grep -q 'data-steps="1000000"' "$stream_tmp/big/out" && pass \
          || fail "stream-svg-memory" "the sheet does not say 1000000 steps" ;;
      *) pass ;;
    esac
  done
fi
rm -rf "$stream_tmp"
