// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * pixman as a peer: the X server's and cairo's pixel engine.  fill
 * (pixman_fill), blit (pixman_blt), text (a solid colour composited
 * through an a1 glyph mask over a pixman_fill of the cell) and scanout
 * (an indexed c8 image composited to x8r8g8b8).  Every result is checked
 * by CRC against the workloads of bench/README.md, so the work is the same
 * as rdc's.
 */
#include <stdlib.h>
#include <string.h>

#include <pixman.h>

#include "bench.h"

#define PIX_STRIDE_WORDS BENCH_W
#define PIX_BPP		 32
/* an a1 mask row holds 8 glyph pixels, padded to the 32-bit row pixman
 * wants */
#define PIX_A1_STRIDE 4

static int pix_has(enum bench_kind kind)
{
	return kind == BENCH_FILL || kind == BENCH_BLIT || kind == BENCH_TEXT ||
	       kind == BENCH_SCANOUT;
}

static void pix_fills(uint32_t *s, const uint32_t *a, uint32_t ops)
{
	uint32_t i;

	for (i = 0; i < ops; i++, a += BENCH_RECORD)
		pixman_fill(s, PIX_STRIDE_WORDS, PIX_BPP, (int)a[0], (int)a[1],
			    (int)bench_fill_w(a), (int)bench_fill_h(a), a[4]);
}

static void pix_blt(uint32_t *s, int sx, int sy, int dx, int dy, int w, int h)
{
	pixman_blt(s, s, PIX_STRIDE_WORDS, PIX_STRIDE_WORDS, PIX_BPP, PIX_BPP,
		   sx, sy, dx, dy, w, h);
}

/*
 * pixman_blt copies rows top to bottom, each left to right, so it may be
 * handed a copy only where that order never reads a pixel it has already
 * written.  Overlapping copies that move down go as bands of dy - sy rows,
 * bottom band first; within one row, copies that move right go as bands of
 * dx - sx columns, rightmost first (what the X server's fb layer does
 * around its own blitter).
 */
static void pix_copy(uint32_t *s, const uint32_t *a)
{
	int sx = (int)a[0], sy = (int)a[1], dx = (int)a[2], dy = (int)a[3];
	int w = (int)a[4], h = (int)a[5], k, band;
	bool overlap = sx < dx + w && dx < sx + w && sy < dy + h && dy < sy + h;

	if (!overlap || dy < sy || (dy == sy && dx <= sx)) {
		pix_blt(s, sx, sy, dx, dy, w, h);
		return;
	}
	if (dy > sy) {
		band = dy - sy;
		for (k = h; k > 0; k -= band) {
			int rows = k < band ? k : band;

			pix_blt(s, sx, sy + k - rows, dx, dy + k - rows, w,
				rows);
		}
		return;
	}
	band = dx - sx;
	for (k = w; k > 0; k -= band) {
		int cols = k < band ? k : band;

		pix_blt(s, sx + k - cols, sy, dx + k - cols, dy, cols, h);
	}
}

static uint8_t bit_reverse(uint8_t v)
{
	uint8_t r = 0;
	int i;

	for (i = 0; i < 8; i++)
		r |= (uint8_t)(((v >> i) & 1) << (7 - i));
	return r;
}

static double pix_text(const struct bench_input *in, uint32_t ops, uint32_t *s,
		       pixman_image_t *dst)
{
	/* the font as one a1 image, glyph g at rows 16 g..16 g + 15 */
	static uint32_t atlas[BENCH_GLYPHS * BENCH_GLYPH_H];
	const uint32_t *a = in->arg;
	pixman_image_t *mask, *fg;
	uint32_t fg_px, i;
	double t0, t;

	/* pixman's a1 has the leftmost pixel in bit 0 on little-endian
	 * hosts (bit 31 on big-endian: not handled, the CRC would say) */
	for (i = 0; i < BENCH_GLYPHS * BENCH_GLYPH_H; i++)
		atlas[i] = bit_reverse(in->font[i]);
	mask = pixman_image_create_bits(PIXMAN_a1, BENCH_GLYPH_W,
					BENCH_GLYPHS * BENCH_GLYPH_H, atlas,
					PIX_A1_STRIDE);
	/* a 1x1 repeating image is pixman's solid source: its one pixel is
	 * rewritten for each glyph */
	fg = pixman_image_create_bits(PIXMAN_a8r8g8b8, 1, 1, &fg_px, 4);
	pixman_image_set_repeat(fg, PIXMAN_REPEAT_NORMAL);
	t0 = bench_tic();
	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		pixman_fill(s, PIX_STRIDE_WORDS, PIX_BPP, (int)a[3], (int)a[4],
			    BENCH_GLYPH_W, BENCH_GLYPH_H, a[2]);
		fg_px = a[1];
		pixman_image_composite32(PIXMAN_OP_OVER, fg, mask, dst, 0, 0, 0,
					 (int32_t)(a[0] * BENCH_GLYPH_H),
					 (int32_t)a[3], (int32_t)a[4],
					 BENCH_GLYPH_W, BENCH_GLYPH_H);
	}
	t = bench_toc(t0);
	pixman_image_unref(fg);
	pixman_image_unref(mask);
	return t;
}

static double pix_scanout(const struct bench_input *in, uint32_t ops,
			  uint32_t *s)
{
	static pixman_indexed_t pal;
	pixman_image_t *src, *dst;
	uint32_t f;
	double t0, t;

	memcpy(pal.rgba, in->clut, sizeof(in->clut));
	src = pixman_image_create_bits(PIXMAN_c8, BENCH_W, BENCH_H,
				       (uint32_t *)in->index, BENCH_W);
	pixman_image_set_indexed(src, &pal);
	dst = pixman_image_create_bits(PIXMAN_x8r8g8b8, BENCH_W, BENCH_H, s,
				       BENCH_W * 4);
	t0 = bench_tic();
	for (f = 0; f < ops; f++)
		pixman_image_composite32(PIXMAN_OP_SRC, src, NULL, dst, 0, 0, 0,
					 0, 0, 0, BENCH_W, BENCH_H);
	t = bench_toc(t0);
	pixman_image_unref(dst);
	pixman_image_unref(src);
	return t;
}

static double pix_run(const struct bench_input *in, uint32_t ops, uint32_t *crc)
{
	uint32_t *s = calloc((size_t)BENCH_W * BENCH_H, 4);
	pixman_image_t *dst;
	const uint32_t *a = in->arg;
	double t0, t = -1;
	uint32_t i;

	if (!s)
		return -1;
	dst = pixman_image_create_bits(PIXMAN_a8r8g8b8, BENCH_W, BENCH_H, s,
				       BENCH_W * 4);
	switch (in->kind) {
	case BENCH_FILL:
		t0 = bench_tic();
		pix_fills(s, in->arg, ops);
		t = bench_toc(t0);
		break;
	case BENCH_BLIT:
		pix_fills(s, in->prefill, BENCH_FILL_OPS);
		t0 = bench_tic();
		for (i = 0; i < ops; i++, a += BENCH_RECORD)
			pix_copy(s, a);
		t = bench_toc(t0);
		break;
	case BENCH_TEXT:
		t = pix_text(in, ops, s, dst);
		break;
	case BENCH_SCANOUT:
		t = pix_scanout(in, ops, s);
		break;
	default:
		break;
	}
	pixman_image_unref(dst);
	*crc = bench_surface_crc(s, BENCH_W * 4);
	free(s);
	return t;
}

const struct bench_peer bench_peer_pixman = {
	.name = "pixman",
	.has = pix_has,
	.run = pix_run,
};
