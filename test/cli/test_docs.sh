# The docs' examples run as the docs say: the tutorial's decks (docs/examples/*.nml) exit 0
# with a clean self-check, the tutorial's hand check of the engine holds, and the README's
# example output is what the program prints.

for deck in docs/examples/*.nml; do
  name=$(basename "$deck" .nml)
  run_ks "$deck"
  if [ "$rc" -eq 0 ] && [ ! -s "$err" ] && grep -q 'MAX EQUILIBRIUM RESIDUAL.* OK$' "$out"; then
    pass
  else
    fail "docs-example-$name" "rc=$rc, stderr: $(head -c 300 "$err"); self-check: $(grep -A2 SELF-CHECK "$out")"
  fi
done

# tutorial §3: F23 at the firing TDC (phi1 = 360) = gas force 8282 N - m3*r*omega^2*(1 + r/l)
# = 8282 - 4500 N, relative 1e-6 (the rod's own inertia adds a small transverse part, < 1e-6
# of it here).
run_ks docs/examples/engine.nml --format csv
run_py - "$out" <<'PY' && pass || fail docs-engine-hand-check "F23 at phi1 = 360 is not 3782 N (rel 1e-6)"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["phi1"]) == 360.0]
expected = 8282 - 0.8 * 0.05 * 300**2 * (1 + 0.05 / 0.2)
computed = float(rows[0]["F23"])
if abs(computed - expected) > 1e-6 * expected:
    print(f"expected {expected}, computed {computed}"); sys.exit(1)
PY

# tutorial §3: the cycle does positive work: the gas force's work per cycle, the integral of
# -F dx over 0..720 deg from the deck's table (linear in the crank angle) and the piston's
# x = r cos(phi) + sqrt(l^2 - r^2 sin^2(phi)) by hand, equals -(work of M1) of a 0.25 deg run
# (gravity and inertia do no net work over the cycle); relative 1e-3 (trapezoidal rules).
run_ks docs/examples/engine.nml --set dphi=0.25 --set n=2881 --format summary
run_py - "$out" docs/examples/engine.nml <<'PY' && pass || fail docs-engine-cycle-work "the engine's work per cycle is not the indicator diagram's"
import csv, math, re, sys
row = next(csv.DictReader(open(sys.argv[1])))
deck = open(sys.argv[2]).read()
nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", deck.split("force(1)%table =", 1)[1].split("/", 1)[0])]
tab = list(zip(nums[0::2], nums[1::2]))
r, l = 0.05, 0.2
x = lambda a: r * math.cos(math.radians(a)) + math.sqrt(l * l - (r * math.sin(math.radians(a)))**2)
def force(a):
    for (a0, f0), (a1, f1) in zip(tab, tab[1:]):
        if a0 <= a <= a1:
            return f0 + (f1 - f0) * (a - a0) / (a1 - a0)
n = 28800
work = sum(-0.5 * (force(720 * i / n) + force(720 * (i + 1) / n)) * (x(720 * (i + 1) / n) - x(720 * i / n)) for i in range(n))
computed = -float(row["work_M1"])
if not work > 400 or abs(computed - work) > 1e-3 * work:
    print(f"by hand {work} J, the program's -work_M1 {computed} J"); sys.exit(1)
PY
# README "One example": every shown line (not the '...' cuts) is a line of the real output.
run_ks data/pr3207.nml
run_py - README.md "$out" <<'PY' && pass || fail readme-example "README's example lines are not in the output"
import sys
readme = open(sys.argv[1], encoding="utf-8").read()
block = readme.split("## One example", 1)[1].split("```", 2)[1]
shown = [l for l in block.splitlines()[1:] if l.strip() and l.strip() != "..."]
actual = set(open(sys.argv[2], encoding="utf-8").read().splitlines())
missing = [l for l in shown if l not in actual]
if missing or len(shown) < 10:
    print("missing:", missing, "shown:", len(shown)); sys.exit(1)
PY

# tutorial §5: the same run diffs as the same (exit 0); the changed load as different (exit 1)
run_ks docs/examples/fourbar.nml --format csv; cp "$out" "$cli_tmp/tut_expected.csv"
run_ks docs/examples/fourbar.nml --format csv --set 'moment(1)%value=-20.001'; cp "$out" "$cli_tmp/tut_fresh.csv"
expect_exit docs-tutorial-diff-same 0 diff "$cli_tmp/tut_expected.csv" "$cli_tmp/tut_expected.csv"
expect_exit docs-tutorial-diff-changed 1 diff "$cli_tmp/tut_expected.csv" "$cli_tmp/tut_fresh.csv"
if grep -q '^different: 415 of 450 values differ' "$out"; then pass; else fail docs-tutorial-diff-report "$(tail -1 "$out")"; fi

# tutorial §4: the sweep's rows as the tutorial prints them
"$KINETOSTAT" sweep docs/examples/fourbar.nml --vary 'dyad(1)%at2(1)=0.08:0.12:5' 2>/dev/null |
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } { print $1 "," $c["M1_max"] "," $c["M1_min"] "," $c["F10_max"] }' \
  >"$cli_tmp/tut_sweep.txt"
run_py - docs/tutorial.md "$cli_tmp/tut_sweep.txt" <<'PY' && pass || fail docs-tutorial-sweep "the tutorial's sweep rows are not the program's"
import sys
doc = open(sys.argv[1], encoding="utf-8").read()
block = doc.split("## 4. A parameter study", 1)[1].split("```")[3]
shown = [l for l in block.splitlines() if l.strip()]
actual = open(sys.argv[2]).read().splitlines()
if shown != actual:
    print("shown:", shown, "actual:", actual); sys.exit(1)
PY
