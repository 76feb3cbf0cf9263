/* SPDX-License-Identifier: MIT */
/*
 * What tests/export/page.sh measures on screenshots of the take-home page, as masks: a
 * pixel is the tree's when it is more than PAPER_DIFF (sum over RGB) from the kiosk's
 * paper (ui's render_paper as bytes, the page's background too).
 *
 *   page_masks silhouette KIOSK.png X0 Y0 X1 Y1 PAGE.png
 *     The tree in the kiosk's front view (screen.png, within the box X0..X1 x Y0..Y1: the
 *     canvas without the bar, the side strip and the ground) against the page's: each
 *     mask cut to its bounding box and laid on a grid of GRID cells across (as many down
 *     as the kiosk's box holds square cells), a cell's value the fraction of its pixels
 *     that are tree; the soft IoU sum(min) / sum(max) over the cells, and both boxes'
 *     width / height. Scale and place drop out: the kiosk's view is orthographic and
 *     pixel-sized by its screen, the page's a perspective framed on the window.
 *   page_masks wind A.png B.png
 *     Two moments of the page: in the crown (the upper half of A's tree box) and at the
 *     trunk's foot (the lowest FOOT_ROWS rows of A's tree, the columns it covers there,
 *     FOOT_PAD pixels either side), the tree pixels of A and how many pixels differ
 *     (more than PIXEL_DIFF over RGB); at the foot also how far the tree's outline moved,
 *     row by row (its first and last tree pixel), at most and on average: an edge pixel
 *     that flips where a slanted edge crosses pixel centres is a move of one pixel, a
 *     sub-pixel move; a foot that sways moves by more.
 *   page_masks turned A.png B.png
 *     The soft IoU of two moments' masks (as silhouette, on A's box's grid), and B's box.
 *
 * Prints one JSON object; exit 0, or 2 (an unreadable image, no tree in one).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "error.h"
#include "pngio.h"

#define PAPER_R 249
#define PAPER_G 243
#define PAPER_B 229
#define PAPER_DIFF 48
#define PIXEL_DIFF 48
#define GRID 48
#define FOOT_ROWS 12
#define FOOT_PAD 4

struct image {
	uint8_t *rgba;
	int w, h;
};

struct box {
	int x0, y0, x1, y1; /* inclusive; x1 < x0: empty */
};

static int load(const char *path, struct image *im)
{
	struct error err = { { 0 } };
	struct buf b;
	unsigned char chunk[65536];
	size_t n;
	FILE *f = fopen(path, "rb");
	int r;

	if (!f) {
		perror(path);
		return -1;
	}
	buf_init(&b);
	while ((n = fread(chunk, 1, sizeof(chunk), f)) > 0)
		if (buf_append(&b, chunk, n) < 0)
			break;
	fclose(f);
	r = pngio_decode_rgba(b.data, b.len, path, &im->rgba, &im->w, &im->h, &err);
	buf_finish(&b);
	if (r < 0)
		fprintf(stderr, "%s\n", err.msg);
	return r;
}

static bool tree_at(const struct image *im, int x, int y)
{
	const uint8_t *p = im->rgba + ((size_t)y * (size_t)im->w + (size_t)x) * 4;

	return abs(p[0] - PAPER_R) + abs(p[1] - PAPER_G) + abs(p[2] - PAPER_B) > PAPER_DIFF;
}

static bool differ_at(const struct image *a, const struct image *b, int x, int y)
{
	const uint8_t *p = a->rgba + ((size_t)y * (size_t)a->w + (size_t)x) * 4;
	const uint8_t *q = b->rgba + ((size_t)y * (size_t)b->w + (size_t)x) * 4;

	return abs(p[0] - q[0]) + abs(p[1] - q[1]) + abs(p[2] - q[2]) > PIXEL_DIFF;
}

/* The tree's bounding box within limit. */
static struct box tree_box(const struct image *im, struct box limit)
{
	struct box b = { limit.x1 + 1, limit.y1 + 1, -1, -1 };

	for (int y = limit.y0; y <= limit.y1; y++)
		for (int x = limit.x0; x <= limit.x1; x++)
			if (tree_at(im, x, y)) {
				b.x0 = x < b.x0 ? x : b.x0;
				b.y0 = y < b.y0 ? y : b.y0;
				b.x1 = x > b.x1 ? x : b.x1;
				b.y1 = y > b.y1 ? y : b.y1;
			}
	return b;
}

static bool box_empty(struct box b)
{
	return b.x1 < b.x0 || b.y1 < b.y0;
}

/* The mask within box b as gx x gy cells: a cell is the tree's when any of its pixels is. */
static uint8_t *cells(const struct image *im, struct box b, int gx, int gy)
{
	uint8_t *v = calloc((size_t)gx * (size_t)gy, 1);
	int w = b.x1 - b.x0 + 1, h = b.y1 - b.y0 + 1;

	if (!v)
		return NULL;
	for (int y = b.y0; y <= b.y1; y++)
		for (int x = b.x0; x <= b.x1; x++)
			if (tree_at(im, x, y))
				v[(y - b.y0) * gy / h * gx + (x - b.x0) * gx / w] = 1;
	return v;
}

/* Whether cell (x, y) or one of its eight neighbours is set. */
static bool near_cell(const uint8_t *v, int gx, int gy, int x, int y)
{
	for (int dy = -1; dy <= 1; dy++)
		for (int dx = -1; dx <= 1; dx++)
			if (x + dx >= 0 && x + dx < gx && y + dy >= 0 && y + dy < gy &&
			    v[(y + dy) * gx + x + dx])
				return true;
	return false;
}

struct overlap {
	double iou;  /* cells both / cells either */
	double near; /* cells of each within a cell of the other's, of all */
	int gx, gy;
};

/* The two masks, each cut to its box, on one grid: GRID cells across, as many down as
 * a's box holds square cells. */
static int overlap(const struct image *a, struct box ba, const struct image *b, struct box bb,
		   struct overlap *o)
{
	int gx = GRID, gy = (int)lround(GRID * (double)(ba.y1 - ba.y0 + 1) / (ba.x1 - ba.x0 + 1));
	long both = 0, either = 0, near = 0, total = 0;
	uint8_t *ca, *cb;

	gy = gy < 1 ? 1 : gy;
	ca = cells(a, ba, gx, gy);
	cb = cells(b, bb, gx, gy);
	if (!ca || !cb) {
		free(ca);
		free(cb);
		return -1;
	}
	for (int y = 0; y < gy; y++)
		for (int x = 0; x < gx; x++) {
			int i = y * gx + x;

			both += ca[i] && cb[i];
			either += ca[i] || cb[i];
			total += ca[i] + cb[i];
			near += (ca[i] && near_cell(cb, gx, gy, x, y)) + (cb[i] && near_cell(ca, gx, gy, x, y));
		}
	free(ca);
	free(cb);
	o->iou = either ? (double)both / either : 0;
	o->near = total ? (double)near / total : 0;
	o->gx = gx;
	o->gy = gy;
	return 0;
}

static double aspect(struct box b)
{
	return (double)(b.x1 - b.x0 + 1) / (b.y1 - b.y0 + 1);
}

static struct box whole(const struct image *im)
{
	return (struct box){ 0, 0, im->w - 1, im->h - 1 };
}

/* The mean colour of the tree's pixels within b, 0..255 a channel. */
static void tree_mean(const struct image *im, struct box b, double mean[3])
{
	double sum[3] = { 0.0, 0.0, 0.0 };
	long n = 0;

	for (int y = b.y0; y <= b.y1; y++)
		for (int x = b.x0; x <= b.x1; x++) {
			const uint8_t *q = im->rgba + ((size_t)y * (size_t)im->w + (size_t)x) * 4;

			if (!tree_at(im, x, y))
				continue;
			for (int c = 0; c < 3; c++)
				sum[c] += q[c];
			n++;
		}
	for (int c = 0; c < 3; c++)
		mean[c] = n > 0 ? sum[c] / (double)n : 0.0;
}

static int silhouette(const struct image *k, struct box limit, const struct image *p)
{
	double mk[3], mp[3];

	struct box bk = tree_box(k, limit), bp = tree_box(p, whole(p));
	struct overlap o;

	if (box_empty(bk) || box_empty(bp)) {
		fprintf(stderr, "page_masks: no tree in the %s picture\n", box_empty(bk) ? "kiosk's" : "page's");
		return 2;
	}
	if (overlap(k, bk, p, bp, &o) < 0)
		return 2;
	tree_mean(k, bk, mk);
	tree_mean(p, bp, mp);
	printf("{\"iou\": %.4f, \"near\": %.4f, \"grid\": [%d, %d], \"kiosk_aspect\": %.4f, "
	       "\"page_aspect\": %.4f, \"kiosk_box\": [%d, %d, %d, %d], "
	       "\"page_box\": [%d, %d, %d, %d], \"kiosk_mean\": [%.1f, %.1f, %.1f], "
	       "\"page_mean\": [%.1f, %.1f, %.1f]}\n",
	       o.iou, o.near, o.gx, o.gy, aspect(bk), aspect(bp), bk.x0, bk.y0, bk.x1, bk.y1,
	       bp.x0, bp.y0, bp.x1, bp.y1, mk[0], mk[1], mk[2], mp[0], mp[1], mp[2]);
	return 0;
}

static int wind(const struct image *a, const struct image *b)
{
	struct box ba = tree_box(a, whole(a)), crown, foot;
	long crown_tree = 0, crown_differ = 0, foot_tree = 0, foot_differ = 0, edge_sum = 0, edges = 0;
	int edge_max = 0;

	if (box_empty(ba) || a->w != b->w || a->h != b->h) {
		fputs("page_masks: no tree, or two sizes\n", stderr);
		return 2;
	}
	crown = (struct box){ ba.x0, ba.y0, ba.x1, ba.y0 + (ba.y1 - ba.y0) / 2 };
	/* the foot: the columns the tree covers in its lowest rows */
	foot = (struct box){ ba.x1 + 1, ba.y1 - FOOT_ROWS + 1, -1, ba.y1 };
	for (int y = foot.y0; y <= foot.y1; y++)
		for (int x = ba.x0; x <= ba.x1; x++)
			if (tree_at(a, x, y)) {
				foot.x0 = x < foot.x0 ? x : foot.x0;
				foot.x1 = x > foot.x1 ? x : foot.x1;
			}
	foot.x0 = foot.x0 - FOOT_PAD < 0 ? 0 : foot.x0 - FOOT_PAD;
	foot.x1 = foot.x1 + FOOT_PAD >= a->w ? a->w - 1 : foot.x1 + FOOT_PAD;
	foot.y1 = foot.y1 + FOOT_PAD >= a->h ? a->h - 1 : foot.y1 + FOOT_PAD;
	for (int y = crown.y0; y <= crown.y1; y++)
		for (int x = crown.x0; x <= crown.x1; x++) {
			crown_tree += tree_at(a, x, y);
			crown_differ += differ_at(a, b, x, y);
		}
	for (int y = foot.y0; y <= foot.y1; y++) {
		int la = -1, ra = -1, lb = -1, rb = -1;

		for (int x = foot.x0; x <= foot.x1; x++) {
			foot_tree += tree_at(a, x, y);
			foot_differ += differ_at(a, b, x, y);
			if (tree_at(a, x, y)) {
				la = la < 0 ? x : la;
				ra = x;
			}
			if (tree_at(b, x, y)) {
				lb = lb < 0 ? x : lb;
				rb = x;
			}
		}
		if (la < 0 && lb < 0)
			continue;
		if (la < 0 || lb < 0) { /* a row of the foot there in one picture alone */
			edge_max = foot.x1 - foot.x0 + 1;
			continue;
		}
		edge_max = abs(la - lb) > edge_max ? abs(la - lb) : edge_max;
		edge_max = abs(ra - rb) > edge_max ? abs(ra - rb) : edge_max;
		edge_sum += abs(la - lb) + abs(ra - rb);
		edges += 2;
	}
	printf("{\"crown_tree\": %ld, \"crown_differ\": %ld, \"foot_tree\": %ld, "
	       "\"foot_differ\": %ld, \"foot_edge_max\": %d, \"foot_edge_mean\": %.4f, "
	       "\"foot_box\": [%d, %d, %d, %d]}\n",
	       crown_tree, crown_differ, foot_tree, foot_differ, edge_max,
	       edges ? (double)edge_sum / edges : 0.0, foot.x0, foot.y0, foot.x1, foot.y1);
	return 0;
}

static int turned(const struct image *a, const struct image *b)
{
	struct box ba = tree_box(a, whole(a)), bb = tree_box(b, whole(b));
	struct overlap o;

	if (box_empty(ba) || box_empty(bb) || overlap(a, ba, b, bb, &o) < 0) {
		fputs("page_masks: no tree\n", stderr);
		return 2;
	}
	printf("{\"iou\": %.4f, \"near\": %.4f, \"box\": [%d, %d, %d, %d], \"size\": [%d, %d]}\n",
	       o.iou, o.near, bb.x0, bb.y0, bb.x1, bb.y1, b->w, b->h);
	return 0;
}

int main(int argc, char **argv)
{
	struct image a = { 0 }, b = { 0 };
	int r = 2;

	if (argc == 8 && !strcmp(argv[1], "silhouette")) {
		struct box limit = { atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), atoi(argv[6]) };

		if (load(argv[2], &a) == 0 && load(argv[7], &b) == 0) {
			limit.x1 = limit.x1 >= a.w ? a.w - 1 : limit.x1;
			limit.y1 = limit.y1 >= a.h ? a.h - 1 : limit.y1;
			r = silhouette(&a, limit, &b);
		}
	} else if (argc == 4 && (!strcmp(argv[1], "wind") || !strcmp(argv[1], "turned"))) {
		if (load(argv[2], &a) == 0 && load(argv[3], &b) == 0)
			r = !strcmp(argv[1], "wind") ? wind(&a, &b) : turned(&a, &b);
	} else {
		fputs("usage: page_masks silhouette KIOSK.png X0 Y0 X1 Y1 PAGE.png | "
		      "wind A.png B.png | turned A.png B.png\n", stderr);
	}
	free(a.rgba);
	free(b.rgba);
	return r;
}
