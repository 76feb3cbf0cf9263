/* SPDX-License-Identifier: MIT */
/* The drawing kept: the journal (autosave.h) restored at the start and written after every
 * edit, and the idle reset that archives the drawing and gives the next visitor a clean
 * canvas. */
#include "kiosk_private.h"

#include <errno.h>
#include <stdio.h>
#include <sys/random.h>
#include <unistd.h>

/* A new drawing's seed: a different tree for each visitor's same strokes. */
static uint64_t fresh_seed(void)
{
	uint64_t seed;

	if (getrandom(&seed, sizeof(seed), GRND_NONBLOCK) != (ssize_t)sizeof(seed))
		seed = kiosk_now_us() ^ ((uint64_t)getpid() << 32);
	return seed;
}

/* The journal: the drawing it holds comes back (unless one was loaded), then it starts
 * afresh from what the app shows. Only an out-of-memory stops the kiosk: a kiosk that
 * cannot save still draws. */
int kiosk_start_autosave(struct kiosk *k)
{
	struct error err = { { 0 } }, warn = { { 0 } };
	struct doc doc;
	int ret;

	k->autosave = autosave_create(k->cfg.state_dir, &err);
	if (!k->autosave) {
		fprintf(stderr, "edaha: warning: autosave: %s; drawings are not kept\n", err.msg);
		return 0;
	}
	if (!k->cfg.doc) {
		doc_init(&doc, 0);
		ret = autosave_restore(k->autosave, &doc, &warn, &err);
		if (warn.msg[0])
			fprintf(stderr, "edaha: warning: autosave: %s\n", warn.msg);
		if (ret < 0)
			fprintf(stderr, "edaha: warning: autosave: %s; starting a new drawing\n",
				err.msg);
		if (ret > 0) {
			size_t nops = doc.nops, cursor = doc.cursor;

			if (app_load_doc(k->app, &doc) < 0) {
				fputs("edaha: out of memory restoring the drawing\n", stderr);
				return -ENOMEM;
			}
			fprintf(stderr, "edaha: autosave: the drawing is back from %s (%zu edits, %zu in effect)\n",
				autosave_path(k->autosave), nops, cursor);
			/* stopped between the idle reset's archive and its clean canvas: that
			 * drawing is kept already, and would be archived (and planted) twice */
			if (autosave_archived_already(k->autosave, &k->app->doc, &k->app->tree) == 1) {
				fputs("edaha: autosave: that drawing was archived before the stop: a new canvas\n",
				      stderr);
				if (app_reset(k->app, fresh_seed()) < 0) {
					doc_finish(&doc);
					return -ENOMEM;
				}
			}
		}
		doc_finish(&doc);
	}
	if (autosave_start(k->autosave, &k->app->doc, &err) < 0) {
		fprintf(stderr, "edaha: warning: autosave: %s\n", err.msg);
		k->autosave_failing = true;
	}
	return 0;
}

/* Every committed stroke and edit goes to the journal before anything else happens. */
void kiosk_save_edits(struct kiosk *k)
{
	struct error err = { { 0 } };

	if (!k->autosave || !autosave_pending(k->autosave, &k->app->doc))
		return;
	if (autosave_sync(k->autosave, &k->app->doc, &err) < 0) {
		if (!k->autosave_failing)
			fprintf(stderr, "edaha: warning: autosave: %s; trying again at the next edit\n",
				err.msg);
		k->autosave_failing = true;
	} else if (k->autosave_failing) {
		fputs("edaha: autosave works again\n", stderr);
		k->autosave_failing = false;
	}
}

/* New pressed after something was drawn (app_take_replaced): that drawing goes to the
 * archive as it stood, its ops then in effect and its tree (the summary), as the idle
 * reset archives one (docs/forest.md: it joins today's forest). */
void kiosk_archive_replaced(struct kiosk *k)
{
	struct error err = { { 0 } };
	struct tree t;
	struct doc then;
	size_t cursor;
	char name[64] = "";

	if (!app_take_replaced(k->app, &t, &cursor))
		return;
	if (k->autosave) {
		/* the same ops, fewer in effect: a view of the document, not a copy */
		then = k->app->doc;
		then.cursor = cursor <= then.nops ? cursor : then.nops;
		if (autosave_archive(k->autosave, &then, &t, k->cfg.archive_keep, name, sizeof(name),
				     &err) < 0)
			fprintf(stderr, "edaha: warning: New: cannot archive the drawing: %s\n",
				err.msg);
		else
			fprintf(stderr, "edaha: New: the drawing is archived as %s/%s\n",
				AUTOSAVE_ARCHIVE_DIR, name);
		if (name[0])
			kiosk_forest_archived(k, name, false);
	}
	tree_finish(&t);
}

/* Nobody drew for reset_after: the drawing goes to the archive, the next visitor gets
 * a clean canvas (the attract screen stays up). */
void kiosk_idle_reset(struct kiosk *k, uint64_t now)
{
	struct error err = { { 0 } };
	char name[64] = "";
	uint64_t number = 0;

	if (now < kiosk_reset_at(k->app, k->cfg.reset_after_us))
		return;
	if (k->autosave && autosave_archive(k->autosave, &k->app->doc, &k->app->tree,
					    k->cfg.archive_keep, name, sizeof(name), &err) < 0)
		fprintf(stderr, "edaha: warning: idle reset: cannot archive the drawing: %s\n", err.msg);
	/* a drawing without a tree is archived too, but never planted */
	if (name[0] && k->app->tree.nbranches)
		number = kiosk_forest_archived(k, name, true);
	else if (name[0])
		kiosk_forest_refresh(k);
	if (app_reset(k->app, fresh_seed()) < 0) {
		kiosk_fail(k, "idle reset", -ENOMEM);
		return;
	}
	fprintf(stderr, "edaha: idle for %.0f s: %s%s%s; a new canvas\n",
		(double)(now - k->app->last_time_us) / 1e6,
		name[0] ? "the drawing is archived as " : "the drawing is cleared",
		name[0] ? AUTOSAVE_ARCHIVE_DIR "/" : "", name);
	/* whoever comes back for it: where it stands */
	if (number)
		kiosk_forest_tell(k, number);
	kiosk_save_edits(k);
}
