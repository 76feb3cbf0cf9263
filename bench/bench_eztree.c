/* SPDX-License-Identifier: MIT */
/*
 * Runs bench/eztree/bench.mjs under node and reads what it prints:
 *
 *   eztree-info TEXT                       shown as it is (versions, the stand-ins)
 *   eztree-result LABEL TARGET TRIANGLES BARK LEAVES MEDIAN_S CPU_S REPS OPTIONS...
 *
 * A separate process, run after our own timings, so the two never share the 2 cores.
 */
#include "bench_eztree.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef BENCH_EZTREE_DIR
#error "bench/meson.build defines BENCH_EZTREE_DIR"
#endif

#define INSTALLED BENCH_EZTREE_DIR "/node_modules/@dgreenheck/ez-tree/package.json"

static void how_to_install(const char *why)
{
	printf("ez-tree: %s: no comparison this run.\n"
	       "  To compare, install it (node and npm needed; pinned to ez-tree 1.1.0, three 0.167.1):\n"
	       "    tools/setup-eztree.sh\n",
	       why);
}

/* One eztree-result line into r; false if it is not one. */
static bool parse_result(const char *line, struct eztree_result *r)
{
	int used = 0;

	memset(r, 0, sizeof(*r));
	if (sscanf(line, "eztree-result %15s %zu %zu %zu %zu %lf %lf %d %n", r->label, &r->target,
		   &r->triangles, &r->bark, &r->leaves, &r->median_s, &r->cpu_s, &r->reps,
		   &used) < 8 ||
	    used == 0)
		return false;
	snprintf(r->options, sizeof(r->options), "%s", line + used);
	r->options[strcspn(r->options, "\n")] = '\0';
	return true;
}

int eztree_run(const char *const *labels, const size_t *targets, size_t n, int reps,
	       struct eztree_result *out)
{
	char cmd[2048], line[1024];
	size_t len, got = 0;
	FILE *f;
	int status;

	if (access(INSTALLED, R_OK) != 0) {
		how_to_install("not installed in " BENCH_EZTREE_DIR "/node_modules");
		return 0;
	}
	/* the directory is meson's source dir: quoted for the shell, a quote in it refused */
	if (strchr(BENCH_EZTREE_DIR, '\''))
		return -1;
	len = (size_t)snprintf(cmd, sizeof(cmd), "\"${NODE:-node}\" '%s/bench.mjs' --reps %d",
			       BENCH_EZTREE_DIR, reps);
	for (size_t i = 0; i < n && len < sizeof(cmd); i++)
		len += (size_t)snprintf(cmd + len, sizeof(cmd) - len, " %s=%zu", labels[i],
					targets[i]);
	if (len + sizeof(" 2>&1") > sizeof(cmd))
		return -1;
	strcat(cmd, " 2>&1");
	fflush(stdout);
	f = popen(cmd, "r");
	if (!f) {
		perror("ez-tree: popen");
		return -1;
	}
	while (fgets(line, sizeof(line), f)) {
		if (!strncmp(line, "eztree-result ", 14)) {
			if (got < n && parse_result(line, &out[got]))
				got++;
			else
				printf("ez-tree: unexpected: %s", line);
		} else if (!strncmp(line, "eztree-info ", 12)) {
			printf("  %s", line + 12);
		} else {
			printf("  node: %s", line);
		}
	}
	status = pclose(f);
	if (status == -1) {
		perror("ez-tree: pclose");
		return -1;
	}
	if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
		how_to_install("node was not found (set NODE to it, or install nodejs)");
		return 0;
	}
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || got != n) {
		printf("ez-tree: the script failed (status %d, %zu of %zu results)\n", status, got, n);
		return -1;
	}
	return (int)n;
}
