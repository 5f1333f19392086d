#!/usr/bin/env python3
r"""Read back kinetostat's DXF sheets (--format dxf [--at K]; standard library only).

  dxf_check.py DRAWING.dxf [RUN.csv K]
      Parses the ASCII DXF as group-code/value pairs (999 comments read apart) and checks:
      the sections HEADER, TABLES, ENTITIES in that order and the closing EOF; the paper's
      size in $LIMMAX is an ISO size A4..A1 (portrait or landscape); the layer table
      defines LINKS, JOINTS, GUIDES, FORCES, TEXT, VPLAN, APLAN, POLYGONS, LEVER, SCALES,
      FRAME, CHARTS, PROFILE; every entity is a LINE, CIRCLE, ARC, SOLID, TEXT or POLYLINE
      (its VERTEXes, SEQEND) on a defined layer with numeric coordinates, inside the paper (an
      ARC by the points of its sweep); every TEXT is ASCII (beyond it AutoCAD's
      \U+XXXX, decoded for the checks below); the frame (20 mm from the left edge, 5 mm
      from the others) is drawn on FRAME.
      With RUN.csv and K (the mechanism at step K): the comment "kinetostat group mechanism
      data-origin=X Y data-scale=S data-rotation=R" gives the view (sheet mm from the top
      left, mm per m, deg), and every joint of step K in RUN.csv (x_P, y_P of `--format csv
      --kinematics`, m; a centre of mass S<i> when the drawing names it) has a circle on
      JOINTS at origin + S * (p turned by R) (y up: DXF y = height - sheet y; within 2e-6
      mm) and its name as a TEXT; every force labelled on TEXT ("NAME = VALUE N") has its
      arrow: as many arrowheads (SOLID on FORCES) as labelled forces at least.
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


ISO_SIZES = {(210, 297), (297, 420), (420, 594), (594, 841)}
LAYERS = ("LINKS", "JOINTS", "GUIDES", "FORCES", "TEXT", "VPLAN", "APLAN", "POLYGONS", "LEVER", "SCALES", "FRAME",
          "CHARTS", "PROFILE")


def decoded(text):
    """A DXF text with AutoCAD's \\U+XXXX escapes decoded."""
    return re.sub(r"\\U\+([0-9A-Fa-f]{4})", lambda m: chr(int(m.group(1), 16)), text)


def main():
    if len(sys.argv) not in (2, 4):
        print(__doc__)
        sys.exit(1)
    bad = []
    try:
        groups = pairs(sys.argv[1])
    except (ValueError, UnicodeDecodeError) as e:
        print(f"{sys.argv[1]}: not an ASCII DXF: {e}")
        sys.exit(1)
    comments = [v for c, v in groups if c == 999]
    groups = [(c, v) for c, v in groups if c != 999]
    sections, layers, entities, header = [], set(), [], {}
    i = 0
    current = None
    while i < len(groups):
        code, value = groups[i]
        if current == "HEADER" and code == 9:
            header[value] = [v for c, v in groups[i + 1:i + 3] if c in (10, 20, 70, 1)]
            i += 1
            continue
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
    for name in LAYERS:
        if name not in layers:
            bad.append(f"layer {name} not defined")
    try:
        width, height = (float(v) for v in header["$LIMMAX"][:2])
    except (KeyError, ValueError):
        width = height = 0.0
        bad.append("no paper size ($LIMMAX)")
    if (round(min(width, height)), round(max(width, height))) not in ISO_SIZES:
        bad.append(f"paper {width} x {height} mm is not an ISO size A4..A1")
    circles, lines, texts = [], [], []
    for e in entities:
        if e.get(8) not in layers:
            bad.append(f"{e['type']} on undefined layer {e.get(8)!r}")
        try:
            if e["type"] in ("LINE", "SOLID"):
                if e["type"] == "LINE":
                    lines.append((e[8], float(e[10]), float(e[20]), float(e[11]), float(e[21])))
                points = [(float(e[10 + k]), float(e[20 + k])) for k in ((0, 1) if e["type"] == "LINE" else (0, 1, 2, 3))]
            elif e["type"] == "CIRCLE":
                circles.append((e[8], float(e[10]), float(e[20]), float(e[40])))
                points = [(float(e[10]) + dx * float(e[40]), float(e[20]) + dy * float(e[40]))
                          for dx, dy in ((-1, -1), (1, 1))]
            elif e["type"] == "ARC":
                start, end = float(e[50]), float(e[51])
                sweep = (end - start) % 360 or 360
                points = [(float(e[10]) + float(e[40]) * math.cos(math.radians(start + sweep * k / 72)),
                           float(e[20]) + float(e[40]) * math.sin(math.radians(start + sweep * k / 72)))
                          for k in range(73)]
            elif e["type"] in ("POLYLINE", "SEQEND"):
                points = [(float(e.get(10, 0)), float(e.get(20, 0)))]
            elif e["type"] == "VERTEX":
                points = [(float(e[10]), float(e[20]))]
            elif e["type"] == "TEXT":
                if not all(32 <= ord(ch) < 127 for ch in e[1]):
                    bad.append(f"TEXT {e[1]!r} is not ASCII")
                texts.append((e[8], float(e[10]), float(e[20]), decoded(e[1])))
                points = [(float(e[10]), float(e[20]))]
            else:
                bad.append(f"unexpected entity {e['type']}")
                continue
        except (KeyError, ValueError) as err:
            bad.append(f"{e['type']} without a numeric group: {err}")
            continue
        for x, y in points:
            if not (-0.01 <= x <= width + 0.01 and -0.01 <= y <= height + 0.01):
                bad.append(f"{e['type']} on {e.get(8)} at ({x:.3f}, {y:.3f}) leaves the {width} x {height} mm paper")
                break
    frame = {(round(a, 3), round(b, 3), round(c, 3), round(d, 3)) for layer, a, b, c, d in lines if layer == "FRAME"}
    for edge in ((20.0, 5.0, width - 5, 5.0), (width - 5, 5.0, width - 5, height - 5), (20.0, 5.0, 20.0, height - 5)):
        key = tuple(round(v, 3) for v in edge)
        if key not in frame and (key[2], key[3], key[0], key[1]) not in frame:
            bad.append(f"no frame line {edge} on FRAME")
    if len(sys.argv) == 2:
        report(bad)
        return
    view = None
    for c in comments:
        m = re.match(r"kinetostat group mechanism data-origin=([-0-9.]+) ([-0-9.]+) data-scale=(\S+) "
                     r"data-rotation=(\S+)", c)
        if m:
            view = [float(v) for v in m.groups()]
    if view is None:
        bad.append("no comment 'kinetostat group mechanism data-origin=... data-scale=... data-rotation=...'")
        report(bad)
        return
    ox, oy, scale, rotation = view
    oy = height - oy
    cr, sr = math.cos(math.radians(rotation)), math.sin(math.radians(rotation))
    rows = list(csv.DictReader(open(sys.argv[2], newline="")))
    row = rows[int(sys.argv[3]) - 1]
    names = {t[3] for t in texts}
    for key in row:
        if not key.startswith("x_"):
            continue
        p = key[2:]
        if re.fullmatch(r"S\w+", p) and p not in names:
            continue  # a centre of mass the drawing does not show (its link is named otherwise)
        px, py = float(row["x_" + p]), float(row["y_" + p])
        x, y = ox + scale * (cr * px - sr * py), oy + scale * (sr * px + cr * py)
        if not any(layer == "JOINTS" and abs(cx - x) <= 2e-6 and abs(cy - y) <= 2e-6 for layer, cx, cy, _ in circles):
            bad.append(f"point {p}: no circle on JOINTS at ({x:.6f}, {y:.6f}) mm")
        if p not in names:
            bad.append(f"point {p}: its name is not written")
    # the labels of the arrows (a force of 0 N is listed, not drawn)
    forces = [t[3] for t in texts if re.fullmatch(r"\S+ = -?[0-9.]+(E[-+][0-9]+)? [NН]", t[3])
              and float(t[3].split(" = ")[1].split()[0]) != 0]
    if not forces:
        bad.append("no force labelled")
    heads = sum(1 for e in entities if e["type"] == "SOLID" and e.get(8) == "FORCES")
    if heads < len(forces):
        bad.append(f"{len(forces)} forces labelled but {heads} arrowheads (SOLID) on FORCES")
    report(bad)


def report(bad):
    if bad:
        print(f"{sys.argv[1]}:")
        print("\n".join(bad[:30]))
        sys.exit(1)


if __name__ == "__main__":
    main()
