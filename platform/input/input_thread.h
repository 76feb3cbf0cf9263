/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The kiosk's input sources (libinput, GPIO) read on a thread of their own. A frame that
 * takes long (a slow board, a huge tree, an emulated CPU) would otherwise leave the
 * kernel's event buffers to overflow and libinput's timers to fire late, and strokes
 * would lose points or break. The thread dispatches the sources as soon as they are
 * readable; their events wait in a queue, with their kernel timestamps, until the main
 * loop takes them through input_thread_source(). Anything else done with the sources
 * while the thread runs (the LEDs, a new screen size) goes between input_thread_lock()
 * and input_thread_unlock().
 */
#include <stddef.h>

#include "error.h"
#include "input_source.h"

/* Events that may wait; past this the newest are dropped (and counted) until the main
 * loop catches up: 20 s of a pen at 200 Hz. */
#define INPUT_THREAD_QUEUE 4096
#define INPUT_THREAD_MAX_SOURCES 8

struct input_thread;

/* deliver(data, ev) gets every queued event, in order, on the main loop's thread. */
struct input_thread *input_thread_create(input_emit_fn deliver, void *data, struct error *err);
/* Stops the thread (if started) and frees the queue; the sources are the caller's. */
void input_thread_destroy(struct input_thread *t);

/* The emit function to give the sources, with the thread as data: queues ev. */
void input_thread_emit(void *t, const struct event *ev);
/* Before input_thread_start: a source for the thread to dispatch. 0 or -ENOSPC. */
int input_thread_add(struct input_thread *t, const struct kiosk_source *src);
/* 0 or a negative errno. */
int input_thread_start(struct input_thread *t, struct error *err);

/* For the main loop: readable while events wait; its dispatch delivers them. */
struct kiosk_source input_thread_source(struct input_thread *t);
int input_thread_dispatch(void *t);

void input_thread_lock(struct input_thread *t);
void input_thread_unlock(struct input_thread *t);
/* Events dropped because the queue was full, since the start. */
unsigned long input_thread_dropped(struct input_thread *t);
