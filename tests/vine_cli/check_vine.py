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


def main():
    kind, path = sys.argv[1], sys.argv[2]
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    v = check_fields(doc)
    if kind == "pole":
        check_pole(v)
    else:
        check_cross(v)


main()
