/* SPDX-License-Identifier: MIT */
/*
 * Imports `libinput record` YAML (version 1): the evdev frames of every pen tablet device
 * in the file become edaha events, processed roughly as libinput's tablet code does.
 * docs/trace-format.md ("libinput recordings") describes the mapping.
 *
 * libyaml's event (streaming) API is used rather than its document loader: a recording
 * of a long session has millions of nodes and the loader keeps them all.
 */
#include "trace.h"
#include "trace_private.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#define RECORD_VERSION 1

/* linux/input-event-codes.h, spelled out: the importer must not need kernel headers. */
#define EV_SYN 0
#define EV_KEY 1
#define EV_ABS 3
#define SYN_REPORT 0
#define ABS_X 0
#define ABS_Y 1
#define ABS_PRESSURE 24
#define ABS_TILT_X 26
#define ABS_TILT_Y 27
#define BTN_TOOL_PEN 320
#define BTN_TOOL_RUBBER 321
#define BTN_TOUCH 330
#define BTN_STYLUS 331
#define BTN_STYLUS2 332

/* Without BTN_TOUCH, the tip is down above this fraction of the pressure range. */
#define PRESSURE_TIP_THRESHOLD 0.05
/* Wacom's physical tilt range, libinput's default when tilt has no resolution. */
#define DEFAULT_TILT_DEGREES 64.0
/* M_PI is not in C11 or POSIX proper. */
#define PI 3.14159265358979323846

enum axis { AX_X, AX_Y, AX_PRESSURE, AX_TILT_X, AX_TILT_Y, AX_COUNT };

static const int axis_codes[AX_COUNT] = { ABS_X, ABS_Y, ABS_PRESSURE, ABS_TILT_X, ABS_TILT_Y };
static const char *const axis_names[AX_COUNT] = { "ABS_X", "ABS_Y", "ABS_PRESSURE",
						  "ABS_TILT_X", "ABS_TILT_Y" };

struct absinfo {
	bool have;
	int64_t min, max, resolution;
	unsigned long line;
};

/* One evdev event: [sec, usec, type, code, value]. */
struct row {
	uint64_t time_us;
	int32_t value;
	uint16_t type, code;
	uint32_t line;
};

struct device {
	char name[128];
	unsigned long line, evdev_line;
	/* From evdev.codes */
	bool key_pen, key_rubber, key_touch;
	bool abs_code[AX_COUNT];
	struct absinfo abs[AX_COUNT];
	struct row *rows;
	size_t nrows, cap;
};

struct li_parser {
	const char *name;
	struct error *err;
	const char *data;
	size_t len;
	int screen_w, screen_h;

	yaml_parser_t yaml;
	yaml_event_t ev; /* the current event, valid if have_ev */
	bool have_ev;

	bool have_version, have_devices;
	size_t ndevices;
	/* Events of each tablet device, merged at the end. */
	struct trace *tablets;
	size_t ntablets, tablets_cap;
};

static int fail_at(struct li_parser *p, unsigned long line, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static int fail_at(struct li_parser *p, unsigned long line, const char *fmt, ...)
{
	char msg[sizeof(p->err->msg)];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	return error_at(p->err, -EINVAL, p->name, line, "%s", msg);
}

static unsigned long cur_line(const struct li_parser *p)
{
	return (unsigned long)p->ev.start_mark.line + 1;
}

static int oom(struct li_parser *p)
{
	return error_at(p->err, -ENOMEM, p->name, 0, "out of memory");
}

/* ---- YAML event plumbing ---------------------------------------------------------- */

static int yaml_fail(struct li_parser *p)
{
	const yaml_parser_t *y = &p->yaml;
	unsigned long line;

	if (y->error == YAML_MEMORY_ERROR)
		return oom(p);
	if (y->error == YAML_READER_ERROR) {
		/* Reader errors (bad UTF-8, control characters) carry a byte offset only. */
		size_t end = y->problem_offset < p->len ? y->problem_offset : p->len;

		line = 1;
		for (size_t i = 0; i < end; i++)
			line += p->data[i] == '\n';
		return fail_at(p, line, "not a libinput recording: %s at byte %zu",
			       y->problem ? y->problem : "unreadable text", y->problem_offset);
	}
	line = (unsigned long)y->problem_mark.line + 1;
	if (y->context)
		return fail_at(p, line, "YAML error: %s %s", y->problem ? y->problem : "error",
			       y->context);
	return fail_at(p, line, "YAML error: %s", y->problem ? y->problem : "error");
}

static int next(struct li_parser *p)
{
	if (p->have_ev) {
		yaml_event_delete(&p->ev);
		p->have_ev = false;
	}
	if (!yaml_parser_parse(&p->yaml, &p->ev))
		return yaml_fail(p);
	p->have_ev = true;
	return 0;
}

static const char *kind(const yaml_event_t *ev)
{
	switch (ev->type) {
	case YAML_SCALAR_EVENT:
		return "a scalar";
	case YAML_SEQUENCE_START_EVENT:
		return "a sequence";
	case YAML_MAPPING_START_EVENT:
		return "a mapping";
	case YAML_ALIAS_EVENT:
		return "an alias";
	default:
		return "nothing";
	}
}

/* Skips the node starting at the current event, leaving its last event current. */
static int skip_node(struct li_parser *p)
{
	size_t depth = 0;

	do {
		switch (p->ev.type) {
		case YAML_SEQUENCE_START_EVENT:
		case YAML_MAPPING_START_EVENT:
			depth++;
			break;
		case YAML_SEQUENCE_END_EVENT:
		case YAML_MAPPING_END_EVENT:
			depth--;
			break;
		default:
			break;
		}
		if (depth > 0) {
			int r = next(p);

			if (r < 0)
				return r;
		}
	} while (depth > 0);
	return 0;
}

static bool is_null(const yaml_event_t *ev)
{
	const char *v = (const char *)ev->data.scalar.value;

	if (ev->type != YAML_SCALAR_EVENT || ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE)
		return false;
	return strcmp(v, "") == 0 || strcmp(v, "~") == 0 || strcmp(v, "null") == 0;
}

/* The current scalar, quoted for a message. */
#define QS(ev) TRACE_Q((const char *)(ev)->data.scalar.value, (ev)->data.scalar.length)

/* The current event must be an integer scalar within lo..hi. */
static int scalar_int(struct li_parser *p, int64_t lo, int64_t hi, const char *what,
		      int64_t *v)
{
	const char *s = (const char *)p->ev.data.scalar.value;
	long long x;
	char *end;

	if (p->ev.type != YAML_SCALAR_EVENT)
		return fail_at(p, cur_line(p), "expected an integer for %s, got %s", what,
			       kind(&p->ev));
	/* Digits with an optional minus, nothing else: strtoll alone takes " +0x1f". */
	if (!((s[0] >= '0' && s[0] <= '9') || (s[0] == '-' && s[1] >= '0' && s[1] <= '9')) ||
	    strlen(s) != p->ev.data.scalar.length)
		return fail_at(p, cur_line(p), "%s %s is not an integer", what, QS(&p->ev));
	errno = 0;
	x = strtoll(s, &end, 10);
	if (*end)
		return fail_at(p, cur_line(p), "%s %s is not an integer", what, QS(&p->ev));
	if (errno == ERANGE || x < lo || x > hi)
		return fail_at(p, cur_line(p), "%s %s out of range %" PRId64 "..%" PRId64, what,
			       QS(&p->ev), lo, hi);
	*v = x;
	return 0;
}

/*
 * Calls fn for each key/value pair of the mapping starting at the current event; fn
 * gets the key's text and its line, with the value's first event current, and must
 * consume the value. Null (an empty value) counts as an empty mapping.
 */
typedef int (*pair_fn)(struct li_parser *p, const char *key, unsigned long key_line,
		       void *data);

static int for_each_pair(struct li_parser *p, const char *what, pair_fn fn, void *data)
{
	int r;

	if (is_null(&p->ev))
		return 0;
	if (p->ev.type != YAML_MAPPING_START_EVENT)
		return fail_at(p, cur_line(p), "expected a mapping for %s, got %s", what,
			       kind(&p->ev));
	for (;;) {
		char key[64];
		unsigned long key_line;

		if ((r = next(p)) < 0)
			return r;
		if (p->ev.type == YAML_MAPPING_END_EVENT)
			return 0;
		key_line = cur_line(p);
		key[0] = '\0';
		if (p->ev.type == YAML_SCALAR_EVENT && p->ev.data.scalar.length < sizeof(key))
			memcpy(key, p->ev.data.scalar.value, p->ev.data.scalar.length + 1);
		else if ((r = skip_node(p)) < 0) /* a complex or overlong key: not ours */
			return r;
		if ((r = next(p)) < 0)
			return r;
		r = key[0] ? fn(p, key, key_line, data) : skip_node(p);
		if (r < 0)
			return r;
	}
}

/* Same for sequences: fn is called with each item's first event current. */
typedef int (*item_fn)(struct li_parser *p, void *data);

static int for_each_item(struct li_parser *p, const char *what, item_fn fn, void *data)
{
	int r;

	if (is_null(&p->ev))
		return 0;
	if (p->ev.type != YAML_SEQUENCE_START_EVENT)
		return fail_at(p, cur_line(p), "expected a sequence for %s, got %s", what,
			       kind(&p->ev));
	for (;;) {
		if ((r = next(p)) < 0)
			return r;
		if (p->ev.type == YAML_SEQUENCE_END_EVENT)
			return 0;
		if ((r = fn(p, data)) < 0)
			return r;
	}
}

/* Reads a flow list of exactly n integers ([min, max, ...] or an evdev row). */
static int int_list(struct li_parser *p, const char *what, int64_t *v, size_t n)
{
	unsigned long line = cur_line(p);
	size_t count = 0;
	int r;

	if (p->ev.type != YAML_SEQUENCE_START_EVENT)
		return fail_at(p, line, "bad %s: expected a list of %zu integers, got %s", what, n,
			       kind(&p->ev));
	for (;;) {
		if ((r = next(p)) < 0)
			return r;
		if (p->ev.type == YAML_SEQUENCE_END_EVENT)
			break;
		if (count < n) {
			r = scalar_int(p, INT64_MIN / 2, INT64_MAX / 2, what, &v[count]);
			if (r < 0)
				return r;
		} else if ((r = skip_node(p)) < 0) {
			return r;
		}
		count++;
	}
	if (count != n)
		return fail_at(p, line, "bad %s: expected %zu integers, got %zu", what, n, count);
	return 0;
}

/* ---- evdev description ------------------------------------------------------------ */

static int axis_of_code(int64_t code)
{
	for (int a = 0; a < AX_COUNT; a++)
		if (axis_codes[a] == code)
			return a;
	return -1;
}

struct codes_ctx {
	struct device *dev;
	int64_t type;
};

static int code_item(struct li_parser *p, void *data)
{
	struct codes_ctx *c = data;
	int64_t code = 0;
	int a, r;

	r = scalar_int(p, 0, 0xffff, "event code", &code);
	if (r < 0)
		return r;
	if (c->type == EV_KEY) {
		c->dev->key_pen |= code == BTN_TOOL_PEN;
		c->dev->key_rubber |= code == BTN_TOOL_RUBBER;
		c->dev->key_touch |= code == BTN_TOUCH;
	} else if (c->type == EV_ABS && (a = axis_of_code(code)) >= 0) {
		c->dev->abs_code[a] = true;
	}
	return 0;
}

static int codes_pair(struct li_parser *p, const char *key, unsigned long key_line, void *data)
{
	struct codes_ctx c = { .dev = data };
	char *end;
	long type;

	errno = 0;
	type = strtol(key, &end, 10);
	if (*end || end == key || errno || type < 0 || type > 0xffff)
		return fail_at(p, key_line, "bad event type \"%.20s\" in codes", key);
	c.type = type;
	return for_each_item(p, "event codes", code_item, &c);
}

static int absinfo_pair(struct li_parser *p, const char *key, unsigned long key_line,
			void *data)
{
	struct device *dev = data;
	int64_t v[5];
	char *end;
	long code;
	int a, r;

	errno = 0;
	code = strtol(key, &end, 10);
	if (*end || end == key || errno || code < 0 || code > 0xffff)
		return fail_at(p, key_line, "bad axis code \"%.20s\" in absinfo", key);
	r = int_list(p, "absinfo [min, max, fuzz, flat, resolution]", v, 5);
	if (r < 0)
		return r;
	for (int i = 0; i < 5; i++) /* struct input_absinfo holds 32-bit values */
		if (v[i] < INT32_MIN || v[i] > INT32_MAX)
			return fail_at(p, key_line, "absinfo value %" PRId64 " out of range", v[i]);
	a = axis_of_code(code);
	if (a >= 0) {
		dev->abs[a].have = true;
		dev->abs[a].min = v[0];
		dev->abs[a].max = v[1];
		dev->abs[a].resolution = v[4];
		dev->abs[a].line = key_line;
	}
	return 0;
}

static int evdev_pair(struct li_parser *p, const char *key, unsigned long key_line, void *data)
{
	struct device *dev = data;

	(void)key_line;
	if (strcmp(key, "name") == 0 && p->ev.type == YAML_SCALAR_EVENT) {
		size_t n = p->ev.data.scalar.length;

		if (n >= sizeof(dev->name))
			n = sizeof(dev->name) - 1;
		/* It ends up in messages: no control characters. */
		for (size_t i = 0; i < n; i++) {
			unsigned char c = p->ev.data.scalar.value[i];

			dev->name[i] = c < 0x20 || c == 0x7f ? '?' : (char)c;
		}
		dev->name[n] = '\0';
		return 0;
	}
	if (strcmp(key, "codes") == 0)
		return for_each_pair(p, "evdev codes", codes_pair, dev);
	if (strcmp(key, "absinfo") == 0)
		return for_each_pair(p, "evdev absinfo", absinfo_pair, dev);
	return skip_node(p);
}

/* ---- events ----------------------------------------------------------------------- */

static int row_item(struct li_parser *p, void *data)
{
	struct device *dev = data;
	unsigned long line = cur_line(p);
	struct row *row;
	int64_t v[5];
	int r;

	if (p->ev.type != YAML_SEQUENCE_START_EVENT)
		return fail_at(p, line, "bad evdev row: expected [sec, usec, type, code, value], got %s",
			       kind(&p->ev));
	r = int_list(p, "evdev row [sec, usec, type, code, value]", v, 5);
	if (r < 0)
		return r;
	/* A struct timeval since the recording began: libinput record normalises usec. */
	if (v[0] < 0)
		return fail_at(p, line, "bad evdev row: sec %" PRId64 " is negative", v[0]);
	if (v[1] < 0 || v[1] > 999999)
		return fail_at(p, line, "bad evdev row: usec %" PRId64 " out of range 0..999999",
			       v[1]);
	/* Compared in seconds first, so that sec * 10^6 cannot overflow. */
	if ((uint64_t)v[0] > TRACE_MAX_TIME_US / 1000000 ||
	    (uint64_t)v[0] * 1000000u + (uint64_t)v[1] > TRACE_MAX_TIME_US)
		return fail_at(p, line, "bad evdev row: time %" PRId64 ".%06" PRId64
			       " s too large (limit %" PRIu64 ".%06" PRIu64 " s)", v[0], v[1],
			       TRACE_MAX_TIME_US / 1000000, TRACE_MAX_TIME_US % 1000000);
	if (v[2] < 0 || v[2] > 0xffff || v[3] < 0 || v[3] > 0xffff)
		return fail_at(p, line, "bad evdev row: type %" PRId64 " code %" PRId64
			       " out of range", v[2], v[3]);
	if (v[4] < INT32_MIN || v[4] > INT32_MAX)
		return fail_at(p, line, "bad evdev row: value %" PRId64 " out of range", v[4]);
	if (dev->nrows == dev->cap) {
		size_t cap = dev->cap ? dev->cap * 2 : 1024;
		struct row *rows;

		if (cap > SIZE_MAX / sizeof(*rows))
			return oom(p);
		rows = realloc(dev->rows, cap * sizeof(*rows));
		if (!rows)
			return oom(p);
		dev->rows = rows;
		dev->cap = cap;
	}
	row = &dev->rows[dev->nrows++];
	row->time_us = (uint64_t)v[0] * 1000000u + (uint64_t)v[1];
	row->type = (uint16_t)v[2];
	row->code = (uint16_t)v[3];
	row->value = (int32_t)v[4];
	row->line = line > UINT32_MAX ? UINT32_MAX : (uint32_t)line;
	return 0;
}

static int event_item_pair(struct li_parser *p, const char *key, unsigned long key_line,
			   void *data)
{
	(void)key_line;
	/* `- libinput:` items (record --with-libinput) and anything else are not ours. */
	if (strcmp(key, "evdev") == 0)
		return for_each_item(p, "evdev frame", row_item, data);
	return skip_node(p);
}

static int event_item(struct li_parser *p, void *data)
{
	return for_each_pair(p, "an events item (- evdev: [...])", event_item_pair, data);
}

/* ---- pen state machine ------------------------------------------------------------ */

struct pen {
	const struct device *dev;
	struct trace *out;
	int32_t value[AX_COUNT];     /* as of the rows read so far */
	int32_t committed[AX_COUNT]; /* as of the last frame */
	bool axis_changed;
	/* Key state as the hardware reports it... */
	bool key_tool[2], key_touch, key_button[2];
	/* ...and as told in events so far. */
	bool in_prox, tip, button[2];
	enum event_tool tool;
};

static bool has_axis(const struct device *dev, enum axis a)
{
	return dev->abs_code[a] && dev->abs[a].have;
}

static double normalized(const struct absinfo *abs, int32_t v)
{
	return ((double)v - (double)abs->min) / ((double)abs->max - (double)abs->min);
}

/* libinput 1.22's adjust_tilt(). */
static double tilt_degrees(const struct absinfo *abs, int32_t v)
{
	double deg;

	/* A resolution is in units per radian, but only if 0 is the centre. */
	if (abs->resolution != 0 && abs->max > 0 && abs->min < 0)
		deg = (double)v / (double)abs->resolution * (180.0 / PI);
	else
		deg = (normalized(abs, v) * 2.0 - 1.0) * DEFAULT_TILT_DEGREES;
	return trace_clamp(deg, -90.0, 90.0);
}

static double screen_pos(const struct absinfo *abs, int32_t v, int screen)
{
	/* The whole tablet area onto the whole screen, as libinput does for external
	 * tablets: max - min + 1 device units span the screen. */
	return ((double)v - (double)abs->min) * screen / ((double)abs->max - (double)abs->min + 1.0);
}

static bool hw_tip(const struct pen *pen)
{
	const struct device *dev = pen->dev;

	if (dev->key_touch)
		return pen->key_touch;
	if (has_axis(dev, AX_PRESSURE))
		return normalized(&dev->abs[AX_PRESSURE], pen->value[AX_PRESSURE]) >
		       PRESSURE_TIP_THRESHOLD;
	return false;
}

static int emit(struct li_parser *p, struct pen *pen, enum event_type type, uint64_t time_us,
		int button, bool pressed)
{
	const struct device *dev = pen->dev;
	struct event ev = {
		.type = type,
		.time_us = time_us,
		.tool = pen->tool,
		.button = button,
		.pressed = pressed,
	};

	ev.x = screen_pos(&dev->abs[AX_X], pen->value[AX_X], p->screen_w);
	ev.y = screen_pos(&dev->abs[AX_Y], pen->value[AX_Y], p->screen_h);
	if (has_axis(dev, AX_PRESSURE))
		ev.pressure = trace_clamp(normalized(&dev->abs[AX_PRESSURE], pen->value[AX_PRESSURE]),
				    0.0, 1.0);
	else
		ev.pressure = pen->tip ? 1.0 : 0.0;
	if (has_axis(dev, AX_TILT_X))
		ev.tilt_x = tilt_degrees(&dev->abs[AX_TILT_X], pen->value[AX_TILT_X]);
	if (has_axis(dev, AX_TILT_Y))
		ev.tilt_y = tilt_degrees(&dev->abs[AX_TILT_Y], pen->value[AX_TILT_Y]);
	if (trace_append(pen->out, &ev) < 0)
		return oom(p);
	return 0;
}

/* The end of a frame (SYN_REPORT): tell what changed, in libinput's order. */
static int flush_frame(struct li_parser *p, struct pen *pen, uint64_t time_us)
{
	bool want = pen->key_tool[EVENT_TOOL_PEN] || pen->key_tool[EVENT_TOOL_ERASER];
	int32_t frame[AX_COUNT];
	enum event_tool tool;
	bool entered = false, leaving = false, tip;
	int r;

	if (pen->in_prox && pen->key_tool[pen->tool])
		tool = pen->tool;
	else
		tool = pen->key_tool[EVENT_TOOL_PEN] ? EVENT_TOOL_PEN : EVENT_TOOL_ERASER;

	if (!pen->in_prox && want) {
		pen->in_prox = true;
		pen->tool = tool;
		entered = true;
		if ((r = emit(p, pen, EVENT_PROXIMITY_IN, time_us, 0, false)) < 0)
			return r;
	} else if (pen->in_prox && (!want || tool != pen->tool)) {
		/* Like libinput: the axes of the leaving frame are mostly zeroed by the
		 * kernel, so the tool leaves where it was last seen, with no motion. */
		leaving = true;
		memcpy(frame, pen->value, sizeof(frame));
		memcpy(pen->value, pen->committed, sizeof(frame));
		pen->axis_changed = false;
	}
	if (pen->in_prox && !entered && pen->axis_changed &&
	    (r = emit(p, pen, EVENT_MOTION, time_us, 0, false)) < 0)
		return r;
	pen->axis_changed = false;
	if (!pen->in_prox) {
		memcpy(pen->committed, pen->value, sizeof(frame));
		return 0;
	}

	tip = hw_tip(pen);
	if (!leaving && tip && !pen->tip) {
		pen->tip = true;
		if ((r = emit(p, pen, EVENT_TIP_DOWN, time_us, 0, false)) < 0)
			return r;
	}
	for (int b = 0; b < 2; b++) {
		bool pressed = !leaving && pen->key_button[b];

		if (pressed == pen->button[b])
			continue;
		pen->button[b] = pressed;
		if ((r = emit(p, pen, EVENT_PEN_BUTTON, time_us, b, pressed)) < 0)
			return r;
	}
	if (pen->tip && (leaving || !tip)) {
		pen->tip = false;
		if ((r = emit(p, pen, EVENT_TIP_UP, time_us, 0, false)) < 0)
			return r;
	}
	if (leaving) {
		if ((r = emit(p, pen, EVENT_PROXIMITY_OUT, time_us, 0, false)) < 0)
			return r;
		pen->in_prox = false;
		memcpy(pen->value, frame, sizeof(frame));
		memcpy(pen->committed, frame, sizeof(frame));
		/* Pen swapped for eraser within one frame: the new tool comes in now. */
		if (want)
			return flush_frame(p, pen, time_us);
		return 0;
	}
	memcpy(pen->committed, pen->value, sizeof(frame));
	return 0;
}

static void apply_row(struct pen *pen, const struct row *row)
{
	bool down = row->value != 0; /* 2 is autorepeat: still down */
	int a;

	if (row->type == EV_ABS && (a = axis_of_code(row->code)) >= 0) {
		if (!has_axis(pen->dev, (enum axis)a) || pen->value[a] == row->value)
			return;
		pen->value[a] = row->value;
		pen->axis_changed = true;
		return;
	}
	if (row->type != EV_KEY)
		return;
	switch (row->code) {
	case BTN_TOOL_PEN:
		pen->key_tool[EVENT_TOOL_PEN] = down;
		break;
	case BTN_TOOL_RUBBER:
		pen->key_tool[EVENT_TOOL_ERASER] = down;
		break;
	case BTN_TOUCH:
		pen->key_touch = down;
		break;
	case BTN_STYLUS:
		pen->key_button[EVENT_PEN_BUTTON_STYLUS] = down;
		break;
	case BTN_STYLUS2:
		pen->key_button[EVENT_PEN_BUTTON_STYLUS2] = down;
		break;
	default:
		break;
	}
}

static int run_frames(struct li_parser *p, const struct device *dev, struct trace *out)
{
	struct pen pen = { .dev = dev, .out = out };
	uint64_t last_time = 0;

	/* Before any event an axis sits at 0, or the end of its range nearest to it. */
	for (int a = 0; a < AX_COUNT; a++) {
		if (has_axis(dev, (enum axis)a))
			pen.value[a] = (int32_t)trace_clamp(0.0, (double)dev->abs[a].min,
						      (double)dev->abs[a].max);
	}
	memcpy(pen.committed, pen.value, sizeof(pen.value));
	for (size_t i = 0; i < dev->nrows; i++) {
		const struct row *row = &dev->rows[i];
		int r;

		if (row->type != EV_SYN) {
			apply_row(&pen, row);
			continue;
		}
		if (row->code != SYN_REPORT)
			continue;
		if (row->time_us < last_time)
			return fail_at(p, row->line, "time goes backwards (%" PRIu64 " < %" PRIu64 " us)",
				       row->time_us, last_time);
		last_time = row->time_us;
		if ((r = flush_frame(p, &pen, row->time_us)) < 0)
			return r;
	}
	/* Rows after the last SYN_REPORT are an unfinished frame: libinput drops it too. */
	return 0;
}

/* ---- devices ---------------------------------------------------------------------- */

static bool is_tablet(const struct device *dev)
{
	return (dev->key_pen || dev->key_rubber) && dev->abs_code[AX_X] && dev->abs_code[AX_Y];
}

static int check_tablet_axes(struct li_parser *p, const struct device *dev)
{
	for (int a = 0; a < AX_COUNT; a++) {
		const struct absinfo *abs = &dev->abs[a];

		if (!dev->abs_code[a])
			continue;
		if (!abs->have)
			return fail_at(p, dev->evdev_line,
				       "device \"%s\" is a pen tablet but has no absinfo for %s (%d)",
				       dev->name, axis_names[a], axis_codes[a]);
		if (abs->max <= abs->min)
			return fail_at(p, abs->line,
				       "device \"%s\": absinfo for %s (%d) has max %" PRId64
				       " <= min %" PRId64,
				       dev->name, axis_names[a], axis_codes[a], abs->max, abs->min);
	}
	return 0;
}

static int finish_device(struct li_parser *p, struct device *dev)
{
	struct trace *tablets, *out;
	int r;

	if (!is_tablet(dev))
		return 0; /* pads, touch, keyboards: not the pen */
	if ((r = check_tablet_axes(p, dev)) < 0)
		return r;
	if (p->ntablets == p->tablets_cap) {
		size_t cap = p->tablets_cap ? p->tablets_cap * 2 : 4;

		tablets = realloc(p->tablets, cap * sizeof(*tablets));
		if (!tablets)
			return oom(p);
		p->tablets = tablets;
		p->tablets_cap = cap;
	}
	out = &p->tablets[p->ntablets++];
	trace_init(out);
	return run_frames(p, dev, out);
}

static int device_pair(struct li_parser *p, const char *key, unsigned long key_line, void *data)
{
	struct device *dev = data;

	if (strcmp(key, "evdev") == 0) {
		dev->evdev_line = key_line;
		return for_each_pair(p, "evdev", evdev_pair, dev);
	}
	if (strcmp(key, "events") == 0)
		return for_each_item(p, "events", event_item, dev);
	return skip_node(p);
}

static int device_item(struct li_parser *p, void *data)
{
	struct device dev = { .line = cur_line(p) };
	int r;

	(void)data;
	p->ndevices++;
	snprintf(dev.name, sizeof(dev.name), "device %zu", p->ndevices);
	if (p->ev.type != YAML_MAPPING_START_EVENT)
		return fail_at(p, dev.line, "expected a mapping for a device, got %s", kind(&p->ev));
	dev.evdev_line = dev.line;
	r = for_each_pair(p, "a device", device_pair, &dev);
	if (r == 0)
		r = finish_device(p, &dev);
	free(dev.rows);
	return r;
}

static int top_pair(struct li_parser *p, const char *key, unsigned long key_line, void *data)
{
	int64_t version;
	int r;

	(void)key_line;
	(void)data;
	if (strcmp(key, "version") == 0) {
		r = scalar_int(p, INT32_MIN, INT32_MAX, "version", &version);
		if (r < 0)
			return r;
		if (version != RECORD_VERSION)
			return fail_at(p, cur_line(p),
				       "unsupported libinput record version %" PRId64
				       " (this edaha reads %d)",
				       version, RECORD_VERSION);
		p->have_version = true;
		return 0;
	}
	if (strcmp(key, "devices") == 0) {
		p->have_devices = true;
		return for_each_item(p, "devices", device_item, NULL);
	}
	return skip_node(p); /* libinput, system, ndevices, ... */
}

static int parse_document(struct li_parser *p)
{
	int r;

	if ((r = next(p)) < 0) /* STREAM-START */
		return r;
	if ((r = next(p)) < 0)
		return r;
	if (p->ev.type == YAML_STREAM_END_EVENT)
		return fail_at(p, 0, "empty file: not a libinput recording");
	if ((r = next(p)) < 0) /* the root node, after DOCUMENT-START */
		return r;
	if (p->ev.type != YAML_MAPPING_START_EVENT)
		return fail_at(p, cur_line(p),
			       "not a libinput recording: expected a YAML mapping with "
			       "\"version\" and \"devices\", got %s",
			       kind(&p->ev));
	if ((r = for_each_pair(p, "the recording", top_pair, NULL)) < 0)
		return r;
	/* Read to the end so that a broken tail is an error, not silently ignored. */
	while (p->ev.type != YAML_STREAM_END_EVENT)
		if ((r = next(p)) < 0)
			return r;
	if (!p->have_version)
		return fail_at(p, 0, "not a libinput recording: no \"version\"");
	if (!p->have_devices)
		return fail_at(p, 0, "not a libinput recording: no \"devices\"");
	if (p->ntablets == 0)
		return fail_at(p, 0, "no pen tablet device in this recording");
	return 0;
}

struct order {
	uint64_t time_us;
	size_t index;
};

/* By time, ties in index order: a stable sort with qsort. */
static int cmp_order(const void *a, const void *b)
{
	const struct order *x = a, *y = b;

	if (x->time_us != y->time_us)
		return x->time_us < y->time_us ? -1 : 1;
	return x->index < y->index ? -1 : x->index > y->index;
}

/*
 * All tablets' events in time order; ties keep the file's order. Each device's list is
 * already in order, so one device (the usual case) needs no sorting at all.
 */
static int merge_tablets(struct li_parser *p, struct trace *out)
{
	struct trace all;
	struct order *order;
	int r = 0;

	if (p->ntablets == 1) {
		*out = p->tablets[0];
		trace_init(&p->tablets[0]);
		return 0;
	}
	trace_init(&all);
	for (size_t d = 0; d < p->ntablets && r == 0; d++)
		for (size_t i = 0; i < p->tablets[d].nevents && r == 0; i++)
			if (trace_append(&all, &p->tablets[d].events[i]) < 0)
				r = oom(p);
	if (r < 0 || all.nevents == 0) {
		trace_finish(&all);
		return r;
	}
	order = calloc(all.nevents, sizeof(*order));
	if (!order) {
		trace_finish(&all);
		return oom(p);
	}
	for (size_t i = 0; i < all.nevents; i++)
		order[i] = (struct order){ .time_us = all.events[i].time_us, .index = i };
	qsort(order, all.nevents, sizeof(*order), cmp_order);
	for (size_t i = 0; i < all.nevents && r == 0; i++)
		if (trace_append(out, &all.events[order[i].index]) < 0)
			r = oom(p);
	free(order);
	trace_finish(&all);
	return r;
}

int trace_parse_libinput(const char *data, size_t len, const char *name, int screen_w,
			 int screen_h, struct trace *t, struct error *err)
{
	struct li_parser p = {
		.name = name,
		.err = err,
		.data = data ? data : "",
		.len = data ? len : 0,
		.screen_w = screen_w,
		.screen_h = screen_h,
	};
	struct trace out;
	int r;

	trace_init(&out);
	trace_finish(t);
	if (screen_w <= 0 || screen_h <= 0)
		return error_at(err, -EINVAL, name, 0, "bad screen size %dx%d", screen_w, screen_h);
	if (!yaml_parser_initialize(&p.yaml))
		return error_at(err, -ENOMEM, name, 0, "out of memory");
	yaml_parser_set_input_string(&p.yaml, (const unsigned char *)p.data, p.len);
	r = parse_document(&p);
	if (r == 0)
		r = merge_tablets(&p, &out);
	if (p.have_ev)
		yaml_event_delete(&p.ev);
	yaml_parser_delete(&p.yaml);
	for (size_t i = 0; i < p.ntablets; i++)
		trace_finish(&p.tablets[i]);
	free(p.tablets);
	if (r < 0) {
		trace_finish(&out);
		return r;
	}
	*t = out;
	return 0;
}
