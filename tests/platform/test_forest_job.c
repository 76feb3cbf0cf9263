/* SPDX-License-Identifier: MIT */
/*
 * The kiosk's forest brought up to date (platform/forest_job.c, docs/forest.md "On the
 * kiosk"), against a model of the rules, on seeded random days of a kiosk: drawings
 * archived (the document corpus's, a damaged and a hostile one among them), archives
 * pruned, files going missing, the clock moving on (past the reset hour or not), the day
 * file removed or damaged, staff's --forest-reset. After every job:
 *  - the standing trees are the day's newest max that can be planted, oldest first,
 *    numbered archive - first + 1, none max or more below the newest;
 *  - a tree that stood before is the same tree (reused, never planted again); a drawing
 *    that could not be planted is named once and never tried again;
 *  - the parts' triangles sum to at most FOREST_TRIANGLES; the scene holds the trees in
 *    that order with those numbers;
 *  - a job from nothing (a kiosk started again, after a kill -9 mid-planting) finds the
 *    same trees, numbers and places.
 *   test_forest_job CORPUS_DIR DAMAGED_FILE
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "autosave.h"
#include "fileio.h"
#include "forest_job.h"
#include "forest_state.h"
#include "rng.h"
#include "test.h"

static uint32_t rng_below(struct rng *r, uint32_t n)
{
	return (uint32_t)(rng_next(r) % n);
}

#define MAX_SOURCES 32

struct source {
	char *data;
	size_t len;
	bool plantable;
};

static struct source sources[MAX_SOURCES];
static size_t nsources;
static char state[256], archive[300];
static size_t jobs, trees_checked, reused, planted_total, fresh_checked, days_begun;

static void add_source(const char *path, bool plantable)
{
	struct error err = { { 0 } };
	struct source *s = &sources[nsources++];

	CHECK(fileio_read_all(path, 1 << 20, &s->data, &s->len, &err) == 0);
	s->plantable = plantable;
}

static int drawing(const struct dirent *e)
{
	size_t n = strlen(e->d_name);

	return n > 6 && strcmp(e->d_name + n - 6, ".edaha") == 0;
}

static void load_sources(const char *corpus, const char *damaged)
{
	struct dirent **list;
	int n = scandir(corpus, &list, drawing, alphasort);
	char path[512];

	CHECK(n > 3);
	for (int i = 0; i < n; i++) {
		struct forest_planted p;
		struct error err = { { 0 } };

		snprintf(path, sizeof(path), "%s/%s", corpus, list[i]->d_name);
		forest_planted_init(&p);
		if (nsources + 2 < MAX_SOURCES)
			add_source(path, forest_plant(path, &p, &err) == 0);
		forest_planted_finish(&p);
		free(list[i]);
	}
	free(list);
	add_source(damaged, false);
	/* hostile: markup where a line should be */
	sources[nsources].data = strdup("edaha-drawing 7\nseed 1\n<script>alert(1)</script>\n");
	sources[nsources].len = strlen(sources[nsources].data);
	sources[nsources++].plantable = false;
}

/* The model's kiosk: its archive (number -> source, -1 none), clock and day. */
#define MAX_ARCHIVE 200
struct model {
	int src[MAX_ARCHIVE + 1];
	int64_t mtime[MAX_ARCHIVE + 1];
	uint64_t next;
	int64_t now;
	int hour, minute;
	size_t max;
	struct forest_day day;
	bool day_file; /* a readable day file holds day */
};

static void archive_path(char *out, size_t size, uint64_t a)
{
	snprintf(out, size, "%s/drawing-%06" PRIu64 ".edaha", archive, a);
}

static void put(struct model *m, uint64_t a, int src)
{
	char path[400];
	FILE *f;
	struct timespec ts[2];

	archive_path(path, sizeof(path), a);
	f = fopen(path, "wb");
	CHECK(f && fwrite(sources[src].data, 1, sources[src].len, f) == sources[src].len);
	CHECK(fclose(f) == 0);
	ts[0] = ts[1] = (struct timespec){ (time_t)m->now, 0 };
	CHECK(utimensat(AT_FDCWD, path, ts, 0) == 0);
	m->src[a] = src;
	m->mtime[a] = m->now;
}

static void drop(struct model *m, uint64_t a)
{
	char path[400];

	archive_path(path, sizeof(path), a);
	CHECK(unlink(path) == 0);
	m->src[a] = -1;
}

/* The last hour:minute at or before now, in UTC (the test's TZ). */
static int64_t reset_moment(const struct model *m, int64_t now)
{
	int64_t off = m->hour * 3600 + m->minute * 60, d = now - off;

	return (d >= 0 ? d / 86400 : (d - 86399) / 86400) * 86400 + off;
}

static uint64_t model_next(const struct model *m)
{
	uint64_t hi = 0;

	for (uint64_t a = 1; a <= MAX_ARCHIVE; a++)
		if (m->src[a] >= 0)
			hi = a;
	return hi + 1;
}

/* What the job must do with the day (the rules of docs/forest.md). */
static void model_day(struct model *m)
{
	int64_t reset = reset_moment(m, m->now);
	uint64_t next = model_next(m), first = next;

	if (!m->day_file) {
		m->day = (struct forest_day){ 0, 0 };
		for (uint64_t a = 1; a < next; a++) {
			if (m->src[a] >= 0 && m->mtime[a] >= reset) {
				first = a;
				break;
			}
		}
	}
	if (reset > m->day.start) {
		m->day = (struct forest_day){ reset, first };
		days_begun++;
	}
	m->day_file = true;
}

/* The standing archive numbers the model expects, oldest first. */
static size_t model_standing(const struct model *m, uint64_t *out)
{
	size_t n = 0, first = 0;
	uint64_t a;

	for (a = model_next(m); a-- > 1 && n < m->max;)
		if (a >= m->day.first && m->src[a] >= 0 && sources[m->src[a]].plantable)
			out[n++] = a;
	for (size_t i = 0; i < n / 2; i++) {
		uint64_t t = out[i];

		out[i] = out[n - 1 - i];
		out[n - 1 - i] = t;
	}
	while (first < n && out[n - 1] - out[first] >= m->max)
		first++;
	memmove(out, out + first, (n - first) * sizeof(*out));
	return n - first;
}

struct kiosk_side {
	struct forest_tree *trees;
	size_t ntrees;
	uint64_t *bad;
	size_t nbad;
	struct forest_scene scene;
};

static bool holds(const struct forest_tree *t, size_t n, const void *p, bool part)
{
	for (size_t i = 0; i < n; i++)
		if ((part ? (const void *)t[i].part : (const void *)t[i].planted) == p)
			return true;
	return false;
}

static void free_trees(struct forest_tree *t, size_t n, const struct forest_tree *keep, size_t nkeep)
{
	for (size_t i = 0; i < n; i++) {
		if (!holds(keep, nkeep, t[i].planted, false)) {
			forest_planted_finish(t[i].planted);
			free(t[i].planted);
		}
		if (!holds(keep, nkeep, t[i].part, true)) {
			forest_part_finish(t[i].part);
			free(t[i].part);
		}
	}
	free(t);
}

/* One job as the kiosk runs it (kiosk_forest.c): its trees and failures adopted. */
static void run_job(struct kiosk_side *k, const struct model *m, struct forest_job *j)
{
	struct error err = { { 0 } };

	*j = (struct forest_job){ .state_dir = state, .max = m->max, .reset_hour = m->hour,
				  .reset_minute = m->minute, .now = m->now, .strength = 0.3,
				  .had = k->trees, .nhad = k->ntrees, .bad = k->bad, .nbad = k->nbad,
				  .scene = &k->scene };
	CHECK(forest_job_run(j, &err) == 0);
	jobs++;
	planted_total += j->planted;
	k->bad = realloc(k->bad, (k->nbad + j->nfailed + 1) * sizeof(*k->bad));
	CHECK(k->bad != NULL);
	for (size_t i = 0; i < j->nfailed; i++) {
		/* named once, never tried again */
		for (size_t b = 0; b < k->nbad; b++)
			CHECK(k->bad[b] != j->failed[i]);
		CHECK(m->src[j->failed[i]] >= 0 && !sources[m->src[j->failed[i]]].plantable);
		k->bad[k->nbad++] = j->failed[i];
	}
}

static void check_job(struct kiosk_side *k, struct model *m)
{
	struct forest_job j;
	uint64_t want[MAX_ARCHIVE];
	size_t nwant, tris = 0;
	struct forest_tree *old = k->trees;
	size_t nold = k->ntrees;

	run_job(k, m, &j);
	model_day(m);
	CHECK(j.day.start == m->day.start && j.day.first == m->day.first);
	CHECK(j.next == model_next(m));
	nwant = model_standing(m, want);
	CHECK(j.ntrees == nwant);
	for (size_t i = 0; i < j.ntrees && i < nwant; i++) {
		const struct forest_tree *t = &j.trees[i];

		CHECK(t->archive == want[i]);
		CHECK(t->number == want[i] - m->day.first + 1);
		CHECK(t->planted && t->part);
		tris += (t->part->mesh.bark.nindices + t->part->mesh.leaves.nindices) / 3;
		for (size_t o = 0; o < nold; o++) {
			if (old[o].archive == t->archive) {
				CHECK(old[o].planted == t->planted); /* the same tree, not planted again */
				reused++;
			}
		}
		trees_checked++;
	}
	CHECK(tris <= FOREST_TRIANGLES);
	if (j.changed) {
		CHECK(k->scene.ntrees == j.ntrees);
		for (size_t i = 0; i < j.ntrees && i < k->scene.ntrees; i++)
			CHECK(k->scene.trees[i].number == j.trees[i].number);
	} else {
		CHECK(j.ntrees == nold);
	}
	/* adopted as the kiosk does */
	free_trees(old, nold, j.trees, j.ntrees);
	k->trees = j.trees;
	k->ntrees = j.ntrees;
	j.trees = NULL;
	j.ntrees = 0;
	forest_job_finish(&j);
}

/* A kiosk started again on the same state directory: the same forest. */
static void check_fresh(const struct kiosk_side *k, const struct model *m)
{
	struct kiosk_side f = { 0 };
	struct forest_job j;

	forest_scene_init(&f.scene);
	run_job(&f, m, &j);
	CHECK(!j.new_day); /* the day file says today already */
	CHECK(j.ntrees == k->ntrees);
	CHECK(j.ntrees == 0 || j.changed);
	for (size_t i = 0; i < j.ntrees && i < k->ntrees; i++) {
		CHECK(j.trees[i].archive == k->trees[i].archive);
		CHECK(j.trees[i].number == k->trees[i].number);
		if (j.changed && k->scene.ntrees == k->ntrees) {
			for (int c = 0; c < 3; c++)
				CHECK(f.scene.trees[i].position[c] == k->scene.trees[i].position[c]);
		}
	}
	fresh_checked++;
	free_trees(j.trees, j.ntrees, NULL, 0);
	j.trees = NULL;
	j.ntrees = 0;
	forest_job_finish(&j);
	free(f.bad);
	forest_scene_finish(&f.scene);
}

static void rm_state(void)
{
	char cmd[600];

	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", state);
	CHECK(system(cmd) == 0);
}

static void scenario(uint64_t seed)
{
	struct rng r;
	struct model m = { .next = 1 };
	struct kiosk_side k = { 0 };
	static const size_t maxes[] = { 1, 2, 3, 5, 8 };
	int steps;

	rng_seed(&r, seed);
	for (int a = 0; a <= MAX_ARCHIVE; a++)
		m.src[a] = -1;
	m.max = maxes[rng_below(&r, 5)];
	m.hour = (int)rng_below(&r, 24);
	m.minute = (int)rng_below(&r, 60);
	m.now = 1796443200 + (int64_t)rng_below(&r, 86400 * 30);
	rm_state();
	CHECK(mkdir(state, 0755) == 0 && mkdir(archive, 0755) == 0);
	forest_scene_init(&k.scene);
	steps = 6 + (int)rng_below(&r, 10);
	for (int s = 0; s < steps; s++) {
		uint32_t what = rng_below(&r, 100);

		if (what < 55) {
			/* the idle reset or New archives a drawing (now and then two) */
			for (uint32_t c = 1 + (rng_below(&r, 4) == 0); c-- > 0;) {
				uint64_t a = model_next(&m);

				if (a <= MAX_ARCHIVE)
					put(&m, a, (int)rng_below(&r, (uint32_t)nsources));
			}
		} else if (what < 65) {
			/* archive_keep prunes the oldest; or a file goes missing */
			for (uint64_t a = 1; a < model_next(&m); a++) {
				if (m.src[a] >= 0 && (what < 60 || rng_below(&r, 3) == 0)) {
					drop(&m, a);
					break;
				}
			}
		} else if (what < 80) {
			m.now += (int64_t)rng_below(&r, 30 * 3600);
		} else if (what < 85) {
			char path[400];

			/* the day file removed, or damaged */
			snprintf(path, sizeof(path), "%s/%s", state, FOREST_STATE_FILE);
			if (rng_below(&r, 2)) {
				(void)unlink(path);
			} else {
				FILE *f = fopen(path, "w");

				CHECK(f && fputs("edaha-forest-day: 1\nstart: yes\n", f) >= 0);
				CHECK(fclose(f) == 0);
			}
			m.day_file = false;
		} else if (what < 90) {
			struct error err = { { 0 } };

			CHECK(forest_state_reset(state, m.now, &err) == 0);
			m.day = (struct forest_day){ m.now, model_next(&m) };
			m.day_file = true;
		}
		check_job(&k, &m);
		if (rng_below(&r, 3) == 0)
			check_fresh(&k, &m);
	}
	free_trees(k.trees, k.ntrees, NULL, 0);
	free(k.bad);
	forest_scene_finish(&k.scene);
}

int main(int argc, char **argv)
{
	const char *tmp = getenv("TMPDIR");
	int n = test_cases(argc > 3 ? atoi(argv[3]) : 120);

	if (argc < 3) {
		fprintf(stderr, "usage: %s CORPUS_DIR DAMAGED_FILE [SCENARIOS]\n", argv[0]);
		return 2;
	}
	setenv("TZ", "UTC", 1);
	tzset();
	snprintf(state, sizeof(state), "%s/edaha-forest-job.%d", tmp ? tmp : "/tmp", (int)getpid());
	snprintf(archive, sizeof(archive), "%s/%s", state, AUTOSAVE_ARCHIVE_DIR);
	load_sources(argv[1], argv[2]);
	for (int s = 0; s < n; s++)
		scenario((uint64_t)s + 1);
	rm_state();
	printf("%d kiosk days: %zu jobs, %zu days begun, %zu standing trees checked (%zu reused, "
	       "%zu planted), %zu restarts found the same forest\n",
	       n, jobs, days_begun, trees_checked, reused, planted_total, fresh_checked);
	for (size_t i = 0; i < nsources; i++)
		free(sources[i].data);
	return 0;
}
