/* SPDX-License-Identifier: MIT */
#include "kiosk_input.h"

#include <stdio.h>
#include <stdlib.h>

#include "config.h"
#include "input_thread.h"
#if HAVE_LIBINPUT
#include "input_libinput.h"
#endif
#if HAVE_GPIOD
#include "gpio.h"
#endif

struct kiosk_input {
	struct input_thread *thread;
#if HAVE_LIBINPUT
	struct input *pen;
#endif
#if HAVE_GPIOD
	struct gpio *gpio;
#endif
};

/* On the main loop's thread: the queued events into the app. */
static void deliver(void *k, const struct event *ev)
{
	kiosk_feed(k, ev);
}

#if HAVE_GPIOD
static void light_mode(void *data, enum button mode)
{
	struct kiosk_input *ki = data;

	/* the input thread reads the buttons of the same chips meanwhile */
	input_thread_lock(ki->thread);
	gpio_set_mode(ki->gpio, mode);
	input_thread_unlock(ki->thread);
}
#endif

#if HAVE_LIBINPUT || HAVE_GPIOD
static int add(struct kiosk_input *ki, struct kiosk_source src)
{
	int ret = input_thread_add(ki->thread, &src);

	if (ret < 0)
		fputs("edaha: input: too many input sources\n", stderr);
	return ret;
}
#endif

struct kiosk_input *kiosk_input_create(const struct config *conf, struct kiosk *k)
{
	struct kiosk_input *ki = calloc(1, sizeof(*ki));
	struct error err = { { 0 } };
	struct kiosk_source src;
	int w, h;

	(void)w, (void)h, (void)conf;
	if (!ki) {
		fputs("edaha: out of memory\n", stderr);
		return NULL;
	}
	ki->thread = input_thread_create(deliver, k, &err);
	if (!ki->thread)
		goto fail;
#if HAVE_LIBINPUT
	kiosk_size(k, &w, &h);
	ki->pen = input_create(conf, w, h, input_thread_emit, ki->thread, &err);
	if (!ki->pen)
		fprintf(stderr, "edaha: warning: no pen input: %s\n", err.msg);
	else if (add(ki, input_source(ki->pen)) < 0)
		goto fail;
#endif
#if HAVE_GPIOD
	ki->gpio = gpio_create(conf, input_thread_emit, ki->thread, &err);
	if (!ki->gpio)
		fprintf(stderr, "edaha: warning: no GPIO buttons: %s\n", err.msg);
	else if (gpio_button_count(ki->gpio) > 0 && add(ki, gpio_source(ki->gpio)) < 0)
		goto fail;
	if (ki->gpio && gpio_led_count(ki->gpio) > 0)
		kiosk_set_mode_listener(k, light_mode, ki);
#endif
	if (input_thread_start(ki->thread, &err) < 0)
		goto fail;
	src = input_thread_source(ki->thread);
	if (kiosk_add_source(k, &src) < 0) {
		fputs("edaha: out of memory\n", stderr);
		goto fail_quiet;
	}
	return ki;

fail:
	if (err.msg[0])
		fprintf(stderr, "edaha: %s\n", err.msg);
fail_quiet:
	kiosk_input_destroy(ki);
	return NULL;
}

void kiosk_input_destroy(struct kiosk_input *ki)
{
	if (!ki)
		return;
	/* the thread first: nothing dispatches the sources after this */
	input_thread_destroy(ki->thread);
#if HAVE_GPIOD
	gpio_destroy(ki->gpio);
#endif
#if HAVE_LIBINPUT
	input_destroy(ki->pen);
#endif
	free(ki);
}
