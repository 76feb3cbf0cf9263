#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Supports for vine.sh, as OBJ files: support.py pole|cross|t OUT.OBJ.

pole: a capped cylinder of radius 0.02 m, 1 m tall from the ground, 32 sides, on the y
axis; cross: the pole and a bar as thick, 0.6 m long, along x through it at y = 0.5 m;
t: issue 24's T, a pole of radius 0.01 m, 0.8 m tall, and a bar as thick, 0.4 m long,
along x across its top (its axis at y = 0.8 m).
Quads for the sides and a polygon a cap, as a 3D program writes them (assimp triangulates).
"""
import math
import sys

R = 0.02
T_R = 0.01
SIDES = 32


def cylinder(f, first, length, point):
    """A capped cylinder of SIDES sides: point(angle, t) places its ring at t along it."""
    for t in (0.0, length):
        for i in range(SIDES):
            f.write("v %.9g %.9g %.9g\n" % point(2 * math.pi * i / SIDES, t))
    b = first + 1
    for i in range(SIDES):
        j = (i + 1) % SIDES
        f.write(f"f {b + i} {b + SIDES + i} {b + SIDES + j} {b + j}\n")
    f.write("f " + " ".join(str(b + i) for i in range(SIDES)) + "\n")
    f.write("f " + " ".join(str(b + SIDES + i) for i in reversed(range(SIDES))) + "\n")
    return first + 2 * SIDES


def main():
    kind, out = sys.argv[1], sys.argv[2]
    with open(out, "w", encoding="ascii") as f:
        f.write(f"# edaha vine test support: {kind}\no {kind}\n")
        if kind == "t":
            n = cylinder(f, 0, 0.8, lambda a, t: (T_R * math.cos(a), t, T_R * math.sin(a)))
            cylinder(f, n, 0.4, lambda a, t: (t - 0.2, 0.8 + T_R * math.cos(a), T_R * math.sin(a)))
            return
        n = cylinder(f, 0, 1.0, lambda a, t: (R * math.cos(a), t, R * math.sin(a)))
        if kind == "cross":
            cylinder(f, n, 0.6, lambda a, t: (t - 0.3, 0.5 + R * math.cos(a), R * math.sin(a)))


main()
