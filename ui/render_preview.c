/* SPDX-License-Identifier: MIT */
/*
 * The side strip's pictures: each card's tree (app_side_items' `preview`) lit like the
 * tree and fitted into its card. A leaf suggestion (the branch with the arrangement's
 * leaves) is seen through the app's camera, as the tree it would change; a template (a
 * preset tree on the New strip) through the template camera, turned a little so that it
 * reads as a 3D tree. The cards themselves are render_ui's.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "app.h"
#include "app_mode.h"
#include "layout.h"
#include "leaf_tint.h"
#include "render_private.h"


/* The picture slot that holds the app's mesh m: previews[] first, then templates[]. */
static int picture_of(const struct app *app, const struct tree_mesh *m)
{
	for (int p = 0; p < ARRANGE_COUNT; p++)
		if (m == &app->previews[p])
			return p;
	for (int t = 0; t < GEN_PRESET_COUNT; t++)
		if (m == &app->templates[t])
			return ARRANGE_COUNT + t;
	return -1;
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

static void template_xf(struct camera_xf *xf)
{
	struct camera c = camera_normalize(APP_TEMPLATE_YAW_DEG, APP_TEMPLATE_PITCH_DEG);

	camera_xf_init(xf, c, vec3(0.0, 0.0, 0.0));
}

/*
 * The GPU copy of picture k, made again only when app->previews_serial says the app's
 * meshes changed since (a slot keeps its serial, so a template seen again after the leaf
 * suggestions changed is uploaded once more). A template's bounds do not depend on the
 * app's camera: they are found here, once.
 */
static int upload(struct render *r, const struct app *app, int k, const struct tree_mesh *tm)
{
	struct render_picture *p = &r->pictures[k];
	int ret;

	if (p->uploaded && p->serial == app->previews_serial)
		return 0;
	p->uploaded = false;
	ret = render_mesh_upload(&p->bark, &tm->bark, r->uint_indices);
	if (ret == 0)
		ret = render_mesh_upload(&p->leaves, &tm->leaves, r->uint_indices);
	r->stats.uploads += 2;
	if (ret < 0)
		return ret;
	if (k >= ARRANGE_COUNT) {
		struct camera_xf xf;
		struct gen_params params;
		struct error err;

		/* a preset that will not read (its test says it does) shows summer */
		p->season = gen_preset((enum gen_preset)(k - ARRANGE_COUNT), &params, &err) == 0
				    ? params.season
				    : SEASON_SUMMER;
		template_xf(&xf);
		p->bounds[0] = p->bounds[1] = INFINITY;
		p->bounds[2] = p->bounds[3] = -INFINITY;
		bounds(&tm->bark, &xf, p->bounds);
		bounds(&tm->leaves, &xf, p->bounds);
	}
	p->uploaded = true;
	p->serial = app->previews_serial;
	return 0;
}

/* World -> clip for a picture: the camera, then the bounds fitted square into the card
 * with a margin, centred; a whole tree stands on the margin at the bottom instead (a hedge
 * is wider than tall). */
#define FIT_MARGIN 1.15

static void fit_matrix(const struct camera_xf *xf, const double b[4], bool stand, float m[16])
{
	double half = 0.5 * fmax(fmax(b[2] - b[0], b[3] - b[1]), 1e-3) * FIT_MARGIN;
	double cx = 0.5 * (b[0] + b[2]), cy = stand ? b[1] + half / FIT_MARGIN : 0.5 * (b[1] + b[3]);
	float cam[16], fit[16] = { 0 };

	camera_matrix(xf, cam);
	fit[0] = (float)(1.0 / half);
	fit[5] = (float)(1.0 / half);
	fit[10] = (float)(-1.0 / SCREEN_DEPTH_M);
	fit[12] = (float)(-cx / half);
	fit[13] = (float)(-cy / half);
	fit[15] = 1.0f;
	memset(m, 0, 16 * sizeof(*m));
	for (int c = 0; c < 4; c++)
		for (int r = 0; r < 4; r++)
			for (int k = 0; k < 4; k++)
				m[c * 4 + r] += fit[k * 4 + r] * cam[c * 4 + k];
}

bool render_previews_shown(const struct app *app)
{
	struct app_side_item items[APP_SIDE_MAX];
	size_t n = app_side_items(app, items);

	for (size_t i = 0; i < n; i++)
		if (items[i].thumbnail && items[i].preview)
			return true;
	return false;
}

/* Picture k (its mesh tm) into the card's picture area pic. */
static int draw_picture(struct render *r, const struct app *app, int k, const struct tree_mesh *tm,
			struct layout_rect pic, const struct camera_xf *app_xf)
{
	struct render_picture *p;
	struct camera_xf own;
	const struct camera_xf *xf = app_xf;
	double b[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY };
	float mvp[16];
	/* inside the card's border; GL counts rows from the bottom */
	GLint x = (GLint)(pic.x + 0.08 * pic.w), w = (GLint)(0.84 * pic.w);
	GLint y = (GLint)(app->screen.height - pic.y - 0.92 * pic.h), h = (GLint)(0.84 * pic.h);
	float leaf[3] = { LEAF_TINT_SUMMER_RGB };
	int ret = upload(r, app, k, tm);

	if (ret < 0)
		return ret;
	p = &r->pictures[k];
	/* leaves in the season of the tree they show, in one colour at this size; a leaf
	 * suggestion shows its leaves in winter too, or it would suggest nothing */
	if (k >= ARRANGE_COUNT) {
		template_xf(&own);
		xf = &own;
		memcpy(b, p->bounds, sizeof(b));
		(void)leaf_tint_uniform(p->season, leaf);
	} else {
		bounds(&tm->bark, xf, b);
		bounds(&tm->leaves, xf, b);
		(void)leaf_tint_uniform(app->tree.season, leaf);
	}
	if (!(b[0] <= b[2]) || w <= 0 || h <= 0)
		return 0; /* nothing to show */
	fit_matrix(xf, b, k >= ARRANGE_COUNT, mvp);
	glViewport(x, y, w, h);
	glScissor(x, y, w, h);
	glClear(GL_DEPTH_BUFFER_BIT);
	glUniformMatrix4fv(r->tree_mvp, 1, GL_FALSE, mvp);
	glEnable(GL_CULL_FACE);
	glUniform1i(r->tree_two_sided, 0);
	glUniform3fv(r->tree_color, 1, render_bark);
	render_mesh_draw(r, &p->bark);
	glDisable(GL_CULL_FACE);
	glUniform1i(r->tree_two_sided, 1);
	glUniform3fv(r->tree_color, 1, leaf);
	render_mesh_draw(r, &p->leaves);
	return 0;
}

int render_previews(struct render *r, const struct app *app, const struct camera_xf *xf,
		    const float light[3])
{
	struct app_side_item items[APP_SIDE_MAX];
	size_t n = app_side_items(app, items);
	size_t tree_triangles = r->stats.tree_triangles;
	enum layout_side_kind kind = n ? app_side_kind(&items[0]) : LAYOUT_SIDE_CARDS;
	int ret = 0;

	if (kind == LAYOUT_SIDE_BUTTONS)
		return 0;
	glUseProgram(r->tree_program);
	glUniform3fv(r->tree_light, 1, light);
	glEnableVertexAttribArray(ATTR_NORMAL);
	glEnable(GL_DEPTH_TEST);
	glEnable(GL_SCISSOR_TEST);
	glDisable(GL_BLEND);
	for (size_t i = 0; i < n && ret == 0; i++) {
		struct layout_rect s = layout_side_slot(&app->screen, i, kind);
		int k = items[i].preview ? picture_of(app, items[i].preview) : -1;

		if (k >= 0)
			ret = draw_picture(r, app, k, items[i].preview, layout_card_picture(s, kind), xf);
	}
	glDisable(GL_SCISSOR_TEST);
	glDisable(GL_DEPTH_TEST);
	glViewport(0, 0, app->screen.width, app->screen.height);
	r->stats.tree_triangles = tree_triangles; /* the stat counts the tree itself */
	return ret;
}

void render_previews_finish(struct render *r)
{
	for (int k = 0; k < RENDER_PICTURES; k++) {
		render_mesh_finish(&r->pictures[k].bark);
		render_mesh_finish(&r->pictures[k].leaves);
		r->pictures[k].uploaded = false;
	}
}
