// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* RECT, FILL_RECT, CIRCLE, ELLIPSE and their fills (span.c's runs). */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "raster.h"

/*
 * The rows of a small rectangle anywhere on a large surface are each a
 * cache line or two no cache holds, and stored row after row, each row's
 * miss waits for the one before: asked for FILL_AHEAD rows ahead, they
 * come in together (rdc-bench -w growth: a 16x16 fill on a 4096-wide
 * surface 1.1-1.4 us -> 0.5 us, an 8x32 one 1.9 -> 0.7 us).  A row's
 * first and last lines are asked for; the hardware brings those between.
 * A surface of FILL_AHEAD_MIN bytes or less (1024x768 XRGB8888 is 3 MiB)
 * stays in a desktop's last-level cache, and there the asking costs more
 * than it brings: rdc-bench's fill with scanout off, about 4% more CPU.
 */
#define FILL_AHEAD     16
#define FILL_AHEAD_MIN (8u << 20)

static inline void row_prefetch(const uint8_t *p, uint32_t len)
{
	__builtin_prefetch(p, 1);
	__builtin_prefetch(p + len - 1, 1);
}

/* dp_run_write's bytes for one row of rect_rows32, the block built */
static inline void rect_row32(uint8_t *p, const uint8_t *blk, uint32_t v,
			      uint32_t n, bool fast)
{
	if (fast)
		fill32_blocks(p, blk, n * 4);
	else
		dp_fill32(p, v, n);
}

/*
 * `done` rows of len bytes (FILL_STORE or more) of blk's pixel from q,
 * `stride` apart, each row asked for FILL_AHEAD rows before it is filled
 * where `ahead` says so.
 */
static rdc_always_inline void rect_rows_fill(uint8_t *q, const uint8_t *blk,
					     uint32_t len, uint32_t stride,
					     uint32_t done, bool ahead)
{
	uint32_t k;

	if (ahead) {
		for (k = 0; k < done; k++, q += stride) {
			if (k + FILL_AHEAD < done)
				row_prefetch(q + FILL_AHEAD * stride, len);
			fill32_blocks(q, blk, len);
		}
	} else {
		for (k = 0; k < done; k++, q += stride)
			fill32_blocks(q, blk, len);
	}
}

/*
 * A filled rectangle's rows [ya, ye] of pixels [xa, xb] (clipped) in
 * XRGB8888 with a ROP that ignores the destination, charged and written
 * row by row as the queued runs would be (see line_run): no queue, and
 * each row dp_fill32's stores.  False (nothing done) for other formats and
 * ROPs.
 */
static bool rect_rows32(struct rdc_dp *dp, int32_t xa, int32_t xb, int32_t ya,
			int32_t ye)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_hw *hw = dp->hw;
	struct rdc_port_window w;
	struct rdc_port_run one;
	uint32_t n = (uint32_t)(xb - xa + 1), v, rows, done, k;
	uint64_t pixels = 0;
	uint8_t *p, blk[FILL_STORE];
	bool fast, ahead;

	if (s->format != RDC_FMT_XRGB8888 || rdc_rop_reads_dst(dp->st.rop))
		return false;
	if (dp->nruns)
		dp_runs_flush(dp);
	v = rdc_rop_apply(dp->st.rop, dp->st.fg, 0);
	for (k = 0; k < FILL_STORE; k += 4)
		rdc_st32(blk + k, v);
	fast = n * 4 >= FILL_STORE && (v & 0xff) * 0x01010101u != v;
	ahead = (uint64_t)s->stride * s->height > FILL_AHEAD_MIN;
	one.addr = s->base + (uint32_t)ya * s->stride + (uint32_t)xa * 4;
	one.len = n * 4;
	one.count = 1;
	rows = (uint32_t)(ye - ya + 1);
	rdc_port_window_open(hw, &w);
	while (rows) {
		done = rdc_port_window_rows_through(hw, &w, one.addr, one.len,
						    s->stride, rows);
		for (k = 0; ahead && k < done && k < FILL_AHEAD; k++)
			row_prefetch(w.vram + one.addr + k * s->stride,
				     one.len);
		if (fast) {
			/*
			 * dp_fill32's rows, the pattern built once for all
			 * (in registers, not stored and reloaded a row:
			 * rdc-bench fill, scanout off, about 10% less CPU),
			 * and the row's address, stride and length in
			 * registers too: the stores may alias `one` and *s
			 */
			rect_rows_fill(w.vram + one.addr, blk, one.len,
				       s->stride, done, ahead);
			one.addr += done * s->stride;
		} else {
			for (k = 0; k < done; k++, one.addr += s->stride) {
				if (ahead && k + FILL_AHEAD < done)
					row_prefetch(w.vram + one.addr +
							     FILL_AHEAD *
								     s->stride,
						     one.len);
				dp_fill32(w.vram + one.addr, v, n);
			}
		}
		pixels += (uint64_t)done * n;
		rows -= done;
		if (!rows)
			break;
		/* the row a line start falls in, in the window if it can */
		if (rdc_port_window_cross(hw, &w, &one, s->stride,
					  RDC_BUS_WRITE)) {
			rect_row32(w.vram + one.addr, blk, v, n, fast);
			pixels += n;
		} else {
			rdc_port_window_close(hw, &w);
			hw->perf.pixels += pixels;
			pixels = 0;
			p = rdc_port_span(hw, one.addr, one.len, RDC_BUS_WRITE);
			if (p) {
				rect_row32(p, blk, v, n, fast);
				hw->perf.pixels += n;
			}
			rdc_port_window_open(hw, &w);
		}
		one.addr += s->stride;
		rows--;
	}
	rdc_port_window_close(hw, &w);
	hw->perf.pixels += pixels;
	return true;
}

void rdc_dp_rect(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, bool fill)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int32_t xr = x + (int32_t)w - 1, yb = y + (int32_t)h - 1, r;
	uint32_t fg = dp->st.fg;

	if (!w || !h)
		return;
	rdc_dp_queue_begin(dp);
	if (fill && dp->queue_spans) {
		/* dp_fill_span's clipping, once for all rows */
		int32_t xa = RDC_MAX(x, c.x0), xb = RDC_MIN(xr, c.x1 - 1);
		int32_t ya = RDC_MAX(y, c.y0), ye = RDC_MIN(yb, c.y1 - 1);

		if (xa <= xb && ya <= ye && rect_rows32(dp, xa, xb, ya, ye)) {
			rdc_dp_queue_end(dp);
			return;
		}
		for (r = ya; xa <= xb && r <= ye; r++)
			dp_queue_run(dp, xa, r, (uint32_t)(xb - xa + 1), 1);
		rdc_dp_queue_end(dp);
		return;
	}
	if (fill) {
		for (r = RDC_MAX(y, c.y0); r <= RDC_MIN(yb, c.y1 - 1); r++)
			dp_fill_span(dp, x, xr, r);
		rdc_dp_queue_end(dp);
		return;
	}
	/* Each pixel once: full top and bottom rows, sides between them. */
	dp_span_fill(dp, &c, y, x, xr, fg);
	if (h > 1)
		dp_span_fill(dp, &c, yb, x, xr, fg);
	if (h > 2) {
		dp_col_fill(dp, &c, x, y + 1, yb - 1, fg);
		if (w > 1)
			dp_col_fill(dp, &c, xr, y + 1, yb - 1, fg);
	}
	rdc_dp_queue_end(dp);
}

/*
 * Row t of a shape symmetric about (cx, cy) covers |dx| in [amin, amax]:
 * draw it at rows cy - t and cy + t (once for t = 0), mirrored left and
 * right (one span when it crosses the centre).  A fill covers [-amax, amax].
 */
static void quad_row(struct rdc_dp *dp, const struct rdc_rect *c, int32_t cx,
		     int32_t cy, uint32_t t, uint32_t amin, uint32_t amax,
		     bool fill)
{
	int32_t rows[2] = { cy - (int32_t)t, cy + (int32_t)t };
	int32_t lo = (int32_t)amin, hi = (int32_t)amax;
	unsigned int k, nrows = t ? 2 : 1;
	uint32_t fg = dp->st.fg;

	for (k = 0; k < nrows; k++) {
		if (fill && !dp->queue_spans) {
			dp_fill_span(dp, cx - hi, cx + hi, rows[k]);
		} else if (fill || amin == 0) {
			/* (queued, a solid fill is dp_fill_span's span) */
			dp_span_fill(dp, c, rows[k], cx - hi, cx + hi, fg);
		} else {
			dp_span_fill(dp, c, rows[k], cx - hi, cx - lo, fg);
			dp_span_fill(dp, c, rows[k], cx + lo, cx + hi, fg);
		}
	}
}

/*
 * Midpoint circle over the octant 0 <= a <= b from (0, r).  Every row is
 * emitted once: the octant's own rows b (runs of a sharing b) and the
 * mirrored rows a (one pixel at b each), except the diagonal point a == b,
 * which its row b already holds.
 */
void rdc_dp_circle(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t r,
		   bool fill)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int64_t d = 1 - (int64_t)r;
	uint32_t a = 0, b = r, ga = 0;

	if (c.x0 >= c.x1 || c.y0 >= c.y1)
		return;
	if (r == 0) {
		if (fill)
			dp_fill_span(dp, cx, cx, cy);
		else
			dp_span_fill(dp, &c, cy, cx, cx, dp->st.fg);
		return;
	}
	/* Nothing of a circle whose bounding box misses the clip shows. */
	if (cx + (int32_t)r < c.x0 || cx - (int32_t)r >= c.x1 ||
	    cy + (int32_t)r < c.y0 || cy - (int32_t)r >= c.y1)
		return;
	rdc_dp_queue_begin(dp);
	while (a <= b) {
		uint32_t na = a + 1, nb = b;

		if (a < b)
			quad_row(dp, &c, cx, cy, a, b, b, fill);
		if (d < 0) {
			d += 2 * (int64_t)a + 3;
		} else {
			d += 2 * ((int64_t)a - b) + 5;
			nb--;
		}
		if (nb != b || na > nb) {
			quad_row(dp, &c, cx, cy, b, ga, a, fill);
			ga = na;
		}
		a = na;
		b = nb;
	}
	rdc_dp_queue_end(dp);
}

/*
 * The rows of an ellipse's quadrant, as docs/commands.md defines them:
 * pixel (a, b) >= 0 is in the fill when the point half a pixel from it
 * towards the centre, along y or along x, is inside or on the ellipse,
 *   4 ry^2 a^2 + rx^2 (2b - 1)^2 <= 4 rx^2 ry^2   (region 1, flat part)
 *   ry^2 (2a - 1)^2 + 4 rx^2 b^2 <= 4 rx^2 ry^2   (region 2, steep part),
 * so row b of the fill is |a| <= W(b) = max(w1, w2), the widest a each
 * test passes, and row b of the outline is W(b + 1) + 1 .. W(b) (at least
 * W(b)).  Both tests are midpoint decisions scaled by 4, stepped along a
 * as b falls from ry to 0 (each w only grows), so the work is rx + ry
 * steps; |terms| < 2^60 for radii up to RDC_SIZE_MAX.  Whichever region
 * reaches further wins on every row, so no switch point can cut one off.
 */
void dp_ellipse_begin(struct dp_ellipse *e, uint32_t rx, uint32_t ry)
{
	int64_t rx2 = (int64_t)rx * rx, ry2 = (int64_t)ry * ry;
	int64_t r4 = 4 * rx2 * ry2, b = ry;

	e->rx2 = rx2;
	e->ry2 = ry2;
	e->b = b;
	e->w1 = 0; /* a = 0 passes region 1's test on every row b <= ry */
	e->w2 = -1;
	e->prev = -1;
	/* the tests for the next candidates a = w1 + 1 and a = w2 + 1 = 0 */
	e->e1 = 4 * ry2 + rx2 * (2 * b - 1) * (2 * b - 1) - r4;
	e->e2 = ry2 + 4 * rx2 * b * b - r4;
}

bool dp_ellipse_row(struct dp_ellipse *e, uint32_t *t, uint32_t *amin,
		    uint32_t *amax)
{
	int64_t w;

	if (e->b < 0)
		return false;
	while (e->e1 <= 0) {
		e->w1++;
		e->e1 += 4 * e->ry2 * (2 * e->w1 + 1);
	}
	while (e->e2 <= 0) {
		e->w2++;
		/* to a + 1 from a = w2: (2a + 1)^2 - (2a - 1)^2 = 8a */
		e->e2 += 8 * e->ry2 * e->w2;
	}
	w = RDC_MAX(e->w1, e->w2);
	*t = (uint32_t)e->b;
	*amax = (uint32_t)w;
	*amin = (uint32_t)RDC_MIN(e->prev + 1, w);
	e->prev = w;
	/* to row b - 1: (2b - 3)^2 - (2b - 1)^2 = -8 (b - 1), and so on */
	e->e1 -= 8 * e->rx2 * (e->b - 1);
	e->e2 -= 4 * e->rx2 * (2 * e->b - 1);
	e->b--;
	return true;
}

/*
 * ELLIPSE and FILL_ELLIPSE: the rows of dp_ellipse_row, mirrored.  A zero
 * radius degenerates to a line.
 */
void rdc_dp_ellipse(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t rx,
		    uint32_t ry, bool fill)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	struct dp_ellipse e;
	uint32_t t, amin, amax;

	if (c.x0 >= c.x1 || c.y0 >= c.y1)
		return;
	if (ry == 0) {
		if (fill)
			dp_fill_span(dp, cx - (int32_t)rx, cx + (int32_t)rx,
				     cy);
		else
			dp_span_fill(dp, &c, cy, cx - (int32_t)rx,
				     cx + (int32_t)rx, dp->st.fg);
		return;
	}
	if (rx == 0) {
		int32_t y;

		/* a patterned fill needs its pixels row by row */
		if (!fill || dp->st.pat_mode == RDC_PAT_NONE)
			dp_col_fill(dp, &c, cx, cy - (int32_t)ry,
				    cy + (int32_t)ry, dp->st.fg);
		else
			for (y = -(int32_t)ry; y <= (int32_t)ry; y++)
				dp_fill_span(dp, cx, cx, cy + y);
		return;
	}
	if (cx + (int32_t)rx < c.x0 || cx - (int32_t)rx >= c.x1 ||
	    cy + (int32_t)ry < c.y0 || cy - (int32_t)ry >= c.y1)
		return;

	rdc_dp_queue_begin(dp);
	dp_ellipse_begin(&e, rx, ry);
	while (dp_ellipse_row(&e, &t, &amin, &amax))
		quad_row(dp, &c, cx, cy, t, amin, amax, fill);
	rdc_dp_queue_end(dp);
}
