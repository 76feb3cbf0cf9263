/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "app.h"
#include "error.h"

/*
 * What the export button writes: the model for other programs (tree-NNNN.glb,
 * tree-NNNN.obj + .mtl), a picture of the screen (tree-NNNN.png, when rgba is given) and
 * the drawing to continue later (tree-NNNN.edaha), in dir, created when missing. NNNN is
 * the first number none of whose five names exists, so an export never replaces an
 * earlier one; each file is written atomically (fileio). On success base holds
 * "tree-NNNN". 0, -EEXIST when 9999 sets are there already, or a negative errno with a
 * message naming the file.
 */
#define EXPORT_DIR_MAX_SETS 9999

int export_dir_write(const struct app *app, const char *dir, const uint8_t *rgba, char *base,
		     size_t base_size, struct error *err);
