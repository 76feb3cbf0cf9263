/* SPDX-License-Identifier: MIT */
#include "trace.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A replay is a few hours of pen input at most; anything bigger is a mistake. */
#define TRACE_MAX_FILE_SIZE ((size_t)256 * 1024 * 1024)

void trace_init(struct trace *t)
{
	memset(t, 0, sizeof(*t));
}

void trace_finish(struct trace *t)
{
	free(t->events);
	trace_init(t);
}

int trace_append(struct trace *t, const struct event *ev)
{
	if (t->nevents == t->cap) {
		size_t cap = t->cap ? t->cap * 2 : 256;
		struct event *events;

		if (cap > SIZE_MAX / sizeof(*events))
			return -ENOMEM;
		events = realloc(t->events, cap * sizeof(*events));
		if (!events)
			return -ENOMEM;
		t->events = events;
		t->cap = cap;
	}
	t->events[t->nevents++] = *ev;
	return 0;
}

static bool is_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r';
}

/*
 * True if the first line that is neither blank nor a comment starts with the word
 * "edaha-trace". libinput recordings start with "# libinput record" and then YAML keys,
 * so comments are skipped for both.
 */
static bool looks_like_edaha(const char *data, size_t len)
{
	static const char magic[] = "edaha-trace";
	const size_t n = sizeof(magic) - 1;
	size_t i = 0;

	if (len >= 3 && memcmp(data, "\xef\xbb\xbf", 3) == 0)
		i = 3; /* a UTF-8 byte order mark */

	while (i < len) {
		size_t start;

		while (i < len && is_blank(data[i]))
			i++;
		start = i;
		if (i < len && data[i] != '\n' && data[i] != '#') {
			if (len - start < n || memcmp(data + start, magic, n) != 0)
				return false;
			return len - start == n || is_blank(data[start + n]) ||
			       data[start + n] == '\n';
		}
		while (i < len && data[i] != '\n')
			i++;
		i++; /* the '\n' */
	}
	return false;
}

static bool is_empty(const char *data, size_t len)
{
	size_t i = 0;

	while (i < len) {
		while (i < len && is_blank(data[i]))
			i++;
		if (i < len && data[i] != '\n' && data[i] != '#')
			return false;
		while (i < len && data[i] != '\n')
			i++;
		i++;
	}
	return true;
}

int trace_parse(const char *data, size_t len, const char *name, int screen_w, int screen_h,
		struct trace *t, struct error *err)
{
	if (is_empty(data, len)) {
		trace_finish(t);
		return error_at(err, -EINVAL, name, 0,
				"empty file: neither an edaha trace nor a libinput recording");
	}
	if (looks_like_edaha(data, len))
		return trace_parse_edaha(data, len, name, screen_w, screen_h, t, err);
	return trace_parse_libinput(data, len, name, screen_w, screen_h, t, err);
}

/* Reads all of fd into a malloc'ed buffer; pipes and /proc files have no usable st_size. */
static int read_all(int fd, const char *path, char **out, size_t *out_len, struct error *err)
{
	size_t cap = 64 * 1024, len = 0;
	char *data = malloc(cap);

	if (!data)
		return error_at(err, -ENOMEM, path, 0, "out of memory");
	for (;;) {
		ssize_t n;

		if (len == cap) {
			char *bigger;

			if (cap > TRACE_MAX_FILE_SIZE) {
				free(data);
				return error_at(err, -EFBIG, path, 0,
						"file too large (limit %zu MiB)",
						TRACE_MAX_FILE_SIZE >> 20);
			}
			cap *= 2;
			bigger = realloc(data, cap);
			if (!bigger) {
				free(data);
				return error_at(err, -ENOMEM, path, 0, "out of memory");
			}
			data = bigger;
		}
		n = read(fd, data + len, cap - len);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0) {
			int r = -errno;

			free(data);
			return error_at(err, r, path, 0, "%s", strerror(-r));
		}
		if (n == 0)
			break;
		len += (size_t)n;
	}
	if (len > TRACE_MAX_FILE_SIZE) {
		free(data);
		return error_at(err, -EFBIG, path, 0, "file too large (limit %zu MiB)",
				TRACE_MAX_FILE_SIZE >> 20);
	}
	*out = data;
	*out_len = len;
	return 0;
}

int trace_load(const char *path, int screen_w, int screen_h, struct trace *t, struct error *err)
{
	struct stat st;
	char *data = NULL;
	size_t len = 0;
	int fd, r;

	fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0) {
		r = -errno;
		trace_finish(t);
		return error_at(err, r, path, 0, "%s", strerror(-r));
	}
	/* Refuse early, before reading 256 MiB only to throw it away. */
	if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
	    (uintmax_t)st.st_size > (uintmax_t)TRACE_MAX_FILE_SIZE) {
		close(fd);
		trace_finish(t);
		return error_at(err, -EFBIG, path, 0,
				"file too large (%jd bytes, limit %zu MiB)", (intmax_t)st.st_size,
				TRACE_MAX_FILE_SIZE >> 20);
	}
	r = read_all(fd, path, &data, &len, err);
	close(fd);
	if (r < 0) {
		trace_finish(t);
		return r;
	}
	r = trace_parse(data, len, path, screen_w, screen_h, t, err);
	free(data);
	return r;
}
