/* SPDX-License-Identifier: MIT */
#include "window_input.h"

#include <string.h>
#include <time.h>

#include "offscreen.h"

static uint64_t stamp(struct window_input *wi)
{
	struct timespec ts;
	uint64_t t;

	/* SDL's own timestamps are milliseconds since its start: too coarse, another clock */
	clock_gettime(CLOCK_MONOTONIC, &ts);
	t = (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
	if (t < wi->last_us)
		t = wi->last_us;
	wi->last_us = t;
	return t;
}

void window_map_point(const struct window_map *m, double wx, double wy, double *ax, double *ay)
{
	struct offscreen_geometry g;
	double px, py, left, top;

	offscreen_geometry(0, m->app_w, m->app_h, m->draw_w, m->draw_h, &g);
	/* points to drawable pixels (a HiDPI window has more pixels than points) */
	px = m->win_w > 0 ? wx * m->draw_w / m->win_w : wx;
	py = m->win_h > 0 ? wy * m->draw_h / m->win_h : wy;
	/* the quad's bottom-left (0) and top-left (2) corners, clip space, y up */
	left = (g.quad[0][0] + 1.0) / 2.0 * m->draw_w;
	top = (1.0 - g.quad[2][1]) / 2.0 * m->draw_h;
	*ax = g.w > 0 ? (px - left) * m->app_w / g.w : 0.0;
	*ay = g.h > 0 ? (py - top) * m->app_h / g.h : 0.0;
	*ax = *ax < 0.0 ? 0.0 : *ax > m->app_w - 1 ? m->app_w - 1 : *ax;
	*ay = *ay < 0.0 ? 0.0 : *ay > m->app_h - 1 ? m->app_h - 1 : *ay;
}

bool window_input_key(SDL_Keycode key, enum button *button)
{
	/* 1-9: the bar's places in its order (src/core/layout.c); letters: the buttons' names */
	static const struct {
		SDL_Keycode key;
		enum button button;
	} map[] = {
		{ SDLK_1, BUTTON_3D },     { SDLK_2, BUTTON_CLONE },   { SDLK_3, BUTTON_LEAF },
		{ SDLK_4, BUTTON_PROPAGATE }, { SDLK_5, BUTTON_SEASON }, { SDLK_6, BUTTON_VINE },
		{ SDLK_7, BUTTON_GROW },   { SDLK_8, BUTTON_UNDO },    { SDLK_9, BUTTON_REDO },
		{ SDLK_d, BUTTON_3D },     { SDLK_c, BUTTON_CLONE },   { SDLK_l, BUTTON_LEAF },
		{ SDLK_p, BUTTON_PROPAGATE }, { SDLK_s, BUTTON_SEASON }, { SDLK_v, BUTTON_VINE },
		{ SDLK_g, BUTTON_GROW },   { SDLK_u, BUTTON_UNDO },    { SDLK_r, BUTTON_REDO },
		{ SDLK_n, BUTTON_NEW },    { SDLK_e, BUTTON_EXPORT },  { SDLK_f, BUTTON_VIEW },
	};

	for (size_t i = 0; i < sizeof(map) / sizeof(map[0]); i++) {
		if (map[i].key == key) {
			*button = map[i].button;
			return true;
		}
	}
	return false;
}

static void pen(struct window_input *wi, enum event_type type, double pressure)
{
	struct event ev = {
		.type = type,
		.time_us = stamp(wi),
		.tool = EVENT_TOOL_PEN,
		.x = wi->x,
		.y = wi->y,
		.pressure = pressure,
	};

	wi->feed(wi->data, &ev);
}

static void pen_button(struct window_input *wi, bool pressed)
{
	struct event ev = {
		.type = EVENT_PEN_BUTTON,
		.time_us = stamp(wi),
		.tool = EVENT_TOOL_PEN,
		.x = wi->x,
		.y = wi->y,
		.pressure = wi->down ? 1.0 : 0.0,
		.button = EVENT_PEN_BUTTON_STYLUS,
		.pressed = pressed,
	};

	wi->stylus = pressed;
	wi->feed(wi->data, &ev);
}

static void button(struct window_input *wi, enum button b, bool pressed)
{
	struct event ev = {
		.type = EVENT_BUTTON,
		.time_us = stamp(wi),
		.button = (int)b,
		.pressed = pressed,
	};

	wi->keys[b] = pressed;
	wi->feed(wi->data, &ev);
}

/* The pen over (x, y): in proximity first if it was not. */
static void move_to(struct window_input *wi, double x, double y, double pressure)
{
	wi->x = x;
	wi->y = y;
	if (!wi->in) {
		wi->in = true;
		pen(wi, EVENT_PROXIMITY_IN, 0.0);
		return;
	}
	pen(wi, EVENT_MOTION, pressure);
}

/* The pen away: its tip and button up first, as a tablet would send them. */
static void leave(struct window_input *wi)
{
	if (!wi->in)
		return;
	if (wi->stylus)
		pen_button(wi, false);
	if (wi->down) {
		wi->down = false;
		pen(wi, EVENT_TIP_UP, 0.0);
	}
	wi->in = false;
	pen(wi, EVENT_PROXIMITY_OUT, 0.0);
}

static void on_mouse(struct window_input *wi, const SDL_Event *ev, const struct window_map *m)
{
	double x, y;

	switch (ev->type) {
	case SDL_MOUSEMOTION:
		window_map_point(m, ev->motion.x, ev->motion.y, &x, &y);
		move_to(wi, x, y, wi->down ? 1.0 : 0.0);
		break;
	case SDL_MOUSEBUTTONDOWN:
	case SDL_MOUSEBUTTONUP: {
		bool pressed = ev->type == SDL_MOUSEBUTTONDOWN;

		window_map_point(m, ev->button.x, ev->button.y, &x, &y);
		if (wi->x != x || wi->y != y || !wi->in)
			move_to(wi, x, y, wi->down ? 1.0 : 0.0);
		if (ev->button.button == SDL_BUTTON_LEFT && pressed != wi->down) {
			wi->down = pressed;
			pen(wi, pressed ? EVENT_TIP_DOWN : EVENT_TIP_UP, pressed ? 1.0 : 0.0);
		} else if (ev->button.button == SDL_BUTTON_RIGHT && pressed != wi->stylus) {
			pen_button(wi, pressed);
		}
		break;
	}
	default:
		break;
	}
}

/* A touch: the first finger down is the pen until it lifts; the others are ignored. */
static void on_finger(struct window_input *wi, const SDL_Event *ev, const struct window_map *m)
{
	const SDL_TouchFingerEvent *f = &ev->tfinger;
	double x, y, p = f->pressure > 0.0f ? (f->pressure > 1.0f ? 1.0 : f->pressure) : 1.0;

	if (ev->type == SDL_FINGERDOWN ? wi->finger || wi->down : !wi->finger || f->fingerId != wi->finger_id)
		return;
	/* normalised to the window */
	window_map_point(m, f->x * m->win_w, f->y * m->win_h, &x, &y);
	switch (ev->type) {
	case SDL_FINGERDOWN:
		wi->finger = true;
		wi->finger_id = f->fingerId;
		move_to(wi, x, y, 0.0);
		wi->down = true;
		pen(wi, EVENT_TIP_DOWN, p);
		break;
	case SDL_FINGERMOTION:
		move_to(wi, x, y, p);
		break;
	case SDL_FINGERUP:
		wi->finger = false;
		wi->x = x;
		wi->y = y;
		leave(wi); /* a finger lifted is out of range too */
		break;
	default:
		break;
	}
}

void window_input_init(struct window_input *wi, display_feed_fn feed, void *data)
{
	memset(wi, 0, sizeof(*wi));
	wi->feed = feed;
	wi->data = data;
}

void window_input_handle(struct window_input *wi, const SDL_Event *ev, const struct window_map *m)
{
	enum button b;

	switch (ev->type) {
	case SDL_MOUSEMOTION:
	case SDL_MOUSEBUTTONDOWN:
	case SDL_MOUSEBUTTONUP:
		/* a touch's mouse twin: the finger events carry its pressure */
		if ((ev->type == SDL_MOUSEMOTION ? ev->motion.which : ev->button.which) !=
			    SDL_TOUCH_MOUSEID && !wi->finger)
			on_mouse(wi, ev, m);
		break;
	case SDL_FINGERDOWN:
	case SDL_FINGERMOTION:
	case SDL_FINGERUP:
		on_finger(wi, ev, m);
		break;
	case SDL_KEYDOWN:
	case SDL_KEYUP:
		/* a held key's repeats are not new presses */
		if (ev->key.repeat || !window_input_key(ev->key.keysym.sym, &b))
			break;
		if ((ev->type == SDL_KEYDOWN) != wi->keys[b])
			button(wi, b, ev->type == SDL_KEYDOWN);
		break;
	case SDL_WINDOWEVENT:
		if (ev->window.event == SDL_WINDOWEVENT_LEAVE && !wi->down)
			leave(wi);
		/* the keys let go while the window is not looking */
		if (ev->window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
			for (int i = 0; i < BUTTON_COUNT; i++) {
				if (wi->keys[i])
					button(wi, (enum button)i, false);
			}
		}
		break;
	default:
		break;
	}
}
