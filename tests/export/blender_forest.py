# SPDX-License-Identifier: MIT
# Run by blender.sh inside Blender (blender -b --factory-startup --python blender_forest.py
# -- FOREST.glb): imports a forest.glb (export_glb_forest; write_samples' forest-3-wind.glb)
# with Blender's bundled glTF importer and checks that the forest came with its wind
# (docs/forest.md, "Headless and for the teacher"): one mesh object a node of the file,
# named as the node ("tree-N"), at the node's translation (glTF's y up is Blender's z up:
# (x, y, z) -> (x, -z, y)), each with its 10 shape keys (plus Basis) and an action made
# from the one animation "wind" (Blender 3.4 names it "wind_tree-N"), every action over
# the same frames (the common loop: 8 s at the scene's frame rate); evaluated at two
# frames, each tree's crown (its highest vertex) moves and its foot (its lowest) does not;
# each action's first and last frames alike. Prints a line "edaha-forest: ..." a tree and
# one for the forest, and exits 0, or raises (Blender then exits 1).
import json
import struct
import sys

import bpy
import numpy

# Debian 12's Blender 3.4.1 importer uses numpy.bool, which Debian 12's numpy 1.24 no
# longer has (blender_wind.py says more): the alias back, for the bundled importer only.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

TARGETS = ["wind-trunk-along", "wind-trunk-across", "wind-limbs-sin", "wind-limbs-cos",
           "wind-branches-sin", "wind-branches-cos", "wind-twigs-sin", "wind-twigs-cos",
           "wind-flutter-sin", "wind-flutter-cos"]
LOOP_S = 8.0


def fail(msg):
    raise RuntimeError("edaha-forest: FAIL: " + msg)


def glb_json(path):
    """The file's JSON chunk: what Blender should have made of it."""
    with open(path, "rb") as f:
        head = f.read(20)
        magic, _, _, json_len, kind = struct.unpack("<IIIII", head)
        if magic != 0x46546C67 or kind != 0x4E4F534A:
            fail("%s is no GLB" % path)
        return json.loads(f.read(json_len))


def positions(obj, frame):
    scene = bpy.context.scene
    scene.frame_set(int(frame), subframe=frame - int(frame))
    ev = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = ev.to_mesh()
    co = [v.co.copy() for v in mesh.vertices]
    ev.to_mesh_clear()
    return co


def check_tree(obj, node, fps):
    x, y, z = node["translation"]
    want = (x, -z, y)
    off = max(abs(a - b) for a, b in zip(obj.location, want))
    if not off < 1e-5:
        fail("%s at %s, the file says %s" % (obj.name, tuple(obj.location), want))
    keys = obj.data.shape_keys
    if keys is None:
        fail("%s has no shape keys" % obj.name)
    names = [k.name for k in keys.key_blocks]
    if names[1:] != TARGETS:
        fail("%s's shape keys %s" % (obj.name, names))
    ad = keys.animation_data
    if ad is None or ad.action is None:
        fail("%s's shape keys are not animated" % obj.name)
    action = ad.action.name
    if action not in ("wind", "wind_" + obj.data.name, "wind_" + obj.name):
        fail("%s's action is %r, not the animation wind" % (obj.name, action))
    if len(ad.action.fcurves) != len(TARGETS):
        fail("%s: %d animated shape keys" % (obj.name, len(ad.action.fcurves)))
    lo, hi = ad.action.frame_range
    if abs((hi - lo) - LOOP_S * fps) > 1e-3:
        fail("%s's action runs over frames %g..%g, not %g s" % (obj.name, lo, hi, LOOP_S))
    rest = [v.co.copy() for v in obj.data.vertices]
    top = max(range(len(rest)), key=lambda i: rest[i].z)
    foot = min(range(len(rest)), key=lambda i: rest[i].z)
    f1 = int(lo) + 1
    f2 = int(lo + (hi - lo) * 0.3)
    a, b = positions(obj, f1), positions(obj, f2)
    moved = (a[top] - b[top]).length
    if not moved > 1e-4:
        fail("%s's crown moved %.3g m between frames %d and %d" % (obj.name, moved, f1, f2))
    if (a[foot] - b[foot]).length != 0.0 or (a[foot] - rest[foot]).length != 0.0:
        fail("%s's foot moved" % obj.name)
    first, last = positions(obj, lo), positions(obj, hi)
    seam = max((first[i] - last[i]).length for i in range(len(rest)))
    if not seam < 1e-5:
        fail("%s's loop ends differ by %.3g m" % (obj.name, seam))
    print("edaha-forest: %s at (%.2f, %.2f, %.2f): %d vertices, shape keys Basis + %d, "
          "action %r (frames %g..%g), the crown moved %.1f mm between frames %d and %d, "
          "the loop's ends %.2g m apart, the foot 0"
          % (obj.name, want[0], want[1], want[2], len(rest), len(names) - 1, action, lo, hi,
             moved * 1e3, f1, f2, seam))
    return lo, hi


def main():
    path = sys.argv[sys.argv.index("--") + 1]
    doc = glb_json(path)
    nodes = doc["nodes"]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if bpy.ops.import_scene.gltf(filepath=path) != {"FINISHED"}:
        fail("the import did not finish")
    fps = bpy.context.scene.render.fps / bpy.context.scene.render.fps_base
    objs = {o.name: o for o in bpy.context.scene.objects if o.type == "MESH"}
    if sorted(objs) != sorted(n["name"] for n in nodes):
        fail("mesh objects %s, the file's nodes %s" % (sorted(objs), [n["name"] for n in nodes]))
    ranges = set()
    for node in nodes:
        if not node["name"].startswith("tree-"):
            fail("a node named %r" % node["name"])
        ranges.add(check_tree(objs[node["name"]], node, fps))
    if len(ranges) != 1:
        fail("the trees' actions run over different frames: %s" % ranges)
    print("edaha-forest: %d trees, one loop of frames %g..%g at %g fps, the foot 0"
          % (len(nodes), *ranges.pop(), fps))


main()
