/* SPDX-License-Identifier: MIT */
/*
 * Prints what the kiosk's input modules make of the devices present, as an edaha trace
 * on stdout (replayable with `edaha --replay`): the pen tablet, mouse or touchscreen
 * through platform/input/input_libinput.c and the GPIO buttons through platform/input/gpio.c, for the
 * VM tests. A mode button pressed lights its LED (gpio_set_mode).
 * SIGTERM or SIGINT end it early, cleanly (the modules are destroyed, LEDs put out).
 *   input_probe [--config FILE] [--seconds N] [--screen WxH]
 */
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "config_file.h"
#include "gpio.h"
#include "input_libinput.h"
#include "trace.h"

struct probe {
	struct gpio *gpio;
	unsigned long count;
};

static void emit(void *data, const struct event *ev)
{
	struct probe *p = data;
	char line[TRACE_LINE_MAX];
	int n = trace_format_event(ev, line, sizeof(line));

	if (n < 0) {
		fprintf(stderr, "input_probe: unwritable event (type %d)\n", (int)ev->type);
		return;
	}
	fputs(line, stdout);
	if (fflush(stdout) == EOF)
		fprintf(stderr, "input_probe: stdout: %s\n", strerror(errno));
	p->count++;
	if (ev->type == EVENT_BUTTON && ev->pressed && p->gpio &&
	    config_button_is_mode((enum button)ev->button))
		gpio_set_mode(p->gpio, (enum button)ev->button);
}

static volatile sig_atomic_t stop;

static void on_signal(int sig)
{
	(void)sig;
	stop = 1;
}

static double now_s(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_MONOTONIC, &ts) < 0)
		return 0;
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

int main(int argc, char **argv)
{
	const char *conf = CONFIG_PATH;
	double seconds = 5;
	int w = 1280, h = 800, status = 0;
	struct probe probe = { 0 };
	struct config cfg;
	struct error err;
	struct input *in;
	struct kiosk_source src[2];
	struct pollfd pfd[2];

	struct sigaction sa = { .sa_handler = on_signal };

	if (sigemptyset(&sa.sa_mask) < 0 || sigaction(SIGTERM, &sa, NULL) < 0 ||
	    sigaction(SIGINT, &sa, NULL) < 0) {
		fprintf(stderr, "input_probe: sigaction: %s\n", strerror(errno));
		return 1;
	}
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--config") == 0 && i + 1 < argc)
			conf = argv[++i];
		else if (strcmp(argv[i], "--seconds") == 0 && i + 1 < argc)
			seconds = atof(argv[++i]);
		else if (strcmp(argv[i], "--screen") == 0 && i + 1 < argc &&
			 sscanf(argv[i + 1], "%dx%d", &w, &h) == 2 && w > 0 && h > 0)
			i++;
		else {
			fprintf(stderr, "usage: input_probe [--config FILE] [--seconds N] [--screen WxH]\n");
			return 2;
		}
	}
	if (config_load(conf, &cfg, stderr, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		return 2;
	}
	in = input_create(&cfg, w, h, emit, &probe, &err);
	if (!in) {
		fprintf(stderr, "%s\n", err.msg);
		return 1;
	}
	probe.gpio = gpio_create(&cfg, emit, &probe, &err);
	if (!probe.gpio) {
		fprintf(stderr, "%s\n", err.msg);
		input_destroy(in);
		return 1;
	}
	fprintf(stderr, "input_probe: %d GPIO buttons, %d LEDs\n", gpio_button_count(probe.gpio),
		gpio_led_count(probe.gpio));
	printf("edaha-trace 1\nscreen %d %d\n", w, h);
	src[0] = input_source(in);
	src[1] = gpio_source(probe.gpio);
	for (int i = 0; i < 2; i++)
		pfd[i] = (struct pollfd){ .fd = src[i].fd, .events = POLLIN };
	for (double end = now_s() + seconds; !stop && now_s() < end;) {
		int n = poll(pfd, 2, 50);

		if (n < 0 && errno != EINTR) {
			fprintf(stderr, "input_probe: poll: %s\n", strerror(errno));
			status = 1;
			break;
		}
		for (int i = 0; i < 2 && n > 0; i++) {
			if (!(pfd[i].revents & POLLIN))
				continue;
			int r = src[i].dispatch(src[i].data);

			if (r < 0) {
				fprintf(stderr, "input_probe: dispatch: %s\n", strerror(-r));
				status = 1;
				pfd[i].fd = -1;
			}
		}
	}
	fprintf(stderr, "input_probe: %lu events\n", probe.count);
	gpio_destroy(probe.gpio);
	input_destroy(in);
	return status;
}
