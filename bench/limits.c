// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The plain-C limits of the byte-moving workloads (bench/README.md,
 * "Limits"): the same bytes stored by the simplest loops and by libc,
 * and with scanout, the frame conversions the chip made meanwhile.
 */
#include <stdlib.h>
#include <string.h>
#include <wchar.h>
#include <zlib.h>

#include "parts.h"

/* ---- plain-C limits of the byte-moving workloads ------------------------- */

/*
 * A limit is the fastest known way of doing the same work, so the loops
 * are written for the compiler to widen: 16-byte vectors (GCC's vector
 * extension: SSE2 on x86-64, NEON on arm64, pairs of words elsewhere),
 * loaded and stored through memcpy so that any alignment is allowed,
 * aligned stores where a row is long enough to align.  Written
 * independently of rdc's own paths.
 */
typedef uint32_t v4u __attribute__((vector_size(16)));

static inline v4u v4_ld(const void *p)
{
	v4u v;

	memcpy(&v, p, sizeof(v));
	return v;
}

static inline void v4_st(void *p, v4u v)
{
	memcpy(p, &v, sizeof(v));
}

/*
 * w pixels of c from p, as pixman's SSE2 fill stores them: pixel by pixel
 * to the first 16-byte boundary, 128-byte blocks of aligned stores, then
 * 64, 32 and 16 bytes, the last pixels one by one.
 */
static inline void row_fill(uint32_t *p, uint32_t c, uint32_t w)
{
	const v4u v = { c, c, c, c };

	for (; w && ((uintptr_t)p & 15); w--)
		*p++ = c;
	for (; w >= 32; w -= 32, p += 32) {
		*(v4u *)p = v;
		*(v4u *)(p + 4) = v;
		*(v4u *)(p + 8) = v;
		*(v4u *)(p + 12) = v;
		*(v4u *)(p + 16) = v;
		*(v4u *)(p + 20) = v;
		*(v4u *)(p + 24) = v;
		*(v4u *)(p + 28) = v;
	}
	if (w >= 16) {
		*(v4u *)p = v;
		*(v4u *)(p + 4) = v;
		*(v4u *)(p + 8) = v;
		*(v4u *)(p + 12) = v;
		w -= 16;
		p += 16;
	}
	if (w >= 8) {
		*(v4u *)p = v;
		*(v4u *)(p + 4) = v;
		w -= 8;
		p += 8;
	}
	if (w >= 4) {
		*(v4u *)p = v;
		w -= 4;
		p += 4;
	}
	while (w--)
		*p++ = c;
}

static void c_fills(uint32_t *s, const uint32_t *a, uint32_t ops)
{
	uint32_t i, yy;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		uint32_t w = bench_fill_w(a), h = bench_fill_h(a), c = a[4];
		uint32_t *p = s + (size_t)a[1] * BENCH_W + a[0];

		for (yy = 0; yy < h; yy++, p += BENCH_W)
			row_fill(p, c, w);
	}
}

static double limit_store(const struct bench_input *in, uint32_t *s)
{
	double t0 = bench_tic();

	c_fills(s, in->arg, in->ops);
	return bench_toc(t0);
}

/* glibc's memset for 32-bit units: the same bytes as the store loop. */
static double limit_wmemset(const struct bench_input *in, uint32_t *s)
{
	const uint32_t *a = in->arg;
	double t0 = bench_tic();
	uint32_t i, yy;

	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		uint32_t w = bench_fill_w(a), h = bench_fill_h(a);

		for (yy = 0; yy < h; yy++)
			wmemset((wchar_t *)(s + (size_t)(a[1] + yy) * BENCH_W +
					    a[0]),
				(wchar_t)a[4], w);
	}
	return bench_toc(t0);
}

/*
 * One row of a copy (xor: d ^= src) of n pixels, d and src in different
 * rows: pixel by pixel to the destination's first 16-byte boundary, then
 * 64 bytes of loads and their aligned stores, as pixman's SSE2 blt does;
 * the last 16 bytes as one unaligned vector, taken before anything is
 * stored (it may overlap what goes before it: its bytes are right).
 */
static inline void row_copy(uint32_t *d, const uint32_t *src, uint32_t n,
			    bool do_xor)
{
	uint8_t *q = (uint8_t *)d, *e = q + (size_t)n * 4;
	const uint8_t *r = (const uint8_t *)src;
	uint32_t k;
	v4u t;

	if (n < 4) {
		for (k = 0; k < n; k++)
			d[k] = do_xor ? d[k] ^ src[k] : src[k];
		return;
	}
	t = v4_ld(r + (size_t)n * 4 - 16);
	if (do_xor)
		t ^= v4_ld(e - 16);
	for (; ((uintptr_t)q & 15) && q < e - 16; q += 4, r += 4) {
		uint32_t v;

		memcpy(&v, r, 4);
		if (do_xor)
			v ^= *(uint32_t *)q;
		memcpy(q, &v, 4);
	}
	for (; q + 64 <= e - 16; q += 64, r += 64) {
		v4u a0 = v4_ld(r), a1 = v4_ld(r + 16);
		v4u a2 = v4_ld(r + 32), a3 = v4_ld(r + 48);

		if (do_xor) {
			a0 ^= *(v4u *)q;
			a1 ^= *(v4u *)(q + 16);
			a2 ^= *(v4u *)(q + 32);
			a3 ^= *(v4u *)(q + 48);
		}
		*(v4u *)q = a0;
		*(v4u *)(q + 16) = a1;
		*(v4u *)(q + 32) = a2;
		*(v4u *)(q + 48) = a3;
	}
	for (; q + 16 <= e - 16; q += 16, r += 16)
		*(v4u *)q = do_xor ? v4_ld(r) ^ *(v4u *)q : v4_ld(r);
	for (; q < e - 16; q += 4, r += 4) {
		uint32_t v;

		memcpy(&v, r, 4);
		if (do_xor)
			v ^= *(uint32_t *)q;
		memcpy(q, &v, 4);
	}
	v4_st(e - 16, t);
}

/*
 * Row order makes overlapping copies read their source before writing
 * over it: bottom-up when moving down.  Within one row (source and
 * destination on the same row) memmove, and for xor a copy of the
 * source row first.  `vec`: the rows of different rows by row_copy, else
 * memmove and the plain xor loop.
 */
static double limit_blit_any(const struct bench_input *in, uint32_t *s,
			     bool do_xor, bool vec)
{
	const uint32_t *a = in->arg;
	uint32_t tmp[BENCH_RECT_MAX], i, yy, xx;
	double t0;

	c_fills(s, in->prefill, BENCH_FILL_OPS);
	t0 = bench_tic();
	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		uint32_t sx = a[0], sy = a[1], dx = a[2], dy = a[3];
		uint32_t w = a[4], h = a[5];
		bool up = dy <= sy;

		for (yy = 0; yy < h; yy++) {
			uint32_t row = up ? yy : h - 1 - yy;
			uint32_t *d = s + (size_t)(dy + row) * BENCH_W + dx;
			const uint32_t *src =
				s + (size_t)(sy + row) * BENCH_W + sx;

			if (sy == dy) {
				if (!do_xor) {
					memmove(d, src, (size_t)w * 4);
					continue;
				}
				memcpy(tmp, src, (size_t)w * 4);
				src = tmp;
			}
			if (vec) {
				row_copy(d, src, w, do_xor);
				continue;
			}
			if (!do_xor) {
				memmove(d, src, (size_t)w * 4);
				continue;
			}
			for (xx = 0; xx < w; xx++)
				d[xx] ^= src[xx];
		}
	}
	return bench_toc(t0);
}

static double limit_blit(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, false, false);
}

static double limit_blit_vec(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, false, true);
}

static double limit_blit_xor(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, true, true);
}

/*
 * 8 fg/bg pixels a glyph row as two vectors: each lane's bit of the row
 * picked by a mask, compared with 0, selects fg or bg (bg ^ (diff & m)).
 */
static double limit_text(const struct bench_input *in, uint32_t *s)
{
	const v4u lo_bits = { 0x80, 0x40, 0x20, 0x10 };
	const v4u hi_bits = { 0x08, 0x04, 0x02, 0x01 };
	const uint32_t *a = in->arg;
	double t0 = bench_tic();
	uint32_t i, row;

	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		const uint8_t *glyph = in->font + a[0] * BENCH_GLYPH_H;
		const v4u bg = { a[2], a[2], a[2], a[2] };
		const v4u diff = bg ^ (v4u) { a[1], a[1], a[1], a[1] };
		uint32_t *p = s + (size_t)a[4] * BENCH_W + a[3];

		for (row = 0; row < BENCH_GLYPH_H; row++, p += BENCH_W) {
			uint32_t bits = glyph[row];
			const v4u b = { bits, bits, bits, bits };
			v4u m0 = (v4u)((b & lo_bits) != 0);
			v4u m1 = (v4u)((b & hi_bits) != 0);

			v4_st(p, bg ^ (diff & m0));
			v4_st(p + 4, bg ^ (diff & m1));
		}
	}
	return bench_toc(t0);
}

static double limit_scanout(const struct bench_input *in, uint32_t *s)
{
	const uint8_t *src = in->index;
	double t0 = bench_tic();
	uint32_t f, i;

	for (f = 0; f < in->ops; f++) {
		for (i = 0; i < BENCH_W * BENCH_H; i++)
			s[i] = in->clut[src[i]];
		/* each frame is a new output: keep every one of them */
		__asm__ volatile("" : : "r"(s) : "memory");
	}
	return bench_toc(t0);
}

const struct limit limits[BENCH_KIND_COUNT][MAX_LIMITS] = {
	[BENCH_FILL] = { { "store", limit_store, "store+scan" },
			 { "wmemset", limit_wmemset, "wmemset+scan" } },
	[BENCH_BLIT] = { { "memmove", limit_blit, "memmove+scan" },
			 { "copy", limit_blit_vec, "copy+scan" } },
	[BENCH_BLIT_XOR] = { { "xor", limit_blit_xor, "xor+scan" } },
	[BENCH_TEXT] = { { "expand", limit_text, "expand+scan" } },
	[BENCH_SCANOUT] = { { "lookup", limit_scanout, NULL } },
};

/*
 * The limit with scanout: after the drawing, the chip's conversion of the
 * surface to an XRGB8888 frame (the X byte cleared, as the CRTC and the
 * sinks see it), done `frames` times: as many frames as the chip scanned
 * out while it drew.  (The chip converts while it draws, seeing the
 * picture half done; the bytes moved are the same.)  Returns the seconds
 * and sets *crc to the last frame's CRC, converted once more untimed when
 * frames is 0, which must equal the chip's frame after the drawing.
 */
double scan_frames(const uint32_t *s, uint64_t frames, double *cpu,
		   uint32_t *crc)
{
	uint32_t *fb = bench_xcalloc((size_t)BENCH_W * BENCH_H, 4);
	const v4u rgb = { 0x00ffffffu, 0x00ffffffu, 0x00ffffffu, 0x00ffffffu };
	uint64_t f;
	double t0 = bench_tic(), t;
	uint32_t i;

	for (f = 0; f < frames; f++) {
		for (i = 0; i < BENCH_W * BENCH_H; i += 4)
			v4_st(fb + i, v4_ld(s + i) & rgb);
		/* each frame is a new output: keep every one of them */
		__asm__ volatile("" : : "r"(fb) : "memory");
	}
	t = bench_toc(t0);
	*cpu = bench_cpu();
	if (!frames)
		for (i = 0; i < BENCH_W * BENCH_H; i++)
			fb[i] = s[i] & 0x00ffffffu;
	*crc = (uint32_t)crc32(0, (const uint8_t *)fb, BENCH_W * BENCH_H * 4);
	free(fb);
	return t;
}
