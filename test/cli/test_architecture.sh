# The house rules of src/ (docs/architecture.md), read from the sources themselves:
# - every folder of src/ has a layer, and a module uses only modules of its own folder or of
#   a lower layer (core <- deck, output <- pictures <- plans <- pipeline, compare <- mechanisms and
#   stages <- cli): the use-arrows point one way;
# - one module per file, the file named after its module, every module prefixed kinetostat_;
# - no folder holds more than 30 % of the lines of src/.
# A new folder must be given its layer here and in docs/architecture.md's map.
run_py - "$root/src" <<'PY' && pass || fail "architecture-layers" "see above"
import os, re, sys
src = sys.argv[1]
layers = {"core": 0, "deck": 1, "output": 1, "pictures": 2, "plans": 2.2, "shaking": 2.5, "pipeline": 3, "compare": 3, "dynamics": 4, "convert": 6,
          "cli": 9}
# one folder per mechanism or stage: above the pipeline, below the CLI; stages that the
# mechanisms use (e.g. a dynamics stage) sit one below them
mechanisms = {"pr3207", "pr3050", "sixbar", "assur", "gears", "cam", "linkage", "gear_geometry",
              "planetary_synthesis", "cam_profile"}
for m in mechanisms:
    layers[m] = 5
bad = []
owner = {}      # module -> folder
uses = []       # (folder, file, line number, used module)
lines_of = {}
for folder in sorted(os.listdir(src)):
    path = os.path.join(src, folder)
    if not os.path.isdir(path):
        bad.append(f"src/{folder}: a file directly in src/ (every module lives in a folder)")
        continue
    if folder not in layers:
        bad.append(f"src/{folder}/: folder has no layer (add it to test/cli/test_architecture.sh and docs/architecture.md)")
        continue
    for name in sorted(os.listdir(path)):
        if not name.endswith(".f90"):
            continue
        text = open(os.path.join(path, name), encoding="utf-8").read()
        lines_of[folder] = lines_of.get(folder, 0) + text.count("\n")
        mods = re.findall(r"^\s*module\s+(?!procedure\b)(\w+)\s*$", text, re.M | re.I)
        if len(mods) != 1:
            bad.append(f"src/{folder}/{name}: {len(mods)} modules (one module per file)")
            continue
        mod = mods[0].lower()
        if not mod.startswith("kinetostat_"):
            bad.append(f"src/{folder}/{name}: module {mod} is not prefixed kinetostat_")
        if name != mod + ".f90":
            bad.append(f"src/{folder}/{name}: file not named after its module {mod}")
        owner[mod] = folder
        for i, line in enumerate(text.splitlines(), 1):
            m = re.match(r"\s*use\s+(kinetostat_\w+)", line, re.I)
            if m:
                uses.append((folder, name, i, m.group(1).lower()))
arrows = 0
for folder, name, i, used in uses:
    if used not in owner:
        bad.append(f"src/{folder}/{name}:{i}: uses {used}, which no file of src/ defines")
        continue
    other = owner[used]
    arrows += 1
    if other == folder:
        continue
    if layers[other] >= layers[folder]:
        bad.append(f"src/{folder}/{name}:{i}: uses {used} of src/{other}/ (layer {layers[other]}),"
                   f" not below src/{folder}/ (layer {layers[folder]})")
total = sum(lines_of.values())
for folder, n in sorted(lines_of.items()):
    if n > 0.30 * total:
        bad.append(f"src/{folder}/: {n} of {total} lines ({100 * n / total:.0f} %), more than 30 %")
for b in bad:
    print(b)
if arrows < 100:
    print(f"only {arrows} use lines read: the test reads nothing")
    sys.exit(1)
sys.exit(1 if bad else 0)
PY
