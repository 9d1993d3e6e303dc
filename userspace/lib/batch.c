// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Command batches: encoders that append RDC_CMD words to a growable array.
 * Arguments are not validated here; the device does that, so a batch can
 * carry deliberately bad commands for hardware tests.
 */
#include <stdlib.h>
#include <string.h>

#include "rdc_priv.h"

/* A batch never grows past what a sane client would queue at once. */
#define BATCH_MAX_WORDS (64u << 20)
#define BATCH_FIRST_CAP 256u

struct rdc_batch {
	uint32_t *w;
	size_t n, cap;
	size_t fg_end; /* rdc_batch_fg_next's SET_FG ends here (else 0) */
	bool surfaces; /* a SET_DST or SET_SRC among the words */
};

rdc_batch *rdc_batch_new(void)
{
	return calloc(1, sizeof(rdc_batch));
}

void rdc_batch_free(rdc_batch *b)
{
	if (!b)
		return;
	free(b->w);
	free(b);
}

void rdc_batch_reset(rdc_batch *b)
{
	if (b) {
		b->n = b->fg_end = 0;
		b->surfaces = false;
	}
}

const uint32_t *rdc_batch_words(const rdc_batch *b, size_t *n)
{
	if (n)
		*n = b ? b->n : 0;
	return b ? b->w : NULL;
}

static int batch_grow(rdc_batch *b, size_t more)
{
	size_t cap;
	uint32_t *w;

	if (!b)
		return RDC_E_INVAL;
	if (more > BATCH_MAX_WORDS - b->n)
		return RDC_E_NOMEM;
	if (b->n + more <= b->cap)
		return 0;
	cap = b->cap ? b->cap : BATCH_FIRST_CAP;
	while (cap < b->n + more)
		cap *= 2;
	w = realloc(b->w, cap * sizeof(*w));
	if (!w)
		return RDC_E_NOMEM;
	b->w = w;
	b->cap = cap;
	return 0;
}

/*
 * Every command asks for room: the test that it has some is inline, the
 * growing is not.  The capacity doubles from BATCH_FIRST_CAP and stops at
 * the first power of two that holds the words, so it never passes
 * BATCH_MAX_WORDS: room within it is room within the limit.
 */
static inline int batch_reserve(rdc_batch *b, size_t more)
{
	if (b && more <= b->cap - b->n)
		return 0;
	return batch_grow(b, more);
}

/*
 * Header plus `n` arguments; the space for the arguments is returned.
 * Right after rdc_batch_fg_next, a command that takes RDC_DRAW_FG takes
 * that SET_FG's colour in its place.
 */
static inline uint32_t *batch_open(rdc_batch *b, uint32_t op, uint32_t flags,
				   size_t n, int *err)
{
	uint32_t *p;

	if (b && (op == RDC_OP_SET_DST || op == RDC_OP_SET_SRC))
		b->surfaces = true;
	if (b && b->fg_end == b->n && b->n >= 2 && rdc_cmd_takes_fg(op) &&
	    n < RDC_CMD_LENGTH) {
		/* [SET_FG, c] becomes [op | DRAW_FG, c, args...] */
		*err = batch_reserve(b, n);
		if (*err)
			return NULL;
		b->fg_end = 0;
		p = b->w + b->n - 2;
		p[0] = RDC_CMD(op, flags | RDC_DRAW_FG, n + 1);
		b->n += n;
		return p + 2;
	}
	*err = batch_reserve(b, n + 1);
	if (*err)
		return NULL;
	p = b->w + b->n;
	p[0] = RDC_CMD(op, flags, n);
	b->n += n + 1;
	return p + 1;
}

int rdc_batch_cmd(rdc_batch *b, uint32_t op, uint32_t flags,
		  const uint32_t *args, size_t n)
{
	uint32_t *p;
	int err;

	/* The length field is 16 bits; longer would silently wrap. */
	if ((!args && n) || n > RDC_CMD_LENGTH)
		return RDC_E_INVAL;
	if (b)
		b->fg_end = 0; /* the words asked for, as they are */
	p = batch_open(b, op, flags, n, &err);
	if (p && n)
		memcpy(p, args, n * sizeof(*p));
	return err;
}

/* rdc_batch_cmd for n <= 4 arguments, stored one by one (no memcpy call). */
static int batch_args(rdc_batch *b, uint32_t op, size_t n, uint32_t a0,
		      uint32_t a1, uint32_t a2, uint32_t a3)
{
	uint32_t *p;
	int err;

	p = batch_open(b, op, 0, n, &err);
	if (!p)
		return err;
	if (n > 0)
		p[0] = a0;
	if (n > 1)
		p[1] = a1;
	if (n > 2)
		p[2] = a2;
	if (n > 3)
		p[3] = a3;
	return 0;
}

int rdc_batch_nop(rdc_batch *b)
{
	return batch_args(b, RDC_OP_NOP, 0, 0, 0, 0, 0);
}

int rdc_batch_fence(rdc_batch *b, uint32_t value)
{
	return batch_args(b, RDC_OP_FENCE, 1, value, 0, 0, 0);
}

int rdc_batch_wait_vblank(rdc_batch *b)
{
	return batch_args(b, RDC_OP_WAIT_VBLANK, 0, 0, 0, 0, 0);
}

int rdc_batch_wait_line(rdc_batch *b, uint32_t line)
{
	return batch_args(b, RDC_OP_WAIT_LINE, 1, line, 0, 0, 0);
}

int rdc_batch_reg_write(rdc_batch *b, uint32_t reg, uint32_t val)
{
	return batch_args(b, RDC_OP_REG_WRITE, 2, reg, val, 0, 0);
}

int rdc_batch_load_clut(rdc_batch *b, uint32_t first, const uint32_t *rgb,
			size_t n)
{
	uint32_t *p;
	int err;

	if (!rgb && n)
		return RDC_E_INVAL;
	if (n > RDC_CLUT_ENTRIES)
		return RDC_E_INVAL;
	p = batch_open(b, RDC_OP_LOAD_CLUT, 0, n + 1, &err);
	if (p) {
		p[0] = first;
		if (n)
			memcpy(p + 1, rgb, n * sizeof(*p));
	}
	return err;
}

int rdc_batch_fg(rdc_batch *b, uint32_t pixel)
{
	return batch_args(b, RDC_OP_SET_FG, 1, pixel, 0, 0, 0);
}

int rdc_batch_fg_next(rdc_batch *b, uint32_t pixel)
{
	int err = rdc_batch_fg(b, pixel);

	if (!err)
		b->fg_end = b->n;
	return err;
}

int rdc_batch_bg(rdc_batch *b, uint32_t pixel)
{
	return batch_args(b, RDC_OP_SET_BG, 1, pixel, 0, 0, 0);
}

int rdc_batch_rop(rdc_batch *b, uint32_t rop)
{
	return batch_args(b, RDC_OP_SET_ROP, 1, rop, 0, 0, 0);
}

int rdc_batch_clip(rdc_batch *b, int x0, int y0, int x1, int y1)
{
	return batch_args(b, RDC_OP_SET_CLIP, 2, RDC_XY(x0, y0), RDC_XY(x1, y1),
			  0, 0);
}

int rdc_batch_dst(rdc_batch *b, uint32_t base, uint32_t stride, uint32_t w,
		  uint32_t h, uint32_t format)
{
	return batch_args(b, RDC_OP_SET_DST, 4, base, stride, RDC_WH(w, h),
			  format);
}

int rdc_batch_src(rdc_batch *b, uint32_t base, uint32_t stride, uint32_t w,
		  uint32_t h, uint32_t format)
{
	return batch_args(b, RDC_OP_SET_SRC, 4, base, stride, RDC_WH(w, h),
			  format);
}

int rdc_batch_pixel(rdc_batch *b, int x, int y)
{
	return batch_args(b, RDC_OP_PIXEL, 1, RDC_XY(x, y), 0, 0, 0);
}

int rdc_batch_line(rdc_batch *b, int x0, int y0, int x1, int y1)
{
	return batch_args(b, RDC_OP_LINE, 2, RDC_XY(x0, y0), RDC_XY(x1, y1), 0,
			  0);
}

int rdc_batch_polyline(rdc_batch *b, const int *xy, size_t n)
{
	uint32_t *p;
	int err;

	if ((!xy && n) || n > RDC_CMD_LENGTH)
		return RDC_E_INVAL;
	p = batch_open(b, RDC_OP_POLYLINE, 0, n, &err);
	for (size_t i = 0; p && i < n; i++)
		p[i] = RDC_XY(xy[2 * i], xy[2 * i + 1]);
	return err;
}

int rdc_batch_rect(rdc_batch *b, int x, int y, uint32_t w, uint32_t h)
{
	return batch_args(b, RDC_OP_RECT, 2, RDC_XY(x, y), RDC_WH(w, h), 0, 0);
}

int rdc_batch_fill_rect(rdc_batch *b, int x, int y, uint32_t w, uint32_t h)
{
	return batch_args(b, RDC_OP_FILL_RECT, 2, RDC_XY(x, y), RDC_WH(w, h), 0,
			  0);
}

int rdc_batch_circle(rdc_batch *b, int cx, int cy, uint32_t r)
{
	return batch_args(b, RDC_OP_CIRCLE, 2, RDC_XY(cx, cy), r, 0, 0);
}

int rdc_batch_fill_circle(rdc_batch *b, int cx, int cy, uint32_t r)
{
	return batch_args(b, RDC_OP_FILL_CIRCLE, 2, RDC_XY(cx, cy), r, 0, 0);
}

int rdc_batch_ellipse(rdc_batch *b, int cx, int cy, uint32_t rx, uint32_t ry)
{
	return batch_args(b, RDC_OP_ELLIPSE, 2, RDC_XY(cx, cy), RDC_WH(rx, ry),
			  0, 0);
}

int rdc_batch_fill_ellipse(rdc_batch *b, int cx, int cy, uint32_t rx,
			   uint32_t ry)
{
	return batch_args(b, RDC_OP_FILL_ELLIPSE, 2, RDC_XY(cx, cy),
			  RDC_WH(rx, ry), 0, 0);
}

int rdc_batch_blit(rdc_batch *b, int sx, int sy, int dx, int dy, uint32_t w,
		   uint32_t h)
{
	return batch_args(b, RDC_OP_BLIT, 3, RDC_XY(sx, sy), RDC_XY(dx, dy),
			  RDC_WH(w, h), 0);
}

/* Rows of 8 pixels or fewer, a byte each, into a word each. */
static rdc_always_inline void mono8_rows(uint32_t *p, const uint8_t *bits,
					 size_t h)
{
	size_t r = 0;

	/* 16 rows at a time through a copy the stores cannot alias:
	 * the compiler widens them 4 or 8 at a time */
	for (; r + 16 <= h; r += 16, p += 16) {
		uint8_t rows[16];

		memcpy(rows, bits + r, sizeof(rows));
		for (size_t k = 0; k < 16; k++)
			p[k] = rows[k];
	}
	for (; r < h; r++)
		*p++ = bits[r];
}

/*
 * MONO, with fg and bg ahead of the rows when `colors` is given.  Inline
 * in both encoders: each knows whether colours come, so the argument
 * count and the tests on `colors` fold away.
 */
static rdc_always_inline int batch_mono(rdc_batch *b, int x, int y, uint32_t w,
					uint32_t h, const uint8_t *bits,
					int transparent, const uint32_t *colors)
{
	size_t row_bytes = ((size_t)w + 7) / 8;
	size_t row_words = (row_bytes + 3) / 4;
	size_t args =
		rdc_cmd_data_at(RDC_OP_MONO, colors ? RDC_MONO_COLORS : 0);
	uint32_t *p;
	int err;

	if (w > RDC_SIZE_MAX || h > RDC_SIZE_MAX || (!bits && w && h))
		return RDC_E_INVAL;
	if (args + row_words * h > RDC_CMD_LENGTH)
		return RDC_E_INVAL;
	p = batch_open(b, RDC_OP_MONO,
		       (transparent ? RDC_MONO_TRANSPARENT : 0) |
			       (colors ? RDC_MONO_COLORS : 0),
		       (uint32_t)(args + row_words * h), &err);
	if (!p)
		return err;
	p[0] = RDC_XY(x, y);
	p[1] = RDC_WH(w, h);
	if (colors) {
		p[2] = colors[0];
		p[3] = colors[1];
	}
	p += args;
	if (row_bytes == 1) { /* 8-pixel glyphs, the console's case */
		mono8_rows(p, bits, h);
		return 0;
	}
	for (size_t r = 0; r < h; r++) {
		for (size_t k = 0; k < row_words; k++) {
			uint8_t pad[4] = { 0 };
			size_t nb = RDC_MIN((size_t)4, row_bytes - 4 * k);

			memcpy(pad, bits + r * row_bytes + 4 * k, nb);
			*p++ = rdc_ld32(pad);
		}
	}
	return 0;
}

int rdc_batch_mono(rdc_batch *b, int x, int y, uint32_t w, uint32_t h,
		   const uint8_t *bits, int transparent)
{
	return batch_mono(b, x, y, w, h, bits, transparent, NULL);
}

static rdc_noinline int batch_mono_colors(rdc_batch *b, int x, int y,
					  uint32_t w, uint32_t h,
					  const uint8_t *bits, uint32_t fg,
					  uint32_t bg, int transparent)
{
	const uint32_t colors[2] = { fg, bg };

	return batch_mono(b, x, y, w, h, bits, transparent, colors);
}

int rdc_batch_mono_colors(rdc_batch *b, int x, int y, uint32_t w, uint32_t h,
			  const uint8_t *bits, uint32_t fg, uint32_t bg,
			  int transparent)
{
	size_t n = rdc_cmd_data_at(RDC_OP_MONO, RDC_MONO_COLORS) + h;
	uint32_t *p;

	/*
	 * A glyph of 16 rows up to 8 pixels wide (a console's 8x16 cell,
	 * one a character) with room for it and no SET_FG to take in is
	 * written here with no call, nothing kept across one, and its rows
	 * in one widened copy; anything else goes the whole way, a call
	 * that may grow the batch.  Same words either way.
	 */
	if (!b || !bits || w - 1 >= 8 || h != 16 || n + 1 > b->cap - b->n ||
	    (b->fg_end == b->n && b->n >= 2))
		return batch_mono_colors(b, x, y, w, h, bits, fg, bg,
					 transparent);
	p = b->w + b->n;
	b->n += n + 1;
	p[0] = RDC_CMD(RDC_OP_MONO,
		       (transparent ? RDC_MONO_TRANSPARENT : 0) |
			       RDC_MONO_COLORS,
		       (uint32_t)n);
	p[1] = RDC_XY(x, y);
	p[2] = RDC_WH(w, h);
	p[3] = fg;
	p[4] = bg;
	mono8_rows(p + 5, bits, h);
	return 0;
}

int rdc_batch_text(rdc_batch *b, int x, int y, const char *s, size_t len,
		   int transparent)
{
	size_t words = (len + 3) / 4;
	uint32_t *p;
	int err;

	if ((!s && len) || 2 + words > RDC_CMD_LENGTH)
		return RDC_E_INVAL;
	p = batch_open(b, RDC_OP_TEXT, transparent ? RDC_MONO_TRANSPARENT : 0,
		       2 + words, &err);
	if (!p)
		return err;
	p[0] = RDC_XY(x, y);
	p[1] = (uint32_t)len;
	for (size_t k = 0; k < words; k++) {
		uint8_t pad[4] = { 0 };

		memcpy(pad, s + 4 * k, RDC_MIN((size_t)4, len - 4 * k));
		p[2 + k] = rdc_ld32(pad);
	}
	return 0;
}

int rdc_batch_submit(rdc_dev *dev, rdc_batch *b)
{
	int ret;

	if (!dev || !b)
		return RDC_E_INVAL;
	ret = rdc_submit_whole(dev, b->w, b->n, b->surfaces);
	rdc_batch_reset(b);
	return ret;
}

int rdc_batch_pen(rdc_batch *b, uint32_t width, uint32_t cap, uint32_t join)
{
	return batch_args(b, RDC_OP_SET_PEN, 1,
			  FIELD_PREP(RDC_PEN_WIDTH, width & 0xff) |
				  FIELD_PREP(RDC_PEN_CAP, cap & 3) |
				  FIELD_PREP(RDC_PEN_JOIN, join & 3),
			  0, 0, 0);
}

int rdc_batch_dash(rdc_batch *b, uint32_t pattern, uint32_t len,
		   uint32_t offset)
{
	return batch_args(b, RDC_OP_SET_DASH, 2, pattern,
			  FIELD_PREP(RDC_DASH_LEN, len & 0x3f) |
				  FIELD_PREP(RDC_DASH_OFFSET, offset & 0x3f),
			  0, 0);
}

/* n points of xy as one command of opcode op with flags. */
static int batch_points(rdc_batch *b, uint32_t op, uint32_t flags,
			const int *xy, size_t n)
{
	uint32_t *p;
	int err;

	if ((!xy && n) || n > RDC_CMD_LENGTH)
		return RDC_E_INVAL;
	p = batch_open(b, op, flags, n, &err);
	for (size_t i = 0; p && i < n; i++)
		p[i] = RDC_XY(xy[2 * i], xy[2 * i + 1]);
	return err;
}

int rdc_batch_polygon(rdc_batch *b, const int *xy, size_t n)
{
	return batch_points(b, RDC_OP_POLYGON, 0, xy, n);
}

int rdc_batch_arc(rdc_batch *b, int cx, int cy, uint32_t rx, uint32_t ry,
		  uint32_t start, uint32_t end, uint32_t mode)
{
	const uint32_t a[3] = {
		RDC_XY(cx, cy),
		RDC_WH(rx, ry),
		FIELD_PREP(RDC_ARC_START, start & 0xffff) |
			FIELD_PREP(RDC_ARC_END, end & 0xffff),
	};

	return rdc_batch_cmd(b, RDC_OP_ARC, mode, a, 3);
}

int rdc_batch_bezier(rdc_batch *b, const int *xy, uint32_t steps)
{
	return batch_points(b, RDC_OP_BEZIER, steps, xy, xy ? 4 : 1);
}

int rdc_batch_hermite(rdc_batch *b, const int *xy, uint32_t steps)
{
	return batch_points(b, RDC_OP_HERMITE, steps, xy, xy ? 4 : 1);
}

int rdc_batch_bspline(rdc_batch *b, const int *xy, size_t n, uint32_t steps)
{
	return batch_points(b, RDC_OP_BSPLINE, steps, xy, n);
}

int rdc_batch_transform(rdc_batch *b, const int32_t *m)
{
	uint32_t a[9];

	if (!m)
		return rdc_batch_cmd(b, RDC_OP_SET_TRANSFORM, 0, NULL, 0);
	for (int i = 0; i < 9; i++)
		a[i] = (uint32_t)m[i];
	return rdc_batch_cmd(b, RDC_OP_SET_TRANSFORM, 0, a, 9);
}

int rdc_batch_viewport(rdc_batch *b, int32_t wx0, int32_t wy0, int32_t wx1,
		       int32_t wy1, int x0, int y0, int x1, int y1)
{
	const uint32_t a[6] = {
		(uint32_t)wx0, (uint32_t)wy0,  (uint32_t)wx1,
		(uint32_t)wy1, RDC_XY(x0, y0), RDC_XY(x1, y1),
	};

	return rdc_batch_cmd(b, RDC_OP_SET_VIEWPORT, 0, a, 6);
}

int rdc_batch_fill_polygon(rdc_batch *b, const int *xy, size_t n, int nonzero)
{
	return batch_points(b, RDC_OP_FILL_POLYGON,
			    nonzero ? RDC_FILL_NONZERO : 0, xy, n);
}

int rdc_batch_flood(rdc_batch *b, int x, int y, uint32_t flags,
		    uint32_t boundary)
{
	const uint32_t a[2] = { RDC_XY(x, y), boundary };

	return rdc_batch_cmd(b, RDC_OP_FLOOD_FILL, flags, a,
			     flags & RDC_FLOOD_BOUNDARY ? 2 : 1);
}

int rdc_batch_pattern_none(rdc_batch *b)
{
	return rdc_batch_cmd(b, RDC_OP_SET_PATTERN, RDC_PAT_NONE, NULL, 0);
}

int rdc_batch_pattern_mono(rdc_batch *b, const uint8_t rows[8], int transparent)
{
	uint32_t a[2] = { 0, 0 };

	if (!rows)
		return RDC_E_INVAL;
	for (int i = 0; i < 8; i++)
		a[i / 4] |= (uint32_t)rows[i] << (8 * (i % 4));
	return rdc_batch_cmd(
		b, RDC_OP_SET_PATTERN,
		transparent ? RDC_PAT_MONO_TRANSPARENT : RDC_PAT_MONO, a, 2);
}

int rdc_batch_pattern_color(rdc_batch *b, const uint32_t px[64])
{
	if (!px)
		return RDC_E_INVAL;
	return rdc_batch_cmd(b, RDC_OP_SET_PATTERN, RDC_PAT_COLOR, px, 64);
}

int rdc_batch_triangle(rdc_batch *b, const int *xy, const uint32_t *colour,
		       const uint32_t *z, int gouraud)
{
	uint32_t a[9];

	if (!xy || !colour || !z)
		return RDC_E_INVAL;
	for (int i = 0; i < 3; i++) {
		a[3 * i] = RDC_XY(xy[2 * i], xy[2 * i + 1]);
		a[3 * i + 1] = colour[i];
		a[3 * i + 2] = z[i];
	}
	return rdc_batch_cmd(b, RDC_OP_TRIANGLE, gouraud ? RDC_TRI_GOURAUD : 0,
			     a, 9);
}

int rdc_batch_zbuf(rdc_batch *b, uint32_t base, uint32_t stride, uint32_t flags)
{
	const uint32_t a[2] = { base, stride };

	return rdc_batch_cmd(b, RDC_OP_SET_ZBUF, flags, a, 2);
}

int rdc_batch_zbuf_off(rdc_batch *b)
{
	return rdc_batch_cmd(b, RDC_OP_SET_ZBUF, 0, NULL, 0);
}

int rdc_batch_clear_z(rdc_batch *b, uint32_t value)
{
	return rdc_batch_cmd(b, RDC_OP_CLEAR_Z, 0, &value, 1);
}

int rdc_batch_aa_line(rdc_batch *b, int x0, int y0, int x1, int y1)
{
	return batch_args(b, RDC_OP_AA_LINE, 2, RDC_XY(x0, y0), RDC_XY(x1, y1),
			  0, 0);
}

int rdc_batch_aa_circle(rdc_batch *b, int cx, int cy, uint32_t r)
{
	return batch_args(b, RDC_OP_AA_CIRCLE, 2, RDC_XY(cx, cy), r, 0, 0);
}

int rdc_batch_aa_ellipse(rdc_batch *b, int cx, int cy, uint32_t rx, uint32_t ry)
{
	return batch_args(b, RDC_OP_AA_ELLIPSE, 2, RDC_XY(cx, cy),
			  RDC_WH(rx, ry), 0, 0);
}

int rdc_batch_aa_ramp(rdc_batch *b, uint32_t n)
{
	return batch_args(b, RDC_OP_SET_AA_RAMP, 1, n, 0, 0, 0);
}

int rdc_batch_alpha(rdc_batch *b, uint32_t alpha)
{
	return batch_args(b, RDC_OP_SET_ALPHA, 1, alpha, 0, 0, 0);
}

int rdc_batch_colorkey(rdc_batch *b, uint32_t key, int enable)
{
	return rdc_batch_cmd(b, RDC_OP_SET_COLORKEY,
			     enable ? RDC_COLORKEY_ENABLE : 0, &key, 1);
}

int rdc_batch_call(rdc_batch *b, uint32_t addr)
{
	return batch_args(b, RDC_OP_CALL, 1, addr, 0, 0, 0);
}

int rdc_batch_ret(rdc_batch *b)
{
	return batch_args(b, RDC_OP_RET, 0, 0, 0, 0, 0);
}

int rdc_batch_jump(rdc_batch *b, uint32_t addr)
{
	return batch_args(b, RDC_OP_JUMP, 1, addr, 0, 0, 0);
}
