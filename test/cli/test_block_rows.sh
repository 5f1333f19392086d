# Block size does not change the output: a run solved and written in blocks of 1 and of 7
# rows (KINETOSTAT_BLOCK_ROWS) gives the bytes of the same run in blocks of the default size
# (stdout, stderr and exit code), in table, CSV, JSON and SVG. The decks are found by listing
# data/*.nml and docs/examples/*.nml, none by hand; a deck that stops by design (exit 3) must
# stop the same way at every block size, so no deck and no format is skipped.
# Default run: the first deck listed of each kind (namelist group) in table, CSV and JSON and
# every other deck with a dynamics stage (`dynamics = 'steady'` or 'given': its figures are
# reduced over the run) in table and JSON, at 1, 7 and the default; SVG at 7 and the default for the first deck
# of each kind; a heavy deck (lib.sh: heavy_deck) in table only, at 7 and the default. `tools/test --long`: every
# deck, every format, all three sizes.

# block_rows_same NAME ARGS...: the run in blocks of 1 and of 7 rows (or the sizes in
# $block_sizes) gives the bytes, the stderr and the exit code of the run at the default size.
block_rows_same() {
  local name="$1"; shift
  local rc0 rcb b
  "$KINETOSTAT" "$@" >"$cli_tmp/blk0.out" 2>"$cli_tmp/blk0.err"; rc0=$?
  for b in $block_sizes; do
    KINETOSTAT_BLOCK_ROWS=$b "$KINETOSTAT" "$@" >"$cli_tmp/blkb.out" 2>"$cli_tmp/blkb.err"; rcb=$?
    if [ "$rc0" -ne "$rcb" ]; then fail "$name" "exit code $rcb in blocks of $b rows, $rc0 at the default"; return; fi
    if ! cmp -s "$cli_tmp/blk0.out" "$cli_tmp/blkb.out"; then
      fail "$name" "output differs in blocks of $b rows: $(diff "$cli_tmp/blk0.out" "$cli_tmp/blkb.out" | head -6)"
      return
    fi
    if ! cmp -s "$cli_tmp/blk0.err" "$cli_tmp/blkb.err"; then
      fail "$name" "stderr differs in blocks of $b rows: $(diff "$cli_tmp/blk0.err" "$cli_tmp/blkb.err" | head -4)"
      return
    fi
  done
  pass
}

# the kind of a deck: its first namelist group
deck_kind() { sed -n 's/^[[:space:]]*&\([A-Za-z0-9_]*\).*/\1/p' "$1" | head -1; }

blk_kinds_seen=" "
for deck in data/*.nml docs/examples/*.nml; do
  name=$(basename "$deck" .nml)
  kind=$(deck_kind "$deck")
  first_of_kind=0
  case "$blk_kinds_seen" in *" $kind "*) ;; *) first_of_kind=1; blk_kinds_seen="$blk_kinds_seen$kind " ;; esac
  dynamic=0
  grep -Eiq "^[^!]*dynamics[[:space:]]*=[[:space:]]*['\"](steady|given)" "$deck" && dynamic=1
  blk_dynamic_decks=$((${blk_dynamic_decks:-0} + dynamic))
  if [ "${KINETOSTAT_LONG:-0}" != 1 ] && [ "$first_of_kind" = 0 ] && [ "$dynamic" = 0 ]; then continue; fi
  block_sizes="1 7"
  # a deck with a dynamics stage that is not the first of its kind: the table and JSON, which
  # hold the figures reduced over the run as well as the rows (its CSV holds the rows only)
  blk_formats="table csv json"
  [ "${KINETOSTAT_LONG:-0}" != 1 ] && [ "$first_of_kind" = 0 ] && blk_formats="table json"
  heavy_deck "$name" && blk_formats="table" block_sizes="7"
  for format in $blk_formats; do
    block_rows_same "block-rows-$name-$format" "$deck" --format "$format"
  done
  if [ "${KINETOSTAT_LONG:-0}" = 1 ]; then
    block_rows_same "block-rows-$name-svg" "$deck" --format svg
  elif [ "$first_of_kind" = 1 ]; then
    block_sizes="7"
    block_rows_same "block-rows-$name-svg" "$deck" --format svg
  fi
done
# the listing found decks of several kinds and decks with a dynamics stage
if [ "$(echo $blk_kinds_seen | wc -w)" -ge 2 ] && [ "${blk_dynamic_decks:-0}" -ge 1 ]; then pass; else
  fail block-rows-listing "kinds [$blk_kinds_seen], ${blk_dynamic_decks:-0} decks with a dynamics stage"
fi

# the knob: a whole number >= 1; anything else is exit 2, one line naming it, nothing written
for bad in 0 -3 x 1.5 " 7" 99999999999999999999; do
  KINETOSTAT_BLOCK_ROWS="$bad" "$KINETOSTAT" data/pr3207.nml >"$cli_tmp/blk.out" 2>"$cli_tmp/blk.err"; rc=$?
  if [ "$rc" -eq 2 ] && [ "$(wc -l <"$cli_tmp/blk.err")" -eq 1 ] && [ ! -s "$cli_tmp/blk.out" ] &&
    grep -q "^kinetostat: error: KINETOSTAT_BLOCK_ROWS: expected a whole number of rows >= 1" "$cli_tmp/blk.err"; then
    pass
  else
    fail "block-rows-bad-value-[$bad]" "exit $rc, stderr: $(head -c 300 "$cli_tmp/blk.err")"
  fi
done
# an empty value is the default
KINETOSTAT_BLOCK_ROWS= "$KINETOSTAT" data/pr3207.nml >"$cli_tmp/blk.out" 2>&1 && pass ||
  fail block-rows-empty "an empty KINETOSTAT_BLOCK_ROWS is not the default: $(head -c 300 "$cli_tmp/blk.out")"

# kinetostat sheets: the course's sheets (their default position, the plan of positions, the
# dynamics over the cycle) do not depend on the block size either: a four-stroke engine with
# its flywheel in blocks of 7 rows against the default, every SVG and DXF byte for byte (a
# PDF carries its time of making)
blk_sheets_deck=data/assur_engine_flywheel.nml
rm -rf "$cli_tmp/blk_sheets0" "$cli_tmp/blk_sheets7"
# (the PDFs, which the comparison leaves out, from a stand-in rsvg-convert: lib.sh, pdf_stand_in)
PATH="$(pdf_stand_in):$PATH" "$KINETOSTAT" sheets "$blk_sheets_deck" -o "$cli_tmp/blk_sheets0" >"$cli_tmp/blk.out" 2>&1; rc0=$?
PATH="$(pdf_stand_in):$PATH" KINETOSTAT_BLOCK_ROWS=7 "$KINETOSTAT" sheets "$blk_sheets_deck" -o "$cli_tmp/blk_sheets7" \
  >>"$cli_tmp/blk.out" 2>&1; rcb=$?
if [ "$rc0" -eq 0 ] && [ "$rcb" -eq 0 ] && [ -s "$cli_tmp/blk_sheets0/kinematics.svg" ] &&
  diff -r -x "*.pdf" "$cli_tmp/blk_sheets0" "$cli_tmp/blk_sheets7" >"$cli_tmp/blk.diff" 2>&1; then
  pass
else
  fail block-rows-sheets "exit $rc0 / $rcb (blocks of 7): $(head -c 300 "$cli_tmp/blk.out") $(head -c 300 "$cli_tmp/blk.diff")"
fi
