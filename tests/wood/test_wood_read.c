/* SPDX-License-Identifier: MIT */
/*
 * Growing wood's settings file (docs/wood-format.md): the defaults, every key read, the
 * limits, and every malformed file in tests/wood/malformed refused at the line its EXPECT
 * file names, the settings untouched.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "malformed_dir.h"
#include "test.h"
#include "wood.h"

static void read_ok(const char *text, struct wood_params *p)
{
	struct error err = { { 0 } };
	int ret = wood_read(text, strlen(text), "w.yaml", 0, p, &err);

	if (ret != 0)
		fprintf(stderr, "refused: %s\n", err.msg);
	CHECK_INT(ret, 0);
}

static void test_defaults(void)
{
	struct wood_params p, q;
	struct error err = { { 0 } };

	memset(&p, 0x5a, sizeof(p));
	wood_params_default(&p);
	CHECK_INT(p.mode, WOOD_BROADLEAF);
	CHECK_INT(p.grid, 64);
	CHECK(p.alpha == WOOD_ALPHA_DEFAULT && p.beta == 1.0 && p.gravity == WOOD_GRAVITY_DEFAULT);
	CHECK(p.wind[0] == 0.0 && p.wind[1] == 0.0 && p.wind[2] == 0.0);
	CHECK_INT(wood_params_check(&p, NULL, &err), 0);
	read_ok("edaha-wood: 1\n", &q);
	CHECK(memcmp(&p, &q, sizeof(p)) == 0);
}

static void test_every_key(void)
{
	struct wood_params p;

	read_ok("edaha-wood: 1\nmode: conifer\ngrid: 128\nalpha: 2.5e1\nbeta: 0.5\n"
		"gravity: 0.002\nwind: [0.001, 0, -0.25]\n", &p);
	CHECK_INT(p.mode, WOOD_CONIFER);
	CHECK_INT(p.grid, 128);
	CHECK(p.alpha == 25 && p.beta == 0.5 && p.gravity == 0.002);
	CHECK(p.wind[0] == 0.001 && p.wind[1] == 0 && p.wind[2] == -0.25);
	/* flow style on one line, as a drawing would hold it; a block sequence */
	read_ok("{edaha-wood: 1, mode: broadleaf, wind: [0, 0, 1]}", &p);
	CHECK_INT(p.mode, WOOD_BROADLEAF);
	CHECK(p.wind[2] == 1);
	read_ok("edaha-wood: 1\nwind:\n  - -1\n  - 0\n  - 0\n", &p);
	CHECK(p.wind[0] == -1);
}

/* Each limit taken and just missed. */
static void test_limits(void)
{
	static const struct {
		const char *ok, *bad;
	} cases[] = {
		{ "alpha: 0", "alpha: -0.001" },
		{ "alpha: 1e6", "alpha: 1.000001e6" },
		{ "beta: 0.1", "beta: 0.0999" },
		{ "beta: 10", "beta: 10.001" },
		{ "gravity: 0", "gravity: -1e-9" },
		{ "gravity: 1", "gravity: 1.0001" },
		{ "wind: [1, 0, -1]", "wind: [1.001, 0, 0]" },
		{ "grid: 64", "grid: 63" },
		{ "grid: 128", "grid: 256" },
	};

	for (size_t i = 0; i < sizeof(cases) / sizeof(*cases); i++) {
		char text[128];
		struct wood_params p;
		struct error err = { { 0 } };

		snprintf(text, sizeof(text), "edaha-wood: 1\n%s\n", cases[i].ok);
		read_ok(text, &p);
		snprintf(text, sizeof(text), "edaha-wood: 1\n%s\n", cases[i].bad);
		CHECK_INT(wood_read(text, strlen(text), "w.yaml", 0, &p, &err), -EINVAL);
		CHECK(strncmp(err.msg, "w.yaml:2: ", 10) == 0);
	}
}

/* A drawing's line: the lines told count from the file's start. */
static void test_offset(void)
{
	struct wood_params p;
	struct error err = { { 0 } };
	const char *line = "{edaha-wood: 1, beta: 99}";

	CHECK_INT(wood_read(line, strlen(line), "d.edaha", 6, &p, &err), -EINVAL);
	CHECK(strncmp(err.msg, "d.edaha:7: beta", 15) == 0);
}

static int read_one(const char *data, size_t len, const char *path, void *out,
		    struct error *err)
{
	return wood_read(data, len, path, 0, out, err);
}

static void test_malformed(const char *dir)
{
	struct wood_params scratch;

	CHECK(malformed_dir_check(dir, read_one, &scratch, sizeof(scratch)) >= 25);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	test_defaults();
	test_every_key();
	test_limits();
	test_offset();
	test_malformed(argv[1]);
	return 0;
}
