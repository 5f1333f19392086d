# Output under faults (sourced by tools/test with test/cli/lib.sh): a full file system, a
# file-size limit, /dev/full, links and FIFOs as -o, planted links and FIFOs in $TMPDIR, the
# mode and owner of a replaced file, signals in the middle of a run and of a sweep. Every
# failure: exit 2 with one line "kinetostat: error: ...", the file as it was, no temporary
# left. Checks that need root (mount) say "skipped" when they cannot run.

ft_dir="$cli_tmp/faults"; mkdir -p "$ft_dir"
ft_tmp="$ft_dir/tmpdir"; mkdir -p "$ft_tmp"    # a private $TMPDIR: nothing may be left in it
# a run of 999 973 steps (about 8 s, 150 MB of table): signals reach it in its middle
ft_big=(data/pr3207.nml --set dphi=0.00036001)

# ft_fails NAME FILE OLD: the last run_ks failed as a write fault must: exit 2, one stderr
# line naming FILE, FILE still holds OLD, no FILE.tmp.* left.
ft_fails() {
  local name="$1" file="$2" old="$3"
  if [ "$rc" -ne 2 ]; then fail "$name" "exit $rc, expected 2; stderr: $(head -c 300 "$err")"; return; fi
  if [ "$(wc -l <"$err")" -ne 1 ] || ! grep -q "^kinetostat: error: $file: cannot write output: " "$err"; then
    fail "$name" "expected one line 'kinetostat: error: $file: cannot write output: ...', got: $(head -c 300 "$err")"; return
  fi
  if [ "$(cat "$file" 2>/dev/null)" != "$old" ]; then fail "$name" "$file changed: $(head -c 100 "$file")"; return; fi
  if ls "$file".tmp.* >/dev/null 2>&1; then fail "$name" "temporary left: $(ls "$file".tmp.*)"; return; fi
  pass
}

# ft_no_temps NAME: nothing left in the private TMPDIR.
ft_no_temps() {
  if [ -n "$(ls -A "$ft_tmp")" ]; then fail "$1" "left in TMPDIR: $(ls -A "$ft_tmp" | head -3)"; else pass; fi
}

# ft_wait_for PATTERN: wait (up to 10 s) until a file matching PATTERN (a glob) exists.
ft_wait_for() {
  local i
  for i in $(seq 1 100); do
    compgen -G "$1" >/dev/null && return 0
    sleep 0.1
  done
  return 1
}

# ft_wait_spool: until the background run (ft_background) holds its spool's file in its
# private TMPDIR (anonymous: seen as a descriptor in /proc/PID/fd), up to 10 s; where /proc
# does not show descriptors, 1.5 s. Fails when the run is gone or no such file was seen.
ft_wait_spool() {
  local i
  [ -d "/proc/$ft_pid/fd" ] || { sleep 1.5; return 0; }
  for i in $(seq 1 200); do
    ls -l "/proc/$ft_pid/fd" 2>/dev/null | grep -qF " -> $ft_tmp/" && return 0
    [ -d "/proc/$ft_pid/fd" ] || return 1
    sleep 0.05
  done
  return 1
}

# ft_background ARGS...: kinetostat in the background with SIGINT at its default action
# (a non-interactive shell starts background jobs with SIGINT ignored), TMPDIR private;
# its id in $ft_pid.
ft_background() {
  if env --default-signal=INT true 2>/dev/null; then
    TMPDIR="$ft_tmp" env --default-signal=INT "$KINETOSTAT" "$@" >"$ft_dir/bg.out" 2>"$ft_dir/bg.err" &
  else
    TMPDIR="$ft_tmp" python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
      "$KINETOSTAT" "$@" >"$ft_dir/bg.out" 2>"$ft_dir/bg.err" &
  fi
  ft_pid=$!
}

# --- /dev/full as -o: the failed write is reported
run_ks data/pr3207.nml -o /dev/full
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q '^kinetostat: error: /dev/full: cannot write output: No space' "$err" \
  && pass || fail faults-o-dev-full "rc=$rc: $(head -c 300 "$err")"
run_ks template pr3207 -o /dev/full
[ "$rc" -eq 2 ] && pass || fail faults-template-dev-full "rc=$rc: $(head -c 300 "$err")"

# --- a full file system (a small tmpfs, filled): every output, of any size
ft_mnt="$ft_dir/mnt"; mkdir -p "$ft_mnt"
if mount -t tmpfs -o size=256k tmpfs "$ft_mnt" 2>"$ft_dir/mount.err"; then
  echo old >"$ft_mnt/FILE"; echo old >"$ft_mnt/SWEEP"
  head -c 1048576 /dev/zero >"$ft_mnt/fill" 2>/dev/null   # ENOSPC: full to the last block
  for args in "data/pr3207.nml" "data/pr3207.nml --format csv" "data/pr3207.nml --format json" \
              "data/pr3207.nml --format summary" "data/pr3207.nml --format svg" "data/sixbar.nml --format csv" \
              "data/pr3207.nml --set dphi=0.01" "template pr3207"; do
    # shellcheck disable=SC2086
    TMPDIR="$ft_tmp" run_ks $args -o "$ft_mnt/FILE"
    ft_fails "faults-full-fs ($args)" "$ft_mnt/FILE" old
  done
  TMPDIR="$ft_tmp" run_ks sweep data/pr3207.nml --quiet --vary dphi=10:30:3 -o "$ft_mnt/SWEEP"
  ft_fails "faults-full-fs (sweep -o)" "$ft_mnt/SWEEP" old
  # room for part of it: the write fails in the middle
  rm -f "$ft_mnt/fill"; head -c $((256 * 1024 - 24 * 1024)) /dev/zero >"$ft_mnt/fill" 2>/dev/null
  TMPDIR="$ft_tmp" run_ks data/pr3207.nml --set dphi=1 --format csv -o "$ft_mnt/FILE"
  ft_fails "faults-fs-fills-during-write" "$ft_mnt/FILE" old
  # the spool of a large stdout run in a full TMPDIR
  rm -f "$ft_mnt/fill"; head -c 1048576 /dev/zero >"$ft_mnt/fill" 2>/dev/null
  TMPDIR="$ft_mnt" run_ks data/pr3207.nml --set dphi=0.01
  [ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && [ ! -s "$out" ] && grep -q 'No space left' "$err" && pass \
    || fail faults-full-tmpdir "rc=$rc, stdout $(wc -c <"$out") bytes: $(head -c 300 "$err")"
  [ "$(ls -A "$ft_mnt" | tr '\n' ' ')" = "FILE SWEEP fill " ] && pass || fail faults-full-fs-leftovers "$(ls -A "$ft_mnt")"
  umount "$ft_mnt" || umount -l "$ft_mnt"
else
  echo "skipped faults-full-fs: cannot mount a tmpfs here ($(head -c 200 "$ft_dir/mount.err"))"
fi

# --- a file-size limit (ulimit -f, 2 KiB), SIGXFSZ ignored (as batch systems do) or not
for ignore in "trap '' XFSZ" ":"; do
  for args in "data/pr3207.nml" "data/pr3207.nml --set dphi=0.01"; do
    echo old >"$ft_dir/limited"
    # shellcheck disable=SC2086
    (eval "$ignore"; ulimit -f 2; TMPDIR="$ft_tmp" "$KINETOSTAT" $args -o "$ft_dir/limited" >"$ft_dir/lim.out" 2>"$ft_dir/lim.err"); rc=$?
    out="$ft_dir/lim.out"; err="$ft_dir/lim.err"
    ft_fails "faults-ulimit-f ($ignore; $args)" "$ft_dir/limited" old
  done
done
(ulimit -f 2; TMPDIR="$ft_tmp" "$KINETOSTAT" data/pr3207.nml --set dphi=0.01 >"$ft_dir/lim.out" 2>"$ft_dir/lim.err"); rc=$?
[ "$rc" -eq 2 ] && grep -q '^kinetostat: error: standard output: cannot write output: File too large' "$ft_dir/lim.err" \
  && pass || fail faults-ulimit-f-stdout "rc=$rc: $(head -c 300 "$ft_dir/lim.err")"
ft_no_temps faults-ulimit-f-temps

# --- links and other non-regular files as -o
echo old >"$ft_dir/real"; ln -sf real "$ft_dir/link"
run_ks data/pr3207.nml -o "$ft_dir/link"
[ "$rc" -eq 0 ] && [ -L "$ft_dir/link" ] && cmp -s "$ft_dir/real" data/expected/pr3207.table && pass \
  || fail faults-o-symlink "rc=$rc; the link must stay a link and its target be written"
rm -f "$ft_dir/real2"; ln -sf real2 "$ft_dir/dangling"
run_ks data/pr3207.nml -o "$ft_dir/dangling"
[ "$rc" -eq 0 ] && [ -L "$ft_dir/dangling" ] && cmp -s "$ft_dir/real2" data/expected/pr3207.table && pass \
  || fail faults-o-dangling-symlink "rc=$rc; the link's target must be created"
# a link to this process' standard output (what /dev/stdout is): written to the
# descriptor, the link stays a link; after a header written by the same shell
ln -sf /proc/self/fd/1 "$ft_dir/fd1"
{ echo header; "$KINETOSTAT" data/pr3207.nml -o "$ft_dir/fd1" 2>/dev/null; } >"$ft_dir/via_fd1"; rc=$?
{ echo header; cat data/expected/pr3207.table; } >"$ft_dir/via_fd1.expected"
[ "$rc" -eq 0 ] && [ -L "$ft_dir/fd1" ] && cmp -s "$ft_dir/via_fd1" "$ft_dir/via_fd1.expected" && pass \
  || fail faults-o-fd-link "rc=$rc; $(ls -l "$ft_dir/fd1"); $(cmp "$ft_dir/via_fd1" "$ft_dir/via_fd1.expected" 2>&1)"
ln -sf /dev/fd/1 "$ft_dir/devfd1"
{ echo header; "$KINETOSTAT" data/pr3207.nml -o "$ft_dir/devfd1" 2>/dev/null; } >"$ft_dir/via_devfd1"; rc=$?
[ "$rc" -eq 0 ] && [ -L "$ft_dir/devfd1" ] && cmp -s "$ft_dir/via_devfd1" "$ft_dir/via_fd1.expected" && pass \
  || fail faults-o-devfd-link "rc=$rc; $(ls -l "$ft_dir/devfd1"); $(cmp "$ft_dir/via_devfd1" "$ft_dir/via_fd1.expected" 2>&1)"
# a link to a FIFO: written into the FIFO, never replaced
mkfifo "$ft_dir/fifo"; ln -sf fifo "$ft_dir/fifolink"
cat "$ft_dir/fifo" >"$ft_dir/fifo.out" & ft_reader=$!
run_ks data/pr3207.nml --set dphi=0.01 -o "$ft_dir/fifolink"; wait "$ft_reader"
[ "$rc" -eq 0 ] && [ -p "$ft_dir/fifo" ] && [ -L "$ft_dir/fifolink" ] && [ "$(head -c 11 "$ft_dir/fifo.out")" = " KINETOSTAT" ] \
  && pass || fail faults-o-fifo-link "rc=$rc; FIFO replaced or nothing read"
run_ks data/pr3207.nml -o "$ft_dir"
[ "$rc" -eq 2 ] && grep -q 'Is a directory' "$err" && pass || fail faults-o-directory "rc=$rc: $(head -c 300 "$err")"

# --- the mode (and, as root, the owner) of a replaced file are kept; a new file gets 666 - umask
echo old >"$ft_dir/private"; chmod 600 "$ft_dir/private"
if [ "$(id -u)" -eq 0 ]; then chown 1234:2345 "$ft_dir/private"; want="600 1234 2345"; else want="600 $(id -u) $(id -g)"; fi
run_ks data/pr3207.nml -o "$ft_dir/private"
[ "$rc" -eq 0 ] && [ "$(stat -c '%a %u %g' "$ft_dir/private")" = "$want" ] && pass \
  || fail faults-mode-kept "rc=$rc; now $(stat -c '%a %u %g' "$ft_dir/private"), expected $want"
rm -f "$ft_dir/new"; (umask 027; "$KINETOSTAT" data/pr3207.nml -o "$ft_dir/new" 2>/dev/null)
[ "$(stat -c '%a' "$ft_dir/new")" = "640" ] && pass || fail faults-mode-new "mode $(stat -c '%a' "$ft_dir/new"), expected 640 (umask 027)"

# --- planted links and FIFOs where temporaries go are never followed (names are random)
echo victim >"$ft_dir/victim"
for n in 1 2 3 4 5 6 7 8; do ln -sf "$ft_dir/victim" "$ft_tmp/kinetostat-$n"; done
ln -sf "$ft_dir/victim" "$ft_tmp/kinetostat-$$-1.out"; mkfifo "$ft_tmp/kinetostat-sweep-fifo"
echo old >"$ft_dir/target"
for pid in $$ $(($$ + 1)) $(($$ + 2)); do ln -sf "$ft_dir/victim" "$ft_dir/target.tmp.$pid"; done
TMPDIR="$ft_tmp" timeout 120 "$KINETOSTAT" data/pr3207.nml --set dphi=0.01 >"$ft_dir/big.out" 2>/dev/null; rc=$?
TMPDIR="$ft_tmp" timeout 120 "$KINETOSTAT" data/pr3207.nml --set dphi=0.01 -o "$ft_dir/target" 2>/dev/null; rc2=$?
TMPDIR="$ft_tmp" timeout 120 "$KINETOSTAT" sweep data/pr3207.nml --vary dphi=10:30:4 --jobs 2 >/dev/null 2>&1; rc3=$?
[ "$rc" -eq 0 ] && [ "$rc2" -eq 0 ] && [ "$rc3" -eq 0 ] && [ "$(cat "$ft_dir/victim")" = victim ] \
  && cmp -s "$ft_dir/big.out" "$ft_dir/target" && pass \
  || fail faults-planted-links "exits $rc $rc2 $rc3 (124: hung), victim now $(head -c 40 "$ft_dir/victim")"
rm -f "$ft_tmp"/kinetostat-* "$ft_dir"/target.tmp.*
ft_no_temps faults-planted-temps

# --- signals in the middle of a run: exit 128 + signal, no temporary, -o FILE as it was
for sig in INT TERM HUP; do
  num=$(kill -l "$sig")
  echo old >"$ft_dir/sigfile"
  ft_background "${ft_big[@]}" -o "$ft_dir/sigfile"
  if ft_wait_for "$ft_dir/sigfile.tmp.*"; then
    mode=$(stat -c '%a' "$ft_dir"/sigfile.tmp.* 2>/dev/null)
    [ "$mode" = 600 ] && pass || fail "faults-temp-mode-600" "the temporary has mode $mode"
  else
    fail "faults-temp-beside" "no $ft_dir/sigfile.tmp.* seen within 10 s of the start of a 10^6-step run"
  fi
  kill -"$sig" "$ft_pid"; wait "$ft_pid" 2>/dev/null; rc=$?
  [ "$rc" -eq $((128 + num)) ] && [ "$(cat "$ft_dir/sigfile")" = old ] && ! ls "$ft_dir"/sigfile.tmp.* >/dev/null 2>&1 \
    && pass || fail "faults-signal-$sig-o" "exit $rc (expected $((128 + num))), file $(head -c 20 "$ft_dir/sigfile"), $(ls "$ft_dir")"
  # to standard output: the spool (anonymous, in TMPDIR) leaves nothing; the signal comes
  # once the spool has its file
  ft_background "${ft_big[@]}"
  ft_wait_spool; spooled=$?
  kill -"$sig" "$ft_pid"; wait "$ft_pid" 2>/dev/null; rc=$?
  [ "$spooled" -eq 0 ] && [ "$rc" -eq $((128 + num)) ] && [ ! -s "$ft_dir/bg.out" ] && pass \
    || fail "faults-signal-$sig-stdout" "exit $rc (expected $((128 + num))), stdout $(wc -c <"$ft_dir/bg.out") bytes, spool's file seen: $([ "$spooled" -eq 0 ] && echo yes || echo no)"
  ft_no_temps "faults-signal-$sig-temps"
done
# SIGTERM after 0.3 s (before the spool took anything)
ft_background "${ft_big[@]}"; sleep 0.3; kill -TERM "$ft_pid"; wait "$ft_pid" 2>/dev/null; rc=$?
[ "$rc" -eq 143 ] && pass || fail faults-signal-early "exit $rc, expected 143"
ft_no_temps faults-signal-early-temps
# a closed pipe: `| head -1` ends the run with SIGPIPE, nothing left
TMPDIR="$ft_tmp" "$KINETOSTAT" data/pr3207.nml --set dphi=0.01 2>/dev/null | head -1 >/dev/null
ft_no_temps faults-head-1
# SIGPIPE ignored (as some shells and CI runners do): the write to the closed pipe is exit 2
(trap '' PIPE; TMPDIR="$ft_tmp" "$KINETOSTAT" data/pr3207.nml --set dphi=0.01 2>"$ft_dir/pipe.err" | head -1 >/dev/null
 exit "${PIPESTATUS[0]}"); rc=$?
[ "$rc" -eq 2 ] && grep -q '^kinetostat: error: standard output: cannot write output: Broken pipe' "$ft_dir/pipe.err" && pass \
  || fail faults-sigpipe-ignored "rc=$rc: $(grep -v warning "$ft_dir/pipe.err" | head -c 300)"
ft_no_temps faults-sigpipe-ignored-temps

# ft_sweep_started: a sweep of two children in the background; its children's ids in
# $ft_children once they run (up to 5 s)
ft_sweep_started() {
  local i
  ft_background sweep data/pr3207.nml --vary dphi=0.0004:0.0005:2 --jobs 2 -o "$ft_dir/sweepfile"
  ft_children=""
  for i in $(seq 1 50); do
    ft_children=$(pgrep -P "$ft_pid" | tr '\n' ' ')
    [ -n "$ft_children" ] && break
    sleep 0.1
  done
  sleep 0.3
}

# --- SIGTERM of a sweep ends its children; no files are left
echo old >"$ft_dir/sweepfile"
ft_sweep_started
kill -TERM "$ft_pid"; wait "$ft_pid" 2>/dev/null; rc=$?
ft_alive=""
for c in $ft_children; do kill -0 "$c" 2>/dev/null && ft_alive="$ft_alive $c"; done
[ -n "$ft_children" ] && [ "$rc" -eq 143 ] && [ -z "$ft_alive" ] && [ "$(cat "$ft_dir/sweepfile")" = old ] && pass \
  || fail faults-sweep-sigterm "exit $rc, children '$ft_children', still alive '$ft_alive'"
ft_no_temps faults-sweep-sigterm-temps
for c in $ft_alive; do kill -KILL "$c" 2>/dev/null; done

# --- SIGKILL of a sweep (no handler runs): its children watch a pipe to it and end within
# 1 s when it closes (an orphan reaped by init, or a zombie, is not computing)
ft_running() { local st; st=$(ps -o stat= -p "$1" 2>/dev/null); [ -n "$st" ] && [ "${st#Z}" = "$st" ]; }
ft_sweep_started
kill -KILL "$ft_pid"; wait "$ft_pid" 2>/dev/null; rc=$?
sleep 1
ft_alive=""
for c in $ft_children; do ft_running "$c" && ft_alive="$ft_alive $c"; done
[ -n "$ft_children" ] && [ "$rc" -eq 137 ] && [ -z "$ft_alive" ] && pass \
  || fail faults-sweep-sigkill "exit $rc, children '$ft_children', still computing 1 s later '$ft_alive'"
for c in $ft_alive; do kill -KILL "$c" 2>/dev/null; done
rm -f "$ft_dir"/sweepfile.tmp.*

# --- out of memory (a limit on the address space, ulimit -v): an allocation that scales with
# the deck, its steps or the output fails as exit 2 with one line naming what did not fit, never
# the run-time library's abort and backtrace
ft_oom() {
  local name="$1" pattern="$2"; shift 2
  if [ "$rc" -eq 2 ] && [ "$(wc -l <"$ft_dir/oom.err")" -eq 1 ] && grep -Eq "^kinetostat: error: .*out of memory: $pattern" "$ft_dir/oom.err"; then pass
  else fail "$name" "exit $rc: $(head -c 300 "$ft_dir/oom.err")"; fi
}
truncate -s 200M "$ft_dir/sparse.nml"
(ulimit -v 100000; "$KINETOSTAT" "$ft_dir/sparse.nml" >/dev/null 2>"$ft_dir/oom.err"); rc=$?
ft_oom faults-oom-deck-file "no room for the deck's text \(209715200 bytes\)"
rm -f "$ft_dir/sparse.nml"
(ulimit -v 100000; head -c 200000000 /dev/zero | "$KINETOSTAT" - >/dev/null 2>"$ft_dir/oom.err"); rc=$?
ft_oom faults-oom-deck-stdin "no room for the deck's text \(more than [0-9]+ bytes read\)"
# tools/test --long: runs of 10^6 steps and their drawings under limits from 24 to 64 MiB end
# either well (exit 0) or with that one line (exit 2): no allocation that grows with the deck,
# the steps or the output (1 MiB or more) aborts. (A small fixed allocation may still find the
# limit reached at the edge; the program needs about 20 MiB to load its libraries.)
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  sed 's/f5c_work = 3000, f5c_idle = 0/f5c = 1000000*100, n = 1000000/; s/dphi = 30 /dphi = 0.00036 /; /phi_cut_/d' \
    data/pr3207.nml >"$ft_dir/oom_pr3207.nml"
  sed 's/  n = 13/  n = 1000000/; s/drive(1)%step = 30/drive(1)%step = 0.00036/' data/linkage_slider_crank.nml \
    >"$ft_dir/oom_linkage.nml"
  ft_bad=""
  for run in "oom_pr3207.nml --format summary" "oom_pr3207.nml --format json" "oom_linkage.nml --format plans --at 2" \
             "oom_linkage.nml --format svg"; do
    for kib in 24576 28672 32768 40960 49152 65536; do
      # shellcheck disable=SC2086
      (ulimit -v "$kib"; cd "$ft_dir" && "$KINETOSTAT" $run >/dev/null 2>"$ft_dir/oom.err"); rc=$?
      if [ "$rc" -eq 0 ] && [ ! -s "$ft_dir/oom.err" ]; then continue; fi
      if [ "$rc" -eq 2 ] && [ "$(wc -l <"$ft_dir/oom.err")" -eq 1 ] && grep -q "^kinetostat: error: .*out of memory: no room for " "$ft_dir/oom.err"; then
        continue
      fi
      small=$(sed -n 's/.*Error allocating \([0-9]*\) bytes.*/\1/p' "$ft_dir/oom.err" | head -1)
      if [ -n "$small" ] && [ "$small" -lt 1048576 ]; then continue; fi
      ft_bad="$ft_bad [$run at $kib KiB: exit $rc: $(head -c 160 "$ft_dir/oom.err" | tr '\n' ' ')]"
    done
  done
  [ -z "$ft_bad" ] && pass || fail faults-oom-sweep "$ft_bad"
  rm -f "$ft_dir"/oom_*.nml
fi
