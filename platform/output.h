/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "app.h"
#include "error.h"

/*
 * The files a drawing is saved as: model.glb, model.obj + model.mtl, skeleton.json and
 * drawing.edaha, plus screen.png when a picture is given. Same state, same bytes.
 */
int output_write_all(const struct app *app, const char *dir, const uint8_t *rgba,
		     struct error *err);
