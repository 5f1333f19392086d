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
      No two text labels of a sheet overlap. A label's box: each run of its text (its own
      text, each <tspan>, the text after a <tspan>) 0.6 x font size x characters wide (UTF-8
      characters, so a Cyrillic letter counts once), reaching from 0.8 x its font size above
      its baseline to 0.2 x it below (the font size of the element's own font-size, style or
      class; a <tspan>'s dy moves the baseline for it and what follows), the runs side by
      side; horizontally placed by its text-anchor (start: from x; middle: centred on x;
      end: ending at x); a rotate(a cx cy) transform turns the box (its bounding box).
      Two boxes overlap when their intersection is wider and taller than 0.01 mm; a box
      must lie on the sheet (its viewBox). Every overlapping pair and every label off the
      sheet is printed with its text and position.

  svg_check.py labels --lines SHEET...
      The same, and no label lies over a line drawn on the sheet: every <line>, <path> (M/L
      polylines), <polygon>, <polyline> and <rect> edge as a band of its stroke width (its
      stroke-width attribute, style or class), every <circle> as a disc (radius + half its
      stroke); the classes grid, ray and paper (light construction lines under everything)
      are not counted. A label's leader line (class "leader") may touch its own label. A box
      closer than its band by more than 0.01 mm fails. Prints the number of leader lines.

  svg_check.py notation en|ru SHEET...
      Typeset labels: no "_" or "^" markup in any <text> but the subtitle (the deck's path and
      title); with ru also no run of two or more Latin letters in a run of text but point
      names (the sheet's data-joint, data-point, data-image values), lowered or raised point
      letters (v_CB), the program's name (kinetostat, "KINETOSTAT <KIND>" opening the title).

  svg_check.py english SHEET...
      No English word in a --lang ru sheet or table: a word of three or more Latin letters
      that is in the list ENGLISH_WORDS fails (symbols such as F21, MPhi3 are not words of
      the list; file paths and the program's name "KINETOSTAT <KIND>" are skipped; in a
      sheet only <text> is read, not its <title>/<desc> metadata, and of the subtitle
      "deck: PATH   TITLE" only its first word: the deck's title is the user's words).
      Prints every hit.

  svg_check.py batch LIST
      Each line of the file LIST, "NAME<TAB>CHECK<TAB>ARGUMENT...", is one of the checks
      above, all in this one process: prints "ok NAME" or "FAIL NAME: its message" a line,
      and fails when any failed.

Exit status 0 when the check passes, 1 with a message when it fails.
"""
import contextlib
import io
import csv
import math
import os
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
    # bytewise sums without carries between bytes, on the rows as big integers (filter Up)
    low = int.from_bytes(b"\x7f" * stride, "big")
    high = int.from_bytes(b"\x80" * stride, "big")
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
            u, v = int.from_bytes(line, "big"), int.from_bytes(previous, "big")
            line = bytearray((((u & low) + (v & low)) ^ ((u ^ v) & high)).to_bytes(stride, "big"))
            rows.append(bytes(line))
            previous = line
            continue
        # the first pixel has no left neighbour (a = c = 0), then each filter in a loop of its own
        for x in range(channels):
            b = previous[x]
            if kind == 3:
                line[x] = (line[x] + b // 2) & 255
            elif kind == 4:
                line[x] = (line[x] + b) & 255  # Paeth of (0, b, 0) is b
        if kind == 1:
            for x in range(channels, stride):
                line[x] = (line[x] + line[x - channels]) & 255
        elif kind == 3:
            for x in range(channels, stride):
                line[x] = (line[x] + (line[x - channels] + previous[x]) // 2) & 255
        elif kind == 4:
            paeth_row(line, previous, channels)
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def paeth_row(line, previous, channels):
    """Undoes the Paeth filter of a row after its first pixel, in place. Where the filtered
    byte is 0 and the row above repeats its pixel (b = c), the predictor is the left byte
    (|b - c| = 0 is the least distance), so the row repeats its last pixel there: such
    stretches are copied, the other bytes computed one by one."""
    stride = len(line)
    # the bytes that need the full rule: a filtered byte not 0, or b != c above
    changed = int.from_bytes(previous[channels:], "big") ^ int.from_bytes(previous[:-channels], "big")
    busy = bytes(line[channels:])
    marks = bytearray(changed.to_bytes(stride - channels, "big"))
    for m in re.finditer(rb"[^\x00]+", busy):
        marks[m.start():m.end()] = busy[m.start():m.end()]
    x = channels
    for m in re.finditer(rb"[^\x00]+", bytes(marks)):
        first, last = m.start() + channels, m.end() + channels
        if first > x:  # a stretch of the left pixel repeated
            span = first - x
            line[x:first] = (bytes(line[x - channels:x]) * (span // channels + 1))[:span]
        for x in range(first, last):
            a, b, c = line[x - channels], previous[x], previous[x - channels]
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            line[x] = (line[x] + (a if pa <= pb and pa <= pc else (b if pb <= pc else c))) & 255
        x = last
    if stride > x:
        span = stride - x
        line[x:stride] = (bytes(line[x - channels:x]) * (span // channels + 1))[:span]


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
                colours.update(pixels.tolist())
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


def style_sizes(source):
    """Font sizes of the text classes and stroke widths of the line classes of the style sheet."""
    sizes, widths = {}, {}
    for cls, body in re.findall(r"\.([A-Za-z_-]+)\s*\{([^}]*)\}", source):
        m = re.search(r"font-size:\s*([0-9.]+)px", body)
        if m:
            sizes[cls] = float(m.group(1))
        m = re.search(r"stroke-width:\s*([0-9.]+)", body)
        widths[cls] = float(m.group(1)) if m else 0.0
    return sizes, widths


def text_size(el, sizes, default=None):
    size = None
    if el.get("font-size"):
        size = float(el.get("font-size").replace("px", ""))
    m = re.search(r"font-size:\s*([0-9.]+)", el.get("style") or "")
    if m:
        size = float(m.group(1))
    if size is None:
        for cls in (el.get("class") or "").split():
            if cls in sizes:
                size = sizes[cls]
    return default if size is None else size


def text_runs(el, sizes):
    """(text, font size, baseline offset) of every run of a <text>: its own text, each <tspan>
    (dy moves the baseline for it and what follows), and the text after a <tspan>."""
    base = text_size(el, sizes, 16.0)  # 16: the SVG default, a label without a size is a bug shown
    runs = []
    offset = 0.0
    if el.text:
        runs.append((el.text, base, offset))
    for child in el:
        if child.tag == SVG_NS + "tspan":
            offset += float(child.get("dy", "0"))
            runs.append(("".join(child.itertext()), text_size(child, sizes, base), offset))
        if child.tail:
            runs.append((child.tail, base, offset))
    return runs, base


def text_box(el, sizes):
    """(box, text) of a <text>: a run of n characters at font size s is 0.6 s n wide and reaches
    from 0.8 s above its baseline to 0.2 s below (kinetostat_typeset's measure), the runs side by
    side; placed by text-anchor; a rotate(a cx cy) turns the box (its bounding box is taken)."""
    runs, base = text_runs(el, sizes)
    text = "".join(r[0] for r in runs)
    width = sum(0.6 * size * len(t) for t, size, _ in runs)
    top = min([off - 0.8 * size for t, size, off in runs if t] or [-0.8 * base])
    bottom = max([off + 0.2 * size for t, size, off in runs if t] or [0.2 * base])
    x = float(el.get("x", "0"))
    y = float(el.get("y", "0"))
    anchor = el.get("text-anchor", "start")
    x0 = {"start": x, "middle": x - width / 2, "end": x - width}[anchor]
    box = (x0, y + top, x0 + width, y + bottom)
    m = re.search(r"rotate\(\s*([-0-9.]+)[ ,]+([-0-9.]+)[ ,]+([-0-9.]+)\s*\)", el.get("transform") or "")
    if m:  # the box's corners turned about the centre of rotation, then their bounding box
        a, cx, cy = (float(v) for v in m.groups())
        c, s_ = math.cos(math.radians(a)), math.sin(math.radians(a))
        corners = [(cx + c * (px - cx) - s_ * (py - cy), cy + s_ * (px - cx) + c * (py - cy))
                   for px in (box[0], box[2]) for py in (box[1], box[3])]
        box = (min(p[0] for p in corners), min(p[1] for p in corners),
               max(p[0] for p in corners), max(p[1] for p in corners))
    return box, text


#: The sheets parsed so far (read_sheet), by path, modification time and size: the checks of
#: one process (a batch: tools/batch_check.py, `batch`) parse a sheet once.
SHEETS = {}


def read_sheet(svg_path):
    """(root element, font sizes, stroke widths of the style sheet's classes) of a sheet,
    parsed once for all the checks of a process (labels, notation); the checks only read it."""
    st = os.stat(svg_path)
    key = (os.path.abspath(svg_path), st.st_mtime_ns, st.st_size)
    if key not in SHEETS:
        source = open(svg_path, encoding="utf-8").read()
        sizes, widths = style_sizes(source)
        SHEETS[key] = ET.fromstring(source), sizes, widths
    return SHEETS[key]


def text_boxes(sheet):
    """(box, text) of every <text> of a sheet (read_sheet): box = (x0, y0, x1, y1) in mm as
    text_box says."""
    root, sizes, _ = sheet
    boxes = []
    for el in root.iter(SVG_NS + "text"):
        box, text = text_box(el, sizes)
        if text.strip():
            boxes.append((box, text))
    return boxes


# Light construction lines drawn under everything: not obstacles of labels.
BACKGROUND_CLASSES = {"paper", "grid", "ray"}


STROKE_WIDTH_RE = re.compile(r"stroke-width:\s*([0-9.]+)")
#: The elements drawn_segments reads, by their tag with or without the SVG namespace.
DRAWN_TAGS = {prefix + tag: tag for tag in ("line", "path", "polygon", "polyline", "rect", "circle")
              for prefix in ("", SVG_NS)}


def drawn_segments(root, widths):
    """Every line drawn on the sheet as (x1, y1, x2, y2, half width, kind): <line>, <path>
    (M/L polylines), <polygon>, <polyline>, <rect> edges, and <circle>s as (cx, cy, cx, cy,
    radius + half width, "disc"); kind "leader" for the leader lines of labels. The classes
    BACKGROUND_CLASSES (grid, rays, paper) are left out."""
    segments = []
    for el in root.iter():
        tag = DRAWN_TAGS.get(el.tag)
        if tag is None:
            continue
        classes = set((el.get("class") or "").split())
        if classes & BACKGROUND_CLASSES:
            continue
        width = None
        if el.get("stroke-width"):
            width = float(el.get("stroke-width"))
        style = el.get("style")
        m = STROKE_WIDTH_RE.search(style) if style else None
        if m:
            width = float(m.group(1))
        if width is None:
            width = max([widths.get(c, 0.0) for c in classes] or [0.0])
            if not classes and el.get("stroke") in (None, "none"):
                width = 0.0
        half = width / 2
        kind = "leader" if "leader" in classes else "line"
        if tag == "line":
            segments.append((float(el.get("x1")), float(el.get("y1")), float(el.get("x2")), float(el.get("y2")),
                             half, kind))
        elif tag == "circle":
            cx, cy, r = float(el.get("cx")), float(el.get("cy")), float(el.get("r"))
            segments.append((cx, cy, cx, cy, r + half, "disc"))
        else:
            if tag == "path":
                points = path_points(el.get("d"))
            elif tag == "rect":
                x, y, w, h = (float(el.get(k)) for k in ("x", "y", "width", "height"))
                points = [(x, y), (x + w, y), (x + w, y + h), (x, y + h), (x, y)]
            else:
                values = [float(v) for v in re.split(r"[ ,]+", el.get("points").strip())]
                points = list(zip(values[0::2], values[1::2]))
                if tag == "polygon":
                    points.append(points[0])
            for a, b in zip(points, points[1:]):
                segments.append((a[0], a[1], b[0], b[1], half, kind))
    return segments


def segment_box_distance(s, box):
    """Distance from segment s = (x1, y1, x2, y2, ...) to the box (x0, y0, x1, y1): 0 when they meet."""
    x1, y1, x2, y2 = s[:4]
    dx, dy = x2 - x1, y2 - y1
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, x1 - box[0]), (dx, box[2] - x1), (-dy, y1 - box[1]), (dy, box[3] - y1)):
        if p == 0:
            if q < 0:
                t0 = 2.0
                break
        elif p < 0:
            t0 = max(t0, q / p)
        else:
            t1 = min(t1, q / p)
    if t0 <= t1:
        return 0.0

    def point_segment(px, py):
        length2 = dx * dx + dy * dy
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - x1) * dx + (py - y1) * dy) / length2))
        return math.hypot(px - x1 - t * dx, py - y1 - t * dy)

    def point_box(px, py):
        return math.hypot(max(box[0] - px, 0.0, px - box[2]), max(box[1] - py, 0.0, py - box[3]))
    return min(point_box(x1, y1), point_box(x2, y2), point_segment(box[0], box[1]), point_segment(box[2], box[1]),
               point_segment(box[0], box[3]), point_segment(box[2], box[3]))


def lines_under_labels(path, sheet, boxes):
    """The labels of the sheet (read_sheet) at path that lie over a drawn line
    (drawn_segments), and the number of its leader lines. A leader line may touch the label
    it leads to."""
    root, _, widths = sheet
    segments = drawn_segments(root, widths)
    # each segment's bounding box and the least gap between it and a label's box at which
    # the segment cannot lie under the label
    # (comparisons written out: this loop runs over every stroke of every sheet checked)
    bounds = []
    cell = 10.0
    grid = {}
    for n, s in enumerate(segments):
        x1, y1, x2, y2, reach = s[0], s[1], s[2], s[3], s[4]
        lo_x, hi_x = (x1, x2) if x1 <= x2 else (x2, x1)
        lo_y, hi_y = (y1, y2) if y1 <= y2 else (y2, y1)
        bounds.append((lo_x, lo_y, hi_x, hi_y, reach - 0.01 + 1e-9))
        gy0, gy1 = int((lo_y - reach) // cell), int((hi_y + reach) // cell) + 1
        for gx in range(int((lo_x - reach) // cell), int((hi_x + reach) // cell) + 1):
            for gy in range(gy0, gy1):
                key = (gx, gy)
                if key in grid:
                    grid[key].append(n)
                else:
                    grid[key] = [n]
    bad = []
    for b, text in boxes:
        seen = set()
        for gx in range(int(b[0] // cell), int(b[2] // cell) + 1):
            for gy in range(int(b[1] // cell), int(b[3] // cell) + 1):
                for n in grid.get((gx, gy), []):
                    if n in seen:
                        continue
                    seen.add(n)
                    # the bounding boxes' gap is no more than the distance: a segment whose
                    # gap leaves no depth above 0.01 mm cannot lie under the label
                    sx0, sy0, sx1, sy1, gap = bounds[n]
                    if sx0 - b[2] >= gap or b[0] - sx1 >= gap or sy0 - b[3] >= gap or b[1] - sy1 >= gap:
                        continue
                    s = segments[n]
                    depth = s[4] - segment_box_distance(s, b)
                    if s[5] == "leader":
                        # its own label: an end of the leader on the box's edge
                        inner = (b[0] + 0.05, b[1] + 0.05, b[2] - 0.05, b[3] - 0.05)
                        if segment_box_distance(s, inner) > 0:
                            continue
                    if depth > 0.01:
                        what = {"disc": "a circle", "leader": "a leader line"}.get(s[5], "a line")
                        bad.append(f"{path}: {text!r} at ({b[0]:.2f}, {b[3]:.2f}) lies over {what} "
                                   f"({s[0]:.2f}, {s[1]:.2f})-({s[2]:.2f}, {s[3]:.2f}) by {depth:.2f} mm")
                        break
                else:
                    continue
                break
            else:
                continue
            break
    leaders = sum(1 for s in segments if s[5] == "leader")
    return bad, leaders


def check_labels(paths, lines=False):
    bad = []
    leaders = 0
    for path in paths:
        sheet = read_sheet(path)
        boxes = text_boxes(sheet)
        view = [float(v) for v in sheet[0].get("viewBox").split()]
        for (b, text) in boxes:
            if b[0] < view[0] - 0.01 or b[2] > view[0] + view[2] + 0.01 or b[1] < view[1] - 0.01 or \
                    b[3] > view[1] + view[3] + 0.01:
                bad.append(f"{path}: {text!r} at ({b[0]:.2f}, {b[3]:.2f}) leaves the sheet "
                           f"(its box ends at x = {b[2]:.2f} mm of {view[2]:.2f})")
        # every pair of boxes that overlap by more than 0.01 mm both ways, in the order of the
        # sheet: a sweep along x (boxes by their left edges: a box meets the ones that begin
        # before its right edge)
        order = sorted(range(len(boxes)), key=lambda k: boxes[k][0][0])
        lefts = [boxes[k][0][0] for k in order]
        pairs = []
        for m, i in enumerate(order):
            right = boxes[i][0][2]
            for k in range(m + 1, len(order)):
                if right - lefts[k] <= 0.01:
                    break
                j = order[k]
                pairs.append((i, j) if i < j else (j, i))
        for i, j in sorted(pairs):
            (a, ta), (b, tb) = boxes[i], boxes[j]
            w = min(a[2], b[2]) - max(a[0], b[0])
            h = min(a[3], b[3]) - max(a[1], b[1])
            if w > 0.01 and h > 0.01:
                bad.append(f"{path}: {ta!r} at ({a[0]:.2f}, {a[3]:.2f}) overlaps {tb!r} at "
                           f"({b[0]:.2f}, {b[3]:.2f}) by {w:.2f} x {h:.2f} mm")
        if lines:
            over, n = lines_under_labels(path, sheet, boxes)
            bad += over
            leaders += n
    if lines:
        print(f"{len(paths)} sheets, {leaders} leader lines")
    if bad:
        print("\n".join(bad[:40]))
        fail(f"{len(bad)} labels over a label, a line or off the sheet")


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


def check_notation(paths, russian):
    """Typeset labels: no "_" or "^" markup in a <text> (the subtitle, which holds the deck's
    path and title, aside); on a Russian sheet also no run of two or more Latin letters in a
    run of text except point names (the sheet's data-joint, data-point and data-image
    values), a lowered or raised run of point letters (v_CB, a_B2B3), Roman numerals (the
    class of a group), the program's name (kinetostat; "KINETOSTAT <KIND>" opening the
    title) and the subtitle."""
    hits = []
    for path in paths:
        root, sizes, _ = read_sheet(path)
        names = set()
        for el in root.iter():
            for key in ("data-joint", "data-point", "data-image"):
                if el.get(key):
                    names.add(el.get(key))
        for el in root.iter(SVG_NS + "text"):
            classes = (el.get("class") or "").split()
            if "subtitle" in classes:
                continue
            runs, base = text_runs(el, sizes)
            whole = "".join(r[0] for r in runs)
            if "_" in whole or "^" in whole:
                hits.append(f"{path}: markup in {whole!r}")
            if not russian:
                continue
            for k, (text, size, offset) in enumerate(runs):
                if "title" in classes and k == 0:
                    text = re.sub(r"^\s*KINETOSTAT\s+\S+", " ", text)
                text = re.sub(r"(?i)kinetostat", " ", text)
                shifted = size < base - 1e-9
                for token in re.findall(r"[A-Za-z0-9]+", text):
                    if token in names or not re.search(r"[A-Za-z]{2}", token) or re.fullmatch(r"[IVX]+", token):
                        continue
                    if shifted and re.fullmatch(r"([A-Z][0-9]*)+", token):
                        continue
                    hits.append(f"{path}: Latin {token!r} in {whole!r}")
    if hits:
        print("\n".join(hits[:60]))
        fail(f"{len(hits)} labels not in the course's notation")


def check_batch(listing):
    """The checks of the file `listing`, a line each (NAME, CHECK, ARGUMENT... by tabs)."""
    failed = 0
    with open(listing, encoding="utf-8") as f:
        for line in f:
            if not line.strip():
                continue
            name, *argv = line.rstrip("\n").split("\t")
            said = io.StringIO()
            try:
                with contextlib.redirect_stdout(said):
                    dispatch(argv)
                code = 0
            except SystemExit as e:
                code = 0 if e.code in (None, 0) else 1
            if code == 0:
                print(f"ok {name}")
            else:
                failed += 1
                print(f"FAIL {name}: " + said.getvalue().strip().replace("\n", "\n    "))
    if failed:
        fail(f"{failed} checks failed")


def dispatch(argv):
    """One check by its command-line words (without the program's name)."""
    if len(argv) == 3 and argv[0] == "hodographs":
        check_hodographs(argv[1], argv[2])
    elif len(argv) == 3 and argv[0] == "png":
        check_png(argv[1], argv[2])
    elif len(argv) >= 3 and argv[0:2] == ["labels", "--lines"]:
        check_labels(argv[2:], lines=True)
    elif len(argv) >= 2 and argv[0] == "labels":
        check_labels(argv[1:])
    elif len(argv) >= 3 and argv[0] == "notation" and argv[1] in ("en", "ru"):
        check_notation(argv[2:], argv[1] == "ru")
    elif len(argv) >= 2 and argv[0] == "english":
        check_english(argv[1:])
    elif len(argv) == 2 and argv[0] == "self-contained":
        check_self_contained(argv[1])
    elif len(argv) == 2 and argv[0] == "batch":
        check_batch(argv[1])
    else:
        fail(__doc__)


def main():
    dispatch(sys.argv[1:])


if __name__ == "__main__":
    main()
