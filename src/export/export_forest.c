/* SPDX-License-Identifier: MIT */
/* forest.glb: every tree of today's forest in one glTF with one wind (export.h;
 * docs/forest.md, "Headless and for the teacher"). */
#include "export.h"
#include "export_gltf.h"
#include "export_wind.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>

/* "tree-18446744073709551615" and its NUL */
#define FOREST_NAME_MAX 32

/* Whether the trees can be written: meshes given, places finite (JSON has no NaN). */
static bool forest_valid(const struct export_forest_tree *trees, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		const struct export_forest_tree *f = &trees[i];

		if (!f->tree || !f->mesh)
			return false;
		for (int c = 0; c < 3; c++)
			if (!isfinite(f->position[c]))
				return false;
	}
	return true;
}

int export_glb_forest(const struct export_forest_tree *trees, size_t n,
		      const struct export_wind *wind, double loop_s, struct buf *out)
{
	struct export_gltf *d;
	int r = 0;

	/* a common loop, whatever the trees: each its own would not loop as one */
	if ((n > 0 && !trees) || !forest_valid(trees, n) ||
	    (wind && (loop_s <= 0.0 || !export_wind_valid(wind, loop_s))))
		return -EINVAL;
	d = export_gltf_create();
	if (!d)
		return -ENOMEM;
	for (size_t i = 0; i < n && r == 0; i++) {
		const struct export_forest_tree *f = &trees[i];
		struct export_wind w;
		char name[FOREST_NAME_MAX];
		struct export_gltf_node node = { name, f->position };

		snprintf(name, sizeof(name), "tree-%" PRIu64, f->number);
		if (wind) {
			/* the forest's wind, each tree's phases from its drawing's seed */
			w = *wind;
			w.seed = f->seed;
		}
		r = export_gltf_add_tree(d, f->tree, f->mesh, f->marks, wind ? &w : NULL, loop_s,
					 &node);
	}
	if (r == 0)
		r = export_gltf_write(d, out);
	export_gltf_destroy(d);
	return r;
}
