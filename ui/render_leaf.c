/* SPDX-License-Identifier: MIT */
/*
 * An origami leaf alone (edaha --headless --leaf): the leaf on the paper, nothing else.
 * The tree program draws it as it draws a tree's leaves, so the picture is the screen's
 * leaf; each face has its own normal, so each is lit flat and the folds between them read.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "leaf_tint.h"
#include "mesh.h"
#include "render_private.h"

/*
 * The light, in world space (towards it): from the upper left as on the screen, but fixed
 * to the leaf and in front of its plane. The screen's light turns with the camera; seen
 * from the side, it would fall behind a flat leaf, or behind a folded one's outer faces.
 */
static const double leaf_light[3] = { -0.48, 0.6, 0.64 };

/* The leaf's extent fills the view but for this margin (a fraction of its size). */
#define LEAF_FIT_MARGIN 1.12

/*
 * World -> clip: the camera about the origin (the leaf's base), then the meshes' view-space
 * box centred and scaled, square pixels, to fill the view but for margin (a fraction of
 * their size); their depth fills the depth range, so near faces of an 8 cm leaf still part
 * cleanly from far ones.
 */
void render_fit_matrix(const struct mesh *const *meshes, size_t nmeshes,
		       const struct camera_xf *xf, int width, int height, double margin,
		       float out[16])
{
	double lo[3] = { INFINITY, INFINITY, INFINITY };
	double hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	double c[3], px_per_m, s[3];
	float cam[16], fit[16] = { 0 };

	for (size_t j = 0; j < nmeshes; j++) {
		const struct mesh *m = meshes[j];

		for (size_t i = 0; i < m->nvertices; i++) {
			const float *p = m->positions + 3 * i;
			struct vec3 v = camera_to_view(xf, vec3(p[0], p[1], p[2]));
			const double q[3] = { v.x, v.y, v.z };

			for (int k = 0; k < 3; k++) {
				lo[k] = fmin(lo[k], q[k]);
				hi[k] = fmax(hi[k], q[k]);
			}
		}
	}
	for (int k = 0; k < 3; k++) {
		/* an empty mesh, or one flat in a direction, still gives a matrix */
		if (!(lo[k] <= hi[k]))
			lo[k] = hi[k] = 0.0;
		c[k] = 0.5 * (lo[k] + hi[k]);
	}
	px_per_m = fmin(width / fmax(hi[0] - lo[0], 1e-6), height / fmax(hi[1] - lo[1], 1e-6)) /
		   margin;
	s[0] = 2.0 * px_per_m / width;
	s[1] = 2.0 * px_per_m / height;
	/* nearer the viewer (larger view z) is smaller depth */
	s[2] = -2.0 / (fmax(hi[2] - lo[2], 1e-6) * margin);
	camera_matrix(xf, cam);
	for (int k = 0; k < 3; k++) {
		fit[5 * k] = (float)s[k];
		fit[12 + k] = (float)(-c[k] * s[k]);
	}
	fit[15] = 1.0f;
	render_mat4_mul(fit, cam, out);
}

int render_leaf(struct render *r, const struct mesh *m, int width, int height)
{
	const float leaf[3] = { LEAF_TINT_SUMMER_RGB };
	struct render_mesh rm;
	struct camera_xf xf;
	struct vec3 l = vec3_norm_or(vec3(leaf_light[0], leaf_light[1], leaf_light[2]),
				     vec3(0.0, 0.0, 1.0));
	float mvp[16], light[3];
	int ret;

	memset(&r->stats, 0, sizeof(r->stats));
	if (width <= 0 || height <= 0)
		return -EINVAL;
	camera_xf_init(&xf, camera_normalize(RENDER_LEAF_YAW_DEG, RENDER_LEAF_PITCH_DEG),
		       vec3(0.0, 0.0, 0.0));
	light[0] = (float)l.x;
	light[1] = (float)l.y;
	light[2] = (float)l.z;
	render_fit_matrix(&m, 1, &xf, width, height, LEAF_FIT_MARGIN, mvp);
	render_drain_gl_errors();
	memset(&rm, 0, sizeof(rm));
	ret = render_mesh_upload(&rm, m, r->uint_indices);

	glViewport(0, 0, width, height);
	glDisable(GL_SCISSOR_TEST);
	glDisable(GL_BLEND);
	glDisable(GL_CULL_FACE);
	glDepthMask(GL_TRUE);
	glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	glClearColor(render_paper[0], render_paper[1], render_paper[2], 1.0f);
	glClearDepthf(1.0f);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	if (ret == 0) {
		glEnable(GL_DEPTH_TEST);
		glDepthFunc(GL_LESS);
		glUseProgram(r->tree_program);
		glUniformMatrix4fv(r->tree_mvp, 1, GL_FALSE, mvp);
		glUniform3fv(r->tree_light, 1, light);
		/* both sides of a leaf show: the back lit as if it faced the viewer */
		glUniform1i(r->tree_two_sided, 1);
		glUniform3fv(r->tree_color, 1, leaf);
		glEnableVertexAttribArray(ATTR_POSITION);
		glEnableVertexAttribArray(ATTR_NORMAL);
		render_mesh_draw(r, &rm);
		glDisableVertexAttribArray(ATTR_NORMAL);
		glDisable(GL_DEPTH_TEST);
		glUseProgram(0);
	}
	render_mesh_finish(&rm);
	if (glGetError() != GL_NO_ERROR)
		return -EIO;
	return ret;
}
