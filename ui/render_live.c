/* SPDX-License-Identifier: MIT */
/*
 * The living tree on the screen (issue 26, docs/living-trees.md): the wind and growing in
 * drawn by the living programs (render_shaders.h, LIVE), which move each vertex by its
 * skeleton data and a few uniforms a frame. The data is bound when the meshes change
 * (live_attrs_bind_*: the bark by the app's marks, the merged leaves by their anchors,
 * per instance for instanced leaves, the wood's bark and the vines to the nearest bark)
 * and packed to 32 bytes a vertex (struct render_live_vertex); a frame uploads nothing
 * but its uniforms, whatever the tree's size. While nothing moves (no wind, no growth,
 * the settled view) the still programs draw, as they always did.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "live.h"
#include "render_private.h"

/* A vertex's living data as the GPU takes it (docs/living-trees.md, "Memory and packing"):
 * the skeleton point and its path length as floats, the band weights as normalised shorts
 * (w0 in 0..1; w1..w3 against the tree's largest path length, which none exceeds), the
 * phases and the flutter direction as bytes; the distance from a leaf's anchor is the
 * shader's own. */
struct render_live_vertex {
	float live0[4];
	uint16_t w[4];
	uint8_t phase[4];
	int8_t flutter[4];
};
_Static_assert(sizeof(struct render_live_vertex) == RENDER_LIVE_STRIDE, "the data's stride");

static const char *const attribs[] = { "a_position", "a_normal", "a_tint", "a_live0",
				       "a_live1", "a_phase", "a_flutter" };
static const GLuint locations[] = { ATTR_POSITION, ATTR_NORMAL, ATTR_TINT, ATTR_LIVE,
				    ATTR_LIVE + 1, ATTR_LIVE + 2, ATTR_LIVE + 3 };

void render_live_program_locate(struct render_live_program *p)
{
	GLuint g = p->tree.program;

	p->along = glGetUniformLocation(g, "u_along");
	p->across = glGetUniformLocation(g, "u_across");
	p->sway = glGetUniformLocation(g, "u_sway");
	p->dir = glGetUniformLocation(g, "u_dir");
	p->theta = glGetUniformLocation(g, "u_theta");
	p->amp_leaf = glGetUniformLocation(g, "u_amp_leaf");
	p->front = glGetUniformLocation(g, "u_front");
	p->swell = glGetUniformLocation(g, "u_swell");
	p->wscale = glGetUniformLocation(g, "u_wscale");
	p->unfolding = glGetUniformLocation(g, "u_unfolding");
}

int render_live_create(struct render *r)
{
	struct render_live *l = &r->live;

	live_attrs_init(&l->attrs);
	if (!render_program_tree_init(&l->merged.tree, "living", render_live_vs, render_live_fs,
				      attribs, locations, sizeof(attribs) / sizeof(*attribs)) ||
	    !render_program_tree_init(&l->merged_tinted.tree, "living tinted",
				      render_live_tinted_vs, render_live_tinted_fs, attribs,
				      locations, sizeof(attribs) / sizeof(*attribs)))
		return -1;
	render_live_program_locate(&l->merged);
	render_live_program_locate(&l->merged_tinted);
	return 0;
}

static void data_finish(struct render_live_data *d)
{
	glDeleteBuffers(1, &d->vbo);
	d->vbo = 0;
	d->ok = false;
}

void render_live_clear(struct render *r)
{
	struct render_live *l = &r->live;
	struct render_live_data *all[] = { &l->bark, &l->leaves, &l->loose, &l->instances,
					   &l->wood, &l->vine[0], &l->vine[1], &l->vine[2],
					   &l->vine[3], &l->grow_instances };

	for (size_t i = 0; i < sizeof(all) / sizeof(*all); i++)
		data_finish(all[i]);
	l->tree_ok = l->wood_ok = l->vines_ok = false;
}

void render_live_finish(struct render *r)
{
	struct render_live *l = &r->live;

	render_live_clear(r);
	glDeleteProgram(l->merged.tree.program);
	glDeleteProgram(l->merged_tinted.tree.program);
	l->merged.tree.program = l->merged_tinted.tree.program = 0;
	live_attrs_finish(&l->attrs);
	free(l->packed);
	free(l->gather);
	free(l->inst_mark);
	l->packed = NULL;
	l->gather = NULL;
	l->inst_mark = NULL;
	l->packed_cap = l->gather_cap = 0;
}

static struct render_live_vertex *packed(struct render_live *l, size_t n)
{
	if (n > l->packed_cap) {
		struct render_live_vertex *p;

		if (n > SIZE_MAX / sizeof(*p))
			return NULL;
		p = realloc(l->packed, n * sizeof(*p));
		if (!p)
			return NULL;
		l->packed = p;
		l->packed_cap = n;
	}
	return l->packed;
}

static uint16_t unorm16(double v, double scale)
{
	double q = v / scale * 65535.0;

	return !(q > 0.0) ? 0 : q >= 65535.0 ? 65535 : (uint16_t)lround(q);
}

static void pack(struct render_live_vertex *o, const struct live_vertex *v, const float scale[4])
{
	memcpy(o->live0, v->point, 3 * sizeof(float));
	o->live0[3] = v->d;
	for (int k = 0; k < LIVE_BANDS; k++)
		o->w[k] = unorm16(v->w[k], scale[k]);
	memcpy(o->phase, v->phase, sizeof(o->phase));
	memcpy(o->flutter, v->flutter, sizeof(o->flutter));
}

int render_live_upload(struct render *r, struct render_live_data *d, const struct live_vertex *v,
		       size_t n, const struct mesh *m, bool expand, const float wscale[4])
{
	struct render_live *l = &r->live;
	size_t count = expand ? m->nindices : n;
	struct render_live_vertex *o = packed(l, count ? count : 1);

	d->ok = false;
	if (!o)
		return -ENOMEM;
	for (size_t i = 0; i < count; i++) {
		size_t at = expand ? m->indices[i] : i;

		if (at >= n)
			return -EINVAL;
		pack(&o[i], &v[at], wscale);
	}
	if (!d->vbo)
		glGenBuffers(1, &d->vbo);
	glBindBuffer(GL_ARRAY_BUFFER, d->vbo);
	glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(count * sizeof(*o)), count ? o : NULL,
		     GL_STATIC_DRAW);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	l->bytes += count * sizeof(*o);
	d->ok = true;
	return 0;
}

/* The tree's data: its band weights against the tree's scales (render_live_begin). */
static int upload(struct render *r, struct render_live_data *d, const struct live_vertex *v,
		  size_t n, const struct mesh *m, bool expand)
{
	return render_live_upload(r, d, v, n, m, expand, r->live.wscale);
}

/* The marks describe t's meshes as they are (tree_mesh_marks: unknown without memory). */
static bool marks_known(const struct app *app)
{
	const struct tree_mesh_marks *mk = &app->mesh_marks;

	return mk->nbark == app->tree.nbranches + 1 && mk->nleaves == app->tree.nleaves + 1 &&
	       mk->bark[mk->nbark - 1].nvertices == app->mesh.bark.nvertices &&
	       mk->leaves[mk->nleaves - 1].nvertices == app->mesh.leaves.nvertices;
}

/* Room for n vertices' data gathered from a binding. */
static struct live_vertex *gathered(struct render_live *l, size_t n)
{
	if (n > l->gather_cap) {
		struct live_vertex *p;

		if (n > SIZE_MAX / sizeof(*p))
			return NULL;
		p = realloc(l->gather, n * sizeof(*p));
		if (!p)
			return NULL;
		l->gather = p;
		l->gather_cap = n;
	}
	return l->gather;
}

/* While the tree grows in, the instances again in the growth's order, so that origami
 * leaves unfold by keyframes (render_instanced_grow.c); otherwise none. v: their data in
 * instance order. A failure leaves them scaling in like the others. */
static int bind_growing(struct render *r, const struct app *app, const struct live_vertex *v,
			size_t n)
{
	struct render_live *l = &r->live;
	struct live_vertex *sorted;
	int ret;

	l->grow_instances.ok = false;
	if (!l->frame.growing) {
		render_instanced_grow_drop(r);
		data_finish(&l->grow_instances);
		return 0;
	}
	ret = render_instanced_grow_order(r, &app->tree, v, r->uploaded_tinted);
	if (ret < 0)
		return ret;
	sorted = malloc(n * sizeof(*sorted) + 1);
	if (!sorted)
		return -ENOMEM;
	for (size_t i = 0; i < n; i++)
		sorted[i] = v[r->inst.grow_order[i]];
	ret = upload(r, &l->grow_instances, sorted, n, NULL, false);
	free(sorted);
	return ret;
}

/* Instanced leaves: a leaf's data per instance (its first vertex's, which all of its
 * vertices share but for the distance from the anchor, the shader's), and the loose
 * leaves' per vertex, in leaf order as leaf_instances lays them out. la: the merged
 * leaves' data, mk their marks. */
static int bind_instanced(struct render *r, const struct app *app, const struct live_attrs *la,
			  const struct tree_mesh_marks *mk)
{
	struct render_live *l = &r->live;
	const struct leaf_instances *li = &r->inst.li;
	size_t nloose = r->inst.nshapes ? li->loose.nvertices : la->n;
	struct live_vertex *v = gathered(l, (li->ninstanced > nloose ? li->ninstanced : nloose) + 1);
	size_t n = 0;
	int ret;

	if (!v)
		return -ENOMEM;
	for (size_t i = 0; i < li->ninstanced; i++) {
		size_t leaf = li->instances[i].leaf, first = mk->leaves[leaf].nvertices;

		if (leaf >= app->tree.nleaves || first >= mk->leaves[leaf + 1].nvertices)
			return -EINVAL; /* a leaf with no vertices has no instance */
		v[i] = la->v[first];
		v[i].leaf = 0.0f;
	}
	ret = upload(r, &l->instances, v, li->ninstanced, NULL, false);
	if (ret == 0)
		ret = bind_growing(r, app, v, li->ninstanced);
	/* nothing instanced: the loose mesh is the merged one */
	if (ret < 0 || r->inst.nshapes == 0)
		return ret < 0 ? ret : upload(r, &l->loose, la->v, la->n, &app->mesh.leaves,
					      !r->inst.loose.indexed);
	/* the instanced leaves' marks, then the others' parts in leaf order */
	for (size_t leaf = 0; leaf < app->tree.nleaves; leaf++)
		l->inst_mark[leaf] = false;
	for (size_t i = 0; i < li->ninstanced; i++)
		l->inst_mark[li->instances[i].leaf] = true;
	for (size_t leaf = 0; leaf < app->tree.nleaves; leaf++) {
		size_t from = mk->leaves[leaf].nvertices, to = mk->leaves[leaf + 1].nvertices;

		if (l->inst_mark[leaf])
			continue;
		if (to - from > nloose - n)
			return -EINVAL; /* the loose mesh is not these leaves' parts */
		memcpy(&v[n], &la->v[from], (to - from) * sizeof(*v));
		n += to - from;
	}
	if (n != nloose)
		return -EINVAL;
	return upload(r, &l->loose, v, n, &li->loose, !r->inst.loose.indexed);
}

/* The bark's and the leaves' data, of the meshes uploaded (mesh_serial's). */
static int bind_tree(struct render *r, const struct app *app, const struct live_skeleton *sk)
{
	struct render_live *l = &r->live;
	const struct tree_mesh_marks *mk = marks_known(app) ? &app->mesh_marks : NULL;
	int ret;

	l->tree_ok = false;
	ret = live_attrs_bind_bark(&l->attrs, sk, &app->tree, &app->mesh.bark, mk);
	if (ret == 0)
		ret = upload(r, &l->bark, l->attrs.v, l->attrs.n, &app->mesh.bark, !r->bark.indexed);
	if (ret == 0)
		ret = live_attrs_bind_leaves(&l->attrs, sk, &app->tree, &app->mesh.leaves, mk);
	if (ret == 0 && r->uploaded_instanced) {
		bool *m = mk ? realloc(l->inst_mark, (app->tree.nleaves + 1) * sizeof(*m)) : NULL;

		if (m)
			l->inst_mark = m;
		ret = !mk ? -EINVAL : !m ? -ENOMEM : bind_instanced(r, app, &l->attrs, mk);
	} else if (ret == 0) {
		ret = upload(r, &l->leaves, l->attrs.v, l->attrs.n, &app->mesh.leaves,
			     !r->leaves.indexed);
	}
	l->tree_ok = ret == 0;
	return ret;
}

/* Any other mesh on the tree (the wood's bark, a vine) to its nearest bark. */
static int bind_nearest(struct render *r, struct render_live_data *d, const struct app *app,
			const struct live_skeleton *sk, const struct mesh *m, bool expand)
{
	int ret = live_attrs_bind_nearest(&r->live.attrs, sk, &app->tree, m);

	d->ok = false;
	return ret < 0 ? ret : upload(r, d, r->live.attrs.v, r->live.attrs.n, m, expand);
}

static int bind_vines(struct render *r, const struct app *app, const struct live_skeleton *sk)
{
	const struct mesh *m[4] = { &app->vines_mesh.bark, &app->vines_mesh.leaves,
				    &app->growth.mesh.bark, &app->growth.mesh.leaves };
	const struct render_mesh *rm[4] = { &r->vine_stems, &r->vine_leaves, &r->grow_stems,
					    &r->grow_leaves };
	struct render_live *l = &r->live;
	int ret = 0;

	l->vines_ok = false;
	for (int i = 0; i < 4 && ret == 0; i++)
		ret = bind_nearest(r, &l->vine[i], app, sk, m[i], !rm[i]->indexed);
	l->vines_ok = ret == 0;
	l->vines_of = r->vines_serial;
	l->vines_mesh_of = r->mesh_serial;
	return ret;
}

bool render_live_begin(struct render *r, const struct app *app, uint64_t now_us)
{
	struct render_live *l = &r->live;
	const struct live_skeleton *sk = app_live_skeleton(app);
	const struct mesh *wood = r->wood_src;
	double s;

	l->on = false;
	l->bytes = 0;
	if (!l->merged.tree.program || !sk || !r->uploaded ||
	    !app_live_at(app, now_us, &l->frame) ||
	    (r->uploaded_instanced && !r->inst.live.tree.program))
		return false;
	s = sk->d_max > 1e-6 ? sk->d_max : 1e-6;
	l->wscale[0] = 1.0f;
	l->wscale[1] = l->wscale[2] = l->wscale[3] = (float)s;
	/* a growth began on meshes bound still: bound again, in its order too */
	if (l->frame.growing && r->uploaded_instanced && !r->inst.grow_ok)
		l->tree_ok = false;
	/* the meshes went up since the data was bound: bind it again (the same skeleton as
	 * the meshes: both are of mesh_serial) */
	if (!l->tree_ok && bind_tree(r, app, sk) < 0)
		return false;
	if (wood && wood->nvertices && (!l->wood_ok || l->wood_of != wood ||
					l->wood_serial != r->wood_serial)) {
		l->wood_of = wood;
		l->wood_serial = r->wood_serial;
		l->wood_ok = bind_nearest(r, &l->wood, app, sk, wood, !r->wood.indexed) == 0;
		if (!l->wood_ok)
			return false;
	}
	l->on = true;
	return true;
}

bool render_live_vines(struct render *r, const struct app *app)
{
	struct render_live *l = &r->live;
	const struct live_skeleton *sk = app_live_skeleton(app);

	if (!l->on)
		return true;
	if (l->frame.growing)
		return false; /* the vines climb after the tree has grown in */
	if ((!l->vines_ok || l->vines_of != r->vines_serial || l->vines_mesh_of != r->mesh_serial) &&
	    bind_vines(r, app, sk) < 0)
		l->vines_ok = false;
	return true;
}

void render_live_uniforms(const struct render *r, const struct render_live_program *p)
{
	render_live_frame_uniforms(p, &r->live.frame, r->live.wscale);
}

void render_live_frame_uniforms(const struct render_live_program *p, const struct app_live_frame *f,
				const float wscale[4])
{
	const struct live_wind_frame *w = &f->wind;
	float dir[9];

	glUniform3f(p->along, (float)(w->amp0 * w->along.x), (float)(w->amp0 * w->along.y),
		    (float)(w->amp0 * w->along.z));
	glUniform3f(p->across, (float)(LIVE_WIND_FIGURE_EIGHT * w->amp0 * w->across.x),
		    (float)(LIVE_WIND_FIGURE_EIGHT * w->amp0 * w->across.y),
		    (float)(LIVE_WIND_FIGURE_EIGHT * w->amp0 * w->across.z));
	glUniform2f(p->sway, (float)w->sway_along, (float)w->sway_across);
	for (int k = 1; k < LIVE_BANDS; k++) {
		dir[3 * (k - 1)] = (float)(w->amp[k] * w->dir[k].x);
		dir[3 * (k - 1) + 1] = (float)(w->amp[k] * w->dir[k].y);
		dir[3 * (k - 1) + 2] = (float)(w->amp[k] * w->dir[k].z);
	}
	glUniform3fv(p->dir, 3, dir);
	glUniform4f(p->theta, (float)w->theta[1], (float)w->theta[2], (float)w->theta[3],
		    (float)w->theta_leaf);
	glUniform1f(p->amp_leaf, (float)w->amp_leaf);
	glUniform1f(p->front, (float)f->front);
	glUniform1f(p->swell, (float)f->swell);
	glUniform4fv(p->wscale, 1, wscale);
}

void render_live_use(struct render *r, const struct render_live_program *p, const float mvp[16],
		     const float light[3])
{
	glUseProgram(p->tree.program);
	glUniformMatrix4fv(p->tree.mvp, 1, GL_FALSE, mvp);
	glUniform3fv(p->tree.light, 1, light);
	render_live_uniforms(r, p);
	r->lit = p->tree;
}

void render_live_pointers(GLuint vbo, GLuint base, size_t first)
{
	const char *at = (const char *)(uintptr_t)(first * RENDER_LIVE_STRIDE);

	glBindBuffer(GL_ARRAY_BUFFER, vbo);
	glVertexAttribPointer(base, 4, GL_FLOAT, GL_FALSE, RENDER_LIVE_STRIDE, at);
	glVertexAttribPointer(base + 1, 4, GL_UNSIGNED_SHORT, GL_TRUE, RENDER_LIVE_STRIDE, at + 16);
	/* not normalised: the shader takes the phase bytes as 0..255 and the flutter bytes as
	 * -127..127 (a normalised signed byte would be (2c + 1) / 255 on GLES 2) */
	glVertexAttribPointer(base + 2, 4, GL_UNSIGNED_BYTE, GL_FALSE, RENDER_LIVE_STRIDE, at + 24);
	glVertexAttribPointer(base + 3, 4, GL_BYTE, GL_FALSE, RENDER_LIVE_STRIDE, at + 28);
}

void render_live_draw(struct render *r, const struct render_mesh *rm,
		      const struct render_live_data *d, bool tinted)
{
	if (!r->live.on) {
		if (tinted)
			render_mesh_draw_tinted(r, rm);
		else
			render_mesh_draw(r, rm);
		return;
	}
	if (rm->count == 0 || !d->ok)
		return;
	render_live_pointers(d->vbo, ATTR_LIVE, 0);
	for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++)
		glEnableVertexAttribArray(ATTR_LIVE + i);
	if (tinted)
		render_mesh_draw_tinted(r, rm);
	else
		render_mesh_draw(r, rm);
	/* the other programs do not read them */
	for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++)
		glDisableVertexAttribArray(ATTR_LIVE + i);
}
