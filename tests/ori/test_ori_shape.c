/* SPDX-License-Identifier: MIT */
/*
 * Issue 24, item 5: the maple preset must read as a Japanese maple (momiji) and the hop as a
 * hop, by the measures of ori_outline.h on the opened leaf's outline: at the opening 1 the
 * issue names, at openings near it and at the rest a grown leaf keeps (so on the tree too;
 * test_ori_place measures leaves placed there). The triangles a leaf costs are printed and
 * held to the budget docs/origami-leaves.md gives for a 20,000-leaf tree.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ori.h"
#include "ori_outline.h"
#include "test.h"

/* triangles a leaf, for 20,000 leaves on the board (docs/origami-leaves.md, Cost) */
#define BUDGET_TRIANGLES 80

/* The margin's points at positions pos, in the margin's order (O first). */
static double (*margin_at(const struct ori_leaf *l, const double (*pos)[3]))[3]
{
	double (*out)[3] = calloc(l->nmargin, sizeof(*out));

	CHECK(out != NULL);
	for (size_t i = 0; i < l->nmargin; i++)
		memcpy(out[i], pos[l->margin[i]], sizeof(out[i]));
	return out;
}

static void show(const char *name, const char *when, const struct ori_outline *m)
{
	printf("%s %s: %zu lobes, tips", name, when, m->nlobes);
	for (size_t j = 0; j < m->nlobes; j++)
		printf(" %.3f", m->tip[j]);
	printf(", sinuses");
	for (size_t j = 0; j + 1 < m->nlobes; j++)
		printf(" %.3f", m->sinus[j]);
	printf(", teeth %d right %d left (least %.4f), behind O %.3f %.3f\n", m->teeth[0],
	       m->teeth[1], m->least_tooth, m->behind[0], m->behind[1]);
}

/* The preset at openings 1, 0.98, 0.95, its rest (curled): the measure holds at each. */
static void check_preset(const char *name, bool (*holds)(const struct ori_outline *, double *,
							 char *, size_t))
{
	static const double openings[] = { 1, 0.98, 0.95, -1 /* rest */ };
	struct ori_design d;
	struct ori_leaf l;
	struct error err;
	double (*pos)[3], worst = INFINITY;
	size_t tris;

	CHECK_INT(ori_preset(name, &d, &err), 0);
	CHECK_INT(ori_build(&d, name, &l, &err), 0);
	pos = calloc(l.nvertices, sizeof(*pos));
	CHECK(pos != NULL);
	for (size_t i = 0; i < sizeof(openings) / sizeof(openings[0]); i++) {
		struct ori_outline m;
		double (*pts)[3], margin;
		char why[160] = "", when[32];

		if (openings[i] < 0) {
			CHECK_INT(ori_rest(&l, pos), 0);
			snprintf(when, sizeof(when), "at rest (%g)", l.rest);
		} else {
			CHECK_INT(ori_open(&l, openings[i], pos), 0);
			snprintf(when, sizeof(when), "at %g", openings[i]);
		}
		pts = margin_at(&l, (const double(*)[3])pos);
		CHECK_INT(ori_outline_measure((const double(*)[3])pts, l.nmargin, &m), 0);
		show(name, when, &m);
		if (!holds(&m, &margin, why, sizeof(why))) {
			fprintf(stderr, "%s %s: %s\n", name, when, why);
			CHECK(0);
		}
		worst = fmin(worst, margin);
		free(pts);
	}
	tris = ori_mesh_triangles(&l);
	printf("%s: %zu triangles a leaf, %zu k for 20,000 leaves; least slack %.3f\n", name,
	       tris, tris * 20, worst);
	CHECK(tris <= BUDGET_TRIANGLES);
	free(pos);
	ori_leaf_finish(&l);
}

/* The measure itself, on an outline made by hand: one lobe with two teeth a side, its
 * base 0.15 behind O; then three such lobes side by side. */
static void test_measure(void)
{
	static const double half[6][2] = {
		{ 0.2, -0.15 }, { 0.25, 0.3 }, { 0.15, 0.35 }, { 0.2, 0.6 }, { 0.08, 0.62 }, { 0, 1 },
	};
	double one[12][3] = { { 0, 0, 0 } }, three[34][3] = { { 0, 0, 0 } };
	struct ori_outline m;
	double margin;
	char why[160];
	size_t n = 1;

	for (int k = 0; k < 6; k++) {
		one[n][0] = half[k][0];
		one[n++][1] = half[k][1];
	}
	for (int k = 4; k >= 0; k--) {
		one[n][0] = -half[k][0];
		one[n++][1] = half[k][1];
	}
	CHECK_INT(ori_outline_measure((const double(*)[3])one, n, &m), 0);
	CHECK_INT(m.nlobes, 1);
	CHECK_NEAR(m.length, 1, 1e-12);
	CHECK_INT(m.teeth[0], 2); /* (0.25, 0.3) and (0.2, 0.6); the notch's ends are none */
	CHECK_INT(m.teeth[1], 2);
	CHECK_INT(m.lobe_teeth[0], 4);
	CHECK_NEAR(m.behind[0], 0.15, 1e-12);
	CHECK_NEAR(m.behind[1], 0.15, 1e-12);
	CHECK(!ori_outline_momiji(&m, &margin, why, sizeof(why)));
	CHECK(strstr(why, "1 lobes") != NULL);
	CHECK(!ori_outline_hop(&m, &margin, why, sizeof(why)));
	/* the lobe turned by -60, 0 and 60 degrees about O, scaled 0.8, 1, 0.8: three lobes,
	 * the outer ones' tips 0.8 of the middle's; a hop but for its teeth */
	n = 1;
	for (int l = 0; l < 3; l++) {
		double a = (l - 1) * 3.14159265358979 / 3, c = cos(a), s = sin(a);
		double f = l == 1 ? 1 : 0.8;

		for (size_t k = 1; k < 12; k++) {
			if ((l > 0 && k < 4) || (l < 2 && k > 8)) /* the inner sides meet in a sinus */
				continue;
			three[n][0] = f * (c * one[k][0] - s * one[k][1]);
			three[n][1] = f * (s * one[k][0] + c * one[k][1]);
			n++;
		}
	}
	CHECK_INT(ori_outline_measure((const double(*)[3])three, n, &m), 0);
	CHECK_INT(m.nlobes, 3);
	CHECK_NEAR(m.tip[0], 0.8, 1e-12);
	CHECK_NEAR(m.tip[1], 1, 1e-12);
	CHECK(!ori_outline_hop(&m, &margin, why, sizeof(why)));
	CHECK(strstr(why, "teeth on a side") != NULL);
}

int main(void)
{
	test_measure();
	check_preset("maple", ori_outline_momiji);
	check_preset("hop", ori_outline_hop);
	printf("ok\n");
	return 0;
}
