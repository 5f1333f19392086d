#!/usr/bin/env python3
"""Is an output of kinetostat well formed, whatever strings a user gave? (standard library only)

  output_check.py FORMAT FILE [--forbid TEXT]... [--forbid-hex HEX]...

FORMAT is one of:
  xml      an SVG sheet: valid UTF-8 without control bytes but tab and newline; well-formed
           XML (xml.etree; tools/test also runs xmllint on the same files).
  json     valid UTF-8; json.loads reads it; no object anywhere has a key "injected".
  csv      valid UTF-8 without control bytes (a field stays on its line); every physical line
           is one row: csv.reader gives as many rows as the file has lines, each with as many
           fields as the header; no bare '"' outside RFC 4180 quoting.
  dxf      ASCII only, without control bytes; group-code/value pairs (an even number of lines,
           every code an integer); the file ends with 0/EOF; every TEXT entity has one value
           (code 1) on one line.
  table    a legacy table or any line-oriented text (a deck, a structure report): valid UTF-8
           without control bytes but newline; no line starts with INJECTED.
Every --forbid TEXT (UTF-8) and --forbid-hex HEX (raw bytes, e.g. 3c623e) must not occur in
the file: the raw form of a hostile string a writer should have escaped.
Exit status 0 when the file passes, 1 with every failure printed.
"""
import csv
import io
import json
import sys
import xml.etree.ElementTree as ET


def control_bytes(data, allowed):
    """Positions (line, byte) of control bytes other than `allowed`."""
    bad = []
    line = 1
    for i, b in enumerate(data):
        if b == 10:
            line += 1
        if (b < 32 or b == 127) and b not in allowed:
            bad.append(f"line {line}: control byte 0x{b:02X}")
            if len(bad) > 5:
                break
    return bad


def utf8(data, bad):
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        bad.append(f"not UTF-8: {e}")
        return data.decode("utf-8", "replace")


def check_xml(data, bad):
    utf8(data, bad)
    bad += control_bytes(data, (9, 10, 13))
    try:
        ET.fromstring(data)
    except ET.ParseError as e:
        bad.append(f"not well-formed XML: {e}")


def has_key(node, key):
    if isinstance(node, dict):
        return key in node or any(has_key(v, key) for v in node.values())
    if isinstance(node, list):
        return any(has_key(v, key) for v in node)
    return False


def check_json(data, bad):
    text = utf8(data, bad)
    try:
        obj = json.loads(text)
    except ValueError as e:
        bad.append(f"not JSON: {e}")
        return
    if has_key(obj, "injected"):
        bad.append('a key "injected" was added')


def check_csv(data, bad):
    text = utf8(data, bad)
    bad += control_bytes(data, (10,))
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    rows = list(csv.reader(io.StringIO(text, newline=""), strict=True))
    if len(rows) != len(lines):
        bad.append(f"{len(lines)} lines but {len(rows)} rows: a field spans lines")
    if rows:
        width = len(rows[0])
        for n, row in enumerate(rows[1:], start=2):
            if len(row) != width:
                bad.append(f"row {n}: {len(row)} fields, the header has {width}")
    for n, line in enumerate(lines, start=1):
        # a '"' must open a field, close it, or be doubled inside one
        inside = False
        i = 0
        while i < len(line):
            c = line[i]
            if inside:
                if c == '"':
                    if i + 1 < len(line) and line[i + 1] == '"':
                        i += 1
                    else:
                        inside = False
                        if i + 1 < len(line) and line[i + 1] != ",":
                            bad.append(f"line {n}: text after a closing quote")
                            break
            elif c == '"':
                if i > 0 and line[i - 1] != ",":
                    bad.append(f"line {n}: a quote inside an unquoted field")
                    break
                inside = True
            i += 1
        if inside:
            bad.append(f"line {n}: a quoted field is not closed on its line")


def check_dxf(data, bad):
    if any(b > 127 for b in data):
        bad.append("a byte above 127: an R12 DXF is ASCII (non-ASCII text is written \\U+XXXX)")
    bad += control_bytes(data, (10,))
    lines = data.decode("ascii", "replace").split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) % 2:
        bad.append(f"{len(lines)} lines: group codes and values must come in pairs")
        return
    pairs = []
    for i in range(0, len(lines), 2):
        try:
            pairs.append((int(lines[i].strip()), lines[i + 1]))
        except ValueError:
            bad.append(f"line {i + 1}: group code {lines[i]!r} is not an integer")
            return
    if not pairs:
        bad.append("empty: no group codes")
        return
    if pairs[-1] != (0, "EOF"):
        bad.append(f"does not end with 0/EOF: {pairs[-1]}")
    for i, (code, value) in enumerate(pairs):
        if code == 0 and value == "TEXT":
            texts = [v for c, v in pairs[i + 1:] if c == 1][:1]
            if not texts:
                bad.append(f"TEXT entity at pair {i + 1} has no value")
    if sum(1 for c, v in pairs if c == 0 and v == "EOF") != 1:
        bad.append("EOF is not the only end")


def check_table(data, bad):
    text = utf8(data, bad)
    bad += control_bytes(data, (10,))
    for n, line in enumerate(text.split("\n"), start=1):
        if line.startswith("INJECTED"):
            bad.append(f"line {n}: an injected line: {line[:60]!r}")


CHECKS = {"xml": check_xml, "json": check_json, "csv": check_csv, "dxf": check_dxf, "table": check_table}


def main():
    args = sys.argv[1:]
    if len(args) < 2 or args[0] not in CHECKS:
        print(__doc__)
        sys.exit(2)
    fmt, path = args[0], args[1]
    forbidden = []
    rest = args[2:]
    while rest:
        if len(rest) < 2 or rest[0] not in ("--forbid", "--forbid-hex"):
            print(__doc__)
            sys.exit(2)
        forbidden.append(rest[1].encode("utf-8") if rest[0] == "--forbid" else bytes.fromhex(rest[1]))
        rest = rest[2:]
    data = open(path, "rb").read()
    bad = []
    if not data:
        bad.append("empty")
    else:
        CHECKS[fmt](data, bad)
    for f in forbidden:
        at = data.find(f)
        if at >= 0:
            line = data.count(b"\n", 0, at) + 1
            bad.append(f"line {line}: the raw text {f!r} (unescaped)")
    if bad:
        print(f"{path} ({fmt}):")
        for b in bad[:12]:
            print("  " + b)
        sys.exit(1)


if __name__ == "__main__":
    main()
