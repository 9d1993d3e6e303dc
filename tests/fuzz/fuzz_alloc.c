// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Large allocations kept between fuzz inputs, for fuzz_rdcd and
 * fuzz_script (linked with -Wl,--wrap=calloc,--wrap=free).
 *
 * Every sim: device allocates two frame buffers of the largest display
 * (2048 x 2048 pixels, 16 MiB each), and every input opens a fresh
 * device.  Under AddressSanitizer each such calloc maps new memory and
 * each free unmaps it: the page faults were most of the time an input
 * took.  Here allocations of FZ_BIG bytes or more come from a few slots
 * allocated once (still with ASan's red zones around them) and are
 * zeroed as calloc promises; anything else goes to the real allocator.
 * What is lost: use after free of such a buffer goes unseen.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define FZ_BIG	 (8u << 20)
#define FZ_SLOTS 4

void *__real_calloc(size_t n, size_t size);
void *__wrap_calloc(size_t n, size_t size);
void __real_free(void *p);
void __wrap_free(void *p);

static struct {
	void *p;
	size_t size;
	int used;
} fz_slot[FZ_SLOTS];

void *__wrap_calloc(size_t n, size_t size)
{
	size_t bytes;

	if (__builtin_mul_overflow(n, size, &bytes) || bytes < FZ_BIG)
		return __real_calloc(n, size);
	for (int i = 0; i < FZ_SLOTS; i++) {
		if (fz_slot[i].used)
			continue;
		if (fz_slot[i].p && fz_slot[i].size != bytes)
			continue;
		if (!fz_slot[i].p) {
			fz_slot[i].p = __real_calloc(1, bytes);
			if (!fz_slot[i].p)
				return NULL;
			fz_slot[i].size = bytes;
		} else {
			memset(fz_slot[i].p, 0, bytes);
		}
		fz_slot[i].used = 1;
		return fz_slot[i].p;
	}
	return __real_calloc(n, size);
}

void __wrap_free(void *p)
{
	for (int i = 0; p && i < FZ_SLOTS; i++) {
		if (fz_slot[i].p == p) {
			fz_slot[i].used = 0;
			return;
		}
	}
	__real_free(p);
}
