/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "app.h"
#include "event.h"
#include "render.h"

/*
 * The words on the kiosk's screen, in each language: short, in words a child says
 * (hiragana for Japanese), UTF-8.
 */

/* The label under a button's icon. */
const char *labels_button(enum button b, enum render_lang lang);
/* A status message; NULL for APP_STATUS_NONE (or out of range). */
const char *labels_status(enum app_status s, enum render_lang lang);
/* A status message with its number in place of '#' (APP_STATUS_IN_FOREST) into out. 0,
 * -EINVAL (no message) or -ENOSPC (out too small). */
int labels_format(enum app_status s, enum render_lang lang, uint64_t number, char *out,
		  size_t size);
/* The attract screen's invitation. */
const char *labels_attract(enum render_lang lang);
/* String i of a language, for i from 0 until NULL: every one the screen may show (to
 * check that a font has their characters). */
const char *labels_nth(enum render_lang lang, size_t i);
