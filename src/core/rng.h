/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

/* The one source of randomness in src/: seeded from the document, so replays repeat. */
struct rng {
	uint64_t s[4];
};

void rng_seed(struct rng *r, uint64_t seed);
uint64_t rng_next(struct rng *r);
/* Uniform in [0, 1). */
double rng_uniform(struct rng *r);
/* Uniform in [lo, hi). */
double rng_range(struct rng *r, double lo, double hi);
