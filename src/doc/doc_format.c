/* SPDX-License-Identifier: MIT */
/*
 * drawing.edaha: line-based text, see docs/document-format.md. Every problem found while
 * reading names the line, because a teacher may well open one in a text editor.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "arrange.h"
#include "doc.h"
#include "gen.h"
#include "ori_kinds.h"
#include "propagate.h"
#include "tree.h"
#include "vine.h"
#include "wood.h"

static const char *const propagate_names[] = {
	[PROPAGATE_FIXED_COUNT] = "fixed-count",
	[PROPAGATE_FIXED_SIZE] = "fixed-size",
};

/* The editing ops' keywords, as written. */
static const char *const edit_keywords[] = {
	[DOC_OP_CLONE_ADD] = "clone-add",
	[DOC_OP_CLONE_REMOVE] = "clone-remove",
	[DOC_OP_ARRANGE] = "arrange",
	[DOC_OP_PROPAGATE] = "propagate",
};

static const char *pattern_name(const struct doc_op *op)
{
	if (op->kind == DOC_OP_ARRANGE)
		return arrange_pattern_name((enum arrange_pattern)op->pattern);
	if (op->pattern >= 0 && op->pattern <= PROPAGATE_FIXED_SIZE)
		return propagate_names[op->pattern];
	return NULL;
}

#define MAX_FIELDS 8

/* import T B, then each branch: PARENT PARENT_T GENERATION N, and its N points X Y Z R,
 * numbers written to read back bit for bit. */
static int write_import(const struct doc_op *op, struct buf *out)
{
	const struct tree *t = op->import;
	size_t n = t ? t->nbranches : 0;

	buf_printf(out, "import %llu %zu\n", (unsigned long long)op->time_us, n);
	for (size_t i = 0; i < n; i++) {
		const struct branch *b = &t->branches[i];

		buf_printf(out, "%d ", b->parent);
		buf_print_exact(out, b->parent_t);
		buf_printf(out, " %d %zu\n", b->generation, b->npoints);
		for (size_t k = 0; k < b->npoints; k++) {
			buf_print_exact(out, b->points[k].x);
			buf_printf(out, " ");
			buf_print_exact(out, b->points[k].y);
			buf_printf(out, " ");
			buf_print_exact(out, b->points[k].z);
			buf_printf(out, " ");
			buf_print_exact(out, b->radii[k]);
			buf_printf(out, "\n");
		}
	}
	return out->failed ? -ENOMEM : 0;
}

int doc_serialize(const struct doc *d, const struct tree *t, struct buf *out)
{
	buf_printf(out, "edaha-drawing %d\n", DOC_FORMAT_VERSION);
	buf_printf(out, "# The history is the drawing; the tree section is a summary for other tools.\n");
	buf_printf(out, "seed %llu\n", (unsigned long long)d->seed);
	if (!camera_is_front(d->view))
		buf_printf(out, "view %.9g %.9g\n", (double)d->view.yaw, (double)d->view.pitch);
	buf_printf(out, "history %zu %zu\n", d->nops, d->cursor);
	for (size_t i = 0; i < d->nops; i++) {
		const struct doc_op *op = &d->ops[i];

		switch (op->kind) {
		case DOC_OP_STROKE:
			buf_printf(out, "stroke %s %llu %zu", event_tool_name(op->tool),
				   (unsigned long long)op->time_us, op->npoints);
			if (!camera_is_front(op->camera))
				buf_printf(out, " %.9g %.9g", (double)op->camera.yaw,
					   (double)op->camera.pitch);
			buf_printf(out, "\n");
			for (size_t k = 0; k < op->npoints; k++) {
				const struct doc_point *p = &op->points[k];

				buf_printf(out, "%.9g %.9g %.9g %lu\n", (double)p->x, (double)p->y,
					   (double)p->pressure, (unsigned long)p->dt_us);
			}
			break;
		case DOC_OP_NEW:
			buf_printf(out, "new %llu\n", (unsigned long long)op->time_us);
			break;
		case DOC_OP_LIFT:
			buf_printf(out, "lift %llu\n", (unsigned long long)op->time_us);
			break;
		case DOC_OP_GENERATE:
			/* the version it was made with: an older drawing's tree stays as it was */
			buf_printf(out, "generate %llu %d %llu ", (unsigned long long)op->time_us,
				   op->params ? op->params->gen_version : GEN_VERSION,
				   (unsigned long long)op->seed);
			if (op->params && gen_write(op->params, out) < 0)
				return -ENOMEM;
			buf_printf(out, "\n");
			break;
		case DOC_OP_SEASON:
			buf_printf(out, "season %llu %s\n", (unsigned long long)op->time_us,
				   season_name((enum season)op->pattern));
			break;
		case DOC_OP_LEAFTYPE:
			buf_printf(out, "leaftype %llu %s\n", (unsigned long long)op->time_us,
				   ori_kind_name(op->pattern) ? ori_kind_name(op->pattern) : "drawn");
			break;
		case DOC_OP_VINE:
			buf_printf(out, "vine %llu", (unsigned long long)op->time_us);
			for (int k = 0; k < 3; k++) {
				buf_printf(out, " ");
				buf_print_exact(out, op->plant[k]);
			}
			buf_printf(out, " ");
			if (op->vine && vine_write(op->vine, out) < 0)
				return -ENOMEM;
			buf_printf(out, "\n");
			break;
		case DOC_OP_GROW:
			buf_printf(out, "grow %llu ", (unsigned long long)op->time_us);
			if (op->wood && wood_write(op->wood, out) < 0)
				return -ENOMEM;
			buf_printf(out, "\n");
			break;
		case DOC_OP_IMPORT:
			if (write_import(op, out) < 0)
				return -ENOMEM;
			break;
		case DOC_OP_CLONE_ADD:
		case DOC_OP_CLONE_REMOVE:
			buf_printf(out, "%s %llu %d\n", edit_keywords[op->kind],
				   (unsigned long long)op->time_us, op->branch);
			break;
		case DOC_OP_ARRANGE:
		case DOC_OP_PROPAGATE: {
			const char *name = pattern_name(op);

			buf_printf(out, "%s %llu %d %s\n", edit_keywords[op->kind],
				   (unsigned long long)op->time_us, op->branch, name ? name : "?");
			break;
		}
		}
	}
	if (t) {
		/* generated elements are their generate op's: the drawing stays parameters */
		buf_printf(out, "tree %zu %zu\n", t->nbranches, t->nleaves);
		for (size_t i = 0; i < t->nbranches; i++) {
			const struct branch *b = &t->branches[i];

			if (b->origin == ORIGIN_GENERATE)
				continue;
			buf_printf(out, "branch %d %d %d %s %zu\n", b->id, b->parent, b->generation,
				   origin_name(b->origin), b->npoints);
		}
		for (size_t i = 0; i < t->nleaves; i++) {
			const struct leaf *l = &t->leaves[i];

			if (l->origin == ORIGIN_GENERATE)
				continue;
			buf_printf(out, "leaf %d %d %s %zu\n", l->id, l->branch, origin_name(l->origin),
				   l->npoints);
		}
	}
	buf_printf(out, "end\n");
	return out->failed ? -ENOMEM : 0;
}

struct reader {
	const char *data, *end, *pos;
	const char *name;
	unsigned long line;
	struct error *err;
	char *copy; /* the current line, NUL-terminated and split in place */
	size_t copy_cap;
	char *fields[MAX_FIELDS + 1];
	int nfields;
};

/* Next non-blank, non-comment line, split into fields. 1 = got one, 0 = end, <0 error. */
static int reader_next(struct reader *r)
{
	while (r->pos < r->end) {
		const char *start = r->pos;
		const char *nl = memchr(start, '\n', (size_t)(r->end - start));
		size_t len = nl ? (size_t)(nl - start) : (size_t)(r->end - start);
		char *s;

		r->pos = nl ? nl + 1 : r->end;
		r->line++;
		if (len && start[len - 1] == '\r')
			len--;
		if (memchr(start, '\0', len))
			return error_at(r->err, -EINVAL, r->name, r->line, "binary data in a text file");
		if (len + 1 > r->copy_cap) {
			char *c = realloc(r->copy, len + 1);

			if (!c)
				return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
			r->copy = c;
			r->copy_cap = len + 1;
		}
		memcpy(r->copy, start, len);
		r->copy[len] = '\0';

		r->nfields = 0;
		for (s = r->copy; *s;) {
			while (*s == ' ' || *s == '\t')
				*s++ = '\0';
			if (!*s)
				break;
			if (r->nfields == 0 && *s == '#')
				break;
			/* a generated tree's parameters are the rest of its line, as YAML */
			if (r->nfields == 4 && !strcmp(r->fields[0], "generate")) {
				r->fields[r->nfields++] = s;
				break;
			}
			/* and a vine's, after its planting point; a grow press's settings */
			if ((r->nfields == 5 && !strcmp(r->fields[0], "vine")) ||
			    (r->nfields == 2 && !strcmp(r->fields[0], "grow"))) {
				r->fields[r->nfields++] = s;
				break;
			}
			if (r->nfields == MAX_FIELDS)
				return error_at(r->err, -EINVAL, r->name, r->line, "too many fields");
			r->fields[r->nfields++] = s;
			while (*s && *s != ' ' && *s != '\t')
				s++;
		}
		if (r->nfields > 0)
			return 1;
	}
	return 0;
}

static int expect_fields(struct reader *r, int n, const char *what)
{
	if (r->nfields != n)
		return error_at(r->err, -EINVAL, r->name, r->line, "expected %d fields for %s, got %d",
				n, what, r->nfields);
	return 0;
}

/* Sets *v only on success; callers still initialise it, as gcc -O3 cannot see that
 * error_at() is negative and warns (-Wmaybe-uninitialized) in release builds. */
static int parse_u64(struct reader *r, const char *s, uint64_t max, uint64_t *v, const char *what)
{
	char *endp;
	unsigned long long x;

	errno = 0;
	if (*s < '0' || *s > '9')
		goto bad;
	x = strtoull(s, &endp, 10);
	if (errno || *endp || x > max)
		goto bad;
	*v = x;
	return 0;
bad:
	return error_at(r->err, -EINVAL, r->name, r->line, "bad %s \"%s\"", what, s);
}

static int parse_float(struct reader *r, const char *s, float lo, float hi, float *v,
		       const char *what)
{
	char *endp;
	float x;

	errno = 0;
	x = strtof(s, &endp);
	if (endp == s || *endp || errno == ERANGE || !isfinite(x))
		return error_at(r->err, -EINVAL, r->name, r->line, "bad %s \"%s\"", what, s);
	if (x < lo || x > hi)
		return error_at(r->err, -EINVAL, r->name, r->line, "%s %s out of range %g..%g", what, s,
				(double)lo, (double)hi);
	*v = x;
	return 0;
}

/* YAW PITCH in degrees, as camera_normalize leaves them. */
static int parse_camera(struct reader *r, const char *yaw, const char *pitch, struct camera *c)
{
	int ret;

	if ((ret = parse_float(r, yaw, -180.0f, 180.0f, &c->yaw, "camera yaw")) < 0 ||
	    (ret = parse_float(r, pitch, CAMERA_PITCH_MIN_DEG, CAMERA_PITCH_MAX_DEG, &c->pitch,
			       "camera pitch")) < 0)
		return ret;
	if (c->yaw == 180.0f)
		c->yaw = -180.0f;
	return 0;
}

static int parse_stroke(struct reader *r, struct doc_op *op, uint64_t version)
{
	uint64_t v = 0, npoints = 0;
	uint32_t last_dt = 0;
	int ret;

	/* version 3: the camera of a stroke drawn on a turned tree follows */
	if (version >= 3 && r->nfields == 6) {
		if ((ret = parse_camera(r, r->fields[4], r->fields[5], &op->camera)) < 0)
			return ret;
	} else if ((ret = expect_fields(r, 4, "stroke")) < 0) {
		return ret;
	}
	if (!event_tool_from_name(r->fields[1], &op->tool))
		return error_at(r->err, -EINVAL, r->name, r->line, "unknown tool \"%s\" (pen, eraser)",
				r->fields[1]);
	if ((ret = parse_u64(r, r->fields[2], UINT64_MAX, &op->time_us, "time")) < 0)
		return ret;
	if ((ret = parse_u64(r, r->fields[3], DOC_MAX_STROKE_POINTS, &npoints, "point count")) < 0)
		return ret;
	if (npoints == 0)
		return error_at(r->err, -EINVAL, r->name, r->line, "a stroke needs at least one point");
	op->points = calloc(npoints, sizeof(*op->points));
	if (!op->points)
		return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
	for (op->npoints = 0; op->npoints < npoints; op->npoints++) {
		struct doc_point *p = &op->points[op->npoints];

		ret = reader_next(r);
		if (ret < 0)
			return ret;
		if (ret == 0)
			return error_at(r->err, -EINVAL, r->name, r->line,
					"file ends inside a stroke (%zu of %llu points)", op->npoints,
					(unsigned long long)npoints);
		if ((ret = expect_fields(r, 4, "a stroke point (x y pressure dt_us)")) < 0 ||
		    (ret = parse_float(r, r->fields[0], -DOC_MAX_COORD_M, DOC_MAX_COORD_M, &p->x, "x")) < 0 ||
		    (ret = parse_float(r, r->fields[1], -DOC_MAX_COORD_M, DOC_MAX_COORD_M, &p->y, "y")) < 0 ||
		    (ret = parse_float(r, r->fields[2], 0.0f, 1.0f, &p->pressure, "pressure")) < 0 ||
		    (ret = parse_u64(r, r->fields[3], UINT32_MAX, &v, "dt_us")) < 0)
			return ret;
		if ((uint32_t)v < last_dt)
			return error_at(r->err, -EINVAL, r->name, r->line,
					"time goes backwards within a stroke (%llu < %lu)",
					(unsigned long long)v, (unsigned long)last_dt);
		p->dt_us = last_dt = (uint32_t)v;
	}
	return 0;
}

/* clone-add T B, clone-remove T B, arrange T B PATTERN, propagate T B PATTERN */
static int parse_edit(struct reader *r, struct doc_op *op)
{
	bool patterned = op->kind == DOC_OP_ARRANGE || op->kind == DOC_OP_PROPAGATE;
	uint64_t v = 0;
	int ret;

	if ((ret = expect_fields(r, patterned ? 4 : 3, r->fields[0])) < 0 ||
	    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0 ||
	    (ret = parse_u64(r, r->fields[2], INT32_MAX, &v, "branch")) < 0)
		return ret;
	op->branch = (int)v;
	if (op->kind == DOC_OP_ARRANGE) {
		enum arrange_pattern p;

		if (!arrange_pattern_from_name(r->fields[3], &p))
			return error_at(r->err, -EINVAL, r->name, r->line,
					"unknown leaf arrangement \"%s\" (whorl-add, whorl-extend, "
					"spiral-extend)", r->fields[3]);
		op->pattern = (int)p;
	} else if (op->kind == DOC_OP_PROPAGATE) {
		op->pattern = -1;
		for (int i = 0; i <= PROPAGATE_FIXED_SIZE; i++)
			if (strcmp(r->fields[3], propagate_names[i]) == 0)
				op->pattern = i;
		if (op->pattern < 0)
			return error_at(r->err, -EINVAL, r->name, r->line,
					"unknown propagation pattern \"%s\" (fixed-count, fixed-size)",
					r->fields[3]);
	}
	return 0;
}

/* generate T GENERATOR SEED {PARAMETERS}, season T NAME (version 5), leaftype T NAME
 * (version 6) */
static int parse_functional(struct reader *r, struct doc_op *op)
{
	uint64_t v = 0;
	int ret;

	if (op->kind == DOC_OP_SEASON) {
		enum season season;

		if ((ret = expect_fields(r, 3, "season")) < 0 ||
		    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0)
			return ret;
		if (!season_from_name(r->fields[2], &season))
			return error_at(r->err, -EINVAL, r->name, r->line,
					"unknown season \"%s\" (spring, summer, autumn, winter)",
					r->fields[2]);
		op->pattern = (int)season;
		return 0;
	}
	if (op->kind == DOC_OP_LEAFTYPE) {
		if ((ret = expect_fields(r, 3, "leaftype")) < 0 ||
		    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0)
			return ret;
		if (!ori_kind_from_name(r->fields[2], &op->pattern))
			return error_at(r->err, -EINVAL, r->name, r->line,
					"unknown leaf type \"%s\" (drawn, entire, hop, maple)",
					r->fields[2]);
		return 0;
	}
	if ((ret = expect_fields(r, 5, "generate (time, generator, seed, parameters)")) < 0 ||
	    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0 ||
	    (ret = parse_u64(r, r->fields[2], UINT32_MAX, &v, "generator version")) < 0 ||
	    (ret = parse_u64(r, r->fields[3], UINT64_MAX, &op->seed, "seed")) < 0)
		return ret;
	if (v < 1 || v > GEN_VERSION)
		return error_at(r->err, -EINVAL, r->name, r->line,
				"generator version %llu is not supported (this edaha has 1 to %d)",
				(unsigned long long)v, GEN_VERSION);
	op->params = malloc(sizeof(*op->params));
	if (!op->params)
		return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
	/* the parameters are YAML on this one line: their errors name it. The tree is built
	 * by the generators of version v, within that version's limits */
	return gen_read_version(r->fields[4], strlen(r->fields[4]), r->name, r->line - 1, (int)v,
				op->params, r->err);
}

/* vine T X Y Z {PARAMETERS} (version 7): the planting point, then a vine file's keys as
 * YAML on the line (docs/vine-format.md). */
static int parse_vine(struct reader *r, struct doc_op *op)
{
	int ret;

	if ((ret = expect_fields(r, 6, "vine (time, x, y, z, parameters)")) < 0 ||
	    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0)
		return ret;
	for (int k = 0; k < 3; k++) {
		float unused;
		char *endp;

		/* read as a double, bit for bit what was written; the range a stroke's */
		if ((ret = parse_float(r, r->fields[2 + k], -DOC_MAX_COORD_M, DOC_MAX_COORD_M,
				       &unused, "planting point")) < 0)
			return ret;
		op->plant[k] = strtod(r->fields[2 + k], &endp);
	}
	op->vine = malloc(sizeof(*op->vine));
	if (!op->vine)
		return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
	return vine_read_at(r->fields[5], strlen(r->fields[5]), r->name, r->line - 1, op->vine,
			    r->err);
}

/* grow T {SETTINGS} (version 8): a wood settings file's keys as YAML on the line. */
static int parse_grow(struct reader *r, struct doc_op *op)
{
	int ret;

	if ((ret = expect_fields(r, 3, "grow (time, settings)")) < 0 ||
	    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0)
		return ret;
	op->wood = malloc(sizeof(*op->wood));
	if (!op->wood)
		return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
	return wood_read(r->fields[2], strlen(r->fields[2]), r->name, r->line - 1, op->wood, r->err);
}

/* A number of an import's line, exactly as written (a double), within [lo, hi]. */
static int parse_exact(struct reader *r, const char *s, double lo, double hi, double *v,
		       const char *what)
{
	char *endp;
	double x;

	errno = 0;
	x = strtod(s, &endp);
	if (endp == s || *endp || errno == ERANGE || !isfinite(x))
		return error_at(r->err, -EINVAL, r->name, r->line, "bad %s \"%s\"", what, s);
	if (x < lo || x > hi)
		return error_at(r->err, -EINVAL, r->name, r->line, "%s %s out of range %g..%g", what, s,
				lo, hi);
	*v = x;
	return 0;
}

/* One branch of an import: its head line (read), then its points. */
static int parse_import_branch(struct reader *r, struct tree *t, size_t i)
{
	uint64_t n = 0, gen = 0;
	double parent, pt;
	struct vec3 *p;
	double *rad;
	int ret;

	if ((ret = expect_fields(r, 4, "an imported branch (parent parent_t generation points)")) < 0 ||
	    (ret = parse_exact(r, r->fields[0], -1, (double)i - 1, &parent, "parent")) < 0 ||
	    (ret = parse_exact(r, r->fields[1], 0, 1, &pt, "parent_t")) < 0 ||
	    (ret = parse_u64(r, r->fields[2], 1000, &gen, "generation")) < 0 ||
	    (ret = parse_u64(r, r->fields[3], DOC_MAX_STROKE_POINTS, &n, "point count")) < 0)
		return ret;
	if (parent != floor(parent))
		return error_at(r->err, -EINVAL, r->name, r->line, "parent %s is not a branch",
				r->fields[0]);
	if (n < 2)
		return error_at(r->err, -EINVAL, r->name, r->line, "a branch needs two points or more");
	p = malloc(n * sizeof(*p));
	rad = malloc(n * sizeof(*rad));
	if (!p || !rad) {
		free(p);
		free(rad);
		return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
	}
	for (size_t k = 0; k < n && ret == 0; k++) {
		ret = reader_next(r);
		if (ret == 0)
			ret = error_at(r->err, -EINVAL, r->name, r->line,
				       "file ends inside an imported branch (%zu of %llu points)", k,
				       (unsigned long long)n);
		if (ret < 0)
			break;
		if ((ret = expect_fields(r, 4, "a branch point (x y z radius)")) < 0 ||
		    (ret = parse_exact(r, r->fields[0], -DOC_MAX_COORD_M, DOC_MAX_COORD_M, &p[k].x, "x")) < 0 ||
		    (ret = parse_exact(r, r->fields[1], -DOC_MAX_COORD_M, DOC_MAX_COORD_M, &p[k].y, "y")) < 0 ||
		    (ret = parse_exact(r, r->fields[2], -DOC_MAX_COORD_M, DOC_MAX_COORD_M, &p[k].z, "z")) < 0 ||
		    (ret = parse_exact(r, r->fields[3], 0, DOC_MAX_COORD_M, &rad[k], "radius")) < 0)
			break;
	}
	if (ret == 0) {
		ret = tree_add_branch(t, (int)parent, pt, ORIGIN_SKETCH, p, rad, n);
		if (ret >= 0) {
			t->branches[ret].generation = (int)gen;
			ret = 0;
		} else {
			ret = error_at(r->err, ret, r->name, r->line, "out of memory");
		}
	}
	free(p);
	free(rad);
	return ret;
}

/* import T B (version 8): B branches follow, parents before children. */
static int parse_import(struct reader *r, struct doc_op *op)
{
	uint64_t n = 0;
	int ret;

	if ((ret = expect_fields(r, 3, "import (time, branches)")) < 0 ||
	    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &op->time_us, "time")) < 0 ||
	    (ret = parse_u64(r, r->fields[2], TREE_MAX_BRANCHES, &n, "branch count")) < 0)
		return ret;
	op->import = malloc(sizeof(*op->import));
	if (!op->import)
		return error_at(r->err, -ENOMEM, r->name, r->line, "out of memory");
	tree_init(op->import);
	for (size_t i = 0; i < n; i++) {
		ret = reader_next(r);
		if (ret == 0)
			ret = error_at(r->err, -EINVAL, r->name, r->line,
				       "file ends inside an import (%zu of %llu branches)", i,
				       (unsigned long long)n);
		if (ret < 0 || (ret = parse_import_branch(r, op->import, i)) < 0)
			return ret;
	}
	return 0;
}

static bool functional_keyword(const char *kw, uint64_t version, enum doc_op_kind *kind)
{
	if (version < 5)
		return false;
	if (!strcmp(kw, "generate"))
		*kind = DOC_OP_GENERATE;
	else if (!strcmp(kw, "season"))
		*kind = DOC_OP_SEASON;
	else if (version >= 6 && !strcmp(kw, "leaftype"))
		*kind = DOC_OP_LEAFTYPE;
	else if (version >= 7 && !strcmp(kw, "vine"))
		*kind = DOC_OP_VINE;
	else if (version >= 8 && !strcmp(kw, "grow"))
		*kind = DOC_OP_GROW;
	else if (version >= 8 && !strcmp(kw, "import"))
		*kind = DOC_OP_IMPORT;
	else
		return false;
	return true;
}

static bool edit_keyword(const char *kw, uint64_t version, enum doc_op_kind *kind)
{
	if (version < 4)
		return false;
	for (int k = DOC_OP_CLONE_ADD; k <= DOC_OP_PROPAGATE; k++)
		if (strcmp(kw, edit_keywords[k]) == 0) {
			*kind = (enum doc_op_kind)k;
			return true;
		}
	return false;
}

static int parse_body(struct reader *r, struct doc *d, uint64_t version)
{
	uint64_t v, nops = 0, cursor = 0;
	bool have_seed = false, have_history = false, in_tree = false;
	int ret;

	while ((ret = reader_next(r)) > 0) {
		const char *kw = r->fields[0];
		struct doc_op op = { 0 };
		enum doc_op_kind edit, functional;

		if (strcmp(kw, "end") == 0) {
			if ((ret = expect_fields(r, 1, "end")) < 0)
				return ret;
			if (!have_seed || !have_history)
				return error_at(r->err, -EINVAL, r->name, r->line, "missing %s line",
						have_seed ? "history" : "seed");
			if (d->nops != nops)
				return error_at(r->err, -EINVAL, r->name, r->line,
						"history says %llu ops, found %zu",
						(unsigned long long)nops, d->nops);
			d->cursor = (size_t)cursor;
			while ((ret = reader_next(r)) > 0)
				return error_at(r->err, -EINVAL, r->name, r->line, "text after \"end\"");
			return ret;
		}
		if (in_tree) {
			/* The summary is rebuilt from the history; only its shape is checked. */
			if (strcmp(kw, "branch") && strcmp(kw, "leaf"))
				return error_at(r->err, -EINVAL, r->name, r->line,
						"unexpected \"%s\" in the tree section", kw);
			continue;
		}
		if (strcmp(kw, "seed") == 0) {
			if (have_seed)
				return error_at(r->err, -EINVAL, r->name, r->line, "second seed line");
			if ((ret = expect_fields(r, 2, "seed")) < 0 ||
			    (ret = parse_u64(r, r->fields[1], UINT64_MAX, &d->seed, "seed")) < 0)
				return ret;
			have_seed = true;
		} else if (version >= 3 && strcmp(kw, "view") == 0) {
			if ((ret = expect_fields(r, 3, "view")) < 0 ||
			    (ret = parse_camera(r, r->fields[1], r->fields[2], &d->view)) < 0)
				return ret;
		} else if (strcmp(kw, "history") == 0) {
			if (have_history)
				return error_at(r->err, -EINVAL, r->name, r->line, "second history line");
			if ((ret = expect_fields(r, 3, "history")) < 0 ||
			    (ret = parse_u64(r, r->fields[1], DOC_MAX_OPS, &nops, "op count")) < 0 ||
			    (ret = parse_u64(r, r->fields[2], nops, &cursor, "cursor")) < 0)
				return ret;
			have_history = true;
		} else if (strcmp(kw, "stroke") == 0 || strcmp(kw, "new") == 0 ||
			   (version >= 2 && strcmp(kw, "lift") == 0) || edit_keyword(kw, version, &edit) ||
			   functional_keyword(kw, version, &functional)) {
			if (!have_history)
				return error_at(r->err, -EINVAL, r->name, r->line,
						"\"%s\" before the history line", kw);
			if (d->nops == nops)
				return error_at(r->err, -EINVAL, r->name, r->line,
						"more ops than the history line says (%llu)",
						(unsigned long long)nops);
			if (edit_keyword(kw, version, &edit)) {
				op.kind = edit;
				ret = parse_edit(r, &op);
			} else if (functional_keyword(kw, version, &functional)) {
				op.kind = functional;
				ret = functional == DOC_OP_VINE	  ? parse_vine(r, &op) :
				      functional == DOC_OP_GROW	  ? parse_grow(r, &op) :
				      functional == DOC_OP_IMPORT ? parse_import(r, &op) :
								    parse_functional(r, &op);
			} else if (kw[0] == 's') {
				op.kind = DOC_OP_STROKE;
				ret = parse_stroke(r, &op, version);
			} else {
				op.kind = kw[0] == 'n' ? DOC_OP_NEW : DOC_OP_LIFT;
				ret = expect_fields(r, 2, kw);
				if (ret == 0)
					ret = parse_u64(r, r->fields[1], UINT64_MAX, &op.time_us, "time");
			}
			if (ret == 0) {
				d->cursor = d->nops; /* append, never truncate, while loading */
				ret = doc_push(d, &op);
				if (ret == -ENOSPC)
					ret = error_at(r->err, -EINVAL, r->name, r->line,
						       "the drawing has more than %u points in all "
						       "(a generated tree's branches and leaves and a "
						       "vine's budget count as points)",
						       DOC_MAX_POINTS);
				else if (ret < 0)
					error_at(r->err, ret, r->name, r->line, "out of memory");
			}
			doc_op_finish(&op);
			if (ret < 0)
				return ret;
		} else if (strcmp(kw, "tree") == 0) {
			if ((ret = expect_fields(r, 3, "tree")) < 0 ||
			    (ret = parse_u64(r, r->fields[1], UINT32_MAX, &v, "branch count")) < 0 ||
			    (ret = parse_u64(r, r->fields[2], UINT32_MAX, &v, "leaf count")) < 0)
				return ret;
			in_tree = true;
		} else {
			return error_at(r->err, -EINVAL, r->name, r->line, "unknown line \"%s\"", kw);
		}
	}
	if (ret < 0)
		return ret;
	return error_at(r->err, -EINVAL, r->name, r->line,
			"file ends without \"end\" (truncated?)");
}

int doc_parse(const char *data, size_t len, const char *name, struct doc *d, struct error *err)
{
	struct reader r = { .data = data, .end = data + len, .pos = data, .name = name, .err = err };
	uint64_t version = 0;
	int ret;

	doc_init(d, 0);
	ret = reader_next(&r);
	if (ret == 0)
		ret = error_at(err, -EINVAL, name, 0, "empty file, not an edaha drawing");
	if (ret < 0)
		goto out;
	if (r.nfields != 2 || strcmp(r.fields[0], "edaha-drawing") != 0) {
		ret = error_at(err, -EINVAL, name, r.line,
			       "not an edaha drawing (expected \"edaha-drawing %d\")", DOC_FORMAT_VERSION);
		goto out;
	}
	if ((ret = parse_u64(&r, r.fields[1], UINT32_MAX, &version, "version")) < 0)
		goto out;
	if (version < 1 || version > DOC_FORMAT_VERSION) {
		ret = error_at(err, -EINVAL, name, r.line,
			       "drawing format version %llu is not supported (this edaha reads 1 to %d)",
			       (unsigned long long)version, DOC_FORMAT_VERSION);
		goto out;
	}
	ret = parse_body(&r, d, version);
out:
	free(r.copy);
	if (ret < 0)
		doc_finish(d);
	return ret;
}
