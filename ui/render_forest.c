/* SPDX-License-Identifier: MIT */
/*
 * Today's forest on the attract screen (issue 27, docs/forest.md): the scene's merged
 * bark and leaves (src/forest/forest_scene.c) drawn by the forest's living programs, one
 * call for the bark and one for the leaves whatever the number of trees, on a gentle
 * disc of ground, seen by a camera that travels slowly round it; the newest tree, while
 * it grows in, drawn apart (its ranges of the same buffers, with its growth's front);
 * each tree's number at its foot, all of them one call. The meshes, their data and the
 * numbers' quads go up when the scene changes (its serial); a frame sets uniforms only.
 */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "forest.h"
#include "layout.h"
#include "leaf_tint.h"
#include "render_private.h"
#include "text.h"

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

/*
 * The numbers: a vertex of a label is its tree's foot (world metres), its offset in
 * pixels from where the foot is on screen, and its atlas texel. A card's vertex is its
 * offset as it is; a glyph's is the text's origin's offset (a_place.xy), rounded to a
 * whole pixel on screen as text_draw rounds it (so a glyph is drawn texel for texel,
 * crisp), then the glyph's corner from there (a_place.zw); a_uv.z is 1 for a glyph (in
 * ink), 0 for the card. The foot's depth is the label's: one behind the camera is clipped
 * whole. Pixels run from the top left, y down, as the batch's do.
 */
static const char label_vs[] =
	"uniform mat4 u_mvp;\n"
	"uniform vec2 u_screen;\n"
	"uniform vec2 u_texel;\n"
	"attribute vec3 a_position;\n"
	"attribute vec4 a_place;\n"
	"attribute vec3 a_uv;\n"
	"varying vec2 v_uv;\n"
	"varying float v_ink;\n"
	"void main() {\n"
	"	vec4 c = u_mvp * vec4(a_position, 1.0);\n"
	"	vec2 foot = vec2(c.x / c.w + 1.0, 1.0 - c.y / c.w) * 0.5 * u_screen;\n"
	"	vec2 o = foot + a_place.xy;\n"
	"	o = mix(o, floor(o + 0.5), a_uv.z) + a_place.zw;\n"
	"	v_uv = a_uv.xy * u_texel;\n"
	"	v_ink = a_uv.z;\n"
	"	gl_Position = vec4(2.0 * o.x / u_screen.x - 1.0, 1.0 - 2.0 * o.y / u_screen.y,\n"
	"			   c.z / c.w, 1.0);\n"
	"}\n";

/* the flat program's: mediump cannot tell a large atlas's texels apart */
static const char label_fs[] =
	"#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
	"precision highp float;\n"
	"#else\n"
	"precision mediump float;\n"
	"#endif\n"
	"uniform sampler2D u_atlas;\n"
	"uniform vec4 u_card;\n"
	"uniform vec4 u_ink;\n"
	"varying vec2 v_uv;\n"
	"varying float v_ink;\n"
	"void main() {\n"
	"	vec4 c = v_ink > 0.5 ? u_ink : u_card;\n"
	"	gl_FragColor = vec4(c.rgb, c.a * texture2D(u_atlas, v_uv).a);\n"
	"}\n";

/* Where the labels' data sits: clear of the flat program's colour (ATTR_COLOR, which
 * stays enabled), in places no other program leaves enabled. */
#define ATTR_LABEL_PLACE ATTR_UV
#define ATTR_LABEL_UV ATTR_ROW0

struct label_vertex {
	float foot[3];
	float place[4];
	float uv[3];
};

static const struct rgba label_card = { 1.0f, 0.992f, 0.965f, 0.85f };
static const struct rgba label_ink = { 0.13f, 0.11f, 0.09f, 1.0f };

static int labels_create(struct render_forest_labels *l)
{
	static const char *const names[] = { "a_position", "a_place", "a_uv" };
	static const GLuint at[] = { ATTR_POSITION, ATTR_LABEL_PLACE, ATTR_LABEL_UV };

	l->program = render_program("forest labels", label_vs, label_fs, names, at, 3);
	if (!l->program)
		return -1;
	l->mvp = glGetUniformLocation(l->program, "u_mvp");
	l->screen = glGetUniformLocation(l->program, "u_screen");
	l->texel = glGetUniformLocation(l->program, "u_texel");
	l->atlas = glGetUniformLocation(l->program, "u_atlas");
	l->card = glGetUniformLocation(l->program, "u_card");
	l->ink = glGetUniformLocation(l->program, "u_ink");
	return 0;
}

int render_forest_create(struct render *r)
{
	struct render_forest *f = &r->forest;

	memset(f, 0, sizeof(*f));
	if (!render_program_tree_init(&f->plain.tree, "forest", render_forest_vs, render_live_fs,
				      attribs, locations, 8) ||
	    !render_program_tree_init(&f->tinted.tree, "forest tinted", render_forest_tinted_vs,
				      render_live_tinted_fs, attribs, locations, 8) ||
	    labels_create(&f->labels) < 0) {
		glDeleteProgram(f->plain.tree.program);
		glDeleteProgram(f->tinted.tree.program);
		f->plain.tree.program = f->tinted.tree.program = 0;
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
	glDeleteBuffers(1, &f->labels.vbo);
	glDeleteProgram(f->labels.program);
	glDeleteProgram(f->plain.tree.program);
	glDeleteProgram(f->tinted.tree.program);
	f->plain.tree.program = f->tinted.tree.program = 0;
	f->labels.program = f->labels.vbo = 0;
	f->labels.ok = false;
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

/* The leaves' season colours as the drawing screen shows a palette colour (leaf_tint_map:
 * lighter than the palette, summer exactly its green); a leaf's vertices share a colour, so
 * each run is mapped once. */
static int upload_leaf_tints(struct render_forest *f, const struct forest_scene *s)
{
	size_t n = s->mesh.leaves.nvertices;
	float *rgb = malloc(3 * n * sizeof(*rgb) + 1), last[3] = { -1.0f, -1.0f, -1.0f }, out[3] = { 0 };
	float summer[3] = { LEAF_TINT_SUMMER_RGB };
	const struct season_rgb *palette;
	int ret;

	if (!rgb)
		return -ENOMEM;
	(void)season_palette(SEASON_SUMMER, &palette);
	for (size_t v = 0; v < n; v++) {
		const float *in = &s->leaf_rgb[3 * v];

		if (memcmp(in, last, sizeof(last)) != 0) {
			memcpy(last, in, sizeof(last));
			if (in[0] == palette[0].r && in[1] == palette[0].g && in[2] == palette[0].b)
				memcpy(out, summer, sizeof(out));
			else
				leaf_tint_map((struct season_rgb){ in[0], in[1], in[2] }, out);
		}
		memcpy(&rgb[3 * v], out, sizeof(out));
	}
	ret = render_mesh_upload_tints(&f->leaves, &s->mesh.leaves, rgb);
	free(rgb);
	return ret;
}

/* The bark's colours when vines climb in the forest: a vine's stems as the drawing screen
 * colours them (render_vine_stem), the rest the bark's. */
static int upload_bark_tints(struct render_forest *f, const struct forest_scene *s)
{
	size_t n = s->mesh.bark.nvertices;
	float *rgb = malloc(3 * n * sizeof(*rgb) + 1);
	int ret;

	if (!rgb)
		return -ENOMEM;
	for (size_t v = 0; v < n; v++)
		memcpy(&rgb[3 * v], s->bark_vine[v] ? render_vine_stem : render_bark, 3 * sizeof(*rgb));
	ret = render_mesh_upload_tints(&f->bark, &s->mesh.bark, rgb);
	free(rgb);
	return ret;
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
		ret = upload_leaf_tints(f, s);
	if (ret == 0 && s->bark_vine)
		ret = upload_bark_tints(f, s);
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
	f->tinted_bark = s->bark_vine != NULL;
	f->ok = true;
	return 0;
}

/*
 * The camera's matrix: the forest's box (its feet's disc and the tallest top) seen from
 * the camera, fitted into the canvas rect of a width x height screen.
 */
static void fit(const struct forest_scene *s, const struct camera_xf *xf,
		const struct layout_rect *rect, int width, int height, float out[16])
{
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	double rad = 1.15 * s->radius + 1.0, sc[3], c[3], px_per_m;
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
	px_per_m = fmin(rect->w / fmax(hi[0] - lo[0], 1e-6), rect->h / fmax(hi[1] - lo[1], 1e-6)) /
		   FOREST_FIT_MARGIN;
	/* view metres to clip: scaled about the view's centre onto the rect's centre */
	sc[0] = 2.0 * px_per_m / width;
	sc[1] = 2.0 * px_per_m / height;
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

/* The camera: once round the forest in FOREST_CAMERA_TURN_S, a little from above. */
#define FOREST_CAMERA_TURN_S 120.0
#define FOREST_CAMERA_PITCH_DEG 24.0

/* Whether the newest tree (the scene's last) grows in at now_us: it joined at
 * app->forest_joined_us (0: none grows) and its growth is not over; *age seconds in. */
static bool growing_at(const struct app *app, uint64_t now_us, double *age)
{
	const struct forest_scene *s = app->forest;
	uint64_t joined = app->forest_joined_us;

	if (joined == 0 || now_us == UINT64_MAX || s->ntrees == 0)
		return false;
	/* a moment before it joined (a clock stepped back) is its growth's start */
	*age = now_us > joined ? (double)(now_us - joined) * 1e-6 : 0.0;
	return *age < s->trees[s->ntrees - 1].grow.duration;
}

void render_forest_frame_at(const struct app *app, uint64_t now_us,
			    struct render_forest_frame *out)
{
	const struct forest_scene *s = app->forest;
	struct layout_rect rect = forest_rect(&app->screen);
	double t = now_us == UINT64_MAX ? 0.0 : (double)now_us / 1e6;
	double yaw = fmod(360.0 * t / FOREST_CAMERA_TURN_S, 360.0) - 180.0;
	struct vec3 l = vec3_norm_or(vec3(forest_light[0], forest_light[1], forest_light[2]),
				     vec3(0.0, 1.0, 0.0));
	struct camera_xf xf;

	memset(out, 0, sizeof(*out));
	camera_xf_init(&xf, camera_normalize(yaw, FOREST_CAMERA_PITCH_DEG),
		       vec3(s->center[0], s->center[1] + 0.4 * s->top, s->center[2]));
	fit(s, &xf, &rect, app->screen.width, app->screen.height, out->mvp);
	out->light[0] = (float)l.x;
	out->light[1] = (float)l.y;
	out->light[2] = (float)l.z;
	/* the scene's wind at t (its loop); every tree drawn whole */
	out->live.moving = true;
	out->live.front = FLT_MAX;
	out->live.swell = 1.0;
	if (s->wind.strength > 0.0)
		live_wind_frame(&s->wind, t, live_wind_angle(&s->wind, t), &out->live.wind);
	if (s->wind.loop > 0.0)
		out->loop_u = fmod(t, s->wind.loop) / s->wind.loop;
	/* the newest tree grows in as a tree does on the drawing screen (live_grow) */
	out->growing = growing_at(app, now_us, &out->age);
	if (out->growing) {
		const struct live_grow *g = &s->trees[s->ntrees - 1].grow;

		out->front = live_grow_front(g, out->age);
		out->swell = g->swell;
	}
}

/* A range [first, end) of rm's indices, with the program in use; the mesh's data
 * pointers as render_mesh_draw sets them (a mesh gone up without indices has one
 * vertex an index, in their order). */
static void draw_range(struct render *r, const struct render_mesh *rm, size_t first,
		       size_t end, bool tinted)
{
	GLsizei count = (GLsizei)(end - first);

	if (end <= first)
		return;
	if (tinted) {
		glBindBuffer(GL_ARRAY_BUFFER, rm->tints);
		glVertexAttribPointer(ATTR_TINT, 3, GL_FLOAT, GL_FALSE, 0, NULL);
		glEnableVertexAttribArray(ATTR_TINT);
	}
	glBindBuffer(GL_ARRAY_BUFFER, rm->positions);
	glVertexAttribPointer(ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	glBindBuffer(GL_ARRAY_BUFFER, rm->normals);
	glVertexAttribPointer(ATTR_NORMAL, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	if (rm->indexed) {
		glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, rm->indices);
		glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT,
			       (const void *)(uintptr_t)(first * sizeof(uint32_t)));
		glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
	} else {
		glDrawArrays(GL_TRIANGLES, (GLint)first, count);
	}
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	if (tinted)
		glDisableVertexAttribArray(ATTR_TINT);
	r->stats.draw_calls++;
	r->stats.triangles += (end - first) / 3;
	r->stats.tree_triangles += (end - first) / 3;
}

/*
 * The bark or the leaves of every tree with its data. Settled, the whole mesh in one
 * call; while the newest tree grows in (its indices the last, from `newest`), the others
 * in one call as settled and the newest in another with its growth's front and swell.
 */
static void draw_part(struct render *r, const struct render_live_program *p,
		      const struct render_mesh *rm, const struct render_live_data *d,
		      GLuint trunk, bool tinted, const struct render_forest_frame *fr,
		      size_t newest)
{
	if (rm->count == 0 || !d->ok || (tinted && !rm->tints))
		return;
	render_live_pointers(d->vbo, ATTR_LIVE, 0);
	glBindBuffer(GL_ARRAY_BUFFER, trunk);
	glVertexAttribPointer(ATTR_TRUNK, 2, GL_UNSIGNED_BYTE, GL_FALSE, 0, NULL);
	for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++)
		glEnableVertexAttribArray(ATTR_LIVE + i);
	glEnableVertexAttribArray(ATTR_TRUNK);
	if (!fr->growing) {
		if (tinted)
			render_mesh_draw_tinted(r, rm);
		else
			render_mesh_draw(r, rm);
	} else {
		draw_range(r, rm, 0, newest, tinted);
		glUniform1f(p->front, (float)fr->front);
		glUniform1f(p->swell, (float)fr->swell);
		draw_range(r, rm, newest, (size_t)rm->count, tinted);
		glUniform1f(p->front, (float)fr->live.front);
		glUniform1f(p->swell, (float)fr->live.swell);
	}
	for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++)
		glDisableVertexAttribArray(ATTR_LIVE + i);
	glDisableVertexAttribArray(ATTR_TRUNK);
}

static const struct render_live_program *use(struct render *r, int which,
					     const struct render_forest_frame *fr)
{
	struct render_forest *f = &r->forest;
	const struct render_live_program *p = which ? &f->tinted : &f->plain;

	glUseProgram(p->tree.program);
	glUniformMatrix4fv(p->tree.mvp, 1, GL_FALSE, fr->mvp);
	glUniform3fv(p->tree.light, 1, fr->light);
	render_live_frame_uniforms(p, &fr->live, f->wscale);
	glUniform1f(f->loop_u[which], (float)fr->loop_u);
	r->lit = p->tree;
	return p;
}

bool render_forest_shown(const struct render *r, const struct app *app, uint64_t now_us)
{
	return r->forest.plain.tree.program && app_forest_at(app, now_us);
}

int render_forest_draw(struct render *r, const struct app *app, uint64_t now_us)
{
	struct render_forest *f = &r->forest;
	const struct forest_scene *s = app->forest;
	const struct forest_scene_tree *newest;
	const struct render_live_program *p;
	struct render_forest_frame fr;
	float leaf[3];
	bool leaves = leaf_tint_uniform(app->tree.season, leaf);
	int ret = upload(r, s);

	if (ret < 0)
		return ret;
	render_forest_frame_at(app, now_us, &fr);
	memcpy(f->mvp, fr.mvp, sizeof(f->mvp));
	newest = &s->trees[s->ntrees - 1];
	/* the newest tree's ranges are the meshes' last (forest_scene_build), as uploaded */
	if (fr.growing && (newest->bark_indices[1] != (size_t)f->bark.count ||
			   newest->leaves_indices[1] != (size_t)f->leaves.count))
		fr.growing = false;

	glEnable(GL_DEPTH_TEST);
	glDepthFunc(GL_LESS);
	glDisable(GL_BLEND);
	/* the ground, still */
	glUseProgram(r->tree_program);
	glUniformMatrix4fv(r->tree_mvp, 1, GL_FALSE, fr.mvp);
	glUniform3fv(r->tree_light, 1, fr.light);
	glUniform1i(r->tree_two_sided, 1);
	glUniform3fv(r->tree_color, 1, forest_ground);
	glEnableVertexAttribArray(ATTR_NORMAL);
	render_mesh_draw(r, &f->ground);
	/* the bark of every tree, one call (two while the newest grows in) */
	p = use(r, f->tinted_bark ? 1 : 0, &fr);
	glEnable(GL_CULL_FACE);
	glCullFace(GL_BACK);
	glUniform1i(p->tree.two_sided, 0);
	glUniform3fv(p->tree.color, 1, render_bark);
	draw_part(r, p, &f->bark, &f->bark_live, f->bark_trunk, f->tinted_bark, &fr,
		  newest->bark_indices[0]);
	glDisable(GL_CULL_FACE);
	/* the leaves of every tree, one call (two), in their season's colours (none in winter) */
	if (leaves && f->tinted_leaves) {
		p = use(r, 1, &fr);
		glUniform1i(f->tinted.tree.two_sided, 1);
		draw_part(r, p, &f->leaves, &f->leaves_live, f->leaves_trunk, true, &fr,
			  newest->leaves_indices[0]);
	} else if (leaves) {
		if (f->tinted_bark)
			p = use(r, 0, &fr);
		glUniform1i(f->plain.tree.two_sided, 1);
		glUniform3fv(f->plain.tree.color, 1, leaf);
		draw_part(r, p, &f->leaves, &f->leaves_live, f->leaves_trunk, false, &fr,
			  newest->leaves_indices[0]);
	}
	/* ATTR_NORMAL stays enabled: it is the flat program's ATTR_COLOR, which the frame
	 * enabled for the UI's batch */
	glDisable(GL_DEPTH_TEST);
	f->drawn = true;
	return 0;
}

/* The numbers' size: as the attract screen's words, a fraction of the screen's height. */
static int label_px(const struct app *app)
{
	return (int)fmax(8.0, round(0.028 * app->screen.height));
}

/* Whether the digits' glyphs are where they were when the quads were built (the font or
 * its atlas may have been set again since, at the same address). */
static bool digits_current(struct render_forest_labels *l, struct font *font, int px)
{
	for (int d = 0; d < 10; d++) {
		const struct font_glyph *g;

		if (!(l->used & 1u << d))
			continue;
		g = font_glyph(font, (uint32_t)('0' + d), px);
		if (!g || memcmp(g, &l->digits[d], sizeof(*g)) != 0)
			return false;
	}
	return true;
}

bool render_forest_labels_current(struct render *r, const struct app *app)
{
	struct render_forest_labels *l = &r->forest.labels;
	int px = label_px(app);

	return l->ok && l->of == app->forest && l->serial == app->forest->serial &&
	       l->font == r->text.font && l->px == px && digits_current(l, r->text.font, px);
}

/*
 * Tree t's label into the batch b (emptied first) as the batch lays out a card and its
 * text, with the foot at the origin: a rounded card 1.2 px tall under the foot, the
 * number centred on it, its origin at a whole pixel there (the glyphs' corners from
 * it). *ncard: the card's vertices (the first); o: the text's origin from the foot.
 */
static void label_layout(struct batch *b, struct font *font, int px,
			 const struct forest_scene_tree *t, size_t *ncard, float o[2])
{
	char num[24];
	struct text_extent e;

	snprintf(num, sizeof(num), "%llu", (unsigned long long)t->number);
	text_measure(font, num, px, &e);
	batch_reset(b);
	batch_rounded_rect(b, -0.5 * e.width - 0.3 * px, 0.15 * px, e.width + 0.6 * px, 1.2 * px,
			   0.3 * px, label_card);
	*ncard = b->nvertices;
	text_draw(b, font, num, px, 0.0, 0.0, label_ink);
	o[0] = (float)(-0.5 * e.width);
	o[1] = (float)(0.15 * px + 0.6 * px + 0.5 * (e.ascent - e.descent));
}

/* The batch's vertices of tree t's label (its first ncard the card's) as the GPU's. */
static void label_vertices(const struct batch *b, size_t ncard, const float o[2],
			   const struct forest_scene_tree *t, struct label_vertex *out)
{
	for (size_t v = 0; v < b->nvertices; v++) {
		const float *bv = &b->v[v * BATCH_FLOATS_PER_VERTEX];
		struct label_vertex *w = &out[v];
		bool glyph = v >= ncard;

		for (int k = 0; k < 3; k++)
			w->foot[k] = (float)t->position[k];
		w->place[0] = glyph ? o[0] : bv[0];
		w->place[1] = glyph ? o[1] : bv[1];
		w->place[2] = glyph ? bv[0] : 0.0f;
		w->place[3] = glyph ? bv[1] : 0.0f;
		w->uv[0] = bv[2];
		w->uv[1] = bv[3];
		w->uv[2] = glyph ? 1.0f : 0.0f;
	}
}

/* Room for n label vertices in *v (*cap of them). */
static int reserve_labels(struct label_vertex **v, size_t *cap, size_t n)
{
	struct label_vertex *w;
	size_t c = *cap ? *cap : 1024;

	if (n <= *cap)
		return 0;
	while (c < n && c <= SIZE_MAX / 2 / sizeof(*w))
		c *= 2;
	if (c < n || !(w = realloc(*v, c * sizeof(*w))))
		return -ENOMEM;
	*v = w;
	*cap = c;
	return 0;
}

/* Every tree's label, built and uploaded: once a scene (O(trees)). 0 or -ENOMEM. */
static int labels_build(struct render *r, const struct app *app)
{
	struct render_forest_labels *l = &r->forest.labels;
	const struct forest_scene *s = app->forest;
	struct font *font = r->text.font;
	int px = label_px(app);
	struct label_vertex *v = NULL;
	size_t n = 0, cap = 0;
	struct batch b;
	int ret = 0;

	l->ok = false;
	l->used = 0;
	batch_init(&b);
	for (size_t i = 0; i < s->ntrees && ret == 0; i++) {
		size_t ncard;
		float o[2];

		label_layout(&b, font, px, &s->trees[i], &ncard, o);
		ret = b.failed ? -ENOMEM : reserve_labels(&v, &cap, n + b.nvertices);
		if (ret < 0)
			break;
		label_vertices(&b, ncard, o, &s->trees[i], v + n);
		n += b.nvertices;
		for (uint64_t k = s->trees[i].number;; k /= 10) {
			l->used |= 1u << (k % 10);
			if (k < 10)
				break;
		}
	}
	batch_finish(&b);
	/* the digits' glyphs as they are now: the quads hold their places */
	for (int d = 0; d < 10 && ret == 0; d++) {
		const struct font_glyph *g;

		if (!(l->used & 1u << d))
			continue;
		g = font_glyph(font, (uint32_t)('0' + d), px);
		if (!g)
			ret = -ENOMEM;
		else
			l->digits[d] = *g;
	}
	if (ret == 0 && n > (size_t)INT32_MAX / sizeof(*v))
		ret = -ENOMEM;
	if (ret == 0) {
		if (!l->vbo)
			glGenBuffers(1, &l->vbo);
		glBindBuffer(GL_ARRAY_BUFFER, l->vbo);
		glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * sizeof(*v)), n ? v : NULL,
			     GL_STATIC_DRAW);
		glBindBuffer(GL_ARRAY_BUFFER, 0);
		l->count = (GLsizei)n;
		l->of = s;
		l->serial = s->serial;
		l->font = font;
		l->px = px;
		l->ok = true;
		l->builds++;
		r->stats.uploads++;
	}
	free(v);
	return ret;
}

/* Each tree's number on a small card at its foot, where the camera shows it: one call,
 * under the batch's words and shapes. */
void render_forest_labels(struct render *r, const struct app *app)
{
	struct render_forest_labels *l = &r->forest.labels;
	GLsizei stride = sizeof(struct label_vertex);

	if (!r->forest.drawn || !app->forest || !r->text.font)
		return;
	if (!render_forest_labels_current(r, app) && labels_build(r, app) < 0)
		return;
	if (l->count == 0 || render_text_sync(r) < 0)
		return;
	glUseProgram(l->program);
	glUniformMatrix4fv(l->mvp, 1, GL_FALSE, r->forest.mvp);
	glUniform2f(l->screen, (float)app->screen.width, (float)app->screen.height);
	glUniform2f(l->texel, 1.0f / (float)r->atlas.w, 1.0f / (float)r->atlas.h);
	glUniform1i(l->atlas, 0);
	glUniform4f(l->card, label_card.r, label_card.g, label_card.b, label_card.a);
	glUniform4f(l->ink, label_ink.r, label_ink.g, label_ink.b, label_ink.a);
	glBindBuffer(GL_ARRAY_BUFFER, l->vbo);
	glVertexAttribPointer(ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, stride, NULL);
	glVertexAttribPointer(ATTR_LABEL_PLACE, 4, GL_FLOAT, GL_FALSE, stride,
			      (const void *)offsetof(struct label_vertex, place));
	glVertexAttribPointer(ATTR_LABEL_UV, 3, GL_FLOAT, GL_FALSE, stride,
			      (const void *)offsetof(struct label_vertex, uv));
	glEnableVertexAttribArray(ATTR_LABEL_PLACE);
	glEnableVertexAttribArray(ATTR_LABEL_UV);
	glDrawArrays(GL_TRIANGLES, 0, l->count);
	/* the other programs do not read them (ATTR_POSITION stays, as everyone's) */
	glDisableVertexAttribArray(ATTR_LABEL_PLACE);
	glDisableVertexAttribArray(ATTR_LABEL_UV);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	glBindTexture(GL_TEXTURE_2D, 0);
	r->stats.draw_calls++;
	r->stats.triangles += (size_t)l->count / 3;
}
