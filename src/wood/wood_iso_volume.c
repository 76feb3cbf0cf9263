// SPDX-License-Identifier: MIT
/*
 * The bark as much as the wood (issue 17, docs/wood.md "Step 7"): marching tetrahedra
 * put the vertices on the iso-surface but the triangles between them are chords, inside
 * a convex surface by its curvature times the square of the edge over 8: a branch of 1.5
 * voxels loses about a tenth of its wood, a trunk of 10 voxels under 1%. Each vertex
 * moves along its normal by its own sag (mean curvature from the normals about it, times
 * its edges' squared length over 8), all by one factor fitted so that the volume is the
 * wood's: 4 to 5 on the bench's zelkova and the tests' trunks (the tetrahedra's diagonal
 * edges are longer than the mesh's, and the rays' density has a bias of its own), moving
 * no vertex more than a third of a voxel.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood.h"

/* no vertex moves farther than this (voxels): the chords' sag is a tenth for the
 * thinnest branch, so more would be a fit gone wrong */
#define VOLUME_MAX_MOVE 0.35

static struct vec3 vpos(const struct mesh *m, uint32_t v)
{
	return vec3(m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]);
}

static struct vec3 vnrm(const struct mesh *m, uint32_t v)
{
	return vec3(m->normals[3 * v], m->normals[3 * v + 1], m->normals[3 * v + 2]);
}

static double volume_of(const struct mesh *m, size_t first_index)
{
	double v = 0.0;

	for (size_t t = first_index; t < m->nindices; t += 3) {
		const uint32_t *i = m->indices + t;

		v += vec3_dot(vpos(m, i[0]), vec3_cross(vpos(m, i[1]), vpos(m, i[2])));
	}
	return v / 6.0;
}

/* Per vertex: w, its sag (m, signed: convex out), and a, the volume one metre along its
 * normal sweeps (a third of its faces' area, along the normal). */
static void sag_and_area(const struct mesh *m, size_t first, size_t first_index, double *w,
			 double *a, double *len2, int *edges)
{
	size_t n = m->nvertices - first;

	memset(w, 0, n * sizeof(*w));
	memset(a, 0, n * sizeof(*a));
	memset(len2, 0, n * sizeof(*len2));
	memset(edges, 0, n * sizeof(*edges));
	for (size_t t = first_index; t < m->nindices; t += 3) {
		const uint32_t *i = m->indices + t;
		struct vec3 p[3], f;

		for (int k = 0; k < 3; k++)
			p[k] = vpos(m, i[k]);
		f = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		for (int k = 0; k < 3; k++) {
			uint32_t u = i[k], v = i[(k + 1) % 3];
			struct vec3 d = vec3_sub(p[(k + 1) % 3], p[k]);
			double l2 = vec3_dot(d, d);
			/* the normal's turn along the edge: its curvature in that direction */
			double kappa = l2 > 0.0 ? vec3_dot(vec3_sub(vnrm(m, v), vnrm(m, u)), d) / l2 : 0;

			a[u - first] += vec3_dot(f, vnrm(m, u)) / 6.0;
			/* each edge twice (once each way, in its two faces), at both ends */
			w[u - first] += kappa;
			w[v - first] += kappa;
			len2[u - first] += l2;
			len2[v - first] += l2;
			edges[u - first]++;
			edges[v - first]++;
		}
	}
	for (size_t i = 0; i < n; i++)
		if (edges[i]) {
			double k = w[i] / edges[i], l2 = len2[i] / edges[i];

			w[i] = k * l2 / 8.0;
		}
}

/* Whether face t still faces the way it did (its normal f0) with some area. */
static bool face_ok(const struct mesh *m, size_t t, struct vec3 f0, double min_area2)
{
	const uint32_t *i = m->indices + t;
	struct vec3 p0 = vpos(m, i[0]);
	struct vec3 f = vec3_cross(vec3_sub(vpos(m, i[1]), p0), vec3_sub(vpos(m, i[2]), p0));

	return vec3_dot(f, f0) > 0.0 && vec3_dot(f, f) > min_area2;
}

int wood_iso_keep_volume(struct mesh *m, size_t first, size_t first_index, double wood,
			 double h)
{
	size_t n = m->nvertices - first, nf = (m->nindices - first_index) / 3;
	double *w = malloc((n + 1) * sizeof(*w)), *a = malloc((n + 1) * sizeof(*a));
	double *len2 = malloc((n + 1) * sizeof(*len2));
	int *edges = malloc((n + 1) * sizeof(*edges));
	float *orig = malloc((3 * n + 1) * sizeof(*orig));
	struct vec3 *f0 = malloc((nf + 1) * sizeof(*f0));
	double swept = 0.0, k, max_move = VOLUME_MAX_MOVE * h;
	const double min_area2 = 4e-24 * h * h * h * h; /* 1e-12 h^2, doubled, squared */
	int ret = 0;

	if (!w || !a || !len2 || !edges || !orig || !f0) {
		ret = -ENOMEM;
		goto out;
	}
	if (n == 0 || !(wood > 0.0))
		goto out;
	memcpy(orig, m->positions + 3 * first, 3 * n * sizeof(*orig));
	for (size_t t = 0; t < nf; t++) {
		const uint32_t *i = m->indices + first_index + 3 * t;
		struct vec3 p0 = vpos(m, i[0]);

		f0[t] = vec3_cross(vec3_sub(vpos(m, i[1]), p0), vec3_sub(vpos(m, i[2]), p0));
	}
	sag_and_area(m, first, first_index, w, a, len2, edges);
	for (size_t i = 0; i < n; i++)
		swept += w[i] * a[i];
	/* a surface without sag anywhere (flat faces only) has nothing to give back */
	if (!(fabs(swept) > 0.0))
		goto out;
	k = (wood - volume_of(m, first_index)) / swept;
	if (!isfinite(k) || k <= 0.0)
		goto out;
	for (size_t i = 0; i < n; i++) {
		double d = fmax(-max_move, fmin(max_move, k * w[i]));

		struct vec3 nv = vnrm(m, (uint32_t)(first + i));

		for (int c = 0; c < 3; c++)
			m->positions[3 * (first + i) + c] =
				(float)(orig[3 * i + c] + d * (c == 0 ? nv.x : c == 1 ? nv.y : nv.z));
	}
	/* where a face would turn over or vanish (a tight crotch), its corners stay put */
	for (int pass = 0; pass < 4; pass++) {
		bool moved = false;

		for (size_t t = 0; t < nf; t++) {
			const uint32_t *i = m->indices + first_index + 3 * t;

			if (face_ok(m, first_index + 3 * t, f0[t], min_area2))
				continue;
			for (int c = 0; c < 3; c++)
				memcpy(m->positions + 3 * i[c], orig + 3 * (i[c] - first),
				       3 * sizeof(*orig));
			moved = true;
		}
		if (!moved)
			break;
		if (pass == 3) /* still turning over: better the chords than a broken bark */
			memcpy(m->positions + 3 * first, orig, 3 * n * sizeof(*orig));
	}
out:
	free(w);
	free(a);
	free(len2);
	free(edges);
	free(orig);
	free(f0);
	return ret;
}
