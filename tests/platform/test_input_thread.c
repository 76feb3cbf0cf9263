/* SPDX-License-Identifier: MIT */
/* The input thread: a source's events reach the main side in order, through its fd,
 * while the main side is busy; a full queue drops the newest and says how many. */
#include <errno.h>
#include <poll.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "input_thread.h"
#include "test.h"

/* A source: each byte written to the pipe becomes n motion events. */
struct pipe_source {
	int fds[2];
	struct input_thread *t;
	int n;
	uint64_t next;
};

static int pipe_dispatch(void *data)
{
	struct pipe_source *p = data;
	char c;

	if (read(p->fds[0], &c, 1) != 1)
		return -1;
	for (int i = 0; i < p->n; i++) {
		struct event ev = { .type = EVENT_MOTION, .time_us = p->next++ };

		input_thread_emit(p->t, &ev);
	}
	return 0;
}

static void pause_ms(long ms)
{
	struct timespec ts = { 0, ms * 1000000L };

	nanosleep(&ts, NULL);
}

struct got {
	uint64_t count, next;
	bool in_order;
};

static void deliver(void *data, const struct event *ev)
{
	struct got *g = data;

	g->in_order &= ev->time_us == g->next;
	g->next = ev->time_us + 1;
	g->count++;
}

/* Waits on the main side's fd and dispatches until `want` events came (bounded). */
static void drain(struct input_thread *t, struct got *g, uint64_t want)
{
	struct kiosk_source src = input_thread_source(t);

	for (int tries = 0; g->count < want && tries < 500; tries++) {
		struct pollfd p = { .fd = src.fd, .events = POLLIN };

		if (poll(&p, 1, 10) > 0)
			CHECK_INT(src.dispatch(src.data), 0);
	}
}

int main(void)
{
	struct got g = { 0, 0, true };
	struct error err = { { 0 } };
	struct pipe_source p = { .n = 3 };
	struct input_thread *t = input_thread_create(deliver, &g, &err);
	struct kiosk_source src;

	CHECK(t);
	CHECK_INT(pipe(p.fds), 0);
	p.t = t;
	src = (struct kiosk_source){ .fd = p.fds[0], .dispatch = pipe_dispatch, .data = &p };
	CHECK_INT(input_thread_add(t, &src), 0);
	CHECK_INT(input_thread_start(t, &err), 0);
	CHECK_INT(input_thread_add(t, &src), -ENOSPC); /* not once it runs */

	/* 100 batches written while the main side does not look: all kept, in order */
	for (int i = 0; i < 100; i++)
		CHECK_INT(write(p.fds[1], "x", 1), 1);
	pause_ms(200);
	drain(t, &g, 300);
	CHECK_INT(g.count, 300);
	CHECK(g.in_order);
	CHECK_INT(input_thread_dropped(t), 0);

	/* more than the queue holds: the oldest stay, the excess is counted */
	input_thread_lock(t); /* the thread waits while locked: nothing is read meanwhile */
	p.n = INPUT_THREAD_QUEUE + 10;
	input_thread_unlock(t);
	CHECK_INT(write(p.fds[1], "x", 1), 1);
	pause_ms(200);
	drain(t, &g, 300 + INPUT_THREAD_QUEUE);
	CHECK_INT(g.count, 300 + INPUT_THREAD_QUEUE);
	CHECK(g.in_order);
	CHECK_INT(input_thread_dropped(t), 10);

	input_thread_destroy(t);
	close(p.fds[0]);
	close(p.fds[1]);
	return 0;
}
