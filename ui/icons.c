/* SPDX-License-Identifier: MIT */
#include "icons.h"

#include <math.h>
#include <stddef.h>

/*
 * Icons are drawn in their own units: x and y from -1 to 1 across the icon's square,
 * y down like the screen.
 */
struct icon {
	struct batch *b;
	struct pt centre;
	double unit; /* pixels per icon unit */
	struct rgba ink, bg;
};

/* Strokes of all icons share one weight, so they read as a set. */
#define LINE 0.17

#define NPTS(a) (sizeof(a) / sizeof((a)[0]))

static struct pt at(const struct icon *ic, double x, double y)
{
	return (struct pt){ ic->centre.x + x * ic->unit, ic->centre.y + y * ic->unit };
}

static struct rgba faded(struct rgba c, float alpha)
{
	c.a *= alpha;
	return c;
}

/* A polyline through icon-unit points. */
static void line(const struct icon *ic, const struct pt *p, size_t n, double width, struct rgba c)
{
	struct pt px[64];

	if (n > NPTS(px))
		n = NPTS(px);
	for (size_t i = 0; i < n; i++)
		px[i] = at(ic, p[i].x, p[i].y);
	batch_polyline(ic->b, px, n, width * ic->unit, c);
}

static void segment(const struct icon *ic, double x0, double y0, double x1, double y1,
		    double width, struct rgba c)
{
	const struct pt p[2] = { { x0, y0 }, { x1, y1 } };

	line(ic, p, 2, width, c);
}

/* A convex polygon through icon-unit points. */
static void fill(const struct icon *ic, const struct pt *p, size_t n, struct rgba c)
{
	struct pt px[64];

	if (n > NPTS(px))
		n = NPTS(px);
	for (size_t i = 0; i < n; i++)
		px[i] = at(ic, p[i].x, p[i].y);
	batch_convex(ic->b, px, n, c);
}

static void disc(const struct icon *ic, double x, double y, double r, struct rgba c)
{
	batch_disc(ic->b, at(ic, x, y), r * ic->unit, c);
}

/* A solid arrow head with its tip at (x, y), pointing along (dx, dy). */
static void arrow_head(const struct icon *ic, double x, double y, double dx, double dy,
		       double length, double half_width, struct rgba c)
{
	double d = hypot(dx, dy);
	double ux = dx / d, uy = dy / d;
	double bx = x - ux * length, by = y - uy * length;

	batch_triangle(ic->b, at(ic, x, y), at(ic, bx - uy * half_width, by + ux * half_width),
		       at(ic, bx + uy * half_width, by - ux * half_width), c);
}

/* A cube in outline, its front and top faces tinted: "see it in 3D". */
static void icon_3d(const struct icon *ic)
{
	const double f = 0.72, o = 0.42; /* front square's side, depth offset */
	const double x0 = -0.78, y0 = -0.36;
	const struct pt front[4] = {
		{ x0, y0 }, { x0 + f * 1.5, y0 }, { x0 + f * 1.5, y0 + f * 1.5 }, { x0, y0 + f * 1.5 },
	};
	const struct pt top[4] = {
		front[0], { x0 + o, y0 - o }, { front[1].x + o, y0 - o }, front[1],
	};
	const struct pt side[4] = {
		front[1], top[2], { front[2].x + o, front[2].y - o }, front[2],
	};
	const struct pt outline[7] = { front[0], top[1], top[2], side[2], front[2], front[3], front[0] };

	fill(ic, front, 4, faded(ic->ink, 0.18f));
	fill(ic, top, 4, faded(ic->ink, 0.40f));
	fill(ic, side, 4, faded(ic->ink, 0.62f));
	line(ic, outline, NPTS(outline), LINE, ic->ink);
	segment(ic, front[0].x, front[0].y, front[1].x, front[1].y, LINE, ic->ink);
	segment(ic, front[1].x, front[1].y, front[2].x, front[2].y, LINE, ic->ink);
	segment(ic, front[1].x, front[1].y, top[2].x, top[2].y, LINE, ic->ink);
}

/* A small branch with a plus badge: "make another one like this". */
static void icon_clone(const struct icon *ic)
{
	const struct pt stem[4] = { { -0.55, 0.92 }, { -0.5, 0.3 }, { -0.36, -0.3 }, { -0.12, -0.88 } };
	const struct pt twig[3] = { { -0.47, 0.1 }, { -0.75, -0.3 }, { -0.86, -0.62 } };
	const struct pt twig2[2] = { { -0.39, -0.2 }, { 0.02, -0.42 } };
	const double cx = 0.46, cy = 0.42;

	line(ic, stem, NPTS(stem), LINE * 1.25, ic->ink);
	line(ic, twig, NPTS(twig), LINE, ic->ink);
	line(ic, twig2, NPTS(twig2), LINE, ic->ink);
	disc(ic, cx, cy, 0.5, ic->ink);
	segment(ic, cx - 0.27, cy, cx + 0.27, cy, LINE, ic->bg);
	segment(ic, cx, cy - 0.27, cx, cy + 0.27, LINE, ic->bg);
}

/* A leaf on a short stalk, its midrib cut out. */
static void icon_leaf(const struct icon *ic)
{
	/* tip to tip along the diagonal, widest in the middle */
	const double ax = -0.62, ay = 0.62, bx = 0.84, by = -0.84;
	const double len = hypot(bx - ax, by - ay);
	const double ux = (bx - ax) / len, uy = (by - ay) / len;
	struct pt outline[2 * 15];
	size_t n = 0;

	for (int side = -1; side <= 1; side += 2) {
		for (int i = 0; i < 15; i++) {
			/* one side tip to tip, the other back */
			double t = side < 0 ? (double)i / 14.0 : 1.0 - (double)i / 14.0;
			/* fuller towards the stalk, like a real leaf */
			double w = 0.5 * sin(VEC_PI * t) * (1.0 - 0.25 * t);

			outline[n++] = (struct pt){ ax + ux * len * t - uy * w * side,
						    ay + uy * len * t + ux * w * side };
		}
	}
	fill(ic, outline, n, ic->ink);
	segment(ic, -0.92, 0.92, ax, ay, LINE, ic->ink);
	segment(ic, ax + ux * 0.2, ay + uy * 0.2, ax + ux * len * 0.8, ay + uy * len * 0.8,
		LINE * 0.55, ic->bg);
}

/* Arrows fanning out from one point: "grow more branches like this". */
static void icon_propagate(const struct icon *ic)
{
	const double ox = -0.72, oy = 0.72, reach = 1.5;

	for (int i = 0; i < 3; i++) {
		double a = -0.5 * VEC_PI * (double)i / 2.0; /* right, up-right, up */
		double dx = cos(a), dy = sin(a);
		double tx = ox + dx * reach, ty = oy + dy * reach;

		segment(ic, ox, oy, tx - dx * 0.3, ty - dy * 0.3, LINE, ic->ink);
		arrow_head(ic, tx, ty, dx, dy, 0.46, 0.27, ic->ink);
	}
	disc(ic, ox, oy, 0.2, ic->ink);
}

/* A circular arrow, anticlockwise for undo, mirrored for redo. */
static void icon_turn(const struct icon *ic, double mirror)
{
	const double cx = 0.08, cy = 0.12, r = 0.62;
	/* from the lower right over the top to the left (y down: angles run clockwise) */
	const double a0 = 0.3 * VEC_PI, a1 = -0.92 * VEC_PI;
	struct pt p[40];
	size_t n = 0;
	double ex, ey, dx, dy;

	for (int i = 0; i < 40; i++) {
		double a = a0 + (a1 - a0) * (double)i / 39.0;

		p[n++] = (struct pt){ mirror * (cx + r * cos(a)), cy + r * sin(a) };
	}
	line(ic, p, n, LINE * 1.1, ic->ink);
	/* the head continues the arc: its direction is the tangent at the end */
	ex = mirror * (cx + r * cos(a1));
	ey = cy + r * sin(a1);
	dx = mirror * sin(a1);
	dy = -cos(a1);
	arrow_head(ic, ex + dx * 0.36, ey + dy * 0.36, dx, dy, 0.55, 0.36, ic->ink);
}

/* A blank sheet with a folded corner. */
static void icon_new(const struct icon *ic)
{
	const struct pt sheet[5] = { { -0.62, -0.86 }, { 0.22, -0.86 }, { 0.66, -0.42 },
				     { 0.66, 0.86 }, { -0.62, 0.86 } };
	const struct pt fold[3] = { { 0.22, -0.86 }, { 0.22, -0.42 }, { 0.66, -0.42 } };
	const struct pt outline[6] = { sheet[0], sheet[1], sheet[2], sheet[3], sheet[4], sheet[0] };

	fill(ic, sheet, NPTS(sheet), ic->bg);
	fill(ic, fold, NPTS(fold), faded(ic->ink, 0.45f));
	line(ic, outline, NPTS(outline), LINE, ic->ink);
	line(ic, fold, NPTS(fold), LINE * 0.7, ic->ink);
}

/* An arrow going down into a USB stick: "take your tree home". */
static void icon_export(const struct icon *ic)
{
	const struct pt body[4] = { { -0.86, 0.3 }, { 0.36, 0.3 }, { 0.36, 0.9 }, { -0.86, 0.9 } };
	const struct pt plug[4] = { { 0.36, 0.42 }, { 0.86, 0.42 }, { 0.86, 0.78 }, { 0.36, 0.78 } };

	fill(ic, body, NPTS(body), ic->ink);
	line(ic, plug, NPTS(plug), LINE * 0.75, ic->ink);
	fill(ic, (const struct pt[4]){ { 0.5, 0.53 }, { 0.6, 0.53 }, { 0.6, 0.63 }, { 0.5, 0.63 } },
	     4, ic->ink);
	fill(ic, (const struct pt[4]){ { 0.66, 0.53 }, { 0.76, 0.53 }, { 0.76, 0.63 }, { 0.66, 0.63 } },
	     4, ic->ink);
	segment(ic, -0.25, -0.92, -0.25, -0.3, LINE * 1.2, ic->ink);
	arrow_head(ic, -0.25, 0.16, 0.0, 1.0, 0.5, 0.42, ic->ink);
}

/* A tree on a turntable with an arrow going round: "turn it back to the front". */
static void icon_view(const struct icon *ic)
{
	const double cx = 0.0, cy = 0.5, rx = 0.86, ry = 0.32;
	const double a0 = -0.1 * VEC_PI, a1 = 1.02 * VEC_PI;
	struct pt p[32];
	double ex, ey, dx, dy;

	disc(ic, 0.0, -0.42, 0.42, ic->ink);
	segment(ic, 0.0, -0.2, 0.0, 0.5, LINE * 1.3, ic->ink);
	/* the front half of the turntable's rim, left to right under the tree */
	for (int i = 0; i < 32; i++) {
		double a = a1 + (a0 - a1) * (double)i / 31.0;

		p[i] = (struct pt){ cx + rx * cos(a), cy + ry * sin(a) };
	}
	line(ic, p, 32, LINE, ic->ink);
	ex = cx + rx * cos(a0);
	ey = cy + ry * sin(a0);
	dx = sin(a0) * rx;
	dy = -cos(a0) * ry;
	arrow_head(ic, ex + 0.3 * dx / hypot(dx, dy), ey + 0.3 * dy / hypot(dx, dy), dx, dy, 0.42,
		   0.3, ic->ink);
}

/*
 * Propagation patterns: a long and a short twig. Fixed count: three leaves on each,
 * smaller on the short one. Fixed size: leaves of one size at one spacing, so the short
 * twig has only those nearest its tip.
 */
static void icon_pattern(const struct icon *ic, bool fixed_size)
{
	const double y[2] = { -0.45, 0.55 }, len[2] = { 1.7, 0.95 };

	for (int k = 0; k < 2; k++) {
		double x0 = -0.85, x1 = x0 + len[k];
		int count = fixed_size ? (k == 0 ? 4 : 2) : 3;

		segment(ic, x0, y[k], x1, y[k], LINE * 0.8, ic->ink);
		for (int i = 0; i < count; i++) {
			/* fixed size: spaced 0.4 back from the tip; fixed count: spread evenly */
			double x = fixed_size ? x1 - 0.4 * i - 0.1 : x0 + len[k] * (i + 1) / (count + 0.3);
			double r = fixed_size ? 0.16 : 0.16 * (k == 0 ? 1.0 : 0.6);

			disc(ic, x, y[k] - r - 0.03, r, ic->ink);
		}
	}
}

void icon_draw(struct batch *b, enum button button, struct pt centre, double size,
	       struct rgba ink, struct rgba bg)
{
	struct icon ic = { b, centre, 0.5 * size, ink, bg };

	switch (button) {
	case BUTTON_3D:
		icon_3d(&ic);
		break;
	case BUTTON_CLONE:
		icon_clone(&ic);
		break;
	case BUTTON_LEAF:
		icon_leaf(&ic);
		break;
	case BUTTON_PROPAGATE:
		icon_propagate(&ic);
		break;
	case BUTTON_UNDO:
		icon_turn(&ic, 1.0);
		break;
	case BUTTON_REDO:
		icon_turn(&ic, -1.0);
		break;
	case BUTTON_NEW:
		icon_new(&ic);
		break;
	case BUTTON_EXPORT:
		icon_export(&ic);
		break;
	case BUTTON_VIEW:
		icon_view(&ic);
		break;
	case BUTTON_FIXED_COUNT:
		icon_pattern(&ic, false);
		break;
	case BUTTON_FIXED_SIZE:
		icon_pattern(&ic, true);
		break;
	case BUTTON_SEASON:
	case BUTTON_TPL_BLANK:
	case BUTTON_TPL_CHERRY:
	case BUTTON_TPL_ZELKOVA:
	case BUTTON_TPL_HEDGE:
	case BUTTON_TPL_BALL:
	case BUTTON_TPL_CONE:
	case BUTTON_TPL_PALM:
	case BUTTON_GEN_MORE:
	case BUTTON_GEN_FEWER:
	case BUTTON_GEN_WIDER:
	case BUTTON_GEN_NARROWER:
	case BUTTON_GEN_TALLER:
	case BUTTON_GEN_SHORTER:
	case BUTTON_GEN_LEAFIER:
	case BUTTON_GEN_BARER:
		break; /* TODO(i14-ui): their icons */
	case BUTTON_COUNT:
		break; /* not on the screen */
	}
}
