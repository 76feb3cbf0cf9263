/* SPDX-License-Identifier: MIT */
/*
 * Twining vines on the visitor's tree (issue 16, seed 004; docs/vines.md): a vine op grows
 * its vine to the end on the tree's bark as it stands, and the tree keeps it. The model
 * is the grown vine all along (exports, the skeleton and undo never see growth).
 */
#include <errno.h>
#include <math.h>

#include "app_private.h"
#include "mesh.h"
#include "sketch.h"
#include "vine.h"
#include "vine_support.h"

int app_vine_support(const struct tree *t, struct vine_support **out)
{
	struct tree_mesh bark;
	int ret;

	*out = NULL;
	tree_mesh_init(&bark);
	/* the bark alone: a vine twines round wood, not leaves */
	ret = tree_mesh_append(&bark, t, 0, t->nleaves);
	if (ret == 0)
		ret = vine_support_create(bark.bark.positions, bark.bark.nvertices, bark.bark.indices,
					  bark.bark.nindices / 3, out);
	tree_mesh_finish(&bark);
	return ret;
}

int app_vine_apply(struct tree *t, const struct doc_op *op)
{
	struct vine_support *s = NULL;
	struct vine v;
	int ret;

	/* a drawing's parameters were checked when read; a full tree takes no more */
	if (!op->vine || t->nvines >= TREE_MAX_VINES || t->nbranches == 0)
		return SKETCH_GREW;
	ret = app_vine_support(t, &s);
	if (ret == -EINVAL)
		return SKETCH_GREW; /* no bark to climb: nothing grows */
	if (ret < 0)
		return ret;
	vine_init(&v, op->vine, vec3(op->plant[0], op->plant[1], op->plant[2]));
	ret = vine_grow(&v, s, INFINITY);
	vine_support_destroy(s);
	if (ret == 0)
		ret = tree_add_vine(t, &v);
	vine_finish(&v);
	if (ret == -ENOSPC)
		return SKETCH_GREW;
	return ret < 0 ? ret : SKETCH_CHANGED;
}
