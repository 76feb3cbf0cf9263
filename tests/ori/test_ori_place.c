/* SPDX-License-Identifier: MIT */
/* Origami leaves placed in the frame of an outline (ori_place.c), their frame found
 * again from their points (ori_kinds.c), meshed as faces (mesh.c), kept by propagation. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "mesh.h"
#include "ori_outline.h"
#include "ori_kinds.h"
#include "ori_place.h"
#include "propagate.h"
#include "test.h"
#include "tree.h"

/* An oval outline of length len from base along axis a, its width along w. */
static size_t oval(struct vec3 base, struct vec3 a, struct vec3 w, double len, struct vec3 *out)
{
	size_t n = 0;

	out[n++] = base;
	for (int i = 1; i <= 7; i++) {
		double x = i / 8.0;

		out[n++] = vec3_add(base, vec3_add(vec3_scale(a, len * x),
						   vec3_scale(w, -0.3 * len * sin(VEC_PI * x))));
	}
	out[n++] = vec3_add(base, vec3_scale(a, len));
	for (int i = 7; i >= 1; i--) {
		double x = i / 8.0;

		out[n++] = vec3_add(base, vec3_add(vec3_scale(a, len * x),
						   vec3_scale(w, 0.3 * len * sin(VEC_PI * x))));
	}
	return n;
}

static void test_names(void)
{
	int k = 99;

	CHECK(ori_kind_from_name("drawn", &k) && k == ORI_KIND_DRAWN);
	CHECK(ori_kind_from_name("maple", &k) && k == ORI_KIND_MAPLE);
	CHECK(ori_kind_from_name("hop", &k) && k == ORI_KIND_HOP);
	CHECK(ori_kind_from_name("entire", &k) && k == ORI_KIND_ENTIRE);
	CHECK(!ori_kind_from_name("ginkgo", &k));
	CHECK(ori_kind_name(ORI_KIND_COUNT) == NULL);
	CHECK(ori_kind_get(ORI_KIND_DRAWN) == NULL);
	for (int i = 0; i < ORI_KIND_COUNT; i++) {
		const struct ori_kind *o = ori_kind_get(i);

		CHECK(o != NULL);
		CHECK(o == ori_kind_get(i)); /* built once */
		CHECK(o->ntriangles == ori_mesh_triangles(&o->leaf));
	}
}

static void test_place(void)
{
	/* an outline in a tilted plane: axis a, width w, its front a x w */
	struct vec3 a = vec3_norm_or(vec3(1, 2, 0.5), vec3(0, 1, 0));
	struct vec3 w = vec3_norm_or(vec3_cross(vec3(0, 0, 1), a), vec3(1, 0, 0));
	struct vec3 base = vec3(0.3, 1.2, -0.4), pts[32], *out;
	struct vec3 nrm = vec3_cross(a, w);
	const struct ori_kind *k = ori_kind_get(ORI_KIND_MAPLE);
	double xf[12], back[12], len = 0.2;
	size_t n = oval(base, a, w, len, pts), nout;

	CHECK_INT(ori_place(k, pts, n, vec3_add(base, vec3(0.001, 0, 0)), xf), 0);
	/* O on the base, +y along the axis scaled to the length, +z along the normal */
	{
		const double o[3] = { 0, 0, 0 }, tip[3] = { 0, k->leaf.size, 0 },
			     up[3] = { 0, 0, k->leaf.size };
		struct vec3 p0 = ori_xf_apply(xf, o), pt = ori_xf_apply(xf, tip),
			    pz = vec3_sub(ori_xf_apply(xf, up), p0);

		CHECK_NEAR(vec3_dist(p0, base), 0.0, 1e-12);
		CHECK_NEAR(vec3_dist(pt, vec3_add(base, vec3_scale(a, len))), 0.0, 1e-12);
		CHECK_NEAR(vec3_dot(vec3_scale(pz, 1.0 / len), nrm), 1.0, 1e-9);
	}
	/* the new outline is the margin at rest, and gives its frame back */
	CHECK_INT(ori_place_outline(ORI_KIND_MAPLE, pts, n, base, &out, &nout), 0);
	CHECK_INT(nout, k->leaf.nmargin);
	CHECK(ori_kind_frame(k, out, nout, back));
	for (int i = 0; i < 12; i++)
		CHECK_NEAR(back[i], xf[i], 1e-12);
	free(out);
	/* the base is the point nearest the attachment: the tip end here */
	CHECK_INT(ori_place(k, pts, n, vec3_add(base, vec3_scale(a, len)), xf), 0);
	CHECK_NEAR(xf[3], base.x + a.x * len, 1e-12);
	/* no frame: too few points, a line, not finite; no such kind */
	CHECK_INT(ori_place(k, pts, 2, base, xf), -EINVAL);
	{
		struct vec3 line[3] = { vec3(0, 0, 0), vec3(1, 0, 0), vec3(2, 0, 0) };

		CHECK_INT(ori_place(k, line, 3, base, xf), -EINVAL);
		line[1].y = NAN;
		CHECK_INT(ori_place(k, line, 3, base, xf), -EINVAL);
	}
	CHECK_INT(ori_place_outline(ORI_KIND_DRAWN, pts, n, base, &out, &nout), -EINVAL);
	CHECK(out == NULL);
}

/* A leaf of each kind meshes as its faces; an outline stays a triangulated polygon. */
static void test_mesh(void)
{
	for (int kind = 0; kind < ORI_KIND_COUNT; kind++) {
		const struct ori_kind *k = ori_kind_get(kind);
		struct vec3 pts[32], *out;
		struct tree t;
		struct tree_mesh tm;
		size_t n = oval(vec3(0, 1, 0), vec3(0, 1, 0), vec3(1, 0, 0), 0.1, pts), nout;
		const struct vec3 trunk[2] = { vec3(0, 0, 0), vec3(0, 1, 0) };
		const double radii[2] = { 0.05, 0.04 };

		tree_init(&t);
		tree_mesh_init(&tm);
		CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, radii, 2), 0);
		CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, pts, n), 0);
		CHECK_INT(t.leaves[0].kind, ORI_KIND_DRAWN);
		t.leaves[0].branch_t = 1.0;
		CHECK_INT(ori_place_leaf(&t, 0, kind), 0);
		CHECK_INT(t.leaves[0].kind, kind);
		CHECK_INT(t.leaves[0].npoints, k->leaf.nmargin);
		CHECK(t.leaves[0].local != NULL);
		/* placing it again as its own kind changes nothing */
		CHECK_INT(ori_place_outline(kind, t.leaves[0].points, t.leaves[0].npoints,
					    vec3(0, 1, 0), &out, &nout), 0);
		free(out);
		CHECK_INT(tree_mesh_build(&tm, &t), 0);
		CHECK_INT(tm.leaves.nindices / 3, k->ntriangles);
		{
			size_t nv = 0;

			for (size_t f = 0; f < k->leaf.nfaces; f++)
				nv += k->leaf.face_len[f];
			CHECK_INT(tm.leaves.nvertices, nv); /* each face its own: flat shading */
		}
		tree_mesh_finish(&tm);
		tree_finish(&t);
	}
}

/* Propagation with a kind chosen places that kind, and copies of it stay it. */
static void test_propagate(void)
{
	struct tree t;
	const struct vec3 trunk[2] = { vec3(0, 0, 0), vec3(0, 3, 0) };
	const double radii[2] = { 0.1, 0.05 };
	struct vec3 pts[32];
	size_t n;
	int added;

	tree_init(&t);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, radii, 2), 0);
	for (int i = 0; i < 4; i++) {
		double y = 0.8 + 0.5 * i;
		const struct vec3 b[2] = { vec3(0, y, 0), vec3(i % 2 ? 1 : -1, y + 0.5, 0) };
		const double r[2] = { 0.03, 0.01 };

		CHECK(tree_add_branch(&t, 0, y / 3.0, ORIGIN_SKETCH, b, r, 2) > 0);
	}
	n = oval(t.branches[1].points[1], vec3(-1, 0.5, 0), vec3(0, 0, 1), 0.15, pts);
	CHECK_INT(tree_add_leaf(&t, 1, ORIGIN_SKETCH, pts, n), 0);
	t.leaves[0].branch_t = 1.0;
	t.leaf_kind = ORI_KIND_HOP;
	added = propagate_apply(&t, 1, PROPAGATE_FIXED_COUNT);
	CHECK(added == 3);
	CHECK_INT(t.leaves[0].kind, ORI_KIND_DRAWN); /* the example stays the visitor's */
	for (size_t i = 1; i < t.nleaves; i++) {
		CHECK_INT(t.leaves[i].kind, ORI_KIND_HOP);
		CHECK_INT(t.leaves[i].npoints, ori_kind_get(ORI_KIND_HOP)->leaf.nmargin);
	}
	/* a copy of a copy is the same kind; a tree copy keeps kinds and the choice */
	{
		struct tree c;

		tree_init(&c);
		CHECK_INT(tree_copy(&c, &t), 0);
		CHECK_INT(c.leaf_kind, ORI_KIND_HOP);
		for (size_t i = 0; i < t.nleaves; i++)
			CHECK_INT(c.leaves[i].kind, t.leaves[i].kind);
		tree_finish(&c);
	}
	tree_finish(&t);
}

/* A placed leaf's outline measured (ori_outline.h): the kind's issue-24 shape, wherever and
 * however large it is placed. Returns the measure's least slack. */
static double check_shape(const struct leaf *lf)
{
	double (*p)[3] = calloc(lf->npoints, sizeof(*p)), margin = 0;
	struct ori_outline m;
	char why[160] = "";
	bool ok;

	CHECK(p != NULL);
	for (size_t i = 0; i < lf->npoints; i++) {
		p[i][0] = lf->points[i].x;
		p[i][1] = lf->points[i].y;
		p[i][2] = lf->points[i].z;
	}
	CHECK_INT(ori_outline_measure((const double(*)[3])p, lf->npoints, &m), 0);
	ok = lf->kind == ORI_KIND_MAPLE ? ori_outline_momiji(&m, &margin, why, sizeof(why)) :
					  ori_outline_hop(&m, &margin, why, sizeof(why));
	if (!ok)
		fprintf(stderr, "%s leaf: %s\n", ori_kind_name(lf->kind), why);
	CHECK(ok);
	free(p);
	return margin;
}

/* Issue 24: maple and hop leaves placed on a tree keep their shape: on outlines of every
 * size and turn (ori_place_leaf), and propagated across a tree. */
static void test_placed_shape(void)
{
	static const int kinds[] = { ORI_KIND_MAPLE, ORI_KIND_HOP };
	double worst = INFINITY;
	size_t placed = 0;

	for (size_t ki = 0; ki < 2; ki++)
		for (int i = 0; i < 40; i++) {
			double a = 0.37 * i, b = 0.53 * i, len = 0.03 + 0.01 * (i % 25);
			struct vec3 ax = vec3_norm_or(vec3(cos(a) * sin(b), cos(b), sin(a) * sin(b)),
						      vec3(0, 1, 0));
			struct vec3 w = vec3_norm_or(vec3_cross(vec3(0.3, 0.2, 1), ax), vec3(1, 0, 0));
			struct vec3 base = vec3(0.1 * i, 1 + 0.05 * i, -0.02 * i), pts[32];
			const struct vec3 trunk[2] = { vec3(0, 0, 0), base };
			const double radii[2] = { 0.05, 0.04 };
			size_t n = oval(base, ax, w, len, pts);
			struct tree t;

			tree_init(&t);
			CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, radii, 2), 0);
			CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, pts, n), 0);
			t.leaves[0].branch_t = 1.0;
			CHECK_INT(ori_place_leaf(&t, 0, kinds[ki]), 0);
			worst = fmin(worst, check_shape(&t.leaves[0]));
			placed++;
			tree_finish(&t);
		}
	for (size_t ki = 0; ki < 2; ki++) {
		struct tree t;
		const struct vec3 trunk[2] = { vec3(0, 0, 0), vec3(0, 3, 0) };
		const double radii[2] = { 0.1, 0.05 };
		struct vec3 pts[32];
		size_t n;

		tree_init(&t);
		CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, radii, 2), 0);
		for (int i = 0; i < 6; i++) {
			double y = 0.6 + 0.4 * i;
			const struct vec3 b[2] = { vec3(0, y, 0),
						   vec3(i % 2 ? 1 : -1, y + 0.5, 0.3 * (i % 3 - 1)) };
			const double r[2] = { 0.03, 0.01 };

			CHECK(tree_add_branch(&t, 0, y / 3.0, ORIGIN_SKETCH, b, r, 2) > 0);
		}
		n = oval(t.branches[1].points[1], vec3(-1, 0.5, 0.2), vec3(0, 0, 1), 0.12, pts);
		CHECK_INT(tree_add_leaf(&t, 1, ORIGIN_SKETCH, pts, n), 0);
		t.leaves[0].branch_t = 1.0;
		t.leaf_kind = kinds[ki];
		CHECK(propagate_apply(&t, 1, PROPAGATE_FIXED_COUNT) > 0);
		for (size_t i = 1; i < t.nleaves; i++) {
			CHECK_INT(t.leaves[i].kind, kinds[ki]);
			worst = fmin(worst, check_shape(&t.leaves[i]));
			placed++;
		}
		tree_finish(&t);
	}
	printf("placed maple and hop leaves: %zu measured, least slack %.3f\n", placed, worst);
}

int main(void)
{
	test_names();
	test_place();
	test_mesh();
	test_propagate();
	test_placed_shape();
	ori_kinds_release();
	return 0;
}
