/* SPDX-License-Identifier: MIT */
/*
 * Writes what a DRM card shows now as a PNG, for the VM tests: the framebuffer of its
 * first active CRTC (XRGB8888, as GBM on llvmpipe and the console make), read through a
 * dumb-buffer mapping. With ROTATION, the picture is turned back as a display turned
 * that much clockwise shows it (90: the panel's top edge on the viewer's right), so
 * that it compares with an unturned render. With WxH, the screen holds a picture of
 * that size scaled to fit, aspect kept, centred: every pixel around it must be black,
 * and the picture is sampled back to WxH (nearest). Needs root (a framebuffer's handle).
 *   scanout CARD OUT.png [ROTATION [WxH]]
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include "buf.h"
#include "fileio.h"
#include "pngio.h"

/* The CRTC's framebuffer, or 0 with why on stderr. */
static uint32_t shown_fb(int fd)
{
	drmModeRes *res = drmModeGetResources(fd);
	uint32_t fb = 0;

	for (int i = 0; res && i < res->count_crtcs && !fb; i++) {
		drmModeCrtc *c = drmModeGetCrtc(fd, res->crtcs[i]);

		if (c && c->mode_valid)
			fb = c->buffer_id;
		drmModeFreeCrtc(c);
	}
	drmModeFreeResources(res);
	if (!fb)
		fputs("scanout: no CRTC shows a framebuffer\n", stderr);
	return fb;
}

/* Logical pixel (x, y) of a w x h picture: where it is on the panel (pw wide). */
static size_t panel_index(int rotation, int x, int y, int w, int h, int pw)
{
	int px, py;

	switch (rotation) {
	case 90:
		px = y, py = w - 1 - x;
		break;
	case 180:
		px = w - 1 - x, py = h - 1 - y;
		break;
	case 270:
		px = h - 1 - y, py = x;
		break;
	default:
		px = x, py = y;
		break;
	}
	return (size_t)py * (size_t)pw + (size_t)px;
}

/* The bytes of the panel's pixel i (row-major). */
static const uint8_t *at(const void *pixels, const drmModeFB *fb, size_t i)
{
	return (const uint8_t *)pixels + (i / fb->width) * fb->pitch + (i % fb->width) * 4;
}

/* Where a pw x ph picture lies when fitted into vw x vh: x0, y0, w, h. */
static void fit(int pw, int ph, int vw, int vh, int r[4])
{
	double scale = (double)vw / pw < (double)vh / ph ? (double)vw / pw : (double)vh / ph;

	r[2] = (int)(pw * scale + 0.5);
	r[3] = (int)(ph * scale + 0.5);
	r[0] = (vw - r[2]) / 2;
	r[1] = (vh - r[3]) / 2;
}

static int write_png(const char *path, const uint8_t *rgba, int w, int h)
{
	struct error err = { { 0 } };
	struct buf png;
	char *dir = strdup(path), *slash;
	int ret;

	if (!dir)
		return -ENOMEM;
	slash = strrchr(dir, '/');
	if (slash)
		*slash = '\0';
	buf_init(&png);
	ret = pngio_encode_rgba(rgba, w, h, &png, &err);
	if (ret == 0)
		ret = fileio_write_atomic(slash ? dir : ".", slash ? slash + 1 : path, png.data,
					  png.len, &err);
	if (ret < 0)
		fprintf(stderr, "scanout: %s\n", err.msg);
	buf_finish(&png);
	free(dir);
	return ret;
}

int main(int argc, char **argv)
{
	struct drm_mode_map_dumb map = { 0 };
	drmModeFBPtr fb = NULL;
	uint8_t *rgba = NULL;
	void *pixels = MAP_FAILED;
	size_t size = 0;
	int fd, rotation = argc > 3 ? atoi(argv[3]) : 0, status = 1, vw, vh, pw = 0, ph = 0;
	int rect[4];
	unsigned long lit = 0;
	uint32_t id;

	if (argc < 3 || (rotation != 0 && rotation != 90 && rotation != 180 && rotation != 270) ||
	    (argc > 4 && (sscanf(argv[4], "%dx%d", &pw, &ph) != 2 || pw <= 0 || ph <= 0))) {
		fputs("usage: scanout CARD OUT.png [0|90|180|270 [WxH]]\n", stderr);
		return 2;
	}
	fd = open(argv[1], O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		fprintf(stderr, "scanout: %s: %s\n", argv[1], strerror(errno));
		return 1;
	}
	if (!(id = shown_fb(fd)))
		goto out;
	fb = drmModeGetFB(fd, id);
	if (!fb || !fb->handle || fb->bpp != 32) {
		fprintf(stderr, "scanout: framebuffer %u: %s\n", id,
			!fb ? strerror(errno) : !fb->handle ? "no handle (not root?)" : "not 32 bpp");
		goto out;
	}
	map.handle = fb->handle;
	size = (size_t)fb->pitch * fb->height;
	if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &map) < 0 ||
	    (pixels = mmap(NULL, size, PROT_READ, MAP_SHARED, fd, (off_t)map.offset)) == MAP_FAILED) {
		fprintf(stderr, "scanout: cannot map framebuffer %u: %s\n", id, strerror(errno));
		goto out;
	}
	/* the screen as the viewer sees it */
	vw = rotation == 90 || rotation == 270 ? (int)fb->height : (int)fb->width;
	vh = rotation == 90 || rotation == 270 ? (int)fb->width : (int)fb->height;
	if (!pw)
		pw = vw, ph = vh;
	fit(pw, ph, vw, vh, rect);
	rgba = malloc((size_t)pw * (size_t)ph * 4);
	if (!rgba) {
		fputs("scanout: out of memory\n", stderr);
		goto out;
	}
	/* around the picture: nothing but black */
	for (int y = 0; y < vh; y++) {
		for (int x = 0; x < vw; x++) {
			const uint8_t *p;

			if (x >= rect[0] && x < rect[0] + rect[2] && y >= rect[1] &&
			    y < rect[1] + rect[3])
				continue;
			p = at(pixels, fb, panel_index(rotation, x, y, vw, vh, (int)fb->width));
			lit += (p[0] | p[1] | p[2]) != 0;
		}
	}
	/* each picture pixel from the screen pixel under its centre */
	for (int y = 0; y < ph; y++) {
		for (int x = 0; x < pw; x++) {
			int sx = rect[0] + (int)((2L * x + 1) * rect[2] / (2L * pw));
			int sy = rect[1] + (int)((2L * y + 1) * rect[3] / (2L * ph));
			const uint8_t *p = at(pixels, fb, panel_index(rotation, sx, sy, vw, vh,
								 (int)fb->width));
			uint8_t *o = rgba + ((size_t)y * (size_t)pw + (size_t)x) * 4;

			/* XRGB8888 is little-endian: blue first */
			o[0] = p[2], o[1] = p[1], o[2] = p[0], o[3] = 255;
		}
	}
	if (lit)
		fprintf(stderr, "scanout: %lu pixels around the %dx%d picture are not black\n",
			lit, pw, ph);
	else if (write_png(argv[2], rgba, pw, ph) == 0)
		status = 0;
out:
	if (pixels != MAP_FAILED)
		munmap(pixels, size);
	if (fb && fb->handle)
		drmCloseBufferHandle(fd, fb->handle);
	drmModeFreeFB(fb);
	free(rgba);
	close(fd);
	return status;
}
