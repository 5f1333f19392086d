# Sourced by tools/kinetostat and tools/test: put where pip installs console scripts (fpm)
# on PATH, also when pyenv's shims were not refreshed or pip fell back to --user.
py_scripts="$(python3 -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null || true)"
py_user_bin="$(python3 -m site --user-base 2>/dev/null || true)/bin"
export PATH="$py_scripts:$py_user_bin:$PATH"

# The build users run (tools/kinetostat): fpm's release profile with link-time optimisation
# (kernels ~15 % faster), the same flags for every object and for the link.
# tools/test checks that this build writes the golden files byte for byte too.
release_build=(--profile release --flag "-flto=auto" --c-flag "-flto=auto" --link-flag "-flto=auto")
