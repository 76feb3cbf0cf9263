/* SPDX-License-Identifier: MIT */
/* The pen-to-screen histogram: percentiles to the bucket, flips counted, the format. */
#include <stdlib.h>
#include <string.h>

#include "latency.h"
#include "test.h"

int main(void)
{
	struct latency *l = malloc(sizeof(*l));
	char line[256];

	CHECK(l);
	latency_init(l);
	CHECK_INT(latency_percentile(l, 0.5), 0);
	latency_format(l, line, sizeof(line));
	CHECK(strstr(line, "no pen events"));

	/* 1..100 ms, one event each: the median is 50 ms, p90 90 ms, to the 0.1 ms bucket */
	for (unsigned i = 1; i <= 100; i++)
		latency_add(l, i * 1000u + 50u, i <= 95 ? 1 : i <= 99 ? 2 : 5);
	CHECK_INT(l->n, 100);
	CHECK_INT(latency_percentile(l, 0.5), 50100);
	CHECK_INT(latency_percentile(l, 0.9), 90100);
	CHECK_INT(latency_percentile(l, 0.0), 1100);
	CHECK_INT(latency_percentile(l, 1.0), 100050); /* the maximum, not its bucket's bound */
	CHECK_INT(l->max_us, 100050);
	CHECK_INT(l->flips[0], 95);
	CHECK_INT(l->flips[1], 4);
	CHECK_INT(l->flips[2], 1);
	latency_format(l, line, sizeof(line));
	CHECK(strstr(line, "100 pen events to screen: median 50.1 ms, p90 90.1 ms"));
	CHECK(strstr(line, "max 100.0 ms; 95.0% by the next flip, 4.0% a frame later, 1.0% later"));

	/* past the last bucket: counted there, the percentile says the true maximum */
	latency_init(l);
	latency_add(l, 5000000u, 1);
	latency_add(l, 10u, 0);
	CHECK_INT(latency_percentile(l, 1.0), 5000000);
	CHECK_INT(latency_percentile(l, 0.5), 100);
	CHECK_INT(l->flips[0], 2);
	free(l);
	return 0;
}
