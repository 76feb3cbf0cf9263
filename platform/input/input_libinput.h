/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The pen tablet (and a mouse or touchscreen) through libinput's udev backend, seat0:
 * tablet tool proximity, tip, pressure, tilt, pen buttons and the eraser; a mouse's left
 * button and the first finger on a touchscreen act as the pen tip. Devices come and go at
 * any time; devices with none of these capabilities are ignored. Positions are screen
 * pixels mapped as config.input says (input_map.h).
 */
#include "config_file.h"
#include "error.h"
#include "input_source.h"

struct input;

/* NULL with a message on failure (no udev, no seat). Devices are opened with open(2):
 * the caller needs read access to /dev/input/event*. */
struct input *input_create(const struct config *cfg, int screen_w, int screen_h,
			   input_emit_fn emit, void *data, struct error *err);
void input_destroy(struct input *in);

/* The descriptor to poll; its dispatch reads every pending event (0 or -errno). */
struct kiosk_source input_source(struct input *in);
int input_dispatch(void *in);

/* After a mode change or a rotated display: positions from now on for this size. */
void input_set_screen(struct input *in, int screen_w, int screen_h);
