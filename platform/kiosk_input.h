/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The kiosk's input, put together: the pen tablet, mouse or touchscreen (input_libinput,
 * where built) and the GPIO buttons (gpio, where built) read on the input thread
 * (input_thread.h) and fed to the kiosk; the mode LEDs follow the mode the kiosk shows.
 * A missing pen or button chip is a warning: the kiosk still shows itself and its
 * on-screen buttons.
 */
#include "config_file.h"
#include "kiosk.h"

struct kiosk_input;

/* Starts reading. NULL (message printed) only when the machine fails: no memory, no
 * thread. */
struct kiosk_input *kiosk_input_create(const struct config *conf, struct kiosk *k);
/* Stops reading; before kiosk_destroy (the LEDs go out). */
void kiosk_input_destroy(struct kiosk_input *ki);
