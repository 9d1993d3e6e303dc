// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The three functions the core's rdc_memcpy/rdc_memmove/rdc_memset
 * (hw-sim/rdc_base.h) become when the compiler does not expand them
 * inline: the MCU's runtime, since the image has no C library.  Built
 * with -fno-tree-loop-distribute-patterns so that the loops do not turn
 * into calls to themselves.  Word copies where both ends are aligned.
 */
#include <stddef.h>
#include <stdint.h>

/* word access to bytes of any type */
typedef uint32_t __attribute__((__may_alias__)) word_t;

void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);

void *memcpy(void *dst, const void *src, size_t n)
{
	uint8_t *d = dst;
	const uint8_t *s = src;

	if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
		for (; n >= 4; n -= 4, d += 4, s += 4)
			*(word_t *)d = *(const word_t *)s;
	}
	while (n--)
		*d++ = *s++;
	return dst;
}

void *memmove(void *dst, const void *src, size_t n)
{
	uint8_t *d = dst;
	const uint8_t *s = src;

	if (d <= s || d >= s + n)
		return memcpy(dst, src, n);
	while (n--)
		d[n] = s[n];
	return dst;
}

void *memset(void *dst, int c, size_t n)
{
	uint8_t *d = dst;
	uint32_t w = (uint8_t)c * 0x01010101u;

	for (; n && ((uintptr_t)d & 3u); n--)
		*d++ = (uint8_t)c;
	for (; n >= 4; n -= 4, d += 4)
		*(word_t *)d = w;
	while (n--)
		*d++ = (uint8_t)c;
	return dst;
}
