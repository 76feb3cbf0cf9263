# SPDX-License-Identifier: MIT
# Run by blender.sh inside Blender (blender -b --factory-startup --python blender_wind.py
# -- MODEL.glb): imports edaha's model.glb with Blender's bundled glTF importer and checks
# that the wind came with it (docs/living-trees.md, "The wind in model.glb"): one mesh
# with its 10 shape keys (plus Basis) named as the file names its targets, an action made
# from the animation "wind" driving them (Blender 3.4 names it "wind_tree"), and,
# evaluated at two frames, a crown vertex (the highest) in different places and the
# trunk's foot (the lowest) in the same; the action's first and last frames alike.
# Prints one line "edaha-wind: ..." and exits 0, or raises (Blender then exits 1).
import sys

import bpy
import numpy

# Debian 12's Blender 3.4.1 importer uses numpy.bool, which Debian 12's numpy 1.24 no
# longer has: every glTF with normals fails to import (KhronosGroup/glTF-Blender-IO#1844,
# fixed in Blender 3.5, not backported). The alias back, for the bundled importer only.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

TARGETS = ["wind-trunk-along", "wind-trunk-across", "wind-limbs-sin", "wind-limbs-cos",
           "wind-branches-sin", "wind-branches-cos", "wind-twigs-sin", "wind-twigs-cos",
           "wind-flutter-sin", "wind-flutter-cos"]


def fail(msg):
    raise RuntimeError("edaha-wind: FAIL: " + msg)


def positions(obj, frame):
    scene = bpy.context.scene
    scene.frame_set(int(frame), subframe=frame - int(frame))
    ev = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = ev.to_mesh()
    co = [v.co.copy() for v in mesh.vertices]
    ev.to_mesh_clear()
    return co


def main():
    path = sys.argv[sys.argv.index("--") + 1]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if bpy.ops.import_scene.gltf(filepath=path) != {"FINISHED"}:
        fail("the import did not finish")
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    if len(meshes) != 1:
        fail("%d mesh objects, wanted 1" % len(meshes))
    obj = meshes[0]
    keys = obj.data.shape_keys
    if keys is None:
        fail("no shape keys")
    names = [k.name for k in keys.key_blocks]
    if len(names) != 1 + len(TARGETS) or names[1:] != TARGETS:
        fail("shape keys %s" % names)
    ad = keys.animation_data
    if ad is None or ad.action is None:
        fail("the shape keys are not animated")
    # Blender names a shape keys' action after the animation and the mesh
    action = ad.action.name
    if action not in ("wind", "wind_" + obj.data.name, "wind_tree"):
        fail("the shape keys' action is %r, not the animation wind" % action)
    curves = len(ad.action.fcurves)
    if curves != len(TARGETS):
        fail("%d animated shape keys" % curves)
    lo, hi = ad.action.frame_range
    rest = [v.co.copy() for v in obj.data.vertices]
    top = max(range(len(rest)), key=lambda i: rest[i].z)
    foot = min(range(len(rest)), key=lambda i: rest[i].z)
    f1 = int(lo) + 1
    f2 = int(lo + (hi - lo) * 0.3)
    a, b = positions(obj, f1), positions(obj, f2)
    moved = (a[top] - b[top]).length
    if not moved > 1e-4:
        fail("the crown's top moved %.3g m between frames %d and %d" % (moved, f1, f2))
    if (a[foot] - b[foot]).length != 0.0 or (a[foot] - rest[foot]).length != 0.0:
        fail("the trunk's foot moved")
    # the loop: its last frame is its first
    first, last = positions(obj, lo), positions(obj, hi)
    seam = max((first[i] - last[i]).length for i in range(len(rest)))
    if not seam < 1e-5:
        fail("the loop's ends differ by %.3g m" % seam)
    print("edaha-wind: %s: %d vertices, shape keys Basis + %d, action %r (frames %g..%g), "
          "the top moved %.1f mm between frames %d and %d, the loop's ends %.2g m apart, "
          "the foot 0"
          % (path.split("/")[-2], len(rest), len(names) - 1, action, lo, hi, moved * 1e3, f1, f2,
             seam))


main()
