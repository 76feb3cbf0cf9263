/* SPDX-License-Identifier: MIT */
/*
 * The origami leaf's geometry (issue 15, docs/origami-leaves.md), on hand-made designs
 * like the presets and on seeded random ones: flat-foldability at every interior vertex
 * (Kawasaki within 0.01 degree, Maekawa, an even number of creases), convex faces, a flat
 * folded state whose faces are isometric to their flat selves, the margin on each part's
 * cut, left-right symmetry, a rigid and continuous opening that ends flat; and the designs
 * that cannot fold refused.
 */
#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "ori.h"
#include "rng.h"
#include "test.h"

#define DEG (180.0 / 3.14159265358979323846)

static struct ori_design fan(void)
{
	struct ori_design d;

	memset(&d, 0, sizeof(d));
	strcpy(d.name, "test");
	d.fold = ORI_FOLD_FAN;
	d.size = 0.08;
	d.rest = 0.9;
	d.middle[0] = d.middle[1] = 25;
	d.nsides = 2;
	d.sides[0] = (struct ori_side){ .angle = 55, .fork_at = 0.5, .fork_a = 30, .fork_b = 30 };
	d.sides[1] = (struct ori_side){ .angle = 45, .fork_at = 0.5, .fork_a = 30, .fork_b = 30 };
	d.junction = 0.38;
	d.theta0 = 200;
	d.width = 0.32;
	d.power = 0.8;
	return d;
}

static struct ori_design hop(void)
{
	struct ori_design d = fan();

	d.size = 0.09;
	d.middle[0] = d.middle[1] = 35;
	d.nnodes = 2;
	d.nodes[0] = (struct ori_node){ .at = 0.3, .phi = { 45, 45 }, .psi = { 32, 32 } };
	d.nodes[1] = (struct ori_node){ .at = 0.55, .phi = { 40, 40 }, .psi = { 30, 30 } };
	d.sides[0] = (struct ori_side){ .angle = 60, .forks = 2, .fork_at = 0.45, .fork_a = 28,
					.fork_b = 28 };
	d.sides[1] = (struct ori_side){ .angle = 55, .forks = 1, .fork_at = 0.5, .fork_a = 30,
					.fork_b = 30 };
	d.junction = 0.5;
	d.theta0 = 360;
	return d;
}

static struct ori_design half(void)
{
	struct ori_design d = fan();

	d.fold = ORI_FOLD_HALF;
	d.size = 0.06;
	d.middle[0] = d.middle[1] = 90;
	d.nsides = 0;
	return d;
}

static bool on_margin(const struct ori_leaf *l, int v)
{
	for (size_t i = 0; i < l->nmargin; i++)
		if (l->margin[i] == v)
			return true;
	return false;
}

static double angle_of(const struct ori_leaf *l, int from, int to)
{
	return atan2(l->flat[to][1] - l->flat[from][1], l->flat[to][0] - l->flat[from][0]);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* Kawasaki (alternate sector angles sum to 180 degrees), Maekawa (|M - V| = 2) and an even
 * crease count at every vertex inside the leaf. Returns how many it checked. */
static size_t check_vertices(const struct ori_leaf *l)
{
	size_t checked = 0;

	for (size_t v = 0; v < l->nvertices; v++) {
		double a[16], sum[2] = { 0, 0 };
		int n = 0, m = 0, val = 0;

		if (on_margin(l, (int)v))
			continue;
		for (size_t c = 0; c < l->ncreases; c++) {
			const struct ori_crease *k = &l->creases[c];

			if (k->a != (int)v && k->b != (int)v)
				continue;
			CHECK(n < 16);
			a[n++] = angle_of(l, (int)v, k->a == (int)v ? k->b : k->a);
			m += k->type == ORI_MOUNTAIN;
			val += k->type == ORI_VALLEY;
		}
		CHECK(n % 2 == 0);
		CHECK(abs(m - val) == 2);
		qsort(a, (size_t)n, sizeof(*a), cmp_double);
		for (int i = 0; i < n; i++) {
			double s = (i + 1 < n ? a[i + 1] : a[0] + 2 * 3.14159265358979323846) - a[i];

			CHECK(s > 0);
			sum[i % 2] += s;
		}
		CHECK_NEAR(sum[0] * DEG, 180.0, 0.01);
		CHECK_NEAR(sum[1] * DEG, 180.0, 0.01);
		checked++;
	}
	return checked;
}

static void check_faces(const struct ori_leaf *l)
{
	for (size_t f = 0; f < l->nfaces; f++) {
		const int *idx = l->face_index + l->face_start[f];
		size_t n = l->face_len[f];
		double area = 0;

		CHECK(n >= 3);
		for (size_t k = 0; k < n; k++) {
			const double *p = l->flat[idx[k]], *q = l->flat[idx[(k + 1) % n]];
			const double *r = l->flat[idx[(k + 2) % n]];
			double turn = (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]);

			CHECK(turn > -1e-12); /* convex, counter-clockwise */
			area += p[0] * q[1] - p[1] * q[0];
		}
		CHECK(area > 0);
		/* the folded face is the flat one moved: every distance kept, flat (2D) */
		for (size_t i = 0; i < n; i++)
			for (size_t j = i + 1; j < n; j++) {
				const double *a = l->flat[idx[i]], *b = l->flat[idx[j]];
				const double *fa = l->folded[idx[i]], *fb = l->folded[idx[j]];

				CHECK_NEAR(hypot(fa[0] - fb[0], fa[1] - fb[1]),
					   hypot(a[0] - b[0], a[1] - b[1]), 1e-9);
			}
	}
}

/* Three folded points on one line. */
static bool collinear(const double *a, const double *b, const double *c, double size)
{
	double cr = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);

	return fabs(cr) <= 1e-9 * size * size;
}

/* The margin in the folded state lies on each part's cut: a line (fan) or the curve
 * x = width size sin(pi s)^power, y = s size (half). */
static void check_cut(const struct ori_leaf *l, const struct ori_design *d)
{
	if (d->fold == ORI_FOLD_HALF) {
		for (size_t i = 0; i < l->nmargin; i++) {
			const double *p = l->folded[l->margin[i]];
			double s = p[1] / d->size;

			CHECK(s > -1e-12 && s < 1 + 1e-12);
			if (s < 1e-6 || s > 1 - 1e-6) { /* O and the tip: the curve is steep there */
				CHECK(fabs(p[0]) < 1e-9);
				continue;
			}
			CHECK_NEAR(p[0], d->width * d->size * pow(sin(3.14159265358979323846 * s),
								 d->power), 1e-9);
		}
		return;
	}
	/* a fan's part: every margin point but O on one line */
	for (int part = 0; part <= (int)(2 * d->nsides); part++) {
		int pts[64], n = 0;

		for (size_t i = 0; i < l->nmargin; i++) {
			int v = l->margin[i];

			if (v == 0)
				continue;
			/* the part's own, ending with the junction it shares with the next part,
			 * and the junction before (its previous neighbour's) */
			if (l->vertex_part[v] == part ||
			    (i + 1 < l->nmargin && l->vertex_part[l->margin[i + 1]] == part))
				pts[n++] = v;
			CHECK(n < 64);
		}
		CHECK(n >= 2);
		for (int k = 2; k < n; k++)
			CHECK(collinear(l->folded[pts[0]], l->folded[pts[1]], l->folded[pts[k]],
					d->size));
	}
}

/* Mirror images: every vertex's (-x, y) is a vertex, creases and their types too. */
static int mirror_of(const struct ori_leaf *l, int v)
{
	for (size_t w = 0; w < l->nvertices; w++)
		if (fabs(l->flat[w][0] + l->flat[v][0]) < 1e-9 &&
		    fabs(l->flat[w][1] - l->flat[v][1]) < 1e-9)
			return (int)w;
	return -1;
}

static void check_mirror(const struct ori_leaf *l)
{
	for (size_t c = 0; c < l->ncreases; c++) {
		const struct ori_crease *k = &l->creases[c];
		int a = mirror_of(l, k->a), b = mirror_of(l, k->b);
		bool found = false;

		CHECK(a >= 0 && b >= 0);
		for (size_t e = 0; e < l->ncreases; e++) {
			const struct ori_crease *q = &l->creases[e];

			found = found || (q->type == k->type && ((q->a == a && q->b == b) ||
								  (q->a == b && q->b == a)));
		}
		CHECK(found);
	}
	for (size_t i = 0; i < l->nmargin; i++)
		CHECK(on_margin(l, mirror_of(l, l->margin[i])));
}

static double dist3(const double *a, const double *b)
{
	return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
		    (a[2] - b[2]) * (a[2] - b[2]));
}

/* Rigid: every face's corners keep their flat distances (so the face keeps its shape and
 * stays planar); symmetric about x = 0; O fixed. */
static void check_rigid(const struct ori_leaf *l, double (*p)[3])
{
	for (size_t f = 0; f < l->nfaces; f++) {
		const int *idx = l->face_index + l->face_start[f];

		for (size_t i = 0; i < l->face_len[f]; i++)
			for (size_t j = i + 1; j < l->face_len[f]; j++) {
				const double *a = l->flat[idx[i]], *b = l->flat[idx[j]];

				CHECK_NEAR(dist3(p[idx[i]], p[idx[j]]), hypot(a[0] - b[0], a[1] - b[1]),
					   1e-6);
			}
	}
	for (size_t v = 0; v < l->nvertices; v++) {
		int w = mirror_of(l, (int)v);

		CHECK(w >= 0);
		CHECK_NEAR(p[w][0], -p[v][0], 1e-9);
		CHECK_NEAR(p[w][1], p[v][1], 1e-9);
		CHECK_NEAR(p[w][2], p[v][2], 1e-9);
	}
	CHECK(fabs(p[0][0]) + fabs(p[0][1]) + fabs(p[0][2]) < 1e-12);
}

static size_t midrib_nodes(const struct ori_leaf *l)
{
	size_t n = 0;

	for (size_t k = 0; k < l->nnodes; k++)
		n += l->nodes[k].midrib;
	return n;
}

static void check_opening(const struct ori_leaf *l)
{
	double (*p)[3] = calloc(l->nvertices, sizeof(*p)), (*q)[3] = calloc(l->nvertices, sizeof(*q));
	double last = 0;

	CHECK(p && q);
	for (int i = 1; i <= 3; i++) {
		CHECK_INT(ori_open(l, 0.25 * i, p), 0);
		check_rigid(l, p);
	}
	/* continuous: a small step moves nothing far (a jump to another branch of the
	 * nodes' closure would) */
	CHECK_INT(ori_open(l, 0, q), 0);
	for (int i = 1; i <= 200; i++) {
		double step = 0;

		CHECK_INT(ori_open(l, i / 200.0, p), 0);
		for (size_t v = 0; v < l->nvertices; v++)
			step = fmax(step, dist3(p[v], q[v]));
		CHECK(step < 0.05 * l->size);
		last = step;
		memcpy(q, p, l->nvertices * sizeof(*p));
	}
	(void)last;
	/* with nodes, the folded midrib is a polyline (bent at its nodes) that straightens as
	 * the leaf opens: its nodes' distance from the line O-tip shrinks to 0 (the side
	 * parts' veins' nodes bend their veins alike, off the plane of symmetry) */
	if (midrib_nodes(l)) {
		double prev = INFINITY;

		for (int i = 1; i <= 4; i++) {
			double bend = 0, *o, *tip;

			CHECK_INT(ori_open(l, 0.2 * i, p), 0);
			o = p[0];
			tip = p[l->tip];
			for (size_t k = 0; k < l->nnodes; k++) {
				const double *n = p[l->creases[l->nodes[k].in].b];

				if (!l->nodes[k].midrib)
					continue;
				double u[3] = { tip[0] - o[0], tip[1] - o[1], tip[2] - o[2] };
				double w[3] = { n[0] - o[0], n[1] - o[1], n[2] - o[2] };
				double c[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
						u[0] * w[1] - u[1] * w[0] };

				CHECK_NEAR(n[0], 0, 1e-9); /* in the plane of symmetry */
				bend = fmax(bend, sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) /
							  sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
			}
			CHECK(bend > 1e-6 * l->size && bend < prev);
			prev = bend;
		}
	}
	/* ends flat, as the pattern lies */
	CHECK_INT(ori_open(l, 1, p), 0);
	for (size_t v = 0; v < l->nvertices; v++) {
		CHECK_NEAR(p[v][0], l->flat[v][0], 1e-9);
		CHECK_NEAR(p[v][1], l->flat[v][1], 1e-9);
		CHECK_NEAR(p[v][2], 0, 1e-9);
	}
	/* at rest: curled, the mirror of the opening at `rest` */
	CHECK_INT(ori_open(l, l->rest, q), 0);
	CHECK_INT(ori_rest(l, p), 0);
	for (size_t v = 0; v < l->nvertices; v++) {
		CHECK_NEAR(p[v][2], -q[v][2], 1e-12);
		CHECK_NEAR(p[v][0], q[v][0], 1e-12);
	}
	free(p);
	free(q);
}

/* The unfolding's keyframes: rigid, from the bud, opening to flat, then curling towards
 * the rest (the mirror of the leaf opened back to `rest`), never the opening reversed. */
static void check_unfold(const struct ori_leaf *l)
{
	size_t n = ORI_UNFOLD_FRAMES, nv = l->nvertices;
	double (*f)[3] = calloc(n * nv, sizeof(*f)), (*p)[3] = calloc(nv, sizeof(*p));
	double zmax_prev = INFINITY;

	CHECK(f && p);
	CHECK_INT(ori_unfold_frames(l, n, f), 0);
	CHECK_INT(ori_open(l, 0, p), 0);
	CHECK(memcmp(p, f, nv * sizeof(*p)) == 0);
	for (size_t j = 0; j < n; j++) {
		double s = (double)j / (double)n, zmax = 0, zsum = 0;

		check_rigid(l, f + j * nv);
		for (size_t v = 0; v < nv; v++) {
			zmax = fmax(zmax, fabs(f[j * nv + v][2]));
			zsum += f[j * nv + v][2];
		}
		if (s <= ORI_UNFOLD_OPEN) { /* opening: flatter every frame */
			CHECK(zmax <= zmax_prev + 1e-12);
			CHECK_INT(ori_open(l, s / ORI_UNFOLD_OPEN, p), 0);
		} else { /* curling: a partly open leaf mirrored, nearer the rest each frame */
			double t = 1 - (s - ORI_UNFOLD_OPEN) / (1 - ORI_UNFOLD_OPEN) * (1 - l->rest);

			CHECK(t >= l->rest && t < 1);
			CHECK_INT(ori_open(l, t, p), 0);
			for (size_t v = 0; v < nv; v++)
				p[v][2] = -p[v][2];
		}
		for (size_t v = 0; v < nv; v++)
			CHECK(dist3(p[v], f[j * nv + v]) < 1e-12);
		(void)zsum;
		zmax_prev = zmax;
	}
	free(f);
	free(p);
}

/* The opening as the kiosk's keyframes take it, in one pass (ori_open_frames): rigid at
 * every frame, continuous (no frame moves a vertex far from the one before), flat at 1. A
 * cheaper sweep than check_opening's, for many designs. */
static void check_frames(const struct ori_leaf *l)
{
	size_t n = 101, nv = l->nvertices;
	double (*f)[3] = calloc(n * nv, sizeof(*f));

	CHECK(f != NULL);
	CHECK_INT(ori_open_frames(l, n, f), 0);
	for (size_t k = 0; k < n; k++) {
		check_rigid(l, f + k * nv);
		for (size_t v = 0; k > 0 && v < nv; v++)
			CHECK(dist3(f[k * nv + v], f[(k - 1) * nv + v]) < 0.05 * l->size);
	}
	for (size_t v = 0; v < nv; v++) {
		CHECK_NEAR(f[(n - 1) * nv + v][0], l->flat[v][0], 1e-9);
		CHECK_NEAR(f[(n - 1) * nv + v][1], l->flat[v][1], 1e-9);
		CHECK_NEAR(f[(n - 1) * nv + v][2], 0, 1e-9);
	}
	free(f);
}

static size_t check_design_as(const struct ori_design *d, bool sweep);

static size_t check_design(const struct ori_design *d)
{
	return check_design_as(d, true);
}

/* sweep: check_opening's 200 openings each solved from the bud; else check_frames. */
static size_t check_design_as(const struct ori_design *d, bool sweep)
{
	struct ori_leaf l;
	struct error err;
	size_t inner;
	int ret = ori_build(d, "test", &l, &err);

	if (ret != 0)
		fprintf(stderr, "refused: %s\n", err.msg);
	CHECK_INT(ret, 0);
	CHECK(l.nfaces >= 2 && l.nmargin >= 3 && l.tip > 0);
	CHECK_NEAR(l.flat[l.tip][1], d->size, 1e-12);
	inner = check_vertices(&l);
	check_faces(&l);
	check_cut(&l, d);
	check_mirror(&l);
	if (sweep)
		check_opening(&l);
	else
		check_frames(&l);
	check_unfold(&l);
	ori_leaf_finish(&l);
	return inner;
}

static void check_refused(const struct ori_design *d, const char *text)
{
	struct ori_leaf l;
	struct error err = { { 0 } };

	CHECK_INT(ori_build(d, "bad.yaml", &l, &err), -EINVAL);
	if (!strstr(err.msg, text) || strncmp(err.msg, "bad.yaml:", 9) != 0) {
		fprintf(stderr, "got \"%s\", wanted \"%s\"\n", err.msg, text);
		CHECK(0);
	}
	CHECK(l.nvertices == 0 && l.flat == NULL);
}

static void test_refused(void)
{
	struct ori_design d = fan();

	d.middle[1] = 28;
	d.line_middle = 7;
	check_refused(&d, "the middle part is not symmetric");
	d = fan();
	d.sides[0].angle = 100;
	d.sides[1].angle = 80; /* 50 + 2 * 180 */
	check_refused(&d, "360 or more cannot fold flat");
	d = hop();
	d.nodes[1].phi[1] = 45;
	check_refused(&d, "is not symmetric");
	/* a vein's children sent wide over the part's boundaries: creases cross */
	d = fan();
	d.sides[0].forks = 1;
	d.sides[0].fork_at = 0.2;
	d.sides[0].fork_a = d.sides[0].fork_b = 60;
	d.sides[0].line = 9;
	check_refused(&d, "bad.yaml:9: sides: part 1: creases cross");
	d = hop();
	d.nodes[0].psi[0] = d.nodes[0].psi[1] = 60;
	check_refused(&d, "psi < phi");
}

/* A random design within the format's ranges; many cannot fold and are refused. */
static struct ori_design random_design(struct rng *r)
{
	struct ori_design d = fan();

	d.size = rng_range(r, 0.02, 0.15);
	d.middle[0] = d.middle[1] = rng_range(r, 10, 60);
	d.nsides = (size_t)(rng_next(r) % 4);
	for (size_t j = 0; j < d.nsides; j++)
		d.sides[j] = (struct ori_side){ .angle = rng_range(r, 20, 70),
						.forks = (int)(rng_next(r) % 3),
						.fork_at = rng_range(r, 0.3, 0.7),
						.fork_a = rng_range(r, 10, 40),
						.fork_b = rng_range(r, 10, 40) };
	d.nnodes = (size_t)(rng_next(r) % 3);
	for (size_t i = 0; i < d.nnodes; i++) {
		double phi = rng_range(r, 30, 70), psi = rng_range(r, 0.3, 0.8) * phi;

		d.nodes[i] = (struct ori_node){ .at = 0.25 + 0.3 * (double)i + rng_range(r, 0, 0.1),
						.phi = { phi, phi }, .psi = { psi, psi } };
	}
	d.junction = rng_range(r, 0.3, 0.6);
	d.theta0 = rng_range(r, 250, 500);
	if (rng_next(r) % 5 == 0) {
		d = half();
		d.width = rng_range(r, 0.1, 0.6);
		d.power = rng_range(r, 0.3, 1.0);
	}
	return d;
}

static void test_random(void)
{
	struct rng r;
	int valid = 0, tried = 0, nodes = 0, forks = 0;

	rng_seed(&r, 15);
	while (valid < 30 && tried < 2000) {
		struct ori_design d = random_design(&r);
		struct ori_leaf l;
		struct error err;
		int ret = ori_build(&d, "random", &l, &err);

		tried++;
		CHECK(ret == 0 || ret == -EINVAL);
		if (ret < 0)
			continue;
		ori_leaf_finish(&l);
		check_design(&d);
		valid++;
		nodes += d.nnodes > 0;
		for (size_t j = 0; j < d.nsides; j++)
			forks += d.sides[j].forks > 0;
	}
	printf("random designs: %d valid of %d tried (%d with midrib nodes, %d forked parts)\n",
	       valid, tried, nodes, forks);
	CHECK(valid >= 30 && nodes >= 5 && forks >= 5);
}

/* A random fan whose side parts' veins have nodes (docs/leaf-format.md, sides[].nodes): a
 * user's own toothed leaf. */
static struct ori_design random_toothed(struct rng *r)
{
	struct ori_design d = random_design(r);

	if (d.fold != ORI_FOLD_FAN)
		d = fan();
	d.nsides = 1 + (size_t)(rng_next(r) % 3);
	for (size_t j = 0; j < d.nsides; j++) {
		struct ori_side *p = &d.sides[j];
		double at = rng_range(r, 0.35, 0.6);

		*p = (struct ori_side){ .angle = rng_range(r, 25, 65), .fork_at = 0.5, .fork_a = 30,
					.fork_b = 30 };
		p->nnodes = (size_t)(rng_next(r) % 3);
		for (size_t i = 0; i < p->nnodes; i++) {
			double phi = rng_range(r, 20, 60), psi = rng_range(r, 0.5, 0.9) * phi;

			p->nodes[i] = (struct ori_node){ .at = at, .phi = { phi, phi },
							 .psi = { psi, psi } };
			at += rng_range(r, 0.1, 0.25);
			if (at >= 0.95)
				p->nnodes = i + 1;
		}
	}
	return d;
}

/* Every check of check_design on a few hundred random toothed designs that build. */
static void test_random_toothed(void)
{
	struct rng r;
	int valid = 0, tried = 0;
	size_t side_nodes = 0, inner = 0;
	int want = test_cases(200);

	rng_seed(&r, 24);
	while (valid < want && tried < 5000) {
		struct ori_design d = random_toothed(&r);
		struct ori_leaf l;
		struct error err;
		int ret = ori_build(&d, "random", &l, &err);
		size_t n = 0;

		tried++;
		CHECK(ret == 0 || ret == -EINVAL);
		if (ret < 0)
			continue;
		for (size_t k = 0; k < l.nnodes; k++)
			n += !l.nodes[k].midrib;
		ori_leaf_finish(&l);
		if (n == 0)
			continue;
		inner += check_design_as(&d, false);
		side_nodes += n;
		valid++;
	}
	printf("random toothed designs: %d valid of %d tried, %zu nodes on side veins, %zu "
	       "vertices inside checked\n", valid, tried, side_nodes, inner);
	CHECK(valid >= want);
}

int main(void)
{
	struct ori_design f = fan(), h = hop(), e = half();

	size_t n;
	const char *const *names = ori_preset_names(&n);

	CHECK(n == 3);
	for (size_t i = 0; i < n; i++) {
		struct ori_design p;
		struct error err;

		struct ori_leaf l;

		CHECK_INT(ori_preset(names[i], &p, &err), 0);
		printf("preset %s: %zu vertices inside\n", names[i], check_design(&p));
		/* the lobes' tips meet the spiral r0 (1 - theta / theta0) (section 2.1): forked
		 * parts by the fitted cut, the midrib through its folded tip */
		CHECK_INT(ori_build(&p, names[i], &l, &err), 0);
		for (size_t k = 0; k < l.nlobes; k++)
			CHECK_NEAR(l.lobes[k].tip, l.lobes[k].target, 1e-6 * p.size);
		ori_leaf_finish(&l);
	}
	CHECK(check_design(&f) == 0); /* a plain fan: no vertex inside */
	CHECK(check_design(&h) >= 4); /* two nodes, forks on the side parts */
	check_design(&e);
	test_refused();
	test_random();
	test_random_toothed();
	printf("ok\n");
	return 0;
}
