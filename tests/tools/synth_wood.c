/* SPDX-License-Identifier: MIT */
#include "synth_wood.h"

#include <errno.h>
#include <stdlib.h>

#include "wood.h"

/* n points from a to b, radii from r0 to r1. */
static void line(struct vec3 *p, double *r, size_t n, struct vec3 a, struct vec3 b, double r0,
		 double r1)
{
	for (size_t k = 0; k < n; k++) {
		double s = (double)k / (double)(n - 1);

		p[k] = vec3_lerp(a, b, s);
		r[k] = r0 + (r1 - r0) * s;
	}
}

static int add(struct tree *t, int parent, double parent_t, struct vec3 a, struct vec3 b,
	       double r0, double r1)
{
	struct vec3 p[11];
	double r[11];

	line(p, r, 11, a, b, r0, r1);
	return tree_add_branch(t, parent, parent_t, ORIGIN_SKETCH, p, r, 11);
}

/* A small square leaf at (x, y, 0). */
static int leaf(struct tree *t, int branch, double x, double y)
{
	const struct vec3 p[] = { { x, y, 0 }, { x + 0.03, y + 0.02, 0 }, { x, y + 0.05, 0 },
				  { x - 0.03, y + 0.02, 0 } };

	return tree_add_leaf(t, branch, ORIGIN_SKETCH, p, 4);
}

static int shape(struct tree *t)
{
	int r;

	/* the trunk's point 6 is at 0.6 m: the limb starts on its axis */
	if ((r = add(t, -1, 0.0, vec3(0, 0, 0), vec3(0, 1, 0), 0.08, 0.08)) < 0 ||
	    (r = add(t, 0, 0.6, vec3(0, 0.6, 0), vec3(0.4, 1.0, 0), 0.05, 0.04)) < 0 ||
	    (r = add(t, 1, 0.8, vec3(0.32, 0.92, 0), vec3(0.42, 1.2, 0.05), 0.006, 0.006)) < 0 ||
	    (r = add(t, 0, 1.0, vec3(0, 1, 0), vec3(-0.1, 1.3, 0), 0.006, 0.006)) < 0 ||
	    (r = leaf(t, 2, 0.42, 1.2)) < 0 || (r = leaf(t, 3, -0.1, 1.3)) < 0)
		return r;
	return 0;
}

static int grow(struct tree *t, int presses, int mode)
{
	struct wood_params p;
	struct wood *w = malloc(sizeof(*w));
	int r;

	if (!w)
		return -ENOMEM;
	wood_params_default(&p);
	p.mode = (enum wood_mode)mode;
	r = wood_begin(w, t, &p);
	if (r < 0) {
		free(w);
		return r;
	}
	t->wood = w; /* the tree frees it */
	for (int i = 0; i < presses && r == 0; i++)
		r = wood_press(w);
	return r;
}

int synth_wood_tree(struct tree *t, int presses, int mode)
{
	int r;

	if (presses < 0)
		return -EINVAL;
	tree_clear(t);
	r = shape(t);
	if (r < 0)
		return r;
	t->lifted = true;
	return presses > 0 ? grow(t, presses, mode) : 0;
}
