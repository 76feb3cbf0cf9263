/* SPDX-License-Identifier: MIT */
#include "input_thread.h"

#include <errno.h>
#include <poll.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>

struct input_thread {
	input_emit_fn deliver;
	void *data;
	struct kiosk_source sources[INPUT_THREAD_MAX_SOURCES];
	size_t nsources;
	pthread_t thread;
	bool started;
	int ready_fd; /* eventfd: events wait (written by the thread) */
	int stop_fd;  /* eventfd: the thread is to end (written by destroy) */
	/* the sources, while the thread dispatches them */
	pthread_mutex_t lock;
	/* the queue: a ring, head is the oldest */
	pthread_mutex_t qlock;
	struct event *queue;
	size_t head, count;
	unsigned long dropped, dropped_told;
};

struct input_thread *input_thread_create(input_emit_fn deliver, void *data, struct error *err)
{
	struct input_thread *t = calloc(1, sizeof(*t));

	if (!t || !(t->queue = calloc(INPUT_THREAD_QUEUE, sizeof(*t->queue)))) {
		free(t);
		error_set(err, -ENOMEM, "input: out of memory");
		return NULL;
	}
	t->deliver = deliver;
	t->data = data;
	t->ready_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	t->stop_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	if (t->ready_fd < 0 || t->stop_fd < 0) {
		error_set(err, -errno, "input: eventfd: %s", strerror(errno));
		if (t->ready_fd >= 0)
			close(t->ready_fd);
		if (t->stop_fd >= 0)
			close(t->stop_fd);
		free(t->queue);
		free(t);
		return NULL;
	}
	pthread_mutex_init(&t->lock, NULL);
	pthread_mutex_init(&t->qlock, NULL);
	return t;
}

void input_thread_destroy(struct input_thread *t)
{
	uint64_t one = 1;

	if (!t)
		return;
	if (t->started) {
		if (write(t->stop_fd, &one, sizeof(one)) != (ssize_t)sizeof(one))
			fprintf(stderr, "edaha: input: cannot stop the input thread: %s\n",
				strerror(errno));
		else
			pthread_join(t->thread, NULL);
	}
	pthread_mutex_destroy(&t->lock);
	pthread_mutex_destroy(&t->qlock);
	close(t->ready_fd);
	close(t->stop_fd);
	free(t->queue);
	free(t);
}

void input_thread_emit(void *data, const struct event *ev)
{
	struct input_thread *t = data;
	uint64_t one = 1;
	bool was_empty;

	pthread_mutex_lock(&t->qlock);
	was_empty = t->count == 0;
	if (t->count < INPUT_THREAD_QUEUE) {
		t->queue[(t->head + t->count) % INPUT_THREAD_QUEUE] = *ev;
		t->count++;
	} else {
		t->dropped++;
	}
	pthread_mutex_unlock(&t->qlock);
	/* one wake-up per batch: the main loop drains the whole queue when it wakes */
	if (was_empty && write(t->ready_fd, &one, sizeof(one)) < 0 && errno != EAGAIN)
		fprintf(stderr, "edaha: input: cannot wake the main loop: %s\n", strerror(errno));
}

int input_thread_add(struct input_thread *t, const struct kiosk_source *src)
{
	if (t->started || t->nsources >= INPUT_THREAD_MAX_SOURCES)
		return -ENOSPC;
	t->sources[t->nsources++] = *src;
	return 0;
}

static void *run(void *data)
{
	struct input_thread *t = data;
	struct pollfd fds[1 + INPUT_THREAD_MAX_SOURCES];

	for (;;) {
		size_t n = t->nsources;

		fds[0] = (struct pollfd){ .fd = t->stop_fd, .events = POLLIN };
		for (size_t i = 0; i < n; i++)
			fds[1 + i] = (struct pollfd){ .fd = t->sources[i].fd, .events = POLLIN };
		if (poll(fds, 1 + n, -1) < 0) {
			if (errno == EINTR)
				continue;
			fprintf(stderr, "edaha: input: poll: %s; no more input\n", strerror(errno));
			return NULL;
		}
		if (fds[0].revents)
			return NULL;
		pthread_mutex_lock(&t->lock);
		/* backwards, so that dropping a failed source leaves the rest in place */
		for (size_t i = n; i-- > 0;) {
			int ret;

			if (!fds[1 + i].revents)
				continue;
			ret = t->sources[i].dispatch(t->sources[i].data);
			if (ret < 0) {
				/* the others still work: drop this one and carry on */
				fprintf(stderr, "edaha: input source %zu failed (%s); ignoring it from now on\n",
					i, strerror(-ret));
				t->sources[i] = t->sources[--t->nsources];
			}
		}
		pthread_mutex_unlock(&t->lock);
	}
}

int input_thread_start(struct input_thread *t, struct error *err)
{
	int ret = pthread_create(&t->thread, NULL, run, t);

	if (ret != 0)
		return error_set(err, -ret, "input: cannot start a thread: %s", strerror(ret));
	t->started = true;
	return 0;
}

struct kiosk_source input_thread_source(struct input_thread *t)
{
	return (struct kiosk_source){ .fd = t->ready_fd, .dispatch = input_thread_dispatch,
				      .data = t };
}

int input_thread_dispatch(void *data)
{
	struct input_thread *t = data;
	struct event batch[64];
	uint64_t value;
	unsigned long dropped;
	size_t n;

	/* reset before draining: an event queued from now on wakes the loop again */
	if (read(t->ready_fd, &value, sizeof(value)) < 0 && errno != EAGAIN)
		return -errno;
	do {
		pthread_mutex_lock(&t->qlock);
		n = t->count < 64 ? t->count : 64;
		for (size_t i = 0; i < n; i++)
			batch[i] = t->queue[(t->head + i) % INPUT_THREAD_QUEUE];
		t->head = (t->head + n) % INPUT_THREAD_QUEUE;
		t->count -= n;
		dropped = t->dropped;
		pthread_mutex_unlock(&t->qlock);
		for (size_t i = 0; i < n; i++)
			t->deliver(t->data, &batch[i]);
	} while (n == 64);
	if (dropped != t->dropped_told) {
		fprintf(stderr, "edaha: input: the app fell behind; %lu events dropped\n",
			dropped - t->dropped_told);
		t->dropped_told = dropped;
	}
	return 0;
}

void input_thread_lock(struct input_thread *t)
{
	pthread_mutex_lock(&t->lock);
}

void input_thread_unlock(struct input_thread *t)
{
	pthread_mutex_unlock(&t->lock);
}

unsigned long input_thread_dropped(struct input_thread *t)
{
	unsigned long d;

	pthread_mutex_lock(&t->qlock);
	d = t->dropped;
	pthread_mutex_unlock(&t->qlock);
	return d;
}
