/* SPDX-License-Identifier: MIT */
/*
 * --headless --forest DIR (docs/forest.md, "Headless and for the teacher"): every *.edaha
 * in DIR planted in name order and numbered 1, 2, 3, ... (a file that cannot be planted
 * is skipped, with why, and takes no number); the newest FOREST_MAX_TREES_DEFAULT stand,
 * placed by forest_layout; forest.json, forest.glb (every standing tree at full
 * detail, with its wind over the forest's common loop) and screen.png (the attract
 * screen's forest at --idle's moment, each tree at its level of detail, the newest
 * growing in from the moment 0; without --idle, grown) written to --out.
 */
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "export.h"
#include "fileio.h"
#include "forest.h"
#include "forest_plant.h"
#include "app.h"
#include "headless.h"
#include "headless_one.h"
#include "render.h"
#include "live.h"

struct standing {
	char *file;   /* its name in DIR */
	uint64_t number;
	struct forest_planted planted;
	double height, crown_width;
};

struct skipped {
	char *file, *why;
};

struct forest_run {
	struct standing *trees; /* a ring of max: the newest planted */
	size_t max, ntrees, next; /* next: where the next one goes */
	struct skipped *skips;
	size_t nskips;
	uint64_t planted;
};

static int by_name(const struct dirent **a, const struct dirent **b)
{
	return strcmp((*a)->d_name, (*b)->d_name);
}

static int is_drawing(const struct dirent *e)
{
	size_t n = strlen(e->d_name);

	return n > 6 && strcmp(e->d_name + n - 6, ".edaha") == 0;
}

static int skip(struct forest_run *f, const char *file, const char *why)
{
	struct skipped *s = realloc(f->skips, (f->nskips + 1) * sizeof(*s));

	if (!s)
		return -ENOMEM;
	f->skips = s;
	s[f->nskips].file = strdup(file);
	s[f->nskips].why = strdup(why);
	if (!s[f->nskips].file || !s[f->nskips].why) {
		free(s[f->nskips].file);
		free(s[f->nskips].why);
		return -ENOMEM;
	}
	f->nskips++;
	return 0;
}

/* Plants dir/name; the newest max stand (the oldest's slot in the ring is reused). */
static int plant(struct forest_run *f, const char *dir, const char *name)
{
	char path[PATH_MAX];
	struct error err = { { 0 } };
	struct standing *s = &f->trees[f->next];
	const char *why;
	int ret;

	if ((size_t)snprintf(path, sizeof(path), "%s/%s", dir, name) >= sizeof(path))
		return skip(f, name, "the path is too long");
	ret = forest_plant(path, &s->planted, &err);
	if (ret == -ENOMEM)
		return ret;
	if (ret < 0) {
		/* the reason without the directory: the file is named beside it */
		why = strncmp(err.msg, path, strlen(path)) == 0 ? err.msg + strlen(path) : err.msg;
		while (*why == ':' || *why == ' ')
			why++;
		fprintf(stderr, "edaha: forest: skipped %s\n", err.msg);
		return skip(f, name, why);
	}
	free(s->file);
	s->file = strdup(name);
	if (!s->file)
		return -ENOMEM;
	s->number = ++f->planted;
	s->height = forest_tree_height(&s->planted.tree);
	s->crown_width = forest_tree_crown_width(&s->planted.tree);
	f->next = (f->next + 1) % f->max;
	if (f->ntrees < f->max)
		f->ntrees++;
	return 0;
}

static int plant_all(struct forest_run *f, const char *dir)
{
	struct dirent **list = NULL;
	int n = scandir(dir, &list, is_drawing, by_name), ret = 0;

	if (n < 0) {
		ret = -errno;
		fprintf(stderr, "edaha: --forest %s: %s\n", dir, strerror(errno));
		return ret;
	}
	for (int i = 0; i < n; i++) {
		if (ret == 0)
			ret = plant(f, dir, list[i]->d_name);
		free(list[i]);
	}
	free(list);
	if (ret == -ENOMEM)
		fputs("edaha: out of memory planting the forest\n", stderr);
	return ret;
}

/* The standing trees, oldest first: the ring from its oldest. */
static struct standing *nth(struct forest_run *f, size_t i)
{
	size_t oldest = f->ntrees < f->max ? 0 : f->next;

	return &f->trees[(oldest + i) % f->max];
}

/* The forest's wind: --wind S, or the breeze where it is not given or 0, as model.glb. */
static int glb(struct forest_run *f, const double *xz, const struct options *o, struct buf *out)
{
	struct export_forest_tree *t = calloc(f->ntrees + 1, sizeof(*t));
	struct export_wind wind = { .strength = o->wind > 0.0 ? o->wind : 0.0,
				    .angle = EXPORT_WIND_ANGLE };
	int ret;

	if (!t)
		return -ENOMEM;
	for (size_t i = 0; i < f->ntrees; i++) {
		struct standing *st = nth(f, i);

		t[i] = (struct export_forest_tree){ &st->planted.tree, &st->planted.mesh,
						    &st->planted.marks, st->planted.seed, st->number,
						    { xz[2 * i], 0.0, xz[2 * i + 1] } };
	}
	ret = export_glb_forest(t, f->ntrees, &wind, LIVE_WIND_COMMON_LOOP_S, out);
	free(t);
	return ret;
}

/* The forest on screen: each tree's part at its share of the triangles, the scene. */
static int build_scene(struct forest_run *f, const double *xz, double strength,
		       struct forest_scene *scene, struct forest_part *parts)
{
	const struct forest_part **pp = calloc(f->ntrees + 1, sizeof(*pp));
	uint64_t *numbers = calloc(f->ntrees + 1, sizeof(*numbers));
	double *widths = calloc(f->ntrees + 1, sizeof(*widths)), *pos = calloc(3 * f->ntrees + 3, sizeof(*pos));
	size_t *share = calloc(f->ntrees + 1, sizeof(*share));
	int ret = pp && numbers && widths && pos && share ? 0 : -ENOMEM;

	for (size_t i = 0; ret == 0 && i < f->ntrees; i++)
		widths[i] = nth(f, i)->crown_width;
	if (ret == 0)
		forest_lod_shares(widths, NULL, f->ntrees, FOREST_TRIANGLES, share);
	for (size_t i = 0; ret == 0 && i < f->ntrees; i++) {
		struct standing *st = nth(f, i);

		ret = forest_part_build(&parts[i], &st->planted.tree, st->planted.seed, share[i],
					strength);
		pp[i] = &parts[i];
		numbers[i] = st->number;
		pos[3 * i] = xz[2 * i];
		pos[3 * i + 2] = xz[2 * i + 1];
	}
	if (ret == 0)
		ret = forest_scene_build(scene, pp, numbers, pos, f->ntrees);
	free(pp);
	free(numbers);
	free(widths);
	free(pos);
	free(share);
	return ret;
}

struct picture {
	const struct options *o;
	struct app *app;
	uint64_t now_us;
};

static int draw(struct render *r, const void *ctx, int width, int height)
{
	const struct picture *p = ctx;
	int ret = headless_set_text(r, p->o);

	(void)width;
	(void)height;
	return ret < 0 ? ret : render_frame_at(r, p->app, p->now_us);
}

/* screen.png: the attract screen showing the forest at --idle's moment (0 without, the
 * newest tree grown). */
static int picture(struct forest_run *f, const double *xz, const struct options *o, struct buf *png)
{
	struct forest_scene scene;
	struct forest_part *parts = calloc(f->ntrees + 1, sizeof(*parts));
	struct picture p = { .o = o };
	int ret = parts ? 0 : -ENOMEM, status = 1;

	forest_scene_init(&scene);
	for (size_t i = 0; parts && i < f->ntrees; i++)
		forest_part_init(&parts[i]);
	if (ret == 0)
		ret = build_scene(f, xz, o->wind > 0.0 ? o->wind : 0.0, &scene, parts);
	if (ret == 0 && !(p.app = app_create(o->width, o->height, 1)))
		ret = -ENOMEM;
	if (ret == 0) {
		/* the attract screen from the start: --idle T is the moment T s into it, the
		 * newest tree having joined at its moment 0 (so T s into its growth); without
		 * --idle, the forest as it stands once grown */
		p.app->forest = &scene;
		p.app->attract_after_us = 1;
		p.app->forest_joined_us = o->idle_given ? 1 : 0;
		p.now_us = 1 + (o->idle_given ? (uint64_t)llround(o->idle_s * 1e6) : 0);
		status = headless_one_picture(o, draw, &p, png);
	}
	if (ret < 0)
		fputs("edaha: out of memory building the forest's picture\n", stderr);
	app_destroy(p.app);
	for (size_t i = 0; parts && i < f->ntrees; i++)
		forest_part_finish(&parts[i]);
	free(parts);
	forest_scene_finish(&scene);
	return status ? -EIO : 0;
}

static int write_files(struct forest_run *f, const struct options *o)
{
	const char *out_dir = o->out_dir;
	struct forest_json_tree *t = calloc(f->ntrees + 1, sizeof(*t));
	struct forest_json_skip *s = calloc(f->nskips + 1, sizeof(*s));
	uint64_t *numbers = calloc(f->ntrees + 1, sizeof(*numbers));
	double *widths = calloc(f->ntrees + 1, sizeof(*widths));
	double *xz = calloc(2 * f->ntrees + 2, sizeof(*xz));
	struct error err = { { 0 } };
	struct buf b, g, png;
	int ret = 0;

	buf_init(&b);
	buf_init(&g);
	buf_init(&png);
	if (!t || !s || !numbers || !widths || !xz)
		ret = -ENOMEM;
	for (size_t i = 0; ret == 0 && i < f->ntrees; i++) {
		numbers[i] = nth(f, i)->number;
		widths[i] = nth(f, i)->crown_width;
	}
	if (ret == 0 && f->ntrees && forest_layout(numbers, widths, f->ntrees, f->max, xz) < 0)
		ret = -EINVAL;
	for (size_t i = 0; ret == 0 && i < f->ntrees; i++) {
		struct standing *st = nth(f, i);

		t[i] = (struct forest_json_tree){ st->number, st->file, { xz[2 * i], 0.0, xz[2 * i + 1] },
						  st->height, st->crown_width,
						  st->planted.tree.nbranches, st->planted.tree.nleaves };
	}
	for (size_t i = 0; i < f->nskips; i++)
		s[i] = (struct forest_json_skip){ f->skips[i].file, f->skips[i].why };
	if (ret == 0)
		ret = forest_json(t, f->ntrees, s, f->nskips, &b);
	if (ret == 0)
		ret = glb(f, xz, o, &g);
	if (ret == 0)
		ret = picture(f, xz, o, &png);
	if (ret == 0)
		ret = fileio_mkdirs(out_dir, &err);
	if (ret == 0)
		ret = fileio_write_atomic(out_dir, "forest.json", b.data, b.len, &err);
	if (ret == 0)
		ret = fileio_write_atomic(out_dir, "forest.glb", g.data, g.len, &err);
	if (ret == 0)
		ret = fileio_write_atomic(out_dir, "screen.png", png.data, png.len, &err);
	if (ret < 0)
		fprintf(stderr, "edaha: %s\n", err.msg[0] ? err.msg : "out of memory");
	buf_finish(&b);
	buf_finish(&g);
	buf_finish(&png);
	free(t);
	free(s);
	free(numbers);
	free(widths);
	free(xz);
	return ret;
}

int headless_forest_run(const struct options *o)
{
	struct forest_run f = { .max = FOREST_MAX_TREES_DEFAULT };
	int ret, status = 0;

	f.trees = calloc(f.max, sizeof(*f.trees));
	if (!f.trees) {
		fputs("edaha: out of memory\n", stderr);
		return 1;
	}
	for (size_t i = 0; i < f.max; i++)
		forest_planted_init(&f.trees[i].planted);
	ret = plant_all(&f, o->forest);
	if (ret < 0)
		status = ret == -ENOMEM ? 1 : 2;
	if (status == 0 && write_files(&f, o) < 0)
		status = 1;
	if (status == 0)
		printf("edaha: wrote forest.json, forest.glb and screen.png to %s (%zu trees standing of %llu planted, %zu "
		       "skipped)\n", o->out_dir, f.ntrees, (unsigned long long)f.planted, f.nskips);
	for (size_t i = 0; i < f.max; i++) {
		forest_planted_finish(&f.trees[i].planted);
		free(f.trees[i].file);
	}
	for (size_t i = 0; i < f.nskips; i++) {
		free(f.skips[i].file);
		free(f.skips[i].why);
	}
	free(f.skips);
	free(f.trees);
	return status;
}
