/* SPDX-License-Identifier: MIT */
#include "synth_vine.h"

#include <errno.h>
#include <math.h>

#include "mesh.h"
#include "vine.h"
#include "vine_support.h"

/* Beside the bark, as the command line's pole plantings are: R + r and a little. */
#define SYNTH_VINE_GAP 0.003

void synth_vine_params(size_t i, struct vine_params *p, struct vec3 *plant)
{
	double d;

	vine_params_default(p);
	if (i % 2 == 1) {
		p->twining = VINE_RIGHT;
		p->leaves_per_node = 2;
		p->seed = 7;
	}
	d = SYNTH_VINE_RADIUS + p->radius + SYNTH_VINE_GAP;
	*plant = i % 2 == 0 ? vec3(d, 0.0, 0.0) : vec3(0.0, 0.0, d);
}

/* The trunk and its leaf. */
static int trunk(struct tree *t)
{
	const struct vec3 p[] = { { 0, 0, 0 }, { 0, SYNTH_VINE_HEIGHT / 2, 0 },
				  { 0, SYNTH_VINE_HEIGHT, 0 } };
	const double r[] = { SYNTH_VINE_RADIUS, SYNTH_VINE_RADIUS, SYNTH_VINE_RADIUS };
	const struct vec3 leaf[] = { { 0, SYNTH_VINE_HEIGHT, 0 },
				     { 0.3, SYNTH_VINE_HEIGHT + 0.2, 0.05 },
				     { 0.1, SYNTH_VINE_HEIGHT + 0.45, 0.1 } };
	int id = tree_add_branch(t, -1, 0.0, ORIGIN_SKETCH, p, r, 3);

	if (id < 0)
		return id;
	t->lifted = true;
	id = tree_add_leaf(t, id, ORIGIN_SKETCH, leaf, 3);
	return id < 0 ? id : 0;
}

/* Vine i grown on s and taken by t. */
static int grow_one(struct tree *t, const struct vine_support *s, size_t i)
{
	struct vine_params p;
	struct vec3 plant;
	struct vine v;
	int r;

	synth_vine_params(i, &p, &plant);
	vine_init(&v, &p, plant);
	r = vine_grow(&v, s, INFINITY);
	if (r == 0)
		r = vine_attach(t, &v);
	vine_finish(&v);
	return r;
}

int synth_vine_tree(struct tree *t, size_t nvines)
{
	struct vine_support *s = NULL;
	struct tree_mesh bark;
	int r;

	if (nvines > SYNTH_VINE_MAX)
		return -EINVAL;
	tree_clear(t);
	r = trunk(t);
	if (r < 0 || nvines == 0)
		return r;
	tree_mesh_init(&bark);
	/* the bark alone, as the kiosk's vines climb it */
	r = tree_mesh_append(&bark, t, 0, t->nleaves);
	if (r == 0)
		r = vine_support_create(bark.bark.positions, bark.bark.nvertices, bark.bark.indices,
					bark.bark.nindices / 3, &s);
	for (size_t i = 0; i < nvines && r == 0; i++)
		r = grow_one(t, s, i);
	vine_support_destroy(s);
	tree_mesh_finish(&bark);
	return r;
}
