/* SPDX-License-Identifier: MIT */
/*
 * write_iso_samples DIR: iso-surfaces (wood_iso) as a tree's bark in GLB files for the
 * Khronos glTF validator (validate_samples.sh): DIR/wood-ball.glb (a ball 6 voxels in
 * radius), wood-blobs.glb (two balls), wood-block.glb (a block of voxels, sharp edges).
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "iso_fields.h"
#include "mesh.h"
#include "tree.h"
#include "wood.h"

static int write_glb(const char *dir, const char *name, const struct wood_grid *g)
{
	char path[4096];
	struct tree t;
	struct tree_mesh tm;
	struct buf b;
	FILE *f;
	int r, ok;

	if (snprintf(path, sizeof(path), "%s/%s", dir, name) >= (int)sizeof(path))
		return -ENAMETOOLONG;
	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&b);
	r = wood_iso(g, 0.5, &tm.bark);
	if (r == 0)
		r = export_glb(&t, &tm, NULL, &b);
	if (r == 0) {
		f = fopen(path, "wb");
		ok = f && fwrite(b.data, 1, b.len, f) == b.len;
		ok = f && fclose(f) == 0 && ok;
		if (!ok) {
			fprintf(stderr, "write_iso_samples: %s: cannot write\n", path);
			r = -EIO;
		} else {
			printf("%s (%zu triangles, %zu bytes)\n", path, tm.bark.nindices / 3, b.len);
		}
	}
	buf_finish(&b);
	tree_mesh_finish(&tm);
	tree_finish(&t);
	return r;
}

int main(int argc, char **argv)
{
	struct wood_grid g;
	int r;

	if (argc != 2) {
		fprintf(stderr, "usage: write_iso_samples DIR\n");
		return 2;
	}
	iso_grid(&g, 16, 16, 16, vec3(-0.08, 0.0, -0.08), 0.01);
	iso_ball(&g, vec3(0.001, 0.079, 0.002), 0.06);
	r = write_glb(argv[1], "wood-ball.glb", &g);
	wood_grid_finish(&g);

	iso_grid(&g, 30, 16, 16, vec3(0, 0, 0), 0.01);
	iso_ball(&g, vec3(0.08, 0.08, 0.08), 0.05);
	iso_ball(&g, vec3(0.22, 0.081, 0.079), 0.045);
	if (r == 0)
		r = write_glb(argv[1], "wood-blobs.glb", &g);
	wood_grid_finish(&g);

	iso_grid(&g, 12, 11, 10, vec3(0, 0, 0), 0.02);
	iso_block(&g, 2, 2, 2, 10, 9, 8, 1.0);
	if (r == 0)
		r = write_glb(argv[1], "wood-block.glb", &g);
	wood_grid_finish(&g);
	if (r < 0) {
		fprintf(stderr, "write_iso_samples: %s\n", strerror(-r));
		return 1;
	}
	return 0;
}
