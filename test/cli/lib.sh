# Helpers for the command-line tests (sourced by tools/test). $KINETOSTAT is the binary.
# Each check prints "FAIL name: detail" on failure and counts passes and failures.
cli_passed=0
cli_failed=0
cli_tmp="$(mktemp -d)"
# Tolerances of golden comparisons (kinetostat diff and numdiff): relative 1e-9, absolute 1e-9
# (for exact zeros).
golden_rtol=1e-9
golden_atol=1e-9

pass() { cli_passed=$((cli_passed + 1)); }
fail() { cli_failed=$((cli_failed + 1)); echo "FAIL $1: $2"; }

# run_ks ARGS...: run kinetostat, capture stdout/stderr/exit code in $out $err $rc.
run_ks() {
  out="$cli_tmp/stdout"; err="$cli_tmp/stderr"
  "$KINETOSTAT" "$@" >"$out" 2>"$err"; rc=$?
}

# run_ks_into FILE ARGS...: run_ks with stdout written to FILE ($out is FILE): for an output a
# script keeps, without a copy (a process) per run.
run_ks_into() {
  out="$1"; err="$cli_tmp/stderr"; shift
  "$KINETOSTAT" "$@" >"$out" 2>"$err"; rc=$?
}

# expect_exit NAME CODE ARGS...: exit code must be CODE.
expect_exit() {
  local name="$1" code="$2"; shift 2
  run_ks "$@"
  if [ "$rc" -eq "$code" ]; then pass; else fail "$name" "exit code $rc, expected $code; stderr: $(head -c 300 "$err")"; fi
}

# expect_input_error NAME PATTERN DECK: exit 2, one stderr line "kinetostat: error: ..." naming
# the deck and matching PATTERN (grep -E), nothing on stdout, no output file, no NaN.
expect_input_error() {
  local name="$1" pattern="$2" deck="$3" code="${4:-2}"
  local target="$cli_tmp/never_written.out"
  rm -f "$target" "$target".tmp.*
  run_ks "$deck" -o "$target"
  local lines; lines=$(wc -l <"$err")
  if [ "$rc" -ne "$code" ]; then fail "$name" "exit code $rc, expected $code; stderr: $(head -c 300 "$err")"; return; fi
  if [ "$lines" -ne 1 ]; then fail "$name" "stderr has $lines lines, expected 1: $(head -c 300 "$err")"; return; fi
  if ! grep -q "^kinetostat: error: $deck" "$err"; then fail "$name" "message does not start with 'kinetostat: error: $deck': $(cat "$err")"; return; fi
  if ! grep -Eq "$pattern" "$err"; then fail "$name" "message does not match /$pattern/: $(cat "$err")"; return; fi
  if ls "$target"* >/dev/null 2>&1; then fail "$name" "output file left behind"; return; fi
  if [ -s "$out" ]; then fail "$name" "something was written to stdout"; return; fi
  if grep -qiE 'backtrace|error termination|runtime error|^STOP' "$err"; then fail "$name" "runtime error text in stderr"; return; fi
  pass
}

# is_output FILE: whether FILE is an output of the program (a legacy table or a CSV file).
is_output() {
  head -1 "$1" | grep -Eq '^ KINETOSTAT |^[A-Za-z0-9_]+(,[A-Za-z0-9_]+)+$'
}

# ks_diff EXPECTED ACTUAL: `kinetostat diff` with the golden tolerances (rtol and atol 1e-9 in
# every column's unit); its report in $cli_tmp/ks_diff.out, its exit code returned.
ks_diff() {
  "$KINETOSTAT" diff --rtol "$golden_rtol" --atol "$golden_atol" "$1" "$2" >"$cli_tmp/ks_diff.out" 2>&1
}

# expect_same NAME EXPECTED ACTUAL: outputs of the program agree by `kinetostat diff` (angles
# modulo 360, deck lines ignored) and, as a second opinion, by numdiff; other files (rows cut
# out of a CSV) by numdiff alone. All within the golden tolerances.
expect_same() {
  local name="$1" expected="$2" actual="$3" drc
  if is_output "$expected"; then
    ks_diff "$expected" "$actual"; drc=$?
    if [ "$drc" -ne 0 ]; then
      fail "$name" "kinetostat diff (exit $drc) finds $actual differs from $expected beyond rel $golden_rtol / abs $golden_atol:
$(head -20 "$cli_tmp/ks_diff.out")"
      return
    fi
  fi
  if numdiff -q -s ' \t\n,=()' -r "$golden_rtol" -a "$golden_atol" "$expected" "$actual" >/dev/null 2>&1; then
    pass
  else
    fail "$name" "numdiff: differs from $expected beyond rel $golden_rtol / abs $golden_atol:
$(numdiff -s ' \t\n,=()' -r "$golden_rtol" -a "$golden_atol" "$expected" "$actual" 2>&1 | head -20)"
  fi
}

# expect_differ NAME EXPECTED ACTUAL: the comparison must report a difference (it can fail):
# `kinetostat diff` exits 1 on outputs of the program, and numdiff exits 1 too (its verdict
# "differ"; 255 is numdiff's own failure, not a difference).
expect_differ() {
  local name="$1" expected="$2" actual="$3" drc
  if is_output "$expected"; then
    ks_diff "$expected" "$actual"; drc=$?
    if [ "$drc" -ne 1 ]; then
      fail "$name" "kinetostat diff exits $drc (expected 1) on a perturbed file: $(head -5 "$cli_tmp/ks_diff.out")"
      return
    fi
  fi
  numdiff -q -s ' \t\n,=()' -r "$golden_rtol" -a "$golden_atol" "$expected" "$actual" >"$cli_tmp/numdiff.out" 2>&1
  drc=$?
  if [ "$drc" -eq 1 ]; then
    pass
  elif [ "$drc" -eq 0 ]; then
    fail "$name" "numdiff accepted a perturbed file: the golden comparison cannot fail"
  else
    fail "$name" "numdiff failed (exit $drc): $(head -3 "$cli_tmp/numdiff.out")"
  fi
}

# expect_no_nan NAME FILE
expect_no_nan() {
  if grep -qiE '(^|[^a-z])(nan|inf|infinity)([^a-z]|$)|\*\*\*' "$2"; then fail "$1" "NaN/Infinity/overflow stars in $2"; else pass; fi
}

# deck_with NAME BASE SED_EXPR: a copy of deck BASE edited by sed, written to $cli_tmp/NAME.nml.
deck_with() {
  local name="$1" base="$2" expr="$3"
  sed -e "$expr" "$base" >"$cli_tmp/$name.nml"
  echo "$cli_tmp/$name.nml"
}

# run_py ARGS...: `python3 ARGS...` (ARGS: - with the script on standard input, -c CODE, or
# FILE.py, then the script's arguments) run by the script's Python server when one is
# running (tools/python_server.py: one interpreter for the many short calls of a script, each
# call in fresh globals with its own arguments, working directory, environment, standard
# input, output and exit status), else by python3. tools/test starts a server before each CLI
# script and stops it after (python_server_start, python_server_stop: its processor time is
# the script's). One call at a time: no run_py in a background job or beside another in a
# pipeline.
python_server_start() {
  [ -z "${py_server_pid:-}" ] || return 0
  py_server_dir="$cli_tmp/python_server"
  rm -rf "$py_server_dir"
  mkdir -p "$py_server_dir" && mkfifo "$py_server_dir/req" "$py_server_dir/resp" || return 1
  python3 "$root/tools/python_server.py" "$py_server_dir" </dev/null &
  py_server_pid=$!
  # its first answer once it reads its requests (a request sent before would be lost)
  local ready=""
  read -r ready <"$py_server_dir/resp"
  [ "$ready" = ready ] || { echo "python_server_start: no server ($ready)" >&2; wait "$py_server_pid"; py_server_pid=""; }
}
python_server_stop() {
  [ -n "${py_server_pid:-}" ] || return 0
  printf 'quit\0\001end\0' 1<>"$py_server_dir/req"
  wait "$py_server_pid"
  py_server_pid=""
}
run_py() {
  if [ -z "${py_server_pid:-}" ] || ! kill -0 "$py_server_pid" 2>/dev/null; then python3 "$@"; return; fi
  local name env=() status="" fd chunks
  # the exported variables (no process: a variable's attributes, by the first letter of its name)
  for name in ${!A@} ${!B@} ${!C@} ${!D@} ${!E@} ${!F@} ${!G@} ${!H@} ${!I@} ${!J@} ${!K@} ${!L@} ${!M@} ${!N@} ${!O@} ${!P@} ${!Q@} ${!R@} ${!S@} ${!T@} ${!U@} ${!V@} ${!W@} ${!X@} ${!Y@} ${!Z@} ${!a@} ${!b@} ${!c@} ${!d@} ${!e@} ${!f@} ${!g@} ${!h@} ${!i@} ${!j@} ${!k@} ${!l@} ${!m@} ${!n@} ${!o@} ${!p@} ${!q@} ${!r@} ${!s@} ${!t@} ${!u@} ${!v@} ${!w@} ${!x@} ${!y@} ${!z@} ${!_@}; do
    [[ -v $name ]] && [[ ${!name@a} == *x* ]] && env+=("$name=${!name}")
  done
  printf '%s\0' "$BASHPID" "$PWD" "${#env[@]}" "${env[@]}" "$@" $'\001end' 1<>"$py_server_dir/req"
  exec {fd}<>"$py_server_dir/resp"
  until read -r -t 5 -u "$fd" status; do
    kill -0 "$py_server_pid" 2>/dev/null || { status=""; break; }
  done
  exec {fd}<&-
  if [ -z "$status" ]; then echo "run_py: the Python server stopped (tools/python_server.py)" >&2; return 1; fi
  mapfile -d '' chunks <"$py_server_dir/out"; printf '%s' "${chunks[@]}"
  mapfile -d '' chunks <"$py_server_dir/err"; printf '%s' "${chunks[@]}" >&2
  return "$status"
}

# check_job CHECKER LABEL ARGS...: a call `python3 tools/CHECKER.py ARGS...` (no argument
# holding a tab), noted to run with the others of CHECKER in one Python process by
# check_batch CHECKER: one check per call, LABEL its name, its first 20 lines of output on
# failure (tools/batch_check.py).
check_job() {
  local checker="$1" IFS=$'\t'; shift
  printf '%s\n' "$*" >>"$cli_tmp/batch.$checker.tsv"
}
check_batch() {
  local checker="$1" jobs="$cli_tmp/batch.$1.tsv" label status
  [ -s "$jobs" ] || { fail "batch-$checker" "no calls noted"; return; }
  rm -rf "$cli_tmp/batch.$checker"
  python3 "$root/tools/batch_check.py" "$checker" "$jobs" "$cli_tmp/batch.$checker" \
    >"$cli_tmp/batch.$checker.status" 2>"$cli_tmp/batch.$checker.err" \
    || fail "batch-$checker" "$(head -20 "$cli_tmp/batch.$checker.err")"
  # the calls' statuses in the order of the calls (a label may repeat: the same call twice)
  while IFS=$'\t' read -r label status; do
    if [ "$status" = 0 ]; then pass
    else fail "$label" "exit ${status:-none}: $(head -20 "$cli_tmp/batch.$checker/$label.out" 2>/dev/null)"; fi
  done < <(paste <(cut -f1 "$jobs") <(cut -f2 "$cli_tmp/batch.$checker.status"))
  rm -f "$jobs"
}

# batch_run CHECKER: the calls noted with check_job for CHECKER run in one Python process
# (tools/batch_check.py) without being counted, for checks that must fail: each call's exit
# status and output are then read by expect_batch_fail.
batch_run() {
  local checker="$1" jobs="$cli_tmp/batch.$1.tsv"
  rm -rf "$cli_tmp/batch.$checker"
  python3 "$root/tools/batch_check.py" "$checker" "$jobs" "$cli_tmp/batch.$checker" \
    >"$cli_tmp/batch.$checker.status" 2>"$cli_tmp/batch.$checker.err" \
    || fail "batch-$checker" "$(head -20 "$cli_tmp/batch.$checker.err")"
  rm -f "$jobs"
}
# expect_batch_fail CHECKER LABEL PATTERN NAME: the call LABEL of the last batch_run of CHECKER
# failed (exit status not 0) with its verdict: its output matches PATTERN (grep, basic regex).
expect_batch_fail() {
  local checker="$1" label="$2" pattern="$3" name="$4" status
  status=$(awk -F'\t' -v label="$label" '$1 == label { print $2 }' "$cli_tmp/batch.$checker.status")
  if [ -n "$status" ] && [ "$status" != 0 ] && grep -q -- "$pattern" "$cli_tmp/batch.$checker/$label.out"; then pass
  else fail "$name" "exit ${status:-none} (a failure expected): $(head -3 "$cli_tmp/batch.$checker/$label.out" 2>/dev/null)"; fi
}

# heavy_deck NAME: true in the default suite (not with tools/test --long) for a bundled deck
# whose every run takes most of a second of processor time in the checks' build (tools/test:
# fpm's debug flags at -O1; the &linkage engine's steady cycles: over 361 poses 0.7 s, the
# engine's over 145 poses of two turns 0.25 s; every other deck 0.02 s at most): the scripts that run each bundled deck in several
# ways run it in one of them by default.
heavy_deck() {
  [ "${KINETOSTAT_LONG:-0}" != 1 ] || return 1
  case "$1" in linkage_pr3207_flywheel | linkage_engine_flywheel) return 0 ;; esac
  return 1
}

# pdf_stand_in: the directory of a stand-in rsvg-convert that writes its -o file ("stand-in
# PDF") at once, for the runs of `kinetostat sheets` whose PDF no check reads (rsvg-convert is
# half of such a run's processor time): PATH="$(pdf_stand_in):$PATH" "$KINETOSTAT" sheets ...
pdf_stand_in() {
  local dir="$cli_tmp/pdf_stand_in"
  if [ ! -x "$dir/rsvg-convert" ]; then
    mkdir -p "$dir"
    printf '#!/bin/sh\nwhile [ $# -gt 1 ] && [ "$1" != -o ]; do shift; done\necho "stand-in PDF" >"$2"\n' \
      >"$dir/rsvg-convert"
    chmod +x "$dir/rsvg-convert"
  fi
  echo "$dir"
}

# run_ks_cached KEY ARGS...: run_ks ARGS once per suite run: the scripts that need the same
# output (the CSV with --kinematics of every bundled deck: test_dxf, test_kinematics,
# test_npy, test_plans) share it under $cli_tmp/cache/KEY; $out, $err and $rc as run_ks sets them (the
# files are the cache's: copy before changing them).
run_ks_cached() {
  local key="$1"; shift
  local dir="$cli_tmp/cache"
  if [ ! -f "$dir/$key.rc" ]; then
    mkdir -p "$dir"
    "$KINETOSTAT" "$@" >"$dir/$key.out" 2>"$dir/$key.err"; echo "$?" >"$dir/$key.rc"
  fi
  out="$dir/$key.out"; err="$dir/$key.err"; read -r rc <"$dir/$key.rc"
}

# from_golden NAME SUFFIX ARGS...: the binary's output of data/NAME.nml with ARGS in $out (and
# $rc), for a script that checks what the bundled decks' outputs look like:
# data/expected/NAME.SUFFIX when there is one - tools/test checks that the goldens are
# the binary's output byte for byte (tools/regen-goldens: SUFFIX csv is --format csv, svg
# --format svg, ru.table --lang ru) - otherwise the binary run.
from_golden() {
  local name="$1" suffix="$2"; shift 2
  if [ -f "data/expected/$name.$suffix" ]; then
    out="$cli_tmp/golden.out"; cp "data/expected/$name.$suffix" "$out"; rc=0
  else
    run_ks "data/$name.nml" "$@"
  fi
}
