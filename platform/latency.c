/* SPDX-License-Identifier: MIT */
#include "latency.h"

#include <stdio.h>
#include <string.h>

void latency_init(struct latency *l)
{
	memset(l, 0, sizeof(*l));
}

void latency_add(struct latency *l, uint64_t us, unsigned flips)
{
	uint64_t b = us / LATENCY_BUCKET_US;

	l->counts[b < LATENCY_BUCKETS ? b : LATENCY_BUCKETS - 1]++;
	l->n++;
	l->sum_us += us;
	if (us > l->max_us)
		l->max_us = us;
	/* flips 0 cannot happen (the frame that shows an event comes after it): count it
	 * with the next flip rather than lose it */
	l->flips[flips <= 1 ? 0 : flips == 2 ? 1 : 2]++;
}

uint64_t latency_percentile(const struct latency *l, double p)
{
	uint64_t want, seen = 0;

	if (l->n == 0)
		return 0;
	p = p < 0.0 ? 0.0 : p > 1.0 ? 1.0 : p;
	/* the rank of the p-th event, 1-based, at least the first */
	want = (uint64_t)(p * (double)l->n + 0.999999);
	if (want < 1)
		want = 1;
	for (uint32_t b = 0; b < LATENCY_BUCKETS; b++) {
		seen += l->counts[b];
		if (seen >= want) {
			uint64_t bound = (uint64_t)(b + 1) * LATENCY_BUCKET_US;

			/* the bucket's bound, but never past what was seen */
			return b + 1 < LATENCY_BUCKETS && bound < l->max_us ? bound : l->max_us;
		}
	}
	return l->max_us;
}

static double pct(uint64_t part, uint64_t all)
{
	return all ? 100.0 * (double)part / (double)all : 0.0;
}

void latency_format(const struct latency *l, char *out, size_t size)
{
	if (l->n == 0) {
		snprintf(out, size, "no pen events shown yet");
		return;
	}
	snprintf(out, size,
		 "%llu pen events to screen: median %.1f ms, p90 %.1f ms, p99 %.1f ms, max %.1f ms; "
		 "%.1f%% by the next flip, %.1f%% a frame later, %.1f%% later",
		 (unsigned long long)l->n, (double)latency_percentile(l, 0.5) / 1000.0,
		 (double)latency_percentile(l, 0.9) / 1000.0,
		 (double)latency_percentile(l, 0.99) / 1000.0, (double)l->max_us / 1000.0,
		 pct(l->flips[0], l->n), pct(l->flips[1], l->n), pct(l->flips[2], l->n));
}
