#!/usr/bin/env python3
"""Read back kinetostat's DXF drawing (--format dxf --at K; standard library only).

  dxf_check.py DRAWING.dxf RUN.csv K
      Parses the ASCII DXF as group-code/value pairs and checks: the sections HEADER, TABLES,
      ENTITIES in that order and the closing EOF; the layer table defines LINKS, JOINTS,
      GUIDES, FORCES, TEXT; every entity is a LINE, CIRCLE or TEXT on a defined layer with
      numeric coordinates; every joint of step K in RUN.csv (x_P, y_P of `--format csv
      --kinematics`, m; a centre of mass S<i> when the drawing names it) has a circle on
      JOINTS at 1000 x its position (mm, within 1e-6 mm) and its name as a TEXT; every force labelled on TEXT ("NAME = VALUE N") has its arrow:
      three LINEs on FORCES meeting at one tip.
Exit status 0 when the drawing passes, 1 with the failures printed.
"""
import csv
import math
import re
import sys


def pairs(path):
    lines = open(path, encoding="ascii").read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) % 2:
        raise ValueError("odd number of lines: group codes and values must come in pairs")
    return [(int(lines[i].strip()), lines[i + 1]) for i in range(0, len(lines), 2)]


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(1)
    bad = []
    try:
        groups = pairs(sys.argv[1])
    except (ValueError, UnicodeDecodeError) as e:
        print(f"{sys.argv[1]}: not an ASCII DXF: {e}")
        sys.exit(1)
    sections, layers, entities = [], set(), []
    i = 0
    current = None
    while i < len(groups):
        code, value = groups[i]
        if code == 0 and value == "SECTION":
            sections.append(groups[i + 1][1])
            current = groups[i + 1][1]
            i += 2
            continue
        if code == 0 and value in ("ENDSEC", "EOF", "TABLE", "ENDTAB"):
            i += 1
            continue
        if code == 0:
            record = {"type": value}
            i += 1
            while i < len(groups) and groups[i][0] != 0:
                record.setdefault(groups[i][0], groups[i][1])
                i += 1
            if current == "TABLES" and value == "LAYER":
                layers.add(record.get(2))
            elif current == "ENTITIES":
                entities.append(record)
            continue
        i += 1
    if sections != ["HEADER", "TABLES", "ENTITIES"]:
        bad.append(f"sections {sections}, expected HEADER, TABLES, ENTITIES")
    if groups[-1] != (0, "EOF"):
        bad.append("no EOF at the end")
    for name in ("LINKS", "JOINTS", "GUIDES", "FORCES", "TEXT"):
        if name not in layers:
            bad.append(f"layer {name} not defined")
    circles, lines, texts = [], [], []
    for e in entities:
        if e.get(8) not in layers:
            bad.append(f"{e['type']} on undefined layer {e.get(8)!r}")
        try:
            if e["type"] == "LINE":
                lines.append((e[8], float(e[10]), float(e[20]), float(e[11]), float(e[21])))
            elif e["type"] == "CIRCLE":
                circles.append((e[8], float(e[10]), float(e[20]), float(e[40])))
            elif e["type"] == "TEXT":
                texts.append((e[8], float(e[10]), float(e[20]), e[1]))
            else:
                bad.append(f"unexpected entity {e['type']}")
        except (KeyError, ValueError) as err:
            bad.append(f"{e['type']} without a numeric group: {err}")
    rows = list(csv.DictReader(open(sys.argv[2], newline="")))
    row = rows[int(sys.argv[3]) - 1]
    names = {t[3] for t in texts}
    for key in row:
        if not key.startswith("x_"):
            continue
        p = key[2:]
        if re.fullmatch(r"S\w+", p) and p not in names:
            continue  # a centre of mass the drawing does not show (its link is named otherwise)
        x, y = 1000 * float(row["x_" + p]), 1000 * float(row["y_" + p])
        if not any(layer == "JOINTS" and abs(cx - x) <= 1e-6 and abs(cy - y) <= 1e-6 for layer, cx, cy, _ in circles):
            bad.append(f"point {p}: no circle on JOINTS at ({x:.6f}, {y:.6f}) mm")
        if p not in names:
            bad.append(f"point {p}: its name is not written")
    forces = [t[3] for t in texts if re.fullmatch(r"\S+ = -?[0-9.]+(E[-+][0-9]+)? N", t[3])]
    if not forces:
        bad.append("no force labelled")
    force_lines = [ln for ln in lines if ln[0] == "FORCES"]
    tips = {}
    for ln in force_lines:
        for end in ((ln[1], ln[2]), (ln[3], ln[4])):
            key = (round(end[0], 4), round(end[1], 4))
            tips[key] = tips.get(key, 0) + 1
    arrows = sum(1 for n in tips.values() if n >= 3)
    if arrows < len(forces):
        bad.append(f"{len(forces)} forces labelled but {arrows} arrow tips (three lines meeting) on FORCES")
    if bad:
        print(f"{sys.argv[1]}:")
        print("\n".join(bad[:30]))
        sys.exit(1)


if __name__ == "__main__":
    main()
