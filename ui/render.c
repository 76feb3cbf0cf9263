/* SPDX-License-Identifier: MIT */
/*
 * The frame: paper and ground, the lit tree, then stroke, buttons, messages and cursor on
 * top; and the renderer's life (create, destroy, stats). The top of ui's renderer: it calls
 * the layers (render_*.c), which call nothing here; what they share with it is below them
 * (render_gl.c, render_shaders.c).
 */
#include "render.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "leaf_colors.h"
#include "leaf_tint.h"
#include "render_private.h"
#include "wood.h"
#include "sketch_seen.h"

/* Flat shapes and glyphs alike: colour times the atlas's coverage (solid for shapes).
 * Texel coordinates become texture ones here, in the vertex shader's high precision. */
static const char flat_vs[] =
	"uniform mat4 u_proj;\n"
	"uniform vec2 u_texel;\n"
	"attribute vec2 a_position;\n"
	"attribute vec2 a_uv;\n"
	"attribute vec4 a_color;\n"
	"varying vec4 v_color;\n"
	"varying vec2 v_uv;\n"
	"void main() {\n"
	"	v_color = a_color;\n"
	"	v_uv = a_uv * u_texel;\n"
	"	gl_Position = u_proj * vec4(a_position, 0.0, 1.0);\n"
	"}\n";

/* mediump (half floats on some GPUs) cannot tell the texels of a 2048-texel atlas apart */
static const char flat_fs[] =
	"#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
	"precision highp float;\n"
	"#else\n"
	"precision mediump float;\n"
	"#endif\n"
	"uniform sampler2D u_atlas;\n"
	"varying vec4 v_color;\n"
	"varying vec2 v_uv;\n"
	"void main() {\n"
	"	gl_FragColor = vec4(v_color.rgb, v_color.a * texture2D(u_atlas, v_uv).a);\n"
	"}\n";

/* Towards the light, in view space: from the upper left, in front of the sketch plane. */
static const float light_dir[3] = { -0.4418339f, 0.7069342f, 0.5522924f };

struct render *render_create(void)
{
	static const char *const tree_attribs[] = { "a_position", "a_normal", "a_tint" };
	static const GLuint tree_locations[] = { ATTR_POSITION, ATTR_NORMAL, ATTR_TINT };
	static const char *const flat_attribs[] = { "a_position", "a_color", "a_uv" };
	static const GLuint flat_locations[] = { ATTR_POSITION, ATTR_COLOR, ATTR_UV };
	struct render *r = calloc(1, sizeof(*r));

	if (!r)
		return NULL;
	batch_init(&r->batch);
	render_drain_gl_errors();

	r->tree_program =
		render_program("tree", render_tree_vs, render_tree_fs, tree_attribs, tree_locations, 2);
	r->flat_program = render_program("flat", flat_vs, flat_fs, flat_attribs, flat_locations, 3);
	if (!r->tree_program || !r->flat_program ||
	    !render_program_tree_init(&r->tinted, "tinted", render_tinted_vs, render_tinted_fs,
				      tree_attribs, tree_locations, 3) ||
	    render_text_init(r) < 0)
		goto fail;
	r->tree_mvp = glGetUniformLocation(r->tree_program, "u_mvp");
	r->tree_color = glGetUniformLocation(r->tree_program, "u_color");
	r->tree_light = glGetUniformLocation(r->tree_program, "u_light");
	r->tree_two_sided = glGetUniformLocation(r->tree_program, "u_two_sided");
	r->flat_proj = glGetUniformLocation(r->flat_program, "u_proj");
	r->flat_texel = glGetUniformLocation(r->flat_program, "u_texel");
	r->flat_atlas = glGetUniformLocation(r->flat_program, "u_atlas");
	glGenBuffers(1, &r->flat_vbo);

	r->uint_indices = render_gl_major_version() >= 3 ||
			  render_has_extension("GL_OES_element_index_uint");
	/* a program that will not build leaves the merged leaves, as on GLES 2 */
	r->instanced = render_gl_major_version() >= 3 && render_instanced_create(r) == 0;
	/* without its programs the tree stands still (it said why) */
	(void)render_live_create(r);
	(void)render_forest_create(r);
	if (glGetError() != GL_NO_ERROR) {
		fprintf(stderr, "render: GL error while setting up\n");
		goto fail;
	}
	return r;
fail:
	render_destroy(r);
	return NULL;
}

void render_destroy(struct render *r)
{
	if (!r)
		return;
	render_mesh_finish(&r->bark);
	render_mesh_finish(&r->wood);
	render_mesh_finish(&r->leaves);
	render_vines_finish(r);
	render_instanced_finish(r);
	render_live_finish(r);
	render_forest_finish(r);
	render_previews_finish(r);
	render_text_finish(r);
	glDeleteBuffers(1, &r->flat_vbo);
	glDeleteProgram(r->tree_program);
	glDeleteProgram(r->tinted.program);
	glDeleteProgram(r->flat_program);
	batch_finish(&r->batch);
	free(r->tint_scratch);
	free(r);
}

void render_get_stats(const struct render *r, struct render_stats *stats)
{
	*stats = r->stats;
}

/* Pixels (origin top left, y down) to clip space, column-major. */
static void pixel_matrix(int width, int height, float m[16])
{
	memset(m, 0, 16 * sizeof(*m));
	m[0] = 2.0f / (float)width;
	m[5] = -2.0f / (float)height;
	m[10] = 1.0f;
	m[12] = -1.0f;
	m[13] = 1.0f;
	m[15] = 1.0f;
}

/* Draws and empties the batch. */
static int flush_batch(struct render *r, const float proj[16])
{
	struct batch *b = &r->batch;
	GLsizei stride = BATCH_FLOATS_PER_VERTEX * sizeof(float);

	if (b->failed) {
		batch_reset(b);
		return -ENOMEM;
	}
	if (b->nvertices == 0)
		return 0;
	/* glyphs new this frame reach the texture first */
	if (render_text_sync(r) < 0) {
		batch_reset(b);
		return -ENOMEM;
	}
	glUseProgram(r->flat_program);
	glUniformMatrix4fv(r->flat_proj, 1, GL_FALSE, proj);
	glUniform2f(r->flat_texel, 1.0f / (float)r->atlas.w, 1.0f / (float)r->atlas.h);
	glUniform1i(r->flat_atlas, 0);
	glBindBuffer(GL_ARRAY_BUFFER, r->flat_vbo);
	glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(b->nvertices * (size_t)stride), b->v,
		     GL_STREAM_DRAW);
	glEnableVertexAttribArray(ATTR_UV);
	glVertexAttribPointer(ATTR_POSITION, 2, GL_FLOAT, GL_FALSE, stride, NULL);
	glVertexAttribPointer(ATTR_UV, 2, GL_FLOAT, GL_FALSE, stride,
			      (const void *)(2 * sizeof(float)));
	glVertexAttribPointer(ATTR_COLOR, 4, GL_FLOAT, GL_FALSE, stride,
			      (const void *)(4 * sizeof(float)));
	glDrawArrays(GL_TRIANGLES, 0, (GLsizei)b->nvertices);
	glDisableVertexAttribArray(ATTR_UV);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	glBindTexture(GL_TEXTURE_2D, 0);
	r->stats.draw_calls++;
	r->stats.triangles += b->nvertices / 3;
	batch_reset(b);
	return 0;
}

/* The leaves are app->tree's, drawn instanced, when instancing is on and there are leaves;
 * an app whose leaves are only in app->mesh (the render tests' hand-made scenes) has its
 * merged leaves drawn. */
static bool leaves_instanced(const struct render *r, const struct app *app)
{
	return r->instanced && app->tree.nleaves > 0 && app->mesh.leaves.nindices > 0;
}

/* The merged leaves' colours in the tree's season. */
static int upload_leaf_tints(struct render *r, const struct app *app)
{
	const struct mesh *m = &app->mesh.leaves;
	float *rgb = m->nvertices <= SIZE_MAX / 3 ? render_tint_scratch(r, 3 * m->nvertices + 3) : NULL;

	if (!rgb)
		return -ENOMEM;
	(void)leaf_tint_vertices(&app->tree, &app->mesh_marks, m->nvertices, rgb);
	return render_mesh_upload_tints(&r->leaves, m, rgb);
}

int render_upload_tree(struct render *r, const struct app *app)
{
	bool inst = leaves_instanced(r, app);
	/* summer is one colour, as the leaves always were; winter's are not drawn */
	bool tinted = leaf_colors_vary(app->tree.season);
	int ret;

	if (r->uploaded && r->mesh_serial == app->mesh_serial && r->uploaded_instanced == inst &&
	    r->uploaded_season == app->tree.season)
		return 0;
	/* not marked uploaded until both succeed, so a failure is retried next frame */
	r->uploaded = false;
	r->live.tree_ok = false; /* the living data is bound again for the new meshes */
	r->upload_bytes = 0;
	ret = render_mesh_upload(&r->bark, &app->mesh.bark, r->uint_indices);
	r->upload_bytes += r->bark.bytes;
	r->wood_src = NULL; /* the wood's bark goes up with it (upload_wood) */
	if (ret == 0 && inst) {
		/* the leaves go one way or the other: the unused copy gives its memory back */
		render_mesh_finish(&r->leaves);
		ret = render_instanced_upload(r, &app->tree, &app->mesh.leaves, &app->mesh_marks,
					      tinted);
	} else if (ret == 0) {
		render_instanced_clear(r); /* GL names 0 and empty arrays on GLES 2: no-ops */
		ret = render_mesh_upload(&r->leaves, &app->mesh.leaves, r->uint_indices);
		if (ret == 0 && tinted)
			ret = upload_leaf_tints(r, app);
		r->upload_bytes += r->leaves.bytes;
	}
	r->uploaded_instanced = inst;
	r->uploaded_tinted = tinted;
	r->uploaded_season = app->tree.season;
	r->stats.uploads += 2;
	if (ret < 0)
		return ret;
	r->uploaded = true;
	r->mesh_serial = app->mesh_serial;
	return 0;
}

/* The lit program for the tree, still or living, with the frame's matrix and light. */
static void use_lit(struct render *r, bool tinted, const float mvp[16], const float light[3])
{
	if (r->live.on) {
		render_live_use(r, tinted ? &r->live.merged_tinted : &r->live.merged, mvp, light);
		return;
	}
	r->lit = tinted ? r->tinted
			: (struct render_program_tree){ r->tree_program, r->tree_mvp, r->tree_color,
							r->tree_light, r->tree_two_sided };
	glUseProgram(r->lit.program);
	glUniformMatrix4fv(r->lit.mvp, 1, GL_FALSE, mvp);
	glUniform3fv(r->lit.light, 1, light);
}

/* The leaves in the tree's season: one colour (summer), a colour each (spring, autumn: the
 * tinted programs), or none (winter). */
static void draw_leaves(struct render *r, const struct app *app, const float mvp[16],
			const float light[3])
{
	float colour[3];

	if (!leaf_tint_uniform(app->tree.season, colour))
		return;
	if (!r->uploaded_tinted) {
		glUniform1i(r->lit.two_sided, 1);
		glUniform3fv(r->lit.color, 1, colour);
		if (r->uploaded_instanced) {
			/* the leaves that are no shape's copies, merged; then a call a shape */
			render_live_draw(r, &r->inst.loose, &r->live.loose, false);
			render_instanced_draw(r, mvp, light, colour, r->unfold, r->nunfold);
		} else {
			render_live_draw(r, &r->leaves, &r->live.leaves, false);
		}
		return;
	}
	use_lit(r, true, mvp, light);
	glUniform1i(r->lit.two_sided, 1);
	if (r->uploaded_instanced) {
		render_live_draw(r, &r->inst.loose, &r->live.loose, true);
		render_instanced_draw(r, mvp, light, NULL, r->unfold, r->nunfold);
	} else {
		render_live_draw(r, &r->leaves, &r->live.leaves, true);
	}
}

/* The wood's bark (issue 17) as the screen shows it at the frame's time: a frame of a
 * press's swelling, or the bark at rest; uploaded when that changes. */
static int upload_wood(struct render *r, const struct app *app)
{
	static const struct mesh none;
	const struct mesh *m = app_wood_bark_at(app, r->frame_us);
	int ret;

	m = m ? m : &none;
	if (m == r->wood_src && r->wood_serial == app->mesh_serial)
		return 0;
	ret = render_mesh_upload(&r->wood, m, r->uint_indices);
	r->upload_bytes += r->wood.bytes;
	r->wood_src = ret == 0 ? m : NULL;
	r->wood_serial = app->mesh_serial;
	return ret;
}

static int draw_tree(struct render *r, const struct app *app, const struct camera_xf *xf,
		     const float light[3])
{
	float mvp[16];
	int ret = render_upload_tree(r, app), r2;

	r2 = upload_wood(r, app);
	if (ret == 0)
		ret = r2;
	/* the wind or a growth: the living programs, with the meshes' data bound when they
	 * changed; otherwise the still ones, as always */
	(void)render_live_begin(r, app, r->frame_us);

	screen_clip_matrix(&app->screen, xf, mvp);
	glEnable(GL_DEPTH_TEST);
	glDepthFunc(GL_LESS);
	glDisable(GL_BLEND);
	use_lit(r, false, mvp, light);
	glEnableVertexAttribArray(ATTR_NORMAL);

	/* branches are closed tubes: their back faces are never seen */
	glEnable(GL_CULL_FACE);
	glCullFace(GL_BACK);
	glUniform1i(r->lit.two_sided, 0);
	glUniform3fv(r->lit.color, 1, render_bark);
	render_live_draw(r, &r->bark, &r->live.bark, false);
	render_live_draw(r, &r->wood, &r->live.wood, false);
	r2 = render_vines_draw(r, app);
	if (ret == 0)
		ret = r2;

	/* leaves are single polygons seen from either side */
	glDisable(GL_CULL_FACE);
	draw_leaves(r, app, mvp, light);
	glDisable(GL_DEPTH_TEST);
	return ret;
}

int render_frame(struct render *r, const struct app *app)
{
	return render_frame_at(r, app, UINT64_MAX);
}

int render_frame_at(struct render *r, const struct app *app, uint64_t now_us)
{
	const struct screen *v = &app->screen;
	struct camera cam;
	struct camera_xf xf;
	struct vec3 l;
	float proj[16], light[3];
	bool previews = render_previews_shown(app);
	int ret, r2;

	(void)app_camera_at(app, now_us, &cam);
	r->nunfold = app_unfold_at(app, now_us, r->unfold, APP_UNFOLD_MAX);
	r->frame_us = now_us;
	camera_xf_init(&xf, cam, sketch_seen_pivot(&app->tree));
	/* the light turns with the camera: the side a visitor looks at is always lit */
	l = camera_dir_from_view(&xf, vec3(light_dir[0], light_dir[1], light_dir[2]));
	light[0] = (float)l.x;
	light[1] = (float)l.y;
	light[2] = (float)l.z;
	memset(&r->stats, 0, sizeof(r->stats));
	if (v->width <= 0 || v->height <= 0)
		return -EINVAL;
	/* errors left by others are not ours to report */
	render_drain_gl_errors();

	/* every piece of state we rely on is set here: the caller may have changed any */
	glViewport(0, 0, v->width, v->height);
	glDisable(GL_SCISSOR_TEST);
	glDisable(GL_CULL_FACE);
	glDepthMask(GL_TRUE);
	glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	glClearColor(render_paper[0], render_paper[1], render_paper[2], 1.0f);
	glClearDepthf(1.0f);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	glEnableVertexAttribArray(ATTR_POSITION);
	glEnableVertexAttribArray(ATTR_COLOR);
	/* blended colour over an opaque target keeps alpha at 1: the PNGs stay opaque */
	glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
	pixel_matrix(v->width, v->height, proj);

	r->forest.drawn = false;
	if (render_forest_shown(r, app, now_us)) {
		/* the attract screen's forest instead of the drawing (render_forest.c) */
		batch_reset(&r->batch);
		ret = render_forest_draw(r, app, now_us);
	} else {
		/* behind the tree */
		glDisable(GL_DEPTH_TEST);
		glEnable(GL_BLEND);
		batch_reset(&r->batch);
		render_ui_ground(&r->batch, app);
		ret = flush_batch(r, proj);

		r2 = draw_tree(r, app, &xf, light);
		if (ret == 0)
			ret = r2;
	}

	/* in front of everything; the cursor last so it shows over the buttons too */
	glEnable(GL_BLEND);
	render_ui_selection(&r->batch, app, &xf);
	render_ui_stroke(&r->batch, app);
	render_ui_buttons(&r->batch, &r->text, app);
	if (previews) {
		/* the thumbnails' pictures go on their cards, under the cursor */
		r2 = flush_batch(r, proj);
		if (ret == 0)
			ret = r2;
		r2 = render_previews(r, app, &xf, light);
		if (ret == 0)
			ret = r2;
		glEnable(GL_BLEND);
	}
	/* the messages over the canvas; UINT64_MAX, the settled view, has none */
	if (now_us != UINT64_MAX) {
		render_ui_status(&r->batch, &r->text, app, now_us);
		if (app_attract_at(app, now_us, NULL)) {
			render_forest_labels(r, app);
			render_ui_attract(&r->batch, &r->text, app, r->forest.drawn);
		}
	}
	render_ui_cursor(&r->batch, app);
	r2 = flush_batch(r, proj);
	if (ret == 0)
		ret = r2;

	glDisable(GL_BLEND);
	glUseProgram(0);
	if (glGetError() != GL_NO_ERROR)
		return -EIO;
	return ret;
}
