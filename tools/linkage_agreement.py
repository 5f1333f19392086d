#!/usr/bin/env python3
"""Agreement of two kinetostat binaries' outputs on the same decks (a solver change that may
move last digits).

usage: tools/linkage_agreement.py OLD_BIN NEW_BIN DECK... [--rtol 1e-12] [--args "..."]

For every deck, both binaries write --format csv and --format json (the JSON's column list
gives each CSV column's unit), then the legacy table in English and Russian, the JSON and
the SVG sheet. Checks:

1. CSV: every value agrees with the old within RTOL times the largest magnitude of the same
   unit in that row (of the old output); the worst ratio per deck is printed.
2. Every other output: lines that differ may differ only in numbers, and each changed number
   must be a rounding of one value whose old CSV value lies within the tolerance of the
   rounding boundary between the old and the new text (some CSV value v of the deck with
   |v - b| <= RTOL x the largest same-unit magnitude of its row, b the midpoint of the old
   and new printed numbers, which differ by one unit of their last digit), or a self-check
   residual line (a line ending in its verdict OK) whose verdict did not change. A changed
   number that is neither (a run's mean or work of a column whose true value is 0, printed
   from roundoff) is reported as an aggregate when it moved by at most RTOL times the
   deck's largest CSV magnitude, and fails otherwise.
3. A CSV value over the row rule is also measured against the largest magnitude of its
   column over the run (a quantity crossing zero), and fails.

Exit 0 when every check passes, 1 otherwise. Standard library only.
"""
import csv
import io
import json
import re
import subprocess
import sys
from decimal import Decimal

NUM = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[EeDd][-+]?\d+)?")
SELFCHECK = re.compile(r"\s(OK|FAIL)\s*$")


def run(binary, deck, args):
    res = subprocess.run([binary, deck] + args, capture_output=True)
    return res.returncode, res.stdout.decode("utf-8", "replace")


def read_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], [[float(c) if c not in ("",) else None for c in r] for r in rows[1:]]


def units_of(json_text):
    try:
        d = json.loads(json_text)
    except ValueError:
        return {}
    return {c["name"]: c.get("unit", "") for c in d.get("columns", []) if c.get("csv", True)}


def csv_check(old_text, new_text, units, rtol):
    head_o, rows_o = read_csv(old_text)
    head_n, rows_n = read_csv(new_text)
    if head_o != head_n or len(rows_o) != len(rows_n):
        return float("inf"), "header or row count differs", []
    worst, where = 0.0, ""
    scales = []  # (value, tolerance) of every old value
    col_big = [max((abs(r[j]) for r in rows_o if r[j] is not None), default=0.0) for j in range(len(head_o))]
    for k, (ro, rn) in enumerate(zip(rows_o, rows_n)):
        big = {}
        for name, v in zip(head_o, ro):
            if v is not None:
                u = units.get(name, name)
                big[u] = max(big.get(u, 0.0), abs(v))
        for name, vo, vn in zip(head_o, ro, rn):
            if (vo is None) != (vn is None):
                return float("inf"), f"row {k + 1} {name}: empty in one", scales
            if vo is None:
                continue
            scale = big[units.get(name, name)]
            scales.append((vo, rtol * scale))
            if vo == vn:
                continue
            ratio = abs(vo - vn) / scale if scale > 0 else float("inf")
            if ratio > worst:
                col = col_big[head_o.index(name)]
                where = f"row {k + 1} {name}: {vo!r} -> {vn!r}"
                if ratio > rtol and col > 0:
                    where += f" ({abs(vo - vn) / col:.1e} of the column's largest magnitude)"
                worst = ratio
    return worst, where, scales


def boundary_ok(a, b, scales):
    """Old text a and new text b of one number: one unit of their last digit apart, and an
    old CSV value within its tolerance of the midpoint."""
    try:
        da, db = Decimal(a.replace("D", "E").replace("d", "e")), Decimal(b.replace("D", "E").replace("d", "e"))
    except Exception:
        return False
    ulp = Decimal(1).scaleb(min(da.as_tuple().exponent, db.as_tuple().exponent))
    if abs(da - db) > ulp * Decimal("1.000001"):
        return False
    mid = float((da + db) / 2)
    return any(abs(abs(v) - abs(mid)) <= tol for v, tol in scales)


def text_check(old, new, scales, big, rtol, notes):
    lo, ln = old.splitlines(), new.splitlines()
    if len(lo) != len(ln):
        return [f"line count {len(lo)} -> {len(ln)}"]
    bad = []
    for i, (a, b) in enumerate(zip(lo, ln)):
        if a == b:
            continue
        if NUM.sub("#", a) != NUM.sub("#", b):
            bad.append(f"line {i + 1}: text differs: {a.strip()[:80]!r} -> {b.strip()[:80]!r}")
            continue
        if SELFCHECK.search(a):
            if ("OK" in a) != ("OK" in b):
                bad.append(f"line {i + 1}: self-check verdict changed")
            continue
        for ta, tb in zip(NUM.findall(a), NUM.findall(b)):
            if ta != tb and not boundary_ok(ta, tb, scales):
                fa, fb = (float(t.replace("D", "E").replace("d", "e")) for t in (ta, tb))
                if abs(fa - fb) <= rtol * big:
                    notes.append(f"line {i + 1}: aggregate {ta} -> {tb} ({abs(fa - fb) / big:.1e} of the largest CSV value)")
                else:
                    bad.append(f"line {i + 1}: {ta} -> {tb} not at a rounding boundary")
    return bad


def main(argv):
    rtol, extra, decks, bins = 1e-12, [], [], []
    it = iter(argv)
    for a in it:
        if a == "--rtol":
            rtol = float(next(it))
        elif a == "--args":
            extra = next(it).split()
        elif len(bins) < 2:
            bins.append(a)
        else:
            decks.append(a)
    old_bin, new_bin = bins
    failed = False
    for deck in decks:
        rc_o, csv_o = run(old_bin, deck, ["--format", "csv"] + extra)
        rc_n, csv_n = run(new_bin, deck, ["--format", "csv"] + extra)
        if rc_o != rc_n:
            print(f"FAIL {deck}: exit {rc_o} -> {rc_n}")
            failed = True
            continue
        if rc_o != 0:
            print(f"same exit {rc_o} {deck}")
            continue
        units = units_of(run(old_bin, deck, ["--format", "json"] + extra)[1])
        worst, where, scales = csv_check(csv_o, csv_n, units, rtol)
        verdict = "ok  " if worst <= rtol else "FAIL"
        failed |= worst > rtol
        print(f"{verdict} {deck}: csv largest difference {worst:.2e} of the row's same-unit largest {where}")
        for fmt in (["--format", "json"], [], ["--lang", "ru"], ["--format", "svg"]):
            ro, to = run(old_bin, deck, fmt + extra)
            rn, tn = run(new_bin, deck, fmt + extra)
            if ro != rn:
                print(f"FAIL {deck} {' '.join(fmt) or 'table'}: exit {ro} -> {rn}")
                failed = True
                continue
            notes = []
            big = max((abs(v) for v, _ in scales), default=0.0)
            bad = text_check(to, tn, scales, big, rtol, notes)
            changed = sum(1 for a, b in zip(to.splitlines(), tn.splitlines()) if a != b)
            if bad:
                failed = True
                print(f"FAIL {deck} {' '.join(fmt) or 'table'}: " + "; ".join(bad[:5]))
            elif changed:
                print(f"ok   {deck} {' '.join(fmt) or 'table'}: {changed} line(s) changed, at rounding boundaries, "
                      "self-check roundoff" + (" or aggregates: " + "; ".join(notes) if notes else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
