/* SPDX-License-Identifier: MIT */
#pragma once
/*
 * What a visitor sees of a leaf's outline (issue 24, docs/origami-leaves.md "What the
 * presets must look like"): its lobes, how deep the notches between them are, its teeth,
 * and whether its base is heart-shaped. Measured on the outline alone, so the same
 * measure serves an opened pattern and a leaf placed on a tree.
 */
#include <stdbool.h>
#include <stddef.h>

#define ORI_OUTLINE_MAX_LOBES 16
/* a lobe's tip stands this much (x the farthest point's distance) above the lower of the
 * two deepest points between it and a higher point (or O) on either side */
#define ORI_OUTLINE_LOBE_PROMINENCE 0.15
/* a tooth sticks out this much (x the middle lobe's length) beyond the line through its
 * two neighbours on the outline */
#define ORI_OUTLINE_TOOTH 0.02

struct ori_outline {
	size_t nlobes;
	size_t lobe[ORI_OUTLINE_MAX_LOBES]; /* the tips' indices in the outline */
	double tip[ORI_OUTLINE_MAX_LOBES];  /* their distance from O, x the middle lobe's */
	double sinus[ORI_OUTLINE_MAX_LOBES]; /* [k]: the deepest point between lobes k and k +
					      * 1, x the nearer of the two tips */
	int lobe_teeth[ORI_OUTLINE_MAX_LOBES]; /* teeth between the sinuses either side (or O) */
	double length;  /* the middle lobe's, in the points' units */
	int teeth[2];   /* right, left of the midrib (O to the middle tip) */
	double least_tooth; /* the smallest tooth counted, x length (0: none) */
	double behind[2];   /* right, left: how far the outline between O and the first
			     * lobe goes back behind O along the midrib, x length (> 0: behind) */
};

/*
 * Measures the outline pts[0..n) (n >= 3), counter-clockwise seen from its front, pts[0]
 * the leaf's base O, in 3D: projected on its plane (Newell's normal, through O), the
 * midrib from O to the farthest point. 0, or -1 if it has no area or fewer than one lobe.
 */
int ori_outline_measure(const double (*pts)[3], size_t n, struct ori_outline *m);

/*
 * Issue 24's measures. A momiji: 5 or 7 lobes, every tip at least 0.6 of the middle lobe's
 * length from O, every sinus at most half as far from O as the tips beside it, a tooth on
 * every lobe. A hop: 3 or 5 lobes, a heart-shaped base (the outline goes back behind O by
 * at least ORI_OUTLINE_HEART x the length on both sides), at least 8 teeth each side.
 * true, or false with what fails in why. *margin: the least slack of the numbers tested
 * (a fraction of their limit; > 0 when it holds), to be quoted.
 */
#define ORI_OUTLINE_HEART 0.1
bool ori_outline_momiji(const struct ori_outline *m, double *margin, char *why, size_t len);
bool ori_outline_hop(const struct ori_outline *m, double *margin, char *why, size_t len);
