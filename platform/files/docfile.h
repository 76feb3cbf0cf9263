/* SPDX-License-Identifier: MIT */
#pragma once

#include "doc.h"
#include "error.h"

/* Reads and parses a drawing.edaha file into *doc (the caller owns it on success). 0, or
 * a negative errno with "file:line: why" in err; -ENOMEM and -EIO are the machine's
 * fault, anything else the file's. */
int docfile_read(const char *path, struct doc *doc, struct error *err);
