#!/usr/bin/env python3
"""Checks of kinetostat's SVG sheets (used by test/cli/test_svg.sh; standard library only).

  svg_check.py hodographs SHEET.svg RUN.csv
      Every hodograph path of the sheet (class "hodograph") read back into forces:
      F = ((X - ox) / s, (oy - Y) / s) with data-origin = "ox oy" (mm) and data-scale = s
      (mm per N), point k = step k. Each must equal the CSV's components of that pair,
      x = F cos(FG), y = F sin(FG) (and the CSV's own x/y component columns where it has
      them: Fx/Fy or F_x/F_y), within the drawing's rounding: coordinates are written to
      0.01 mm and the origin lies on that grid, so |error| <= 0.005 mm / s per component
      (tolerance 0.0051 mm / s + 1e-9 relative). Prints expected vs computed on failure.

  svg_check.py png IMAGE.png SHEET.svg
      The PNG (rsvg-convert at 96 px per inch) has the sheet's size (width and height in mm
      * 96 / 25.4, +-1 px) and is not blank: at least 1 % of its pixels are not white and
      it has more than two colours.

  svg_check.py self-contained SHEET.svg
      No reference to anything outside the file: no href, no url(), no @import, no script,
      no font other than the generic families.

Exit status 0 when the check passes, 1 with a message when it fails.
"""
import csv
import math
import re
import struct
import sys
import zlib
import xml.etree.ElementTree as ET

SVG_NS = "{http://www.w3.org/2000/svg}"


def fail(message):
    print(message)
    sys.exit(1)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = rows[0]
    # an empty field is a step without a value (a jammed cam follower), drawn at 0
    return {name: [float(r[i]) if r[i] != "" else 0.0 for r in rows[1:]] for i, name in enumerate(header)}


def path_points(d):
    """Points of an "M x y L x y ..." path."""
    tokens = d.split()
    points = []
    i = 0
    while i < len(tokens):
        if tokens[i] not in ("M", "L"):
            fail(f"unexpected path token {tokens[i]!r}")
        points.append((float(tokens[i + 1]), float(tokens[i + 2])))
        i += 3
    return points


def check_hodographs(svg_path, csv_path):
    columns = read_csv(csv_path)
    root = ET.parse(svg_path).getroot()
    paths = [p for p in root.iter(SVG_NS + "path") if p.get("class") == "hodograph"]
    if not paths:
        fail(f"{svg_path}: no hodograph path")
    worst = 0.0
    compared = 0
    for p in paths:
        name = p.get("data-force")
        ox, oy = (float(v) for v in p.get("data-origin").split())
        scale = float(p.get("data-scale"))
        points = path_points(p.get("d"))
        if name not in columns or name + "G" not in columns:
            fail(f"{svg_path}: hodograph {name} has no {name}/{name}G columns in {csv_path}")
        magnitude, angle = columns[name], columns[name + "G"]
        if p.get("data-thinned") is not None:
            compared += check_thinned(svg_path, p, name, points, ox, oy, scale, magnitude, angle)
            continue
        if len(points) != len(magnitude):
            fail(f"{svg_path}: hodograph {name} has {len(points)} points, the CSV {len(magnitude)} steps")
        references = [("magnitude/angle",
                       [m * math.cos(math.radians(a)) for m, a in zip(magnitude, angle)],
                       [m * math.sin(math.radians(a)) for m, a in zip(magnitude, angle)])]
        for cx, cy in ((name + "x", name + "y"), (name + "_x", name + "_y")):
            if cx in columns and cy in columns:
                references.append((f"{cx}/{cy} columns", columns[cx], columns[cy]))
        for k, (x, y) in enumerate(points):
            fx, fy = (x - ox) / scale, (oy - y) / scale
            for label, ex, ey in references:
                tol = 0.0051 / scale + 1e-9 * math.hypot(ex[k], ey[k])
                err = max(abs(fx - ex[k]), abs(fy - ey[k]))
                worst = max(worst, err * scale)
                compared += 1
                if err > tol:
                    fail(f"{svg_path}: {name} step {k + 1}: expected ({ex[k]:.6g}, {ey[k]:.6g}) N from the CSV's "
                         f"{label}, the path gives ({fx:.6g}, {fy:.6g}) N; error {err:.3g} N > tolerance {tol:.3g} N")
    print(f"{len(paths)} hodographs, {compared} point comparisons, largest error {worst:.4f} mm on the sheet")


def check_thinned(svg_path, p, name, points, ox, oy, scale, magnitude, angle):
    """A long run's hodograph drawn through some of its steps: at most 2000 points, each the
    force of a step (in step order, within the drawing's rounding), and the largest and
    smallest x and y components of the whole run among them (the curve keeps its extremes)."""
    steps, drawn = int(p.get("data-steps")), int(p.get("data-thinned"))
    if steps != len(magnitude) or drawn != len(points) or drawn > 2000:
        fail(f"{svg_path}: {name}: {drawn} points drawn ({len(points)} in the path, at most 2000) "
             f"of {steps} steps ({len(magnitude)} in the CSV)")
    ex = [m * math.cos(math.radians(a)) for m, a in zip(magnitude, angle)]
    ey = [m * math.sin(math.radians(a)) for m, a in zip(magnitude, angle)]
    tol = 0.0051 / scale + 1e-9 * max(map(abs, magnitude))
    k = 0
    drawn_f = []
    for x, y in points:
        fx, fy = (x - ox) / scale, (oy - y) / scale
        while k < steps and max(abs(fx - ex[k]), abs(fy - ey[k])) > tol:
            k += 1
        if k == steps:
            fail(f"{svg_path}: {name}: drawn point ({fx:.6g}, {fy:.6g}) N is no step's force (in step order)")
        drawn_f.append((fx, fy))
    for label, values, got in (("x", ex, [f[0] for f in drawn_f]), ("y", ey, [f[1] for f in drawn_f])):
        for what, want, have in (("largest", max(values), max(got)), ("smallest", min(values), min(got))):
            if abs(want - have) > tol:
                fail(f"{svg_path}: {name}: {what} {label} component {want:.6g} N of the run, drawn {have:.6g} N")
    return len(points)


def png_pixels(path):
    """Width, height and rows of RGBA tuples of an 8-bit RGB or RGBA PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path}: not a PNG")
    pos = 8
    idat = b""
    width = height = None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace != 0:
                fail(f"{path}: unsupported PNG (depth {depth}, colour type {colour}, interlace {interlace})")
            channels = 4 if colour == 6 else 3
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows = []
    previous = bytearray(stride)
    i = 0
    for _ in range(height):
        kind = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        if kind == 0:
            rows.append(bytes(line))
            previous = line
            continue
        if kind == 2:
            line = bytearray((u + v) & 255 for u, v in zip(line, previous))
            rows.append(bytes(line))
            previous = line
            continue
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pred) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def check_png(png_path, svg_path):
    root = ET.parse(svg_path).getroot()
    mm = [float(root.get(k).removesuffix("mm")) for k in ("width", "height")]
    expected = [round(v * 96 / 25.4) for v in mm]
    width, height, channels, rows = png_pixels(png_path)
    if abs(width - expected[0]) > 1 or abs(height - expected[1]) > 1:
        fail(f"{png_path}: {width} x {height} px, expected {expected[0]} x {expected[1]} px "
             f"({mm[0]} x {mm[1]} mm at 96 px per inch)")
    white = (0xFFFFFFFF,) if channels == 4 else None
    inked = 0
    colours = set()
    for row in rows:
        if channels == 4:
            pixels = memoryview(row).cast("I")  # one RGBA pixel per 32-bit word
            inked += len(pixels) - pixels.tolist().count(white[0])
            if len(colours) < 64:
                colours.update(pixels.tolist()[:64])
        else:
            for x in range(0, len(row), 3):
                if row[x:x + 3] != b"\xff\xff\xff":
                    inked += 1
                if len(colours) < 64:
                    colours.add(bytes(row[x:x + 3]))
    share = inked / (width * height)
    if share < 0.01 or len(colours) <= 2:
        fail(f"{png_path}: looks blank: {100 * share:.2f} % of the pixels are not white (expected >= 1 %), "
             f"{len(colours)} colours (expected > 2)")
    print(f"{png_path}: {width} x {height} px, {100 * share:.1f} % inked, {len(colours)}+ colours")


def check_self_contained(svg_path):
    text = open(svg_path, encoding="utf-8").read()
    for pattern in (r"href", r"url\(", r"@import", r"<script", r"<image", r"<foreignObject"):
        if re.search(pattern, text):
            fail(f"{svg_path}: refers outside itself ({pattern})")
    for family in re.findall(r"font-family:\s*([^;]+);", text) + re.findall(r'font-family="([^"]+)"', text):
        if family.strip() not in ("sans-serif", "serif", "monospace"):
            fail(f"{svg_path}: font-family {family!r} is not a generic family")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "hodographs":
        check_hodographs(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "png":
        check_png(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3 and sys.argv[1] == "self-contained":
        check_self_contained(sys.argv[2])
    else:
        fail(__doc__)


if __name__ == "__main__":
    main()
