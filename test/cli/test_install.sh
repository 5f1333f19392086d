# tools/kinetostat and tools/bootstrap, run on a copy of the scripts with stand-ins for fpm,
# apt-get and python3 (nothing is installed or built): the fast path runs an up-to-date
# binary at once, a build says one line, the Debian path asks apt-get for the system packages
# only, puts fpm (and for --test the linter) into the project venv .local/venv, and never uses
# --break-system-packages.

inst="$cli_tmp/install"
rm -rf "$inst"; mkdir -p "$inst/tree/tools" "$inst/tree/src" "$inst/tree/app" "$inst/stub" "$inst/bin"
log="$inst/calls.log"; : >"$log"
cp tools/kinetostat tools/bootstrap tools/env.sh "$inst/tree/tools/"
echo 'name = "stand-in"' >"$inst/tree/fpm.toml"
echo 'module m; end module m' >"$inst/tree/src/m.f90"
echo 'program p; end program p' >"$inst/tree/app/main.f90"

# the commands the scripts may use, from this machine; the toolchain only as stand-ins
for c in bash sh env dirname basename mktemp rm mkdir cat ls id uname find touch chmod sed grep head tail \
  tr cp mv sleep date wc readlink ln; do
  p="$(command -v "$c" 2>/dev/null)" && ln -sf "$p" "$inst/bin/$c"
done
cat >"$inst/stub/fpm" <<EOF
#!/bin/bash
echo "fpm \$*" >>"$log"
mkdir -p "$inst/tree/.local/bin"
printf '#!/bin/bash\necho "binary \$*"\n' >"$inst/tree/.local/bin/kinetostat"
chmod +x "$inst/tree/.local/bin/kinetostat"
EOF
cat >"$inst/stub/fake-bootstrap" <<EOF
#!/bin/bash
echo "bootstrap \$*" >>"$log"
EOF
chmod +x "$inst/stub/fpm" "$inst/stub/fake-bootstrap"

# ---- tools/kinetostat: first run, fast path, rebuild after a source changes
mv "$inst/tree/tools/bootstrap" "$inst/tree/tools/bootstrap.real"
cp "$inst/stub/fake-bootstrap" "$inst/tree/tools/bootstrap"
ks_path="$inst/stub:$inst/bin"
PATH="$ks_path" HOME="$inst" "$inst/tree/tools/kinetostat" --version >"$inst/out" 2>"$inst/err"
if [ "$(cat "$inst/out")" = "binary --version" ] && [ "$(cat "$inst/err")" = "kinetostat: building (first run, about 2 minutes) ..." ] \
  && grep -q '^fpm install --profile release' "$log" && grep -q '^bootstrap $' "$log"; then pass
else fail install-first-run "stdout: $(cat "$inst/out"); stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi

: >"$log"
# the best of three runs' processor time (user + sys of the script and what it starts: bash's
# `time`), which the machine's load does not stretch as it does wall time
took_ms=100000
for try in 1 2 3; do
  t=$( { TIMEFORMAT='%3U %3S'; time PATH="$ks_path" HOME="$inst" "$inst/tree/tools/kinetostat" a b \
    >"$inst/out" 2>"$inst/err"; } 2>&1 | awk '{ printf "%d", ($1 + $2) * 1000 }')
  [ "${t:-100000}" -lt "$took_ms" ] && took_ms=$t
done
# < 0.1 s over the binary is the promise (docs/install.md measures ~0.01 s with the real
# binary); here the whole run, stand-in binary included, must take < 100 ms of processor time
if [ "$(cat "$inst/out")" = "binary a b" ] && [ ! -s "$inst/err" ] && [ ! -s "$log" ] && [ "$took_ms" -lt 100 ]; then pass
else fail install-fast-path "took ${took_ms} ms of processor time (limit 100); stdout: $(cat "$inst/out"); stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi

touch -d '+1 minute' "$inst/tree/src/m.f90"
PATH="$ks_path" HOME="$inst" "$inst/tree/tools/kinetostat" >"$inst/out" 2>"$inst/err"
if [ "$(cat "$inst/err")" = "kinetostat: rebuilding (sources changed) ..." ] && grep -q '^fpm install' "$log"; then pass
else fail install-rebuild "stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi
mv "$inst/tree/tools/bootstrap.real" "$inst/tree/tools/bootstrap"

# ---- tools/bootstrap, Debian path: gfortran and fpm missing, python3 -m venv refused until
# python3-venv is installed (as on a new Debian 12 / Ubuntu 24.04)
cat >"$inst/stub/apt-get" <<EOF
#!/bin/bash
echo "apt-get \$*" >>"$log"
case "\$*" in *python3-venv*) touch "$inst/venv_ok" ;; esac
case "\$*" in *gfortran*) printf '#!/bin/bash\n' >"$inst/stub/gfortran"; chmod +x "$inst/stub/gfortran" ;; esac
exit 0
EOF
# the venv's python: logs, and `-m pip install PACKAGE` puts a stand-in command into the venv
cat >"$inst/venv-python" <<'EOF'
#!/bin/bash
echo "venv-python $*" >>"$CALLS_LOG"
for a in "$@"; do
  case "$a" in fpm) t=fpm ;; fortitude-lint*) t=fortitude ;; *) continue ;; esac
  printf '#!/bin/bash\necho fortitude 0.10.0\n' >"$(dirname "$0")/$t"; chmod +x "$(dirname "$0")/$t"
done
EOF
cat >"$inst/stub/python3" <<EOF
#!/bin/bash
echo "python3 \$*" >>"$log"
case "\$1 \$2" in
  "-m venv")
    [ -e "$inst/venv_ok" ] || exit 1
    mkdir -p "\$3/bin"
    cp "$inst/venv-python" "\$3/bin/python"; cp "$inst/venv-python" "\$3/bin/pip"
    chmod +x "\$3/bin/python" "\$3/bin/pip" ;;
  "-m pip") echo "pip outside a venv" >>"$log"; exit 1 ;;
  *) exit 1 ;;
esac
EOF
printf '#!/bin/bash\nexec "$@"\n' >"$inst/stub/sudo"; chmod +x "$inst/stub/sudo"
export CALLS_LOG="$log"
chmod +x "$inst/stub/apt-get" "$inst/stub/python3"
rm -f "$inst/stub/fpm"
# stand-ins that are present: the test tools (so that only --test's linter is missing)
for c in numdiff xmllint rsvg-convert; do printf '#!/bin/bash\n' >"$inst/stub/$c"; chmod +x "$inst/stub/$c"; done
: >"$log"
PATH="$inst/stub:$inst/bin" HOME="$inst" "$inst/tree/tools/bootstrap" >"$inst/out" 2>"$inst/err"; brc=$?
if [ "$brc" -eq 0 ] && grep -q '^apt-get install .*gfortran.*python3-venv' "$log" && [ -x "$inst/tree/.local/venv/bin/fpm" ] \
  && grep -q '^venv-python -m pip install .* fpm$' "$log" && ! grep -q 'fortitude' "$log" \
  && ! grep -q 'break-system-packages\|pip outside a venv\|liblapack' "$log" \
  && [ "$(wc -l <"$inst/err")" -eq 2 ]; then pass
else fail install-bootstrap-debian "exit $brc; stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi

# second run: everything present, silent, no package manager
: >"$log"
PATH="$inst/stub:$inst/bin" HOME="$inst" "$inst/tree/tools/bootstrap" >"$inst/out" 2>"$inst/err"; brc=$?
if [ "$brc" -eq 0 ] && [ ! -s "$inst/err" ] && ! grep -q 'apt-get\|pip' "$log"; then pass
else fail install-bootstrap-idempotent "exit $brc; stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi

# --test adds the pinned linter, into the same venv
: >"$log"
PATH="$inst/stub:$inst/bin" HOME="$inst" "$inst/tree/tools/bootstrap" --test >"$inst/out" 2>"$inst/err"; brc=$?
if [ "$brc" -eq 0 ] && grep -q '^venv-python -m pip install .* fortitude-lint==0.10.0$' "$log" \
  && [ -x "$inst/tree/.local/venv/bin/fortitude" ] && ! grep -q 'apt-get\|break-system' "$log"; then pass
else fail install-bootstrap-test "exit $brc; stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi

# no apt-get (macOS, Fedora, conda): names what is missing and stops, runs no package manager
rm -f "$inst/stub/apt-get" "$inst/stub/gfortran"
: >"$log"
PATH="$inst/stub:$inst/bin" HOME="$inst" "$inst/tree/tools/bootstrap" >"$inst/out" 2>"$inst/err"; brc=$?
if [ "$brc" -eq 1 ] && grep -q '^bootstrap: missing gfortran .*docs/install.md' "$inst/err"; then pass
else fail install-bootstrap-no-apt "exit $brc; stderr: $(cat "$inst/err"); calls: $(cat "$log")"; fi

# the scripts themselves never name --break-system-packages
if ! grep -q -- '--break-system-packages' tools/bootstrap tools/env.sh tools/kinetostat tools/test; then pass
else fail install-no-break-system-packages "found in tools/"; fi
