/* SPDX-License-Identifier: MIT */
#include "fail_alloc.h"

#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

static long calls;        /* allocations since the last fail_alloc_at */
static long fail_at = -1; /* this one fails; -1: none */
static volatile long live; /* blocks allocated and not freed (volatile: the compiler
			    * assumes malloc changes no variable) */

#if FAIL_ALLOC_HOOK
extern void *__libc_malloc(size_t n);
extern void *__libc_calloc(size_t n, size_t size);
extern void *__libc_realloc(void *p, size_t n);
extern void __libc_free(void *p);

/* A failing allocation, as POSIX describes it. Not inlined: break here to see who got it. */
__attribute__((noinline)) static void *injected(void)
{
	errno = ENOMEM;
	return NULL;
}

static bool inject(void)
{
	return fail_at >= 0 && calls++ == fail_at;
}

void *malloc(size_t n)
{
	void *p = inject() ? injected() : __libc_malloc(n);

	live += p != NULL;
	return p;
}

void *calloc(size_t n, size_t size)
{
	void *p = inject() ? injected() : __libc_calloc(n, size);

	live += p != NULL;
	return p;
}

void *realloc(void *old, size_t n)
{
	void *p;

	if (!old)
		return malloc(n);
	if (inject())
		return injected(); /* the old block stays valid, as with a real failure */
	p = __libc_realloc(old, n);
	if (!p && n == 0)
		live--;
	return p;
}

void free(void *p)
{
	live -= p != NULL;
	__libc_free(p);
}
#endif

void fail_alloc_at(long n)
{
	calls = 0;
	fail_at = n;
}

void fail_alloc_off(void)
{
	fail_at = -1;
}

long fail_alloc_calls(void)
{
	return calls;
}

long fail_alloc_live(void)
{
	return live;
}

bool fail_alloc_hooked(void)
{
	void *(*volatile alloc)(size_t) = malloc; /* not inlined: as the library calls it */
	long was = live;
	void *probe = alloc(1);
	bool hooked = live == was + 1;

	free(probe);
	if (!hooked)
		fprintf(stderr, "malloc is not ours (valgrind?): no allocation failures\n");
	return hooked;
}
