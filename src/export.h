/* SPDX-License-Identifier: MIT */
#pragma once

#include "buf.h"
#include "mesh.h"
#include "tree.h"

/*
 * Exporters append to `out` in memory; platform/ puts the bytes into files. All return 0
 * or a negative errno (-ENOMEM; -EFBIG past glTF's 4 GiB; -EINVAL for a bad MTL name) and
 * leave `out` as it was on failure. Same input, same bytes.
 */

/* glTF 2.0 binary: y up, metres, normals, "bark" and double-sided "leaves" materials. */
int export_glb(const struct tree_mesh *m, struct buf *out);
/* Wavefront OBJ with its MTL; the OBJ refers to the MTL as mtl_name (e.g. "model.mtl"). */
int export_obj(const struct tree_mesh *m, const char *mtl_name, struct buf *obj, struct buf *mtl);
/* Renames the MTL an OBJ made by export_obj refers to (its mtllib line), for an OBJ built
 * before its file's name was known. 0, -EINVAL (no mtllib line, a bad name) or -ENOMEM
 * (obj unchanged then). */
int export_obj_mtllib(struct buf *obj, const char *mtl_name);
/* skeleton.json, see docs/skeleton-format.md. */
int export_skeleton(const struct tree *t, struct buf *out);
