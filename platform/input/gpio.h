/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The mode/action buttons and the mode LEDs on GPIO lines (libgpiod, v1 API or v2 when
 * built against libgpiod >= 2). Lines are found by chip label and line name or offset as
 * config.gpio says; both edges, active-low, pull-up, software debounce
 * (gpio_debounce.h). A chip or line that cannot be found or requested is a warning on
 * stderr: the kiosk runs without that button.
 */
#include "config_file.h"
#include "error.h"
#include "input_source.h"

struct gpio;

/* NULL only when out of memory or without epoll; missing lines are warnings. */
struct gpio *gpio_create(const struct config *cfg, input_emit_fn emit, void *data,
			 struct error *err);
void gpio_destroy(struct gpio *g);

/* One descriptor for all the button lines; dispatch reads their edges (0 or -errno). */
struct kiosk_source gpio_source(struct gpio *g);
int gpio_dispatch(void *g);

/* Lights the LED of mode (a mode button) and puts out the others; BUTTON_COUNT: none. */
void gpio_set_mode(struct gpio *g, enum button mode);

/* How many button lines and LEDs were found and requested. */
int gpio_button_count(const struct gpio *g);
int gpio_led_count(const struct gpio *g);
