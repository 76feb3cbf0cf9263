/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

/*
 * How long pen input takes to reach the screen: a histogram of the time from each pen
 * event's kernel timestamp to the page flip that showed it, and how many flips that took
 * (1: the very next flip showed it; 2: it waited one frame). Buckets of 0.1 ms up to 2 s
 * keep percentiles exact to 0.1 ms in constant memory however long the kiosk runs. Pure.
 */
#define LATENCY_BUCKET_US 100u
#define LATENCY_BUCKETS 20000u /* the last one holds everything from 2 s on */
#define LATENCY_FLIPS 3        /* next flip, the one after, later */

struct latency {
	uint32_t counts[LATENCY_BUCKETS];
	uint64_t n, sum_us, max_us;
	uint64_t flips[LATENCY_FLIPS];
};

void latency_init(struct latency *l);
/* One event shown us after its timestamp, by the flips-th flip after it came (>= 1). */
void latency_add(struct latency *l, uint64_t us, unsigned flips);
/* The smallest bucket bound that at least p (0..1) of the events lie under, in µs, at
 * most the largest seen; 0 with no events. */
uint64_t latency_percentile(const struct latency *l, double p);
/* "412 pen events to screen: median 14.2 ms, p90 ..., p99 ..., max ...; 97.1% by the
 * next flip, 2.9% a frame later, 0.0% later" (or "no pen events"). */
void latency_format(const struct latency *l, char *out, size_t size);
