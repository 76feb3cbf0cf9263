/* SPDX-License-Identifier: MIT */
/* libFuzzer: the autosave journal's replay, whatever a power cut or a bad card left. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "journal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct journal_replay r;
	struct error err;
	struct doc d;

	doc_init(&d, 0);
	if (journal_replay((const char *)data, size, "fuzz.journal", &d, &r, &err) == 0) {
		/* what it gives is a drawing the app can take, and it read what it says */
		if (d.cursor > d.nops || d.nops > DOC_MAX_OPS || doc_total_points(&d) > DOC_MAX_POINTS ||
		    r.good > size || (!r.torn && r.good != size))
			abort();
		/* written back and read again: the same drawing */
		{
			struct buf b;
			struct doc e;

			buf_init(&b);
			doc_init(&e, 0);
			if (journal_header(&b) == 0 && journal_record(&d, 0, &b) == 0 &&
			    (journal_replay((const char *)b.data, b.len, "again", &e, &r, &err) != 0 ||
			     r.torn || e.nops != d.nops || e.cursor != d.cursor || e.seed != d.seed))
				abort();
			doc_finish(&e);
			buf_finish(&b);
		}
	}
	doc_finish(&d);
	return 0;
}
