#!/usr/bin/env python3
"""Check a steady cycle by its own law, from the JSON of a run with dynamics = 'steady' or
'given' (standard library only).

usage: tools/cycle_check.py RUN.json CYCLE_DEG [DELTA]

The run's steps must cover the cycle (one turn: 360, two turns: 720) at a fine, even step that
holds every kink of the loads (a gas table's points). Checked, each with its tolerance, and
printed as expected against computed on failure:

- the balancing moment is the driving moment at every step: M1 = M_d (relative 1e-9 of |M_d|);
- M_d = -(1/cycle) * integral of M_red over the cycle (composite Simpson on the steps,
  relative 1e-6 of the largest |M_red|): the loads' work and M_d's cancel over the whole
  cycle, not over one turn;
- dT closes: 0 at the first and the last step (1e-9 of its range), and dT is the integral
  of M_d + M_red from the first step (Simpson, 1e-6 of the range);
- the energy equation: 1/2 (J_fw + J_red) omega^2 - dT is the same at every step (1e-9);
- delta: (omega_max - omega_min)/omega_m of the figures equals delta (1e-9) and the steps'
  extremes agree (1e-3 of delta: the steps may miss the extreme by a part of a step);
- the time: t of the last step is the period.
With CYCLE_DEG = 720 also: M_red over the second turn is not that of the first (the cycle
really is two turns).
"""
import json
import math
import sys


def fail(what, expected, computed):
    print(f"cycle_check: {what}: expected {expected!r}, computed {computed!r}")
    sys.exit(1)


def simpson_cumulative(x, y):
    """Cumulative integral at every even index (Simpson on pairs of steps), trapezoid-free."""
    out = {0: 0.0}
    acc = 0.0
    for i in range(0, len(x) - 2, 2):
        h = (x[i + 2] - x[i]) / 2.0
        acc += h / 3.0 * (y[i] + 4.0 * y[i + 1] + y[i + 2])
        out[i + 2] = acc
    return out


def main():
    run = json.load(open(sys.argv[1]))
    cycle = float(sys.argv[2])
    delta_asked = float(sys.argv[3]) if len(sys.argv) > 3 else None
    cols = [c["name"] for c in run["columns"]]
    rows = run["rows"]
    dyn = run["dynamics"]
    col = {name: [r[cols.index(name)] for r in rows] for name in ("phi1", "M1", "M_red", "J_red", "dT", "omega1", "t")}
    phi = col["phi1"]
    if len(phi) % 2 == 0:
        fail("the number of steps (Simpson needs an odd count)", "odd", len(phi))
    if abs(phi[-1] - phi[0] - cycle) > 1e-9 * cycle:
        fail("the steps' span, deg", cycle, phi[-1] - phi[0])
    md, jfw, wm = dyn["M_d"], dyn["J_flywheel"], dyn["omega_mean"]
    # M1 = M_d at every step
    worst = max(abs(m - md) for m in col["M1"])
    if worst > 1e-9 * abs(md):
        fail("max |M1 - M_d| (N*m) at most", 1e-9 * abs(md), worst)
    # M_d from the loads' work over the whole cycle
    rad = [math.radians(p) for p in phi]
    mred = col["M_red"]
    work = simpson_cumulative(rad, mred)[len(rad) - 1]
    md_law = -work / math.radians(cycle)
    if abs(md_law - md) > 1e-6 * max(abs(m) for m in mred):
        fail("M_d = -(1/cycle) integral of M_red (N*m)", md_law, md)
    # dT closes and is the integral of M_d + M_red
    dt = col["dT"]
    span = max(dt) - min(dt)
    if abs(dt[0]) > 1e-9 * span or abs(dt[-1]) > 1e-9 * span:
        fail("dT at the first and the last step (J)", (0.0, 0.0), (dt[0], dt[-1]))
    integral = simpson_cumulative(rad, [md + m for m in mred])
    worst = max(abs(integral[i] - dt[i]) for i in integral)
    if worst > 1e-6 * span:
        fail("max |dT - Simpson integral of M_d + M_red| (J) at most", 1e-6 * span, worst)
    # the energy equation
    energy = [0.5 * (jfw + j) * w * w - d for j, w, d in zip(col["J_red"], col["omega1"], dt)]
    if max(energy) - min(energy) > 1e-9 * max(abs(e) for e in energy):
        fail("1/2 (J_fw + J_red) omega^2 - dT constant (J)", (min(energy), min(energy)), (min(energy), max(energy)))
    # delta
    delta = (dyn["omega_max"] - dyn["omega_min"]) / wm
    if abs(delta - dyn["delta"]) > 1e-9 * dyn["delta"]:
        fail("delta from the figures' extremes", dyn["delta"], delta)
    if delta_asked is not None and abs(delta - delta_asked) > 1e-9 * delta_asked:
        fail("delta asked", delta_asked, delta)
    steps = (max(col["omega1"]) - min(col["omega1"])) / wm
    if abs(steps - delta) > 1e-3 * delta:
        fail("delta from the steps' omega1", delta, steps)
    if abs(0.5 * (dyn["omega_max"] + dyn["omega_min"]) - wm) > 1e-9 * wm:
        fail("(omega_max + omega_min)/2", wm, 0.5 * (dyn["omega_max"] + dyn["omega_min"]))
    if abs(col["t"][-1] - dyn["period"]) > 1e-9 * dyn["period"]:
        fail("t at the last step = period (s)", dyn["period"], col["t"][-1])
    if cycle > 360:
        half = (len(phi) - 1) // 2
        diff = max(abs(mred[i] - mred[i + half]) for i in range(half))
        if diff <= 1e-6 * max(abs(m) for m in mred):
            fail("M_red over the second turn differs from the first (N*m)", "> 0", diff)
    if not run["selfcheck"]["ok"]:
        fail("self-check", True, run["selfcheck"])
    print(f"cycle_check: ok: M_d = {md:.9g} N*m (law {md_law:.9g}), delta = {delta:.12g}, "
          f"J_fw = {jfw:.9g} kg*m^2 over {cycle:g} deg")


if __name__ == "__main__":
    main()
