/* SPDX-License-Identifier: MIT */
#include "gpio_debounce.h"

void gpio_debounce_init(struct gpio_debounce *d, bool pressed, uint64_t window_us)
{
	d->pressed = pressed;
	d->have_time = false;
	d->last_us = 0;
	d->window_us = window_us;
}

bool gpio_debounce_edge(struct gpio_debounce *d, bool pressed, uint64_t t_us)
{
	if (pressed == d->pressed)
		return false;
	/* a time before the last one is a clock that jumped: the window starts again */
	if (d->have_time && t_us >= d->last_us && t_us - d->last_us < d->window_us)
		return false;
	d->pressed = pressed;
	d->have_time = true;
	d->last_us = t_us;
	return true;
}
