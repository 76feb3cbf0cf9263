#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What edaha --headless --leaf writes, checked (leaf.sh).

check_origami.py json ORIGAMI.JSON OPENING: origami.json has the issue's keys first, in
its order, and edaha's after them; every index is in range; folded and opened have a row
a vertex; the margin is a simple closed polygon; the faces are convex and counter-clockwise
and tile the margin's area; O is at the origin, the midrib on +y; at opening 1 the leaf
is the flat pattern; the lobes are reported.
check_origami.py glb LEAF.GLB: the leaf's material is double-sided.
Prints what is wrong and exits 1, else prints a summary and exits 0.
"""
import json
import math
import struct
import sys

REQUIRED = ["format", "version", "vertices", "creases", "margin", "faces", "folded", "opened"]
OURS = ["name", "opening", "triangles", "lobes"]
EPS = 2e-6  # numbers are written to the micrometre


def fail(msg):
    print(f"check_origami: {msg}", file=sys.stderr)
    sys.exit(1)


def number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def rows(doc, key, n, width):
    r = doc[key]
    if not isinstance(r, list) or len(r) != n:
        fail(f"{key}: {len(r) if isinstance(r, list) else r!r} rows, wanted {n} (a vertex each)")
    for i, p in enumerate(r):
        if not isinstance(p, list) or len(p) != width or not all(number(x) for x in p):
            fail(f"{key}[{i}]: {p!r} is not {width} numbers")
    return r


def index(v, n, what):
    if not isinstance(v, int) or isinstance(v, bool) or not 0 <= v < n:
        fail(f"{what}: {v!r} is not a vertex index below {n}")
    return v


def area(poly):
    return 0.5 * sum(poly[i][0] * poly[(i + 1) % len(poly)][1] -
                     poly[(i + 1) % len(poly)][0] * poly[i][1] for i in range(len(poly)))


def check_json(path, opening):
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    keys = list(doc.keys())
    if keys[:len(REQUIRED)] != REQUIRED:
        fail(f"the keys begin {keys[:len(REQUIRED)]}, wanted {REQUIRED}")
    for k in OURS:
        if k not in doc:
            fail(f"no \"{k}\"")
    if doc["format"] != "edaha-origami" or doc["version"] != 1:
        fail(f"format {doc['format']!r} version {doc['version']!r}")
    if not isinstance(doc["name"], str) or not doc["name"]:
        fail(f"name {doc['name']!r}")
    if not number(doc["opening"]) or abs(doc["opening"] - opening) > 1e-6:
        fail(f"opening {doc['opening']!r}, wanted {opening}")
    flat = rows(doc, "vertices", len(doc["vertices"]), 2)
    n = len(flat)
    if n < 3:
        fail(f"{n} vertices")
    folded = rows(doc, "folded", n, 2)
    opened = rows(doc, "opened", n, 3)
    if flat[0] != [0, 0] or folded[0] != [0, 0] or opened[0] != [0, 0, 0]:
        fail(f"vertex 0 is not O at the origin: {flat[0]} {folded[0]} {opened[0]}")

    creases = doc["creases"]
    if not isinstance(creases, list) or not creases:
        fail("no creases")
    midrib = False
    for i, c in enumerate(creases):
        if not isinstance(c, dict) or list(c.keys())[:3] != ["a", "b", "type"]:
            fail(f"creases[{i}]: {c!r}, wanted a, b, type")
        a = index(c["a"], n, f"creases[{i}].a")
        b = index(c["b"], n, f"creases[{i}].b")
        if a == b or c["type"] not in ("mountain", "valley"):
            fail(f"creases[{i}]: {c!r}")
        # the midrib: a valley from O straight up +y
        if a == 0 and c["type"] == "valley" and abs(flat[b][0]) < EPS and flat[b][1] > 0:
            midrib = True
    if not midrib:
        fail("no valley from O along +y (the midrib)")

    margin = [index(v, n, f"margin[{i}]") for i, v in enumerate(doc["margin"])]
    if len(margin) < 3 or len(set(margin)) != len(margin) or margin[0] != 0:
        fail(f"margin {margin}: not a closed polygon of distinct vertices from O")
    outline = [flat[v] for v in margin]
    if area(outline) <= 0:
        fail("the margin is not counter-clockwise")

    faces = doc["faces"]
    total = 0.0
    triangles = 0
    for f, face in enumerate(faces):
        idx = [index(v, n, f"faces[{f}]") for v in face]
        if len(idx) < 3 or len(set(idx)) != len(idx):
            fail(f"faces[{f}]: {face}")
        poly = [flat[v] for v in idx]
        for k in range(len(poly)):
            p, q, r = poly[k], poly[(k + 1) % len(poly)], poly[(k + 2) % len(poly)]
            cross = (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0])
            if cross < -1e-9:
                fail(f"faces[{f}] is not convex and counter-clockwise at corner {k + 1}")
        total += area(poly)
        triangles += len(idx) - 2
    # the faces cover the leaf, no more and no less (to the numbers' rounding)
    if abs(total - area(outline)) > 1e-3 * area(outline):
        fail(f"the faces' area {total:.9f} m2 is not the margin's {area(outline):.9f}")
    if doc["triangles"] != triangles:
        fail(f"triangles {doc['triangles']}, the faces make {triangles}")

    if opening == 1:
        for i in range(n):
            if max(abs(opened[i][0] - flat[i][0]), abs(opened[i][1] - flat[i][1]),
                   abs(opened[i][2])) > EPS:
                fail(f"open at 1, vertex {i} is at {opened[i]}, not flat at {flat[i]}")

    lobes = doc["lobes"]
    if not isinstance(lobes, list) or not lobes:
        fail("no lobes")
    for i, lo in enumerate(lobes):
        if not isinstance(lo, dict) or list(lo.keys()) != ["theta", "target", "tip"] or \
                not all(number(lo[k]) for k in lo) or lo["tip"] <= 0:
            fail(f"lobes[{i}]: {lo!r}")
    print(f"{path}: {doc['name']} at {doc['opening']}: {n} vertices, {len(creases)} creases, "
          f"{len(faces)} faces, {triangles} triangles, {len(lobes)} lobes")


def check_glb(path):
    with open(path, "rb") as f:
        data = f.read()
    magic, version, length = struct.unpack_from("<III", data, 0)
    jlen, jtype = struct.unpack_from("<II", data, 12)
    if magic != 0x46546C67 or version != 2 or length != len(data) or jtype != 0x4E4F534A:
        fail(f"{path}: not a GLB 2 file")
    gltf = json.loads(data[20:20 + jlen])
    mats = gltf.get("materials", [])
    if len(mats) != 1 or mats[0].get("doubleSided") is not True:
        fail(f"{path}: materials {mats}, wanted the one double-sided leaf material")
    print(f"{path}: {len(gltf['meshes'][0]['primitives'])} primitive, double-sided")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "json":
        check_json(sys.argv[2], float(sys.argv[3]))
    elif len(sys.argv) == 3 and sys.argv[1] == "glb":
        check_glb(sys.argv[2])
    else:
        fail("usage: check_origami.py json ORIGAMI.JSON OPENING | glb LEAF.GLB")
