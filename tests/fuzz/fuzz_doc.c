/* SPDX-License-Identifier: MIT */
/* libFuzzer: the document loader, and the app rebuilding whatever it accepts. */
#include <stddef.h>
#include <stdint.h>

#include "app.h"
#include "doc.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct error err;
	struct doc d;
	struct app *app;

	if (doc_parse((const char *)data, size, "fuzz.edaha", &d, &err) < 0)
		return 0;
	/* Keep rebuilds cheap: huge accepted documents are valid but slow, not bugs. */
	app = d.nops < 64 ? app_create(320, 200, 1) : NULL;
	if (app && app_load_doc(app, &d) == 0) {
		struct buf b;

		buf_init(&b);
		(void)doc_serialize(&app->doc, &app->tree, &b);
		buf_finish(&b);
	}
	app_destroy(app);
	doc_finish(&d);
	return 0;
}
