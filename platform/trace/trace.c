/* SPDX-License-Identifier: MIT */
#include "trace.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "trace_private.h"

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

const char *trace_quote(const char *s, size_t len, char *buf, size_t size)
{
	size_t o = 0, i;

	/* Leaves room for one more escape, "...", the closing quote and the NUL. */
	buf[o++] = '"';
	for (i = 0; i < len && o + 8 < size; i++) {
		unsigned char c = (unsigned char)s[i];

		if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\')
			buf[o++] = (char)c;
		else
			o += (size_t)snprintf(buf + o, size - o, "\\x%02x", c);
	}
	if (i < len) {
		memcpy(buf + o, "...", 3);
		o += 3;
	}
	buf[o++] = '"';
	buf[o] = '\0';
	return buf;
}

double trace_clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
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

int trace_load(const char *path, int screen_w, int screen_h, struct trace *t, struct error *err)
{
	char *data;
	size_t len;
	int r;

	r = fileio_read_all(path, TRACE_MAX_FILE_SIZE, &data, &len, err);
	if (r < 0) {
		trace_finish(t);
		return r;
	}
	r = trace_parse(data, len, path, screen_w, screen_h, t, err);
	free(data);
	return r;
}
