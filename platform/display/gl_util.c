/* SPDX-License-Identifier: MIT */
#include "gl_util.h"

#include <GLES3/gl3.h>
#include <errno.h>
#include <string.h>

bool gl_has_extension(const char *list, const char *word)
{
	size_t n = strlen(word);

	for (const char *p = list; p && (p = strstr(p, word)); p += n) {
		if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
			return true;
	}
	return false;
}

int gl_read_rgba(int w, int h, uint8_t *rgba, uint8_t *row)
{
	size_t stride = (size_t)w * 4;

	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
	if (glGetError() != GL_NO_ERROR)
		return -EIO;
	for (int y = 0; y < h / 2; y++) {
		uint8_t *top = rgba + (size_t)y * stride;
		uint8_t *bottom = rgba + (size_t)(h - 1 - y) * stride;

		memcpy(row, top, stride);
		memcpy(top, bottom, stride);
		memcpy(bottom, row, stride);
	}
	return 0;
}

unsigned gl_make_renderbuffer(unsigned format, int samples, int width, int height)
{
	GLuint rb = 0;

	glGenRenderbuffers(1, &rb);
	glBindRenderbuffer(GL_RENDERBUFFER, rb);
	if (samples > 0)
		glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
	else
		glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
	return rb;
}
