// SPDX-License-Identifier: GPL-2.0-only
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
	if (b)
		b->n = 0;
}

const uint32_t *rdc_batch_words(const rdc_batch *b, size_t *n)
{
	if (n)
		*n = b ? b->n : 0;
	return b ? b->w : NULL;
}

static int batch_reserve(rdc_batch *b, size_t more)
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

/* Header plus `n` arguments; the space for the arguments is returned. */
static uint32_t *batch_open(rdc_batch *b, uint32_t op, uint32_t flags, size_t n,
			    int *err)
{
	uint32_t *p;

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
	p = batch_open(b, op, flags, n, &err);
	if (p && n)
		memcpy(p, args, n * sizeof(*p));
	return err;
}

static int batch_args(rdc_batch *b, uint32_t op, size_t n, uint32_t a0,
		      uint32_t a1, uint32_t a2, uint32_t a3)
{
	const uint32_t a[4] = {a0, a1, a2, a3};

	return rdc_batch_cmd(b, op, 0, a, n);
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

int rdc_batch_mono(rdc_batch *b, int x, int y, uint32_t w, uint32_t h,
		   const uint8_t *bits, int transparent)
{
	size_t row_bytes = ((size_t)w + 7) / 8;
	size_t row_words = (row_bytes + 3) / 4;
	uint32_t *p;
	int err;

	if (w > RDC_SIZE_MAX || h > RDC_SIZE_MAX || (!bits && w && h))
		return RDC_E_INVAL;
	if (2 + row_words * h > RDC_CMD_LENGTH)
		return RDC_E_INVAL;
	p = batch_open(b, RDC_OP_MONO, transparent ? RDC_MONO_TRANSPARENT : 0,
		       2 + row_words * h, &err);
	if (!p)
		return err;
	p[0] = RDC_XY(x, y);
	p[1] = RDC_WH(w, h);
	p += 2;
	for (size_t r = 0; r < h; r++) {
		for (size_t k = 0; k < row_words; k++) {
			uint8_t pad[4] = {0};
			size_t nb = RDC_MIN((size_t)4, row_bytes - 4 * k);

			memcpy(pad, bits + r * row_bytes + 4 * k, nb);
			*p++ = rdc_ld32(pad);
		}
	}
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
		uint8_t pad[4] = {0};

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
	ret = rdc_submit(dev, b->w, b->n);
	b->n = 0;
	return ret;
}
