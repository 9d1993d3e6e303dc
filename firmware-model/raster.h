/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Shared by the rasterisers (span.c, line.c, shape.c, blit.c, mono.c):
 * pixel access, the solid runs and their queue.  Not for other files.
 */
#ifndef RDC_RASTER_H
#define RDC_RASTER_H

#include "dp_int.h"
#include "../hw-sim/bus.h"

static inline uint32_t fmt_mask(unsigned int bpp)
{
	return bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
}

#define FILL_BLOCK 64 /* a run of this many bytes or more takes fill32_blocks */
#define FILL_STORE 32 /* bytes of pattern one store of dp_fill32 writes */

/*
 * len bytes (FILL_STORE or more) of the pattern blk, one XRGB8888 pixel
 * repeated, at p: stores of the whole block, which the compiler keeps in
 * registers (wide stores, no reads): the first block where the pixels
 * start, the others from the first 16-byte boundary on, so that no store
 * but the first and the last splits a cache line, two blocks a pass
 * (pixman's fill does the same; rdc-bench's fill with scanout off about
 * 3% less CPU), the last one ending at the end (overlapping the one
 * before: every pixel is the same).  Pixels not 4-byte aligned in memory
 * keep their phase by not being realigned.  A caller filling many rows
 * builds blk once, outside its loop, where it stays in registers.
 */
static rdc_always_inline void fill32_blocks(uint8_t *p, const uint8_t *blk,
					    size_t len)
{
	uint8_t *e = p + len;

	rdc_memcpy(p, blk, FILL_STORE);
	if (((uintptr_t)p & 3) == 0)
		p = (uint8_t *)(((uintptr_t)p + 16) & ~(uintptr_t)15);
	else
		p += FILL_STORE;
	for (; p + 2 * FILL_STORE <= e; p += 2 * FILL_STORE) {
		rdc_memcpy(p, blk, FILL_STORE);
		rdc_memcpy(p + FILL_STORE, blk, FILL_STORE);
	}
	if (p + FILL_STORE <= e) {
		rdc_memcpy(p, blk, FILL_STORE);
		p += FILL_STORE;
	}
	if (p < e)
		rdc_memcpy(e - FILL_STORE, blk, FILL_STORE);
}

/* n XRGB8888 pixels of v: memset when its bytes agree, else fill32_blocks. */
static inline void dp_fill32(uint8_t *p, uint32_t v, uint32_t n)
{
	size_t len = (size_t)n * 4, i;
	uint8_t blk[FILL_STORE];

	if ((v & 0xff) * 0x01010101u == v) {
		rdc_memset(p, (int)(v & 0xff), len);
		return;
	}
	if (len < FILL_STORE) {
		for (i = 0; i < len; i += 4)
			rdc_st32(p + i, v);
		return;
	}
	for (i = 0; i < FILL_STORE; i += 4)
		rdc_st32(blk + i, v);
	fill32_blocks(p, blk, len);
}

/*
 * A run of v (XRGB8888, `pair` holding it twice in VRAM byte order) at q:
 * a span, or a column of r->count pixels `stride` apart.  Every pixel is
 * v, so 8-byte stores of two of them may overlap: a short span's first
 * and last 8, 16 or 32 bytes cover it in a fixed number of stores.
 * Returns the pixels written.
 */
static inline uint32_t run_store32(uint8_t *q, const struct rdc_port_run *r,
				   uint32_t stride, const uint8_t *pair,
				   uint32_t v)
{
	uint32_t len = r->len, cnt = r->count, k;

	if (cnt != 1) {
		/* the count held in a register: byte stores may alias r */
		for (k = 0; k < cnt; k++, q += stride)
			rdc_memcpy(q, pair, 4);
		return cnt;
	}
	if (len == 4) {
		rdc_memcpy(q, pair, 4);
	} else if (len <= 16) {
		rdc_memcpy(q, pair, 8);
		rdc_memcpy(q + len - 8, pair, 8);
	} else if (len <= 32) {
		rdc_memcpy(q, pair, 8);
		rdc_memcpy(q + 8, pair, 8);
		rdc_memcpy(q + len - 16, pair, 8);
		rdc_memcpy(q + len - 8, pair, 8);
	} else if (len < FILL_BLOCK) {
		for (k = 0; k < 32; k += 8)
			rdc_memcpy(q + k, pair, 8);
		for (k = 0; k < 32; k += 8)
			rdc_memcpy(q + len - 32 + k, pair, 8);
	} else {
		dp_fill32(q, v, len / 4);
	}
	return len / 4;
}

/*
 * DST formats the run queue takes (see span.c): whole bytes,
 * pixel-aligned (a pixel never straddles a burst, so a one-pixel column
 * is a one-pixel span).  Inline: every line asks.
 */
static inline bool dp_runs_ok(const struct rdc_dp *dp)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);

	/* bpp / 8 a power of two: a mask, not a division (every command) */
	return !dp->ref_paths && (bpp == 8 || bpp == 16 || bpp == 32) &&
	       ((s->base | s->stride) & (bpp / 8 - 1)) == 0;
}
/* The pixels of run r at p with colour fg through the ROP. */
void dp_run_write(struct rdc_dp *dp, uint8_t *p, const struct rdc_port_run *r,
		  uint32_t fg);
/*
 * Run r, refused by the open port window w (a scanout event falls in
 * it), charged and written in the window across the line start that
 * falls in it, or else as its rdc_port_span / rdc_port_column call
 * charges it, w closed around the call and open again after it.
 * *pixels, a perf count the caller has not yet added, is added before
 * that port call (which could let someone look at it).
 */
void dp_run_refused(struct rdc_dp *dp, struct rdc_port_window *w,
		    const struct rdc_port_run *r, unsigned int kind,
		    uint64_t *pixels);
/* Charge and write the queued runs dp->runs[0, nruns). */
void dp_runs_flush(struct rdc_dp *dp);
/* Queue count pixels down from x, y (count 1: n pixels across). */
void dp_queue_run(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t n,
		  uint32_t count);
/* Solid span [xa, xb] of row y, clipped here. */
void dp_span_fill(struct rdc_dp *dp, const struct rdc_rect *c, int32_t y,
		  int32_t xa, int32_t xb, uint32_t colour);
/* Solid vertical run [ya, yb] of column x, clipped here. */
void dp_col_fill(struct rdc_dp *dp, const struct rdc_rect *c, int32_t x,
		 int32_t ya, int32_t yb, uint32_t colour);
/* The staged pixels dp->px[0, n) of a BLIT or HOST_BLIT to DST row y. */
void dp_blit_span(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n);

/* Does the global alpha let a BLIT or HOST_BLIT draw at all? */
static inline bool blit_drawn(const struct rdc_dp *dp)
{
	return !rdc_format_indexed(dp->st.dst.format) ||
	       dp->st.alpha >= RDC_ALPHA_THRESHOLD;
}

#endif /* RDC_RASTER_H */
