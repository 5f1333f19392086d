#!/usr/bin/env python3
"""Checks of kinetostat's plans (--format json --at K --plans; standard library only).

  plans_check.py PLANS.json RUN.csv [--lever] [--polygons]
      RUN.csv is the same deck's `--format csv --kinematics`. Checks, each printing expected
      vs computed on failure:
      - the plans' equations hold: velocity_residual <= 1e-9 x (1 + largest velocity image),
        acceleration_residual <= 1e-9 x (1 + largest acceleration image);
      - every centre of mass S<i> on the acceleration plan equals the CSV's ax_S<i>, ay_S<i>
        at that step (relative 1e-9 of the largest image, absolute 1e-9 m/s^2);
      - every vector equation of the velocity plan (velocity_equations): its relative
        velocities omega x (P - Q) and its chain from the image of Q to the image of P;
      - every vector equation of the acceleration plan (acceleration_equations): its normal
        component is -omega^2 (P - Q), its tangential eps x (P - Q) (omega, eps of its link,
        P, Q the point and the known point it starts from, all from the CSV), its Coriolis
        component 2 omega x v_rel (v_rel from the velocity plan; "reverse" equations: a point
        of the guide's link from the slider's, 2 omega_slider x v_rel), and the image of Q plus
        its components is the image of P (relative 1e-9 of the largest vector involved);
      - with --polygons: every force polygon (of the links, link_force_plans, and of the
        groups, force_plans) closes (closure and the vectors' sum <= 1e-9 of its largest
        vector), and every pair force in a polygon (or its reaction F<j><i>; the sum of its
        tangential and normal parts, which must be perpendicular) has the magnitude of the
        CSV's <F>_x, <F>_y components (relative 1e-9 of the polygon's largest vector);
      - with --groups: the same for the groups' polygons only;
      - with --lever: Zhukovsky's lever equals the run's driving moment (relative 1e-9,
        absolute 1e-9 N*m); when the CSV has friction (P_loss_<pair> columns) the lever
        lists every such pair (zhukovsky.friction.pairs): a revolute pair's relative rate is
        the CSV's omega<on> - omega<from> (the frame at rest), its couple opposes it, a
        prismatic pair's force opposes its relative velocity, each pair's power on the lever
        (couple x relative rate, force . relative velocity) is minus its P_loss_<pair>, and
        the friction's total power is minus P_loss (relative 1e-9 of P_loss, absolute 1e-9 W);
        on a steady cycle's true motion (zhukovsky.flywheel) the flywheel's and the rotor's
        moment is -J times the driving link's eps column (relative 1e-9, absolute 1e-9 N*m).
Exit status 0 when every check passes, 1 otherwise.
"""
import csv
import json
import math
import sys


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    flags = {a for a in sys.argv[1:] if a.startswith("--")}
    if len(args) != 2:
        print(__doc__)
        sys.exit(1)
    plans = json.load(open(args[0]))
    rows = list(csv.reader(open(args[1], newline="")))
    header, row = rows[0], rows[plans["step"]]
    col = {name: float(row[i]) for i, name in enumerate(header)}
    bad = []

    def largest(plan):
        return max([math.hypot(p["x"], p["y"]) for p in plan["points"]] or [0.0])

    vmax, amax = largest(plans["velocity_plan"]), largest(plans["acceleration_plan"])
    if plans["velocity_residual"] > 1e-9 * (1 + vmax):
        bad.append(f"velocity equations: residual {plans['velocity_residual']:.3e} m/s (largest image {vmax:.3e})")
    if plans["acceleration_residual"] > 1e-9 * (1 + amax):
        bad.append(f"acceleration equations: residual {plans['acceleration_residual']:.3e} m/s^2 "
                   f"(largest image {amax:.3e})")
    for p in plans["acceleration_plan"]["points"]:
        name = p["name"]
        if "ax_" + name in col:
            expected = (col["ax_" + name], col["ay_" + name])
            if math.hypot(p["x"] - expected[0], p["y"] - expected[1]) > 1e-9 * amax + 1e-9:
                bad.append(f"acceleration of {name}: expected {expected}, plan ({p['x']}, {p['y']})")
    vimg = {p["name"]: (p["x"], p["y"]) for p in plans["velocity_plan"]["points"]}
    aimg = {p["name"]: (p["x"], p["y"]) for p in plans["acceleration_plan"]["points"]}

    def pos(name):
        return (col["x_" + name], col["y_" + name])

    def close(got, want, scale):
        return math.hypot(got[0] - want[0], got[1] - want[1]) <= 1e-9 * max(scale, 1.0)

    for eq in plans.get("acceleration_equations", []):
        point, link, start = eq["point"], eq["link"], eq["from"]
        where = f"equation of {point} (link {link or 'frame'}, from {start or 'the pole'})"
        if point not in aimg or (start and start not in aimg):
            bad.append(f"{where}: a point without an image")
            continue
        base = aimg[start] if start else (0.0, 0.0)
        total = list(base)
        scale = max([math.hypot(*aimg[point]), math.hypot(*base)]
                    + [math.hypot(v["x"], v["y"]) for v in eq["vectors"]])
        for v in eq["vectors"]:
            total[0] += v["x"]
            total[1] += v["y"]
            got = (v["x"], v["y"])
            if v["kind"] in "ntk":
                try:
                    r = (pos(point)[0] - pos(start)[0], pos(point)[1] - pos(start)[1])
                    if "phi" + link in col or "omega" + link in col:
                        om, ep = col["omega" + link], col["eps" + link]
                    else:  # a translating link (a slider on the frame): no angle columns
                        om, ep = 0.0, 0.0
                except KeyError as missing:
                    bad.append(f"{where}: no CSV column {missing}")
                    continue
                if v["kind"] == "n":
                    want = (-om * om * r[0], -om * om * r[1])
                elif v["kind"] == "t":
                    want = (-ep * r[1], ep * r[0])
                elif eq.get("reverse"):
                    # the guide's point relative to the slider (at `from`), in the slider's turning frame
                    slider = eq["slider"]
                    om_m = col["omega" + slider] if "omega" + slider in col else 0.0
                    vg = (vimg[point][0] + om * r[1], vimg[point][1] - om * r[0])
                    vrel = (vg[0] - vimg[start][0], vg[1] - vimg[start][1])
                    want = (-2 * om_m * vrel[1], 2 * om_m * vrel[0])
                else:
                    vg = (vimg[start][0] - om * r[1], vimg[start][1] + om * r[0])
                    vrel = (vimg[point][0] - vg[0], vimg[point][1] - vg[1])
                    want = (-2 * om * vrel[1], 2 * om * vrel[0])
                if not close(got, want, scale):
                    bad.append(f"{where}: {v['name']} expected {want}, plan {got}")
        if not close(total, aimg[point], scale):
            bad.append(f"{where}: image of {start or 'the pole'} + components = {tuple(total)}, "
                       f"image of {point} {aimg[point]}")
    # the velocity plan's equations: each relative velocity v_PQ = omega_L x (P - Q), and the
    # chain from the image of Q (or the pole) ends at the image of P
    for eq in plans.get("velocity_equations", []):
        point, link, start = eq["point"], eq["link"], eq["from"]
        where = f"velocity equation of {point} (link {link or 'frame'}, from {start or 'the pole'})"
        if point not in vimg or (start and start not in vimg):
            bad.append(f"{where}: a point without an image")
            continue
        base = vimg[start] if start else (0.0, 0.0)
        total = list(base)
        scale = max([math.hypot(*vimg[point]), math.hypot(*base)]
                    + [math.hypot(v["x"], v["y"]) for v in eq["vectors"]])
        for v in eq["vectors"]:
            total[0] += v["x"]
            total[1] += v["y"]
            if v["kind"] == "t":
                try:
                    r = (pos(point)[0] - pos(start)[0], pos(point)[1] - pos(start)[1])
                    om = col["omega" + link] if "omega" + link in col else 0.0
                except KeyError as missing:
                    bad.append(f"{where}: no CSV column {missing}")
                    continue
                want = (-om * r[1], om * r[0])
                if not close((v["x"], v["y"]), want, scale):
                    bad.append(f"{where}: {v['name']} expected {want}, plan {(v['x'], v['y'])}")
        if not close(total, vimg[point], scale):
            bad.append(f"{where}: image of {start or 'the pole'} + relative velocities = {tuple(total)}, "
                       f"image of {point} {vimg[point]}")
    if "velocity_equations" in plans and len(plans["velocity_equations"]) != len(plans.get("acceleration_equations", [])):
        bad.append("the velocity plan has not one equation per equation of the acceleration plan")
    polygon_sets = []
    if "--polygons" in flags:
        polygon_sets = [("link", plans["link_force_plans"]), ("group", plans["force_plans"])]
    elif "--groups" in flags:
        polygon_sets = [("group", plans["force_plans"])]
    for key, polygons in polygon_sets:
        for poly in polygons:
            what = f"force polygon of {key} {poly[key]}"
            if poly["closure"] > 1e-9:
                bad.append(f"{what} does not close: {poly['closure']:.3e} of its "
                           f"largest vector ({[v['name'] for v in poly['vectors']]})")
            big = max([math.hypot(v["x"], v["y"]) for v in poly["vectors"]] or [0.0])
            gap = (sum(v["x"] for v in poly["vectors"]), sum(v["y"] for v in poly["vectors"]))
            if math.hypot(*gap) > 1e-9 * max(big, 1.0):
                bad.append(f"{what}: the vectors sum to {gap}, largest vector {big}")
            # a reaction split into its tangential and normal parts: perpendicular parts, summed
            reactions = {}
            for v in poly["vectors"]:
                name = v["name"].split("^")[0]
                if v.get("kind") in ("n", "t", "f"):
                    reactions.setdefault(name, []).append(v)
                elif name + "_x" in col or (len(name) == 3 and "F" + name[2] + name[1] + "_x" in col):
                    reactions.setdefault(name, []).append(v)
            for name, parts in reactions.items():
                if len(parts) == 2:
                    dot = parts[0]["x"] * parts[1]["x"] + parts[0]["y"] * parts[1]["y"]
                    if abs(dot) > 1e-9 * max(big, 1.0) ** 2:
                        bad.append(f"{what}: the parts of {name} are not perpendicular (dot {dot!r})")
                vx, vy = sum(p["x"] for p in parts), sum(p["y"] for p in parts)
                csv_name = name
                if csv_name + "_x" not in col and len(name) == 3 and name[0] == "F":
                    csv_name = "F" + name[2] + name[1]
                if csv_name + "_x" not in col:
                    bad.append(f"{what}: reaction {name} is no pair force of the CSV")
                    continue
                # the components' frame (the angle column's) may differ from the position
                # frame: compare magnitudes
                f = math.hypot(col[csv_name + "_x"], col[csv_name + "_y"])
                mag = math.hypot(vx, vy)
                if abs(mag - f) > 1e-9 * max(big, 1.0):
                    bad.append(f"{name} in the {what}: |F| expected {f!r}, plan {mag!r}")
    if "--lever" in flags:
        z = plans["zhukovsky"]
        if z["effort"] is None:
            bad.append(f"no lever: {z.get('note', '')}")
        elif abs(z["effort"] - z["run"]) > 1e-9 * abs(z["run"]) + 1e-9:
            bad.append(f"Zhukovsky's lever: expected {z['driver']} = {z['run']!r}, lever {z['effort']!r}")
        losses = {name[len("P_loss_"):]: v for name, v in col.items() if name.startswith("P_loss_")}
        if losses and z["effort"] is not None:
            check_friction(z, losses, col, bad)
        if "flywheel" in z:
            eps = col.get("eps" + z["driver"][1:])
            expected = None if eps is None else -z["flywheel"]["J"] * eps
            if expected is None or abs(z["flywheel"]["moment"] - expected) > 1e-9 * abs(expected) + 1e-9:
                bad.append(f"lever flywheel: moment expected -J*eps{z['driver'][1:]} = {expected!r}, "
                           f"lever {z['flywheel']['moment']!r}")
    if bad:
        print(f"{args[0]} (step {plans['step']}):")
        print("\n".join(bad))
        sys.exit(1)


def check_friction(z, losses, col, bad):
    """The pairs' friction on the lever against the CSV's P_loss_<pair> and omega columns."""
    if "friction" not in z:
        bad.append(f"Zhukovsky's lever: the CSV has friction in {sorted(losses)}, the lever none")
        return
    tol = 1e-9 * max(col.get("P_loss", 0.0), 1.0)
    pairs = {p["pair"]: p for p in z["friction"]["pairs"]}
    if sorted(pairs) != sorted(losses):
        bad.append(f"lever friction: pairs expected {sorted(losses)}, lever {sorted(pairs)}")

    def omega(link):
        return col.get("omega" + link, col.get("omegaL" + link, 0.0))

    total = 0.0
    for name, loss in losses.items():
        if name not in pairs:
            continue
        p = pairs[name]
        if "moment" in p:
            rel = omega(p["on"]) - omega(p["from"])
            if abs(p["relative"] - rel) > 1e-9 * (abs(omega(p["on"])) + abs(omega(p["from"]))) + 1e-12:
                bad.append(f"lever friction {name}: relative rate expected {rel!r}, lever {p['relative']!r}")
            if p["moment"] * p["relative"] > 0:
                bad.append(f"lever friction {name}: couple {p['moment']!r} turns with the relative rate {p['relative']!r}")
            power = p["moment"] * p["relative"]
        else:
            f, v = p["force"], p["relative"]
            power = f["x"] * v["x"] + f["y"] * v["y"]
            if abs(f["x"] * v["y"] - f["y"] * v["x"]) > 1e-9 * math.hypot(f["x"], f["y"]) * math.hypot(v["x"], v["y"]) \
                    or power > 0:
                bad.append(f"lever friction {name}: force {f} does not oppose the relative velocity {v}")
        for what, value in (("power (moment x rate)", power), ("power", p["power"])):
            if abs(value + loss) > tol:
                bad.append(f"lever friction {name}: {what} expected -P_loss_{name} = {-loss!r}, lever {value!r}")
        total += p["power"]
    if abs(z["friction"]["power"] + col["P_loss"]) > tol or abs(total - z["friction"]["power"]) > tol:
        bad.append(f"lever friction: total power expected -P_loss = {-col['P_loss']!r}, lever "
                   f"{z['friction']['power']!r} (pairs' sum {total!r})")


if __name__ == "__main__":
    main()
