/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

/*
 * Every bench takes --quick: its smallest sizes and one or two repetitions, so that the
 * tests run each one under ASan+UBSan (bench/meson.build) and a bench that crashes,
 * leaks or reads freed memory fails CI. Its figures are then not worth quoting.
 */
extern bool bench_quick;
/* Reads --quick and takes it out of argv; what is left are the bench's operands, which
 * `operands` names in the usage ("[TREE.json]"; NULL: it takes none). 0, or 1 after
 * printing the usage (an unknown option, or operands it does not take). */
int bench_init(int *argc, char **argv, const char *operands);
/* reps, or at most 2 with --quick */
int bench_reps(int reps);
/* How many of n sizes (smallest first) to run: all, or the first two with --quick. */
size_t bench_count(size_t n);
#define BENCH_COUNT(array) bench_count(sizeof(array) / sizeof((array)[0]))

/* Monotonic seconds. */
double bench_now(void);
/* Sorts v in place and returns its median. */
double bench_median(double *v, size_t n);
/* Runs fn(arg) `reps` times and returns the median wall time in seconds. */
double bench_run(void (*fn)(void *arg), void *arg, int reps);
/* Prints "name size median_ms growth" rows consistently; growth is vs the previous row. */
void bench_row(const char *name, double size, double median_s, double *prev_size, double *prev_s);
