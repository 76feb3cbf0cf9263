#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks edaha's --dump-voxels output (docs/wood.md, "Voxels dumped") from outside:
the header and the fields' layout, densities within 0..1 and never below density0, the
dumped displacements at rest (the net force of gravity, wind and the springs on every free
mass point at most 1e-3 m g), and compression and tension as the springs give them.
Usage: check_voxels.py DIR"""
import json
import math
import struct
import sys
from array import array


def fail(msg):
    print("check_voxels: " + msg, file=sys.stderr)
    sys.exit(1)


def main(d):
    meta = json.load(open(d + "/voxels.json"))
    raw = open(d + "/voxels.bin", "rb").read()
    if meta.get("format") != "edaha-voxels" or meta.get("version") != 1:
        fail("not an edaha-voxels version 1 header")
    nx, ny, nz = meta["dims"]
    n = nx * ny * nz
    size = {"f64": 8, "u8": 1}
    fields = {}
    end = 0
    for name, f in meta["fields"].items():
        width = size[f["type"]] * f["components"] * n
        chunk = raw[f["offset"]:f["offset"] + width]
        if len(chunk) != width:
            fail("field %s runs past the end of voxels.bin" % name)
        if f["type"] == "f64":
            a = array("d")
            a.frombytes(chunk)
            if sys.byteorder != "little":
                a.byteswap()
        else:
            a = array("B", chunk)
        fields[name] = a
        end = max(end, f["offset"] + width)
    if end != len(raw):
        fail("voxels.bin is %d bytes, the fields %d" % (len(raw), end))
    for name in ("density0", "density", "compression", "tension", "displacement", "flags"):
        if name not in fields:
            fail("no field " + name)
    d0, rho, comp, tens, disp, flags = (fields[k] for k in ("density0", "density",
                                                             "compression", "tension",
                                                             "displacement", "flags"))
    for i in range(n):
        if not (0.0 <= rho[i] <= 1.0) or rho[i] < d0[i]:
            fail("voxel %d: density %r (before %r)" % (i, rho[i], d0[i]))
    g = meta["gravity"]
    wind = meta["wind"]
    load = (wind[0], -g, wind[2])
    offs = [(a, b, c) for c in (-1, 0, 1) for b in (-1, 0, 1) for a in (-1, 0, 1)
            if (a, b, c) != (0, 0, 0)]
    worst_force = 0.0
    worst_sum = 0.0
    points = 0
    for z in range(nz):
        for y in range(ny):
            for x in range(nx):
                i = x + nx * (y + ny * z)
                if not flags[i] & 1:
                    continue
                points += 1
                f = [load[0], load[1], load[2]]
                c = t = 0.0
                ui = (disp[3 * i], disp[3 * i + 1], disp[3 * i + 2])
                for a, b, cc in offs:
                    X, Y, Z = x + a, y + b, z + cc
                    if not (0 <= X < nx and 0 <= Y < ny and 0 <= Z < nz):
                        continue
                    j = X + nx * (Y + ny * Z)
                    if not flags[j] & 1:
                        continue
                    length = math.sqrt(a * a + b * b + cc * cc)
                    e = (a / length, b / length, cc / length)
                    s = sum(e[k] * (disp[3 * j + k] - ui[k]) for k in range(3))  # k = 1
                    for k in range(3):
                        f[k] += s * e[k]
                    if s < 0:
                        c -= s
                    else:
                        t += s
                if not flags[i] & 2:
                    worst_force = max(worst_force, math.sqrt(sum(v * v for v in f)))
                scale = max(c, t, 1e-300)
                worst_sum = max(worst_sum, abs(c - comp[i]) / scale, abs(t - tens[i]) / scale)
    if points == 0:
        fail("no mass point")
    if g > 0 and worst_force > 1e-3 * g:
        fail("not at rest: a free point's net force is %.3g (at most %.3g)" %
             (worst_force, 1e-3 * g))
    if worst_sum > 1e-6:
        fail("compression or tension differ from the springs' by %.3g" % worst_sum)
    print("%d mass points at rest (worst net force %.3g m g), forces as the springs give "
          "them (to %.2g)" % (points, worst_force / g if g else 0.0, worst_sum))


if __name__ == "__main__":
    main(sys.argv[1])
