/* SPDX-License-Identifier: MIT */
/* Leaves grouped by shape (src/mesh/leaf_instances.c): the copies propagation (scaled, fixed
 * count; unscaled, fixed size) and arrangement (turned about the branch) make are
 * instances of the leaf they copy; a different leaf is a shape of its own; each leaf comes
 * back from its shape and matrix within 1e-6 (double) and float precision (what the GPU
 * gets); the shapes' triangles are the ones mesh.c makes for each leaf; the leaves not
 * drawn instanced make the same mesh tree_mesh_build does (none is built when no shape
 * is instanced); the cap on instanced shapes;
 * degenerate leaves; determinism; allocation failures. Trees are built by hand, bent and
 * out of the picture plane. */
#include <errno.h>
#include <string.h>

#include "arrange.h"
#include "fail_alloc.h"
#include "leaf_instances.h"
#include "propagate.h"
#include "test.h"

/* A bent branch from `root` (or from the point at pt on parent). */
static int add_bent(struct tree *t, int parent, double pt, struct vec3 root, struct vec3 dir,
		    struct vec3 bend, double len, int n, double r0)
{
	struct vec3 p[16];
	double r[16], l0;
	int id;

	CHECK(n >= 2 && n <= 16);
	if (parent >= 0)
		root = tree_frame_at(&t->branches[parent], pt).origin;
	for (int k = 0; k < n; k++) {
		double s = (double)k / (n - 1);

		p[k] = vec3_add(vec3_scale(dir, s), vec3_scale(bend, s * s));
		r[k] = r0 * (1.0 - 0.7 * s);
	}
	l0 = vec3_polyline_length(p, (size_t)n);
	for (int k = 0; k < n; k++)
		p[k] = vec3_add(root, vec3_scale(p[k], len / l0));
	id = tree_add_branch(t, parent, parent >= 0 ? pt : 0.0, ORIGIN_SKETCH, p, r, (size_t)n);
	CHECK(id >= 0);
	return id;
}

/* A lobed leaf of n points beside branch b at u, tilted out of its plane, a little bent
 * (not planar); `lobe` makes different shapes. */
static int add_leaf(struct tree *t, int b, double u, double size, int n, double lobe)
{
	struct tree_frame f = tree_frame_at(&t->branches[b], u);
	struct vec3 p[32];
	int id;

	CHECK(n <= 32);
	for (int i = 0; i < n; i++) {
		double a = 2.0 * VEC_PI * i / n, l = i % 2 ? lobe : 1.0;
		double out = 0.3 * size * (1.0 + cos(a)) + 0.05 * size * sin(3 * a);

		p[i] = vec3_add(f.origin,
				vec3_add(vec3_scale(f.normal, 0.05 + size * l * (1.0 + cos(a))),
					 vec3_add(vec3_scale(f.tangent, 0.4 * size * l * sin(a)),
						  vec3_scale(f.binormal, out))));
	}
	id = tree_add_leaf(t, b, ORIGIN_SKETCH, p, (size_t)n);
	CHECK(id >= 0);
	t->leaves[id].branch_t = u;
	CHECK_INT(tree_leaf_attach(t, (size_t)id), 0);
	return id;
}

/* trunk, the source S (no child branches) and four targets of different lengths, one a
 * child of another, all bent in 3D. */
static int build_branches(struct tree *t)
{
	int trunk, s, c;

	tree_init(t);
	trunk = add_bent(t, -1, 0, vec3(0.1, 0, -0.2), vec3(0, 1, 0), vec3(0.3, 0, 0.2), 4.0, 9,
			 0.2);
	s = add_bent(t, trunk, 0.5, vec3(0, 0, 0), vec3(1, 0.5, 0.3), vec3(0, 0.2, -0.3), 2.0, 7,
		     0.08);
	add_bent(t, trunk, 0.6, vec3(0, 0, 0), vec3(-1, 0.4, -0.2), vec3(0, 0.3, 0.1), 1.0, 5,
		 0.06);
	c = add_bent(t, trunk, 0.9, vec3(0, 0, 0), vec3(0.2, 1, -0.8), vec3(-0.4, 0, 0), 3.0, 10,
		     0.07);
	add_bent(t, c, 0.4, vec3(0, 0, 0), vec3(0.2, 1, -0.5), vec3(0.1, 0, 0.1), 0.6, 5, 0.03);
	add_bent(t, trunk, 0.3, vec3(0, 0, 0), vec3(0.3, -0.4, 1), vec3(0, 0.2, 0), 1.5, 6, 0.05);
	return s;
}

/* Every leaf from its shape and matrix: within 1e-6 in double, float precision in float. */
static void check_points(const struct leaf_instances *li, const struct tree *t)
{
	bool *seen = calloc(t->nleaves + 1, sizeof(*seen));

	CHECK(seen);
	CHECK_INT(li->ninstances, t->nleaves);
	for (size_t i = 0; i < li->ninstances; i++) {
		const struct leaf_instance *in = &li->instances[i];
		const struct leaf *l = &t->leaves[in->leaf];
		const struct leaf_shape *s = &li->shapes[in->shape];
		const float *m = &li->matrices[12 * i];

		CHECK(!seen[in->leaf]);
		seen[in->leaf] = true;
		CHECK(i >= s->first && i < s->first + s->count);
		CHECK((i < li->ninstanced) == s->instanced);
		CHECK_INT(l->npoints, s->npoints);
		for (size_t k = 0; k < l->npoints; k++) {
			struct vec3 p = leaf_instances_point(li, t, i, k);
			struct vec3 d = vec3_sub(t->leaves[s->base].points[k], s->centroid);
			struct vec3 q = vec3((double)m[0] * d.x + (double)m[1] * d.y +
						     (double)m[2] * d.z + (double)m[3],
					     (double)m[4] * d.x + (double)m[5] * d.y +
						     (double)m[6] * d.z + (double)m[7],
					     (double)m[8] * d.x + (double)m[9] * d.y +
						     (double)m[10] * d.z + (double)m[11]);

			CHECK(vec3_dist(p, l->points[k]) <= 1e-6);
			/* floats: 2^-24 of coordinates a few metres from the origin */
			CHECK(vec3_dist(q, l->points[k]) <= 2e-6);
		}
		/* M is a rotation times a scale: M^T M = s^2 I, det > 0 */
		{
			const double *x = in->xf;
			struct vec3 c0 = vec3(x[0], x[4], x[8]), c1 = vec3(x[1], x[5], x[9]),
				    c2 = vec3(x[2], x[6], x[10]);
			double s2 = vec3_dot(c0, c0);

			CHECK_NEAR(vec3_dot(c1, c1), s2, 1e-9 * s2);
			CHECK_NEAR(vec3_dot(c2, c2), s2, 1e-9 * s2);
			CHECK_NEAR(vec3_dot(c0, c1), 0, 1e-9 * s2);
			CHECK_NEAR(vec3_dot(c0, c2), 0, 1e-9 * s2);
			CHECK_NEAR(vec3_dot(c1, c2), 0, 1e-9 * s2);
			CHECK(vec3_dot(vec3_cross(c0, c1), c2) > 0);
		}
	}
	free(seen);
}

/* One leaf's outline triangulated by mesh.c on its own. */
static void leaf_mesh(const struct leaf *l, struct tree_mesh *tm)
{
	struct tree one;
	struct leaf copy = *l;

	memset(&one, 0, sizeof(one));
	one.leaves = &copy;
	one.nleaves = 1;
	tree_mesh_init(tm);
	CHECK_INT(tree_mesh_append(tm, &one, 0, 0), 0);
}

/* Each instanced leaf: its shape's triangles are the ones mesh.c makes for it, the
 * vertices moved by its matrix, the normals turned; the rest is the merged mesh of the
 * leaves left, byte for byte; the triangles add up to tree_mesh_build's. */
static void check_meshes(const struct leaf_instances *li, const struct tree *t)
{
	struct tree_mesh full, loose;
	struct tree rest;
	size_t tris = 0, n = 0;

	for (size_t i = 0; i < li->ninstanced; i++) {
		const struct leaf_instance *in = &li->instances[i];
		const struct mesh *sm = &li->shapes[in->shape].mesh;
		const double *x = in->xf;
		struct tree_mesh tm;

		leaf_mesh(&t->leaves[in->leaf], &tm);
		CHECK_INT(tm.leaves.nvertices, sm->nvertices);
		CHECK_INT(tm.leaves.nindices, sm->nindices);
		CHECK(memcmp(tm.leaves.indices, sm->indices, sm->nindices * sizeof(uint32_t)) == 0);
		for (size_t v = 0; v < sm->nvertices; v++) {
			const float *p = &sm->positions[3 * v], *nn = &sm->normals[3 * v];
			const float *q = &tm.leaves.positions[3 * v];
			const float *qn = &tm.leaves.normals[3 * v];

			for (int r = 0; r < 3; r++) {
				const double *row = &x[4 * r];
				double pos = row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];

				CHECK_NEAR(pos, q[r], 2e-6);
			}
			{
				struct vec3 m = vec3(x[0] * nn[0] + x[1] * nn[1] + x[2] * nn[2],
						     x[4] * nn[0] + x[5] * nn[1] + x[6] * nn[2],
						     x[8] * nn[0] + x[9] * nn[1] + x[10] * nn[2]);

				m = vec3_norm_or(m, vec3(0, 0, 0));
				CHECK_NEAR(m.x, qn[0], 1e-5);
				CHECK_NEAR(m.y, qn[1], 1e-5);
				CHECK_NEAR(m.z, qn[2], 1e-5);
			}
		}
		tris += sm->nindices / 3;
		tree_mesh_finish(&tm);
	}
	CHECK_INT(tris, li->ntriangles);

	memset(&rest, 0, sizeof(rest));
	rest.leaves = calloc(t->nleaves + 1, sizeof(*rest.leaves));
	CHECK(rest.leaves);
	for (size_t i = li->ninstanced; i < li->ninstances; i++)
		n++;
	for (size_t i = 0; i < t->nleaves; i++) {
		bool inst = false;

		for (size_t k = 0; k < li->ninstanced; k++)
			inst = inst || li->instances[k].leaf == i;
		if (!inst)
			rest.leaves[rest.nleaves++] = t->leaves[i];
	}
	CHECK_INT(rest.nleaves, n);
	if (li->ninstanced_shapes == 0) {
		/* nothing instanced: the whole leaves mesh is the caller's */
		CHECK_INT(li->loose.nvertices + li->loose.nindices, 0);
		free(rest.leaves);
		return;
	}
	tree_mesh_init(&loose);
	CHECK_INT(tree_mesh_append(&loose, &rest, 0, 0), 0);
	CHECK_INT(loose.leaves.nvertices, li->loose.nvertices);
	CHECK_INT(loose.leaves.nindices, li->loose.nindices);
	CHECK(!n || memcmp(loose.leaves.positions, li->loose.positions,
			   3 * li->loose.nvertices * sizeof(float)) == 0);
	CHECK(!n || memcmp(loose.leaves.indices, li->loose.indices,
			   li->loose.nindices * sizeof(uint32_t)) == 0);
	tree_mesh_finish(&loose);
	free(rest.leaves);

	tree_mesh_init(&full);
	CHECK_INT(tree_mesh_build(&full, t), 0);
	CHECK_INT(full.leaves.nindices / 3, li->ntriangles + li->loose.nindices / 3);
	tree_mesh_finish(&full);
}

static void check_all(const struct leaf_instances *li, const struct tree *t)
{
	check_points(li, t);
	check_meshes(li, t);
}

/* 1 drawn leaf, turned copies (whorl-add x 3), scaled copies (fixed count onto 4
 * branches): 20 leaves, one shape. Then a different leaf: a shape of its own, merged. */
static void test_propagate_arrange(void)
{
	struct tree t;
	struct leaf_instances li;
	int s = build_branches(&t);
	int drawn;

	drawn = add_leaf(&t, s, 0.6, 0.06, 9, 0.6);
	for (int k = 0; k < 3; k++)
		CHECK_INT(arrange_apply(&t, s, ARRANGE_WHORL_ADD), 1);
	CHECK_INT(t.nleaves, 4);
	CHECK_INT(propagate_apply(&t, s, PROPAGATE_FIXED_COUNT), 16);
	CHECK_INT(t.nleaves, 20);

	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 1);
	CHECK_INT(li.ninstanced_shapes, 1);
	CHECK_INT(li.shapes[0].base, drawn);
	CHECK_INT(li.shapes[0].count, 20);
	CHECK(li.shapes[0].instanced);
	CHECK_INT(li.ninstances, 20);
	CHECK_INT(li.ninstanced, 20);
	CHECK_INT(li.loose.nindices, 0);
	/* in leaf order; the base is itself at M = I */
	for (size_t i = 0; i < 20; i++)
		CHECK_INT(li.instances[i].leaf, i);
	CHECK(li.instances[0].xf[0] == 1.0 && li.instances[0].xf[5] == 1.0 &&
	      li.instances[0].xf[10] == 1.0 && li.instances[0].xf[1] == 0.0);
	CHECK_INT(li.ntriangles, 20 * (li.shapes[0].mesh.nindices / 3));
	check_all(&li, &t);

	/* a leaf drawn by hand with the same number of points but lobed differently */
	add_leaf(&t, s, 0.3, 0.06, 9, 0.8);
	/* and one like the first but with a point more */
	add_leaf(&t, s, 0.8, 0.06, 10, 0.6);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 3);
	CHECK_INT(li.ninstanced_shapes, 1);
	CHECK_INT(li.shapes[0].count, 20);
	CHECK_INT(li.shapes[1].base, 20);
	CHECK_INT(li.shapes[1].count, 1);
	CHECK(!li.shapes[1].instanced);
	CHECK_INT(li.shapes[2].base, 21);
	CHECK(!li.shapes[2].instanced);
	CHECK_INT(li.ninstanced, 20);
	CHECK_INT(li.instances[20].leaf, 20);
	CHECK_INT(li.instances[21].leaf, 21);
	CHECK(li.loose.nindices > 0);
	check_all(&li, &t);

	leaf_instances_finish(&li);
	tree_finish(&t);
}

/* Leaves drawn by hand, none a copy: every one its own shape, none instanced, no loose
 * mesh built (it would be tree_mesh_build's). */
static void test_no_copies(void)
{
	struct tree t;
	struct leaf_instances li;
	int s = build_branches(&t);

	for (int k = 0; k < 6; k++)
		add_leaf(&t, s, 0.2 + 0.1 * k, 0.05, 7, 0.5 + 0.05 * k);
	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 6);
	CHECK_INT(li.ninstanced_shapes, 0);
	CHECK_INT(li.ninstanced, 0);
	CHECK_INT(li.ninstances, 6);
	CHECK_INT(li.loose.nindices, 0);
	CHECK_INT(li.ntriangles, 0);
	check_all(&li, &t);
	leaf_instances_finish(&li);
	tree_finish(&t);
}

/* Fixed size: unscaled copies, only those that fit; several source leaves, several
 * shapes, each with its copies. */
static void test_fixed_size(void)
{
	struct tree t;
	struct leaf_instances li;
	int s = build_branches(&t);
	int added;

	add_leaf(&t, s, 0.95, 0.05, 7, 0.6);
	add_leaf(&t, s, 0.7, 0.04, 7, 0.7);
	add_leaf(&t, s, 0.2, 0.05, 8, 0.6);
	added = propagate_apply(&t, s, PROPAGATE_FIXED_SIZE);
	CHECK(added >= 6);
	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 3);
	CHECK_INT(li.shapes[0].count + li.shapes[1].count + li.shapes[2].count, t.nleaves);
	for (size_t k = 0; k < 3; k++) {
		CHECK_INT(li.shapes[k].base, k);
		CHECK(li.shapes[k].count >= 2);
		CHECK(li.shapes[k].instanced);
	}
	/* the unscaled copies: M is a rotation */
	for (size_t i = 0; i < li.ninstances; i++) {
		const double *x = li.instances[i].xf;

		CHECK_NEAR(x[0] * x[0] + x[4] * x[4] + x[8] * x[8], 1.0, 1e-9);
	}
	check_all(&li, &t);
	/* propagating again copies copies: still the same shapes */
	CHECK(propagate_apply(&t, s, PROPAGATE_FIXED_COUNT) > 0);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 3);
	check_all(&li, &t);
	leaf_instances_finish(&li);
	tree_finish(&t);
}

/* Moved by a similarity by hand: a leaf in the picture plane (planar) matches its mirror
 * image turned over; one point moved by 1e-4 of the size does not match. */
static void test_by_hand(void)
{
	struct tree t;
	struct leaf_instances li;
	struct vec3 p[6] = { { 0, 0, 0 }, { 0.1, 0.02, 0 }, { 0.2, 0.01, 0 }, { 0.25, 0.05, 0 },
			     { 0.12, 0.09, 0 }, { 0.03, 0.04, 0 } };
	struct vec3 q[6];
	int b;

	tree_init(&t);
	b = add_bent(&t, -1, 0, vec3(0, 0, 0), vec3(0, 1, 0), vec3(0, 0, 0), 3.0, 4, 0.1);
	CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, p, 6) >= 0);
	/* mirrored in x and moved: in the plane a reflection, in space a half turn about y */
	for (int k = 0; k < 6; k++)
		q[k] = vec3(1.0 - p[k].x, 2.0 + p[k].y, 0);
	CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, q, 6) >= 0);
	/* scaled 2.5 times, turned 30 degrees about z, moved */
	for (int k = 0; k < 6; k++) {
		double c = cos(VEC_PI / 6), s = sin(VEC_PI / 6);

		q[k] = vec3(-1.0 + 2.5 * (c * p[k].x - s * p[k].y),
			    3.0 + 2.5 * (s * p[k].x + c * p[k].y), 0.5);
	}
	CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, q, 6) >= 0);
	/* stretched in x only: not similar */
	for (int k = 0; k < 6; k++)
		q[k] = vec3(1.5 * p[k].x, p[k].y + 1.0, 0);
	CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, q, 6) >= 0);
	/* one point off by 1e-4 of the size */
	memcpy(q, p, sizeof(q));
	for (int k = 0; k < 6; k++)
		q[k].y += 0.5;
	q[3].x += 1e-4 * 0.15;
	CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, q, 6) >= 0);
	/* the points in another order: not matched point for point */
	for (int k = 0; k < 6; k++)
		q[k] = vec3(p[(k + 1) % 6].x, p[(k + 1) % 6].y + 1.5, 0);
	CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, q, 6) >= 0);

	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 4);
	CHECK_INT(li.shapes[0].count, 3);
	CHECK_INT(li.shapes[1].base, 3);
	CHECK_INT(li.shapes[2].base, 4);
	CHECK_INT(li.shapes[3].base, 5);
	CHECK_INT(li.ninstanced, 3);
	/* the mirror image: M turns the leaf over (its z column points along -z) */
	CHECK_NEAR(li.instances[1].xf[10], -1.0, 1e-12);
	CHECK_NEAR(li.instances[2].xf[0], 2.5 * cos(VEC_PI / 6), 1e-12);
	check_all(&li, &t);
	leaf_instances_finish(&li);
	tree_finish(&t);
}

/* Leaves with no frame or no place: shapes of their own, merged like tree_mesh_build
 * merges them (which leaves them out). */
static void test_degenerate(void)
{
	struct tree t;
	struct leaf_instances li;
	struct vec3 line[4] = { { 0, 0, 0 }, { 1, 1, 0 }, { 2, 2, 0 }, { 3, 3, 0 } };
	struct vec3 two[2] = { { 0, 0, 0 }, { 1, 0, 0 } };
	struct vec3 bad[3] = { { 0, 0, 0 }, { NAN, 0, 0 }, { 0, 1, 0 } };
	struct vec3 same[3] = { { 1, 1, 1 }, { 1, 1, 1 }, { 1, 1, 1 } };
	int b;

	tree_init(&t);
	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes + li.ninstances + li.loose.nindices, 0);
	b = add_bent(&t, -1, 0, vec3(0, 0, 0), vec3(0, 1, 0), vec3(0, 0, 0), 3.0, 4, 0.1);
	for (int k = 0; k < 2; k++) {
		CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, line, 4) >= 0);
		CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, two, 2) >= 0);
		CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, bad, 3) >= 0);
		CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, same, 3) >= 0);
	}
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, 8);
	CHECK_INT(li.ninstanced, 0);
	CHECK_INT(li.loose.nindices, 0);
	for (size_t i = 0; i < li.nshapes; i++)
		CHECK_INT(li.instances[i].leaf, i);
	leaf_instances_finish(&li);
	tree_finish(&t);
}

/* More shapes with copies than LEAF_INSTANCES_MAX_SHAPES: those with the most copies
 * (ties: the earlier) are instanced, the rest merged. */
static void test_cap(void)
{
	const size_t nshapes = LEAF_INSTANCES_MAX_SHAPES + 10;
	struct tree t;
	struct leaf_instances li;
	int b;

	tree_init(&t);
	b = add_bent(&t, -1, 0, vec3(0, 0, 0), vec3(0, 1, 0), vec3(0, 0, 0), 3.0, 4, 0.1);
	for (size_t copy = 0; copy < 3; copy++) {
		for (size_t j = 0; j < nshapes; j++) {
			struct vec3 p[5];

			if (copy == 2 && j < LEAF_INSTANCES_MAX_SHAPES - 4)
				continue; /* the last 14 shapes get a third copy */
			for (int k = 0; k < 5; k++) {
				double a = 2.0 * VEC_PI * k / 5;
				double r = k == 2 ? 0.5 + 0.01 * (double)j : 1.0;

				p[k] = vec3(0.1 * (double)j + 0.2 * (double)copy + 0.1 * r * cos(a),
					    1.0 + 0.1 * r * sin(a), 0.3 * (double)copy);
			}
			CHECK(tree_add_leaf(&t, b, ORIGIN_SKETCH, p, 5) >= 0);
		}
	}
	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &t), 0);
	CHECK_INT(li.nshapes, nshapes);
	CHECK_INT(li.ninstanced_shapes, LEAF_INSTANCES_MAX_SHAPES);
	for (size_t j = 0; j < nshapes; j++) {
		bool third = j >= LEAF_INSTANCES_MAX_SHAPES - 4;

		CHECK_INT(li.shapes[j].count, third ? 3 : 2);
		/* 14 with three copies, then the first 50 with two */
		CHECK(li.shapes[j].instanced == (third || j < LEAF_INSTANCES_MAX_SHAPES - 14));
	}
	check_all(&li, &t);
	leaf_instances_finish(&li);
	tree_finish(&t);
}

static void test_determinism(void)
{
	struct tree t;
	struct leaf_instances a, b;
	int s = build_branches(&t);

	add_leaf(&t, s, 0.9, 0.05, 7, 0.6);
	add_leaf(&t, s, 0.5, 0.04, 7, 0.7);
	CHECK(propagate_apply(&t, s, PROPAGATE_FIXED_COUNT) > 0);
	leaf_instances_init(&a);
	leaf_instances_init(&b);
	CHECK_INT(leaf_instances_build(&a, &t), 0);
	/* built twice over the same scratch, and fresh */
	CHECK_INT(leaf_instances_build(&b, &t), 0);
	CHECK_INT(leaf_instances_build(&b, &t), 0);
	CHECK_INT(a.nshapes, b.nshapes);
	CHECK_INT(a.ninstances, b.ninstances);
	CHECK(memcmp(a.matrices, b.matrices, 12 * a.ninstances * sizeof(float)) == 0);
	for (size_t i = 0; i < a.ninstances; i++) {
		CHECK_INT(a.instances[i].leaf, b.instances[i].leaf);
		CHECK(memcmp(a.instances[i].xf, b.instances[i].xf, sizeof(a.instances[i].xf)) == 0);
	}
	for (size_t k = 0; k < a.nshapes; k++) {
		CHECK_INT(a.shapes[k].mesh.nindices, b.shapes[k].mesh.nindices);
		CHECK(memcmp(a.shapes[k].mesh.positions, b.shapes[k].mesh.positions,
			     3 * a.shapes[k].mesh.nvertices * sizeof(float)) == 0);
	}
	leaf_instances_finish(&a);
	leaf_instances_finish(&b);
	tree_finish(&t);
}

#if FAIL_ALLOC_HOOK /* allocation failures: not under sanitizers, which own malloc */
/* Each allocation of a build fails in turn, on a fresh li and on one built before:
 * -ENOMEM, li empty, nothing leaked; then the build gets through. */
static void test_oom(void)
{
	struct tree t;
	int s;

	if (!fail_alloc_hooked())
		return;
	s = build_branches(&t);
	add_leaf(&t, s, 0.9, 0.05, 7, 0.6);
	add_leaf(&t, s, 0.5, 0.04, 7, 0.7);
	CHECK(propagate_apply(&t, s, PROPAGATE_FIXED_COUNT) > 0);
	add_leaf(&t, s, 0.3, 0.04, 7, 0.9);
	for (int warm = 0; warm < 2; warm++) {
		for (long n = 0;; n++) {
			struct leaf_instances li;
			long before = fail_alloc_live();
			int r;

			leaf_instances_init(&li);
			if (warm)
				CHECK_INT(leaf_instances_build(&li, &t), 0);
			fail_alloc_at(n);
			r = leaf_instances_build(&li, &t);
			fail_alloc_off();
			if (r < 0) {
				CHECK_INT(r, -ENOMEM);
				CHECK_INT(li.nshapes + li.ninstances + li.ninstanced, 0);
				CHECK_INT(li.loose.nindices, 0);
			}
			leaf_instances_finish(&li);
			CHECK_INT(fail_alloc_live(), before);
			if (fail_alloc_calls() <= n) {
				CHECK_INT(r, 0);
				break;
			}
		}
	}
	tree_finish(&t);
}
#else
static void test_oom(void)
{
}
#endif

int main(void)
{
	test_propagate_arrange();
	test_fixed_size();
	test_no_copies();
	test_by_hand();
	test_degenerate();
	test_cap();
	test_determinism();
	test_oom();
	return 0;
}
