/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

/* Monotonic seconds. */
double bench_now(void);
/* Sorts v in place and returns its median. */
double bench_median(double *v, size_t n);
/* Runs fn(arg) `reps` times and returns the median wall time in seconds. */
double bench_run(void (*fn)(void *arg), void *arg, int reps);
/* Prints "name size median_ms growth" rows consistently; growth is vs the previous row. */
void bench_row(const char *name, double size, double median_s, double *prev_size, double *prev_s);
