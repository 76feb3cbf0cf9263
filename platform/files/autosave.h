/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "doc.h"
#include "error.h"
#include "tree.h"

/*
 * The drawing on screen, kept through crashes, watchdog restarts and power cuts: every
 * committed stroke and edit is appended to DIR/drawing.journal (src/doc/journal.h) and
 * fsync'ed before the loop goes on. On start the journal gives the drawing back; the
 * idle reset archives it to DIR/archive/drawing-NNNNNN.edaha and starts afresh.
 */
#define AUTOSAVE_JOURNAL "drawing.journal"
/* Past this many bytes appended the journal is rewritten as one record. */
#define AUTOSAVE_COMPACT_BYTES (4u << 20)
#define AUTOSAVE_ARCHIVE_DIR "archive"
#define AUTOSAVE_ARCHIVE_MAX 999999u

struct autosave;

/* Makes DIR if needed. NULL with err on failure. */
struct autosave *autosave_create(const char *dir, struct error *err);
void autosave_destroy(struct autosave *a);
const char *autosave_path(const struct autosave *a);

/*
 * Reads the journal into *doc (doc_init'ed by the caller): 1 when it held a drawing, 0
 * when there was none. A torn last record (a power cut) or a file that is no journal at
 * all is not an error: what could be read is kept, the rest is said in *warn (warn->msg
 * empty when all was well) and an unreadable file is moved aside to drawing.journal.bad.
 * Negative errno with err only when the journal cannot be read at all (I/O).
 */
int autosave_restore(struct autosave *a, struct doc *doc, struct error *warn,
		     struct error *err);
/* Starts the journal afresh with d as its one record (atomically). 0 or -errno. */
int autosave_start(struct autosave *a, const struct doc *d, struct error *err);
/* Appends what changed in d since the last start/sync and fsyncs it: 0 (also when
 * nothing changed) or -errno. After a failure the next call starts afresh. */
int autosave_sync(struct autosave *a, const struct doc *d, struct error *err);
/* Whether d changed since the journal last saw it. */
bool autosave_pending(const struct autosave *a, const struct doc *d);
/* Writes d (with t's summary) to DIR/archive under the next free number, keeping at most
 * keep archives (the oldest go; 0: keep all). name gets the file name. 0 or -errno. */
int autosave_archive(struct autosave *a, const struct doc *d, const struct tree *t,
		     unsigned keep, char *name, size_t name_size, struct error *err);
/* 1 when d (with t's summary) is, byte for byte, the newest archived drawing: the kiosk
 * stopped between archiving it and clearing the journal (a power cut, a kill), so the
 * journal's drawing is one already archived; 0 when not (or no archive); -errno. */
int autosave_archived_already(struct autosave *a, const struct doc *d, const struct tree *t);
/* The number in an archived drawing's name "drawing-NNNNNN.edaha", or 0 for another name. */
unsigned autosave_archive_number(const char *name);
