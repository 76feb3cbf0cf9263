/* SPDX-License-Identifier: MIT */
/* Writes edaha traces (docs/trace-format.md) for `edaha --record`. */
#include "trace.h"
#include "trace_private.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct trace_writer {
	FILE *f;
	int error; /* first failure, negative errno */
	uint64_t last_time;
};

static bool pen_state_valid(const struct event *ev)
{
	return event_tool_name(ev->tool) && isfinite(ev->x) && isfinite(ev->y) &&
	       ev->pressure >= 0.0 && ev->pressure <= 1.0 && ev->tilt_x >= -90.0 &&
	       ev->tilt_x <= 90.0 && ev->tilt_y >= -90.0 && ev->tilt_y <= 90.0;
}

int trace_format_event(const struct event *ev, char *line, size_t size)
{
	const char *type = event_type_name(ev->type);
	const char *name;
	int n;

	if (!type || ev->time_us > TRACE_MAX_TIME_US)
		return -EINVAL;
	/* %.17g: enough digits that strtod gives back the very same double. */
	switch (ev->type) {
	case EVENT_BUTTON:
		name = button_name((enum button)ev->button);
		if (!name)
			return -EINVAL;
		n = snprintf(line, size, "%" PRIu64 " button %s %s\n", ev->time_us, name,
			     ev->pressed ? "pressed" : "released");
		break;
	case EVENT_PEN_BUTTON:
		name = event_pen_button_name((enum event_pen_button)ev->button);
		if (!name || !pen_state_valid(ev))
			return -EINVAL;
		n = snprintf(line, size, "%" PRIu64 " pen-button %s %s %s %.17g %.17g %.17g %.17g %.17g\n",
			     ev->time_us, name, ev->pressed ? "pressed" : "released",
			     event_tool_name(ev->tool), ev->x, ev->y, ev->pressure, ev->tilt_x,
			     ev->tilt_y);
		break;
	default:
		if (!pen_state_valid(ev))
			return -EINVAL;
		n = snprintf(line, size, "%" PRIu64 " %s %s %.17g %.17g %.17g %.17g %.17g\n",
			     ev->time_us, type, event_tool_name(ev->tool), ev->x, ev->y,
			     ev->pressure, ev->tilt_x, ev->tilt_y);
		break;
	}
	if (n < 0)
		return -EINVAL;
	if ((size_t)n >= size)
		return -ENOSPC;
	return n;
}

struct trace_writer *trace_writer_create(const char *path, int screen_w, int screen_h,
					 struct error *err)
{
	struct trace_writer *w;

	if (screen_w <= 0 || screen_h <= 0) {
		error_at(err, -EINVAL, path, 0, "bad screen size %dx%d", screen_w, screen_h);
		return NULL;
	}
	w = calloc(1, sizeof(*w));
	if (!w) {
		error_at(err, -ENOMEM, path, 0, "out of memory");
		return NULL;
	}
	w->f = fopen(path, "w");
	if (!w->f) {
		error_at(err, -errno, path, 0, "%s", strerror(errno));
		free(w);
		return NULL;
	}
	if (fprintf(w->f, "edaha-trace 1\n# recorded by edaha\nscreen %d %d\n", screen_w,
		    screen_h) < 0 ||
	    fflush(w->f) != 0) {
		error_at(err, -errno, path, 0, "%s", strerror(errno));
		fclose(w->f);
		free(w);
		return NULL;
	}
	return w;
}

int trace_writer_write(struct trace_writer *w, const struct event *ev)
{
	char line[TRACE_LINE_MAX];
	struct event e = *ev;
	int n;

	if (w->error)
		return w->error;
	/*
	 * A recording must always read back. Events come from several clocks (tablet,
	 * GPIO) and devices may overshoot their ranges by a hair: clamp rather than lose
	 * the session. A replay may push times past the parsers' limit by its gaps:
	 * they stop there. Non-finite positions have no sensible fix and are refused.
	 */
	if (e.time_us < w->last_time)
		e.time_us = w->last_time;
	if (e.time_us > TRACE_MAX_TIME_US)
		e.time_us = TRACE_MAX_TIME_US;
	e.pressure = trace_clamp(e.pressure, 0.0, 1.0);
	e.tilt_x = trace_clamp(e.tilt_x, -90.0, 90.0);
	e.tilt_y = trace_clamp(e.tilt_y, -90.0, 90.0);
	n = trace_format_event(&e, line, sizeof(line));
	if (n < 0)
		return n;
	if (fwrite(line, 1, (size_t)n, w->f) != (size_t)n) {
		w->error = errno ? -errno : -EIO;
		return w->error;
	}
	w->last_time = e.time_us;
	/* A crash then loses at most the stroke being drawn. */
	if (e.type == EVENT_PROXIMITY_OUT || e.type == EVENT_BUTTON) {
		if (fflush(w->f) != 0) {
			w->error = errno ? -errno : -EIO;
			return w->error;
		}
	}
	return 0;
}

int trace_writer_destroy(struct trace_writer *w)
{
	int r;

	if (!w)
		return 0;
	r = w->error;
	if (fflush(w->f) != 0 && r == 0)
		r = errno ? -errno : -EIO;
	/* The kiosk gets switched off at the wall: make the recording durable. */
	if (fsync(fileno(w->f)) != 0 && r == 0 && errno != EINVAL && errno != EROFS)
		r = -errno;
	if (fclose(w->f) != 0 && r == 0)
		r = errno ? -errno : -EIO;
	free(w);
	return r;
}
