/* SPDX-License-Identifier: MIT */
/*
 * The wood's bark at the forest's level of detail (docs/forest.md, "The wood and the
 * vines"): its iso-surface (wood_iso: closed, oriented, a manifold) made coarser by
 * half-edge collapses, the cheapest first by the quadric error metric (Garland and
 * Heckbert 1997: each vertex carries the sum of its faces' planes, squared and weighted by
 * their areas; a collapse costs the squared distances of the vertex kept from the planes of
 * both). A vertex goes into a neighbour and stays where that one is, so what is left is a
 * subset of the mesh's own vertices, their normals still the surface's. A collapse is
 * taken only if it keeps a closed manifold (the edge's two faces and the link condition;
 * never a tetrahedron flattened) and turns no face over; the vertices farthest along each
 * of +-x, +-y, +-z stay, so the wood's box does too. A grid's vertex clustering would
 * lose a limb thinner than its cell; collapses keep it, thinner.
 *
 * The order of the collapses does not depend on how many triangles are wanted, so it is
 * found once (lod_decimate_plan) and any budget takes a prefix of it. Same mesh, same
 * sequence: the heap orders equal costs by the vertices' numbers.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "forest_lod_private.h"

#define NONE UINT32_MAX
/* Rounds of every edge offered again when the heap runs dry (collapses refused before
 * may be taken once their neighbourhood has changed). */
#define DEC_ROUNDS 8

enum {
	DEC_GONE = 1u << 0,
	DEC_PINNED = 1u << 1,
};

struct cand {
	double cost;
	uint32_t from, to;
	uint32_t ver_from, ver_to;
};

struct dec {
	size_t nv, nf, live, dead_at_start;
	double *p;        /* 3 a vertex */
	double *q;        /* 10 a vertex: xx xy xz xw yy yz yw zz zw ww */
	uint32_t *f;      /* 3 a face: its vertices now */
	uint8_t *dead;    /* a face */
	/* each vertex's faces: a list of corners (corner c is face c / 3's), spliced on
	 * collapse; dead faces are unlinked as they are met */
	uint32_t *head, *tail, *next;
	uint32_t *ver;
	uint8_t *flags;
	uint32_t *mark, stamp;
	uint32_t *fu, *fv; /* scratch: faces of the two ends */
	size_t cap_fu, cap_fv;
	struct cand *heap;
	size_t nheap, cap_heap;
	struct lod_decimate *out;
	size_t cap_seq;
};

static bool cand_less(const struct cand *a, const struct cand *b)
{
	if (a->cost != b->cost)
		return a->cost < b->cost;
	if (a->from != b->from)
		return a->from < b->from;
	return a->to < b->to;
}

static int heap_push(struct dec *d, struct cand c)
{
	size_t i;

	if (d->nheap == d->cap_heap) {
		size_t cap = d->cap_heap ? 2 * d->cap_heap : 1024;
		struct cand *h = realloc(d->heap, cap * sizeof(*h));

		if (!h)
			return -ENOMEM;
		d->heap = h;
		d->cap_heap = cap;
	}
	i = d->nheap++;
	while (i > 0 && cand_less(&c, &d->heap[(i - 1) / 2])) {
		d->heap[i] = d->heap[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	d->heap[i] = c;
	return 0;
}

static struct cand heap_pop(struct dec *d)
{
	struct cand top = d->heap[0], last = d->heap[--d->nheap];
	size_t i = 0;

	for (;;) {
		size_t c = 2 * i + 1;

		if (c >= d->nheap)
			break;
		if (c + 1 < d->nheap && cand_less(&d->heap[c + 1], &d->heap[c]))
			c++;
		if (!cand_less(&d->heap[c], &last))
			break;
		d->heap[i] = d->heap[c];
		i = c;
	}
	if (d->nheap)
		d->heap[i] = last;
	return top;
}

/* ---- quadrics -------------------------------------------------------------------- */

static void quadric_add(double *q, const double n[3], double w0, double a)
{
	const double v[4] = { n[0], n[1], n[2], w0 };
	int k = 0;

	for (int i = 0; i < 4; i++)
		for (int j = i; j < 4; j++)
			q[k++] += a * v[i] * v[j];
}

/* p^T Q p for p = (x, y, z, 1). */
static double quadric_at(const double *q, const double *p)
{
	const double x = p[0], y = p[1], z = p[2];

	return q[0] * x * x + 2.0 * (q[1] * x * y + q[2] * x * z + q[3] * x) + q[4] * y * y +
	       2.0 * (q[5] * y * z + q[6] * y) + q[7] * z * z + 2.0 * q[8] * z + q[9];
}

static void face_normal(const double *a, const double *b, const double *c, double n[3])
{
	const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
	const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };

	n[0] = e1[1] * e2[2] - e1[2] * e2[1];
	n[1] = e1[2] * e2[0] - e1[0] * e2[2];
	n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

static void quadrics(struct dec *d)
{
	for (size_t f = 0; f < d->nf; f++) {
		const uint32_t *v = &d->f[3 * f];
		double n[3], len, w0;

		face_normal(&d->p[3 * v[0]], &d->p[3 * v[1]], &d->p[3 * v[2]], n);
		len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		if (!(len > 0.0) || !isfinite(len))
			continue;
		for (int k = 0; k < 3; k++)
			n[k] /= len;
		w0 = -(n[0] * d->p[3 * v[0]] + n[1] * d->p[3 * v[0] + 1] + n[2] * d->p[3 * v[0] + 2]);
		/* weighted by its area (len / 2) */
		for (int k = 0; k < 3; k++)
			quadric_add(&d->q[10 * v[k]], n, w0, 0.5 * len);
	}
}

/* ---- the faces about a vertex --------------------------------------------------------- */

static int grow_u32(uint32_t **a, size_t *cap, size_t n)
{
	uint32_t *p;
	size_t c;

	if (n <= *cap)
		return 0;
	c = *cap ? *cap : 16;
	while (c < n)
		c *= 2;
	p = realloc(*a, c * sizeof(*p));
	if (!p)
		return -ENOMEM;
	*a = p;
	*cap = c;
	return 0;
}

/* The live faces of vertex x into *out (grown), dead ones unlinked. Returns how many, or
 * (size_t)-1 without memory. */
static size_t faces_of(struct dec *d, uint32_t x, uint32_t **out, size_t *cap)
{
	uint32_t prev = NONE, c = d->head[x];
	size_t n = 0;

	while (c != NONE) {
		uint32_t nx = d->next[c];

		if (d->dead[c / 3]) {
			if (prev == NONE)
				d->head[x] = nx;
			else
				d->next[prev] = nx;
			if (d->tail[x] == c)
				d->tail[x] = prev;
		} else {
			if (grow_u32(out, cap, n + 1) < 0)
				return (size_t)-1;
			(*out)[n++] = c / 3;
			prev = c;
		}
		c = nx;
	}
	return n;
}

static bool face_has(const struct dec *d, uint32_t f, uint32_t v)
{
	return d->f[3 * f] == v || d->f[3 * f + 1] == v || d->f[3 * f + 2] == v;
}

/* ---- candidates ------------------------------------------------------------------------ */

/* The edge a-b offered, in the direction that costs less (a pinned vertex never goes). */
static int offer(struct dec *d, uint32_t a, uint32_t b)
{
	bool ab = !(d->flags[a] & DEC_PINNED), ba = !(d->flags[b] & DEC_PINNED);
	double cab, cba;
	struct cand c;

	if (!ab && !ba)
		return 0;
	/* a into b: the vertex kept is b, where it is */
	cab = quadric_at(&d->q[10 * a], &d->p[3 * b]) + quadric_at(&d->q[10 * b], &d->p[3 * b]);
	cba = quadric_at(&d->q[10 * a], &d->p[3 * a]) + quadric_at(&d->q[10 * b], &d->p[3 * a]);
	cab = isfinite(cab) ? cab : HUGE_VAL;
	cba = isfinite(cba) ? cba : HUGE_VAL;
	if (ab && (!ba || cab < cba || (cab == cba && a > b)))
		c = (struct cand){ cab, a, b, d->ver[a], d->ver[b] };
	else
		c = (struct cand){ cba, b, a, d->ver[b], d->ver[a] };
	return heap_push(d, c);
}

/* Every edge of a live face offered once (a consistently oriented manifold has each edge
 * once as a -> b with a < b). */
static int offer_all(struct dec *d)
{
	int r = 0;

	for (size_t f = 0; f < d->nf && r == 0; f++) {
		if (d->dead[f])
			continue;
		for (int k = 0; k < 3 && r == 0; k++) {
			uint32_t a = d->f[3 * f + k], b = d->f[3 * f + (k + 1) % 3];

			if (a < b)
				r = offer(d, a, b);
		}
	}
	return r;
}

/*
 * Whether u may go into v: the edge has two faces (a manifold's), the two ends share no
 * neighbour but those faces' third vertices (the link condition: no fold, no pinch), the
 * mesh is more than a tetrahedron there, and no other face of u turns over or flattens
 * as u moves to v. nu, nv: the faces of u and v (in d->fu, d->fv). -ENOMEM, 0 (no) or 1.
 */
static int may_collapse(struct dec *d, uint32_t u, uint32_t v, size_t nu, size_t nv)
{
	uint32_t s1, s2, shared = 0, common = 0;

	for (size_t i = 0; i < nu; i++)
		shared += face_has(d, d->fu[i], v);
	if (shared != 2 || (nu == 3 && nv == 3))
		return 0;
	s1 = ++d->stamp;
	s2 = ++d->stamp;
	for (size_t i = 0; i < nu; i++)
		for (int k = 0; k < 3; k++)
			d->mark[d->f[3 * d->fu[i] + k]] = s1;
	for (size_t i = 0; i < nv; i++) {
		for (int k = 0; k < 3; k++) {
			uint32_t w = d->f[3 * d->fv[i] + k];

			if (w != u && w != v && d->mark[w] == s1) {
				d->mark[w] = s2;
				common++;
			}
		}
	}
	if (common != 2)
		return 0;
	for (size_t i = 0; i < nu; i++) {
		uint32_t f = d->fu[i];
		const double *c[3], *c2[3];
		double n0[3], n1[3], dot, l0, l1;

		if (face_has(d, f, v))
			continue;
		for (int k = 0; k < 3; k++) {
			uint32_t w = d->f[3 * f + k];

			c[k] = &d->p[3 * w];
			c2[k] = w == u ? &d->p[3 * v] : c[k];
		}
		face_normal(c[0], c[1], c[2], n0);
		face_normal(c2[0], c2[1], c2[2], n1);
		dot = n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2];
		l0 = n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2];
		l1 = n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2];
		/* turned over, or (next to) a sliver of no area */
		if (!(dot > 0.0) || !(l1 > 1e-12 * l0))
			return 0;
	}
	return 1;
}

static int record(struct dec *d, uint32_t u, uint32_t v)
{
	struct lod_decimate *o = d->out;

	if (o->n == d->cap_seq) {
		size_t cap = d->cap_seq ? 2 * d->cap_seq : 256;
		uint32_t *a = realloc(o->from, cap * sizeof(*a)), *b;

		if (!a)
			return -ENOMEM;
		o->from = a;
		b = realloc(o->to, cap * sizeof(*b));
		if (!b)
			return -ENOMEM;
		o->to = b;
		d->cap_seq = cap;
	}
	o->from[o->n] = u;
	o->to[o->n] = v;
	o->n++;
	return 0;
}

/* u goes into v; v's edges are offered again. */
static int collapse(struct dec *d, uint32_t u, uint32_t v, size_t nu)
{
	size_t nv;
	uint32_t s;
	int r;

	for (size_t i = 0; i < nu; i++) {
		uint32_t f = d->fu[i];

		if (face_has(d, f, v)) {
			d->dead[f] = 1;
			d->live--;
			continue;
		}
		for (int k = 0; k < 3; k++)
			if (d->f[3 * f + k] == u)
				d->f[3 * f + k] = v;
	}
	/* u's corners become v's */
	if (d->head[u] != NONE) {
		if (d->head[v] == NONE)
			d->head[v] = d->head[u];
		else
			d->next[d->tail[v]] = d->head[u];
		d->tail[v] = d->tail[u];
		d->head[u] = d->tail[u] = NONE;
	}
	for (int k = 0; k < 10; k++)
		d->q[10 * v + k] += d->q[10 * u + k];
	d->flags[u] |= DEC_GONE;
	d->ver[v]++;
	r = record(d, u, v);
	if (r < 0)
		return r;
	nv = faces_of(d, v, &d->fv, &d->cap_fv);
	if (nv == (size_t)-1)
		return -ENOMEM;
	s = ++d->stamp;
	for (size_t i = 0; i < nv && r == 0; i++) {
		for (int k = 0; k < 3 && r == 0; k++) {
			uint32_t w = d->f[3 * d->fv[i] + k];

			if (w == v || d->mark[w] == s)
				continue;
			d->mark[w] = s;
			r = offer(d, v, w);
		}
	}
	return r;
}

/* Collapses, cheapest first, until the heap runs dry. *done counts them. */
static int run(struct dec *d, size_t *done)
{
	while (d->nheap) {
		struct cand c = heap_pop(d);
		size_t nu, nv;
		int ok;

		if ((d->flags[c.from] | d->flags[c.to]) & DEC_GONE || d->ver[c.from] != c.ver_from ||
		    d->ver[c.to] != c.ver_to)
			continue; /* an edge that is no more, or priced before a change */
		nu = faces_of(d, c.from, &d->fu, &d->cap_fu);
		nv = faces_of(d, c.to, &d->fv, &d->cap_fv);
		if (nu == (size_t)-1 || nv == (size_t)-1)
			return -ENOMEM;
		ok = may_collapse(d, c.from, c.to, nu, nv);
		if (ok < 0)
			return ok;
		if (!ok)
			continue;
		ok = collapse(d, c.from, c.to, nu);
		if (ok < 0)
			return ok;
		(*done)++;
	}
	return 0;
}

/* The first vertex of a face farthest along each of +-x, +-y, +-z stays. */
static void pin_extremes(struct dec *d)
{
	for (int k = 0; k < 3; k++) {
		uint32_t lo = NONE, hi = NONE;

		for (size_t f = 0; f < d->nf; f++) {
			for (int c = 0; c < 3; c++) {
				uint32_t v = d->f[3 * f + c];

				if (lo == NONE || d->p[3 * v + k] < d->p[3 * lo + k] ||
				    (d->p[3 * v + k] == d->p[3 * lo + k] && v < lo))
					lo = v;
				if (hi == NONE || d->p[3 * v + k] > d->p[3 * hi + k] ||
				    (d->p[3 * v + k] == d->p[3 * hi + k] && v < hi))
					hi = v;
			}
		}
		if (lo != NONE)
			d->flags[lo] |= DEC_PINNED;
		if (hi != NONE)
			d->flags[hi] |= DEC_PINNED;
	}
}

static void dec_finish(struct dec *d)
{
	free(d->p);
	free(d->q);
	free(d->f);
	free(d->dead);
	free(d->head);
	free(d->tail);
	free(d->next);
	free(d->ver);
	free(d->flags);
	free(d->mark);
	free(d->fu);
	free(d->fv);
	free(d->heap);
}

static int dec_init(struct dec *d, const struct mesh *m)
{
	size_t nv = m->nvertices, nf = m->nindices / 3;

	memset(d, 0, sizeof(*d));
	d->nv = nv;
	d->nf = nf;
	d->live = nf;
	if (nv >= NONE || 3 * nf >= NONE)
		return -EINVAL;
	d->p = malloc((nv ? nv : 1) * 3 * sizeof(*d->p));
	d->q = calloc(nv ? nv : 1, 10 * sizeof(*d->q));
	d->f = malloc((nf ? nf : 1) * 3 * sizeof(*d->f));
	d->dead = calloc(nf ? nf : 1, 1);
	d->head = malloc((nv ? nv : 1) * sizeof(*d->head));
	d->tail = malloc((nv ? nv : 1) * sizeof(*d->tail));
	d->next = malloc((nf ? nf : 1) * 3 * sizeof(*d->next));
	d->ver = calloc(nv ? nv : 1, sizeof(*d->ver));
	d->flags = calloc(nv ? nv : 1, 1);
	d->mark = calloc(nv ? nv : 1, sizeof(*d->mark));
	if (!d->p || !d->q || !d->f || !d->dead || !d->head || !d->tail || !d->next || !d->ver ||
	    !d->flags || !d->mark)
		return -ENOMEM;
	for (size_t i = 0; i < 3 * nv; i++)
		d->p[i] = m->positions[i];
	for (size_t v = 0; v < nv; v++)
		d->head[v] = d->tail[v] = NONE;
	for (size_t c = 0; c < 3 * nf; c++) {
		uint32_t v = m->indices[c];

		if (v >= nv)
			return -EINVAL;
		d->f[c] = v;
		d->next[c] = NONE;
		/* corners in order: each vertex's list is its faces in order */
		if (d->head[v] == NONE)
			d->head[v] = (uint32_t)c;
		else
			d->next[d->tail[v]] = (uint32_t)c;
		d->tail[v] = (uint32_t)c;
	}
	/* a face with a vertex twice is no face: left out from the start */
	for (size_t f = 0; f < nf; f++) {
		const uint32_t *v = &d->f[3 * f];

		if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
			d->dead[f] = 1;
			d->live--;
			d->dead_at_start++;
		}
	}
	quadrics(d);
	pin_extremes(d);
	return 0;
}

void lod_decimate_init(struct lod_decimate *d)
{
	memset(d, 0, sizeof(*d));
}

void lod_decimate_finish(struct lod_decimate *d)
{
	free(d->from);
	free(d->to);
	lod_decimate_init(d);
}

int lod_decimate_plan(struct lod_decimate *out, const struct mesh *m)
{
	struct dec d;
	int r;

	lod_decimate_finish(out);
	out->m = m;
	r = dec_init(&d, m);
	d.out = out;
	if (r == 0)
		r = offer_all(&d);
	for (int round = 0; r == 0 && round < DEC_ROUNDS; round++) {
		size_t done = 0;

		r = run(&d, &done);
		if (r < 0 || done == 0)
			break;
		r = offer_all(&d);
	}
	out->start = d.nf - d.dead_at_start;
	out->fewest = d.live;
	dec_finish(&d);
	if (r < 0) {
		lod_decimate_finish(out);
		out->m = m;
	}
	return r;
}

/* Collapses that bring the triangles to max or below (each takes two), or all. */
static size_t collapses_for(const struct lod_decimate *d, size_t max)
{
	size_t k;

	if (d->start <= max)
		return 0;
	k = (d->start - max + 1) / 2;
	return k < d->n ? k : d->n;
}

size_t lod_decimate_triangles(const struct lod_decimate *d, size_t max)
{
	return d->start - 2 * collapses_for(d, max);
}

/* Where vertex v went after the collapses (rep[x] == x: it stays). */
static uint32_t find(uint32_t *rep, uint32_t v)
{
	uint32_t r = v;

	while (rep[r] != r)
		r = rep[r];
	while (rep[v] != r) {
		uint32_t n = rep[v];

		rep[v] = r;
		v = n;
	}
	return r;
}

int lod_decimate_apply(const struct lod_decimate *d, size_t max, struct mesh *out)
{
	const struct mesh *m = d->m;
	size_t nv = m->nvertices, nf = m->nindices / 3, k = collapses_for(d, max), keep_v = 0;
	size_t keep_f = 0, v0 = out->nvertices, i0 = out->nindices;
	uint32_t *rep = malloc((nv ? nv : 1) * sizeof(*rep));
	uint32_t *at = malloc((nv ? nv : 1) * sizeof(*at));
	int r = -ENOMEM;

	if (!rep || !at)
		goto done;
	for (size_t v = 0; v < nv; v++) {
		rep[v] = (uint32_t)v;
		at[v] = NONE;
	}
	for (size_t i = 0; i < k; i++)
		rep[d->from[i]] = d->to[i];
	/* a face stays when its corners are still three vertices */
	for (size_t f = 0; f < nf; f++) {
		uint32_t a = find(rep, m->indices[3 * f]), b = find(rep, m->indices[3 * f + 1]);
		uint32_t c = find(rep, m->indices[3 * f + 2]);

		if (a == b || b == c || a == c)
			continue;
		keep_f++;
		at[a] = at[b] = at[c] = 0;
	}
	for (size_t v = 0; v < nv; v++)
		if (at[v] == 0)
			keep_v++;
	r = -EINVAL;
	if (keep_v > UINT32_MAX - v0)
		goto done;
	r = mesh_reserve(out, keep_v, 3 * keep_f);
	if (r < 0)
		goto done;
	for (size_t v = 0; v < nv; v++) {
		if (at[v] != 0)
			continue;
		at[v] = (uint32_t)out->nvertices;
		memcpy(&out->positions[3 * out->nvertices], &m->positions[3 * v], 3 * sizeof(float));
		memcpy(&out->normals[3 * out->nvertices], &m->normals[3 * v], 3 * sizeof(float));
		out->nvertices++;
	}
	for (size_t f = 0; f < nf; f++) {
		uint32_t c[3];

		for (int j = 0; j < 3; j++)
			c[j] = find(rep, m->indices[3 * f + (size_t)j]);
		if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
			continue;
		for (int j = 0; j < 3; j++)
			out->indices[out->nindices++] = at[c[j]];
	}
	r = 0;
done:
	if (r < 0) {
		out->nvertices = v0;
		out->nindices = i0;
	}
	free(at);
	free(rep);
	return r;
}

int forest_lod_decimate(const struct mesh *m, size_t max_triangles, struct mesh *out,
			size_t *fewest)
{
	struct lod_decimate d;
	int r;

	lod_decimate_init(&d);
	r = lod_decimate_plan(&d, m);
	if (r == 0)
		r = lod_decimate_apply(&d, max_triangles, out);
	if (r == 0 && fewest)
		*fewest = d.fewest;
	lod_decimate_finish(&d);
	return r;
}
