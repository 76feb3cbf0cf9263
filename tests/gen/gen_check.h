/* SPDX-License-Identifier: MIT */
#pragma once

/* What gen_check's commands share (gen_check.c says what each asserts). */
#include <stdbool.h>
#include <stddef.h>

#include "skel.h"

/* M_PI is POSIX, not C11. */
#define PI 3.14159265358979323846
#define DEG_PER_RAD (180.0 / PI)

/* A broken rule: counted, and the first few printed. */
void bad(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
extern int failures;
/* The exit status: 0, or 1 with the count of broken rules. */
int finish(const char *what);

/* Loads or exits 2: a file the command cannot read is a broken test, said plainly. */
void load_skel(const char *path, struct skel *s);
/* Comma-separated numbers into v (at most max): how many. */
int parse_list(const char *s, double *v, int max);

double dot3(const double a[3], const double b[3]);
double dist3(const double a[3], const double b[3]);
/* The angle between unit vectors, degrees. */
double angle_deg(const double a[3], const double b[3]);
/* The signed angle from a to b about the unit axis k (right-handed), degrees in
 * [0, 360), of their parts across k. */
double azimuth_deg(const double a[3], const double b[3], const double k[3]);
/* Each branch's place among its siblings in id order (rank), and how many children each
 * has (nkids): arrays of s->nbranches, freed by the caller. */
void family(const struct skel *s, int **rank, int **nkids);

int check_tree(int argc, char **argv);
int check_radii(int argc, char **argv);
int check_palm(int argc, char **argv);
int check_angles(int argc, char **argv);
int check_spread(int argc, char **argv);
int check_clip(int argc, char **argv);
int check_precision(int argc, char **argv);
int check_param(int argc, char **argv);
