# Shaking force and moment (--shaking) and counterweight balancing (kinetostat balance):
# tools/shaking_check.py re-computes them (differences of the centre of mass and of the
# angular momentum, the frame reactions, d'Alembert, the balanced decks); then the errors.
while IFS= read -r line; do
  case "$line" in
    "ok "*) pass ;;
    "FAIL "*) fail "shaking" "${line#FAIL }" ;;
    *) fail "shaking" "unexpected line from tools/shaking_check.py: $line" ;;
  esac
done < <(run_py "$root/tools/shaking_check.py" "$KINETOSTAT" 2>&1)

# the option leaves the default outputs alone and adds its columns at the end
run_ks "$root/data/assur_fourbar.nml" --format csv --shaking
if head -1 "$out" | grep -q ',M1,F_shake,F_shakeG,F_shake_x,F_shake_y,M_shake,F_frame_x,F_frame_y,M_frame$'; then pass
else fail "shaking-columns" "header: $(head -1 "$out")"; fi
run_ks "$root/data/assur_fourbar.nml" --format summary --shaking
if head -1 "$out" | grep -q 'F_shake_max'; then pass; else fail "shaking-summary" "header: $(head -c 300 "$out")"; fi

# usage and input errors: one line, the right exit code, no output file
balance_error() {
  local name="$1" code="$2" pattern="$3"; shift 3
  local target="$cli_tmp/balanced.nml"
  rm -f "$target" "$target".tmp.*
  run_ks "$@" -o "$target"
  if [ "$rc" -ne "$code" ]; then fail "$name" "exit $rc, expected $code: $(head -c 300 "$err")"; return; fi
  if ! head -1 "$err" | grep -Eq "^kinetostat: error: .*$pattern"; then fail "$name" "stderr: $(head -c 300 "$err")"; return; fi
  if ls "$target"* >/dev/null 2>&1; then fail "$name" "output file left behind"; return; fi
  pass
}
balance_error "balance-fraction-range" 1 "--fraction must lie in \[0, 1\]" balance "$root/data/assur_slider_crank.nml" --method partial --fraction 1.5
balance_error "balance-fraction-negative" 1 "--fraction must lie in \[0, 1\]" balance "$root/data/assur_slider_crank.nml" --method partial --fraction=-0.1
balance_error "balance-fraction-text" 1 "--fraction needs a number" balance "$root/data/assur_slider_crank.nml" --method partial --fraction half
balance_error "balance-fraction-without-partial" 1 "--fraction belongs to --method partial" balance "$root/data/assur_slider_crank.nml" --fraction 0.5
balance_error "balance-method" 1 "--method must be full, crank or partial" balance "$root/data/assur_fourbar.nml" --method total
balance_error "balance-no-crank" 1 "needs a crank that turns the mechanism" balance "$root/data/assur_pr3050.nml" --method crank
balance_error "balance-not-linkage" 2 "balance works on the linkage decks" balance "$root/data/cam_flat.nml"
balance_error "balance-gears" 2 "balance works on the linkage decks" balance "$root/data/gears_reducer.nml"
balance_error "balance-linkage-full-impossible" 3 "&linkage: full balance is impossible.*--method partial" balance "$root/data/linkage_slider_crank.nml"
balance_error "balance-linkage-partial-not-slider-crank" 1 "&linkage: --method partial balances a slider-crank" balance "$root/data/linkage_fourbar.nml" --method partial
balance_error "balance-full-impossible" 3 "full balance is impossible.*--method partial" balance "$root/data/assur_slider_crank.nml"
balance_error "balance-partial-not-slider-crank" 1 "--method partial balances a slider-crank" balance "$root/data/assur_fourbar.nml" --method partial
balance_error "shaking-gears" 1 "--shaking: only linkage mechanisms" "$root/data/gears_reducer.nml" --shaking
balance_error "method-without-balance" 1 "belong to the balance subcommand" "$root/data/assur_fourbar.nml" --method crank

# a sweep with --shaking: the summary columns of the shaking force, the same in 1 and 2 processes
run_ks sweep "$root/data/assur_fourbar.nml" --vary crank_m=0.5:1.5:3 --shaking --jobs 1
cp "$out" "$cli_tmp/sweep_one"
run_ks sweep "$root/data/assur_fourbar.nml" --vary crank_m=0.5:1.5:3 --shaking --jobs 2
if [ "$rc" -eq 0 ] && head -1 "$out" | grep -q 'F_shake_max' && cmp -s "$out" "$cli_tmp/sweep_one"; then pass
else fail "shaking-sweep" "exit $rc; header $(head -c 200 "$out")"; fi

# balance --lang ru: the report in Russian, the course's words (противовес, уравновешивание,
# главный вектор сил инерции), no English word left (tools/svg_check.py english); the balanced
# deck, with its Russian comments, runs. The deck variables (crank_m, dyad(1)%m3) stay.
for args in "assur_fourbar.nml" "assur_fourbar.nml --method crank" "assur_slider_crank.nml --method partial"; do
  # shellcheck disable=SC2086
  run_ks balance "$root/data/"$args --lang ru
  sed -e 's/^kinetostat: balance: //' -e 's/[A-Za-z0-9_]*([0-9]*)%[A-Za-z0-9_]*//g' "$err" >"$cli_tmp/balance_ru.txt"
  if [ "$rc" -ne 0 ] || ! grep -q 'противовес' "$cli_tmp/balance_ru.txt" || ! grep -q 'уравновешивани' "$cli_tmp/balance_ru.txt"; then
    fail "balance-ru ($args)" "exit $rc; report: $(head -c 400 "$err")"
  elif ! run_py "$root/tools/svg_check.py" english "$cli_tmp/balance_ru.txt" >"$cli_tmp/balance_ru.check" 2>&1; then
    fail "balance-ru ($args)" "English words in the Russian report: $(head -5 "$cli_tmp/balance_ru.check")"
  else
    cp "$out" "$cli_tmp/balanced_ru.nml"
    run_ks "$cli_tmp/balanced_ru.nml" --format summary
    if [ "$rc" -eq 0 ]; then pass; else fail "balance-ru ($args)" "the balanced deck does not run: exit $rc: $(head -c 300 "$err")"; fi
  fi
done
# three-digit exponents keep their E: --fraction 1e-300 is "1.00E-300", never "1.00-300"
run_ks balance "$root/data/assur_slider_crank.nml" --method partial --fraction 1e-300
if [ "$rc" -eq 0 ] && grep -q ' 1.00E-300 of the reciprocating mass' "$err" && ! grep -Eq '[0-9][+-][0-9]{3}' "$err"; then pass
else fail "balance-exponent-e" "exit $rc; report: $(grep -E 'reciprocating|[0-9][+-][0-9]{3}' "$err" | head -3)"; fi

# balance of an &linkage deck: the four-bar twin of data/assur_fourbar.nml gets the same
# counterweights and the same report figures (the lines but for the deck's variable names and
# the frame the angle is given in), its shaking force vanishes (max |F_shake| <= 1e-9 of
# before, from the balanced deck's own --shaking run) and the total centre of mass of the
# balanced deck stays where the report says
run_ks balance "$root/data/linkage_fourbar.nml" -o "$cli_tmp/lb.nml"; rc_l=$rc; cp "$err" "$cli_tmp/lb.err"
run_ks balance "$root/data/assur_fourbar.nml" -o "$cli_tmp/ab.nml"; cp "$err" "$cli_tmp/ab.err"
run_ks "$cli_tmp/lb.nml" --shaking --kinematics --format csv; cp "$out" "$cli_tmp/lb.csv"; rc_r=$rc
run_ks "$root/data/linkage_fourbar.nml" --shaking --format csv; cp "$out" "$cli_tmp/l0.csv"
run_py - "$cli_tmp/lb.err" "$cli_tmp/ab.err" "$cli_tmp/lb.csv" "$cli_tmp/l0.csv" "$cli_tmp/lb.nml" <<'PY' && [ "$rc_l$rc_r" = 00 ] && pass || fail balance-linkage-fourbar "exit $rc_l/$rc_r (see above)"
import csv, re, sys
lk, asr = open(sys.argv[1]).read(), open(sys.argv[2]).read()
num = lambda t, pat: re.findall(pat, t)
for pat in [r"stays at \(([-0-9.]+), ([-0-9.]+)\)", r"counterweight on link (\d): ([0-9.]+) kg at r = ([0-9.]+) m",
            r"max \|F_shake\|: before ([0-9.E+-]+)", r"max \|M_shake\|: before ([0-9.]+ N\*m, after [0-9.]+)",
            r"max \|M1\|     : before ([0-9.]+ N\*m, after [0-9.]+)", r"-> ([0-9.]+) kg, \S+ [0-9.]+ -> ([0-9.]+) kg"]:
    a, b = num(lk, pat), num(asr, pat)
    assert a and a == b, (pat, a, b)
after = list(csv.DictReader(open(sys.argv[3]))); before = list(csv.DictReader(open(sys.argv[4])))
fa = max(float(r["F_shake"]) for r in after); fb = max(float(r["F_shake"]) for r in before)
assert fb > 100 and fa <= 1e-9 * fb, (fa, fb)
src = open(sys.argv[5]).read()
m = {k: float(re.findall(r"link\(%s\)%%m = ([-0-9.eE+]+)" % k, src)[-1]) for k in "123"}
M = sum(m.values())
cx, cy = [float(v) for v in num(lk, r"stays at \(([-0-9.]+), ([-0-9.]+)\)")[0]]
for r in after:
    x = sum(m[k] * float(r["x_S" + k]) for k in m) / M; y = sum(m[k] * float(r["y_S" + k]) for k in m) / M
    assert abs(x - cx) <= 6e-4 and abs(y - cy) <= 6e-4, (x, y, cx, cy)
PY
# the slider-crank twins: --method partial gives the same counterweight and figures
run_ks balance "$root/data/linkage_slider_crank.nml" --method partial --fraction 0.5 -o "$cli_tmp/lp.nml"; rc_l=$rc
sed -e 's/ (dyad 1)//' -e 's/ from its pivot at the reference position/ in the link'"'"'s axes/' -e 's/^.*self-check.*$//' \
  -e 's/link(1)%\([mj]\)/crank_\1/g' -e 's/centre of mass.*$//' "$err" >"$cli_tmp/lp.err"
run_ks balance "$root/data/assur_slider_crank.nml" --method partial --fraction 0.5 -o "$cli_tmp/ap.nml"
sed -e 's/ (dyad 1)//' -e 's/^.*self-check.*$//' -e 's/centre of mass.*$//' "$err" >"$cli_tmp/ap.err"
[ "$rc_l$rc" = 00 ] && grep -q "counterweight on link 1: 2.74 kg" "$cli_tmp/lp.err" && cmp -s "$cli_tmp/lp.err" "$cli_tmp/ap.err" && pass \
  || fail balance-linkage-partial "exit $rc_l/$rc: $(diff "$cli_tmp/lp.err" "$cli_tmp/ap.err" | head -6)"
