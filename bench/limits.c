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

static void c_fills(uint32_t *s, const uint32_t *a, uint32_t ops)
{
	uint32_t i, yy, xx;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		uint32_t w = bench_fill_w(a), h = bench_fill_h(a), c = a[4];

		for (yy = 0; yy < h; yy++) {
			uint32_t *p = s + (size_t)(a[1] + yy) * BENCH_W + a[0];

			for (xx = 0; xx < w; xx++)
				p[xx] = c;
		}
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
 * Row order makes overlapping copies read their source before writing
 * over it: bottom-up when moving down; within one row memmove, and for
 * xor a copy of the source row first when source and destination share
 * the row.
 */
static double limit_blit_any(const struct bench_input *in, uint32_t *s,
			     bool do_xor)
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

			if (!do_xor) {
				memmove(d, src, (size_t)w * 4);
				continue;
			}
			if (sy == dy) {
				memcpy(tmp, src, (size_t)w * 4);
				src = tmp;
			}
			for (xx = 0; xx < w; xx++)
				d[xx] ^= src[xx];
		}
	}
	return bench_toc(t0);
}

static double limit_blit(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, false);
}

static double limit_blit_xor(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, true);
}

static double limit_text(const struct bench_input *in, uint32_t *s)
{
	const uint32_t *a = in->arg;
	double t0 = bench_tic();
	uint32_t i, row, bit;

	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		const uint8_t *glyph = in->font + a[0] * BENCH_GLYPH_H;
		uint32_t fg = a[1], bg = a[2];
		uint32_t *p = s + (size_t)a[4] * BENCH_W + a[3];

		for (row = 0; row < BENCH_GLYPH_H; row++, p += BENCH_W) {
			uint8_t bits = glyph[row];

			for (bit = 0; bit < BENCH_GLYPH_W; bit++)
				p[bit] = (bits & (0x80 >> bit)) ? fg : bg;
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
	[BENCH_BLIT] = { { "memmove", limit_blit, "memmove+scan" } },
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
	uint64_t f;
	double t0 = bench_tic(), t;
	uint32_t i;

	for (f = 0; f < frames; f++) {
		for (i = 0; i < BENCH_W * BENCH_H; i++)
			fb[i] = s[i] & 0x00ffffffu;
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
