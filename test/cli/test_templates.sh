# Templates (every kind and the generic-engine presets fourbar, engine), template -o FILE,
# the man page renders, the bash completion completes.

# --- every template runs: exit 0, nothing on stderr (but the coarse-step remark:
# the pr3207 and assur templates switch a load at 30 deg steps), self-check OK. The kinds
# and presets are those --help lists (the registry's).
run_ks --help
tpl_kinds="$(sed -n 's/^Kinds: //p; s/^Presets (template): //p' "$out" | tr -d ',')"
[ "$(echo $tpl_kinds | wc -w)" -ge 12 ] && pass || fail template-kinds "--help lists too few kinds: $tpl_kinds"
for kind in $tpl_kinds; do
  run_ks template "$kind"; cp "$out" "$cli_tmp/tpl_$kind.nml"
  if [ "$rc" -ne 0 ] || [ ! -s "$cli_tmp/tpl_$kind.nml" ]; then fail "template-$kind" "rc=$rc: $(cat "$err")"; continue; fi
  run_ks "$cli_tmp/tpl_$kind.nml"
  if [ "$rc" -eq 0 ] && ! grep -qv 'the input step 30 deg is coarser than 5 deg' "$err" && ! grep -q 'FAILED' "$out"; then pass
  else fail "template-$kind-runs" "rc=$rc, stderr: $(head -c 300 "$err")"; fi
done
# the presets are the tutorial's decks, byte for byte
cmp -s "$cli_tmp/tpl_fourbar.nml" docs/examples/fourbar.nml && pass || fail template-fourbar-is-tutorial-deck \
  "$(diff "$cli_tmp/tpl_fourbar.nml" docs/examples/fourbar.nml | head -5)"
cmp -s "$cli_tmp/tpl_engine.nml" docs/examples/engine.nml && pass || fail template-engine-is-tutorial-deck \
  "$(diff "$cli_tmp/tpl_engine.nml" docs/examples/engine.nml | head -5)"
# sane numbers. Four-bar: over a whole turn the moments do no net work (the rocker swings
# back, gravity and inertia are conservative), so the mean of M1 over the 24 steps of
# 15 deg is ~0 next to its peak (trapezoid rule; 5 % of the peak allowed).
run_ks "$cli_tmp/tpl_fourbar.nml" --format csv
run_py - "$out" <<'PY' && pass || fail template-fourbar-work "mean M1 over a turn not ~0"
import csv, sys
m = [float(r["M1"]) for r in csv.DictReader(open(sys.argv[1]))]
mean = sum(m[:-1]) / (len(m) - 1)
peak = max(abs(x) for x in m)
if not (len(m) == 25 and peak > 1.0 and abs(mean) < 0.05 * peak):
    print(f"steps {len(m)}, mean {mean}, peak {peak}"); sys.exit(1)
PY
# Engine: at the firing top dead centre (phi1 = 360) the rod carries the gas force less the
# piston's inertia force m3*r*omega^2*(1 + r/l): 8282 - 0.8*0.05*300^2*1.25 = 3782 N (rel
# 1e-3: the rod's own inertia adds a little).
run_ks "$cli_tmp/tpl_engine.nml" --format csv
run_py - "$out" <<'PY' && pass || fail template-engine-tdc "F23 at the firing TDC is not ~3782 N"
import csv, sys
r = [row for row in csv.DictReader(open(sys.argv[1])) if float(row["phi1"]) == 360.0][0]
if abs(float(r["F23"]) - 3782.0) > 3.782:
    print(r["F23"]); sys.exit(1)
PY

# --- template KIND -o FILE: the file holds what stdout would; replaced atomically
run_ks template fourbar -o "$cli_tmp/tpl_o.nml"
if [ "$rc" -eq 0 ] && [ ! -s "$out" ] && cmp -s "$cli_tmp/tpl_o.nml" docs/examples/fourbar.nml \
  && ! ls "$cli_tmp"/tpl_o.nml.tmp.* >/dev/null 2>&1; then pass
else fail template-o-file "rc=$rc, stdout $(wc -c <"$out") bytes, $(ls "$cli_tmp" | grep tpl_o)"; fi
echo "old text" >"$cli_tmp/tpl_o.nml"
run_ks --output="$cli_tmp/tpl_o.nml" template engine
[ "$rc" -eq 0 ] && cmp -s "$cli_tmp/tpl_o.nml" docs/examples/engine.nml && pass || fail template-output-replaces "rc=$rc"
run_ks template fourbar -o "$cli_tmp/no_such_dir/x.nml"
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && pass || fail template-o-unwritable "rc=$rc: $(cat "$err")"
expect_exit template-unknown 1 template nosuch
grep -q "presets: fourbar, engine" "$err" && pass || fail template-unknown-lists-presets "$(cat "$err")"

# --- --format=csv is --format csv
run_ks data/pr3207.nml --format=csv; cp "$out" "$cli_tmp/eq.csv"
run_ks data/pr3207.nml --format csv
cmp -s "$out" "$cli_tmp/eq.csv" && [ -s "$out" ] && pass || fail format-equals-form "--format=csv differs from --format csv"

# --- --help, the usage line, the man page and the completion against the option table:
# test/cli/test_options.sh
if command -v groff >/dev/null 2>&1; then
  if groff -man -Tutf8 -ww man/kinetostat.1 2>"$cli_tmp/groff.err" >"$cli_tmp/man.txt" && [ ! -s "$cli_tmp/groff.err" ] \
    && sed 's/.\x08//g' "$cli_tmp/man.txt" | grep -c 'EXIT STATUS' >/dev/null; then pass
  else fail man-renders "groff: $(head -5 "$cli_tmp/groff.err")"; fi
fi
# bash completion: subcommands, options, kinds, formats, decks
complete_words() {
  bash -c 'source completions/kinetostat.bash; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _kinetostat; echo "${COMPREPLY[*]}"' _ "$@"
}
[ "$(complete_words kinetostat --form)" = "--format" ] && pass || fail completion-option "$(complete_words kinetostat --form)"
[ "$(complete_words kinetostat --format j)" = "json" ] && pass || fail completion-format "$(complete_words kinetostat --format j)"
[ "$(complete_words kinetostat template four)" = "fourbar" ] && pass || fail completion-kind "$(complete_words kinetostat template four)"
[ "$(complete_words kinetostat di)" = "diff" ] && pass || fail completion-subcommand "$(complete_words kinetostat di)"
[ "$(complete_words kinetostat data/pr3207.)" = "data/pr3207.nml" ] && pass || fail completion-deck "$(complete_words kinetostat data/pr3207.)"
[ "$(complete_words kinetostat diff --rt)" = "--rtol" ] && pass || fail completion-diff-option "$(complete_words kinetostat diff --rt)"
# the &linkage template's commented stages (dynamics, a load table over the crank's angle,
# friction) run when uncommented: the flywheel, the table's force and the losses appear
run_ks template linkage
sed -e "s/^  ! dynamics = /  dynamics = /" -e "s/^  ! force(2)%/  force(2)%/" -e "s/^  ! pair(1)%f/  pair(1)%f/" "$out" \
  >"$cli_tmp/tpl_linkage_all.nml"
run_ks "$cli_tmp/tpl_linkage_all.nml" --format csv
if [ "$rc" -eq 0 ] && head -1 "$out" | grep -q "P_loss_F10" && head -1 "$out" | grep -q "J_red" && \
   grep -q "dynamics = 'steady'" "$cli_tmp/tpl_linkage_all.nml" && grep -q "force(2)%table = " "$cli_tmp/tpl_linkage_all.nml"; then pass
else fail template-linkage-stages "exit $rc: $(head -c 300 "$err") $(head -1 "$out" | head -c 300)"; fi
