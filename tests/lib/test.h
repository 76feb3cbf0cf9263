/* SPDX-License-Identifier: MIT */
#pragma once

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "test_config.h"

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

/*
 * How many seeded random cases a property test runs: n in the plain build; under
 * ASan+UBSan, where a case costs 3 to 10 times as much, a quarter (at least one). The
 * sanitizers look for memory errors and undefined behaviour, which the first cases to
 * reach a path show; the property itself is checked on all n by the plain build, which
 * tools/test runs too.
 */
static inline int test_cases(int n)
{
	return TEST_SANITIZED ? (n + 3) / 4 : n;
}
