/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * Software debounce of one button line, pure (tests/platform/test_gpio_debounce.c):
 * a change is accepted unless it comes within the debounce time of the last accepted
 * change; a "change" to the state already held is dropped.
 */
#include <stdbool.h>
#include <stdint.h>

struct gpio_debounce {
	bool pressed;      /* the accepted state */
	bool have_time;    /* false until the first accepted change */
	uint64_t last_us;  /* time of the last accepted change */
	uint64_t window_us;
};

void gpio_debounce_init(struct gpio_debounce *d, bool pressed, uint64_t window_us);

/* An edge at t_us to `pressed`: true if it is accepted (d->pressed is then updated). A
 * time before the last accepted one (a clock that jumped back) is accepted. */
bool gpio_debounce_edge(struct gpio_debounce *d, bool pressed, uint64_t t_us);
