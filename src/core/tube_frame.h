/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "vec.h"

/*
 * Frames along a polyline, for the tubes round it (the branches' bark, mesh.c; the wood's
 * prisms, wood_voxel.c; the vines' stems, vine_shape.c): at each point a unit tangent and
 * a unit normal across it that does not twist from point to point, so the rings a tube is
 * made of line up.
 */

/* A unit vector perpendicular to unit t, a fixed function of t: towards the viewer (+z)
 * unless t nearly is, so a sketched branch in z = 0 has its rings facing the screen and a
 * vertical trunk its corners on x and z. */
struct vec3 tube_frame_perpendicular(struct vec3 t);

/* The unit tangent at point i of p[0..k), k >= 2: the mean of the directions in and out
 * (the one there is at an end; the way out at a hairpin, where they cancel). */
struct vec3 tube_frame_tangent(const struct vec3 *p, size_t k, size_t i);

/*
 * Tangents t[0..k) and rotation-minimising normals n[0..k) along p[0..k), k >= 2: n[0] is
 * tube_frame_perpendicular(t[0]), each next one carried over by the double reflection method
 * (Wang, Juettler, Zheng, Liu 2008); a point given twice carries the frame over as it is.
 */
void tube_frame_build(const struct vec3 *p, size_t k, struct vec3 *t, struct vec3 *n);
