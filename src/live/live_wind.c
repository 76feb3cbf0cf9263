/* SPDX-License-Identifier: MIT */
/* The wind: the tree's numbers, a frame's, a vertex's offset and its decomposition into
 * morph targets and weights (live.h). */
#include <errno.h>
#include <math.h>
#include <stdbool.h>

#include "live_private.h"

static const double band_hz[LIVE_BANDS] = LIVE_WIND_BAND_HZ;
static const double band_sway[LIVE_BANDS] = LIVE_WIND_BAND_SWAY;
static const double band_bob[LIVE_BANDS] = LIVE_WIND_BAND_BOB;

/* The trunk's period for a tree H metres tall (live.h). */
static double trunk_period(double height)
{
	double p = LIVE_WIND_PERIOD_REF_S * sqrt(fmax(height, 0.0) / LIVE_WIND_HEIGHT_REF_M);

	return p < LIVE_WIND_PERIOD_MIN_S ? LIVE_WIND_PERIOD_MIN_S
	       : p > LIVE_WIND_PERIOD_MAX_S ? LIVE_WIND_PERIOD_MAX_S : p;
}

/* The least harmonic >= want above `above` that is not the across motion's (2 n). */
static int next_harmonic(double want, int above, int across)
{
	int m = (int)lround(want);

	if (m <= above)
		m = above + 1;
	if (m == across)
		m++;
	return m;
}

/* Whether a loop is 0 (the tree's own) or a common loop within its bounds. */
static bool loop_valid(double loop)
{
	return loop == 0.0 ||
	       (loop >= LIVE_WIND_COMMON_LOOP_MIN_S && loop <= LIVE_WIND_COMMON_LOOP_MAX_S);
}

int live_wind_setup(struct live_wind *w, const struct live_skeleton *sk,
		    const struct live_wind_params *p)
{
	int n;

	if (!(p->strength >= 0 && p->strength <= 1) || !isfinite(p->angle) || !loop_valid(p->loop))
		return -EINVAL;
	w->strength = p->strength;
	w->angle = p->angle;
	w->height = sk->height;
	w->period = trunk_period(sk->height);
	if (p->loop > 0.0) {
		/* the common loop: the trunk's period the nearest whole part of it */
		n = (int)lround(p->loop / w->period);
		n = n < 1 ? 1 : n;
		w->loop = p->loop;
	} else {
		n = (int)floor(LIVE_WIND_LOOP_MAX_S / w->period);
		n = n < 1 ? 1 : n;
		w->loop = n * w->period;
	}
	w->harmonic[0] = n;
	for (int k = 1; k < LIVE_BANDS; k++)
		w->harmonic[k] = next_harmonic(band_hz[k] * w->loop, w->harmonic[k - 1], 2 * n);
	w->harmonic[LIVE_BANDS] = next_harmonic(LIVE_WIND_LEAF_HZ * w->loop,
						w->harmonic[LIVE_BANDS - 1], 2 * n);
	w->amp0 = p->strength * LIVE_WIND_TRUNK_SWAY * sk->height;
	w->amp[0] = 0.0;
	for (int k = 1; k < LIVE_BANDS; k++)
		w->amp[k] = p->strength * band_sway[k];
	w->amp_leaf = p->strength * LIVE_WIND_LEAF_SWAY;
	return 0;
}

double live_wind_hz(const struct live_wind *w, int m)
{
	return m / w->loop;
}

double live_wind_angle(const struct live_wind *w, double t)
{
	return w->angle + LIVE_WIND_DRIFT_RAD * sin(2.0 * VEC_PI * t / LIVE_WIND_DRIFT_PERIOD_S);
}

/* The fraction of the loop at t, in [0, 1). */
static double loop_fraction(const struct live_wind *w, double t)
{
	double u = t / w->loop;

	return u - floor(u);
}

/* 2 pi m u reduced to [0, 2 pi): exact for a whole number of cycles. */
static double harmonic_angle(int m, double u)
{
	double c = m * u;

	return 2.0 * VEC_PI * (c - floor(c));
}

static void directions(double angle, struct vec3 *along, struct vec3 *across,
		       struct vec3 dir[LIVE_BANDS])
{
	*along = vec3(cos(angle), 0.0, sin(angle));
	*across = vec3(-sin(angle), 0.0, cos(angle));
	dir[0] = vec3(0, 0, 0);
	for (int k = 1; k < LIVE_BANDS; k++)
		dir[k] = vec3_norm_or(vec3_add(*along, vec3(0.0, band_bob[k], 0.0)), *along);
}

static void frame_at(const struct live_wind *w, double u, double angle, struct live_wind_frame *f)
{
	directions(angle, &f->along, &f->across, f->dir);
	f->amp0 = w->amp0;
	f->amp_leaf = w->amp_leaf;
	f->theta[0] = harmonic_angle(w->harmonic[0], u);
	f->sway_along = sin(f->theta[0]);
	f->sway_across = sin(harmonic_angle(2 * w->harmonic[0], u));
	f->amp[0] = 0.0;
	for (int k = 1; k < LIVE_BANDS; k++) {
		f->amp[k] = w->amp[k];
		f->theta[k] = harmonic_angle(w->harmonic[k], u);
	}
	f->theta_leaf = harmonic_angle(w->harmonic[LIVE_BANDS], u);
}

void live_wind_frame(const struct live_wind *w, double t, double angle, struct live_wind_frame *f)
{
	frame_at(w, loop_fraction(w, t), angle, f);
}

/* A phase byte in radians. */
static double phase_rad(uint8_t p)
{
	return 2.0 * VEC_PI * p / 256.0;
}

static struct vec3 flutter_dir(const struct live_vertex *v)
{
	return vec3(v->flutter[0] / 127.0, v->flutter[1] / 127.0, v->flutter[2] / 127.0);
}

struct vec3 live_wind_frame_offset(const struct live_wind_frame *f, const struct live_vertex *v)
{
	double w0 = f->amp0 * v->w[0];
	struct vec3 o = vec3_add(vec3_scale(f->along, w0 * f->sway_along),
				 vec3_scale(f->across, w0 * LIVE_WIND_FIGURE_EIGHT * f->sway_across));

	for (int k = 1; k < LIVE_BANDS; k++)
		o = vec3_add(o, vec3_scale(f->dir[k], f->amp[k] * v->w[k] *
							  sin(f->theta[k] + phase_rad(v->phase[k]))));
	return vec3_add(o, vec3_scale(flutter_dir(v), f->amp_leaf * v->leaf *
							 sin(f->theta_leaf + phase_rad(v->phase[0]))));
}

struct vec3 live_wind_offset(const struct live_wind *w, const struct live_vertex *v, double t)
{
	struct live_wind_frame f;

	live_wind_frame(w, t, w->angle, &f);
	return live_wind_frame_offset(&f, v);
}

/* sin(theta + phi) = sin theta cos phi + cos theta sin phi: a (sin, cos) pair of targets. */
void live_wind_targets(const struct live_wind *w, const struct live_vertex *v,
		       struct vec3 out[LIVE_WIND_TARGETS])
{
	struct vec3 along, across, dir[LIVE_BANDS], n = flutter_dir(v);
	double w0 = w->amp0 * v->w[0], wl = w->amp_leaf * v->leaf, pl = phase_rad(v->phase[0]);

	directions(w->angle, &along, &across, dir);
	out[LIVE_TARGET_ALONG] = vec3_scale(along, w0);
	out[LIVE_TARGET_ACROSS] = vec3_scale(across, w0 * LIVE_WIND_FIGURE_EIGHT);
	for (int k = 1; k < LIVE_BANDS; k++) {
		double a = w->amp[k] * v->w[k], p = phase_rad(v->phase[k]);
		int j = LIVE_TARGET_BAND1 + 2 * (k - 1);

		out[j] = vec3_scale(dir[k], a * cos(p));
		out[j + 1] = vec3_scale(dir[k], a * sin(p));
	}
	out[LIVE_TARGET_LEAF] = vec3_scale(n, wl * cos(pl));
	out[LIVE_TARGET_LEAF + 1] = vec3_scale(n, wl * sin(pl));
}

void live_wind_weights_at(const struct live_wind *w, double u, double out[LIVE_WIND_TARGETS])
{
	struct live_wind_frame f;

	frame_at(w, u - floor(u), w->angle, &f);
	out[LIVE_TARGET_ALONG] = f.sway_along;
	out[LIVE_TARGET_ACROSS] = f.sway_across;
	for (int k = 1; k < LIVE_BANDS; k++) {
		int j = LIVE_TARGET_BAND1 + 2 * (k - 1);

		out[j] = sin(f.theta[k]);
		out[j + 1] = cos(f.theta[k]);
	}
	out[LIVE_TARGET_LEAF] = sin(f.theta_leaf);
	out[LIVE_TARGET_LEAF + 1] = cos(f.theta_leaf);
}

void live_wind_weights(const struct live_wind *w, double t, double out[LIVE_WIND_TARGETS])
{
	live_wind_weights_at(w, loop_fraction(w, t), out);
}

void live_wind_rates_at(const struct live_wind *w, double u, double out[LIVE_WIND_TARGETS])
{
	struct live_wind_frame f;
	double o0 = 2.0 * VEC_PI * w->harmonic[0] / w->loop;

	frame_at(w, u - floor(u), w->angle, &f);
	out[LIVE_TARGET_ALONG] = o0 * cos(f.theta[0]);
	out[LIVE_TARGET_ACROSS] = 2.0 * o0 * cos(harmonic_angle(2 * w->harmonic[0], u - floor(u)));
	for (int k = 1; k < LIVE_BANDS; k++) {
		double o = 2.0 * VEC_PI * w->harmonic[k] / w->loop;
		int j = LIVE_TARGET_BAND1 + 2 * (k - 1);

		out[j] = o * cos(f.theta[k]);
		out[j + 1] = -o * sin(f.theta[k]);
	}
	{
		double o = 2.0 * VEC_PI * w->harmonic[LIVE_BANDS] / w->loop;

		out[LIVE_TARGET_LEAF] = o * cos(f.theta_leaf);
		out[LIVE_TARGET_LEAF + 1] = -o * sin(f.theta_leaf);
	}
}
