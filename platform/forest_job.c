/* SPDX-License-Identifier: MIT */
/* The kiosk's forest brought up to date on the planting thread (forest_job.h). */
#include "forest_job.h"

#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "autosave.h"
#include "forest_state.h"

/* A part kept at a share that grew by no more than this: rebuilding every tree each time
 * one joins would cost the planting thread seconds for a look nobody sees. Never kept when
 * it is over its new share: the budget holds. */
#define FOREST_JOB_SHARE_SLACK 1.25

static bool listed(const uint64_t *list, size_t n, uint64_t a)
{
	for (size_t i = 0; i < n; i++)
		if (list[i] == a)
			return true;
	return false;
}

static const struct forest_tree *had(const struct forest_job *j, uint64_t archive)
{
	for (size_t i = 0; i < j->nhad; i++)
		if (j->had[i].archive == archive)
			return &j->had[i];
	return NULL;
}

static bool is_had_planted(const struct forest_job *j, const struct forest_planted *p)
{
	for (size_t i = 0; i < j->nhad; i++)
		if (j->had[i].planted == p)
			return true;
	return false;
}

static bool is_had_part(const struct forest_job *j, const struct forest_part *p)
{
	for (size_t i = 0; i < j->nhad; i++)
		if (j->had[i].part == p)
			return true;
	return false;
}

static void drop_planted(struct forest_planted *p)
{
	if (p) {
		forest_planted_finish(p);
		free(p);
	}
}

static void drop_part(struct forest_part *p)
{
	if (p) {
		forest_part_finish(p);
		free(p);
	}
}

static size_t part_triangles(const struct forest_part *p)
{
	return (p->mesh.bark.nindices + p->mesh.leaves.nindices) / 3;
}

static int note_failed(struct forest_job *j, uint64_t archive)
{
	uint64_t *f = realloc(j->failed, (j->nfailed + 1) * sizeof(*f));

	if (!f)
		return -ENOMEM;
	j->failed = f;
	f[j->nfailed++] = archive;
	return 0;
}

/* Plants archive number a into a new forest_planted; NULL with *ret 0 when the drawing
 * cannot be planted (the journal names it and why), or with *ret -ENOMEM. */
static struct forest_planted *plant(struct forest_job *j, uint64_t a, int *ret)
{
	char path[PATH_MAX];
	struct forest_planted *p = malloc(sizeof(*p));
	struct error err = { { 0 } };
	int r;

	*ret = 0;
	if (!p) {
		*ret = -ENOMEM;
		return NULL;
	}
	forest_planted_init(p);
	if ((size_t)snprintf(path, sizeof(path), "%s/%s/drawing-%06" PRIu64 ".edaha", j->state_dir,
			     AUTOSAVE_ARCHIVE_DIR, a) >= sizeof(path))
		r = error_set(&err, -ENAMETOOLONG, "%s/%s/drawing-%06" PRIu64 ".edaha: path too long",
			      j->state_dir, AUTOSAVE_ARCHIVE_DIR, a);
	else
		r = forest_plant(path, p, &err);
	if (r == 0) {
		j->planted++;
		return p;
	}
	free(p);
	if (r == -ENOMEM) {
		*ret = r;
		return NULL;
	}
	/* a damaged, hostile or empty drawing stays in the archive; the forest goes on */
	fprintf(stderr, "edaha: forest: skipped %s\n", err.msg);
	*ret = note_failed(j, a);
	return NULL;
}

/* The standing archive numbers, oldest first, into out (max of them): the day's newest,
 * leaving out those known bad, and those max or more numbers below the newest (so every
 * one has a slot of its own in the layout even when files between went missing). */
static size_t standing(const struct forest_job *j, const uint64_t *numbers, size_t n,
		       uint64_t *keep, size_t *idx, uint64_t *out)
{
	size_t m = 0, got, first = 0;

	for (size_t i = 0; i < n; i++)
		if (!listed(j->bad, j->nbad, numbers[i]) && !listed(j->failed, j->nfailed, numbers[i]))
			keep[m++] = numbers[i];
	got = forest_day_standing(&j->day, keep, m, j->max, idx);
	for (size_t i = 0; i < got; i++)
		out[i] = keep[idx[i]];
	while (first < got && out[got - 1] - out[first] >= j->max)
		first++;
	memmove(out, out + first, (got - first) * sizeof(*out));
	return got - first;
}

/* Every standing tree planted (reused or new); a drawing that cannot be planted is left
 * out and the standing chosen again. */
static int plant_standing(struct forest_job *j, const uint64_t *numbers, size_t n)
{
	uint64_t *keep = calloc(n + 1, sizeof(*keep)), *st = calloc(j->max + 1, sizeof(*st));
	size_t *idx = calloc(j->max + 1, sizeof(*idx)), ns = 0;
	int ret = keep && st && idx ? 0 : -ENOMEM;
	bool again = true;

	j->trees = calloc(j->max + 1, sizeof(*j->trees));
	if (!j->trees)
		ret = -ENOMEM;
	while (ret == 0 && again) {
		again = false;
		ns = standing(j, numbers, n, keep, idx, st);
		for (size_t i = 0; ret == 0 && i < ns; i++) {
			const struct forest_tree *h = had(j, st[i]);
			struct forest_tree *t = NULL;

			for (size_t k = 0; k < j->ntrees; k++)
				if (j->trees[k].archive == st[i])
					t = &j->trees[k];
			if (t)
				continue;
			t = &j->trees[j->ntrees];
			*t = (struct forest_tree){ .archive = st[i] };
			if (h) {
				t->planted = h->planted;
				t->part = h->part;
				t->share = h->share;
			} else if (!(t->planted = plant(j, st[i], &ret))) {
				again = ret == 0;
				continue;
			}
			j->ntrees++;
		}
	}
	/* what stands: those still in the last standing, oldest first */
	if (ret == 0) {
		for (size_t i = 0; i < ns; i++) {
			for (size_t k = i; k < j->ntrees; k++) {
				if (j->trees[k].archive == st[i]) {
					struct forest_tree t = j->trees[k];

					j->trees[k] = j->trees[i];
					j->trees[i] = t;
					break;
				}
			}
		}
		/* planted meanwhile but no longer standing (a newer one came): dropped */
		for (size_t k = ns; k < j->ntrees; k++)
			if (!is_had_planted(j, j->trees[k].planted))
				drop_planted(j->trees[k].planted);
		j->ntrees = ns;
		for (size_t i = 0; i < ns; i++)
			j->trees[i].number = forest_day_number(&j->day, j->trees[i].archive);
	}
	free(keep);
	free(st);
	free(idx);
	return ret;
}

/*
 * Which parts to make again at their new shares: those missing, and those whose share grew
 * past FOREST_JOB_SHARE_SLACK times the one they were made for (worth the look); a part
 * kept may be over its new share (a tree joined and every share shrank a little) as long
 * as the whole forest stays within FOREST_TRIANGLES: the most over theirs are made again
 * until it does. So a tree joining costs one planting and few parts, not forty.
 */
static int choose_redo(const struct forest_job *j, const size_t *share, bool *redo)
{
	size_t n = j->ntrees, total = 0;

	for (size_t i = 0; i < n; i++) {
		const struct forest_tree *t = &j->trees[i];

		redo[i] = !t->part || (double)share[i] > FOREST_JOB_SHARE_SLACK * (double)t->share;
		total += redo[i] ? share[i] : part_triangles(t->part);
	}
	while (total > FOREST_TRIANGLES) {
		size_t worst = n, over = 0;

		for (size_t i = 0; i < n; i++) {
			size_t tri = redo[i] ? 0 : part_triangles(j->trees[i].part);

			if (tri > share[i] && tri - share[i] > over) {
				over = tri - share[i];
				worst = i;
			}
		}
		if (worst == n)
			return -EINVAL; /* never: the shares sum to at most the total */
		total -= over;
		redo[worst] = true;
	}
	return 0;
}

/* Each tree's part at its share of the forest's triangles, the layout, the scene. */
static int build_scene(struct forest_job *j)
{
	size_t n = j->ntrees;
	double *widths = calloc(n + 1, sizeof(*widths)), *xz = calloc(2 * n + 2, sizeof(*xz));
	double *pos = calloc(3 * n + 3, sizeof(*pos));
	uint64_t *numbers = calloc(n + 1, sizeof(*numbers));
	size_t *share = calloc(n + 1, sizeof(*share));
	const struct forest_part **parts = calloc(n + 1, sizeof(*parts));
	bool *redo = calloc(n + 1, sizeof(*redo));
	int ret = widths && xz && pos && numbers && share && parts && redo ? 0 : -ENOMEM;

	for (size_t i = 0; ret == 0 && i < n; i++) {
		widths[i] = forest_tree_crown_width(&j->trees[i].planted->tree);
		numbers[i] = j->trees[i].number;
	}
	if (ret == 0) {
		forest_lod_shares(widths, NULL, n, FOREST_TRIANGLES, share);
		ret = choose_redo(j, share, redo);
	}
	for (size_t i = 0; ret == 0 && i < n; i++) {
		struct forest_tree *t = &j->trees[i];
		struct forest_part *p;

		if (!redo[i])
			continue;
		p = malloc(sizeof(*p));
		if (!p) {
			ret = -ENOMEM;
			break;
		}
		forest_part_init(p);
		ret = forest_part_build(p, &t->planted->tree, t->planted->seed, share[i], j->strength);
		if (ret < 0) {
			free(p);
			break;
		}
		t->part = p;
		t->share = share[i];
	}
	if (ret == 0 && n && forest_layout(numbers, widths, n, j->max, xz) < 0)
		ret = -EINVAL; /* never: standing() gives every tree its own slot */
	for (size_t i = 0; ret == 0 && i < n; i++) {
		parts[i] = j->trees[i].part;
		pos[3 * i] = xz[2 * i];
		pos[3 * i + 2] = xz[2 * i + 1];
	}
	if (ret == 0)
		ret = forest_scene_build(j->scene, parts, numbers, pos, n);
	free(widths);
	free(xz);
	free(pos);
	free(numbers);
	free(share);
	free(parts);
	free(redo);
	return ret;
}

static bool same_as_had(const struct forest_job *j)
{
	if (j->ntrees != j->nhad)
		return false;
	for (size_t i = 0; i < j->ntrees; i++)
		if (j->trees[i].archive != j->had[i].archive || j->trees[i].number != j->had[i].number)
			return false;
	return true;
}

int forest_job_run(struct forest_job *j, struct error *err)
{
	struct error warn = { { 0 } };
	uint64_t *numbers = NULL;
	size_t n = 0;
	int ret;

	j->trees = NULL;
	j->ntrees = 0;
	j->failed = NULL;
	j->nfailed = 0;
	j->planted = 0;
	j->changed = j->new_day = false;
	ret = forest_state_load(j->state_dir, &j->day, &warn, err);
	if (warn.msg[0])
		fprintf(stderr, "edaha: forest: warning: %s; a new day begins\n", warn.msg);
	if (ret == 0)
		ret = forest_state_archive(j->state_dir, &numbers, &n, &j->next, err);
	if (ret == 0) {
		int64_t reset = forest_state_reset_moment(j->now, j->reset_hour, j->reset_minute);
		/* without a day file, today's drawings are found by their time */
		uint64_t first = j->day.start ? j->next
					      : forest_state_first_since(j->state_dir, numbers, n,
									 reset, j->next);

		if (forest_day_update(&j->day, reset, first)) {
			j->new_day = true;
			ret = forest_state_save(j->state_dir, &j->day, err);
		}
	}
	if (ret == 0 && (ret = plant_standing(j, numbers, n)) < 0)
		error_set(err, ret, "out of memory planting the forest");
	if (ret == 0 && !same_as_had(j)) {
		j->changed = true;
		ret = build_scene(j);
		if (ret < 0)
			error_set(err, ret, "out of memory building the forest");
	}
	free(numbers);
	if (ret < 0)
		forest_job_finish(j);
	return ret;
}

void forest_job_finish(struct forest_job *j)
{
	for (size_t i = 0; j->trees && i < j->ntrees; i++) {
		if (!is_had_planted(j, j->trees[i].planted))
			drop_planted(j->trees[i].planted);
		if (!is_had_part(j, j->trees[i].part))
			drop_part(j->trees[i].part);
	}
	free(j->trees);
	free(j->failed);
	j->trees = NULL;
	j->failed = NULL;
	j->ntrees = j->nfailed = 0;
}
