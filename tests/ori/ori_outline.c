/* SPDX-License-Identifier: MIT */
/* A leaf outline's lobes, notches, teeth and base (ori_outline.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ori_outline.h"

static void sub(const double a[3], const double b[3], double out[3])
{
	for (int i = 0; i < 3; i++)
		out[i] = a[i] - b[i];
}

static double dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double a[3], const double b[3], double out[3])
{
	double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2];
	double z = a[0] * b[1] - a[1] * b[0];

	out[0] = x;
	out[1] = y;
	out[2] = z;
}

static bool unit(double v[3])
{
	double l = sqrt(dot(v, v));

	if (!(l > 0))
		return false;
	for (int i = 0; i < 3; i++)
		v[i] /= l;
	return true;
}

/* The outline in its plane: y along the midrib (O to the farthest point), x to its right. */
static int project(const double (*pts)[3], size_t n, double (*p)[2])
{
	double nrm[3] = { 0, 0, 0 }, up[3], right[3], far = 0;
	size_t tip = 0;

	for (size_t k = 0; k < n; k++) {
		const double *a = pts[k], *b = pts[(k + 1) % n];

		nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
		nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
		nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
	}
	if (!unit(nrm))
		return -1;
	for (size_t k = 1; k < n; k++) {
		double d[3];

		sub(pts[k], pts[0], d);
		if (dot(d, d) > far) {
			far = dot(d, d);
			tip = k;
		}
	}
	sub(pts[tip], pts[0], up);
	for (int i = 0; i < 3; i++) /* in the plane */
		up[i] -= dot(up, nrm) * nrm[i];
	if (!unit(up))
		return -1;
	cross(up, nrm, right);
	for (size_t k = 0; k < n; k++) {
		double d[3];

		sub(pts[k], pts[0], d);
		p[k][0] = dot(d, right);
		p[k][1] = dot(d, up);
	}
	return 0;
}

/* The deepest r from lobe i walking by step (+-1) until a higher point or O. */
static double base_of(const double *r, size_t n, size_t i, int step)
{
	double lo = r[i];

	for (size_t k = (i + n + (size_t)step) % n;; k = (k + n + (size_t)step) % n) {
		if (r[k] > r[i])
			return lo;
		lo = fmin(lo, r[k]);
		if (k == 0)
			return lo;
	}
}

int ori_outline_measure(const double (*pts)[3], size_t n, struct ori_outline *m)
{
	double (*p)[2] = calloc(n, sizeof(*p)), *r = calloc(n, sizeof(*r)), rmax = 0, axis[2];
	size_t mid, deep[ORI_OUTLINE_MAX_LOBES];
	int ret = -1;

	memset(m, 0, sizeof(*m));
	if (!p || !r || n < 3 || project(pts, n, p) < 0)
		goto out;
	for (size_t k = 0; k < n; k++) {
		r[k] = hypot(p[k][0], p[k][1]);
		rmax = fmax(rmax, r[k]);
	}
	/* lobes: local maxima of r (the first of a level run) standing out enough */
	for (size_t k = 1; k < n && m->nlobes < ORI_OUTLINE_MAX_LOBES; k++) {
		double prom;

		if (!(r[k] > r[k - 1] && r[k] >= r[(k + 1) % n]))
			continue;
		prom = r[k] - fmax(base_of(r, n, k, -1), base_of(r, n, k, 1));
		if (prom >= ORI_OUTLINE_LOBE_PROMINENCE * rmax)
			m->lobe[m->nlobes++] = k;
	}
	if (m->nlobes == 0)
		goto out;
	mid = m->lobe[m->nlobes / 2];
	m->length = r[mid];
	axis[0] = p[mid][0] / r[mid];
	axis[1] = p[mid][1] / r[mid];
	for (size_t j = 0; j < m->nlobes; j++) {
		m->tip[j] = r[m->lobe[j]] / m->length;
		if (j + 1 < m->nlobes) {
			double lo = INFINITY;

			for (size_t k = m->lobe[j]; k <= m->lobe[j + 1]; k++)
				if (r[k] < lo) {
					lo = r[k];
					deep[j] = k;
				}
			m->sinus[j] = lo / fmin(r[m->lobe[j]], r[m->lobe[j + 1]]);
		}
	}
	/* teeth: salient convex corners but the lobes' tips and the notch's ends at O */
	for (size_t k = 2; k + 1 < n; k++) {
		const double *a = p[k - 1], *b = p[k], *c = p[k + 1];
		double ab[2] = { b[0] - a[0], b[1] - a[1] }, bc[2] = { c[0] - b[0], c[1] - b[1] };
		double ac[2] = { c[0] - a[0], c[1] - a[1] }, h;
		bool tip = false;

		for (size_t j = 0; j < m->nlobes; j++)
			tip = tip || m->lobe[j] == k;
		if (tip || ab[0] * bc[1] - ab[1] * bc[0] <= 0)
			continue;
		h = fabs(ac[0] * ab[1] - ac[1] * ab[0]) / hypot(ac[0], ac[1]) / m->length;
		if (h < ORI_OUTLINE_TOOTH)
			continue;
		m->teeth[axis[0] * b[1] - axis[1] * b[0] > 0 ? 1 : 0]++;
		for (size_t j = 0; j < m->nlobes; j++)
			if ((j == 0 || k > deep[j - 1]) && (j + 1 == m->nlobes || k < deep[j])) {
				m->lobe_teeth[j]++;
				break;
			}
		m->least_tooth = m->least_tooth > 0 ? fmin(m->least_tooth, h) : h;
	}
	/* the base: from O to the first lobe on the right, from the last back on the left */
	m->behind[0] = m->behind[1] = -INFINITY;
	for (size_t k = 1; k <= m->lobe[0]; k++)
		m->behind[0] = fmax(m->behind[0], -(p[k][0] * axis[0] + p[k][1] * axis[1]));
	for (size_t k = m->lobe[m->nlobes - 1]; k < n; k++)
		m->behind[1] = fmax(m->behind[1], -(p[k][0] * axis[0] + p[k][1] * axis[1]));
	m->behind[0] /= m->length;
	m->behind[1] /= m->length;
	ret = 0;
out:
	free(p);
	free(r);
	return ret;
}

/* Keeps the least slack; false with why if it is not above 0. */
static bool slack(double have, double limit, bool above, double *margin, char *why, size_t len,
		  const char *what)
{
	double s = above ? have / limit - 1 : 1 - have / limit;

	*margin = fmin(*margin, s);
	if (s >= 0)
		return true;
	snprintf(why, len, "%s: %.4g against %.4g", what, have, limit);
	return false;
}

bool ori_outline_momiji(const struct ori_outline *m, double *margin, char *why, size_t len)
{
	bool ok = true;

	*margin = INFINITY;
	if (m->nlobes != 5 && m->nlobes != 7) {
		snprintf(why, len, "%zu lobes, not 5 or 7", m->nlobes);
		return false;
	}
	for (size_t j = 0; j < m->nlobes; j++) {
		ok = slack(m->tip[j], 0.6, true, margin, why, len, "a lobe's tip, x the middle's") && ok;
		if (j + 1 < m->nlobes)
			ok = slack(m->sinus[j], 0.5, false, margin, why, len,
				   "a sinus, x the tips beside it") && ok;
		if (m->lobe_teeth[j] < 1) {
			snprintf(why, len, "lobe %zu has no tooth", j + 1);
			ok = false;
		}
	}
	return ok;
}

bool ori_outline_hop(const struct ori_outline *m, double *margin, char *why, size_t len)
{
	bool ok = true;

	*margin = INFINITY;
	if (m->nlobes != 3 && m->nlobes != 5) {
		snprintf(why, len, "%zu lobes, not 3 or 5", m->nlobes);
		return false;
	}
	for (int s = 0; s < 2; s++) {
		ok = slack(m->behind[s], ORI_OUTLINE_HEART, true, margin, why, len,
			   "the base behind O, x the length") && ok;
		ok = slack(m->teeth[s], 8, true, margin, why, len, "teeth on a side") && ok;
	}
	return ok;
}
