# Legible sheets: on every bundled deck's --format svg sheet and its --format svg --at K and
# --format plans --at K sheets at three steps (first, middle, last), in English and Russian,
# no text label leaves the sheet and no two
# overlap (tools/svg_check.py labels: box width = 0.6 x font size x characters, height = font
# size, placed by text-anchor); no English word on a --lang ru sheet or in a --lang ru table
# (tools/svg_check.py english: a word list); both checks can fail.
svg_check="$root/tools/svg_check.py"
legible_dir="$cli_tmp/legible"
mkdir -p "$legible_dir"

for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  [ "$name" = assur_toggle ] && continue
  run_ks "$deck" --format csv
  steps=$(($(wc -l <"$out") - 1))
  # the design kinds draw no sheet of forces (--format svg is refused): their Russian table only
  case "$name" in gear_geometry_*|planetary_synthesis*|cam_profile_*)
    run_ks "$deck" --lang ru; cp "$out" "$legible_dir/$name.ru.table"
    python3 "$svg_check" english "$legible_dir/$name.ru.table" >"$cli_tmp/check.out" 2>&1 \
      && pass || fail "legible-russian-$name" "$(head -20 "$cli_tmp/check.out")"
    continue ;;
  esac
  for lang in en ru; do
    sheets=()
    run_ks "$deck" --format svg --lang "$lang"
    if [ "$rc" -ne 0 ]; then fail "legible-runs-$name-$lang" "rc=$rc: $(head -c 300 "$err")"; continue; fi
    cp "$out" "$legible_dir/$name.$lang.svg"; sheets+=("$legible_dir/$name.$lang.svg")
    case "$name" in gears_*|cam_*) ;; *)
      for k in 1 $(((steps + 1) / 2)) "$steps"; do
        run_ks "$deck" --format svg --at "$k" --lang "$lang"
        if [ "$rc" -ne 0 ]; then fail "legible-at-runs-$name-$k-$lang" "rc=$rc: $(head -c 300 "$err")"; continue; fi
        cp "$out" "$legible_dir/$name.at$k.$lang.svg"; sheets+=("$legible_dir/$name.at$k.$lang.svg")
        run_ks "$deck" --format plans --at "$k" --lang "$lang"
        if [ "$rc" -ne 0 ]; then fail "legible-plans-runs-$name-$k-$lang" "rc=$rc: $(head -c 300 "$err")"; continue; fi
        cp "$out" "$legible_dir/$name.plans$k.$lang.svg"; sheets+=("$legible_dir/$name.plans$k.$lang.svg")
      done ;;
    esac
    python3 "$svg_check" labels "${sheets[@]}" >"$cli_tmp/check.out" 2>&1 \
      && pass || fail "legible-labels-$name-$lang" "$(head -20 "$cli_tmp/check.out")"
    if [ "$lang" = ru ]; then
      run_ks "$deck" --lang ru; cp "$out" "$legible_dir/$name.ru.table"
      python3 "$svg_check" english "${sheets[@]}" "$legible_dir/$name.ru.table" >"$cli_tmp/check.out" 2>&1 \
        && pass || fail "legible-russian-$name" "$(head -20 "$cli_tmp/check.out")"
    fi
  done
done

# the overlap check can fail: a second label written over the first one of a sheet
sheet="$legible_dir/pr3207.at1.en.svg"
first_text=$(grep -m1 -o '<text x="[^"]*" y="[^"]*" class="label"[^>]*>[^<]*</text>' "$sheet")
sed "s|</svg>|$first_text</svg>|" "$sheet" >"$cli_tmp/overlap.svg"
python3 "$svg_check" labels "$cli_tmp/overlap.svg" >/dev/null 2>&1 \
  && fail legible-labels-can-fail "a label written twice at one place was accepted" || pass
# ... and so can the word check: an English legend word on a Russian sheet
sed 's|>реакция<|>pair force<|' "$legible_dir/pr3207.at1.ru.svg" >"$cli_tmp/english.svg"
if cmp -s "$cli_tmp/english.svg" "$legible_dir/pr3207.at1.ru.svg"; then
  fail legible-russian-can-fail "the perturbation did not change the sheet"
elif python3 "$svg_check" english "$cli_tmp/english.svg" >/dev/null 2>&1; then
  fail legible-russian-can-fail "an English word on a Russian sheet was accepted"
else pass; fi
# a Russian sheet's units: Н, Н·м, град
grep -q ' Н под углом [0-9.]* град<' "$legible_dir/pr3207.at1.ru.svg" && grep -q 'Н·м<' "$legible_dir/pr3207.at1.ru.svg" \
  && pass || fail legible-russian-units "no 'Н под углом ... град' or 'Н·м' on the Russian --at sheet"
# the axes of the mechanism's frame are drawn and named
grep -q 'font-style="italic" text-anchor="middle">x</text>' "$legible_dir/sixbar.at1.en.svg" \
  && grep -q 'font-style="italic" text-anchor="middle">y</text>' "$legible_dir/sixbar.at1.en.svg" \
  && pass || fail legible-axes "no x and y axis labels on the --at sheet"

# the student's header: the 1991 line on the legacy table (date, time, surname, group,
# variant) and a title block on every sheet, in the sheet's language, overlapping nothing
run_ks data/sixbar.nml --lang ru --student "Иванов И.И." --group "МТ-301" --variant 7
head -1 "$out" | grep -Eq '^ ДАТА [0-9]{2}\.[0-9]{2}\.[0-9]{4}  ВРЕМЯ [0-9]{2}:[0-9]{2}  ФАМИЛИЯ Иванов И\.И\.  ГРУППА МТ-301  ВАРИАНТ 7$' \
  && sed -n 2p "$out" | grep -q '^ KINETOSTAT  T.FTN' && pass || fail legible-student-table "$(head -2 "$out")"
run_ks data/sixbar.nml --student Ivanov --group MT-301 --variant 7
head -1 "$out" | grep -Eq '^ DATE [0-9.]{10}  TIME [0-9:]{5}  NAME Ivanov  GROUP MT-301  VARIANT 7$' \
  && pass || fail legible-student-table-en "$(head -1 "$out")"
# the title block is ГОСТ 2.104's form 1 (185 x 55 mm): its grid's words in the sheet's
# language, the student in Разраб./Drawn, group and variant in the organisation field
for args in "--format svg" "--format svg --at 2" "--format plans --at 2"; do
  # shellcheck disable=SC2086  # args is a word list
  run_ks data/sixbar.nml $args --lang ru --student "Иванов И.И." --group "МТ-301" --variant 7
  cp "$out" "$cli_tmp/student.svg"
  missing=""
  for w in Изм. Лист '№ докум.' Подп. Дата Разраб. Пров. Т.контр. Н.контр. Утв. Лит. Масса Масштаб \
    'Лист 1' 'Листов 1' 'Иванов И.И.' 'группа МТ-301' 'вариант 7'; do
    grep -q ">$w<" "$cli_tmp/student.svg" || missing="$missing '$w'"
  done
  grep -q '<rect x="20.00" y="[0-9.]*" width="185.00" height="55.00"' "$cli_tmp/student.svg" || missing="$missing 185x55-frame"
  [ -z "$missing" ] \
    && python3 "$svg_check" labels "$cli_tmp/student.svg" >"$cli_tmp/check.out" 2>&1 \
    && python3 "$svg_check" english "$cli_tmp/student.svg" >>"$cli_tmp/check.out" 2>&1 \
    && pass || fail "legible-student-sheet-$args" "missing:$missing $(head -5 "$cli_tmp/check.out")"
  # shellcheck disable=SC2086  # args is a word list
  run_ks data/sixbar.nml $args --student Ivanov --group MT-301 --variant 7
  missing=""
  for w in Rev. Sheet 'Doc. No.' Sign. Date Drawn Checked 'Tech. ctrl' 'Std. ctrl' Approved Lit. Mass Scale \
    'Sheets 1' Ivanov 'group MT-301' 'variant 7'; do
    grep -q ">$w<" "$out" || missing="$missing '$w'"
  done
  cp "$out" "$cli_tmp/student_en.svg"
  [ -z "$missing" ] && python3 "$svg_check" labels "$cli_tmp/student_en.svg" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "legible-student-sheet-en-$args" "missing:$missing $(head -5 "$cli_tmp/check.out")"
done
# without the options nothing changes: the goldens hold (tools/test compares them)
