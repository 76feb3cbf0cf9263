/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: today's forest's day file (forest_day_read, docs/forest.md "Which trees") on
 * arbitrary bytes. A refusal names the file and a line of it ("fuzz:LINE: "; only running
 * out of memory may name the file alone) and changes nothing. What is accepted has a start
 * a signed second count holds, reads the same a second time, and written back by
 * forest_day_write reads back the same.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "forest.h"
#include "fuzz_refusal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct forest_day day = { 123456789, 42 }, again = { 0 }, back = { 0 };
	struct error err = { { 0 } };
	struct buf b;
	int ret = forest_day_read((const char *)data, size, "fuzz", &day, &err);

	if (ret < 0) {
		fuzz_check_refusal(ret, &err, fuzz_lines_of(data, size));
		if (day.start != 123456789 || day.first != 42)
			abort();
		return 0;
	}
	if (ret != 0 || day.start < 0)
		abort();
	if (forest_day_read((const char *)data, size, "again", &again, &err) != 0 ||
	    again.start != day.start || again.first != day.first)
		abort();
	buf_init(&b);
	if (forest_day_write(&day, &b) != 0 ||
	    forest_day_read((const char *)b.data, b.len, "written", &back, &err) != 0 ||
	    back.start != day.start || back.first != day.first)
		abort();
	buf_finish(&b);
	return 0;
}
