/* SPDX-License-Identifier: MIT */
#include "screen.h"

#include <string.h>

void screen_init(struct screen *v, int width, int height)
{
	v->width = width;
	v->height = height;
	v->m_per_px = SCREEN_HEIGHT_M / height;
	v->ground_y_px = SCREEN_GROUND_FRACTION * height;
}

struct vec3 screen_to_world(const struct screen *v, double x_px, double y_px)
{
	return vec3((x_px - 0.5 * v->width) * v->m_per_px, (v->ground_y_px - y_px) * v->m_per_px, 0.0);
}

void screen_from_world(const struct screen *v, struct vec3 p, double *x_px, double *y_px)
{
	*x_px = 0.5 * v->width + p.x / v->m_per_px;
	*y_px = v->ground_y_px - p.y / v->m_per_px;
}

void screen_clip_matrix(const struct screen *v, const struct camera_xf *xf, float m[16])
{
	double sx = 2.0 / (v->m_per_px * v->width);
	double sy = 2.0 / (v->m_per_px * v->height);
	float cam[16], proj[16];

	memset(m, 0, 16 * sizeof(*m));
	if (xf && !xf->identity) {
		screen_clip_matrix(v, NULL, proj);
		camera_matrix(xf, cam);
		for (int c = 0; c < 4; c++)
			for (int r = 0; r < 4; r++)
				for (int k = 0; k < 4; k++)
					m[c * 4 + r] += proj[k * 4 + r] * cam[c * 4 + k];
		return;
	}
	/* x_clip = x * sx; y_clip = y * sy + (1 - 2 ground / h); z_clip = -z / depth */
	m[0] = (float)sx;
	m[5] = (float)sy;
	m[10] = (float)(-1.0 / SCREEN_DEPTH_M);
	m[13] = (float)(1.0 - 2.0 * v->ground_y_px / v->height);
	m[15] = 1.0f;
}
