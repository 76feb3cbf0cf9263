/* SPDX-License-Identifier: MIT */
#include "export_vines.h"

#include "vine.h"

int export_vines_build(struct export_vines *ev, const struct tree *t)
{
	int r = 0;

	mesh_init(&ev->stems);
	mesh_init(&ev->leaves);
	for (size_t i = 0; i < t->nvines && r == 0; i++)
		r = vine_mesh_append(&t->vines[i], &ev->stems, &ev->leaves);
	if (r < 0) {
		mesh_clear(&ev->stems);
		mesh_clear(&ev->leaves);
	}
	return r;
}

void export_vines_finish(struct export_vines *ev)
{
	mesh_finish(&ev->stems);
	mesh_finish(&ev->leaves);
}
