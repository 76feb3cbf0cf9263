/* SPDX-License-Identifier: MIT */
#include "mesh.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "frame.h"
#include "ori_kinds.h"
#include "view.h"

/* Tubes never get thinner than this, so no ring collapses into a point (no zero-area faces). */
#define TUBE_MIN_RADIUS 0.0005
/* Consecutive points closer than this (metres) are the same point. */
#define TUBE_MIN_STEP 1e-6
/* The tip closes with a cone this many tip radii long: reads as a rounded end. */
#define TUBE_TIP_LENGTH 1.0
/* Limits how far taper tilts the smooth normals (|dr/ds|), so steep tapers still shade sanely. */
#define TUBE_MAX_SLOPE 3.0
/* A child's root ring stays within this fraction of the room its parent's tube leaves it
 * (the parent's rings lean at bends, which narrows its tube a little between them). */
#define TUBE_JOINT_MARGIN 0.9
/* Consecutive leaf points closer than this (metres) are the same point. */
#define LEAF_MIN_STEP 1e-7

/* Pixels a metre at the reference screen height (see mesh.h). */
#define TUBE_PX_PER_M (MESH_REF_SCREEN_PX / VIEW_HEIGHT_M)

void tree_mesh_init(struct tree_mesh *tm)
{
	mesh_init(&tm->bark);
	mesh_init(&tm->leaves);
}

void tree_mesh_finish(struct tree_mesh *tm)
{
	mesh_finish(&tm->bark);
	mesh_finish(&tm->leaves);
}

static size_t grow_cap(size_t cap, size_t need)
{
	size_t ncap = cap ? cap : 256;

	while (ncap < need)
		ncap *= 2;
	return ncap;
}

static uint32_t mesh_push_vertex(struct mesh *m, struct vec3 p, struct vec3 n)
{
	float *pos = &m->positions[3 * m->nvertices];
	float *nor = &m->normals[3 * m->nvertices];

	pos[0] = (float)p.x;
	pos[1] = (float)p.y;
	pos[2] = (float)p.z;
	nor[0] = (float)n.x;
	nor[1] = (float)n.y;
	nor[2] = (float)n.z;
	return (uint32_t)m->nvertices++;
}

static void mesh_push_tri(struct mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t *idx = &m->indices[m->nindices];

	idx[0] = a;
	idx[1] = b;
	idx[2] = c;
	m->nindices += 3;
}

static bool vec3_finite(struct vec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* Ring shapes for every side count, and what each count costs in accuracy. */
struct lod {
	/* 1 - cos(pi / sides): how far a polygon's edge middles fall inside its circle. */
	double sag[MESH_MAX_SIDES + 1];
	double cs[MESH_MAX_SIDES + 1][MESH_MAX_SIDES], sn[MESH_MAX_SIDES + 1][MESH_MAX_SIDES];
	double cos_turn, sin_turn; /* of MESH_DROP_TURN_DEG */
	int fixed; /* every ring's sides (a tree's `sides`), or 0: by radius */
};

static void lod_init(struct lod *l)
{
	memset(l, 0, sizeof(*l));
	for (int s = MESH_MIN_SIDES; s <= MESH_MAX_SIDES; s++) {
		l->sag[s] = 1.0 - cos(VEC_PI / s);
		for (int j = 0; j < s; j++) {
			l->cs[s][j] = cos(2.0 * VEC_PI * j / s);
			l->sn[s][j] = sin(2.0 * VEC_PI * j / s);
		}
	}
	l->cos_turn = cos(MESH_DROP_TURN_DEG * VEC_PI / 180.0);
	l->sin_turn = sin(MESH_DROP_TURN_DEG * VEC_PI / 180.0);
}

static int lod_sides(const struct lod *l, double radius)
{
	double px = radius * TUBE_PX_PER_M;
	int s = MESH_MIN_SIDES;

	if (l->fixed)
		return l->fixed;
	if (!(px > 0)) /* NaN too */
		return s;
	while (s < MESH_MAX_SIDES && px * l->sag[s] > MESH_SIDE_ERROR_PX)
		s++;
	return s;
}

int mesh_ring_sides(double radius)
{
	struct lod l;

	lod_init(&l);
	return lod_sides(&l, radius);
}

double mesh_drop_tolerance(double radius)
{
	double px = MESH_DROP_ERROR_PX / TUBE_PX_PER_M, rel = MESH_DROP_RADIUS_FRACTION * radius;

	return rel < px ? rel : px;
}

/* A tree's fixed ring sides within what the tables hold, or 0 (by radius). */
static int tree_sides(const struct tree *t)
{
	if (t->sides <= 0)
		return 0;
	return t->sides < MESH_MIN_SIDES ? MESH_MIN_SIDES : t->sides > MESH_MAX_SIDES ? MESH_MAX_SIDES : t->sides;
}

/* Per-build scratch arrays, grown to the longest polyline seen, reused across elements. */
struct scratch {
	struct vec3 *p; /* cleaned points */
	struct vec3 *t; /* tangents */
	struct vec3 *n; /* frame normals */
	double *r;      /* radii */
	int *sides;     /* ring sides */
	double *x, *y;  /* leaf points in their plane */
	size_t *live;   /* leaf polygon vertices not clipped yet */
	size_t cap;
	struct lod lod;
	/* Branches that children's roots hide in, cleaned once per build: branch i's points
	 * are hp/hx/hy[host_at[i] ..] (position, arc length, radius), host_n[i] of them;
	 * host_at[i] == SIZE_MAX until needed. host_at/host_n have nhosts entries. */
	size_t *host_at, *host_n, nhosts;
	struct vec3 *hp;
	double *hx, *hy;
	size_t hlen, hcap;
};

static void scratch_finish(struct scratch *s)
{
	free(s->p);
	free(s->t);
	free(s->n);
	free(s->r);
	free(s->sides);
	free(s->x);
	free(s->y);
	free(s->live);
	free(s->host_at);
	free(s->host_n);
	free(s->hp);
	free(s->hx);
	free(s->hy);
	memset(s, 0, sizeof(*s));
}

#define SCRATCH_GROW(field, cap)                                                  \
	do {                                                                      \
		void *p_ = realloc(s->field, (cap) * sizeof(*s->field));          \
		if (!p_)                                                          \
			return -ENOMEM;                                           \
		s->field = p_;                                                    \
	} while (0)

static int scratch_reserve(struct scratch *s, size_t n)
{
	size_t cap;

	if (n <= s->cap)
		return 0;
	if (n > SIZE_MAX / 2 / sizeof(struct vec3))
		return -ENOMEM;
	cap = grow_cap(s->cap, n);
	/* s->cap only moves once every array has the new size. */
	SCRATCH_GROW(p, cap);
	SCRATCH_GROW(t, cap);
	SCRATCH_GROW(n, cap);
	SCRATCH_GROW(r, cap);
	SCRATCH_GROW(sides, cap);
	SCRATCH_GROW(x, cap);
	SCRATCH_GROW(y, cap);
	SCRATCH_GROW(live, cap);
	s->cap = cap;
	return 0;
}

/*
 * A branch's usable points one by one: finite, radius clamped, consecutive duplicates
 * merged. The tube and the joint test of its children see the same polyline.
 */
struct walk {
	const struct branch *b;
	size_t i, n; /* next raw point; cleaned points so far */
	struct vec3 prev;
};

static void walk_init(struct walk *w, const struct branch *b)
{
	w->b = b;
	w->i = 0;
	w->n = 0;
	w->prev = vec3(0, 0, 0);
}

static bool walk_next(struct walk *w, struct vec3 *p, double *radius)
{
	while (w->i < w->b->npoints) {
		struct vec3 q = w->b->points[w->i];
		double r = w->b->radii ? w->b->radii[w->i] : 0.0;

		w->i++;
		if (!vec3_finite(q))
			continue;
		if (!isfinite(r) || r < TUBE_MIN_RADIUS)
			r = TUBE_MIN_RADIUS;
		if (w->n > 0) {
			struct vec3 d = vec3_sub(q, w->prev);

			if (vec3_dot(d, d) <= TUBE_MIN_STEP * TUBE_MIN_STEP)
				continue;
		}
		w->prev = q;
		w->n++;
		*p = q;
		*radius = r;
		return true;
	}
	return false;
}

static size_t tube_clean(const struct branch *b, struct scratch *s)
{
	struct walk w;
	size_t k = 0;

	walk_init(&w, b);
	while (walk_next(&w, &s->p[k], &s->r[k]))
		k++;
	return k;
}

/* fmin/fmax are library calls; these see only finite numbers. */
static double dmin(double a, double b)
{
	return a < b ? a : b;
}

static double dmax(double a, double b)
{
	return a > b ? a : b;
}

/* A host branch's cleaned points, as joint_room reads them. */
struct host {
	const struct vec3 *p;
	const double *x, *r; /* arc length, radius */
	size_t n;
	double r0; /* radius at point 0: TUBE_MIN_RADIUS if its root ring may have shrunk */
};

/* Branch `b`'s cleaned points, from the cache or walked into it. 0 or -ENOMEM. */
static int host_get(struct scratch *s, const struct tree *t, int b, struct host *h)
{
	const struct branch *br = &t->branches[b];
	size_t at;

	if (s->nhosts < t->nbranches) {
		size_t *a = realloc(s->host_at, t->nbranches * sizeof(*a));

		if (!a)
			return -ENOMEM;
		s->host_at = a;
		a = realloc(s->host_n, t->nbranches * sizeof(*a));
		if (!a)
			return -ENOMEM;
		s->host_n = a;
		for (size_t i = s->nhosts; i < t->nbranches; i++)
			s->host_at[i] = SIZE_MAX;
		s->nhosts = t->nbranches;
	}
	if (s->host_at[b] == SIZE_MAX) {
		struct walk w;
		struct vec3 q;
		double r;
		size_t n = 0;

		if (br->npoints > s->hcap - s->hlen) {
			size_t cap;
			void *np;

			if (br->npoints > SIZE_MAX / 2 / sizeof(struct vec3) - s->hlen)
				return -ENOMEM;
			cap = grow_cap(s->hcap, s->hlen + br->npoints);
			np = realloc(s->hp, cap * sizeof(*s->hp));
			if (!np)
				return -ENOMEM;
			s->hp = np;
			np = realloc(s->hx, cap * sizeof(*s->hx));
			if (!np)
				return -ENOMEM;
			s->hx = np;
			np = realloc(s->hy, cap * sizeof(*s->hy));
			if (!np)
				return -ENOMEM;
			s->hy = np;
			s->hcap = cap;
		}
		walk_init(&w, br);
		while (walk_next(&w, &q, &r)) {
			size_t i = s->hlen + n;

			s->hp[i] = q;
			s->hy[i] = r;
			s->hx[i] = n ? s->hx[i - 1] + vec3_dist(s->hp[i - 1], q) : 0.0;
			n++;
		}
		s->host_at[b] = s->hlen;
		s->host_n[b] = n;
		s->hlen += n;
	}
	at = s->host_at[b];
	h->p = &s->hp[at];
	h->x = &s->hx[at];
	h->r = &s->hy[at];
	h->n = s->host_n[b];
	h->r0 = h->n ? h->r[0] : 0.0;
	if (br->parent >= 0 && br->parent < b)
		h->r0 = TUBE_MIN_RADIUS;
	return 0;
}

static double host_r(const struct host *h, size_t i)
{
	return i == 0 ? h->r0 : h->r[i];
}

/* Radius of segment i of the host at arc length `at`. */
static double host_lerp(const struct host *h, size_t i, double at)
{
	double r0 = host_r(h, i);

	return r0 + (h->r[i + 1] - r0) * (at - h->x[i]) / (h->x[i + 1] - h->x[i]);
}

/* The segment holding arc length `at` (the first or last one beyond the ends). */
static size_t host_segment(const struct host *h, double at)
{
	size_t lo = 0, hi = h->n - 1;

	/* invariant: x[lo] <= at < x[hi], or at the ends */
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (h->x[mid] <= at)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

/* Nearest point to `root` on host segments [j0, j1]: segment, fraction, squared distance. */
static void host_nearest(const struct host *h, struct vec3 root, size_t j0, size_t j1, size_t *jq,
			 double *fq, double *best2)
{
	for (size_t j = j0; j <= j1; j++) {
		struct vec3 e = vec3_sub(h->p[j + 1], h->p[j]), q;
		double f = vec3_dot(vec3_sub(root, h->p[j]), e) / vec3_dot(e, e), d2;

		f = f < 0 ? 0 : f > 1 ? 1 : f;
		q = vec3_sub(root, vec3_add(h->p[j], vec3_scale(e, f)));
		d2 = vec3_dot(q, q);
		if (d2 < *best2) {
			*best2 = d2;
			*jq = j;
			*fq = f;
		}
	}
}

/* A root is looked for this many segments either side of where its parent_t puts it. */
#define JOINT_LOOK_SEGMENTS 2

/*
 * How large a child's root ring (centre `root`, facing unit `dir`, radius at most rc) may
 * be and still lie inside the tube of host h (its parent or grandparent). Returns false
 * when the root is not inside that tube's radius at all.
 *
 * The root is looked for near arc-length parameter `hint` of the host (the attachment
 * point the tree records), a few segments either way; with `scan`, over the whole host if
 * it is not there (sketching and lifting always record it right, so a child costs the
 * same on a long parent as on a short one).
 *
 * Let q be the nearest point found, d the distance to it, a the host's direction there,
 * S = |dir x a| plus the few degrees a tangent may turn when rings are left out. A ring
 * point at offset y*rho along a (|y| <= S) lies rho*sqrt(1 - y^2) + d from the axis, and
 * the host's tube there holds a circle of k*R(s_q + y*rho) - tol, where
 * k = cos(pi / sides) * TUBE_JOINT_MARGIN (a polygon's inscribed circle, with the fewest
 * sides of the host's points over the reach and of the kept rings around q, whichever
 * they are), tol = mesh_drop_tolerance (how far left-out rings let the tube stray from its
 * polyline) and R the radius profile: piecewise linear, then the tip cone. With L its
 * steepest slope over the ring's reach, R(s_q + y*rho) >= R(s_q) - L*rho*|y|, so it
 * suffices that rho * max(sqrt(1 - y^2) + k*L*|y|) <= k*(R(s_q) - L*d) - tol - d. The
 * host's root disc is a cliff: the ring may not reach behind it.
 */
static bool joint_room(const struct host *h, double hint, bool scan, struct vec3 root,
		       struct vec3 dir, double rc, const struct lod *lod, double *room)
{
	double best2 = INFINITY, fq = 0.0, d, len, sq, rq, sn, reach, lo, hi, rside;
	double slope = 0.0, k, kl, den, fit;
	size_t jq = 0, j0, j1, i;
	struct vec3 a;
	int sj;

	if (h->n < 2)
		return false;
	len = h->x[h->n - 1];
	hint = hint >= 0 && hint <= 1 ? hint : 0.0; /* NaN too */
	j0 = host_segment(h, hint * len);
	j1 = j0 + JOINT_LOOK_SEGMENTS < h->n - 2 ? j0 + JOINT_LOOK_SEGMENTS : h->n - 2;
	j0 = j0 > JOINT_LOOK_SEGMENTS ? j0 - JOINT_LOOK_SEGMENTS : 0;
	host_nearest(h, root, j0, j1, &jq, &fq, &best2);
	sq = h->x[jq] + fq * (h->x[jq + 1] - h->x[jq]);
	if (scan && !(sqrt(best2) < host_lerp(h, jq, sq))) {
		best2 = INFINITY;
		host_nearest(h, root, 0, h->n - 2, &jq, &fq, &best2);
		sq = h->x[jq] + fq * (h->x[jq + 1] - h->x[jq]);
	}
	d = sqrt(best2);
	/* (judged on the drawn root radius: whether the root is on the host at all) */
	if (!(d < h->r[jq] + fq * (h->r[jq + 1] - h->r[jq])))
		return false;
	rq = host_lerp(h, jq, sq);
	a = vec3_norm_or(vec3_sub(h->p[jq + 1], h->p[jq]), vec3(0, 1, 0));

	/* The ring's reach along the host, and the steepest radius slope over it. */
	sn = dmin(1.0, vec3_len(vec3_cross(dir, a)) + lod->sin_turn);
	reach = rc * sn + d;
	lo = sq - reach;
	hi = sq + reach;
	rside = dmin(host_r(h, jq), h->r[jq + 1]);
	for (i = host_segment(h, lo); i + 1 < h->n && h->x[i] <= hi; i++) {
		slope = dmax(slope, fabs(h->r[i + 1] - host_r(h, i)) / (h->x[i + 1] - h->x[i]));
		rside = dmin(rside, dmin(host_r(h, i), h->r[i + 1]));
	}
	if (hi > len)
		slope = dmax(slope, 1.0 / TUBE_TIP_LENGTH);
	/* The fewest sides of the kept rings around q: points left out have the sides of the
	 * kept ring before them, so that ring has point jq's (or jq + 1's, if left out) and the
	 * one after is no further than the first point past jq + 1 whose count differs. */
	sj = lod_sides(lod, h->r[jq + 1]);
	for (i = jq + 1; i < h->n && i <= jq + MESH_DROP_MAX_SPAN; i++) {
		rside = dmin(rside, h->r[i]);
		if (lod_sides(lod, h->r[i]) != sj)
			break;
	}
	k = (1.0 - lod->sag[lod_sides(lod, rside)]) * TUBE_JOINT_MARGIN;

	/* max of sqrt(1 - y^2) + kl*y over 0 <= y <= sn */
	kl = k * slope;
	den = sn * sqrt(1.0 + kl * kl) >= kl ? sqrt(1.0 + kl * kl) : sqrt(1.0 - sn * sn) + kl * sn;
	fit = (k * (rq - slope * d) - mesh_drop_tolerance(dmax(h->r[jq], h->r[jq + 1])) - d) / den;
	if (lo < 0)
		fit = dmin(fit, (sq - d) / sn);
	*room = fit;
	return true;
}

/*
 * The root ring of branch `index` (centre root, facing dir, drawn radius *rc) shrinks until
 * it lies inside its parent's tube, or its grandparent's where that leaves more room (a
 * child near its parent's root: looked for where the parent hangs on it); never below
 * TUBE_MIN_RADIUS. A root that is not on its parent stays as drawn. 0 or -ENOMEM.
 */
static int joint_radius(const struct tree *t, size_t index, struct vec3 root, struct vec3 dir,
			double *rc, struct scratch *s)
{
	const struct branch *br = &t->branches[index];
	int parent = br->parent, gp;
	struct host h;
	double room, room2;
	int r;

	if (parent < 0 || (size_t)parent >= index)
		return 0;
	r = host_get(s, t, parent, &h);
	if (r < 0)
		return r;
	if (!joint_room(&h, br->parent_t, true, root, dir, *rc, &s->lod, &room) || room >= *rc)
		return 0;
	gp = t->branches[parent].parent;
	if (gp >= 0 && gp < parent) {
		r = host_get(s, t, gp, &h);
		if (r < 0)
			return r;
		if (joint_room(&h, t->branches[parent].parent_t, false, root, dir, *rc, &s->lod,
			       &room2))
			room = dmax(room, room2);
	}
	*rc = dmax(dmin(room, *rc), TUBE_MIN_RADIUS);
	return 0;
}

/* Does the branch turn by at most MESH_DROP_TURN_DEG at point i? */
static bool tube_turn_ok(const struct scratch *s, size_t i, double cos_turn)
{
	struct vec3 in = vec3_sub(s->p[i], s->p[i - 1]), out = vec3_sub(s->p[i + 1], s->p[i]);

	return vec3_dot(in, out) >= cos_turn * vec3_len(in) * vec3_len(out); /* NaN: keep */
}

/* May the points between a and c go, the straight tube from ring a to ring c standing in? */
static bool tube_span_ok(const struct scratch *s, size_t a, size_t c, double cos_turn)
{
	struct vec3 d = vec3_sub(s->p[c], s->p[a]);
	double dd = vec3_dot(d, d), dl = sqrt(dd);

	for (size_t j = a; j < c; j++) {
		struct vec3 e = vec3_sub(s->p[j + 1], s->p[j]);

		/* points left out have their first ring's sides (c's may differ); NaN: keep */
		if ((j + 1 < c && s->sides[j + 1] != s->sides[a]) ||
		    !(vec3_dot(e, d) >= cos_turn * vec3_len(e) * dl))
			return false;
	}
	for (size_t j = a + 1; j < c; j++) {
		double f = vec3_dot(vec3_sub(s->p[j], s->p[a]), d) / dd;
		struct vec3 on;
		double rr;

		f = f < 0 ? 0 : f > 1 ? 1 : f;
		on = vec3_add(s->p[a], vec3_scale(d, f));
		rr = s->r[a] + (s->r[c] - s->r[a]) * f;
		if (!(vec3_dist(s->p[j], on) + fabs(s->r[j] - rr) <= mesh_drop_tolerance(s->r[j])))
			return false;
	}
	return true;
}

/*
 * Leaves out the rings the straight tube between their neighbours can do without (see
 * mesh.h), compacting points, radii and sides in place. Returns the number of rings kept.
 */
static size_t tube_simplify(struct scratch *s, size_t k, double cos_turn)
{
	size_t a = 0, kept = 1;

	/* Greedy from the root: each kept ring reaches as far as it can. Reads stay at or
	 * past a, writes at or before it. */
	while (a + 1 < k) {
		size_t b = a + 1;

		while (b + 1 < k && b + 1 - a <= MESH_DROP_MAX_SPAN &&
		       tube_turn_ok(s, b, cos_turn) && tube_span_ok(s, a, b + 1, cos_turn))
			b++;
		s->p[kept] = s->p[b];
		s->r[kept] = s->r[b];
		s->sides[kept] = s->sides[b];
		kept++;
		a = b;
	}
	return kept;
}

/* dr/ds at point i, clamped: tilts the normals of a tapering tube. */
static double tube_slope(const struct scratch *s, size_t k, size_t i)
{
	size_t a = i > 0 ? i - 1 : i;
	size_t b = i + 1 < k ? i + 1 : i;
	double len = 0.0, slope;

	for (size_t j = a; j < b; j++)
		len += vec3_dist(s->p[j], s->p[j + 1]);
	slope = len > 0 ? (s->r[b] - s->r[a]) / len : 0.0;
	return slope < -TUBE_MAX_SLOPE ? -TUBE_MAX_SLOPE : slope > TUBE_MAX_SLOPE ? TUBE_MAX_SLOPE : slope;
}

/* Direction of side j of a ring of `sides` sides in the frame (n, b). */
static struct vec3 ring_dir(const struct lod *l, int sides, struct vec3 n, struct vec3 b, int j)
{
	return vec3_add(vec3_scale(n, l->cs[sides][j]), vec3_scale(b, l->sn[sides][j]));
}

/*
 * Joins ring A (na vertices from a0) to the next ring B (nb from b0). Vertex i of a ring
 * sits at angle 2 pi i / count in frames that do not twist, so the two are zipped by
 * angle: always step on along the ring whose next vertex comes first (B on ties, which
 * for equal counts makes the quads' usual two triangles). na + nb triangles.
 */
static void tube_zip(struct mesh *m, uint32_t a0, uint32_t na, uint32_t b0, uint32_t nb)
{
	uint32_t i = 0, j = 0;

	if (na == nb) { /* the usual case, the same triangles more cheaply */
		for (i = 0; i < na; i++) {
			uint32_t i1 = i + 1 == na ? 0 : i + 1;

			mesh_push_tri(m, a0 + i, b0 + i1, b0 + i);
			mesh_push_tri(m, a0 + i, a0 + i1, b0 + i1);
		}
		return;
	}
	/* No modulo in here: it is the hot loop of the whole mesh. */
	while (i < na || j < nb) {
		uint32_t ia = i == na ? 0 : i, jb = j == nb ? 0 : j;

		if (j < nb && (i == na || (j + 1) * na <= (i + 1) * nb)) {
			mesh_push_tri(m, a0 + ia, b0 + (j + 1 == nb ? 0 : j + 1), b0 + j);
			j++;
		} else {
			mesh_push_tri(m, a0 + i, a0 + (i + 1 == na ? 0 : i + 1), b0 + jb);
			i++;
		}
	}
}

/* One ring of vertices per kept point, zipped together; returns the first ring's first vertex. */
static uint32_t tube_side(struct mesh *m, const struct scratch *sc, size_t k)
{
	uint32_t base = (uint32_t)m->nvertices, ring = base;

	for (size_t i = 0; i < k; i++) {
		struct vec3 t = sc->t[i], n = sc->n[i], b = vec3_cross(t, n);
		double slope = tube_slope(sc, k, i);

		for (int j = 0; j < sc->sides[i]; j++) {
			struct vec3 radial = ring_dir(&sc->lod, sc->sides[i], n, b, j);
			struct vec3 pos = vec3_add(sc->p[i], vec3_scale(radial, sc->r[i]));
			struct vec3 nor = vec3_norm_or(vec3_sub(radial, vec3_scale(t, slope)), radial);

			mesh_push_vertex(m, pos, nor);
		}
	}
	for (size_t i = 0; i + 1 < k; i++) {
		uint32_t na = (uint32_t)sc->sides[i], nb = (uint32_t)sc->sides[i + 1];

		tube_zip(m, ring, na, ring + na, nb);
		ring += na;
	}
	return base;
}

/* Copies vertex v's position with a new normal (caps shade flat / as a cone). */
static uint32_t push_copy(struct mesh *m, uint32_t v, struct vec3 normal)
{
	const float *q = &m->positions[3 * (size_t)v];

	return mesh_push_vertex(m, vec3(q[0], q[1], q[2]), normal);
}

/* The root: a flat disc facing back along the axis (inside the parent for child branches). */
static void tube_root(struct mesh *m, const struct scratch *sc, uint32_t ring, uint32_t s)
{
	struct vec3 back = vec3_scale(sc->t[0], -1.0);
	uint32_t c = mesh_push_vertex(m, sc->p[0], back);

	for (uint32_t j = 0; j < s; j++)
		push_copy(m, ring + j, back);
	for (uint32_t j = 0; j < s; j++)
		mesh_push_tri(m, c, c + 1 + (j + 1) % s, c + 1 + j);
}

/* The tip: a cone TUBE_TIP_LENGTH radii long on the last ring, apex on the axis. */
static void tube_tip(struct mesh *m, const struct scratch *sc, size_t last, uint32_t ring)
{
	struct vec3 t = sc->t[last], n = sc->n[last], b = vec3_cross(t, n);
	double r = sc->r[last], h = TUBE_TIP_LENGTH * r;
	int sides = sc->sides[last];
	uint32_t first = (uint32_t)m->nvertices, s = (uint32_t)sides, apex;

	for (int j = 0; j < sides; j++) {
		/* The cone side's normal: radial * h + t * r, normalised. */
		struct vec3 radial = ring_dir(&sc->lod, sides, n, b, j);
		struct vec3 nor = vec3_norm_or(vec3_add(vec3_scale(radial, h), vec3_scale(t, r)), t);

		push_copy(m, ring + (uint32_t)j, nor);
	}
	apex = mesh_push_vertex(m, vec3_add(sc->p[last], vec3_scale(t, h)), t);
	for (uint32_t j = 0; j < s; j++)
		mesh_push_tri(m, first + j, first + (j + 1) % s, apex);
}

/*
 * Branch `index` as a closed tube: rings run counter-clockwise around the tangent, so the
 * side, the root disc and the tip cone all wind counter-clockwise seen from outside. What
 * it makes depends on the branch and its parent only, so appending gives a full build's bytes.
 */
static int tube_build(struct mesh *m, const struct tree *tr, size_t index, struct scratch *sc)
{
	const struct branch *br = &tr->branches[index];
	size_t k, nv = 0, ni = 0;
	uint32_t base, last;
	int r;

	r = scratch_reserve(sc, br->npoints);
	if (r < 0)
		return r;
	k = tube_clean(br, sc);
	if (k < 2)
		return 0;

	/* The root ring hides inside the parent (before simplifying: its radius counts there). */
	{
		struct vec3 dir = vec3_norm_or(vec3_sub(sc->p[1], sc->p[0]), vec3(0, 1, 0));

		r = joint_radius(tr, index, sc->p[0], dir, &sc->r[0], sc);
		if (r < 0)
			return r;
	}
	for (size_t i = 0; i < k; i++)
		sc->sides[i] = lod_sides(&sc->lod, sc->r[i]);
	k = tube_simplify(sc, k, sc->lod.cos_turn);
	frame_build(sc->p, k, sc->t, sc->n);

	for (size_t i = 0; i < k; i++)
		nv += (size_t)sc->sides[i];
	/* rings + root disc + tip cone; a ring's sides make 2 triangles (zips, caps) */
	ni = 3 * 2 * nv;
	nv += (size_t)sc->sides[0] + 1 + (size_t)sc->sides[k - 1] + 1;
	r = mesh_reserve(m, nv, ni);
	if (r < 0)
		return r;
	base = tube_side(m, sc, k);
	tube_root(m, sc, base, (uint32_t)sc->sides[0]);
	last = (uint32_t)(m->nvertices - (size_t)sc->sides[0] - 1 - (size_t)sc->sides[k - 1]);
	tube_tip(m, sc, k - 1, last);
	return 0;
}

/* Twice the signed area of (a, b, c) in the leaf plane: > 0 when counter-clockwise. */
static double orient(const struct scratch *s, size_t a, size_t b, size_t c)
{
	return (s->x[b] - s->x[a]) * (s->y[c] - s->y[a]) - (s->y[b] - s->y[a]) * (s->x[c] - s->x[a]);
}

static bool same_point(const struct scratch *s, size_t a, size_t b)
{
	return s->x[a] == s->x[b] && s->y[a] == s->y[b];
}

/* Does any other remaining vertex lie in (or on) triangle (a, b, c)? Then it is no ear. */
static bool ear_blocked(const struct scratch *s, size_t cnt, size_t a, size_t b, size_t c,
			double eps)
{
	for (size_t i = 0; i < cnt; i++) {
		size_t q = s->live[i];

		if (q == a || q == b || q == c)
			continue;
		/* A polygon touching itself repeats a point; that copy does not block the ear. */
		if (same_point(s, q, a) || same_point(s, q, b) || same_point(s, q, c))
			continue;
		if (orient(s, a, b, q) >= -eps && orient(s, b, c, q) >= -eps &&
		    orient(s, c, a, q) >= -eps)
			return true;
	}
	return false;
}

static void live_remove(struct scratch *s, size_t *cnt, size_t i)
{
	memmove(&s->live[i], &s->live[i + 1], (*cnt - i - 1) * sizeof(*s->live));
	(*cnt)--;
}

/*
 * Ear clipping of the counter-clockwise polygon (x, y)[0..n): emits triangles as indices
 * base + i. Collinear vertices and zero-width spikes are dropped without a triangle. A
 * polygon with no ear left (self-intersecting junk) gets its most convex corners clipped
 * as a best effort; inverted leftovers are dropped.
 */
static void leaf_clip(struct mesh *m, struct scratch *s, size_t n, uint32_t base, double eps)
{
	size_t cnt = n, i = 0, misses = 0;

	for (size_t j = 0; j < n; j++)
		s->live[j] = j;

	while (cnt > 3) {
		size_t a = s->live[(i + cnt - 1) % cnt], b = s->live[i], c = s->live[(i + 1) % cnt];
		double o = orient(s, a, b, c);

		if (fabs(o) <= eps || (o > 0 && !ear_blocked(s, cnt, a, b, c, eps))) {
			if (fabs(o) > eps)
				mesh_push_tri(m, base + (uint32_t)a, base + (uint32_t)b, base + (uint32_t)c);
			live_remove(s, &cnt, i);
			if (i >= cnt)
				i = 0;
			misses = 0;
			continue;
		}
		i = (i + 1) % cnt;
		if (++misses < cnt)
			continue;

		/* A whole round without an ear: clip the most convex corner regardless. */
		{
			size_t best = cnt;
			double best_o = eps;

			for (size_t j = 0; j < cnt; j++) {
				double oj = orient(s, s->live[(j + cnt - 1) % cnt], s->live[j],
						   s->live[(j + 1) % cnt]);

				if (oj > best_o) {
					best_o = oj;
					best = j;
				}
			}
			if (best == cnt)
				return;
			mesh_push_tri(m, base + (uint32_t)s->live[(best + cnt - 1) % cnt],
				      base + (uint32_t)s->live[best],
				      base + (uint32_t)s->live[(best + 1) % cnt]);
			live_remove(s, &cnt, best);
			i = best < cnt ? best : 0;
			misses = 0;
		}
	}
	if (cnt == 3 && orient(s, s->live[0], s->live[1], s->live[2]) > eps)
		mesh_push_tri(m, base + (uint32_t)s->live[0], base + (uint32_t)s->live[1],
			      base + (uint32_t)s->live[2]);
}

/*
 * An origami leaf: its kind's faces at rest (ori_mesh_append), flat-shaded so the folds
 * show, in the frame its points give back. 1 when it is not one (its points do not fit
 * its kind: an outline, meshed as one), 0 or -ENOMEM.
 */
static int origami_build(struct mesh *m, const struct leaf *l)
{
	const struct ori_kind *k;
	double xf[12];

	if (l->kind < 0 || l->kind >= ORI_KIND_COUNT)
		return 1;
	k = ori_kind_get(l->kind);
	if (!k)
		return -ENOMEM; /* built on first use: only memory can be missing */
	for (size_t i = 0; i < l->npoints; i++)
		if (!vec3_finite(l->points[i]))
			return 0; /* corrupt leaf: left out, as an outline would be */
	if (!ori_kind_frame(k, l->points, l->npoints, xf))
		return 1;
	return ori_mesh_append(&k->leaf, (const double (*)[3])k->rest, xf, m);
}

/*
 * A leaf: the polygon projected onto its best-fit plane (Newell normal), ear-clipped there,
 * the 3D points kept as they are. One-sided, facing along the Newell normal.
 */
static int leaf_build(struct mesh *m, const struct leaf *l, struct scratch *s)
{
	struct vec3 c = vec3(0, 0, 0), nn = vec3(0, 0, 0), normal, u, v;
	double extent = 0.0, area2, eps;
	size_t k = 0;
	uint32_t base;
	int r;

	r = origami_build(m, l);
	if (r <= 0)
		return r;
	r = scratch_reserve(s, l->npoints);
	if (r < 0)
		return r;
	for (size_t i = 0; i < l->npoints; i++) {
		struct vec3 q = l->points[i];

		if (!vec3_finite(q))
			return 0; /* corrupt leaf: leave it out rather than guess */
		if (k > 0 && vec3_dist(q, s->p[k - 1]) <= LEAF_MIN_STEP)
			continue;
		s->p[k++] = q;
	}
	/* The polygon is closed implicitly; drop an explicit closing point. */
	while (k > 1 && vec3_dist(s->p[k - 1], s->p[0]) <= LEAF_MIN_STEP)
		k--;
	if (k < 3)
		return 0;

	for (size_t i = 0; i < k; i++)
		c = vec3_add(c, s->p[i]);
	c = vec3_scale(c, 1.0 / (double)k);
	for (size_t i = 0; i < k; i++) {
		struct vec3 a = vec3_sub(s->p[i], c), b = vec3_sub(s->p[(i + 1) % k], c);

		/* Newell: the sum of edge cross products is twice the area vector. */
		nn = vec3_add(nn, vec3_cross(a, b));
		extent = fmax(extent, vec3_len(a));
	}
	area2 = vec3_len(nn);
	if (!(area2 > 1e-12 * extent * extent) || area2 < 1e-18)
		return 0; /* no area, or a figure eight that cancels out */
	normal = vec3_scale(nn, 1.0 / area2);

	u = frame_perpendicular(normal);
	v = vec3_cross(normal, u);
	for (size_t i = 0; i < k; i++) {
		struct vec3 d = vec3_sub(s->p[i], c);

		s->x[i] = vec3_dot(d, u);
		s->y[i] = vec3_dot(d, v);
	}

	r = mesh_reserve(m, k, 3 * (k - 2));
	if (r < 0)
		return r;
	base = (uint32_t)m->nvertices;
	for (size_t i = 0; i < k; i++)
		mesh_push_vertex(m, s->p[i], normal);

	/* Relative tolerance: a leaf is a leaf at any size. */
	eps = 1e-10 * extent * extent;
	{
		size_t before = m->nindices;

		leaf_clip(m, s, k, base, eps);
		if (m->nindices == before)
			m->nvertices = base; /* nothing came of it: no stray vertices */
	}
	return 0;
}

void tree_mesh_marks_init(struct tree_mesh_marks *mk)
{
	memset(mk, 0, sizeof(*mk));
}

void tree_mesh_marks_finish(struct tree_mesh_marks *mk)
{
	free(mk->bark);
	free(mk->leaves);
	tree_mesh_marks_init(mk);
}

/* Marks from element `first` on, in step with m: keeps what is known, or forgets it all. */
static void mark_start(struct tree_mesh_mark **marks, size_t *n, size_t first, const struct mesh *m)
{
	if (first == 0) {
		*n = 0;
		if (*marks) {
			(*marks)[0] = (struct tree_mesh_mark){ 0, 0 };
			*n = 1;
		}
		return;
	}
	if (*n != first + 1 || (*marks)[first].nvertices != m->nvertices ||
	    (*marks)[first].nindices != m->nindices)
		*n = 0;
}

static void mark_next(struct tree_mesh_mark **marks, size_t *n, size_t *cap, const struct mesh *m)
{
	if (*n == 0)
		return;
	if (*n == *cap) {
		size_t ncap = *cap ? *cap * 2 : 64;
		struct tree_mesh_mark *p = realloc(*marks, ncap * sizeof(*p));

		if (!p) {
			*n = 0; /* unknown: undo meshes the tree again */
			return;
		}
		*marks = p;
		*cap = ncap;
	}
	(*marks)[(*n)++] = (struct tree_mesh_mark){ m->nvertices, m->nindices };
}

static void marks_reserve_first(struct tree_mesh_mark **marks, size_t *cap)
{
	if (*cap == 0) {
		*marks = malloc(64 * sizeof(**marks));
		*cap = *marks ? 64 : 0;
	}
}

int tree_mesh_append_marked(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
			    size_t first_leaf, struct tree_mesh_marks *mk)
{
	struct scratch sc;
	int r = 0;

	memset(&sc, 0, sizeof(sc));
	lod_init(&sc.lod);
	sc.lod.fixed = tree_sides(t);
	if (mk) {
		marks_reserve_first(&mk->bark, &mk->cap_bark);
		marks_reserve_first(&mk->leaves, &mk->cap_leaves);
		mark_start(&mk->bark, &mk->nbark, first_branch, &tm->bark);
		mark_start(&mk->leaves, &mk->nleaves, first_leaf, &tm->leaves);
	}
	for (size_t i = first_branch; i < t->nbranches && r == 0; i++) {
		/* a branch the wood holds has the wood's bark (wood.h): an empty part here */
		if (!tree_branch_in_wood(t, i))
			r = tube_build(&tm->bark, t, i, &sc);
		if (mk)
			mark_next(&mk->bark, &mk->nbark, &mk->cap_bark, &tm->bark);
	}
	for (size_t i = first_leaf; i < t->nleaves && r == 0; i++) {
		r = leaf_build(&tm->leaves, &t->leaves[i], &sc);
		if (mk)
			mark_next(&mk->leaves, &mk->nleaves, &mk->cap_leaves, &tm->leaves);
	}

	scratch_finish(&sc);
	if (r < 0) {
		/* Half a tree is no tree. */
		mesh_clear(&tm->bark);
		mesh_clear(&tm->leaves);
		if (mk)
			mk->nbark = mk->nleaves = 0;
	}
	return r;
}

/* Appends part i of src (between marks i and i + 1) to m, its indices moved along. */
static int copy_part(struct mesh *m, const struct mesh *src, const struct tree_mesh_mark *marks,
		     size_t i)
{
	size_t v0 = marks[i].nvertices, nv = marks[i + 1].nvertices - v0;
	size_t i0 = marks[i].nindices, ni = marks[i + 1].nindices - i0;
	uint32_t base;
	int r = mesh_reserve(m, nv, ni);

	if (r < 0)
		return r;
	base = (uint32_t)m->nvertices;
	memcpy(&m->positions[3 * m->nvertices], &src->positions[3 * v0], nv * 3 * sizeof(float));
	memcpy(&m->normals[3 * m->nvertices], &src->normals[3 * v0], nv * 3 * sizeof(float));
	/* a part's triangles use its own vertices only: they move with them */
	if (base == v0) {
		memcpy(&m->indices[m->nindices], &src->indices[i0], ni * sizeof(*m->indices));
	} else {
		const uint32_t *restrict from = &src->indices[i0];
		uint32_t *restrict to = &m->indices[m->nindices];
		uint32_t shift = base - (uint32_t)v0;

		for (size_t k = 0; k < ni; k++)
			to[k] = from[k] + shift;
	}
	m->nvertices += nv;
	m->nindices += ni;
	return 0;
}

int tree_mesh_build_reusing(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
			    const struct tree_mesh *from, const struct tree_mesh_marks *from_mk,
			    const int *reuse_branch, const int *reuse_leaf)
{
	struct scratch sc;
	int r = 0;

	mesh_clear(&tm->bark);
	mesh_clear(&tm->leaves);
	/* about as large as from: room at once, not by doubling */
	if (mesh_reserve(&tm->bark, from->bark.nvertices, from->bark.nindices) < 0 ||
	    mesh_reserve(&tm->leaves, from->leaves.nvertices, from->leaves.nindices) < 0)
		return -ENOMEM;
	memset(&sc, 0, sizeof(sc));
	lod_init(&sc.lod);
	sc.lod.fixed = tree_sides(t);
	marks_reserve_first(&mk->bark, &mk->cap_bark);
	marks_reserve_first(&mk->leaves, &mk->cap_leaves);
	mark_start(&mk->bark, &mk->nbark, 0, &tm->bark);
	mark_start(&mk->leaves, &mk->nleaves, 0, &tm->leaves);
	for (size_t i = 0; i < t->nbranches && r == 0; i++) {
		if (reuse_branch[i] >= 0)
			r = copy_part(&tm->bark, &from->bark, from_mk->bark, (size_t)reuse_branch[i]);
		else
			r = tube_build(&tm->bark, t, i, &sc);
		mark_next(&mk->bark, &mk->nbark, &mk->cap_bark, &tm->bark);
	}
	for (size_t i = 0; i < t->nleaves && r == 0; i++) {
		if (reuse_leaf[i] >= 0)
			r = copy_part(&tm->leaves, &from->leaves, from_mk->leaves, (size_t)reuse_leaf[i]);
		else
			r = leaf_build(&tm->leaves, &t->leaves[i], &sc);
		mark_next(&mk->leaves, &mk->nleaves, &mk->cap_leaves, &tm->leaves);
	}
	scratch_finish(&sc);
	if (r < 0) {
		mesh_clear(&tm->bark);
		mesh_clear(&tm->leaves);
		mk->nbark = mk->nleaves = 0;
	}
	return r;
}

int tree_mesh_build_parts(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
			  const struct tree *t, const size_t *branches, size_t nb, const size_t *leaves,
			  size_t nl)
{
	struct scratch sc;
	int r = 0;

	mesh_clear(&out->bark);
	mesh_clear(&out->leaves);
	memset(&sc, 0, sizeof(sc));
	lod_init(&sc.lod);
	sc.lod.fixed = tree_sides(t);
	marks_reserve_first(&out_mk->bark, &out_mk->cap_bark);
	marks_reserve_first(&out_mk->leaves, &out_mk->cap_leaves);
	mark_start(&out_mk->bark, &out_mk->nbark, 0, &out->bark);
	mark_start(&out_mk->leaves, &out_mk->nleaves, 0, &out->leaves);
	for (size_t k = 0; k < nb && r == 0; k++) {
		if (branches[k] >= t->nbranches)
			r = -EINVAL;
		else if (!tree_branch_in_wood(t, branches[k]))
			r = tube_build(&out->bark, t, branches[k], &sc);
		mark_next(&out_mk->bark, &out_mk->nbark, &out_mk->cap_bark, &out->bark);
	}
	for (size_t k = 0; k < nl && r == 0; k++) {
		if (leaves[k] >= t->nleaves)
			r = -EINVAL;
		else
			r = leaf_build(&out->leaves, &t->leaves[leaves[k]], &sc);
		mark_next(&out_mk->leaves, &out_mk->nleaves, &out_mk->cap_leaves, &out->leaves);
	}
	scratch_finish(&sc);
	/* every part must be marked: a mark that could not be kept is a failure here */
	if (r == 0 && (out_mk->nbark != nb + 1 || out_mk->nleaves != nl + 1))
		r = -ENOMEM;
	if (r < 0) {
		mesh_clear(&out->bark);
		mesh_clear(&out->leaves);
		out_mk->nbark = out_mk->nleaves = 0;
	}
	return r;
}

int tree_mesh_append(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
		     size_t first_leaf)
{
	return tree_mesh_append_marked(tm, t, first_branch, first_leaf, NULL);
}

int tree_mesh_build_marked(struct tree_mesh *tm, const struct tree *t, struct tree_mesh_marks *mk)
{
	mesh_clear(&tm->bark);
	mesh_clear(&tm->leaves);
	return tree_mesh_append_marked(tm, t, 0, 0, mk);
}

int tree_mesh_build(struct tree_mesh *tm, const struct tree *t)
{
	return tree_mesh_build_marked(tm, t, NULL);
}

bool tree_mesh_truncate(struct tree_mesh *tm, struct tree_mesh_marks *mk, size_t nb, size_t nl)
{
	if (nb >= mk->nbark || nl >= mk->nleaves)
		return false;
	tm->bark.nvertices = mk->bark[nb].nvertices;
	tm->bark.nindices = mk->bark[nb].nindices;
	tm->leaves.nvertices = mk->leaves[nl].nvertices;
	tm->leaves.nindices = mk->leaves[nl].nindices;
	mk->nbark = nb + 1;
	mk->nleaves = nl + 1;
	return true;
}
