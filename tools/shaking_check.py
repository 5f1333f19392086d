#!/usr/bin/env python3
"""Independent checks of kinetostat's shaking columns and of `kinetostat balance` (standard
library only). Usage: shaking_check.py KINETOSTAT. Prints "ok NAME" or "FAIL NAME: detail"
per check; exits 1 when any failed.

- F_shake against -M * (second difference of the total centre of mass) * omega1^2 (constant
  crank speed, central differences over +-h in the crank angle), at several angles;
- M_shake against -(difference of the total angular momentum about the origin) / dt, with
  the momentum sum m r_S x v_S + J omega (v_S from differences of the positions);
- F_frame, M_frame against minus the sum of the printed frame reactions (their components,
  points, prismatic moments) minus M1;
- d'Alembert: with the deck's loads off, F_frame = F_shake + M g and
  M_frame = M_shake + sum r_S x m g;
- balance: the fully balanced four-bar's F_shake <= 1e-9 of the unbalanced maximum at every
  step; the partial balance of the slider-crank removes the fraction F of the reciprocating
  mass's primary component (the first harmonic of F_shake along the guide, before minus
  after = F * m_rec * r * omega1^2).
"""
import csv, io, math, os, re, subprocess, sys, tempfile

KS = sys.argv[1]
failed = 0


def check(name, ok, detail=""):
    global failed
    if ok:
        print(f"ok {name}")
    else:
        failed += 1
        print(f"FAIL {name}: {detail}")


def run(args):
    p = subprocess.run([KS] + args + ["-q"], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{args}: exit {p.returncode}: {p.stderr}")
    return list(csv.DictReader(io.StringIO(p.stdout)))


def deck_values(path):
    """name -> number for the simple scalar assignments of a deck (comments dropped)."""
    vals = {}
    for line in open(path, encoding="utf-8"):
        line = line.split("!")[0]
        for m in re.finditer(r"([A-Za-z_][\w()%]*)\s*=\s*([-+0-9.eEdD]+)(?=\s*(,|$))", line):
            try:
                vals[m.group(1).lower()] = float(m.group(2).replace("d", "e").replace("D", "e"))
            except ValueError:
                pass
    return vals


def assur_bodies(path):
    """[(centre, link label, m, J)] of an &assur deck (links numbered as in its columns)."""
    v = deck_values(path)
    crank = int(v.get("crank_id", 1))
    out = [(f"S{crank}", str(crank), v.get("crank_m", 0.0), v.get("crank_j", 0.0))]
    d = 1
    while f"dyad({d})%link2" in v:
        for q, (mk, jk) in ((2, ("m2", "j2")), (3, ("m3", "j3"))):
            lid = int(v[f"dyad({d})%link{q}"])
            label = "L1" if lid == 1 else str(lid)
            out.append((f"S{lid}", label, v.get(f"dyad({d})%{mk}", 0.0), v.get(f"dyad({d})%{jk}", 0.0)))
        d += 1
    return out


def fd_checks(name, deck, bodies, omega, angle_args, centres=(30.0, 100.0, 200.0, 310.0)):
    """F_shake and M_shake at `centres` (deg) against differences over h = 0.1 deg."""
    h_deg = 0.1
    h = math.radians(h_deg)
    mass = sum(b[2] for b in bodies)
    worst_f = worst_m = 0.0
    fmax = mmax = 0.0
    for c in centres:
        rows = run([deck, "--format", "csv", "--shaking", "--kinematics"] + angle_args(c - 2 * h_deg, h_deg, 5))
        rc = []
        for r in rows:
            rc.append([sum(b[2] * float(r[f"{a}_{b[0]}"]) for b in bodies) / mass for a in ("x", "y")])
        mid = rows[2]
        f_fd = [-mass * omega**2 * (rc[3][i] - 2 * rc[2][i] + rc[1][i]) / h**2 for i in range(2)]
        f = [float(mid["F_shake_x"]), float(mid["F_shake_y"])]
        worst_f = max(worst_f, math.hypot(f[0] - f_fd[0], f[1] - f_fd[1]))
        fmax = max(fmax, math.hypot(*f))

        def momentum(k):
            hz = 0.0
            for (s, link, m, j) in bodies:
                x, y = float(rows[k][f"x_{s}"]), float(rows[k][f"y_{s}"])
                vx = omega * (float(rows[k + 1][f"x_{s}"]) - float(rows[k - 1][f"x_{s}"])) / (2 * h)
                vy = omega * (float(rows[k + 1][f"y_{s}"]) - float(rows[k - 1][f"y_{s}"])) / (2 * h)
                w = float(rows[k].get(f"omega{link}", 0.0) or 0.0)
                hz += m * (x * vy - y * vx) + j * w
            return hz
        m_fd = -omega * (momentum(3) - momentum(1)) / (2 * h)
        worst_m = max(worst_m, abs(float(mid["M_shake"]) - m_fd))
        mmax = max(mmax, abs(float(mid["M_shake"])))
    check(f"{name}: F_shake vs -M r_c'' (differences, h = {h_deg} deg)", worst_f <= 1e-5 * fmax,
          f"largest difference {worst_f:.3e} N, limit 1e-5 of {fmax:.4e} N")
    check(f"{name}: M_shake vs -dH/dt (differences)", worst_m <= 1e-5 * max(mmax, fmax * 0.1),
          f"largest difference {worst_m:.3e} N*m, limit 1e-5 of {max(mmax, fmax * 0.1):.4e}")


def assur_angles(start, step, n):
    return ["--set", f"phi_start={start!r}", "--set", f"dphi={step!r}", "--set", f"n={n}"]


def frame_checks(name, deck, pairs, drive, extra=()):
    """F_frame, M_frame equal minus the printed frame reactions (pairs: (force, point, moment))."""
    rows = run([deck, "--format", "csv", "--shaking", "--kinematics"] + list(extra))
    worst = 0.0
    scale = 0.0
    for r in rows:
        fx = fy = mz = 0.0
        for (f, p, m) in pairs:
            ax, ay = float(r[f"{f}_x"]), float(r[f"{f}_y"])
            fx -= ax
            fy -= ay
            if p:
                mz -= float(r[f"x_{p}"]) * ay - float(r[f"y_{p}"]) * ax
            if m:
                mz -= float(r[m])
        if drive:
            mz -= float(r[drive])
        d = [fx - float(r["F_frame_x"]), fy - float(r["F_frame_y"])]
        worst = max(worst, math.hypot(*d), abs(mz - float(r["M_frame"])) if "M_frame" in r else 0.0)
        scale = max(scale, math.hypot(fx, fy), abs(mz))
    check(f"{name}: F_frame, M_frame = minus the frame reactions", worst <= 1e-12 * scale,
          f"largest difference {worst:.3e}, limit 1e-12 of {scale:.4e}")
    return rows


def dalembert(name, deck, bodies, g_vec, extra):
    """With the loads off: F_frame = F_shake + M g, M_frame = M_shake + sum r_S x m g."""
    rows = run([deck, "--format", "csv", "--shaking", "--kinematics"] + extra)
    worst = scale = 0.0
    for r in rows:
        fx = float(r["F_shake_x"]) + sum(b[2] for b in bodies) * g_vec[0]
        fy = float(r["F_shake_y"]) + sum(b[2] for b in bodies) * g_vec[1]
        mz = float(r["M_shake"]) + sum(b[2] * (float(r[f"x_{b[0]}"]) * g_vec[1] - float(r[f"y_{b[0]}"]) * g_vec[0])
                                       for b in bodies)
        worst = max(worst, abs(fx - float(r["F_frame_x"])), abs(fy - float(r["F_frame_y"])),
                    abs(mz - float(r["M_frame"])))
        scale = max(scale, abs(fx), abs(fy), abs(mz))
    check(f"{name}: d'Alembert (loads off): frame total = shaking + weights", worst <= 1e-9 * scale,
          f"largest difference {worst:.3e}, limit 1e-9 of {scale:.4e}")


root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.chdir(root)

# F_shake, M_shake against differences
fd_checks("assur_fourbar", "data/assur_fourbar.nml", assur_bodies("data/assur_fourbar.nml"), 20.0, assur_angles)
fd_checks("assur_slider_crank", "data/assur_slider_crank.nml", assur_bodies("data/assur_slider_crank.nml"), 50.0,
          assur_angles)
fd_checks("assur_sixbar", "data/assur_sixbar.nml",
          [b for b in assur_bodies("data/assur_sixbar.nml")], 100.0,
          lambda s, st, n: ["--set", "start_at=''"] + assur_angles(s, st, n))
v = deck_values("data/pr3207.nml")
fd_checks("pr3207", "data/pr3207.nml", [("S1", "1", v["m1"], 0.0), ("S3", "3", v["m3"], v["j3"]),
                                         ("S5", "5", v["m5"], 0.0)], v["omega1"], assur_angles)

# the frame's total against the printed reactions
frame_checks("assur_fourbar", "data/assur_fourbar.nml", [("F30", "D", ""), ("F10", "A", "")], "M1")
frame_checks("assur_slider_crank", "data/assur_slider_crank.nml", [("F30", "J30", "F30M"), ("F10", "J10", "")], "M1")
frame_checks("assur_pr3050", "data/assur_pr3050.nml", [("F14", "J14", ""), ("F34", "J34", "")], "")
frame_checks("pr3050", "data/pr3050.nml", [("F14", "A", ""), ("F34", "C", "")], "")
pr3207_rows = frame_checks("pr3207 (force only)", "data/pr3207.nml", [("F16", "A", ""), ("F36", "C", ""), ("F56", "", "")],
                           "M1")
check("pr3207: no M_frame (the ram's guide moment is not computed)", "M_frame" not in pr3207_rows[0],
      ", ".join(pr3207_rows[0].keys()))

# d'Alembert with the loads off
dalembert("assur_fourbar", "data/assur_fourbar.nml", assur_bodies("data/assur_fourbar.nml"), (0.0, -9.81),
          ["--set", "force(1)%value=0", "--set", "moment(1)%value=0"])
dalembert("assur_slider_crank", "data/assur_slider_crank.nml", assur_bodies("data/assur_slider_crank.nml"),
          (0.0, -9.81), ["--set", "force(1)%value=0", "--set", "force(1)%idle=0"])
dalembert("sixbar (F56 through H)", "data/sixbar.nml", [], (0.0, 0.0), ["--set", "f5=13*0", "--set", "g=0"])

# balance: full on the four-bar, partial on the slider-crank
with tempfile.TemporaryDirectory() as tmp:
    balanced = os.path.join(tmp, "fourbar_balanced.nml")
    p = subprocess.run([KS, "balance", "data/assur_fourbar.nml", "-o", balanced], capture_output=True, text=True)
    check("balance four-bar: exit 0", p.returncode == 0, p.stderr)
    before = run(["data/assur_fourbar.nml", "--format", "csv", "--shaking"])
    after = run([balanced, "--format", "csv", "--shaking"])
    fmax = max(float(r["F_shake"]) for r in before)
    worst = max(float(r["F_shake"]) for r in after)
    check("balance four-bar: F_shake <= 1e-9 of the unbalanced maximum at every step", worst <= 1e-9 * fmax,
          f"balanced max {worst:.3e} N, unbalanced max {fmax:.4e} N")
    p = subprocess.run([KS, balanced, "--strict"], capture_output=True, text=True)
    check("balance four-bar: the balanced deck's self-check passes (--strict exit 0)", p.returncode == 0, p.stderr)
    check("balance four-bar: counterweights marked in the deck",
          open(balanced).read().count("! counterweight on link") == 2, open(balanced).read()[-600:])

    for frac in (0.5, 1.0, 0.3):
        out = os.path.join(tmp, f"sc_{frac}.nml")
        args = [KS, "balance", "data/assur_slider_crank.nml", "--method", "partial", "-o", out]
        if frac != 0.5:
            args += ["--fraction", str(frac)]
        p = subprocess.run(args, capture_output=True, text=True)
        check(f"balance slider-crank partial {frac}: exit 0", p.returncode == 0, p.stderr)
        sets = ["--set", "dphi=5"]

        def first_harmonic(path):
            rows = run([path, "--format", "csv", "--shaking"] + sets)[:-1]   # one turn, 0..355 deg
            n = len(rows)
            a = 2.0 / n * sum(float(r["F_shake_x"]) * math.cos(math.radians(float(r["phi1"]))) for r in rows)
            return a
        v = deck_values("data/assur_slider_crank.nml")
        share = 0.12 / v["dyad(1)%l2"]      # the rod's s2 along its axis over its length
        m_rec = v["dyad(1)%m3"] + v["dyad(1)%m2"] * share
        m_rot = v["dyad(1)%m2"] * (1.0 - share)
        # the crank's counterweight: its own mass (centred already), the rod's rotating part
        # and F of the reciprocating mass
        expected = (m_rot + frac * m_rec) * 0.1 * 50.0**2
        removed = first_harmonic("data/assur_slider_crank.nml") - first_harmonic(out)
        check(f"balance slider-crank partial {frac}: primary component reduced by (m_rot + F*m_rec)*r*w^2",
              abs(removed - expected) <= 1e-9 * m_rec * 0.1 * 50.0**2,
              f"removed {removed:.10e} N, expected {expected:.10e} N")

sys.exit(1 if failed else 0)
