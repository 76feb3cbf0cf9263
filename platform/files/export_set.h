/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What the export button writes, as bytes in memory first and then as files in a
 * directory given by its fd (a USB stick's edaha/ from edaha-usb-helper, or
 * kiosk.export_dir): tree-NNNN.glb, .obj + .mtl, .png (when there is a picture), .edaha
 * and .html, the take-home page (docs/page.md; when the viewer's scripts were found). The
 * bytes are built on the kiosk's main thread, which owns the app; the writing may happen
 * on another thread, as it only touches the set, the fd and the viewer's scripts (read
 * once at start, kept until the writer is gone). The page is made by the writing, as it
 * shows the set's number, which only the directory's listing tells.
 *
 * The rules, for a stick that may be pulled, full or hostile at any moment:
 *  - never over anything: the number is one no name in the directory has (one readdir,
 *    case-insensitive, export_names.h), and renames refuse to replace (RENAME_NOREPLACE);
 *  - never through a symlink: every file is created O_EXCL | O_NOFOLLOW relative to the
 *    directory fd;
 *  - never half a file under a final name: each file goes to a temporary
 *    .tree-NNNN.EXT.tmp, is written and fsynced; only when all are, they are renamed
 *    and the directory is fsynced;
 *  - on failure nothing of the set is left that can be removed: no temporaries, no
 *    final names.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "app.h"
#include "buf.h"
#include "error.h"
#include "export_names.h"
#include "page_viewer.h"

/* The files, in export_names_suffixes' order; an empty png or html is not written. */
enum export_set_file { EXPORT_SET_GLB, EXPORT_SET_OBJ, EXPORT_SET_MTL, EXPORT_SET_PNG,
		       EXPORT_SET_EDAHA, EXPORT_SET_HTML };

struct export_set {
	struct buf files[EXPORT_NAMES_NSUFFIXES];
	/* the strength the .glb sways at (kiosk.wind); 0, as export_set_init leaves it: the
	 * default breeze (export_glb_wind) */
	double wind;
	/* Save on today's forest (docs/forest.md): forest-DATE.glb written after the set, by
	 * the same rules, under the first of forest-DATE.glb, forest-DATE-2.glb, ... that no
	 * name in the directory has (empty: none). DATE: "YYYY-MM-DD". */
	struct buf forest;
	char forest_date[11];
	char forest_name[40]; /* the name it got, once written */
	bool forest_only;     /* an empty canvas on the forest: no tree's files */
	/* the page: export_set_init takes the kiosk's (export_set_page_default), no viewer:
	 * no page; its date, as the page says it, export_set_build's day ("": none) */
	struct page_look page;
	char page_date[64];
};

/* The page every set from now on carries (the kiosk's, set once it has read the viewer;
 * NULL: none). The viewer must outlive every set's writing. Main thread. */
void export_set_page_default(const struct page_look *look);
/* Takes the page's look from export_set_page_default. */
void export_set_init(struct export_set *s);
void export_set_finish(struct export_set *s);
/* The app's drawing as the set's bytes, the picture from rgba (app->screen's size, top row
 * first) when given; the page's date is today's (the local clock). 0 or -ENOMEM / -EFBIG
 * with a message. */
int export_set_build(struct export_set *s, const struct app *app, const uint8_t *rgba,
		     struct error *err);
/* Lists dirfd once: the number for the next set, and removes temporaries of ours an
 * interrupted write left behind. 0, -ENOSPC (every number taken) or -errno. */
int export_set_pick(int dirfd, unsigned *number, struct error *err);
/* Writes the set as that number (the rules above), its page made first (-ENOMEM). 0, or
 * -errno with a message naming the file; -EEXIST when one of its names turned up
 * meanwhile. */
int export_set_write(int dirfd, struct export_set *s, unsigned number, struct error *err);
/* forest-DATE[-N].glb (s->forest) into dirfd: temporary, fsync, rename never over a
 * name, fsync of the directory; s->forest_name says which. 0, or -errno with a message
 * (nothing of it left: no temporary, no final name). */
#define EXPORT_SET_FOREST_MAX 99
int export_set_write_forest(int dirfd, struct export_set *s, struct error *err);
/* pick and write, once more with a new number if a name turned up taken meanwhile, then
 * the forest's file when there is one. On success base is "tree-NNNN" (with
 * forest_only, the forest's file alone is written and base is its name). */
int export_set_save(int dirfd, struct export_set *s, char *base, size_t base_size,
		    struct error *err);
/* Renames from to to in dirfd, failing with EEXIST rather than replacing: renameat2's
 * RENAME_NOREPLACE, or where a filesystem lacks it (EINVAL) or noreplace is false, a
 * check that to is no name followed by renameat (safe: we are the only writer). */
int export_set_rename(int dirfd, const char *from, const char *to, bool noreplace);
