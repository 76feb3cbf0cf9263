#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What edaha --headless --support writes, checked (vine.sh).

check_vine.py pole SKELETON.JSON: the skeleton's keys (the tree's parts empty), every key
of a vine file, the shoots' and leaves' fields; each internode l/d long along the raw axis;
on the pole (radius 0.02 m, 1 m, the y axis) the twined points (contacts below the top) lie
at R + r from the axis, within 0.1 r, and wind the way `twining` says (right: azimuth
atan2(-z, x) increasing, counter-clockwise seen from above).
check_vine.py cross SKELETON.JSON: the same fields; the main axis reaches above 0.9 m (past
the bar at 0.5 m).
check_vine.py any SKELETON.JSON: the same fields.
With SUPPORT.OBJ after SKELETON.JSON (issue 24): every point of every shoot's smooth axis
lies at least 0.95 r from the support's triangles (to the micrometre the file is written
to) and outside it (outside every closed piece: a winding number below 1/2), measured here
with the support's triangles.
Prints what is wrong and exits 1, else prints a summary and exits 0.
"""
import json
import math
import sys

POLE_R = 0.02
PARAMS = ["edaha-vine", "internode", "radius", "step_time", "angle", "free_nodes", "twining",
          "leaves_per_node", "cotyledons", "leaf_size", "points_per_internode", "ring_sides",
          "sweep", "internodes", "seed"]
EPS = 2e-6  # numbers are written to the micrometre


def fail(msg):
    print(f"check_vine: {msg}", file=sys.stderr)
    sys.exit(1)


def number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def points(p, what):
    if not isinstance(p, list):
        fail(f"{what}: not a list")
    for i, q in enumerate(p):
        if not isinstance(q, list) or len(q) != 3 or not all(number(x) for x in q):
            fail(f"{what}[{i}]: {q!r} is not 3 numbers")
    return p


def check_fields(doc):
    for k in ["format", "version", "up", "units", "view", "season", "branches", "leaves"]:
        if k not in doc:
            fail(f"no \"{k}\": the skeleton's keys are not kept")
    if doc["format"] != "edaha-skeleton" or doc["version"] != 2:
        fail(f"format {doc['format']!r} version {doc['version']!r}")
    if doc["branches"] != [] or doc["leaves"] != []:
        fail("a vine alone has tree parts")
    if not isinstance(doc.get("vines"), list) or len(doc["vines"]) != 1:
        fail("not one vine in \"vines\"")
    v = doc["vines"][0]
    if list(v)[:len(PARAMS)] != PARAMS:
        fail(f"the vine's keys begin {list(v)[:len(PARAMS)]}, wanted {PARAMS}")
    for k in ["plant", "shoots", "leaves"]:
        if k not in v:
            fail(f"the vine has no \"{k}\"")
    points([v["plant"]], "plant")
    shoots = v["shoots"]
    if not shoots or shoots[0]["parent"] != -1:
        fail("no main axis first")
    for i, s in enumerate(shoots):
        for k in ["parent", "node", "axis", "smooth", "contacts", "stopped"]:
            if k not in s:
                fail(f"shoot {i}: no \"{k}\"")
        if not (-1 <= s["parent"] < i) or (i > 0) != (s["parent"] >= 0):
            fail(f"shoot {i}: parent {s['parent']}")
        n = len(points(s["axis"], f"shoot {i} axis"))
        if len(points(s["smooth"], f"shoot {i} smooth")) != n:
            fail(f"shoot {i}: smooth has {len(s['smooth'])} points, axis {n}")
        c = s["contacts"]
        if c != sorted(set(c)) or any(not isinstance(k, int) or not 0 <= k < n for k in c):
            fail(f"shoot {i}: contacts {c[:5]}... are not increasing indices below {n}")
        if not isinstance(s["stopped"], bool):
            fail(f"shoot {i}: stopped {s['stopped']!r}")
    if shoots[0]["axis"][0] != v["plant"]:
        fail(f"the main axis starts at {shoots[0]['axis'][0]}, not the plant {v['plant']}")
    for j, leaf in enumerate(v["leaves"]):
        if not 0 <= leaf["shoot"] < len(shoots) or not isinstance(leaf["cotyledon"], bool):
            fail(f"leaf {j}: shoot {leaf['shoot']} cotyledon {leaf['cotyledon']!r}")
        if len(points(leaf["points"], f"leaf {j}")) != 4:
            fail(f"leaf {j}: not 4 corners")
        if not isinstance(leaf["node"], int) or leaf["node"] < 0:
            fail(f"leaf {j}: node {leaf['node']!r}")
    # every segment of every raw axis is an internode's d-th
    seg = v["internode"] / v["points_per_internode"]
    for i, s in enumerate(shoots):
        a = s["axis"]
        for k in range(1, len(a)):
            d = math.dist(a[k - 1], a[k])
            if abs(d - seg) > 1e-3 * seg + 2 * EPS:
                fail(f"shoot {i}: segment {k} is {d:.6f} m long, not l/d = {seg:.6f}")
    return v


def check_pole(v):
    r = v["radius"]
    main = v["shoots"][0]
    a = main["axis"]
    twined = [k for k in main["contacts"] if a[k][1] < 1.0 - r]
    if len(twined) < 2 * v["points_per_internode"]:
        fail(f"only {len(twined)} twined points on the pole")
    for k in twined:
        x, _, z = a[k]
        d = math.hypot(x, z)
        if abs(d - (POLE_R + r)) > 0.1 * r:
            fail(f"point {k} at {a[k]}: {d:.6f} m from the axis, not R + r = "
                 f"{POLE_R + r:.6f} within 0.1 r")
    # the winding: the azimuth's turn between consecutive twined points (each less than a
    # half turn), summed; right is atan2(-z, x) increasing
    turn = 0.0
    for k0, k1 in zip(twined, twined[1:]):
        if k1 != k0 + 1:
            continue
        t0 = math.atan2(-a[k0][2], a[k0][0])
        t1 = math.atan2(-a[k1][2], a[k1][0])
        turn += (t1 - t0 + math.pi) % (2 * math.pi) - math.pi
    want = 1 if v["twining"] == "right" else -1
    if turn * want < 2 * math.pi:
        fail(f"twining {v['twining']}: the twined points turn {math.degrees(turn):.0f} "
             "degrees about the pole")
    print(f"check_vine: pole: {len(twined)} twined points at R + r, {v['twining']}, "
          f"{turn / (2 * math.pi):+.1f} turns")


def check_cross(v):
    top = max(p[1] for p in v["shoots"][0]["axis"])
    if top <= 0.9:
        fail(f"the main axis reaches {top:.3f} m, not above 0.9 m")
    print(f"check_vine: cross: the main axis reaches {top:.3f} m")


def load_obj(path):
    """The OBJ's triangles (polygons as fans), grouped into its connected pieces."""
    verts, faces = [], []
    with open(path, encoding="ascii") as f:
        for line in f:
            w = line.split()
            if w and w[0] == "v":
                verts.append(tuple(float(x) for x in w[1:4]))
            elif w and w[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    parent = list(range(len(verts)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for face in faces:
        for k in face[1:]:
            parent[find(k)] = find(face[0])
    pieces = {}
    for face in faces:
        tris = pieces.setdefault(find(face[0]), [])
        for k in range(1, len(face) - 1):
            tris.append((verts[face[0]], verts[face[k]], verts[face[k + 1]]))
    return list(pieces.values())


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def seg_dist(p, a, b):
    ab = sub(b, a)
    t = dot(sub(p, a), ab) / dot(ab, ab) if dot(ab, ab) > 0 else 0.0
    t = min(max(t, 0.0), 1.0)
    return math.dist(p, (a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]))


def tri_dist(p, a, b, c):
    """The foot on the plane if it falls inside the triangle, else the nearest edge."""
    n = cross(sub(b, a), sub(c, a))
    nn = dot(n, n)
    if nn > 0:
        h = dot(sub(p, a), n) / nn
        f = (p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2])
        if (dot(cross(sub(b, a), sub(f, a)), n) >= 0 and dot(cross(sub(c, b), sub(f, b)), n) >= 0
                and dot(cross(sub(a, c), sub(f, c)), n) >= 0):
            return abs(h) * math.sqrt(nn)
    return min(seg_dist(p, a, b), seg_dist(p, b, c), seg_dist(p, c, a))


def winding(p, tris):
    """The winding number of a closed piece about p (Van Oosterom and Strackee)."""
    w = 0.0
    for t in tris:
        a, b, c = sub(t[0], p), sub(t[1], p), sub(t[2], p)
        la, lb, lc = math.sqrt(dot(a, a)), math.sqrt(dot(b, b)), math.sqrt(dot(c, c))
        w += 2 * math.atan2(dot(a, cross(b, c)),
                            la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb)
    return w / (4 * math.pi)


def check_clear(v, support):
    r = v["radius"]
    pieces = load_obj(support)
    worst = (math.inf, None)
    for i, s in enumerate(v["shoots"]):
        for k, p in enumerate(s["smooth"]):
            d = min(tri_dist(p, *t) for tris in pieces for t in tris)
            if d < worst[0]:
                worst = (d, (i, k))
            if d < 0.95 * r - 2 * EPS:
                fail(f"shoot {i}: smoothed point {k} {p} is {d / r:.3f} r from the support")
            if any(abs(winding(p, tris)) >= 0.5 for tris in pieces):
                fail(f"shoot {i}: smoothed point {k} {p} is inside the support")
    print(f"check_vine: the smoothed axis keeps {worst[0] / r:.4f} r from the support at "
          f"worst (shoot {worst[1][0]}, point {worst[1][1]}), outside it")


def main():
    kind, path = sys.argv[1], sys.argv[2]
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    v = check_fields(doc)
    if kind == "pole":
        check_pole(v)
    elif kind == "cross":
        check_cross(v)
    if len(sys.argv) > 3:
        check_clear(v, sys.argv[3])


main()
