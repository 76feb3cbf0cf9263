/* SPDX-License-Identifier: MIT */
/* What a frame shows, as a value (struct kiosk_look), and when the screen changes with no
 * input: the facts behind the loop's decision to draw (frame_due) and to wake (the UI
 * timer). Functions of the app and the clock alone. */
#include "kiosk_private.h"

#include <string.h>

void kiosk_look_of(const struct app *app, uint64_t now_us, struct kiosk_look *l)
{
	struct app_side_item items[APP_SIDE_MAX];

	memset(l, 0, sizeof(*l)); /* padding too, though only fields are compared */
	l->status = app_status_at(app, now_us, NULL);
	l->attract = app_attract_at(app, now_us, NULL);
	/* each only where it shows: a planting that changes nothing on the screen (the
	 * forest off it, no message with a number) draws no frame */
	l->forest = app_forest_at(app, now_us);
	l->forest_serial = l->forest ? app->forest->serial : 0;
	l->status_number = l->status == APP_STATUS_IN_FOREST ? app->status_number : 0;
	l->forest_number = l->status == APP_STATUS_SAVED || l->status == APP_STATUS_SAVED_USB
				   ? app->forest_number
				   : 0;
	l->mesh_serial = app->mesh_serial;
	l->previews_serial = app->previews_serial;
	l->stroke_points = app->stroke.npoints;
	l->stroke_active = app->stroke.active;
	l->pen_in = app->pen.in_proximity;
	l->pen_tool = app->pen.tool;
	l->pen_x = app->pen.x;
	l->pen_y = app->pen.y;
	l->orbiting = app->orbiting;
	l->turning = app->turning;
	l->ui_held = app->ui_button_held;
	l->ui_button = app->ui_button;
	l->side_held = app->side_held;
	l->mode = app->mode;
	l->pattern = app->pattern;
	memcpy(l->buttons, app->buttons_down, sizeof(l->buttons));
	l->camera = app->camera;
	l->selected = app->selected;
	l->suggestions = app->suggestions;
	l->season = app->tree.season;
	l->nside = app_side_items(app, items);
	for (size_t i = 0; i < l->nside; i++) {
		enum button b = items[i].button;

		l->side[i] = (struct kiosk_side_look){
			.thumbnail = items[i].thumbnail,
			.lit = items[i].lit,
			.enabled = b < BUTTON_GEN_MORE || b > BUTTON_GEN_BARER || app_gen_possible(app, b),
			.button = b,
			.tap = items[i].tap,
			.preview = items[i].preview,
		};
	}
}

static bool side_equal(const struct kiosk_look *a, const struct kiosk_look *b)
{
	if (a->nside != b->nside)
		return false;
	for (size_t i = 0; i < a->nside; i++) {
		const struct kiosk_side_look *x = &a->side[i], *y = &b->side[i];

		if (x->thumbnail != y->thumbnail || x->lit != y->lit || x->enabled != y->enabled ||
		    x->button != y->button || x->tap != y->tap || x->preview != y->preview)
			return false;
	}
	return true;
}

bool kiosk_look_equal(const struct kiosk_look *a, const struct kiosk_look *b)
{
	return a->mesh_serial == b->mesh_serial && a->previews_serial == b->previews_serial &&
	       a->stroke_points == b->stroke_points && a->stroke_active == b->stroke_active &&
	       a->pen_in == b->pen_in && a->pen_tool == b->pen_tool && a->pen_x == b->pen_x &&
	       a->pen_y == b->pen_y && a->orbiting == b->orbiting && a->turning == b->turning &&
	       a->ui_held == b->ui_held && a->ui_button == b->ui_button &&
	       a->side_held == b->side_held && a->mode == b->mode && a->pattern == b->pattern &&
	       memcmp(a->buttons, b->buttons, sizeof(a->buttons)) == 0 &&
	       a->camera.yaw == b->camera.yaw && a->camera.pitch == b->camera.pitch &&
	       a->selected == b->selected && a->suggestions == b->suggestions &&
	       a->status == b->status && a->attract == b->attract && a->season == b->season &&
	       a->forest == b->forest && a->forest_serial == b->forest_serial &&
	       a->status_number == b->status_number && a->forest_number == b->forest_number &&
	       side_equal(a, b);
}

/* Whether frames must keep coming at now_us without any input: the turn into 3D, new
 * leaves unfolding, a grown bark swelling, a message fading out (a vine growing:
 * app_vines_advance). */
bool kiosk_animating_at(const struct app *app, uint64_t now_us, bool turning)
{
	uint64_t until;

	struct app_unfold_span span;

	if (turning || app_unfold_at(app, now_us, &span, 1) > 0)
		return true;
	/* a grow press under way (its message's dots move) or its bark swelling */
	if (app->grow_waiting)
		return true;
	if (app->swell_start_us != UINT64_MAX &&
	    (now_us < app->swell_start_us || now_us - app->swell_start_us < APP_SWELL_US))
		return true;
	return app_status_at(app, now_us, &until) != APP_STATUS_NONE &&
	       now_us + APP_STATUS_FADE_US >= until;
}

/* When the idle reset is due for the drawing there is (UINT64_MAX: never). */
uint64_t kiosk_reset_at(const struct app *app, uint64_t reset_after_us)
{
	/* an empty canvas has nothing to archive; a pen on the tablet is someone there */
	if (!reset_after_us || !app->doc.nops || app->stroke.active || app->pen.in_proximity)
		return UINT64_MAX;
	return app->last_time_us + reset_after_us;
}

/* The next moment the screen changes with no input (UINT64_MAX: none): a message
 * starts fading or ends, the attract screen begins, the idle reset. */
uint64_t kiosk_next_change(const struct app *app, uint64_t now_us, uint64_t reset_after_us)
{
	uint64_t until, from, next = kiosk_reset_at(app, reset_after_us);

	/* a held message (saving) changes when its result comes, not by the clock */
	if (app_status_at(app, now_us, &until) != APP_STATUS_NONE && until != UINT64_MAX)
		next = now_us + APP_STATUS_FADE_US < until ? until - APP_STATUS_FADE_US : until;
	if (!app_attract_at(app, now_us, &from) && from < next)
		next = from;
	return next;
}
