/* SPDX-License-Identifier: MIT */
/* Growing in: the front along the skeleton and what it does to a vertex (live.h). */
#include <math.h>

#include "live_private.h"

/* 3u^2 - 2u^3 on [0, 1]: eases in and out; exactly 0 and 1 at the ends and beyond. */
static double ease(double u)
{
	if (!(u > 0))
		return 0.0;
	if (u >= 1)
		return 1.0;
	return u * u * (3.0 - 2.0 * u);
}

void live_grow_setup(struct live_grow *g, const struct live_skeleton *sk)
{
	double dur = LIVE_GROW_RATE_S * sqrt(fmax(sk->d_max, 0.0));

	g->d_max = sk->d_max;
	g->swell = fmax(LIVE_GROW_SWELL * sk->d_max, LIVE_GROW_MIN_SWELL_M);
	/* a micrometre a metre more: a vertex's d is a float, which may round up past d_max */
	g->d_end = g->d_max + g->swell + 1e-6 * (1.0 + g->d_max);
	g->duration = dur < LIVE_GROW_MIN_S   ? LIVE_GROW_MIN_S
		      : dur > LIVE_GROW_MAX_S ? LIVE_GROW_MAX_S
					      : dur;
}

double live_grow_front(const struct live_grow *g, double t)
{
	double u = ease(t / g->duration);

	/* exactly d_end once grown, whatever the rounding of u * d_end */
	return u >= 1.0 ? g->d_end : g->d_end * u;
}

bool live_grow_visible(double front, double d)
{
	return d <= front;
}

double live_grow_pull(const struct live_grow *g, double front, double d)
{
	return ease((front - d) / g->swell);
}

struct vec3 live_grow_position(const struct live_grow *g, double front, const struct live_vertex *v,
			       struct vec3 pos)
{
	double f = live_grow_pull(g, front, v->d), k = 1.0 - f;

	return vec3(pos.x * f + v->point[0] * k, pos.y * f + v->point[1] * k,
		    pos.z * f + v->point[2] * k);
}

/* ease^-1(y) for y in [0, 1], by bisection: ease is increasing there. */
static double ease_inverse(double y)
{
	double lo = 0.0, hi = 1.0;

	if (!(y > 0.0))
		return 0.0;
	if (y >= 1.0)
		return 1.0;
	for (int i = 0; i < 60; i++) {
		double mid = 0.5 * (lo + hi);

		if (ease(mid) < y)
			lo = mid;
		else
			hi = mid;
	}
	return hi;
}

void live_grow_unfold_bounds(double front, double swell, unsigned nframes, double *bound)
{
	for (unsigned k = 0; k <= nframes; k++)
		bound[k] = front - swell * ease_inverse((double)k / (double)(nframes ? nframes : 1));
}

unsigned live_grow_unfold_frame(double front, double swell, unsigned nframes, double d)
{
	unsigned k = 0;

	/* the bounds fall with k: count those at or past d */
	while (k < nframes && d <= front - swell * ease_inverse((double)(k + 1) / (double)nframes))
		k++;
	return k;
}
