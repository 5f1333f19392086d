# Sourced by tools/kinetostat, tools/bootstrap and tools/test: put the Python tools (fpm,
# fortitude) on PATH wherever tools/bootstrap or a user put them: the project venv
# .local/venv, pipx's ~/.local/bin, pip's scripts directory (also when pyenv's shims were not
# refreshed or pip used --user).
env_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
py_scripts="$(python3 -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null || true)"
py_user_base="$(python3 -m site --user-base 2>/dev/null || true)"
export PATH="$env_root/.local/venv/bin${py_scripts:+:$py_scripts}${py_user_base:+:$py_user_base/bin}:$PATH:$HOME/.local/bin"

# LAPACK outside the linker's default directories: Homebrew's keg-only lapack (Apple silicon,
# Intel), an active conda environment. Found there, it is given to the linker (LIBRARY_PATH)
# and to the loader (rpath in the release build below).
kinetostat_lapack_dir=""
for d in /opt/homebrew/opt/lapack/lib /usr/local/opt/lapack/lib ${CONDA_PREFIX:+"$CONDA_PREFIX/lib"}; do
  if [ -e "$d/liblapack.so" ] || [ -e "$d/liblapack.dylib" ] || [ -e "$d/liblapack.a" ]; then kinetostat_lapack_dir="$d"; break; fi
done
lapack_link=""
if [ -n "$kinetostat_lapack_dir" ]; then
  export LIBRARY_PATH="$kinetostat_lapack_dir${LIBRARY_PATH:+:$LIBRARY_PATH}"
  lapack_link=" -Wl,-rpath,$kinetostat_lapack_dir"
fi

# The build users run (tools/kinetostat): fpm's release profile with link-time optimisation
# (kernels ~15 % faster), the same flags for every object and for the link.
# tools/test checks that this build writes the golden files byte for byte too.
release_build=(--profile release --flag "-flto=auto" --c-flag "-flto=auto" --link-flag "-flto=auto$lapack_link")
