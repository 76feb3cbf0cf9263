/* SPDX-License-Identifier: MIT */
/*
 * The vine's support (seed 004, issue 16): a triangle mesh in a bounding-volume hierarchy
 * for the growth's contact queries, asked thousands of times with a small max (a few stem
 * radii), so a query must prune hard.
 *
 * The tree. Binary, its nodes in one flat array: the root at 0, then the two children of
 * each inner node side by side at an even index, so that both boxes a query compares come
 * in one 64-byte line (the array is aligned to 64). A node's box is the axis-aligned box of
 * its triangles, kept as floats: the positions come as floats, so their min and max are
 * floats and the boxes are exact. Leaves hold up to LEAF_MAX triangles, copied in leaf
 * order (a query reads a leaf's triangles from one place and never touches the caller's
 * arrays again), their vertices as the floats they came as: every computation is in double,
 * and a float converts to a double exactly, so this is a double copy at half the memory
 * (40 bytes a triangle instead of 80, which counts when 100k triangles meet the cache).
 *
 * The build. Top down over a work stack (no recursion): a node splits its triangles by
 * their box centres along the longest axis of the centres' box, where the surface area
 * heuristic (SAH, SAH_BINS bins) says the two halves' boxes cost least (area x
 * triangles); the bins give the halves' boxes too. Below depth SAH_DEPTH, and whenever the
 * bins cannot part them, at the median (ties by triangle index), which halves the count;
 * so the depth stays under SAH_DEPTH + log2(ntriangles) <= 62, and the query's stack of
 * STACK entries always suffices. Triangles with the same centre are parted by their order.
 * Every choice is a function of the input alone: the same mesh gives the same tree.
 *
 * The query. From the root, nearest child first (the farther one waits on a fixed stack,
 * with its box distance), skipping any node whose box is farther than the best triangle
 * so far, or than max at first. A triangle's distance is Ericson's closest point on a
 * triangle (Real-Time Collision Detection, 5.1.5: the Voronoi regions of its vertices,
 * edges and face) in double precision; in the face's region the point is the projection on
 * the plane, which rounds less on long thin triangles than a + v ab + w ac. Triangles
 * without area (cross product exactly 0: repeated or collinear vertices) are their three
 * edges, a repeated vertex an edge of length 0; and when rounding on a sliver puts the
 * point beyond an edge, the edges answer instead, so the point returned is always on the
 * triangle. Equal distances go to the lower triangle index, as a scan in index order
 * would; a node is skipped only when its box is farther than the best by more than
 * rounding (BOX_SLACK), so a triangle at the same distance is still looked at.
 *
 * Leaves of up to 3 rather than 4: a query near the surface then tests fewer triangles
 * (Ericson's test, with its branches, costs several box tests) for one more level of
 * boxes, which measured about 20 % faster on a growth's queries, for about 20 % more
 * build time.
 *
 * The crossing query (does a segment meet a triangle: the growth's steps, the drawn axis's
 * pulls) walks every node whose box overlaps the segment's box, and tests a triangle by
 * signs alone: the ends not strictly on one side of its plane, and the edge products
 * [b - a, p - a, q - a] all of one sign, zeros counting for both. An edge's product for
 * its two triangles is the same computation negated, so no segment passes between them:
 * watertight, and conservative at edges and ends.
 *
 * Costs (bench/bench_vine_support.c, docs/vines.md): 40 bytes a triangle and 32 a node,
 * about one node a triangle; the build O(n log n), with 44 bytes a triangle of scratch; a
 * query near the surface O(log n): on 100k triangles 20 to 30 nodes, 2 to 5 leaves, 4 to
 * 10 triangles.
 */
#include "vine_support.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LEAF_MAX 3
#define SAH_BINS 16
#define SAH_DEPTH 32
#define STACK 64
/* Node indices are uint32_t, there are at most 2n of them, and a triangle's index keeps
 * its top bit free for FLAT. */
#define MAX_TRIANGLES ((size_t)INT32_MAX)
#define FLAT 0x80000000u
#define LINE 64
/* A node is skipped when its box distance squared, less this much of it, still exceeds
 * the best: the box's and the triangle's rounding cannot hide a tie. */
#define BOX_SLACK (1.0 - 8.0 * DBL_EPSILON)

struct box {
	float lo[3], hi[3];
};

struct node {
	struct box box;
	uint32_t first; /* a leaf's first triangle, or an inner node's first child */
	uint32_t count; /* a leaf's triangles (1..LEAF_MAX); 0: an inner node */
};

struct tri {
	float v[9];     /* a, b, c */
	uint32_t index; /* the caller's, | FLAT if it has no area: its edges answer */
};

struct vine_support {
	size_t ntriangles;
	struct tri *tris; /* in leaf order */
	void *node_block; /* what nodes is in, aligned */
	struct node *nodes;
	size_t nnodes;
	struct vec3 lo, hi;
};

/* The build's view of a triangle. */
struct prim {
	struct box box;
	float c[3]; /* the box's centre */
	uint32_t index;
	uint32_t bin; /* sah_split's, while it splits */
};

struct task {
	uint32_t node, begin, end, depth;
	struct box box, cbox; /* the triangles', and their centres' */
};

static void *alloc_array(size_t n, size_t size, size_t extra)
{
	if (n > (SIZE_MAX - extra) / size)
		return NULL;
	return malloc(n * size + extra);
}

/* n nodes aligned to LINE in a block of their own. */
static struct node *alloc_nodes(size_t n, void **block)
{
	unsigned char *b = alloc_array(n, sizeof(struct node), LINE);
	size_t off;

	if (!b)
		return NULL;
	off = (LINE - (size_t)((uintptr_t)b % LINE)) % LINE;
	*block = b;
	return (struct node *)(b + off);
}

/* ---- The build ---- */

static const struct box empty = { { INFINITY, INFINITY, INFINITY },
				  { -INFINITY, -INFINITY, -INFINITY } };

/* Written out: -O2 keeps a loop of 3 a loop, and the build spends its time here. */
static inline void box_grow(struct box *b, const float lo[3], const float hi[3])
{
	b->lo[0] = lo[0] < b->lo[0] ? lo[0] : b->lo[0];
	b->lo[1] = lo[1] < b->lo[1] ? lo[1] : b->lo[1];
	b->lo[2] = lo[2] < b->lo[2] ? lo[2] : b->lo[2];
	b->hi[0] = hi[0] > b->hi[0] ? hi[0] : b->hi[0];
	b->hi[1] = hi[1] > b->hi[1] ? hi[1] : b->hi[1];
	b->hi[2] = hi[2] > b->hi[2] ? hi[2] : b->hi[2];
}

static double box_area(const struct box *b)
{
	double dx = (double)b->hi[0] - b->lo[0], dy = (double)b->hi[1] - b->lo[1];
	double dz = (double)b->hi[2] - b->lo[2];

	return dx * dy + dy * dz + dz * dx;
}

/* The box of prims [0, n), and of their centres. */
static void boxes_of(const struct prim *p, size_t n, struct box *box, struct box *cbox)
{
	struct box b = empty, c = empty; /* locals: kept in registers */

	for (size_t i = 0; i < n; i++) {
		box_grow(&b, p[i].box.lo, p[i].box.hi);
		box_grow(&c, p[i].c, p[i].c);
	}
	*box = b;
	*cbox = c;
}

/* Which of SAH_BINS bins along the axis a centre falls in: c >= clo and c - clo <=
 * SAH_BINS / scale, so b is in [0, SAH_BINS] (the last only by rounding). */
static unsigned bin_of(float c, double clo, double scale)
{
	unsigned b = (unsigned)(((double)c - clo) * scale);

	return b < SAH_BINS - 1 ? b : SAH_BINS - 1;
}

/*
 * Where prims [0, n) split by the SAH along axis, the lesser first, and the two halves'
 * boxes (l: [0, split), r: the rest); 0 when no split parts them.
 */
static size_t sah_split(struct prim *p, size_t n, int axis, const struct box *cbox,
			struct box l[2], struct box r[2])
{
	struct box bin[SAH_BINS], cbin[SAH_BINS], right[SAH_BINS], cright[SAH_BINS], acc, cacc;
	size_t count[SAH_BINS] = { 0 }, nright[SAH_BINS + 1], nleft = 0, i, j;
	double clo = cbox->lo[axis], scale = SAH_BINS / ((double)cbox->hi[axis] - clo);
	double best = INFINITY;
	int split = -1;

	for (int b = 0; b < SAH_BINS; b++)
		bin[b] = cbin[b] = empty;
	for (i = 0; i < n; i++) {
		unsigned b = bin_of(p[i].c[axis], clo, scale);

		p[i].bin = b;
		count[b]++;
		box_grow(&bin[b], p[i].box.lo, p[i].box.hi);
		box_grow(&cbin[b], p[i].c, p[i].c);
	}
	/* right[b]: bins b.. together */
	acc = cacc = empty;
	nright[SAH_BINS] = 0;
	for (int b = SAH_BINS - 1; b > 0; b--) {
		box_grow(&acc, bin[b].lo, bin[b].hi);
		box_grow(&cacc, cbin[b].lo, cbin[b].hi);
		right[b] = acc;
		cright[b] = cacc;
		nright[b] = count[b] + nright[b + 1];
	}
	acc = empty;
	for (int b = 0; b < SAH_BINS - 1; b++) {
		double cost;

		nleft += count[b];
		box_grow(&acc, bin[b].lo, bin[b].hi);
		if (nleft == 0 || nleft == n)
			continue;
		cost = box_area(&acc) * (double)nleft +
		       box_area(&right[b + 1]) * (double)nright[b + 1];
		if (cost < best) {
			best = cost;
			split = b;
		}
	}
	if (split < 0)
		return 0;
	l[0] = l[1] = empty;
	for (int b = 0; b <= split; b++) {
		box_grow(&l[0], bin[b].lo, bin[b].hi);
		box_grow(&l[1], cbin[b].lo, cbin[b].hi);
	}
	r[0] = right[split + 1];
	r[1] = cright[split + 1];
	for (i = 0, j = n; i < j;) {
		if (p[i].bin <= (unsigned)split) {
			i++;
		} else {
			struct prim t = p[i];

			p[i] = p[--j];
			p[j] = t;
		}
	}
	return i;
}

static bool prim_less(const struct prim *a, const struct prim *b, int axis)
{
	return a->c[axis] < b->c[axis] || (a->c[axis] == b->c[axis] && a->index < b->index);
}

static void prim_swap(struct prim *a, struct prim *b)
{
	struct prim t = *a;

	*a = *b;
	*b = t;
}

/* Puts the prim of rank k (by centre along axis, then index) at k, the lesser before it:
 * quickselect with the median of three as pivot. */
static void select_median(struct prim *p, size_t n, size_t k, int axis)
{
	size_t lo = 0, hi = n - 1;

	while (hi > lo) {
		size_t mid = lo + (hi - lo) / 2, i, store;

		if (prim_less(&p[mid], &p[lo], axis))
			prim_swap(&p[mid], &p[lo]);
		if (prim_less(&p[hi], &p[lo], axis))
			prim_swap(&p[hi], &p[lo]);
		if (prim_less(&p[hi], &p[mid], axis))
			prim_swap(&p[hi], &p[mid]);
		/* the median of the three is the pivot, kept at hi */
		prim_swap(&p[mid], &p[hi]);
		for (i = store = lo; i < hi; i++)
			if (prim_less(&p[i], &p[hi], axis))
				prim_swap(&p[i], &p[store++]);
		prim_swap(&p[store], &p[hi]);
		if (store == k)
			return;
		if (store < k)
			lo = store + 1;
		else
			hi = store - 1;
	}
}

/* Where task t's prims split (relative to t->begin), and the halves' boxes; 0: a leaf. */
static size_t split(const struct task *t, struct prim *p, struct box l[2], struct box r[2])
{
	size_t n = t->end - t->begin, mid = 0;
	const struct box *c = &t->cbox;
	int axis = 0;

	if (n <= LEAF_MAX)
		return 0;
	for (int k = 1; k < 3; k++)
		if ((double)c->hi[k] - c->lo[k] > (double)c->hi[axis] - c->lo[axis])
			axis = k;
	if (c->hi[axis] == c->lo[axis]) { /* every centre the same: halves as they are */
		mid = n / 2;
	} else {
		if (t->depth < SAH_DEPTH)
			mid = sah_split(p, n, axis, c, l, r);
		if (mid > 0)
			return mid;
		mid = n / 2;
		select_median(p, n, mid, axis);
	}
	boxes_of(p, mid, &l[0], &l[1]);
	boxes_of(p + mid, n - mid, &r[0], &r[1]);
	return mid;
}

static int build(struct vine_support *s, struct prim *p)
{
	struct task stack[STACK];
	size_t top = 0;
	/* the root, a spare to put the pairs on even places, and a pair an inner node: fewer
	 * than n inner nodes */
	struct node *nodes = alloc_nodes(2 * s->ntriangles, &s->node_block), *small;
	void *block;

	if (!nodes)
		return -ENOMEM;
	s->nodes = nodes;
	s->nnodes = 2;
	stack[0] = (struct task){ .node = 0, .begin = 0, .end = (uint32_t)s->ntriangles };
	boxes_of(p, s->ntriangles, &stack[0].box, &stack[0].cbox);
	top = 1;
	while (top > 0) {
		struct task t = stack[--top];
		struct node *node = &nodes[t.node];
		struct box l[2], r[2];
		size_t mid = split(&t, p + t.begin, l, r);
		uint32_t c = (uint32_t)s->nnodes;

		node->box = t.box;
		if (mid == 0) {
			node->first = t.begin;
			node->count = t.end - t.begin;
			continue;
		}
		/* the median's halving keeps the depth below STACK - 2: both children fit */
		if (top + 2 > STACK)
			abort();
		node->first = c;
		node->count = 0;
		s->nnodes += 2;
		stack[top++] = (struct task){ c + 1, t.begin + (uint32_t)mid, t.end, t.depth + 1,
					      r[0], r[1] };
		stack[top++] = (struct task){ c, t.begin, t.begin + (uint32_t)mid, t.depth + 1,
					      l[0], l[1] };
	}
	/* fewer nodes than the worst case: moved to a block their size (or kept where they
	 * are, if there is no memory for it) */
	small = alloc_nodes(s->nnodes, &block);
	if (small) {
		memcpy(small, nodes, s->nnodes * sizeof(*nodes));
		free(s->node_block);
		s->node_block = block;
		s->nodes = small;
	}
	return 0;
}

int vine_support_create(const float *positions, size_t nvertices, const uint32_t *indices,
			size_t ntriangles, struct vine_support **out)
{
	struct vine_support *s;
	struct prim *p;
	int r;

	if (!out || (nvertices > 0 && !positions) || (ntriangles > 0 && !indices))
		return -EINVAL;
	/* no array this long can exist, nor a tree of it be numbered */
	if (nvertices > SIZE_MAX / (3 * sizeof(float)) || ntriangles > MAX_TRIANGLES ||
	    ntriangles > SIZE_MAX / (3 * sizeof(uint32_t)))
		return -ENOMEM;
	for (size_t i = 0; i < 3 * nvertices; i++)
		if (!isfinite(positions[i]))
			return -EINVAL;
	for (size_t i = 0; i < 3 * ntriangles; i++)
		if (indices[i] >= nvertices)
			return -EINVAL;
	s = calloc(1, sizeof(*s));
	if (!s)
		return -ENOMEM;
	s->ntriangles = ntriangles;
	if (ntriangles == 0) {
		*out = s;
		return 0;
	}
	s->tris = alloc_array(ntriangles, sizeof(*s->tris), 0);
	p = alloc_array(ntriangles, sizeof(*p), 0);
	if (!s->tris || !p) {
		free(p);
		vine_support_destroy(s);
		return -ENOMEM;
	}
	for (size_t i = 0; i < ntriangles; i++) {
		const uint32_t *t = indices + 3 * i;

		p[i].box = empty;
		for (int k = 0; k < 3; k++) {
			const float *v = positions + 3 * (size_t)t[k];

			box_grow(&p[i].box, v, v);
		}
		/* halves first: lo + hi may overflow a float */
		for (int k = 0; k < 3; k++)
			p[i].c[k] = 0.5f * p[i].box.lo[k] + 0.5f * p[i].box.hi[k];
		p[i].index = (uint32_t)i;
	}
	r = build(s, p);
	if (r < 0) {
		free(p);
		vine_support_destroy(s);
		return r;
	}
	for (size_t i = 0; i < ntriangles; i++) {
		const uint32_t *t = indices + 3 * (size_t)p[i].index;
		struct tri *tr = &s->tris[i];
		struct vec3 v[3], n;

		for (int k = 0; k < 3; k++) {
			memcpy(tr->v + 3 * k, positions + 3 * (size_t)t[k], 3 * sizeof(float));
			v[k] = vec3(tr->v[3 * k], tr->v[3 * k + 1], tr->v[3 * k + 2]);
		}
		n = vec3_cross(vec3_sub(v[1], v[0]), vec3_sub(v[2], v[0]));
		tr->index = p[i].index | (n.x == 0 && n.y == 0 && n.z == 0 ? FLAT : 0);
	}
	free(p);
	s->lo = vec3(s->nodes[0].box.lo[0], s->nodes[0].box.lo[1], s->nodes[0].box.lo[2]);
	s->hi = vec3(s->nodes[0].box.hi[0], s->nodes[0].box.hi[1], s->nodes[0].box.hi[2]);
	*out = s;
	return 0;
}

void vine_support_destroy(struct vine_support *s)
{
	if (!s)
		return;
	free(s->node_block);
	free(s->tris);
	free(s);
}

size_t vine_support_triangles(const struct vine_support *s)
{
	return s->ntriangles;
}

/* An empty support's box is the origin. */
void vine_support_bounds(const struct vine_support *s, struct vec3 *lo, struct vec3 *hi)
{
	*lo = s->lo;
	*hi = s->hi;
}

/* ---- The query ---- */

static double dist2(struct vec3 p, struct vec3 q)
{
	struct vec3 d = vec3_sub(p, q);

	return vec3_dot(d, d);
}

/* The nearest point to p on segment a-b (a itself if b is a), and its squared distance. */
static double segment_d2(struct vec3 p, struct vec3 a, struct vec3 b, struct vec3 *q)
{
	struct vec3 ab = vec3_sub(b, a);
	double len2 = vec3_dot(ab, ab), t = 0.0;

	if (len2 > 0) {
		t = vec3_dot(vec3_sub(p, a), ab) / len2;
		t = t < 0 ? 0 : t > 1 ? 1 : t;
	}
	*q = t == 0 ? a : t == 1 ? b : vec3_add(a, vec3_scale(ab, t));
	return dist2(p, *q);
}

/* A triangle as its edges: the nearest of them, the first on equal distance. */
static double edges_d2(struct vec3 p, struct vec3 a, struct vec3 b, struct vec3 c,
		       struct vec3 *q)
{
	struct vec3 q1, q2;
	double d0 = segment_d2(p, a, b, q);
	double d1 = segment_d2(p, b, c, &q1);
	double d2 = segment_d2(p, c, a, &q2);

	if (d1 < d0) {
		d0 = d1;
		*q = q1;
	}
	if (d2 < d0) {
		d0 = d2;
		*q = q2;
	}
	return d0;
}

/* Ericson's ClosestPtPointTriangle: the squared distance and the point. */
static double triangle_d2(const struct tri *t, struct vec3 p, struct vec3 *q)
{
	const float *f = t->v;
	struct vec3 a = vec3(f[0], f[1], f[2]), b = vec3(f[3], f[4], f[5]);
	struct vec3 c = vec3(f[6], f[7], f[8]), ab, ac, ap, bp, cp, n;
	double d1, d2, d3, d4, d5, d6, va, vb, vc, v, w;

	if (t->index & FLAT)
		return edges_d2(p, a, b, c, q);
	ab = vec3_sub(b, a);
	ac = vec3_sub(c, a);
	ap = vec3_sub(p, a);
	d1 = vec3_dot(ab, ap);
	d2 = vec3_dot(ac, ap);
	if (d1 <= 0 && d2 <= 0) { /* vertex a */
		*q = a;
		return dist2(p, a);
	}
	bp = vec3_sub(p, b);
	d3 = vec3_dot(ab, bp);
	d4 = vec3_dot(ac, bp);
	if (d3 >= 0 && d4 <= d3) { /* vertex b */
		*q = b;
		return dist2(p, b);
	}
	vc = d1 * d4 - d3 * d2;
	if (vc <= 0 && d1 >= 0 && d3 <= 0) { /* edge ab */
		v = d1 / (d1 - d3);
		*q = vec3_add(a, vec3_scale(ab, v));
		return dist2(p, *q);
	}
	cp = vec3_sub(p, c);
	d5 = vec3_dot(ab, cp);
	d6 = vec3_dot(ac, cp);
	if (d6 >= 0 && d5 <= d6) { /* vertex c */
		*q = c;
		return dist2(p, c);
	}
	vb = d5 * d2 - d1 * d6;
	if (vb <= 0 && d2 >= 0 && d6 <= 0) { /* edge ac */
		w = d2 / (d2 - d6);
		*q = vec3_add(a, vec3_scale(ac, w));
		return dist2(p, *q);
	}
	va = d3 * d6 - d5 * d4;
	if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) { /* edge bc */
		w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
		*q = vec3_add(b, vec3_scale(vec3_sub(c, b), w));
		return dist2(p, *q);
	}
	/* the face, unless rounding on a sliver says the point is beyond an edge */
	if (!(va >= 0 && vb >= 0 && vc >= 0 && va + vb + vc > 0))
		return edges_d2(p, a, b, c, q);
	n = vec3_cross(ab, ac);
	*q = vec3_sub(p, vec3_scale(n, vec3_dot(ap, n) / vec3_dot(n, n)));
	return dist2(p, *q);
}

/* How far p is from the box along one axis (0 inside): p less p clamped to the box,
 * which compiles to max and min, without a branch to mispredict. */
static inline double axis_d(double p, float lo, float hi)
{
	double l = lo, h = hi, c = p > l ? p : l;

	c = c < h ? c : h;
	return p - c;
}

static inline double box_d2(const struct box *b, struct vec3 p)
{
	double dx = axis_d(p.x, b->lo[0], b->hi[0]), dy = axis_d(p.y, b->lo[1], b->hi[1]);
	double dz = axis_d(p.z, b->lo[2], b->hi[2]);

	return dx * dx + dy * dy + dz * dz;
}

/* Whether a box at d2 can hold a triangle as near as best2, rounding allowed for. */
static inline bool box_open(double d2, double best2)
{
	return d2 * BOX_SLACK <= best2;
}

double vine_support_distance(const struct vine_support *s, struct vec3 p, double max,
			     struct vec3 *nearest, size_t *triangle)
{
	struct {
		uint32_t node;
		double d2;
	} stack[STACK];
	size_t top = 0;
	uint32_t ni = 0, best = UINT32_MAX;
	double best2, d;
	struct vec3 bestq = p;

	/* nothing is nearer than 0, nor than NaN; a point at infinity is nowhere */
	if (!(max > 0) || s->ntriangles == 0 || !isfinite(p.x) || !isfinite(p.y) ||
	    !isfinite(p.z))
		return max;
	/* max * max may round below a distance whose square root rounds below max: the
	 * slack lets such a triangle in, and the last test below decides */
	best2 = max * max / BOX_SLACK;
	if (!box_open(box_d2(&s->nodes[0].box, p), best2))
		return max;
	for (;;) {
		const struct node *n = &s->nodes[ni];

		if (n->count > 0) {
			for (uint32_t i = n->first; i < n->first + n->count; i++) {
				const struct tri *t = &s->tris[i];
				uint32_t index = t->index & ~FLAT;
				struct vec3 q;
				double d2 = triangle_d2(t, p, &q);

				if (d2 < best2 || (d2 == best2 && index < best)) {
					best2 = d2;
					best = index;
					bestq = q;
				}
			}
		} else {
			uint32_t c0 = n->first, c1 = c0 + 1;
			double d0 = box_d2(&s->nodes[c0].box, p), d1 = box_d2(&s->nodes[c1].box, p);

			if (d1 < d0) {
				uint32_t tc = c0;
				double td = d0;

				c0 = c1;
				d0 = d1;
				c1 = tc;
				d1 = td;
			}
			if (box_open(d0, best2)) {
				if (box_open(d1, best2)) {
					stack[top].node = c1;
					stack[top].d2 = d1;
					top++;
				}
				ni = c0;
				continue;
			}
		}
		/* the nearest waiting node that may still hold something nearer */
		while (top > 0 && !box_open(stack[top - 1].d2, best2))
			top--;
		if (top == 0)
			break;
		ni = stack[--top].node;
	}
	if (best == UINT32_MAX)
		return max;
	d = sqrt(best2);
	if (!(d < max))
		return max;
	if (nearest)
		*nearest = bestq;
	if (triangle)
		*triangle = best;
	return d;
}

/* ---- Crossing ---- */

/* Whether box b overlaps the box lo..hi (touching counts). */
static bool box_meets(const struct box *b, struct vec3 lo, struct vec3 hi)
{
	return b->lo[0] <= hi.x && b->hi[0] >= lo.x && b->lo[1] <= hi.y && b->hi[1] >= lo.y &&
	       b->lo[2] <= hi.z && b->hi[2] >= lo.z;
}

/* [d, p - a, q - a]: which side of the line a + s d edge p-q passes. Swapping p and q
 * negates it exactly, so the two triangles of an edge see it alike. */
static double edge_side(struct vec3 a, struct vec3 d, struct vec3 p, struct vec3 q)
{
	return vec3_dot(d, vec3_cross(vec3_sub(p, a), vec3_sub(q, a)));
}

/*
 * Segment a-b (d = b - a, box lo..hi) against a triangle: its ends not strictly on one
 * side of the plane, and the line through the triangle, its edges included (the signs of
 * the three edge products agree, a zero agreeing with either). A segment in the plane
 * meets it when their boxes overlap.
 */
static bool triangle_crossed(const struct tri *t, struct vec3 a, struct vec3 b, struct vec3 d,
			     struct vec3 lo, struct vec3 hi)
{
	const float *f = t->v;
	struct vec3 p0 = vec3(f[0], f[1], f[2]), p1 = vec3(f[3], f[4], f[5]);
	struct vec3 p2 = vec3(f[6], f[7], f[8]), n;
	double sa, sb, e0, e1, e2;

	if (t->index & FLAT)
		return false; /* no area: nothing to cross */
	n = vec3_cross(vec3_sub(p1, p0), vec3_sub(p2, p0));
	sa = vec3_dot(vec3_sub(a, p0), n);
	sb = vec3_dot(vec3_sub(b, p0), n);
	if ((sa > 0 && sb > 0) || (sa < 0 && sb < 0))
		return false;
	if (sa == 0 && sb == 0) {
		struct box tb = { { fminf(fminf(f[0], f[3]), f[6]), fminf(fminf(f[1], f[4]), f[7]),
				    fminf(fminf(f[2], f[5]), f[8]) },
				  { fmaxf(fmaxf(f[0], f[3]), f[6]), fmaxf(fmaxf(f[1], f[4]), f[7]),
				    fmaxf(fmaxf(f[2], f[5]), f[8]) } };

		return box_meets(&tb, lo, hi);
	}
	e0 = edge_side(a, d, p0, p1);
	e1 = edge_side(a, d, p1, p2);
	e2 = edge_side(a, d, p2, p0);
	return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
}

bool vine_support_crosses(const struct vine_support *s, struct vec3 a, struct vec3 b)
{
	uint32_t stack[STACK];
	size_t top = 0;
	struct vec3 lo, hi, d;

	if (s->ntriangles == 0 || !isfinite(a.x) || !isfinite(a.y) || !isfinite(a.z) ||
	    !isfinite(b.x) || !isfinite(b.y) || !isfinite(b.z))
		return false;
	lo = vec3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
	hi = vec3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
	d = vec3_sub(b, a);
	if (!box_meets(&s->nodes[0].box, lo, hi))
		return false;
	stack[top++] = 0;
	while (top > 0) {
		const struct node *n = &s->nodes[stack[--top]];

		if (n->count > 0) {
			for (uint32_t i = n->first; i < n->first + n->count; i++)
				if (triangle_crossed(&s->tris[i], a, b, d, lo, hi))
					return true;
			continue;
		}
		/* a level leaves at most one node waiting: the depth (<= 62) bounds the stack */
		for (uint32_t c = n->first; c < n->first + 2; c++)
			if (box_meets(&s->nodes[c].box, lo, hi))
				stack[top++] = c;
	}
	return false;
}
