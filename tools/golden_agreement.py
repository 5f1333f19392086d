#!/usr/bin/env python3
"""Check that two sets of golden outputs (data/expected of two binaries) agree to roundoff.

usage: tools/golden_agreement.py OLD NEW [--rtol R] [--verbose]
       tools/golden_agreement.py --git REV NEW      (OLD: data/expected as committed at REV)

A formula that is as accurate as the one it replaces but rounds differently moves the last
digits of some outputs. This script says whether every change between OLD and NEW (two
directories of files NAME.csv, NAME.json, NAME.table, NAME.ru.table, NAME.svg) is such a
roundoff change:

- CSV: the same header and rows; every value within R (default 1e-12) times its scale of
  the old value: the largest magnitude of the same unit in that row (old and new; units
  from NAME.json's columns), or the column's largest magnitude over the run when that is
  larger (a quantity crossing zero, alone of its unit in the row, such as dJ_red: its
  roundoff is relative to its size over the cycle, not to its value at the crossing). An absolute tolerance in the unit itself cannot work for a row whose forces
  reach 2.2e4 N: the 13 significant digits written are 1e-9 N apart there, and the roundoff
  of one multiplication is ~4e-12 N.
- every other changed line: the same text around its numbers; a changed number is
  * a self-check figure (a line of the equilibrium residual, the power-balance mismatch or
    the drive's deviation; JSON "selfcheck") at roundoff level: both values at most 1e-6
    (the self-check's limit), so both read OK;
  * a full-precision number (13 significant digits, as the CSV writes them; JSON rows are
    checked against the row's largest value of the same unit, other numbers against
    themselves) within R;
  * a statistic of the run (a line of a mean or a work): within R of the largest value of
    its unit in the old CSV (times the input's span in rad for a work), as the CSV values it
    sums are;
  * a rounded number (a table's field, an SVG coordinate): one unit of its last digit
    apart, and some old CSV value of the deck lies within R (of its row's largest value of
    the same unit) of the rounding boundary between the two, so that either rounding is
    the value's; or, in an SVG, the new line is one the old drawing already has, or the
    new number is one the old line already has (the same element or point drawn at another
    step with the other rounding: a quantity constant over the steps whose last digit the
    roundoff already decided step by step).

Prints one line per file that differs and a verdict; exit status 0 when every change is
explained, 1 otherwise, 2 on a usage error.
"""
import argparse
import csv
import io
import json
import math
import os
import re
import subprocess
import sys

NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[EeDd][-+]?\d+)?")
SELFCHECK = re.compile(r"RESIDUAL|MISMATCH|M_d|НЕВЯЗК|РАСХОЖДЕН|НЕСООТВЕТСТВ|selfcheck|max_residual|max_mismatch")
SELFCHECK_LIMIT = 1.0e-6
STATISTIC = re.compile(r"\bMEAN\b|\bWORK\b|СРЕДН|РАБОТА|\"mean\"|\"work\"")


def read_dir(path):
    return {name: open(os.path.join(path, name), "rb").read() for name in sorted(os.listdir(path))}


def read_git(rev):
    root = subprocess.run(["git", "rev-parse", "--show-toplevel"], capture_output=True, text=True, check=True).stdout.strip()
    names = subprocess.run(["git", "-C", root, "ls-tree", "--name-only", rev, "data/expected/"],
                           capture_output=True, text=True, check=True).stdout.split()
    files = {}
    for full in names:
        files[os.path.basename(full)] = subprocess.run(["git", "-C", root, "show", f"{rev}:{full}"],
                                                       capture_output=True, check=True).stdout
    return files


def units_of(files, stem):
    """Column name -> unit, from the deck's JSON golden (csv columns only)."""
    raw = files.get(stem + ".json")
    if raw is None:
        return None
    try:
        doc = json.loads(raw.decode())
    except ValueError:
        return None
    return {c["name"]: c.get("unit", "") for c in doc.get("columns", []) if c.get("csv", True)}


def parse_csv(raw):
    rows = list(csv.reader(io.StringIO(raw.decode())))
    return rows[0], rows[1:]


def to_float(text):
    try:
        return float(text.replace("D", "E").replace("d", "e"))
    except ValueError:
        return None


def row_scales(header, row, units, other=None):
    """Largest |value| of each unit in the row (and in `other`, the same row of the other file)."""
    scale = {}
    for rw in (row, other) if other is not None else (row,):
        for name, cell in zip(header, rw):
            v = to_float(cell)
            if v is None or not math.isfinite(v):
                continue
            u = units.get(name, "?") if units else "?"
            scale[u] = max(scale.get(u, 0.0), abs(v))
    return scale


def check_csv(name, old, new, units, rtol, problems):
    h_old, r_old = parse_csv(old)
    h_new, r_new = parse_csv(new)
    if h_old != h_new or len(r_old) != len(r_new):
        problems.append(f"{name}: header or row count differ")
        return 0.0
    worst = 0.0
    col_top = column_maxima(h_old, r_old)
    for k, (ro, rn) in enumerate(zip(r_old, r_new)):
        scale = row_scales(h_old, ro, units, rn)
        for col, (a, b) in enumerate(zip(ro, rn)):
            if a == b:
                continue
            x, y = to_float(a), to_float(b)
            if x is None or y is None:
                problems.append(f"{name}: row {k + 1} {h_old[col]}: '{a}' -> '{b}' (not numbers)")
                continue
            s = max(scale.get(units.get(h_old[col], "?") if units else "?", 0.0), col_top.get(h_old[col], 0.0))
            rel = abs(x - y) / s if s > 0 else math.inf
            worst = max(worst, rel)
            if rel > rtol:
                problems.append(f"{name}: row {k + 1} {h_old[col]}: {a} -> {b}, {rel:.2e} of the row's largest "
                                f"{units.get(h_old[col], '?') if units else ''} value (limit {rtol:g})")
    return worst


def csv_cells(files, stem):
    """(value, scale) of every cell of the deck's old CSV: the scale is its row's largest |value| of its unit."""
    raw = files.get(stem + ".csv")
    if raw is None:
        return []
    units = units_of(files, stem)
    header, rows = parse_csv(raw)
    cells = []
    for row in rows:
        scale = row_scales(header, row, units)
        for name, cell in zip(header, row):
            v = to_float(cell)
            if v is not None and math.isfinite(v):
                cells.append((v, scale.get(units.get(name, "?") if units else "?", abs(v))))
    return cells


def run_scale(files, stem, line):
    """Scale of a run statistic's line (a mean, a work): the largest |value| of the old CSV in
    the line's unit (a work in J: a moment's N*m times the run's span of the input angle in rad,
    or a force's N times the span of the stroke is not known: N*m and N both count)."""
    raw = files.get(stem + ".csv")
    units = units_of(files, stem)
    if raw is None or units is None:
        return 0.0
    header, rows = parse_csv(raw)
    line = english_units(line)
    words = set(re.findall(r"[A-Za-z*/^0-9]+", line))
    wanted = {u for u in set(units.values()) if u and u in words}
    span = 1.0
    if "J" in words or "Дж" in line:
        wanted |= {"N*m", "N"}
        phi = [to_float(r[0]) for r in rows if r and to_float(r[0]) is not None]
        if phi:
            span = max(1.0, math.radians(max(phi) - min(phi)))
    scale = 0.0
    for row in rows:
        for name, cell in zip(header, row):
            v = to_float(cell)
            if v is not None and math.isfinite(v) and units.get(name) in wanted:
                scale = max(scale, abs(v))
    return scale * span


def last_place(token):
    """Value of one unit in the last written digit of a number token."""
    if re.search(r"[EeDd]", token):
        mant, exp = re.split(r"[EeDd]", token, maxsplit=1)
    else:
        mant, exp = token, "0"
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    return 10.0 ** (int(exp) - decimals)


def significant_digits(token):
    mant = re.split(r"[EeDd]", token)[0].lstrip("+-").replace(".", "").lstrip("0")
    return len(mant)


def json_row_columns(files, stem):
    """[(name, unit)] of the JSON rows' columns, or None without a JSON golden."""
    raw = files.get(stem + ".json")
    if raw is None:
        return None
    doc = json.loads(raw.decode())
    return [(c.get("name", ""), c.get("unit", "")) for c in doc.get("columns", [])]


def column_maxima(header, rows):
    """Largest |value| of each column over the run."""
    top = {}
    for row in rows:
        for name, cell in zip(header, row):
            v = to_float(cell)
            if v is not None and math.isfinite(v):
                top[name] = max(top.get(name, 0.0), abs(v))
    return top


def old_column_maxima(files, stem):
    raw = files.get(stem + ".csv")
    if raw is None:
        return {}
    return column_maxima(*parse_csv(raw))


# Russian unit words of the legacy tables, as whole words, to the CSV's units.
RUSSIAN_UNITS = [("Н*м", "N*m"), ("Дж", "J"), ("град", "deg"), ("Н", "N")]


def english_units(line):
    for ru, en in RUSSIAN_UNITS:
        line = re.sub(r"(?<![А-Яа-яЁё])" + re.escape(ru) + r"(?![А-Яа-яЁё])", en, line)
    return line


def check_text(name, stem, old, new, old_files, rtol, problems):
    lo = old.decode(errors="replace").split("\n")
    ln = new.decode(errors="replace").split("\n")
    if len(lo) != len(ln):
        problems.append(f"{name}: {len(lo)} lines -> {len(ln)} lines")
        return 0
    cells = None
    columns = json_row_columns(old_files, stem) if name.endswith(".json") else None
    col_names = [n for n, _ in columns] if columns is not None else None
    col_units = [u for _, u in columns] if columns is not None else None
    col_top = old_column_maxima(old_files, stem) if col_names else {}
    changed = 0
    old_lines = set(lo)
    for i, (a, b) in enumerate(zip(lo, ln)):
        if a == b:
            continue
        changed += 1
        ta, tb = NUMBER.split(a), NUMBER.split(b)
        na, nb = NUMBER.findall(a), NUMBER.findall(b)
        if ta != tb or len(na) != len(nb):
            problems.append(f"{name}:{i + 1}: text changed:\n  - {a[:160]}\n  + {b[:160]}")
            continue
        selfcheck = bool(SELFCHECK.search(a))
        is_row = col_units is not None and a.strip().startswith("[") and len(na) == len(col_units)
        row_scale = {}
        if is_row:
            for k, tok in enumerate(na):
                u = col_units[k]
                row_scale[u] = max(row_scale.get(u, 0.0), abs(float(tok)), abs(float(nb[k])))
        for k, (x, y) in enumerate(zip(na, nb)):
            if x == y:
                continue
            vx, vy = to_float(x), to_float(y)
            if selfcheck and max(abs(vx), abs(vy)) <= SELFCHECK_LIMIT:
                continue
            if significant_digits(x) >= 13 or significant_digits(y) >= 13:
                s = max(row_scale.get(col_units[k], 0.0), col_top.get(col_names[k], 0.0)) if is_row \
                    else max(abs(vx), abs(vy))
                if s > 0 and abs(vx - vy) <= rtol * s:
                    continue
                problems.append(f"{name}:{i + 1}: {x} -> {y}: {abs(vx - vy) / s if s else math.inf:.2e} relative")
                continue
            if STATISTIC.search(a):
                s = run_scale(old_files, stem, a)
                if abs(vx - vy) <= rtol * s:
                    continue
                problems.append(f"{name}:{i + 1}: {x} -> {y}: {abs(vx - vy) / s if s else math.inf:.2e} of the run's "
                                "largest value of its unit")
                continue
            unit = last_place(x)
            if abs(abs(vx - vy) - unit) > 1e-6 * unit:
                problems.append(f"{name}:{i + 1}: {x} -> {y}: more than one unit of the last digit")
                continue
            boundary = 0.5 * (vx + vy)
            if name.endswith(".svg") and (b in old_lines or y in na):
                # the old drawing already has this very element, or this line this very
                # number, with the other rounding (a quantity constant over the steps, drawn
                # at each, whose roundoff already decided this digit step by step)
                continue
            if cells is None:
                cells = csv_cells(old_files, stem)
            if not any(abs(abs(v) - abs(boundary)) <= rtol * s for v, s in cells):
                problems.append(f"{name}:{i + 1}: {x} -> {y}: no CSV value within {rtol:g} of the boundary {boundary!r}")
    return changed


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("old", nargs="?")
    ap.add_argument("new")
    ap.add_argument("--git", metavar="REV", help="old goldens: data/expected as committed at REV")
    ap.add_argument("--rtol", type=float, default=1e-12)
    args = ap.parse_args()
    if (args.git is None) == (args.old is None):
        ap.print_usage(sys.stderr)
        return 2
    old_files = read_git(args.git) if args.git else read_dir(args.old)
    new_files = read_dir(args.new)
    problems = []
    if sorted(old_files) != sorted(new_files):
        problems.append(f"file lists differ: only old {sorted(set(old_files) - set(new_files))}, "
                        f"only new {sorted(set(new_files) - set(old_files))}")
    n_diff = 0
    for name in sorted(set(old_files) & set(new_files)):
        old, new = old_files[name], new_files[name]
        if old == new:
            continue
        n_diff += 1
        stem = name.split(".")[0]
        before = len(problems)
        if name.endswith(".csv"):
            worst = check_csv(name, old, new, units_of(old_files, stem), args.rtol, problems)
            print(f"{name}: CSV values differ by at most {worst:.2e} of their row's largest value of the same unit")
        else:
            changed = check_text(name, stem, old, new, old_files, args.rtol, problems)
            print(f"{name}: {changed} lines changed")
        for p in problems[before:]:
            print("  " + p)
    print(f"golden_agreement: {n_diff} of {len(new_files)} files differ; "
          + ("every change is roundoff (rtol %g)" % args.rtol if not problems else f"{len(problems)} changes NOT explained"))
    return 0 if not problems else 1


if __name__ == "__main__":
    sys.exit(main())
