/* SPDX-License-Identifier: MIT */
/* What the vine tests share (vine_test.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "vine_test.h"

void cylinder(struct mesh_build *m, double R, double h, int sides, struct vec3 o, int axis)
{
	size_t b = m->np;

	m->p = realloc(m->p, (m->np + 2 * (size_t)sides + 2) * 3 * sizeof(*m->p));
	m->t = realloc(m->t, (m->nt + 4 * (size_t)sides) * 3 * sizeof(*m->t));
	CHECK(m->p && m->t);
	for (int i = 0; i < sides; i++) {
		double a = 2 * VEC_PI * i / sides, u = R * cos(a), w = R * sin(a);

		for (int e = 0; e < 2; e++) {
			float *q = m->p + 3 * m->np++;
			struct vec3 v = axis == 1 ? vec3(o.x + u, o.y + e * h, o.z + w) :
						    vec3(o.x + e * h, o.y + u, o.z + w);

			q[0] = (float)v.x;
			q[1] = (float)v.y;
			q[2] = (float)v.z;
		}
	}
	for (int e = 0; e < 2; e++) {
		float *q = m->p + 3 * m->np++;
		struct vec3 v = axis == 1 ? vec3(o.x, o.y + e * h, o.z) : vec3(o.x + e * h, o.y, o.z);

		q[0] = (float)v.x;
		q[1] = (float)v.y;
		q[2] = (float)v.z;
	}
	for (int i = 0; i < sides; i++) {
		uint32_t j = (uint32_t)((i + 1) % sides), a0 = (uint32_t)(b + 2 * (size_t)i);
		uint32_t a1 = a0 + 1, b0 = (uint32_t)b + 2 * j, b1 = b0 + 1;
		uint32_t c0 = (uint32_t)(b + 2 * (size_t)sides), c1 = c0 + 1;
		uint32_t tri[4][3] = { { a0, b0, a1 }, { a1, b0, b1 }, { c0, b0, a0 }, { c1, a1, b1 } };

		memcpy(m->t + 3 * m->nt, tri, sizeof(tri));
		m->nt += 4;
	}
}

struct vine_support *support_of(struct mesh_build *m)
{
	struct vine_support *s;

	CHECK_INT(vine_support_create(m->p, m->np, m->t, m->nt, &s), 0);
	free(m->p);
	free(m->t);
	memset(m, 0, sizeof(*m));
	return s;
}

struct vine_support *pole(double R, double h, int sides)
{
	struct mesh_build m = { 0 };

	cylinder(&m, R, h, sides, vec3(0, 0, 0), 1);
	return support_of(&m);
}

double azimuth(struct vec3 p)
{
	return atan2(-p.z, p.x);
}

bool pole_helix(const struct vine_shoot *sh, double below, struct helix *h)
{
	size_t first = 0, last = 0;
	bool any = false;
	double turned = 0, sum = 0, lo = INFINITY, hi = 0;

	for (size_t i = 0; i < sh->n; i++) {
		if (!sh->contact[i] || sh->axis[i].y > below)
			continue;
		if (!any)
			first = i;
		any = true;
		last = i;
	}
	if (!any || last == first)
		return false;
	for (size_t i = first; i <= last; i++) {
		double rad = hypot(sh->axis[i].x, sh->axis[i].z);

		if (i > first)
			turned += remainder(azimuth(sh->axis[i]) - azimuth(sh->axis[i - 1]), 2 * VEC_PI);
		sum += rad;
		lo = fmin(lo, rad);
		hi = fmax(hi, rad);
	}
	h->first = first;
	h->last = last;
	h->turned = turned;
	h->pitch = (sh->axis[last].y - sh->axis[first].y) / (fabs(turned) / (2 * VEC_PI));
	h->radius_mean = sum / (double)(last - first + 1);
	h->radius_min = lo;
	h->radius_max = hi;
	return true;
}
