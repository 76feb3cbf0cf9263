/* SPDX-License-Identifier: MIT */
/* Tangents and rotation-minimising frames along a polyline (tube_frame.h). */
#include "tube_frame.h"

#include <math.h>

struct vec3 tube_frame_perpendicular(struct vec3 t)
{
	struct vec3 ref = fabs(t.z) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0);

	return vec3_norm_or(vec3_sub(ref, vec3_scale(t, vec3_dot(ref, t))), vec3(0, 1, 0));
}

struct vec3 tube_frame_tangent(const struct vec3 *p, size_t k, size_t i)
{
	struct vec3 in = i > 0 ? vec3_sub(p[i], p[i - 1]) : vec3_sub(p[1], p[0]);
	struct vec3 out = i + 1 < k ? vec3_sub(p[i + 1], p[i]) : in;
	struct vec3 din = vec3_norm_or(in, vec3(0, 1, 0)), dout = vec3_norm_or(out, din);

	/* a hairpin averages to nothing: the way out then */
	return vec3_norm_or(vec3_add(din, dout), dout);
}

/* Reflects v in the plane through the origin with normal a (|a|^2 = aa). */
static struct vec3 reflect(struct vec3 v, struct vec3 a, double aa)
{
	return vec3_sub(v, vec3_scale(a, 2.0 * vec3_dot(v, a) / aa));
}

void tube_frame_build(const struct vec3 *p, size_t k, struct vec3 *t, struct vec3 *n)
{
	for (size_t i = 0; i < k; i++)
		t[i] = tube_frame_tangent(p, k, i);
	n[0] = tube_frame_perpendicular(t[0]);
	for (size_t i = 0; i + 1 < k; i++) {
		struct vec3 v1 = vec3_sub(p[i + 1], p[i]), r;
		double c1 = vec3_dot(v1, v1);

		if (c1 > 1e-30) {
			struct vec3 rl = reflect(n[i], v1, c1), tl = reflect(t[i], v1, c1);
			struct vec3 v2 = vec3_sub(t[i + 1], tl);
			double c2 = vec3_dot(v2, v2);

			r = c2 > 1e-20 ? reflect(rl, v2, c2) : rl;
		} else {
			r = n[i];
		}
		/* back to perpendicular, so rounding cannot build up */
		r = vec3_sub(r, vec3_scale(t[i + 1], vec3_dot(r, t[i + 1])));
		n[i + 1] = vec3_norm_or(r, tube_frame_perpendicular(t[i + 1]));
	}
}
