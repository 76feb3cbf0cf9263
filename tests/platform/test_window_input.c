/* SPDX-License-Identifier: MIT */
/* The window's input (window_input.c) without a window: SDL events made by hand become
 * the pen and the bar's buttons; pointer positions are mapped onto the scaled picture. */
#include <string.h>

#include "test.h"
#include "window_input.h"

#define MAX_EVENTS 64

struct sink {
	struct event ev[MAX_EVENTS];
	size_t n;
};

static void feed(void *data, const struct event *ev)
{
	struct sink *s = data;

	CHECK(s->n < MAX_EVENTS);
	s->ev[s->n++] = *ev;
}

/* A 1280x800 picture in a 960x700 window (HiDPI: twice the pixels): scaled by 1.5
 * (1920 px wide, letterboxed above and below). */
static const struct window_map scaled = { 1280, 800, 960, 700, 1920, 1400 };
static const struct window_map same = { 1280, 800, 1280, 800, 1280, 800 };

/* window_map_point goes through offscreen_geometry's quad, in floats */
static void test_map(void)
{
	double x, y;

	window_map_point(&same, 640, 736, &x, &y);
	CHECK_NEAR(x, 640, 1e-3);
	CHECK_NEAR(y, 736, 1e-3);
	/* 1920x1200 of 1920x1400 pixels: 100 px of black above */
	window_map_point(&scaled, 0, 50, &x, &y);
	CHECK_NEAR(x, 0, 1e-3);
	CHECK_NEAR(y, 0, 1e-3);
	window_map_point(&scaled, 480, 350, &x, &y);
	CHECK_NEAR(x, 640, 1e-3);
	CHECK_NEAR(y, 400, 1e-3);
	/* the black bands clamp to the picture's edge */
	window_map_point(&scaled, 959, 699, &x, &y);
	CHECK_NEAR(x, 1918 / 1.5, 1e-3);
	CHECK_NEAR(y, 799, 1e-3);
	window_map_point(&scaled, -5, 10, &x, &y);
	CHECK_NEAR(x, 0, 1e-3);
	CHECK_NEAR(y, 0, 1e-3);
}

static void test_keys(void)
{
	/* 1-9: the bar's order (src/core/layout.c) */
	static const enum button digits[] = { BUTTON_3D, BUTTON_CLONE, BUTTON_LEAF,
					      BUTTON_PROPAGATE, BUTTON_SEASON, BUTTON_VINE,
					      BUTTON_GROW, BUTTON_UNDO, BUTTON_REDO };
	static const struct {
		char key;
		const char *name;
	} letters[] = { { 'd', "3d" }, { 'c', "clone" }, { 'l', "leaf" }, { 'p', "propagate" },
			{ 's', "season" }, { 'v', "vine" }, { 'g', "grow" }, { 'u', "undo" },
			{ 'r', "redo" }, { 'n', "new" }, { 'e', "export" }, { 'f', "view" } };
	bool used[BUTTON_COUNT] = { false };
	enum button b;

	for (int i = 0; i < 9; i++) {
		CHECK(window_input_key(SDLK_1 + i, &b));
		CHECK_INT(b, digits[i]);
	}
	for (size_t i = 0; i < sizeof(letters) / sizeof(letters[0]); i++) {
		CHECK(window_input_key(letters[i].key, &b));
		CHECK(strcmp(button_name(b), letters[i].name) == 0);
		CHECK(!used[b]); /* one letter a button */
		used[b] = true;
	}
	/* Escape and 0 press nothing: a stray key does not quit nor clear a drawing */
	CHECK(!window_input_key(SDLK_ESCAPE, &b));
	CHECK(!window_input_key(SDLK_0, &b));
	CHECK(!window_input_key(SDLK_q, &b));
}

static SDL_Event mouse(Uint32 type, int x, int y, Uint8 button)
{
	SDL_Event e;

	memset(&e, 0, sizeof(e));
	e.type = type;
	if (type == SDL_MOUSEMOTION) {
		e.motion.x = x;
		e.motion.y = y;
		e.motion.which = 0;
	} else {
		e.button.x = x;
		e.button.y = y;
		e.button.button = button;
		e.button.which = 0;
	}
	return e;
}

static SDL_Event key(Uint32 type, SDL_Keycode sym, Uint8 repeat)
{
	SDL_Event e;

	memset(&e, 0, sizeof(e));
	e.type = type;
	e.key.keysym.sym = sym;
	e.key.repeat = repeat;
	return e;
}

static SDL_Event window(Uint8 what)
{
	SDL_Event e;

	memset(&e, 0, sizeof(e));
	e.type = SDL_WINDOWEVENT;
	e.window.event = what;
	return e;
}

static void test_stroke(void)
{
	struct sink s = { .n = 0 };
	struct window_input wi;
	SDL_Event e[] = {
		mouse(SDL_MOUSEMOTION, 480, 350, 0),
		mouse(SDL_MOUSEBUTTONDOWN, 480, 350, SDL_BUTTON_LEFT),
		mouse(SDL_MOUSEMOTION, 490, 350, 0),
		mouse(SDL_MOUSEBUTTONUP, 490, 360, SDL_BUTTON_LEFT),
		mouse(SDL_MOUSEBUTTONDOWN, 490, 360, SDL_BUTTON_RIGHT),
		mouse(SDL_MOUSEBUTTONUP, 490, 360, SDL_BUTTON_RIGHT),
		key(SDL_KEYDOWN, SDLK_1, 0),
		key(SDL_KEYDOWN, SDLK_1, 1), /* a repeat: no second press */
		key(SDL_KEYUP, SDLK_1, 0),
		key(SDL_KEYDOWN, SDLK_ESCAPE, 0),
		key(SDL_KEYDOWN, SDLK_u, 0),
		window(SDL_WINDOWEVENT_FOCUS_LOST), /* lets go of the held u */
		mouse(SDL_MOUSEBUTTONDOWN, 100, 100, SDL_BUTTON_LEFT),
		window(SDL_WINDOWEVENT_LEAVE), /* a drag out of the window goes on */
		mouse(SDL_MOUSEBUTTONUP, 100, 100, SDL_BUTTON_LEFT),
		window(SDL_WINDOWEVENT_LEAVE),
	};
	static const enum event_type want[] = {
		EVENT_PROXIMITY_IN, EVENT_TIP_DOWN, EVENT_MOTION, EVENT_MOTION, EVENT_TIP_UP,
		EVENT_PEN_BUTTON, EVENT_PEN_BUTTON, EVENT_BUTTON, EVENT_BUTTON, EVENT_BUTTON,
		EVENT_BUTTON, EVENT_MOTION, EVENT_TIP_DOWN, EVENT_TIP_UP, EVENT_PROXIMITY_OUT,
	};

	window_input_init(&wi, feed, &s);
	for (size_t i = 0; i < sizeof(e) / sizeof(e[0]); i++)
		window_input_handle(&wi, &e[i], &scaled);
	CHECK_INT(s.n, sizeof(want) / sizeof(want[0]));
	for (size_t i = 0; i < s.n; i++) {
		CHECK_INT(s.ev[i].type, want[i]);
		CHECK(i == 0 || s.ev[i].time_us >= s.ev[i - 1].time_us);
	}
	/* the pen at the picture's centre, down with a mouse's pressure 1 */
	CHECK_NEAR(s.ev[0].x, 640, 1e-3);
	CHECK_NEAR(s.ev[0].y, 400, 1e-3);
	CHECK_NEAR(s.ev[1].pressure, 1.0, 0);
	CHECK_NEAR(s.ev[2].x, 640 + 10 * 2 / 1.5, 1e-3);
	/* the button up moved the pen first */
	CHECK_NEAR(s.ev[3].y, 400 + 10 * 2 / 1.5, 1e-3);
	CHECK_NEAR(s.ev[4].pressure, 0.0, 0);
	CHECK(s.ev[5].pressed && !s.ev[6].pressed);
	CHECK_INT(s.ev[5].button, EVENT_PEN_BUTTON_STYLUS);
	CHECK_INT(s.ev[7].button, BUTTON_3D);
	CHECK(s.ev[7].pressed && !s.ev[8].pressed);
	CHECK_INT(s.ev[9].button, BUTTON_UNDO);
	CHECK(s.ev[9].pressed && !s.ev[10].pressed);
}

int main(void)
{
	test_map();
	test_keys();
	test_stroke();
	return 0;
}
