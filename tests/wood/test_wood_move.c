/* SPDX-License-Identifier: MIT */
/*
 * Leaves and vines move out with the growing bark (issue 17, wood_move_out): a vertical
 * trunk with a limb and a thin twig, leaves on all three and a vine grown round the trunk,
 * pressed three times with a large alpha: afterwards no leaf point and no vine axis point
 * is buried; moved leaves keep their shape and stay out when their branch's frame is
 * followed; leaves far from the wood are untouched bit for bit; moved vine points sit on
 * the bark (within a voxel and the stem's radius of it); the same input gives the same
 * bytes; the app's grow press leaves nothing buried either.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app_private.h"
#include "mesh.h"
#include "sketch.h"
#include "test.h"
#include "vine.h"
#include "vine_support.h"
#include "wood.h"

#define TRUNK_R 0.08
#define PRESSES 3

static void line(struct vec3 *p, double *r, size_t n, struct vec3 a, struct vec3 b, double r0,
		 double r1)
{
	for (size_t k = 0; k < n; k++) {
		double s = (double)k / (double)(n - 1);

		p[k] = vec3_lerp(a, b, s);
		r[k] = r0 + (r1 - r0) * s;
	}
}

/* A leaf on branch b at bt: a quad from `at` outwards along `out`, across along `side`. */
static void leaf(struct tree *t, int b, double bt, struct vec3 at, struct vec3 out,
		 struct vec3 side)
{
	struct vec3 q[4] = {
		at,
		vec3_add(at, vec3_add(vec3_scale(out, 0.05), vec3_scale(side, 0.02))),
		vec3_add(at, vec3_scale(out, 0.09)),
		vec3_add(at, vec3_sub(vec3_scale(out, 0.05), vec3_scale(side, 0.02))),
	};
	int id = tree_add_leaf(t, b, ORIGIN_SKETCH, q, 4);

	CHECK(id >= 0);
	t->leaves[id].branch_t = bt;
	CHECK_INT(tree_leaf_attach(t, (size_t)id), 0);
}

/* Leaves far from any wood: on the twig's outer end. */
#define FAR_FIRST 9

static void leaves(struct tree *t)
{
	const struct vec3 up = vec3(0, 1, 0);
	const struct vec3 limb_dir = vec3_norm_or(vec3(0.5, 0.3, 0), up);
	const struct vec3 limb_up = vec3_norm_or(vec3(-0.3, 0.5, 0), up);

	/* on the trunk's bark, all round it */
	for (int k = 0; k < 6; k++) {
		double a = k * VEC_PI / 3.0, y = 0.15 + 0.13 * k;
		struct vec3 out = vec3(cos(a), 0, sin(a)), side = vec3(-sin(a), 0, cos(a));

		leaf(t, 0, y, vec3_add(vec3(0, y, 0), vec3_scale(out, TRUNK_R)), out, side);
	}
	/* on the limb: above, in front, behind */
	leaf(t, 1, 0.5, vec3_add(vec3(0.25, 0.75, 0), vec3_scale(limb_up, 0.05)), limb_up,
	     limb_dir);
	leaf(t, 1, 0.7, vec3(0.35, 0.81, 0.05), vec3(0, 0, 1), limb_dir);
	leaf(t, 1, 0.3, vec3(0.15, 0.69, -0.05), vec3(0, 0, -1), limb_dir);
	/* on the twig's far end (FAR_FIRST on) */
	leaf(t, 2, 0.9, vec3(0.86, 1.18, 0.0), up, vec3(0, 0, 1));
	leaf(t, 2, 1.0, vec3(0.9, 1.2, 0.0), vec3(1, 0, 0), vec3(0, 0, 1));
}

/* The tree: a trunk of 1 m (r 0.08), a limb from 0.6 of it, a twig off the limb's end. */
static void build(struct tree *t)
{
	struct vec3 p[11];
	double r[11];

	tree_init(t);
	line(p, r, 11, vec3(0, 0, 0), vec3(0, 1, 0), TRUNK_R, TRUNK_R);
	CHECK_INT(tree_add_branch(t, -1, 0, ORIGIN_SKETCH, p, r, 11), 0);
	line(p, r, 6, vec3(0, 0.6, 0), vec3(0.5, 0.9, 0), 0.05, 0.04);
	CHECK_INT(tree_add_branch(t, 0, 0.6, ORIGIN_SKETCH, p, r, 6), 1);
	line(p, r, 5, vec3(0.5, 0.9, 0), vec3(0.9, 1.2, 0), 0.008, 0.005);
	CHECK_INT(tree_add_branch(t, 1, 1.0, ORIGIN_SKETCH, p, r, 5), 2);
	t->lifted = true;
	leaves(t);
}

/* A vine planted beside the trunk's foot, grown on the tree's bark. */
static void vine(struct tree *t)
{
	struct vine_support *s = NULL;
	struct tree_mesh bark;
	struct vine_params p;
	struct vine v;

	vine_params_default(&p);
	tree_mesh_init(&bark);
	CHECK_INT(tree_mesh_append(&bark, t, 0, t->nleaves), 0);
	CHECK_INT(vine_support_create(bark.bark.positions, bark.bark.nvertices, bark.bark.indices,
				      bark.bark.nindices / 3, &s),
		  0);
	vine_init(&v, &p, vec3(TRUNK_R + p.radius + 0.003, 0.0, 0.0));
	CHECK_INT(vine_grow(&v, s, INFINITY), 0);
	CHECK_INT(vine_attach(t, &v), 0);
	vine_finish(&v);
	vine_support_destroy(s);
	tree_mesh_finish(&bark);
}

static void params(struct wood_params *p)
{
	wood_params_default(p);
	p->grid = 64;
	p->alpha = 1e6; /* the most allowed: the wood grows a lot */
}

static size_t vine_points(const struct tree *t)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nvines; i++)
		for (size_t s = 0; s < t->vines[i].nshoots; s++)
			n += t->vines[i].shoots[s].n;
	return n;
}

/* Every vine axis point of t, in order, into out. */
static void vine_gather(const struct tree *t, struct vec3 *out)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nvines; i++)
		for (size_t s = 0; s < t->vines[i].nshoots; s++)
			for (size_t k = 0; k < t->vines[i].shoots[s].n; k++)
				out[n++] = t->vines[i].shoots[s].axis[k];
}

static size_t buried_leaf_points(const struct wood *w, const struct tree *t)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nleaves; i++)
		for (size_t k = 0; k < t->leaves[i].npoints; k++)
			n += wood_density_at(&w->g, t->leaves[i].points[k]) > 0.5;
	return n;
}

static size_t buried_vine_points(const struct wood *w, const struct tree *t)
{
	size_t n = vine_points(t), b = 0;
	struct vec3 *p = malloc((n ? n : 1) * sizeof(*p));

	CHECK(p);
	vine_gather(t, p);
	for (size_t k = 0; k < n; k++)
		b += wood_density_at(&w->g, p[k]) > 0.5;
	free(p);
	return b;
}

/* Leaf i's shape against the original's: every pairwise distance within 1e-9. */
static void check_shape(const struct leaf *a, const struct leaf *b)
{
	CHECK_INT(a->npoints, b->npoints);
	for (size_t i = 0; i < a->npoints; i++)
		for (size_t j = i + 1; j < a->npoints; j++)
			CHECK_NEAR(vec3_dist(a->points[i], a->points[j]),
				   vec3_dist(b->points[i], b->points[j]), 1e-9);
}

/* The moved vine points of this press (before -> after) sit on the bark: within a voxel
 * and the stem's radius of the iso-surface. */
static size_t check_on_bark(const struct wood *w, const struct vec3 *before,
			    const struct vec3 *after, size_t n, double radius)
{
	struct vine_support *s = NULL;
	size_t moved = 0;

	CHECK_INT(vine_support_create(w->bark.positions, w->bark.nvertices, w->bark.indices,
				      w->bark.nindices / 3, &s),
		  0);
	for (size_t k = 0; k < n; k++) {
		double d;

		if (memcmp(&before[k], &after[k], sizeof(before[k])) == 0)
			continue;
		moved++;
		d = vine_support_distance(s, after[k], 1.0, NULL, NULL);
		if (!(d <= w->g.h + radius))
			fprintf(stderr, "vine point %zu: %.4f m from the bark (h %.4f)\n", k, d,
				w->g.h);
		CHECK(d <= w->g.h + radius);
	}
	vine_support_destroy(s);
	return moved;
}

/* Leaves' points of t, in order, into out (npoints each). */
static void leaf_gather(const struct tree *t, struct vec3 *out)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nleaves; i++)
		for (size_t k = 0; k < t->leaves[i].npoints; k++)
			out[n++] = t->leaves[i].points[k];
}

/* A leaf moved in this press went no further than it had to: 0.1 voxel back (less than
 * the margin's 0.05 voxel and a little) buries it again. */
static void check_leaves_near(const struct wood *w, const struct tree *t,
			      const struct vec3 *before)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];
		struct vec3 d = vec3_sub(l->points[0], before[n]);
		double s = vec3_len(d);
		bool back = false;

		if (s > 0.0) {
			d = vec3_scale(d, 1.0 / s);
			for (size_t k = 0; k < l->npoints; k++)
				back |= wood_density_at(&w->g, vec3_sub(l->points[k],
									vec3_scale(d, 0.1 * w->g.h))) >
					0.5;
			CHECK(back);
		}
		n += l->npoints;
	}
}

/* The whole case: the tree, its wood and PRESSES presses each followed by the move. */
static void run(struct tree *t, struct wood *w, bool verbose)
{
	struct tree orig;
	struct wood_params p;
	size_t n, moved_vine = 0, moved_leaves = 0;
	double shift = 0.0;
	struct vec3 *before, *after, leaves_before[64];

	build(t);
	vine(t);
	tree_init(&orig);
	CHECK_INT(tree_copy(&orig, t), 0);
	n = vine_points(t);
	CHECK(n > 100 && t->nleaves * 4 <= 64);
	before = malloc(n * sizeof(*before));
	after = malloc(n * sizeof(*after));
	CHECK(before && after);
	params(&p);
	CHECK_INT(wood_begin(w, t, &p), 0);
	CHECK(w->voxelised[0] && w->voxelised[1] && !w->voxelised[2]);
	for (int press = 0; press < PRESSES; press++) {
		CHECK_INT(wood_press(w), 0);
		vine_gather(t, before);
		leaf_gather(t, leaves_before);
		if (verbose)
			fprintf(stderr, "press %d: buried before: %zu leaf points, %zu vine points\n",
				press + 1, buried_leaf_points(w, t), buried_vine_points(w, t));
		CHECK(press > 0 || buried_leaf_points(w, t) > 0);
		CHECK(press > 0 || buried_vine_points(w, t) > 0);
		CHECK_INT(wood_move_out(w, t), 0);
		CHECK_INT(buried_leaf_points(w, t), 0);
		CHECK_INT(buried_vine_points(w, t), 0);
		check_leaves_near(w, t, leaves_before);
		vine_gather(t, after);
		moved_vine += check_on_bark(w, before, after, n, t->vines[0].p.radius);
	}
	CHECK(moved_vine > 0);
	/* shapes kept; the far leaves not touched at all */
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *a = &t->leaves[i], *b = &orig.leaves[i];
		bool same = memcmp(a->points, b->points, a->npoints * sizeof(*a->points)) == 0;

		check_shape(a, b);
		moved_leaves += !same;
		if (vec3_dist(a->points[0], b->points[0]) > shift)
			shift = vec3_dist(a->points[0], b->points[0]);
		if (i >= FAR_FIRST) {
			CHECK(same);
			CHECK(memcmp(a->local, b->local, a->npoints * sizeof(*a->local)) == 0);
		}
	}
	CHECK(moved_leaves >= 6);
	if (verbose)
		fprintf(stderr, "moved: %zu leaves (by up to %.4f m), %zu vine points (%zu of "
			"them, press after press); h %.4f m\n",
			moved_leaves, shift, moved_vine, n, w->g.h);
	/* contacts as they were */
	for (size_t s = 0; s < t->vines[0].nshoots; s++)
		CHECK(memcmp(t->vines[0].shoots[s].contact, orig.vines[0].shoots[s].contact,
			     t->vines[0].shoots[s].n) == 0);
	free(before);
	free(after);
	tree_finish(&orig);
}

/* Following the branches' frames again keeps the leaves where they were moved. */
static void test_follow(struct tree *t, const struct wood *w)
{
	struct tree c;

	tree_init(&c);
	CHECK_INT(tree_copy(&c, t), 0);
	tree_leaves_follow(&c, -1);
	for (size_t i = 0; i < c.nleaves; i++)
		for (size_t k = 0; k < c.leaves[i].npoints; k++)
			CHECK(vec3_dist(c.leaves[i].points[k], t->leaves[i].points[k]) < 1e-12);
	CHECK_INT(buried_leaf_points(w, &c), 0);
	tree_finish(&c);
}

static bool same_trees(const struct tree *a, const struct tree *b)
{
	if (a->nleaves != b->nleaves || a->nvines != b->nvines)
		return false;
	for (size_t i = 0; i < a->nleaves; i++)
		if (memcmp(a->leaves[i].points, b->leaves[i].points,
			   a->leaves[i].npoints * sizeof(struct vec3)) != 0 ||
		    memcmp(a->leaves[i].local, b->leaves[i].local,
			   a->leaves[i].npoints * sizeof(struct vec3)) != 0)
			return false;
	for (size_t i = 0; i < a->nvines; i++) {
		if (a->vines[i].nshoots != b->vines[i].nshoots)
			return false;
		for (size_t s = 0; s < a->vines[i].nshoots; s++)
			if (a->vines[i].shoots[s].n != b->vines[i].shoots[s].n ||
			    memcmp(a->vines[i].shoots[s].axis, b->vines[i].shoots[s].axis,
				   a->vines[i].shoots[s].n * sizeof(struct vec3)) != 0)
				return false;
	}
	return true;
}

/* A grow op's year (wood_grow, what app_wood_apply and the kiosk's press off the loop
 * do): it moves them out too. */
static void test_app(void)
{
	struct tree t;
	struct wood_params p;

	build(&t);
	vine(&t);
	params(&p);
	for (int press = 0; press < PRESSES; press++) {
		CHECK_INT(wood_grow(&t, &p), 0);
		CHECK(t.wood);
		CHECK_INT(buried_leaf_points(t.wood, &t), 0);
		CHECK_INT(buried_vine_points(t.wood, &t), 0);
	}
	tree_finish(&t);
}

/* The density's interpolation: the samples at the voxels' centres, 0 outside. */
static void test_density(void)
{
	struct wood_grid g;

	CHECK_INT(wood_grid_create(&g, 2, 1, 1, vec3(0, 0, 0), 1.0), 0);
	g.density[0] = 1.0;
	g.density[1] = 0.0;
	CHECK_NEAR(wood_density_at(&g, vec3(0.5, 0.5, 0.5)), 1.0, 0);
	CHECK_NEAR(wood_density_at(&g, vec3(1.0, 0.5, 0.5)), 0.5, 1e-15);
	CHECK_NEAR(wood_density_at(&g, vec3(0.0, 0.5, 0.5)), 0.5, 1e-15);
	CHECK_NEAR(wood_density_at(&g, vec3(0.5, 1.0, 0.5)), 0.5, 1e-15);
	CHECK_NEAR(wood_density_at(&g, vec3(0.5, 0.5, -0.5)), 0.0, 0);
	CHECK_NEAR(wood_density_at(&g, vec3(50, 0.5, 0.5)), 0.0, 0);
	CHECK_NEAR(wood_density_at(&g, vec3(NAN, 0.5, 0.5)), 0.0, 0);
	wood_grid_finish(&g);
}

int main(void)
{
	struct tree a, b;
	struct wood wa, wb;

	test_density();
	run(&a, &wa, true);
	test_follow(&a, &wa);
	run(&b, &wb, false);
	CHECK(same_trees(&a, &b));
	wood_finish(&wa);
	wood_finish(&wb);
	tree_finish(&a);
	tree_finish(&b);
	test_app();
	printf("wood_move: ok\n");
	return 0;
}
