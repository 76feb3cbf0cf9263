/* SPDX-License-Identifier: MIT */
#include "icons.h"

#include <math.h>
#include <stddef.h>

#include "app_mode.h"

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

/* A leaf from (ax, ay) to its tip (bx, by), half as wide as `width` at most, widest
 * towards the stalk, its midrib cut out. */
static void leaf_shape(const struct icon *ic, double ax, double ay, double bx, double by,
		       double width)
{
	const double len = hypot(bx - ax, by - ay);
	const double ux = (bx - ax) / len, uy = (by - ay) / len;
	struct pt outline[2 * 15];
	size_t n = 0;

	for (int side = -1; side <= 1; side += 2) {
		for (int i = 0; i < 15; i++) {
			/* one side tip to tip, the other back */
			double t = side < 0 ? (double)i / 14.0 : 1.0 - (double)i / 14.0;
			/* fuller towards the stalk, like a real leaf */
			double w = width * sin(VEC_PI * t) * (1.0 - 0.25 * t);

			outline[n++] = (struct pt){ ax + ux * len * t - uy * w * side,
						    ay + uy * len * t + ux * w * side };
		}
	}
	fill(ic, outline, n, ic->ink);
	segment(ic, ax + ux * 0.2, ay + uy * 0.2, ax + ux * len * 0.8, ay + uy * len * 0.8,
		LINE * 0.55, ic->bg);
}

/* A leaf on a short stalk. */
static void icon_leaf(const struct icon *ic)
{
	leaf_shape(ic, -0.62, 0.62, 0.84, -0.84, 0.5);
	segment(ic, -0.92, 0.92, -0.62, 0.62, LINE, ic->ink);
}

/* The ink part way to the background, opaque: a lighter shade that can lie under strokes
 * (a faded colour would show what is behind it, and darken where its discs overlap). */
static struct rgba shade(const struct icon *ic, float k)
{
	return (struct rgba){ ic->bg.r + (ic->ink.r - ic->bg.r) * k,
			      ic->bg.g + (ic->ink.g - ic->bg.g) * k,
			      ic->bg.b + (ic->ink.b - ic->bg.b) * k, ic->ink.a };
}

/*
 * The vine's stem round the pole: a helix seen from the side, from the foot up, at turn
 * t (0 at the foot, VINE_TURNS at the tip); in front of the pole while its cosine is
 * positive.
 */
#define VINE_POLE_X (-0.12)
#define VINE_TURNS 2.0
#define VINE_STEPS 48

static struct pt vine_at(double t, bool *front)
{
	double a = 2.0 * VEC_PI * t, k = t / VINE_TURNS;
	/* a little narrower as it climbs, as a young tip is */
	double r = 0.44 - 0.1 * k;

	if (front)
		*front = cos(a) > 0.0;
	return (struct pt){ VINE_POLE_X + r * sin(a), 0.8 - 1.28 * k };
}

/* The stem's stretches on one side of the pole, each a polyline of its own. */
static void vine_stem(const struct icon *ic, bool front, double width, struct rgba c)
{
	struct pt run[VINE_STEPS + 1];
	size_t n = 0;

	for (int i = 0; i < VINE_STEPS; i++) {
		double t0 = VINE_TURNS * i / VINE_STEPS, t1 = VINE_TURNS * (i + 1) / VINE_STEPS;
		bool f1;
		struct pt p0 = vine_at(t0, NULL), p1 = vine_at(t1, &f1);

		/* a step crossing a side belongs to the side it ends on */
		if (f1 == front) {
			if (n == 0)
				run[n++] = p0;
			run[n++] = p1;
		} else if (n > 0) {
			line(ic, run, n, width, c);
			n = 0;
		}
	}
	if (n > 0)
		line(ic, run, n, width, c);
}

/* A leaf growing from the stem at turn t, pointing along (dx, dy). */
static void vine_leaf(const struct icon *ic, double t, double dx, double dy, double width)
{
	struct pt p = vine_at(t, NULL);

	leaf_shape(ic, p.x, p.y, p.x + dx, p.y + dy, width);
}

/*
 * A vine twining up a pole, a leaf out to the side and one at its tip: the stem goes
 * behind the pole in a lighter shade and over it in front, so it reads as wound round.
 */
static void icon_vine(const struct icon *ic)
{
	const double half = 0.14, top = -0.95, foot = 0.97;
	const struct pt pole[4] = { { VINE_POLE_X - half, top }, { VINE_POLE_X + half, top },
				    { VINE_POLE_X + half, foot }, { VINE_POLE_X - half, foot } };
	const double stem = LINE * 1.2;

	vine_stem(ic, false, stem, shade(ic, 0.55f));
	fill(ic, pole, NPTS(pole), shade(ic, 0.3f));
	vine_stem(ic, true, stem, ic->ink);
	/* a leaf out from the left of the first turn, and at the tip, up past the pole */
	vine_leaf(ic, 0.75, -0.6, -0.24, 0.3);
	vine_leaf(ic, VINE_TURNS, 0.78, -0.42, 0.36);
}

/* A round badge with a plus or a minus cut out: "more of it", "less of it". */
static void badge(const struct icon *ic, double cx, double cy, bool plus)
{
	disc(ic, cx, cy, 0.46, ic->bg);
	disc(ic, cx, cy, 0.38, ic->ink);
	segment(ic, cx - 0.21, cy, cx + 0.21, cy, LINE, ic->bg);
	if (plus)
		segment(ic, cx, cy - 0.21, cx, cy + 0.21, LINE, ic->bg);
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

/* A fork of branches, more of them for "more", with its badge. */
static void icon_branches(const struct icon *ic, bool more)
{
	const struct pt trunk[3] = { { -0.3, 0.95 }, { -0.28, 0.3 }, { -0.2, -0.2 } };
	const struct pt left[3] = { { -0.25, 0.1 }, { -0.62, -0.35 }, { -0.78, -0.85 } };
	const struct pt right[3] = { { -0.2, -0.2 }, { 0.12, -0.55 }, { 0.34, -0.9 } };

	line(ic, trunk, NPTS(trunk), LINE * 1.3, ic->ink);
	line(ic, left, NPTS(left), LINE, ic->ink);
	line(ic, right, NPTS(right), LINE, ic->ink);
	if (more) {
		segment(ic, -0.62, -0.35, -0.95, -0.45, LINE * 0.8, ic->ink);
		segment(ic, -0.2, -0.2, -0.3, -0.8, LINE * 0.8, ic->ink);
		segment(ic, 0.12, -0.55, 0.5, -0.55, LINE * 0.8, ic->ink);
	}
	badge(ic, 0.46, 0.42, more);
}

/* A round crown centred at (x, cy) on a trunk down to the ground at `foot`. */
static void small_tree(const struct icon *ic, double x, double cy, double rx, double ry,
		       double foot)
{
	struct pt crown[32];

	segment(ic, x, foot, x, cy, LINE * 1.3, ic->ink);
	for (int i = 0; i < 32; i++) {
		double a = 2.0 * VEC_PI * i / 32.0;

		crown[i] = (struct pt){ x + rx * cos(a), cy + ry * sin(a) };
	}
	fill(ic, crown, NPTS(crown), ic->ink);
}

/* A tree with arrows either side: pointing out from a wide crown, in at a narrow one. */
static void icon_width(const struct icon *ic, bool wider)
{
	const double y = -0.2, rx = wider ? 0.5 : 0.24;

	small_tree(ic, 0.0, y, rx, 0.52, 0.95);
	for (int side = -1; side <= 1; side += 2) {
		if (wider) {
			segment(ic, side * (rx + 0.12), y, side * 0.75, y, LINE, ic->ink);
			arrow_head(ic, side * 1.08, y, side, 0.0, 0.4, 0.3, ic->ink);
		} else {
			segment(ic, side * 1.08, y, side * 0.75, y, LINE, ic->ink);
			arrow_head(ic, side * (rx + 0.1), y, -side, 0.0, 0.4, 0.3, ic->ink);
		}
	}
}

/* A tree with an arrow beside it: up by a tall tree, down by a short one. */
static void icon_height(const struct icon *ic, bool taller)
{
	const double ax = 0.58;

	if (taller) {
		small_tree(ic, -0.32, -0.36, 0.38, 0.58, 0.95);
		segment(ic, ax, 0.92, ax, -0.5, LINE, ic->ink);
		arrow_head(ic, ax, -0.98, 0.0, -1.0, 0.44, 0.32, ic->ink);
	} else {
		small_tree(ic, -0.32, 0.3, 0.42, 0.32, 0.95);
		segment(ic, ax, -0.92, ax, 0.45, LINE, ic->ink);
		arrow_head(ic, ax, 0.95, 0.0, 1.0, 0.44, 0.32, ic->ink);
	}
}

/* A leaf with its badge. */
static void icon_leaves(const struct icon *ic, bool more)
{
	leaf_shape(ic, -0.72, 0.5, 0.62, -0.86, 0.46);
	segment(ic, -0.95, 0.75, -0.72, 0.5, LINE, ic->ink);
	badge(ic, 0.46, 0.42, more);
}

/* A blank sheet and a pencil: "draw your own". */
static void icon_blank(const struct icon *ic)
{
	const struct pt sheet[5] = { { -0.72, -0.86 }, { 0.12, -0.86 }, { 0.56, -0.42 },
				     { 0.56, 0.86 }, { -0.72, 0.86 } };
	const struct pt fold[3] = { { 0.12, -0.86 }, { 0.12, -0.42 }, { 0.56, -0.42 } };
	const struct pt outline[6] = { sheet[0], sheet[1], sheet[2], sheet[3], sheet[4], sheet[0] };
	/* the pencil along (1, -1), its point at the lower left, on the sheet */
	const double px = -0.1, py = 0.5, k = 0.7071, len = 1.2, half = 0.15;
	const double bx = px + k * 0.34, by = py - k * 0.34;
	const struct pt body[4] = {
		{ bx + k * half, by + k * half },
		{ bx + k * len + k * half, by - k * len + k * half },
		{ bx + k * len - k * half, by - k * len - k * half },
		{ bx - k * half, by - k * half },
	};
	const struct pt tip[3] = { { px, py }, body[0], body[3] };
	const struct pt drawn[4] = { { -0.5, 0.62 }, { -0.38, 0.4 }, { -0.26, 0.62 }, { -0.14, 0.5 } };

	fill(ic, sheet, NPTS(sheet), ic->bg);
	fill(ic, fold, NPTS(fold), faded(ic->ink, 0.45f));
	line(ic, outline, NPTS(outline), LINE * 0.8, ic->ink);
	line(ic, fold, NPTS(fold), LINE * 0.6, ic->ink);
	line(ic, drawn, NPTS(drawn), LINE * 0.6, ic->ink);
	fill(ic, body, NPTS(body), ic->ink);
	fill(ic, tip, NPTS(tip), faded(ic->ink, 0.55f));
}

/* Spring: a cherry blossom, five notched petals round a cut-out heart. */
static void icon_blossom(const struct icon *ic)
{
	for (int k = 0; k < 5; k++) {
		double a = -0.5 * VEC_PI + 2.0 * VEC_PI * k / 5.0, c = cos(a), s = sin(a);
		/* the notch: a small wedge of the background at the petal's outer end */
		const struct pt notch[3] = { { 0.92 * c, 0.92 * s },
					     { 0.7 * c - 0.12 * s, 0.7 * s + 0.12 * c },
					     { 0.7 * c + 0.12 * s, 0.7 * s - 0.12 * c } };

		disc(ic, 0.48 * c, 0.48 * s, 0.36, ic->ink);
		fill(ic, notch, NPTS(notch), ic->bg);
	}
	disc(ic, 0.0, 0.0, 0.2, ic->bg);
	disc(ic, 0.0, 0.0, 0.09, ic->ink);
}

/* Grow: a cut trunk's year rings with a plus, "one more ring": a year older, a trunk
 * thicker. The rings are off centre, wider to the lower left, as wood grows where it
 * bears the load; bold and few, to read at a button's size. */
static void icon_grow(const struct icon *ic)
{
	static const double ring[3] = { 0.9, 0.6, 0.31 };
	double cx = 0.0, cy = 0.0;

	for (int k = 0; k < 3; k++) {
		cx = -0.1 + 0.06 * k;
		cy = -0.06 - 0.06 * k;
		disc(ic, cx, cy, ring[k], ic->ink);
		disc(ic, cx, cy, ring[k] - LINE, ic->bg);
	}
	disc(ic, cx, cy, 0.08, ic->ink); /* the pith */
	badge(ic, 0.58, 0.58, true);
}

/* Summer: the sun. */
static void icon_sun(const struct icon *ic)
{
	disc(ic, 0.0, 0.0, 0.44, ic->ink);
	for (int k = 0; k < 8; k++) {
		double a = 2.0 * VEC_PI * k / 8.0;

		segment(ic, 0.64 * cos(a), 0.64 * sin(a), 0.9 * cos(a), 0.9 * sin(a), LINE, ic->ink);
	}
}

/* Autumn: a maple leaf, five pointed lobes (each convex) on a stalk. */
static void icon_maple(const struct icon *ic)
{
	static const struct {
		double deg, len, width;
	} lobes[5] = {
		{ -90.0, 0.95, 0.3 },  { -145.0, 0.9, 0.28 }, { -35.0, 0.9, 0.28 },
		{ 160.0, 0.6, 0.2 }, { 20.0, 0.6, 0.2 },
	};
	const double cx = 0.0, cy = 0.12;

	segment(ic, cx, cy, 0.1, 0.95, LINE * 0.8, ic->ink);
	for (size_t k = 0; k < NPTS(lobes); k++) {
		double a = lobes[k].deg * VEC_PI / 180.0, dx = cos(a), dy = sin(a);
		double l = lobes[k].len, w = lobes[k].width, at = 0.38 * l;
		const struct pt kite[4] = {
			{ cx - dx * 0.1, cy - dy * 0.1 },
			{ cx + dx * at - dy * w, cy + dy * at + dx * w },
			{ cx + dx * l, cy + dy * l },
			{ cx + dx * at + dy * w, cy + dy * at - dx * w },
		};

		fill(ic, kite, NPTS(kite), ic->ink);
	}
	disc(ic, cx, cy, 0.26, ic->ink);
}

/* The origami hop leaf: three broad lobes, the side ones toothed. */
static void icon_hop(const struct icon *ic)
{
	static const struct {
		double deg, len, width;
	} lobes[5] = {
		{ -90.0, 0.95, 0.42 }, { -160.0, 0.8, 0.36 }, { -20.0, 0.8, 0.36 },
		{ -130.0, 0.85, 0.2 }, { -50.0, 0.85, 0.2 },
	};
	const double cx = 0.0, cy = 0.2;

	segment(ic, cx, cy, 0.0, 0.95, LINE * 0.8, ic->ink);
	for (size_t k = 0; k < NPTS(lobes); k++) {
		double a = lobes[k].deg * VEC_PI / 180.0, dx = cos(a), dy = sin(a);
		double l = lobes[k].len, w = lobes[k].width, at = 0.45 * l;
		const struct pt kite[4] = {
			{ cx - dx * 0.1, cy - dy * 0.1 },
			{ cx + dx * at - dy * w, cy + dy * at + dx * w },
			{ cx + dx * l, cy + dy * l },
			{ cx + dx * at + dy * w, cy + dy * at - dx * w },
		};

		fill(ic, kite, NPTS(kite), ic->ink);
	}
	disc(ic, cx, cy, 0.3, ic->ink);
}

/* The origami entire leaf: a plain upright blade on its stalk. */
static void icon_entire(const struct icon *ic)
{
	leaf_shape(ic, 0.0, 0.55, 0.0, -0.95, 0.55);
	segment(ic, 0.0, 0.95, 0.0, 0.55, LINE, ic->ink);
}

/* Winter: a snowflake, six arms with twigs. */
static void icon_snowflake(const struct icon *ic)
{
	for (int k = 0; k < 6; k++) {
		double a = -0.5 * VEC_PI + VEC_PI * k / 3.0, dx = cos(a), dy = sin(a);

		segment(ic, 0.0, 0.0, 0.92 * dx, 0.92 * dy, LINE * 0.85, ic->ink);
		for (int side = -1; side <= 1; side += 2) {
			double b = a + side * VEC_PI / 4.0;

			segment(ic, 0.55 * dx, 0.55 * dy, 0.55 * dx + 0.3 * cos(b), 0.55 * dy + 0.3 * sin(b),
				LINE * 0.7, ic->ink);
		}
	}
	disc(ic, 0.0, 0.0, 0.14, ic->ink);
}

void icon_draw_season(struct batch *b, enum season season, struct pt centre, double size,
		      struct rgba ink, struct rgba bg)
{
	struct icon ic = { b, centre, 0.5 * size, ink, bg };

	switch (season) {
	case SEASON_SPRING:
		icon_blossom(&ic);
		break;
	case SEASON_AUTUMN:
		icon_maple(&ic);
		break;
	case SEASON_WINTER:
		icon_snowflake(&ic);
		break;
	case SEASON_SUMMER:
	case SEASON_COUNT:
		icon_sun(&ic);
		break;
	}
}

/* A New strip card's icon, as its template's row says (app_mode_new.c). */
static void icon_template(const struct icon *ic, const struct app_template *tpl)
{
	switch (tpl->picture) {
	case APP_TEMPLATE_SHEET:
		icon_blank(ic);
		break;
	case APP_TEMPLATE_TREE:
		break; /* the picture is the tree itself (render_preview.c) */
	}
}

void icon_draw(struct batch *b, enum button button, struct pt centre, double size,
	       struct rgba ink, struct rgba bg)
{
	struct icon ic = { b, centre, 0.5 * size, ink, bg };
	const struct app_template *tpl = app_template_of(button);

	if (tpl) {
		icon_template(&ic, tpl);
		return;
	}
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
		icon_sun(&ic); /* summer's; icon_draw_season shows the tree's */
		break;
	case BUTTON_LEAF_DRAWN:
		icon_leaf(&ic); /* the leaf mode's own: the visitor's leaf */
		break;
	case BUTTON_LEAF_ENTIRE:
		icon_entire(&ic);
		break;
	case BUTTON_LEAF_HOP:
		icon_hop(&ic);
		break;
	case BUTTON_LEAF_MAPLE:
		icon_maple(&ic);
		break;
	case BUTTON_GROW:
		icon_grow(&ic);
		break;
	case BUTTON_VINE:
		icon_vine(&ic);
		break;
	case BUTTON_GEN_MORE:
	case BUTTON_GEN_FEWER:
		icon_branches(&ic, button == BUTTON_GEN_MORE);
		break;
	case BUTTON_GEN_WIDER:
	case BUTTON_GEN_NARROWER:
		icon_width(&ic, button == BUTTON_GEN_WIDER);
		break;
	case BUTTON_GEN_TALLER:
	case BUTTON_GEN_SHORTER:
		icon_height(&ic, button == BUTTON_GEN_TALLER);
		break;
	case BUTTON_GEN_LEAFIER:
	case BUTTON_GEN_BARER:
		icon_leaves(&ic, button == BUTTON_GEN_LEAFIER);
		break;
	default:
		break; /* BUTTON_COUNT, not on the screen; the templates, above */
	}
}
