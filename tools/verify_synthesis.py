#!/usr/bin/env python3
"""Independent re-computation of the design kinds (gear_geometry, planetary_synthesis,
cam_profile) from their decks, compared with the binary's CSV and contour output.

Usage: tools/verify_synthesis.py KINETOSTAT [--long]

Each quantity is found by a second method (Python standard library only):
- gear pair: the working pressure angle by bisection on the involute function (the program
  uses Newton's method); eps_alpha from the ends of the path of contact found by bisection
  along the line of action against the tip circles, in a frame with the centres on the y axis;
  the tip thickness from the involute's polar angle as a function of its roll angle; the
  largest specific sliding from 2001 points of the active path; the flags;
- shift = 'auto': the chosen point is acceptable, its sliding is equal, and no acceptable
  point of the equal-sliding curve on a grid of x1 (step 0.002; x2 by bisection) is nearer
  the origin by more than the grid can tell;
- the blocking contour: every point lies on its curve (the curve's quantity is 0 there);
- planetary: brute force over every (z1, z2, z3) up to the answer's ring;
- cam: s from the laws, s' and s'' by central differences of s, the pitch curve rebuilt in
  the cam frame, its normal and radius of curvature by differences of the curve, the
  pressure angle from that normal, r_prime (roller) from a bisection whose test is a dense
  grid of cam angles (20000 a turn), r_base (flat face) from the same grid, the face width.
Prints one line per mismatch and "verify_synthesis: N values, M mismatches"; exits 1 on any.
"""
import csv
import io
import math
import os
import subprocess
import sys

BIN = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("KINETOSTAT", "")
LONG = "--long" in sys.argv[2:]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
N_CMP = [0]
BAD = [0]


def run(deck, *args):
    r = subprocess.run([BIN, deck, *args], capture_output=True, text=True, cwd=ROOT)
    if r.returncode not in (0, 4):
        print("RUN FAILED", deck, args, r.stderr.strip()[:300])
        BAD[0] += 1
        return None
    return r.stdout


def run_csv(deck, *args):
    out = run(deck, "--format", "csv", "--quiet", *args)
    return list(csv.DictReader(io.StringIO(out))) if out is not None else []


def close(name, computed, expected, rtol=1e-9, atol=1e-12):
    N_CMP[0] += 1
    if not abs(computed - expected) <= atol + rtol * abs(expected):
        print("MISMATCH %s: program %r, check %r" % (name, computed, expected))
        BAD[0] += 1


def truth(name, ok, detail=""):
    N_CMP[0] += 1
    if not ok:
        print("FAILED %s %s" % (name, detail))
        BAD[0] += 1


# ---------------------------------------------------------------- gear pair

def inv(a):
    return math.tan(a) - a


def inv_inverse(v):
    """Bisection on [0, pi/2) (the program uses Newton's method), to the last bit: it stops
    when a step changes neither end (every later step would be the same)."""
    lo, hi = 0.0, math.pi / 2 - 1e-12
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if inv(mid) < v:
            if lo == mid:
                break
            lo = mid
        else:
            if hi == mid:
                break
            hi = mid
    return 0.5 * (lo + hi)


def pair(m, z1, z2, x1, x2, alpha=20.0, ha=1.0, c=0.25, sa_min=0.25, samples=2000):
    al = math.radians(alpha)
    v = inv(al) + 2 * (x1 + x2) * math.tan(al) / (z1 + z2)
    if v <= 0:
        return None
    aw_ = inv_inverse(v)
    rb0 = [m * z * math.cos(al) / 2 for z in (z1, z2)]
    a = m * (z1 + z2) / 2
    aw = a * math.cos(al) / math.cos(aw_)
    y = (aw - a) / m
    dy = x1 + x2 - y
    g = {"x1": x1, "x2": x2, "a_w": aw, "alpha_w": math.degrees(aw_), "y": y, "delta_y": dy}
    zs, xs = (z1, z2), (x1, x2)
    rb, ra = [], []
    for i in (0, 1):
        n = str(i + 1)
        d = m * zs[i]
        g["d" + n] = d
        g["db" + n] = d * math.cos(al)
        g["dw" + n] = 2 * aw * zs[i] / (z1 + z2)
        g["da" + n] = d + 2 * m * (ha + xs[i] - dy)
        g["df" + n] = d - 2 * m * (ha + c - xs[i])
        s = m * (math.pi / 2 + 2 * xs[i] * math.tan(al))
        g["s" + n] = s
        r, rbi, rai = d / 2, d * math.cos(al) / 2, g["da" + n] / 2
        rb.append(rbi)
        ra.append(rai)
        # the involute's polar angle at radius R from its roll angle t = sqrt((R/rb)^2 - 1)
        polar = lambda R: (lambda t: t - math.atan(t))(math.sqrt(max(0.0, (R / rbi) ** 2 - 1)))
        half = s / (2 * r) + polar(r) - polar(rai)   # half the tooth's angle at the tip
        g["sa" + n] = 2 * rai * half
        g["x%s_min" % n] = ha - zs[i] / 2 * math.sin(al) ** 2
        g["undercut" + n] = 1 if xs[i] < g["x%s_min" % n] else 0
        g["pointed" + n] = 1 if g["sa" + n] < sa_min * m else 0
    if ra[0] <= rb0[0] or ra[1] <= rb0[1]:
        return None                                         # no involute flank
    # the path of contact: O1 = (0, 0), O2 = (0, a_w); the line of action through the pitch
    # point (0, rw1) at alpha_w to the x axis, tangent to the base circles at N1 and N2
    # (t = distance from N1 along it); where it crosses the tip circles, by bisection
    u = (math.cos(aw_), math.sin(aw_))
    N1 = (-rb[0] * math.sin(aw_), rb[0] * math.cos(aw_))   # foot of O1 on the line
    L = aw * math.sin(aw_)                                  # N1N2
    def dist(t, centre):
        return math.hypot(N1[0] + t * u[0] - centre[0], N1[1] + t * u[1] - centre[1])
    def cross(centre, radius, lo, hi):
        flo = dist(lo, centre) - radius
        for _ in range(200):  # to the last bit (inv_inverse)
            mid = 0.5 * (lo + hi)
            if (dist(mid, centre) - radius > 0) == (flo > 0):
                if lo == mid:
                    break
                lo = mid
            else:
                if hi == mid:
                    break
                hi = mid
        return 0.5 * (lo + hi)
    # gear 2's tip circle: its crossing on N1's side of N2 (the foot of O2, t = N1N2); gear
    # 1's tip circle: its crossing on N2's side of N1 (t = 0)
    t_start = cross((0, aw), ra[1], L - 10 * aw, L)
    t_end = cross((0, 0), ra[0], 0.0, 10 * aw)
    pb = math.pi * m * math.cos(al)
    g["eps_alpha"] = (t_end - t_start) / pb
    g["interference1"] = 1 if t_start < 0 else 0
    g["interference2"] = 1 if t_end > L else 0
    # specific sliding along the active path (t: distance from N1)
    lam1 = lam2 = 0.0
    for k in range(samples + 1):
        t = t_start + (t_end - t_start) * k / samples
        lam1 = max(lam1, abs(1 - (L - t) / t * z1 / z2) if t > 0 else 1e30)
        lam2 = max(lam2, abs(1 - t / (L - t) * z2 / z1) if t < L else 1e30)
    g["lambda1"], g["lambda2"] = lam1, lam2
    return g


def acceptable(g):
    return g is not None and not any(g[k] for k in ("undercut1", "undercut2", "pointed1", "pointed2",
                                                     "interference1", "interference2")) \
        and g["eps_alpha"] >= 1.2


def check_pair_row(name, row, m, z1, z2, **rack):
    g = pair(m, z1, z2, float(row["x1"]), float(row["x2"]), **rack)
    for key, value in g.items():
        if key.startswith(("undercut", "pointed", "interference")):
            truth("%s %s" % (name, key), int(row[key]) == value, "(program %s, check %s)" % (row[key], value))
        elif key.startswith("lambda"):
            close("%s %s" % (name, key), float(row[key]), value, rtol=1e-8)
        else:
            close("%s %s" % (name, key), float(row[key]), value, rtol=1e-9, atol=1e-12)
    return g


def equal_sliding_x2(m, z1, z2, x1):
    """x2 with lambda1 = lambda2: a scan of x2 (step 0.2), then bisection."""
    def f(x2):
        g = pair(m, z1, z2, x1, x2, samples=1)
        if g is None:
            return None
        return g["lambda1"] - g["lambda2"]
    prev_x, prev = None, None
    x2 = -3.0
    while x2 <= 5.0:
        v = f(x2)
        if v is not None and prev is not None and prev < 0 <= v:
            lo, hi = prev_x, x2
            for _ in range(45):
                mid = 0.5 * (lo + hi)
                fm = f(mid)
                if fm is not None and fm < 0:
                    lo = mid
                else:
                    hi = mid
            r = 0.5 * (lo + hi)
            g = pair(m, z1, z2, x1, r, samples=1)
            if g and abs(g["lambda1"] - g["lambda2"]) < 1e-6 * (g["lambda1"] + g["lambda2"]):
                return r
            return None
        prev_x, prev = x2, v
        x2 += 0.2
    return None


def check_gears():
    decks = [("data/gear_geometry_shift.nml", 3.0, 12, 24, ()),
             ("data/gear_geometry_shift.nml", 3.0, 12, 24, ("--set", "x1=0", "--set", "x2=0")),
             ("data/gear_geometry_shift.nml", 2.0, 17, 60, ("--set", "m=2", "--set", "z1=17", "--set", "z2=60",
                                                          "--set", "x1=-0.3", "--set", "x2=1.1")),
             ("data/gear_geometry_shift.nml", 3.0, 12, 24, ("--set", "x1=1.2", "--set", "x2=-0.8")),
             ("data/gear_geometry_auto.nml", 4.0, 13, 27, ("--set", "a_w=82"))]
    for deck, m, z1, z2, args in decks:
        rows = run_csv(deck, *args)
        if rows:
            check_pair_row("%s %s" % (deck, " ".join(args[1::2])), rows[0], m, z1, z2)
    # a prescribed centre distance: the sum of the shifts and the equal sliding
    rows = run_csv("data/gear_geometry_auto.nml", "--set", "a_w=82")
    if rows:
        r = rows[0]
        close("centre a_w", float(r["a_w"]), 82.0, rtol=1e-12)
        close("centre sliding", float(r["lambda1"]), float(r["lambda2"]), rtol=1e-7)
    # shift = 'auto'
    cases = [("data/gear_geometry_auto.nml", 4.0, 13, 27, ())]
    if LONG:
        cases += [("data/gear_geometry_auto.nml", 4.0, z1, z2, ("--set", "z1=%d" % z1, "--set", "z2=%d" % z2))
                  for z1, z2 in ((12, 24), (20, 40), (17, 17), (25, 75))]
    for deck, m, z1, z2, args in cases:
        rows = run_csv(deck, *args)
        if not rows:
            continue
        r = rows[0]
        name = "auto %d/%d" % (z1, z2)
        g = check_pair_row(name, r, m, z1, z2)
        truth(name + " acceptable", acceptable(g))
        close(name + " equal sliding", g["lambda1"], g["lambda2"], rtol=1e-6)
        chosen = float(r["x1"]) ** 2 + float(r["x2"]) ** 2
        best, where = None, None
        step = 0.002 if LONG else 0.02
        x1 = -1.0
        while x1 <= 3.0:
            x2 = equal_sliding_x2(m, z1, z2, x1)
            if x2 is not None and acceptable(pair(m, z1, z2, x1, x2, samples=1)):
                n = x1 * x1 + x2 * x2
                if best is None or n < best:
                    best, where = n, (x1, x2)
            x1 += step
        truth(name + " nearest the origin", best is not None and chosen <= best + 1e-6,
              "(program x1^2 + x2^2 = %r, grid's best %r at %r)" % (chosen, best, where))


def check_contour():
    r = subprocess.run([BIN, "contour", "data/gear_geometry_auto.nml"], capture_output=True, text=True, cwd=ROOT)
    truth("contour runs", r.returncode == 0, r.stderr[:200])
    rows = list(csv.DictReader(io.StringIO(r.stdout)))
    m, z1, z2 = 4.0, 13, 27
    names = set()
    for row in rows:
        name, x1, x2 = row["curve"], float(row["x1"]), float(row["x2"])
        names.add(name)
        if name.startswith("undercut"):
            i = int(name[-1])
            x = x1 if i == 1 else x2
            close("contour %s" % name, x, 1 - (z1 if i == 1 else z2) / 2 * math.sin(math.radians(20)) ** 2)
            continue
        g = pair(m, z1, z2, x1, x2, samples=1)
        if name.startswith("pointed"):
            level = g["sa" + name[-1]] - 0.25 * m
            scale = m
        elif name == "eps1":
            level, scale = g["eps_alpha"] - 1, 1
        elif name == "eps1_2":
            level, scale = g["eps_alpha"] - 1.2, 1
        else:
            # interference: the active path's end at N1 (gear 1) or N2 (gear 2)
            al = math.radians(g["alpha_w"])
            L = g["a_w"] * math.sin(al)
            rho = lambda n: math.sqrt(max(0, (g["da" + n] / 2) ** 2 - (g["db" + n] / 2) ** 2))
            level = L - (rho("2") if name[-1] == "1" else rho("1"))
            scale = L
        truth("contour %s at (%.6f, %.6f)" % (name, x1, x2), abs(level) <= 1e-9 * scale, "level %r" % level)
    truth("contour has its curves", {"undercut1", "undercut2", "pointed1", "pointed2", "eps1", "eps1_2",
                                     "interference1", "interference2"} <= names, sorted(names))


# ---------------------------------------------------------------- planetary train

def check_planetary():
    cases = [("data/planetary_synthesis.nml", 5.0, 3, 0.04, 17, 85, ())]
    cases += [("data/planetary_synthesis.nml", u, k, tol, 17, 85, ("--set", "u=%g" % u, "--set", "k=%d" % k,
                                                                   "--set", "u_tolerance=%g" % tol))
              for u, k, tol in ((3.2, 3, 0.04), (7.1, 3, 0.02), (4.0, 5, 0.01), (6.3, 2, 0.0))]
    for deck, u, k, tol, zmin, zring, args in cases:
        rows = run_csv(deck, *args)
        if not rows:
            continue
        r = rows[0]
        z1, z2, z3 = int(r["z1"]), int(r["z2"]), int(r["z3"])

        def ok(a, b, c):
            return (c == a + 2 * b and (a + c) % k == 0 and (k == 1 or (a + b) * math.sin(math.pi / k) > b + 2)
                    and a >= zmin and b >= zmin and c >= zring and abs(1 + c / a - u) <= tol * u)
        name = "planetary u=%g k=%d" % (u, k)
        truth(name + " meets every condition", ok(z1, z2, z3), (z1, z2, z3))
        close(name + " u_actual", float(r["u_actual"]), 1 + z3 / z1, rtol=1e-12)
        smaller = [(a, (c - a) // 2, c) for c in range(zring, z3) for a in range(1, c)
                   if (c - a) % 2 == 0 and ok(a, (c - a) // 2, c)]
        truth(name + " no smaller ring", not smaller, smaller[:3])
        same = [(a, (z3 - a) // 2) for a in range(1, z3) if (z3 - a) % 2 == 0 and ok(a, (z3 - a) // 2, z3)]
        nearest = min(abs(1 + z3 / a - u) for a, _ in same)
        truth(name + " nearest ratio", abs(abs(1 + z3 / z1 - u) - nearest) < 1e-12)


# ---------------------------------------------------------------- cam

def law(kind, xi, h):
    if kind == "dwell":
        return 0.0
    if kind == "constant_velocity":
        return h * xi
    if kind == "parabolic":
        return 2 * h * xi * xi if xi <= 0.5 else h * (1 - 2 * (1 - xi) ** 2)
    if kind == "harmonic":
        return h / 2 * (1 - math.cos(math.pi * xi))
    if kind == "cycloidal":
        return h * (xi - math.sin(2 * math.pi * xi) / (2 * math.pi))
    return h * (10 * xi ** 3 - 15 * xi ** 4 + 6 * xi ** 5)


class Cam:
    def __init__(self, laws, betas, lifts, scale=1.0):
        self.seg = []
        phi, s = 0.0, 0.0
        for k, b, h in zip(laws, betas, lifts):
            self.seg.append((k, math.radians(b), h * scale, phi, s))
            phi += math.radians(b)
            s += h * scale

    def s(self, phi, side=0):
        """Displacement at phi (rad); side -1/+1 takes the segment ending/starting at a joint."""
        for i, (k, b, h, p0, s0) in enumerate(self.seg):
            last = i == len(self.seg) - 1
            if p0 <= phi < p0 + b or (last and phi >= p0):
                xi = (phi - p0) / b
                return s0 + law(k, min(1.0, max(0.0, xi)), h)
        return 0.0

    def derivs(self, phi, h=1e-4):
        """s, s', s'' by central differences inside a segment (one-sided at its ends)."""
        i = self.index(phi)
        k, b, hh, p0, s0 = self.seg[i]
        xi = (phi - p0) / b
        f = lambda p: s0 + law(k, (p - p0) / b, hh)   # the segment's own law, continued
        return f(phi), (f(phi + h) - f(phi - h)) / (2 * h), (f(phi + h) - 2 * f(phi) + f(phi - h)) / h ** 2

    def index(self, phi):
        for i, (k, b, h, p0, s0) in enumerate(self.seg):
            if p0 <= phi < p0 + b:
                return i
        return len(self.seg) - 1


def rot(v, a):
    c, s = math.cos(a), math.sin(a)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def check_cam_deck(deck, cfg, args=()):
    rows = run_csv(deck, *args)
    if not rows:
        return
    out = run(deck, "--format", "json", "--quiet", *args)
    import json
    summary = {e["name"]: e["value"] for e in json.loads(out)["summary"]}
    cam = Cam(cfg["law"], cfg["beta"], cfg["lift"], math.radians(1) if cfg["follower"] == "oscillating" else 1.0)
    sg = 1.0 if cfg["omega"] > 0 else -1.0
    w = abs(cfg["omega"])
    name = "%s %s" % (deck, " ".join(args[1::2]))
    # the law at the steps (s'' jumps in the middle of a parabolic segment: not compared there)
    top = max(abs(float(r["d2s"])) for r in rows)
    top_ds = max(abs(float(r["ds"])) for r in rows)
    for r in rows:
        phi = math.radians(float(r["phi"]))
        s, ds, d2s = cam.derivs(phi)
        unit = math.degrees(1) if cfg["follower"] == "oscillating" else 1.0
        close(name + " s at %s" % r["phi"], float(r["s"]), s * unit, rtol=1e-9, atol=1e-12)
        k, b, hh, p0, s0 = cam.seg[cam.index(phi)]
        if not (k == "parabolic" and abs((phi - p0) / b - 0.5) < 1e-9):
            close(name + " ds at %s" % r["phi"], float(r["ds"]), ds, rtol=1e-6, atol=1e-7 * top_ds)
            close(name + " d2s at %s" % r["phi"], float(r["d2s"]), d2s, rtol=1e-5, atol=1e-6 * top)
        close(name + " v at %s" % r["phi"], float(r["v"]), float(r["ds"]) * w, rtol=1e-12)
        close(name + " a at %s" % r["phi"], float(r["a"]), float(r["d2s"]) * w * w, rtol=1e-12)
    if cfg["follower"] == "flat":
        rb = summary["r_base"]
        # r_base from a dense grid: the least with rb + s + s'' >= rho_min
        need = max(cfg["rho_min"] - sum(cam.derivs(p)[::2]) for p in
                   (2 * math.pi * k / 20000 for k in range(20000)))
        close(name + " r_base (dense grid)", rb, need, rtol=1e-6)
        width = max(cam.derivs(2 * math.pi * k / 20000)[1] for k in range(20000)) - \
            min(cam.derivs(2 * math.pi * k / 20000)[1] for k in range(20000))
        close(name + " face_width", summary["face_width"], width, rtol=1e-6)
        for r in rows:
            truth(name + " rho >= rho_min at %s" % r["phi"], float(r["rho"]) >= cfg["rho_min"] * (1 - 1e-12),
                  r["rho"])
            phi = math.radians(float(r["phi"]))
            s, ds, d2s = cam.derivs(phi)
            close(name + " rho at %s" % r["phi"], float(r["rho"]), rb + s + d2s, rtol=1e-4, atol=1e-9)
            # the contact point (sg s', rb + s) turned into the cam frame
            c = rot((sg * ds, rb + s), -sg * phi)
            close(name + " x_profile", float(r["x_profile"]), c[0], rtol=1e-5, atol=1e-9)
            close(name + " y_profile", float(r["y_profile"]), c[1], rtol=1e-5, atol=1e-9)
        return
    rr = cfg["roller_radius"]
    lim = (math.radians(cfg["pmax"]), math.radians(cfg.get("pret", cfg["pmax"])))

    def pitch(phi, rp, psi0=None):
        """The pitch point in the fixed frame at cam angle phi (the law's own segment)."""
        s = cam.derivs(phi)[0]
        if cfg["follower"] == "roller":
            e = cfg["offset"]
            return (e, math.sqrt(rp * rp - e * e) + s)
        P = cfg["pivot"]
        d = math.hypot(*P)
        ez = (-P[0] / d, -P[1] / d)
        a = rot(ez, psi0 + s)
        return (P[0] + cfg["arm"] * a[0], P[1] + cfg["arm"] * a[1])

    def psi0_of(rp):
        P = cfg["pivot"]
        d = math.hypot(*P)
        return math.acos((d * d + cfg["arm"] ** 2 - rp * rp) / (2 * d * cfg["arm"]))

    def theta(phi, rp, psi0=None, h=1e-6):
        """The pressure angle from the pitch curve's normal in the cam frame (differences)."""
        cam_pt = lambda p: rot(pitch(p, rp, psi0), -sg * p)
        a, b = cam_pt(phi - h), cam_pt(phi + h)
        t = (b[0] - a[0], b[1] - a[1])
        n = (sg * -t[1], sg * t[0])                     # outward (the curve runs against the cam)
        n = rot(n, sg * phi)                              # back to the fixed frame
        B = pitch(phi, rp, psi0)
        if cfg["follower"] == "roller":
            u = (0.0, 1.0)
        else:
            P = cfg["pivot"]
            u = (-(B[1] - P[1]), B[0] - P[0])
        uu = math.hypot(*u)
        u = (u[0] / uu, u[1] / uu)
        wv = (u[1], -u[0])
        return math.atan2(n[0] * wv[0] + n[1] * wv[1], n[0] * u[0] + n[1] * u[1])

    rp = summary["r_prime"]
    psi0 = math.radians(summary["psi0"]) if "psi0" in summary else None
    close(name + " r_base = r_prime - roller", summary["r_base"], rp - rr, rtol=1e-12)
    for r in rows:
        phi = math.radians(float(r["phi"]))
        i = cam.index(phi)
        close(name + " theta at %s" % r["phi"], float(r["theta"]), math.degrees(theta(phi, rp, psi0)), atol=1e-4,
              rtol=0)
        truth(name + " theta within its limit at %s" % r["phi"],
              abs(float(r["theta"])) <= math.degrees(lim[1 if cam.seg[i][2] < 0 else 0]) * (1 + 1e-9), r["theta"])
        B = rot(pitch(phi, rp, psi0), -sg * phi)
        close(name + " x_pitch", float(r["x_pitch"]), B[0], rtol=1e-9, atol=1e-12)
        close(name + " y_pitch", float(r["y_pitch"]), B[1], rtol=1e-9, atol=1e-12)
        close(name + " roller", math.hypot(float(r["x_profile"]) - B[0], float(r["y_profile"]) - B[1]), rr,
              rtol=1e-9, atol=1e-12)
        # the pitch curve's radius of curvature from three points 1e-4 rad apart
        h = 1e-4
        p0, p1, p2 = (rot(pitch(q, rp, psi0), -sg * q) for q in (phi - h, phi, phi + h))
        if cam.index(phi - h) == i == cam.index(phi + h):
            a, b, c = math.dist(p0, p1), math.dist(p1, p2), math.dist(p0, p2)
            area2 = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0])
            if abs(area2) > 1e-14:
                rho = -sg * a * b * c / (2 * area2)
                close(name + " rho_pitch at %s" % r["phi"], float(r["rho_pitch"]), rho, rtol=1e-4)
    # the least pitch circle from a bisection over a dense grid of cam angles

    def fits(radius):
        p0_ = psi0_of(radius) if cfg["follower"] == "oscillating" else None
        n = 20000 if LONG else 4000
        for k in range(n + 1):
            for side in (-1, 1):
                phi = 2 * math.pi * k / n + side * 1e-9
                if not 0 <= phi <= 2 * math.pi:
                    continue
                i = cam.index(phi)
                if abs(theta(phi, radius, p0_)) > lim[1 if cam.seg[i][2] < 0 else 0]:
                    return False
        return True
    lo, hi = rp * 0.9, rp * 1.1
    truth(name + " r_prime fits", fits(rp * (1 + 1e-6)))
    truth(name + " a smaller pitch circle does not", not fits(rp * (1 - 1e-3)))
    if LONG:
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            if fits(mid):
                hi = mid
            else:
                lo = mid
        close(name + " r_prime (dense bisection)", rp, hi, rtol=1e-5)


def check_cams():
    check_cam_deck("data/cam_profile_roller.nml",
                   dict(follower="roller", law=["cycloidal", "dwell", "harmonic", "dwell"], beta=[120, 60, 120, 60],
                        lift=[0.02, 0, -0.02, 0], offset=0.005, roller_radius=0.008, pmax=30, pret=45, omega=10.0))
    check_cam_deck("data/cam_profile_roller.nml",
                   dict(follower="roller", law=["cycloidal", "dwell", "harmonic", "dwell"], beta=[120, 60, 120, 60],
                        lift=[0.02, 0, -0.02, 0], offset=-0.004, roller_radius=0.008, pmax=30, pret=45, omega=-10.0),
                   ("--set", "omega=-10", "--set", "offset=-0.004"))
    check_cam_deck("data/cam_profile_flat.nml",
                   dict(follower="flat", law=["harmonic", "harmonic"], beta=[180, 180], lift=[0.05, -0.05],
                        rho_min=0.05, omega=1.0))
    check_cam_deck("data/cam_profile_flat.nml",
                   dict(follower="flat", law=["poly345", "dwell", "cycloidal", "dwell"], beta=[90, 90, 90, 90],
                        lift=[0.02, 0, -0.02, 0], rho_min=0.005, omega=-3.0),
                   ("--set", "law='poly345','dwell','cycloidal','dwell'", "--set", "beta=90,90,90,90",
                    "--set", "lift=0.02,0,-0.02,0", "--set", "rho_min=0.005", "--set", "omega=-3"))
    check_cam_deck("data/cam_profile_oscillating.nml",
                   dict(follower="oscillating", law=["poly345", "dwell", "parabolic", "dwell"],
                        beta=[100, 80, 100, 80], lift=[20, 0, -20, 0], arm=0.08, pivot=(0.09, 0.06),
                        roller_radius=0.01, pmax=40, pret=50, omega=5.0))


def main():
    if not BIN or not os.access(BIN, os.X_OK):
        print("verify_synthesis: no kinetostat binary (give its path)")
        return 1
    check_gears()
    check_contour()
    check_planetary()
    check_cams()
    print("verify_synthesis: %d values, %d mismatches" % (N_CMP[0], BAD[0]))
    return 1 if BAD[0] else 0


if __name__ == "__main__":
    sys.exit(main())
