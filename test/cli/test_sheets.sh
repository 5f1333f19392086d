# kinetostat sheets DECK -o DIR (docs/course.md): the course's sheets of the three flywheel
# decks and a class-III deck, in English and Russian: the files named by content (SVG, DXF,
# and PDF when rsvg-convert is installed), an ISO A1 landscape (or --paper) sheet with the
# ГОСТ frame and the title block (its fields: the drawing's name, Масштаб, Лист N of M, the
# designation in графа 2 and 26, the student), no deck path in the title block, the course's
# headings, no label over a label or a line (svg_check.py labels --lines), the notation, no
# Latin word on a Russian sheet, the DXF read back; -o DIR all or nothing and an earlier
# run's sheets removed; usage errors.
sheets_check="$root/tools/svg_check.py"
sheets_iso() {  # SVG PAPER-W PAPER-H: the paper's size and the frame (a message and false if not)
  local size frame
  size=$(grep -o -m1 'width="[0-9.]*mm" height="[0-9.]*mm"' "$1" | head -1)
  [ -n "$size" ] || { echo "$1: no width and height in mm"; return 1; }
  # the first width x height in mm must be PAPER-W x PAPER-H; the frame's rectangle 20 mm in
  # from the left and 5 mm from the other edges; the title block 185 x 55 mm
  frame=$(echo "$size" | awk -v pw="$2" -v ph="$3" -F'"' '{ w = $2; h = $4; sub("mm", "", w); sub("mm", "", h)
    if (w + 0 != pw + 0 || h + 0 != ph + 0) { print "size " w " x " h " mm, expected " pw " x " ph; exit 1 }
    printf "<rect x=\"20.00\" y=\"5.00\" width=\"%.2f\" height=\"%.2f\" class=\"border\"/>\n", w - 25, h - 10 }') \
    || { echo "$1: $frame"; return 1; }
  grep -qF "$frame" "$1" || { echo "$1: no frame $frame"; return 1; }
  grep -q '<rect x="[0-9.]*" y="[0-9.]*" width="185.00" height="55.00"' "$1" || { echo "$1: no title block"; return 1; }
}
sheets_decks="pr3207_flywheel class3"
# the other two flywheel decks with tools/test --long (a few seconds each)
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then sheets_decks="$sheets_decks sixbar_flywheel assur_pr3207_flywheel"; fi
# (the PDFs: rsvg-convert, half of a run's processor time, converts the first run's three
# sheets; the later runs of the default suite write a stand-in PDF - lib.sh, pdf_stand_in -
# whose file is checked the same way; with tools/test --long every run converts)
sheets_first_path="$PATH"
for deck in $sheets_decks; do
  sheets_langs="en ru"
  [ "$deck" = class3 ] && [ "${KINETOSTAT_LONG:-0}" != 1 ] && sheets_langs="en"
  for lang in $sheets_langs; do
    dir="$cli_tmp/sheets_${deck}_$lang"
    rm -rf "$dir"
    run_ks sheets "data/$deck.nml" -o "$dir" --lang "$lang" --student "Иванов И.И." --group МТ-301 --variant 7
    if [ "${KINETOSTAT_LONG:-0}" != 1 ] && command -v rsvg-convert >/dev/null; then PATH="$(pdf_stand_in):$sheets_first_path"; fi
    if [ "$rc" -ne 0 ] || [ -s "$out" ]; then fail "sheets-run-$deck-$lang" "exit $rc: $(head -c 300 "$err")"; continue; fi
    expected="kinematics kinetostatics"
    case "$deck" in *flywheel) expected="dynamics kinematics kinetostatics" ;; esac
    missing=""
    for s in $expected; do
      for ext in svg dxf; do [ -s "$dir/$s.$ext" ] || missing="$missing $s.$ext"; done
      if command -v rsvg-convert >/dev/null; then [ -s "$dir/$s.pdf" ] || missing="$missing $s.pdf"; fi
    done
    made=$(cd "$dir" && ls | sed 's/\..*//' | sort -u | tr '\n' ' ')
    [ "$made" = "$expected " ] || missing="$missing (made: $made)"
    [ -z "$missing" ] && pass || fail "sheets-files-$deck-$lang" "missing:$missing"
    for s in $expected; do
      svg="$dir/$s.svg"
      sheets_iso "$svg" 841.00 594.00 >"$cli_tmp/check.out" 2>&1 || { fail "sheets-iso-$deck-$s-$lang" "$(tail -2 "$cli_tmp/check.out")"; continue; }
      # (the checkers' calls run in one Python process each after the loop: check_batch)
      check_job svg_check "sheets-legible-$deck-$s-$lang" labels --lines "$svg"
      check_job svg_check "sheets-notation-$deck-$s-$lang" notation "$lang" "$svg"
      check_job dxf_check "sheets-dxf-$deck-$s-$lang" "$dir/$s.dxf"
      [ "$lang" = ru ] && check_job svg_check "sheets-english-$deck-$s" english "$svg"
      # the title block: the student, Лист N of M, no deck path
      n_total=$(echo "$expected" | wc -w)
      grep -q ">Иванов И.И.<" "$svg" && grep -q "Листов $n_total<\|Sheets $n_total<" "$svg" \
        && ! grep -q ">[^<]*$deck.nml[^<]*</text>" <(grep -v 'class="subtitle"' "$svg" | grep -v "deck\|файл") \
        && pass || fail "sheets-title-block-$deck-$s-$lang" "no student, wrong sheet count or a deck path in the block"
    done
    if [ "$s" = dynamics ] || [ -s "$dir/dynamics.svg" ]; then
      svg="$dir/dynamics.svg"
      missing=""
      if [ "$lang" = ru ]; then words="Приведенные моменты|Работы сил|Приведенный момент инерции|Мерцалова|Истинная угловая скорость|Угловое ускорение|Диаграмма Виттенбауэра|Маховик \(диск\)|Масштаб"
      else words="Reduced moments|Work of the forces|Reduced moment of inertia|Merzalov|True speed|Angular acceleration|Wittenbauer|Flywheel \(a disc\)|Scale"; fi
      IFS='|' read -r -a heads <<<"$words"
      for w in "${heads[@]}"; do grep -Eq ">$w" "$svg" || grep -Eq "$w" "$svg" || missing="$missing '$w'"; done
      grep -q ">1:[0-9.]*<" "$svg" || missing="$missing scale-1:n"
      grep -q "μφ = 1.5 " "$svg" || missing="$missing mu-phi"
      [ -z "$missing" ] && pass || fail "sheets-dynamics-headings-$deck-$lang" "missing:$missing"
    fi
  done
done

check_batch svg_check
check_batch dxf_check
PATH="$sheets_first_path"

# The PDFs (rsvg-convert, half of a run's processor time) are checked above; the later runs of
# the default suite write a stand-in PDF (lib.sh: pdf_stand_in), their SVG and DXF as ever; with
# tools/test --long every run converts. PATH is restored at the end.
sheets_path="$PATH"
if [ "${KINETOSTAT_LONG:-0}" != 1 ] && command -v rsvg-convert >/dev/null; then PATH="$(pdf_stand_in):$PATH"; fi

# each Assur group drawn apart on the kinetostatics sheet: every link with one inner joint
# gets its moment equation about it, a group with a sliding inner pair (PR 3207's 2,3) the
# group's about its pivot on the frame (the arms h in mm at the drawing's μl, the forces in
# N, the couples in N·m). The equation's unknown (data-unknown, or a τ part) from the
# drawing's numbers = the one drawn within 0.5 %: R^τ (or a reaction whose line is known,
# PR 3207's F21 square to the lever, arm |CB|) = |Σ of the others| / h μl; the arm of a
# guide's reaction (PR 3207's F56 on the ram) = |Σ| / F μl. The polygon's forces = the
# run's (--format json --plans at the sheet's step) within 1e-9 N.
sheets_moments() {  # SVG [JSON]: "ok N GROUPS" or "differs: ..."
  run_py - "$@" <<'PY'
import json, re, sys
text = open(sys.argv[1], encoding="utf-8").read()
run = {}
if len(sys.argv) > 2:
    for poly in json.load(open(sys.argv[2]))["force_plans"]:
        for v in poly["vectors"]:
            run[v["name"]] = (v["x"] ** 2 + v["y"] ** 2) ** 0.5
n, bad = 0, []
for eq in re.finditer(r'<g class="moment-equation" data-link="([^"]*)" data-about="([^"]*)" data-mu-l="([^"]*)">(.*?)</g>\s*</g>', text, re.S):
    mu = float(eq.group(3))
    rest, sought = 0.0, None
    for arm in re.finditer(r'<g class="arm"([^>]*)>', eq.group(4)):
        a = dict(re.findall(r'(data-[\w-]+)="([^"]*)"', arm.group(1)))
        if "data-moment" in a:
            rest += float(a["data-moment"])
        elif "data-unknown" in a or "^τ" in a["data-force-name"]:
            sought = a
        else:
            rest += float(a["data-sense"]) * float(a["data-force"]) * float(a["data-h"]) * mu
    if sought is None:
        continue
    n += 1
    name = sought["data-force-name"]
    if sought.get("data-unknown", "force").strip() == "arm":
        drawn = float(sought["data-h"])
        computed = abs(rest) / (float(sought["data-force"]) * mu)
        what = "arm of " + name
    else:
        drawn = float(sought["data-force"])
        computed = abs(rest) / (float(sought["data-h"]) * mu)
        what = name
        if run and abs(run.get(name, -1.0) - drawn) > 1e-9 * max(drawn, 1.0):
            bad.append(f'{name}: drawn {drawn:.10g} N, run {run.get(name)}')
    if abs(computed - drawn) > 5e-3 * max(drawn, 1e-9):
        bad.append(f'{what} about {eq.group(2)}: moment equation {computed:.6g}, drawn {drawn:.6g}')
groups = len(re.findall(r'class="group-apart"', text))
if groups == 0:
    bad.append("no group drawn apart")
print(f"differs: {'; '.join(bad)}" if bad else f"ok {n} {groups}")
PY
}
for case in pr3207_flywheel_en pr3207_flywheel_ru class3_en; do
  svg="$cli_tmp/sheets_$case/kinetostatics.svg"
  deck=${case%_*}
  step=$(sed -n 's/.*\(position\|положение\) \([0-9][0-9]*\)<\/title>.*/\2/p' "$svg" | head -1)
  "$KINETOSTAT" "data/$deck.nml" --format json --at "$step" --plans >"$cli_tmp/apart.json" 2>/dev/null
  verdict=$(sheets_moments "$svg" "$cli_tmp/apart.json")
  case "$verdict" in ok*) pass ;; *) fail "sheets-groups-apart-$case" "$verdict" ;; esac
done
# class III: three τ found by three moment equations (links 2, 3, 4 about their joints with 5)
verdict=$(sheets_moments "$cli_tmp/sheets_class3_en/kinetostatics.svg")
[ "$verdict" = "ok 3 1" ] && pass || fail sheets-groups-apart-class3-tau "expected 3 moment equations with τ, got: $verdict"
# PR 3207: F21 about C (the group 2,3) and the arm of F56 (the ram) found by the equations;
# must fail: either drawn 2 % off
svg="$cli_tmp/sheets_pr3207_flywheel_en/kinetostatics.svg"
verdict=$(sheets_moments "$svg")
[ "$verdict" = "ok 2 2" ] && pass || fail sheets-groups-apart-pr3207 "expected F21 about C and the arm of F56, got: $verdict"
for bad in 'h21:F21 about C' 'h56:arm of F56 about D'; do
  run_py -c "import re, sys; t = open(sys.argv[1], encoding='utf-8').read(); print(re.sub(r'(data-arm=\"' + sys.argv[2] + r'\"[^>]*data-h=\")([^\"]*)', lambda m: m.group(1) + repr(1.02 * float(m.group(2))), t), end='')" \
    "$svg" "${bad%%:*}" >"$cli_tmp/apart_bad.svg"
  verdict=$(sheets_moments "$cli_tmp/apart_bad.svg")
  case "$verdict" in "differs: ${bad#*:}"*) pass ;; *) fail sheets-groups-apart-pr3207-must-fail "a wrong ${bad%%:*} passed: $verdict" ;; esac
done
# must fail: an arm of R^τ drawn 2 % too long
run_py -c "import re, sys; t = open(sys.argv[1], encoding='utf-8').read(); print(re.sub(r'(data-force-name=\"F21\^τ\" data-force=\"[^\"]*\" data-h=\")([^\"]*)', lambda m: m.group(1) + repr(1.02 * float(m.group(2))), t), end='')" \
  "$cli_tmp/sheets_class3_en/kinetostatics.svg" >"$cli_tmp/apart_bad.svg"
verdict=$(sheets_moments "$cli_tmp/apart_bad.svg")
case "$verdict" in "differs: F21^τ about"*) pass ;; *) fail sheets-groups-apart-must-fail "a wrong arm passed: $verdict" ;; esac

# the kinematics sheet's structure is kinetostat structure's (W, the formula), its output
# link's diagrams and its values table the run's
dir="$cli_tmp/sheets_class3_en"
formula=$("$KINETOSTAT" structure data/class3.nml | sed -n 's/^ STRUCTURE FORMULA: //p' | sed 's/ -> / → /g')
run_py - "$dir/kinematics.svg" "$formula" <<'PY' && pass || fail sheets-kinematics-structure "the structure or W differs"
import re, sys
plain = re.sub(r"<[^>]+>", "", open(sys.argv[1], encoding="utf-8").read())
assert "structure formula: " + sys.argv[2] in plain, sys.argv[2]
assert "W = 3n − 2p5 − p4 = 1" in plain, "W"
assert "Displacement of link" in plain or "Angle of link" in plain, "output link"
PY

# the plan of positions: 12 positions from the output link's extreme position, found by
# solving. PR 3207: the ram's extremes are where the crank is square to the rocker, at
# phi1 = acos(l_ab/l_ac) and 360 deg minus it; position 0 begins the working stroke (the
# longer, from 73.17 deg: the cutting zone is 95..265 deg). The default --at of a flywheel
# deck is the step of the largest |M1| at constant speed: the same deck without its
# dynamics, run at 1 deg (data/pr3207.nml --set dphi=1).
dir="$cli_tmp/sheets_pr3207_flywheel_en"
run_ks data/pr3207.nml --set dphi=1 --format csv
run_py - "$dir/kinematics.svg" "$dir/kinetostatics.svg" "$out" <<'PY' && pass || fail sheets-positions-pr3207 "the plan of positions or the default position differs"
import csv, math, re, sys
plain = re.sub(r"<[^>]+>", "", open(sys.argv[1], encoding="utf-8").read())
assert "Plan of positions (12, from the extreme position of link 5)" in plain, "heading"
expected = f"{math.degrees(math.acos(0.11 / 0.38)):.2f}"
got = re.search(r"position 0: the extreme position of link 5, φ1 = ([0-9.]+) deg", plain)
assert got and got.group(1) == expected, (got and got.group(1), expected)
rows = list(csv.DictReader(open(sys.argv[3])))
k = max(range(len(rows)), key=lambda i: abs(float(rows[i]["M1"]))) + 1
kin = open(sys.argv[2], encoding="utf-8").read()
assert f"step {k} of 361" in kin, ("default --at", k)
assert f"position {k} " in plain, ("kinematics position", k)
PY
# a rocker (the four-bar's link 3, --positions 8): at position 0 the crank and the coupler
# are in line, |AC| = l_BC + l_AB = 0.45 m, and the rocker's angle is extreme there (the
# deck run at position 0's printed angle and 0.01 deg either side)
dir="$cli_tmp/sheets_fourbar"
rm -rf "$dir"
run_ks sheets data/assur_fourbar.nml -o "$dir" --positions 8 --point C
phi0=$(sed 's/<[^>]*>//g' "$dir/kinematics.svg" | grep -o 'position 0: the extreme position of link 3, φ1 = [0-9.]*' | sed 's/.*= //')
if [ "$rc" -eq 0 ] && [ -n "$phi0" ]; then
  run_ks data/assur_fourbar.nml --set "phi_start=$(run_py -c "print($phi0 - 0.01)")" --set dphi=0.01 --set n=3 \
    --format csv --kinematics
  run_py - "$out" "$dir/kinematics.svg" <<'PY' && pass || fail sheets-positions-rocker "position 0 is not the rocker's extreme"
import csv, math, re, sys
r = list(csv.DictReader(open(sys.argv[1])))
ac = math.hypot(float(r[1]["x_C"]) - float(r[1]["x_A"]), float(r[1]["y_C"]) - float(r[1]["y_A"]))
assert abs(ac - 0.45) < 1e-6, ("|AC|", ac)
p = [float(x["phi3"]) for x in r]
assert (p[1] - p[0]) * (p[1] - p[2]) > 0, ("phi3 not extreme", p)
plain = re.sub(r"<[^>]+>", "", open(sys.argv[2], encoding="utf-8").read())
assert "Plan of positions (8, from the extreme position of link 3)" in plain and "trajectory of C" in plain
PY
  run_py "$sheets_check" labels --lines "$dir/kinematics.svg" >"$cli_tmp/check.out" 2>&1 && pass \
    || fail sheets-positions-rocker-legible "$(head -3 "$cli_tmp/check.out")"
else fail sheets-positions-rocker "exit $rc, no position 0: $(head -c 300 "$err")"; fi
# a four-stroke engine (cycle 720 deg): position 0 its top dead centre (the deck's 0 deg, the
# piston farthest from the crank), the dynamics sheet over the whole cycle
dir="$cli_tmp/sheets_engine"
rm -rf "$dir"
run_ks sheets data/assur_engine_flywheel.nml -o "$dir" --lang ru --output-link 3
if [ "$rc" -eq 0 ] && grep -q 'положение 0: крайнее положение звена 3, φ1 = 0.00 град' <(sed 's/<[^>]*>//g' "$dir/kinematics.svg") \
  && grep -q '>720<' "$dir/dynamics.svg" \
  && run_py "$sheets_check" labels --lines "$dir/kinematics.svg" "$dir/dynamics.svg" >"$cli_tmp/check.out" 2>&1 \
  && run_py "$sheets_check" english "$dir/kinematics.svg" "$dir/dynamics.svg" >>"$cli_tmp/check.out" 2>&1; then pass
else fail sheets-engine-720 "exit $rc $(head -c 300 "$err") $(head -3 "$cli_tmp/check.out")"; fi
# bad values: exit 2, one line naming the option, nothing written
for bad in "--positions 10" "--point Q" "--output-link 9" "--output-link x"; do
  rm -rf "$cli_tmp/x"
  run_ks sheets data/assur_fourbar.nml -o "$cli_tmp/x" $bad
  if [ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" = 1 ] && grep -q -- "${bad% *}" "$err" && [ ! -e "$cli_tmp/x" ]; then pass
  else fail "sheets-bad-${bad// /-}" "exit $rc: $(head -c 200 "$err")"; fi
done

# the figures the dynamics sheet prints are the run's (the flywheel's J, D, the Wittenbauer
# segment k-l = delta omega_m^2 J_fw / mu_T)
dir="$cli_tmp/sheets_pr3207_flywheel_en"
run_py - "$dir/dynamics.svg" <<'PY' && pass || fail sheets-dynamics-figures "the sheet's numbers differ from the run's"
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
plain = re.sub(r"<[^>]+>", "", t)
assert "k–l = 123.2 mm" in plain, "k-l"  # 0.04 * 7.5^2 * 273.8 J / 5 J/mm
assert "= 274 kg·m²" in plain
assert "⌀1123" in plain and ">225<" in t, "disc dimensions"
PY

# A4 (ГОСТ 2.301: portrait, its title block along the short side): the kinetostatics sheet
# 210 x 297 mm with the frame and the title block; no label over a label or a line, leader
# lines counted (the class-III group, the four-bar, the two six-bar decks, in English and in
# Russian); the mechanism 50 mm across at the least (its joints' extent on the sheet)
# (the six-bar's flywheel deck, a second of processor time, with --long: PR 3207's flywheel deck
# is drawn on A4 below)
sheets_a4="class3:en assur_fourbar:en sixbar_example:en sixbar_example:ru"
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then sheets_a4="$sheets_a4 sixbar_flywheel:en class3:ru assur_fourbar:ru sixbar_flywheel:ru"; fi
for deck_lang in $sheets_a4; do
  deck="${deck_lang%:*}"; lang="${deck_lang#*:}"
  dir="$cli_tmp/sheets_a4_${deck}_$lang"
  rm -rf "$dir"
  run_ks sheets "data/$deck.nml" -o "$dir" --paper A4 --lang "$lang" --student X --group G --variant 1
  if [ "$rc" -eq 0 ] && sheets_iso "$dir/kinetostatics.svg" 210.00 297.00 >"$cli_tmp/check.out" 2>&1 \
    && run_py "$sheets_check" labels --lines "$dir/kinetostatics.svg" >>"$cli_tmp/check.out" 2>&1 \
    && run_py - "$dir/kinetostatics.svg" >>"$cli_tmp/check.out" 2>&1 <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
m = t[t.index('<g class="mechanism"'):]
m = m[:m.index("</g>")] if "</g>" in m else m
pts = [(float(x), float(y)) for x, y in re.findall(r'<circle cx="([0-9.]+)" cy="([0-9.]+)" r="[0-9.]+" class="(?:joint|com)"', m)]
across = max(max(x for x, _ in pts) - min(x for x, _ in pts), max(y for _, y in pts) - min(y for _, y in pts))
assert across >= 50.0, f"the mechanism is {across:.1f} mm across on A4, expected 50 mm at the least"
PY
  then
    pass
  else
    fail "sheets-a4-$deck-$lang" "exit $rc: $(grep -v '^[0-9]* sheets' "$cli_tmp/check.out" | head -4)"
  fi
done
# PR 3207's ram: its guide's reaction F56 on the mechanism as on the group drawn apart: its line
# of action 1.75 m from the ram (h56 = 23.4 mm at 0.075 m/mm), off the drawing, stated; the
# dynamics sheet on A4 portrait too (210 x 297, the frame, the title block)
dir="$cli_tmp/sheets_a4_pr3207"
rm -rf "$dir"
run_ks sheets data/pr3207_flywheel.nml -o "$dir" --paper A4 --lang ru --student X --group G --variant 1
if [ "$rc" -eq 0 ] && grep -q "F56 приложена к точке звена, её линия действия в 1.75 м от неё" <(sed 's/<[^>]*>//g' "$dir/kinetostatics.svg") \
  && grep -q 'data-arm="h56"[^>]*data-h="2.3392918' "$dir/kinetostatics.svg" \
  && sheets_iso "$dir/dynamics.svg" 210.00 297.00 >/dev/null 2>&1 \
  && run_py "$sheets_check" labels --lines "$dir/kinetostatics.svg" >"$cli_tmp/check.out" 2>&1; then pass
else fail sheets-a4-guide-reaction "exit $rc: no F56 line of action note, dynamics not 210 x 297, or $(head -3 "$cli_tmp/check.out")"; fi

# A3 and A2 landscape: the kinematics (on A3 its two sheets, kinematics and kinematics-2, as
# A4's) and the dynamics sheets' middle column stops above the title block (A3), the mechanism
# panel's heading in two lines (in Russian on A2 its break before a subscript): no label over a
# label or a line, leader lines counted (PR 3207; the engine and the six-bar in --long)
sheets_a3="pr3207_flywheel:A3:en:420.00:297.00 pr3207_flywheel:A2:ru:594.00:420.00"
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  sheets_a3="$sheets_a3 assur_engine_flywheel:A3:en:420.00:297.00 sixbar_flywheel:A3:ru:420.00:297.00"
fi
for spec in $sheets_a3; do
  IFS=: read -r deck paper lang pw ph <<<"$spec"
  dir="$cli_tmp/sheets_${paper}_${deck}_$lang"
  rm -rf "$dir"
  # (A2 with the options checked below: --designation, --sheet-numbers, --at)
  sheets_opts=()
  [ "$paper" = A2 ] && sheets_opts=(--designation "ТММ.КП.07.003" --sheet-numbers 4,5,6 --at 7)
  run_ks sheets "data/$deck.nml" -o "$dir" --paper "$paper" --lang "$lang" --student X --group G --variant 1 "${sheets_opts[@]}"
  sheet_word=Sheet; total_word=Sheets
  [ "$lang" = ru ] && { sheet_word="Лист"; total_word="Листов"; }
  sheets_a3_svgs="$dir/kinematics.svg"
  [ "$paper" = A3 ] && sheets_a3_svgs="$sheets_a3_svgs $dir/kinematics-2.svg"
  [ "$deck" = sixbar_flywheel ] || sheets_a3_svgs="$sheets_a3_svgs $dir/dynamics.svg"
  if [ "$rc" -eq 0 ] && sheets_iso "$dir/kinematics.svg" "$pw" "$ph" >"$cli_tmp/check.out" 2>&1 \
    && { [ "$paper" != A3 ] || { sheets_iso "$dir/kinematics-2.svg" "$pw" "$ph" && grep -q ">$sheet_word 2<" "$dir/kinematics-2.svg" \
      && grep -q ">$sheet_word 3<" "$dir/kinetostatics.svg" && grep -q ">$total_word 4<" "$dir/kinematics.svg"; }; } >>"$cli_tmp/check.out" 2>&1 \
    && run_py "$sheets_check" labels --lines $sheets_a3_svgs >>"$cli_tmp/check.out" 2>&1; then pass
  else fail "sheets-$paper-$deck-$lang" "exit $rc: $(grep -v '^[0-9]* sheets' "$cli_tmp/check.out" | head -4)"; fi
done

# --paper, --designation (графа 2 and 26, turned 180 deg), --sheet-numbers, --at: the A2
# sheets above (in Russian)
dir="$cli_tmp/sheets_A2_pr3207_flywheel_ru"
if sheets_iso "$dir/dynamics.svg" 594.00 420.00 >/dev/null 2>&1 \
  && sheets_iso "$dir/kinetostatics.svg" 594.00 420.00 >/dev/null 2>&1 \
  && [ "$(grep -c '>ТММ.КП.07.003<' "$dir/dynamics.svg")" = 2 ] && grep -q 'rotate(180' "$dir/dynamics.svg" \
  && grep -q '>Лист 6<' "$dir/dynamics.svg" && grep -q '>Лист 5<' "$dir/kinetostatics.svg" \
  && grep -q '>Лист 4<' "$dir/kinematics.svg" \
  && grep -q '>Листов 3<' "$dir/kinetostatics.svg" && grep -q 'положение 7 из 361' "$dir/kinetostatics.svg" \
  && run_py "$sheets_check" labels --lines "$dir/kinetostatics.svg" >"$cli_tmp/check.out" 2>&1; then pass
else fail sheets-options "$(ls "$dir" | tr '\n' ' ') $(head -3 "$cli_tmp/check.out" 2>/dev/null)"; fi
# the default position: the step of the largest |M1|
run_ks data/assur_slider_crank.nml --format summary
row=$(run_py - "$out" <<'PY'
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))[0]
mx, mn = float(r["M1_max"]), float(r["M1_min"])
print(r["M1_max_at"] if abs(mx) >= abs(mn) else r["M1_min_at"])
PY
)
dir="$cli_tmp/sheets_at"
run_ks sheets data/assur_slider_crank.nml -o "$dir"
step=$(run_py -c "print(int(round(float('$row') / 30)) + 1)")
grep -q "step $step of 13" "$dir/kinetostatics.svg" && pass || fail sheets-default-at "not at step $step (phi1 = $row deg)"

# all or nothing: a failing deck writes nothing and leaves an earlier run's sheets; a deck
# without a cycle removes the earlier dynamics sheet
dir="$cli_tmp/sheets_aon"
rm -rf "$dir"
# (the first A1 run's sheets of the same deck, copied)
cp -r "$cli_tmp/sheets_pr3207_flywheel_en" "$dir"
cp "$dir/dynamics.svg" "$cli_tmp/sheets_before.svg"
run_ks sheets data/pr3207_flywheel.nml -o "$dir" --set l_ab=10
if [ "$rc" -ne 0 ] && cmp -s "$dir/dynamics.svg" "$cli_tmp/sheets_before.svg" && [ "$(ls -A "$dir" | grep -c tmp)" = 0 ]; then pass
else fail sheets-all-or-nothing "exit $rc; the earlier sheets changed or temporaries left"; fi
run_ks sheets data/pr3207.nml -o "$dir"
if [ "$rc" -eq 0 ] && [ ! -e "$dir/dynamics.svg" ] && [ ! -e "$dir/dynamics.dxf" ] && [ ! -e "$dir/dynamics.pdf" ] \
  && [ -s "$dir/kinetostatics.svg" ]; then pass
else fail sheets-stale-removed "exit $rc; $(ls "$dir")"; fi

# a design deck: its one sheet (gears, planetary, cam) as SVG and DXF, the linkage's sheets of
# an earlier run in the same directory removed; --at puts the cam's follower
run_ks sheets data/cam_profile_roller.nml -o "$dir" --at 13
if [ "$rc" -eq 0 ] && [ -s "$dir/cam.svg" ] && [ -s "$dir/cam.dxf" ] && [ ! -e "$dir/kinetostatics.svg" ] \
  && [ ! -e "$dir/kinematics.dxf" ] && grep -q 'follower at φ = 60.0 deg' "$dir/cam.svg"; then pass
else fail sheets-design-cam "exit $rc; $(ls "$dir")"; fi
for d in gear_geometry_auto:gears planetary_synthesis:planetary; do
  run_ks sheets "data/${d%%:*}.nml" -o "$dir"
  if [ "$rc" -eq 0 ] && [ -s "$dir/${d##*:}.svg" ] && [ -s "$dir/${d##*:}.dxf" ] && [ ! -e "$dir/cam.svg" ] \
    && xmllint --noout "$dir/${d##*:}.svg" 2>/dev/null; then pass
  else fail "sheets-design-${d##*:}" "exit $rc; $(ls "$dir")"; fi
done

# usage errors
expect_exit sheets-no-dir 1 sheets data/pr3207.nml
expect_exit sheets-paper 1 sheets data/pr3207.nml -o "$cli_tmp/x" --paper A0
expect_exit sheets-numbers 1 sheets data/pr3207.nml -o "$cli_tmp/x" --sheet-numbers 1,x
expect_exit sheets-numbers-count 1 sheets data/pr3207_flywheel.nml -o "$cli_tmp/x" --sheet-numbers 1,2
expect_exit sheets-format 1 sheets data/pr3207.nml -o "$cli_tmp/x" --format csv
expect_exit sheets-paper-without 1 data/pr3207.nml --paper A3
expect_exit sheets-gears 1 sheets data/gears_reducer.nml -o "$cli_tmp/x"

# the designation and the student are a user's strings: every sheet well formed with hostile
# ones (tools/output_check.py: XML, the DXF's group-code pairs in ASCII)
dir="$cli_tmp/sheets_hostile"
rm -rf "$dir"
run_ks sheets data/pr3207_flywheel.nml -o "$dir" --designation $'<b>&amp;"x\'\x01\n0\nEOF' --student $'<i>\n999'
ok=1
[ "$rc" -eq 0 ] || ok=0
for f in "$dir"/*.svg; do run_py "$root/tools/output_check.py" xml "$f" --forbid "<b>" --forbid "<i>" >/dev/null 2>&1 || ok=0; done
for f in "$dir"/*.dxf; do run_py "$root/tools/output_check.py" dxf "$f" >/dev/null 2>&1 || ok=0; done
[ "$ok" = 1 ] && pass || fail sheets-hostile-strings "exit $rc or a sheet not well formed"

# Zhukovsky's lever read off as a student reads it (A1 and A4, PR 3207 with its flywheel):
# every load's arm and the balancing force's measured on the drawing (the distance from the
# pole p to the line of its arrow, the arrow's tail and tip as drawn) and read to 0.5 mm, the
# forces as the table gives them (a load too short to draw: its arm as the lever's group
# states it); P_b = -sum(±F h) / h_b, M = P_b l. The read-off must agree with the computed
# moment within 2 % of it, every drawn arm must be the one its group states within 0.1 mm
# (the coordinates' 0.01 mm over the arrow's length), and the worst case of reading every
# length 0.25 mm off must stay within 10 % of the moment (2 % on A1): a lever large enough to
# read. Must fail: F5c's arrow moved 2 mm, its force 5 % off.
sheets_lever_read() {  # SVG BOUND%: "ok ..." or "differs: ..."
  run_py - "$@" <<'PY'
import math, re, sys
text = open(sys.argv[1], encoding="utf-8").read()
bound_limit = float(sys.argv[2])
lever = re.search(r'<g class="lever" data-pole="([-0-9.]+) ([-0-9.]+)" data-mu="([^"]+)"', text)
px, py = float(lever.group(1)), float(lever.group(2))
def groups(cls):
    for g in re.finditer(r'<g class="' + cls + r'"([^>]*)>(.*?)</g>', text, re.S):
        a = dict(re.findall(r'(data-[\w-]+)="([^"]*)"', g.group(1)))
        line = re.search(r'<line x1="([-0-9.]+)" y1="([-0-9.]+)"', g.group(2))
        head = re.search(r'<polygon points="([-0-9.]+),([-0-9.]+)', g.group(2))
        ends = (float(line.group(1)), float(line.group(2)), float(head.group(1)), float(head.group(2))) if line and head else None
        yield a, ends
def arm(e):
    x1, y1, x2, y2 = e
    return abs((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) / math.hypot(x2 - x1, y2 - y1)
def read(h):
    return 0.5 * round(h / 0.5)
bad, total, spread, n = [], 0.0, 0.0, 0
for a, e in groups("lever-load"):
    f, h = float(a["data-force"]), float(a["data-h"])
    if e:
        n += 1
        if abs(arm(e) - h) > 0.1:
            bad.append(f'{a["data-name"]}: arm drawn {arm(e):.2f} mm, stated {h:.2f} mm')
        h = arm(e)
    total += float(a["data-sense"]) * f * read(h)
    spread += 0.25 * f
(b, e), = list(groups("lever-balancing"))
hb = read(arm(e) if e else float(b["data-h"]))
p = -total / (float(b["data-sense"]) * hb)
m, l, computed = p * float(b["data-length"]), float(b["data-length"]), abs(float(b["data-effort"]))
worst = (spread + 0.25 * abs(p)) / hb * l
if abs(abs(m) - computed) > 0.02 * computed:
    bad.append(f"read off {m:.4g} N·m, computed {computed:.4g} N·m (more than 2 % apart)")
if worst > bound_limit / 100 * computed:
    bad.append(f"too small to read: lengths 0.25 mm off move M by up to {100 * worst / computed:.1f} % (limit {bound_limit} %)")
if n == 0:
    bad.append("no load drawn on the lever")
print("differs: " + "; ".join(bad) if bad else f"ok read off {m:.4g} N·m, computed {computed:.4g} N·m, |pb| {hb} mm, worst {100 * worst / computed:.1f} %")
PY
}
for case in "sheets_pr3207_flywheel_en:2" "sheets_a4_pr3207:10"; do
  svg="$cli_tmp/${case%:*}/kinetostatics.svg"
  verdict=$(sheets_lever_read "$svg" "${case#*:}")
  case "$verdict" in ok*) pass ;; *) fail "sheets-lever-read-${case%:*}" "$verdict" ;; esac
done
svg="$cli_tmp/sheets_a4_pr3207/kinetostatics.svg"
run_py -c "import re, sys; t = open(sys.argv[1], encoding='utf-8').read(); print(re.sub(r'(data-name=\"F5c\".*?<line x1=\"[-0-9.]+\" y1=\")([-0-9.]+)', lambda m: m.group(1) + f'{float(m.group(2)) + 2:.2f}', t, count=1, flags=re.S), end='')" \
  "$svg" >"$cli_tmp/lever_bad.svg"
verdict=$(sheets_lever_read "$cli_tmp/lever_bad.svg" 10)
case "$verdict" in "differs: F5c: arm drawn"*) pass ;; *) fail sheets-lever-read-must-fail-arm "an arrow 2 mm off passed: $verdict" ;; esac
run_py -c "import re, sys; t = open(sys.argv[1], encoding='utf-8').read(); print(re.sub(r'(data-name=\"F5c\" data-force=\")([^\"]+)', lambda m: m.group(1) + repr(1.05 * float(m.group(2))), t, count=1), end='')" \
  "$svg" >"$cli_tmp/lever_bad.svg"
verdict=$(sheets_lever_read "$cli_tmp/lever_bad.svg" 10)
case "$verdict" in "differs: read off"*) pass ;; *) fail sheets-lever-read-must-fail-force "a force 5 % off passed: $verdict" ;; esac

# no label over a label or a line on the dynamics sheets of the flywheel decks: A4 and A1
# (PR 3207 by default - its A1 sheets above; every flywheel deck with tools/test --long)
sheets_dyn="sheets_a4_pr3207"
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  for deck in assur_engine_flywheel assur_pr3207_flywheel linkage_engine_flywheel linkage_pr3207_flywheel sixbar_flywheel; do
    for paper in A4 A1; do
      dir="$cli_tmp/sheets_dyn_${deck}_$paper"
      rm -rf "$dir"
      run_ks sheets "data/$deck.nml" -o "$dir" --paper "$paper"
      [ "$rc" -eq 0 ] || fail "sheets-dynamics-run-$deck-$paper" "exit $rc: $(head -c 300 "$err")"
      sheets_dyn="$sheets_dyn sheets_dyn_${deck}_$paper"
    done
  done
fi
for d in $sheets_dyn; do
  run_py "$sheets_check" labels --lines "$cli_tmp/$d/dynamics.svg" >"$cli_tmp/check.out" 2>&1 && pass \
    || fail "sheets-dynamics-legible-$d" "$(grep -v '^[0-9]* sheets' "$cli_tmp/check.out" | head -4)"
done
# A4 (portrait, ГОСТ 2.301): the kinematics on two sheets, kinematics (the plan of positions,
# the structure, the output link's diagrams) and kinematics-2 (the mechanism in the position,
# the values, the plans of velocities and accelerations, the values read off), each 210 x 297
# with the frame and the title block, numbered one after the other (Sheet 1 and 2 of 4 for a
# flywheel deck); no label over a label or a line (leader lines counted), nothing drawn inside
# the title block's rectangle (its own lines and words, written first, aside). The A4
# directories of the checks above are reused; PR 3207 and the class-III deck by default, the
# other flywheel decks and languages with --long.
sheets_in_block() {  # SVG...: "ok" or what lies inside the title block
  run_py - "$@" <<'PY'
import re, sys
bad = []
for path in sys.argv[1:]:
    t = open(path, encoding="utf-8").read()
    m = re.search(r'<rect x="([0-9.]+)" y="([0-9.]+)" width="185.00" height="55.00"[^>]*/>', t)
    if not m:
        bad.append(f"{path}: no title block"); continue
    x0, y0 = float(m.group(1)), float(m.group(2))
    box = (x0, y0, x0 + 185.0, y0 + 55.0)
    def points(el):
        a = dict(re.findall(r'\b([a-z0-9]+)="([^"]*)"', el))
        out = []
        for kx, ky in (("x", "y"), ("x1", "y1"), ("x2", "y2"), ("cx", "cy")):
            if kx in a and ky in a:
                try: out.append((float(a[kx]), float(a[ky])))
                except ValueError: pass
        if "points" in a:
            v = [float(s) for s in re.split(r"[ ,]+", a["points"].strip()) if s]
            out += list(zip(v[0::2], v[1::2]))
        return out
    inside = lambda p: box[0] + 0.01 < p[0] < box[2] - 0.01 and box[1] + 0.01 < p[1] < box[3] - 0.01
    els = re.findall(r"<(?:text|line|rect|circle|polyline|polygon)\b[^>]*>", t[m.end():])
    k = 0
    while k < len(els) and all(box[0] - 0.01 <= p[0] <= box[2] + 0.01 and box[1] - 0.01 <= p[1] <= box[3] + 0.01
                                for p in points(els[k])):
        k += 1
    for el in els[k:]:
        if any(inside(p) for p in points(el)):
            bad.append(f"{path}: {el[:90]}"); break
    if k < 10:
        bad.append(f"{path}: the title block has {k} entities")
print("ok" if not bad else "; ".join(bad))
PY
}
sheets_a4k="pr3207_flywheel:ru class3:en"
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  sheets_a4k="$sheets_a4k pr3207_flywheel:en class3:ru sixbar_flywheel:en sixbar_flywheel:ru assur_pr3207_flywheel:en assur_pr3207_flywheel:ru"
fi
for deck_lang in $sheets_a4k; do
  deck="${deck_lang%:*}"; lang="${deck_lang#*:}"
  dir="$cli_tmp/sheets_a4_${deck}_$lang"
  [ "$deck_lang" = pr3207_flywheel:ru ] && dir="$cli_tmp/sheets_a4_pr3207"
  rc=0
  if [ ! -s "$dir/kinematics-2.svg" ]; then
    rm -rf "$dir"
    run_ks sheets "data/$deck.nml" -o "$dir" --paper A4 --lang "$lang" --student X --group G --variant 1
  fi
  n_total=3
  case "$deck" in *flywheel) n_total=4 ;; esac
  if [ "$lang" = ru ]; then heads="План положений|Планы скоростей и ускорений"; sheet_word="Лист"; total_word="Листов"
  else heads="Plan of positions|Plans of velocities and accelerations"; sheet_word="Sheet"; total_word="Sheets"; fi
  : >"$cli_tmp/check.out"
  ok=1
  [ "$rc" -eq 0 ] || { ok=0; echo "exit $rc: $(head -c 300 "$err")" >>"$cli_tmp/check.out"; }
  for ext in svg dxf; do
    for s in kinematics kinematics-2; do [ -s "$dir/$s.$ext" ] || { ok=0; echo "no $s.$ext" >>"$cli_tmp/check.out"; }; done
  done
  if command -v rsvg-convert >/dev/null; then [ -s "$dir/kinematics-2.pdf" ] || { ok=0; echo "no kinematics-2.pdf" >>"$cli_tmp/check.out"; }; fi
  number=0
  for s in kinematics kinematics-2; do
    number=$((number + 1))
    svg="$dir/$s.svg"
    sheets_iso "$svg" 210.00 297.00 >>"$cli_tmp/check.out" 2>&1 || ok=0
    run_py "$sheets_check" labels --lines "$svg" >>"$cli_tmp/check.out" 2>&1 || ok=0
    verdict=$(sheets_in_block "$svg")
    [ "$verdict" = ok ] || { ok=0; echo "$verdict" >>"$cli_tmp/check.out"; }
    head_word="${heads%%|*}"; [ "$s" = kinematics-2 ] && head_word="${heads#*|}"
    grep -q "$head_word" "$svg" && grep -q ">$sheet_word $number<" "$svg" && grep -q ">$total_word $n_total<" "$svg" \
      || { ok=0; echo "$s: no '$head_word' or not $sheet_word $number of $n_total" >>"$cli_tmp/check.out"; }
    if [ "$lang" = ru ]; then run_py "$sheets_check" english "$svg" >>"$cli_tmp/check.out" 2>&1 || ok=0; fi
  done
  [ "$ok" = 1 ] && pass || fail "sheets-a4-kinematics-$deck-$lang" "$(grep -v '^[0-9]* sheets\|^ok$' "$cli_tmp/check.out" | head -4)"
done
# must fail: a line drawn into the title block
dir="$cli_tmp/sheets_a4_pr3207"
sed 's|</svg>|<line x1="100.00" y1="250.00" x2="150.00" y2="260.00" class="thin"/></svg>|' "$dir/kinematics.svg" \
  >"$cli_tmp/a4_bad.svg"
verdict=$(sheets_in_block "$cli_tmp/a4_bad.svg")
case "$verdict" in *'<line x1="100.00" y1="250.00"'*) pass ;; *) fail sheets-a4-block-must-fail "a line in the title block passed: $verdict" ;; esac
# --sheet-numbers on A4: one number more (the second kinematics sheet after the first); the
# second sheet's files removed when the same directory gets a deck's sheets without it
expect_exit sheets-a4-numbers-count 1 sheets data/pr3207_flywheel.nml -o "$cli_tmp/x" --paper A4 --sheet-numbers 1,2,3
cp -r "$dir" "$cli_tmp/sheets_a4_stale"
run_ks sheets data/cam_profile_roller.nml -o "$cli_tmp/sheets_a4_stale"
if [ "$rc" -eq 0 ] && [ -s "$cli_tmp/sheets_a4_stale/cam.svg" ] && [ -z "$(ls "$cli_tmp/sheets_a4_stale" | grep '^kinematics')" ]; then pass
else fail sheets-a4-stale-removed "exit $rc; $(ls "$cli_tmp/sheets_a4_stale" | tr '\n' ' ')"; fi
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  rm -rf "$cli_tmp/sheets_a4_numbers"
  run_ks sheets data/pr3207_flywheel.nml -o "$cli_tmp/sheets_a4_numbers" --paper A4 --sheet-numbers 4,5,6,7
  d="$cli_tmp/sheets_a4_numbers"
  if [ "$rc" -eq 0 ] && grep -q '>Sheet 4<' "$d/kinematics.svg" && grep -q '>Sheet 5<' "$d/kinematics-2.svg" \
    && grep -q '>Sheet 6<' "$d/kinetostatics.svg" && grep -q '>Sheet 7<' "$d/dynamics.svg" && grep -q '>Sheets 4<' "$d/dynamics.svg"; then pass
  else fail sheets-a4-numbers "exit $rc $(head -c 200 "$err")"; fi
fi
# the stand-in rsvg-convert (above) off PATH
PATH="$sheets_path"

# The plans of velocities and accelerations fill their panels on every paper: each plan's
# drawing (its rays, components, pole and images) is at least PERCENT % of its panel's smaller
# side across (its larger extent; 35 % on A3's and A4's second kinematics sheet, A2 and A1;
# the sheets of the checks above),
# every word of the plan (its labels and its notes "at the pole π: ...", "not drawn, shorter
# than 1 mm: ...") inside its panel, no note and no line of the values read off the plans
# smaller than 1.8 mm (ГОСТ 2.304's smallest).
# Must fail: a plan drawn at half its size, a note moved 80 mm right, past its panel's edge,
# the values read off the plans at 1.4 mm.
sheets_plans_fill() {  # PERCENT SVG...: "ok ..." or "differs: ..."
  run_py - "$root/tools" "$@" <<'PY'
import math, re, sys
sys.path.insert(0, sys.argv[1])
import xml.etree.ElementTree as ET
import svg_check as sc
least = float(sys.argv[2]) / 100
bad, seen, worst = [], 0, 1e9
read_heads = ("Values read off the plans", "Величины по планам")
for path in sys.argv[3:]:
    src = open(path, encoding="utf-8").read()
    sizes, _ = sc.style_sizes(src)
    panel, read_panel, smallest_read = None, None, 1e9
    for el in ET.fromstring(src).iter():
        if el.tag == sc.SVG_NS + "rect" and el.get("class") == "panel":
            panel = [float(el.get(k)) for k in ("x", "y", "width", "height")]
        if el.tag == sc.SVG_NS + "text" and "".join(el.itertext()) in read_heads:
            read_panel = panel
        if el.tag == sc.SVG_NS + "text" and read_panel is not None and el.get("class") == "num":
            x, y, w, h = read_panel
            if x <= float(el.get("x")) <= x + w and y <= float(el.get("y")) <= y + h:
                smallest_read = min(smallest_read, sc.text_size(el, sizes))
        if el.tag != sc.SVG_NS + "g" or el.get("class") not in ("velocity-plan", "acceleration-plan"):
            continue
        seen += 1
        x, y, w, h = panel
        pts = []
        for c in el.iter():
            tag = c.tag.replace(sc.SVG_NS, "")
            if tag == "line" and c.get("class") != "leader":
                pts += [(float(c.get("x1")), float(c.get("y1"))), (float(c.get("x2")), float(c.get("y2")))]
            elif tag == "polygon":
                v = [float(s) for s in re.split(r"[ ,]+", c.get("points").strip())]
                pts += list(zip(v[0::2], v[1::2]))
            elif tag == "circle":
                pts.append((float(c.get("cx")), float(c.get("cy"))))
            elif tag == "text":
                (x0, y0, x1, y1), text = sc.text_box(c, sizes)
                if x0 < x - 0.01 or x1 > x + w + 0.01 or y0 < y - 0.01 or y1 > y + h + 0.01:
                    bad.append(f"{path}: {text[:40]!r} leaves its panel ({x0:.2f} .. {x1:.2f} of {x:.2f} .. {x + w:.2f} mm)")
                if c.get("class") == "note" and sc.text_size(c, sizes) < 1.8 - 1e-9:
                    bad.append(f"{path}: note {text[:40]!r} at {sc.text_size(c, sizes)} mm")
        across = max(max(p[0] for p in pts) - min(p[0] for p in pts), max(p[1] for p in pts) - min(p[1] for p in pts))
        share = across / min(w, h)
        worst = min(worst, share)
        if share < least:
            bad.append(f"{path}: the {el.get('class')} is {across:.1f} mm across in its {w:.1f} x {h:.1f} mm panel "
                       f"({100 * share:.0f} %, expected {100 * least:.0f} % at the least)")
    if read_panel is None or smallest_read == 1e9:
        bad.append(f"{path}: no values read off the plans")
    elif smallest_read < 1.8 - 1e-9:
        bad.append(f"{path}: the values read off the plans at {smallest_read} mm (1.8 mm at the least)")
if seen == 0:
    bad.append("no plan found")
print("differs: " + "; ".join(bad[:6]) if bad else f"ok {seen} plans, the smallest {100 * worst:.0f} % of its panel")
PY
}
sheets_fill_svgs="$cli_tmp/sheets_a4_class3_en/kinematics-2.svg $cli_tmp/sheets_a4_pr3207/kinematics-2.svg"
sheets_fill_svgs="$sheets_fill_svgs $cli_tmp/sheets_A2_pr3207_flywheel_ru/kinematics.svg"
sheets_fill_svgs="$sheets_fill_svgs $cli_tmp/sheets_A3_pr3207_flywheel_en/kinematics-2.svg"
sheets_fill_svgs="$sheets_fill_svgs $cli_tmp/sheets_class3_en/kinematics.svg"
# (assur_pr3207_flywheel on A3: its acceleration plan's note "at the pole π: j16, ..." as wide
# as its panel, the most values read off; a few seconds, with --long)
if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
  dir="$cli_tmp/sheets_fill_assur_A3"
  rm -rf "$dir"
  run_ks sheets data/assur_pr3207_flywheel.nml -o "$dir" --paper A3
  [ "$rc" -eq 0 ] || fail sheets-plans-fill-run "exit $rc: $(head -c 300 "$err")"
  run_py "$sheets_check" labels --lines "$dir/kinematics.svg" "$dir/kinematics-2.svg" >"$cli_tmp/check.out" 2>&1 && pass \
    || fail sheets-plans-fill-assur-A3-legible "$(grep -v '^[0-9]* sheets' "$cli_tmp/check.out" | head -3)"
  sheets_fill_svgs="$sheets_fill_svgs $dir/kinematics-2.svg"
fi
verdict=$(sheets_plans_fill 35 $sheets_fill_svgs)
case "$verdict" in ok*) pass ;; *) fail sheets-plans-fill "$verdict" ;; esac
# must fail: the acceleration plan drawn at half its size about its pole; a note moved 80 mm
# right, past the panel's edge
svg="$cli_tmp/sheets_a4_class3_en/kinematics-2.svg"
run_py - "$svg" >"$cli_tmp/fill_bad.svg" <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
start = t.index('<g class="acceleration-plan"')
end = t.index("</g>", start)
px, py = (float(v) for v in re.search(r'data-pole="([-0-9.]+) ([-0-9.]+)"', t[start:]).groups())
half = lambda m, o: f"{o + 0.5 * (float(m) - o):.2f}"
def shrink(el):
    el = re.sub(r' (x1|x2|cx)="([-0-9.]+)"', lambda m: f' {m.group(1)}="{half(m.group(2), px)}"', el.group(0))
    el = re.sub(r' (y1|y2|cy)="([-0-9.]+)"', lambda m: f' {m.group(1)}="{half(m.group(2), py)}"', el)
    return re.sub(r'points="([^"]*)"', lambda m: 'points="' + " ".join(
        f"{half(a, px)},{half(b, py)}" for a, b in (p.split(",") for p in m.group(1).split())) + '"', el)
body = re.sub(r'<(?:line|circle|polygon) [^>]*>', shrink, t[start:end])
print(t[:start] + body + t[end:], end="")
PY
verdict=$(sheets_plans_fill 35 "$cli_tmp/fill_bad.svg")
case "$verdict" in "differs: "*"acceleration-plan is"*) pass ;; *) fail sheets-plans-fill-must-fail-size "a plan at half its size passed: $verdict" ;; esac
sed -E '/<g class="acceleration-plan"/,/<\/g>/ s/(<text x=")([0-9.]+)(" y="[0-9.]+" class="note")/\1\2X\3/' "$svg" \
  | run_py -c "import re, sys; print(re.sub(r'x=\"([0-9.]+)X\"', lambda m: f'x=\"{float(m.group(1)) + 80:.2f}\"', sys.stdin.read()), end='')" \
  >"$cli_tmp/fill_bad.svg"
verdict=$(sheets_plans_fill 35 "$cli_tmp/fill_bad.svg")
case "$verdict" in "differs: "*"leaves its panel"*) pass ;; *) fail sheets-plans-fill-must-fail-note "a note off its panel passed: $verdict" ;; esac
# must fail: the values read off the plans at 1.4 mm (as they were on one A3 sheet)
run_py - "$svg" >"$cli_tmp/fill_bad.svg" <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
start = t.index(">Values read off the plans<")
print(t[:start] + re.sub(r'class="num"( style="font-size: [0-9.]+px")?', 'class="num" style="font-size: 1.4px"', t[start:]), end="")
PY
verdict=$(sheets_plans_fill 35 "$cli_tmp/fill_bad.svg")
case "$verdict" in "differs: "*"values read off the plans at 1.4 mm"*) pass ;; *) fail sheets-plans-fill-must-fail-read "values read off at 1.4 mm passed: $verdict" ;; esac

# No file on a course sheet: no deck path (no "data/", no ".nml") anywhere in an SVG (its
# visible text, its <title> and <desc>, its attributes) or a DXF (its TEXT and its comments);
# and on a Russian sheet no Latin word of three or more letters in the visible text (SVG
# <text>, DXF TEXT) but these exceptions: the deck's own title (its `title = '...'`, the user's
# words), the program's name "kinetostat" and Roman numerals (a group's class, III); a
# sub- or superscript (l_AB) is a run of its own (these runs have no --set). Every offending text
# printed. The sheets of the checks above (A1: PR 3207's flywheel deck in both languages, the
# class-III deck in English, and here in Russian; A4, A3, A2 of PR 3207's flywheel deck and
# A4 of the class-III deck; with --long the six-bar's and the &assur PR 3207 flywheel decks,
# both languages).
sheets_no_file() {  # DECK LANG FILE...: "ok N texts" or the offending texts
  run_py - "$@" <<'PY'
import re, sys
import xml.etree.ElementTree as ET
deck, lang, paths = sys.argv[1], sys.argv[2], sys.argv[3:]
title = re.search(r"^\s*title\s*=\s*'([^']*)'", open(deck, encoding="utf-8").read(), re.M | re.I)
title = title.group(1) if title else None
bad, n = [], 0
def visible(path):
    src = open(path, encoding="utf-8").read()
    if path.endswith(".svg"):
        # a <text>'s runs apart (a sub- or superscript, l_AB, is a run of its own)
        runs = lambda el: [el.text or ""] + [r for c in el.iter() if c is not el for r in (c.text or "", c.tail or "")]
        return src, [runs(el) for el in ET.fromstring(src).iter("{http://www.w3.org/2000/svg}text")]
    lines = src.split("\n")
    texts, entity = [], None
    for i in range(0, len(lines) - 1, 2):
        code, value = lines[i].strip(), lines[i + 1]
        if code == "0":
            entity = value
        elif code == "1" and entity == "TEXT":
            texts.append([re.sub(r"\\U\+([0-9A-Fa-f]{4})", lambda m: chr(int(m.group(1), 16)), value)])
    return src, texts
for path in paths:
    src, texts = visible(path)
    n += len(texts)
    for what in ("data/", ".nml"):
        if what in src:
            where = ["".join(t) for t in texts if what in "".join(t)] or [l.strip() for l in src.split("\n") if what in l]
            bad.append(f"{path}: {what!r} in {where[0][:160]!r}")
    if lang != "ru":
        continue
    for t in texts:
        words = []
        for run in t:
            rest = run.replace(title, " ") if title else run
            rest = re.sub(r"\bkinetostat\b", " ", rest)
            words += [w for w in re.findall(r"[A-Za-z]{3,}", rest) if not re.fullmatch(r"[IVX]+", w)]
        if words:
            bad.append(f"{path}: Latin {', '.join(words)} in {''.join(t)[:160]!r}")
if not n:
    bad.append("no text read")
print("differs: " + "\n  ".join(bad[:40]) if bad else f"ok {n} texts")
PY
}
dir="$cli_tmp/sheets_class3_ru"
if [ ! -s "$dir/kinematics.svg" ]; then
  PATH="$(pdf_stand_in):$PATH" run_ks sheets data/class3.nml -o "$dir" --lang ru --student "Иванов И.И." --group МТ-301 --variant 7
  [ "$rc" -eq 0 ] || fail sheets-no-file-run "exit $rc: $(head -c 300 "$err")"
fi
for spec in pr3207_flywheel:en:sheets_pr3207_flywheel_en pr3207_flywheel:ru:sheets_pr3207_flywheel_ru \
  class3:en:sheets_class3_en class3:ru:sheets_class3_ru class3:en:sheets_a4_class3_en pr3207_flywheel:ru:sheets_a4_pr3207 \
  pr3207_flywheel:en:sheets_A3_pr3207_flywheel_en pr3207_flywheel:ru:sheets_A2_pr3207_flywheel_ru \
  sixbar_flywheel:en:sheets_sixbar_flywheel_en sixbar_flywheel:ru:sheets_sixbar_flywheel_ru \
  assur_pr3207_flywheel:en:sheets_assur_pr3207_flywheel_en assur_pr3207_flywheel:ru:sheets_assur_pr3207_flywheel_ru; do
  IFS=: read -r deck lang d <<<"$spec"
  [ -d "$cli_tmp/$d" ] || continue
  verdict=$(sheets_no_file "data/$deck.nml" "$lang" "$cli_tmp/$d"/*.svg "$cli_tmp/$d"/*.dxf)
  case "$verdict" in ok*) pass ;; *) fail "sheets-no-file-$d" "$verdict" ;; esac
done
# the design kinds' sheets made by kinetostat sheets name no file either (in Russian: the
# gear pair, the planetary train, the cam)
for deck in gear_geometry_shift planetary_synthesis cam_profile_roller; do
  d="sheets_design_ru_$deck"
  PATH="$(pdf_stand_in):$PATH" run_ks sheets "data/$deck.nml" -o "$cli_tmp/$d" --lang ru
  [ "$rc" -eq 0 ] || { fail "sheets-no-file-$d" "exit $rc: $(head -c 300 "$err")"; continue; }
  verdict=$(sheets_no_file "data/$deck.nml" ru "$cli_tmp/$d"/*.svg "$cli_tmp/$d"/*.dxf)
  case "$verdict" in ok*) pass ;; *) fail "sheets-no-file-$d" "$verdict" ;; esac
done
# must fail: a path in a DXF's TEXT, an English word on a Russian sheet
sed 's|>Масштаб<|>Масштаб data/x.nml scale<|' "$cli_tmp/sheets_class3_ru/kinematics.svg" >"$cli_tmp/no_file_bad.svg"
verdict=$(sheets_no_file data/class3.nml ru "$cli_tmp/no_file_bad.svg")
case "$verdict" in *"'data/' in 'Масштаб data/x.nml scale'"*"Latin data, nml, scale in"*) pass ;; *) fail sheets-no-file-must-fail "a path and English words passed: $verdict" ;; esac

# Legible on A4 and A3: no text of a course sheet smaller than 1.8 mm (the project's least
# size, ГОСТ 2.304's smallest; a sub- or superscript's run aside: its text's size counts) -
# a value's line too long for its column broken after the value, a chart's heading with its
# scales on two lines, the plan of positions' foot on two; and A3's second kinematics sheet
# uses the strip left of the title block (a panel reaching 45 mm down beside it: the values
# read off the plans).
# Every text too small printed.
sheets_least_text() {  # SVG...: "ok SMALLEST" or the texts too small
  run_py - "$root/tools" "$@" <<'PY'
import re, sys
sys.path.insert(0, sys.argv[1])
import xml.etree.ElementTree as ET
import svg_check as sc
bad, least = [], 1e9
for path in sys.argv[2:]:
    src = open(path, encoding="utf-8").read()
    sizes, _ = sc.style_sizes(src)
    for el in ET.fromstring(src).iter(sc.SVG_NS + "text"):
        size = sc.text_size(el, sizes)
        least = min(least, size)
        if size < 1.8 - 1e-9:
            bad.append(f"{path}: {size} mm {''.join(el.itertext())[:100]!r}")
print("differs: " + "\n  ".join(bad[:20]) if bad else f"ok {least}")
PY
}
for d in sheets_a4_class3_en sheets_a4_pr3207 sheets_A3_pr3207_flywheel_en sheets_a4_class3_ru sheets_a4_sixbar_flywheel_en \
  sheets_a4_sixbar_flywheel_ru sheets_a4_assur_pr3207_flywheel_en sheets_a4_assur_pr3207_flywheel_ru; do
  [ -d "$cli_tmp/$d" ] || continue
  verdict=$(sheets_least_text "$cli_tmp/$d"/*.svg)
  case "$verdict" in ok*) pass ;; *) fail "sheets-least-text-$d" "$verdict" ;; esac
done
verdict=$(run_py - "$cli_tmp/sheets_A3_pr3207_flywheel_en/kinematics-2.svg" <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
bx, by = (float(v) for v in re.search(r'<rect x="([0-9.]+)" y="([0-9.]+)" width="185.00" height="55.00"', t).groups())
beside = [(x, y, w, h) for x, y, w, h in ((float(a) for a in m) for m in re.findall(
    r'<rect x="([0-9.]+)" y="([0-9.]+)" width="([0-9.]+)" height="([0-9.]+)" class="panel"', t)) if y + h >= by + 45 and x + w <= bx]
print(f"ok {beside[0][2]:.0f} x {beside[0][3]:.0f} mm" if beside else f"no panel left of the title block at x {bx} y {by}")
PY
)
case "$verdict" in ok*) pass ;; *) fail sheets-A3-strip "$verdict" ;; esac
