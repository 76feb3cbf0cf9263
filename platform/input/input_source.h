/* SPDX-License-Identifier: MIT */
#pragma once

/* What the input modules (input_libinput, gpio) share: the loop's source type and how
 * they hand over events. */
#include "event.h"
#include "kiosk_source.h"

/* Called for every event a source makes, in order, from its dispatch. */
typedef void (*input_emit_fn)(void *data, const struct event *ev);
