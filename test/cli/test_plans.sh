# The graphical method as numbers (--format json --at K --plans): on every bundled linkage deck
# at its first, second, middle and last steps (PR 3050's at the steps where its input moves;
# its groups at rest too) - the plans' equations hold, the acceleration images of the centres
# of mass equal the kinematics columns, every force polygon closes (<= 1e-9 of its largest
# vector) with the CSV's pair forces in it, in the course's order (tau and n parts adjacent,
# whole and inner reactions listed), Zhukovsky's lever equals the run's driving effort
# (relative 1e-9) with every load force of the links' polygons on it and the loads' powers and
# the balancing power summing to zero, the values table agrees with the plans and the CSV's
# rates, and the groups are the same at every step and the structural analysis's
# (kinetostat structure) - tools/plans_check.py; the checks can fail; usage errors.
plans_check="$root/tools/plans_check.py"
plans_dir="$cli_tmp/plans"
mkdir -p "$plans_dir"
declare -A plans_steps  # a deck's step count (its CSV's rows), noted once
# sheet_lines SVG: its texts, one a line, the typeset runs joined (F<tspan>21</tspan> -> F21)
sheet_lines() {
  run_py -c 'import html, re, signal, sys
signal.signal(signal.SIGPIPE, signal.SIG_DFL)
for m in re.findall(r"<text[^>]*>(.*?)</text>", open(sys.argv[1], encoding="utf-8").read()):
    print(html.unescape(re.sub(r"<[^>]+>", "", m)))' "$1"
}

# DECK:CHECKS - lever, polygons (of the links and of the groups) or groups (the groups' only).
# The legacy PR 3207 and PR 3050 tables leave out their massless blocks' and the
# rod-in-cylinder reactions: their links' polygons do not close, their groups' do (those
# reactions are inside a group). On the friction decks the lever adds every pair's friction
# (its power against the CSV's P_loss_<pair>); on the flywheel decks (the true motion of a
# steady cycle) the flywheel's and the rotor's inertia moment -J eps1 acts on the crank.
for spec in assur_fourbar:lever,polygons assur_fourbar_global:lever,polygons assur_sixbar:lever,polygons \
  assur_sixbar_global:lever,polygons assur_slider_crank:lever,polygons assur_pr3207:lever,polygons \
  sixbar:lever,polygons sixbar_example:lever,polygons class3:lever,polygons fivebar:lever,polygons \
  linkage_fourbar:lever,polygons linkage_slider_crank:lever,polygons pr3207:lever,groups pr3050:lever,groups \
  pr3207_flywheel:lever,groups assur_pr3207_flywheel:lever,polygons sixbar_flywheel:lever,polygons \
  friction_fourbar_resist:lever,polygons \
  assur_pr3050:lever,polygons assur_pr3050_friction:lever,polygons assur_pr3207_friction:lever,polygons \
  assur_sixbar_friction:lever,polygons \
  friction_slider_crank:lever,polygons; do
  name=${spec%%:*}; checks=${spec#*:}
  flags="--order --values"
  case ",$checks," in *,lever,*) flags="$flags --lever" ;; esac
  case ",$checks," in *,polygons,*) flags="$flags --polygons" ;; esac
  case ",$checks," in *,groups,*) flags="$flags --groups" ;; esac
  run_ks_cached "$name.kin.csv" "data/$name.nml" --format csv --kinematics
  cp "$out" "$plans_dir/$name.csv"
  steps=$(($(wc -l <"$out") - 1)); plans_steps[$name]=$steps
  ks=$(printf '%s\n' 1 2 $(((steps + 1) / 2)) "$steps" | awk '$1 <= '"$steps"' && !seen[$1]++')
  rest=""
  # PR 3050 starts and stops at rest: no velocity plan there (the lever needs one); its
  # groups are checked at rest too
  case "$name" in pr3050|assur_pr3050*) ks="2 3 $(((steps + 1) / 2)) $((steps - 1))"; rest=1 ;; esac
  step_files=()
  for k in $ks; do
    run_ks_into "$plans_dir/$name.$k.json" "data/$name.nml" --format json --at "$k" --plans
    if [ "$rc" -ne 0 ]; then fail "plans-runs-$name-$k" "rc=$rc: $(head -c 300 "$err")"; continue; fi
    step_files+=("$plans_dir/$name.$k.json")
  done
  # shellcheck disable=SC2086  # flags is a word list
  check_job plans_check "plans-$name-$(echo $ks | tr ' ' ',')" "${step_files[@]}" "$plans_dir/$name.csv" $flags
  if [ -n "$rest" ]; then
    run_ks_into "$plans_dir/$name.$rest.json" "data/$name.nml" --format json --at "$rest" --plans
    step_files+=("$plans_dir/$name.$rest.json")
  fi
  # the groups: the same at every step, and the structural analysis's where it runs
  structure=()
  case "$name" in
    class3|fivebar|linkage_*) structure=(--structure "$("$KINETOSTAT" structure "data/$name.nml" | sed -n 's/^ STRUCTURE FORMULA: //p')") ;;
  esac
  check_job plans_check "plans-groups-$name" groups "${step_files[@]}" "${structure[@]}"
done
# the generic decks' groups (derived from the topology) equal the structural analysis of the
# same mechanism written as a &linkage deck
for twin in assur_fourbar:linkage_fourbar assur_slider_crank:linkage_slider_crank; do
  check_job plans_check "plans-groups-twin-${twin%%:*}" groups "$plans_dir/${twin%%:*}".*.json \
    --structure "$("$KINETOSTAT" structure "data/${twin#*:}.nml" | sed -n 's/^ STRUCTURE FORMULA: //p')"
done
check_batch plans_check
# the five-bar's two drives: an input link's polygon each, M4 (not the lever's unknown) a
# load of the lever; PR 3050's cylinder and rod one input unit at every step, at rest too
run_py -c 'import json, sys; d = json.load(open(sys.argv[1]))
assert [p["label"] for p in d["force_plans"]] == ["II(2,3)", "I(0,4)", "I(0,1)"], d["force_plans"]
assert [p["moment"]["name"] for p in d["force_plans"][1:]] == ["M4", "M1"]
assert "M4" in [l["name"] for l in d["zhukovsky"]["loads"]]' "$plans_dir/fivebar.2.json" >"$cli_tmp/check.out" 2>&1 \
  && pass || fail plans-fivebar-drives "$(tail -3 "$cli_tmp/check.out")"
grep -q '"groups": \[' "$plans_dir/pr3050.1.json" && grep -A1 '"groups": \[' "$plans_dir/pr3050.1.json" | grep -q '"label": "I(4,1,2,3)"' \
  && pass || fail plans-pr3050-rest-groups "$(grep -A2 '"groups"' "$plans_dir/pr3050.1.json")"

# the plans JSON in the run's envelope: format_version (first), program, mechanism, deck_title, overrides, selfcheck,
# warnings; the sheet's rotation against the position frame
run_ks data/fivebar.nml --format json --at 2 --plans --set 'link(2)%m=2'
run_py -c 'import json, sys; d = json.load(open(sys.argv[1]))
assert type(d["format_version"]) is int and list(d)[0] == "format_version", d.get("format_version")
for key in ("program", "mechanism", "title", "deck", "deck_title", "overrides", "selfcheck", "warnings", "sheet_rotation"):
    assert key in d, key
assert d["overrides"] == ["link(2)%m=2"] and d["mechanism"] == "linkage" and d["selfcheck"]["ok"], d
assert d["deck_title"] == "five-bar with two motors", d["deck_title"]' "$out" >"$cli_tmp/check.out" 2>&1 \
  && pass || fail plans-json-envelope "$(tail -3 "$cli_tmp/check.out")"

# the new checks can fail: a load left off the lever, a load's power changed, a reaction's
# parts apart, the inner reaction dropped, the groups changed at one step, groups that are not
# the structure's, a wrong value in the table; a lever off by one part in 1e6; the friction on
# the lever left out (the effort of the loads alone, what the lever gave before it counted the
# pairs' friction), one pair dropped, a couple turned round; the flywheel on the lever left out
# (the effort of the links' loads alone); an acceleration component off by one part in 1e6
# (the first equation's normal one); a group's reaction part moved (F43's tangential part in
# the six-bar's group 4,5). The perturbed plans are made in one Python process, the checks run
# in another (batch_run): each must fail with its verdict (expect_batch_fail).
run_py - "$plans_dir" "$cli_tmp" <<'PY'
import json, os, sys
plans, tmp = sys.argv[1:]
def perturb(source, target, change):
    d = json.load(open(os.path.join(plans, source)))
    change(d)
    with open(os.path.join(tmp, target), "w") as f:
        print(json.dumps(d), file=f)
def drop_g4(d):
    z = d["zhukovsky"]; z["loads"] = [l for l in z["loads"] if l["name"] != "G4"]
def power(d):
    d["zhukovsky"]["loads"][0]["power"] *= 1 + 1e-6
def order(d):
    v = d["force_plans"][0]["vectors"]; v.insert(1, v.pop())
def inner(d):
    p = d["force_plans"][0]; p["reactions"] = [r for r in p["reactions"] if not r["inner"]]
def groups(d):
    d["groups"][1]["label"] = "III(2,3,4,5)"
def values(d):
    [v for v in d["values"] if v["name"] == "omega2"][0]["sense"] = "??"
def lever(d):
    d["zhukovsky"]["effort"] *= 1 + 1e-6
def no_friction(d):
    z = d["zhukovsky"]; z["effort"] -= z.pop("friction")["share"]
def pair_dropped(d):
    d["zhukovsky"]["friction"]["pairs"].pop()
def couple_turned(d):
    p = d["zhukovsky"]["friction"]["pairs"][0]; p["moment"] = -p["moment"]
def no_flywheel(d):
    z = d["zhukovsky"]; z["effort"] += z.pop("flywheel")["moment"]
def component(d):
    v = d["acceleration_equations"][0]["vectors"][0]; v["x"] += 1e-6 * abs(v["x"]) + 1e-6
def group_part(d):
    v = [v for p in d["force_plans"] for v in p["vectors"] if v["name"] == "F43^τ"][0]
    v["x"] += 1e-6 * abs(v["x"]) + 1e-6
# each bundled plan and the changes made to it, each written to CHANGE.json
for source, changes in {"sixbar.2.json": [drop_g4, inner, groups, values], "class3.2.json": [power],
                        "linkage_fourbar.2.json": [order], "sixbar.1.json": [lever, component, group_part],
                        "friction_slider_crank.19.json": [no_friction],
                        "assur_sixbar_friction.19.json": [pair_dropped],
                        "friction_fourbar_resist.91.json": [couple_turned],
                        "pr3207_flywheel.181.json": [no_flywheel]}.items():
    for change in changes:
        perturb(source, change.__name__ + ".json", change)
PY
check_job plans_check load "$cli_tmp/drop_g4.json" "$plans_dir/sixbar.csv" --lever
check_job plans_check power "$cli_tmp/power.json" "$plans_dir/class3.csv" --lever
check_job plans_check order "$cli_tmp/order.json" "$plans_dir/linkage_fourbar.csv" --order
check_job plans_check inner "$cli_tmp/inner.json" "$plans_dir/sixbar.csv" --order
check_job plans_check groups groups "$plans_dir/sixbar.1.json" "$cli_tmp/groups.json"
check_job plans_check structure groups "$plans_dir/fivebar.2.json" --structure "I(0,1) -> II(2,3,4)"
check_job plans_check values "$cli_tmp/values.json" "$plans_dir/sixbar.csv" --values
check_job plans_check lever "$cli_tmp/lever.json" "$plans_dir/sixbar.csv" --lever
check_job plans_check no_friction "$cli_tmp/no_friction.json" "$plans_dir/friction_slider_crank.csv" --lever
check_job plans_check pair_dropped "$cli_tmp/pair_dropped.json" "$plans_dir/assur_sixbar_friction.csv" --lever
check_job plans_check couple_turned "$cli_tmp/couple_turned.json" "$plans_dir/friction_fourbar_resist.csv" --lever
check_job plans_check no_flywheel "$cli_tmp/no_flywheel.json" "$plans_dir/pr3207_flywheel.csv" --lever
check_job plans_check component "$cli_tmp/component.json" "$plans_dir/sixbar.csv"
check_job plans_check group "$cli_tmp/group_part.json" "$plans_dir/sixbar.csv" --groups
sed -E 's/("name": "F21", "x": )-?([0-9])/\1\21/' "$plans_dir/sixbar.1.json" >"$cli_tmp/bad_polygon.json"
if cmp -s "$cli_tmp/bad_polygon.json" "$plans_dir/sixbar.1.json"; then
  fail plans-polygon-can-fail "the perturbation did not change the plans"
else
  check_job plans_check polygon "$cli_tmp/bad_polygon.json" "$plans_dir/sixbar.csv" --polygons
fi
batch_run plans_check
expect_batch_fail plans_check load "the load forces \['G4'\] of the links' polygons are not on the lever" plans-lever-load-can-fail
expect_batch_fail plans_check power "lever: the loads' powers and the balancing power sum to" plans-lever-power-can-fail
expect_batch_fail plans_check order "the parts of F21 are not adjacent\|ends with" plans-order-can-fail
expect_batch_fail plans_check inner "no inner reaction" plans-inner-can-fail
expect_batch_fail plans_check groups "groups change between steps" plans-groups-can-fail
expect_batch_fail plans_check structure "the structure formula" plans-structure-can-fail
expect_batch_fail plans_check values "values table: omega2" plans-values-can-fail
expect_batch_fail plans_check lever "Zhukovsky's lever: expected M1 = " plans-lever-can-fail
expect_batch_fail plans_check no_friction "Zhukovsky's lever: the CSV has friction in .*, the lever none" plans-lever-friction-can-fail
expect_batch_fail plans_check pair_dropped "lever friction: pairs expected" plans-lever-friction-pair-can-fail
expect_batch_fail plans_check couple_turned "turns with the relative rate" plans-lever-friction-sense-can-fail
expect_batch_fail plans_check no_flywheel "Zhukovsky's lever: expected M1 = " plans-lever-flywheel-can-fail
expect_batch_fail plans_check component "a_B^n expected" plans-component-can-fail
expect_batch_fail plans_check group "F43" plans-group-can-fail
cmp -s "$cli_tmp/bad_polygon.json" "$plans_dir/sixbar.1.json" || expect_batch_fail plans_check polygon "F21" plans-polygon-can-fail
run_ks data/sixbar_flywheel.nml --format plans --at 5
sheet_lines "$out" >"$cli_tmp/lines.txt"; grep -qx 'flywheel and rotor included: J = 104 kg·m², -J·ε = 243 N·m' "$cli_tmp/lines.txt" && pass \
  || fail plans-flywheel-sheet "no flywheel line: $(sheet_lines "$out" | grep -i flywheel)"
run_ks data/pr3207_flywheel.nml --format plans --at 5 --lang ru
sheet_lines "$out" >"$cli_tmp/lines.txt"; grep -qx 'маховик и ротор учтены: J = 274 кг·м², -J·ε = -242 Н·м' "$cli_tmp/lines.txt" && pass \
  || fail plans-flywheel-sheet-ru "no flywheel line: $(sheet_lines "$out" | grep маховик)"
# the friction's share on the sheet, in both languages (P_loss typeset: P with loss lowered)
run_ks data/friction_slider_crank.nml --format plans --at 3
sheet_lines "$out" >"$cli_tmp/lines.txt"; grep -qx 'pair friction included: -Ploss/ω1 = 2.26 N·m' "$cli_tmp/lines.txt" && pass \
  || fail plans-friction-sheet "no friction line: $(sheet_lines "$out" | grep friction)"
run_ks data/assur_pr3050_friction.nml --format plans --at 2 --lang ru
sheet_lines "$out" >"$cli_tmp/lines.txt"; grep -qx 'трение в парах учтено: -Pтр/vотн = 172 Н' "$cli_tmp/lines.txt" && pass \
  || fail plans-friction-sheet-ru "no friction line: $(sheet_lines "$out" | grep трение)"

# every deck's equations name the components in the course's notation, a_B^n ... a_B^r
grep -q '"name": "a_B2B3^k", "kind": "k"' "$plans_dir"/pr3207.*.json && pass || fail plans-coriolis "no Coriolis component in PR 3207's plans"

# the six-bar's groups as kinetostatics solves them: the dyads 4,5 and 2,3, then the crank
grep -o '"group": "[0-9,]*"' "$plans_dir/sixbar.1.json" | tr '\n' ' ' | grep -qx '"group": "4,5" "group": "2,3" "group": "1" ' \
  && pass || fail plans-sixbar-groups "$(grep -o '"group": "[0-9,]*"' "$plans_dir/sixbar.1.json")"
# ... in the course's order: F43^tau, the loads of 4 and 5, F56, F43^n; then F21^tau, the loads of
# 2 and 3 with the known F34, F36^tau, F36^n, F21^n, the inner reactions F45, F23
run_py -c 'import json, sys; d = json.load(open(sys.argv[1])); p = d["force_plans"]
assert [v["name"] for v in p[0]["vectors"]] == ["F43^τ", "G4", "Phi4", "G5", "Phi5", "F5", "F56", "F43^n"], p[0]
assert [v["name"] for v in p[1]["vectors"]] == ["F21^τ", "G2", "Phi2", "G3", "F34", "F36^τ", "F36^n", "F21^n"], p[1]
assert [r["name"] for r in p[0]["reactions"]] == ["F43", "F56", "F45"] and [r["name"] for r in p[1]["reactions"]] == ["F21", "F36", "F23"]' \
  "$plans_dir/sixbar_example.1.json" >"$cli_tmp/check.out" 2>&1 && pass || fail plans-sixbar-order "$(tail -3 "$cli_tmp/check.out")"

# PR 3207's ram from the block's point the other way round; PR 3050's cylinder and rod one body
# of their group (the frame's reaction on the cylinder split along the line to the rod's joint B)
grep -q '"point": "S5", "link": "5", "from": "D", "slider": "4", "reverse": true' "$plans_dir"/pr3207.*.json \
  && pass || fail plans-pr3207-ram "$(cat "$plans_dir"/pr3207.*.json | grep -o '"point": "S5"[^[]*' | head -3)"
grep -q '"group": "1,2,3".*"name": "F14^τ"' "$plans_dir"/pr3050.*.json \
  && pass || fail plans-pr3050-group "$(cat "$plans_dir"/pr3050.*.json | grep -o '"group": "[^]]*' | head -1)"

# the generic PR 3050 deck (its cylinder's F_drive on the cylinder L1, -F_drive on the rod 2)
# against the dedicated program at the same steps: the lever's effort, and the frame's reaction
# on the cylinder split along A-B the same way (relative 1e-9 of the polygon's largest vector)
for k in 2 5 9; do
  run_py -c 'import json, math, sys
g, d = (json.load(open(f)) for f in sys.argv[1:3])
zg, zd = g["zhukovsky"], d["zhukovsky"]
assert abs(zg["effort"] - zd["effort"]) <= 1e-9 * abs(zd["effort"]), (zg, zd)
part = lambda p, n: [(v["x"], v["y"]) for q in p["force_plans"] for v in q["vectors"] if v["name"] == n][0]
big = max(math.hypot(v["x"], v["y"]) for q in d["force_plans"] for v in q["vectors"])
for n in ("F14^τ", "F14^n", "F34^τ", "F34^n"):
    a, b = part(g, n), part(d, n)
    assert math.hypot(a[0] - b[0], a[1] - b[1]) <= 1e-9 * big, (n, a, b)' \
    "$plans_dir/assur_pr3050.$k.json" "$plans_dir/pr3050.$k.json" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "plans-assur-pr3050-as-dedicated-$k" "$(tail -3 "$cli_tmp/check.out")"
done
grep -q '"link": "L1", "closure": [^,]*, "vectors": \[{"name": "GL1".*{"name": "F_drive"' "$plans_dir/assur_pr3050.5.json" \
  && grep -q '"link": "2", "closure": [^,]*, "vectors": \[.*{"name": "-F_drive"' "$plans_dir/assur_pr3050.5.json" \
  && pass || fail plans-assur-pr3050-drive "$(grep -o '"link": "[L0-9]*", "closure": [^,]*' "$plans_dir/assur_pr3050.5.json")"
# ... and its sheet prints the lever's F_drive beside the run's, in English and in Russian
for lang in en ru; do
  run_ks data/assur_pr3050.nml --format plans --at 3 --lang "$lang"
  case $lang in
    en) want='balancing effort from the lever: Fdrive = 21395 N' ;;
    ru) want='уравновешивающее усилие по рычагу: Fд = 21395 Н' ;;
  esac
  sheet_lines "$out" >"$cli_tmp/lines.txt"; grep -qx "$want" "$cli_tmp/lines.txt" && pass || fail "plans-assur-pr3050-sheet-$lang" "$(sheet_lines "$out" | grep 21395)"
done

# the manual's worked example (T.FTN, phi1 = 66.8 deg): the lever gives M1 = 902.0 N*m
grep -q '"zhukovsky": {"driver": "M1", "effort": 9.0203548' "$plans_dir/sixbar_example.1.json" \
  && pass || fail plans-worked-example "$(grep zhukovsky "$plans_dir/sixbar_example.1.json")"

# usage: --plans needs --format json or dxf and --at; not for gears or cams
expect_exit plans-needs-at 1 data/sixbar.nml --format json --plans
expect_exit plans-needs-json 1 data/sixbar.nml --format svg --at 1 --plans
expect_exit plans-at-needs-plans 1 data/sixbar.nml --format json --at 1
expect_exit plans-not-gears 1 data/gears_reducer.nml --format json --at 1 --plans
expect_exit plans-sheet-needs-at 1 data/sixbar.nml --format plans

# the plans sheet: well-formed, self-contained, renders; its lever line is the JSON's
run_ks data/sixbar_example.nml --format plans --at 1
cp "$out" "$plans_dir/sixbar_example.plans.svg"
xmllint --noout "$plans_dir/sixbar_example.plans.svg" 2>"$cli_tmp/xmllint.err" && pass \
  || fail plans-sheet-xmllint "$(head -5 "$cli_tmp/xmllint.err")"
run_py "$root/tools/svg_check.py" self-contained "$plans_dir/sixbar_example.plans.svg" >"$cli_tmp/check.out" 2>&1 \
  && pass || fail plans-sheet-self-contained "$(cat "$cli_tmp/check.out")"
# rendered to a PNG and decoded (1.3 s) with tools/test --long; the default suite renders the
# plans as test_sheets' kinematics sheet to PDF and test_svg's sheets to PNG
if [ "${KINETOSTAT_LONG:-0}" != 1 ]; then :
elif rsvg-convert -o "$plans_dir/plans.png" "$plans_dir/sixbar_example.plans.svg" 2>/dev/null; then
  run_py "$root/tools/svg_check.py" png "$plans_dir/plans.png" "$plans_dir/sixbar_example.plans.svg" \
    >"$cli_tmp/check.out" 2>&1 && pass || fail plans-sheet-png "$(cat "$cli_tmp/check.out")"
else fail plans-sheet-render "rsvg-convert failed"; fi
sheet_lines "$plans_dir/sixbar_example.plans.svg" >"$cli_tmp/lines.txt"
grep -qx 'Pb = 9020 N;  M1 = Pb l = 902 N·m' "$cli_tmp/lines.txt" \
  && grep -qx 'analytic value of the step: M1 = 902 N·m' "$cli_tmp/lines.txt" \
  && pass || fail plans-sheet-lever "$(grep 'M1 = ' "$cli_tmp/lines.txt")"
# ... the deck's title and the --set changes on it
run_ks data/fivebar.nml --format plans --at 3 --set 'link(2)%m=2'
sheet_lines "$out" >"$cli_tmp/lines.txt"; grep -qx 'deck: data/fivebar.nml   five-bar with two motors   --set link(2)%m=2' "$cli_tmp/lines.txt" && pass \
  || fail plans-sheet-header "$(sheet_lines "$out" | grep deck)"

# the sheet in the mechanism's frame: its joints where the CSV puts them, the velocity images
# where the plans put them, every relative velocity of a link drawn perpendicular to the drawn
# link (data-joint, data-point, data-image): every linkage deck at its middle step (with
# tools/test --long at each step checked above); the plans as DXF read back
for json in "$plans_dir"/*.json; do
  base=${json##*/}; name=${base%%.*}; k=${base#*.}; k=${k%.json}
  case "$k" in *[!0-9]*) continue ;; esac
  steps=${plans_steps[$name]}
  if [ "${KINETOSTAT_LONG:-0}" != 1 ] && [ "$k" -ne $(((steps + 1) / 2)) ]; then continue; fi
  case "$name:$k" in pr3050:1|assur_pr3050*:1|pr3050:"$steps"|assur_pr3050*:"$steps") continue ;; esac
  run_ks_into "$plans_dir/$name.$k.svg" "data/$name.nml" --format plans --at "$k"
  check_job plans_check "plans-sheet-$name-$k" sheet "$plans_dir/$name.$k.svg" "$json" "$plans_dir/$name.csv"
done
check_batch plans_check
for spec in sixbar_example:1 pr3207:3 pr3050:3 fivebar:2 class3:19 friction_slider_crank:19; do
  name=${spec%%:*}; k=${spec#*:}
  run_ks_into "$plans_dir/$name.$k.dxf" "data/$name.nml" --format dxf --at "$k" --plans
  [ -f "$plans_dir/$name.$k.json" ] || run_ks_into "$plans_dir/$name.$k.json" "data/$name.nml" --format json --at "$k" --plans
  { run_py "$root/tools/dxf_check.py" "$plans_dir/$name.$k.dxf" && run_py "$plans_check" dxf "$plans_dir/$name.$k.dxf" \
    "$plans_dir/$name.$k.json"; } >"$cli_tmp/check.out" 2>&1 && pass || fail "plans-dxf-$name-$k" "$(head -8 "$cli_tmp/check.out")"
done
# ... and the sheet checks can fail: two images' marks swapped, the plan drawn unturned (the
# old sheet: its own frame), a DXF without the velocity plan's circles
run_py - "$plans_dir/sixbar.7.svg" >"$cli_tmp/bad.svg" <<'PY'
import re, sys
s = open(sys.argv[1], encoding="utf-8").read()
marks = re.findall(r'<circle cx="[^"]*" cy="[^"]*"([^>]*data-image="(?:b|c)")', s)
b = re.search(r'<circle (cx="[^"]*" cy="[^"]*")([^>]*data-image="b")', s)
c = re.search(r'<circle (cx="[^"]*" cy="[^"]*")([^>]*data-image="c")', s)
s = s.replace(b.group(0), "@@B@@").replace(c.group(0), "<circle " + b.group(1) + c.group(2)).replace("@@B@@", "<circle " + c.group(1) + b.group(2))
print(s, end="")
PY
run_py "$plans_check" sheet "$cli_tmp/bad.svg" "$plans_dir/sixbar.7.json" "$plans_dir/sixbar.csv" >"$cli_tmp/check.out" 2>&1
grep -q "velocity image b drawn at" "$cli_tmp/check.out" && pass || fail plans-sheet-marks-can-fail "$(head -3 "$cli_tmp/check.out")"
sed -E 's/(class="velocity-plan"[^>]*data-rotation=")[^"]*"/\10"/; s/(class="mechanism"[^>]*data-rotation=")[^"]*"/\10"/' \
  "$plans_dir/sixbar.7.svg" >"$cli_tmp/bad.svg"
run_py - "$cli_tmp/bad.svg" "$plans_dir/sixbar.7.json" <<'PY'
# the velocity images drawn in the position frame (unturned), the mechanism left turned
import json, math, re, sys
svg, plans = open(sys.argv[1], encoding="utf-8").read(), json.load(open(sys.argv[2]))
g = re.search(r'class="velocity-plan" data-pole="([-0-9.]+) ([-0-9.]+)" data-mu="([^"]+)"', svg)
px, py, mu = float(g.group(1)), float(g.group(2)), float(g.group(3))
for p in plans["velocity_plan"]["points"]:
    svg = re.sub(r'<circle cx="[^"]*" cy="[^"]*"([^>]*data-image="%s")' % p["name"].lower(),
                 '<circle cx="%.2f" cy="%.2f"\\1' % (px + p["x"] / mu, py - p["y"] / mu), svg)
open(sys.argv[1], "w", encoding="utf-8").write(svg)
PY
sed -i -E 's/(class="mechanism"[^>]*data-rotation=")0"/\1'"$(run_py -c 'import json,sys; print(json.load(open(sys.argv[1]))["sheet_rotation"])' "$plans_dir/sixbar.7.json")"'"/' "$cli_tmp/bad.svg"
run_py "$plans_check" sheet "$cli_tmp/bad.svg" "$plans_dir/sixbar.7.json" "$plans_dir/sixbar.csv" >"$cli_tmp/check.out" 2>&1
grep -q "is not perpendicular to the drawn link" "$cli_tmp/check.out" && pass \
  || fail plans-sheet-perpendicular-can-fail "$(head -3 "$cli_tmp/check.out")"
awk 'BEGIN { drop = 0 } { if (drop && $0 == "VPLAN") { sub(/VPLAN/, "TEXT") } print; drop = ($0 == "  8" || $0 == "8") }' \
  "$plans_dir/sixbar_example.1.dxf" >"$cli_tmp/bad.dxf"
run_py "$plans_check" dxf "$cli_tmp/bad.dxf" "$plans_dir/sixbar_example.1.json" >"$cli_tmp/check.out" 2>&1
grep -q "VPLAN: no circle at the image of" "$cli_tmp/check.out" && pass || fail plans-dxf-can-fail "$(head -3 "$cli_tmp/check.out")"
