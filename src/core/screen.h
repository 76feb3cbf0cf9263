/* SPDX-License-Identifier: MIT */
#pragma once

#include "camera.h"
#include "vec.h"

/*
 * Screen <-> world. The screen shows the sketch plane z = 0 from +z, looking along -z:
 * the ground line sits at SCREEN_GROUND_FRACTION of the screen height from the top, the
 * screen's vertical centre line is x = 0, and the screen height spans SCREEN_HEIGHT_M metres
 * (a full-height drawing is a 10 m tree). Pixels are square.
 */
#define SCREEN_HEIGHT_M 10.0
#define SCREEN_GROUND_FRACTION 0.92
/* Depth range the projection keeps, metres either side of z = 0. */
#define SCREEN_DEPTH_M 50.0

struct screen {
	int width, height;   /* pixels */
	double m_per_px;     /* metres per pixel */
	double ground_y_px;  /* screen y of the ground line */
};

void screen_init(struct screen *v, int width, int height);
struct vec3 screen_to_world(const struct screen *v, double x_px, double y_px);
void screen_from_world(const struct screen *v, struct vec3 p, double *x_px, double *y_px);
/* Column-major 4x4 matrix from world to GL clip space (orthographic, y up), seen through
 * the camera xf (NULL: the front view). */
void screen_clip_matrix(const struct screen *v, const struct camera_xf *xf, float m[16]);
