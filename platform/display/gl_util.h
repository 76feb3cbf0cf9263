/* SPDX-License-Identifier: MIT */
#pragma once

/* Small GL/EGL helpers the headless framebuffer, the kiosk's display and its offscreen
 * picture share. Need a current context (gl_read_rgba). */
#include <stdbool.h>
#include <stdint.h>

/* Whether a space-separated extension list (EGL's or GL's) holds word; list may be NULL. */
bool gl_has_extension(const char *list, const char *word);

/* Reads w x h RGBA pixels of the bound read framebuffer, top row first (GL's first row is
 * the bottom one). row: scratch of w * 4 bytes. 0, or -EIO when GL reports an error. */
int gl_read_rgba(int w, int h, uint8_t *rgba, uint8_t *row);

/* A renderbuffer of format (GL_RGBA8, GL_DEPTH_COMPONENT24, ...), multisampled when
 * samples > 0 (GLES 3), bound; 0 when GL has none to give. */
unsigned gl_make_renderbuffer(unsigned format, int samples, int width, int height);
