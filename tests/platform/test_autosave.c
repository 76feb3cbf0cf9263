/* SPDX-License-Identifier: MIT */
/*
 * The autosave journal: a session's edits appended one by one read back as the drawing;
 * a journal cut at any byte of its last record (a power cut) reads back as the drawing
 * before that edit; a damaged or foreign file starts a new drawing and is kept aside;
 * the archive numbers drawings and keeps only so many.
 */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"
#include "autosave.h"
#include "buf.h"
#include "test.h"
#include "trace.h"

#define MAX_STATES 64

static char *serialize(const struct doc *d)
{
	struct buf b;
	char *s;

	buf_init(&b);
	CHECK_INT(doc_serialize(d, NULL, &b), 0);
	CHECK_INT(buf_append(&b, "", 1), 0);
	s = strdup((const char *)b.data);
	buf_finish(&b);
	return s;
}

static char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	char *data;
	long n;

	CHECK(f);
	CHECK_INT(fseek(f, 0, SEEK_END), 0);
	n = ftell(f);
	rewind(f);
	data = malloc((size_t)n + 1);
	CHECK(data);
	CHECK_INT((long)fread(data, 1, (size_t)n, f), n);
	fclose(f);
	*len = (size_t)n;
	return data;
}

static void spit(const char *path, const char *data, size_t len)
{
	FILE *f = fopen(path, "wb");

	CHECK(f);
	CHECK_INT((long)fwrite(data, 1, len, f), (long)len);
	CHECK_INT(fclose(f), 0);
}

/* Restores into a new doc and checks it is `want` (NULL: no drawing). */
static void check_restore(const char *dir, const char *want, bool expect_warn)
{
	struct error err = { { 0 } }, warn = { { 0 } };
	struct autosave *a = autosave_create(dir, &err);
	struct doc d;
	int ret;

	CHECK(a);
	doc_init(&d, 0);
	ret = autosave_restore(a, &d, &warn, &err);
	CHECK(ret >= 0);
	if (expect_warn != (warn.msg[0] != '\0')) {
		fprintf(stderr, "warning expected %d, got \"%s\"\n", expect_warn, warn.msg);
		CHECK(false);
	}
	if (want) {
		char *got = serialize(&d);

		CHECK_INT(ret, 1);
		if (strcmp(got, want) != 0) {
			fprintf(stderr, "restored:\n%s\nwanted:\n%s\n", got, want);
			CHECK(false);
		}
		free(got);
	} else {
		CHECK_INT(ret, 0);
	}
	doc_finish(&d);
	autosave_destroy(a);
}

static void press(struct app *app, enum button b, uint64_t t)
{
	struct event ev = { .type = EVENT_BUTTON, .time_us = t, .button = b, .pressed = true };

	app_handle_event(app, &ev);
	ev.pressed = false;
	ev.time_us += 1000;
	app_handle_event(app, &ev);
}

int main(int argc, char **argv)
{
	char tmpl[] = "/tmp/edaha-autosave-XXXXXX", path[600], bad[640], name[64];
	char *states[MAX_STATES];
	size_t ends[MAX_STATES], nstates = 0, len;
	struct error err = { { 0 } };
	struct trace t;
	struct app *app;
	struct autosave *a;
	char *data;

	CHECK(argc == 2);
	CHECK(mkdtemp(tmpl));
	snprintf(path, sizeof(path), "%s/%s", tmpl, AUTOSAVE_JOURNAL);
	trace_init(&t);
	CHECK_INT(trace_load(argv[1], 1280, 800, &t, &err), 0);
	app = app_create(1280, 800, 7);
	CHECK(app);

	/* no journal yet: nothing to restore, no warning */
	check_restore(tmpl, NULL, false);

	a = autosave_create(tmpl, &err);
	CHECK(a);
	CHECK_INT(autosave_start(a, &app->doc, &err), 0);
	CHECK(!autosave_pending(a, &app->doc));
	states[nstates] = serialize(&app->doc);
	ends[nstates++] = (size_t)-1;
	/* the session, then undo twice, redo, undo and a new stroke (drops the redo) */
	for (size_t i = 0; i <= t.nevents + 5; i++) {
		if (i < t.nevents) {
			app_handle_event(app, &t.events[i]);
		} else if (i == t.nevents + 5) {
			for (size_t k = 0; k < t.nevents && k < 40; k++) {
				struct event ev = t.events[k];

				ev.time_us += 100000000u;
				app_handle_event(app, &ev);
			}
		} else {
			static const enum button seq[] = { BUTTON_UNDO, BUTTON_UNDO, BUTTON_REDO,
							   BUTTON_UNDO, BUTTON_UNDO };
			press(app, seq[i - t.nevents], 90000000u + i * 10000u);
		}
		if (!autosave_pending(a, &app->doc))
			continue;
		CHECK_INT(autosave_sync(a, &app->doc, &err), 0);
		CHECK(!autosave_pending(a, &app->doc));
		CHECK(nstates < MAX_STATES);
		states[nstates] = serialize(&app->doc);
		free(slurp(path, &ends[nstates]));
		nstates++;
	}
	autosave_destroy(a);
	fprintf(stderr, "autosave: %zu records, journal %zu bytes\n", nstates - 1, ends[nstates - 1]);
	CHECK(nstates >= 8); /* the trace's strokes and edits, the undos, the new stroke */

	/* the whole journal is the drawing as it is */
	check_restore(tmpl, states[nstates - 1], false);

	/* cut anywhere in the last record: the drawing before it, with a warning */
	data = slurp(path, &len);
	CHECK_INT(len, ends[nstates - 1]);
	for (size_t cut = ends[nstates - 2]; cut < len; cut++) {
		spit(path, data, cut);
		check_restore(tmpl, states[nstates - 2], cut != ends[nstates - 2]);
	}
	/* a flipped byte in the middle record: everything before it */
	{
		size_t mid = nstates / 2, at = (ends[mid - 1] + ends[mid]) / 2;

		data[at] ^= 0x20;
		spit(path, data, len);
		check_restore(tmpl, states[mid - 1], true);
		data[at] ^= 0x20;
	}
	/* restarted from the restored drawing (compaction): the same drawing, one record */
	spit(path, data, len);
	{
		struct doc d;
		struct error warn;

		a = autosave_create(tmpl, &err);
		doc_init(&d, 0);
		CHECK_INT(autosave_restore(a, &d, &warn, &err), 1);
		CHECK_INT(autosave_start(a, &d, &err), 0);
		autosave_destroy(a);
		doc_finish(&d);
		free(slurp(path, &len));
		CHECK(len < ends[nstates - 1]);
		check_restore(tmpl, states[nstates - 1], false);
	}
	/* not a journal: a new drawing, the file kept aside */
	spit(path, "hello\n", 6);
	check_restore(tmpl, NULL, true);
	snprintf(bad, sizeof(bad), "%s.bad", path);
	CHECK(access(bad, F_OK) == 0);
	CHECK(access(path, F_OK) != 0);
	/* a symlink in its place: moved aside, its target untouched */
	CHECK_INT(unlink(bad), 0);
	CHECK_INT(symlink("/etc/passwd", path), 0);
	check_restore(tmpl, NULL, true);
	{
		struct stat st;

		CHECK(access(path, F_OK) != 0);
		CHECK_INT(lstat(bad, &st), 0);
		CHECK(S_ISLNK(st.st_mode));
		CHECK_INT(unlink(bad), 0);
	}

	/* the archive: numbered, the oldest beyond keep removed */
	a = autosave_create(tmpl, &err);
	CHECK_INT(autosave_archived_already(a, &app->doc, &app->tree), 0); /* none yet */
	for (int i = 1; i <= 5; i++) {
		char want[32];

		CHECK_INT(autosave_archive(a, &app->doc, &app->tree, 3, name, sizeof(name), &err), 0);
		snprintf(want, sizeof(want), "drawing-%06d.edaha", i);
		CHECK(strcmp(name, want) == 0);
	}
	snprintf(bad, sizeof(bad), "%s/archive/drawing-000002.edaha", tmpl);
	CHECK(access(bad, F_OK) != 0);
	snprintf(bad, sizeof(bad), "%s/archive/drawing-000003.edaha", tmpl);
	CHECK(access(bad, F_OK) == 0);
	/* a stop between the archive and the clean canvas: the journal's drawing is the
	 * newest archived one, byte for byte; another drawing (one op fewer) is not */
	CHECK_INT(autosave_archived_already(a, &app->doc, &app->tree), 1);
	if (app->doc.cursor > 0) {
		struct doc fewer = app->doc;

		fewer.cursor--;
		CHECK_INT(autosave_archived_already(a, &fewer, &app->tree), 0);
	}
	autosave_destroy(a);

	for (size_t i = 0; i < nstates; i++)
		free(states[i]);
	free(data);
	app_destroy(app);
	trace_finish(&t);
	return system((snprintf(bad, sizeof(bad), "rm -rf %s", tmpl), bad)) == 0 ? 0 : 1;
}
