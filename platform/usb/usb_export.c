/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* syncfs */
#include "usb_export.h"

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <time.h>
#include <unistd.h>

#include "config.h"
#include "export_set.h"
#include "fileio.h"
#include "gallery.h"
#include "usb_client.h"
#if HAVE_USB_MONITOR
#include "usb_monitor.h"
#endif

#define USB_MAX_STICKS 8
#define USB_QUEUE 8
/* the helper: mounting reads the FAT of a slow stick; ejecting writes it back */
#define USB_MOUNT_TIMEOUT_MS 30000
#define USB_EJECT_TIMEOUT_MS 60000
/* after a failed write: how long the kernel may take to say the stick is gone */
#define USB_GONE_WAIT_MS 1500

enum job_kind { JOB_PROBE, JOB_EXPORT };

struct job {
	enum job_kind kind;
	char kname[USB_PROTO_KNAME_MAX]; /* "": no stick, the local copy only */
	struct export_set *set;          /* JOB_EXPORT's, owned */
};

struct result {
	enum job_kind kind;
	char kname[USB_PROTO_KNAME_MAX];
	enum usb_outcome outcome;
	bool local_tried, local_ok;
};

enum stick_state { STICK_PROBING, STICK_READY, STICK_BAD };

struct stick {
	char kname[USB_PROTO_KNAME_MAX];
	enum stick_state state;
};

struct usb_export {
	struct usb_export_config cfg;
	char socket[128], local[256], sys_block[128];
#if HAVE_USB_MONITOR
	struct usb_monitor *mon;
#endif
	int wake_fd; /* eventfd: results wait */
	pthread_t thread;
	bool started;
	pthread_mutex_t lock; /* the queues and quit */
	pthread_cond_t cond;
	struct job jobs[USB_QUEUE];
	size_t njobs;
	struct result results[USB_QUEUE];
	size_t nresults;
	bool quit;
	/* the main thread's alone */
	struct stick sticks[USB_MAX_STICKS];
	size_t nsticks;
	bool saving;                           /* an export is queued or being written */
	char saving_kname[USB_PROTO_KNAME_MAX]; /* to which stick ("": none) */
	bool pulled;                           /* that stick went meanwhile */
};

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

enum app_status usb_export_status_of(enum usb_outcome o)
{
	switch (o) {
	case USB_OUTCOME_OK:
		return APP_STATUS_SAVED_USB;
	case USB_OUTCOME_PULLED:
		return APP_STATUS_STICK_PULLED;
	case USB_OUTCOME_FULL:
		return APP_STATUS_STICK_FULL;
	case USB_OUTCOME_READ_ONLY:
		return APP_STATUS_STICK_LOCKED;
	case USB_OUTCOME_UNUSABLE:
		return APP_STATUS_STICK_UNUSABLE;
	case USB_OUTCOME_FAILED:
		break;
	}
	return APP_STATUS_SAVE_FAILED;
}

/* ---- the thread -------------------------------------------------------------------- */

/* Whether the block device is still there (sysfs): a failed write on a stick that is
 * gone was a stick pulled. */
static bool present(const struct usb_export *ux, const char *kname, int wait_ms)
{
	char path[256];

	snprintf(path, sizeof(path), "%s/%s", ux->sys_block, kname);
	for (int waited = 0;; waited += 100) {
		struct timespec ts = { 0, 100 * 1000000L };

		if (access(path, F_OK) < 0)
			return false;
		if (waited >= wait_ms)
			return true;
		nanosleep(&ts, NULL);
	}
}

static void eject(struct usb_export *ux, const char *kname)
{
	struct usb_request req = { .op = USB_OP_EJECT };
	struct error err = { { 0 } };
	struct usb_answer ans;
	int fd;

	snprintf(req.kname, sizeof(req.kname), "%s", kname);
	if (usb_client_call(ux->socket, &req, USB_EJECT_TIMEOUT_MS, &ans, &fd, &err) < 0)
		fprintf(stderr, "edaha: usb: eject %s: %s\n", kname, err.msg);
	else if (ans.reason != USB_REASON_NONE)
		fprintf(stderr, "edaha: usb: eject %s: %s: %s\n", kname, usb_reason_name(ans.reason),
			ans.text);
}

/* Asks the helper to mount the stick: *dirfd its edaha/, or the outcome that tells why
 * not (the helper's reason; a helper that cannot be reached is a failure). */
static enum usb_outcome mount_stick(struct usb_export *ux, const char *kname, int *dirfd,
				    char *fstype, size_t size)
{
	struct usb_request req = { .op = USB_OP_MOUNT };
	struct error err = { { 0 } };
	struct usb_answer ans;
	int ret;

	snprintf(req.kname, sizeof(req.kname), "%s", kname);
	ret = usb_client_call(ux->socket, &req, USB_MOUNT_TIMEOUT_MS, &ans, dirfd, &err);
	if (ret < 0) {
		fprintf(stderr, "edaha: usb: %s: %s\n", kname, err.msg);
		/* it may have mounted it before the answer went astray */
		eject(ux, kname);
		return present(ux, kname, 0) ? USB_OUTCOME_FAILED : USB_OUTCOME_PULLED;
	}
	if (ans.reason != USB_REASON_NONE) {
		fprintf(stderr, "edaha: usb: %s cannot be used: %s (%s)\n", kname,
			usb_reason_name(ans.reason), ans.text);
		return usb_outcome_of(ans.reason, 0, present(ux, kname, 0));
	}
	snprintf(fstype, size, "%s", ans.fstype);
	return USB_OUTCOME_OK;
}

static enum usb_outcome probe(struct usb_export *ux, const char *kname)
{
	char fstype[USB_PROTO_FSTYPE_MAX];
	int dirfd = -1;
	enum usb_outcome o = mount_stick(ux, kname, &dirfd, fstype, sizeof(fstype));

	if (o == USB_OUTCOME_OK) {
		close(dirfd);
		eject(ux, kname);
		fprintf(stderr, "edaha: usb: %s (%s) is ready\n", kname, fstype);
	}
	return o;
}

/* The directory's gallery, after a set went in. A failure is said and no more: the set
 * stands, its files whole, and the old index.html is left as it was. */
static void write_gallery(const struct usb_export *ux, int dirfd, const char *where)
{
	struct error err = { { 0 } };
	size_t count = 0;

	if (gallery_write(dirfd, ux->cfg.language, &count, &err) < 0)
		fprintf(stderr,
			"edaha: gallery: %s/" GALLERY_FILE " not rewritten (the tree is saved): %s\n",
			where, err.msg);
	else
		fprintf(stderr, "edaha: gallery: %s/" GALLERY_FILE " lists %zu trees\n", where, count);
}

static enum usb_outcome save_to_stick(struct usb_export *ux, const char *kname,
				      struct export_set *set)
{
	char fstype[USB_PROTO_FSTYPE_MAX], base[32];
	struct error err = { { 0 } };
	double t0 = now_s();
	int dirfd = -1, ret;
	enum usb_outcome o = mount_stick(ux, kname, &dirfd, fstype, sizeof(fstype));

	if (o != USB_OUTCOME_OK)
		return o;
	fprintf(stderr, "edaha: usb: writing to %s (%s)\n", kname, fstype);
	ret = export_set_save(dirfd, set, base, sizeof(base), &err);
	if (ret == 0) {
		char where[USB_PROTO_KNAME_MAX + 8];

		snprintf(where, sizeof(where), "%s/edaha", kname);
		write_gallery(ux, dirfd, where);
	}
	/* on the stick, not in the cache, before anyone is told it may go */
	if (ret == 0 && syncfs(dirfd) < 0)
		ret = error_set(&err, -errno, "syncfs: %s", strerror(errno));
	close(dirfd);
	eject(ux, kname);
	o = usb_outcome_of(USB_REASON_NONE, ret,
			   ret == 0 || present(ux, kname,
					       ret == -ENOSPC || ret == -EFBIG ? 0 : USB_GONE_WAIT_MS));
	if (o == USB_OUTCOME_OK && set->forest_only)
		fprintf(stderr, "edaha: usb: saved %s to %s/edaha in %.1f s; unmounted, safe to pull\n",
			set->forest_name, kname, now_s() - t0);
	else if (o == USB_OUTCOME_OK)
		fprintf(stderr,
			"edaha: usb: saved %s.glb, .obj, .mtl, %s.edaha %s%sto %s/edaha in %.1f s; "
			"unmounted, safe to pull\n",
			base, set->files[EXPORT_SET_PNG].len ? ".png, " : "",
			set->forest_name[0] ? set->forest_name : "", set->forest_name[0] ? " " : "",
			kname, now_s() - t0);
	else
		fprintf(stderr, "edaha: usb: saving to %s failed (%s): %s\n", kname,
			usb_outcome_name(o), err.msg);
	return o;
}

static bool save_local(struct usb_export *ux, struct export_set *set)
{
	struct error err = { { 0 } };
	char base[32];
	int fd, ret;

	ret = fileio_mkdirs(ux->local, &err);
	if (ret == 0) {
		fd = open(ux->local, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
		if (fd < 0) {
			ret = error_set(&err, -errno, "%s", strerror(errno));
		} else {
			ret = export_set_save(fd, set, base, sizeof(base), &err);
			if (ret == 0)
				write_gallery(ux, fd, ux->local);
			close(fd);
		}
	}
	if (ret < 0)
		fprintf(stderr, "edaha: export to %s failed: %s\n", ux->local, err.msg);
	else if (set->forest_only)
		fprintf(stderr, "edaha: exported %s/%s\n", ux->local, set->forest_name);
	else
		fprintf(stderr, "edaha: exported %s/%s.glb, .obj, .mtl, %s.edaha%s%s\n", ux->local,
			base, set->files[EXPORT_SET_PNG].len ? ".png, " : "",
			set->forest_name[0] ? " and " : "", set->forest_name);
	return ret == 0;
}

static void run(struct usb_export *ux, struct job *job, struct result *res)
{
	memset(res, 0, sizeof(*res));
	res->kind = job->kind;
	memcpy(res->kname, job->kname, sizeof(res->kname));
	if (job->kind == JOB_PROBE) {
		res->outcome = probe(ux, job->kname);
		return;
	}
	/* the stick first: the visitor waits for it */
	if (job->kname[0])
		res->outcome = save_to_stick(ux, job->kname, job->set);
	if (ux->local[0]) {
		res->local_tried = true;
		res->local_ok = save_local(ux, job->set);
	}
}

static void free_job(struct job *job)
{
	if (job->set) {
		export_set_finish(job->set);
		free(job->set);
		job->set = NULL;
	}
}

static void *thread_main(void *data)
{
	struct usb_export *ux = data;

	pthread_mutex_lock(&ux->lock);
	for (;;) {
		struct job job;
		struct result res;
		uint64_t one = 1;

		while (!ux->quit && ux->njobs == 0)
			pthread_cond_wait(&ux->cond, &ux->lock);
		if (ux->quit)
			break;
		job = ux->jobs[0];
		memmove(ux->jobs, ux->jobs + 1, --ux->njobs * sizeof(*ux->jobs));
		pthread_mutex_unlock(&ux->lock);
		run(ux, &job, &res);
		free_job(&job);
		pthread_mutex_lock(&ux->lock);
		/* as many results as jobs fit: the main thread takes them before queueing more */
		if (ux->nresults < USB_QUEUE)
			ux->results[ux->nresults++] = res;
		if (write(ux->wake_fd, &one, sizeof(one)) < 0)
			fprintf(stderr, "edaha: usb: cannot wake the main loop: %s\n", strerror(errno));
	}
	pthread_mutex_unlock(&ux->lock);
	return NULL;
}

/* ---- the main thread ---------------------------------------------------------------- */

static int queue(struct usb_export *ux, const struct job *job)
{
	int ret = 0;

	pthread_mutex_lock(&ux->lock);
	/* results count too: each job makes one, and they have as much room */
	if (ux->njobs + ux->nresults >= USB_QUEUE) {
		ret = -ENOSPC;
	} else {
		ux->jobs[ux->njobs++] = *job;
		pthread_cond_signal(&ux->cond);
	}
	pthread_mutex_unlock(&ux->lock);
	return ret;
}

static void tell(struct usb_export *ux, enum app_status s, bool held)
{
	if (ux->cfg.status)
		ux->cfg.status(ux->cfg.data, s, held);
}

static struct stick *find(struct usb_export *ux, const char *kname)
{
	for (size_t i = 0; i < ux->nsticks; i++)
		if (strcmp(ux->sticks[i].kname, kname) == 0)
			return &ux->sticks[i];
	return NULL;
}

void usb_export_added(struct usb_export *ux, const char *kname)
{
	struct job job = { .kind = JOB_PROBE };
	struct stick *s;

	/* known already: a change event (udev's own after the helper's mount, say) */
	if (!ux->cfg.usb || !usb_proto_kname_valid(kname) || find(ux, kname))
		return;
	if (ux->nsticks >= USB_MAX_STICKS) {
		fprintf(stderr, "edaha: usb: %s ignored: %d sticks in already\n", kname, USB_MAX_STICKS);
		return;
	}
	s = &ux->sticks[ux->nsticks++];
	snprintf(s->kname, sizeof(s->kname), "%s", kname);
	s->state = STICK_PROBING;
	memcpy(job.kname, s->kname, sizeof(job.kname));
	fprintf(stderr, "edaha: usb: %s plugged in\n", kname);
	if (queue(ux, &job) < 0)
		fprintf(stderr, "edaha: usb: %s: too much to do; looked at when saving\n", kname);
}

void usb_export_removed(struct usb_export *ux, const char *kname)
{
	struct stick *s = find(ux, kname);

	if (!s)
		return;
	fprintf(stderr, "edaha: usb: %s removed\n", kname);
	*s = ux->sticks[--ux->nsticks];
	/* only news when it matters: while being written to */
	if (ux->saving && strcmp(ux->saving_kname, kname) == 0 && !ux->pulled) {
		ux->pulled = true;
		fprintf(stderr, "edaha: usb: %s pulled out while saving\n", kname);
		tell(ux, APP_STATUS_STICK_PULLED, false);
	}
}

bool usb_export_busy(const struct usb_export *ux)
{
	return ux->saving;
}

/* The stick to save to: one that was fine when put in, else any (a failed look may have
 * been the helper's, and saving says again why not). */
static const struct stick *choose(const struct usb_export *ux)
{
	for (size_t i = 0; i < ux->nsticks; i++)
		if (ux->sticks[i].state == STICK_READY)
			return &ux->sticks[i];
	for (size_t i = 0; i < ux->nsticks; i++)
		if (ux->sticks[i].state == STICK_PROBING)
			return &ux->sticks[i];
	return ux->nsticks ? &ux->sticks[0] : NULL;
}

void usb_export_start(struct usb_export *ux, const struct app *app, const uint8_t *rgba,
		      struct buf *forest, const char *forest_date)
{
	struct job job = { .kind = JOB_EXPORT };
	struct error err = { { 0 } };
	const struct stick *s = ux->cfg.usb ? choose(ux) : NULL;

	if (ux->saving) {
		fputs("edaha: export: the last one is still being saved; this press is ignored\n",
		      stderr);
		return;
	}
	if (ux->cfg.usb && !s) {
		fputs("edaha: usb: export with no stick in\n", stderr);
		tell(ux, APP_STATUS_NO_STICK, false);
		if (!ux->local[0])
			return;
	}
	job.set = malloc(sizeof(*job.set));
	if (!job.set) {
		fputs("edaha: export: out of memory\n", stderr);
		tell(ux, APP_STATUS_SAVE_FAILED, false);
		return;
	}
	export_set_init(job.set);
	job.set->wind = ux->cfg.wind;
	if (forest && forest->len && forest_date) {
		struct buf empty;

		/* moved, not copied: a class's forest may be tens of megabytes */
		buf_init(&empty);
		job.set->forest = *forest;
		*forest = empty;
		snprintf(job.set->forest_date, sizeof(job.set->forest_date), "%s", forest_date);
		/* an empty canvas on the forest: the forest alone, no empty tree beside it */
		job.set->forest_only = app->tree.nbranches == 0;
	}
	if (!job.set->forest_only && export_set_build(job.set, app, rgba, &err) < 0) {
		fprintf(stderr, "edaha: export failed: %s\n", err.msg);
		free_job(&job);
		tell(ux, APP_STATUS_SAVE_FAILED, false);
		return;
	}
	if (s)
		memcpy(job.kname, s->kname, sizeof(job.kname));
	if (queue(ux, &job) < 0) {
		fputs("edaha: export: too much to do; not saved\n", stderr);
		free_job(&job);
		tell(ux, APP_STATUS_SAVE_FAILED, false);
		return;
	}
	ux->saving = true;
	ux->pulled = false;
	memcpy(ux->saving_kname, job.kname, sizeof(ux->saving_kname));
	if (s)
		tell(ux, APP_STATUS_SAVING, true);
}

static void on_result(struct usb_export *ux, const struct result *r)
{
	struct stick *s = r->kname[0] ? find(ux, r->kname) : NULL;

	if (r->kind == JOB_PROBE) {
		if (!s)
			return; /* gone meanwhile */
		s->state = r->outcome == USB_OUTCOME_OK ? STICK_READY : STICK_BAD;
		/* a save under way has the screen; a helper not there is no news for a child */
		if (!ux->saving && r->outcome != USB_OUTCOME_FAILED && r->outcome != USB_OUTCOME_PULLED)
			tell(ux, r->outcome == USB_OUTCOME_OK ? APP_STATUS_STICK_READY
							     : usb_export_status_of(r->outcome),
			     false);
		return;
	}
	ux->saving = false;
	if (r->kname[0]) {
		enum usb_outcome o = ux->pulled && r->outcome != USB_OUTCOME_OK ? USB_OUTCOME_PULLED
										 : r->outcome;

		if (s)
			s->state = o == USB_OUTCOME_OK ? STICK_READY : s->state;
		tell(ux, usb_export_status_of(o), false);
	} else if (!ux->cfg.usb) {
		/* no sticks at all: the local copy is the export */
		tell(ux, r->local_ok ? APP_STATUS_SAVED : APP_STATUS_SAVE_FAILED, false);
	}
}

static int dispatch_results(void *data)
{
	struct usb_export *ux = data;
	struct result res[USB_QUEUE];
	uint64_t n;
	size_t count;

	if (read(ux->wake_fd, &n, sizeof(n)) < 0 && errno != EAGAIN)
		return -errno;
	pthread_mutex_lock(&ux->lock);
	count = ux->nresults;
	memcpy(res, ux->results, count * sizeof(*res));
	ux->nresults = 0;
	pthread_mutex_unlock(&ux->lock);
	for (size_t i = 0; i < count; i++)
		on_result(ux, &res[i]);
	return 0;
}

#if HAVE_USB_MONITOR
static void on_monitor(void *data, const struct usb_monitor_event *ev)
{
	if (ev->action == USB_MONITOR_ADDED)
		usb_export_added(data, ev->kname);
	else
		usb_export_removed(data, ev->kname);
}

static int dispatch_monitor(void *data)
{
	struct usb_export *ux = data;

	return usb_monitor_dispatch(ux->mon, on_monitor, ux);
}
#endif

size_t usb_export_sources(struct usb_export *ux, struct kiosk_source *out, size_t max)
{
	size_t n = 0;

	if (n < max)
		out[n++] = (struct kiosk_source){ ux->wake_fd, dispatch_results, ux };
#if HAVE_USB_MONITOR
	if (ux->mon && n < max)
		out[n++] = (struct kiosk_source){ usb_monitor_fd(ux->mon), dispatch_monitor, ux };
#endif
	return n;
}

struct usb_export *usb_export_create(const struct usb_export_config *cfg, struct error *err)
{
	struct usb_export *ux = calloc(1, sizeof(*ux));
	int ret;

	if (!ux) {
		error_set(err, -ENOMEM, "usb: out of memory");
		return NULL;
	}
	ux->cfg = *cfg;
	ux->wake_fd = -1;
	snprintf(ux->socket, sizeof(ux->socket), "%s", cfg->helper_socket ? cfg->helper_socket : "");
	snprintf(ux->local, sizeof(ux->local), "%s", cfg->local_dir ? cfg->local_dir : "");
	snprintf(ux->sys_block, sizeof(ux->sys_block), "%s",
		 cfg->sys_block ? cfg->sys_block : "/sys/class/block");
	pthread_mutex_init(&ux->lock, NULL);
	pthread_cond_init(&ux->cond, NULL);
	ux->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	if (ux->wake_fd < 0) {
		error_set(err, -errno, "usb: eventfd: %s", strerror(errno));
		goto fail;
	}
	ret = pthread_create(&ux->thread, NULL, thread_main, ux);
	if (ret != 0) {
		error_set(err, -ret, "usb: cannot start its thread: %s", strerror(ret));
		goto fail;
	}
	ux->started = true;
#if HAVE_USB_MONITOR
	if (cfg->usb && cfg->monitor) {
		struct error merr = { { 0 } };

		ux->mon = usb_monitor_create(&merr);
		if (!ux->mon)
			fprintf(stderr, "edaha: warning: %s\n", merr.msg);
		else if ((ret = usb_monitor_enumerate(ux->mon, on_monitor, ux)) < 0)
			fprintf(stderr, "edaha: warning: usb: cannot list the sticks in: %s\n",
				strerror(-ret));
	}
#else
	if (cfg->usb && cfg->monitor)
		fputs("edaha: warning: usb: built without libudev, so no sticks are seen\n", stderr);
#endif
	return ux;

fail:
	usb_export_destroy(ux);
	return NULL;
}

void usb_export_destroy(struct usb_export *ux)
{
	if (!ux)
		return;
	if (ux->started) {
		pthread_mutex_lock(&ux->lock);
		ux->quit = true;
		pthread_cond_signal(&ux->cond);
		pthread_mutex_unlock(&ux->lock);
		pthread_join(ux->thread, NULL);
	}
	for (size_t i = 0; i < ux->njobs; i++)
		free_job(&ux->jobs[i]);
#if HAVE_USB_MONITOR
	usb_monitor_destroy(ux->mon);
#endif
	if (ux->wake_fd >= 0)
		close(ux->wake_fd);
	pthread_cond_destroy(&ux->cond);
	pthread_mutex_destroy(&ux->lock);
	free(ux);
}
