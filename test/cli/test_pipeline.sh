# The one run pipeline: JSON and --lang ru for every deck, output that can never lie
# (no NaN, no '*', checked writes, -o onto devices and FIFOs), option forms.

# --- JSON loads for every bundled deck, and carries the CSV's values: the JSON of every deck
# (from_golden: the golden check proves data/expected's the binary's output), checked in one
# Python process after the loop, a verdict line per deck
: >"$cli_tmp/json_list.tsv"
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  [ "$name" = assur_toggle ] && continue
  from_golden "$name" json --format json
  if [ "$rc" -ne 0 ]; then fail "json-loads-$name" "rc=$rc: $(head -c 300 "$err")"; continue; fi
  cp "$out" "$cli_tmp/json_$name.json"
  printf '%s\t%s\n' "$name" "$cli_tmp/json_$name.json" >>"$cli_tmp/json_list.tsv"
done
# the first key is the layout's version, an integer (docs/cli.md "JSON format version")
run_py - "$cli_tmp/json_list.tsv" >"$cli_tmp/json.out" 2>&1 <<'PY'
import json, sys
for line in open(sys.argv[1]):
    name, path = line.rstrip("\n").split("\t")
    try:
        d = json.load(open(path))
        assert d["rows"] and d["columns"]
        v = d.get("format_version")
        assert type(v) is int and v >= 1 and list(d)[0] == "format_version", v
        print("ok", name)
    except Exception as exc:  # noqa: BLE001 - the deck's verdict, whatever went wrong
        print("FAIL %s: %r" % (name, exc))
PY
while IFS=$'\t' read -r name _; do
  if grep -qx "ok $name" "$cli_tmp/json.out"; then pass
  else fail "json-loads-$name" "$(grep -m1 "^FAIL $name:" "$cli_tmp/json.out" || tail -3 "$cli_tmp/json.out")"; fi
done <"$cli_tmp/json_list.tsv"
# the JSON rows equal the CSV rows (csv columns, same text)
run_ks data/pr3207.nml --format csv; cp "$out" "$cli_tmp/p.csv"
run_ks data/pr3207.nml --format json; cp "$out" "$cli_tmp/p.json"
run_py - "$cli_tmp/p.csv" "$cli_tmp/p.json" <<'PY' && pass || fail json-equals-csv "JSON rows differ from the CSV"
import csv, json, sys
rows = list(csv.reader(open(sys.argv[1])))
d = json.load(open(sys.argv[2]))
names = [c["name"] for c in d["columns"] if c["csv"]]
assert rows[0] == names, (rows[0], names)
for r, j in zip(rows[1:], d["rows"]):
    assert [float(x) for x in r] == [float(x) for x in j[:len(r)]], (r, j)
PY

# --- --lang ru: every table's columns line up (display width, not bytes) with the English one
for deck in data/pr3207.nml data/assur_sixbar.nml data/pr3050.nml; do
  name=$(basename "$deck" .nml)
  run_ks "$deck" --lang ru; cp "$out" "$cli_tmp/$name.ru"
  run_ks "$deck"; cp "$out" "$cli_tmp/$name.en"
  # the rows of numbers are the same text in both languages
  if diff <(grep -E '^ +-?[0-9]+\.[0-9]+ ' "$cli_tmp/$name.en") <(grep -E '^ +-?[0-9]+\.[0-9]+ ' "$cli_tmp/$name.ru") >/dev/null; then
    pass; else fail "ru-rows-$name" "numeric rows differ between --lang en and --lang ru"; fi
done
# units lines are as wide (in characters) as the header they sit under
run_py - "$cli_tmp/pr3207.ru" <<'PY' && pass || fail ru-units-aligned "Cyrillic units line misaligned"
import sys
lines = open(sys.argv[1], encoding="utf-8").read().split("\n")
i = next(k for k, l in enumerate(lines) if l.strip().startswith("PHI1"))
assert len(lines[i]) == len(lines[i + 2]), (lines[i], lines[i + 2])
PY
grep -q 'ИСХОДНЫЕ ДАННЫЕ' "$cli_tmp/pr3207.ru" && grep -q 'РЕЗУЛЬТАТЫ РАСЧЕТА' "$cli_tmp/pr3207.ru" \
  && pass || fail ru-headings "no ИСХОДНЫЕ ДАННЫЕ / РЕЗУЛЬТАТЫ РАСЧЕТА"
run_ks data/sixbar.nml --lang ru
grep -q '^       F0         F21         F32         F43         F45         F36         F16         F56$' "$out" \
  && pass || fail ru-tftn-header "T.FTN header is not appendix 2's eight columns"

# --- a value too wide for its field: exponent form in the field, never '*'
run_ks "$(deck_with m5big data/pr3207.nml 's/m5 = 60/m5 = 1e8/')"
cp "$out" "$cli_tmp/m5big.table"
[ "$rc" -eq 0 ] && grep -q 'E+09' "$cli_tmp/m5big.table" && pass || fail pr3207-wide-exponent "rc=$rc or no exponent form"
expect_no_nan pr3207-wide-no-stars "$cli_tmp/m5big.table"
grep -qE '[0-9]\.[0-9]{2}[0-9]+\.[0-9]' "$cli_tmp/m5big.table" && fail pr3207-fields-run-together "fields run together" || pass
# --- a non-finite result: exit 3 naming step, input angle and column
expect_input_error pr3207-omega-overflow '&pr3207: step 1 \(phi1 = 0 deg\): F16 is not finite' \
  "$(deck_with omega_huge data/pr3207.nml 's/omega1 = 7.5/omega1 = 1e308/')" 3

# --- checked writes
"$KINETOSTAT" data/pr3207.nml >/dev/full 2>"$cli_tmp/full.err"; rc=$?
[ "$rc" -eq 2 ] && [ "$(wc -l <"$cli_tmp/full.err")" -eq 1 ] && grep -q '^kinetostat: error: standard output' "$cli_tmp/full.err" \
  && pass || fail stdout-full "rc=$rc, stderr: $(cat "$cli_tmp/full.err")"
# -o onto a device writes to it and leaves it a device (never renamed over)
if [ -c /dev/null ] && [ -w /dev/null ]; then
  run_ks data/pr3207.nml -o /dev/null
  [ "$rc" -eq 0 ] && [ -c /dev/null ] && pass || fail o-dev-null "rc=$rc or /dev/null is no longer a device"
  ls /dev/null.tmp.* >/dev/null 2>&1 && fail o-dev-null-temp "temporary left in /dev" || pass
fi
# -o onto a FIFO writes into it (a reader gets the table); the FIFO stays a FIFO
fifo="$cli_tmp/fifo"; mkfifo "$fifo"
cat "$fifo" >"$cli_tmp/fifo.out" & reader=$!
run_ks data/pr3207.nml -o "$fifo"; wait "$reader"
[ "$rc" -eq 0 ] && [ -p "$fifo" ] && cmp -s "$cli_tmp/fifo.out" data/expected/pr3207.table \
  && pass || fail o-fifo "rc=$rc, FIFO replaced or content differs"
# -o into a directory that does not exist: exit 2, nothing left
run_ks data/pr3207.nml -o "$cli_tmp/no/such/dir/out.table"
[ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && pass || fail o-bad-dir "rc=$rc: $(cat "$err")"

# --- option forms
run_ks data/pr3207.nml --format=csv; cmp -s "$out" data/expected/pr3207.csv && pass || fail format-equals "--format=csv differs"
expect_exit format-unknown 1 data/pr3207.nml --format xml
expect_exit lang-unknown 1 data/pr3207.nml --lang de
run_ks --help
grep -q -- '--format table|csv|json' "$out" && grep -q -- '--lang' "$out" && grep -q '^Kinds: pr3207, pr3050, sixbar, assur, gears, cam, linkage, gear_geometry, planetary_synthesis, cam_profile$' "$out" \
  && pass || fail help-lists "--help lacks formats, --lang or the registry's kinds"
