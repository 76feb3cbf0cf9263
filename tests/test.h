/* SPDX-License-Identifier: MIT */
#pragma once

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/*
 * Minimal test helpers: each test program runs its checks and exits non-zero on the
 * first failure, printing where. Meson counts programs.
 */
#define CHECK(cond)                                                                       \
	do {                                                                              \
		if (!(cond)) {                                                            \
			fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
			exit(1);                                                          \
		}                                                                         \
	} while (0)

#define CHECK_NEAR(a, b, eps)                                                             \
	do {                                                                              \
		double a_ = (a), b_ = (b);                                                \
		if (!(fabs(a_ - b_) <= (eps))) {                                          \
			fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.9g, %s = %.9g (eps %g)\n", \
				__FILE__, __LINE__, #a, a_, #b, b_, (double)(eps));       \
			exit(1);                                                          \
		}                                                                         \
	} while (0)

#define CHECK_INT(a, b)                                                                   \
	do {                                                                              \
		long long a_ = (long long)(a), b_ = (long long)(b);                       \
		if (a_ != b_) {                                                           \
			fprintf(stderr, "%s:%d: CHECK_INT failed: %s = %lld, %s = %lld\n", __FILE__, \
				__LINE__, #a, a_, #b, b_);                                \
			exit(1);                                                          \
		}                                                                         \
	} while (0)
