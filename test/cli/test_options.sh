# The option table (src/cli/kinetostat_cli_options.f90) writes --help's synopsis and the
# usage line; tools/check_options.py checks the man page and the bash completion against
# them, and docs/cli.md's synopsis: every option, subcommand, value of --format/--lang/--frame/
# --method, kind and preset.

opt_dir="$cli_tmp/options"; mkdir -p "$opt_dir"
run_py tools/check_options.py "$KINETOSTAT" >"$opt_dir/check.out" 2>&1
grep -qx 'check_options: ok' "$opt_dir/check.out" && pass || fail options-man-completion "$(head -20 "$opt_dir/check.out")"

# the check can fail: a kind dropped from the completion, an option from the man page's
# synopsis, a subcommand from the completion
sed 's/ linkage / /' completions/kinetostat.bash >"$opt_dir/no_linkage.bash"
run_py tools/check_options.py "$KINETOSTAT" --completion "$opt_dir/no_linkage.bash" --man "" >"$opt_dir/bad1.out" 2>&1
grep -q "^check_options: completion: 'kinetostat template ' lacks the kind linkage$" "$opt_dir/bad1.out" \
  && grep -q '^check_options: [0-9]* problems$' "$opt_dir/bad1.out" && pass \
  || fail options-check-fails-on-completion "$(cat "$opt_dir/bad1.out")"
sed 's/ balance structure / /' completions/kinetostat.bash >"$opt_dir/no_sub.bash"
run_py tools/check_options.py "$KINETOSTAT" --completion "$opt_dir/no_sub.bash" --man "" >"$opt_dir/bad2.out" 2>&1
grep -q "lacks the subcommand structure$" "$opt_dir/bad2.out" && pass \
  || fail options-check-fails-on-subcommand "$(cat "$opt_dir/bad2.out")"
awk '!(/^\.RB \[ \\-\\-shaking \]$/ && !done++)' man/kinetostat.1 >"$opt_dir/no_shaking.1"
run_py tools/check_options.py "$KINETOSTAT" --completion "" --man "$opt_dir/no_shaking.1" >"$opt_dir/bad3.out" 2>&1
grep -q "^check_options: man: SYNOPSIS of 'kinetostat' differs from --help: lacks \['--shaking'\]" "$opt_dir/bad3.out" \
  && pass || fail options-check-fails-on-man "$(cat "$opt_dir/bad3.out")"

# an option of another subcommand is a usage error naming it (the table says which)
run_ks template fourbar --kinematics
[ "$rc" -eq 1 ] && grep -q '^kinetostat: error: template does not take --kinematics$' "$err" && pass \
  || fail options-not-of-template "rc=$rc: $(head -2 "$err")"
run_ks data/pr3207.nml --rtol 1e-3
[ "$rc" -eq 1 ] && grep -q '^kinetostat: error: --rtol does not go with the run of a deck$' "$err" && [ ! -s "$out" ] && pass \
  || fail options-not-of-run "rc=$rc: $(head -2 "$err")"
run_ks sweep data/pr3207.nml --vary l_ab=0.1:0.11:2 --lang ru
[ "$rc" -eq 1 ] && grep -q '^kinetostat: error: sweep does not take --lang$' "$err" && pass \
  || fail options-not-of-sweep "rc=$rc: $(head -2 "$err")"
run_ks diff data/expected/pr3207.csv data/expected/pr3207.csv --format csv
[ "$rc" -eq 2 ] && grep -q '^kinetostat: error: diff does not take --format; usage: kinetostat diff A B' "$err" && pass \
  || fail options-not-of-diff "rc=$rc: $(head -2 "$err")"
# the usage line printed with a usage error is the table's, every subcommand
run_ks --no-such-option
[ "$rc" -eq 1 ] && [ "$(grep -o ' | kinetostat [a-z-]*' "$err" | wc -l)" -eq 9 ] && pass \
  || fail options-usage-line "rc=$rc: $(cat "$err")"
