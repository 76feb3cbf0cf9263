/* SPDX-License-Identifier: MIT */
#include "seat.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "config.h"
#if HAVE_LIBSEAT
#include <libseat.h>
#endif

/* How long a daemon may take to let us onto the seat at start. */
#define SEAT_WAIT_MS 5000
/* Cards tried at start are opened one by one: a few at a time at most. */
#define SEAT_MAX_DEVICES 8

struct seat_device {
	int fd, id;
};

struct seat {
	struct seat_listener listener; /* set once the seat is ours: not during create */
	void *data;
	bool active;
	char name[64];
#if HAVE_LIBSEAT
	struct libseat *ls; /* NULL: devices are opened directly */
	struct seat_device devices[SEAT_MAX_DEVICES];
	size_t ndevices;
#endif
};

#if HAVE_LIBSEAT
static void enable_seat(struct libseat *ls, void *data)
{
	struct seat *s = data;

	(void)ls;
	s->active = true;
	if (s->listener.enable)
		s->listener.enable(s->data);
}

static void disable_seat(struct libseat *ls, void *data)
{
	struct seat *s = data;

	s->active = false;
	if (s->listener.disable)
		s->listener.disable(s->data);
	/* the daemon waits for this before it lets the other VT in */
	if (libseat_disable_seat(ls) < 0)
		fprintf(stderr, "edaha: seat: cannot acknowledge the switch: %s\n", strerror(errno));
}

static const struct libseat_seat_listener libseat_listener = {
	.enable_seat = enable_seat,
	.disable_seat = disable_seat,
};

static void log_libseat(enum libseat_log_level level, const char *fmt, va_list args)
{
	(void)level;
	fputs("edaha: seat: ", stderr);
	vfprintf(stderr, fmt, args);
	fputc('\n', stderr);
}

static int64_t now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

/*
 * A seat from a daemon: seatd, then logind. libseat would go on to its builtin backend,
 * which forks a seat server inside edaha; without a daemon we open devices ourselves
 * instead. LIBSEAT_BACKEND, when set, is libseat's to follow.
 */
static struct libseat *open_libseat(struct seat *s)
{
	static const char *const daemons[] = { "seatd", "logind" };
	const char *forced = getenv("LIBSEAT_BACKEND");
	struct libseat *ls = NULL;

	/* libseat says why each backend failed; a kiosk without a daemon is normal */
	libseat_set_log_level(LIBSEAT_LOG_LEVEL_SILENT);
	if (forced && forced[0]) {
		snprintf(s->name, sizeof(s->name), "libseat (%s)", forced);
		ls = libseat_open_seat(&libseat_listener, s);
	} else {
		/* no other thread runs yet: the environment is ours to change */
		for (size_t i = 0; !ls && i < sizeof(daemons) / sizeof(daemons[0]); i++) {
			if (setenv("LIBSEAT_BACKEND", daemons[i], 1) < 0)
				break;
			snprintf(s->name, sizeof(s->name), "libseat (%s)", daemons[i]);
			ls = libseat_open_seat(&libseat_listener, s);
		}
		unsetenv("LIBSEAT_BACKEND");
	}
	libseat_set_log_handler(log_libseat);
	libseat_set_log_level(LIBSEAT_LOG_LEVEL_ERROR);
	return ls;
}

/* The daemon enables the seat after opening it, when our VT is in front. */
static int wait_active(struct seat *s, struct error *err)
{
	int64_t deadline = now_ms() + SEAT_WAIT_MS;

	while (!s->active) {
		int64_t left = deadline - now_ms();

		if (left <= 0)
			return error_set(err, -ETIMEDOUT, "%s: %s not enabled within %d s (is another "
					 "VT in front?)", s->name, libseat_seat_name(s->ls),
					 SEAT_WAIT_MS / 1000);
		if (libseat_dispatch(s->ls, (int)left) < 0)
			return error_set(err, -errno, "%s: %s", s->name, strerror(errno));
	}
	return 0;
}
#endif

struct seat *seat_create(const struct seat_listener *listener, void *data, struct error *err)
{
	struct seat *s = calloc(1, sizeof(*s));

	if (!s) {
		error_set(err, -ENOMEM, "seat: out of memory");
		return NULL;
	}
#if HAVE_LIBSEAT
	s->ls = open_libseat(s);
	if (s->ls && wait_active(s, err) < 0) {
		seat_destroy(s);
		return NULL;
	}
	if (!s->ls)
#endif
	{
		snprintf(s->name, sizeof(s->name), "direct");
		s->active = true;
	}
	if (listener)
		s->listener = *listener;
	s->data = data;
	return s;
}

void seat_destroy(struct seat *s)
{
	if (!s)
		return;
#if HAVE_LIBSEAT
	while (s->ndevices > 0)
		seat_close(s, s->devices[s->ndevices - 1].fd);
	if (s->ls && libseat_close_seat(s->ls) < 0)
		fprintf(stderr, "edaha: seat: cannot close it: %s\n", strerror(errno));
#endif
	free(s);
}

const char *seat_describe(const struct seat *s)
{
	return s->name;
}

int seat_fd(const struct seat *s)
{
#if HAVE_LIBSEAT
	if (s->ls)
		return libseat_get_fd(s->ls);
#else
	(void)s;
#endif
	return -1;
}

int seat_dispatch(struct seat *s)
{
#if HAVE_LIBSEAT
	if (s->ls && libseat_dispatch(s->ls, 0) < 0)
		return errno ? -errno : -EIO;
#else
	(void)s;
#endif
	return 0;
}

bool seat_active(const struct seat *s)
{
	return s->active;
}

int seat_open(struct seat *s, const char *path)
{
	int fd;

#if HAVE_LIBSEAT
	if (s->ls) {
		int id;

		if (s->ndevices == SEAT_MAX_DEVICES)
			return -EMFILE;
		id = libseat_open_device(s->ls, path, &fd);
		if (id < 0)
			return errno ? -errno : -EIO;
		/* the daemon's fd arrives without close-on-exec */
		if (fcntl(fd, F_SETFD, FD_CLOEXEC) < 0) {
			int ret = -errno;

			libseat_close_device(s->ls, id);
			close(fd);
			return ret;
		}
		s->devices[s->ndevices++] = (struct seat_device){ fd, id };
		return fd;
	}
#else
	(void)s;
#endif
	fd = open(path, O_RDWR | O_CLOEXEC | O_NOCTTY);
	return fd < 0 ? -errno : fd;
}

void seat_close(struct seat *s, int fd)
{
#if HAVE_LIBSEAT
	for (size_t i = 0; i < s->ndevices; i++) {
		if (s->devices[i].fd != fd)
			continue;
		if (libseat_close_device(s->ls, s->devices[i].id) < 0)
			fprintf(stderr, "edaha: seat: cannot give a device back: %s\n",
				strerror(errno));
		s->devices[i] = s->devices[--s->ndevices];
		break;
	}
#else
	(void)s;
#endif
	if (close(fd) < 0)
		fprintf(stderr, "edaha: close: %s\n", strerror(errno));
}
