/* SPDX-License-Identifier: MIT */
/*
 * The edaha trace text format, version 1 (docs/trace-format.md): one event a line,
 * whitespace separated fields, positions in pixels of the `screen` the file declares.
 */
#include "trace.h"
#include "trace_private.h"

#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TRACE_VERSION 1
/* The longest valid line has 10 fields; one more tells "trailing garbage" apart. */
#define MAX_FIELDS 11
#define MAX_SCREEN 65535

struct edaha_parser {
	const char *name;
	struct error *err;
	const char *data;
	size_t len, pos;
	unsigned long lineno;

	/* The current line, NUL-terminated and cut into fields in place. */
	char *line;
	size_t line_cap;
	char *fields[MAX_FIELDS];
	size_t nfields; /* all fields on the line, even past MAX_FIELDS */

	int screen_w, screen_h; /* what the caller wants */
	long file_w, file_h;    /* what the file says */
	uint64_t last_time;
	struct trace out;
};

#define Q(s) TRACE_Q((s), strlen(s))

static int fail(struct edaha_parser *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static int fail(struct edaha_parser *p, const char *fmt, ...)
{
	char msg[sizeof(p->err->msg)];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	return error_at(p->err, -EINVAL, p->name, p->lineno, "%s", msg);
}

static bool is_space(char c)
{
	return c == ' ' || c == '\t';
}

/* Copies the next line into p->line (grown as needed: lines have no length limit). */
static int copy_line(struct edaha_parser *p)
{
	const char *start = p->data + p->pos;
	const char *nl = memchr(start, '\n', p->len - p->pos);
	size_t n = nl ? (size_t)(nl - start) : p->len - p->pos;

	p->pos += n + (nl ? 1 : 0);
	p->lineno++;
	if (n > 0 && start[n - 1] == '\r')
		n--;
	if (memchr(start, '\0', n))
		return fail(p, "NUL byte in line: this is not a text file");
	if (n + 1 > p->line_cap) {
		size_t cap = p->line_cap ? p->line_cap : 256;
		char *line;

		while (cap < n + 1)
			cap *= 2;
		line = realloc(p->line, cap);
		if (!line)
			return error_at(p->err, -ENOMEM, p->name, p->lineno, "out of memory");
		p->line = line;
		p->line_cap = cap;
	}
	memcpy(p->line, start, n);
	p->line[n] = '\0';
	return 0;
}

static void split_fields(struct edaha_parser *p)
{
	char *s = p->line;

	p->nfields = 0;
	for (;;) {
		while (is_space(*s))
			s++;
		if (!*s)
			break;
		if (p->nfields < MAX_FIELDS)
			p->fields[p->nfields] = s;
		p->nfields++;
		while (*s && !is_space(*s))
			s++;
		if (*s)
			*s++ = '\0';
	}
}

/* Reads up to the next line that is not blank or a comment: 1, 0 at the end, or < 0. */
static int next_line(struct edaha_parser *p)
{
	while (p->pos < p->len) {
		int r = copy_line(p);

		if (r < 0)
			return r;
		split_fields(p);
		if (p->nfields > 0 && p->fields[0][0] != '#')
			return 1;
	}
	return 0;
}

static bool parse_uint(const char *s, uint64_t *v)
{
	unsigned long long u;
	char *end;

	/* strtoull would take a sign, spaces or "0x"; a plain run of digits only. */
	if (!isdigit((unsigned char)s[0]))
		return false;
	for (const char *c = s; *c; c++)
		if (!isdigit((unsigned char)*c))
			return false;
	errno = 0;
	u = strtoull(s, &end, 10);
	if (errno == ERANGE || *end)
		return false;
	*v = (uint64_t)u;
	return true;
}

static int parse_number(struct edaha_parser *p, const char *s, const char *what, double *v)
{
	char *end;
	double d;

	errno = 0;
	d = strtod(s, &end);
	if (end == s || *end)
		return fail(p, "bad number %s for %s", Q(s), what);
	if (!isfinite(d))
		return fail(p, "%s %s is not a finite number", what, Q(s));
	/* Decimal only, as the writer prints: no hex floats. Tiny values (ERANGE) are fine. */
	if (strpbrk(s, "xXpP"))
		return fail(p, "bad number %s for %s", Q(s), what);
	*v = d;
	return 0;
}

static int parse_ranged(struct edaha_parser *p, const char *s, const char *what, double lo,
			double hi, double *v)
{
	int r = parse_number(p, s, what, v);

	if (r < 0)
		return r;
	if (*v < lo || *v > hi)
		return fail(p, "%s %s out of range %g..%g", what, s, lo, hi);
	return 0;
}

static int parse_pressed(struct edaha_parser *p, const char *s, bool *pressed)
{
	if (strcmp(s, "pressed") == 0)
		*pressed = true;
	else if (strcmp(s, "released") == 0)
		*pressed = false;
	else
		return fail(p, "expected pressed or released, got %s", Q(s));
	return 0;
}

static int expect_fields(struct edaha_parser *p, size_t n, const char *what)
{
	if (p->nfields == n)
		return 0;
	if (p->nfields > n)
		return fail(p, "expected %zu fields for %s, got %zu (trailing %s)", n, what,
			    p->nfields, Q(p->fields[n]));
	return fail(p, "expected %zu fields for %s, got %zu", n, what, p->nfields);
}

static int parse_header(struct edaha_parser *p)
{
	uint64_t version;
	int r = next_line(p);

	if (r < 0)
		return r;
	if (r == 0)
		return error_at(p->err, -EINVAL, p->name, 0,
				"empty file: no \"edaha-trace %d\" header", TRACE_VERSION);
	if (strcmp(p->fields[0], "edaha-trace") != 0)
		return fail(p, "not an edaha trace: expected \"edaha-trace %d\" first, got %s",
			    TRACE_VERSION, Q(p->fields[0]));
	if (p->nfields < 2)
		return fail(p, "expected \"edaha-trace <version>\", the version is missing");
	if (!parse_uint(p->fields[1], &version))
		return fail(p, "bad trace version %s", Q(p->fields[1]));
	if (version != TRACE_VERSION)
		return fail(p, "unsupported trace version %" PRIu64 " (this edaha reads %d)",
			    version, TRACE_VERSION);
	return expect_fields(p, 2, "the header");
}

static int parse_screen_size(struct edaha_parser *p, const char *s, const char *what, long *v)
{
	uint64_t u;

	if (!parse_uint(s, &u) || u == 0 || u > MAX_SCREEN)
		return fail(p, "bad screen %s %s (expected 1..%d pixels)", what, Q(s), MAX_SCREEN);
	*v = (long)u;
	return 0;
}

static int parse_screen(struct edaha_parser *p)
{
	int r = next_line(p);

	if (r < 0)
		return r;
	if (r == 0)
		return fail(p, "missing \"screen W H\" line after the header");
	if (strcmp(p->fields[0], "screen") != 0)
		return fail(p, "expected \"screen W H\" after the header, got %s", Q(p->fields[0]));
	r = expect_fields(p, 3, "screen");
	if (r < 0)
		return r;
	r = parse_screen_size(p, p->fields[1], "width", &p->file_w);
	if (r < 0)
		return r;
	return parse_screen_size(p, p->fields[2], "height", &p->file_h);
}

/* Fields from `first` on: tool x y pressure tilt_x tilt_y. */
static int parse_pen_state(struct edaha_parser *p, size_t first, struct event *ev)
{
	char **f = p->fields + first;
	int r;

	if (!event_tool_from_name(f[0], &ev->tool))
		return fail(p, "unknown tool %s (expected pen or eraser)", Q(f[0]));
	if ((r = parse_number(p, f[1], "x", &ev->x)) < 0 ||
	    (r = parse_number(p, f[2], "y", &ev->y)) < 0 ||
	    (r = parse_ranged(p, f[3], "pressure", 0.0, 1.0, &ev->pressure)) < 0 ||
	    (r = parse_ranged(p, f[4], "tilt_x", -90.0, 90.0, &ev->tilt_x)) < 0 ||
	    (r = parse_ranged(p, f[5], "tilt_y", -90.0, 90.0, &ev->tilt_y)) < 0)
		return r;
	/* Positions are in the file's screen pixels; scale only when the screens differ,
	 * so a trace replayed on the screen it was recorded on stays bit-exact. */
	if (p->file_w != p->screen_w)
		ev->x = ev->x * p->screen_w / (double)p->file_w;
	if (p->file_h != p->screen_h)
		ev->y = ev->y * p->screen_h / (double)p->file_h;
	/* 1e308 is finite, but not once scaled up to a bigger screen. */
	if (!isfinite(ev->x) || !isfinite(ev->y))
		return fail(p, "position %s %s out of range on a %dx%d screen", f[1], f[2],
			    p->screen_w, p->screen_h);
	return 0;
}

static int parse_pen_button(struct edaha_parser *p, struct event *ev)
{
	enum event_pen_button button;
	int r = expect_fields(p, 10, "pen-button");

	if (r < 0)
		return r;
	if (!event_pen_button_from_name(p->fields[2], &button))
		return fail(p, "unknown pen button %s (expected stylus or stylus2)",
			    Q(p->fields[2]));
	ev->button = (int)button;
	r = parse_pressed(p, p->fields[3], &ev->pressed);
	if (r < 0)
		return r;
	return parse_pen_state(p, 4, ev);
}

/* Appends name to a space-separated list for a message; a list too long is cut short. */
static void append_name(char *names, size_t size, size_t *o, const char *name)
{
	int n;

	if (!name || *o >= size)
		return;
	n = snprintf(names + *o, size - *o, "%s%s", *o ? " " : "", name);
	if (n > 0)
		*o += (size_t)n;
}

static int parse_button(struct edaha_parser *p, struct event *ev)
{
	enum button button;
	int r = expect_fields(p, 4, "button");

	if (r < 0)
		return r;
	if (!button_from_name(p->fields[2], &button)) {
		/* every name (290 bytes with vine), room for a few more, within err->msg */
		char names[384];
		size_t o = 0;

		names[0] = '\0';
		for (int b = 0; b < BUTTON_COUNT; b++)
			append_name(names, sizeof(names), &o, button_name((enum button)b));
		return fail(p, "unknown button %s (valid: %s)", Q(p->fields[2]), names);
	}
	ev->button = (int)button;
	return parse_pressed(p, p->fields[3], &ev->pressed);
}

static int parse_event(struct edaha_parser *p, struct event *ev)
{
	int r;

	memset(ev, 0, sizeof(*ev));
	if (strcmp(p->fields[0], "screen") == 0 || strcmp(p->fields[0], "edaha-trace") == 0)
		return fail(p, "%s may only appear once, at the top", Q(p->fields[0]));
	if (p->nfields < 2)
		return fail(p, "expected \"<time_us> <event> ...\", got 1 field");
	if (!parse_uint(p->fields[0], &ev->time_us))
		return fail(p, "bad time %s (expected microseconds, an unsigned integer)",
			    Q(p->fields[0]));
	if (ev->time_us > TRACE_MAX_TIME_US)
		return fail(p, "time %" PRIu64 " too large (limit %" PRIu64 " us)", ev->time_us,
			    TRACE_MAX_TIME_US);
	if (!event_type_from_name(p->fields[1], &ev->type)) {
		char names[256];
		size_t o = 0;

		/* From the table, like the buttons: the list can't go stale. Types are
		 * numbered from EVENT_PROXIMITY_IN with no gaps. */
		names[0] = '\0';
		for (int type = EVENT_PROXIMITY_IN; event_type_name((enum event_type)type); type++)
			append_name(names, sizeof(names), &o, event_type_name((enum event_type)type));
		return fail(p, "unknown event %s (valid: %s)", Q(p->fields[1]), names);
	}

	switch (ev->type) {
	case EVENT_PEN_BUTTON:
		r = parse_pen_button(p, ev);
		break;
	case EVENT_BUTTON:
		r = parse_button(p, ev);
		break;
	default:
		r = expect_fields(p, 8, p->fields[1]);
		if (r == 0)
			r = parse_pen_state(p, 2, ev);
		break;
	}
	if (r < 0)
		return r;
	if (ev->time_us < p->last_time)
		return fail(p, "time goes backwards (%" PRIu64 " < %" PRIu64 ")", ev->time_us,
			    p->last_time);
	p->last_time = ev->time_us;
	return 0;
}

static int parse_all(struct edaha_parser *p)
{
	int r;

	if (p->screen_w <= 0 || p->screen_h <= 0)
		return error_at(p->err, -EINVAL, p->name, 0, "bad screen size %dx%d", p->screen_w,
				p->screen_h);
	r = parse_header(p);
	if (r < 0)
		return r;
	r = parse_screen(p);
	if (r < 0)
		return r;
	while ((r = next_line(p)) > 0) {
		struct event ev;

		r = parse_event(p, &ev);
		if (r < 0)
			return r;
		if (trace_append(&p->out, &ev) < 0)
			return error_at(p->err, -ENOMEM, p->name, p->lineno, "out of memory");
	}
	return r;
}

int trace_parse_edaha(const char *data, size_t len, const char *name, int screen_w,
		      int screen_h, struct trace *t, struct error *err)
{
	struct edaha_parser p = {
		.name = name,
		.err = err,
		.data = data,
		.len = data ? len : 0,
		.screen_w = screen_w,
		.screen_h = screen_h,
	};
	int r;

	/* Windows editors may put a byte order mark in front. */
	if (p.len >= 3 && memcmp(p.data, "\xef\xbb\xbf", 3) == 0)
		p.pos = 3;
	trace_init(&p.out);
	r = parse_all(&p);
	free(p.line);
	trace_finish(t);
	if (r < 0) {
		trace_finish(&p.out);
		return r;
	}
	*t = p.out;
	return 0;
}
