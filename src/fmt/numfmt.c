/* SPDX-License-Identifier: MIT */
#include "numfmt.h"

#include <math.h>

#define NUMFMT_LIMIT 1e12

size_t numfmt_micro(char out[NUMFMT_MAX], double v, bool trim)
{
	char digits[24];
	unsigned long long a;
	long long q;
	size_t len = 0, n = 0;
	int frac = 6;

	if (!isfinite(v))
		v = 0.0;
	v = v < -NUMFMT_LIMIT ? -NUMFMT_LIMIT : v > NUMFMT_LIMIT ? NUMFMT_LIMIT : v;
	q = llround(v * 1e6);
	a = q < 0 ? (unsigned long long)-q : (unsigned long long)q;
	if (trim) {
		while (frac > 0 && a % 10 == 0) {
			a /= 10;
			frac--;
		}
	}
	do {
		digits[n++] = (char)('0' + a % 10);
		a /= 10;
	} while (a || (int)n <= frac);
	if (q < 0)
		out[len++] = '-';
	while (n) {
		if ((int)n == frac)
			out[len++] = '.';
		out[len++] = digits[--n];
	}
	out[len] = '\0';
	return len;
}
