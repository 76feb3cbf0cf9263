/* SPDX-License-Identifier: MIT */
#include "lift.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Depth candidates tried for each branch end. */
#define CANDIDATES 48

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
		w2 = r * r - (x - xc) * (x - xc);
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

static double angle_between(struct vec3 a, struct vec3 b)
{
	double c = vec3_dot(a, b) / (vec3_len(a) * vec3_len(b) + 1e-300);

	return acos(c < -1 ? -1 : c > 1 ? 1 : c);
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
 * Among n admissible depths z[] with field values d[] (the largest is best): the
 * sparsest, a tie (the field is symmetric in z about a trunk, and constant within a
 * cell) broken at random; or with LIFT_PICK_RANDOM, any of them.
 */
static double pick_depth(const double *z, const double *d, int n, double best,
			 enum lift_pick pick, struct rng *rng)
{
	int idx[CANDIDATES], m = 0;

	for (int i = 0; i < n; i++)
		if (pick == LIFT_PICK_RANDOM || d[i] >= best - 1e-6 * best)
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
 * 4.3 on top of 4.1: branch b's points go from its start's depth to its end's (by arc
 * length), plus the curvature depth. Uses depth[] (npoints) as scratch.
 */
static void branch_depth(struct branch *b, const struct seg *s, double *depth)
{
	double len = tree_branch_length(b), walked = 0;

	curvature_depth(b, depth);
	for (size_t k = 0; k < b->npoints; k++) {
		double f = len > 0 ? walked / len : 0;

		if (k + 1 < b->npoints)
			walked += hypot(b->points[k + 1].x - b->points[k].x,
					b->points[k + 1].y - b->points[k].y);
		b->points[k].z = s->s.z + (s->e.z - s->s.z) * f + depth[k];
	}
}

/*
 * 4.1 and 4.3, generation by generation: each branch's start is the point of its parent's
 * final polyline it hangs on (so the constraints hold for the branch as it ends up), its
 * end's depth the sparsest (or, LIFT_PICK_RANDOM, a random) admissible one; then its
 * points get their depth at once, before its children are placed.
 *
 * Without a turn (the first tree), f is set up here and left holding the tree's branches.
 * With one (the second tree of 4.2), f is the first tree's, and this lift goes on from it
 * as if its branches were the first ones placed: the hull test and f see each branch where
 * the merge will put it (struct turn). Its trunk, which the merge leaves out, is not added.
 */
static int lift_once(struct tree *t, struct rng *rng, enum lift_pick pick, struct field *f,
		     const struct turn *tu)
{
	struct hull h = { 0 };
	struct seg *seg;
	struct anchor *root, *leaf;
	struct vec3 *shift;
	double *depth;
	int *order;
	size_t maxn = 1;
	int maxgen = 0, ret;
	double xmin = INFINITY, xmax = -INFINITY, rmax = 0;

	ret = hull_build(&h, t);
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < t->nbranches; i++)
		maxn = t->branches[i].npoints > maxn ? t->branches[i].npoints : maxn;
	seg = malloc((t->nbranches + 1) * sizeof(*seg));
	root = malloc((t->nbranches + 1) * sizeof(*root));
	leaf = malloc((t->nleaves + 1) * sizeof(*leaf));
	depth = malloc(maxn * sizeof(*depth));
	order = malloc((t->nbranches + 1) * sizeof(*order));
	shift = calloc(t->nbranches + 1, sizeof(*shift));
	if (!seg || !root || !leaf || !depth || !order || !shift) {
		ret = -ENOMEM;
		goto out;
	}
	for (size_t i = 0; i < h.n; i++) {
		xmin = fmin(xmin, h.p[i].x);
		xmax = fmax(xmax, h.p[i].x);
	}
	/* the field covers the hull, and so the turned tree too (the trunk's base is in it) */
	rmax = LIFT_HULL_SCALE * 0.5 * (xmax - xmin) + 1e-3;
	if (!tu) {
		f->cell = fmax(xmax - xmin + 2 * rmax, 2 * rmax) / LIFT_FIELD_N;
		f->x0 = 0.5 * (xmin + xmax) - 0.5 * LIFT_FIELD_N * f->cell;
		f->z0 = -0.5 * LIFT_FIELD_N * f->cell;
		for (int i = 0; i < LIFT_FIELD_N * LIFT_FIELD_N; i++)
			f->d[i] = INFINITY;
		for (int i = 0; i < TILES * TILES; i++)
			f->tile_max[i] = INFINITY;
	}

	/* The largest drawn angle between each parent and its children. */
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		seg[i].s = b->points[0];
		seg[i].e = b->points[b->npoints - 1];
		seg[i].max_child_angle = 0;
		maxgen = b->generation > maxgen ? b->generation : maxgen;
	}
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		if (b->parent >= 0) {
			double a = angle_between(vec3_sub(seg[b->parent].e, seg[b->parent].s),
						 vec3_sub(seg[i].e, seg[i].s));

			seg[b->parent].max_child_angle = fmax(seg[b->parent].max_child_angle, a);
		}
	}
	/* Where everything hangs, on the drawing as it is. */
	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent >= 0)
			tree_locate(&t->branches[t->branches[i].parent], t->branches[i].parent_t,
				    &root[i].segment, &root[i].seg_t);
	for (size_t i = 0; i < t->nleaves; i++)
		tree_locate(&t->branches[t->leaves[i].branch], t->leaves[i].branch_t, &leaf[i].segment,
			    &leaf[i].seg_t);

	for (int g = 0; g <= maxgen; g++) {
		size_t n = 0;

		for (size_t i = 0; i < t->nbranches; i++)
			if (t->branches[i].generation == g)
				order[n++] = (int)i;
		/* a seeded random order within the generation (Fisher-Yates) */
		for (size_t i = n; i > 1; i--) {
			size_t j = (size_t)(rng_next(rng) % i);
			int tmp = order[i - 1];

			order[i - 1] = order[j];
			order[j] = tmp;
		}
		for (size_t k = 0; k < n; k++) {
			int id = order[k];
			struct branch *b = &t->branches[id];
			struct seg *s = &seg[id];
			double best = -1, best_angle = INFINITY, best_angle_z = 0;
			double cz[CANDIDATES], cd[CANDIDATES];
			int nadmissible = 0;

			/* a trunk's ends stay in the sketch plane */
			if (b->parent >= 0) {
				const struct seg *p = &seg[b->parent];
				struct vec3 pd = vec3_sub(p->e, p->s);
				double plen = vec3_len(pd), dxy, lo, hi, reach, hlo, hhi;
				double amax = fmin(LIFT_MAX_ANGLE_RATIO * p->max_child_angle, VEC_PI);

				/* on the parent, which (an earlier generation) has its depth */
				s->s.z = anchor_point(&t->branches[b->parent], root[id]).z;
				/* the merge moves a turned first generation onto the first tree's
				 * trunk (the same as this one), and the rest with it */
				if (tu && t->branches[b->parent].parent < 0) {
					struct vec3 on = anchor_point(&t->branches[b->parent], root[id]);

					shift[id] = vec3_sub(on, turn_point(tu->base, vec3(0, 0, 0), s->s));
				} else if (tu) {
					shift[id] = shift[b->parent];
				}
				dxy = hypot(s->e.x - s->s.x, s->e.y - s->s.y);
				/* 45..135 degrees from the view direction: |dz| <= |dxy| */
				lo = s->s.z - dxy;
				hi = s->s.z + dxy;
				/* at most 1.2 x the parent's length */
				reach = LIFT_MAX_LENGTH_RATIO * plen;
				if (reach > dxy) {
					double dz = sqrt(reach * reach - dxy * dxy);

					lo = fmax(lo, s->s.z - dz);
					hi = fmin(hi, s->s.z + dz);
				} else {
					lo = hi = s->s.z;
				}
				/* inside the hull; if it leaves no depth within the length and view
				 * rules, the hull's depth nearest the start; if it has none (a turned
				 * end can be farther in front of or behind the trunk than the hull is
				 * deep), the depth within those rules nearest the hull */
				if (hull_range(&h, tu, shift[id], s->e.x, s->e.y, &hlo, &hhi)) {
					lo = fmax(lo, hlo);
					hi = fmin(hi, hhi);
					if (lo > hi)
						lo = hi = fmin(fmax(s->s.z, hlo), hhi);
				} else {
					lo = hi = fmin(fmax(hlo, lo), hi);
				}
				for (int c = 0; c < CANDIDATES; c++) {
					double z = lo + (hi - lo) * c / (CANDIDATES - 1);
					struct vec3 e = vec3(s->e.x, s->e.y, z);
					double a = angle_between(pd, vec3_sub(e, s->s));

					if (a <= amax + 1e-9) {
						struct vec3 at = tu ? turn_point(tu->base, shift[id], e) : e;

						cz[nadmissible] = z;
						cd[nadmissible] = field_at(f, at.x, at.z);
						best = fmax(best, cd[nadmissible++]);
					} else if (a < best_angle) {
						best_angle = a;
						best_angle_z = z;
					}
				}
				s->e.z = nadmissible ? pick_depth(cz, cd, nadmissible, best, pick, rng) :
						       best_angle_z;
			}
			branch_depth(b, s, depth);
			if (!tu)
				field_add(f, s->s, s->e);
			else if (b->parent >= 0)
				field_add(f, turn_point(tu->base, shift[id], s->s),
					  turn_point(tu->base, shift[id], s->e));
		}
	}
	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent >= 0)
			t->branches[i].parent_t =
				anchor_param(&t->branches[t->branches[i].parent], root[i]);
	for (size_t i = 0; i < t->nleaves; i++)
		t->leaves[i].branch_t = anchor_param(&t->branches[t->leaves[i].branch], leaf[i]);
	tree_leaves_follow(t, -1);
	ret = 0;
out:
	free(h.p);
	free(shift);
	free(seg);
	free(root);
	free(leaf);
	free(depth);
	free(order);
	return ret;
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
