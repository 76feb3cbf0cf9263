/* SPDX-License-Identifier: MIT */
#include "lift.h"

#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Depth candidates tried for each branch end. */
#define CANDIDATES 48
/* Generations below a branch its deep look-ahead sees (lifter_deeper), and the work it may
 * do over a lift: so many outcome()s per branch of the tree. */
#define LOOKAHEAD 3
#define LOOKAHEAD_WORK 2048

/* The sketch's 2D convex hull (Andrew's monotone chain), counter-clockwise. */
struct hull {
	struct vec3 *p;
	size_t n;
	double ymin, ymax;
};

static int cmp_xy(const void *a, const void *b)
{
	const struct vec3 *p = a, *q = b;

	if (p->x != q->x)
		return p->x < q->x ? -1 : 1;
	return (p->y > q->y) - (p->y < q->y);
}

static double cross2(struct vec3 o, struct vec3 a, struct vec3 b)
{
	return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static int hull_build(struct hull *h, const struct tree *t)
{
	size_t n = 0, k = 0;
	struct vec3 *pts;

	for (size_t i = 0; i < t->nbranches; i++)
		n += t->branches[i].npoints;
	pts = malloc((n + 1) * sizeof(*pts));
	h->p = malloc((2 * n + 2) * sizeof(*h->p));
	if (!pts || !h->p) {
		free(pts);
		free(h->p);
		return -ENOMEM;
	}
	n = 0;
	for (size_t i = 0; i < t->nbranches; i++)
		for (size_t j = 0; j < t->branches[i].npoints; j++)
			pts[n++] = t->branches[i].points[j];
	qsort(pts, n, sizeof(*pts), cmp_xy);
	for (size_t i = 0; i < n; i++) {
		while (k >= 2 && cross2(h->p[k - 2], h->p[k - 1], pts[i]) <= 0)
			k--;
		h->p[k++] = pts[i];
	}
	for (size_t i = n - 1, lo = k + 1; i-- > 0;) {
		while (k >= lo && cross2(h->p[k - 2], h->p[k - 1], pts[i]) <= 0)
			k--;
		h->p[k++] = pts[i];
	}
	h->n = k > 1 ? k - 1 : k;
	h->ymin = INFINITY;
	h->ymax = -INFINITY;
	for (size_t i = 0; i < h->n; i++) {
		h->ymin = fmin(h->ymin, h->p[i].y);
		h->ymax = fmax(h->ymax, h->p[i].y);
	}
	free(pts);
	return 0;
}

/* The hull's horizontal extent at height y: centre and half width (0 outside). */
static void hull_span(const struct hull *h, double y, double *xc, double *hw)
{
	double lo = INFINITY, hi = -INFINITY;

	for (size_t i = 0; i < h->n; i++) {
		struct vec3 a = h->p[i], b = h->p[(i + 1) % h->n];

		if ((a.y <= y && b.y >= y) || (b.y <= y && a.y >= y)) {
			double x = a.y == b.y ? a.x : a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);

			lo = fmin(lo, x);
			hi = fmax(hi, x);
			if (a.y == b.y) {
				lo = fmin(lo, b.x);
				hi = fmax(hi, b.x);
			}
		}
	}
	if (lo > hi) {
		*xc = 0;
		*hw = 0;
		return;
	}
	*xc = 0.5 * (lo + hi);
	*hw = 0.5 * (hi - lo);
}

/*
 * The second lift of 4.2 is turned 90 degrees about the vertical through the trunk's base
 * and its first generation moved onto the first tree's trunk; where a branch of it ends up:
 * turn_point(base, shift, p) with the shift of its first-generation ancestor. Lengths and
 * angles are kept, so 4.1's length, angle and view rules are the same in either frame; the
 * hull and the distance field are not, and the second lift sees them as they will be
 * after the turn.
 */
struct turn {
	struct vec3 base;
};

static struct vec3 turn_point(struct vec3 base, struct vec3 shift, struct vec3 p)
{
	struct vec3 d = vec3_sub(p, base);

	return vec3(base.x + d.z + shift.x, p.y + shift.y, base.z - d.x + shift.z);
}

/*
 * The depths z for which the end (x, y, z) lies inside the scaled 3D hull (discs swept
 * along y): [*lo, *hi]. With a turn (tu), the end as the merge will place it,
 * turn_point(base, shift, (x, y, z)): z becomes its x, and x fixes its depth. Returns false
 * if no depth is inside (only with a turn: a drawn end is inside the 2D hull); *lo = *hi
 * is then the depth nearest the hull.
 */
static bool hull_range(const struct hull *h, const struct turn *tu, struct vec3 shift, double x,
		       double y, double *lo, double *hi)
{
	struct vec3 at0 = tu ? turn_point(tu->base, shift, vec3(x, y, 0)) : vec3(x, y, 0);
	double xc, hw, r, w2, c = 0;

	hull_span(h, fmin(fmax(at0.y, h->ymin), h->ymax), &xc, &hw);
	r = LIFT_HULL_SCALE * hw;
	if (tu) {
		w2 = r * r - at0.z * at0.z;
		c = xc - at0.x; /* the depth that turns to the hull's centre line */
	} else {
		/* the drawn end is in the 2D hull, so inside the disc but for rounding (at the
		 * hull's top, where the disc is a point, it came out a hair outside) */
		w2 = fmax(r * r - (x - xc) * (x - xc), 0);
	}
	if (w2 < 0) {
		*lo = *hi = c;
		return false;
	}
	*lo = tu ? c - sqrt(w2) : -sqrt(w2);
	*hi = tu ? c + sqrt(w2) : sqrt(w2);
	return true;
}

/* Squared distances on the ground (x, z) to every branch placed so far (squared: only
 * compared, never added, so no square roots), in tiles of TILE x TILE cells that know
 * their largest value: a tile farther from a new branch than that is left alone. */
#define TILE 8
#define TILES (LIFT_FIELD_N / TILE)
_Static_assert(LIFT_FIELD_N % TILE == 0, "the field is made of whole tiles");
struct field {
	double x0, z0, cell;
	float d[LIFT_FIELD_N * LIFT_FIELD_N];
	float tile_max[TILES * TILES];
};

static double seg_dist2(double px, double pz, double ax, double az, double bx, double bz)
{
	double dx = bx - ax, dz = bz - az, dd = dx * dx + dz * dz;
	double s = dd > 0 ? ((px - ax) * dx + (pz - az) * dz) / dd : 0.0;

	s = s < 0 ? 0 : s > 1 ? 1 : s;
	dx = ax + s * dx - px;
	dz = az + s * dz - pz;
	return dx * dx + dz * dz;
}

/* Squared distance between [lo0, hi0] x [lo1, hi1] and [lo2, hi2] x [lo3, hi3], less a
 * margin far larger than seg_dist2's rounding: a bound that never exceeds what it
 * computes, so skipping changes no cell. */
static double box_dist2_below(double xlo, double xhi, double zlo, double zhi, double sxlo,
			      double sxhi, double szlo, double szhi)
{
	double dx = fmax(0, fmax(sxlo - xhi, xlo - sxhi)), dz = fmax(0, fmax(szlo - zhi, zlo - szhi));

	return (dx * dx + dz * dz) * (1 - 1e-9) - 1e-9;
}

static void field_add(struct field *f, struct vec3 a, struct vec3 b)
{
	double sxlo = fmin(a.x, b.x), sxhi = fmax(a.x, b.x), szlo = fmin(a.z, b.z), szhi = fmax(a.z, b.z);

	for (int tj = 0; tj < TILES; tj++) {
		/* cell centres exactly as below, so the tile's box holds them */
		double zlo = f->z0 + (tj * TILE + 0.5) * f->cell;
		double zhi = f->z0 + (tj * TILE + TILE - 1 + 0.5) * f->cell;

		for (int ti = 0; ti < TILES; ti++) {
			float *m = &f->tile_max[tj * TILES + ti], mx = 0;
			double xlo = f->x0 + (ti * TILE + 0.5) * f->cell;
			double xhi = f->x0 + (ti * TILE + TILE - 1 + 0.5) * f->cell;

			if (box_dist2_below(xlo, xhi, zlo, zhi, sxlo, sxhi, szlo, szhi) >= *m)
				continue; /* no cell of the tile is farther than the new branch */
			for (int j = tj * TILE; j < tj * TILE + TILE; j++) {
				double z = f->z0 + (j + 0.5) * f->cell;

				for (int i = ti * TILE; i < ti * TILE + TILE; i++) {
					double x = f->x0 + (i + 0.5) * f->cell;
					float d = (float)seg_dist2(x, z, a.x, a.z, b.x, b.z);
					float *c = &f->d[j * LIFT_FIELD_N + i];

					if (d < *c)
						*c = d;
					mx = *c > mx ? *c : mx;
				}
			}
			*m = mx;
		}
	}
}

static double field_at(const struct field *f, double x, double z)
{
	int i = (int)floor((x - f->x0) / f->cell), j = (int)floor((z - f->z0) / f->cell);

	i = i < 0 ? 0 : i >= LIFT_FIELD_N ? LIFT_FIELD_N - 1 : i;
	j = j < 0 ? 0 : j >= LIFT_FIELD_N ? LIFT_FIELD_N - 1 : j;
	return f->d[j * LIFT_FIELD_N + i];
}

/* The angle between a and b (0 if either is 0): atan2 keeps it exact near 0 and pi, where
 * acos of the cosine loses half the digits. */
static double angle_between(struct vec3 a, struct vec3 b)
{
	return atan2(vec3_len(vec3_cross(a, b)), vec3_dot(a, b));
}

/* x at index i, extended past the ends by point reflection, so smoothing bends nothing
 * there: a straight end stays straight. */
static double reflected(const double *x, size_t n, long i)
{
	if (i < 0)
		return 2 * x[0] - x[-i < (long)n ? -i : (long)n - 1];
	if (i >= (long)n) {
		long j = 2 * ((long)n - 1) - i;

		return 2 * x[n - 1] - x[j >= 0 ? j : 0];
	}
	return x[i];
}

/* Box filter of half width w, three passes (close to a Gaussian). */
static void smooth_profile(double *x, size_t n, size_t w)
{
	double *tmp;

	if (w == 0 || n < 3)
		return;
	tmp = malloc(n * sizeof(*tmp));
	if (!tmp)
		return;
	for (int pass = 0; pass < 3; pass++) {
		for (size_t i = 0; i < n; i++) {
			double sum = 0;

			for (long k = (long)i - (long)w; k <= (long)(i + w); k++)
				sum += reflected(x, n, k);
			tmp[i] = sum / (double)(2 * w + 1);
		}
		memcpy(x, tmp, n * sizeof(*x));
	}
	free(tmp);
}

/*
 * 4.3: depth along one branch from the constant-curvature rule. In the stroke's frame
 * (u along the chord, x across it on the screen, y the depth): kappa = max |x''|, |y''| =
 * sqrt(kappa^2 - x''^2), its sign flipping where x' = 0; y(0) = 0 and y'(0) such that
 * y'(end) = 0. Writes y for each point into depth.
 */
static void curvature_depth(const struct branch *b, double *depth)
{
	size_t n = b->npoints;
	struct vec3 a = b->points[0], e = b->points[n - 1];
	double cx = e.x - a.x, cy = e.y - a.y, L = hypot(cx, cy);
	double *u, *x, *ypp, kappa = 0, sign = 1, y, yp, sum;
	double xlo = 0, xhi = 0, ylo = 0, yhi = 0;

	for (size_t i = 0; i < n; i++)
		depth[i] = 0;
	if (n < 3 || L <= 0)
		return;
	u = malloc(3 * n * sizeof(*u));
	if (!u)
		return; /* depth along the branch is a refinement: none rather than fail */
	x = u + n;
	ypp = x + n;
	cx /= L;
	cy /= L;
	for (size_t i = 0; i < n; i++) {
		double dx = b->points[i].x - a.x, dy = b->points[i].y - a.y;

		u[i] = dx * cx + dy * cy;
		x[i] = -dx * cy + dy * cx;
		xlo = fmin(xlo, x[i]);
		xhi = fmax(xhi, x[i]);
	}
	/* Second derivatives amplify the hand's tremor: smooth x over ~1/32 of the stroke
	 * first, so kappa is the curvature the child drew. */
	smooth_profile(x, n, n / 64 > 0 ? n / 64 : 1);
	for (size_t i = 1; i + 1 < n; i++) {
		double h0 = u[i] - u[i - 1], h1 = u[i + 1] - u[i];

		ypp[i] = h0 > 1e-9 && h1 > 1e-9 ?
				 2 * ((x[i + 1] - x[i]) / h1 - (x[i] - x[i - 1]) / h0) / (h0 + h1) :
				 0;
		kappa = fmax(kappa, fabs(ypp[i]));
	}
	ypp[0] = ypp[n - 1] = 0;
	for (size_t i = 1; i + 1 < n; i++) {
		double xpp = ypp[i], xp = x[i + 1] - x[i - 1];

		/* y'' has the sign of -x', so it turns where x' = 0: x = sin gives y = cos */
		if (xp != 0)
			sign = xp > 0 ? -1 : 1;
		ypp[i] = sign * sqrt(fmax(kappa * kappa - xpp * xpp, 0));
	}
	/* y'(u) = y'(0) + int y''; choose y'(0) so that y'(end) = 0 */
	sum = 0;
	for (size_t i = 1; i < n; i++)
		sum += 0.5 * (ypp[i - 1] + ypp[i]) * (u[i] - u[i - 1]);
	yp = -sum;
	y = 0;
	for (size_t i = 1; i < n; i++) {
		double h = u[i] - u[i - 1], yp1 = yp + 0.5 * (ypp[i - 1] + ypp[i]) * h;

		y += 0.5 * (yp + yp1) * h;
		yp = yp1;
		depth[i] = y;
		ylo = fmin(ylo, y);
		yhi = fmax(yhi, y);
	}
	/* Both ends stay where 4.1 put them: tilt the profile so y(end) = 0. */
	for (size_t i = 1; i < n; i++)
		depth[i] -= u[n - 1] > 0 ? depth[n - 1] * u[i] / u[n - 1] : 0;
	ylo = yhi = 0;
	for (size_t i = 0; i < n; i++) {
		ylo = fmin(ylo, depth[i]);
		yhi = fmax(yhi, depth[i]);
	}
	/* A helix is as deep as it is wide: never deeper than the stroke's own sideways
	 * excursion (guards against strokes the rule was not made for, like zigzags). */
	if (yhi - ylo > xhi - xlo && yhi - ylo > 0)
		for (size_t i = 0; i < n; i++)
			depth[i] *= (xhi - xlo) / (yhi - ylo);
	free(u);
}

/*
 * What a depth of a branch's end leaves its children (lifter_score), or its descendants
 * (lifter_deep): how many would have no depth keeping the angle rule, the hull, the length
 * rule. Fewer is better, in that order.
 */
struct lookahead {
	long angle, hull, length;
};

/* A score worse than any. */
#define LOOKAHEAD_WORST ((struct lookahead){ LONG_MAX, 0, 0 })

static int lookahead_cmp(const struct lookahead *a, const struct lookahead *b)
{
	const long x[] = { a->angle, a->hull, a->length };
	const long y[] = { b->angle, b->hull, b->length };

	for (int i = 0; i < 3; i++)
		if (x[i] != y[i])
			return x[i] < y[i] ? -1 : 1;
	return 0;
}

/* a + b (neither LOOKAHEAD_WORST) */
static struct lookahead lookahead_add(struct lookahead a, struct lookahead b)
{
	return (struct lookahead){ a.angle + b.angle, a.hull + b.hull, a.length + b.length };
}

/*
 * Among n candidate depths z[] with field values d[] (the largest is best) and look-ahead
 * scores la[]: of those with the best score, the sparsest, a tie (the field is symmetric
 * in z about a trunk, and constant within a cell) broken at random; or with
 * LIFT_PICK_RANDOM, any of them.
 */
static double pick_depth(const double *z, const double *d, const struct lookahead *la, int n,
			 enum lift_pick pick, struct rng *rng)
{
	int idx[CANDIDATES], m = 0, top = 0;
	bool first[CANDIDATES];
	double best = -1;

	for (int i = 1; i < n; i++)
		if (lookahead_cmp(&la[i], &la[top]) < 0)
			top = i;
	for (int i = 0; i < n; i++) {
		first[i] = lookahead_cmp(&la[i], &la[top]) == 0;
		if (first[i])
			best = fmax(best, d[i]);
	}
	for (int i = 0; i < n; i++)
		if (first[i] && (pick == LIFT_PICK_RANDOM || d[i] >= best - 1e-6 * best))
			idx[m++] = i;
	return z[idx[m > 1 ? rng_next(rng) % (uint64_t)m : 0]];
}

/* A branch as 4.1 sees it: the segment from its start to its end. */
struct seg {
	struct vec3 s, e;
	double max_child_angle; /* the largest drawn angle to its children */
};

/* Where a branch or a leaf hangs, as (segment, fraction): arc-length parameters change
 * when the branches gain depth, the points they name do not. */
struct anchor {
	size_t segment;
	double seg_t;
};

static struct vec3 anchor_point(const struct branch *b, struct anchor a)
{
	size_t k = a.segment;

	return k + 1 < b->npoints ? vec3_lerp(b->points[k], b->points[k + 1], a.seg_t) : b->points[k];
}

/* The parameter of anchor a on b once b has depth. When a lies on a vertex, the rounding
 * of the new arc lengths could make tree_locate() (and so tree_frame_at(), which leaves
 * follow) give the neighbouring segment and its direction: nudge the parameter by a few
 * ulps until it names the same segment again. */
static double anchor_param(const struct branch *b, struct anchor a)
{
	double t = tree_param(b, a.segment, a.seg_t);

	for (int i = 0; i < 64; i++) {
		size_t k;
		double f;

		tree_locate(b, t, &k, &f);
		if (k == a.segment)
			break;
		t = nextafter(t, k < a.segment ? 2.0 : -1.0);
	}
	return t;
}

/*
 * 4.1's rules for one branch end, as the depths dz of the end relative to the start that
 * keep them: up to two intervals (the angle rule can cut a gap out of the view rule's
 * range when the limit is obtuse), in increasing order.
 */
struct dzset {
	int n;
	double lo[2], hi[2];
};

static struct dzset dzset_point(double dz)
{
	return (struct dzset){ 1, { dz, 0 }, { dz, 0 } };
}

static void dzset_add(struct dzset *s, double lo, double hi)
{
	if (lo <= hi && s->n < 2) {
		s->lo[s->n] = lo;
		s->hi[s->n++] = hi;
	}
}

/* s intersected with [lo, hi]. */
static struct dzset dzset_clip(const struct dzset *s, double lo, double hi)
{
	struct dzset r = { 0 };

	for (int i = 0; i < s->n; i++)
		dzset_add(&r, fmax(s->lo[i], lo), fmin(s->hi[i], hi));
	return r;
}

/* The point of non-empty s nearest [lo, hi]. */
static double dzset_nearest(const struct dzset *s, double lo, double hi)
{
	double best = s->lo[0], gap = INFINITY;

	for (int i = 0; i < s->n; i++) {
		double z = s->hi[i] < lo ? s->hi[i] : s->lo[i] > hi ? s->lo[i] : fmax(s->lo[i], lo);
		double g = z < lo ? lo - z : z > hi ? z - hi : 0;

		if (g < gap) {
			gap = g;
			best = z;
		}
	}
	return best;
}

/* The k-th of n depths spread evenly over non-empty s, ends included. */
static double dzset_spread(const struct dzset *s, int k, int n)
{
	double total = 0, at;

	for (int i = 0; i < s->n; i++)
		total += s->hi[i] - s->lo[i];
	at = n > 1 ? total * k / (n - 1) : 0;
	for (int i = 0; i < s->n; i++) {
		double w = s->hi[i] - s->lo[i];

		if (at <= w || i == s->n - 1)
			return fmin(s->lo[i] + at, s->hi[i]);
		at -= w;
	}
	return s->lo[0];
}

/* What 4.1 needs to know of a branch besides its start's depth and its parent's chord. */
struct rules {
	double dx, dy;   /* its chord as the front view shows it */
	double dxy;      /* its length there */
	double amax;     /* 1.2 x the largest drawn angle between its parent and its children */
	double cos_amax;
	double hlo, hhi; /* the depths of its end inside the hull (absolute) */
	bool hull;       /* false: no depth is (a turned end); hlo = hhi the nearest */
};

/* How the rules fared for one branch end (docs/lifting.md, "When a rule cannot hold"). */
enum lift_outcome {
	LIFT_KEPT,      /* every rule */
	LIFT_NO_LENGTH, /* no depth within view, angle and hull keeps the length */
	LIFT_NO_HULL,   /* no depth within view and angle is inside the hull */
	LIFT_NO_ANGLE,  /* no depth within the view rule keeps the angle */
};

/*
 * The depths dz that keep the view rule (|dz| <= dxy, the chord's length on the screen)
 * and the angle rule (at most amax from the parent's chord pd). With t = atan(dz / dxy) in
 * [-pi/4, pi/4] the branch's direction is (cos t u, sin t) for u its direction on the
 * screen, so cos(angle) = (k cos t + pd.z sin t) / |pd| = rho cos(t - t0): the rule is an
 * arc of t about t0, exactly, however narrow. If no t keeps it, *s is the depth of the
 * least angle within the view rule, and false is returned.
 */
static bool view_angle_range(const struct rules *r, struct vec3 pd, struct dzset *s)
{
	double dxy = r->dxy, plen = vec3_len(pd), k, rho, t0, c = r->cos_amax, alpha;

	s->n = 0;
	if (dxy <= 0) {
		*s = dzset_point(0); /* no chord on the screen: no depth either */
		return true;
	}
	if (plen <= 0 || r->amax >= VEC_PI) {
		dzset_add(s, -dxy, dxy);
		return true;
	}
	k = (r->dx * pd.x + r->dy * pd.y) / dxy;
	rho = sqrt(k * k + pd.z * pd.z) / plen;
	t0 = atan2(pd.z, k);
	if (c <= -rho || (rho <= 1e-12 && c <= 0)) {
		/* every direction is within the limit (rho 0: all at right angles) */
		dzset_add(s, -dxy, dxy);
		return true;
	}
	if (c < rho && rho > 1e-12) {
		/* a hair inside the arc, so rounding never puts its ends outside the limit */
		alpha = acos(c / rho) * (1 - 1e-12);
		for (int j = -1; j <= 1; j++) {
			double lo = fmax(t0 - alpha + 2 * VEC_PI * j, -0.25 * VEC_PI);
			double hi = fmin(t0 + alpha + 2 * VEC_PI * j, 0.25 * VEC_PI);

			if (lo <= hi) {
				/* |t| <= pi/4: tan is exact enough, and |dz| <= dxy */
				lo = lo <= -0.25 * VEC_PI ? -dxy : dxy * tan(lo);
				hi = hi >= 0.25 * VEC_PI ? dxy : dxy * tan(hi);
				if (s->n && lo <= s->hi[s->n - 1])
					s->hi[s->n - 1] = fmax(s->hi[s->n - 1], hi);
				else
					dzset_add(s, lo, hi);
			}
		}
		if (s->n)
			return true;
	}
	/* none: the t nearest t0 round the circle, within [-pi/4, pi/4] */
	if (fabs(t0) <= 0.25 * VEC_PI) {
		*s = dzset_point(dxy * tan(t0));
		/* A branch drawn (all but) straight on from its parent has a limit of (all but)
		 * 0, which cos() cannot tell from 0 (cos(5e-9) is 1): the arc is then lost in
		 * rounding, but its centre, leaning as the parent does, keeps the rule. */
		if (angle_between(vec3(r->dx, r->dy, s->lo[0]), pd) <= r->amax + 1e-10)
			return true;
	} else if (fabs(remainder(t0 - 0.25 * VEC_PI, 2 * VEC_PI)) <=
		 fabs(remainder(t0 + 0.25 * VEC_PI, 2 * VEC_PI)))
		*s = dzset_point(dxy);
	else
		*s = dzset_point(-dxy);
	return false;
}

/*
 * The depths of a branch's end (absolute z) that 4.1 may choose, its start at depth zs and
 * its parent's chord pd: those keeping every rule, or where that cannot be, what
 * docs/lifting.md says: the view rule always; the angle rule if any depth within the view
 * rule keeps it, otherwise the least angle; the hull if any depth within those keeps it,
 * otherwise the depth nearest the hull within them and the length rule (if it can hold
 * there); the length rule if any depth within all those keeps it, otherwise the shortest.
 */
static enum lift_outcome admissible(const struct rules *r, double zs, struct vec3 pd,
				    struct dzset *out)
{
	double dxy = r->dxy, reach = LIFT_MAX_LENGTH_RATIO * vec3_len(pd), dl;
	struct dzset va, in, fit;
	enum lift_outcome res = LIFT_KEPT;

	if (!view_angle_range(r, pd, &va)) {
		*out = va;
		res = LIFT_NO_ANGLE;
	} else {
		/* the length rule: |dz| <= dl; none if the screen alone makes it too long */
		dl = reach >= dxy ? sqrt(reach * reach - dxy * dxy) : -1;
		in = r->hull ? dzset_clip(&va, r->hlo - zs, r->hhi - zs) : (struct dzset){ 0 };
		if (in.n == 0) {
			fit = dzset_clip(&va, -dl, dl);
			*out = dzset_point(dzset_nearest(fit.n ? &fit : &va, r->hlo - zs, r->hhi - zs));
			res = LIFT_NO_HULL;
		} else {
			*out = dzset_clip(&in, -dl, dl);
			if (out->n == 0) {
				*out = dzset_point(dzset_nearest(&in, 0, 0));
				res = LIFT_NO_LENGTH;
			}
		}
	}
	for (int i = 0; i < out->n; i++) {
		out->lo[i] += zs;
		out->hi[i] += zs;
	}
	return res;
}

/*
 * admissible()'s outcome alone, for the look-ahead, which asks it of every child at every
 * candidate. Where the view, length and hull rules leave a range and the parent's chord
 * points forwards on the screen (k > 0), the direction in it nearest the parent's is the
 * depth dxy * pd.z / k (t = t0) clamped to the range: if that keeps the angle rule with
 * room to spare, every rule holds; otherwise admissible() decides.
 */
static enum lift_outcome outcome(const struct rules *r, double zs, struct vec3 pd)
{
	double dxy = r->dxy, plen = vec3_len(pd), reach = LIFT_MAX_LENGTH_RATIO * plen;
	double k = dxy > 0 ? (r->dx * pd.x + r->dy * pd.y) / dxy : 0, lo = -dxy, hi = dxy;
	struct dzset set;

	if (r->hull && reach >= dxy && k > 0 && plen > 0) {
		double dl = sqrt(reach * reach - dxy * dxy), dz;

		lo = fmax(fmax(lo, -dl), r->hlo - zs);
		hi = fmin(fmin(hi, dl), r->hhi - zs);
		dz = fmin(fmax(dxy * pd.z / k, lo), hi);
		if (lo <= hi && r->dx * pd.x + r->dy * pd.y + dz * pd.z >=
					(r->cos_amax + 1e-9) * plen * sqrt(dxy * dxy + dz * dz))
			return LIFT_KEPT;
	}
	return admissible(r, zs, pd, &set);
}

/* 4.3 on top of 4.1: branch b's points go from its start's depth to its end's, plus the
 * curvature depth. */
static void branch_depth(struct branch *b, const struct seg *s, const double *depth,
			 const double *frac)
{
	for (size_t k = 0; k < b->npoints; k++)
		b->points[k].z = s->s.z + (s->e.z - s->s.z) * frac[k] + depth[k];
}

/*
 * Where along branch b each point is, as a fraction of its length on the screen: 4.3 runs
 * the depth from the start's to the end's by it, so the end is exactly where 4.1 put it
 * (the drawn depth of a stroke on a turned tree is not the lift's).
 */
static void screen_fractions(const struct branch *b, double *f)
{
	double len = 0, walked = 0;

	for (size_t k = 0; k + 1 < b->npoints; k++)
		len += hypot(b->points[k + 1].x - b->points[k].x, b->points[k + 1].y - b->points[k].y);
	for (size_t k = 0; k < b->npoints; k++) {
		f[k] = len > 0 ? walked / len : 0;
		if (k + 1 < b->npoints)
			walked += hypot(b->points[k + 1].x - b->points[k].x,
					b->points[k + 1].y - b->points[k].y);
	}
	f[b->npoints - 1] = 1;
}

/*
 * The state of one lift (lift_once). Depths of a child's start on its parent are affine in
 * the parent's start and end depths: z = zs + (ze - zs) at_f + at_d, at_f the fraction along
 * the parent on the screen, at_d 4.3's depth there (which 4.1 does not change).
 */
struct lifter {
	struct tree *t;
	const struct turn *tu; /* the second lift of 4.2, or NULL */
	struct field *f;
	struct hull h;
	struct seg *seg;
	struct anchor *root, *leaf;
	struct vec3 *shift;  /* with tu: where the merge moves each branch after the turn */
	struct rules *rules; /* each branch's, once the trunk is placed */
	long work;           /* what is left of the deep look-ahead's outcome()s */
	double *at_f, *at_d;
	int *order, *first, *next; /* a generation's branches; each branch's children */
	/* 4.3's depth and the fraction along the screen of every point, branch i's from
	 * at[i]: neither depends on where 4.1 puts the branch */
	double *depth, *frac;
	size_t *at;
	int maxgen;
};

static void lifter_finish(struct lifter *L)
{
	free(L->h.p);
	free(L->seg);
	free(L->root);
	free(L->leaf);
	free(L->shift);
	free(L->rules);
	free(L->at_f);
	free(L->order);
	free(L->depth);
	free(L->at);
}

static int lifter_init(struct lifter *L, struct tree *t, const struct turn *tu, struct field *f)
{
	size_t nb = t->nbranches + 1, npoints = 1;
	int ret;

	*L = (struct lifter){ .t = t, .tu = tu, .f = f, .work = LOOKAHEAD_WORK * (long)nb };
	ret = hull_build(&L->h, t);
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < t->nbranches; i++)
		npoints += t->branches[i].npoints;
	L->seg = malloc(nb * sizeof(*L->seg));
	L->root = malloc(nb * sizeof(*L->root));
	L->leaf = malloc((t->nleaves + 1) * sizeof(*L->leaf));
	L->shift = calloc(nb, sizeof(*L->shift));
	L->rules = malloc(nb * sizeof(*L->rules));
	L->at_f = malloc(2 * nb * sizeof(*L->at_f));
	L->order = malloc(3 * nb * sizeof(*L->order));
	L->depth = malloc(2 * npoints * sizeof(*L->depth));
	L->at = malloc(nb * sizeof(*L->at));
	if (!L->seg || !L->root || !L->leaf || !L->shift || !L->rules || !L->at_f || !L->order ||
	    !L->depth || !L->at) {
		lifter_finish(L);
		return -ENOMEM;
	}
	L->at_d = L->at_f + nb;
	L->first = L->order + nb;
	L->next = L->first + nb;
	L->frac = L->depth + npoints;
	return 0;
}

/* The distance field over the hull (and so over the turned tree too: the trunk's base is
 * in it), for the first lift. */
static void lifter_field(struct lifter *L)
{
	struct field *f = L->f;
	double xmin = INFINITY, xmax = -INFINITY, rmax;

	for (size_t i = 0; i < L->h.n; i++) {
		xmin = fmin(xmin, L->h.p[i].x);
		xmax = fmax(xmax, L->h.p[i].x);
	}
	rmax = LIFT_HULL_SCALE * 0.5 * (xmax - xmin) + 1e-3;
	if (L->tu)
		return;
	f->cell = fmax(xmax - xmin + 2 * rmax, 2 * rmax) / LIFT_FIELD_N;
	f->x0 = 0.5 * (xmin + xmax) - 0.5 * LIFT_FIELD_N * f->cell;
	f->z0 = -0.5 * LIFT_FIELD_N * f->cell;
	for (int i = 0; i < LIFT_FIELD_N * LIFT_FIELD_N; i++)
		f->d[i] = INFINITY;
	for (int i = 0; i < TILES * TILES; i++)
		f->tile_max[i] = INFINITY;
}

/*
 * The sketch as the front view shows it (a stroke drawn on a turned tree has depth; the
 * lift chooses its own), the largest drawn angle between each parent and its children,
 * each branch's children, where everything hangs (on the drawing as it is) and where each
 * child's start is along its parent.
 */
static void lifter_sketch(struct lifter *L)
{
	struct tree *t = L->t;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		L->seg[i].s = vec3(b->points[0].x, b->points[0].y, 0);
		L->seg[i].e = vec3(b->points[b->npoints - 1].x, b->points[b->npoints - 1].y, 0);
		L->seg[i].max_child_angle = 0;
		L->maxgen = b->generation > L->maxgen ? b->generation : L->maxgen;
		L->first[i] = L->next[i] = -1;
	}
	for (size_t i = t->nbranches; i-- > 0;) {
		int p = t->branches[i].parent;

		if (p < 0)
			continue;
		L->seg[p].max_child_angle =
			fmax(L->seg[p].max_child_angle,
			     angle_between(vec3_sub(L->seg[p].e, L->seg[p].s),
					   vec3_sub(L->seg[i].e, L->seg[i].s)));
		L->next[i] = L->first[p];
		L->first[p] = (int)i;
		tree_locate(&t->branches[p], t->branches[i].parent_t, &L->root[i].segment,
			    &L->root[i].seg_t);
	}
	for (size_t i = 0; i < t->nleaves; i++)
		tree_locate(&t->branches[t->leaves[i].branch], t->leaves[i].branch_t,
			    &L->leaf[i].segment, &L->leaf[i].seg_t);
	for (size_t i = 0, at = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		const double *depth = L->depth + at, *frac = L->frac + at;

		L->at[i] = at;
		at += b->npoints;
		curvature_depth(b, L->depth + L->at[i]);
		screen_fractions(b, L->frac + L->at[i]);
		for (int c = L->first[i]; c >= 0; c = L->next[c]) {
			size_t k = L->root[c].segment, j = k + 1 < b->npoints ? k + 1 : k;
			double s = L->root[c].seg_t;

			L->at_f[c] = frac[k] + (frac[j] - frac[k]) * s;
			L->at_d[c] = depth[k] + (depth[j] - depth[k]) * s;
		}
	}
}

/* The rules of branch id, its end's hull range seen as the merge will place it. */
static void lifter_rules(struct lifter *L, int id)
{
	const struct seg *s = &L->seg[id];
	struct rules *r = &L->rules[id];

	r->dx = s->e.x - s->s.x;
	r->dy = s->e.y - s->s.y;
	r->dxy = hypot(r->dx, r->dy);
	r->amax = fmin(LIFT_MAX_ANGLE_RATIO * L->seg[L->t->branches[id].parent].max_child_angle,
		       VEC_PI);
	r->cos_amax = cos(r->amax);
	r->hull = hull_range(&L->h, L->tu, L->shift[id], s->e.x, s->e.y, &r->hlo, &r->hhi);
}

/*
 * Once the trunk is placed: where the merge moves each branch of the second tree (a first
 * generation branch onto the first tree's trunk, the same as this one, and the rest with
 * it), and every branch's rules.
 */
static void lifter_prepare(struct lifter *L)
{
	struct tree *t = L->t;

	for (int g = 1; g <= L->maxgen; g++)
		for (size_t i = 0; i < t->nbranches; i++) {
			const struct branch *b = &t->branches[i];

			if (b->generation != g || b->parent < 0)
				continue;
			if (L->tu && t->branches[b->parent].parent < 0) {
				struct vec3 on = anchor_point(&t->branches[b->parent], L->root[i]);
				struct vec3 s = vec3(L->seg[i].s.x, L->seg[i].s.y, on.z);

				L->shift[i] = vec3_sub(on, turn_point(L->tu->base, vec3(0, 0, 0), s));
			} else if (L->tu) {
				L->shift[i] = L->shift[b->parent];
			}
			lifter_rules(L, (int)i);
		}
}

/*
 * The chord of branch id's parent as the rules see it. In the second lift a first
 * generation branch is turned onto the first tree's trunk, which is not turned: the angle
 * the merged copy makes with it is the angle to that trunk turned back (x, y, z) ->
 * (-z, y, x), here where the trunk's chord has no depth, (0, dy, dx).
 */
static struct vec3 parent_chord(const struct lifter *L, int id)
{
	int p = L->t->branches[id].parent;
	struct vec3 pd = vec3_sub(L->seg[p].e, L->seg[p].s);

	return L->tu && L->t->branches[p].parent < 0 ? vec3(-pd.z, pd.y, pd.x) : pd;
}

/* The look-ahead score of end depth e for branch id, its start s: its children's
 * outcomes. */
static struct lookahead lifter_score(const struct lifter *L, int id, struct vec3 s, struct vec3 e)
{
	struct vec3 pd = vec3_sub(e, s);
	struct lookahead la = { 0 };

	for (int c = L->first[id]; c >= 0; c = L->next[c]) {
		double zs = s.z + (e.z - s.z) * L->at_f[c] + L->at_d[c];

		switch (outcome(&L->rules[c], zs, pd)) {
		case LIFT_NO_ANGLE:
			la.angle++;
			break;
		case LIFT_NO_HULL:
			la.hull++;
			break;
		case LIFT_NO_LENGTH:
			la.length++;
			break;
		case LIFT_KEPT:
			break;
		}
	}
	return la;
}

static int lifter_candidates(const struct lifter *L, int id, double zs, struct vec3 pd,
			     double *cz);

/* a, or b if b is lower */
static const struct lookahead *lookahead_min(const struct lookahead *a, const struct lookahead *b)
{
	return b && lookahead_cmp(b, a) < 0 ? b : a;
}

static struct lookahead lifter_deep(struct lifter *L, int id, struct vec3 s, struct vec3 e,
				    int depth, const struct lookahead *limit, bool length);

/* The least lifter_deep() of branch id over its candidate depths, its start at depth zs and
 * its parent's chord pd; worse than *limit if none is better. */
static struct lookahead lifter_best(struct lifter *L, int id, double zs, struct vec3 pd, int depth,
				    const struct lookahead *limit, bool length)
{
	struct vec3 s = vec3(L->seg[id].s.x, L->seg[id].s.y, zs);
	struct lookahead best = LOOKAHEAD_WORST;
	double cz[CANDIDATES];
	int m = lifter_candidates(L, id, zs, pd, cz);

	for (int c = 0; c < m && (best.angle || best.hull || best.length) && L->work > 0; c++) {
		struct lookahead la;

		if (c > 0 && cz[c] == cz[c - 1])
			continue; /* (where no depth keeps every rule: the one there is) */
		la = lifter_deep(L, id, s, vec3(L->seg[id].e.x, L->seg[id].e.y, cz[c]), depth,
				 lookahead_min(&best, limit), length);
		if (lookahead_cmp(&la, &best) < 0)
			best = la;
	}
	/* (out of work before a candidate: lifter_deeper() throws the result away) */
	return best.angle == LONG_MAX ? (struct lookahead){ 0 } : best;
}

/*
 * The deep look-ahead of lifter_deeper(): how many of branch id's descendants, down to
 * `depth` generations below it, would find no depth keeping the angle rule or the hull,
 * its start s and its end e: each child's outcome and, below it, the least its own
 * descendants can make over its candidate depths, and so on. A turned end that no depth
 * puts inside the hull is not counted: no depth above it helps either. Stops as soon as
 * the sum is worse than *limit (it only grows), or L->work runs out.
 */
static struct lookahead lifter_deep(struct lifter *L, int id, struct vec3 s, struct vec3 e,
				    int depth, const struct lookahead *limit, bool length)
{
	struct vec3 pd = vec3_sub(e, s);
	struct lookahead la = { 0 };

	for (int c = L->first[id]; c >= 0 && L->work > 0; c = L->next[c]) {
		double zs = s.z + (e.z - s.z) * L->at_f[c] + L->at_d[c];

		L->work--;
		switch (outcome(&L->rules[c], zs, pd)) {
		case LIFT_NO_ANGLE:
			la.angle++;
			break;
		case LIFT_NO_HULL:
			la.hull += L->rules[c].hull;
			break;
		case LIFT_NO_LENGTH:
			la.length += length;
			break;
		case LIFT_KEPT:
			break;
		}
		if (depth > 1 && L->first[c] >= 0 && !(limit && lookahead_cmp(&la, limit) > 0)) {
			/* what is left of the limit for c's descendants */
			struct lookahead rest = { 0 };

			if (limit)
				rest = (struct lookahead){ limit->angle - la.angle, limit->hull - la.hull,
							   limit->length - la.length };
			la = lookahead_add(la, lifter_best(L, c, zs, pd, depth - 1, limit ? &rest : NULL,
							   length));
		}
		if (limit && lookahead_cmp(&la, limit) > 0)
			break;
	}
	return la;
}

/*
 * The candidate depths cz[] for branch id's end, its start at depth zs and its parent's
 * chord pd. Where every rule can hold: CANDIDATES depths evenly spaced over the range the
 * view, length and hull rules leave, those that keep the angle rule too (to 1e-9 rad); if
 * the angle rule leaves only depths between them, CANDIDATES spread over those
 * (admissible(), exact). Otherwise the one depth admissible() gives, CANDIDATES times (the
 * drawing's seeded generator then picks one of the equal ones, as it always has). Returns
 * how many.
 */
static int lifter_candidates(const struct lifter *L, int id, double zs, struct vec3 pd,
			     double *cz)
{
	const struct rules *r = &L->rules[id];
	struct dzset set;
	int m = 0;

	if (admissible(r, zs, pd, &set) == LIFT_KEPT) {
		double dxy = r->dxy, reach = LIFT_MAX_LENGTH_RATIO * vec3_len(pd);
		double dz = sqrt(fmax(reach * reach - dxy * dxy, 0));
		double lo = fmax(fmax(zs - dxy, zs - dz), r->hlo);
		double hi = fmin(fmin(zs + dxy, zs + dz), r->hhi);
		/* (the same bounds as the set's, but for rounding) */
		double eps = 1e-12 * (dxy + fabs(zs) + 1);

		for (int c = 0; c < CANDIDATES; c++) {
			double z = lo + (hi - lo) * c / (CANDIDATES - 1);

			for (int i = 0; i < set.n; i++)
				if (z >= set.lo[i] - eps && z <= set.hi[i] + eps) {
					cz[m++] = z;
					break;
				}
		}
		if (m > 0)
			return m;
	}
	for (int c = 0; c < CANDIDATES; c++)
		cz[c] = dzset_spread(&set, c, CANDIDATES);
	return CANDIDATES;
}

/*
 * The look-ahead one generation deep sees a child that no depth lets keep the rules, not
 * a grandchild: a twig ending at the top of the sketch, where the hull's disc is a point,
 * must start near the sketch plane, so its parent must not lean far out, and that is
 * its grandparent's doing. So branch id's end, chosen among the candidates cz[] (field
 * values cd[]) by its children's scores, is looked at LOOKAHEAD generations deep
 * (lifter_deep): if another candidate lets fewer of its descendants break the angle rule
 * or the hull, the end goes to the sparsest of those that let the fewest, and of those,
 * that leave the fewest children too long. Where the first choice is as good as any, as
 * far as the look-ahead sees, it stays (so does a tree that keeps every rule). A lift
 * asks at most LOOKAHEAD_WORK x its branches outcome()s of it; when they are spent, the
 * first choice stays.
 */
static void lifter_deeper(struct lifter *L, int id, const double *cz, const double *cd, int m,
			  enum lift_pick pick, struct rng *rng)
{
	struct seg *s = &L->seg[id];
	struct lookahead deep[CANDIDATES], full[CANDIDATES], now, best;

	if (L->first[id] < 0 || L->work <= 0)
		return;
	now = lifter_deep(L, id, s->s, s->e, LOOKAHEAD, NULL, false);
	if (!now.angle && !now.hull)
		return;
	best = now;
	for (int c = 0; c < m; c++) {
		deep[c] = cz[c] == s->e.z ?
				  now :
				  lifter_deep(L, id, s->s, vec3(s->e.x, s->e.y, cz[c]), LOOKAHEAD, &best, false);
		if (lookahead_cmp(&deep[c], &best) < 0)
			best = deep[c];
	}
	if (L->work <= 0 || lookahead_cmp(&best, &now) == 0)
		return;
	/* of those, the ones that leave the fewest children too long, or if the work allows,
	 * the fewest descendants as far as the look-ahead sees */
	now = LOOKAHEAD_WORST;
	for (int c = 0; c < m; c++) {
		if (lookahead_cmp(&deep[c], &best) != 0) {
			deep[c] = full[c] = LOOKAHEAD_WORST;
			continue;
		}
		deep[c].length = lifter_score(L, id, s->s, vec3(s->e.x, s->e.y, cz[c])).length;
		full[c] = lifter_deep(L, id, s->s, vec3(s->e.x, s->e.y, cz[c]), LOOKAHEAD, &now, true);
		now = *lookahead_min(&now, &full[c]);
	}
	s->e.z = pick_depth(cz, cd, L->work > 0 ? full : deep, m, pick, rng);
}

/*
 * 4.1 for one branch (not a trunk): its start on its parent, which (an earlier generation)
 * has its depth; its end's depth the sparsest (or a random) candidate among those with the
 * best look-ahead score.
 */
static void lifter_place(struct lifter *L, int id, enum lift_pick pick, struct rng *rng)
{
	struct seg *s = &L->seg[id];
	const struct branch *b = &L->t->branches[id];
	double cz[CANDIDATES], cd[CANDIDATES], stop = -INFINITY;
	struct lookahead score[CANDIDATES];
	int m, top = 0;

	s->s.z = anchor_point(&L->t->branches[b->parent], L->root[id]).z;
	m = lifter_candidates(L, id, s->s.z, parent_chord(L, id), cz);
	for (int c = 0; c < m; c++) {
		struct vec3 e = vec3(s->e.x, s->e.y, cz[c]);
		struct vec3 at = L->tu ? turn_point(L->tu->base, L->shift[id], e) : e;

		cd[c] = field_at(L->f, at.x, at.z);
		score[c] = LOOKAHEAD_WORST;
	}
	/* The sparsest rule needs the scores only where they can decide: if the sparsest
	 * candidate leaves its children every rule, only those as sparse as it (the rest
	 * score worst: the choice is the same as with every score). */
	for (int c = 1; c < m; c++)
		top = cd[c] > cd[top] ? c : top;
	score[top] = lifter_score(L, id, s->s, vec3(s->e.x, s->e.y, cz[top]));
	if (pick == LIFT_PICK_SPARSEST && lookahead_cmp(&score[top], &(struct lookahead){ 0 }) == 0)
		stop = cd[top] - 1e-6 * cd[top];
	for (int c = 0; c < m; c++)
		if (c != top && !(cd[c] < stop))
			score[c] = lifter_score(L, id, s->s, vec3(s->e.x, s->e.y, cz[c]));
	s->e.z = pick_depth(cz, cd, score, m, pick, rng);
	lifter_deeper(L, id, cz, cd, m, pick, rng);
}

/* Generation g's branches in L->order, in a seeded random order (Fisher-Yates); returns how
 * many. */
static size_t lifter_generation(struct lifter *L, int g, struct rng *rng)
{
	const struct tree *t = L->t;
	size_t n = 0;

	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].generation == g)
			L->order[n++] = (int)i;
	for (size_t i = n; i > 1; i--) {
		size_t j = (size_t)(rng_next(rng) % i);
		int tmp = L->order[i - 1];

		L->order[i - 1] = L->order[j];
		L->order[j] = tmp;
	}
	return n;
}

/*
 * Branch id once its ends have their depths: its points get theirs (4.3) and f holds it,
 * where the merge will put it in the second lift (whose trunk the merge leaves out).
 */
static void lifter_settle(struct lifter *L, int id)
{
	struct branch *b = &L->t->branches[id];
	const struct seg *s = &L->seg[id];
	const struct turn *tu = L->tu;

	branch_depth(b, s, L->depth + L->at[id], L->frac + L->at[id]);
	if (!tu)
		field_add(L->f, s->s, s->e);
	else if (b->parent >= 0)
		field_add(L->f, turn_point(tu->base, L->shift[id], s->s),
			  turn_point(tu->base, L->shift[id], s->e));
}

/* Every child branch and leaf back on its lifted parent, where it hung on the drawing. */
static void lifter_reattach(struct lifter *L)
{
	struct tree *t = L->t;

	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent >= 0)
			t->branches[i].parent_t =
				anchor_param(&t->branches[t->branches[i].parent], L->root[i]);
	for (size_t i = 0; i < t->nleaves; i++)
		t->leaves[i].branch_t = anchor_param(&t->branches[t->leaves[i].branch], L->leaf[i]);
	tree_leaves_follow(t, -1);
}

/*
 * 4.1 and 4.3, generation by generation: each branch's start is the point of its parent's
 * final polyline it hangs on (so the constraints hold for the branch as it ends up), its
 * end's depth chosen by lifter_place; then its points get their depth at once, before its
 * children are placed.
 *
 * Without a turn (the first tree), f is set up here and left holding the tree's branches.
 * With one (the second tree of 4.2), f is the first tree's, and this lift goes on from it
 * as if its branches were the first ones placed: the hull test and f see each branch where
 * the merge will put it (struct turn). Its trunk, which the merge leaves out, is not added.
 */
static int lift_once(struct tree *t, struct rng *rng, enum lift_pick pick, struct field *f,
		     const struct turn *tu)
{
	struct lifter L;
	int ret = lifter_init(&L, t, tu, f);

	if (ret < 0)
		return ret;
	lifter_field(&L);
	lifter_sketch(&L);
	for (int g = 0; g <= L.maxgen; g++) {
		size_t n;

		/* the rules need the trunk placed */
		if (g == 1)
			lifter_prepare(&L);
		n = lifter_generation(&L, g, rng);
		for (size_t k = 0; k < n; k++) {
			int id = L.order[k];

			/* a trunk's ends stay in the sketch plane */
			if (t->branches[id].parent >= 0)
				lifter_place(&L, id, pick, rng);
			lifter_settle(&L, id);
		}
	}
	lifter_reattach(&L);
	lifter_finish(&L);
	return 0;
}

static int copy_tree(struct tree *dst, const struct tree *src)
{
	tree_init(dst);
	for (size_t i = 0; i < src->nbranches; i++) {
		const struct branch *b = &src->branches[i];

		if (tree_add_branch(dst, b->parent, b->parent_t, b->origin, b->points, b->radii,
				    b->npoints) < 0)
			return -ENOMEM;
	}
	for (size_t i = 0; i < src->nleaves; i++) {
		const struct leaf *l = &src->leaves[i];
		int id = tree_add_leaf(dst, l->branch, l->origin, l->points, l->npoints);

		if (id < 0)
			return -ENOMEM;
		dst->leaves[id].branch_t = l->branch_t;
		dst->leaves[id].kind = l->kind;
		if (l->local && tree_leaf_attach(dst, (size_t)id) < 0)
			return -ENOMEM;
	}
	return 0;
}

/* 4.2: the second tree turned 90 degrees about the trunk's base, merged without trunks. */
static int merge_turned(struct tree *a, const struct tree *b)
{
	struct vec3 base = a->branches[0].points[0];
	int *map = malloc((b->nbranches + 1) * sizeof(*map));
	struct vec3 *shifts = malloc((b->nbranches + 1) * sizeof(*shifts));
	size_t first = a->nbranches;

	if (!map || !shifts) {
		free(map);
		free(shifts);
		return -ENOMEM;
	}
	for (size_t i = 0; i < b->nbranches; i++) {
		const struct branch *br = &b->branches[i];
		struct vec3 *p, shift = vec3(0, 0, 0);
		int parent, id;

		if (br->parent < 0) {
			map[i] = (int)i; /* A and B are copies of one sketch: trunks map onto A's */
			shifts[i] = vec3(0, 0, 0);
			continue;
		}
		p = malloc(br->npoints * sizeof(*p));
		if (!p) {
			free(map);
			free(shifts);
			return -ENOMEM;
		}
		for (size_t k = 0; k < br->npoints; k++) {
			struct vec3 d = vec3_sub(br->points[k], base);

			p[k] = vec3(base.x + d.z, br->points[k].y, base.z - d.x);
		}
		parent = map[br->parent];
		/* first-generation branches hang on A's trunk, which is not turned; everything
		 * on them moves with them */
		if (b->branches[br->parent].parent < 0)
			shift = vec3_sub(tree_frame_at(&a->branches[parent], br->parent_t).origin, p[0]);
		else
			shift = shifts[br->parent];
		shifts[i] = shift;
		for (size_t k = 0; k < br->npoints; k++)
			p[k] = vec3_add(p[k], shift);
		id = tree_add_branch(a, parent, br->parent_t, ORIGIN_MERGE, p, br->radii, br->npoints);
		free(p);
		if (id < 0) {
			free(map);
			free(shifts);
			return -ENOMEM;
		}
		map[i] = id;
		if (parent >= (int)first) {
			/* on a turned branch: the same point, whatever the new rounding */
			struct anchor at;

			tree_locate(&b->branches[br->parent], br->parent_t, &at.segment, &at.seg_t);
			a->branches[id].parent_t = anchor_param(&a->branches[parent], at);
		}
	}
	free(shifts);
	for (size_t i = 0; i < b->nleaves; i++) {
		const struct leaf *l = &b->leaves[i];
		struct anchor at;
		int id;

		if (map[l->branch] < (int)first)
			continue; /* leaves on the trunk are not copied with it */
		id = tree_add_leaf(a, map[l->branch], ORIGIN_MERGE, l->points, l->npoints);
		if (id < 0) {
			free(map);
			return -ENOMEM;
		}
		/* the same segment (and frame) of the turned branch as of B's */
		tree_locate(&b->branches[l->branch], l->branch_t, &at.segment, &at.seg_t);
		a->leaves[id].branch_t = anchor_param(&a->branches[map[l->branch]], at);
		a->leaves[id].local = NULL;
		a->leaves[id].kind = l->kind;
		if (l->local) {
			a->leaves[id].local = malloc(l->npoints * sizeof(*l->local));
			if (!a->leaves[id].local) {
				free(map);
				return -ENOMEM;
			}
			memcpy(a->leaves[id].local, l->local, l->npoints * sizeof(*l->local));
		}
	}
	free(map);
	tree_leaves_follow(a, -1);
	return 0;
}

int lift_tree(struct tree *t, struct rng *rng, bool merge)
{
	return lift_tree_with(t, rng, merge, LIFT_PICK_SPARSEST);
}

int lift_tree_with(struct tree *t, struct rng *rng, bool merge, enum lift_pick pick)
{
	struct tree a, b;
	struct rng ra, rb;
	struct field *f;
	int ret;

	if (t->nbranches == 0 || t->lifted)
		return 0;
	f = malloc(sizeof(*f));
	if (!f)
		return -ENOMEM;
	rng_seed(&ra, rng_next(rng));
	rng_seed(&rb, rng_next(rng));
	ret = copy_tree(&a, t);
	if (ret == 0)
		ret = lift_once(&a, &ra, pick, f, NULL);
	tree_init(&b);
	if (ret == 0 && merge) {
		/* 4.1's "all branches placed so far" for the second tree starts with the first
		 * tree's: its branches go where both trees are sparsest, not onto the first
		 * tree's once turned */
		struct turn tu = { .base = t->branches[0].points[0] };

		ret = copy_tree(&b, t);
		if (ret == 0)
			ret = lift_once(&b, &rb, pick, f, &tu);
		if (ret == 0)
			ret = merge_turned(&a, &b);
	}
	free(f);
	tree_finish(&b);
	if (ret < 0) {
		tree_finish(&a);
		return ret;
	}
	/* keep what sketching remembers */
	a.last_sketched = -1;
	a.lifted = true;
	a.sides = t->sides;
	a.season = t->season;
	a.leaf_kind = t->leaf_kind;
	a.has_profile = t->has_profile;
	memcpy(a.profile, t->profile, sizeof(a.profile));
	tree_finish(t);
	*t = a;
	return 0;
}
