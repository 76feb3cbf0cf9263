/* SPDX-License-Identifier: MIT */
/*
 * imgcmp [--max-diff N] [--max-fraction F] [--diff OUT.png] EXPECTED.png ACTUAL.png
 *
 * Compares two images with a tolerance: a pixel differs when any channel is more than
 * N apart; the images match when at most a fraction F of the pixels differ. Rasterisers
 * round differently in the last bit, so golden tests need this slack.
 * Exit 0: match; 1: sizes differ or too many pixels differ; 2: usage or unreadable input.
 */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "error.h"
#include "pngio.h"

struct image {
	uint8_t *rgba;
	int width, height;
};

static void usage(void)
{
	fprintf(stderr, "usage: imgcmp [--max-diff N] [--max-fraction F] [--diff OUT.png] "
			"EXPECTED.png ACTUAL.png\n");
}

static int read_file(const char *path, struct buf *b)
{
	FILE *f = fopen(path, "rb");
	unsigned char chunk[65536];
	size_t n;
	int r = 0;

	if (!f)
		return -errno;
	while ((n = fread(chunk, 1, sizeof(chunk), f)) > 0) {
		r = buf_append(b, chunk, n);
		if (r < 0)
			break;
	}
	if (r == 0 && ferror(f))
		r = -EIO;
	fclose(f);
	return r;
}

static int load(const char *path, struct image *img)
{
	struct buf b;
	struct error err;
	int r;

	buf_init(&b);
	r = read_file(path, &b);
	if (r < 0) {
		fprintf(stderr, "imgcmp: %s: %s\n", path, strerror(-r));
		buf_finish(&b);
		return r;
	}
	r = pngio_decode_rgba(b.data, b.len, path, &img->rgba, &img->width, &img->height, &err);
	buf_finish(&b);
	if (r < 0)
		fprintf(stderr, "imgcmp: %s\n", err.msg);
	return r;
}

static int write_file(const char *path, const struct buf *b)
{
	FILE *f = fopen(path, "wb");
	int r = 0;

	if (!f)
		return -errno;
	if (fwrite(b->data, 1, b->len, f) != b->len)
		r = -EIO;
	if (fclose(f) != 0 && r == 0)
		r = -errno;
	return r;
}

/* Differing pixels in red over a faded copy of the expected image, so they can be found. */
static int write_diff(const char *path, const struct image *a, const struct image *b, int max_diff)
{
	size_t npixels = (size_t)a->width * (size_t)a->height;
	uint8_t *out = malloc(npixels * 4);
	struct buf png;
	struct error err;
	int r;

	if (!out)
		return -ENOMEM;
	for (size_t i = 0; i < npixels; i++) {
		const uint8_t *p = a->rgba + i * 4, *q = b->rgba + i * 4;
		uint8_t *o = out + i * 4;
		int worst = 0;

		for (int c = 0; c < 4; c++) {
			int d = abs((int)p[c] - (int)q[c]);

			worst = d > worst ? d : worst;
		}
		if (worst > max_diff) {
			o[0] = 255;
			o[1] = 0;
			o[2] = 0;
		} else {
			uint8_t grey = (uint8_t)(160 + (p[0] + p[1] + p[2]) / 3 * 95 / 255);

			o[0] = o[1] = o[2] = grey;
		}
		o[3] = 255;
	}
	buf_init(&png);
	r = pngio_encode_rgba(out, a->width, a->height, &png, &err);
	free(out);
	if (r == 0)
		r = write_file(path, &png);
	buf_finish(&png);
	return r;
}

static bool parse_int(const char *s, int *v)
{
	char *end;
	long l;

	errno = 0;
	l = strtol(s, &end, 10);
	if (errno || end == s || *end || l < 0 || l > 255)
		return false;
	*v = (int)l;
	return true;
}

static bool parse_fraction(const char *s, double *v)
{
	char *end;

	errno = 0;
	*v = strtod(s, &end);
	return !errno && end != s && !*end && *v >= 0.0 && *v <= 1.0;
}

int main(int argc, char **argv)
{
	int max_diff = 8;
	double max_fraction = 0.001;
	const char *diff_path = NULL, *paths[2];
	int npaths = 0, status;
	struct image img[2] = { { 0 }, { 0 } };
	size_t npixels, ndiffer = 0;
	int worst = 0;

	for (int i = 1; i < argc; i++) {
		const char *arg = argv[i];

		if (!strcmp(arg, "--max-diff") && i + 1 < argc) {
			if (!parse_int(argv[++i], &max_diff)) {
				fprintf(stderr, "imgcmp: --max-diff wants 0..255, not '%s'\n", argv[i]);
				return 2;
			}
		} else if (!strcmp(arg, "--max-fraction") && i + 1 < argc) {
			if (!parse_fraction(argv[++i], &max_fraction)) {
				fprintf(stderr, "imgcmp: --max-fraction wants 0..1, not '%s'\n", argv[i]);
				return 2;
			}
		} else if (!strcmp(arg, "--diff") && i + 1 < argc) {
			diff_path = argv[++i];
		} else if (arg[0] == '-' && arg[1] != '\0') {
			usage();
			return 2;
		} else if (npaths < 2) {
			paths[npaths++] = arg;
		} else {
			usage();
			return 2;
		}
	}
	if (npaths != 2) {
		usage();
		return 2;
	}

	if (load(paths[0], &img[0]) < 0 || load(paths[1], &img[1]) < 0) {
		status = 2;
		goto out;
	}
	if (img[0].width != img[1].width || img[0].height != img[1].height) {
		fprintf(stderr, "imgcmp: sizes differ: %s is %dx%d, %s is %dx%d\n", paths[0],
			img[0].width, img[0].height, paths[1], img[1].width, img[1].height);
		status = 1;
		goto out;
	}

	npixels = (size_t)img[0].width * (size_t)img[0].height;
	for (size_t i = 0; i < npixels; i++) {
		const uint8_t *p = img[0].rgba + i * 4, *q = img[1].rgba + i * 4;
		int pixel_worst = 0;

		for (int c = 0; c < 4; c++) {
			int d = abs((int)p[c] - (int)q[c]);

			pixel_worst = d > pixel_worst ? d : pixel_worst;
		}
		if (pixel_worst > max_diff)
			ndiffer++;
		worst = pixel_worst > worst ? pixel_worst : worst;
	}
	if (diff_path) {
		int r = write_diff(diff_path, &img[0], &img[1], max_diff);

		if (r < 0)
			fprintf(stderr, "imgcmp: cannot write %s: %s\n", diff_path, strerror(-r));
	}
	if ((double)ndiffer > max_fraction * (double)npixels) {
		fprintf(stderr,
			"imgcmp: %s and %s differ: %zu of %zu pixels (%.3f%%) by more than %d "
			"(worst %d); at most %.3f%% may%s%s\n",
			paths[0], paths[1], ndiffer, npixels, 100.0 * (double)ndiffer / (double)npixels,
			max_diff, worst, 100.0 * max_fraction, diff_path ? "; see " : "",
			diff_path ? diff_path : "");
		status = 1;
	} else {
		printf("imgcmp: %s and %s match (%zu of %zu pixels differ by more than %d, worst %d)\n",
		       paths[0], paths[1], ndiffer, npixels, max_diff, worst);
		status = 0;
	}
out:
	free(img[0].rgba);
	free(img[1].rgba);
	return status;
}
