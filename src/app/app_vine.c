/* SPDX-License-Identifier: MIT */
/*
 * Twining vines on the visitor's tree (issue 16, seed 004; docs/vines.md): a vine op grows
 * its vine to the end on the tree's bark as it stands, and the tree keeps it. The model
 * is the grown vine all along (exports, the skeleton and undo never see growth). The vine
 * op's row of app_ops.c applies here; app_vine_hook starts the growth after an op.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "app_private.h"
#include "mesh.h"
#include "sketch.h"
#include "vine.h"
#include "vine_support.h"

/* w's triangles after m's. 0 or -ENOMEM. */
static int append_wood(struct mesh *m, const struct mesh *w)
{
	size_t v0 = m->nvertices;
	int ret = mesh_reserve(m, w->nvertices, w->nindices);

	if (ret < 0)
		return ret;
	memcpy(&m->positions[3 * v0], w->positions, 3 * w->nvertices * sizeof(float));
	memcpy(&m->normals[3 * v0], w->normals, 3 * w->nvertices * sizeof(float));
	for (size_t i = 0; i < w->nindices; i++)
		m->indices[m->nindices + i] = w->indices[i] + (uint32_t)v0;
	m->nvertices += w->nvertices;
	m->nindices += w->nindices;
	return 0;
}

int app_vine_support(const struct tree *t, struct vine_support **out)
{
	struct tree_mesh bark;
	int ret;

	*out = NULL;
	tree_mesh_init(&bark);
	/* the bark alone: a vine twines round wood, not leaves; a grown tree's trunk and
	 * limbs are its wood's bark (tree_mesh_append leaves their tubes out) */
	ret = tree_mesh_append(&bark, t, 0, t->nleaves);
	if (ret == 0 && t->wood && t->wood->bark.nvertices)
		ret = append_wood(&bark.bark, &t->wood->bark);
	if (ret == 0)
		ret = vine_support_create(bark.bark.positions, bark.bark.nvertices, bark.bark.indices,
					  bark.bark.nindices / 3, out);
	tree_mesh_finish(&bark);
	return ret;
}

/* The vine op on t, on bark, the index of t's bark (NULL: made here). */
static int vine_apply(struct tree *t, const struct doc_op *op, const struct vine_support *bark)
{
	struct vine_support *s = NULL;
	struct vine v;
	int ret = 0;

	/* a drawing's parameters were checked when read; a full tree takes no more */
	if (!op->vine || t->nvines >= TREE_MAX_VINES || t->nbranches == 0)
		return SKETCH_GREW;
	if (!bark)
		ret = app_vine_support(t, &s);
	if (ret == -EINVAL)
		return SKETCH_GREW; /* no bark to climb: nothing grows */
	if (ret < 0)
		return ret;
	vine_init(&v, op->vine, vec3(op->plant[0], op->plant[1], op->plant[2]));
	ret = vine_grow(&v, bark ? bark : s, INFINITY);
	vine_support_destroy(s);
	if (ret == 0)
		ret = vine_attach(t, &v);
	vine_finish(&v);
	if (ret == -ENOSPC)
		return SKETCH_GREW;
	return ret < 0 ? ret : SKETCH_CHANGED;
}

int app_vine_apply(struct app *app, const struct doc_op *op)
{
	/* the tap's index of this very tree, if the op is the tap's */
	return vine_apply(&app->tree, op, op == app->bark_index_op ? app->bark_index : NULL);
}

/* The settled vines' meshes, the growing one left out. 0 or -ENOMEM (empty then). */
static int vines_mesh_build(struct app *app)
{
	struct tree_mesh *m = &app->vines_mesh;
	size_t n = app->tree.nvines - (app->growth.on && app->tree.nvines ? 1 : 0);
	int ret = 0;

	mesh_clear(&m->bark);
	mesh_clear(&m->leaves);
	for (size_t i = 0; i < n && ret == 0; i++)
		ret = vine_mesh_append(&app->tree.vines[i], &m->bark, &m->leaves);
	app->vines_mesh_of = app->mesh_serial;
	app->vines_mesh_growing = app->growth.on;
	app->vines_serial++;
	if (ret < 0) {
		mesh_clear(&m->bark);
		mesh_clear(&m->leaves);
	}
	return ret;
}

int app_vines_refresh(struct app *app)
{
	if (app->vines_mesh_of == app->mesh_serial && app->vines_mesh_growing == app->growth.on)
		return 0;
	return vines_mesh_build(app);
}

void app_vine_growth_clear(struct app *app)
{
	struct app_vine_growth *g = &app->growth;

	if (!g->on)
		return;
	g->on = false;
	vine_finish(&g->v);
	vine_support_destroy(g->support);
	g->support = NULL;
	mesh_clear(&g->mesh.bark);
	mesh_clear(&g->mesh.leaves);
	app->vines_serial++;
}

int app_vine_growth_start(struct app *app, const struct doc_op *op)
{
	struct app_vine_growth *g = &app->growth;
	int ret;

	app_vine_growth_clear(app); /* the one before shows grown */
	/* the bark it grew on: the tree's, which a vine does not change; the tap's index */
	if (app->bark_index && op == app->bark_index_op) {
		g->support = app->bark_index;
		app->bark_index = NULL;
		app->bark_index_op = NULL;
	} else {
		ret = app_vine_support(&app->tree, &g->support);
		if (ret < 0)
			return ret == -EINVAL ? 0 : ret;
	}
	vine_init(&g->v, op->vine, vec3(op->plant[0], op->plant[1], op->plant[2]));
	g->start_us = op->time_us;
	g->on = true;
	return app_vines_refresh(app);
}

/* A vine the op planted starts growing on screen; one it took away (a new tree) took the
 * growing with it. The vines' meshes follow the tree's. */
static int vine_after_op(struct app *app, const struct doc_op *op,
			 const struct app_op_before *before, int meshed)
{
	int ret = 0, r2;

	if (meshed == 0 && app->tree.nvines > before->nvines)
		ret = app_vine_growth_start(app, op);
	else if (meshed == 0 && app->tree.nvines < before->nvines)
		app_vine_growth_clear(app);
	r2 = app_vines_refresh(app);
	return ret < 0 ? ret : r2;
}

const struct app_op_hook app_vine_hook = {
	.name = "vine",
	.after_op = vine_after_op,
	.clear = app_vine_growth_clear,
};

bool app_vines_advance(struct app *app, uint64_t now_us)
{
	struct app_vine_growth *g = &app->growth;
	size_t points;
	double until;
	int ret;

	/* a loaded drawing's vine climbs once its tree has grown in (app_live.c) */
	if (app_live_vines(app, now_us) < 0 || app_vines_refresh(app) < 0)
		app->failed = app->failed ? app->failed : -ENOMEM;
	if (!g->on)
		return false;
	points = g->v.points;
	until = INFINITY;
	if (now_us != UINT64_MAX) {
		double s = now_us > g->start_us ? (double)(now_us - g->start_us) * 1e-6 : 0.0;

		until = s * APP_VINE_POINTS_PER_S * g->v.p.step_time;
	}
	ret = vine_grow(&g->v, g->support, until);
	if (ret < 0 || vine_done(&g->v)) {
		app_vine_growth_clear(app);
		(void)app_vines_refresh(app);
		return false;
	}
	if (g->v.points != points || g->mesh.bark.nvertices == 0) {
		mesh_clear(&g->mesh.bark);
		mesh_clear(&g->mesh.leaves);
		if (vine_mesh_append(&g->v, &g->mesh.bark, &g->mesh.leaves) < 0) {
			app_vine_growth_clear(app);
			(void)app_vines_refresh(app);
			return false;
		}
		app->vines_serial++;
	}
	return true;
}
