/* SPDX-License-Identifier: MIT */
/*
 * The leaf suggestions' thumbnails: each suggested arrangement's branch and leaves, lit
 * like the tree and seen through the same camera, fitted into its card on the side strip.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "app.h"
#include "layout.h"
#include "render_private.h"

static const float bark_color[3] = { 0.47f, 0.32f, 0.20f };
static const float leaf_color[3] = { 0.33f, 0.62f, 0.24f };

static int upload(struct render *r, const struct app *app)
{
	int ret = 0;

	if (r->previews_uploaded && r->previews_serial == app->previews_serial)
		return 0;
	r->previews_uploaded = false;
	for (int p = 0; p < ARRANGE_COUNT && ret == 0; p++) {
		if (!(app->suggestions & (1u << p)))
			continue;
		ret = render_mesh_upload(&r->preview_bark[p], &app->previews[p].bark, r->uint_indices);
		if (ret == 0)
			ret = render_mesh_upload(&r->preview_leaves[p], &app->previews[p].leaves,
						 r->uint_indices);
		r->stats.uploads += 2;
	}
	if (ret < 0)
		return ret;
	r->previews_uploaded = true;
	r->previews_serial = app->previews_serial;
	return 0;
}

/* View-space bounds (x, y) of a mesh's vertices. */
static void bounds(const struct mesh *m, const struct camera_xf *xf, double b[4])
{
	for (size_t i = 0; i < m->nvertices; i++) {
		const float *p = m->positions + 3 * i;
		struct vec3 v = camera_to_view(xf, vec3(p[0], p[1], p[2]));

		b[0] = fmin(b[0], v.x);
		b[1] = fmin(b[1], v.y);
		b[2] = fmax(b[2], v.x);
		b[3] = fmax(b[3], v.y);
	}
}

/* World -> clip for a thumbnail: the camera, then the bounds fitted square into the card
 * with a margin, centred. */
static void fit_matrix(const struct camera_xf *xf, const double b[4], float m[16])
{
	double cx = 0.5 * (b[0] + b[2]), cy = 0.5 * (b[1] + b[3]);
	double half = 0.5 * fmax(fmax(b[2] - b[0], b[3] - b[1]), 1e-3) * 1.15;
	float cam[16], fit[16] = { 0 };

	camera_matrix(xf, cam);
	fit[0] = (float)(1.0 / half);
	fit[5] = (float)(1.0 / half);
	fit[10] = (float)(-1.0 / VIEW_DEPTH_M);
	fit[12] = (float)(-cx / half);
	fit[13] = (float)(-cy / half);
	fit[15] = 1.0f;
	memset(m, 0, 16 * sizeof(*m));
	for (int c = 0; c < 4; c++)
		for (int r = 0; r < 4; r++)
			for (int k = 0; k < 4; k++)
				m[c * 4 + r] += fit[k * 4 + r] * cam[c * 4 + k];
}

int render_previews(struct render *r, const struct app *app, const struct camera_xf *xf,
		    const float light[3])
{
	enum arrange_pattern list[ARRANGE_COUNT];
	size_t n = app->mode == APP_MODE_LEAF ? app_suggestions(app, list) : 0;
	size_t tree_triangles = r->stats.tree_triangles;
	int ret;

	if (n == 0)
		return 0;
	ret = upload(r, app);
	if (ret < 0)
		return ret;
	glUseProgram(r->tree_program);
	glUniform3fv(r->tree_light, 1, light);
	glEnableVertexAttribArray(ATTR_NORMAL);
	glEnable(GL_DEPTH_TEST);
	glEnable(GL_SCISSOR_TEST);
	glDisable(GL_BLEND);
	for (size_t i = 0; i < n; i++) {
		struct layout_rect s = layout_side_slot(&app->view, i, LAYOUT_SIDE_CARDS);
		const struct tree_mesh *tm = &app->previews[list[i]];
		double b[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY };
		float mvp[16];
		/* inside the card's border; GL counts rows from the bottom */
		GLint x = (GLint)(s.x + 0.08 * s.w), w = (GLint)(0.84 * s.w);
		GLint y = (GLint)(app->view.height - s.y - 0.92 * s.h), h = (GLint)(0.84 * s.h);

		bounds(&tm->bark, xf, b);
		bounds(&tm->leaves, xf, b);
		if (!(b[0] <= b[2]) || w <= 0 || h <= 0)
			continue;
		fit_matrix(xf, b, mvp);
		glViewport(x, y, w, h);
		glScissor(x, y, w, h);
		glClear(GL_DEPTH_BUFFER_BIT);
		glUniformMatrix4fv(r->tree_mvp, 1, GL_FALSE, mvp);
		glEnable(GL_CULL_FACE);
		glUniform1i(r->tree_two_sided, 0);
		glUniform3fv(r->tree_color, 1, bark_color);
		render_mesh_draw(r, &r->preview_bark[list[i]]);
		glDisable(GL_CULL_FACE);
		glUniform1i(r->tree_two_sided, 1);
		glUniform3fv(r->tree_color, 1, leaf_color);
		render_mesh_draw(r, &r->preview_leaves[list[i]]);
	}
	glDisable(GL_SCISSOR_TEST);
	glDisable(GL_DEPTH_TEST);
	glViewport(0, 0, app->view.width, app->view.height);
	r->stats.tree_triangles = tree_triangles; /* the stat counts the tree itself */
	return 0;
}

void render_previews_finish(struct render *r)
{
	for (int p = 0; p < ARRANGE_COUNT; p++) {
		render_mesh_finish(&r->preview_bark[p]);
		render_mesh_finish(&r->preview_leaves[p]);
	}
	r->previews_uploaded = false;
}
