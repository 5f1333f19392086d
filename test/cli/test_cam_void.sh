# Cam steps without forces (the follower jammed, or the contact lost): data/cam_translating.nml
# has one of each (phi = 90, 300 deg). Their force cells are empty in CSV and null in JSON,
# never 0; the summary leaves them out of the extremes and means and says how many.

run_ks data/cam_translating.nml --format csv
run_py - "$out" <<'PY' && pass || fail cam-void-csv "jammed/lost rows are not empty in the force columns"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
void = [r for r in rows if r["JAM"] == "1" or r["LOST"] == "1"]
forces = ["N", "F21", "F21G", "F23C", "F23CG", "F23D", "F23DG", "KF"]
ok = [r["phi"] for r in void] == ["9.000000000000E+001", "3.000000000000E+002"]
ok = ok and all(r[c] == "" for r in void for c in forces)
ok = ok and all(r[c] != "" for r in rows if r not in void for c in forces)
if not ok:
    print([(r["phi"], [r[c] for c in forces]) for r in void]); sys.exit(1)
PY

run_ks data/cam_translating.nml --format json
run_py - "$out" <<'PY' && pass || fail cam-void-json "JSON invalid or the void cells are not null"
import json, sys
doc = json.load(open(sys.argv[1]))
cols = [c["name"] if isinstance(c, dict) else c for c in doc["columns"]]
rows = doc["rows"]
jam, lost, n = cols.index("JAM"), cols.index("LOST"), cols.index("N")
void = [r for r in rows if r[jam] == 1 or r[lost] == 1]
if len(void) != 2 or any(r[n] is not None for r in void) or any(r[n] is None for r in rows if r not in void):
    print(void); sys.exit(1)
PY

# the summary: N's extremes and mean over the steps with contact only (mean: trapezoid over
# the stretches between such steps, divided by the angle they cover), rows_left_out = 2
run_ks data/cam_translating.nml --format csv; cp "$out" "$cli_tmp/cam_void.csv"
run_ks data/cam_translating.nml --format summary
run_py - "$out" "$cli_tmp/cam_void.csv" <<'PY' && pass || fail cam-void-summary "summary counts jammed/lost steps"
import csv, sys
s = next(csv.DictReader(open(sys.argv[1])))
rows = list(csv.DictReader(open(sys.argv[2])))
pts = [(float(r["phi"]), float(r["N"]) if r["N"] else None) for r in rows]
good = [v for _, v in pts if v is not None]
area = span = 0.0
for (x0, v0), (x1, v1) in zip(pts, pts[1:]):
    if v0 is not None and v1 is not None:
        area += 0.5 * (v0 + v1) * (x1 - x0); span += x1 - x0
checks = [int(s["rows_left_out"]) == 2, abs(float(s["N_min"]) - min(good)) <= 1e-12 * max(good),
          float(s["N_min"]) > 100, abs(float(s["N_max"]) - max(good)) <= 1e-12 * max(good),
          abs(float(s["N_mean"]) - area / span) <= 1e-12 * max(good)]
if not all(checks):
    print(checks, s["rows_left_out"], s["N_min"], s["N_max"], s["N_mean"], area / span); sys.exit(1)
PY

run_ks data/cam_translating.nml
grep -q '^   STEPS LEFT OUT  =                 2  (JAMMED OR LOST CONTACT: NO FORCES, NOT IN MAX, MIN, MEAN)$' "$out" \
  && grep -q '^   N MIN           =   1.045693091E+02  N    AT PHI =   270.00 deg$' "$out" \
  && pass || fail cam-void-table "$(grep -A8 '^ SUMMARY' "$out")"

# kinetostat diff: an empty cell equals an empty cell, and differs from a 0
run_ks diff "$cli_tmp/cam_void.csv" "$cli_tmp/cam_void.csv"
[ "$rc" -eq 0 ] && pass || fail cam-void-diff-same "rc=$rc $(cat "$out" "$err")"
sed 's/^\(9.000000000000E+001,[^,]*,[^,]*,[^,]*,[^,]*\),,/\1,0.000000000000E+000,/' "$cli_tmp/cam_void.csv" >"$cli_tmp/cam_void0.csv"
run_ks diff "$cli_tmp/cam_void.csv" "$cli_tmp/cam_void0.csv"
[ "$rc" -eq 1 ] && grep -q '^step 4, column N:' "$out" && pass || fail cam-void-diff-zero "rc=$rc $(cat "$out" "$err")"
