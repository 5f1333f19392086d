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

  svg_check.py labels SHEET.svg...
      No two text labels of a sheet overlap. A label's box: width = 0.6 x font size x
      characters (UTF-8 characters, so a Cyrillic letter counts once), height = font size,
      from 0.8 x font size above the baseline to 0.2 x font size below it (the font size of
      the element's class in the sheet's style sheet, or its own font-size); horizontally
      placed by its text-anchor (start: from x; middle: centred on x; end: ending at x);
      a rotate(a cx cy) transform turns the box (its bounding box is taken).
      Two boxes overlap when their intersection is wider and taller than 0.01 mm; a box
      must lie on the sheet (its viewBox). Every overlapping pair and every label off the
      sheet is printed with its text and position.

  svg_check.py english SHEET...
      No English word in a --lang ru sheet or table: a word of three or more Latin letters
      that is in the list ENGLISH_WORDS fails (symbols such as F21, MPhi3 are not words of
      the list; file paths and the program's name "KINETOSTAT <KIND>" are skipped; in a
      sheet only <text> is read, not its <title>/<desc> metadata, and of the subtitle
      "deck: PATH   TITLE" only its first word: the deck's title is the user's words).
      Prints every hit.

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


# A long run's curves (kinetostat_row_keeper): every step up to ALL_ROWS steps; beyond, per
# bucket of the run's steps (SHEET_BUCKETS of them, halved for a curve of two coordinates)
# the smallest and the largest value of each coordinate.
ALL_ROWS = 4096
SHEET_BUCKETS = 2048


def check_thinned(svg_path, p, name, points, ox, oy, scale, magnitude, angle):
    """A long run's hodograph drawn through some of its steps: at most 4096 points, each the
    force of a step (in step order, within the drawing's rounding), and in every one of the
    1024 buckets of steps (bucket b: the steps k with floor((k - 1) 1024 / n) = b - 1) the
    largest and smallest x and y components of the bucket among them: every peak survives."""
    steps, drawn = int(p.get("data-steps")), int(p.get("data-thinned"))
    if steps != len(magnitude) or drawn != len(points) or drawn > ALL_ROWS:
        fail(f"{svg_path}: {name}: {drawn} points drawn ({len(points)} in the path, at most {ALL_ROWS}) "
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
    # every bucket's extremes are drawn
    buckets = SHEET_BUCKETS // 2
    members = [[] for _ in range(buckets)]
    for j in range(steps):
        members[(j * buckets) // steps].append(j)
    # drawn points near each step (the drawing's rounding), found through a grid of cells
    cells = {}
    for d in drawn_f:
        cells.setdefault((round(d[0] / tol), round(d[1] / tol)), []).append(d)

    def is_drawn(j):
        cx, cy = round(ex[j] / tol), round(ey[j] / tol)
        return any(abs(d[0] - ex[j]) <= tol and abs(d[1] - ey[j]) <= tol
                   for i in (-1, 0, 1) for m in (-1, 0, 1) for d in cells.get((cx + i, cy + m), ()))
    for b, ks in enumerate(members):
        for values, coordinate in ((ex, 0), (ey, 1)):
            for j in (max(ks, key=lambda i: values[i]), min(ks, key=lambda i: values[i])):
                if not is_drawn(j):
                    fail(f"{svg_path}: {name}: bucket {b + 1} of {buckets}: the extreme "
                         f"{'xy'[coordinate]} component at step {j + 1} ({ex[j]:.6g}, {ey[j]:.6g}) N is not drawn")
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


def text_boxes(svg_path):
    """(box, text) of every <text>: box = (x0, y0, x1, y1) in mm as the docstring says."""
    source = open(svg_path, encoding="utf-8").read()
    sizes = {}
    for cls, body in re.findall(r"\.([A-Za-z_-]+)\s*\{([^}]*)\}", source):
        m = re.search(r"font-size:\s*([0-9.]+)px", body)
        if m:
            sizes[cls] = float(m.group(1))
    root = ET.fromstring(source)
    boxes = []
    for el in root.iter(SVG_NS + "text"):
        text = "".join(el.itertext())
        if not text.strip():
            continue
        size = None
        if el.get("font-size"):
            size = float(el.get("font-size").replace("px", ""))
        style = el.get("style") or ""
        m = re.search(r"font-size:\s*([0-9.]+)", style)
        if m:
            size = float(m.group(1))
        if size is None:
            for cls in (el.get("class") or "").split():
                if cls in sizes:
                    size = sizes[cls]
        if size is None:
            size = 16.0  # the SVG default: a label without a size is a bug the test shows
        x = float(el.get("x", "0"))
        y = float(el.get("y", "0"))
        width = 0.6 * size * len(text)
        anchor = el.get("text-anchor", "start")
        x0 = {"start": x, "middle": x - width / 2, "end": x - width}[anchor]
        box = (x0, y - 0.8 * size, x0 + width, y + 0.2 * size)
        m = re.search(r"rotate\(\s*([-0-9.]+)[ ,]+([-0-9.]+)[ ,]+([-0-9.]+)\s*\)", el.get("transform") or "")
        if m:  # the box's corners turned about the centre of rotation, then their bounding box
            a, cx, cy = (float(v) for v in m.groups())
            c, s_ = math.cos(math.radians(a)), math.sin(math.radians(a))
            corners = [(cx + c * (px - cx) - s_ * (py - cy), cy + s_ * (px - cx) + c * (py - cy))
                       for px in (box[0], box[2]) for py in (box[1], box[3])]
            box = (min(p[0] for p in corners), min(p[1] for p in corners),
                   max(p[0] for p in corners), max(p[1] for p in corners))
        boxes.append((box, text))
    return boxes


def check_labels(paths):
    bad = []
    for path in paths:
        boxes = text_boxes(path)
        view = [float(v) for v in ET.parse(path).getroot().get("viewBox").split()]
        for (b, text) in boxes:
            if b[0] < view[0] - 0.01 or b[2] > view[0] + view[2] + 0.01 or b[1] < view[1] - 0.01 or \
                    b[3] > view[1] + view[3] + 0.01:
                bad.append(f"{path}: {text!r} at ({b[0]:.2f}, {b[3]:.2f}) leaves the sheet "
                           f"(its box ends at x = {b[2]:.2f} mm of {view[2]:.2f})")
        for i in range(len(boxes)):
            (a, ta) = boxes[i]
            for j in range(i + 1, len(boxes)):
                (b, tb) = boxes[j]
                w = min(a[2], b[2]) - max(a[0], b[0])
                h = min(a[3], b[3]) - max(a[1], b[1])
                if w > 0.01 and h > 0.01:
                    bad.append(f"{path}: {ta!r} at ({a[0]:.2f}, {a[3]:.2f}) overlaps {tb!r} at "
                               f"({b[0]:.2f}, {b[3]:.2f}) by {w:.2f} x {h:.2f} mm")
    if bad:
        print("\n".join(bad[:40]))
        fail(f"{len(bad)} overlapping label pairs")


ENGLISH_WORDS = set("""
spur helical bevel planetary worm series parallel balance contact mesh carrier sun ring teeth
dyad dyads mode driver driven output echoed below derived global coordinates coordinate base
radius pitch pressure follower profile lift rise return dwell flat translating roller
the of and for from with at to in on by per step steps forces force pair weight inertia load loads
lengths length angle angles deg counterclockwise axis frame mechanism deck gravity down sheet
hodographs hodograph tip each vector over cycle point zero driving moment mean magnitudes
magnitude stage stages plan plans velocities velocity accelerations acceleration polygon lever
balancing scale pole normal tangential coriolis relative group groups input link links crank
rocker slider guide results result note notes total gear gears ratio efficiency torque power
speed teeth module wheel pinion cam follower echo data summary warning error residual check
self max min largest smallest value values of tables right up origin input work per cycle
""".split())


def check_english(paths):
    hits = []
    for path in paths:
        for n, line in enumerate(open(path, encoding="utf-8"), 1):
            if path.endswith(".svg"):
                if line.startswith("<desc>") or line.startswith("<title>") or "<text" not in line:
                    continue
                if 'class="subtitle"' in line:  # "deck: PATH   TITLE": the title is the deck's own words
                    line = line.split(":")[0] + "<"
                line = "".join(re.findall(r">([^<]*)</text>", line))
            # not words: file paths, the program's name with its kind ("KINETOSTAT GEARS")
            line = re.sub(r"\S*/\S*|\S+\.nml\b|KINETOSTAT\s+[A-Z]+", " ", line)
            # deck variable names echoed as the 1991 printouts did ("CRANK_M   =", "VALUE(25) =")
            line = re.sub(r"^\s+[A-Z][A-Z0-9_]*(\([0-9]+\))?\s*=", "= ", line)
            line = re.sub(r"^\s*НАЗВАНИЕ:.*", " ", line)  # the deck's title: the user's words
            line = re.sub(r"\b\w*_\w*\b", " ", line)
            line = re.sub(r"=\s+[a-z]+\b", "= ", line)  # a keyword the deck gave ("LAYOUT = series")
            for unit in re.findall(r"[0-9]\s+(N\*m|N|deg|kg)(?![\w*])", line):
                hits.append(f"{path}:{n}: unit {unit!r} in {line.strip()[:120]!r}")
            for word in re.findall(r"[A-Za-z]{3,}", line):
                if word.lower() in ENGLISH_WORDS:
                    hits.append(f"{path}:{n}: {word!r} in {line.strip()[:120]!r}")
    if hits:
        print("\n".join(hits[:400]))
        fail(f"{len(hits)} English words")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "hodographs":
        check_hodographs(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "png":
        check_png(sys.argv[2], sys.argv[3])
    elif len(sys.argv) >= 3 and sys.argv[1] == "labels":
        check_labels(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "english":
        check_english(sys.argv[2:])
    elif len(sys.argv) == 3 and sys.argv[1] == "self-contained":
        check_self_contained(sys.argv[2])
    else:
        fail(__doc__)


if __name__ == "__main__":
    main()
