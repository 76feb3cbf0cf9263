/* SPDX-License-Identifier: MIT */
/*
 * Step 7 of growing wood (wood.h, docs/wood.md): the bark as the iso-surface of the
 * density by Doi's method, marching tetrahedra. The samples are the voxels' centres,
 * padded by one layer of zeros on every side so that the surface always closes. Each
 * cube of 8 neighbouring samples is split into the same 6 tetrahedra (Kuhn's split along
 * its diagonal from the lowest corner to the highest), so every edge of every tetrahedron
 * joins a sample P to P + d, d one of the 7 non-zero 0/1 vectors, and the cubes' faces
 * are split alike on both sides: the surface is watertight with one vertex an edge.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood.h"

/* An edge's crossing stays this fraction of its length away from either end: a sample
 * exactly at the iso value (inside, as >= iso) would otherwise put the vertices of
 * several edges on that sample, and their triangles would have no area. 1e-3 rather than
 * less, as positions are floats: a float keeps 1e-3 voxel apart up to some 8,000 voxels
 * from the world's origin (its relative step is 1.2e-7), and the surface moves by no
 * more than that. */
#define ISO_EPS 1e-3
/* A gradient (density change a voxel) below this has vanished: the faces' normals then. */
#define ISO_GRAD_MIN 1e-9
/* Directions from a sample to the other end of its edges: bit 0 x, bit 1 y, bit 2 z. */
#define ISO_DIRS 7
/* Most new vertices and indices a cube can make: 19 edges, 6 tetrahedra of 2 triangles. */
#define ISO_CUBE_VERTICES 19
#define ISO_CUBE_INDICES 36
#define ISO_NONE UINT32_MAX

/* Kuhn's 6 tetrahedra of the unit cube: corners as bit masks (x 1, y 2, z 4), each a
 * path from corner 0 to corner 7 along one axis at a time (one permutation each). */
static const uint8_t iso_tets[6][4] = {
	{ 0, 1, 3, 7 }, { 0, 1, 5, 7 }, { 0, 2, 3, 7 },
	{ 0, 2, 6, 7 }, { 0, 4, 5, 7 }, { 0, 4, 6, 7 },
};

struct iso {
	const struct wood_grid *g;
	double iso;
	struct mesh *out;
	int sx, sy, sz;     /* padded samples along each axis: the grid's + 2 */
	uint32_t *lo, *hi;  /* the vertex on each edge (ISO_DIRS a sample) of two slabs */
	double *below, *above; /* sample layers k and k + 1, padded: sx * sy values each */
	int k;              /* the layer of cubes being marched: samples k and k + 1 */
};

/* The density at padded sample (i, j, k), voxel (i - 1, j - 1, k - 1); 0 outside. */
static double iso_sample(const struct wood_grid *g, int i, int j, int k)
{
	if (i < 1 || j < 1 || k < 1 || i > g->nx || j > g->ny || k > g->nz)
		return 0.0;
	return g->density[wood_index(g, i - 1, j - 1, k - 1)];
}

/* Where along an edge from a to b the field crosses iso, kept within [ISO_EPS,
 * 1 - ISO_EPS]; a and b lie on either side, so b != a (NaN goes to an end). */
static double iso_edge_t(double a, double b, double iso)
{
	double t = (iso - a) / (b - a);

	if (!(t > ISO_EPS))
		t = ISO_EPS;
	if (!(t < 1.0 - ISO_EPS))
		t = 1.0 - ISO_EPS;
	return t;
}

/*
 * The density's gradient at a sample (density a voxel): central differences, each
 * averaged over the 3 x 3 samples across it with weights 1 2 1 (Sobel's, or Zucker and
 * Hummel's, smoothing). Plain central differences on the voxelised wood's one-voxel
 * ramp, clamped at 0 and 1, leave a ball's normals 7 degrees from radial on average and
 * 20 at worst; smoothed, 1.4 and 4.4 (tests/wood/test_wood_iso.c).
 */
static const double iso_smooth[3] = { 0.25, 0.5, 0.25 };

/* The same away from the grid's sides: p the sample's density, sy and sz the strides. */
static struct vec3 iso_gradient_inner(const double *p, ptrdiff_t sy, ptrdiff_t sz)
{
	struct vec3 d = vec3(0, 0, 0);

	for (int a = -1; a <= 1; a++)
		for (int b = -1; b <= 1; b++) {
			double ab = 0.5 * iso_smooth[a + 1] * iso_smooth[b + 1];

			d.x += ab * (p[1 + a * sy + b * sz] - p[-1 + a * sy + b * sz]);
			d.y += ab * (p[a + sy + b * sz] - p[a - sy + b * sz]);
			d.z += ab * (p[a + b * sy + sz] - p[a + b * sy - sz]);
		}
	return d;
}

static struct vec3 iso_gradient(const struct wood_grid *g, int i, int j, int k)
{
	struct vec3 d = vec3(0, 0, 0);

	if (i > 1 && j > 1 && k > 1 && i < g->nx && j < g->ny && k < g->nz)
		return iso_gradient_inner(g->density + wood_index(g, i - 1, j - 1, k - 1), g->nx,
					  (ptrdiff_t)g->nx * g->ny);
	for (int a = -1; a <= 1; a++)
		for (int b = -1; b <= 1; b++) {
			double ab = 0.5 * iso_smooth[a + 1] * iso_smooth[b + 1];

			d.x += ab * (iso_sample(g, i + 1, j + a, k + b) -
				     iso_sample(g, i - 1, j + a, k + b));
			d.y += ab * (iso_sample(g, i + a, j + 1, k + b) -
				     iso_sample(g, i + a, j - 1, k + b));
			d.z += ab * (iso_sample(g, i + a, j + b, k + 1) -
				     iso_sample(g, i + a, j + b, k - 1));
		}
	return d;
}

static struct vec3 iso_corner(int m)
{
	return vec3(m & 1, (m >> 1) & 1, (m >> 2) & 1);
}

/* The smooth normal where the edge from sample p (padded indices) along d is crossed at
 * t: minus the gradient, interpolated, unit; zero where it vanishes (faces' normals then). */
static struct vec3 iso_normal(const struct wood_grid *g, const int p[3], int d, double t)
{
	struct vec3 g0 = iso_gradient(g, p[0], p[1], p[2]);
	struct vec3 g1 = iso_gradient(g, p[0] + (d & 1), p[1] + ((d >> 1) & 1), p[2] + ((d >> 2) & 1));
	struct vec3 n = vec3_scale(vec3_lerp(g0, g1, t), -1.0);
	double len = vec3_len(n);

	if (!(len >= ISO_GRAD_MIN) || !isfinite(len))
		return vec3(0, 0, 0);
	return vec3_scale(n, 1.0 / len);
}

/* Appends the vertex where the edge from sample p along d is crossed (room reserved). */
static uint32_t iso_add_vertex(struct iso *s, const int p[3], int d)
{
	const struct wood_grid *g = s->g;
	double a = iso_sample(g, p[0], p[1], p[2]);
	double b = iso_sample(g, p[0] + (d & 1), p[1] + ((d >> 1) & 1), p[2] + ((d >> 2) & 1));
	double t = iso_edge_t(a, b, s->iso);
	struct vec3 q = vec3_add(iso_corner(0), vec3_scale(iso_corner(d), t));
	struct vec3 n = iso_normal(g, p, d, t);
	struct mesh *m = s->out;
	float *pos = m->positions + 3 * m->nvertices, *nor = m->normals + 3 * m->nvertices;

	/* padded sample i is voxel i - 1, whose centre is at (i - 1 + 0.5) h */
	pos[0] = (float)(g->origin.x + (p[0] - 0.5 + q.x) * g->h);
	pos[1] = (float)(g->origin.y + (p[1] - 0.5 + q.y) * g->h);
	pos[2] = (float)(g->origin.z + (p[2] - 0.5 + q.z) * g->h);
	nor[0] = (float)n.x;
	nor[1] = (float)n.y;
	nor[2] = (float)n.z;
	return (uint32_t)m->nvertices++;
}

/* The vertex on the edge of cube (i, j, s->k) from corner m0 to corner m1 (m0's bits a
 * subset of m1's), made the first time any tetrahedron asks for it. */
static uint32_t iso_edge_vertex(struct iso *s, int i, int j, int m0, int m1)
{
	int p[3] = { i + (m0 & 1), j + ((m0 >> 1) & 1), s->k + ((m0 >> 2) & 1) };
	int d = m1 ^ m0;
	/* an edge starting in the upper layer lies in it (d has no z), so is still there
	 * when that layer becomes the lower one */
	uint32_t *slab = (m0 & 4) ? s->hi : s->lo;
	uint32_t *v = slab + ((size_t)p[0] + (size_t)s->sx * (size_t)p[1]) * ISO_DIRS + (d - 1);

	if (*v == ISO_NONE)
		*v = iso_add_vertex(s, p, d);
	return *v;
}

/* A corner's place along a tetrahedron's edge from corner m0 to m1, cube coordinates. */
static struct vec3 iso_local(const double val[8], double iso, int m0, int m1)
{
	double t = iso_edge_t(val[m0], val[m1], iso);

	return vec3_add(iso_corner(m0), vec3_scale(iso_corner(m1 ^ m0), t));
}

/* Appends triangle v (positions q, cube coordinates), turned so that its normal points
 * along out (from the inside corners towards the outside ones): counter-clockwise seen
 * from outside. The triangle's plane separates those corners, so the sign is sure. */
static void iso_emit(struct mesh *m, const uint32_t v[3], const struct vec3 q[3], struct vec3 out)
{
	struct vec3 n = vec3_cross(vec3_sub(q[1], q[0]), vec3_sub(q[2], q[0]));
	uint32_t *idx = m->indices + m->nindices;
	bool flip = vec3_dot(n, out) < 0.0;

	idx[0] = v[0];
	idx[1] = flip ? v[2] : v[1];
	idx[2] = flip ? v[1] : v[2];
	m->nindices += 3;
}

/* A tetrahedron's edge (corners a and b, either order) as its vertex and cube place. */
static void iso_tet_edge(struct iso *s, int i, int j, const double val[8], int a, int b,
			 uint32_t *v, struct vec3 *q)
{
	int m0 = (a & b) == a ? a : b, m1 = m0 == a ? b : a;

	*v = iso_edge_vertex(s, i, j, m0, m1);
	*q = iso_local(val, s->iso, m0, m1);
}

/* Two corners in (ins) and two out (outs): the quad round them, its corners on edges
 * a-c, a-d, b-d, b-c in that order, cut into two triangles along its shorter diagonal
 * (the better shaped pair; the first on a tie). */
static void iso_quad(struct iso *s, int i, int j, const double val[8], const int ins[2],
		     const int outs[2], struct vec3 dir)
{
	uint32_t v[4], t0[3], t1[3];
	struct vec3 q[4], p0[3], p1[3];
	int r;

	iso_tet_edge(s, i, j, val, ins[0], outs[0], &v[0], &q[0]);
	iso_tet_edge(s, i, j, val, ins[0], outs[1], &v[1], &q[1]);
	iso_tet_edge(s, i, j, val, ins[1], outs[1], &v[2], &q[2]);
	iso_tet_edge(s, i, j, val, ins[1], outs[0], &v[3], &q[3]);
	r = vec3_dist(q[1], q[3]) < vec3_dist(q[0], q[2]); /* 1: cut 1-3 rather than 0-2 */
	for (int e = 0; e < 3; e++) {
		int a = (r + e) & 3, b = (r + (e ? e + 1 : 0)) & 3;

		t0[e] = v[a];
		p0[e] = q[a];
		t1[e] = v[b];
		p1[e] = q[b];
	}
	iso_emit(s->out, t0, p0, dir);
	iso_emit(s->out, t1, p1, dir);
}

/* One tetrahedron of cube (i, j, s->k): its corners c, the cube's values and which are
 * inside (bit m of in). One triangle when one corner is alone on its side; a quad, cut
 * along its shorter diagonal, when two and two. */
static void iso_tet(struct iso *s, int i, int j, const uint8_t c[4], const double val[8],
		    unsigned in)
{
	int ins[4], outs[4], nin = 0, nout = 0;
	struct vec3 dir, cin = vec3(0, 0, 0), cout = vec3(0, 0, 0);
	uint32_t v[3];
	struct vec3 q[3];

	for (int e = 0; e < 4; e++) {
		if (in & (1u << c[e])) {
			ins[nin++] = c[e];
			cin = vec3_add(cin, iso_corner(c[e]));
		} else {
			outs[nout++] = c[e];
			cout = vec3_add(cout, iso_corner(c[e]));
		}
	}
	if (nin == 0 || nout == 0)
		return;
	dir = vec3_sub(vec3_scale(cout, 1.0 / nout), vec3_scale(cin, 1.0 / nin));
	if (nin == 1 || nout == 1) {
		int lone = nin == 1 ? ins[0] : outs[0], *others = nin == 1 ? outs : ins;

		for (int e = 0; e < 3; e++)
			iso_tet_edge(s, i, j, val, lone, others[e], &v[e], &q[e]);
		iso_emit(s->out, v, q, dir);
		return;
	}
	iso_quad(s, i, j, val, ins, outs, dir);
}

/* Cube (i, j, s->k), its lowest corner at padded sample (i, j, s->k). */
static int iso_cube(struct iso *s, int i, int j)
{
	double val[8];
	unsigned in = 0;
	int r;

	for (int m = 0; m < 8; m++) {
		const double *layer = (m & 4) ? s->above : s->below;

		val[m] = layer[(size_t)(i + (m & 1)) + (size_t)s->sx * (size_t)(j + ((m >> 1) & 1))];
		if (val[m] >= s->iso)
			in |= 1u << m;
	}
	if (in == 0 || in == 0xff)
		return 0;
	r = mesh_reserve(s->out, ISO_CUBE_VERTICES, ISO_CUBE_INDICES);
	if (r < 0)
		return r;
	for (int t = 0; t < 6; t++)
		iso_tet(s, i, j, iso_tets[t], val, in);
	return 0;
}

/* The layer of cubes between sample layers s->k and s->k + 1. */
static int iso_layer(struct iso *s)
{
	for (int j = 0; j + 1 < s->sy; j++)
		for (int i = 0; i + 1 < s->sx; i++) {
			int r = iso_cube(s, i, j);

			if (r < 0)
				return r;
		}
	return 0;
}

/* f made unit; up if it has no length (no face about it has any area: cannot happen). */
static struct vec3 iso_unit_or_up(struct vec3 f)
{
	double len = vec3_len(f);

	return len > 0.0 && isfinite(len) ? vec3_scale(f, 1.0 / len) : vec3(0, 1, 0);
}

/*
 * The normals of vertices [first..): where the gradient vanished, or disagrees with the
 * faces about them (the sum of their normals, by area), the faces' normal. Indices from
 * first_index on.
 */
static int iso_fix_normals(struct mesh *m, size_t first, size_t first_index)
{
	size_t n = m->nvertices - first;
	double *acc = calloc(3 * n + 1, sizeof(*acc));

	if (!acc)
		return -ENOMEM;
	for (size_t t = first_index; t < m->nindices; t += 3) {
		const uint32_t *v = m->indices + t;
		struct vec3 p[3], f;

		for (int e = 0; e < 3; e++)
			p[e] = vec3(m->positions[3 * v[e]], m->positions[3 * v[e] + 1],
				    m->positions[3 * v[e] + 2]);
		f = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		for (int e = 0; e < 3; e++) {
			double *a = acc + 3 * (v[e] - first);

			a[0] += f.x;
			a[1] += f.y;
			a[2] += f.z;
		}
	}
	for (size_t i = 0; i < n; i++) {
		float *nor = m->normals + 3 * (first + i);
		struct vec3 f = vec3(acc[3 * i], acc[3 * i + 1], acc[3 * i + 2]);
		struct vec3 s = vec3(nor[0], nor[1], nor[2]);

		if (vec3_dot(s, f) > 0.0)
			continue;
		f = iso_unit_or_up(f);
		nor[0] = (float)f.x;
		nor[1] = (float)f.y;
		nor[2] = (float)f.z;
	}
	free(acc);
	return 0;
}

/* Padded sample layer k into layer: the grid's densities, zeros about them (a copy, so
 * that the cubes read their corners without asking where they are). */
static void iso_fill_layer(const struct iso *s, double *layer, int k)
{
	const struct wood_grid *g = s->g;

	memset(layer, 0, (size_t)s->sx * (size_t)s->sy * sizeof(*layer));
	if (k < 1 || k > g->nz)
		return;
	for (int j = 1; j <= g->ny; j++)
		memcpy(layer + 1 + (size_t)s->sx * (size_t)j, g->density + wood_index(g, 0, j - 1, k - 1),
		       (size_t)g->nx * sizeof(*layer));
}

static int iso_march(struct iso *s)
{
	size_t slab = (size_t)s->sx * (size_t)s->sy * ISO_DIRS;

	memset(s->lo, 0xff, slab * sizeof(*s->lo));
	memset(s->hi, 0xff, slab * sizeof(*s->hi));
	iso_fill_layer(s, s->above, 0);
	for (s->k = 0; s->k + 1 < s->sz; s->k++) {
		uint32_t *t;
		double *l = s->below;
		int r;

		s->below = s->above;
		s->above = l;
		iso_fill_layer(s, s->above, s->k + 1);
		r = iso_layer(s);
		if (r < 0)
			return r;
		/* the upper layer becomes the lower one, its in-plane vertices kept */
		t = s->lo;
		s->lo = s->hi;
		s->hi = t;
		memset(s->hi, 0xff, slab * sizeof(*s->hi));
	}
	return 0;
}

int wood_iso(const struct wood_grid *g, double iso, struct mesh *out)
{
	struct iso s = { .g = g, .iso = iso, .out = out };
	size_t first = out->nvertices, first_index = out->nindices, plane;
	int r;

	s.sx = g->nx + 2;
	s.sy = g->ny + 2;
	s.sz = g->nz + 2;
	plane = (size_t)s.sx * (size_t)s.sy;
	s.lo = malloc(plane * ISO_DIRS * sizeof(*s.lo));
	s.hi = malloc(plane * ISO_DIRS * sizeof(*s.hi));
	s.below = malloc(plane * sizeof(*s.below));
	s.above = malloc(plane * sizeof(*s.above));
	r = s.lo && s.hi && s.below && s.above ? iso_march(&s) : -ENOMEM;
	free(s.lo);
	free(s.hi);
	free(s.below);
	free(s.above);
	if (r == 0)
		r = iso_fix_normals(out, first, first_index);
	if (r < 0) {
		/* nothing appended after all */
		out->nvertices = first;
		out->nindices = first_index;
	}
	return r;
}
