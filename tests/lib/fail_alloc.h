/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>

/*
 * Allocation failures on purpose: tests/lib/fail_alloc.c replaces malloc, calloc, realloc and
 * free the way glibc documents ("Replacing malloc"), counts the allocations and fails the
 * one a test asks for (NULL and errno ENOMEM, as POSIX describes it). Sanitizers replace
 * malloc themselves, so under them nothing is replaced and FAIL_ALLOC_HOOK is 0: tests
 * leave their allocation-failure checks out then.
 */
#define FAIL_ALLOC_HOOK 1
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
	__has_feature(memory_sanitizer)
#undef FAIL_ALLOC_HOOK
#define FAIL_ALLOC_HOOK 0
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#undef FAIL_ALLOC_HOOK
#define FAIL_ALLOC_HOOK 0
#endif

/* Counts allocations (malloc, calloc, realloc of a block) from 0; allocation n fails. */
void fail_alloc_at(long n);
/* No more failures, and no more counting. */
void fail_alloc_off(void);
/* Allocations since fail_alloc_at, the failed one included. */
long fail_alloc_calls(void);
/* Blocks allocated and not yet freed. */
long fail_alloc_live(void);
/* Whether the program's malloc is this one (not under valgrind, which brings its own);
 * if not, says so on stderr. */
bool fail_alloc_hooked(void);
