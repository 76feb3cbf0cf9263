/* SPDX-License-Identifier: MIT */
/*
 * A twining vine's shapes (seed 004, Kasakura 3.3; docs/vines.md): the smoothed axes, the
 * leaves and the meshes, all drawn from the raw axes vine_grow.c made, which they never
 * change.
 *
 * Smoothing (3.3.1): where the azimuth of consecutive directions jumps by 45 degrees or
 * more (the rod re-pivoting, a turn to clear the support), the points within d/2 of the
 * jump become a cubic Hermite spline between the span's ends, the raw directions there as
 * tangents. The free parts (the main axis's first, non-twining internodes with the
 * cotyledon node; a stopped apex's last 2d points), straight and vertical or circling in
 * the air, are bent by horizontal cubic Bezier offsets within +-5 l/d, drawn from the seed.
 *
 * Neither knows the support, so what is drawn is the smoothed axis kept clear of it
 * (vine_clear, which vine_grow calls while it has the support): a smoothed point nearer
 * than r, or beyond the surface from its raw point, is pulled back towards the raw point
 * (which the growth kept r clear) until it is neither; the shoot keeps how far (`pull`)
 * with the smoothed point it was found for (`smooth`), and every drawing applies it.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tube_frame.h"
#include "mesh.h"
#include "rng.h"
#include "vine.h"
#include "vine_support.h"

/* The azimuth jump that is smoothed over. */
#define VINE_SMOOTH_JUMP_DEG 45.0
/* A direction this close to vertical (horizontal length over length) has no azimuth. */
#define VINE_VERTICAL_EPS 1e-9
/* The Bezier offsets' reach, in segments (l/d). */
#define VINE_BEND_SEGMENTS 5.0
/* The tip's cone is this many radii long. */
#define VINE_TIP_LENGTH 1.0
/* A smoothed point pulled back clear of the support is found to this fraction of r along
 * its way, in at most this many halvings. */
#define VINE_PULL_PRECISION 0.01
#define VINE_PULL_STEPS 24

static size_t points_per_internode(const struct vine *v)
{
	return v->p.points_per_internode > 0 ? (size_t)v->p.points_per_internode : 1;
}

/* The azimuth of e, about +y counter-clockwise seen from above; false when e is vertical. */
static bool azimuth(struct vec3 e, double *az)
{
	double h = hypot(e.x, e.z);

	if (!(h > VINE_VERTICAL_EPS * vec3_len(e)))
		return false;
	*az = atan2(-e.z, e.x);
	return true;
}

/* Does the azimuth jump at point i (between directions i - 1 and i)? */
static bool jumps(const struct vec3 *a, size_t i)
{
	double a0, a1, da;

	if (!azimuth(vec3_sub(a[i], a[i - 1]), &a0) || !azimuth(vec3_sub(a[i + 1], a[i]), &a1))
		return false; /* straight up or down: no azimuth to jump from or to */
	da = remainder(a1 - a0, 2.0 * VEC_PI); /* wrapped: 350 -> 10 degrees is 20 */
	return fabs(da) >= VINE_SMOOTH_JUMP_DEG * VEC_PI / 180.0 - 1e-12;
}

/* The raw span [lo, hi] as a cubic Hermite spline between its ends, written to out. */
static void hermite(const struct vec3 *a, struct vec3 *out, size_t lo, size_t hi)
{
	double len = 0;
	struct vec3 m0, m1;

	for (size_t j = lo; j < hi; j++)
		len += vec3_dist(a[j], a[j + 1]);
	/* tangents as long as the span, so the curve runs at about the points' pace */
	m0 = vec3_scale(vec3_norm_or(vec3_sub(a[lo + 1], a[lo]), vec3(0, 1, 0)), len);
	m1 = vec3_scale(vec3_norm_or(vec3_sub(a[hi], a[hi - 1]), vec3(0, 1, 0)), len);
	for (size_t j = lo + 1; j < hi; j++) {
		double u = (double)(j - lo) / (double)(hi - lo), u2 = u * u, u3 = u2 * u;
		double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
		double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;

		out[j] = vec3_add(vec3_add(vec3_scale(a[lo], h00), vec3_scale(m0, h10)),
				  vec3_add(vec3_scale(a[hi], h01), vec3_scale(m1, h11)));
	}
}

/*
 * Every jump's span [i - d/2, i + d/2] (clamped to the shoot) smoothed; spans that
 * overlap are merged into one, so the result does not depend on the order they are met in.
 */
static void smooth_jumps(const struct vine *v, const struct vine_shoot *sh, struct vec3 *out)
{
	size_t half = points_per_internode(v) / 2, lo = 0, hi = 0;
	bool open = false;

	if (half == 0 || sh->n < 3)
		return;
	for (size_t i = 1; i + 1 < sh->n; i++) {
		size_t a, b;

		if (!jumps(sh->axis, i))
			continue;
		a = i > half ? i - half : 0;
		b = i + half < sh->n - 1 ? i + half : sh->n - 1;
		if (open && a < hi) {
			hi = b;
			continue;
		}
		if (open && hi - lo >= 2)
			hermite(sh->axis, out, lo, hi);
		lo = a;
		hi = b;
		open = true;
	}
	if (open && hi - lo >= 2)
		hermite(sh->axis, out, lo, hi);
}

/*
 * Part `part` of shoot `shoot`, points [lo, hi], bent by the horizontal cubic Bezier offset
 * with control offsets (0, c1, c2, c3), u = (i - lo) / (hi - lo); c3 is 0 unless the part
 * ends free (a stopped apex's tip). The controls come from the seed and the indices alone.
 */
static void bend(const struct vine *v, size_t shoot, uint64_t part, size_t lo, size_t hi,
		 bool free_end, struct vec3 *out)
{
	double reach = VINE_BEND_SEGMENTS * v->p.internode / (double)points_per_internode(v);
	struct vec3 c[3];
	struct rng r;

	if (hi <= lo)
		return;
	rng_seed(&r, v->p.seed ^ ((uint64_t)shoot * 0x9E3779B97F4A7C15ULL) ^ part);
	/* always six draws, so c1 and c2 are the same whether or not c3 is used */
	for (int k = 0; k < 3; k++) {
		double x = rng_range(&r, -reach, reach), z = rng_range(&r, -reach, reach);

		c[k] = vec3(x, 0, z);
	}
	if (!free_end)
		c[2] = vec3(0, 0, 0);
	for (size_t i = lo + 1; i <= hi; i++) {
		double u = (double)(i - lo) / (double)(hi - lo), t = 1 - u;
		double b1 = 3 * t * t * u, b2 = 3 * t * u * u, b3 = u * u * u;

		/* y untouched: the offset is horizontal, the height the growth gave stays */
		out[i].x += b1 * c[0].x + b2 * c[1].x + b3 * c[2].x;
		out[i].z += b1 * c[0].z + b2 * c[1].z + b3 * c[2].z;
	}
}

/* The free parts bent: [0, free_until] (the cotyledon node and the non-twining internodes,
 * as one part: both start at the root), and a stopped apex's last 2d points. */
static void bend_free(const struct vine *v, size_t shoot, struct vec3 *out)
{
	const struct vine_shoot *sh = &v->shoots[shoot];
	size_t d = points_per_internode(v), last = sh->n - 1;
	size_t fe = sh->free_until < last ? sh->free_until : last, tip;

	/* the non-twining part ends where twining starts (kept in place), or at the tip */
	bend(v, shoot, 0, 0, fe, sh->stopped && fe == last, out);
	if (!sh->stopped)
		return;
	tip = last > 2 * d ? last - 2 * d : 0;
	if (tip < fe)
		tip = fe; /* the two parts never overlap */
	bend(v, shoot, 1, tip, last, true, out);
}

/* The parent's node point a lateral grows from (its raw index), or none. */
static bool parent_node(const struct vine *v, size_t shoot, size_t *at)
{
	const struct vine_shoot *sh = &v->shoots[shoot];

	if (sh->parent < 0 || (size_t)sh->parent >= shoot || sh->node < 0)
		return false;
	*at = (size_t)sh->node * points_per_internode(v);
	return *at < v->shoots[sh->parent].n;
}

/*
 * A shoot's smoothed axis into out (sh->n points), before it is kept clear. parent_at:
 * the parent's drawn point at the lateral's node, or NULL: a lateral's root moves with it
 * (the parent's bend, spline or pull may have moved it), the move fading out over its
 * first internode, so the lateral still starts on its parent.
 */
static void smooth_shoot(const struct vine *v, size_t shoot, const struct vec3 *parent_at,
			 struct vec3 *out)
{
	const struct vine_shoot *sh = &v->shoots[shoot];
	size_t d = points_per_internode(v), at;

	memcpy(out, sh->axis, sh->n * sizeof(*out));
	if (sh->n >= 2) {
		smooth_jumps(v, sh, out);
		bend_free(v, shoot, out);
	}
	if (parent_at && sh->n > 0 && parent_node(v, shoot, &at)) {
		const struct vine_shoot *ps = &v->shoots[sh->parent];
		struct vec3 moved = vec3_sub(*parent_at, ps->axis[at]);

		/* the root exactly on the parent's point (it is the raw one, never moved itself) */
		out[0] = vec3_add(*parent_at, vec3_sub(out[0], ps->axis[at]));
		for (size_t i = 1; i < sh->n && i < d; i++)
			out[i] = vec3_add(out[i], vec3_scale(moved, 1.0 - (double)i / (double)d));
	}
}

/* Point p drawn `pull` of the way from raw to smoothed: exactly the smoothed at 1, the
 * raw at 0. */
static struct vec3 pulled(struct vec3 raw, struct vec3 p, double pull)
{
	return pull == 1.0 ? p : vec3_add(raw, vec3_scale(vec3_sub(p, raw), pull));
}

/* The smoothed axis out of shoot sh pulled clear as vine_clear found: each pull applies
 * to the smoothed point it was found for (the smoothing is a function of the raw axes,
 * the seed and `stopped`, so after vine_grow that is every point). */
static void pull_shoot(const struct vine_shoot *sh, struct vec3 *out)
{
	size_t n = sh->cleared < sh->n ? sh->cleared : sh->n;

	if (!sh->pull || !sh->smooth)
		return;
	for (size_t i = 0; i < n; i++)
		if (memcmp(&sh->smooth[i], &out[i], sizeof(out[i])) == 0)
			out[i] = pulled(sh->axis[i], out[i], sh->pull[i]);
}

/* A shoot's drawn axis into out: smoothed, then pulled clear. */
static void draw_shoot(const struct vine *v, size_t shoot, const struct vec3 *parent_at,
		       struct vec3 *out)
{
	smooth_shoot(v, shoot, parent_at, out);
	pull_shoot(&v->shoots[shoot], out);
}

int vine_smooth(const struct vine *v, size_t shoot, struct vec3 **out)
{
	const struct vine_shoot *sh = &v->shoots[shoot];
	struct vec3 *a, *pa = NULL;
	size_t at = 0;
	/* a parent drawn before it (vine_grow.c's laterals: always shoot 0) */
	bool lateral = parent_node(v, shoot, &at);

	a = malloc((sh->n ? sh->n : 1) * sizeof(*a));
	if (!a)
		return -ENOMEM;
	if (lateral) {
		int ret = vine_smooth(v, (size_t)sh->parent, &pa);

		if (ret < 0) {
			free(a);
			return ret;
		}
	}
	draw_shoot(v, shoot, lateral ? &pa[at] : NULL, a);
	free(pa);
	*out = a;
	return 0;
}

/* Every shoot's smoothed axis, in order (a parent before its laterals). 0 or -ENOMEM. */
static int smooth_all(const struct vine *v, struct vec3 ***out)
{
	struct vec3 **axes = calloc(v->nshoots ? v->nshoots : 1, sizeof(*axes));

	if (!axes)
		return -ENOMEM;
	for (size_t k = 0; k < v->nshoots; k++) {
		const struct vine_shoot *sh = &v->shoots[k];
		size_t at = 0;

		axes[k] = malloc((sh->n ? sh->n : 1) * sizeof(**axes));
		if (!axes[k]) {
			for (size_t j = 0; j < k; j++)
				free(axes[j]);
			free(axes);
			return -ENOMEM;
		}
		draw_shoot(v, k, parent_node(v, k, &at) ? &axes[sh->parent][at] : NULL, axes[k]);
	}
	*out = axes;
	return 0;
}

static void free_all(const struct vine *v, struct vec3 **axes)
{
	if (!axes)
		return;
	for (size_t k = 0; k < v->nshoots; k++)
		free(axes[k]);
	free(axes);
}

/* ---- Clear of the support ---- */

/* Drawn at p, is the stem clear: p at least r from s, and p reached from its raw point
 * without crossing the support (so on the same side of it: outside)? */
static bool reachable(const struct vine *v, const struct vine_support *s, struct vec3 raw,
		      struct vec3 p)
{
	double r = v->p.radius;

	return vine_support_distance(s, p, r, NULL, NULL) >= r &&
	       !vine_support_crosses(s, raw, p);
}

/*
 * How far from raw towards its smoothed point p the stem may be drawn: 1 when p is clear,
 * else the farthest pull found clear by bisection, to VINE_PULL_PRECISION r along the
 * way (VINE_PULL_STEPS halvings at most); 0 (the raw point) when nothing nearer is.
 */
static double pull_of(const struct vine *v, const struct vine_support *s, struct vec3 raw,
		      struct vec3 p)
{
	double lo = 0, hi = 1, len = vec3_dist(raw, p), r = v->p.radius;

	if (memcmp(&raw, &p, sizeof(p)) == 0 || reachable(v, s, raw, p))
		return 1;
	for (int i = 0; i < VINE_PULL_STEPS && (hi - lo) * len > VINE_PULL_PRECISION * r; i++) {
		double mid = 0.5 * (lo + hi);

		if (reachable(v, s, raw, pulled(raw, p, mid)))
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

/*
 * Shoot k's pulls for its smoothed axis sm (what smooth_shoot gave): found again only for
 * the points whose smoothed point changed since they were last found (growth changes the
 * tip's splines and a stopping shoot's bends), so a growth cleared at every frame costs
 * what one cleared at its end does. The root is never pulled: it is where the shoot was
 * planted, or its parent's drawn point.
 */
static void clear_shoot(struct vine *v, const struct vine_support *s, size_t k,
			const struct vec3 *sm)
{
	struct vine_shoot *sh = &v->shoots[k];

	for (size_t i = 0; i < sh->n; i++) {
		if (i < sh->cleared && memcmp(&sh->smooth[i], &sm[i], sizeof(sm[i])) == 0)
			continue;
		sh->smooth[i] = sm[i];
		sh->pull[i] = i == 0 ? 1.0 : pull_of(v, s, sh->axis[i], sm[i]);
	}
	sh->cleared = sh->n;
	sh->cleared_stopped = sh->stopped;
}

int vine_clear(struct vine *v, const struct vine_support *s)
{
	size_t longest = 0;
	struct vec3 *sm;
	bool *redo, any = false;

	if (!s)
		return 0;
	for (size_t k = 0; k < v->nshoots; k++) {
		const struct vine_shoot *sh = &v->shoots[k];

		longest = sh->n > longest ? sh->n : longest;
		any = any || sh->cleared != sh->n || sh->cleared_stopped != sh->stopped;
	}
	if (!any)
		return 0; /* nothing grew or stopped since: a frame that added no point */
	sm = malloc((longest ? longest : 1) * sizeof(*sm));
	redo = calloc(v->nshoots, sizeof(*redo));
	if (!sm || !redo) {
		free(sm);
		free(redo);
		return -ENOMEM;
	}
	/* parents first: a lateral starts from its parent's drawn node point */
	for (size_t k = 0; k < v->nshoots; k++) {
		struct vine_shoot *sh = &v->shoots[k];
		size_t at = 0;
		bool lateral = parent_node(v, k, &at);
		struct vec3 root;

		redo[k] = sh->cleared != sh->n || sh->cleared_stopped != sh->stopped ||
			  (lateral && redo[sh->parent]);
		if (!redo[k] || sh->n == 0)
			continue;
		if (!sh->smooth || !sh->pull)
			continue; /* made by hand, not grown: nowhere to keep what is found */
		if (lateral) {
			const struct vine_shoot *ps = &v->shoots[sh->parent];

			if (!ps->pull || at >= ps->cleared)
				continue; /* its parent not cleared: it is drawn smoothed */
			root = pulled(ps->axis[at], ps->smooth[at], ps->pull[at]);
		}
		smooth_shoot(v, k, lateral ? &root : NULL, sm);
		clear_shoot(v, s, k, sm);
	}
	free(sm);
	free(redo);
	return 0;
}

/* u turned by angle a about unit t (u perpendicular to t). */
static struct vec3 turn(struct vec3 u, struct vec3 t, double a)
{
	return vec3_add(vec3_scale(u, cos(a)), vec3_scale(vec3_cross(t, u), sin(a)));
}

/* Leaves carried at node k of shoot s, before the buds take theirs; *cot when cotyledons. */
static int node_leaves(const struct vine *v, size_t s, size_t k, bool *cot)
{
	*cot = v->shoots[s].parent < 0 && k == 1 && v->p.cotyledons > 0;
	if (*cot)
		return v->p.cotyledons;
	return v->p.leaves_per_node > 0 ? v->p.leaves_per_node : 0;
}

/*
 * The phyllotaxis angle of leaf j of node k (about the stem, from T x up): alternate,
 * each node's leaf half a turn from the last; opposite pairs a quarter turn from the last
 * pair (decussate); the cotyledons a pair, or one.
 */
static double leaf_angle(const struct vine *v, size_t k, int j, bool cot)
{
	if (cot)
		return VEC_PI * j;
	if (v->p.leaves_per_node >= 2)
		return 0.5 * VEC_PI * (double)(k % 4) + VEC_PI * j;
	return VEC_PI * (double)(k % 2);
}

/* The reference direction at a node: T x up, or x when T is vertical. */
static struct vec3 leaf_ref(struct vec3 t)
{
	return vec3_norm_or(vec3_cross(t, vec3(0, 1, 0)), vec3(1, 0, 0));
}

/*
 * The leaves of node k of shoot s, on its smoothed axis a, appended to out (room for
 * them made already). A bud takes the leaf nearest the way its lateral starts out.
 */
static size_t node_build(const struct vine *v, size_t s, size_t k, const struct vec3 *a,
			 struct vine_leaf *out)
{
	const struct vine_shoot *sh = &v->shoots[s];
	size_t d = points_per_internode(v), at = k * d, made = 0;
	double g = v->p.leaf_size;
	bool cot, gone[64] = { false };
	int count = node_leaves(v, s, k, &cot);
	struct vec3 t = tube_frame_tangent(a, sh->n, at), ref = leaf_ref(t), o[64];

	if (count > 64)
		count = 64; /* vine_params_check keeps it to 2 */
	for (int j = 0; j < count; j++)
		o[j] = turn(ref, t, leaf_angle(v, k, j, cot));
	if (!cot) {
		for (size_t j = 0; j < v->nshoots; j++) {
			const struct vine_shoot *ls = &v->shoots[j];
			struct vec3 go;
			int best = -1;

			if (ls->parent != (int)s || ls->node < 0 || (size_t)ls->node != k)
				continue;
			go = ls->n > 1 ? vec3_sub(ls->axis[1], ls->axis[0]) : ref;
			for (int i = 0; i < count; i++)
				if (!gone[i] && (best < 0 || vec3_dot(o[i], go) > vec3_dot(o[best], go)))
					best = i;
			if (best >= 0)
				gone[best] = true;
		}
	}
	for (int j = 0; j < count; j++) {
		struct vine_leaf *l;
		struct vec3 p = a[at], w;

		if (gone[j])
			continue;
		l = &out[made++];
		w = vec3_norm_or(vec3_cross(o[j], t), ref); /* the front faces up the stem */
		l->shoot = s;
		l->node = k;
		l->cotyledon = cot;
		l->p[0] = p;
		l->p[1] = vec3_add(p, vec3_scale(vec3_add(o[j], w), g));
		l->p[2] = vec3_add(p, vec3_scale(o[j], 2 * g));
		l->p[3] = vec3_add(p, vec3_scale(vec3_sub(o[j], w), g));
	}
	return made;
}

/* Every leaf on the smoothed axes; *out allocated. 0 or -ENOMEM. */
static int leaves_on(const struct vine *v, struct vec3 *const *axes, struct vine_leaf **out,
		     size_t *n)
{
	size_t total = 0, made = 0;
	struct vine_leaf *l;

	for (size_t s = 0; s < v->nshoots; s++)
		for (size_t k = 1; k <= vine_shoot_nodes(v, s); k++) {
			bool cot;

			total += (size_t)node_leaves(v, s, k, &cot);
		}
	l = malloc((total ? total : 1) * sizeof(*l));
	if (!l)
		return -ENOMEM;
	for (size_t s = 0; s < v->nshoots; s++)
		for (size_t k = 1; k <= vine_shoot_nodes(v, s); k++)
			made += node_build(v, s, k, axes[s], l + made);
	*out = l;
	*n = made;
	return 0;
}

int vine_leaves(const struct vine *v, struct vine_leaf **out, size_t *n)
{
	struct vec3 **axes;
	int ret = smooth_all(v, &axes);

	if (ret < 0)
		return ret;
	ret = leaves_on(v, axes, out, n);
	free_all(v, axes);
	return ret;
}

static void push_vertex(struct mesh *m, struct vec3 p, struct vec3 n)
{
	float *pos = &m->positions[3 * m->nvertices], *nor = &m->normals[3 * m->nvertices];

	pos[0] = (float)p.x;
	pos[1] = (float)p.y;
	pos[2] = (float)p.z;
	nor[0] = (float)n.x;
	nor[1] = (float)n.y;
	nor[2] = (float)n.z;
	m->nvertices++;
}

static void push_tri(struct mesh *m, size_t a, size_t b, size_t c)
{
	uint32_t *idx = &m->indices[m->nindices];

	idx[0] = (uint32_t)a;
	idx[1] = (uint32_t)b;
	idx[2] = (uint32_t)c;
	m->nindices += 3;
}

static int ring_sides(const struct vine *v)
{
	return v->p.ring_sides >= 3 ? v->p.ring_sides : 3;
}

/*
 * A shoot's tube: a ring of M sides at every point of its smoothed axis a (counter-clockwise
 * about the tangent, so the sides wind counter-clockwise seen from outside), open at the
 * root (on the ground, or inside its parent), closed by a cone VINE_TIP_LENGTH radii long.
 * M (n + 1) + 1 vertices, 2 M (n - 1) + M triangles; room made already.
 */
void vine_stem_tube(const struct vec3 *a, size_t n, size_t sides, double r, struct vec3 *t,
		    struct vec3 *nr, struct mesh *m)
{
	size_t base = m->nvertices, cone, apex;
	double h = VINE_TIP_LENGTH * r;

	/* rotation-minimising: the rings do not twist */
	tube_frame_build(a, n, t, nr);
	for (size_t i = 0; i < n; i++) {
		struct vec3 b = vec3_cross(t[i], nr[i]);

		for (size_t j = 0; j < sides; j++) {
			double th = 2.0 * VEC_PI * (double)j / (double)sides;
			struct vec3 rad = vec3_add(vec3_scale(nr[i], cos(th)), vec3_scale(b, sin(th)));

			push_vertex(m, vec3_add(a[i], vec3_scale(rad, r)), rad);
		}
	}
	for (size_t i = 0; i + 1 < n; i++) {
		size_t r0 = base + i * sides, r1 = r0 + sides;

		for (size_t j = 0; j < sides; j++) {
			size_t j1 = j + 1 == sides ? 0 : j + 1;

			push_tri(m, r0 + j, r1 + j1, r1 + j);
			push_tri(m, r0 + j, r0 + j1, r1 + j1);
		}
	}
	/* the tip: the last ring again with the cone's normals, and its apex */
	cone = m->nvertices;
	{
		struct vec3 tt = t[n - 1], b = vec3_cross(tt, nr[n - 1]);

		for (size_t j = 0; j < sides; j++) {
			double th = 2.0 * VEC_PI * (double)j / (double)sides;
			struct vec3 rad = vec3_add(vec3_scale(nr[n - 1], cos(th)), vec3_scale(b, sin(th)));
			struct vec3 nor = vec3_norm_or(vec3_add(vec3_scale(rad, h), vec3_scale(tt, r)), tt);

			push_vertex(m, vec3_add(a[n - 1], vec3_scale(rad, r)), nor);
		}
		apex = m->nvertices;
		push_vertex(m, vec3_add(a[n - 1], vec3_scale(tt, h)), tt);
	}
	for (size_t j = 0; j < sides; j++)
		push_tri(m, cone + j, cone + (j + 1 == sides ? 0 : j + 1), apex);
}

/* A leaf as a quad (two triangles) facing its front; room made already. */
static void leaf_quad(const struct vine_leaf *l, struct mesh *m)
{
	size_t base = m->nvertices;
	/* the diagonals' cross product: the front, from which the corners run counter-clockwise */
	struct vec3 nor = vec3_norm_or(vec3_cross(vec3_sub(l->p[2], l->p[0]), vec3_sub(l->p[3], l->p[1])),
				       vec3(0, 1, 0));

	for (int i = 0; i < 4; i++)
		push_vertex(m, l->p[i], nor);
	push_tri(m, base, base + 1, base + 2);
	push_tri(m, base, base + 2, base + 3);
}

int vine_mesh_append(const struct vine *v, struct mesh *stem, struct mesh *leaves)
{
	size_t sides = (size_t)ring_sides(v), nv = 0, ni = 0, longest = 0, nl = 0;
	struct vec3 **axes, *t = NULL, *nr = NULL;
	struct vine_leaf *l = NULL;
	int ret = smooth_all(v, &axes);

	if (ret < 0)
		return ret;
	for (size_t s = 0; s < v->nshoots; s++) {
		size_t n = v->shoots[s].n;

		if (n < 2)
			continue; /* a bud that never grew: nothing to sweep */
		nv += sides * (n + 1) + 1;
		ni += 3 * (2 * sides * (n - 1) + sides);
		longest = n > longest ? n : longest;
	}
	ret = leaves_on(v, axes, &l, &nl);
	if (ret == 0) {
		t = malloc((longest ? longest : 1) * sizeof(*t));
		nr = malloc((longest ? longest : 1) * sizeof(*nr));
		if (!t || !nr)
			ret = -ENOMEM;
	}
	/* room for everything first: either mesh comes out whole or as it was */
	if (ret == 0)
		ret = mesh_reserve(stem, nv, ni);
	if (ret == 0)
		ret = mesh_reserve(leaves, 4 * nl, 6 * nl);
	if (ret == 0) {
		for (size_t s = 0; s < v->nshoots; s++)
			if (v->shoots[s].n >= 2)
				vine_stem_tube(axes[s], v->shoots[s].n, (size_t)ring_sides(v),
					       v->p.radius, t, nr, stem);
		for (size_t i = 0; i < nl; i++)
			leaf_quad(&l[i], leaves);
	}
	free(t);
	free(nr);
	free(l);
	free_all(v, axes);
	return ret;
}
