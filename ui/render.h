/* SPDX-License-Identifier: MIT */
#pragma once

struct app;

/*
 * Draws what the kiosk shows for an app state: the tree, the stroke under the pen, the
 * hover cursor and the on-screen mode buttons. Needs a current GLES context (2.0 or later);
 * draws into the bound framebuffer at app->view's size. Same state, same pixels.
 */
struct render;

struct render *render_create(void);
void render_destroy(struct render *r);
/* Returns 0, or -EIO if GL reported an error. */
int render_frame(struct render *r, const struct app *app);
