/* SPDX-License-Identifier: MIT */
/*
 * A twining vine alone on its support (edaha --headless --support): the support in the
 * bark's colour, the stems a stem green, the leaves the screen's leaf green, drawn by the
 * tree program from a fixed three-quarter view and framed as a leaf alone is
 * (render_fit_matrix), so the picture is the same for the same vine.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "leaf_tint.h"
#include "mesh.h"
#include "render_private.h"

/* The light, in world space (towards it): from the upper left and in front, as the leaf's,
 * fixed to the scene so that the picture does not depend on the camera's code. */
static const double vine_light[3] = { -0.48, 0.6, 0.64 };


#define VINE_FIT_MARGIN 1.08

int render_vine(struct render *r, const struct mesh *support, const struct mesh *stems,
		const struct mesh *leaves, int width, int height)
{
	const float leaf[3] = { LEAF_TINT_SUMMER_RGB };
	const struct mesh *meshes[3] = { support, stems, leaves };
	const float *colors[3] = { render_bark, render_vine_stem, leaf };
	struct render_mesh rm[3];
	struct camera_xf xf;
	struct vec3 l = vec3_norm_or(vec3(vine_light[0], vine_light[1], vine_light[2]),
				     vec3(0.0, 0.0, 1.0));
	float mvp[16], light[3];
	int ret = 0;

	memset(&r->stats, 0, sizeof(r->stats));
	if (width <= 0 || height <= 0)
		return -EINVAL;
	camera_xf_init(&xf, camera_normalize(RENDER_VINE_YAW_DEG, RENDER_VINE_PITCH_DEG),
		       vec3(0.0, 0.0, 0.0));
	light[0] = (float)l.x;
	light[1] = (float)l.y;
	light[2] = (float)l.z;
	render_fit_matrix(meshes, 3, &xf, width, height, VINE_FIT_MARGIN, mvp);
	render_drain_gl_errors();
	memset(rm, 0, sizeof(rm));
	for (int i = 0; i < 3 && ret == 0; i++)
		ret = render_mesh_upload(&rm[i], meshes[i], r->uint_indices);

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
		glEnableVertexAttribArray(ATTR_POSITION);
		glEnableVertexAttribArray(ATTR_NORMAL);
		for (int i = 0; i < 3; i++) {
			/* a leaf shows both sides; the support and the stems are closed */
			glUniform1i(r->tree_two_sided, i == 2);
			glUniform3fv(r->tree_color, 1, colors[i]);
			render_mesh_draw(r, &rm[i]);
		}
		glDisableVertexAttribArray(ATTR_NORMAL);
		glDisable(GL_DEPTH_TEST);
		glUseProgram(0);
	}
	for (int i = 0; i < 3; i++)
		render_mesh_finish(&rm[i]);
	if (glGetError() != GL_NO_ERROR)
		return -EIO;
	return ret;
}

static int vines_upload(struct render *r, const struct app *app)
{
	const struct mesh *m[4] = { &app->vines_mesh.bark, &app->vines_mesh.leaves,
				    &app->growth.mesh.bark, &app->growth.mesh.leaves };
	struct render_mesh *rm[4] = { &r->vine_stems, &r->vine_leaves, &r->grow_stems,
				      &r->grow_leaves };
	int ret = 0;

	if (r->vines_uploaded && r->vines_serial == app->vines_serial)
		return 0;
	for (int i = 0; i < 4 && ret == 0; i++)
		ret = render_mesh_upload(rm[i], m[i], r->uint_indices);
	r->stats.uploads += 4;
	r->vines_uploaded = ret == 0;
	r->vines_serial = app->vines_serial;
	return ret;
}

int render_vines_draw(struct render *r, const struct app *app)
{
	float leaf[3];
	int ret;

	if (app->tree.nvines == 0 && !r->vines_uploaded)
		return 0;
	ret = vines_upload(r, app);
	if (ret < 0)
		return ret;
	/* a tree growing in has its vines climb after it */
	if (!render_live_vines(r, app))
		return 0;
	/* the stems are closed tubes, as the bark; drawn by the tree's lit program, still or
	 * living */
	glEnable(GL_CULL_FACE);
	glUniform1i(r->lit.two_sided, 0);
	glUniform3fv(r->lit.color, 1, render_vine_stem);
	render_live_draw(r, &r->vine_stems, &r->live.vine[0], false);
	render_live_draw(r, &r->grow_stems, &r->live.vine[2], false);
	/* a vine's leaves in the tree's season's colour; in winter it has none, as the tree */
	if (!leaf_tint_uniform(app->tree.season, leaf))
		return 0;
	glDisable(GL_CULL_FACE);
	glUniform1i(r->lit.two_sided, 1);
	glUniform3fv(r->lit.color, 1, leaf);
	render_live_draw(r, &r->vine_leaves, &r->live.vine[1], false);
	render_live_draw(r, &r->grow_leaves, &r->live.vine[3], false);
	return 0;
}

void render_vines_finish(struct render *r)
{
	render_mesh_finish(&r->vine_stems);
	render_mesh_finish(&r->vine_leaves);
	render_mesh_finish(&r->grow_stems);
	render_mesh_finish(&r->grow_leaves);
	r->vines_uploaded = false;
}
