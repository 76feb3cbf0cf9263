/* SPDX-License-Identifier: MIT */
#pragma once

#include <math.h>
#include <stddef.h>

/* M_PI is POSIX, not C11. */
#define VEC_PI 3.14159265358979323846

/* World coordinates: metres, y up, the sketch plane is z = 0 seen from +z. */
struct vec3 {
	double x, y, z;
};

static inline struct vec3 vec3(double x, double y, double z)
{
	return (struct vec3){ x, y, z };
}

static inline struct vec3 vec3_add(struct vec3 a, struct vec3 b)
{
	return vec3(a.x + b.x, a.y + b.y, a.z + b.z);
}

static inline struct vec3 vec3_sub(struct vec3 a, struct vec3 b)
{
	return vec3(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline struct vec3 vec3_scale(struct vec3 a, double s)
{
	return vec3(a.x * s, a.y * s, a.z * s);
}

static inline double vec3_dot(struct vec3 a, struct vec3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline struct vec3 vec3_cross(struct vec3 a, struct vec3 b)
{
	return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static inline double vec3_len(struct vec3 a)
{
	return sqrt(vec3_dot(a, a));
}

static inline double vec3_dist(struct vec3 a, struct vec3 b)
{
	return vec3_len(vec3_sub(a, b));
}

/* Returns a unit vector, or `fallback` when a is (nearly) zero. */
static inline struct vec3 vec3_norm_or(struct vec3 a, struct vec3 fallback)
{
	double l = vec3_len(a);

	return l > 1e-12 ? vec3_scale(a, 1.0 / l) : fallback;
}

static inline struct vec3 vec3_lerp(struct vec3 a, struct vec3 b, double t)
{
	return vec3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}

/* Arc length of a polyline. */
static inline double vec3_polyline_length(const struct vec3 *p, size_t n)
{
	double len = 0.0;

	for (size_t i = 1; i < n; i++)
		len += vec3_dist(p[i - 1], p[i]);
	return len;
}
