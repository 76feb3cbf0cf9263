/* SPDX-License-Identifier: MIT */
/*
 * The screen's colours of the seasons (ui/leaf_tint.c), without GL: summer's palette green
 * becomes the screen's green, the curve keeps colours in 0..1 and in order, and every
 * leaf has one colour whichever way it is drawn: merged (a colour a vertex of the tree's
 * leaves mesh), instanced (a colour an instance) or loose (a colour a vertex of the
 * leaves no instanced shape draws).
 */
#include <string.h>

#include "leaf_colors.h"
#include "leaf_tint.h"
#include "scene.h"
#include "test.h"

static void test_map(void)
{
	static const float screen[3] = { LEAF_TINT_SUMMER_RGB };
	const struct season_rgb *summer, *autumn;
	float out[3], prev[3] = { -1.0f, -1.0f, -1.0f };

	CHECK_INT(season_palette(SEASON_SUMMER, &summer), 1);
	leaf_tint_map(summer[0], out);
	for (int k = 0; k < 3; k++)
		CHECK_NEAR(out[k], screen[k], 1e-6);
	/* summer is the very floats the screen always drew */
	CHECK(leaf_tint_uniform(SEASON_SUMMER, out));
	CHECK(memcmp(out, screen, sizeof(out)) == 0);
	CHECK(!leaf_tint_uniform(SEASON_WINTER, out));
	CHECK(leaf_tint_uniform(SEASON_AUTUMN, out));
	CHECK(season_palette(SEASON_AUTUMN, &autumn) > 1);
	{
		float first[3];

		leaf_tint_map(autumn[0], first);
		CHECK(memcmp(out, first, sizeof(out)) == 0);
	}
	/* the ends stay, out of range is clamped, and the order of shades is kept */
	leaf_tint_map((struct season_rgb){ 0.0f, 0.0f, 0.0f }, out);
	CHECK(out[0] == 0.0f && out[1] == 0.0f && out[2] == 0.0f);
	leaf_tint_map((struct season_rgb){ 1.0f, 1.0f, 1.0f }, out);
	CHECK_NEAR(out[0] + out[1] + out[2], 3.0, 1e-6);
	leaf_tint_map((struct season_rgb){ 2.0f, -1.0f, 1.5f }, out);
	CHECK_NEAR(out[0], 1.0, 1e-6);
	CHECK(out[1] == 0.0f);
	for (int i = 0; i <= 100; i++) {
		float x = (float)i / 100.0f;

		leaf_tint_map((struct season_rgb){ x, x, x }, out);
		for (int k = 0; k < 3; k++) {
			CHECK(out[k] >= x - 1e-6f); /* lighter, never darker */
			CHECK(out[k] > prev[k]);
			prev[k] = out[k];
		}
	}
}

/* The screen's colour of leaf l in the tree's season. */
static void leaf_colour(const struct tree *t, size_t l, float out[3])
{
	const struct season_rgb *c;

	CHECK(season_palette(t->season, &c) > 0);
	leaf_tint_map(c[season_leaf_color(t->season, &t->leaves[l])], out);
}

static void check_vertices(const float *rgb, size_t from, size_t to, const float c[3])
{
	for (size_t v = from; v < to; v++)
		CHECK(memcmp(rgb + 3 * v, c, 3 * sizeof(float)) == 0);
}

static void test_leaves(enum season season)
{
	struct app app;
	struct leaf_instances li;
	const struct tree_mesh_marks *mk = &app.mesh_marks;
	float *merged, *inst, *loose, c[3];
	size_t at = 0, shades = 0;
	float seen[SEASON_MAX_COLORS][3];

	scene_leafy(&app, 640, 400, (struct camera){ 0.0f, 0.0f }, true);
	app.tree.season = season;
	leaf_instances_init(&li);
	CHECK_INT(leaf_instances_build(&li, &app.tree), 0);
	CHECK(li.ninstanced_shapes > 0 && li.ninstanced < li.ninstances);
	CHECK_INT(mk->nleaves, app.tree.nleaves + 1);
	merged = malloc(3 * sizeof(float) * app.mesh.leaves.nvertices);
	inst = malloc(3 * sizeof(float) * li.ninstanced);
	loose = malloc(3 * sizeof(float) * li.loose.nvertices);
	CHECK(merged && inst && loose);

	CHECK(leaf_tint_vertices(&app.tree, mk, app.mesh.leaves.nvertices, merged));
	leaf_tint_instances(&app.tree, &li, inst);
	CHECK_INT(leaf_tint_loose(&app.tree, mk, &li, loose), 0);
	/* merged: each leaf's part of the mesh in its colour */
	for (size_t l = 0; l < app.tree.nleaves; l++) {
		bool known = false;

		leaf_colour(&app.tree, l, c);
		check_vertices(merged, mk->leaves[l].nvertices, mk->leaves[l + 1].nvertices, c);
		for (size_t k = 0; k < shades; k++)
			known = known || memcmp(seen[k], c, sizeof(c)) == 0;
		if (!known && shades < SEASON_MAX_COLORS)
			memcpy(seen[shades++], c, sizeof(c));
	}
	/* leaves have shades of their own */
	CHECK(shades >= 2);
	/* instanced: each instance its leaf's */
	for (size_t i = 0; i < li.ninstanced; i++) {
		leaf_colour(&app.tree, li.instances[i].leaf, c);
		check_vertices(inst, i, i + 1, c);
	}
	/* loose: the leaves of no instanced shape, in order, as many vertices as merged */
	for (size_t l = 0; l < app.tree.nleaves; l++) {
		size_t n = mk->leaves[l + 1].nvertices - mk->leaves[l].nvertices;
		bool instanced = false;

		for (size_t i = 0; i < li.ninstanced; i++)
			instanced = instanced || li.instances[i].leaf == l;
		if (instanced)
			continue;
		leaf_colour(&app.tree, l, c);
		check_vertices(loose, at, at + n, c);
		at += n;
	}
	CHECK_INT(at, li.loose.nvertices);

	/* marks that do not describe the meshes: every vertex the first colour */
	{
		const struct season_rgb *pal;
		struct tree_mesh_marks none;

		tree_mesh_marks_init(&none);
		CHECK(season_palette(season, &pal) > 1);
		leaf_tint_map(pal[0], c);
		CHECK_INT(leaf_tint_loose(&app.tree, &none, &li, loose), 0);
		check_vertices(loose, 0, li.loose.nvertices, c);
		CHECK(leaf_tint_vertices(&app.tree, &none, app.mesh.leaves.nvertices, merged));
		check_vertices(merged, 0, app.mesh.leaves.nvertices, c);
	}
	/* winter: no colours, nothing painted */
	app.tree.season = SEASON_WINTER;
	CHECK(!leaf_tint_vertices(&app.tree, mk, app.mesh.leaves.nvertices, merged));

	free(merged);
	free(inst);
	free(loose);
	leaf_instances_finish(&li);
	scene_leafy_finish(&app);
}

int main(void)
{
	test_map();
	test_leaves(SEASON_AUTUMN);
	test_leaves(SEASON_SPRING);
	return 0;
}
