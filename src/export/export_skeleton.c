/* SPDX-License-Identifier: MIT */
#include "export.h"
#include "export_wind.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "json_out.h"
#include "ori_kinds.h"
#include "vine_json.h"
#include "wood.h"

#define SKELETON_FORMAT "edaha-skeleton"

static struct json_object *jpoints(const struct vec3 *p, size_t n)
{
	struct json_object *arr = json_object_new_array();

	for (size_t i = 0; i < n; i++) {
		struct json_object *xyz = json_object_new_array_ext(3);

		xyz = json_out_push(xyz, json_out_num(p[i].x));
		xyz = json_out_push(xyz, json_out_num(p[i].y));
		xyz = json_out_push(xyz, json_out_num(p[i].z));
		arr = json_out_push(arr, xyz);
	}
	return arr;
}

static struct json_object *jbranch(const struct branch *b)
{
	struct json_object *o = json_object_new_object();
	struct json_object *radii = json_object_new_array();

	for (size_t i = 0; i < b->npoints; i++)
		radii = json_out_push(radii, json_out_num(b->radii[i]));
	o = json_out_set(o, "id", json_object_new_int(b->id));
	o = json_out_set(o, "parent", json_object_new_int(b->parent));
	o = json_out_set(o, "generation", json_object_new_int(b->generation));
	o = json_out_set(o, "origin", json_object_new_string(origin_name(b->origin)));
	if (b->origin == ORIGIN_GENERATE)
		o = json_out_set(o, "level", json_object_new_int(b->level));
	o = json_out_set(o, "parent_t", json_out_num(b->parent_t));
	o = json_out_set(o, "points", jpoints(b->points, b->npoints));
	return json_out_set(o, "radii", radii);
}

static struct json_object *jleaf(const struct leaf *l)
{
	struct json_object *o = json_object_new_object();

	o = json_out_set(o, "id", json_object_new_int(l->id));
	o = json_out_set(o, "branch", json_object_new_int(l->branch));
	o = json_out_set(o, "branch_t", json_out_num(l->branch_t));
	o = json_out_set(o, "origin", json_object_new_string(origin_name(l->origin)));
	/* origami leaves only, so a drawn leaf's bytes are what they were */
	if (ori_kind_name(l->kind) && l->kind >= 0)
		o = json_out_set(o, "kind", json_object_new_string(ori_kind_name(l->kind)));
	return json_out_set(o, "points", jpoints(l->points, l->npoints));
}

/* The tree's wood (docs/skeleton-format.md): its presses and grid, and which branches it
 * holds (their bark is the wood's in the meshes). */
static struct json_object *jwood(const struct tree *t)
{
	const struct wood *w = t->wood;
	const struct wood_grid *g = &w->g;
	struct json_object *o = json_object_new_object();
	struct json_object *grid = json_object_new_array_ext(3);
	struct json_object *origin = json_object_new_array_ext(3);
	struct json_object *ids = json_object_new_array();

	grid = json_out_push(grid, json_object_new_int(g->nx));
	grid = json_out_push(grid, json_object_new_int(g->ny));
	grid = json_out_push(grid, json_object_new_int(g->nz));
	origin = json_out_push(origin, json_out_num(g->origin.x));
	origin = json_out_push(origin, json_out_num(g->origin.y));
	origin = json_out_push(origin, json_out_num(g->origin.z));
	for (size_t i = 0; i < t->nbranches; i++)
		if (tree_branch_in_wood(t, i))
			ids = json_out_push(ids, json_object_new_int(t->branches[i].id));
	o = json_out_set(o, "presses", json_object_new_int(w->presses));
	o = json_out_set(o, "mode", json_object_new_string(w->p.mode == WOOD_CONIFER ? "conifer"
										   : "broadleaf"));
	o = json_out_set(o, "grid", grid);
	o = json_out_set(o, "voxel", json_out_num(g->h));
	o = json_out_set(o, "origin", origin);
	return json_out_set(o, "branches", ids);
}

/* The skeleton as a json-c object, for the writers below; NULL without memory. */
static struct json_object *skeleton_object(const struct tree *t)
{
	struct json_object *root = json_object_new_object();
	struct json_object *view = json_object_new_array_ext(3);
	struct json_object *branches = json_object_new_array();
	struct json_object *leaves = json_object_new_array();

	/* The front view looks along -z (src/core/screen.h). */
	view = json_out_push(view, json_object_new_int(0));
	view = json_out_push(view, json_object_new_int(0));
	view = json_out_push(view, json_object_new_int(-1));
	for (size_t i = 0; i < t->nbranches; i++)
		branches = json_out_push(branches, jbranch(&t->branches[i]));
	for (size_t i = 0; i < t->nleaves; i++)
		leaves = json_out_push(leaves, jleaf(&t->leaves[i]));

	root = json_out_set(root, "format", json_object_new_string(SKELETON_FORMAT));
	root = json_out_set(root, "version", json_object_new_int(SKELETON_VERSION));
	root = json_out_set(root, "up", json_object_new_string("y"));
	root = json_out_set(root, "units", json_object_new_string("m"));
	root = json_out_set(root, "view", view);
	root = json_out_set(root, "season", json_object_new_string(season_name(t->season)));
	root = json_out_set(root, "branches", branches);
	root = json_out_set(root, "leaves", leaves);
	/* absent without wood: a tree never grown has the keys it always had */
	if (t->wood)
		root = json_out_set(root, "wood", jwood(t));
	/* absent without vines: a tree without them has the keys it always had */
	if (t->nvines > 0)
		root = vine_json_set(root, t->vines, t->nvines);
	return root;
}

/* One motion of the wind: its harmonic, frequency and amplitude. */
static struct json_object *jmotion(const struct live_wind *w, const char *name, int harmonic,
				   double amplitude)
{
	struct json_object *o = json_object_new_object();

	o = json_out_set(o, "name", json_object_new_string(name));
	o = json_out_set(o, "harmonic", json_object_new_int(harmonic));
	o = json_out_set(o, "hz", json_out_num(live_wind_hz(w, harmonic)));
	return json_out_set(o, "amplitude", json_out_num(amplitude));
}

/* The wind model.glb's animation carries (docs/skeleton-format.md, "Wind"). */
static struct json_object *jwind(const struct live_wind *w, uint64_t seed)
{
	static const char *const bands[LIVE_BANDS] = { "trunk", "limbs", "branches", "twigs" };
	struct json_object *o = json_object_new_object();
	struct json_object *motions = json_object_new_array_ext(LIVE_BANDS + 2);

	motions = json_out_push(motions, jmotion(w, "trunk", w->harmonic[0], w->amp0));
	motions = json_out_push(motions, jmotion(w, "trunk-across", 2 * w->harmonic[0],
						 LIVE_WIND_FIGURE_EIGHT * w->amp0));
	for (int k = 1; k < LIVE_BANDS; k++)
		motions = json_out_push(motions, jmotion(w, bands[k], w->harmonic[k], w->amp[k]));
	motions = json_out_push(motions,
				jmotion(w, "flutter", w->harmonic[LIVE_BANDS], w->amp_leaf));
	o = json_out_set(o, "strength", json_out_num(w->strength));
	o = json_out_set(o, "angle", json_out_num(w->angle * 180.0 / VEC_PI));
	/* exactly: a seed past 2^53 would round as a double */
	o = json_out_set(o, "seed", json_object_new_uint64(seed));
	o = json_out_set(o, "height", json_out_num(w->height));
	o = json_out_set(o, "period", json_out_num(w->period));
	o = json_out_set(o, "loop", json_out_num(w->loop));
	return json_out_set(o, "motions", motions);
}

int export_skeleton_wind(const struct tree *t, const struct export_wind *wind, struct buf *out)
{
	struct export_wind_tree wt;
	struct json_object *root;
	int r;

	if (!wind)
		return export_skeleton(t, out);
	r = export_wind_tree_init(&wt, t, wind, 0.0);
	if (r == -ENODATA) {
		export_wind_tree_finish(&wt);
		return export_skeleton(t, out);
	}
	/* last, after "vines": the keys before it are export_skeleton's */
	root = r == 0 ? json_out_set(skeleton_object(t), "wind", jwind(&wt.w, wind->seed)) : NULL;
	export_wind_tree_finish(&wt);
	if (r < 0)
		return r;
	if (!root)
		return -ENOMEM;
	r = json_out_append(root, "\n", out);
	json_object_put(root);
	return r;
}

int export_skeleton(const struct tree *t, struct buf *out)
{
	struct json_object *root = skeleton_object(t);
	int r;

	if (!root)
		return -ENOMEM;

	/* Compact: a big tree is hundreds of thousands of numbers; one per line would bloat it. */
	r = json_out_append(root, "\n", out);
	json_object_put(root);
	return r;
}

int export_skeleton_vines(const struct tree *t, const struct vine *vines, size_t nvines,
			  struct buf *out)
{
	/* json-c replaces a key's value in place: t's own vines, if any, give way */
	struct json_object *root = vine_json_set(skeleton_object(t), vines, nvines);
	int r;

	if (!root)
		return -ENOMEM;
	r = json_out_append(root, "\n", out);
	json_object_put(root);
	return r;
}
