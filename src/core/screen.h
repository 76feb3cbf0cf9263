/* SPDX-License-Identifier: MIT */
#pragma once

#include "camera.h"
#include "vec.h"

/*
 * Screen <-> world. The screen shows the sketch plane z = 0 from +z, looking along -z:
 * the ground line sits at VIEW_GROUND_FRACTION of the screen height from the top, the
 * screen's vertical centre line is x = 0, and the screen height spans VIEW_HEIGHT_M metres
 * (a full-height drawing is a 10 m tree). Pixels are square.
 */
#define VIEW_HEIGHT_M 10.0
#define VIEW_GROUND_FRACTION 0.92
/* Depth range the projection keeps, metres either side of z = 0. */
#define VIEW_DEPTH_M 50.0

struct view {
	int width, height;   /* pixels */
	double m_per_px;     /* metres per pixel */
	double ground_y_px;  /* screen y of the ground line */
};

void view_init(struct view *v, int width, int height);
struct vec3 view_to_world(const struct view *v, double x_px, double y_px);
void view_to_screen(const struct view *v, struct vec3 p, double *x_px, double *y_px);
/* Column-major 4x4 matrix from world to GL clip space (orthographic, y up), seen through
 * the camera xf (NULL: the front view). */
void view_clip_matrix(const struct view *v, const struct camera_xf *xf, float m[16]);
