/* SPDX-License-Identifier: MIT */
/* Binding a mesh's vertices to the skeleton: struct live_attrs (live.h). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "live_private.h"

void live_attrs_init(struct live_attrs *a)
{
	memset(a, 0, sizeof(*a));
}

void live_attrs_finish(struct live_attrs *a)
{
	free(a->v);
	live_attrs_init(a);
}

/* Room for n vertices, a->n = n. 0 or -ENOMEM (a then empty). */
static int attrs_size(struct live_attrs *a, size_t n)
{
	if (n > a->cap) {
		struct live_vertex *v;

		if (n > SIZE_MAX / sizeof(*v))
			return -ENOMEM;
		v = realloc(a->v, n * sizeof(*v));
		if (!v) {
			live_attrs_finish(a);
			return -ENOMEM;
		}
		a->v = v;
		a->cap = n;
	}
	a->n = n;
	return 0;
}

static struct vec3 vertex_at(const struct mesh *m, size_t i)
{
	const float *p = &m->positions[3 * i];

	return vec3(p[0], p[1], p[2]);
}

/*
 * Where each element's vertices begin, [0..n] (n + 1 entries, malloc'ed): mk's when it
 * describes this mesh, else counted by meshing the elements alone (tree_mesh_build_parts:
 * each part has the vertices a full build gives it). 0, -EINVAL or -ENOMEM.
 */
static int ranges(const struct tree *t, const struct mesh *m, const struct tree_mesh_marks *mk,
		  bool leaves, size_t **out)
{
	size_t n = leaves ? t->nleaves : t->nbranches;
	size_t *r = malloc((n + 1) * sizeof(*r));
	const struct tree_mesh_mark *marks = NULL;
	struct tree_mesh parts;
	struct tree_mesh_marks pmk;
	size_t *ids = NULL;
	int ret = 0;

	*out = NULL;
	if (!r)
		return -ENOMEM;
	if (mk && (leaves ? mk->nleaves : mk->nbark) == n + 1) {
		marks = leaves ? mk->leaves : mk->bark;
		for (size_t i = 0; i <= n; i++)
			r[i] = marks[i].nvertices;
	} else if (mk && (leaves ? mk->nleaves : mk->nbark) != 0) {
		free(r);
		return -EINVAL; /* marks of another tree */
	} else {
		tree_mesh_init(&parts);
		tree_mesh_marks_init(&pmk);
		ids = malloc((n ? n : 1) * sizeof(*ids));
		if (!ids)
			ret = -ENOMEM;
		for (size_t i = 0; ids && i < n; i++)
			ids[i] = i;
		if (ret == 0)
			ret = leaves ? tree_mesh_build_parts(&parts, &pmk, t, NULL, 0, ids, n)
				     : tree_mesh_build_parts(&parts, &pmk, t, ids, n, NULL, 0);
		if (ret == 0 && (leaves ? pmk.nleaves : pmk.nbark) != n + 1)
			ret = -ENOMEM; /* the parts' marks could not be kept */
		for (size_t i = 0; ret == 0 && i <= n; i++)
			r[i] = (leaves ? pmk.leaves : pmk.bark)[i].nvertices;
		free(ids);
		tree_mesh_marks_finish(&pmk);
		tree_mesh_finish(&parts);
	}
	if (ret == 0 && (r[0] != 0 || r[n] != m->nvertices))
		ret = -EINVAL;
	for (size_t i = 0; ret == 0 && i < n; i++)
		if (r[i] > r[i + 1])
			ret = -EINVAL;
	if (ret < 0) {
		free(r);
		return ret;
	}
	*out = r;
	return 0;
}

static bool skeleton_of(const struct live_skeleton *sk, const struct tree *t)
{
	return sk->nbranches == t->nbranches && sk->nleaves == t->nleaves;
}

/*
 * The arc length on branch b of the skeleton point vertex v moves with: v projected onto
 * the polyline, then snapped to the point whose ring v is on (|v - p_i| = r_i within
 * LIVE_RING_SNAP r_i, p_i within a radius of the projection along the branch), so a ring
 * moves rigidly even where the branch bends.
 */
static double bark_arc(const struct live_skeleton *sk, const struct branch *b, size_t id,
		       struct vec3 v)
{
	const double *arc = &sk->arc[sk->branches[id].first];
	double best = INFINITY, s = 0.0, snap_err = INFINITY, snapped = -1.0;
	size_t seg = 0;

	if (b->npoints < 2)
		return 0.0;
	for (size_t j = 0; j + 1 < b->npoints; j++) {
		struct vec3 e = vec3_sub(b->points[j + 1], b->points[j]), d = vec3_sub(v, b->points[j]);
		double ee = vec3_dot(e, e), f = ee > 0 ? vec3_dot(d, e) / ee : 0.0, d2;

		f = f > 0 ? (f < 1 ? f : 1.0) : 0.0;
		d = vec3_sub(d, vec3_scale(e, f));
		d2 = vec3_dot(d, d);
		if (d2 < best) {
			best = d2;
			seg = j;
			s = arc[j] + f * (arc[j + 1] - arc[j]);
		}
	}
	for (size_t i = seg > 0 ? seg - 1 : 0; i < b->npoints && i <= seg + 2; i++) {
		double r = b->radii ? b->radii[i] : 0.0;
		double err = fabs(vec3_dist(v, b->points[i]) - r);

		/* float positions: a micrometre of rounding on a tree of metres */
		if (r > 0 && fabs(arc[i] - s) <= r && err <= LIVE_RING_SNAP * r + 1e-6 && err < snap_err) {
			snap_err = err;
			snapped = arc[i];
		}
	}
	return snapped >= 0 ? snapped : s;
}

int live_attrs_bind_bark(struct live_attrs *a, const struct live_skeleton *sk, const struct tree *t,
			 const struct mesh *bark, const struct tree_mesh_marks *mk)
{
	size_t *r;
	int ret;

	if (!skeleton_of(sk, t))
		return -EINVAL;
	ret = ranges(t, bark, mk, false, &r);
	if (ret < 0)
		return ret;
	ret = attrs_size(a, bark->nvertices);
	for (size_t b = 0; ret == 0 && b < t->nbranches; b++)
		for (size_t i = r[b]; i < r[b + 1]; i++)
			live_skeleton_vertex(sk, t, b, bark_arc(sk, &t->branches[b], b, vertex_at(bark, i)),
					     &a->v[i]);
	free(r);
	return ret;
}

/* The mean of vertices [v0, v1)'s normals: the leaf's facing, folds and all. */
static struct vec3 mean_normal(const struct mesh *m, size_t v0, size_t v1)
{
	struct vec3 n = vec3(0, 0, 0);

	for (size_t i = v0; i < v1; i++)
		n = vec3_add(n, vec3(m->normals[3 * i], m->normals[3 * i + 1], m->normals[3 * i + 2]));
	return vec3_norm_or(n, vec3(0, 0, 0));
}

int live_attrs_bind_leaves(struct live_attrs *a, const struct live_skeleton *sk,
			   const struct tree *t, const struct mesh *leaves,
			   const struct tree_mesh_marks *mk)
{
	struct live_grid g = { 0 };
	bool grid = false;
	size_t *r;
	int ret;

	if (!skeleton_of(sk, t))
		return -EINVAL;
	ret = ranges(t, leaves, mk, true, &r);
	if (ret < 0)
		return ret;
	ret = attrs_size(a, leaves->nvertices);
	for (size_t l = 0; ret == 0 && l < t->nleaves; l++) {
		struct live_vertex anchor;
		struct vec3 at, n;

		if (r[l] == r[l + 1])
			continue;
		n = mean_normal(leaves, r[l], r[l + 1]);
		if (!live_skeleton_leaf(sk, t, l, n, &anchor)) {
			/* a leaf on no branch: on the skeleton point nearest its first vertex */
			size_t b;
			double s;

			if (!grid) {
				ret = live_grid_build(&g, sk, t);
				if (ret < 0)
					break;
				grid = true;
			}
			live_grid_nearest(&g, vertex_at(leaves, r[l]), &b, &s);
			live_skeleton_vertex(sk, t, b, s, &anchor);
			anchor.phase[0] = sk->leaf_phase[l];
			live_snorm(n, anchor.flutter);
		}
		at = vec3(anchor.point[0], anchor.point[1], anchor.point[2]);
		for (size_t i = r[l]; i < r[l + 1]; i++) {
			a->v[i] = anchor;
			a->v[i].leaf = (float)vec3_dist(vertex_at(leaves, i), at);
		}
	}
	if (grid)
		live_grid_finish(&g);
	free(r);
	if (ret < 0)
		live_attrs_finish(a);
	return ret;
}

int live_attrs_bind_nearest(struct live_attrs *a, const struct live_skeleton *sk,
			    const struct tree *t, const struct mesh *m)
{
	struct live_grid g;
	int ret;

	if (!skeleton_of(sk, t))
		return -EINVAL;
	if (m->nvertices == 0)
		return attrs_size(a, 0);
	ret = live_grid_build(&g, sk, t);
	if (ret < 0)
		return ret;
	ret = attrs_size(a, m->nvertices);
	for (size_t i = 0; ret == 0 && i < m->nvertices; i++) {
		size_t b;
		double s;

		live_grid_nearest(&g, vertex_at(m, i), &b, &s);
		live_skeleton_vertex(sk, t, b, s, &a->v[i]);
	}
	live_grid_finish(&g);
	return ret;
}
