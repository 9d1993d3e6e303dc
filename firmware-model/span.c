// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The display processor's rasterisers, split by primitive: span.c (this
 * file: spans, columns and the queue of solid runs every other one ends
 * in), line.c, shape.c (rectangles, circles, ellipses), blit.c (BLIT, the
 * ROPs, READBACK) and mono.c (HOST_BLIT, MONO, TEXT).  Every primitive is
 * decomposed into horizontal spans (one rdc_port_span call each) or
 * vertical runs (one rdc_port_column call each), so the bus model charges
 * whole bursts and the cost of a command follows from the work it does.
 * The tests hold the plain per-pixel versions these are checked against
 * (tests/unit/ref*.c).
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "raster.h"

/*
 * Write pixels [xa, xa + n) of destination row y, already inside the
 * effective clip.  vals == NULL: every pixel gets `solid`; on != NULL:
 * only pixels with on[i] set are written (transparent mono and text),
 * which the bus sees as a read-modify-write of the whole span.
 */
static void span_emit(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		      uint32_t solid, const uint32_t *vals, const uint8_t *on)
{
	struct rdc_hw *hw = dp->hw;
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);
	unsigned int rop = dp->st.rop;
	uint32_t mask = fmt_mask(bpp);
	uint64_t bit0 = (uint64_t)xa * bpp, bit1 = bit0 + (uint64_t)n * bpp;
	uint32_t addr, len, first, i, cnt = n;
	unsigned int kind;
	uint8_t *p;

	if (!n)
		return;
	addr = s->base + (uint32_t)y * s->stride + (uint32_t)(bit0 / 8);
	len = (uint32_t)((bit1 + 7) / 8 - bit0 / 8);
	if (on || rdc_rop_reads_dst(rop)) {
		kind = RDC_BUS_RMW;
	} else {
		kind = RDC_BUS_WRITE;
		if (bit0 & 7)
			kind |= RDC_BUS_HEAD_PARTIAL;
		if (bit1 & 7)
			kind |= RDC_BUS_TAIL_PARTIAL;
	}
	p = rdc_port_span(hw, addr, len, kind);
	if (!p)
		return;
	first = (uint32_t)(bit0 & 7);

	if (!vals && !on && !rdc_rop_reads_dst(rop)) {
		/* Solid fill that ignores the destination: memset speed. */
		uint32_t v = rdc_rop_apply(rop, solid, 0) & mask;

		if (bpp == 32) {
			dp_fill32(p, v, n);
			hw->perf.pixels += n;
			return;
		}
		if (bpp == 8) {
			rdc_memset(p, (int)v, n);
			hw->perf.pixels += n;
			return;
		}
	}

	if (vals && !on && bpp >= 8 && !dp->ref_paths &&
	    (rop == RDC_ROP_COPY || rop == RDC_ROP_COPY_INVERTED)) {
		/* Staged pixels over a destination the ROP ignores. */
		uint32_t inv = rop == RDC_ROP_COPY ? 0 : mask;

		switch (bpp) {
		case 32:
			for (i = 0; i < n; i++)
				rdc_st32(p + 4 * i, vals[i] ^ inv);
			break;
		case 24:
			for (i = 0; i < n; i++)
				rdc_st24(p + 3 * i, (vals[i] ^ inv) & mask);
			break;
		case 16:
			for (i = 0; i < n; i++)
				rdc_st16(p + 2 * i, (vals[i] ^ inv) & mask);
			break;
		default:
			for (i = 0; i < n; i++)
				p[i] = (uint8_t)(vals[i] ^ inv);
			break;
		}
		hw->perf.pixels += n;
		return;
	}

	for (i = 0; i < n; i++) {
		uint32_t bit = first + i * bpp, s_px, d_px;

		if (on && !on[i]) {
			cnt--;
			continue;
		}
		s_px = vals ? vals[i] : solid;
		d_px = rdc_rop_reads_dst(rop) ? rdc_px_get(p, bpp, bit) : 0;
		rdc_px_put(p, bpp, bit, rdc_rop_apply(rop, s_px, d_px) & mask);
	}
	hw->perf.pixels += cnt;
}

/*
 * Queued solid runs.  Lines and outlines are many runs of a few pixels;
 * rather than a port call each, they are queued in dp->runs and charged
 * together in a port window (rdc_port_window_runs), which takes them for
 * as long as no scanout event falls inside; the run it stops at goes
 * through dp_run_refused.  Each run is charged and written exactly as
 * dp_span_fill / dp_col_fill would, so pixels, cycles and counters are
 * the same, for the DST formats dp_runs_ok (raster.h) takes.
 */

/* The pixels of run r at p with colour fg through the ROP. */
void dp_run_write(struct rdc_dp *dp, uint8_t *p, const struct rdc_port_run *r,
		  uint32_t fg)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format), rop = dp->st.rop;
	uint32_t mask = fmt_mask(bpp), bytes = bpp / 8, k;
	uint32_t n = r->count == 1 ? r->len / bytes : r->count;
	uint32_t step = r->count == 1 ? bytes : s->stride;

	if (!rdc_rop_reads_dst(rop)) {
		uint32_t v = rdc_rop_apply(rop, fg, 0) & mask;

		if (bpp == 32 && r->count == 1) {
			dp_fill32(p, v, n);
		} else if (bpp == 8 && r->count == 1) {
			rdc_memset(p, (int)v, n);
		} else if (bpp == 32) {
			for (k = 0; k < n; k++, p += step)
				rdc_st32(p, v);
		} else if (bpp == 16) {
			for (k = 0; k < n; k++, p += step)
				rdc_st16(p, v);
		} else {
			for (k = 0; k < n; k++, p += step)
				*p = (uint8_t)v;
		}
	} else {
		for (k = 0; k < n; k++, p += step)
			rdc_px_put(p, bpp, 0,
				   rdc_rop_apply(rop, fg,
						 rdc_px_get(p, bpp, 0)) &
					   mask);
	}
	dp->hw->perf.pixels += n;
}

/* Runs [first, first + n) charged in the port window, their bytes at p. */
static void runs_write(struct rdc_dp *dp, uint8_t *p, uint32_t first,
		       uint32_t n)
{
	const struct rdc_surface *s = &dp->st.dst;
	const struct rdc_port_run *r = dp->runs + first, *end = r + n;
	uint32_t stride = s->stride, v, k;
	uint64_t pixels = 0;
	uint8_t pair[8], blk[FILL_STORE];
	bool same;

	if (rdc_format_bpp(s->format) != 32 || rdc_rop_reads_dst(dp->st.rop)) {
		for (; r < end; r++)
			dp_run_write(dp, p + r->addr, r, dp->st.fg);
		return;
	}
	/*
	 * XRGB8888 over a destination the ROP ignores: plain stores, and
	 * rows of a block or more dp_fill32's wide stores.
	 */
	v = rdc_rop_apply(dp->st.rop, dp->st.fg, 0);
	rdc_st32(pair, v);
	rdc_st32(pair + 4, v);
	/* dp_fill32's pattern built once for all runs (see rect_rows32) */
	for (k = 0; k < FILL_STORE; k += 4)
		rdc_st32(blk + k, v);
	same = (v & 0xff) * 0x01010101u == v;
	for (; r < end; r++) {
		uint8_t *q = p + r->addr;

		if (r->count == 1 && r->len >= FILL_BLOCK) {
			if (same)
				rdc_memset(q, (int)(v & 0xff), r->len);
			else
				fill32_blocks(q, blk, r->len);
			pixels += r->len / 4;
			continue;
		}
		pixels += run_store32(q, r, stride, pair, v);
	}
	dp->hw->perf.pixels += pixels;
}

void dp_run_refused(struct rdc_dp *dp, struct rdc_port_window *w,
		    const struct rdc_port_run *r, unsigned int kind,
		    uint64_t *pixels)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t stride = dp->st.dst.stride;
	uint8_t *p;

	if (rdc_port_window_cross(hw, w, r, stride, kind)) {
		dp_run_write(dp, w->vram + r->addr, r, dp->st.fg);
		return;
	}
	rdc_port_window_close(hw, w);
	hw->perf.pixels += *pixels;
	*pixels = 0;
	if (r->count == 1)
		p = rdc_port_span(hw, r->addr, r->len, kind);
	else
		p = rdc_port_column(hw, r->addr, stride, r->count, r->len,
				    kind);
	if (p)
		dp_run_write(dp, p, r, dp->st.fg);
	rdc_port_window_open(hw, w);
}

void dp_runs_flush(struct rdc_dp *dp)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_hw *hw = dp->hw;
	unsigned int kind = rdc_rop_reads_dst(dp->st.rop) ? RDC_BUS_RMW :
							    RDC_BUS_WRITE;
	uint32_t i = 0, done;
	uint64_t pixels = 0; /* runs_write counts its own */
	struct rdc_port_window w;

	/*
	 * The runs in a port window: those that end by the next line start,
	 * on through it while nobody looks (rdc_port_window_runs), and the
	 * run it falls in as dp_run_refused takes it
	 */
	rdc_port_window_open(hw, &w);
	while (i < dp->nruns) {
		done = rdc_port_window_runs(hw, &w, dp->runs + i, dp->nruns - i,
					    s->stride, kind);
		runs_write(dp, w.vram, i, done);
		i += done;
		if (i == dp->nruns)
			break;
		dp_run_refused(dp, &w, &dp->runs[i++], kind, &pixels);
	}
	rdc_port_window_close(hw, &w);
	dp->nruns = 0;
}

void rdc_dp_queue_begin(struct rdc_dp *dp)
{
	dp->queue_spans = dp_runs_ok(dp) && dp->st.pat_mode == RDC_PAT_NONE;
}

void rdc_dp_queue_end(struct rdc_dp *dp)
{
	if (dp->queue_spans)
		dp_runs_flush(dp);
	dp->queue_spans = false;
}

/* Queue count pixels down from x, y (count 1: n pixels across). */
void dp_queue_run(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t n,
		  uint32_t count)
{
	const struct rdc_surface *s = &dp->st.dst;
	uint32_t bytes = rdc_format_bpp(s->format) / 8;
	struct rdc_port_run *r = &dp->runs[dp->nruns];

	r->addr = s->base + (uint32_t)y * s->stride + (uint32_t)x * bytes;
	r->len = n * bytes;
	r->count = count;
	if (++dp->nruns == RDC_DP_CHUNK)
		dp_runs_flush(dp);
}

void rdc_dp_queue_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb)
{
	dp_queue_run(dp, xa, y, (uint32_t)(xb - xa + 1), 1);
}

/* Solid span [xa, xb] of row y, clipped here. */
void dp_span_fill(struct rdc_dp *dp, const struct rdc_rect *c, int32_t y,
		  int32_t xa, int32_t xb, uint32_t colour)
{
	if (y < c->y0 || y >= c->y1)
		return;
	xa = RDC_MAX(xa, c->x0);
	xb = RDC_MIN(xb, c->x1 - 1);
	if (xa > xb)
		return;
	if (dp->queue_spans)
		dp_queue_run(dp, xa, y, (uint32_t)(xb - xa + 1), 1);
	else
		span_emit(dp, y, xa, (uint32_t)(xb - xa + 1), colour, NULL,
			  NULL);
}

/* Solid vertical run [ya, yb] of column x, clipped here. */
void dp_col_fill(struct rdc_dp *dp, const struct rdc_rect *c, int32_t x,
		 int32_t ya, int32_t yb, uint32_t colour)
{
	struct rdc_hw *hw = dp->hw;
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);
	unsigned int rop = dp->st.rop;
	uint32_t mask = fmt_mask(bpp), bit, count, k;
	unsigned int kind;
	uint8_t *p;

	if (x < c->x0 || x >= c->x1)
		return;
	ya = RDC_MAX(ya, c->y0);
	yb = RDC_MIN(yb, c->y1 - 1);
	if (ya > yb)
		return;
	if (dp->queue_spans) {
		/* one pixel is a span; pixel-aligned, it costs the same */
		dp_queue_run(dp, x, ya, 1, (uint32_t)(yb - ya + 1));
		return;
	}
	if (ya == yb) {
		span_emit(dp, ya, x, 1, colour, NULL, NULL);
		return;
	}
	count = (uint32_t)(yb - ya + 1);
	bit = (uint32_t)x * bpp;
	if (rdc_rop_reads_dst(rop))
		kind = RDC_BUS_RMW;
	else if (bpp < 8)
		kind = RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL |
		       RDC_BUS_TAIL_PARTIAL;
	else
		kind = RDC_BUS_WRITE;
	p = rdc_port_column(hw, s->base + (uint32_t)ya * s->stride + bit / 8,
			    s->stride, count, (bpp + 7) / 8, kind);
	if (!p)
		return;
	for (k = 0; k < count; k++) {
		uint8_t *q = p + (size_t)k * s->stride;
		uint32_t d = 0;

		if (rdc_rop_reads_dst(rop))
			d = rdc_px_get(q, bpp, bit & 7);

		rdc_px_put(q, bpp, bit & 7,
			   rdc_rop_apply(rop, colour, d) & mask);
	}
	hw->perf.pixels += count;
}

void rdc_dp_pixel(struct rdc_dp *dp, int32_t x, int32_t y)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);

	dp_span_fill(dp, &c, y, x, x, dp->st.fg);
}

void rdc_dp_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);

	dp_span_fill(dp, &c, y, xa, xb, dp->st.fg);
}

void rdc_dp_span_px(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		    uint32_t solid, const uint32_t *vals, const uint8_t *on)
{
	span_emit(dp, y, xa, n, solid, vals, on);
}

bool rdc_dp_read_row(struct rdc_dp *dp, const struct rdc_surface *s, int32_t y,
		     int32_t xa, uint32_t n, uint32_t *out)
{
	unsigned int bpp = rdc_format_bpp(s->format);
	uint64_t bit0 = (uint64_t)xa * bpp, bit1 = bit0 + (uint64_t)n * bpp;
	const uint8_t *p;
	uint32_t i;

	if (!n)
		return true;
	p = rdc_port_span(dp->hw,
			  s->base + (uint32_t)y * s->stride +
				  (uint32_t)(bit0 / 8),
			  (uint32_t)((bit1 + 7) / 8 - bit0 / 8), RDC_BUS_READ);
	if (!p)
		return false;
	for (i = 0; i < n; i++)
		out[i] = rdc_px_get(p, bpp, (uint32_t)(bit0 & 7) + i * bpp);
	return true;
}

bool rdc_dp_read_px(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		    uint32_t *out)
{
	return rdc_dp_read_row(dp, &dp->st.dst, y, xa, n, out);
}

uint32_t rdc_dp_px_load(const uint8_t *p, unsigned int bpp, uint32_t bit)
{
	return rdc_px_get(p, bpp, bit);
}

void rdc_dp_px_store(uint8_t *p, unsigned int bpp, uint32_t bit, uint32_t v)
{
	rdc_px_put(p, bpp, bit, v & fmt_mask(bpp));
}
