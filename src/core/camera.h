/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>

#include "vec.h"

/*
 * The orbit camera of a 3D tree. The projection stays the front view's orthographic
 * one (screen.h); the camera turns the world about a pivot, the trunk's base, before it is
 * shown: yaw about the vertical, then pitch about the screen's horizontal. Angles are in
 * degrees and stored as float, so what a drawing records is exactly what was used.
 *
 * "View space" is what the front view shows: x right, y up, z towards the viewer. With
 * yaw = pitch = 0 it is world space, bit for bit.
 */

/* Looking from a little below the ground to well above the crown. */
#define CAMERA_PITCH_MIN_DEG -20.0f
#define CAMERA_PITCH_MAX_DEG 75.0f

struct camera {
	float yaw;   /* degrees, -180 <= yaw < 180: the camera's azimuth, 90 = from +x */
	float pitch; /* degrees, CAMERA_PITCH_MIN_DEG..MAX: above the horizon */
};

/* The camera as a rigid transform, built once per use. */
struct camera_xf {
	bool identity;
	struct vec3 pivot;
	struct vec3 right, up, back; /* the view axes in world space */
};

bool camera_is_front(struct camera c);
/* Wraps yaw into -180..180 and clamps pitch. NaN becomes 0. */
struct camera camera_normalize(double yaw, double pitch);
void camera_xf_init(struct camera_xf *xf, struct camera c, struct vec3 pivot);
struct vec3 camera_to_view(const struct camera_xf *xf, struct vec3 world);
struct vec3 camera_from_view(const struct camera_xf *xf, struct vec3 view);
/* A world direction (not a point) in view space. */
struct vec3 camera_dir_to_view(const struct camera_xf *xf, struct vec3 dir);
struct vec3 camera_dir_from_view(const struct camera_xf *xf, struct vec3 dir);
/* Column-major 4x4 world -> view matrix (float, for GL). */
void camera_matrix(const struct camera_xf *xf, float m[16]);
