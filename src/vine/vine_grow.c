/* SPDX-License-Identifier: MIT */
/*
 * A twining vine's growth (seed 004, Kasakura 3.2; docs/vines.md): circumnutation and
 * apical dominance around a support.
 *
 * The axis is points P_i, d per internode, l/d apart. Up to point U d it grows straight
 * up; from there the apex's free rod, the last two internodes (all one direction, leaning
 * theta_p from the vertical), sweeps about the vertical through its pivot at omega in the
 * twining direction, one new point every step_time. Spheres of radius r at the rod's
 * points are tested against the support: the sweep stops at the first touching azimuth
 * (sampled so that no point moves more than r / 2 between samples, then bisected to
 * within 0.01 r), the touching point nearest the pivot becomes the pivot, and the sweep
 * goes on about it with the angle left. A new point that would come closer than r to the
 * support, or that the step to it would reach through the support (l/d may exceed 2r, and
 * a point deep inside a thick support is r clear too), is turned back against the
 * twining direction (about the vertical through the tip, the least turn that clears it):
 * the thesis moves only the pivot and lets the stem sink in; edaha keeps every point r
 * clear and outside. On a convex support that lays each point on the surface r out, so
 * the twined stem is a helix leaning theta_p. Then vine_clear (vine_shape.c) keeps the
 * drawn, smoothed axis clear too.
 *
 * Apical dominance: an apex whose rod touched nothing for two internodes stops, and the
 * main axis's next bud from the root, at node U + 1, U + 2, ..., grows as the new apex
 * (its node loses a leaf), circling from its first point.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "vine.h"
#include "vine_support.h"

/* Bisection stops when the rod's tip is known to this fraction of r. */
#define VINE_CONTACT_PRECISION 0.01

static double deg(double d)
{
	return d * VEC_PI / 180.0;
}

/* The direction at azimuth az leaning th radians from +y. */
static struct vec3 lean_dir(double th, double az)
{
	return vec3(sin(th) * cos(az), cos(th), -sin(th) * sin(az));
}

/* The rod's direction at azimuth az: leaning theta_p from +y. */
static struct vec3 rod_dir(const struct vine *v, double az)
{
	return lean_dir(deg(v->p.angle), az);
}

/* +1: azimuth grows counter-clockwise seen from above (right-twining); -1: left. */
static double twist(const struct vine *v)
{
	return v->p.twining == VINE_RIGHT ? 1.0 : -1.0;
}

static double seg(const struct vine *v)
{
	return v->p.internode / v->p.points_per_internode;
}

/* Clear of the support by at least r? (No support: always.) */
static bool clear(const struct vine_support *s, const struct vine *v, struct vec3 p)
{
	return !s || vine_support_distance(s, p, v->p.radius, NULL, NULL) >= v->p.radius;
}

/*
 * A new point p, l/d from the tip: clear, and the segment to it crosses no triangle. A
 * point is a step away from the last, more than 2r when l/d is: clear alone would take one
 * deep inside a thick support (a bar, a trunk) as clear as one outside it.
 */
static bool clear_step(const struct vine_support *s, const struct vine *v, struct vec3 tip,
		       struct vec3 p)
{
	return clear(s, v, p) && (!s || !vine_support_crosses(s, tip, p));
}

void vine_init(struct vine *v, const struct vine_params *p, struct vec3 plant)
{
	memset(v, 0, sizeof(*v));
	v->p = *p;
	v->plant = plant;
	v->active = 0;
	v->next_bud = p->free_nodes + 1;
}

void vine_finish(struct vine *v)
{
	for (size_t i = 0; i < v->nshoots; i++) {
		free(v->shoots[i].axis);
		free(v->shoots[i].contact);
		free(v->shoots[i].smooth);
		free(v->shoots[i].pull);
	}
	free(v->shoots);
	memset(v, 0, sizeof(*v));
	v->active = -1;
}

int vine_copy(struct vine *dst, const struct vine *src)
{
	*dst = *src;
	dst->shoots = NULL;
	dst->nshoots = dst->cap = 0;
	if (src->nshoots == 0)
		return 0;
	dst->shoots = calloc(src->nshoots, sizeof(*dst->shoots));
	if (!dst->shoots) {
		vine_finish(dst);
		return -ENOMEM;
	}
	dst->cap = src->nshoots;
	for (size_t i = 0; i < src->nshoots; i++) {
		const struct vine_shoot *s = &src->shoots[i];
		struct vine_shoot *d = &dst->shoots[i];

		bool clears = s->n && s->smooth && s->pull;

		*d = *s;
		d->cap = s->n;
		d->axis = s->n ? malloc(s->n * sizeof(*d->axis)) : NULL;
		d->contact = s->n ? malloc(s->n * sizeof(*d->contact)) : NULL;
		d->smooth = clears ? malloc(s->n * sizeof(*d->smooth)) : NULL;
		d->pull = clears ? malloc(s->n * sizeof(*d->pull)) : NULL;
		dst->nshoots++;
		if ((s->n && (!d->axis || !d->contact)) || (clears && (!d->smooth || !d->pull))) {
			vine_finish(dst);
			return -ENOMEM;
		}
		if (s->n) {
			memcpy(d->axis, s->axis, s->n * sizeof(*d->axis));
			memcpy(d->contact, s->contact, s->n * sizeof(*d->contact));
		}
		if (clears) {
			/* the rest were never written */
			memcpy(d->smooth, s->smooth, s->cleared * sizeof(*d->smooth));
			memcpy(d->pull, s->pull, s->cleared * sizeof(*d->pull));
		} else {
			d->cleared = 0;
		}
	}
	return 0;
}

size_t vine_bytes(const struct vine *v)
{
	size_t n = v->cap * sizeof(*v->shoots);

	for (size_t i = 0; i < v->nshoots; i++) {
		const struct vine_shoot *sh = &v->shoots[i];

		n += sh->cap * (sizeof(struct vec3) + 1);
		if (sh->smooth)
			n += sh->cap * (sizeof(struct vec3) + sizeof(double));
	}
	return n;
}

bool vine_done(const struct vine *v)
{
	return v->active < 0;
}

size_t vine_shoot_nodes(const struct vine *v, size_t shoot)
{
	const struct vine_shoot *sh = &v->shoots[shoot];

	return sh->n ? (sh->n - 1) / (size_t)v->p.points_per_internode : 0;
}

/* Room for one more point on sh, in every per-point array (cap moves once all have it). */
static int reserve_point(struct vine_shoot *sh)
{
	size_t cap;
	struct vec3 *a;
	uint8_t *c;
	double *w;

	if (sh->n < sh->cap)
		return 0;
	cap = sh->cap ? 2 * sh->cap : 64;
	a = realloc(sh->axis, cap * sizeof(*a));
	if (!a)
		return -ENOMEM;
	sh->axis = a;
	c = realloc(sh->contact, cap * sizeof(*c));
	if (!c)
		return -ENOMEM;
	sh->contact = c;
	a = realloc(sh->smooth, cap * sizeof(*a));
	if (!a)
		return -ENOMEM;
	sh->smooth = a;
	w = realloc(sh->pull, cap * sizeof(*w));
	if (!w)
		return -ENOMEM;
	sh->pull = w;
	sh->cap = cap;
	return 0;
}

static int add_shoot(struct vine *v, int parent, int node, struct vec3 root, double az,
		     size_t free_until)
{
	struct vine_shoot *sh;

	if (v->nshoots == v->cap) {
		size_t cap = v->cap ? 2 * v->cap : 8;
		struct vine_shoot *n = realloc(v->shoots, cap * sizeof(*n));

		if (!n)
			return -ENOMEM;
		v->shoots = n;
		v->cap = cap;
	}
	sh = &v->shoots[v->nshoots];
	memset(sh, 0, sizeof(*sh));
	sh->parent = parent;
	sh->node = node;
	sh->azimuth = az;
	sh->free_until = free_until;
	sh->pivot = free_until;
	if (reserve_point(sh) < 0) {
		free(sh->axis);
		free(sh->contact);
		free(sh->smooth);
		free(sh->pull);
		return -ENOMEM;
	}
	sh->axis[0] = root;
	sh->contact[0] = 0;
	sh->n = 1;
	v->nshoots++;
	return 0;
}

/* The rod's points laid out from the pivot at azimuth az. */
static void lay_rod(const struct vine *v, struct vine_shoot *sh, double az)
{
	struct vec3 d = vec3_scale(rod_dir(v, az), seg(v));

	sh->azimuth = az;
	for (size_t k = sh->pivot + 1; k < sh->n; k++)
		sh->axis[k] = vec3_add(sh->axis[sh->pivot], vec3_scale(d, (double)(k - sh->pivot)));
}

/* The first rod point (k from 1, counted from the pivot) within r of the support with
 * the rod at azimuth az; 0 when none is. */
static size_t rod_touch(const struct vine *v, const struct vine_support *s,
			const struct vine_shoot *sh, double az)
{
	struct vec3 d = vec3_scale(rod_dir(v, az), seg(v));

	for (size_t k = 1; sh->pivot + k < sh->n; k++)
		if (!clear(s, v, vec3_add(sh->axis[sh->pivot], vec3_scale(d, (double)k))))
			return k;
	return 0;
}

/*
 * Sweeps the rod by up to `angle` radians in the twining direction, pivoting on each
 * point that touches; true if anything touched.
 */
static bool sweep(struct vine *v, const struct vine_support *s, struct vine_shoot *sh,
		  double angle)
{
	double sg = twist(v), r = v->p.radius;
	double reach_per_point = seg(v) * sin(deg(v->p.angle));
	bool touched = false;

	while (angle > 0 && sh->pivot + 1 < sh->n) {
		double reach = reach_per_point * (double)(sh->n - 1 - sh->pivot);
		double step = reach > 0 ? 0.5 * r / reach : angle, lo = 0, hi = -1;
		size_t k;

		if ((k = rod_touch(v, s, sh, sh->azimuth)) != 0) {
			hi = 0; /* touching already: pivot on it at once */
		} else {
			for (double a = fmin(step, angle);; a = fmin(a + step, angle)) {
				if (rod_touch(v, s, sh, sh->azimuth + sg * a)) {
					hi = a;
					break;
				}
				lo = a;
				if (a >= angle)
					break;
			}
		}
		if (hi < 0) { /* a free turn: the whole angle */
			lay_rod(v, sh, sh->azimuth + sg * angle);
			break;
		}
		while (hi > 0 && (hi - lo) * reach > VINE_CONTACT_PRECISION * r) {
			double mid = 0.5 * (lo + hi);

			if (rod_touch(v, s, sh, sh->azimuth + sg * mid))
				hi = mid;
			else
				lo = mid;
		}
		k = rod_touch(v, s, sh, sh->azimuth + sg * hi);
		lay_rod(v, sh, sh->azimuth + sg * lo);
		sh->pivot += k ? k : 1;
		sh->contact[sh->pivot] = 1;
		touched = true;
		angle -= lo;
	}
	return touched;
}

/*
 * The direction of a point l/d from tip that clears the support: the azimuth nearest az
 * at the rod's lean (turning against the twining direction first, then with it, half a
 * turn each way); walled in there (under a bar across its way), the least lean beyond,
 * in steps of VINE_SLIDE_DEG up to horizontal, so the stem creeps along the obstacle's
 * underside rather than sinking into it. False when nothing clears.
 */
#define VINE_SLIDE_DEG 6.0
/* The point l/d from tip leaning th radians at azimuth az. */
static struct vec3 step_point(const struct vine *v, struct vec3 tip, double th, double az)
{
	return vec3_add(tip, vec3_scale(lean_dir(th, az), seg(v)));
}

static bool unwind(const struct vine *v, const struct vine_support *s, struct vec3 tip,
		   double az, struct vec3 *dir, double *az_out)
{
	double r = v->p.radius;

	for (double lean = v->p.angle; lean <= 90.0 + 1e-9;
	     lean = lean < 90.0 && lean + VINE_SLIDE_DEG > 90.0 ? 90.0 : lean + VINE_SLIDE_DEG) {
		double th = deg(lean), reach = seg(v) * sin(th);
		double step = reach > 0 ? 0.5 * r / reach : VEC_PI;

		for (int way = 0; way < 2; way++) {
			double sg = way == 0 ? -twist(v) : twist(v), lo = 0, hi = -1;

			for (double a = fmin(step, VEC_PI);; a = fmin(a + step, VEC_PI)) {
				if (clear_step(s, v, tip, step_point(v, tip, th, az + sg * a))) {
					hi = a;
					break;
				}
				lo = a;
				if (a >= VEC_PI)
					break;
			}
			if (hi < 0)
				continue;
			while ((hi - lo) * reach > VINE_CONTACT_PRECISION * r) {
				double mid = 0.5 * (lo + hi);

				if (clear_step(s, v, tip, step_point(v, tip, th, az + sg * mid)))
					hi = mid;
				else
					lo = mid;
			}
			*az_out = az + sg * hi;
			*dir = lean_dir(th, *az_out);
			return true;
		}
		if (lean >= 90.0)
			break;
	}
	return false;
}

static void stop(struct vine_shoot *sh)
{
	sh->stopped = true;
}

/* The main axis's horizontal heading at point i (its azimuth), 0 where it is vertical. */
static double heading(const struct vine_shoot *sh, size_t i)
{
	size_t j = i + 1 < sh->n ? i + 1 : i;
	struct vec3 d = vec3_sub(sh->axis[j], sh->axis[j ? j - 1 : 0]);

	return hypot(d.x, d.z) > 1e-12 ? atan2(-d.z, d.x) : 0.0;
}

/* The next apex: the main axis's next bud from the root; -1 when none is left. */
static int next_apex(struct vine *v)
{
	const struct vine_shoot *m = &v->shoots[0];
	size_t d = (size_t)v->p.points_per_internode, at = (size_t)v->next_bud * d;
	int ret;

	if (at >= m->n)
		return -1;
	ret = add_shoot(v, 0, v->next_bud, m->axis[at], heading(m, at) + VEC_PI, 0);
	if (ret < 0)
		return ret;
	v->next_bud++;
	return (int)v->nshoots - 1;
}

/* One step of step_time for the growing apex. */
static int step(struct vine *v, const struct vine_support *s)
{
	struct vine_shoot *sh = &v->shoots[v->active];
	size_t d = (size_t)v->p.points_per_internode, tip = sh->n - 1;
	bool touched;
	struct vec3 q;

	if (reserve_point(sh) < 0)
		return -ENOMEM;
	if (tip < sh->free_until) {
		q = vec3_add(sh->axis[tip], vec3(0, seg(v), 0));
		if (clear_step(s, v, sh->axis[tip], q)) {
			sh->axis[sh->n] = q;
			sh->contact[sh->n++] = 0;
			v->points++;
			return 0;
		}
		/* something right above: the apex starts circling here */
		sh->free_until = tip;
		sh->pivot = tip;
	}
	q = vec3_add(sh->axis[tip], vec3_scale(rod_dir(v, sh->azimuth), seg(v)));
	if (!clear_step(s, v, sh->axis[tip], q)) {
		struct vec3 dir;
		double az;

		/* the tip presses on the support: it is the pivot, and the new point goes the
		 * nearest way that clears; the rod is then that one point, laid already */
		sh->contact[tip] = 1;
		if (!unwind(v, s, sh->axis[tip], sh->azimuth, &dir, &az)) {
			stop(sh); /* walled in: nowhere to grow */
			return 0;
		}
		sh->azimuth = az;
		sh->axis[sh->n] = vec3_add(sh->axis[tip], vec3_scale(dir, seg(v)));
		sh->contact[sh->n++] = 0;
		sh->pivot = sh->n - 1;
		v->points++;
		sh->since_touch = 0;
		return 0;
	}
	sh->axis[sh->n] = q;
	sh->contact[sh->n++] = 0;
	v->points++;
	if (sh->n - 1 > 2 * d && sh->pivot < sh->n - 1 - 2 * d)
		sh->pivot = sh->n - 1 - 2 * d;
	touched = sweep(v, s, sh, deg(v->p.sweep * v->p.step_time));
	sh->since_touch = touched ? 0 : sh->since_touch + 1;
	if (sh->since_touch >= 2 * d)
		stop(sh);
	return 0;
}

int vine_grow(struct vine *v, const struct vine_support *s, double until)
{
	double steps = floor(until / v->p.step_time + 1e-9);
	size_t budget = (size_t)v->p.internodes * (size_t)v->p.points_per_internode;

	if (v->nshoots == 0 && v->active == 0) {
		int ret = add_shoot(v, -1, 0, v->plant, 0.0,
				    (size_t)v->p.free_nodes * (size_t)v->p.points_per_internode);

		if (ret < 0)
			return ret;
	}
	while (v->active >= 0 && (double)v->steps < steps) {
		int ret;

		if (v->points >= budget) {
			v->active = -1;
			break;
		}
		if (v->shoots[v->active].stopped) {
			int next = next_apex(v);

			if (next == -ENOMEM)
				return next;
			v->active = next;
			continue;
		}
		if ((ret = step(v, s)) < 0)
			return ret;
		v->steps++;
	}
	/* the smoothing may bring the drawn stem nearer than the raw axis: keep it clear */
	return vine_clear(v, s);
}
