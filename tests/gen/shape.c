/* SPDX-License-Identifier: MIT */
#include "shape.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

int shape_parse(char **argv, int argc, struct shape *s)
{
	int need;

	memset(s, 0, sizeof(*s));
	if (argc < 1)
		return 0;
	if (!strcmp(argv[0], "sphere"))
		s->kind = SHAPE_SPHERE, need = 5;
	else if (!strcmp(argv[0], "box"))
		s->kind = SHAPE_BOX, need = 7;
	else if (!strcmp(argv[0], "cone"))
		s->kind = SHAPE_CONE, need = 6;
	else
		return 0;
	if (argc < need)
		return 0;
	for (int k = 0; k < 3; k++)
		s->c[k] = atof(argv[1 + k]);
	if (s->kind == SHAPE_BOX)
		for (int k = 0; k < 3; k++)
			s->half[k] = 0.5 * atof(argv[4 + k]);
	else
		s->r = atof(argv[4]);
	if (s->kind == SHAPE_CONE)
		s->h = atof(argv[5]);
	return need;
}

/* Distance from (x, y) to the segment (ax, ay)-(bx, by). */
static double seg2(double x, double y, double ax, double ay, double bx, double by)
{
	double dx = bx - ax, dy = by - ay;
	double t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);

	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return hypot(x - ax - t * dx, y - ay - t * dy);
}

double shape_distance(const struct shape *s, const double x[3])
{
	double d[3] = { x[0] - s->c[0], x[1] - s->c[1], x[2] - s->c[2] };

	switch (s->kind) {
	case SHAPE_BOX: {
		double q[3], out = 0, in = -INFINITY;

		for (int k = 0; k < 3; k++) {
			q[k] = fabs(d[k]) - s->half[k];
			out += q[k] > 0 ? q[k] * q[k] : 0;
			in = fmax(in, q[k]);
		}
		return sqrt(out) + fmin(in, 0);
	}
	case SHAPE_CONE: {
		/* the meridian half-plane: the triangle (0, 0), (r, 0), (0, h) in (rho, y); its
		 * edge on the axis is no surface */
		double rho = hypot(d[0], d[2]), y = d[1];
		double dist = fmin(seg2(rho, y, 0, 0, s->r, 0), seg2(rho, y, s->r, 0, 0, s->h));
		bool inside = y >= 0 && rho <= s->r * (1 - y / s->h);

		return inside ? -dist : dist;
	}
	case SHAPE_SPHERE:
		break;
	}
	return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - s->r;
}

/* Two numbers in [0, 1) for sample i: a Kronecker sequence (even spread, no clumps). */
static void uv(unsigned i, double *u, double *v)
{
	*u = fmod(0.5 + i * 0.7548776662466927, 1.0);
	*v = fmod(0.5 + i * 0.5698402909980532, 1.0);
}

static void set3(double p[3], double x, double y, double z)
{
	p[0] = x;
	p[1] = y;
	p[2] = z;
}

void shape_sample(const struct shape *s, unsigned i, unsigned n, double p[3], double nrm[3])
{
	double u, v, w = (i + 0.5) / n; /* w picks the part of the surface by area */

	uv(i, &u, &v);
	switch (s->kind) {
	case SHAPE_BOX: {
		const double *h = s->half;
		double area[3] = { h[1] * h[2], h[0] * h[2], h[0] * h[1] }, sum = area[0] + area[1] + area[2];
		int axis = w * sum < area[0] ? 0 : w * sum < area[0] + area[1] ? 1 : 2;
		int a = (axis + 1) % 3, b = (axis + 2) % 3;
		double sign = (i & 1) ? 1.0 : -1.0;

		set3(nrm, 0, 0, 0);
		nrm[axis] = sign;
		p[axis] = s->c[axis] + sign * h[axis];
		p[a] = s->c[a] + (2 * u - 1) * h[a];
		p[b] = s->c[b] + (2 * v - 1) * h[b];
		return;
	}
	case SHAPE_CONE: {
		double slant = hypot(s->r, s->h), side = PI * s->r * slant, base = PI * s->r * s->r;
		double phi = 2 * PI * v;

		if (w * (side + base) < base) {
			double rho = s->r * sqrt(u);

			set3(p, s->c[0] + rho * cos(phi), s->c[1], s->c[2] + rho * sin(phi));
			set3(nrm, 0, -1, 0);
		} else {
			/* uniform by area: the distance from the apex goes as sqrt */
			double t = sqrt(u), rho = s->r * t;

			set3(p, s->c[0] + rho * cos(phi), s->c[1] + s->h * (1 - t), s->c[2] + rho * sin(phi));
			set3(nrm, s->h * cos(phi) / slant, s->r / slant, s->h * sin(phi) / slant);
		}
		return;
	}
	case SHAPE_SPHERE:
		break;
	}
	/* Fibonacci sphere: w uniform in height is uniform by area */
	{
		double y = 1 - 2 * w, rho = sqrt(fmax(0, 1 - y * y)), phi = i * 2.399963229728653;

		set3(nrm, rho * cos(phi), y, rho * sin(phi));
		for (int k = 0; k < 3; k++)
			p[k] = s->c[k] + s->r * nrm[k];
	}
}

double shape_inradius(const struct shape *s)
{
	switch (s->kind) {
	case SHAPE_BOX:
		return fmin(s->half[0], fmin(s->half[1], s->half[2]));
	case SHAPE_CONE:
		return s->r * s->h / (s->r + hypot(s->r, s->h));
	case SHAPE_SPHERE:
		break;
	}
	return s->r;
}
