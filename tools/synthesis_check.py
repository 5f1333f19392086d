#!/usr/bin/env python3
r"""Read back the design kinds' sheets (kinetostat --format svg / dxf of &gear_geometry and
&cam_profile; standard library only).

  synthesis_check.py involutes SHEET.svg RUN.csv
      The meshing drawing of a gear pair: the group of class "meshing" gives the view
      (data-origin "X Y" in sheet mm, data-scale in sheet mm per mm, data-rotation 90: the
      pair's point q = (x, y) sits at X - S*y, Y - S*x), data-a-w the centre distance. Every
      path with data-flank = N (a flank of gear N) is read back into the pair's frame, about
      gear N's centre (O1 at the origin, O2 at (a_w, 0)), and must lie on one involute of
      that gear's base circle (r_b = db/2 of RUN.csv, --format csv): with r its points'
      radii and theta their polar angles, theta -/+ inv(acos(r_b/r)) is the involute's start
      angle, the same for every point; since the involutes of a circle are parallel curves
      r_b apart per radian, r_b times the spread of that angle is the points' distance
      across the involutes, at most 0.015 mm of the sheet (coordinates are written to 0.01
      mm) over the scale. Every point lies between the base and the tip circle (da/2), and
      each gear has at least six flanks.

  synthesis_check.py cam-profile DRAWING.dxf RUN.csv
      The cam's actual profile in the DXF: exactly one POLYLINE on layer PROFILE, closed
      (flag 70 = 1); the comment "kinetostat group cam data-origin=X Y data-scale=S ...
      data-subdivision=N" gives the cam frame (sheet mm from the top left, mm per m) and the
      vertices per output step; the polyline has N * (rows - 1) vertices (the 360 deg row is
      the 0 deg one) and vertex j*N, read back into the cam frame (m), is RUN.csv's
      (x_profile, y_profile) of row j + 1 within 2e-6 mm of the paper over the scale.

Prints what it checked; on failure every mismatch (expected vs read) and exits 1.
"""
import csv
import math
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"


def fail(lines):
    print("\n".join(lines[:40]))
    sys.exit(1)


def involute(a):
    return math.tan(a) - a


def path_points(d):
    return [(float(x), float(y)) for x, y in re.findall(r"[ML]\s*([-0-9.]+)[ ,]([-0-9.]+)", d)]


def check_involutes(svg_path, csv_path):
    row = next(csv.DictReader(open(csv_path, newline="")))
    root = ET.parse(svg_path).getroot()
    group = next((g for g in root.iter(SVG + "g") if g.get("class") == "meshing"), None)
    if group is None:
        fail([f"{svg_path}: no group of class meshing"])
    ox, oy = (float(v) for v in group.get("data-origin").split())
    scale = float(group.get("data-scale"))
    if float(group.get("data-rotation")) != 90.0:
        fail([f"{svg_path}: data-rotation {group.get('data-rotation')}, expected 90"])
    a_w = float(group.get("data-a-w"))
    if abs(a_w - float(row["a_w"])) > 1e-9 * a_w:
        fail([f"a_w: sheet {a_w}, CSV {row['a_w']}"])
    tolerance = 0.015 / scale
    bad, counts, worst = [], {1: 0, 2: 0}, 0.0
    for el in group.iter(SVG + "path"):
        gear = el.get("data-flank")
        if gear is None:
            continue
        n = int(gear)
        rb, ra = float(row[f"db{n}"]) / 2, float(row[f"da{n}"]) / 2
        cx = 0.0 if n == 1 else a_w
        pts = []
        for X, Y in path_points(el.get("d")):
            x, y = (oy - Y) / scale - cx, (ox - X) / scale
            pts.append((math.hypot(x, y), math.atan2(y, x)))
        counts[n] += 1
        for r, _ in pts:
            if not rb - tolerance <= r <= ra + tolerance:
                bad.append(f"gear {n}: a flank point at r = {r:.4f} mm, outside r_b = {rb:.4f} .. r_a = {ra:.4f}")
        # the start angle both ways an involute unwinds; the flank is one of them
        best = None
        for sense in (1, -1):
            starts = [theta - sense * involute(math.acos(min(1.0, rb / max(r, rb)))) for r, theta in pts]
            ref = starts[0]
            spread = max(abs(math.remainder(s - ref, 2 * math.pi)) for s in starts) * rb
            best = spread if best is None else min(best, spread)
        worst = max(worst, best)
        if best > 2 * tolerance:
            bad.append(f"gear {n}: flank {counts[n]} is {best:.4f} mm off an involute of r_b = {rb:.4f} mm "
                       f"(tolerance {2 * tolerance:.4f})")
    for n in (1, 2):
        if counts[n] < 6:
            bad.append(f"gear {n}: {counts[n]} flanks drawn, expected 6 at least")
    if bad:
        fail([f"{svg_path}:"] + bad)
    print(f"involutes: {counts[1]} + {counts[2]} flanks on their base circles' involutes, "
          f"largest distance {worst:.2e} mm (tolerance {2 * tolerance:.2e})")


def dxf_records(path):
    lines = open(path, encoding="ascii").read().split("\n")
    pairs = [(int(lines[i].strip()), lines[i + 1]) for i in range(0, len(lines) - 1, 2)]
    comments = [v for c, v in pairs if c == 999]
    records, current = [], None
    for code, value in pairs:
        if code == 999:
            continue
        if code == 0:
            current = {"type": value}
            records.append(current)
        elif current is not None:
            current.setdefault(code, value)
    return comments, records


def check_cam_profile(dxf_path, csv_path):
    rows = list(csv.DictReader(open(csv_path, newline="")))
    comments, records = dxf_records(dxf_path)
    text = open(dxf_path, encoding="ascii").read()
    m = re.search(r"\$LIMMAX\n\s*10\n([-0-9.]+)\n\s*20\n([-0-9.]+)", text)
    height = float(m.group(2))
    view = None
    for c in comments:
        m = re.match(r"kinetostat group cam data-origin=([-0-9.]+) ([-0-9.]+) data-scale=(\S+) .*"
                     r"data-subdivision=(\d+)", c)
        if m:
            view = (float(m.group(1)), float(m.group(2)), float(m.group(3)), int(m.group(4)))
    if view is None:
        fail([f"{dxf_path}: no comment 'kinetostat group cam data-origin=... data-subdivision=...'"])
    ox, oy, scale, sub = view
    polylines, k = [], 0
    while k < len(records):
        r = records[k]
        if r["type"] == "POLYLINE" and r.get(8) == "PROFILE":
            vertices = []
            k += 1
            while k < len(records) and records[k]["type"] == "VERTEX":
                vertices.append((float(records[k][10]), float(records[k][20])))
                k += 1
            polylines.append((r.get(70, "0").strip(), vertices))
            continue
        k += 1
    if len(polylines) != 1:
        fail([f"{dxf_path}: {len(polylines)} POLYLINEs on layer PROFILE, expected 1"])
    flag, vertices = polylines[0]
    bad = []
    if flag != "1":
        bad.append(f"the profile's POLYLINE is not closed (70 = {flag})")
    if len(vertices) != sub * (len(rows) - 1):
        bad.append(f"{len(vertices)} vertices, expected {sub} x {len(rows) - 1} = {sub * (len(rows) - 1)}")
    tolerance = 2e-6 / scale
    worst = 0.0
    for j, row in enumerate(rows[:-1]):
        if j * sub >= len(vertices):
            break
        X, Y = vertices[j * sub]
        x, y = (X - ox) / scale, (Y - (height - oy)) / scale
        ex, ey = float(row["x_profile"]), float(row["y_profile"])
        d = math.hypot(x - ex, y - ey)
        worst = max(worst, d)
        if d > tolerance + 1e-12:
            bad.append(f"phi = {row['phi']}: vertex ({x:.9f}, {y:.9f}) m, CSV ({ex:.9f}, {ey:.9f}) m")
    if bad:
        fail([f"{dxf_path}:"] + bad)
    print(f"cam-profile: a closed POLYLINE of {len(vertices)} vertices on PROFILE, the CSV's {len(rows) - 1} "
          f"points among them, largest distance {worst:.2e} m (tolerance {tolerance:.2e})")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "involutes":
        check_involutes(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "cam-profile":
        check_cam_profile(sys.argv[2], sys.argv[3])
    else:
        fail([__doc__])


if __name__ == "__main__":
    main()
