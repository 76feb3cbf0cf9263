/* SPDX-License-Identifier: MIT */
/*
 * Today's forest on the attract screen (issue 27, docs/forest.md): the scene's merged
 * bark and leaves (src/forest/forest_scene.c) drawn by the forest's living programs, one
 * call for the bark and one for the leaves whatever the number of trees, on a gentle
 * disc of ground, seen by a camera that travels slowly round it; each tree's number at its
 * foot. The meshes and their data go up when the scene changes (its serial); a frame sets
 * uniforms only.
 */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "forest.h"
#include "layout.h"
#include "leaf_tint.h"
#include "render_private.h"
#include "text.h"

static const float forest_bark[3] = { 0.47f, 0.32f, 0.20f };
static const float forest_ground[3] = { 0.80f, 0.74f, 0.58f };
/* the light, world space (towards it): from the upper left and in front of the camera's
 * start, fixed to the forest so it does not flicker as the camera travels */
static const double forest_light[3] = { -0.45, 0.75, 0.48 };
#define GROUND_SIDES 72
#define FOREST_FIT_MARGIN 1.12

static const char *const attribs[] = { "a_position", "a_normal", "a_tint", "a_live0",
				       "a_live1", "a_phase", "a_flutter", "a_trunk" };
static const GLuint locations[] = { ATTR_POSITION, ATTR_NORMAL, ATTR_TINT, ATTR_LIVE,
				    ATTR_LIVE + 1, ATTR_LIVE + 2, ATTR_LIVE + 3, ATTR_TRUNK };

int render_forest_create(struct render *r)
{
	struct render_forest *f = &r->forest;

	memset(f, 0, sizeof(*f));
	if (!render_program_tree_init(&f->plain.tree, "forest", render_forest_vs, render_live_fs,
				      attribs, locations, 8) ||
	    !render_program_tree_init(&f->tinted.tree, "forest tinted", render_forest_tinted_vs,
				      render_live_tinted_fs, attribs, locations, 8)) {
		glDeleteProgram(f->plain.tree.program);
		f->plain.tree.program = 0;
		return -1;
	}
	render_live_program_locate(&f->plain);
	render_live_program_locate(&f->tinted);
	f->loop_u[0] = glGetUniformLocation(f->plain.tree.program, "u_loop_u");
	f->loop_u[1] = glGetUniformLocation(f->tinted.tree.program, "u_loop_u");
	return 0;
}

/* The part of the canvas the forest is framed in: above the attract screen's band
 * (render_overlay.c's: 16% of the height and its margins). */
static struct layout_rect forest_rect(const struct screen *v)
{
	struct layout_rect rect = layout_canvas(v);

	rect.h = fmax(1.0, rect.h - 0.2 * v->height);
	return rect;
}

static void forest_clear(struct render_forest *f)
{
	render_mesh_finish(&f->bark);
	render_mesh_finish(&f->leaves);
	render_mesh_finish(&f->ground);
	glDeleteBuffers(1, &f->bark_live.vbo);
	glDeleteBuffers(1, &f->leaves_live.vbo);
	glDeleteBuffers(1, &f->bark_trunk);
	glDeleteBuffers(1, &f->leaves_trunk);
	f->bark_live.vbo = f->leaves_live.vbo = f->bark_trunk = f->leaves_trunk = 0;
	f->bark_live.ok = f->leaves_live.ok = false;
	f->ok = false;
	f->of = NULL;
}

void render_forest_finish(struct render *r)
{
	struct render_forest *f = &r->forest;

	forest_clear(f);
	glDeleteProgram(f->plain.tree.program);
	glDeleteProgram(f->tinted.tree.program);
	f->plain.tree.program = f->tinted.tree.program = 0;
}

/* A disc of ground under the forest, a little wider than its crowns. */
static int ground_mesh(struct mesh *m, const struct forest_scene *s)
{
	double rad = 1.15 * s->radius + 1.0;
	int ret = mesh_reserve(m, GROUND_SIDES + 1, 3 * GROUND_SIDES);

	if (ret < 0)
		return ret;
	for (int i = 0; i <= GROUND_SIDES; i++) {
		double a = 2.0 * VEC_PI * i / GROUND_SIDES;
		float *p = &m->positions[3 * i], *n = &m->normals[3 * i];

		p[0] = (float)(s->center[0] + (i < GROUND_SIDES ? rad * cos(a) : 0.0));
		p[1] = (float)(s->center[1] - 0.01);
		p[2] = (float)(s->center[2] + (i < GROUND_SIDES ? rad * sin(a) : 0.0));
		n[0] = n[2] = 0.0f;
		n[1] = 1.0f;
	}
	for (int i = 0; i < GROUND_SIDES; i++) {
		m->indices[3 * i] = GROUND_SIDES;
		m->indices[3 * i + 1] = (uint32_t)((i + 1) % GROUND_SIDES);
		m->indices[3 * i + 2] = (uint32_t)i;
	}
	m->nvertices = GROUND_SIDES + 1;
	m->nindices = 3 * GROUND_SIDES;
	return 0;
}

/* A tree's trunk harmonic and phase a vertex, expanded by the mesh's indices when it went
 * up without them. */
static int upload_trunk(GLuint *vbo, const uint8_t *trunk, const struct mesh *m, bool expand)
{
	size_t count = expand ? m->nindices : m->nvertices;
	uint8_t *o = malloc(2 * count + 2);

	if (!o)
		return -ENOMEM;
	for (size_t i = 0; i < count; i++) {
		size_t at = expand ? m->indices[i] : i;

		o[2 * i] = trunk[2 * at];
		o[2 * i + 1] = trunk[2 * at + 1];
	}
	if (!*vbo)
		glGenBuffers(1, vbo);
	glBindBuffer(GL_ARRAY_BUFFER, *vbo);
	glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(2 * count), count ? o : NULL, GL_STATIC_DRAW);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	free(o);
	return 0;
}

/* The scene's meshes and data, when it changed since they went up. */
static int upload(struct render *r, const struct forest_scene *s)
{
	struct render_forest *f = &r->forest;
	struct mesh g;
	float w = 1e-6f;
	int ret;

	if (f->ok && f->of == s && f->serial == s->serial)
		return 0;
	forest_clear(f);
	/* the band weights 1..3 are metres along the chain: against the largest there is */
	for (size_t i = 0; i < s->bark.n; i++)
		for (int k = 1; k < LIVE_BANDS; k++)
			w = fmaxf(w, s->bark.v[i].w[k]);
	for (size_t i = 0; i < s->leaves.n; i++)
		for (int k = 1; k < LIVE_BANDS; k++)
			w = fmaxf(w, s->leaves.v[i].w[k]);
	f->wscale[0] = 1.0f;
	f->wscale[1] = f->wscale[2] = f->wscale[3] = w;
	mesh_init(&g);
	ret = ground_mesh(&g, s);
	if (ret == 0)
		ret = render_mesh_upload(&f->ground, &g, r->uint_indices);
	mesh_finish(&g);
	if (ret == 0)
		ret = render_mesh_upload(&f->bark, &s->mesh.bark, r->uint_indices);
	if (ret == 0)
		ret = render_mesh_upload(&f->leaves, &s->mesh.leaves, r->uint_indices);
	if (ret == 0 && s->leaf_rgb)
		ret = render_mesh_upload_tints(&f->leaves, &s->mesh.leaves, s->leaf_rgb);
	if (ret == 0)
		ret = render_live_upload(r, &f->bark_live, s->bark.v, s->bark.n, &s->mesh.bark,
					 !f->bark.indexed, f->wscale);
	if (ret == 0)
		ret = render_live_upload(r, &f->leaves_live, s->leaves.v, s->leaves.n,
					 &s->mesh.leaves, !f->leaves.indexed, f->wscale);
	if (ret == 0)
		ret = upload_trunk(&f->bark_trunk, s->bark_trunk, &s->mesh.bark, !f->bark.indexed);
	if (ret == 0)
		ret = upload_trunk(&f->leaves_trunk, s->leaves_trunk, &s->mesh.leaves,
				   !f->leaves.indexed);
	r->stats.uploads += 3;
	if (ret < 0) {
		forest_clear(f);
		return ret;
	}
	f->of = s;
	f->serial = s->serial;
	f->tinted_leaves = s->leaf_rgb != NULL;
	f->ok = true;
	return 0;
}

/*
 * The camera's matrix: the forest's box (its feet's disc and the tallest top) seen from
 * the camera, fitted into the canvas rect of a width x height screen; xf out for the
 * labels, with the pixels a metre and the view's centre.
 */
static void fit(const struct forest_scene *s, const struct camera_xf *xf,
		const struct layout_rect *rect, int width, int height, float out[16],
		double *px_per_m, double c[3])
{
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	double rad = 1.15 * s->radius + 1.0, sc[3];
	float cam[16], box[16] = { 0 };

	/* the ground's rim and the same circle at the tallest top: a cylinder, whichever
	 * way the camera faces */
	for (int i = 0; i < 64; i++) {
		double a = 2.0 * VEC_PI * (i / 2) / 32.0;
		struct vec3 p = vec3(s->center[0] + rad * cos(a), i & 1 ? s->top : s->center[1],
				     s->center[2] + rad * sin(a));
		struct vec3 v = camera_to_view(xf, p);
		const double q[3] = { v.x, v.y, v.z };

		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], q[k]);
			hi[k] = fmax(hi[k], q[k]);
		}
	}
	for (int k = 0; k < 3; k++)
		c[k] = 0.5 * (lo[k] + hi[k]);
	*px_per_m = fmin(rect->w / fmax(hi[0] - lo[0], 1e-6), rect->h / fmax(hi[1] - lo[1], 1e-6)) /
		    FOREST_FIT_MARGIN;
	/* view metres to clip: scaled about the view's centre onto the rect's centre */
	sc[0] = 2.0 * *px_per_m / width;
	sc[1] = 2.0 * *px_per_m / height;
	sc[2] = -2.0 / (fmax(hi[2] - lo[2], 1e-6) * FOREST_FIT_MARGIN);
	camera_matrix(xf, cam);
	for (int k = 0; k < 3; k++)
		box[5 * k] = (float)sc[k];
	box[12] = (float)(-c[0] * sc[0] + 2.0 * (rect->x + 0.5 * rect->w) / width - 1.0);
	box[13] = (float)(-c[1] * sc[1] + 1.0 - 2.0 * (rect->y + 0.5 * rect->h) / height);
	box[14] = (float)(-c[2] * sc[2]);
	box[15] = 1.0f;
	render_mat4_mul(box, cam, out);
}

/* The frame's uniforms: the scene's wind at t (its loop), nothing growing. */
static void frame_at(const struct forest_scene *s, double t, struct app_live_frame *fr)
{
	memset(fr, 0, sizeof(*fr));
	fr->moving = true;
	fr->front = FLT_MAX;
	fr->swell = 1.0;
	if (s->wind.strength > 0.0)
		live_wind_frame(&s->wind, t, live_wind_angle(&s->wind, t), &fr->wind);
}

static void draw_part(struct render *r, const struct render_mesh *rm,
		      const struct render_live_data *d, GLuint trunk, bool tinted)
{
	if (rm->count == 0 || !d->ok)
		return;
	render_live_pointers(d->vbo, ATTR_LIVE, 0);
	glBindBuffer(GL_ARRAY_BUFFER, trunk);
	glVertexAttribPointer(ATTR_TRUNK, 2, GL_UNSIGNED_BYTE, GL_FALSE, 0, NULL);
	for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++)
		glEnableVertexAttribArray(ATTR_LIVE + i);
	glEnableVertexAttribArray(ATTR_TRUNK);
	if (tinted)
		render_mesh_draw_tinted(r, rm);
	else
		render_mesh_draw(r, rm);
	for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++)
		glDisableVertexAttribArray(ATTR_LIVE + i);
	glDisableVertexAttribArray(ATTR_TRUNK);
}

static void use(struct render *r, int which, const float mvp[16], const float light[3],
		const struct app_live_frame *fr, double loop_u)
{
	struct render_forest *f = &r->forest;
	const struct render_live_program *p = which ? &f->tinted : &f->plain;

	glUseProgram(p->tree.program);
	glUniformMatrix4fv(p->tree.mvp, 1, GL_FALSE, mvp);
	glUniform3fv(p->tree.light, 1, light);
	render_live_frame_uniforms(p, fr, f->wscale);
	glUniform1f(f->loop_u[which], (float)loop_u);
	r->lit = p->tree;
}

bool render_forest_shown(const struct render *r, const struct app *app, uint64_t now_us)
{
	return r->forest.plain.tree.program && app_forest_at(app, now_us);
}

/* The camera: once round the forest in FOREST_CAMERA_TURN_S, a little from above. */
#define FOREST_CAMERA_TURN_S 120.0
#define FOREST_CAMERA_PITCH_DEG 24.0

int render_forest_draw(struct render *r, const struct app *app, uint64_t now_us)
{
	struct render_forest *f = &r->forest;
	const struct forest_scene *s = app->forest;
	struct layout_rect rect = forest_rect(&app->screen);
	double t = now_us == UINT64_MAX ? 0.0 : (double)now_us / 1e6, px, c[3], loop_u = 0.0;
	double yaw = fmod(360.0 * t / FOREST_CAMERA_TURN_S, 360.0) - 180.0;
	struct camera_xf xf;
	struct app_live_frame fr;
	struct vec3 l = vec3_norm_or(vec3(forest_light[0], forest_light[1], forest_light[2]),
				     vec3(0.0, 1.0, 0.0));
	float mvp[16], light[3] = { (float)l.x, (float)l.y, (float)l.z }, leaf[3];
	bool leaves = leaf_tint_uniform(app->tree.season, leaf);
	int ret = upload(r, s);

	if (ret < 0)
		return ret;
	camera_xf_init(&xf, camera_normalize(yaw, FOREST_CAMERA_PITCH_DEG),
		       vec3(s->center[0], s->center[1] + 0.4 * s->top, s->center[2]));
	fit(s, &xf, &rect, app->screen.width, app->screen.height, mvp, &px, c);
	f->xf = xf;
	f->px_per_m = px;
	memcpy(f->c, c, sizeof(f->c));
	if (s->wind.loop > 0.0)
		loop_u = fmod(t, s->wind.loop) / s->wind.loop;
	frame_at(s, t, &fr);

	glEnable(GL_DEPTH_TEST);
	glDepthFunc(GL_LESS);
	glDisable(GL_BLEND);
	/* the ground, still */
	glUseProgram(r->tree_program);
	glUniformMatrix4fv(r->tree_mvp, 1, GL_FALSE, mvp);
	glUniform3fv(r->tree_light, 1, light);
	glUniform1i(r->tree_two_sided, 1);
	glUniform3fv(r->tree_color, 1, forest_ground);
	glEnableVertexAttribArray(ATTR_NORMAL);
	render_mesh_draw(r, &f->ground);
	/* the bark of every tree, one call */
	use(r, 0, mvp, light, &fr, loop_u);
	glEnable(GL_CULL_FACE);
	glCullFace(GL_BACK);
	glUniform1i(f->plain.tree.two_sided, 0);
	glUniform3fv(f->plain.tree.color, 1, forest_bark);
	draw_part(r, &f->bark, &f->bark_live, f->bark_trunk, false);
	glDisable(GL_CULL_FACE);
	/* the leaves of every tree, one call, in their season's colours (none in winter) */
	if (leaves && f->tinted_leaves) {
		use(r, 1, mvp, light, &fr, loop_u);
		glUniform1i(f->tinted.tree.two_sided, 1);
		draw_part(r, &f->leaves, &f->leaves_live, f->leaves_trunk, true);
	} else if (leaves) {
		glUniform1i(f->plain.tree.two_sided, 1);
		glUniform3fv(f->plain.tree.color, 1, leaf);
		draw_part(r, &f->leaves, &f->leaves_live, f->leaves_trunk, false);
	}
	/* ATTR_NORMAL stays enabled: it is the flat program's ATTR_COLOR, which the frame
	 * enabled for the UI's batch */
	glDisable(GL_DEPTH_TEST);
	f->drawn = true;
	return 0;
}

/* Each tree's number on a small card at its foot, where the camera shows it. */
void render_forest_labels(struct render *r, const struct app *app)
{
	const struct render_forest *f = &r->forest;
	const struct forest_scene *s = app->forest;
	const struct ui_text *t = &r->text;
	struct layout_rect rect = forest_rect(&app->screen);
	int px = (int)fmax(8.0, round(0.028 * app->screen.height));
	const struct rgba card = { 1.0f, 0.992f, 0.965f, 0.85f }, ink = { 0.13f, 0.11f, 0.09f, 1.0f };

	if (!f->drawn || !s || !t->font)
		return;
	for (size_t i = 0; i < s->ntrees; i++) {
		const struct forest_scene_tree *tr = &s->trees[i];
		struct vec3 v = camera_to_view(&f->xf, vec3(tr->position[0], tr->position[1],
							    tr->position[2]));
		double x = rect.x + 0.5 * rect.w + f->px_per_m * (v.x - f->c[0]);
		double y = rect.y + 0.5 * rect.h - f->px_per_m * (v.y - f->c[1]);
		char num[24];
		struct text_extent e;

		snprintf(num, sizeof(num), "%llu", (unsigned long long)tr->number);
		text_measure(t->font, num, px, &e);
		batch_rounded_rect(&r->batch, x - 0.5 * e.width - 0.3 * px, y + 0.15 * px,
				   e.width + 0.6 * px, 1.2 * px, 0.3 * px, card);
		text_draw(&r->batch, t->font, num, px, x - 0.5 * e.width,
			  y + 0.15 * px + 0.6 * px + 0.5 * (e.ascent - e.descent), ink);
	}
}
