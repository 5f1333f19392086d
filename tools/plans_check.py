#!/usr/bin/env python3
"""Checks of kinetostat's plans (--format json --at K --plans; standard library only).

  plans_check.py PLANS.json... RUN.csv [--lever] [--polygons] [--groups] [--order] [--values]
      RUN.csv is the same deck's `--format csv --kinematics`, PLANS.json its steps' plans.
      Checks, each printing expected vs computed on failure:
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
        moment is -J times the driving link's eps column (relative 1e-9, absolute 1e-9 N*m);
        and the lever's loads (zhukovsky.loads): every load force of the links' force
        polygons is one of them (by name; the driver's force apart), the flywheel's moment is
        one (M_fw), a force's power is its force . the velocity image of its point, a
        moment's is its value x the CSV's omega of its link and its couple's force is
        value / l perpendicular to its two points, every arm is |power| / |F| (arm_mm the same
        over the lever's scale), the balancing force's power is effort x rate (P_bal at its
        point along that point's velocity), and the loads' powers and the balancing power sum
        to zero (1e-9 of the largest);
      - with --order: every group's force polygon in the course's order - the tangential and
        normal parts of a reaction adjacent (the last and the first part of the polygon
        count as adjacent), every reaction (split or whole) listed whole in "reactions"
        (its parts' sum; drawn from vertex tail to vertex head of the polygon), a dyad's (II)
        inner reaction listed and equal to the vertex head minus the vertex tail and to the
        CSV's pair force of its two links (its magnitude), and for a dyad the first part of
        the polygon the tangential part of the reaction whose normal part closes it;
      - with --values: the values table - every v_<P> and a_<P> is |the image of P|, every
        omega<i> and eps<i> is |the CSV's omega<i>, eps<i>| with its sense (ccw for a positive
        value, cw for a negative one), every other v_.. or a_.. entry is the magnitude of the
        plans' vector of that name (relative 1e-9);
  plans_check.py sheet SHEET.svg PLANS.json RUN.csv
      The plans sheet (--format plans --at K) against the plans of the same step: the
      mechanism group's joints and centres of mass (data-joint, data-point) are where its view
      (data-origin, data-scale, data-rotation) puts the CSV's positions, the velocity plan's
      image marks (data-image) where its group (data-pole, data-mu, data-rotation) puts the
      plans' velocities (0.01 mm, the SVG's rounding); no transform on them or their
      ancestors; the rotation is the JSON's sheet_rotation; and for every relative velocity
      of a link's two points (a tangential term v_PQ of the velocity equations) the drawn
      image difference is perpendicular to the drawn link PQ: |cos| <= 0.02 mm / the shorter
      of the two (both at least 2 mm on the sheet).
  plans_check.py dxf SHEET.dxf PLANS.json
      The plans sheet as DXF (--format dxf --at K --plans) read back: the groups' comments
      (velocity-plan, acceleration-plan, lever, force-polygon) give each drawing's pole and
      scale; every image of both plans has its circle on layer VPLAN or APLAN at pole +
      (q1, -q2) / mu (q the image turned by the sheet's rotation; DXF y = paper height - y;
      0.01 mm), the lever (layer LEVER) and every unit's force polygon (POLYGONS) have as many
      arrowheads (SOLID) as vectors drawn (1 mm and longer).
  plans_check.py groups PLANS.json... [--structure FORMULA]
      the groups (units of the structure) are the same at every step given, and with
      --structure equal the structure formula `kinetostat structure` prints (the units'
      labels, "I(0,1) -> II(2,3)").
Exit status 0 when every check passes, 1 otherwise.
"""
import csv
import json
import math
import re
import sys


def groups_main(argv):
    """The groups of several steps' plans: the same at every step, the structure formula's."""
    structure = None
    if "--structure" in argv:
        i = argv.index("--structure")
        structure = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    bad = []
    seen = None
    for path in argv:
        plans = json.load(open(path))
        if "groups" in plans:
            labels = [g["label"] for g in plans["groups"]]
        else:  # the force polygons' groups, the input link last
            labels = [p["group"] for p in plans["force_plans"]][::-1]
        if seen is None:
            seen = (path, labels)
        elif labels != seen[1]:
            bad.append(f"groups change between steps: {seen[0]} {seen[1]}, {path} {labels}")
        order = [p.get("label", p["group"]) for p in plans["force_plans"]]
        if order != labels[::-1]:
            bad.append(f"{path}: force polygons {order} not the groups {labels} from the last")
    if structure is not None and seen is not None:
        want = [u.strip() for u in structure.split("->")]
        if seen[1] != want:
            bad.append(f"groups {seen[1]}, the structure formula {want}")
    if bad:
        print("\n".join(bad))
        sys.exit(1)


def turned(v, deg):
    a = math.radians(deg)
    return (math.cos(a) * v[0] - math.sin(a) * v[1], math.sin(a) * v[0] + math.cos(a) * v[1])


def sheet_main(argv):
    """The plans sheet's marks against the plans and the CSV; perpendicular relative velocities."""
    import xml.etree.ElementTree as ET
    svg_path, json_path, csv_path = argv
    plans = json.load(open(json_path))
    rows = list(csv.reader(open(csv_path, newline="")))
    header, row = rows[0], rows[plans["step"]]
    col = {name: float(row[i]) for i, name in enumerate(header)}
    ns = "{http://www.w3.org/2000/svg}"
    root = ET.parse(svg_path).getroot()
    bad = []
    parent = {c: p for p in root.iter() for c in p}

    def chain_has_transform(el):
        while el is not None:
            if el.get("transform"):
                return True
            el = parent.get(el)
        return False

    def centre(el):
        return (float(el.get("cx")), float(el.get("cy")))

    groups = {}
    for g in root.iter(ns + "g"):
        groups.setdefault(g.get("class"), g)
    mech, vplan = groups.get("mechanism"), groups.get("velocity-plan")
    if mech is None or vplan is None:
        print(f"{svg_path}: no mechanism or velocity-plan group")
        sys.exit(1)
    ox, oy = map(float, mech.get("data-origin").split())
    scale, rot = float(mech.get("data-scale")), float(mech.get("data-rotation"))
    if abs(rot - plans["sheet_rotation"]) > 1e-9 * max(1.0, abs(rot)):
        bad.append(f"the mechanism drawn turned by {rot} deg, the JSON's sheet_rotation {plans['sheet_rotation']}")
    joints = {}
    for el in mech.iter():
        name = el.get("data-joint") or el.get("data-point")
        if not name:
            continue
        if chain_has_transform(el):
            bad.append(f"joint {name}: a transform on it or an ancestor")
        joints[name] = centre(el)
        if "x_" + name in col:
            q = turned((col["x_" + name], col["y_" + name]), rot)
            want = (ox + scale * q[0], oy - scale * q[1])
            if math.hypot(joints[name][0] - want[0], joints[name][1] - want[1]) > 0.011:
                bad.append(f"joint {name} drawn at {joints[name]}, the CSV's position at {want}")
    px, py = map(float, vplan.get("data-pole").split())
    mu, vrot = float(vplan.get("data-mu")), float(vplan.get("data-rotation"))
    images = {}
    for el in vplan.iter():
        name = el.get("data-image")
        if not name:
            continue
        if chain_has_transform(el):
            bad.append(f"image {name}: a transform on it or an ancestor")
        images[name] = centre(el)
    for p in plans["velocity_plan"]["points"]:
        name = p["name"].lower()
        if name not in images:
            bad.append(f"velocity image {name} not marked on the sheet")
            continue
        q = turned((p["x"], p["y"]), vrot)
        want = (px + q[0] / mu, py - q[1] / mu)
        if math.hypot(images[name][0] - want[0], images[name][1] - want[1]) > 0.011:
            bad.append(f"velocity image {name} drawn at {images[name]}, the plans' at {want}")

    def joint(name):
        if name in joints:
            return joints[name]
        # the point of a link under another link's point (B3 under B; J21_3 under J21)
        base = name.rsplit("_", 1)[0] if "_" in name else name.rstrip("0123456789")
        return joints.get(base)

    # the images by their position on the plan (a chain's corner is an image: B3 under B)
    by_position = [((p["x"], p["y"]), p["name"]) for p in plans["velocity_plan"]["points"]]
    vmax = max([math.hypot(*q) for q, _ in by_position] or [1.0])

    def image_at(v):
        for q, name in by_position:
            if math.hypot(q[0] - v[0], q[1] - v[1]) <= 1e-9 * vmax:
                return images.get(name.lower())
        return None

    vimg = {p["name"]: (p["x"], p["y"]) for p in plans["velocity_plan"]["points"]}
    checked = 0
    for eq in plans["velocity_equations"]:
        tip = list(vimg.get(eq["from"], (0.0, 0.0))) if eq["from"] else [0.0, 0.0]
        for v in eq["vectors"]:
            start = tuple(tip)
            tip = [tip[0] + v["x"], tip[1] + v["y"]]
            if v["kind"] != "t" or not eq["from"]:
                continue
            a, b = joint(eq["point"]), joint(eq["from"])
            ia, ib = image_at(tip), image_at(start)
            if None in (a, b, ia, ib):
                bad.append(f"{v['name']}: a point without its mark ({eq['point']}, {eq['from']}, or the images)")
                continue
            d_link = (a[0] - b[0], a[1] - b[1])
            d_img = (ia[0] - ib[0], ia[1] - ib[1])
            la, li = math.hypot(*d_link), math.hypot(*d_img)
            if la < 2.0 or li < 2.0:
                continue
            checked += 1
            cos = (d_link[0] * d_img[0] + d_link[1] * d_img[1]) / (la * li)
            if abs(cos) > 0.02 / min(la, li):
                bad.append(f"{v['name']}: the drawn image difference is not perpendicular to the drawn link "
                           f"{eq['from']}{eq['point']} (cos {cos:.4f})")
    if checked == 0 and any(v["kind"] == "t" for eq in plans["velocity_equations"] for v in eq["vectors"] if eq["from"]):
        bad.append("no relative velocity long enough to check on the sheet")
    if bad:
        print(f"{svg_path}:")
        print("\n".join(bad))
        sys.exit(1)


def dxf_main(argv):
    """The plans DXF read back: images' circles, the lever's and polygons' arrowheads."""
    dxf_path, json_path = argv
    plans = json.load(open(json_path))
    lines = open(dxf_path, encoding="ascii").read().split("\n")
    pairs = [(int(lines[i].strip()), lines[i + 1]) for i in range(0, len(lines) - 1, 2)]
    height = None
    for i, (c, v) in enumerate(pairs):
        if c == 9 and v == "$LIMMAX":
            height = float(pairs[i + 2][1])
    comments = [v for c, v in pairs if c == 999]
    entities, cur = [], None
    for c, v in pairs:
        if c == 0:
            cur = {"type": v}
            entities.append(cur)
        elif cur is not None and c in (8, 10, 20, 40):
            cur[c] = v if c == 8 else float(v)
    bad = []

    def group(kind, **match):
        for text in comments:
            if not text.startswith("kinetostat group " + kind + " "):
                continue
            attrs = dict(re.findall(r"(data-[a-z-]+)=(\S+(?: [-0-9.]+(?= data-|$))?)", text))
            if all(attrs.get(k) == v for k, v in match.items()):
                return attrs
        return None

    for kind, layer, key in (("velocity-plan", "VPLAN", "velocity_plan"), ("acceleration-plan", "APLAN", "acceleration_plan")):
        g = group(kind)
        if g is None:
            bad.append(f"no {kind} group comment")
            continue
        px, py = map(float, g["data-pole"].split())
        mu, rot = float(g["data-mu"]), float(g["data-rotation"])
        circles = [(e[10], height - e[20]) for e in entities if e["type"] == "CIRCLE" and e.get(8) == layer]
        for p in plans[key]["points"]:
            q = turned((p["x"], p["y"]), rot)
            want = (px + q[0] / mu, py - q[1] / mu)
            if not any(math.hypot(x - want[0], y - want[1]) <= 0.011 for x, y in circles):
                bad.append(f"{layer}: no circle at the image of {p['name']} {want}")
    heads = {layer: sum(1 for e in entities if e["type"] == "SOLID" and e.get(8) == layer) for layer in ("LEVER", "POLYGONS")}
    g = group("lever")
    z = plans["zhukovsky"]
    if z["effort"] is not None:
        if g is None:
            bad.append("no lever group comment")
        else:
            mu_f = float(g["data-mu-force"])
            drawn = 0
            for ld in z["loads"] + [z["balancing"]]:
                f = math.hypot(ld["couple"]["x"], ld["couple"]["y"]) if ld["kind"] == "moment" else math.hypot(ld["x"], ld["y"])
                pair = ld["kind"] == "moment" or len(ld.get("points", [])) == 2
                if f / mu_f >= 1.0 and not (ld["kind"] == "moment" and ld["couple"]["l"] == 0):
                    drawn += 2 if pair else 1
            if heads["LEVER"] != drawn:
                bad.append(f"LEVER: {heads['LEVER']} arrowheads, {drawn} loads' forces drawn")
    drawn = 0
    for poly in plans["force_plans"]:
        g = group("force-polygon", **{"data-group": poly["group"]})
        if g is None:
            bad.append(f"no force-polygon group comment for {poly['group']}")
            continue
        mu = float(g["data-mu"])
        n = len(poly["vectors"])
        tips = [(0.0, 0.0)]
        for v in poly["vectors"]:
            tips.append((tips[-1][0] + v["x"], tips[-1][1] + v["y"]))
        drawn += sum(1 for v in poly["vectors"] if math.hypot(v["x"], v["y"]) / mu >= 1.0)
        for r in poly["reactions"]:
            if not r["inner"] and any(v["name"] == r["name"] for v in poly["vectors"]):
                continue  # a whole reaction drawn as it is, not split
            a, b = tips[r["tail"]], tips[r["head"] % (n + 1)]
            if math.hypot(b[0] - a[0], b[1] - a[1]) / mu >= 1.0:
                drawn += 1
    # the input link's drawing adds its forces' arrows (at least its polygon's)
    if heads["POLYGONS"] < drawn:
        bad.append(f"POLYGONS: {heads['POLYGONS']} arrowheads, the polygons draw {drawn} vectors")
    if bad:
        print(f"{dxf_path}:")
        print("\n".join(bad))
        sys.exit(1)


def main():
    if sys.argv[1:2] == ["groups"]:
        groups_main(sys.argv[2:])
        return
    if sys.argv[1:2] == ["sheet"] and len(sys.argv) == 5:
        sheet_main(sys.argv[2:])
        return
    if sys.argv[1:2] == ["dxf"] and len(sys.argv) == 4:
        dxf_main(sys.argv[2:])
        return
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    flags = {a for a in sys.argv[1:] if a.startswith("--")}
    if len(args) < 2:
        print(__doc__)
        sys.exit(1)
    rows = list(csv.reader(open(args[-1], newline="")))
    failed = False
    for path in args[:-1]:
        failed = check_one(path, rows, flags) or failed
    sys.exit(1 if failed else 0)


def check_one(path, rows, flags):
    """Every check asked for on one step's plans; prints the failures, returns whether any."""
    args = [path]
    plans = json.load(open(path))
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
        if z["effort"] is not None:
            check_loads(plans, z, col, vimg, bad)
        if "flywheel" in z:
            eps = col.get("eps" + z["driver"][1:])
            expected = None if eps is None else -z["flywheel"]["J"] * eps
            if expected is None or abs(z["flywheel"]["moment"] - expected) > 1e-9 * abs(expected) + 1e-9:
                bad.append(f"lever flywheel: moment expected -J*eps{z['driver'][1:]} = {expected!r}, "
                           f"lever {z['flywheel']['moment']!r}")
    if "--order" in flags:
        check_order(plans, col, bad)
    if "--values" in flags:
        check_values(plans, col, vimg, aimg, bad)
    if bad:
        print(f"{args[0]} (step {plans['step']}):")
        print("\n".join(bad))
    return bool(bad)


def is_pair_force(name):
    return len(name) == 3 and name[0] == "F" and name[1:].isdigit()


def check_loads(plans, z, col, vimg, bad):
    """The lever's loads: every load force of the links' polygons, the powers and the arms."""
    if "loads" not in z or "balancing" not in z:
        bad.append("lever: no loads or no balancing force listed (zhukovsky.loads, zhukovsky.balancing)")
        return
    loads = {ld["name"]: ld for ld in z["loads"]}
    driver = z["driver"]
    wanted = set()
    for poly in plans["link_force_plans"]:
        for v in poly["vectors"]:
            name = v["name"]
            if is_pair_force(name) or name in (driver, "-" + driver):
                continue
            wanted.add(name)
    missing = sorted(wanted - set(loads))
    if missing:
        bad.append(f"lever: the load forces {missing} of the links' polygons are not on the lever "
                   f"(its loads: {sorted(loads)})")
    if "flywheel" in z and "M_fw" not in loads:
        bad.append("lever: the flywheel's moment M_fw is not one of its loads")
    mu = plans["scales"]["lever_mu_v"]
    powers = [ld["power"] for ld in z["loads"]] + [z["balancing"]["power"]]
    big = max(abs(p) for p in powers) if powers else 0.0
    if abs(sum(powers)) > 1e-9 * max(big, 1e-300):
        bad.append(f"lever: the loads' powers and the balancing power sum to {sum(powers)!r} W (largest {big!r})")
    bal = z["balancing"]
    rate = z["rate"]["value"]
    if abs(bal["power"] - z["effort"] * rate) > 1e-9 * max(abs(bal["power"]), big * 1e-6, 1e-12):
        bad.append(f"lever: balancing power {bal['power']!r}, effort x rate {z['effort'] * rate!r}")

    def omega(link):
        return col.get("omega" + link, 0.0)

    for ld in z["loads"] + [bal]:
        name, power = ld["name"], ld["power"]
        tol = 1e-9 * max(big, 1e-12)
        if ld["kind"] == "moment":
            c = ld["couple"]
            want = ld["value"] * omega(ld["link"])
            if abs(power - want) > tol:
                bad.append(f"lever: {name}: power {power!r}, M x omega{ld['link']} = {want!r}")
            f = math.hypot(c["x"], c["y"])
            p1, p2 = c["points"]
            if c["l"] > 0 and abs(f * c["l"] - abs(ld["value"])) > 1e-9 * max(abs(ld["value"]), 1e-12):
                bad.append(f"lever: {name}: couple force {f!r} x l {c['l']!r} is not |M| = {abs(ld['value'])!r}")
            if "x_" + p1 in col and "x_" + p2 in col:
                d = (col["x_" + p1] - col["x_" + p2], col["y_" + p1] - col["y_" + p2])
                if abs(d[0] * c["x"] + d[1] * c["y"]) > 1e-9 * f * math.hypot(*d) + 1e-12:
                    bad.append(f"lever: {name}: the couple's force is not perpendicular to {p1}{p2}")
        else:
            f = (ld["x"], ld["y"])
            pts = ld["points"]
            if len(pts) == 1 and pts[0] in vimg:
                want = f[0] * vimg[pts[0]][0] + f[1] * vimg[pts[0]][1]
                if abs(power - want) > tol:
                    bad.append(f"lever: {name} at {pts[0]}: power {power!r}, F . v_{pts[0]} = {want!r}")
            elif len(pts) == 2 and pts[0] in vimg and pts[1] in vimg:
                dv = (vimg[pts[0]][0] - vimg[pts[1]][0], vimg[pts[0]][1] - vimg[pts[1]][1])
                want = f[0] * dv[0] + f[1] * dv[1]
                if abs(power - want) > tol:
                    bad.append(f"lever: {name} at {pts}: power {power!r}, F . (v_{pts[0]} - v_{pts[1]}) = {want!r}")
            elif pts and pts[0]:
                bad.append(f"lever: {name}: its point(s) {pts} have no image on the velocity plan")
            if name == "P_bal" and pts[0] in vimg:
                v = vimg[pts[0]]
                if abs(f[0] * v[1] - f[1] * v[0]) > 1e-9 * math.hypot(*f) * math.hypot(*v) + 1e-12:
                    bad.append(f"lever: P_bal is not along the velocity of {pts[0]} (perpendicular to the link)")
            size = math.hypot(*f)
            if size > 0 and abs(ld["arm_plan"] - abs(power) / size) > 1e-9 * max(ld["arm_plan"], 1e-12):
                bad.append(f"lever: {name}: arm {ld['arm_plan']!r} m/s, |power| / |F| = {abs(power) / size!r}")
        if abs(ld["arm_mm"] - ld["arm_plan"] / mu) > 1e-9 * max(ld["arm_mm"], 1e-9):
            bad.append(f"lever: {name}: arm_mm {ld['arm_mm']!r}, arm_plan / mu_v {ld['arm_plan'] / mu!r}")


def check_order(plans, col, bad):
    """The groups' polygons in the course's order, their whole and inner reactions."""
    for poly in plans["force_plans"]:
        where = f"force polygon of {poly.get('label', poly['group'])}"
        vecs = poly["vectors"]
        n = len(vecs)
        tips = [(0.0, 0.0)]
        for v in vecs:
            tips.append((tips[-1][0] + v["x"], tips[-1][1] + v["y"]))
        listed = {r["name"]: r for r in poly.get("reactions", [])}
        parts = {}
        for j, v in enumerate(vecs):
            if v.get("kind") in ("t", "n", "f"):
                parts.setdefault(v["name"].split("^")[0], []).append(j)
        for name, idx in parts.items():
            if len(idx) == 2 and (idx[1] - idx[0]) % n not in (1, n - 1):
                bad.append(f"{where}: the parts of {name} are not adjacent (at {idx} of {[v['name'] for v in vecs]})")
            whole = (sum(vecs[j]["x"] for j in idx), sum(vecs[j]["y"] for j in idx))
            big = max(math.hypot(v["x"], v["y"]) for v in vecs)
            if name not in listed:
                bad.append(f"{where}: reaction {name} is not listed whole")
                continue
            r = listed[name]
            if math.hypot(r["x"] - whole[0], r["y"] - whole[1]) > 1e-9 * big:
                bad.append(f"{where}: {name} listed {(r['x'], r['y'])}, its parts sum to {whole}")
        for r in poly.get("reactions", []):
            big = max(math.hypot(v["x"], v["y"]) for v in vecs)
            drawn = (tips[r["head"] % (n + 1)][0] - tips[r["tail"]][0], tips[r["head"] % (n + 1)][1] - tips[r["tail"]][1])
            if r["head"] < r["tail"] and not r["inner"]:
                # drawn across the polygon's start: from the vertex tail to the end, then on
                drawn = (tips[n][0] - tips[r["tail"]][0] + tips[r["head"]][0], tips[n][1] - tips[r["tail"]][1] + tips[r["head"]][1])
            if math.hypot(drawn[0] - r["x"], drawn[1] - r["y"]) > 1e-9 * big:
                bad.append(f"{where}: {r['name']} drawn from vertex {r['tail']} to {r['head']} is {drawn}, listed {(r['x'], r['y'])}")
            if r["inner"]:
                name = r["name"]
                csv_name = name if name + "_x" in col else "F" + name[2] + name[1]
                if csv_name + "_x" in col:
                    f = math.hypot(col[csv_name + "_x"], col[csv_name + "_y"])
                    if abs(math.hypot(r["x"], r["y"]) - f) > 1e-9 * big:
                        bad.append(f"{where}: inner reaction {name} {math.hypot(r['x'], r['y'])!r}, the CSV's |{csv_name}| {f!r}")
        dyad = poly.get("label", "").startswith("II(") or poly["group"].count(",") == 1
        if dyad and not any(r["inner"] for r in poly.get("reactions", [])):
            bad.append(f"{where}: no inner reaction")
        if dyad and vecs and vecs[0].get("kind") == "t":
            first = vecs[0]["name"].split("^")[0]
            if vecs[-1]["name"] != first + "^n":
                bad.append(f"{where}: starts with {vecs[0]['name']} but ends with {vecs[-1]['name']}, not {first}^n")


def check_values(plans, col, vimg, aimg, bad):
    """The values table against the images, the plans' vectors and the CSV's rates."""
    vectors = {}
    for key in ("velocity_equations", "acceleration_equations"):
        for eq in plans[key]:
            for v in eq["vectors"]:
                vectors[v["name"]] = math.hypot(v["x"], v["y"])
    if not plans.get("values"):
        bad.append("values table: none")
    for entry in plans.get("values", []):
        name, value = entry["name"], entry["value"]
        if name.startswith(("omega", "eps")):
            link = name[5:] if name.startswith("omega") else name[3:]
            key = ("omega" if name.startswith("omega") else "eps") + link
            rate = col.get(key)
            if rate is None:
                bad.append(f"values table: {name} has no CSV column {key}")
                continue
            sense = "ccw" if rate > 0 else "cw" if rate < 0 else ""
            if abs(value - abs(rate)) > 1e-9 * max(abs(rate), 1e-12) or entry["sense"] != sense:
                bad.append(f"values table: {name} = {value!r} {entry['sense']}, the CSV's {key} = {rate!r}")
            continue
        point = name[2:]
        if name.startswith("v_") and point in vimg:
            want = math.hypot(*vimg[point])
        elif name.startswith("a_") and "^" not in name and point in aimg:
            want = math.hypot(*aimg[point])
        elif name in vectors:
            want = vectors[name]
        else:
            bad.append(f"values table: {name} is no image or vector of the plans")
            continue
        if abs(value - want) > 1e-9 * max(want, 1e-12):
            bad.append(f"values table: {name} = {value!r}, the plans' {want!r}")


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
