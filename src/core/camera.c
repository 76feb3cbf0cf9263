/* SPDX-License-Identifier: MIT */
#include "camera.h"

#include <math.h>

bool camera_is_front(struct camera c)
{
	return c.yaw == 0.0f && c.pitch == 0.0f;
}

struct camera camera_normalize(double yaw, double pitch)
{
	struct camera c;

	if (!isfinite(yaw))
		yaw = 0.0;
	if (!isfinite(pitch))
		pitch = 0.0;
	yaw = fmod(yaw, 360.0);
	if (yaw >= 180.0)
		yaw -= 360.0;
	else if (yaw < -180.0)
		yaw += 360.0;
	c.yaw = (float)yaw;
	if (c.yaw >= 180.0f) /* rounding to float can land on the open end */
		c.yaw = -180.0f;
	c.pitch = (float)(pitch < CAMERA_PITCH_MIN_DEG ? CAMERA_PITCH_MIN_DEG :
			  pitch > CAMERA_PITCH_MAX_DEG ? CAMERA_PITCH_MAX_DEG : pitch);
	return c;
}

void camera_xf_init(struct camera_xf *xf, struct camera c, struct vec3 pivot)
{
	double y = c.yaw * (VEC_PI / 180.0), p = c.pitch * (VEC_PI / 180.0);

	xf->identity = camera_is_front(c);
	xf->pivot = pivot;
	/* The camera sits at azimuth yaw, raised by pitch, looking at the pivot. */
	xf->right = vec3(cos(y), 0.0, -sin(y));
	xf->up = vec3(-sin(y) * sin(p), cos(p), -cos(y) * sin(p));
	xf->back = vec3(sin(y) * cos(p), sin(p), cos(y) * cos(p));
	if (xf->identity) {
		xf->right = vec3(1, 0, 0);
		xf->up = vec3(0, 1, 0);
		xf->back = vec3(0, 0, 1);
	}
}

struct vec3 camera_dir_to_view(const struct camera_xf *xf, struct vec3 d)
{
	if (xf->identity)
		return d;
	return vec3(vec3_dot(d, xf->right), vec3_dot(d, xf->up), vec3_dot(d, xf->back));
}

struct vec3 camera_dir_from_view(const struct camera_xf *xf, struct vec3 d)
{
	if (xf->identity)
		return d;
	return vec3_add(vec3_scale(xf->right, d.x),
			vec3_add(vec3_scale(xf->up, d.y), vec3_scale(xf->back, d.z)));
}

struct vec3 camera_to_view(const struct camera_xf *xf, struct vec3 w)
{
	if (xf->identity)
		return w;
	return vec3_add(xf->pivot, camera_dir_to_view(xf, vec3_sub(w, xf->pivot)));
}

struct vec3 camera_from_view(const struct camera_xf *xf, struct vec3 v)
{
	if (xf->identity)
		return v;
	return vec3_add(xf->pivot, camera_dir_from_view(xf, vec3_sub(v, xf->pivot)));
}

void camera_matrix(const struct camera_xf *xf, float m[16])
{
	/* rows are the view axes; the pivot maps to itself */
	struct vec3 t = vec3_sub(xf->pivot, camera_dir_to_view(xf, xf->pivot));
	const struct vec3 r = xf->identity ? vec3(1, 0, 0) : xf->right;
	const struct vec3 u = xf->identity ? vec3(0, 1, 0) : xf->up;
	const struct vec3 b = xf->identity ? vec3(0, 0, 1) : xf->back;

	m[0] = (float)r.x, m[4] = (float)r.y, m[8] = (float)r.z, m[12] = (float)t.x;
	m[1] = (float)u.x, m[5] = (float)u.y, m[9] = (float)u.z, m[13] = (float)t.y;
	m[2] = (float)b.x, m[6] = (float)b.y, m[10] = (float)b.z, m[14] = (float)t.z;
	m[3] = 0.0f, m[7] = 0.0f, m[11] = 0.0f, m[15] = 1.0f;
}
