# --format svg: every bundled deck's sheet parses as XML, needs no other file,
# renders to a PNG of the sheet's size that is not blank, and its hodographs read back into
# the CSV's force components; --pairs selects and rejects; the checks can fail.
# The PNG check (0.3 s of Python a sheet) runs in the default suite on three sheets (PR 3207, a
# cam, a planetary gear train: a linkage's hodographs, a cam's diagrams, a train's stage
# panels) and PR 3207's --at sheet, on every sheet with tools/test --long (the generic
# six-bar with friction's, a linkage's hodographs as PR 3207's, among them). The sheets and CSV files of the bundled decks are their
# goldens (lib.sh from_golden).
svg_check="$root/tools/svg_check.py"
# png_wanted NAME: whether the sheet of deck NAME is rendered and checked as a PNG in this run
png_wanted() {
  [ "${KINETOSTAT_LONG:-0}" = 1 ] && return 0
  case " pr3207 cam_flat gears_planetary " in
    *" $1 "*) return 0 ;;
  esac
  return 1
}

# the per-deck checks of tools/svg_check.py, run in one process after the loop (svg_check.py batch)
svg_batch="$cli_tmp/svg_batch.txt"
: >"$svg_batch"
for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  [ "$name" = assur_toggle ] && continue
  # the design kinds draw their own sheets (test/cli/test_synthesis.sh), no sheet of forces
  case "$name" in gear_geometry_*|planetary_synthesis*|cam_profile_*) continue ;; esac
  from_golden "$name" svg --format svg
  if [ "$rc" -ne 0 ]; then fail "svg-runs-$name" "rc=$rc: $(head -c 300 "$err")"; continue; fi
  cp "$out" "$cli_tmp/$name.svg"
  # well-formed XML
  if xmllint --noout "$cli_tmp/$name.svg" 2>"$cli_tmp/xmllint.err"; then pass
  else fail "svg-xmllint-$name" "$(head -5 "$cli_tmp/xmllint.err")"; fi
  # self-contained: no href, url(), script, image, non-generic font
  printf 'svg-self-contained-%s\tself-contained\t%s\n' "$name" "$cli_tmp/$name.svg" >>"$svg_batch"
  # rendered: the sheet's size at 96 px per inch, not blank
  if ! png_wanted "$name"; then :
  elif rsvg-convert -o "$cli_tmp/$name.png" "$cli_tmp/$name.svg" 2>"$cli_tmp/rsvg.err"; then
    run_py "$svg_check" png "$cli_tmp/$name.png" "$cli_tmp/$name.svg" >"$cli_tmp/check.out" 2>&1 \
      && pass || fail "svg-png-$name" "$(cat "$cli_tmp/check.out")"
  else
    fail "svg-render-$name" "rsvg-convert failed: $(head -3 "$cli_tmp/rsvg.err")"
  fi
  # hodographs = the CSV's components (the gear decks have stages, no hodographs)
  case "$name" in gears_*) continue ;; esac
  from_golden "$name" csv --format csv; cp "$out" "$cli_tmp/$name.csv"
  printf 'svg-hodographs-%s\thodographs\t%s\t%s\n' "$name" "$cli_tmp/$name.svg" "$cli_tmp/$name.csv" >>"$svg_batch"
done
run_py "$svg_check" batch "$svg_batch" >"$cli_tmp/svg_batch.out" 2>&1
if [ "$(grep -c '^ok \|^FAIL ' "$cli_tmp/svg_batch.out")" -ne "$(grep -c . "$svg_batch")" ]; then
  fail svg-batch "tools/svg_check.py batch did not report every check: $(tail -5 "$cli_tmp/svg_batch.out")"
fi
while read -r verdict check_name; do
  case "$verdict" in
    ok) pass ;;
    FAIL) fail "${check_name%%:*}" "$(awk -v n="FAIL ${check_name%%:*}:" 'index($0, n) == 1 {on = 1; print; next}
      on && /^    / {print; next} {on = 0}' "$cli_tmp/svg_batch.out")" ;;
  esac
done < <(grep '^ok \|^FAIL ' "$cli_tmp/svg_batch.out")

# the hodograph check can fail: the first point of F36's path moved by about 0.9 mm
sed -E '/data-force="F36"/s/d="M ([0-9]+)\.([0-9]+)/d="M \1.9\2/' "$cli_tmp/pr3207.svg" >"$cli_tmp/bad.svg"
if cmp -s "$cli_tmp/pr3207.svg" "$cli_tmp/bad.svg"; then fail svg-check-can-fail "the perturbation did not change the sheet"
else
  run_py "$svg_check" hodographs "$cli_tmp/bad.svg" "$cli_tmp/pr3207.csv" >"$cli_tmp/check.out" 2>&1
  grep -q "F36" "$cli_tmp/check.out" && pass \
    || fail svg-check-can-fail "a moved hodograph point was not reported: $(head -3 "$cli_tmp/check.out")"
fi
# ... and so can the blank-image check (a sheet with nothing drawn on it)
printf '<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297">%s</svg>\n' \
  '<rect width="210" height="297" fill="#ffffff"/>' >"$cli_tmp/blank.svg"
rsvg-convert -o "$cli_tmp/blank.png" "$cli_tmp/blank.svg" 2>/dev/null
run_py "$svg_check" png "$cli_tmp/blank.png" "$cli_tmp/blank.svg" >"$cli_tmp/check.out" 2>&1
grep -q "looks blank" "$cli_tmp/check.out" && pass \
  || fail svg-blank-can-fail "a blank PNG was not reported: $(head -3 "$cli_tmp/check.out")"

# same deck, same bytes
run_ks data/sixbar.nml --format svg; cp "$out" "$cli_tmp/again.svg"
cmp -s "$cli_tmp/again.svg" "$cli_tmp/sixbar.svg" && pass || fail svg-deterministic "two runs differ"

# --pairs: only the named pairs, in the named order, any case
run_ks data/pr3207.nml --format svg --pairs f36,F16
forces=$(grep -o 'data-force="[^"]*"' "$out" | tr '\n' ' ')
[ "$rc" -eq 0 ] && [ "$forces" = 'data-force="F36" data-force="F16" ' ] \
  && pass || fail svg-pairs-select "rc=$rc, hodographs: $forces"
grep -q '>F21</text>' "$out" && fail svg-pairs-legend "F21 still in the legend" || pass
# an unknown pair: exit 1 naming the deck and the pair forces there are; nothing written
run_ks data/pr3207.nml --format svg --pairs F16,F99 -o "$cli_tmp/never.svg"
[ "$rc" -eq 1 ] && grep -q "^kinetostat: error: --pairs: 'F99' is not a pair force of data/pr3207.nml (pair forces: F16, F21, F36, F34, F56)" "$err" \
  && [ ! -e "$cli_tmp/never.svg" ] && pass || fail svg-pairs-unknown "rc=$rc: $(cat "$err")"
expect_exit svg-pairs-needs-svg 1 data/pr3207.nml --pairs F16
# the gear decks: one vector panel per stage, no hodograph
grep -q '>stage 2</text>' "$cli_tmp/gears_reducer.svg" && ! grep -q 'class="hodograph"' "$cli_tmp/gears_reducer.svg" \
  && pass || fail svg-gears-stages "no stage panels, or a hodograph of stages"

# --at K: every linkage deck drawn at one step (xmllint, self-contained, PNG of A4 size, not
# blank), and the forces listed on the sheet carry the CSV's magnitudes (to the 3-4 digits
# shown: relative 0.5 %, or 0.5 N at 100 N and above)
for spec in pr3207:2 pr3050:4 sixbar:2 sixbar_example:1 assur_pr3207:2 assur_sixbar:2 assur_slider_crank:3 assur_pr3050:3; do
  name=${spec%%:*}; k=${spec##*:}
  run_ks "data/$name.nml" --format svg --at "$k"
  if [ "$rc" -ne 0 ]; then fail "svg-at-runs-$name" "rc=$rc: $(head -c 300 "$err")"; continue; fi
  cp "$out" "$cli_tmp/${name}_at.svg"
  xmllint --noout "$cli_tmp/${name}_at.svg" 2>"$cli_tmp/xmllint.err" && pass \
    || fail "svg-at-xmllint-$name" "$(head -5 "$cli_tmp/xmllint.err")"
  run_py "$svg_check" self-contained "$cli_tmp/${name}_at.svg" >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "svg-at-self-contained-$name" "$(cat "$cli_tmp/check.out")"
  if ! png_wanted "$name"; then :
  elif rsvg-convert -o "$cli_tmp/${name}_at.png" "$cli_tmp/${name}_at.svg" 2>"$cli_tmp/rsvg.err"; then
    run_py "$svg_check" png "$cli_tmp/${name}_at.png" "$cli_tmp/${name}_at.svg" >"$cli_tmp/check.out" 2>&1 \
      && pass || fail "svg-at-png-$name" "$(cat "$cli_tmp/check.out")"
  else
    fail "svg-at-render-$name" "rsvg-convert failed: $(head -3 "$cli_tmp/rsvg.err")"
  fi
  run_ks "data/$name.nml" --format csv; cp "$out" "$cli_tmp/$name.csv"
  run_py - "$cli_tmp/${name}_at.svg" "$cli_tmp/$name.csv" "$k" <<'PY' >"$cli_tmp/check.out" 2>&1 \
    && pass || fail "svg-at-forces-$name" "$(cat "$cli_tmp/check.out")"
import csv, re, sys
import xml.etree.ElementTree as ET
table, k = list(csv.DictReader(open(sys.argv[2]))), int(sys.argv[3])
row = table[k - 1]
# the texts as a reader sees them (typeset: F<tspan>21</tspan> reads F21)
texts = ["".join(t.itertext()) for t in ET.parse(sys.argv[1]).getroot().iter("{http://www.w3.org/2000/svg}text")]
listed = dict(m.groups() for m in (re.fullmatch(r"(F\w+) = (-?[0-9.]+) N(?: at [0-9.]+ deg)?", t) for t in texts) if m)
pairs = [c for c in row if c + "G" in row]
missing = [p for p in pairs if p not in listed]
assert not missing, f"pair forces not on the sheet: {missing}"
for p in pairs:
    expected, shown = abs(float(row[p])), float(listed[p])
    assert abs(shown - expected) <= max(0.5, 0.005 * expected), f"{p}: sheet {shown} N, CSV {expected} N"
print(f"{len(pairs)} pair forces as in the CSV")
PY
done
# the drawings' errors: a step out of range, a mechanism that is not drawn, --at without svg
run_ks data/pr3207.nml --format svg --at 14
[ "$rc" -eq 1 ] && grep -q '^kinetostat: error: --at 14: data/pr3207.nml has 13 steps (1..13)$' "$err" \
  && pass || fail svg-at-range "rc=$rc: $(cat "$err")"
for deck in data/cam_flat.nml data/gears_reducer.nml; do
  run_ks "$deck" --format svg --at 1
  [ "$rc" -eq 1 ] && grep -q "^kinetostat: error: $deck: &[a-z]*: --at: this mechanism is not drawn" "$err" && [ ! -s "$out" ] \
    && pass || fail "svg-at-not-drawn-$(basename "$deck" .nml)" "rc=$rc: $(cat "$err")"
done
expect_exit svg-at-needs-svg 1 data/pr3207.nml --at 2
expect_exit svg-at-zero 1 data/pr3207.nml --format svg --at 0
