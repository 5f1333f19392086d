#!/usr/bin/env python3
"""Check the points' velocities and accelerations of `kinetostat --kinematics --format csv`
against central differences of the positions (standard library only).

    motion_check.py RUN.csv [--link L] [--rtol R]

The positions x_P, y_P are functions of the input link's angle phi<L> (deg, uniform steps h),
so at every row with two rows on each side
    v = x'(phi) omega<L>,   a = x''(phi) omega<L>^2 + x'(phi) eps<L>
with the central differences of fourth order x' = (x[-2] - 8 x[-1] + 8 x[1] - x[2]) / 12h and
x'' = (-x[-2] + 16 x[-1] - 30 x[0] + 16 x[1] - x[2]) / 12h^2 (h in rad; error ~h^4, so a step
of 0.5 deg keeps both the truncation and the CSV's 13 digits below 1e-7): this holds for the
true motion of a steady cycle too (omega, eps varying). Every vx_P, vy_P and ax_P, ay_P column
is compared; the tolerance is R (default 1e-6) times the largest speed (acceleration) of any
point over the rows. Prints the worst relative deviation per kind and 'motion: OK' or
'motion: FAIL ...' (exit 1).
"""
import csv
import math
import sys


def main(argv):
    args = argv[1:]
    link = "1"
    rtol = None
    if "--link" in args:
        i = args.index("--link")
        link = args[i + 1]
        del args[i:i + 2]
    if "--rtol" in args:
        i = args.index("--rtol")
        rtol = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 1:
        print(__doc__)
        return 2
    with open(args[0], newline="") as f:
        rows = list(csv.reader(f))
    head, data = rows[0], [[float(x) if x else 0.0 for x in r] for r in rows[1:]]
    col = {name: i for i, name in enumerate(head)}
    for name in ("phi" + link, "omega" + link, "eps" + link):
        if name not in col:
            print(f"motion: FAIL no column {name}")
            return 1
    phi = [r[col["phi" + link]] for r in data]
    if len(phi) < 5:
        print("motion: FAIL fewer than 5 rows")
        return 1
    h = math.radians(phi[1] - phi[0])
    for k in range(1, len(phi)):
        if abs(math.radians(phi[k] - phi[k - 1]) - h) > 1e-9 * abs(h):
            print(f"motion: FAIL phi{link} not in uniform steps at row {k + 1}")
            return 1
    if rtol is None:
        rtol = 1e-6
    points = [name[3:] for name in head if name.startswith("vx_")]
    if not points:
        print("motion: FAIL no vx_ columns")
        return 1
    worst = {"v": (0.0, ""), "a": (0.0, "")}
    failures = []
    n_acc = 0
    checks = {"v": [], "a": []}
    for p in points:
        if "x_" + p not in col:
            failures.append(f"{p}: no position columns")
            continue
        has_a = "ax_" + p in col
        n_acc += has_a
        dev = {"v": [], "a": []}
        for k in range(2, len(data) - 2):
            om = data[k][col["omega" + link]]
            ep = data[k][col["eps" + link]]
            for axis in "xy":
                x = [data[j][col[axis + "_" + p]] for j in range(k - 2, k + 3)]
                d1 = (x[0] - 8.0 * x[1] + 8.0 * x[3] - x[4]) / (12.0 * h)
                d2 = (-x[0] + 16.0 * x[1] - 30.0 * x[2] + 16.0 * x[3] - x[4]) / (12.0 * h * h)
                dev["v"].append((data[k][col["v" + axis + "_" + p]], d1 * om, k, axis))
                if has_a:
                    dev["a"].append((data[k][col["a" + axis + "_" + p]], d2 * om * om + d1 * ep, k, axis))
        for kind, items in dev.items():
            checks[kind] += [(c, e, k, axis, p) for c, e, k, axis in items]
    for kind, items in checks.items():
        if not items:
            continue
        scale = max(max(abs(c), abs(e)) for c, e, _, _, _ in items)
        scale = max(scale, 1e-300)
        for computed, expected, k, axis, p in items:
            rel = abs(computed - expected) / scale
            if rel > worst[kind][0]:
                worst[kind] = (rel, f"{kind}{axis}_{p} row {k + 1}")
            if rel > rtol:
                failures.append(f"{kind}{axis}_{p} row {k + 1}: expected {expected:.12g} computed {computed:.12g} "
                                f"(relative to {scale:.6g}: {rel:.3g} > {rtol:.3g})")
    print(f"motion: {len(points)} points, {n_acc} with accelerations, {len(data) - 4} rows, h = {h:.3g} rad; "
          f"worst velocity {worst['v'][0]:.3g} ({worst['v'][1]}), worst acceleration {worst['a'][0]:.3g} "
          f"({worst['a'][1]}), tolerance {rtol:.3g}")
    if failures:
        for f in failures[:10]:
            print("  " + f)
        print(f"motion: FAIL {len(failures)} values")
        return 1
    print("motion: OK")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
