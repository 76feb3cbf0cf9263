/* SPDX-License-Identifier: MIT */
/* The flat layers: ground, the stroke under the pen, the labelled buttons, the hover cursor. */
#include <math.h>

#include "app.h"
#include "app_mode.h"
#include "icons.h"
#include "labels.h"
#include "layout.h"
#include "render_private.h"
#include "sketch_seen.h"
#include "text.h"

static const struct rgba ink = { 0.16f, 0.13f, 0.12f, 1.0f };
static const struct rgba white = { 1.0f, 1.0f, 1.0f, 1.0f };
static const struct rgba eraser_fill = { 0.86f, 0.85f, 0.83f, 1.0f };
static const struct rgba eraser_edge = { 0.58f, 0.56f, 0.53f, 1.0f };

static const struct rgba soil_top = { 0.875f, 0.820f, 0.700f, 1.0f };
static const struct rgba soil_bottom = { 0.925f, 0.890f, 0.800f, 1.0f };
static const struct rgba ground_line = { 0.600f, 0.500f, 0.380f, 1.0f };

static const struct rgba bar_fill = { 0.925f, 0.895f, 0.830f, 1.0f };
static const struct rgba bar_edge = { 0.790f, 0.730f, 0.630f, 1.0f };
static const struct rgba button_fill = { 1.0f, 0.992f, 0.965f, 1.0f };
static const struct rgba button_pressed_fill = { 0.870f, 0.840f, 0.770f, 1.0f };
static const struct rgba button_border = { 0.640f, 0.580f, 0.500f, 1.0f };
static const struct rgba shadow = { 0.350f, 0.250f, 0.150f, 0.28f };

/* The season button's colour is its season's: blossom pink, sun orange, maple red, snow blue. */
static struct rgba season_accent(enum season season)
{
	switch (season) {
	case SEASON_SPRING:
		return (struct rgba){ 0.88f, 0.38f, 0.58f, 1.0f };
	case SEASON_AUTUMN:
		return (struct rgba){ 0.80f, 0.22f, 0.10f, 1.0f };
	case SEASON_WINTER:
		return (struct rgba){ 0.30f, 0.55f, 0.85f, 1.0f };
	case SEASON_SUMMER:
	case SEASON_COUNT:
		break;
	}
	return (struct rgba){ 0.92f, 0.58f, 0.06f, 1.0f };
}

/* Each button has its own colour, so children can say "the green one"; a pair of
 * parameter buttons shares one, so they read as a pair. */
static struct rgba accent(enum button button)
{
	if (app_template_of(button)) /* the New strip's cards: the tree's greens */
		return (struct rgba){ 0.30f, 0.50f, 0.26f, 1.0f };
	switch (button) {
	case BUTTON_3D:
		return (struct rgba){ 0.22f, 0.44f, 0.80f, 1.0f };
	case BUTTON_CLONE:
		return (struct rgba){ 0.58f, 0.33f, 0.74f, 1.0f };
	case BUTTON_LEAF:
		return (struct rgba){ 0.24f, 0.58f, 0.22f, 1.0f };
	case BUTTON_PROPAGATE:
	case BUTTON_FIXED_COUNT: /* its patterns */
	case BUTTON_FIXED_SIZE:
		return (struct rgba){ 0.90f, 0.48f, 0.12f, 1.0f };
	case BUTTON_VINE: /* a green-teal, apart from the leaf's green and save's teal */
		return (struct rgba){ 0.0f, 0.56f, 0.50f, 1.0f };
	case BUTTON_GROW: /* wood: a deep walnut, darker than the branches' brown below */
		return (struct rgba){ 0.40f, 0.24f, 0.12f, 1.0f };
	case BUTTON_EXPORT:
		return (struct rgba){ 0.10f, 0.50f, 0.62f, 1.0f };
	case BUTTON_GEN_MORE: /* branches: bark brown */
	case BUTTON_GEN_FEWER:
		return (struct rgba){ 0.55f, 0.34f, 0.16f, 1.0f };
	case BUTTON_GEN_WIDER:
	case BUTTON_GEN_NARROWER:
		return (struct rgba){ 0.16f, 0.44f, 0.72f, 1.0f };
	case BUTTON_GEN_TALLER:
	case BUTTON_GEN_SHORTER:
		return (struct rgba){ 0.62f, 0.30f, 0.66f, 1.0f };
	case BUTTON_GEN_LEAFIER:
	case BUTTON_GEN_BARER:
	case BUTTON_LEAF_DRAWN: /* the leaf cards: the leaf mode's green */
	case BUTTON_LEAF_ENTIRE:
	case BUTTON_LEAF_HOP:
	case BUTTON_LEAF_MAPLE:
		return (struct rgba){ 0.24f, 0.58f, 0.22f, 1.0f };
	default:
		return (struct rgba){ 0.33f, 0.30f, 0.28f, 1.0f };
	}
}

static struct rgba scaled(struct rgba c, float k)
{
	return (struct rgba){ c.r * k, c.g * k, c.b * k, c.a };
}

static struct rgba with_alpha(struct rgba c, float a)
{
	c.a *= a;
	return c;
}

/* Pixel sizes chosen on an 800-pixel-tall kiosk screen follow the screen. */
static double ui_scale(const struct screen *v)
{
	return fmax(0.5, v->height / 800.0);
}

/* Under a 3D tree seen from above, the ground round its trunk shows as an ellipse: it
 * tells which branches come forward and which go back. Pitch is not animated, so the
 * settled camera is the one on the screen. */
static void ground_patch(struct batch *b, const struct app *app)
{
	const struct screen *v = &app->screen;
	struct vec3 pivot = sketch_seen_pivot(&app->tree);
	double reach = 0.0, x, y, rx, ry, k = sin(app->camera.pitch * (VEC_PI / 180.0));
	struct pt p[48];

	if (!app->tree.lifted || fabs(k) < 0.02)
		return;
	for (size_t i = 0; i < app->tree.nbranches; i++)
		for (size_t j = 0; j < app->tree.branches[i].npoints; j++) {
			struct vec3 q = app->tree.branches[i].points[j];

			reach = fmax(reach, hypot(q.x - pivot.x, q.z - pivot.z));
		}
	screen_from_world(v, pivot, &x, &y);
	rx = (reach + 0.5) / v->m_per_px;
	ry = rx * fabs(k);
	for (int i = 0; i < 48; i++)
		p[i] = (struct pt){ x + rx * cos(i * VEC_PI / 24), y + ry * sin(i * VEC_PI / 24) };
	batch_convex(b, p, 48, with_alpha(ground_line, 0.16f));
	for (int i = 0; i < 48; i++)
		p[i] = (struct pt){ x + 0.5 * rx * cos(i * VEC_PI / 24), y + 0.5 * ry * sin(i * VEC_PI / 24) };
	batch_convex(b, p, 48, with_alpha(ground_line, 0.12f));
}

void render_ui_ground(struct batch *b, const struct app *app)
{
	const struct screen *v = &app->screen;
	double gy = v->ground_y_px, w = v->width, h = v->height;
	double s = ui_scale(v);

	if (gy >= h)
		return;
	/* a faint shade above the line, the soil below: soft, not a hard edge */
	batch_rect_gradient(b, 0.0, gy - 10.0 * s, w, 10.0 * s, with_alpha(ground_line, 0.0f),
			    with_alpha(ground_line, 0.22f));
	batch_rect_gradient(b, 0.0, gy, w, h - gy, soil_top, soil_bottom);
	batch_rect(b, 0.0, gy - 1.5 * s, w, 3.0 * s, ground_line);
	ground_patch(b, app);
}

static double clamp01(double x)
{
	/* also maps NaN to 0 */
	return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0;
}

/* Half the width of the stroke a tool leaves at a pressure. */
static double stroke_radius(enum event_tool tool, double pressure)
{
	double p = clamp01(pressure);

	if (tool == EVENT_TOOL_ERASER)
		return 0.5 * (24.0 + 12.0 * p);
	return 0.5 * (2.0 + 10.0 * p);
}

/* Discs at the points joined by tapers: round caps and joins, width following pressure. */
static void ribbon(struct batch *b, const struct app_stroke *s, double grow, struct rgba c)
{
	struct pt prev = { 0.0, 0.0 };
	double prev_r = 0.0;

	for (size_t i = 0; i < s->npoints; i++) {
		const struct app_point *p = &s->points[i];
		struct pt pt = { p->x, p->y };
		double r = stroke_radius(s->tool, p->pressure) + grow;

		batch_disc(b, pt, r, c);
		if (i > 0)
			batch_taper(b, prev, prev_r, pt, r, c);
		prev = pt;
		prev_r = r;
	}
}

void render_ui_stroke(struct batch *b, const struct app *app)
{
	const struct app_stroke *s = &app->stroke;

	if (!s->active || s->npoints == 0)
		return;
	if (s->tool == EVENT_TOOL_ERASER) {
		/* a pale band with a rim: clearly not ink */
		ribbon(b, s, 1.5, eraser_edge);
		ribbon(b, s, 0.0, eraser_fill);
	} else {
		ribbon(b, s, 0.0, ink);
	}
}

/* A bar button is lit while its mode is on, as its GPIO LED is (the mode table's say,
 * app_modes.c; the side strip's say so themselves: `lit`). */
static bool button_active(const struct app *app, enum button button)
{
	return button == app_lit_button(app);
}

static bool button_enabled(const struct app *app, enum button button)
{
	if (button == BUTTON_UNDO)
		return doc_can_undo(&app->doc);
	if (button == BUTTON_REDO)
		return doc_can_redo(&app->doc);
	if (button == BUTTON_VIEW)
		return !camera_is_front(app->camera);
	/* an empty canvas has no season to show, no wood to grow */
	if (button == BUTTON_SEASON || button == BUTTON_GROW)
		return app->tree.nbranches > 0;
	if (button >= BUTTON_GEN_MORE && button <= BUTTON_GEN_BARER)
		return app_gen_possible(app, button);
	return true;
}

/*
 * A button's label: ~26% of its height (21 px, 13 mm, on an 800-pixel kiosk screen 50 cm
 * tall: a child reads it from a metre away), smaller only if it would not fit the width.
 */
#define LABEL_OF_HEIGHT 0.26
#define LABEL_MIN_OF_HEIGHT 0.18
#define LABEL_SIDE_OF_WIDTH 0.05 /* kept clear at either end */
#define LABEL_BASELINE_OF_HEIGHT 0.85

/* A named card's band is 0.34 of a button's height (layout.c): its word is the size of a
 * button's label, its baseline high enough for descenders. */
#define CARD_LABEL_OF_BAND (LABEL_OF_HEIGHT / 0.34)
#define CARD_BASELINE_OF_BAND 0.28

int render_ui_label_px(double button_h)
{
	return (int)fmax(1.0, round(LABEL_OF_HEIGHT * button_h));
}

int render_ui_card_label_px(double band)
{
	return (int)fmax(1.0, round(CARD_LABEL_OF_BAND * band));
}

double render_ui_label_room(double button_w)
{
	return (1.0 - 2.0 * LABEL_SIDE_OF_WIDTH) * button_w;
}

static void draw_label(struct batch *b, const struct ui_text *t, const char *label,
		       const struct layout_button *lb, double y, struct rgba c)
{
	int min_px = (int)fmax(1.0, round(LABEL_MIN_OF_HEIGHT * lb->h));
	int px = text_fit(t->font, label, render_ui_label_px(lb->h), min_px,
			  render_ui_label_room(lb->w));
	struct text_extent e;

	text_measure(t->font, label, px, &e);
	text_draw(b, t->font, label, px, lb->x + 0.5 * (lb->w - e.width),
		  y + LABEL_BASELINE_OF_HEIGHT * lb->h, c);
}

static void draw_icon(struct batch *b, const struct app *app, enum button button, struct pt at,
		      double size, struct rgba ink, struct rgba bg)
{
	if (button == BUTTON_SEASON)
		icon_draw_season(b, app->tree.season, at, size, ink, bg);
	else
		icon_draw(b, button, at, size, ink, bg);
}

static void draw_button(struct batch *b, const struct ui_text *t, const struct app *app,
			const struct layout_button *lb, bool active)
{
	bool pressed = lb->button < BUTTON_COUNT && app->buttons_down[lb->button];
	bool enabled = button_enabled(app, lb->button);
	float alpha = enabled ? 1.0f : 0.3f;
	struct rgba colour = lb->button == BUTTON_SEASON ? season_accent(app->tree.season)
							 : accent(lb->button);
	double w = lb->w, h = lb->h;
	double radius = 0.24 * h, border = fmax(1.5, 0.045 * h);
	/* a pressed button sinks onto its shadow */
	double lift = 0.06 * h, y = lb->y + (pressed ? 0.045 * h : 0.0);
	const char *label = t->font ? labels_button(lb->button, t->lang) : "";
	struct rgba fill, edge, icon_ink, label_ink;

	if (active) {
		double glow = 0.08 * h;

		batch_rounded_rect(b, lb->x - glow, lb->y - glow, w + 2.0 * glow, h + 2.0 * glow,
				   radius + glow, with_alpha(colour, 0.32f));
		fill = pressed ? scaled(colour, 0.8f) : colour;
		edge = scaled(colour, 0.62f);
		icon_ink = label_ink = white;
	} else {
		fill = pressed ? button_pressed_fill : button_fill;
		edge = with_alpha(button_border, alpha);
		icon_ink = with_alpha(colour, alpha);
		/* darker than the icon: thin strokes on white need the contrast */
		label_ink = with_alpha(scaled(colour, 0.72f), alpha);
	}
	if (!pressed)
		batch_rounded_rect(b, lb->x, lb->y + lift, w, h, radius, with_alpha(shadow, alpha));
	batch_rounded_rect(b, lb->x, y, w, h, radius, fill);
	batch_rounded_frame(b, lb->x, y, w, h, radius, active ? 1.6 * border : border, edge);
	if (!label[0]) {
		draw_icon(b, app, lb->button, (struct pt){ lb->x + 0.5 * w, y + 0.5 * h }, 0.62 * h,
			  icon_ink, fill);
		return;
	}
	/* the icon up, the word under it */
	draw_icon(b, app, lb->button, (struct pt){ lb->x + 0.5 * w, y + 0.36 * h }, 0.48 * h,
		  icon_ink, fill);
	draw_label(b, t, label, lb, y, label_ink);
}

/* A named card's word, in the band of height `band` under its picture: as large as a
 * button's label beside it. */
static void draw_card_label(struct batch *b, const struct ui_text *t, const char *label,
			    struct layout_rect r, double y, double band, struct rgba c)
{
	int px = render_ui_card_label_px(band);
	struct text_extent e;

	px = text_fit(t->font, label, px, (int)fmax(1.0, 0.7 * px), render_ui_label_room(r.w));
	text_measure(t->font, label, px, &e);
	text_draw(b, t->font, label, px, r.x + 0.5 * (r.w - e.width),
		  y + r.h - CARD_BASELINE_OF_BAND * band, c);
}

/*
 * A card of the side strip: a picture (drawn into it by render_preview.c), or the blank
 * canvas's empty sheet, framed in the colour of what it makes, its word under it when it
 * is named; lit when it is the choice in effect.
 */
static void draw_card(struct batch *b, const struct ui_text *t, const struct app *app,
		      const struct app_side_item *item, struct layout_rect r,
		      enum layout_side_kind kind)
{
	struct rgba frame = accent(item->button == BUTTON_COUNT ? BUTTON_LEAF : item->button);
	bool pressed = item->button != BUTTON_COUNT && app->buttons_down[item->button];
	double radius = 0.12 * r.w, border = fmax(1.5, 0.03 * r.w);
	double y = r.y + (pressed ? 0.03 * r.w : 0.0);
	struct layout_rect pic = layout_card_picture((struct layout_rect){ r.x, y, r.w, r.h }, kind);
	const char *label = t->font && kind == LAYOUT_SIDE_NAMED_CARDS
				    ? labels_button(item->button, t->lang)
				    : "";

	if (item->lit) {
		double glow = 0.06 * r.w;

		batch_rounded_rect(b, r.x - glow, y - glow, r.w + 2.0 * glow, r.h + 2.0 * glow,
				   radius + glow, with_alpha(frame, 0.32f));
	}
	if (!pressed)
		batch_rounded_rect(b, r.x, r.y + 0.04 * r.w, r.w, r.h, radius, shadow);
	batch_rounded_rect(b, r.x, y, r.w, r.h, radius, pressed ? button_pressed_fill : button_fill);
	batch_rounded_frame(b, r.x, y, r.w, r.h, radius, item->lit ? 1.6 * border : border, frame);
	if (!item->preview && item->button != BUTTON_COUNT)
		icon_draw(b, item->button, (struct pt){ pic.x + 0.5 * pic.w, pic.y + 0.52 * pic.h },
			  0.66 * pic.w, scaled(frame, 0.9f), button_fill);
	if (label[0])
		draw_card_label(b, t, label, r, y, r.h - pic.h, scaled(frame, 0.8f));
}

/* The side strip, from what the active mode offers (app_side_items): buttons in pairs, or
 * cards. A parameter button that would change nothing is drawn disabled. */
static void render_ui_side(struct batch *b, const struct ui_text *t, const struct app *app)
{
	struct app_side_item items[APP_SIDE_MAX];
	size_t n = app_side_items(app, items);
	enum layout_side_kind kind = n ? app_side_kind(&items[0]) : LAYOUT_SIDE_BUTTONS;

	for (size_t i = 0; i < n; i++) {
		struct layout_rect r = layout_side_slot(&app->screen, i, kind);

		if (kind == LAYOUT_SIDE_BUTTONS) {
			struct layout_button lb = { items[i].button, r.x, r.y, r.w, r.h,
						    layout_side_target(&app->screen, i, kind) };

			draw_button(b, t, app, &lb, items[i].lit);
		} else {
			draw_card(b, t, app, &items[i], r, kind);
		}
	}
}
void render_ui_selection(struct batch *b, const struct app *app, const struct camera_xf *xf)
{
	const struct branch *br;
	struct pt p[256];
	size_t n;
	double s = ui_scale(&app->screen);

	if (app->mode != APP_MODE_CLONE || app->selected < 0 ||
	    (size_t)app->selected >= app->tree.nbranches)
		return;
	br = &app->tree.branches[app->selected];
	n = br->npoints < 256 ? br->npoints : 256;
	for (size_t i = 0; i < n; i++) {
		double x, y;
		/* at most 256 points along it, ends included */
		size_t k = n > 1 ? i * (br->npoints - 1) / (n - 1) : 0;

		screen_from_world(&app->screen, camera_to_view(xf, br->points[k]), &x, &y);
		p[i] = (struct pt){ x, y };
	}
	/* a glow along the chosen branch in the clone button's colour */
	batch_polyline(b, p, n, 14.0 * s, with_alpha(accent(BUTTON_CLONE), 0.35f));
	batch_polyline(b, p, n, 5.0 * s, with_alpha(accent(BUTTON_CLONE), 0.9f));
}

void render_ui_buttons(struct batch *b, const struct ui_text *t, const struct app *app)
{
	const struct screen *v = &app->screen;
	struct layout_rect bar = layout_bar(v);
	struct layout_button buttons[LAYOUT_NBUTTONS];
	size_t n = layout_buttons(v, buttons, LAYOUT_NBUTTONS);
	double s = ui_scale(v);

	/* the bar casts a faint shadow on the canvas, and has a rim */
	batch_rect_hgradient(b, bar.x - 8.0 * s, 0.0, 8.0 * s, bar.h, with_alpha(shadow, 0.0f),
			     with_alpha(shadow, 0.25f));
	batch_rect(b, bar.x, bar.y, bar.w, bar.h, bar_fill);
	batch_rect(b, bar.x, bar.y, fmax(1.0, 2.0 * s), bar.h, bar_edge);
	for (size_t i = 0; i < n && i < LAYOUT_NBUTTONS; i++)
		draw_button(b, t, app, &buttons[i], button_active(app, buttons[i].button));
	if (app->tree.lifted) {
		struct layout_button view = layout_view_button(v);

		draw_button(b, t, app, &view, false);
	}
	render_ui_side(b, t, app);
}

/* Two arrows chasing each other round the pen: "drag here to turn the tree". */
static void orbit_cursor(struct batch *b, struct pt at, double s)
{
	const double r = 13.0 * s;

	for (int half = 0; half < 2; half++) {
		struct pt p[12];
		double a0 = VEC_PI * (half + 0.08), a1 = VEC_PI * (half + 0.78), ax, ay;

		for (int i = 0; i < 12; i++) {
			double a = a0 + (a1 - a0) * i / 11.0;

			p[i] = (struct pt){ at.x + r * cos(a), at.y + r * sin(a) };
		}
		batch_polyline(b, p, 12, 6.5 * s, with_alpha(white, 0.85f));
		batch_polyline(b, p, 12, 3.0 * s, ink);
		ax = -sin(a1);
		ay = cos(a1);
		batch_triangle(b, (struct pt){ p[11].x + ax * 7.0 * s, p[11].y + ay * 7.0 * s },
			       (struct pt){ p[11].x + cos(a1) * 5.0 * s, p[11].y + sin(a1) * 5.0 * s },
			       (struct pt){ p[11].x - cos(a1) * 5.0 * s, p[11].y - sin(a1) * 5.0 * s },
			       ink);
	}
	batch_disc(b, at, 2.0 * s, ink);
}

void render_ui_cursor(struct batch *b, const struct app *app)
{
	const struct app_pen *pen = &app->pen;
	struct pt at = { pen->x, pen->y };
	double s = ui_scale(&app->screen);

	if (!pen->in_proximity)
		return;
	/* a white halo keeps the ring visible over ink and bark */
	if (pen->tool == EVENT_TOOL_ERASER) {
		/* as large as the eraser's touch */
		double r = stroke_radius(EVENT_TOOL_ERASER, 0.0);

		batch_ring(b, at, r - 2.5 * s, r + 2.5 * s, with_alpha(white, 0.85f));
		batch_ring(b, at, r - 1.0 * s, r + 1.0 * s, eraser_edge);
	} else if (app->orbiting || (!app->stroke.active && app_would_orbit(app, pen->x, pen->y))) {
		orbit_cursor(b, at, s);
	} else {
		batch_ring(b, at, 4.0 * s, 10.5 * s, with_alpha(white, 0.85f));
		batch_ring(b, at, 5.5 * s, 8.5 * s, ink);
		batch_disc(b, at, 1.5 * s, ink);
	}
}
