/* SPDX-License-Identifier: MIT */
/*
 * libinput (udev backend) -> struct event. See input_libinput.h and docs/config.md.
 */
#include "input_libinput.h"

#include <errno.h>
#include <fcntl.h>
#include <libinput.h>
#include <libudev.h>
#include <linux/input-event-codes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "input_map.h"

#define INPUT_SEAT "seat0"

/* Who holds the one pen of the app at the moment. */
enum pen_owner { OWNER_NONE = 0, OWNER_TABLET, OWNER_POINTER, OWNER_TOUCH };

struct input_device {
	struct input_device *next;
	struct libinput_device *dev; /* referenced */
	double w_mm, h_mm;           /* 0 when libinput does not know */
	bool direct;                 /* a screen tablet or touchscreen: no aspect fitting */
};

struct input {
	struct libinput *li;
	struct udev *udev;
	input_emit_fn emit;
	void *data;
	struct config cfg;
	int screen_w, screen_h;
	struct input_device *devices;

	/* the pen as the app sees it */
	enum pen_owner owner;
	struct libinput_device *owner_dev;
	bool in, down;
	struct event last; /* position, tool, pressure, tilt of the last event */
	uint64_t last_time; /* of the last event given out */
	double mouse_x, mouse_y;
	int32_t touch_slot;
	bool debug;
};

static int open_restricted(const char *path, int flags, void *user_data)
{
	(void)user_data;
	int fd = open(path, flags | O_CLOEXEC);

	return fd < 0 ? -errno : fd;
}

static void close_restricted(int fd, void *user_data)
{
	(void)user_data;
	if (close(fd) < 0)
		fprintf(stderr, "edaha: input: close: %s\n", strerror(errno));
}

static const struct libinput_interface interface = {
	.open_restricted = open_restricted,
	.close_restricted = close_restricted,
};

static uint64_t now_us(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_MONOTONIC, &ts) < 0)
		return 0;
	return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

/* libinput's own events (a tablet's proximity, timers) can be stamped a few microseconds
 * before one already given out; the event model and traces need time never to go back. */
static void deliver(struct input *in, struct event *ev)
{
	if (ev->time_us < in->last_time)
		ev->time_us = in->last_time;
	in->last_time = ev->time_us;
	in->emit(in->data, ev);
}

static void emit(struct input *in, enum event_type type, uint64_t time_us)
{
	struct event ev = in->last;

	ev.type = type;
	ev.time_us = time_us;
	ev.button = 0;
	ev.pressed = false;
	switch (type) {
	case EVENT_PROXIMITY_IN:
		in->in = true;
		break;
	case EVENT_PROXIMITY_OUT:
		in->in = false;
		break;
	case EVENT_TIP_DOWN:
		in->down = true;
		break;
	case EVENT_TIP_UP:
		in->down = false;
		ev.pressure = 0.0;
		break;
	default:
		break;
	}
	deliver(in, &ev);
}

/* Lets go of the pen: tip up and out of proximity, whoever held it. */
static void release_pen(struct input *in, uint64_t time_us)
{
	if (in->down)
		emit(in, EVENT_TIP_UP, time_us);
	if (in->in)
		emit(in, EVENT_PROXIMITY_OUT, time_us);
	in->owner = OWNER_NONE;
	in->owner_dev = NULL;
}

/* Takes the pen for owner on dev; another holder is released first. */
static void take_pen(struct input *in, enum pen_owner owner, struct libinput_device *dev,
		     uint64_t time_us)
{
	if (in->owner != OWNER_NONE && (in->owner != owner || in->owner_dev != dev))
		release_pen(in, time_us);
	in->owner = owner;
	in->owner_dev = dev;
}

static struct input_device *find_device(struct input *in, struct libinput_device *dev)
{
	for (struct input_device *d = in->devices; d; d = d->next)
		if (d->dev == dev)
			return d;
	return NULL;
}

static void map_for(const struct input *in, const struct input_device *d, struct input_map *m)
{
	enum config_area area = in->cfg.input.area;

	if (!d || d->direct)
		area = CONFIG_AREA_STRETCH;
	input_map_init(m, in->cfg.input.rotation, area, in->cfg.input.area_rect, d ? d->w_mm : 0,
		       d ? d->h_mm : 0, in->screen_w, in->screen_h);
}

static void device_added(struct input *in, struct libinput_device *dev)
{
	bool tablet = libinput_device_has_capability(dev, LIBINPUT_DEVICE_CAP_TABLET_TOOL);
	bool pointer = libinput_device_has_capability(dev, LIBINPUT_DEVICE_CAP_POINTER);
	bool touch = libinput_device_has_capability(dev, LIBINPUT_DEVICE_CAP_TOUCH);
	struct input_device *d;
	double w, h;

	if (!tablet && !pointer && !touch)
		return; /* keyboards, pads, switches: not ours */
	d = calloc(1, sizeof(*d));
	if (!d) {
		fprintf(stderr, "edaha: input: out of memory, %s ignored\n",
			libinput_device_get_name(dev));
		return;
	}
	d->dev = libinput_device_ref(dev);
	if (libinput_device_get_size(dev, &w, &h) == 0 && w > 0 && h > 0) {
		d->w_mm = w;
		d->h_mm = h;
	}
	/* libinput offers a calibration matrix on direct devices only */
	d->direct = touch || libinput_device_config_calibration_has_matrix(dev);
	d->next = in->devices;
	in->devices = d;
	fprintf(stderr, "edaha: input: %s added (%s%s%s%s)\n", libinput_device_get_name(dev),
		tablet ? "tablet " : "", pointer ? "pointer " : "", touch ? "touch " : "",
		d->direct ? "direct" : "indirect");
}

static void device_removed(struct input *in, struct libinput_device *dev)
{
	struct input_device **pp = &in->devices;

	if (in->owner_dev == dev)
		release_pen(in, now_us());
	while (*pp && (*pp)->dev != dev)
		pp = &(*pp)->next;
	if (!*pp)
		return;
	struct input_device *d = *pp;

	*pp = d->next;
	fprintf(stderr, "edaha: input: %s removed\n", libinput_device_get_name(dev));
	libinput_device_unref(d->dev);
	free(d);
}

/* ---- tablet --------------------------------------------------------------------- */

static void tablet_state(struct input *in, struct libinput_event_tablet_tool *t,
			 const struct input_device *d)
{
	struct libinput_tablet_tool *tool = libinput_event_tablet_tool_get_tool(t);
	struct input_map m;
	double tx = 0.0, ty = 0.0;

	map_for(in, d, &m);
	input_map_point(&m, libinput_event_tablet_tool_get_x_transformed(t, 1.0),
			libinput_event_tablet_tool_get_y_transformed(t, 1.0), &in->last.x,
			&in->last.y);
	in->last.tool = libinput_tablet_tool_get_type(tool) == LIBINPUT_TABLET_TOOL_TYPE_ERASER
				? EVENT_TOOL_ERASER
				: EVENT_TOOL_PEN;
	if (libinput_tablet_tool_has_pressure(tool)) {
		double p = libinput_event_tablet_tool_get_pressure(t);

		in->last.pressure = p < 0.0 ? 0.0 : p > 1.0 ? 1.0 : p;
	} else {
		in->last.pressure =
			libinput_event_tablet_tool_get_tip_state(t) == LIBINPUT_TABLET_TOOL_TIP_DOWN
				? 1.0
				: 0.0;
	}
	if (libinput_tablet_tool_has_tilt(tool)) {
		tx = libinput_event_tablet_tool_get_tilt_x(t);
		ty = libinput_event_tablet_tool_get_tilt_y(t);
	}
	input_map_tilt(&m, tx, ty, &in->last.tilt_x, &in->last.tilt_y);
}

static void tablet_event(struct input *in, struct libinput_event *e)
{
	struct libinput_event_tablet_tool *t = libinput_event_get_tablet_tool_event(e);
	struct libinput_device *dev = libinput_event_get_device(e);
	const struct input_device *d = find_device(in, dev);
	uint64_t time = libinput_event_tablet_tool_get_time_usec(t);
	enum event_tool old_tool = in->last.tool;

	if (!d)
		return;
	take_pen(in, OWNER_TABLET, dev, time);
	tablet_state(in, t, d);
	switch (libinput_event_get_type(e)) {
	case LIBINPUT_EVENT_TABLET_TOOL_PROXIMITY:
		if (libinput_event_tablet_tool_get_proximity_state(t) ==
		    LIBINPUT_TABLET_TOOL_PROXIMITY_STATE_IN) {
			if (in->in && old_tool != in->last.tool) { /* pen flipped to eraser */
				release_pen(in, time);
				take_pen(in, OWNER_TABLET, dev, time);
			}
			if (!in->in)
				emit(in, EVENT_PROXIMITY_IN, time);
		} else {
			release_pen(in, time);
		}
		break;
	case LIBINPUT_EVENT_TABLET_TOOL_TIP:
		if (!in->in)
			emit(in, EVENT_PROXIMITY_IN, time);
		if (libinput_event_tablet_tool_get_tip_state(t) == LIBINPUT_TABLET_TOOL_TIP_DOWN) {
			if (!in->down)
				emit(in, EVENT_TIP_DOWN, time);
		} else if (in->down) {
			emit(in, EVENT_TIP_UP, time);
		}
		break;
	case LIBINPUT_EVENT_TABLET_TOOL_AXIS:
		if (!in->in)
			emit(in, EVENT_PROXIMITY_IN, time);
		emit(in, EVENT_MOTION, time);
		break;
	case LIBINPUT_EVENT_TABLET_TOOL_BUTTON: {
		uint32_t b = libinput_event_tablet_tool_get_button(t);
		struct event ev = in->last;

		if (b != BTN_STYLUS && b != BTN_STYLUS2)
			break;
		ev.type = EVENT_PEN_BUTTON;
		ev.time_us = time;
		ev.button = b == BTN_STYLUS ? EVENT_PEN_BUTTON_STYLUS : EVENT_PEN_BUTTON_STYLUS2;
		ev.pressed = libinput_event_tablet_tool_get_button_state(t) ==
			     LIBINPUT_BUTTON_STATE_PRESSED;
		deliver(in, &ev);
		break;
	}
	default:
		break;
	}
}

/* ---- mouse ---------------------------------------------------------------------- */

static void pointer_event(struct input *in, struct libinput_event *e)
{
	struct libinput_event_pointer *p = libinput_event_get_pointer_event(e);
	struct libinput_device *dev = libinput_event_get_device(e);
	uint64_t time = libinput_event_pointer_get_time_usec(p);
	enum libinput_event_type type = libinput_event_get_type(e);

	if (!find_device(in, dev))
		return;
	/* a mouse does not take the pen from a tablet or finger that holds it down */
	if (in->owner != OWNER_POINTER && in->owner != OWNER_NONE && in->down)
		return;
	take_pen(in, OWNER_POINTER, dev, time);
	if (type == LIBINPUT_EVENT_POINTER_MOTION) {
		in->mouse_x += libinput_event_pointer_get_dx(p);
		in->mouse_y += libinput_event_pointer_get_dy(p);
	} else if (type == LIBINPUT_EVENT_POINTER_MOTION_ABSOLUTE) {
		in->mouse_x = libinput_event_pointer_get_absolute_x_transformed(p, (uint32_t)in->screen_w);
		in->mouse_y = libinput_event_pointer_get_absolute_y_transformed(p, (uint32_t)in->screen_h);
	}
	in->mouse_x = in->mouse_x < 0 ? 0 : in->mouse_x > in->screen_w ? in->screen_w : in->mouse_x;
	in->mouse_y = in->mouse_y < 0 ? 0 : in->mouse_y > in->screen_h ? in->screen_h : in->mouse_y;
	in->last.x = in->mouse_x;
	in->last.y = in->mouse_y;
	in->last.tool = EVENT_TOOL_PEN;
	in->last.tilt_x = in->last.tilt_y = 0.0;
	in->last.pressure = in->down ? 1.0 : 0.0;
	if (!in->in)
		emit(in, EVENT_PROXIMITY_IN, time);
	switch (type) {
	case LIBINPUT_EVENT_POINTER_MOTION:
	case LIBINPUT_EVENT_POINTER_MOTION_ABSOLUTE:
		emit(in, EVENT_MOTION, time);
		break;
	case LIBINPUT_EVENT_POINTER_BUTTON:
		if (libinput_event_pointer_get_button(p) != BTN_LEFT)
			break;
		if (libinput_event_pointer_get_button_state(p) == LIBINPUT_BUTTON_STATE_PRESSED) {
			in->last.pressure = 1.0;
			if (!in->down)
				emit(in, EVENT_TIP_DOWN, time);
		} else if (in->down) {
			emit(in, EVENT_TIP_UP, time);
		}
		break;
	default:
		break;
	}
}

/* ---- touchscreen ---------------------------------------------------------------- */

static void touch_event(struct input *in, struct libinput_event *e)
{
	struct libinput_event_touch *t = libinput_event_get_touch_event(e);
	struct libinput_device *dev = libinput_event_get_device(e);
	const struct input_device *d = find_device(in, dev);
	enum libinput_event_type type = libinput_event_get_type(e);
	uint64_t time = libinput_event_touch_get_time_usec(t);
	bool ours = in->owner == OWNER_TOUCH && in->owner_dev == dev;
	struct input_map m;

	if (!d || type == LIBINPUT_EVENT_TOUCH_FRAME)
		return;
	if (type == LIBINPUT_EVENT_TOUCH_CANCEL) {
		if (ours)
			release_pen(in, time);
		return;
	}
	if (type == LIBINPUT_EVENT_TOUCH_DOWN) {
		if ((ours && in->down) || (in->owner != OWNER_NONE && !ours && in->down))
			return; /* a second finger, or someone else draws */
		take_pen(in, OWNER_TOUCH, dev, time);
		in->touch_slot = libinput_event_touch_get_seat_slot(t);
	} else if (!ours || libinput_event_touch_get_seat_slot(t) != in->touch_slot) {
		return;
	}
	if (type == LIBINPUT_EVENT_TOUCH_UP) {
		release_pen(in, time);
		return;
	}
	map_for(in, d, &m);
	input_map_point(&m, libinput_event_touch_get_x_transformed(t, 1),
			libinput_event_touch_get_y_transformed(t, 1), &in->last.x, &in->last.y);
	in->last.tool = EVENT_TOOL_PEN;
	in->last.pressure = 1.0;
	in->last.tilt_x = in->last.tilt_y = 0.0;
	if (type == LIBINPUT_EVENT_TOUCH_DOWN) {
		if (!in->in)
			emit(in, EVENT_PROXIMITY_IN, time);
		emit(in, EVENT_TIP_DOWN, time);
	} else {
		emit(in, EVENT_MOTION, time);
	}
}

/* ---- the module ----------------------------------------------------------------- */

int input_dispatch(void *data)
{
	struct input *in = data;
	struct libinput_event *e;
	int r = libinput_dispatch(in->li);

	if (r < 0)
		return r;
	while ((e = libinput_get_event(in->li))) {
		if (in->debug)
			fprintf(stderr, "edaha: input: libinput event %d\n",
				(int)libinput_event_get_type(e));
		switch (libinput_event_get_type(e)) {
		case LIBINPUT_EVENT_DEVICE_ADDED:
			device_added(in, libinput_event_get_device(e));
			break;
		case LIBINPUT_EVENT_DEVICE_REMOVED:
			device_removed(in, libinput_event_get_device(e));
			break;
		case LIBINPUT_EVENT_TABLET_TOOL_AXIS:
		case LIBINPUT_EVENT_TABLET_TOOL_PROXIMITY:
		case LIBINPUT_EVENT_TABLET_TOOL_TIP:
		case LIBINPUT_EVENT_TABLET_TOOL_BUTTON:
			tablet_event(in, e);
			break;
		case LIBINPUT_EVENT_POINTER_MOTION:
		case LIBINPUT_EVENT_POINTER_MOTION_ABSOLUTE:
		case LIBINPUT_EVENT_POINTER_BUTTON:
			pointer_event(in, e);
			break;
		case LIBINPUT_EVENT_TOUCH_DOWN:
		case LIBINPUT_EVENT_TOUCH_UP:
		case LIBINPUT_EVENT_TOUCH_MOTION:
		case LIBINPUT_EVENT_TOUCH_CANCEL:
		case LIBINPUT_EVENT_TOUCH_FRAME:
			touch_event(in, e);
			break;
		default:
			break; /* keyboards, gestures, pads, switches: not ours */
		}
		libinput_event_destroy(e);
	}
	return 0;
}

struct input *input_create(const struct config *cfg, int screen_w, int screen_h,
			   input_emit_fn emit_fn, void *data, struct error *err)
{
	struct input *in = calloc(1, sizeof(*in));
	int r;

	if (!in) {
		error_set(err, -ENOMEM, "input: out of memory");
		return NULL;
	}
	in->emit = emit_fn;
	in->data = data;
	if (cfg)
		in->cfg = *cfg;
	else
		config_defaults(&in->cfg);
	in->screen_w = screen_w > 0 ? screen_w : 1;
	in->screen_h = screen_h > 0 ? screen_h : 1;
	in->mouse_x = in->screen_w / 2.0;
	in->mouse_y = in->screen_h / 2.0;
	in->udev = udev_new();
	if (!in->udev) {
		error_set(err, -ENOMEM, "input: udev_new failed");
		goto fail;
	}
	in->li = libinput_udev_create_context(&interface, in, in->udev);
	if (!in->li) {
		error_set(err, -ENOMEM, "input: libinput_udev_create_context failed");
		goto fail;
	}
	/* EDAHA_INPUT_DEBUG=1: libinput's own debug log on stderr, and every event type */
	in->debug = getenv("EDAHA_INPUT_DEBUG") && strcmp(getenv("EDAHA_INPUT_DEBUG"), "1") == 0;
	if (in->debug)
		libinput_log_set_priority(in->li, LIBINPUT_LOG_PRIORITY_DEBUG);
	r = libinput_udev_assign_seat(in->li, INPUT_SEAT);
	if (r != 0) {
		error_set(err, -ENODEV, "input: cannot assign seat %s (udev running?)", INPUT_SEAT);
		goto fail;
	}
	/* the devices present now arrive as DEVICE_ADDED events */
	r = input_dispatch(in);
	if (r < 0) {
		error_set(err, r, "input: libinput_dispatch: %s", strerror(-r));
		goto fail;
	}
	return in;
fail:
	input_destroy(in);
	return NULL;
}

void input_destroy(struct input *in)
{
	if (!in)
		return;
	while (in->devices) {
		struct input_device *d = in->devices;

		in->devices = d->next;
		libinput_device_unref(d->dev);
		free(d);
	}
	if (in->li)
		libinput_unref(in->li);
	if (in->udev)
		udev_unref(in->udev);
	free(in);
}

struct kiosk_source input_source(struct input *in)
{
	return (struct kiosk_source){ .fd = libinput_get_fd(in->li),
				      .dispatch = input_dispatch,
				      .data = in };
}

void input_set_screen(struct input *in, int screen_w, int screen_h)
{
	in->screen_w = screen_w > 0 ? screen_w : 1;
	in->screen_h = screen_h > 0 ? screen_h : 1;
}
