/* SPDX-License-Identifier: MIT */
/*
 * What the kiosk says over the canvas: a status message ("Saved!") in a card at the top,
 * fading out at its end, and the attract screen that invites a visitor to draw when
 * nobody has for a while. Both are drawn from the app's clock; the attract screen does
 * not move, so an idle kiosk draws nothing.
 */
#include <math.h>

#include "app.h"
#include "app_mode.h"
#include "labels.h"
#include "layout.h"
#include "render_private.h"
#include "text.h"

static const struct rgba ink = { 0.16f, 0.13f, 0.12f, 1.0f };
static const struct rgba white = { 1.0f, 1.0f, 1.0f, 1.0f };
static const struct rgba card = { 1.0f, 0.992f, 0.965f, 1.0f };
static const struct rgba shadow = { 0.350f, 0.250f, 0.150f, 0.28f };
static const struct rgba paper = { 0.975f, 0.953f, 0.898f, 1.0f };
static const struct rgba soil = { 0.875f, 0.820f, 0.700f, 1.0f };
static const struct rgba bark = { 0.47f, 0.32f, 0.20f, 1.0f };
static const struct rgba leaf = { 0.33f, 0.62f, 0.24f, 1.0f };
static const struct rgba leaf_light = { 0.45f, 0.70f, 0.30f, 1.0f };
static const struct rgba pen_body = { 0.22f, 0.44f, 0.80f, 1.0f };
static const struct rgba pen_grip = { 0.15f, 0.30f, 0.56f, 1.0f };
static const struct rgba pen_cone = { 0.80f, 0.78f, 0.74f, 1.0f };

static struct rgba faded(struct rgba c, float a)
{
	c.a *= a;
	return c;
}

static bool good_news(enum app_status s)
{
	return s == APP_STATUS_SAVED || s == APP_STATUS_SAVED_USB || s == APP_STATUS_STICK_READY ||
	       s == APP_STATUS_IN_FOREST;
}

/* What to do next, in a mode: shown in the mode's colour, with an arrow down to the
 * ground the visitor is to tap. */
static bool hint(enum app_status s)
{
	return s == APP_STATUS_VINE_TAP || s == APP_STATUS_VINE_WHERE;
}

static struct rgba status_colour(enum app_status s)
{
	if (hint(s))
		return (struct rgba){ 0.0f, 0.56f, 0.50f, 1.0f }; /* the vine button's teal */
	if (good_news(s))
		return (struct rgba){ 0.24f, 0.58f, 0.22f, 1.0f };
	if (s == APP_STATUS_SAVING)
		return (struct rgba){ 0.20f, 0.45f, 0.78f, 1.0f };
	if (s == APP_STATUS_GROWING)
		return (struct rgba){ 0.40f, 0.24f, 0.12f, 1.0f }; /* the grow button's walnut */
	return (struct rgba){ 0.86f, 0.36f, 0.12f, 1.0f };
}

/* A tick for good news, three dots for something under way (lighting in turn while a
 * tree grows), an arrow down for a hint, "!" for bad, white in a disc of the message's
 * colour. */
static void status_icon(struct batch *b, enum app_status s, struct pt c, double r, float a,
			uint64_t now_us)
{
	batch_disc(b, c, r, faded(status_colour(s), a));
	if (s == APP_STATUS_GROWING) {
		/* under way: the dots light one after another, so the visitor sees it move */
		unsigned lit = (unsigned)(now_us / 250000u % 4u);

		for (int i = -1; i <= 1; i++)
			batch_disc(b, (struct pt){ c.x + 0.42 * r * i, c.y }, 0.14 * r,
				   faded(white, (unsigned)(i + 1) < lit ? a : 0.35f * a));
	} else if (s == APP_STATUS_SAVING) {
		for (int i = -1; i <= 1; i++)
			batch_disc(b, (struct pt){ c.x + 0.42 * r * i, c.y }, 0.14 * r, faded(white, a));
	} else if (good_news(s)) {
		const struct pt tick[3] = { { c.x - 0.45 * r, c.y + 0.02 * r },
					    { c.x - 0.12 * r, c.y + 0.36 * r },
					    { c.x + 0.48 * r, c.y - 0.32 * r } };

		batch_polyline(b, tick, 3, 0.24 * r, faded(white, a));
	} else if (hint(s)) {
		const struct pt shaft[2] = { { c.x, c.y - 0.55 * r }, { c.x, c.y + 0.40 * r } };
		const struct pt head[3] = { { c.x - 0.36 * r, c.y + 0.08 * r },
					    { c.x, c.y + 0.50 * r },
					    { c.x + 0.36 * r, c.y + 0.08 * r } };

		batch_polyline(b, shaft, 2, 0.24 * r, faded(white, a));
		batch_polyline(b, head, 3, 0.24 * r, faded(white, a));
	} else {
		const struct pt bar[2] = { { c.x, c.y - 0.52 * r }, { c.x, c.y + 0.12 * r } };

		batch_polyline(b, bar, 2, 0.26 * r, faded(white, a));
		batch_disc(b, (struct pt){ c.x, c.y + 0.48 * r }, 0.15 * r, faded(white, a));
	}
}

/* The message card: 12% of the screen's height, its words 5% (40 px, 25 mm on the kiosk). */
#define CARD_OF_HEIGHT 0.12
#define MESSAGE_OF_HEIGHT 0.05
#define CARD_TOP_OF_HEIGHT 0.05

/* The canvas right of the side strip: a message there covers none of its buttons. */
static struct layout_rect free_canvas(const struct app *app)
{
	struct layout_rect canvas = layout_canvas(&app->screen);
	struct app_side_item items[APP_SIDE_MAX];
	size_t n = app_side_items(app, items);
	double right = 0.0;

	for (size_t i = 0; i < n; i++) {
		struct layout_rect t = layout_side_target(&app->screen, i, app_side_kind(&items[0]));

		right = fmax(right, t.x + t.w);
	}
	canvas.w -= right;
	canvas.x += right;
	return canvas;
}

/* A message's card centred over the canvas with its top at y: its icon, and msg (NULL:
 * the icon alone), faded to a. */
static void status_card(struct batch *b, const struct ui_text *t, const struct app *app,
			enum app_status s, const char *msg, double y, float a, uint64_t now_us)
{
	const struct screen *v = &app->screen;
	struct layout_rect canvas = free_canvas(app);
	double h = round(CARD_OF_HEIGHT * v->height), r = 0.36 * h, pad = 0.12 * h;
	double w = 2.0 * (pad + r), x;
	struct text_extent e = { 0 };
	int px = (int)fmax(1.0, round(MESSAGE_OF_HEIGHT * v->height));

	if (msg) {
		px = text_fit(t->font, msg, px, (int)fmax(1.0, 0.5 * px),
			      0.9 * canvas.w - w - 0.6 * h);
		text_measure(t->font, msg, px, &e);
		w += 0.2 * h + e.width + 0.4 * h;
	}
	x = canvas.x + round(0.5 * (canvas.w - w));
	batch_rounded_rect(b, x, y + 0.06 * h, w, h, 0.5 * h, faded(shadow, a));
	batch_rounded_rect(b, x, y, w, h, 0.5 * h, faded(card, a));
	batch_rounded_frame(b, x, y, w, h, 0.5 * h, fmax(1.5, 0.04 * h),
			    faded(status_colour(s), a));
	status_icon(b, s, (struct pt){ x + pad + r, y + 0.5 * h }, r, a, now_us);
	if (msg)
		text_draw(b, t->font, msg, px, x + 2.0 * (pad + r) + 0.2 * h,
			  y + 0.5 * h + 0.5 * (e.ascent - e.descent), faded(ink, a));
}

void render_ui_status(struct batch *b, const struct ui_text *t, const struct app *app,
		      uint64_t now_us)
{
	const struct screen *v = &app->screen;
	uint64_t until;
	enum app_status s = app_status_at(app, now_us, &until);
	double h = round(CARD_OF_HEIGHT * v->height), y = round(CARD_TOP_OF_HEIGHT * v->height);
	char words[160];
	const char *msg = NULL;
	float a;

	if (s == APP_STATUS_NONE)
		return;
	/* the last half second fades it out */
	a = until - now_us >= APP_STATUS_FADE_US
		    ? 1.0f
		    : (float)(until - now_us) / (float)APP_STATUS_FADE_US;
	if (t->font)
		msg = labels_format(s, t->lang, app->status_number, words, sizeof(words)) == 0
			      ? words
			      : NULL;
	status_card(b, t, app, s, msg, y, a, now_us);
	/* saved: where to find the tree later, in today's forest */
	if ((s == APP_STATUS_SAVED || s == APP_STATUS_SAVED_USB) && app->forest_number) {
		msg = t->font && labels_format(APP_STATUS_IN_FOREST, t->lang, app->forest_number,
					       words, sizeof(words)) == 0
			      ? words
			      : NULL;
		status_card(b, t, app, APP_STATUS_IN_FOREST, msg, y + round(1.25 * h), a, now_us);
	}
}

/* A leaf: a lens from base along angle a (radians, y down), length len. */
static void lens(struct batch *b, struct pt base, double a, double len, struct rgba c)
{
	struct pt p[18];
	double ux = cos(a), uy = sin(a);

	for (int i = 0; i < 18; i++) {
		/* along the axis 0..1 and back, bulging 0.3 of the length at the middle */
		double s = i < 9 ? i / 8.0 : (17 - i) / 8.0, side = i < 9 ? 1.0 : -1.0;
		double along = s * len, off = side * 0.3 * len * sin(VEC_PI * s);

		p[i] = (struct pt){ base.x + along * ux - off * uy, base.y + along * uy + off * ux };
	}
	batch_convex(b, p, 18, c);
}

/* A limb of the little tree: a taper with round ends. */
static void limb(struct batch *b, struct pt p0, double r0, struct pt p1, double r1)
{
	batch_disc(b, p0, r0, bark);
	batch_disc(b, p1, r1, bark);
	batch_taper(b, p0, r0, p1, r1, bark);
}

/* The pen leans up to the right: a point `along` its axis from the tip and `across` it,
 * in units of u. */
static struct pt on_pen(struct pt tip, double along, double across, double u)
{
	const double dx = 0.55, dy = -0.835; /* the axis, tip to end */

	return (struct pt){ tip.x + u * (along * dx - across * dy),
			    tip.y + u * (along * dy + across * dx) };
}

/* Nib, cone, grip, body with a highlight, end cap. */
static void pen(struct batch *b, struct pt tip, double u)
{
	const double hw = 1.8; /* half the body's width */

	batch_triangle(b, tip, on_pen(tip, 5.0, hw, u), on_pen(tip, 5.0, -hw, u), pen_cone);
	batch_triangle(b, tip, on_pen(tip, 1.8, 0.65, u), on_pen(tip, 1.8, -0.65, u), ink);
	batch_disc(b, on_pen(tip, 24.0, 0.0, u), hw * u, pen_grip);
	batch_quad(b, on_pen(tip, 9.5, hw, u), on_pen(tip, 24.0, hw, u), on_pen(tip, 24.0, -hw, u),
		   on_pen(tip, 9.5, -hw, u), pen_body);
	batch_quad(b, on_pen(tip, 5.0, hw, u), on_pen(tip, 9.5, hw, u), on_pen(tip, 9.5, -hw, u),
		   on_pen(tip, 5.0, -hw, u), pen_grip);
	batch_quad(b, on_pen(tip, 10.4, -0.9, u), on_pen(tip, 22.5, -0.9, u),
		   on_pen(tip, 22.5, -1.3, u), on_pen(tip, 10.4, -1.3, u), faded(white, 0.45f));
}

/* A tree being drawn: trunk and branches, leaves, and the pen putting the last branch in
 * (a line of ink from its tip). u: pixels a unit; (cx, base): the foot of the trunk. */
static void illustration(struct batch *b, double cx, double base, double u)
{
	struct pt foot = { cx, base }, top = { cx - 0.6 * u, base - 17.0 * u };
	struct pt left = { cx - 9.5 * u, base - 17.0 * u }, right = { cx + 8.5 * u, base - 20.0 * u };
	struct pt crown = { cx - 2.0 * u, base - 25.0 * u };
	struct pt from = { cx + 4.0 * u, base - 15.8 * u }, tip = { cx + 10.5 * u, base - 27.0 * u };
	struct pt drawn[8], soilp[40];

	for (int i = 0; i < 40; i++)
		soilp[i] = (struct pt){ cx + 17.0 * u * cos(i * VEC_PI / 20),
					base + 2.2 * u * sin(i * VEC_PI / 20) };
	batch_convex(b, soilp, 40, soil);

	limb(b, foot, 1.9 * u, top, 0.8 * u);
	limb(b, (struct pt){ cx - 0.3 * u, base - 8.5 * u }, 0.8 * u, left, 0.35 * u);
	limb(b, (struct pt){ cx - 0.4 * u, base - 11.5 * u }, 0.75 * u, right, 0.35 * u);
	limb(b, (struct pt){ cx - 0.55 * u, base - 15.5 * u }, 0.6 * u, crown, 0.3 * u);

	lens(b, left, -2.7, 5.0 * u, leaf);
	lens(b, left, -1.9, 4.6 * u, leaf_light);
	lens(b, (struct pt){ cx - 5.5 * u, base - 13.2 * u }, 2.6, 4.0 * u, leaf_light);
	lens(b, right, -0.9, 5.0 * u, leaf);
	lens(b, right, -0.1, 4.4 * u, leaf_light);
	lens(b, crown, -2.1, 5.0 * u, leaf_light);
	lens(b, crown, -1.2, 4.8 * u, leaf);
	lens(b, (struct pt){ cx + 4.5 * u, base - 15.6 * u }, 0.5, 3.8 * u, leaf);

	/* the branch the pen is drawing: a curve of ink, thin at first */
	for (int i = 0; i < 8; i++) {
		double s = i / 7.0;

		drawn[i] = (struct pt){ from.x + (tip.x - from.x) * s - 2.0 * u * sin(VEC_PI * s),
					from.y + (tip.y - from.y) * s - 0.8 * u * sin(VEC_PI * s) };
	}
	batch_polyline(b, drawn, 8, 0.55 * u, ink);

	pen(b, tip, u);
}

/* The invitation's words: 6% of the screen's height (48 px, 3 cm on the kiosk). */
#define INVITE_OF_HEIGHT 0.06

/* A tree in the wind stays in sight: the invitation is a band along the canvas's foot
 * (the trunk's foot does not move; the crown does), the little tree on its left, and the
 * drawing is faded only a little. */
static void attract_band(struct batch *b, const struct ui_text *t, const struct app *app)
{
	const struct screen *v = &app->screen;
	struct layout_rect canvas = layout_canvas(v);
	/* the little tree with its pen stands 51 units tall and 42 wide: us, pixels a unit */
	double u = 0.01 * v->height, ch = 16.0 * u, us = ch / 56.0, radius = 3.0 * u;
	double pic = 44.0 * us, y = round(canvas.y + canvas.h - ch - 3.0 * u), cw, x;
	const char *msg = t->font ? labels_attract(t->lang) : NULL;
	struct text_extent e = { 0 };
	int px = (int)fmax(1.0, round(INVITE_OF_HEIGHT * v->height));

	if (msg) {
		px = text_fit(t->font, msg, px, (int)fmax(1.0, 0.4 * px),
			      0.9 * canvas.w - pic - 6.0 * u);
		text_measure(t->font, msg, px, &e);
	}
	cw = fmin(0.9 * canvas.w, pic + e.width + 6.0 * u);
	x = round(canvas.x + 0.5 * (canvas.w - cw));
	batch_rect(b, canvas.x, canvas.y, canvas.w, canvas.h, faded(paper, 0.25f));
	batch_rounded_rect(b, x, y + 0.8 * u, cw, ch, radius, shadow);
	batch_rounded_rect(b, x, y, cw, ch, radius, card);
	illustration(b, x + 2.0 * u + 18.0 * us, y + ch - 3.0 * us, us);
	if (msg)
		text_draw(b, t->font, msg, px, x + pic + 2.0 * u,
			  y + 0.5 * ch + 0.5 * (e.ascent - e.descent), ink);
}

void render_ui_attract(struct batch *b, const struct ui_text *t, const struct app *app,
		       bool forest)
{
	const struct screen *v = &app->screen;
	struct layout_rect canvas = layout_canvas(v);
	double u = 0.01 * v->height, cx = canvas.x + 0.5 * canvas.w, base = 0.60 * v->height;
	double cw = fmin(0.9 * canvas.w, 62.0 * u), ch = 66.0 * u;
	double x = round(cx - 0.5 * cw), y = round(base - 48.0 * u), radius = 4.0 * u;
	const char *msg = t->font ? labels_attract(t->lang) : NULL;
	struct text_extent e = { 0 };
	int px = (int)fmax(1.0, round(INVITE_OF_HEIGHT * v->height));

	if (forest || (app->live.strength > 0.0 && app->tree.nbranches > 0)) {
		attract_band(b, t, app);
		return;
	}
	if (msg) {
		px = text_fit(t->font, msg, px, (int)fmax(1.0, 0.4 * px), 0.9 * canvas.w - 6.0 * u);
		text_measure(t->font, msg, px, &e);
		cw = fmin(0.9 * canvas.w, fmax(cw, e.width + 8.0 * u));
		x = round(cx - 0.5 * cw);
	}
	/* the drawing stays, faint, round a card that reads over any drawing */
	batch_rect(b, canvas.x, canvas.y, canvas.w, canvas.h, faded(paper, 0.8f));
	batch_rounded_rect(b, x, y + 0.8 * u, cw, ch, radius, shadow);
	batch_rounded_rect(b, x, y, cw, ch, radius, card);
	illustration(b, cx, base, u);
	if (msg)
		text_draw(b, t->font, msg, px, cx - 0.5 * e.width, base + 11.0 * u, ink);
}
