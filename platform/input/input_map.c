/* SPDX-License-Identifier: MIT */
#include "input_map.h"

#include <string.h>

void input_map_rotate(int rotation, double u, double v, double *ru, double *rv)
{
	/* The tablet turned clockwise: its x axis points down the screen at 90 degrees. */
	switch (rotation) {
	case 90:
		*ru = 1.0 - v;
		*rv = u;
		break;
	case 180:
		*ru = 1.0 - u;
		*rv = 1.0 - v;
		break;
	case 270:
		*ru = v;
		*rv = 1.0 - u;
		break;
	default:
		*ru = u;
		*rv = v;
		break;
	}
}

void input_map_init(struct input_map *m, int rotation, enum config_area area,
		    const double rect[4], double tablet_w, double tablet_h, int screen_w,
		    int screen_h)
{
	double tw = tablet_w, th = tablet_h;

	m->rotation = rotation == 90 || rotation == 180 || rotation == 270 ? rotation : 0;
	m->screen_w = screen_w > 0 ? screen_w : 1;
	m->screen_h = screen_h > 0 ? screen_h : 1;
	m->area[0] = m->area[1] = 0.0;
	m->area[2] = m->area[3] = 1.0;
	if (area == CONFIG_AREA_RECT && rect) {
		memcpy(m->area, rect, sizeof(m->area));
		return;
	}
	if (area != CONFIG_AREA_FIT || !(tw > 0.0) || !(th > 0.0))
		return;
	if (m->rotation == 90 || m->rotation == 270) {
		tw = tablet_h;
		th = tablet_w;
	}
	double ta = tw / th, sa = m->screen_w / m->screen_h;

	if (ta > sa) { /* the tablet is wider: all its height, the middle of its width */
		double f = sa / ta;

		m->area[0] = (1.0 - f) / 2.0;
		m->area[2] = m->area[0] + f;
	} else {
		double f = ta / sa;

		m->area[1] = (1.0 - f) / 2.0;
		m->area[3] = m->area[1] + f;
	}
}

static double clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

void input_map_point(const struct input_map *m, double u, double v, double *x, double *y)
{
	double ru, rv;

	input_map_rotate(m->rotation, u, v, &ru, &rv);
	ru = (ru - m->area[0]) / (m->area[2] - m->area[0]);
	rv = (rv - m->area[1]) / (m->area[3] - m->area[1]);
	*x = clamp(ru, 0.0, 1.0) * m->screen_w;
	*y = clamp(rv, 0.0, 1.0) * m->screen_h;
}

void input_map_tilt(const struct input_map *m, double tx, double ty, double *sx, double *sy)
{
	switch (m->rotation) {
	case 90:
		*sx = -ty;
		*sy = tx;
		break;
	case 180:
		*sx = -tx;
		*sy = -ty;
		break;
	case 270:
		*sx = ty;
		*sy = -tx;
		break;
	default:
		*sx = tx;
		*sy = ty;
		break;
	}
}
