/* SPDX-License-Identifier: MIT */
/*
 * Today's forest on the kiosk (docs/forest.md, "On the kiosk"): brought up to date by a
 * job on a thread of its own (forest_job.h) at the start, after every archived drawing
 * when the reset hour comes or the clock is set (a realtime timer, woken by either), and
 * once a minute (staff's edaha --forest-reset); the scene it builds is
 * swapped into the one the app shows between frames. The thread runs at a lower priority
 * than the loop, so a planting never delays the pen.
 */
#define _GNU_SOURCE
#include "kiosk_private.h"

#include <errno.h>
#include <inttypes.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "export.h"
#include "forest_state.h"
#include "forest_job.h"

/* How often the day file and the clock are looked at. */
#define KIOSK_FOREST_CHECK_S 60
/* The planting thread's nice: below the loop that draws and reads the pen. */
#define KIOSK_FOREST_NICE 10

struct kiosk_forest {
	struct kiosk *k;
	struct forest_tree *trees; /* standing, oldest first; the main loop's */
	size_t ntrees;
	uint64_t *bad; /* archive numbers that could not be planted */
	size_t nbad;
	struct forest_day day;
	uint64_t next;          /* the next archived drawing's number */
	bool known;             /* a job has finished: day and next are the archive's */
	uint64_t tell;          /* an idle reset's archive number, told once known */
	struct forest_scene shown, back; /* shown: app->forest; back: the job's */
	uint64_t serial;
	/* the job on its thread */
	int fd, timer_fd, day_fd; /* the job's, the minute's, the reset moment's */
	pthread_t thread;
	bool running, again;
	struct forest_job job;
	struct error err;
	int result;
	uint64_t started_us;
};

static void *run(void *arg)
{
	struct kiosk_forest *f = arg;
	uint64_t one = 1;

	/* this thread alone (Linux's nice is per thread); failing leaves it as it was */
	(void)setpriority(PRIO_PROCESS, (id_t)gettid(), KIOSK_FOREST_NICE);
	f->result = forest_job_run(&f->job, &f->err);
	while (write(f->fd, &one, sizeof(one)) < 0 && errno == EINTR)
		;
	return NULL;
}

/* Starts a job, or asks for one after the one under way. */
void kiosk_forest_refresh(struct kiosk *k)
{
	struct kiosk_forest *f = k->forest;
	int ret;

	if (!f)
		return;
	if (f->running) {
		f->again = true;
		return;
	}
	f->again = false;
	f->job = (struct forest_job){
		.state_dir = k->cfg.state_dir,
		.max = k->cfg.forest_max ? k->cfg.forest_max : FOREST_MAX_TREES_DEFAULT,
		.reset_hour = k->cfg.forest_reset_hour,
		.reset_minute = k->cfg.forest_reset_minute,
		.now = (int64_t)time(NULL),
		.strength = k->cfg.wind < 0.0 ? LIVE_WIND_DEFAULT_STRENGTH : k->cfg.wind,
		.had = f->trees,
		.nhad = f->ntrees,
		.bad = f->bad,
		.nbad = f->nbad,
		.scene = &f->back,
	};
	if (f->job.strength > 1.0)
		f->job.strength = 0.0; /* as kiosk_live_setup: out of range stands still */
	f->err = (struct error){ { 0 } };
	f->started_us = kiosk_now_us();
	ret = pthread_create(&f->thread, NULL, run, f);
	if (ret != 0) {
		fprintf(stderr, "edaha: forest: cannot start planting: %s\n", strerror(ret));
		return;
	}
	f->running = true;
}

static bool holds_planted(const struct forest_tree *t, size_t n, const struct forest_planted *p)
{
	for (size_t i = 0; i < n; i++)
		if (t[i].planted == p)
			return true;
	return false;
}

static bool holds_part(const struct forest_tree *t, size_t n, const struct forest_part *p)
{
	for (size_t i = 0; i < n; i++)
		if (t[i].part == p)
			return true;
	return false;
}

/* The trees no longer standing, or their parts made again, freed; the job's list kept. */
static void adopt_trees(struct kiosk_forest *f)
{
	struct forest_job *j = &f->job;

	for (size_t i = 0; i < f->ntrees; i++) {
		if (!holds_planted(j->trees, j->ntrees, f->trees[i].planted)) {
			forest_planted_finish(f->trees[i].planted);
			free(f->trees[i].planted);
		}
		if (!holds_part(j->trees, j->ntrees, f->trees[i].part)) {
			forest_part_finish(f->trees[i].part);
			free(f->trees[i].part);
		}
	}
	free(f->trees);
	f->trees = j->trees;
	f->ntrees = j->ntrees;
	j->trees = NULL;
	j->ntrees = 0;
}

static void say(const struct kiosk_forest *f, uint64_t newest_before, size_t planted, bool first)
{
	double s = (double)(kiosk_now_us() - f->started_us) / 1e6;
	const struct forest_tree *newest = f->ntrees ? &f->trees[f->ntrees - 1] : NULL;

	if (f->job.new_day)
		fprintf(stderr, "edaha: forest: a new day: drawing-%06" PRIu64 ".edaha and later "
			"are today's forest\n", f->day.first);
	if (!f->job.changed)
		return;
	if (!first && newest && newest->archive > newest_before && planted)
		fprintf(stderr, "edaha: forest: No. %" PRIu64 " planted (drawing-%06" PRIu64
			".edaha) in %.2f s; %zu trees standing\n",
			newest->number, newest->archive, s, f->ntrees);
	else if (newest)
		fprintf(stderr, "edaha: forest: %zu trees standing (No. %" PRIu64 " to %" PRIu64
			"), built in %.2f s\n", f->ntrees, f->trees[0].number, newest->number, s);
	else
		fputs("edaha: forest: no tree stands: the attract screen invites the day's first\n",
		      stderr);
}

/* The job done: its trees and scene taken, its failures remembered, again if asked. */
static int on_done(void *data)
{
	struct kiosk_forest *f = data;
	struct kiosk *k = f->k;
	uint64_t n, newest_before = f->ntrees ? f->trees[f->ntrees - 1].archive : 0;
	bool first = !f->known;

	if (!f->running || read(f->fd, &n, sizeof(n)) < 0)
		return 0;
	pthread_join(f->thread, NULL);
	f->running = false;
	if (f->result < 0) {
		fprintf(stderr, "edaha: forest: %s; trying again at the next drawing\n", f->err.msg);
	} else {
		uint64_t *b = f->job.nfailed ? realloc(f->bad, (f->nbad + f->job.nfailed) * sizeof(*b))
					     : f->bad;

		if (b) {
			memcpy(b + f->nbad, f->job.failed, f->job.nfailed * sizeof(*b));
			f->bad = b;
			f->nbad += f->job.nfailed;
		}
		f->day = f->job.day;
		f->next = f->job.next;
		f->known = true;
		adopt_trees(f);
		if (f->job.changed) {
			struct forest_scene t = f->shown;

			f->shown = f->back;
			f->back = t;
			/* the renderer keeps the scene's buffers by pointer and serial */
			f->shown.serial = ++f->serial;
			/* a tree that joined grows in; at the start the forest stands grown */
			if (!first && f->ntrees && f->trees[f->ntrees - 1].archive > newest_before)
				k->app->forest_joined_us = kiosk_now_us();
		}
		say(f, newest_before, f->job.planted, first);
		forest_job_finish(&f->job);
		app_set_forest_number(k->app, kiosk_forest_number(k));
		if (f->tell) {
			uint64_t number = forest_day_number(&f->day, f->tell);

			/* archived before the forest was known (a slow start): told now */
			f->tell = 0;
			if (number)
				kiosk_forest_tell(k, number);
		}
	}
	if (f->again)
		kiosk_forest_refresh(k);
	return 0;
}

/* The day's next reset moment after now: the realtime timer's, cancelled when the clock
 * is set (NTP's first step on a board without a clock, a technician's date -s), so a new
 * day is seen at once either way. */
static int arm_day(struct kiosk_forest *f)
{
	const struct kiosk_config *c = &f->k->cfg;
	int64_t now = (int64_t)time(NULL);
	int64_t r = forest_state_reset_moment(now + 25 * 3600, c->forest_reset_hour,
					      c->forest_reset_minute);
	struct itimerspec at = { { 0, 0 }, { 0, 0 } };

	/* the last moment at or before 25 h on may be the second after now (a 23 h day) */
	for (int i = 0; i < 3; i++) {
		int64_t p = forest_state_reset_moment(r - 1, c->forest_reset_hour,
						      c->forest_reset_minute);

		if (p <= now)
			break;
		r = p;
	}
	at.it_value.tv_sec = (time_t)(r > now ? r : now + 1);
	return timerfd_settime(f->day_fd, TFD_TIMER_ABSTIME | TFD_TIMER_CANCEL_ON_SET, &at, NULL);
}

static int on_day(void *data)
{
	struct kiosk_forest *f = data;
	uint64_t n;

	/* expired, or ECANCELED: the clock was set; either way the day is looked at again */
	if (read(f->day_fd, &n, sizeof(n)) < 0 && errno != ECANCELED)
		return 0;
	if (arm_day(f) < 0)
		fprintf(stderr, "edaha: forest: warning: the reset hour's timer: %s\n", strerror(errno));
	kiosk_forest_refresh(f->k);
	return 0;
}

static int on_minute(void *data)
{
	struct kiosk_forest *f = data;
	uint64_t n;

	if (read(f->timer_fd, &n, sizeof(n)) == (ssize_t)sizeof(n))
		kiosk_forest_refresh(f->k);
	return 0;
}

int kiosk_forest_create(struct kiosk *k)
{
	struct itimerspec every = { { KIOSK_FOREST_CHECK_S, 0 }, { KIOSK_FOREST_CHECK_S, 0 } };
	struct kiosk_forest *f;
	struct kiosk_source src[3];

	if (!k->cfg.forest || !k->autosave)
		return 0;
	f = calloc(1, sizeof(*f));
	if (!f)
		return -ENOMEM;
	f->k = k;
	f->fd = f->timer_fd = f->day_fd = -1;
	f->fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	f->timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
	f->day_fd = timerfd_create(CLOCK_REALTIME, TFD_NONBLOCK | TFD_CLOEXEC);
	forest_scene_init(&f->shown);
	forest_scene_init(&f->back);
	k->forest = f;
	if (f->fd < 0 || f->timer_fd < 0 || f->day_fd < 0 ||
	    timerfd_settime(f->timer_fd, 0, &every, NULL) < 0 || arm_day(f) < 0) {
		fprintf(stderr, "edaha: forest: %s: today's forest is off\n", strerror(errno));
		kiosk_forest_destroy(k);
		return 0;
	}
	src[0] = (struct kiosk_source){ f->fd, on_done, f };
	src[1] = (struct kiosk_source){ f->timer_fd, on_minute, f };
	src[2] = (struct kiosk_source){ f->day_fd, on_day, f };
	for (size_t i = 0; i < 3; i++)
		if (kiosk_add_source(k, &src[i]) < 0)
			return -ENOMEM;
	k->app->forest = &f->shown;
	kiosk_forest_refresh(k);
	return 0;
}

void kiosk_forest_destroy(struct kiosk *k)
{
	struct kiosk_forest *f = k->forest;

	if (!f)
		return;
	if (f->running) {
		pthread_join(f->thread, NULL);
		forest_job_finish(&f->job);
	}
	for (size_t i = 0; i < f->ntrees; i++) {
		forest_planted_finish(f->trees[i].planted);
		free(f->trees[i].planted);
		forest_part_finish(f->trees[i].part);
		free(f->trees[i].part);
	}
	free(f->trees);
	free(f->bad);
	forest_scene_finish(&f->shown);
	forest_scene_finish(&f->back);
	if (f->fd >= 0)
		close(f->fd);
	if (f->timer_fd >= 0)
		close(f->timer_fd);
	if (f->day_fd >= 0)
		close(f->day_fd);
	if (k->app && k->app->forest == &f->shown)
		k->app->forest = NULL;
	free(f);
	k->forest = NULL;
}

uint64_t kiosk_forest_number(const struct kiosk *k)
{
	const struct kiosk_forest *f = k->forest;

	return f && f->known ? forest_day_number(&f->day, f->next) : 0;
}

void kiosk_forest_tell(struct kiosk *k, uint64_t number)
{
	fprintf(stderr, "edaha: forest: the drawing is No. %" PRIu64 " in today's forest\n", number);
	app_tell_forest_number(k->app, number, kiosk_now_us());
}

uint64_t kiosk_forest_archived(struct kiosk *k, const char *name, bool tell)
{
	struct kiosk_forest *f = k->forest;
	uint64_t a = autosave_archive_number(name), number;

	if (!f || !a)
		return 0;
	if (f->known && a >= f->next)
		f->next = a + 1;
	kiosk_forest_refresh(k);
	app_set_forest_number(k->app, kiosk_forest_number(k));
	if (!f->known) {
		f->tell = tell ? a : 0;
		return 0;
	}
	number = forest_day_number(&f->day, a);
	return number;
}

int kiosk_forest_glb(struct kiosk *k, struct buf *out, char date[11])
{
	struct kiosk_forest *f = k->forest;
	struct export_forest_tree *t;
	struct export_wind wind = { .strength = k->cfg.wind > 0.0 ? k->cfg.wind : 0.0,
				    .angle = EXPORT_WIND_ANGLE };
	time_t day;
	struct tm tm;
	int ret;

	if (!f || !f->ntrees || f->shown.ntrees != f->ntrees)
		return -ENODATA;
	t = calloc(f->ntrees, sizeof(*t));
	if (!t)
		return -ENOMEM;
	for (size_t i = 0; i < f->ntrees; i++) {
		const struct forest_tree *ft = &f->trees[i];
		const double *p = f->shown.trees[i].position;

		t[i] = (struct export_forest_tree){ &ft->planted->tree, &ft->planted->mesh,
						    &ft->planted->marks, ft->planted->seed, ft->number,
						    { p[0], p[1], p[2] } };
	}
	ret = export_glb_forest(t, f->ntrees, &wind, LIVE_WIND_COMMON_LOOP_S, out);
	free(t);
	/* the day's date: the one it began on at reset_at (after midnight, before reset_at,
	 * it is still yesterday's forest) */
	day = f->day.start ? (time_t)f->day.start : time(NULL);
	if (!localtime_r(&day, &tm) || strftime(date, 11, "%Y-%m-%d", &tm) != 10)
		snprintf(date, 11, "0000-00-00");
	return ret;
}
