# Legible sheets. On every bundled deck's --format svg sheet (the design kinds' too) and, for
# every linkage deck, its
# --format svg --at K sheets at the first, second, middle and last steps, in English and
# Russian: no text label leaves the sheet, none overlaps another and none lies over a drawn
# line (tools/svg_check.py labels --lines: typeset boxes, every stroke as a band of its width;
# leader lines counted and shown); the symbols typeset (tools/svg_check.py notation: no _ or ^
# markup; on a Russian sheet no Latin word). The plans sheets (--format plans --at K, first,
# middle, last step) the same. No English word on a
# --lang ru sheet or in a --lang ru table (tools/svg_check.py english: a word list). Every
# check can fail. The default suite draws the four steps in both languages for PR 3207 and the
# six-bar and, for the other linkage decks in turn, the first step in English or the middle one
# in Russian (the heavy decks of lib.sh, the &linkage twins of pr3207_flywheel and
# assur_engine_flywheel, none); tools/test --long every step in both. The English run sheets, the Russian tables and
# the CSV that gives the step count are read from data/expected, not run again: the suite's
# golden check proves them the binary's output byte for byte.
svg_check="$root/tools/svg_check.py"
legible_dir="$cli_tmp/legible"
mkdir -p "$legible_dir"
model_sheets=(); model_ru=(); plans_sheets=(); ru_sheets=()

legible_turn=0
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  [ "$name" = assur_toggle ] && continue
  legible_turn=$((1 - legible_turn))
  csv="data/expected/$name.csv"  # the golden where there is one (lib.sh from_golden)
  [ -f "$csv" ] || { run_ks "$deck" --format csv; csv="$out"; }
  steps=$(($(wc -l <"$csv") - 1))
  for lang in en ru; do
    # the slowest sheets (0.4-2.3 s each in the debug build) in Russian with --long only
    case "${KINETOSTAT_LONG:-0}:$lang:$name" in
      0:ru:sixbar_flywheel | 0:ru:assur_pr3207_flywheel | 0:ru:friction_fourbar_resist | 0:ru:linkage_pr3207_flywheel | \
      0:ru:linkage_engine_flywheel) ;;
      *)
        # (the English sheet is its golden, read where it is: lib.sh from_golden)
        sheet="$legible_dir/$name.$lang.svg"
        if [ "$lang" = en ] && [ -f "data/expected/$name.svg" ]; then sheet="data/expected/$name.svg"; rc=0
        else run_ks_into "$sheet" "$deck" --format svg --lang "$lang"; fi
        if [ "$rc" -ne 0 ]; then fail "legible-runs-$name-$lang" "rc=$rc: $(head -c 300 "$err")"; continue; fi
        model_sheets+=("$sheet")
        [ "$lang" = ru ] && model_ru+=("$sheet") && ru_sheets+=("$sheet") ;;
    esac
    # no step drawn: gear stages, cams, and the design kinds (their own sheets)
    case "$name" in gears_*|cam_*|gear_geometry_*|planetary_synthesis*) ;; *)
      middle=$(((steps + 1) / 2))
      for k in $(printf '%s\n' 1 2 "$middle" "$steps" | awk '$1 >= 1' | sort -un); do
        [ "$k" -gt "$steps" ] && continue
        if [ "${KINETOSTAT_LONG:-0}" != 1 ] && [ "$name" != pr3207 ] && [ "$name" != sixbar ]; then
          # one of the two in turn along the listed decks (each language on every other deck)
          case "$lang:$k:$legible_turn" in en:1:0 | "ru:$middle:1") ;; *) continue ;; esac
          # a heavy deck's (lib.sh) --at and plans sheets with --long: its twin's are drawn
          heavy_deck "$name" && continue
        fi
        run_ks_into "$legible_dir/$name.at$k.$lang.svg" "$deck" --format svg --at "$k" --lang "$lang"
        if [ "$rc" -ne 0 ]; then fail "legible-at-runs-$name-$k-$lang" "rc=$rc: $(head -c 300 "$err")"; continue; fi
        model_sheets+=("$legible_dir/$name.at$k.$lang.svg")
        [ "$lang" = ru ] && model_ru+=("$legible_dir/$name.at$k.$lang.svg") && ru_sheets+=("$legible_dir/$name.at$k.$lang.svg")
        [ "$k" = 2 ] && continue
        run_ks_into "$legible_dir/$name.plans$k.$lang.svg" "$deck" --format plans --at "$k" --lang "$lang"
        if [ "$rc" -ne 0 ]; then fail "legible-plans-runs-$name-$k-$lang" "rc=$rc: $(head -c 300 "$err")"; continue; fi
        plans_sheets+=("$legible_dir/$name.plans$k.$lang.svg")
        model_sheets+=("$legible_dir/$name.plans$k.$lang.svg")
        [ "$lang" = ru ] && model_ru+=("$legible_dir/$name.plans$k.$lang.svg") && ru_sheets+=("$legible_dir/$name.plans$k.$lang.svg")
      done ;;
    esac
    if [ "$lang" = ru ]; then
      if [ -f "data/expected/$name.ru.table" ]; then ru_sheets+=("data/expected/$name.ru.table")
      else run_ks_into "$legible_dir/$name.ru.table" "$deck" --lang ru; ru_sheets+=("$legible_dir/$name.ru.table"); fi
    fi
  done
done
# the sheets on the drawing model: off every label, every line and the sheet's edge; the
# notation; no English word on a Russian sheet or table (one Python process, which parses a
# sheet once for all its checks: check_batch, svg_check's read_sheet)
check_job svg_check legible-labels-lines labels --lines "${model_sheets[@]}"
check_job svg_check legible-notation notation en "${model_sheets[@]}"
check_job svg_check legible-notation-ru notation ru "${model_ru[@]}"
check_job svg_check legible-labels-plans labels "${plans_sheets[@]}"
check_job svg_check legible-russian english "${ru_sheets[@]}"
check_batch svg_check
echo "legible: $(grep -E '^[0-9]+ sheets, [0-9]+ leader lines' "$cli_tmp/batch.svg_check/legible-labels-lines.out")"

# the overlap check can fail: a second label written over the first one of a sheet
sheet="$legible_dir/pr3207.at1.en.svg"
first_text=$(grep -m1 -o '<text x="[^"]*" y="[^"]*" class="label"[^>]*>[^<]*</text>' "$sheet")
sed "s|</svg>|$first_text</svg>|" "$sheet" >"$cli_tmp/overlap.svg"
run_py "$svg_check" labels "$cli_tmp/overlap.svg" >"$cli_tmp/check.out" 2>&1
grep -q "overlaps" "$cli_tmp/check.out" && pass \
  || fail legible-labels-can-fail "a label written twice at one place was not reported: $(head -3 "$cli_tmp/check.out")"
# ... and the line check: a label written on the middle of the sheet's first drawn line
read -r x1 y1 x2 y2 < <(grep -m1 -o '<line x1="[^"]*" y1="[^"]*" x2="[^"]*" y2="[^"]*" class="link\|<line x1="[^"]*" y1="[^"]*" x2="[^"]*" y2="[^"]*"' \
  "$legible_dir/sixbar.at1.en.svg" | grep -o '"[-0-9.]*"' | tr -d '"' | tr '\n' ' ')
awk -v x="$(run_py -c "print(($x1 + $x2) / 2)")" -v y="$(run_py -c "print(($y1 + $y2) / 2)")" \
  '{ sub("</svg>", "<text x=\"" x "\" y=\"" y "\" class=\"num\" text-anchor=\"middle\">F21</text></svg>"); print }' \
  "$legible_dir/sixbar.at1.en.svg" >"$cli_tmp/online.svg"
if run_py "$svg_check" labels --lines "$cli_tmp/online.svg" >"$cli_tmp/check.out" 2>&1; then
  fail legible-lines-can-fail "a label written over a line was accepted"
else grep -q "lies over a line" "$cli_tmp/check.out" && pass || fail legible-lines-can-fail "$(head -3 "$cli_tmp/check.out")"; fi
# ... and the notation checks: markup on an English sheet, a Latin word on a Russian one
sed 's|</svg>|<text x="30" y="30" class="num">a_CB^n</text></svg>|' "$legible_dir/sixbar.at1.en.svg" >"$cli_tmp/markup.svg"
run_py "$svg_check" notation en "$cli_tmp/markup.svg" >"$cli_tmp/check.out" 2>&1
grep -q "markup in 'a_CB^n'" "$cli_tmp/check.out" && pass || fail legible-notation-can-fail "a_CB^n accepted"
sed 's|</svg>|<text x="30" y="30" class="num">MPhi3 = 615 Н·м</text></svg>|' "$legible_dir/sixbar.at1.ru.svg" >"$cli_tmp/latin.svg"
run_py "$svg_check" notation ru "$cli_tmp/latin.svg" >"$cli_tmp/check.out" 2>&1
grep -q "Latin 'MPhi3'" "$cli_tmp/check.out" && pass || fail legible-notation-ru-can-fail "MPhi3 accepted on a Russian sheet"
# ... and so can the word check: an English legend word on a Russian sheet
sed 's|>реакция<|>pair force<|' "$legible_dir/pr3207.at1.ru.svg" >"$cli_tmp/english.svg"
if cmp -s "$cli_tmp/english.svg" "$legible_dir/pr3207.at1.ru.svg"; then
  fail legible-russian-can-fail "the perturbation did not change the sheet"
else
  run_py "$svg_check" english "$cli_tmp/english.svg" >"$cli_tmp/check.out" 2>&1
  grep -qE "english\.svg:[0-9]+: '(pair|force)' in" "$cli_tmp/check.out" && pass \
    || fail legible-russian-can-fail "an English word on a Russian sheet was not reported: $(head -3 "$cli_tmp/check.out")"
fi
# a Russian sheet's units and symbols: Н, Н·м, град; Φ and M_и typeset
grep -q ' Н под углом [0-9.]* град<' "$legible_dir/pr3207.at1.ru.svg" && grep -q 'Н·м<' "$legible_dir/pr3207.at1.ru.svg" \
  && grep -q '>Φ<tspan dy="[0-9.]*" font-size="[0-9.]*">3</tspan>' "$legible_dir/pr3207.at2.ru.svg" \
  && grep -q '>M<tspan dy="[0-9.]*" font-size="[0-9.]*">и3</tspan>' "$legible_dir/pr3207.at2.ru.svg" \
  && pass || fail legible-russian-units "no 'Н под углом ... град', 'Н·м', Φ3 or M_и3 on the Russian --at sheet"
# the axes of the mechanism's frame are drawn and named
grep -q 'style="font-style: italic">x</text>' "$legible_dir/sixbar.at1.en.svg" \
  && grep -q 'style="font-style: italic">y</text>' "$legible_dir/sixbar.at1.en.svg" \
  && pass || fail legible-axes "no x and y axis labels on the --at sheet"
# standard formats with the ГОСТ frame: every sheet on the model is an ISO size, framed
run_py - "${model_sheets[@]}" <<'PY' >"$cli_tmp/check.out" 2>&1 && pass || fail legible-formats "$(head -5 "$cli_tmp/check.out")"
import re, sys
iso = {(210, 297), (297, 420), (420, 594), (594, 841)}
for path in sys.argv[1:]:
    text = open(path, encoding="utf-8").read()
    w, h = (float(v) for v in re.search(r'width="([0-9.]+)mm" height="([0-9.]+)mm"', text).groups())
    assert (min(w, h), max(w, h)) in iso, f"{path}: {w} x {h} mm is not an ISO size"
    frame = f'<rect x="20.00" y="5.00" width="{w - 25:.2f}" height="{h - 10:.2f}" class="border"/>'
    assert frame in text, f"{path}: no frame {frame}"
print(len(sys.argv) - 1, "sheets on ISO formats with the frame")
PY

# the student's header: the 1991 line on the legacy table (date, time, surname, group,
# variant) and a title block on every sheet, in the sheet's language, overlapping nothing
run_ks data/sixbar.nml --lang ru --student "Иванов И.И." --group "МТ-301" --variant 7
head -1 "$out" | grep -Eq '^ ДАТА [0-9]{2}\.[0-9]{2}\.[0-9]{4}  ВРЕМЯ [0-9]{2}:[0-9]{2}  ФАМИЛИЯ Иванов И\.И\.  ГРУППА МТ-301  ВАРИАНТ 7$' \
  && sed -n 2p "$out" | grep -q '^ KINETOSTAT  T.FTN' && pass || fail legible-student-table "$(head -2 "$out")"
run_ks data/sixbar.nml --student Ivanov --group MT-301 --variant 7
head -1 "$out" | grep -Eq '^ DATE [0-9.]{10}  TIME [0-9:]{5}  NAME Ivanov  GROUP MT-301  VARIANT 7$' \
  && pass || fail legible-student-table-en "$(head -1 "$out")"
# the title block is ГОСТ 2.104's form 1 (185 x 55 mm): its grid's words in the sheet's
# language, the student in Разраб./Drawn, group and variant in the organisation field; no
# deck path in the designation; the drawing's scale in Масштаб on the --at sheet
for args in "--format svg" "--format svg --at 2" "--format plans --at 2"; do
  # shellcheck disable=SC2086  # args is a word list
  run_ks data/sixbar.nml $args --lang ru --student "Иванов И.И." --group "МТ-301" --variant 7
  cp "$out" "$cli_tmp/student.svg"
  missing=""
  for w in Изм. Лист '№ докум.' Подп. Дата Разраб. Пров. Т.контр. Н.контр. Утв. Лит. Масса Масштаб \
    'Лист 1' 'Листов 1' 'Иванов И.И.' 'группа МТ-301' 'вариант 7'; do
    grep -q ">$w<" "$cli_tmp/student.svg" || missing="$missing '$w'"
  done
  grep -q '<rect x="[0-9.]*" y="[0-9.]*" width="185.00" height="55.00"' "$cli_tmp/student.svg" || missing="$missing 185x55-frame"
  grep -q '>МТ-301.7' "$cli_tmp/student.svg" && missing="$missing deck-in-designation"
  [ "$args" = "--format svg --at 2" ] && ! grep -q '>1:[0-9.]*<' "$cli_tmp/student.svg" && missing="$missing scale"
  [ -z "$missing" ] \
    && run_py "$svg_check" labels "$cli_tmp/student.svg" >"$cli_tmp/check.out" 2>&1 \
    && run_py "$svg_check" english "$cli_tmp/student.svg" >>"$cli_tmp/check.out" 2>&1 \
    && pass || fail "legible-student-sheet-$args" "missing:$missing $(head -5 "$cli_tmp/check.out")"
  # shellcheck disable=SC2086  # args is a word list
  run_ks data/sixbar.nml $args --student Ivanov --group MT-301 --variant 7
  missing=""
  for w in Rev. Sheet 'Doc. No.' Sign. Date Drawn Checked 'Tech. ctrl' 'Std. ctrl' Approved Lit. Mass Scale \
    'Sheets 1' Ivanov 'group MT-301' 'variant 7'; do
    grep -q ">$w<" "$out" || missing="$missing '$w'"
  done
  cp "$out" "$cli_tmp/student_en.svg"
  [ -z "$missing" ] && run_py "$svg_check" labels "$cli_tmp/student_en.svg" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "legible-student-sheet-en-$args" "missing:$missing $(head -5 "$cli_tmp/check.out")"
done
# a long drawing name fits its field (smaller, or on two lines), not cut
run_ks data/pr3207_flywheel.nml --format plans --at 120 --student Ivanov --group MT-301 --variant 7
grep -q '>Plans of velocities, accelerations, forces<' "$out" && pass \
  || fail legible-student-name-whole "$(grep -o '>Plans of[^<]*<' "$out")"
