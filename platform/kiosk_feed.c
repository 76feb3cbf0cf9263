/* SPDX-License-Identifier: MIT */
/* An event into the app (kiosk_feed): kept off the app while another VT is in front,
 * stamped for the pen-to-screen figures, written to the recording. */
#include "kiosk_private.h"

#include <stdio.h>

static bool is_pen(const struct event *ev)
{
	return ev->type == EVENT_PROXIMITY_IN || ev->type == EVENT_PROXIMITY_OUT ||
	       ev->type == EVENT_TIP_DOWN || ev->type == EVENT_TIP_UP ||
	       ev->type == EVENT_MOTION || ev->type == EVENT_PEN_BUTTON;
}

/* What may still reach the app while another VT is in front: what ends a stroke or a
 * press begun before the switch. */
static bool ends_something(const struct event *ev)
{
	return ev->type == EVENT_TIP_UP || ev->type == EVENT_PROXIMITY_OUT ||
	       ((ev->type == EVENT_BUTTON || ev->type == EVENT_PEN_BUTTON) && !ev->pressed);
}

void kiosk_feed(struct kiosk *k, const struct event *ev)
{
	/* libinput and the GPIO lines stay open across a VT switch: the pen must not draw on
	 * a screen the visitor cannot see */
	if (!display_seat_active(k->display) && !ends_something(ev))
		return;
	if (is_pen(ev) && k->npending < KIOSK_MAX_PENDING)
		k->pending[k->npending++] = (struct kiosk_pending){ ev->time_us, k->shown };
	if (k->rec && trace_writer_write(k->rec, ev) < 0) {
		fprintf(stderr, "edaha: %s: cannot write the recording; recording stops\n",
			k->cfg.record);
		if (trace_writer_destroy(k->rec) < 0)
			fprintf(stderr, "edaha: %s: cannot write the recording\n", k->cfg.record);
		k->rec = NULL;
	}
	app_handle_event(k->app, ev);
}
