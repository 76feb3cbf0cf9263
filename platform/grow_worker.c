/* SPDX-License-Identifier: MIT */
/* The kiosk's grow presses on a thread of their own (grow_worker.h). */
#include "grow_worker.h"

#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>

struct grow_worker {
	int fd;
	pthread_t thread;
	bool running; /* a thread to join */
	/* the job: set before the thread starts, read back after it is joined */
	struct tree *tree;
	struct wood_params p;
	uint64_t serial;
	int result;
};

struct grow_worker *grow_worker_create(struct error *err)
{
	struct grow_worker *w = calloc(1, sizeof(*w));

	if (!w) {
		error_set(err, -ENOMEM, "out of memory");
		return NULL;
	}
	w->fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	if (w->fd < 0) {
		error_set(err, -errno, "eventfd: %s", strerror(errno));
		free(w);
		return NULL;
	}
	return w;
}

static void *grow(void *arg)
{
	struct grow_worker *w = arg;
	uint64_t one = 1;

	w->result = wood_grow(w->tree, &w->p);
	/* the loop wakes: a failed write leaves it to the next press's poll, never lost */
	while (write(w->fd, &one, sizeof(one)) < 0 && errno == EINTR)
		;
	return NULL;
}

static void join(struct grow_worker *w)
{
	uint64_t n;

	if (!w->running)
		return;
	pthread_join(w->thread, NULL);
	w->running = false;
	while (read(w->fd, &n, sizeof(n)) < 0 && errno == EINTR)
		;
}

void grow_worker_destroy(struct grow_worker *w)
{
	if (!w)
		return;
	join(w);
	if (w->tree) {
		tree_finish(w->tree);
		free(w->tree);
	}
	close(w->fd);
	free(w);
}

int grow_worker_fd(const struct grow_worker *w)
{
	return w->fd;
}

bool grow_worker_busy(const struct grow_worker *w)
{
	return w->running;
}

int grow_worker_start(struct grow_worker *w, struct tree *t, const struct wood_params *p,
		      uint64_t serial)
{
	int ret;

	if (w->running)
		return -EBUSY;
	w->tree = t;
	w->p = *p;
	w->serial = serial;
	w->result = 0;
	ret = pthread_create(&w->thread, NULL, grow, w);
	if (ret != 0) {
		w->tree = NULL;
		return -ret;
	}
	w->running = true;
	return 0;
}

int grow_worker_take(struct grow_worker *w, struct tree **t, int *result, uint64_t *serial)
{
	uint64_t n;

	if (!w->running)
		return -EAGAIN;
	/* done only once the thread has said so */
	if (read(w->fd, &n, sizeof(n)) < 0)
		return -EAGAIN;
	pthread_join(w->thread, NULL);
	w->running = false;
	*t = w->tree;
	*result = w->result;
	*serial = w->serial;
	w->tree = NULL;
	return 0;
}
