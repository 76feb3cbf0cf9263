/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "buf.h"
#include "doc.h"
#include "error.h"

/*
 * The autosave journal (docs/journal-format.md): a drawing as a run of records, each
 * "ops from index FROM on are these, and the cursor is C", appended one per committed
 * edit. Replaying them in order gives the drawing; a record cut short or damaged by a
 * power cut (length or CRC-32 wrong) ends the replay there, losing only that edit.
 * Each record's ops are a drawing.edaha document, so the journal reads with the
 * document's own parser and limits.
 */
#define JOURNAL_VERSION 1
/* A record larger than a drawing file can be is damage, not data. */
#define JOURNAL_MAX_RECORD DOC_MAX_FILE_BYTES

int journal_header(struct buf *out);
/* The record that takes a journal holding d's ops[0..from) (with any cursor) to d.
 * 0 or -ENOMEM. */
int journal_record(const struct doc *d, size_t from, struct buf *out);

struct journal_replay {
	size_t records; /* records applied */
	size_t good;    /* bytes of data they and the header take: the rest is torn */
	bool torn;      /* something followed them that did not read */
	struct error tail; /* what was wrong with it, "name:line: ..." */
};

/*
 * Replays a journal into *d (doc_init'ed by the caller, replaced). 0 on success, also
 * with a torn tail (r->torn); -EINVAL with err when the data is not an edaha journal at
 * all (wrong header or version); -ENOMEM. On failure *d holds an empty drawing.
 */
int journal_replay(const char *data, size_t len, const char *name, struct doc *d,
		   struct journal_replay *r, struct error *err);
