/* SPDX-License-Identifier: MIT */
/*
 * Today's forest on the screen (ui/render_forest.c, docs/forest.md "On the screen"), drawn
 * headless on seeded random forests (1 to 8 random trees of 1 to 150 branches, 0 to 12
 * leaves each, 2 to 15 m, and the functional trees' presets, each a part at its share of
 * 300,000 triangles, in a breeze), at random moments of the camera's round:
 *
 * - the newest tree grows in (app->forest_joined_us): a microsecond before its growth
 *   ends the frame is the settled one byte for byte (the frame with nothing growing),
 *   and from its end on it is; at a fifth, half and four fifths of its growth the newest
 *   tree's pixels (those that differ from the other trees alone: the same scene cut
 *   before the newest tree's ranges) are fewer than at its end, while the other trees'
 *   (those the others alone show over the bare ground, seen as they are there) are not;
 *   at most 2 draw calls more while it grows, and a frame uploads nothing;
 * - the numbers at the feet (with the labels' font): built once a scene, however the
 *   camera travels, and again when the scene or the font changes; one draw call; every
 *   pixel they change (against the same frame with every foot moved behind the camera,
 *   where a number is hidden) lies within a card where the CPU's projection of its foot
 *   puts it, and every card on the forest's part of the screen changes some pixels;
 * - the kiosk draws frames while the forest shows, whatever the drawing
 *   (app_live_at(.., NULL)).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "egl_headless.h"
#include "font_file.h"
#include "forest.h"
#include "layout.h"
#include "live_trees.h"
#include "render.h"
#include "render_private.h"
#include "rng.h"
#include "test.h"
#include "text.h"

#define WIDTH 480
#define HEIGHT 300
#define MAXN 8

struct forest {
	struct tree trees[MAXN];
	struct forest_part parts[MAXN];
	size_t n;
	struct forest_scene scene;
};

struct shot {
	uint8_t *rgba;
	struct render_stats st;
};

static uint64_t serials = 1000; /* every scene the renderer sees, a serial of its own */

static void forest_random(struct forest *f, struct rng *r, int c)
{
	const struct forest_part *pp[MAXN];
	uint64_t numbers[MAXN];
	double widths[MAXN], xz[2 * MAXN], pos[3 * MAXN];
	size_t share[MAXN];

	f->n = 1 + (size_t)(rng_next(r) % MAXN);
	for (size_t i = 0; i < f->n; i++) {
		tree_init(&f->trees[i]);
		if (rng_next(r) % 5 == 0)
			live_trees_preset(&f->trees[i],
					  (enum gen_preset)(rng_next(r) % GEN_PRESET_COUNT));
		else
			live_trees_random(&f->trees[i], 1 + (int)(rng_next(r) % 150),
					  (int)(rng_next(r) % 13), 500 + (uint64_t)c * 16 + i,
					  rng_range(r, 2.0, 15.0));
		/* numbers of one to three digits, as a day's */
		numbers[i] = 1 + (uint64_t)(rng_next(r) % 120) * MAXN + i;
		widths[i] = forest_tree_crown_width(&f->trees[i]);
	}
	forest_lod_shares(widths, NULL, f->n, FOREST_TRIANGLES, share);
	CHECK(forest_layout(numbers, widths, f->n, 1000, xz) > 0);
	for (size_t i = 0; i < f->n; i++) {
		forest_part_init(&f->parts[i]);
		CHECK(forest_part_build(&f->parts[i], &f->trees[i], 7 + i, share[i], 0.35) == 0);
		pp[i] = &f->parts[i];
		pos[3 * i] = xz[2 * i];
		pos[3 * i + 1] = 0.0;
		pos[3 * i + 2] = xz[2 * i + 1];
	}
	forest_scene_init(&f->scene);
	CHECK(forest_scene_build(&f->scene, pp, numbers, pos, f->n) == 0);
	f->scene.serial = ++serials;
}

static void forest_finish(struct forest *f)
{
	for (size_t i = 0; i < f->n; i++) {
		forest_part_finish(&f->parts[i]);
		tree_finish(&f->trees[i]);
	}
	forest_scene_finish(&f->scene);
}

/* The scene cut before tree `keep`'s ranges: the trees before it alone, every vertex,
 * weight and camera as in s (ntrees at least 1, so the forest shows: its labels are not
 * looked at). keep 0: the bare ground. */
static struct forest_scene cut(const struct forest_scene *s, size_t keep)
{
	struct forest_scene c = *s;

	c.ntrees = keep ? keep : 1;
	c.mesh.bark.nindices = keep ? s->trees[keep].bark_indices[0] : 0;
	c.mesh.leaves.nindices = keep ? s->trees[keep].leaves_indices[0] : 0;
	c.serial = ++serials;
	return c;
}

static void draw(struct render *r, struct egl_headless *egl, struct app *app,
		 const struct forest_scene *s, uint64_t joined, uint64_t now, struct shot *out)
{
	app->forest = s;
	app->forest_joined_us = joined;
	CHECK(render_frame_at(r, app, now) == 0);
	render_get_stats(r, &out->st);
	CHECK(egl_headless_read_rgba(egl, out->rgba) == 0);
}

static bool pixel_same(const uint8_t *a, const uint8_t *b, size_t i)
{
	return memcmp(a + 4 * i, b + 4 * i, 4) == 0;
}

static size_t count_diff(const uint8_t *a, const uint8_t *b)
{
	size_t n = 0;

	for (size_t i = 0; i < (size_t)WIDTH * HEIGHT; i++)
		n += !pixel_same(a, b, i);
	return n;
}

/* The other trees' pixels in x: where they alone (o) show over the bare ground (g), and
 * x shows them as they are there. */
static size_t count_others(const uint8_t *x, const uint8_t *o, const uint8_t *g)
{
	size_t n = 0;

	for (size_t i = 0; i < (size_t)WIDTH * HEIGHT; i++)
		n += !pixel_same(o, g, i) && pixel_same(x, o, i);
	return n;
}

struct growth_stats {
	int forests, moments;
	double least_newest;    /* the largest fraction of its end's pixels a moment had */
	double least_others;    /* the others' pixels while it grows against at its end */
	size_t end_pixels;      /* pixels the newest tree covers at its end, all forests */
	unsigned most_draws, most_draws_growing;
};

static void check_growth(struct render *r, struct egl_headless *egl, struct app *app,
			 struct forest *f, struct rng *rg, struct shot sh[5],
			 struct growth_stats *gs)
{
	const struct forest_scene *s = &f->scene;
	const struct live_grow *g = &s->trees[s->ntrees - 1].grow;
	uint64_t dur = (uint64_t)llround(g->duration * 1e6); /* within half a microsecond */
	uint64_t now = 20000000 + rng_next(rg) % 120000000;
	struct forest_scene others = cut(s, s->ntrees - 1), ground = cut(s, 0);
	/* moments while a good part of the tree is not drawn yet: the front at 0.07, 0.24,
	 * 0.48 and 0.73 of D_max (ease(u) 1.12). It passes D_max at 0.79 of the growth;
	 * after, only the tips swell, which may take a pixel more here and a pixel less
	 * there, and a small tree's last twigs take none */
	static const double at[] = { 0.15, 0.3, 0.45, 0.6 };
	size_t newest_end, others_end;

	CHECK(g->duration >= LIVE_GROW_MIN_S && g->duration <= LIVE_GROW_MAX_S);
	draw(r, egl, app, &ground, 0, now, &sh[3]);
	draw(r, egl, app, &others, 0, now, &sh[2]);
	/* settled: nothing grows (0), and the same a microsecond past the growth */
	draw(r, egl, app, s, 0, now, &sh[0]);
	draw(r, egl, app, s, now - dur - 1, now, &sh[1]);
	CHECK(memcmp(sh[0].rgba, sh[1].rgba, (size_t)WIDTH * HEIGHT * 4) == 0);
	CHECK(sh[1].st.draw_calls == sh[0].st.draw_calls && sh[1].st.uploads == 0);
	/* a microsecond before its end: drawn growing (apart), the same bytes */
	draw(r, egl, app, s, now - (dur - 1), now, &sh[1]);
	CHECK(memcmp(sh[0].rgba, sh[1].rgba, (size_t)WIDTH * HEIGHT * 4) == 0);
	CHECK(sh[1].st.draw_calls <= sh[0].st.draw_calls + 2 && sh[1].st.uploads == 0);
	gs->most_draws = sh[0].st.draw_calls > gs->most_draws ? sh[0].st.draw_calls : gs->most_draws;
	gs->most_draws_growing = sh[1].st.draw_calls > gs->most_draws_growing
					 ? sh[1].st.draw_calls
					 : gs->most_draws_growing;
	newest_end = count_diff(sh[0].rgba, sh[2].rgba);
	others_end = count_others(sh[0].rgba, sh[2].rgba, sh[3].rgba);
	CHECK(newest_end > 0);
	gs->end_pixels += newest_end;
	for (size_t k = 0; k < sizeof(at) / sizeof(*at); k++) {
		uint64_t age = (uint64_t)llround(at[k] * (double)dur);
		size_t newest, oth;

		draw(r, egl, app, s, now - age, now, &sh[4]);
		CHECK(sh[4].st.uploads == 0);
		newest = count_diff(sh[4].rgba, sh[2].rgba);
		oth = count_others(sh[4].rgba, sh[2].rgba, sh[3].rgba);
		if (newest >= newest_end || oth < others_end)
			fprintf(stderr, "forest %d, %zu trees, at %.2f of %.2f s: the newest %zu pixels "
				"(%zu at its end), the others %zu (%zu)\n", gs->forests, s->ntrees,
				at[k], g->duration, newest, newest_end, oth, others_end);
		CHECK(newest < newest_end);
		CHECK(oth >= others_end);
		gs->least_newest = fmax(gs->least_newest, (double)newest / (double)newest_end);
		if (others_end)
			gs->least_others = fmin(gs->least_others, (double)oth / (double)others_end);
		gs->moments++;
	}
	gs->forests++;
}

/* Where the CPU puts tree t's card: the foot through mvp (in double), then the card's
 * box as the batch lays it out; px the numbers' size. */
static void card_box(const float mvp[16], const struct forest_scene_tree *t, struct font *font,
		     int px, double box[4])
{
	double c[4];
	char num[24];
	struct text_extent e;
	double x, y;

	for (int i = 0; i < 4; i++)
		c[i] = mvp[i] * t->position[0] + mvp[4 + i] * t->position[1] +
		       mvp[8 + i] * t->position[2] + mvp[12 + i];
	x = (c[0] / c[3] + 1.0) * 0.5 * WIDTH;
	y = (1.0 - c[1] / c[3]) * 0.5 * HEIGHT;
	snprintf(num, sizeof(num), "%llu", (unsigned long long)t->number);
	text_measure(font, num, px, &e);
	box[0] = x - 0.5 * e.width - 0.3 * px;
	box[1] = y + 0.15 * px;
	box[2] = x + 0.5 * e.width + 0.3 * px;
	box[3] = y + 1.35 * px;
}

/* The scene with every foot moved behind the camera (along what the camera sees as one
 * point, towards it): its numbers hidden, all else as s. trees: room for s's. */
static struct forest_scene hidden(const struct forest_scene *s, const float m[16],
				  struct forest_scene_tree *trees)
{
	struct forest_scene h = *s;
	/* the world direction the screen's x and y do not change along */
	double d[3] = { m[4] * m[9] - m[8] * m[5], m[8] * m[1] - m[0] * m[9],
			m[0] * m[5] - m[4] * m[1] };
	double dz = m[2] * d[0] + m[6] * d[1] + m[10] * d[2], k;

	CHECK(fabs(dz) > 1e-9);
	k = -4.0 / dz; /* clip z falls by 4: before the near plane */
	memcpy(trees, s->trees, s->ntrees * sizeof(*trees));
	for (size_t i = 0; i < s->ntrees; i++)
		for (int j = 0; j < 3; j++)
			trees[i].position[j] += k * d[j];
	h.trees = trees;
	h.serial = ++serials;
	return h;
}

struct label_stats {
	int forests, cards_seen;
	size_t pixels;
	double worst_outside; /* pixels: how far a changed pixel lay outside every card */
};

static void check_labels(struct render *r, struct egl_headless *egl, struct app *app,
			 struct forest *f, struct rng *rg, struct shot sh[5], struct label_stats *ls)
{
	const struct forest_scene *s = &f->scene;
	struct forest_scene_tree trees[MAXN];
	struct forest_scene h;
	struct layout_rect rect = layout_canvas(&app->screen);
	int px = (int)fmax(8.0, round(0.028 * HEIGHT));
	uint64_t now = 1 + rng_next(rg) % 240000000;
	size_t builds = r->forest.labels.builds;
	double boxes[MAXN][4];
	float mvp[16];

	rect.h -= 0.2 * HEIGHT; /* the forest's part: above the invitation's band */
	draw(r, egl, app, s, 0, now, &sh[0]);
	CHECK(r->forest.labels.builds == builds + 1 && r->forest.labels.count > 0);
	memcpy(mvp, r->forest.mvp, sizeof(mvp));
	/* the camera travels: the same quads; a frame adds nothing to the batch for them */
	for (int k = 1; k <= 3; k++) {
		size_t before;

		draw(r, egl, app, s, 0, now + (uint64_t)k * 2500000, &sh[1]);
		before = r->batch.nvertices;
		render_forest_labels(r, app);
		CHECK(r->batch.nvertices == before);
	}
	CHECK(r->forest.labels.builds == builds + 1);
	h = hidden(s, mvp, trees);
	draw(r, egl, app, &h, 0, now, &sh[1]);
	/* no number drawn: they all went behind the camera */
	for (size_t i = 0; i < s->ntrees; i++)
		card_box(mvp, &s->trees[i], r->text.font, px, boxes[i]);
	for (int y = 0; y < HEIGHT; y++)
		for (int x = 0; x < WIDTH; x++) {
			size_t i = (size_t)y * WIDTH + (size_t)x;
			double cx = x + 0.5, cy = y + 0.5, out = INFINITY;

			if (pixel_same(sh[0].rgba, sh[1].rgba, i))
				continue;
			ls->pixels++;
			for (size_t t = 0; t < s->ntrees; t++) {
				double dx = fmax(0.0, fmax(boxes[t][0] - cx, cx - boxes[t][2]));
				double dy = fmax(0.0, fmax(boxes[t][1] - cy, cy - boxes[t][3]));

				out = fmin(out, fmax(dx, dy));
			}
			ls->worst_outside = fmax(ls->worst_outside, out);
			CHECK(out <= 1.0);
		}
	/* every card on the forest's part of the screen shows */
	for (size_t t = 0; t < s->ntrees; t++) {
		const double *b = boxes[t];
		size_t changed = 0;

		if (b[0] < rect.x || b[2] > rect.x + rect.w || b[1] < rect.y ||
		    b[3] > rect.y + rect.h)
			continue;
		for (int y = (int)ceil(b[1]); y < (int)floor(b[3]); y++)
			for (int x = (int)ceil(b[0]); x < (int)floor(b[2]); x++)
				changed += !pixel_same(sh[0].rgba, sh[1].rgba,
						       (size_t)y * WIDTH + (size_t)x);
		CHECK(changed > 0);
		ls->cards_seen++;
	}
	ls->forests++;
}

/* The kiosk draws frames while the forest shows, whatever the drawing: an empty canvas
 * in still air, the attract screen with a forest on it. */
static void check_living(struct forest *f)
{
	struct app *app = app_create(WIDTH, HEIGHT, 1);

	CHECK(app);
	app->attract_after_us = 1000000;
	CHECK(!app_live_at(app, 2000000, NULL)); /* nothing moves */
	app->forest = &f->scene;
	CHECK(!app_live_at(app, 500000, NULL));  /* before the attract screen: the drawing's */
	CHECK(app_live_at(app, 2000000, NULL));
	app->forest_joined_us = 1500000;
	CHECK(app_live_at(app, 2000000, NULL));
	CHECK(!app_live_at(app, UINT64_MAX, NULL));
	app_destroy(app);
}

int main(void)
{
	struct error err = { { 0 } };
	struct egl_headless *egl = egl_headless_create(WIDTH, HEIGHT, &err);
	struct growth_stats gs = { .least_others = INFINITY };
	struct label_stats ls = { 0 };
	struct shot sh[5];
	struct forest *f = calloc(1, sizeof(*f));
	struct render *r;
	struct app *app;
	struct rng rg;
	const char *used;
	char *font;
	size_t len, builds;
	int cases = test_cases(200);

	if (!egl) {
		fprintf(stderr, "forest-screen: %s\n", err.msg);
		return 1;
	}
	CHECK(f && (r = render_create()) && (app = app_create(WIDTH, HEIGHT, 1)));
	app->attract_after_us = 1;
	for (int k = 0; k < 5; k++)
		CHECK((sh[k].rgba = malloc((size_t)WIDTH * HEIGHT * 4)));
	rng_seed(&rg, 2727);
	/* the growth without the labels (no font): the trees' pixels alone */
	for (int c = 0; c < cases; c++) {
		forest_random(f, &rg, c);
		if (c == 0)
			check_living(f);
		check_growth(r, egl, app, f, &rg, sh, &gs);
		forest_finish(f);
	}
	CHECK(gs.most_draws <= 20 && gs.most_draws_growing <= gs.most_draws + 2);
	printf("forest-screen: %d random forests, %d moments of their newest tree's growth: its "
	       "end the settled frame byte for byte; the newest tree at most %.3f of its end's "
	       "pixels (%zu at the ends in all), the others at least %.3f of theirs; draw calls "
	       "at most %u, %u growing\n", gs.forests, gs.moments, gs.least_newest,
	       gs.end_pixels, gs.least_others, gs.most_draws, gs.most_draws_growing);

	/* the numbers, in the labels' font */
	CHECK(font_file_read(NULL, &font, &len, &used, &err) == 0);
	CHECK(render_set_text(r, font, len, RENDER_LANG_EN) == 0);
	for (int c = 0; c < cases / 2; c++) {
		forest_random(f, &rg, 1000 + c);
		check_labels(r, egl, app, f, &rg, sh, &ls);
		/* the scene built again: built again */
		builds = r->forest.labels.builds;
		f->scene.serial = ++serials;
		draw(r, egl, app, &f->scene, 0, 5000000, &sh[0]);
		CHECK(r->forest.labels.builds == builds + 1);
		/* the font set again, its atlas anew and another glyph first, so the digits
		 * land elsewhere in it: built again, the same picture */
		if (c % 10 == 0) {
			CHECK(render_set_text(r, font, len, RENDER_LANG_EN) == 0);
			CHECK(font_glyph(r->text.font, 'W', 77));
			draw(r, egl, app, &f->scene, 0, 5000000, &sh[1]);
			CHECK(r->forest.labels.builds == builds + 2);
			CHECK(memcmp(sh[0].rgba, sh[1].rgba, (size_t)WIDTH * HEIGHT * 4) == 0);
		}
		forest_finish(f);
	}
	free(font);
	printf("forest-screen: %d random forests' numbers: built once a scene, %zu pixels, every "
	       "one within its card (worst %.2f px outside), %d cards seen\n", ls.forests,
	       ls.pixels, ls.worst_outside, ls.cards_seen);
	for (int k = 0; k < 5; k++)
		free(sh[k].rgba);
	app->forest = NULL;
	app_destroy(app);
	render_destroy(r);
	egl_headless_destroy(egl);
	free(f);
	return 0;
}
