# --kinematics: the kinematics columns come only when asked, after the ordinary
# columns (so every default row is a prefix of the kinematics row); the legacy table ignores
# the option; the JSON with them loads and names them with their units and frames.

for deck in data/*.nml; do
  name=$(basename "$deck" .nml)
  [ "$name" = assur_toggle ] && continue
  # the design kinds have no kinematics columns (--kinematics changes nothing there)
  case "$name" in gear_geometry_*|planetary_synthesis*|cam_profile_*) continue ;; esac
  run_ks "$deck" --format csv; cp "$out" "$cli_tmp/k_plain.csv"
  run_ks "$deck" --format csv --kinematics; cp "$out" "$cli_tmp/k_kin.csv"
  python3 - "$cli_tmp/k_plain.csv" "$cli_tmp/k_kin.csv" <<'PY' && pass || fail "kinematics-csv-$name" "kinematics CSV is not the default CSV plus columns"
import sys
plain = open(sys.argv[1]).read().splitlines()
kin = open(sys.argv[2]).read().splitlines()
assert len(plain) == len(kin) and len(plain) > 1
for p, k in zip(plain, kin):
    assert k.startswith(p + ","), (p[:60], k[:60])
extra = kin[0][len(plain[0]) + 1:].split(",")
assert any(c.startswith("x_") for c in extra), extra
assert any(c.endswith("_x") for c in extra), extra
assert "nan" not in open(sys.argv[2]).read().lower()
PY
  run_ks "$deck"; cp "$out" "$cli_tmp/k_plain.table"
  run_ks "$deck" --kinematics
  if cmp -s "$out" "$cli_tmp/k_plain.table"; then pass; else fail "kinematics-table-$name" "--kinematics changed the legacy table"; fi
done

run_ks data/sixbar.nml --format json --kinematics
python3 - "$out" <<'PY' && pass || fail kinematics-json "JSON with --kinematics does not load or lacks the columns"
import json, sys
d = json.load(open(sys.argv[1]))
cols = {c["name"]: c for c in d["columns"]}
assert cols["x_H"]["unit"] == "m" and cols["x_H"]["kinematic"] is True
assert cols["omega3"]["unit"] == "rad/s" and cols["eps4"]["unit"] == "rad/s^2"
assert cols["ax_S4"]["unit"] == "m/s^2"
# F43 is given in frame 2 (x2 at beta - 180 deg in frame 1), F21 in frame 1
assert abs(cols["F43_x"]["frame_angle"] - (-153.43494882292202)) < 1e-9, cols["F43_x"]
assert cols["F21_x"]["frame_angle"] == 0
assert all(len(r) == len(d["columns"]) for r in d["rows"])
PY
run_ks data/sixbar.nml --format json
if [ "$rc" -ne 0 ] || ! grep -q '"columns"' "$out"; then fail kinematics-json-default "rc=$rc: $(head -c 300 "$err")"
elif grep -q '"kinematic"' "$out"; then fail kinematics-json-default "default JSON lists kinematics columns"
else pass; fi
