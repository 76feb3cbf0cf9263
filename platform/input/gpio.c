/* SPDX-License-Identifier: MIT */
/*
 * GPIO buttons and LEDs through libgpiod. EDAHA_GPIOD_V2 (set by platform/meson.build
 * when libgpiod >= 2) picks the v2 API; otherwise the v1 API of Debian 12 (1.6). All
 * button lines' descriptors sit in one epoll set, so the loop polls one descriptor.
 */
#include "gpio.h"

#include <dirent.h>
#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "gpio_debounce.h"

#ifndef EDAHA_GPIOD_V2
#define EDAHA_GPIOD_V2 0
#endif

#define GPIO_CONSUMER "edaha"
#define GPIO_EVENTS_AT_ONCE 16

struct gpio_line {
	enum button button;
	const struct config_gpio_line *conf;
	int fd;
	struct gpio_debounce db;
	bool recheck; /* a change was dropped in the window: read the line when it closes */
#if EDAHA_GPIOD_V2
	struct gpiod_line_request *req;
	unsigned int offset;
#else
	struct gpiod_chip *chip;
	struct gpiod_line *line;
#endif
};

struct gpio {
	int epfd;
	int timerfd; /* fires when a debounce window with a dropped change closes */
	input_emit_fn emit;
	void *data;
	struct config cfg;
	struct gpio_line buttons[BUTTON_COUNT], leds[BUTTON_COUNT];
	int nbuttons, nleds;
#if EDAHA_GPIOD_V2
	struct gpiod_edge_event_buffer *events;
#endif
};

static void warn_line(const struct config_gpio_line *c, const char *kind, enum button b,
		      const char *what)
{
	char line[CONFIG_NAME_MAX + 16];

	if (c->offset >= 0)
		snprintf(line, sizeof(line), "%d", c->offset);
	else
		snprintf(line, sizeof(line), "\"%s\"", c->name);
	fprintf(stderr, "edaha: warning: gpio %s %s (chip \"%s\" line %s, config line %lu): %s\n",
		kind, button_name(b), c->chip, line, c->conf_line, what);
}

#if EDAHA_GPIOD_V2
/* ---- libgpiod v2 ---------------------------------------------------------------- */

/* Opens the chip whose label (or name, "gpiochip0") is label: NULL if none. */
static struct gpiod_chip *open_chip(const char *label)
{
	struct gpiod_chip *found = NULL;
	struct dirent *de;
	DIR *dir = opendir("/dev");

	if (!dir)
		return NULL;
	while (!found && (de = readdir(dir))) {
		char path[300];
		struct gpiod_chip *chip;
		struct gpiod_chip_info *info;

		if (strncmp(de->d_name, "gpiochip", 8) != 0)
			continue;
		snprintf(path, sizeof(path), "/dev/%s", de->d_name);
		chip = gpiod_chip_open(path);
		if (!chip)
			continue;
		info = gpiod_chip_get_info(chip);
		if (info && (strcmp(gpiod_chip_info_get_label(info), label) == 0 ||
			     strcmp(gpiod_chip_info_get_name(info), label) == 0))
			found = chip;
		if (info)
			gpiod_chip_info_free(info);
		if (!found)
			gpiod_chip_close(chip);
	}
	if (closedir(dir) < 0)
		fprintf(stderr, "edaha: gpio: closedir: %s\n", strerror(errno));
	return found;
}

static int request(struct gpio_line *l, bool output, const char **why)
{
	const struct config_gpio_line *c = l->conf;
	struct gpiod_chip *chip = open_chip(c->chip);
	struct gpiod_line_settings *s = NULL;
	struct gpiod_line_config *lc = NULL;
	struct gpiod_request_config *rc = NULL;
	int off, r = -1;

	*why = "no such chip";
	if (!chip)
		return -1;
	off = c->offset >= 0 ? c->offset : gpiod_chip_get_line_offset_from_name(chip, c->name);
	*why = "no such line";
	if (off < 0)
		goto out;
	*why = "out of memory";
	s = gpiod_line_settings_new();
	lc = gpiod_line_config_new();
	rc = gpiod_request_config_new();
	if (!s || !lc || !rc)
		goto out;
	*why = "bad line settings";
	gpiod_line_settings_set_active_low(s, c->active_low);
	if (output) {
		if (gpiod_line_settings_set_direction(s, GPIOD_LINE_DIRECTION_OUTPUT) < 0 ||
		    gpiod_line_settings_set_output_value(s, GPIOD_LINE_VALUE_INACTIVE) < 0)
			goto out;
	} else {
		if (gpiod_line_settings_set_direction(s, GPIOD_LINE_DIRECTION_INPUT) < 0 ||
		    gpiod_line_settings_set_edge_detection(s, GPIOD_LINE_EDGE_BOTH) < 0 ||
		    gpiod_line_settings_set_event_clock(s, GPIOD_LINE_CLOCK_MONOTONIC) < 0 ||
		    (c->pull_up && gpiod_line_settings_set_bias(s, GPIOD_LINE_BIAS_PULL_UP) < 0))
			goto out;
	}
	unsigned int uoff = (unsigned int)off;

	if (gpiod_line_config_add_line_settings(lc, &uoff, 1, s) < 0)
		goto out;
	gpiod_request_config_set_consumer(rc, GPIO_CONSUMER);
	*why = "request failed (busy, or no permission?)";
	l->req = gpiod_chip_request_lines(chip, rc, lc);
	if (!l->req)
		goto out;
	l->offset = uoff;
	l->fd = gpiod_line_request_get_fd(l->req);
	r = 0;
out:
	if (rc)
		gpiod_request_config_free(rc);
	if (lc)
		gpiod_line_config_free(lc);
	if (s)
		gpiod_line_settings_free(s);
	gpiod_chip_close(chip); /* a v2 request lives on without its chip */
	return r;
}

static int line_value(struct gpio_line *l)
{
	enum gpiod_line_value v = gpiod_line_request_get_value(l->req, l->offset);

	return v == GPIOD_LINE_VALUE_ERROR ? -1 : v == GPIOD_LINE_VALUE_ACTIVE;
}

static int set_value(struct gpio_line *l, bool on)
{
	return gpiod_line_request_set_value(l->req, l->offset,
					    on ? GPIOD_LINE_VALUE_ACTIVE
					       : GPIOD_LINE_VALUE_INACTIVE);
}

static void release(struct gpio_line *l)
{
	if (l->req)
		gpiod_line_request_release(l->req);
	l->req = NULL;
}

/* Reads up to GPIO_EVENTS_AT_ONCE edges: calls edge() for each. */
static int read_edges(struct gpio *g, struct gpio_line *l,
		      void (*edge)(struct gpio *, struct gpio_line *, bool, uint64_t))
{
	int n = gpiod_line_request_read_edge_events(l->req, g->events, GPIO_EVENTS_AT_ONCE);

	if (n < 0)
		return -errno;
	for (int i = 0; i < n; i++) {
		struct gpiod_edge_event *e =
			gpiod_edge_event_buffer_get_event(g->events, (unsigned long)i);

		if (!e)
			continue;
		edge(g, l, gpiod_edge_event_get_event_type(e) == GPIOD_EDGE_EVENT_RISING_EDGE,
		     gpiod_edge_event_get_timestamp_ns(e) / 1000u);
	}
	return 0;
}

#else
/* ---- libgpiod v1 (1.6) ---------------------------------------------------------- */

static struct gpiod_chip *open_chip(const char *label)
{
	struct gpiod_chip_iter *it = gpiod_chip_iter_new();
	struct gpiod_chip *chip, *found = NULL;

	if (!it)
		return NULL;
	while ((chip = gpiod_chip_iter_next_noclose(it))) {
		if (!found && (strcmp(gpiod_chip_label(chip), label) == 0 ||
			       strcmp(gpiod_chip_name(chip), label) == 0))
			found = chip;
		else
			gpiod_chip_close(chip);
	}
	gpiod_chip_iter_free_noclose(it);
	return found;
}

static int request(struct gpio_line *l, bool output, const char **why)
{
	const struct config_gpio_line *c = l->conf;
	struct gpiod_line_request_config rc = { .consumer = GPIO_CONSUMER };

	*why = "no such chip";
	l->chip = open_chip(c->chip);
	if (!l->chip)
		return -1;
	l->line = c->offset >= 0 ? gpiod_chip_get_line(l->chip, (unsigned int)c->offset)
				 : gpiod_chip_find_line(l->chip, c->name);
	*why = "no such line";
	if (!l->line)
		goto fail;
	if (c->active_low)
		rc.flags |= GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW;
	*why = "request failed (busy, or no permission?)";
	if (output) {
		rc.request_type = GPIOD_LINE_REQUEST_DIRECTION_OUTPUT;
		if (gpiod_line_request(l->line, &rc, 0) < 0)
			goto fail;
		return 0;
	}
	rc.request_type = GPIOD_LINE_REQUEST_EVENT_BOTH_EDGES;
	if (c->pull_up)
		rc.flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
	if (gpiod_line_request(l->line, &rc, 0) < 0) {
		/* kernels before 5.5 know no bias flags: try without, and say so */
		if (!c->pull_up)
			goto fail;
		rc.flags &= ~(int)GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
		if (gpiod_line_request(l->line, &rc, 0) < 0)
			goto fail;
		warn_line(c, "button", l->button, "pull-up not supported here, line requested without");
	}
	l->fd = gpiod_line_event_get_fd(l->line);
	if (l->fd < 0) {
		*why = "no event descriptor";
		goto fail;
	}
	return 0;
fail:
	gpiod_chip_close(l->chip); /* releases the line too */
	l->chip = NULL;
	l->line = NULL;
	return -1;
}

static int line_value(struct gpio_line *l)
{
	return gpiod_line_get_value(l->line);
}

static int set_value(struct gpio_line *l, bool on)
{
	return gpiod_line_set_value(l->line, on ? 1 : 0);
}

static void release(struct gpio_line *l)
{
	if (l->chip)
		gpiod_chip_close(l->chip);
	l->chip = NULL;
	l->line = NULL;
}

static int read_edges(struct gpio *g, struct gpio_line *l,
		      void (*edge)(struct gpio *, struct gpio_line *, bool, uint64_t))
{
	struct gpiod_line_event ev[GPIO_EVENTS_AT_ONCE];
	int n = gpiod_line_event_read_fd_multiple(l->fd, ev, GPIO_EVENTS_AT_ONCE);

	if (n < 0)
		return -errno;
	for (int i = 0; i < n; i++)
		edge(g, l, ev[i].event_type == GPIOD_LINE_EVENT_RISING_EDGE,
		     (uint64_t)ev[i].ts.tv_sec * 1000000u + (uint64_t)ev[i].ts.tv_nsec / 1000u);
	return 0;
}
#endif

/* ---- common --------------------------------------------------------------------- */

static uint64_t now_us(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_MONOTONIC, &ts) < 0)
		return 0;
	return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

static void emit_button(struct gpio *g, struct gpio_line *l, bool pressed, uint64_t t_us)
{
	struct event ev = { .type = EVENT_BUTTON };

	ev.time_us = t_us;
	ev.button = (int)l->button;
	ev.pressed = pressed;
	g->emit(g->data, &ev);
}

/* Arms the timer for when l's window closes (an earlier deadline already set wins). */
static void arm(struct gpio *g, const struct gpio_line *l)
{
	struct itimerspec old, it = { 0 };
	uint64_t now = now_us(), due = l->db.last_us + l->db.window_us;
	uint64_t in = due > now ? due - now + 1000u : 1000u; /* a millisecond past the edge */

	if (timerfd_gettime(g->timerfd, &old) == 0 &&
	    (old.it_value.tv_sec || old.it_value.tv_nsec) &&
	    (uint64_t)old.it_value.tv_sec * 1000000u + (uint64_t)old.it_value.tv_nsec / 1000u <= in)
		return;
	it.it_value.tv_sec = (time_t)(in / 1000000u);
	it.it_value.tv_nsec = (long)(in % 1000000u) * 1000L;
	if (timerfd_settime(g->timerfd, 0, &it, NULL) < 0)
		fprintf(stderr, "edaha: gpio: timerfd_settime: %s\n", strerror(errno));
}

static void edge(struct gpio *g, struct gpio_line *l, bool pressed, uint64_t t_us)
{
	if (gpio_debounce_edge(&l->db, pressed, t_us)) {
		emit_button(g, l, pressed, t_us);
		return;
	}
	/* dropped in the window: the line may settle on the other state with no edge to come */
	if (pressed != l->db.pressed) {
		l->recheck = true;
		arm(g, l);
	}
}

/* The window closed: each line that dropped a change is read, and follows its level. */
static void settle(struct gpio *g)
{
	uint64_t expirations, now = now_us();

	if (read(g->timerfd, &expirations, sizeof(expirations)) < 0 && errno != EAGAIN)
		fprintf(stderr, "edaha: gpio: timerfd: %s\n", strerror(errno));
	for (int i = 0; i < g->nbuttons; i++) {
		struct gpio_line *l = &g->buttons[i];
		int v;

		if (!l->recheck)
			continue;
		if (l->db.have_time && now < l->db.last_us + l->db.window_us) {
			arm(g, l); /* a change was accepted since: its window is still open */
			continue;
		}
		l->recheck = false;
		v = line_value(l);
		if (v >= 0 && gpio_debounce_edge(&l->db, v == 1, now))
			emit_button(g, l, v == 1, now);
	}
}

int gpio_dispatch(void *data)
{
	struct gpio *g = data;
	struct epoll_event ready[BUTTON_COUNT + 1];
	int n = epoll_wait(g->epfd, ready, BUTTON_COUNT + 1, 0);

	if (n < 0)
		return errno == EINTR ? 0 : -errno;
	for (int i = 0; i < n; i++) {
		struct gpio_line *l = ready[i].data.ptr;
		int r;

		if (!l) {
			settle(g);
			continue;
		}
		r = read_edges(g, l, edge);

		if (r < 0 && r != -EAGAIN && r != -EINTR)
			return r;
	}
	return 0;
}

struct gpio *gpio_create(const struct config *cfg, input_emit_fn emit, void *data,
			 struct error *err)
{
	struct gpio *g = calloc(1, sizeof(*g));

	if (!g) {
		error_set(err, -ENOMEM, "gpio: out of memory");
		return NULL;
	}
	g->emit = emit;
	g->data = data;
	g->cfg = *cfg;
	g->timerfd = -1;
	g->epfd = epoll_create1(EPOLL_CLOEXEC);
	if (g->epfd < 0) {
		error_set(err, -errno, "gpio: epoll_create1: %s", strerror(errno));
		free(g);
		return NULL;
	}
	g->timerfd = timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC | TFD_NONBLOCK);
	struct epoll_event te = { .events = EPOLLIN, .data.ptr = NULL };

	if (g->timerfd < 0 || epoll_ctl(g->epfd, EPOLL_CTL_ADD, g->timerfd, &te) < 0) {
		error_set(err, -errno, "gpio: timerfd: %s", strerror(errno));
		gpio_destroy(g);
		return NULL;
	}
#if EDAHA_GPIOD_V2
	g->events = gpiod_edge_event_buffer_new(GPIO_EVENTS_AT_ONCE);
	if (!g->events) {
		error_set(err, -ENOMEM, "gpio: out of memory");
		gpio_destroy(g);
		return NULL;
	}
#endif
	for (int b = 0; b < BUTTON_COUNT; b++) {
		const struct config_gpio_line *c = &g->cfg.gpio.buttons[b];
		struct gpio_line *l = &g->buttons[g->nbuttons];
		struct epoll_event ee = { .events = EPOLLIN };
		const char *why;
		int v;

		if (!c->set)
			continue;
		memset(l, 0, sizeof(*l));
		l->button = (enum button)b;
		l->conf = c;
		if (request(l, false, &why) < 0) {
			warn_line(c, "button", l->button, why);
			continue;
		}
		v = line_value(l);
		gpio_debounce_init(&l->db, v == 1, (uint64_t)g->cfg.gpio.debounce_ms * 1000u);
		ee.data.ptr = l;
		if (epoll_ctl(g->epfd, EPOLL_CTL_ADD, l->fd, &ee) < 0) {
			warn_line(c, "button", l->button, strerror(errno));
			release(l);
			continue;
		}
		g->nbuttons++;
	}
	for (int b = 0; b < BUTTON_COUNT; b++) {
		const struct config_gpio_line *c = &g->cfg.gpio.leds[b];
		struct gpio_line *l = &g->leds[g->nleds];
		const char *why;

		if (!c->set)
			continue;
		memset(l, 0, sizeof(*l));
		l->button = (enum button)b;
		l->conf = c;
		if (request(l, true, &why) < 0) {
			warn_line(c, "LED", l->button, why);
			continue;
		}
		g->nleds++;
	}
	return g;
}

void gpio_destroy(struct gpio *g)
{
	if (!g)
		return;
	for (int i = 0; i < g->nbuttons; i++)
		release(&g->buttons[i]);
	for (int i = 0; i < g->nleds; i++) {
		if (set_value(&g->leds[i], false) < 0)
			warn_line(g->leds[i].conf, "LED", g->leds[i].button, strerror(errno));
		release(&g->leds[i]);
	}
#if EDAHA_GPIOD_V2
	if (g->events)
		gpiod_edge_event_buffer_free(g->events);
#endif
	if (g->timerfd >= 0 && close(g->timerfd) < 0)
		fprintf(stderr, "edaha: gpio: close: %s\n", strerror(errno));
	if (g->epfd >= 0 && close(g->epfd) < 0)
		fprintf(stderr, "edaha: gpio: close: %s\n", strerror(errno));
	free(g);
}

struct kiosk_source gpio_source(struct gpio *g)
{
	return (struct kiosk_source){ .fd = g->epfd, .dispatch = gpio_dispatch, .data = g };
}

void gpio_set_mode(struct gpio *g, enum button mode)
{
	for (int i = 0; i < g->nleds; i++) {
		struct gpio_line *l = &g->leds[i];

		if (set_value(l, l->button == mode) < 0)
			warn_line(l->conf, "LED", l->button, strerror(errno));
	}
}

int gpio_button_count(const struct gpio *g)
{
	return g->nbuttons;
}

int gpio_led_count(const struct gpio *g)
{
	return g->nleds;
}
