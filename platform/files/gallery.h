/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The stick's gallery, edaha/index.html (docs/usb.md): every tree saved in a directory (a
 * USB stick's edaha/, kiosk.export_dir), newest first, each its picture, number and date
 * linking to its page tree-NNNN.html. Rebuilt from one listing of the directory at every
 * Save, after the set, so it is right whatever else wrote there.
 *
 * The directory may hold anything (another kiosk's sets, an older version's, a hostile
 * stick's names), so:
 *  - a tree is a number whose page tree-NNNN.html, or before pages its model
 *    tree-NNNN.glb, is a regular file named exactly as export_names_format names it (any
 *    other spelling, "TREE-0001.HTML", "tree-1.html", is not listed); its picture
 *    tree-NNNN.png likewise. No name from the directory is printed: the links, numbers,
 *    dates and words are formatted here, and HTML-escaped all the same;
 *  - newest first is by number, highest first: a set's number is one past the highest
 *    the directory held when it was saved (export_names.h), so it is the order the sets
 *    were saved in there, whichever kiosk saved them and whatever its clock said (a
 *    board without a real-time clock, FAT's local times, a computer's copy); numbers are
 *    unique, so there are no ties to break by time;
 *  - the page runs no script and loads nothing but the pictures beside it; its
 *    Content-Security-Policy tells the browser so;
 *  - written as .index.html.tmp (O_EXCL | O_NOFOLLOW, fsynced), renamed over index.html
 *    (replacing whatever was there, another kiosk's index or a symlink, never following
 *    it), the directory fsynced: the old index or the whole new one, never half.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "buf.h"
#include "config_file.h"
#include "error.h"

#define GALLERY_FILE "index.html"
/* The kiosk's paper (ui/gl/render_shaders.c's render_paper, 0.975 0.953 0.898) */
#define GALLERY_PAPER "#f9f3e5"
/* Dates before this (a board whose clock was never set) are not shown: 2000-01-01 UTC. */
#define GALLERY_DATE_MIN 946684800

struct gallery_tree {
	unsigned number;
	bool page;     /* tree-NNNN.html is there: the link; else the model tree-NNNN.glb */
	bool picture;  /* tree-NNNN.png is there */
	int64_t mtime; /* the linked file's, seconds since the epoch */
};

struct gallery {
	struct gallery_tree *trees; /* newest (highest number) first */
	size_t count, cap;
};

void gallery_init(struct gallery *g);
void gallery_finish(struct gallery *g);
/* One listing of dirfd (its offset untouched), and one fstatat for each tree's date:
 * the trees in g, newest first. 0, or -errno with a message. */
int gallery_list(int dirfd, struct gallery *g, struct error *err);
/* index.html's bytes for g in lang, dates in local time. 0 or -ENOMEM. */
int gallery_html(const struct gallery *g, enum config_language lang, struct buf *out);
/* Lists dirfd and writes its index.html by the rules above; *count (may be NULL) the
 * trees in it. 0, or -errno with a message (index.html as it was, no temporary left). */
int gallery_write(int dirfd, enum config_language lang, size_t *count, struct error *err);
