/* SPDX-License-Identifier: MIT */
/*
 * Steps 2-3 of growing wood (wood.h, docs/wood.md): the thick branches as octagonal
 * prisms, then the prisms' union registered in the voxel space as a density field by
 * rays along z. The rays' inside test is exact: the triangles' x and y are snapped to a
 * lattice of 2^-16 voxel on which every ray lies, the 2D orientations are computed in
 * integers, and a ray exactly on an edge or a vertex is decided by a symbolic
 * perturbation, so no crossing is counted twice or missed.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "tube_frame.h"
#include "wood.h"

_Static_assert(WOOD_PRISM_SIDES == 8, "the prisms are octagons (the corner tables below)");
_Static_assert(WOOD_RAYS == 5, "the rays are a voxel's centre and four about it");

/* wood_grid_create's limit on a side. */
#define WOOD_MAX_CELLS 1024
/* Dims are ceil(extent / h), less this many voxels, so the longest side is `cells`
 * exactly and not one more for a rounding. */
#define WOOD_DIMS_SLACK 1e-9
/* Consecutive points of a branch closer than this (metres) are one point. */
#define WOOD_SAME_POINT 1e-9

/* An axis-aligned box. */
struct wood_box {
	double lo[3], hi[3];
};

static void box_empty(struct wood_box *b)
{
	for (int a = 0; a < 3; a++) {
		b->lo[a] = INFINITY;
		b->hi[a] = -INFINITY;
	}
}

static void box_add(struct wood_box *b, const float *p)
{
	for (int a = 0; a < 3; a++) {
		b->lo[a] = fmin(b->lo[a], (double)p[a]);
		b->hi[a] = fmax(b->hi[a], (double)p[a]);
	}
}

static void box_union(struct wood_box *b, const struct wood_box *c)
{
	for (int a = 0; a < 3; a++) {
		b->lo[a] = fmin(b->lo[a], c->lo[a]);
		b->hi[a] = fmax(b->hi[a], c->hi[a]);
	}
}

/*
 * The grid about a box: padded by WOOD_PAD of its longest side, `cells` along that side,
 * centred on the box across and from its pad below upward.
 * wood_prisms (to choose the branches) and wood_grid_for (to make the grid) share it, so
 * both see the same h bit for bit. 0 or -EINVAL (an empty, flat or non-finite box).
 */
static int grid_frame(const struct wood_box *b, int cells, struct vec3 *origin, double *h,
		      int dims[3])
{
	double longest = 0.0, pad, lo[3];

	if (cells < 1 || cells > WOOD_MAX_CELLS)
		return -EINVAL;
	for (int a = 0; a < 3; a++) {
		if (!isfinite(b->lo[a]) || !isfinite(b->hi[a]) || b->hi[a] < b->lo[a])
			return -EINVAL;
		longest = fmax(longest, b->hi[a] - b->lo[a]);
	}
	if (!(longest > 0.0))
		return -EINVAL;
	pad = WOOD_PAD * longest;
	*h = (longest + 2.0 * pad) / cells;
	for (int a = 0; a < 3; a++) {
		double n = ceil((b->hi[a] - b->lo[a] + 2.0 * pad) / *h - WOOD_DIMS_SLACK);

		dims[a] = n < 1.0 ? 1 : n > cells ? cells : (int)n;
		/* across (x, z) the grid is centred on the box, so that a tree symmetric about
		 * a vertical plane through its middle meets its voxels the same way on both
		 * sides; upward it starts at the pad below the box, where the ground is */
		lo[a] = a == 1 ? b->lo[a] - pad : 0.5 * (b->lo[a] + b->hi[a]) - 0.5 * dims[a] * *h;
	}
	*origin = vec3(lo[0], lo[1], lo[2]);
	return 0;
}

/* ---- Step 2: the prisms ---- */

/* The octagon's corners at 2 pi j / 8, exact at the quarter turns (cos(pi / 2) in double
 * is not 0, and a prism along an axis should have its corners on it). */
#define WOOD_R2 0.70710678118654752440
static const double oct_c[8] = { 1, WOOD_R2, 0, -WOOD_R2, -1, -WOOD_R2, 0, WOOD_R2 };
static const double oct_s[8] = { 0, WOOD_R2, 1, WOOD_R2, 0, -WOOD_R2, -1, -WOOD_R2 };

/* A branch's rings: its usable points, their tangents, rotation-minimising normals and
 * the octagons' corners (float, as the mesh keeps them). */
struct rings {
	struct vec3 *p, *t, *n;
	double *r;
	float *v; /* 3 * WOOD_PRISM_SIDES a ring */
	size_t k, cap;
	const bool *fork_tip; /* per branch: children start at its tip (NULL: none do) */
};

static void rings_finish(struct rings *s)
{
	free(s->p);
	free(s->t);
	free(s->n);
	free(s->r);
	free(s->v);
	memset(s, 0, sizeof(*s));
}

static int rings_reserve(struct rings *s, size_t n)
{
	void *q;

	if (n <= s->cap)
		return 0;
	if (n > SIZE_MAX / (3 * WOOD_PRISM_SIDES * sizeof(float)))
		return -ENOMEM;
#define WOOD_GROW(f, size)                        \
	do {                                      \
		q = realloc(s->f, n * (size));    \
		if (!q)                           \
			return -ENOMEM;           \
		s->f = q;                         \
	} while (0)
	WOOD_GROW(p, sizeof(*s->p));
	WOOD_GROW(t, sizeof(*s->t));
	WOOD_GROW(n, sizeof(*s->n));
	WOOD_GROW(r, sizeof(*s->r));
	WOOD_GROW(v, 3 * WOOD_PRISM_SIDES * sizeof(*s->v));
#undef WOOD_GROW
	s->cap = n;
	return 0;
}

static bool vec3_finite(struct vec3 a)
{
	return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

/* Corner j of ring i's octagon: in the plane across the ring's tangent. */
static struct vec3 ring_dir(const struct rings *s, size_t i, int j)
{
	struct vec3 b = vec3_cross(s->t[i], s->n[i]);

	return vec3_add(vec3_scale(s->n[i], oct_c[j]), vec3_scale(b, oct_s[j]));
}

/*
 * Branch b's rings into s: s->k >= 2 when it can be voxelised, 0 when not (fewer than two
 * distinct points, or a point or radius not finite). 0 or -ENOMEM.
 */
static int branch_rings(const struct branch *b, struct rings *s)
{
	int ret;

	s->k = 0;
	if (b->npoints < 2)
		return 0;
	ret = rings_reserve(s, b->npoints + 1);
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < b->npoints; i++) {
		if (!vec3_finite(b->points[i]) || !isfinite(b->radii[i])) {
			s->k = 0;
			return 0;
		}
		/* a repeated point has no direction: one ring there (its first radius) */
		if (s->k > 0 && vec3_dist(b->points[i], s->p[s->k - 1]) <= WOOD_SAME_POINT)
			continue;
		s->p[s->k] = b->points[i];
		s->r[s->k] = fmax(0.0, b->radii[i]);
		s->k++;
	}
	if (s->k < 2) {
		s->k = 0;
		return 0;
	}
	/* Children that start at the tip start on its end face, where the density is about
	 * a half: the wood goes on by half the tip's radius, so that their swept roots are
	 * inside the bark (docs/wood.md, "The prisms"). */
	if (s->fork_tip && s->fork_tip[b->id] && s->r[s->k - 1] > 0.0) {
		struct vec3 d = vec3_sub(s->p[s->k - 1], s->p[s->k - 2]);

		s->p[s->k] = vec3_add(s->p[s->k - 1],
				      vec3_scale(d, 0.5 * s->r[s->k - 1] / vec3_len(d)));
		s->r[s->k] = s->r[s->k - 1];
		s->k++;
	}
	tube_frame_build(s->p, s->k, s->t, s->n);
	for (size_t i = 0; i < s->k; i++)
		for (int j = 0; j < WOOD_PRISM_SIDES; j++) {
			struct vec3 q = vec3_add(s->p[i], vec3_scale(ring_dir(s, i, j), s->r[i]));
			float *v = s->v + 3 * (WOOD_PRISM_SIDES * i + (size_t)j);

			v[0] = (float)q.x;
			v[1] = (float)q.y;
			v[2] = (float)q.z;
		}
	return 0;
}

static void rings_box(const struct rings *s, struct wood_box *b)
{
	box_empty(b);
	for (size_t i = 0; i < s->k * WOOD_PRISM_SIDES; i++)
		box_add(b, s->v + 3 * i);
}

/* A branch that may be voxelised: its root radius and its prisms' box. */
struct candidate {
	size_t id;
	double r;
	struct wood_box box;
};

static int candidate_cmp(const void *a, const void *b)
{
	const struct candidate *x = a, *y = b;

	if (x->r != y->r)
		return x->r > y->r ? -1 : 1;
	return (x->id > y->id) - (x->id < y->id);
}

/*
 * Which branches are voxelised. The grid's h depends on the box, the box on the branches
 * chosen, so: thickest first (equal radii together), add branches while the thinnest
 * added is at least WOOD_PRISM_MIN_VOXELS voxels of the grid the branches so far make.
 * Adding thinner branches only grows the box, so once a group fails every larger one
 * does: the result is the most branches that are all thick enough in their own grid.
 * Returns how many of the sorted candidates are in.
 */
static size_t choose(struct candidate *c, size_t n, int cells)
{
	struct wood_box box;
	size_t in = 0;

	qsort(c, n, sizeof(*c), candidate_cmp);
	box_empty(&box);
	while (in < n) {
		size_t end = in;
		struct wood_box grown = box;
		struct vec3 origin;
		double h;
		int dims[3];

		while (end < n && c[end].r == c[in].r)
			box_union(&grown, &c[end++].box);
		if (grid_frame(&grown, cells, &origin, &h, dims) < 0 ||
		    c[in].r < WOOD_PRISM_MIN_VOXELS * h)
			break;
		box = grown;
		in = end;
	}
	return in;
}

static void put_vertex(struct mesh *m, const float *p, struct vec3 n)
{
	float *q = m->positions + 3 * m->nvertices, *d = m->normals + 3 * m->nvertices;

	memcpy(q, p, 3 * sizeof(*q));
	d[0] = (float)n.x;
	d[1] = (float)n.y;
	d[2] = (float)n.z;
	m->nvertices++;
}

static void put_triangle(struct mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
	m->indices[m->nindices++] = a;
	m->indices[m->nindices++] = b;
	m->indices[m->nindices++] = c;
}

static struct vec3 fvec(const float *p)
{
	return vec3(p[0], p[1], p[2]);
}

/* The octagon of ring i as a cap facing `normal` (its plane's): a fan, counter-clockwise
 * seen from outside. */
static void put_cap(struct mesh *m, const struct rings *s, size_t i, bool end)
{
	const float *v = s->v + 3 * WOOD_PRISM_SIDES * i;
	struct vec3 normal = end ? s->t[i] : vec3_scale(s->t[i], -1.0);
	uint32_t base = (uint32_t)m->nvertices;

	for (int j = 0; j < WOOD_PRISM_SIDES; j++)
		put_vertex(m, v + 3 * j, normal);
	/* corners go counter-clockwise about t (n, b, t right-handed): the end cap as is,
	 * the start cap (seen from -t) reversed */
	for (uint32_t j = 1; j + 1 < WOOD_PRISM_SIDES; j++) {
		if (end)
			put_triangle(m, base, base + j, base + j + 1);
		else
			put_triangle(m, base, base + j + 1, base + j);
	}
}

/* The prism of the internode between rings i and i + 1: eight sides, each a quad (two
 * triangles) with one normal, then the two caps. */
static void put_prism(struct mesh *m, const struct rings *s, size_t i)
{
	const float *a = s->v + 3 * WOOD_PRISM_SIDES * i, *b = a + 3 * WOOD_PRISM_SIDES;

	for (int j = 0; j < WOOD_PRISM_SIDES; j++) {
		int j1 = (j + 1) % WOOD_PRISM_SIDES;
		const float *a0 = a + 3 * j, *a1 = a + 3 * j1, *b0 = b + 3 * j, *b1 = b + 3 * j1;
		/* the quad's normal from its diagonals (a twisted quad has no plane) */
		struct vec3 nrm = vec3_cross(vec3_sub(fvec(b1), fvec(a0)), vec3_sub(fvec(b0), fvec(a1)));
		struct vec3 out = vec3_add(ring_dir(s, i, j), ring_dir(s, i, j1));
		uint32_t base = (uint32_t)m->nvertices;

		nrm = vec3_norm_or(nrm, vec3_norm_or(out, s->n[i]));
		put_vertex(m, a0, nrm);
		put_vertex(m, a1, nrm);
		put_vertex(m, b1, nrm);
		put_vertex(m, b0, nrm);
		put_triangle(m, base, base + 1, base + 2);
		put_triangle(m, base, base + 2, base + 3);
	}
	put_cap(m, s, i, false);
	put_cap(m, s, i + 1, true);
}

#define WOOD_PRISM_VERTICES (6 * WOOD_PRISM_SIDES)
#define WOOD_PRISM_INDICES (3 * (2 * WOOD_PRISM_SIDES + 2 * (WOOD_PRISM_SIDES - 2)))

/* Every candidate branch: its root radius and box. *n set. 0 or -ENOMEM. */
static int candidates(const struct tree *t, struct rings *s, struct candidate *c, size_t *n)
{
	*n = 0;
	for (size_t b = 0; b < t->nbranches; b++) {
		int ret = branch_rings(&t->branches[b], s);

		if (ret < 0)
			return ret;
		if (s->k < 2 || !(s->r[0] > 0.0))
			continue;
		c[*n].id = b;
		c[*n].r = s->r[0];
		rings_box(s, &c[*n].box);
		(*n)++;
	}
	return 0;
}

/* The chosen branches' prisms, in the tree's order. 0 or -ENOMEM (out as it was). */
static int put_branches(const struct tree *t, const bool *in, struct rings *s, struct mesh *out)
{
	size_t internodes = 0;
	int ret;

	for (size_t b = 0; b < t->nbranches; b++) {
		if (!in[b])
			continue;
		ret = branch_rings(&t->branches[b], s);
		if (ret < 0)
			return ret;
		internodes += s->k - 1;
	}
	if (internodes > SIZE_MAX / WOOD_PRISM_INDICES)
		return -ENOMEM;
	ret = mesh_reserve(out, internodes * WOOD_PRISM_VERTICES, internodes * WOOD_PRISM_INDICES);
	if (ret < 0)
		return ret;
	for (size_t b = 0; b < t->nbranches; b++) {
		if (!in[b])
			continue;
		ret = branch_rings(&t->branches[b], s); /* reserved already: cannot fail */
		if (ret < 0)
			return ret;
		for (size_t i = 0; i + 1 < s->k; i++)
			put_prism(out, s, i);
	}
	return 0;
}

int wood_prisms(const struct tree *t, int cells, struct mesh *out, bool *voxelised)
{
	struct rings s = { 0 };
	struct candidate *c = NULL;
	bool *in = NULL, *fork_tip = NULL;
	size_t n = 0, nin;
	size_t nv = out->nvertices, ni = out->nindices;
	int ret;

	if (cells < 1 || cells > WOOD_MAX_CELLS)
		return -EINVAL;
	c = malloc((t->nbranches ? t->nbranches : 1) * sizeof(*c));
	in = calloc(t->nbranches ? t->nbranches : 1, sizeof(*in));
	fork_tip = calloc(t->nbranches ? t->nbranches : 1, sizeof(*fork_tip));
	ret = c && in && fork_tip ? 0 : -ENOMEM;
	for (size_t b = 0; ret == 0 && b < t->nbranches; b++) {
		int parent = t->branches[b].parent;

		if (parent >= 0 && (size_t)parent < t->nbranches && t->branches[b].parent_t >= 1.0)
			fork_tip[parent] = true;
	}
	s.fork_tip = fork_tip;
	if (ret == 0)
		ret = candidates(t, &s, c, &n);
	if (ret == 0) {
		nin = choose(c, n, cells);
		for (size_t i = 0; i < nin; i++)
			in[c[i].id] = true;
		ret = put_branches(t, in, &s, out);
	}
	if (ret == 0 && voxelised)
		memcpy(voxelised, in, t->nbranches * sizeof(*in));
	if (ret < 0) {
		out->nvertices = nv;
		out->nindices = ni;
	}
	rings_finish(&s);
	free(c);
	free(in);
	free(fork_tip);
	return ret;
}

int wood_grid_for(const struct mesh *prisms, int cells, struct wood_grid *g)
{
	struct wood_box b;
	struct vec3 origin;
	double h;
	int dims[3], ret;

	memset(g, 0, sizeof(*g));
	if (prisms->nvertices == 0 || prisms->nindices == 0)
		return -EINVAL;
	box_empty(&b);
	for (size_t i = 0; i < prisms->nvertices; i++)
		box_add(&b, prisms->positions + 3 * i);
	ret = grid_frame(&b, cells, &origin, &h, dims);
	if (ret < 0)
		return ret;
	return wood_grid_create(g, dims[0], dims[1], dims[2], origin, h);
}

/* ---- Step 3: the rays ---- */

/* The lattice x and y are snapped to: 2^16 points a voxel. Every ray lies on it (at a
 * quarter, half or three quarters of a voxel). */
#define LAT_BITS 16
#define LAT_ONE ((int64_t)1 << LAT_BITS)
#define LAT_QUARTER (LAT_ONE / 4)
/* |coordinate| at most 2^29 (8,192 voxels out): differences below 2^30, so the 2D
 * orientations' products stay below 2^60. Farther corners are clamped, a map of each
 * vertex on its own, so a closed mesh stays closed. */
#define LAT_MAX ((int64_t)1 << 29)
/* z (grid units) kept within this, so a wild vertex cannot make inf - inf. */
#define WOOD_Z_MAX 1e9

/*
 * A triangle as the rays see it: lattice x and y, z in voxels, its box. Its corners are
 * sorted by (x, y), so a triangle and the same one reversed (the caps two prisms share)
 * give a ray the same z bit for bit; `delta` keeps which way it faces.
 */
struct ray_tri {
	int64_t x[3], y[3];
	int64_t lo[2], hi[2];
	int64_t area; /* twice the signed area of the sorted corners seen from +z; never 0 */
	double z[3];
	int delta; /* what crossing it upwards adds: -1 facing +z (leaving), +1 entering */
};

/* A crossing along a ray: where, and +1 entering (a face seen from below) or -1. */
struct crossing {
	double z;
	int delta;
};

static int64_t lattice(double u)
{
	double v = u * (double)LAT_ONE;

	if (isnan(v))
		return 0;
	v = fmax(-(double)LAT_MAX, fmin((double)LAT_MAX, v));
	return (int64_t)floor(v + 0.5);
}

static int64_t orient(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
	return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/*
 * The side of edge a->b that p is on, as the sign of orient(a, b, p), and on the edge's
 * line that of p moved by (e, e^2), e > 0 infinitely small (simulation of simplicity): a
 * real point off every line, so what the rays count is exactly what a real ray counts.
 * The rule flips with the edge's direction, so two triangles sharing an edge never both
 * claim, or both miss, a ray on it. 0 only for a point edge (a flat triangle).
 */
static int edge_side(int64_t o, int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
	if (o != 0)
		return o > 0 ? 1 : -1;
	/* orient(a, b, p + (e, e^2)) = o - (by - ay) e + (bx - ax) e^2 */
	if (by != ay)
		return by < ay ? 1 : -1;
	return (bx > ax) - (bx < ax);
}

/* Whether the ray at lattice (px, py) crosses t, and at what z. */
static bool ray_hit(const struct ray_tri *t, int64_t px, int64_t py, double *z)
{
	int s = t->area > 0 ? 1 : -1;
	int64_t w0, w1, w2;

	if (px < t->lo[0] || px > t->hi[0] || py < t->lo[1] || py > t->hi[1])
		return false;
	w0 = orient(t->x[1], t->y[1], t->x[2], t->y[2], px, py);
	if (edge_side(w0, t->x[1], t->y[1], t->x[2], t->y[2]) != s)
		return false;
	w1 = orient(t->x[2], t->y[2], t->x[0], t->y[0], px, py);
	if (edge_side(w1, t->x[2], t->y[2], t->x[0], t->y[0]) != s)
		return false;
	w2 = orient(t->x[0], t->y[0], t->x[1], t->y[1], px, py);
	if (edge_side(w2, t->x[0], t->y[0], t->x[1], t->y[1]) != s)
		return false;
	/* barycentric: w0 + w1 + w2 == area exactly, each of its sign (or 0) */
	*z = ((double)(s * w0) * t->z[0] + (double)(s * w1) * t->z[1] + (double)(s * w2) * t->z[2]) /
	     (double)(s * t->area);
	return true;
}

static bool corner_before(const struct ray_tri *t, int a, int b)
{
	return t->x[a] < t->x[b] || (t->x[a] == t->x[b] && t->y[a] < t->y[b]);
}

static void corner_swap(struct ray_tri *t, int a, int b)
{
	int64_t x = t->x[a], y = t->y[a];
	double z = t->z[a];

	t->x[a] = t->x[b];
	t->y[a] = t->y[b];
	t->z[a] = t->z[b];
	t->x[b] = x;
	t->y[b] = y;
	t->z[b] = z;
	t->area = -t->area; /* an odd permutation */
}

/* The corners in (x, y) order (distinct: the triangle is not flat). */
static void tri_sort(struct ray_tri *t)
{
	if (corner_before(t, 1, 0))
		corner_swap(t, 0, 1);
	if (corner_before(t, 2, 1))
		corner_swap(t, 1, 2);
	if (corner_before(t, 1, 0))
		corner_swap(t, 0, 1);
}

/* Every triangle the rays can cross (not flat seen along z), in grid units. *n set.
 * 0 or -EINVAL (an index past the vertices). */
static int ray_tris(const struct wood_grid *g, const struct mesh *m, struct ray_tri *out,
		    size_t *n)
{
	const double o[3] = { g->origin.x, g->origin.y, g->origin.z };

	*n = 0;
	for (size_t f = 0; f + 2 < m->nindices; f += 3) {
		struct ray_tri *t = &out[*n];

		for (int c = 0; c < 3; c++) {
			uint32_t v = m->indices[f + (size_t)c];
			const float *p;
			double z;

			if (v >= m->nvertices)
				return -EINVAL;
			p = m->positions + 3 * (size_t)v;
			t->x[c] = lattice(((double)p[0] - o[0]) / g->h);
			t->y[c] = lattice(((double)p[1] - o[1]) / g->h);
			z = ((double)p[2] - o[2]) / g->h;
			t->z[c] = isnan(z) ? 0.0 : fmax(-WOOD_Z_MAX, fmin(WOOD_Z_MAX, z));
		}
		t->area = orient(t->x[0], t->y[0], t->x[1], t->y[1], t->x[2], t->y[2]);
		if (t->area == 0)
			continue; /* seen edge-on: no real ray crosses it */
		t->delta = t->area > 0 ? -1 : 1;
		tri_sort(t);
		t->lo[0] = t->x[0] < t->x[1] ? t->x[0] : t->x[1];
		t->lo[0] = t->x[2] < t->lo[0] ? t->x[2] : t->lo[0];
		t->hi[0] = t->x[0] > t->x[1] ? t->x[0] : t->x[1];
		t->hi[0] = t->x[2] > t->hi[0] ? t->x[2] : t->hi[0];
		t->lo[1] = t->y[0] < t->y[1] ? t->y[0] : t->y[1];
		t->lo[1] = t->y[2] < t->lo[1] ? t->y[2] : t->lo[1];
		t->hi[1] = t->y[0] > t->y[1] ? t->y[0] : t->y[1];
		t->hi[1] = t->y[2] > t->hi[1] ? t->y[2] : t->hi[1];
		(*n)++;
	}
	return 0;
}

static int64_t floor_div(int64_t a, int64_t b)
{
	int64_t q = a / b;

	return (a % b != 0 && a < 0) ? q - 1 : q;
}

/* The columns a triangle's box covers: [*lo, *hi] of 0..n-1; false if none. */
static bool tri_columns(int64_t lo, int64_t hi, int n, int *clo, int *chi)
{
	int64_t a = floor_div(lo, LAT_ONE), b = floor_div(hi, LAT_ONE);

	if (b < 0 || a >= n)
		return false;
	*clo = a < 0 ? 0 : (int)a;
	*chi = b >= n ? n - 1 : (int)b;
	return true;
}

/* Triangles binned per column (x, y) as CSR: column c's are idx[start[c] .. start[c+1]). */
struct bins {
	size_t *start;
	uint32_t *idx;
	size_t most; /* the most in one column */
};

static void bins_finish(struct bins *b)
{
	free(b->start);
	free(b->idx);
	memset(b, 0, sizeof(*b));
}

static int bins_make(struct bins *b, const struct wood_grid *g, const struct ray_tri *t, size_t n)
{
	size_t cols = (size_t)g->nx * (size_t)g->ny, total = 0;
	int x0, x1, y0, y1;

	memset(b, 0, sizeof(*b));
	b->start = calloc(cols + 1, sizeof(*b->start));
	if (!b->start)
		return -ENOMEM;
	for (size_t i = 0; i < n; i++) {
		if (!tri_columns(t[i].lo[0], t[i].hi[0], g->nx, &x0, &x1) ||
		    !tri_columns(t[i].lo[1], t[i].hi[1], g->ny, &y0, &y1))
			continue;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				b->start[(size_t)y * (size_t)g->nx + (size_t)x + 1]++;
	}
	for (size_t c = 0; c < cols; c++) {
		if (b->start[c + 1] > b->most)
			b->most = b->start[c + 1];
		total += b->start[c + 1];
		b->start[c + 1] = total;
	}
	b->idx = malloc((total ? total : 1) * sizeof(*b->idx));
	if (!b->idx) {
		bins_finish(b);
		return -ENOMEM;
	}
	/* fill, using start[c] as column c's cursor, then shift back */
	for (size_t i = 0; i < n; i++) {
		if (!tri_columns(t[i].lo[0], t[i].hi[0], g->nx, &x0, &x1) ||
		    !tri_columns(t[i].lo[1], t[i].hi[1], g->ny, &y0, &y1))
			continue;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				b->idx[b->start[(size_t)y * (size_t)g->nx + (size_t)x]++] = (uint32_t)i;
	}
	for (size_t c = cols; c > 0; c--)
		b->start[c] = b->start[c - 1];
	b->start[0] = 0;
	return 0;
}

/* Along z; at one z entering first, so solids that touch (prisms' shared caps) make one
 * stretch inside and a full voxel is 1 exactly, not two stretches that round short. */
static bool crossing_before(const struct crossing *a, const struct crossing *b)
{
	return a->z < b->z || (a->z == b->z && a->delta > b->delta);
}

static int crossing_cmp(const void *a, const void *b)
{
	return crossing_before(a, b) ? -1 : crossing_before(b, a) ? 1 : 0;
}

/* Sorts a ray's crossings (a total order, so deterministic). */
static void crossings_sort(struct crossing *c, size_t n)
{
	if (n > 32) {
		qsort(c, n, sizeof(*c), crossing_cmp);
		return;
	}
	for (size_t i = 1; i < n; i++) {
		struct crossing x = c[i];
		size_t j = i;

		for (; j > 0 && crossing_before(&x, &c[j - 1]); j--)
			c[j] = c[j - 1];
		c[j] = x;
	}
}

/*
 * A row of columns' (one y) sums of the lengths inside, per voxel, over their rays:
 * len[k * nx + x], written out to the field a z-layer at a time, x in order (the field's
 * own order, where a column alone would stride a layer a voxel). [lo, hi) of z and
 * [xlo, xhi) of x touched.
 */
struct row {
	double *len;
	int nx, nz, lo, hi, xlo, xhi;
};

/* Adds [za, zb] (voxels along z) to column x of the row, clipped to the grid. */
static void row_add(struct row *r, int x, double za, double zb)
{
	int k0, k1;

	za = za > 0.0 ? za : 0.0;
	zb = zb < r->nz ? zb : (double)r->nz;
	if (!(zb > za))
		return;
	k0 = (int)floor(za);
	k1 = (int)ceil(zb);
	for (int k = k0; k < k1; k++) {
		double a = za > k ? za : (double)k, b = zb < k + 1 ? zb : k + 1.0;

		r->len[(size_t)k * (size_t)r->nx + (size_t)x] += b - a;
	}
	r->lo = k0 < r->lo ? k0 : r->lo;
	r->hi = k1 > r->hi ? k1 : r->hi;
	r->xlo = x < r->xlo ? x : r->xlo;
	r->xhi = x + 1 > r->xhi ? x + 1 : r->xhi;
}

/* Row y's sums into the field, the row cleared. */
static void row_flush(struct row *r, struct wood_grid *g, int y)
{
	for (int k = r->lo; k < r->hi; k++) {
		double *len = r->len + (size_t)k * (size_t)r->nx;
		double *d = g->density + wood_index(g, 0, y, k);

		for (int x = r->xlo; x < r->xhi; x++) {
			/* each ray adds at most 1 a voxel; the clamp only keeps rounding in 0..1 */
			double v = len[x] < WOOD_RAYS ? len[x] : (double)WOOD_RAYS;

			if (v > 0.0)
				d[x] += v / WOOD_RAYS;
			len[x] = 0.0;
		}
	}
	r->lo = r->xlo = INT_MAX;
	r->hi = r->xhi = 0;
}

/* One ray: its crossings, then the stretches where their sum from below is above 0. */
static void ray_cast(struct row *row, int x, const struct ray_tri *t, const uint32_t *idx,
		     size_t n, int64_t px, int64_t py, struct crossing *cr)
{
	size_t m = 0;
	int w = 0;
	double start = 0.0;

	for (size_t i = 0; i < n; i++) {
		const struct ray_tri *ti = &t[idx[i]];

		if (ray_hit(ti, px, py, &cr[m].z))
			cr[m++].delta = ti->delta;
	}
	crossings_sort(cr, m);
	for (size_t i = 0; i < m; i++) {
		int was = w;

		w += cr[i].delta;
		if (was <= 0 && w > 0)
			start = cr[i].z;
		else if (was > 0 && w <= 0)
			row_add(row, x, start, cr[i].z);
	}
}

/* The rays of a voxel, in quarters of a voxel from its low corner: the centre, and the
 * four points half-way from it to the corners. */
static const int ray_q[WOOD_RAYS][2] = { { 2, 2 }, { 1, 1 }, { 3, 1 }, { 1, 3 }, { 3, 3 } };

static void column_cast(struct row *row, const struct ray_tri *t, const struct bins *b, int x,
			int y, struct crossing *cr)
{
	size_t c = (size_t)y * (size_t)row->nx + (size_t)x;
	const uint32_t *idx = b->idx + b->start[c];
	size_t n = b->start[c + 1] - b->start[c];

	if (n == 0)
		return;
	for (int r = 0; r < WOOD_RAYS; r++)
		ray_cast(row, x, t, idx, n, (4 * (int64_t)x + ray_q[r][0]) * LAT_QUARTER,
			 (4 * (int64_t)y + ray_q[r][1]) * LAT_QUARTER, cr);
}

int wood_voxelise(struct wood_grid *g, const struct mesh *prisms)
{
	size_t ntri = prisms->nindices / 3, n;
	struct ray_tri *t = NULL;
	struct crossing *cr = NULL;
	struct row row = { .nx = g->nx, .nz = g->nz, .lo = INT_MAX, .xlo = INT_MAX };
	struct bins b = { 0 };
	int ret;

	if (ntri == 0)
		return 0;
	if (ntri > UINT32_MAX || ntri > SIZE_MAX / sizeof(*t))
		return -ENOMEM;
	t = malloc(ntri * sizeof(*t));
	if (!t)
		return -ENOMEM;
	ret = ray_tris(g, prisms, t, &n);
	if (ret == 0)
		ret = bins_make(&b, g, t, n);
	if (ret == 0) {
		cr = malloc((b.most ? b.most : 1) * sizeof(*cr));
		row.len = calloc((size_t)g->nx * (size_t)g->nz, sizeof(*row.len));
		ret = cr && row.len ? 0 : -ENOMEM;
	}
	for (int y = 0; ret == 0 && y < g->ny; y++) {
		for (int x = 0; x < g->nx; x++)
			column_cast(&row, t, &b, x, y, cr);
		row_flush(&row, g, y);
	}
	bins_finish(&b);
	free(row.len);
	free(cr);
	free(t);
	return ret;
}
