# Strings a user gives, in and out (sourced by tools/test with test/cli/lib.sh): every output
# stays valid with hostile strings in the deck path, the title, --student/--group/--variant,
# the joints' names and the --set text (tools/output_check.py: XML, JSON, CSV fields per line,
# DXF group-code pairs, no injected table line, no raw byte that should have been escaped);
# decks in CP1251 decoded, other encodings refused; texts counted in characters; nothing after
# the group's '/'; the capacities of docs/cli.md enforced with their limits.
output_check="$root/tools/output_check.py"
strings_dir="$cli_tmp/strings"
rm -rf "$strings_dir"; mkdir -p "$strings_dir"

# check_output NAME FORMAT FILE [--forbid ...]: FILE passes output_check.py FORMAT (and xmllint
# for xml).
check_output() {
  local name="$1" format="$2" file="$3"; shift 3
  if ! run_py "$output_check" "$format" "$file" "$@" >"$strings_dir/check.out" 2>&1; then
    fail "$name" "$(head -8 "$strings_dir/check.out")"; return
  fi
  if [ "$format" = xml ] && ! xmllint --noout "$file" 2>"$strings_dir/xmllint.err"; then
    fail "$name" "xmllint: $(head -3 "$strings_dir/xmllint.err")"; return
  fi
  pass
}

# with_title DECK TITLE OUT: DECK with its title line made "  title = 'TITLE'" (any bytes).
with_title() {
  run_py -c '
import os, re, sys
text = open(sys.argv[1], "rb").read()
title = os.fsencode(sys.argv[2])
open(sys.argv[3], "wb").write(re.sub(rb"title *=[^\n]*", lambda m: b"title = \x27" + title + b"\x27", text, count=1))
' "$1" "$2" "$3"
}

# --- hostile strings: a directory whose name holds quotes, markup, a CDATA end, separators,
# a newline with a line that looks like a DXF group code and one starting INJECTED, control
# bytes, 0xFF; a title with the same (but newlines) plus %%d, ^J, '/', '!' and Cyrillic; the
# student fields with newlines and 0xFF
hostile_dir="$strings_dir/x\",\"injected\":true,\"y\":\"<b>&]]>,\"q"$'\x01\t\n  0\nEOF\nINJECTED\xff'"é %%d ^J"
mkdir -p "$hostile_dir"
hostile_title='x","injected":true,"y":"<b>&amp;]]>,q'$'\x01\t''%%d ^J 0 EOF Шарнир a/b ! c & d'
student=$'Иванов"<b>&]]>,\nINJECTED\x01\xff'
group=$'ИУ7-42,"\n  0\nEOF'
variant=$'3\xd0'
for base in assur_fourbar linkage_fourbar; do
  deck="$hostile_dir/$base.nml"
  with_title "data/$base.nml" "$hostile_title" "$deck"
  grep -q 'Шарнир' "$deck" || { fail "strings-$base-deck" "the title was not replaced"; continue; }
  for spec in "table:table:" "table-ru:table:--lang ru" "csv:csv:--format csv" "json:json:--format json" \
              "svg:xml:--format svg" "summary:csv:--format summary" "svg-at:xml:--format svg --at 3" \
              "plans:xml:--format plans --at 3" "plans-json:json:--format json --at 3 --plans" "dxf:dxf:--format dxf --at 3"; do
    label=${spec%%:*}; rest=${spec#*:}; format=${rest%%:*}; options=${rest#*:}
    # shellcheck disable=SC2086
    run_ks "$deck" $options --student "$student" --group "$group" --variant "$variant"
    if [ "$rc" -ne 0 ]; then fail "strings-$base-$label" "exit $rc: $(head -c 300 "$err")"; continue; fi
    forbid=(--forbid-hex ff)
    [ "$format" = xml ] && forbid+=(--forbid "<b>")
    check_output "strings-$base-$label" "$format" "$out" "${forbid[@]}"
  done
done
# the JSON keeps the strings as text: the title and the path are there, escaped, not added keys
run_ks "$hostile_dir/linkage_fourbar.nml" --format json --at 3 --plans
run_py - "$out" <<'PY' && pass || fail strings-plans-json-deck "the deck path is not the JSON's text"
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
assert d["deck"].endswith('injected":true,"y":"<b>&]]>,"q\x01\t\n  0\nEOF\nINJECTED\u00ffé %%d ^J/linkage_fourbar.nml'), d["deck"]
PY
run_ks "$hostile_dir/assur_fourbar.nml" --format json
run_py - "$out" <<'PY' && pass || fail strings-json-title "the title is not the JSON's text"
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
assert d["deck_title"] == 'x","injected":true,"y":"<b>&amp;]]>,q\x01\t%%d ^J 0 EOF Шарнир a/b ! c & d', d["deck_title"]
PY
# the table's lines: DECK, TITLE and the student line each one line, escaped as the messages
# write them (\n, \t, \xNN)
run_ks "$hostile_dir/assur_fourbar.nml" --student "$student" --group "$group" --variant "$variant"
run_py - "$out" "$hostile_dir/assur_fourbar.nml" "$student" "$group" "$variant" <<'PY' && pass || fail strings-table-lines "see above"
import os, sys
def shown(b):
    out, i = [], 0
    text = b.decode("utf-8", "surrogateescape")
    for ch in text:
        c = ord(ch)
        if 0xDC80 <= c <= 0xDCFF:
            out.append("\\x%02X" % (c - 0xDC00))
        elif ch in "\n\r\t":
            out.append({"\n": "\\n", "\r": "\\r", "\t": "\\t"}[ch])
        elif c < 32 or c == 127:
            out.append("\\x%02X" % c)
        else:
            out.append(ch)
    return "".join(out)
arg = [os.fsencode(a) for a in sys.argv[2:]]
lines = open(sys.argv[1], encoding="utf-8").read().split("\n")
want = [" DECK: " + shown(arg[0]),
        " TITLE: " + shown('x","injected":true,"y":"<b>&amp;]]>,q\x01\t%%d ^J 0 EOF Шарнир a/b ! c & d'.encode()),
        "  NAME " + shown(arg[1]) + "  GROUP " + shown(arg[2]) + "  VARIANT " + shown(arg[3])]
missing = [w for w in want if not any(l == w or (w.startswith("  NAME") and l.startswith(" DATE") and l.endswith(w))
                                      for l in lines)]
if missing:
    print("missing lines:", missing, "\ntable head:", lines[:4])
    sys.exit(1)
PY
# structure: DECK and TITLE lines escaped
run_ks structure "$hostile_dir/linkage_fourbar.nml"
[ "$rc" -eq 0 ] && check_output strings-structure table "$out" --forbid-hex ff || fail strings-structure "exit $rc: $(head -c 300 "$err")"
# --set text: in the table's echo, the JSON's overrides and the summary's and a sweep's columns
set_title=$'title=\'a,"b" <&>]]> 0 EOF\x01\t\''
for spec in "table:table:" "json:json:--format json" "summary:csv:--format summary" "svg:xml:--format svg"; do
  label=${spec%%:*}; rest=${spec#*:}; format=${rest%%:*}; options=${rest#*:}
  # shellcheck disable=SC2086
  run_ks data/assur_fourbar.nml --set "$set_title" $options
  if [ "$rc" -ne 0 ]; then fail "strings-set-$label" "exit $rc: $(head -c 300 "$err")"; continue; fi
  check_output "strings-set-$label" "$format" "$out"
done
run_ks sweep data/assur_fourbar.nml --vary omega1=10:20:2 --set "$set_title" --jobs 1
[ "$rc" -eq 0 ] && [ "$(wc -l <"$out")" -eq 3 ] && check_output strings-sweep csv "$out" \
  || fail strings-sweep "exit $rc, $(wc -l <"$out") lines: $(head -c 300 "$err")"
# a text in quotes ends on its line (a newline in it would take the next line's padding)
run_ks data/assur_fourbar.nml --set $'title=\'a\nINJECTED\''
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "&assur: title: unclosed quote ' (a text must end on its line" "$err" \
  && pass || fail strings-set-newline "exit $rc: $(cat "$err")"
# a --set value that is not UTF-8 is refused (a deck's text is UTF-8)
run_ks data/pr3207.nml --set $'l_ab=0.11\xff'
[ "$rc" -eq 2 ] && grep -qx "kinetostat: error: --set 'l_ab=0.11\\\\xFF': byte \\\\xFF is not UTF-8 (a deck's text is UTF-8)" "$err" \
  && pass || fail strings-set-not-utf8 "exit $rc: $(cat "$err")"

# --- encodings: a deck saved in CP1251 (Notepad "ANSI") reads as its UTF-8 twin: the Russian
# title decoded in the table, the JSON and the SVG; the output is the UTF-8 deck's but for the
# DECK line
ru_title='Шарнирный четырёхзвенник: кривошип, шатун, коромысло (ЁЖИК)'
with_title data/assur_fourbar.nml "$ru_title" "$strings_dir/ru.nml"
sed '1i ! Исходные данные: вариант 7' "$strings_dir/ru.nml" >"$strings_dir/utf8.nml"
run_py -c 'import sys; open(sys.argv[2], "wb").write(open(sys.argv[1], encoding="utf-8").read().encode("cp1251"))' \
  "$strings_dir/utf8.nml" "$strings_dir/cp1251.nml"
run_ks "$strings_dir/cp1251.nml"; cp "$out" "$strings_dir/cp1251.table"
run_ks "$strings_dir/utf8.nml"
[ "$rc" -eq 0 ] && grep -qx " TITLE: $ru_title" "$strings_dir/cp1251.table" \
  && diff <(grep -v '^ DECK:' "$strings_dir/cp1251.table") <(grep -v '^ DECK:' "$out") >/dev/null \
  && pass || fail strings-cp1251-table "$(grep TITLE "$strings_dir/cp1251.table") $(head -c 200 "$err")"
run_ks "$strings_dir/cp1251.nml" --format json
run_py -c 'import json,sys; t=json.load(open(sys.argv[1], encoding="utf-8"))["deck_title"]; assert t == sys.argv[2], t' \
  "$out" "$ru_title" && pass || fail strings-cp1251-json "$(grep deck_title "$out")"
run_ks "$strings_dir/cp1251.nml" --format svg
grep -q ">DECK: .*cp1251.nml   $ru_title<\|$ru_title" "$out" && check_output strings-cp1251-svg xml "$out" \
  || fail strings-cp1251-svg "the title is not on the sheet"
"$KINETOSTAT" - <"$strings_dir/cp1251.nml" >"$strings_dir/stdin.table" 2>"$strings_dir/stdin.err"
grep -qx " TITLE: $ru_title" "$strings_dir/stdin.table" && pass || fail strings-cp1251-stdin "$(cat "$strings_dir/stdin.err")"
# a byte 0xFF (CP1251's я) in a title is a letter: decoded
with_title data/assur_fourbar.nml $'a\xffb' "$strings_dir/ff_title.nml"
run_ks "$strings_dir/ff_title.nml"
[ "$rc" -eq 0 ] && grep -qx ' TITLE: aяb' "$out" && pass || fail strings-cp1251-ff "exit $rc: $(grep TITLE "$out") $(cat "$err")"
# anything else is refused, naming the line and the byte: a CP1251 degree sign, Latin-1, a mix
printf '! 30\xb0\n' | cat - "$strings_dir/cp1251.nml" >"$strings_dir/degree.nml"
expect_input_error strings-cp1251-degree 'degree.nml:1: byte \\xB0 is neither UTF-8 nor a Cyrillic letter of CP1251 \(save the deck as UTF-8\)$' \
  "$strings_dir/degree.nml"
with_title data/assur_fourbar.nml $'caf\xe9 \xd0\xb4\xd0\xb0' "$strings_dir/mixed.nml"
expect_input_error strings-mixed-encodings 'mixed.nml:[0-9]+: byte \\xE9 is not UTF-8, but line [0-9]+ is UTF-8: the deck mixes two encodings' \
  "$strings_dir/mixed.nml"
with_title data/assur_fourbar.nml $'na\xefve \xb0' "$strings_dir/latin1.nml"
expect_input_error strings-latin1 'latin1.nml:[0-9]+: byte \\xB0 is neither UTF-8' "$strings_dir/latin1.nml"

# --- texts count characters: a 45-letter Russian title (90 bytes) is accepted, 81 letters are
# refused saying so; a 5-letter Cyrillic joint name is accepted in both generic groups and
# names the kinematics columns, the sheet's label and the DXF's text
title45=$(run_py -c 'print("Ж" * 45)')
title81=$(run_py -c 'print("Ж" * 81)')
for base in assur_fourbar linkage_fourbar; do
  run_ks "data/$base.nml" --set "title='$title45'"
  [ "$rc" -eq 0 ] && grep -qx " TITLE: $title45" "$out" && pass || fail "strings-title45-$base" "exit $rc: $(head -c 300 "$err")"
  run_ks "data/$base.nml" --set "title='$title81'"
  [ "$rc" -eq 2 ] && grep -q ": title: longer than 80 characters (it has 81)" "$err" && pass \
    || fail "strings-title81-$base" "exit $rc: $(head -c 300 "$err")"
done
run_ks data/assur_fourbar.nml --set "crank_joint='Опора'" --format csv --kinematics
[ "$rc" -eq 0 ] && head -1 "$out" | grep -q ',x_Опора,y_Опора,' && pass || fail strings-joint-assur "exit $rc: $(head -c 300 "$err")"
run_ks data/assur_fourbar.nml --set "crank_joint='ОпораОпора'"
[ "$rc" -eq 2 ] && grep -q "crank_joint: longer than 8 characters (it has 10)" "$err" && pass \
  || fail strings-joint-assur-long "exit $rc: $(head -c 300 "$err")"
sed "s/'A'/'Опора'/g" data/linkage_fourbar.nml >"$strings_dir/joint.nml"
run_ks "$strings_dir/joint.nml" --format csv --kinematics
[ "$rc" -eq 0 ] && head -1 "$out" | grep -q ',x_Опора,y_Опора' && pass || fail strings-joint-linkage "exit $rc: $(head -c 300 "$err")"
cp "$out" "$strings_dir/joint.csv"
# kinetostat diff reads a CSV whose columns carry a Cyrillic name
sed '3s/,\([0-9]\)/,9\1/' "$strings_dir/joint.csv" >"$strings_dir/joint_changed.csv"
run_ks diff "$strings_dir/joint.csv" "$strings_dir/joint.csv"
rc_same=$rc
run_ks diff "$strings_dir/joint.csv" "$strings_dir/joint_changed.csv"
[ "$rc_same" -eq 0 ] && [ "$rc" -eq 1 ] && grep -q '^step 2, column ' "$out" && pass \
  || fail strings-joint-diff "exit $rc_same and $rc: $(head -3 "$out") $(cat "$err")"
run_ks "$strings_dir/joint.nml" --format dxf --at 3
[ "$rc" -eq 0 ] && grep -qx '\\U+041E\\U+043F\\U+043E\\U+0440\\U+0430' "$out" && check_output strings-joint-dxf dxf "$out" \
  || fail strings-joint-dxf "exit $rc: $(grep -m2 'U+' "$out") $(head -c 200 "$err")"
run_ks "$strings_dir/joint.nml" --format svg --at 3
[ "$rc" -eq 0 ] && grep -q '>Опора</text>' "$out" && pass || fail strings-joint-svg "exit $rc: $(head -c 300 "$err")"
run_ks "$strings_dir/joint.nml" --format json --at 3 --plans
[ "$rc" -eq 0 ] && check_output strings-joint-plans json "$out" && ! grep -q '\\u00' "$out" && pass \
  || fail strings-joint-plans "a name cut in the plans: $(grep -m3 '\\u00' "$out")"

# --- nothing after the group's '/': a fraction as a textbook writes it, a line after the '/'
# (both read as something else before: exit 0 with delta = 1, J_flywheel = 1, l_ab ignored)
sed 's/^\/$/  delta = 1\/25, j_rotor = 0.6\n\//' data/pr3207_flywheel.nml >"$strings_dir/fraction.nml"
expect_input_error strings-fraction 'fraction.nml:[0-9]+: &pr3207: delta = 1/25: a fraction\? write 0\.04$' "$strings_dir/fraction.nml"
sed 's/^\/$/  j_flywheel = 1\/16\n\//' data/sixbar_flywheel.nml >"$strings_dir/fraction16.nml"
expect_input_error strings-fraction-16 '&sixbar: j_flywheel = 1/16: a fraction\? write 0\.0625$' "$strings_dir/fraction16.nml"
{ cat data/pr3207.nml; printf '  l_ab = 5\n'; } >"$strings_dir/after.nml"
line=$(wc -l <"$strings_dir/after.nml")
expect_input_error strings-after-slash "after.nml:$line: &pr3207: l_ab = 5: text after the group's closing '/'" "$strings_dir/after.nml"
{ cat data/pr3207.nml; printf '\n  ! notes\n\n'; } >"$strings_dir/after_comment.nml"
run_ks "$strings_dir/after_comment.nml" --format csv
[ "$rc" -eq 0 ] && cmp -s "$out" data/expected/pr3207.csv && pass || fail strings-after-comment "exit $rc: $(cat "$err")"
with_title data/assur_fourbar.nml 'a/b, c!d & e' "$strings_dir/slash_text.nml"
run_ks "$strings_dir/slash_text.nml"
[ "$rc" -eq 0 ] && grep -qx ' TITLE: a/b, c!d & e' "$out" && pass || fail strings-slash-in-text "exit $rc: $(cat "$err")"

# --- capacities: every row of docs/cli.md's table, its last column given as --set, is exit 2
# naming the array element and the limit of the middle column
run_py - "$KINETOSTAT" "$root/docs/cli.md" <<'PY' >"$strings_dir/capacities.log" 2>&1 && pass || fail strings-capacities "$(head -20 "$strings_dir/capacities.log")"
import re, subprocess, sys
deck = {"pr3207": "data/pr3207.nml", "pr3050": "data/pr3050.nml", "sixbar": "data/sixbar.nml",
        "assur": "data/assur_fourbar.nml", "gears": "data/gears_reducer.nml", "cam": "data/cam_flat.nml",
        "linkage": "data/linkage_fourbar.nml", "cam_profile": "data/cam_profile_flat.nml"}
row = re.compile(r"^\| `&(\w+)` \| `([^`]+)`.*? \| (\d+) ([^|]+?) \| `([^`]+)` \|$")
bad, rows = [], 0
for line in open(sys.argv[2], encoding="utf-8"):
    m = row.match(line.strip())
    if not m:
        continue
    rows += 1
    group, array, limit, noun, example = m.groups()
    setting = re.sub(r"\s*=\s*", "=", example, count=1)
    element = re.match(r"[^=]*\(\d+\)", example).group(0)
    p = subprocess.run([sys.argv[1], deck[group], "--set", setting], capture_output=True, text=True)
    want = f"&{group}: {element}: at most {limit} {noun}"
    if p.returncode != 2 or len(p.stderr.splitlines()) != 1 or not p.stderr.rstrip("\n").endswith(want):
        bad.append(f"--set {setting}: exit {p.returncode}, {p.stderr.strip()!r}; expected ...{want!r}")
if rows < 20:
    bad.append(f"only {rows} rows found in the capacity table of docs/cli.md")
print("\n".join(bad) or f"{rows} capacities ok")
sys.exit(1 if bad else 0)
PY
# in a deck: the deck's line, and a list of too many values
sed 's/^\/$/  link(49)%id = 49\n\//' data/linkage_fourbar.nml >"$strings_dir/link49.nml"
expect_input_error strings-capacity-deck 'link49.nml:[0-9]+: &linkage: link\(49\): at most 48 links$' "$strings_dir/link49.nml"
run_py -c "
import sys
s = open('data/pr3207_flywheel.nml').read()
open(sys.argv[1], 'w').write(s.replace('\n/\n', '\n  md_table = ' + ', '.join(['1'] * 5764) + '\n/\n'))
" "$strings_dir/md5764.nml"
expect_input_error strings-capacity-list 'md5764.nml:[0-9]+: &pr3207: md_table: at most 5762 values \(2881 points\)$' "$strings_dir/md5764.nml"
