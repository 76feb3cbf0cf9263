/* SPDX-License-Identifier: MIT */
/*
 * A twining vine's growth (issue 16, docs/vines.md) on supports made here: a pole (the
 * helix: its radius, handedness, pitch, segment lengths and lean, clearance), a pole
 * shorter than the growth (the apex stops above it, the buds take over in order), a
 * planting out of reach (the apex stops after circling two internodes), a cross (past the
 * junction up the upper arm), a T (stops above the bar); growth in small time steps gives
 * what growth at once does.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "test.h"
#include "vine.h"
#include "vine_support.h"
#include "vine_test.h"

#define DEG (180.0 / VEC_PI)

static struct vine_params params(double angle, enum vine_twining tw, int internodes)
{
	struct vine_params p;

	vine_params_default(&p);
	p.angle = angle;
	p.twining = tw;
	p.internodes = internodes;
	return p;
}

/* On a pole of radius R (64 sides) 1 m tall, planted r + 13 mm from its side. */
static void test_pole(double angle, enum vine_twining tw)
{
	const double R = 0.02, H = 1.0;
	struct vine_support *s = pole(R, H, 64);
	struct vine_params p = params(angle, tw, 300);
	struct vine v;
	const struct vine_shoot *sh;
	size_t d = (size_t)p.points_per_internode, u = (size_t)p.free_nodes * d;
	double l = p.internode / (double)d;
	struct helix h;

	vine_init(&v, &p, vec3(R + 0.015, 0, 0));
	CHECK_INT(vine_grow(&v, s, 1e9), 0);
	sh = &v.shoots[0];
	/* every segment l/d; from U d on each leans theta_p (none slides on a plain pole) */
	for (size_t i = 1; i < sh->n; i++) {
		struct vec3 e = vec3_sub(sh->axis[i], sh->axis[i - 1]);

		CHECK_NEAR(vec3_len(e), l, 1e-9);
		if (i > u)
			CHECK_NEAR(acos(e.y / vec3_len(e)) * DEG, angle, 1e-6);
		else
			CHECK_NEAR(e.y, l, 1e-12);
	}
	/* the twined part: points touching, below the top's rim */
	CHECK(pole_helix(sh, H - 0.05, &h));
	CHECK(h.first > 0 && h.last > h.first + 8 * d);
	CHECK_NEAR(h.radius_min, R + p.radius, 0.1 * p.radius);
	CHECK_NEAR(h.radius_max, R + p.radius, 0.1 * p.radius);
	/* right: counter-clockwise seen from above, a right-handed helix; left the mirror */
	CHECK(tw == VINE_RIGHT ? h.turned > 2 * VEC_PI : h.turned < -2 * VEC_PI);
	{
		double want = 2 * VEC_PI * (R + p.radius) / tan(angle / DEG);

		printf("pole, %g degrees, %s: pitch %.4f m, 2 pi (R + r) / tan theta_p = %.4f m\n",
		       angle, tw == VINE_RIGHT ? "right" : "left", h.pitch, want);
		CHECK(fabs(h.pitch - want) <= 0.05 * want);
	}
	/* nothing closer than 0.95 r */
	for (size_t k = 0; k < v.nshoots; k++)
		for (size_t i = 0; i < v.shoots[k].n; i++)
			CHECK(vine_support_distance(s, v.shoots[k].axis[i], 1, NULL, NULL) >=
			      0.95 * p.radius);
	/* the stems' meshes: no vertex more than 0.05 r inside the pole (below its top, where
	 * the pole is a cylinder of radius R: 64 sides, their faces R cos(pi / 64) out) */
	{
		struct mesh stem, leaves;

		mesh_init(&stem);
		mesh_init(&leaves);
		CHECK_INT(vine_mesh_append(&v, &stem, &leaves), 0);
		CHECK(stem.nvertices > 0 && leaves.nvertices > 0);
		for (size_t i = 0; i < stem.nvertices; i++) {
			const float *q = stem.positions + 3 * i;

			if (q[1] > 0.0 && q[1] < H - 0.01)
				CHECK(hypot(q[0], q[2]) >= R * cos(VEC_PI / 64) - 0.05 * p.radius);
		}
		mesh_finish(&stem);
		mesh_finish(&leaves);
	}
	/* the pole is 1 m and the budget longer: the apex stops above its top, and the buds
	 * at nodes U + 1, U + 2, ... take over in that order */
	CHECK(sh->stopped);
	CHECK(sh->axis[sh->n - 1].y > H);
	CHECK(v.nshoots >= 3);
	for (size_t k = 1; k < v.nshoots; k++) {
		CHECK_INT(v.shoots[k].parent, 0);
		CHECK_INT(v.shoots[k].node, p.free_nodes + (int)k);
	}
	vine_finish(&v);
	vine_support_destroy(s);
}

/* Planted out of reach: nothing touches, the apex stops at (U + 2) d. */
static void test_out_of_reach(void)
{
	struct mesh_build m = { 0 };
	struct vine_support *s;
	struct vine_params p = params(18, VINE_LEFT, 40);
	struct vine v;

	cylinder(&m, 0.02, 1, 32, vec3(0, 0, 0), 1);
	s = support_of(&m);
	vine_init(&v, &p, vec3(0.5, 0, 0));
	CHECK_INT(vine_grow(&v, s, 1e9), 0);
	CHECK(v.shoots[0].stopped);
	CHECK_INT(v.shoots[0].n - 1, (p.free_nodes + 2) * p.points_per_internode);
	for (size_t k = 0; k < v.nshoots; k++)
		for (size_t i = 0; i < v.shoots[k].n; i++)
			CHECK(!v.shoots[k].contact[i]);
	CHECK(vine_done(&v));
	vine_finish(&v);
	vine_support_destroy(s);
}

/*
 * Every raw point of v at least r (to rounding) outside the cylinders: a pole of radius R
 * on the y axis from 0 to H, and a bar of radius rb along x from x0 to x1 at height yb;
 * returns the least clearance over r. Measured from the cylinders themselves (32 sides:
 * their faces R cos(pi / 32) out), not the support's index.
 */
static double outside_cross(const struct vine *v, double R, double H, double rb, double yb,
			    double x0, double x1)
{
	double r = v->p.radius, worst = INFINITY, face = cos(VEC_PI / 32);

	for (size_t k = 0; k < v->nshoots; k++)
		for (size_t i = 1; i < v->shoots[k].n; i++) {
			struct vec3 p = v->shoots[k].axis[i];
			double dp = p.y >= 0 && p.y <= H ? hypot(p.x, p.z) - R * face : INFINITY;
			double db = p.x >= x0 && p.x <= x1 ? hypot(p.y - yb, p.z) - rb * face : INFINITY;
			double d = fmin(dp, db);

			worst = fmin(worst, d / r);
			if (!(d >= (1 - 1e-6) * r - 0.01 * R))
				fprintf(stderr, "shoot %zu point %zu (%.5f %.5f %.5f): %.3f r from the "
					"cylinders' faces\n", k, i, p.x, p.y, p.z, d / r);
			CHECK(d >= (1 - 1e-6) * r - 0.01 * R);
		}
	return worst;
}

/* A cross (a bar through the pole at 0.5 m) and a T (the bar on top at 0.6 m); the raw
 * axis never inside either (the command line's cross, its bar as thick as the pole, took a
 * left-twining stem 3.4 mm into the bar: a step of l/d = 7.5 mm reached through the
 * surface to a point r clear inside). */
static void test_cross_and_t(void)
{
	struct mesh_build m = { 0 };
	struct vine_support *s;
	struct vine_params p = params(18, VINE_RIGHT, 60);
	struct vine v;
	double top = 0;

	cylinder(&m, 0.02, 1.2, 32, vec3(0, 0, 0), 1);
	cylinder(&m, 0.015, 0.6, 32, vec3(-0.3, 0.5, 0), 0);
	s = support_of(&m);
	vine_init(&v, &p, vec3(0.035, 0, 0));
	CHECK_INT(vine_grow(&v, s, 1e9), 0);
	for (size_t i = 0; i < v.shoots[0].n; i++)
		top = fmax(top, v.shoots[0].axis[i].y);
	printf("cross: the main axis reaches %.3f m (the junction at 0.5 m, the pole's top 1.2 m)\n",
	       top);
	CHECK(top > 1.0); /* twined past the junction, up the upper arm */
	outside_cross(&v, 0.02, 1.2, 0.015, 0.5, -0.3, 0.3);
	vine_finish(&v);
	vine_support_destroy(s);

	/* the command line's cross, both ways */
	for (int tw = 0; tw < 2; tw++) {
		struct vine_params q = params(18, tw ? VINE_RIGHT : VINE_LEFT, 60);

		cylinder(&m, 0.02, 1.0, 32, vec3(0, 0, 0), 1);
		cylinder(&m, 0.02, 0.6, 32, vec3(-0.3, 0.5, 0), 0);
		s = support_of(&m);
		vine_init(&v, &q, vec3(0.023, 0, 0));
		CHECK_INT(vine_grow(&v, s, 1e9), 0);
		printf("the command line's cross, %s: the raw axis %.4f r outside it at worst\n",
		       tw ? "right" : "left", outside_cross(&v, 0.02, 1.0, 0.02, 0.5, -0.3, 0.3));
		vine_finish(&v);
		vine_support_destroy(s);
	}

	cylinder(&m, 0.02, 0.6, 32, vec3(0, 0, 0), 1);
	cylinder(&m, 0.015, 0.6, 32, vec3(-0.3, 0.615, 0), 0);
	s = support_of(&m);
	vine_init(&v, &p, vec3(0.035, 0, 0));
	CHECK_INT(vine_grow(&v, s, 1e9), 0);
	top = 0;
	for (size_t i = 0; i < v.shoots[0].n; i++)
		top = fmax(top, v.shoots[0].axis[i].y);
	printf("T: the main axis stops at %.3f m (the bar's top at 0.63 m)\n", top);
	CHECK(v.shoots[0].stopped);
	CHECK(top > 0.63 && top < 0.63 + 3 * p.internode);
	outside_cross(&v, 0.02, 0.6, 0.015, 0.615, -0.3, 0.3);
	vine_finish(&v);
	vine_support_destroy(s);
}

/* The drawn axes of a and b (vine_smooth: smoothed, kept clear) the same, bit for bit;
 * returns the points a pull moved from the smoothing. */
static size_t same_drawn(const struct vine *a, const struct vine *b)
{
	size_t pulled = 0;

	CHECK_INT(a->nshoots, b->nshoots);
	for (size_t k = 0; k < a->nshoots; k++) {
		struct vec3 *x, *y;

		CHECK_INT(a->shoots[k].n, b->shoots[k].n);
		CHECK_INT(a->shoots[k].cleared, a->shoots[k].n);
		CHECK_INT(b->shoots[k].cleared, b->shoots[k].n);
		CHECK_INT(vine_smooth(a, k, &x), 0);
		CHECK_INT(vine_smooth(b, k, &y), 0);
		CHECK(memcmp(x, y, a->shoots[k].n * sizeof(*x)) == 0);
		for (size_t i = 0; i < a->shoots[k].n; i++)
			pulled += a->shoots[k].pull[i] != 1.0;
		free(x);
		free(y);
	}
	return pulled;
}

/* Growing by frames (30 or 60 a second of some clock) gives what growing at once does:
 * the raw axes, and the drawn ones, which each frame keeps clear of the support anew (on
 * a T, where they are pulled back at the junction). */
static void test_steps(void)
{
	struct mesh_build m = { 0 };
	struct vine_support *s;
	struct vine_params p = params(30, VINE_RIGHT, 60);
	struct vine a, b;
	double end = 700 * p.step_time;
	size_t pulled = 0;

	/* issue 24's T: a pole of 1 cm, 0.8 m, a bar as thick across its top */
	cylinder(&m, 0.01, 0.8, 32, vec3(0, 0, 0), 1);
	cylinder(&m, 0.01, 0.4, 32, vec3(-0.2, 0.8, 0), 0);
	s = support_of(&m);
	vine_init(&a, &p, vec3(0.014, 0, 0.002));
	CHECK_INT(vine_grow(&a, s, end), 0);
	for (int fps = 30; fps <= 60; fps += 30) {
		vine_init(&b, &p, vec3(0.014, 0, 0.002));
		/* a step of growth every 0.05 s of the clock: frames fall anywhere in it */
		for (double t = 0; t <= end + 1e-9; t += p.step_time * 20.0 / fps)
			CHECK_INT(vine_grow(&b, s, t), 0);
		CHECK_INT(vine_grow(&b, s, end), 0);
		CHECK_INT(a.nshoots, b.nshoots);
		for (size_t k = 0; k < a.nshoots; k++) {
			CHECK_INT(a.shoots[k].n, b.shoots[k].n);
			CHECK(memcmp(a.shoots[k].axis, b.shoots[k].axis,
				     a.shoots[k].n * sizeof(*a.shoots[k].axis)) == 0);
		}
		pulled = same_drawn(&a, &b);
		vine_finish(&b);
	}
	printf("by frames on the T: the same raw and drawn axes, %zu of %zu points pulled clear\n",
	       pulled, a.points + a.nshoots);
	CHECK(pulled > 0);
	/* a copy draws the same */
	CHECK_INT(vine_copy(&b, &a), 0);
	CHECK(same_drawn(&a, &b) == pulled);
	vine_finish(&b);
	vine_finish(&a);
	vine_support_destroy(s);
}

int main(void)
{
	test_pole(18, VINE_RIGHT);
	test_pole(18, VINE_LEFT);
	test_pole(30, VINE_RIGHT);
	test_out_of_reach();
	test_cross_and_t();
	test_steps();
	printf("ok\n");
	return 0;
}
