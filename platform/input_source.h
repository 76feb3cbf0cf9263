/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The kiosk loop polls descriptors given as struct kiosk_source (platform/kiosk_source.h);
 * until that header lands this spells out the same struct, so the input modules build.
 */
#ifdef __has_include
#if __has_include("kiosk_source.h")
#include "kiosk_source.h"
#define INPUT_HAVE_KIOSK_SOURCE 1
#endif
#endif

#ifndef INPUT_HAVE_KIOSK_SOURCE
/* fd becomes readable: call dispatch(data); a negative return is -errno, fatal. */
struct kiosk_source {
	int fd;
	int (*dispatch)(void *data);
	void *data;
};
#endif

#include "event.h"

/* How the input modules hand over events. */
typedef void (*input_emit_fn)(void *data, const struct event *ev);
