/* SPDX-License-Identifier: MIT */
/* A branch's tube: its rings (sides by radius or the tree's), the joint into its parent,
 * the simplified polyline, root and tip (mesh_private.h). */
#include "mesh_private.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "tube_frame.h"

void mesh_lod_init(struct lod *l)
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
	l->drop_scale = 1.0;
}

void mesh_lod_coarsen(struct lod *l, const struct mesh_coarse *c)
{
	double turn;

	if (!c)
		return;
	if (c->max_sides > 0)
		l->max_sides = c->max_sides < MESH_MIN_SIDES ? MESH_MIN_SIDES : c->max_sides;
	/* below 1 (or NaN) would be finer than the tree's own mesh, not coarser */
	if (!(c->drop_scale > 1.0))
		return;
	l->drop_scale = c->drop_scale;
	if (l->drop_scale > MESH_COARSE_MAX_SCALE)
		l->drop_scale = MESH_COARSE_MAX_SCALE;
	turn = MESH_DROP_TURN_DEG * l->drop_scale;
	turn = turn < MESH_COARSE_MAX_TURN_DEG ? turn : MESH_COARSE_MAX_TURN_DEG;
	/* only rings are left out more readily: joints stay as the tree's own (sin_turn) */
	l->cos_turn = cos(turn * VEC_PI / 180.0);
}

static int lod_sides(const struct lod *l, double radius)
{
	double px = radius * TUBE_PX_PER_M;
	int s = MESH_MIN_SIDES;

	if (l->fixed)
		s = l->fixed;
	else if (px > 0) /* NaN: the fewest */
		while (s < MESH_MAX_SIDES && px * l->sag[s] > MESH_SIDE_ERROR_PX)
			s++;
	return l->max_sides && s > l->max_sides ? l->max_sides : s;
}

/* mesh_drop_tolerance, drop_scale times (exactly it at 1). */
static double lod_drop_tolerance(const struct lod *l, double radius)
{
	return mesh_drop_tolerance(radius) * l->drop_scale;
}

int mesh_ring_sides(double radius)
{
	struct lod l;

	mesh_lod_init(&l);
	return lod_sides(&l, radius);
}

double mesh_drop_tolerance(double radius)
{
	double px = MESH_DROP_ERROR_PX / TUBE_PX_PER_M, rel = MESH_DROP_RADIUS_FRACTION * radius;

	return rel < px ? rel : px;
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
		if (!mesh_vec3_finite(q))
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

static size_t tube_clean(const struct branch *b, struct mesh_scratch *s)
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
static int host_get(struct mesh_scratch *s, const struct tree *t, int b, struct host *h)
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
			cap = mesh_grow_cap(s->hcap, s->hlen + br->npoints);
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
 * polyline; coarser bark strays further, which the joint does not follow: mesh.h) and R
 * the radius profile: piecewise linear, then the tip cone. With L its steepest slope over
 * the ring's reach, R(s_q + y*rho) >= R(s_q) - L*rho*|y|, so it
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
			double *rc, struct mesh_scratch *s)
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
static bool tube_turn_ok(const struct mesh_scratch *s, size_t i, double cos_turn)
{
	struct vec3 in = vec3_sub(s->p[i], s->p[i - 1]), out = vec3_sub(s->p[i + 1], s->p[i]);

	return vec3_dot(in, out) >= cos_turn * vec3_len(in) * vec3_len(out); /* NaN: keep */
}

/* May the points between a and c go, the straight tube from ring a to ring c standing in? */
static bool tube_span_ok(const struct mesh_scratch *s, size_t a, size_t c, double cos_turn)
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
		if (!(vec3_dist(s->p[j], on) + fabs(s->r[j] - rr) <=
		      lod_drop_tolerance(&s->lod, s->r[j])))
			return false;
	}
	return true;
}

/*
 * Leaves out the rings the straight tube between their neighbours can do without (see
 * mesh.h), compacting points, radii and sides in place. Returns the number of rings kept.
 */
static size_t tube_simplify(struct mesh_scratch *s, size_t k, double cos_turn)
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
static double tube_slope(const struct mesh_scratch *s, size_t k, size_t i)
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
static uint32_t tube_side(struct mesh *m, const struct mesh_scratch *sc, size_t k)
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
static void tube_root(struct mesh *m, const struct mesh_scratch *sc, uint32_t ring, uint32_t s)
{
	struct vec3 back = vec3_scale(sc->t[0], -1.0);
	uint32_t c = mesh_push_vertex(m, sc->p[0], back);

	for (uint32_t j = 0; j < s; j++)
		push_copy(m, ring + j, back);
	for (uint32_t j = 0; j < s; j++)
		mesh_push_tri(m, c, c + 1 + (j + 1) % s, c + 1 + j);
}

/* The tip: a cone TUBE_TIP_LENGTH radii long on the last ring, apex on the axis. */
static void tube_tip(struct mesh *m, const struct mesh_scratch *sc, size_t last, uint32_t ring)
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
int mesh_tube_build(struct mesh *m, const struct tree *tr, size_t index, struct mesh_scratch *sc)
{
	const struct branch *br = &tr->branches[index];
	size_t k, nv = 0, ni = 0;
	uint32_t base, last;
	int r;

	r = mesh_scratch_reserve(sc, br->npoints);
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
	tube_frame_build(sc->p, k, sc->t, sc->n);

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
