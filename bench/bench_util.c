/* SPDX-License-Identifier: MIT */
#include "bench_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

bool bench_quick;

int bench_init(int *argc, char **argv, const char *operands)
{
	int kept = 1;

	for (int i = 1; i < *argc; i++) {
		if (strcmp(argv[i], "--quick") == 0)
			bench_quick = true;
		else if (argv[i][0] == '-' || !operands)
			goto usage;
		else
			argv[kept++] = argv[i];
	}
	*argc = kept;
	argv[kept] = NULL;
	if (bench_quick)
		printf("(--quick: the smallest sizes, %d repetitions at most: a test, not figures "
		       "to quote)\n", bench_reps(1000));
	return 0;
usage:
	fprintf(stderr, "usage: %s [--quick]%s%s\n"
		"  --quick  the smallest sizes, one or two repetitions (a test, not figures)\n",
		argv[0], operands ? " " : "", operands ? operands : "");
	return 1;
}

int bench_reps(int reps)
{
	return bench_quick && reps > 2 ? 2 : reps;
}

size_t bench_count(size_t n)
{
	return bench_quick && n > 2 ? 2 : n;
}

double bench_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

double bench_median(double *v, size_t n)
{
	if (n == 0)
		return 0.0;
	qsort(v, n, sizeof(*v), cmp_double);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double bench_run(void (*fn)(void *arg), void *arg, int reps)
{
	double *t = calloc((size_t)reps, sizeof(*t));
	double m;

	if (!t)
		return NAN;
	for (int i = 0; i < reps; i++) {
		double t0 = bench_now();

		fn(arg);
		t[i] = bench_now() - t0;
	}
	m = bench_median(t, (size_t)reps);
	free(t);
	return m;
}

void bench_row(const char *name, double size, double median_s, double *prev_size, double *prev_s)
{
	if (*prev_size > 0 && *prev_s > 0) {
		/* exponent k in cost ~ size^k between this row and the previous one */
		double k = log(median_s / *prev_s) / log(size / *prev_size);

		printf("%-28s %10.0f %12.3f ms   x%.2f for x%.1f size (~n^%.2f)\n", name, size,
		       median_s * 1e3, median_s / *prev_s, size / *prev_size, k);
	} else {
		printf("%-28s %10.0f %12.3f ms\n", name, size, median_s * 1e3);
	}
	*prev_size = size;
	*prev_s = median_s;
}
