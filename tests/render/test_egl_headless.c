/* SPDX-License-Identifier: MIT */
/* egl_headless: a cleared colour reads back exactly, top row first; clean teardown. */
#include <GLES2/gl2.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "egl_headless.h"
#include "test.h"

static void check_pixel(const uint8_t *rgba, int width, int x, int y, const uint8_t want[4])
{
	const uint8_t *p = rgba + ((size_t)y * (size_t)width + (size_t)x) * 4;

	if (memcmp(p, want, 4) != 0) {
		fprintf(stderr, "pixel %d,%d is %u %u %u %u, want %u %u %u %u\n", x, y, p[0], p[1],
			p[2], p[3], want[0], want[1], want[2], want[3]);
		exit(1);
	}
}

static void test_clear(int width, int height)
{
	/* n/255 for whole n, so the colour survives float conversion exactly */
	static const uint8_t blue[4] = { 51, 102, 153, 255 }, red[4] = { 255, 0, 0, 255 };
	struct error err = { "" };
	struct egl_headless *e = egl_headless_create(width, height, &err);
	uint8_t *rgba = malloc((size_t)width * (size_t)height * 4);
	int top = height / 4;

	if (!e)
		fprintf(stderr, "egl_headless_create: %s\n", err.msg);
	CHECK(e);
	CHECK(rgba);
	glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
	glClear(GL_COLOR_BUFFER_BIT);
	/* GL counts rows from the bottom: these are the top rows of the image */
	glEnable(GL_SCISSOR_TEST);
	glScissor(0, height - top, width, top);
	glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
	glClear(GL_COLOR_BUFFER_BIT);
	glDisable(GL_SCISSOR_TEST);
	CHECK_INT(glGetError(), GL_NO_ERROR);

	CHECK_INT(egl_headless_read_rgba(e, rgba), 0);
	for (int y = 0; y < height; y++) {
		for (int x = 0; x < width; x++)
			check_pixel(rgba, width, x, y, y < top ? red : blue);
	}
	/* reading leaves the framebuffer bound for drawing: a second read sees the same */
	glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
	glClear(GL_COLOR_BUFFER_BIT);
	CHECK_INT(egl_headless_read_rgba(e, rgba), 0);
	check_pixel(rgba, width, 0, 0, blue);
	check_pixel(rgba, width, width - 1, height - 1, blue);

	free(rgba);
	egl_headless_destroy(e);
}

int main(void)
{
	struct error err = { "" };

	test_clear(64, 32);
	/* odd sizes: rows of any length, a middle row that stays put when flipped */
	test_clear(3, 5);
	test_clear(1280, 800);

	CHECK(egl_headless_create(0, 10, &err) == NULL);
	CHECK(strstr(err.msg, "0x10") != NULL);
	CHECK(egl_headless_create(100000, 10, &err) == NULL);
	CHECK(err.msg[0] != '\0');
	egl_headless_destroy(NULL);
	return 0;
}
