/* SPDX-License-Identifier: MIT */
/* What the kiosk tells the visitor between edits: status messages and the attract screen.
 * Both are functions of the app's clock (event times) and the time asked about, so a
 * headless run can render any moment and the kiosk knows when to wake up next. */
#include <stdint.h>

#include "app.h"

void app_set_status(struct app *app, enum app_status status, uint64_t now_us)
{
	if (status < APP_STATUS_NONE || status >= APP_STATUS_COUNT)
		status = APP_STATUS_NONE;
	app->status = status;
	app->status_us = now_us;
	app->status_held = false;
}

void app_hold_status(struct app *app, enum app_status status, uint64_t now_us)
{
	app_set_status(app, status, now_us);
	app->status_held = app->status != APP_STATUS_NONE;
}

enum app_status app_status_at(const struct app *app, uint64_t now_us, uint64_t *until_us)
{
	/* a held message has no end, and so no fade: the kiosk's timer waits for none */
	uint64_t until = app->status_held ? UINT64_MAX : app->status_us + APP_STATUS_US;

	if (until_us)
		*until_us = until;
	if (app->status == APP_STATUS_NONE || now_us < app->status_us || now_us >= until)
		return APP_STATUS_NONE;
	return app->status;
}

void app_tell_forest_number(struct app *app, uint64_t number, uint64_t now_us)
{
	if (!number)
		return;
	app_set_status(app, APP_STATUS_IN_FOREST, now_us);
	app->status_number = number;
}

void app_set_forest_number(struct app *app, uint64_t number)
{
	app->forest_number = number;
}

bool app_attract_at(const struct app *app, uint64_t now_us, uint64_t *from_us)
{
	uint64_t from = UINT64_MAX;

	if (app->attract_after_us && app->last_time_us <= UINT64_MAX - app->attract_after_us)
		from = app->last_time_us + app->attract_after_us;
	if (from_us)
		*from_us = from;
	return now_us >= from;
}

bool app_forest_at(const struct app *app, uint64_t now_us)
{
	return app->forest && app->forest->ntrees > 0 && now_us != UINT64_MAX &&
	       app_attract_at(app, now_us, NULL);
}
