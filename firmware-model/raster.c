// SPDX-License-Identifier: GPL-2.0-only
/*
 * The display processor's rasterisers.  Every primitive is decomposed into
 * horizontal spans (one rdc_port_span call each) or vertical runs (one
 * rdc_port_column call each), so the bus model charges whole bursts and
 * the cost of a command follows from the work it does.  The tests hold
 * the plain per-pixel versions these are checked against
 * (tests/unit/ref*.c).
 */
#include "dp_int.h"
#include "../hw-sim/bus.h"

struct rdc_rect rdc_dp_eff_clip(const struct rdc_dp *dp)
{
	struct rdc_rect r = dp->st.clip;

	r.x0 = RDC_MAX(r.x0, 0);
	r.y0 = RDC_MAX(r.y0, 0);
	r.x1 = RDC_MIN(r.x1, (int32_t)dp->st.dst.width);
	r.y1 = RDC_MIN(r.y1, (int32_t)dp->st.dst.height);
	if (r.x1 < r.x0)
		r.x1 = r.x0;
	if (r.y1 < r.y0)
		r.y1 = r.y0;
	return r;
}

static uint32_t fmt_mask(unsigned int bpp)
{
	return bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
}

/* Pixel at bit offset `bit` from p (sub-byte pixels MSB first). */
static inline uint32_t px_ld(const uint8_t *p, unsigned int bpp, uint32_t bit)
{
	switch (bpp) {
	case 32:
		return rdc_ld32(p + bit / 8);
	case 24:
		return rdc_ld24(p + bit / 8);
	case 16:
		return rdc_ld16(p + bit / 8);
	case 8:
		return p[bit / 8];
	default:
		return (p[bit / 8] >> (8 - bpp - (bit & 7))) & fmt_mask(bpp);
	}
}

static inline void px_st(uint8_t *p, unsigned int bpp, uint32_t bit,
			 uint32_t v)
{
	unsigned int sh;
	uint32_t m;

	switch (bpp) {
	case 32:
		rdc_st32(p + bit / 8, v);
		break;
	case 24:
		rdc_st24(p + bit / 8, v);
		break;
	case 16:
		rdc_st16(p + bit / 8, v);
		break;
	case 8:
		p[bit / 8] = (uint8_t)v;
		break;
	default:
		sh = 8 - bpp - (bit & 7);
		m = fmt_mask(bpp) << sh;
		p[bit / 8] = (uint8_t)((p[bit / 8] & ~m) | ((v << sh) & m));
		break;
	}
}

/* Byte k of a little-endian word stream. */
static inline uint32_t word_byte(const uint32_t *w, uint32_t k)
{
	return (w[k / 4] >> (8 * (k % 4))) & 0xff;
}

/* Pixel at bit offset `bit` of a row of host words (same packing as VRAM). */
static uint32_t word_px(const uint32_t *w, unsigned int bpp, uint32_t bit)
{
	uint32_t k = bit / 8, v = 0;
	unsigned int i;

	if (bpp < 8)
		return (word_byte(w, k) >> (8 - bpp - (bit & 7))) &
		       fmt_mask(bpp);
	for (i = 0; i < bpp / 8; i++)
		v |= word_byte(w, k + i) << (8 * i);
	return v;
}

#define FILL_BLOCK 64 /* bytes of pattern copied at a time */

/*
 * n XRGB8888 pixels of v: memset when the bytes agree, else a pattern block the
 * compiler turns into wide stores.
 */
static void fill32(uint8_t *p, uint32_t v, uint32_t n)
{
	size_t len = (size_t)n * 4, i;
	uint8_t pair[8];
	uint64_t v2;

	if ((v & 0xff) * 0x01010101u == v) {
		rdc_memset(p, (int)(v & 0xff), len);
		return;
	}
	if (len < FILL_BLOCK) {
		for (i = 0; i < len; i += 4)
			rdc_st32(p + i, v);
		return;
	}
	/* one block by 8-byte stores, then doubling copies of it */
	rdc_st32(pair, v);
	rdc_st32(pair + 4, v);
	rdc_memcpy(&v2, pair, sizeof(v2));
	for (i = 0; i < FILL_BLOCK; i += sizeof(v2))
		rdc_memcpy(p + i, &v2, sizeof(v2));
	for (; i * 2 <= len; i *= 2)
		rdc_memcpy(p + i, p, i);
	rdc_memcpy(p + i, p, len - i);
}

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
			fill32(p, v, n);
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
		d_px = rdc_rop_reads_dst(rop) ? px_ld(p, bpp, bit) : 0;
		px_st(p, bpp, bit, rdc_rop_apply(rop, s_px, d_px) & mask);
	}
	hw->perf.pixels += cnt;
}

/*
 * Queued solid runs.  Lines and outlines are many runs of a few pixels;
 * rather than a port call each, they are queued in dp->runs and charged
 * together by rdc_port_runs, which takes them for as long as no scanout
 * event falls inside; the run it stops at goes through the port call the
 * per-run path would make.  Each run is charged and written exactly as
 * span_fill / col_fill would, so pixels, cycles and counters are the same.
 * Only for DST formats of whole bytes, pixel-aligned (a pixel never
 * straddles a burst, so a one-pixel column is a one-pixel span).
 */
static bool runs_ok(const struct rdc_dp *dp)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);

	return !dp->ref_paths && (bpp == 8 || bpp == 16 || bpp == 32) &&
	       s->base % (bpp / 8) == 0 && s->stride % (bpp / 8) == 0;
}

/* The pixels of run r at p with colour fg through the ROP. */
static void run_write(struct rdc_dp *dp, uint8_t *p,
		      const struct rdc_port_run *r, uint32_t fg)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format), rop = dp->st.rop;
	uint32_t mask = fmt_mask(bpp), bytes = bpp / 8, k;
	uint32_t n = r->count == 1 ? r->len / bytes : r->count;
	uint32_t step = r->count == 1 ? bytes : s->stride;

	if (!rdc_rop_reads_dst(rop)) {
		uint32_t v = rdc_rop_apply(rop, fg, 0) & mask;

		if (bpp == 32 && r->count == 1) {
			fill32(p, v, n);
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
			px_st(p, bpp, 0,
			      rdc_rop_apply(rop, fg, px_ld(p, bpp, 0)) & mask);
	}
	dp->hw->perf.pixels += n;
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
		fill32(q, v, len / 4);
	}
	return len / 4;
}

/* Runs [first, first + n) charged by rdc_port_runs, their bytes at p. */
static void runs_write(struct rdc_dp *dp, uint8_t *p, uint32_t first,
		       uint32_t n)
{
	const struct rdc_surface *s = &dp->st.dst;
	const struct rdc_port_run *r = dp->runs + first, *end = r + n;
	uint32_t stride = s->stride, v, staged = 0;
	uint64_t pixels = 0;
	uint8_t pair[8];

	if (rdc_format_bpp(s->format) != 32 || rdc_rop_reads_dst(dp->st.rop)) {
		for (; r < end; r++)
			run_write(dp, p + r->addr, r, dp->st.fg);
		return;
	}
	/*
	 * XRGB8888 over a destination the ROP ignores: plain stores, and
	 * rows of a block or more copied from one row of the colour staged
	 * in dp->px (one memcpy a row, the fill's memset speed).
	 */
	v = rdc_rop_apply(dp->st.rop, dp->st.fg, 0);
	rdc_st32(pair, v);
	rdc_st32(pair + 4, v);
	for (; r < end; r++) {
		uint8_t *q = p + r->addr;

		if (r->count == 1 && r->len >= FILL_BLOCK) {
			if (r->len <= sizeof(dp->px)) {
				if (staged < r->len) {
					fill32((uint8_t *)dp->px, v,
					       r->len / 4);
					staged = r->len;
				}
				rdc_memcpy(q, dp->px, r->len);
			} else {
				fill32(q, v, r->len / 4);
			}
			pixels += r->len / 4;
			continue;
		}
		pixels += run_store32(q, r, stride, pair, v);
	}
	dp->hw->perf.pixels += pixels;
}

static void runs_flush(struct rdc_dp *dp)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_hw *hw = dp->hw;
	unsigned int kind = rdc_rop_reads_dst(dp->st.rop) ? RDC_BUS_RMW :
							     RDC_BUS_WRITE;
	uint32_t fg = dp->st.fg, i = 0, done;
	const struct rdc_port_run *r;
	uint8_t *p;

	while (i < dp->nruns) {
		p = rdc_port_runs(hw, dp->runs + i, dp->nruns - i, s->stride,
				  kind, &done);
		runs_write(dp, p, i, done);
		i += done;
		if (i == dp->nruns)
			break;
		r = &dp->runs[i++];
		if (r->count == 1)
			p = rdc_port_span(hw, r->addr, r->len, kind);
		else
			p = rdc_port_column(hw, r->addr, s->stride, r->count,
					    r->len, kind);
		if (p)
			run_write(dp, p, r, fg);
	}
	dp->nruns = 0;
}

void rdc_dp_queue_begin(struct rdc_dp *dp)
{
	dp->queue_spans = runs_ok(dp) && dp->st.pat_mode == RDC_PAT_NONE;
}

void rdc_dp_queue_end(struct rdc_dp *dp)
{
	if (dp->queue_spans)
		runs_flush(dp);
	dp->queue_spans = false;
}

/* Queue count pixels down from x, y (count 1: n pixels across). */
static void queue_run(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t n,
		      uint32_t count)
{
	const struct rdc_surface *s = &dp->st.dst;
	uint32_t bytes = rdc_format_bpp(s->format) / 8;
	struct rdc_port_run *r = &dp->runs[dp->nruns];

	r->addr = s->base + (uint32_t)y * s->stride + (uint32_t)x * bytes;
	r->len = n * bytes;
	r->count = count;
	if (++dp->nruns == RDC_DP_CHUNK)
		runs_flush(dp);
}

void rdc_dp_queue_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb)
{
	queue_run(dp, xa, y, (uint32_t)(xb - xa + 1), 1);
}

/* Solid span [xa, xb] of row y, clipped here. */
static void span_fill(struct rdc_dp *dp, const struct rdc_rect *c, int32_t y,
		      int32_t xa, int32_t xb, uint32_t colour)
{
	if (y < c->y0 || y >= c->y1)
		return;
	xa = RDC_MAX(xa, c->x0);
	xb = RDC_MIN(xb, c->x1 - 1);
	if (xa > xb)
		return;
	if (dp->queue_spans)
		queue_run(dp, xa, y, (uint32_t)(xb - xa + 1), 1);
	else
		span_emit(dp, y, xa, (uint32_t)(xb - xa + 1), colour, NULL,
			  NULL);
}

/* Solid vertical run [ya, yb] of column x, clipped here. */
static void col_fill(struct rdc_dp *dp, const struct rdc_rect *c, int32_t x,
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
		queue_run(dp, x, ya, 1, (uint32_t)(yb - ya + 1));
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
			d = px_ld(q, bpp, bit & 7);

		px_st(q, bpp, bit & 7, rdc_rop_apply(rop, colour, d) & mask);
	}
	hw->perf.pixels += count;
}

void rdc_dp_pixel(struct rdc_dp *dp, int32_t x, int32_t y)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);

	span_fill(dp, &c, y, x, x, dp->st.fg);
}

static int64_t div_ceil(int64_t a, int64_t b)
{
	/* b > 0 */
	return a >= 0 ? (a + b - 1) / b : -((-a) / b);
}

static int64_t div_floor(int64_t a, int64_t b)
{
	return a >= 0 ? a / b : -((-a + b - 1) / b);
}

void rdc_dp_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);

	span_fill(dp, &c, y, xa, xb, dp->st.fg);
}

void rdc_dp_span_px(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		    uint32_t solid, const uint32_t *vals, const uint8_t *on)
{
	span_emit(dp, y, xa, n, solid, vals, on);
}

bool rdc_dp_read_px(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		    uint32_t *out)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);
	uint64_t bit0 = (uint64_t)xa * bpp, bit1 = bit0 + (uint64_t)n * bpp;
	const uint8_t *p;
	uint32_t i;

	if (!n)
		return true;
	p = rdc_port_span(dp->hw,
			  s->base + (uint32_t)y * s->stride + (uint32_t)(bit0 / 8),
			  (uint32_t)((bit1 + 7) / 8 - bit0 / 8), RDC_BUS_READ);
	if (!p)
		return false;
	for (i = 0; i < n; i++)
		out[i] = px_ld(p, bpp, (uint32_t)(bit0 & 7) + i * bpp);
	return true;
}

uint32_t rdc_dp_px_load(const uint8_t *p, unsigned int bpp, uint32_t bit)
{
	return px_ld(p, bpp, bit);
}

void rdc_dp_px_store(uint8_t *p, unsigned int bpp, uint32_t bit, uint32_t v)
{
	px_st(p, bpp, bit, v & fmt_mask(bpp));
}

/*
 * Midpoint line.  The endpoints are first put in a canonical order (the
 * major axis increasing), so line(a, b) and line(b, a) are the same pixels.
 * Step i along the major axis (0..n) lands on minor offset
 *   j(i) = floor((2 * i * m + n) / (2 * n)),   n = |major delta|, m = |minor|
 * which is Bresenham's choice with ties rounded away from the start.
 *
 * Clipping happens before rasterisation, Liang-Barsky style but on the
 * discrete step parameter i instead of a real one: each clip edge bounds i
 * from one side (the major-axis edges directly, the minor-axis edges by
 * inverting j(i) in closed form), the bounds are intersected, and the
 * decision variable (the remainder of that division) is started at the
 * first visible i.  So a clipped line has exactly the unclipped line's
 * pixels inside the clip, and the cost follows the visible part only.
 */
void rdc_dp_line(struct rdc_dp *dp, int32_t x0, int32_t y0, int32_t x1,
		 int32_t y1, bool skip_first, bool skip_last)
{
	int32_t adx = x1 > x0 ? x1 - x0 : x0 - x1;
	int32_t ady = y1 > y0 ? y1 - y0 : y0 - y1;
	int64_t n = RDC_MAX(adx, ady);

	rdc_dp_line_steps(dp, x0, y0, x1, y1, skip_first ? 1 : 0,
			  n - (skip_last ? 1 : 0));
}

/*
 * One run of line_queue's direct path: charged in the open window and
 * written at once, or (refused) charged and written by the port call
 * runs_flush would make for it, in a window of its own.  *pixels is the
 * perf count not yet added, added before any port call that could let
 * someone look at it.
 */
static inline void line_run(struct rdc_dp *dp, struct rdc_port_window *w,
			    const struct rdc_port_run *r, const uint8_t *pair,
			    uint64_t *pixels)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t stride = dp->st.dst.stride;
	uint8_t *p;

	if (r->count == 1 ? rdc_port_window_span(hw, w, r->addr, r->len) :
			    rdc_port_window_column(hw, w, r, stride)) {
		*pixels += run_store32(w->vram + r->addr, r, stride, pair,
				       rdc_ld32(pair));
		return;
	}
	rdc_port_window_close(hw, w);
	hw->perf.pixels += *pixels;
	*pixels = 0;
	if (r->count == 1)
		p = rdc_port_span(hw, r->addr, r->len, RDC_BUS_WRITE);
	else
		p = rdc_port_column(hw, r->addr, stride, r->count, r->len,
				    RDC_BUS_WRITE);
	if (p)
		run_write(dp, p, r, dp->st.fg);
	rdc_port_window_open(hw, w);
}

/*
 * rdc_dp_line_steps' loop with its runs queued: the same runs, clipped
 * the same way, as span_fill / col_fill would draw them.
 */
static void line_queue(struct rdc_dp *dp, const struct rdc_rect *c,
		       bool xmajor, int32_t u0, int32_t v0, int32_t sv,
		       int64_t n, int64_t m, int64_t ilo, int64_t ihi,
		       int64_t j, int64_t rem)
{
	const struct rdc_surface *s = &dp->st.dst;
	uint32_t bytes = rdc_format_bpp(s->format) / 8;
	/* held in registers: stores to dp->runs may alias dp's fields */
	const uint32_t base = s->base, stride = s->stride;
	uint32_t nruns = dp->nruns;
	int64_t i = ilo, run, k, q = 0, rr = 0;
	/*
	 * XRGB8888 over a destination the ROP ignores: each run is charged
	 * and written as it is made (rdc_port_window), not queued; a run the
	 * window refuses takes the port call runs_flush would make.
	 */
	bool direct = bytes == 4 && !rdc_rop_reads_dst(dp->st.rop);
	struct rdc_port_window w = {0};
	struct rdc_port_run one;
	uint64_t pixels = 0;
	uint32_t fg = 0;
	uint8_t pair[8];
	/* u runs along the major axis, v steps across it */
	const int32_t ulo = xmajor ? c->x0 : c->y0;
	const int32_t uhi = xmajor ? c->x1 : c->y1;
	const int32_t vlo = xmajor ? c->y0 : c->x0;
	const int32_t vhi = xmajor ? c->y1 : c->x1;
	const uint32_t umul = xmajor ? bytes : stride;
	const uint32_t vmul = xmajor ? stride : bytes;

	if (direct) {
		if (nruns)
			runs_flush(dp);
		nruns = 0;
		fg = rdc_rop_apply(dp->st.rop, dp->st.fg, 0);
		rdc_st32(pair, fg);
		rdc_st32(pair + 4, fg);
		rdc_port_window_open(dp->hw, &w);
	}

	/*
	 * One run a pass.  The per-step loop adds 2m to rem until it reaches
	 * 2n: k = ceil((2n - rem) / 2m) steps, the last one the run's end.
	 * Once rem < 2m (after the first run) that is q or q + 1 for
	 * q = floor(n / m): q + 1 exactly when rem < 2n - 2mq (run slicing,
	 * no division).  Without a minor move (m == 0) the run goes to ihi.
	 */
	if (m > 0) {
		q = n / m;
		rr = 2 * n - 2 * m * q;
	}
	for (; i <= ihi; i++, j++) {
		int32_t v, a, b;
		struct rdc_port_run *r;

		run = i;
		if (m == 0) {
			i = ihi;
		} else {
			if (rem < 2 * m)
				k = q + (rem < rr);
			else
				k = (2 * n - rem + 2 * m - 1) / (2 * m);
			if (run + k - 1 >= ihi) {
				i = ihi;
			} else {
				i = run + k - 1;
				rem += 2 * m * k - 2 * n;
			}
		}
		v = v0 + sv * (int32_t)j;
		a = u0 + (int32_t)run;
		b = u0 + (int32_t)i;
		r = direct ? &one : &dp->runs[nruns];
		if (v < vlo || v >= vhi)
			continue;
		a = RDC_MAX(a, ulo);
		b = RDC_MIN(b, uhi - 1);
		if (a > b)
			continue;
		/* a span along x, or a column along y */
		r->addr = base + (uint32_t)v * vmul + (uint32_t)a * umul;
		r->len = xmajor ? (uint32_t)(b - a + 1) * bytes : bytes;
		r->count = xmajor ? 1 : (uint32_t)(b - a + 1);
		if (direct) {
			line_run(dp, &w, r, pair, &pixels);
			continue;
		}
		if (++nruns == RDC_DP_CHUNK) {
			dp->nruns = nruns;
			runs_flush(dp);
			nruns = 0;
		}
	}
	if (direct) {
		rdc_port_window_close(dp->hw, &w);
		dp->hw->perf.pixels += pixels;
		return;
	}
	dp->nruns = nruns;
	runs_flush(dp);
}

void rdc_dp_line_steps(struct rdc_dp *dp, int32_t x0, int32_t y0, int32_t x1,
		       int32_t y1, int64_t first, int64_t last)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int32_t adx = x1 > x0 ? x1 - x0 : x0 - x1;
	int32_t ady = y1 > y0 ? y1 - y0 : y0 - y1;
	bool xmajor = adx >= ady && adx > 0;
	int32_t u0, v0, sv, cu0, cu1, cv0, cv1;
	int64_t n, m, ilo, ihi, jlo, jhi, i, j, rem, run;
	uint32_t fg = dp->st.fg;

	if (c.x0 >= c.x1 || c.y0 >= c.y1)
		return;
	if ((xmajor && x1 < x0) || (!xmajor && y1 < y0)) {
		int32_t t;
		int64_t f = first;

		t = x0, x0 = x1, x1 = t;
		t = y0, y0 = y1, y1 = t;
		first = RDC_MAX(adx, ady) - last;
		last = RDC_MAX(adx, ady) - f;
	}
	if (xmajor) {
		u0 = x0, v0 = y0, n = adx, m = ady, sv = y1 < y0 ? -1 : 1;
		cu0 = c.x0, cu1 = c.x1 - 1, cv0 = c.y0, cv1 = c.y1 - 1;
	} else {
		u0 = y0, v0 = x0, n = ady, m = adx, sv = x1 < x0 ? -1 : 1;
		cu0 = c.y0, cu1 = c.y1 - 1, cv0 = c.x0, cv1 = c.x1 - 1;
	}

	ilo = RDC_MAX(RDC_MAX(first, (int64_t)0), (int64_t)cu0 - u0);
	ihi = RDC_MIN(RDC_MIN(last, n), (int64_t)cu1 - u0);
	if (sv > 0) {
		jlo = (int64_t)cv0 - v0;
		jhi = (int64_t)cv1 - v0;
	} else {
		jlo = (int64_t)v0 - cv1;
		jhi = (int64_t)v0 - cv0;
	}
	if (jhi < 0 || jlo > m)
		return;
	if (n > 0 && m > 0) {
		/* j(i) >= jlo  <=>  i >= ceil((2n*jlo - n) / 2m) */
		if (jlo > 0)
			ilo = RDC_MAX(ilo, div_ceil(2 * n * jlo - n, 2 * m));
		/* j(i) <= jhi  <=>  2im < 2n(jhi + 1) - n */
		ihi = RDC_MIN(ihi,
			      div_ceil(2 * n * (jhi + 1) - n, 2 * m) - 1);
	} else if (jlo > 0) {
		return; /* j is always 0 */
	}
	if (ilo > ihi)
		return;

	if (n > 0) {
		j = div_floor(2 * ilo * m + n, 2 * n);
		rem = 2 * ilo * m + n - j * 2 * n;
	} else {
		j = 0;
		rem = 0;
	}
	run = ilo;
	if (runs_ok(dp)) {
		line_queue(dp, &c, xmajor, u0, v0, sv, n, m, ilo, ihi, j, rem);
		return;
	}
	for (i = ilo; i <= ihi; i++) {
		int64_t nj = j;

		if (i < ihi) {
			rem += 2 * m;
			if (rem >= 2 * n) {
				rem -= 2 * n;
				nj++;
			}
		}
		if (nj != j || i == ihi) {
			int32_t v = v0 + sv * (int32_t)j;

			if (xmajor)
				span_fill(dp, &c, v, u0 + (int32_t)run,
					  u0 + (int32_t)i, fg);
			else
				col_fill(dp, &c, v, u0 + (int32_t)run,
					 u0 + (int32_t)i, fg);
			run = i + 1;
			j = nj;
		}
	}
}

/*
 * memcpy with a length the compiler knows nothing about: where it knows
 * the length is at most a staging buffer it expands the copy inline
 * (rep movsq on x86), which is slower than the library's for rows of a
 * few hundred bytes.
 */
static inline void row_copy(uint8_t *d, const uint8_t *s, size_t n)
{
	rdc_hide_var(n);
	rdc_memcpy(d, s, n);
}

/*
 * A filled rectangle's rows [ya, ye] of pixels [xa, xb] (clipped) in
 * XRGB8888 with a ROP that ignores the destination, charged and written
 * row by row as the queued runs would be (see line_run): no queue, and
 * each row one memcpy of the colour staged in dp->px.  False (nothing
 * done) for other formats and ROPs.
 */
static bool rect_rows32(struct rdc_dp *dp, int32_t xa, int32_t xb,
			int32_t ya, int32_t ye)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_hw *hw = dp->hw;
	struct rdc_port_window w;
	struct rdc_port_run one;
	uint32_t n = (uint32_t)(xb - xa + 1), v, rows, done, k;
	uint64_t pixels = 0;
	uint8_t *p;

	if (s->format != RDC_FMT_XRGB8888 || rdc_rop_reads_dst(dp->st.rop))
		return false;
	if (dp->nruns)
		runs_flush(dp);
	v = rdc_rop_apply(dp->st.rop, dp->st.fg, 0);
	if (n <= RDC_DP_CHUNK)
		fill32((uint8_t *)dp->px, v, n);
	one.addr = s->base + (uint32_t)ya * s->stride + (uint32_t)xa * 4;
	one.len = n * 4;
	one.count = 1;
	rows = (uint32_t)(ye - ya + 1);
	rdc_port_window_open(hw, &w);
	while (rows) {
		done = rdc_port_window_rows(hw, &w, one.addr, one.len,
					    s->stride, rows);
		for (k = 0; k < done; k++, one.addr += s->stride) {
			p = w.vram + one.addr;
			if (n <= RDC_DP_CHUNK)
				row_copy(p, (const uint8_t *)dp->px, one.len);
			else
				fill32(p, v, n);
		}
		pixels += (uint64_t)done * n;
		rows -= done;
		if (!rows)
			break;
		rdc_port_window_close(hw, &w);
		hw->perf.pixels += pixels;
		pixels = 0;
		p = rdc_port_span(hw, one.addr, one.len, RDC_BUS_WRITE);
		if (p)
			run_write(dp, p, &one, dp->st.fg);
		rdc_port_window_open(hw, &w);
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
			queue_run(dp, xa, r, (uint32_t)(xb - xa + 1), 1);
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
	span_fill(dp, &c, y, x, xr, fg);
	if (h > 1)
		span_fill(dp, &c, yb, x, xr, fg);
	if (h > 2) {
		col_fill(dp, &c, x, y + 1, yb - 1, fg);
		if (w > 1)
			col_fill(dp, &c, xr, y + 1, yb - 1, fg);
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
			span_fill(dp, c, rows[k], cx - hi, cx + hi, fg);
		} else {
			span_fill(dp, c, rows[k], cx - hi, cx - lo, fg);
			span_fill(dp, c, rows[k], cx + lo, cx + hi, fg);
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
			span_fill(dp, &c, cy, cx, cx, dp->st.fg);
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
			dp_fill_span(dp, cx - (int32_t)rx, cx + (int32_t)rx, cy);
		else
			span_fill(dp, &c, cy, cx - (int32_t)rx,
				  cx + (int32_t)rx, dp->st.fg);
		return;
	}
	if (rx == 0) {
		int32_t y;

		/* a patterned fill needs its pixels row by row */
		if (!fill || dp->st.pat_mode == RDC_PAT_NONE)
			col_fill(dp, &c, cx, cy - (int32_t)ry,
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

/*
 * Clip a source rectangle against [0, sw) x [0, sh) and its destination
 * against the clip, shrinking both together.  False if nothing remains.
 */
static bool clip_pair(const struct rdc_rect *c, int64_t sw, int64_t sh,
		      int64_t *sx, int64_t *sy, int64_t *dx, int64_t *dy,
		      int64_t *w, int64_t *h)
{
	int64_t d;

	if (*sx < 0)
		*dx -= *sx, *w += *sx, *sx = 0;
	if (*sy < 0)
		*dy -= *sy, *h += *sy, *sy = 0;
	*w = RDC_MIN(*w, sw - *sx);
	*h = RDC_MIN(*h, sh - *sy);
	if (*dx < c->x0)
		d = c->x0 - *dx, *sx += d, *dx += d, *w -= d;
	if (*dy < c->y0)
		d = c->y0 - *dy, *sy += d, *dy += d, *h -= d;
	*w = RDC_MIN(*w, c->x1 - *dx);
	*h = RDC_MIN(*h, c->y1 - *dy);
	return *w > 0 && *h > 0;
}

/*
 * Screen-to-screen copy.  Pieces of at most RDC_DP_CHUNK pixels are read
 * whole before they are written, and visited in descending address order
 * when the destination lies above the source (ascending otherwise), as
 * memmove does, so any overlap of the two rectangles copies correctly.
 */
/*
 * Write the staged pixels dp->px[0, n) of a BLIT or HOST_BLIT to DST row y
 * from xa (inside the clip), in this order: the colour key drops source
 * pixels equal to it (compared in the source format, masked to its pixel
 * size), the ROP combines the others with the destination, and a global
 * alpha below opaque blends that result over the destination
 * (rdc_dp_blend; one read-modify-write span).  Indexed formats have no
 * blend: blit_drawn() lets them draw only at alpha >= RDC_ALPHA_THRESHOLD.
 */
static void blit_span(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n)
{
	const struct rdc_dp_state *st = &dp->st;
	unsigned int fmt = st->dst.format, bpp = rdc_format_bpp(fmt);
	uint32_t mask = fmt_mask(bpp), key = st->colorkey & mask, i, cnt = 0;
	bool blend = st->alpha != RDC_ALPHA_OPAQUE && !rdc_format_indexed(fmt);
	uint64_t bit0 = (uint64_t)xa * bpp, bit1 = bit0 + (uint64_t)n * bpp;
	uint8_t *p;

	if (st->colorkey_on)
		for (i = 0; i < n; i++)
			dp->on[i] = dp->px[i] != key;
	if (!blend) {
		span_emit(dp, y, xa, n, 0, dp->px,
			  st->colorkey_on ? dp->on : NULL);
		return;
	}
	p = rdc_port_span(dp->hw,
			  st->dst.base + (uint32_t)y * st->dst.stride +
				  (uint32_t)(bit0 / 8),
			  (uint32_t)((bit1 + 7) / 8 - bit0 / 8), RDC_BUS_RMW);
	if (!p)
		return;
	for (i = 0; i < n; i++) {
		uint32_t bit = (uint32_t)(bit0 & 7) + i * bpp, d;

		if (st->colorkey_on && !dp->on[i])
			continue;
		d = px_ld(p, bpp, bit);
		px_st(p, bpp, bit,
		      rdc_dp_blend(fmt, rdc_rop_apply(st->rop, dp->px[i], d) &
						mask,
				   d, st->alpha) & mask);
		cnt++;
	}
	dp->hw->perf.pixels += cnt;
}

/*
 * d[i] = rop(s[i], d[i]) for len bytes.  The ROPs are bitwise, so for
 * pixels of whole bytes this is the per-pixel ROP; the switch is outside
 * the loop so each case is a plain loop the compiler can widen.
 */
#define ROP_BLOCK 32u
static rdc_always_inline void rop_bytes_as(unsigned int r,
					   uint8_t *restrict d,
					   const uint8_t *restrict s,
					   uint32_t len)
{
	uint32_t i;

	for (; len >= ROP_BLOCK; len -= ROP_BLOCK) {
		for (i = 0; i < ROP_BLOCK; i++)
			d[i] = (uint8_t)rdc_rop_apply(r, s[i], d[i]);
		d += ROP_BLOCK;
		s += ROP_BLOCK;
	}
	for (i = 0; i < len; i++)
		d[i] = (uint8_t)rdc_rop_apply(r, s[i], d[i]);
}

/*
 * d and s do not overlap; blocks of a fixed size with restrict let the
 * compiler use wide registers (kept out of line, where restrict holds).
 */
static rdc_noinline void
rop_bytes(uint8_t *restrict d, const uint8_t *restrict s, uint32_t len,
	  unsigned int rop)
{
	switch (rop) {
	case RDC_ROP_COPY:
		rdc_memcpy(d, s, len);
		break;
	case RDC_ROP_CLEAR:
		rop_bytes_as(RDC_ROP_CLEAR, d, s, len);
		break;
	case RDC_ROP_AND:
		rop_bytes_as(RDC_ROP_AND, d, s, len);
		break;
	case RDC_ROP_AND_REVERSE:
		rop_bytes_as(RDC_ROP_AND_REVERSE, d, s, len);
		break;
	case RDC_ROP_AND_INVERTED:
		rop_bytes_as(RDC_ROP_AND_INVERTED, d, s, len);
		break;
	case RDC_ROP_NOOP:
		rop_bytes_as(RDC_ROP_NOOP, d, s, len);
		break;
	case RDC_ROP_XOR:
		rop_bytes_as(RDC_ROP_XOR, d, s, len);
		break;
	case RDC_ROP_OR:
		rop_bytes_as(RDC_ROP_OR, d, s, len);
		break;
	case RDC_ROP_NOR:
		rop_bytes_as(RDC_ROP_NOR, d, s, len);
		break;
	case RDC_ROP_EQUIV:
		rop_bytes_as(RDC_ROP_EQUIV, d, s, len);
		break;
	case RDC_ROP_INVERT:
		rop_bytes_as(RDC_ROP_INVERT, d, s, len);
		break;
	case RDC_ROP_OR_REVERSE:
		rop_bytes_as(RDC_ROP_OR_REVERSE, d, s, len);
		break;
	case RDC_ROP_COPY_INVERTED:
		rop_bytes_as(RDC_ROP_COPY_INVERTED, d, s, len);
		break;
	case RDC_ROP_OR_INVERTED:
		rop_bytes_as(RDC_ROP_OR_INVERTED, d, s, len);
		break;
	case RDC_ROP_NAND:
		rop_bytes_as(RDC_ROP_NAND, d, s, len);
		break;
	default:
		rop_bytes_as(RDC_ROP_SET, d, s, len);
		break;
	}
}

/*
 * BLIT's fast path, for SRC and DST of the same whole-byte format with no
 * colour key and no blend: n pixels read from saddr go to DST row y from
 * xa through the ROP byte by byte, charged as the read span and the write
 * span, then moved straight from SRC to DST when the two do not
 * overlap (memmove for COPY even when they do); an overlapping ROP stages
 * the source first, as the per-pixel path does.
 */
/* len bytes from src to p through the ROP, overlap-safe. */
static inline void blit_bytes(struct rdc_dp *dp, uint8_t *p,
			      const uint8_t *src, uint32_t len)
{
	unsigned int rop = dp->st.rop;

	if (rop == RDC_ROP_COPY) {
		rdc_memmove(p, src, len);
	} else if (src + len <= p || p + len <= src) {
		rop_bytes(p, src, len, rop);
	} else {
		rdc_memcpy(dp->px, src, len);
		rop_bytes(p, (const uint8_t *)dp->px, len, rop);
	}
}

static void blit_row(struct rdc_dp *dp, uint32_t saddr, int32_t y, int32_t xa,
		     uint32_t n)
{
	const struct rdc_surface *s = &dp->st.dst;
	uint32_t bytes = rdc_format_bpp(s->format) / 8, len = n * bytes;
	unsigned int rop = dp->st.rop;
	const uint8_t *src;
	uint8_t *p;

	p = rdc_port_span_pair(dp->hw, saddr,
			       s->base + (uint32_t)y * s->stride +
				       (uint32_t)xa * bytes,
			       len,
			       rdc_rop_reads_dst(rop) ? RDC_BUS_RMW :
							RDC_BUS_WRITE,
			       &src);
	if (!p)
		return;
	blit_bytes(dp, p, src, len);
	dp->hw->perf.pixels += n;
}

/* Does the global alpha let a BLIT or HOST_BLIT draw at all? */
static bool blit_drawn(const struct rdc_dp *dp)
{
	return !rdc_format_indexed(dp->st.dst.format) ||
	       dp->st.alpha >= RDC_ALPHA_THRESHOLD;
}

void rdc_dp_blit(struct rdc_dp *dp, int32_t sx32, int32_t sy32, int32_t dx32,
		 int32_t dy32, uint32_t w32, uint32_t h32)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	const struct rdc_surface *ss = &dp->st.src, *ds = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(ss->format);
	int64_t sx = sx32, sy = sy32, dx = dx32, dy = dy32, w = w32, h = h32;
	struct rdc_hw *hw = dp->hw;
	struct rdc_port_window win;
	unsigned int kind;
	uint64_t sbit, dbit;
	bool back, fast;
	int64_t k;

	if (!blit_drawn(dp) ||
	    !clip_pair(&c, ss->width, ss->height, &sx, &sy, &dx, &dy, &w, &h))
		return;
	sbit = (uint64_t)ss->base * 8 + (uint64_t)sy * ss->stride * 8 +
	       (uint64_t)sx * bpp;
	dbit = (uint64_t)ds->base * 8 + (uint64_t)dy * ds->stride * 8 +
	       (uint64_t)dx * bpp;
	back = dbit > sbit;
	fast = !dp->ref_paths && ss->format == ds->format && bpp >= 8 &&
	       !dp->st.colorkey_on &&
	       (dp->st.alpha == RDC_ALPHA_OPAQUE ||
		rdc_format_indexed(ds->format));

	/*
	 * The fast rows are charged as read/write pairs in a port window
	 * and their bytes moved at once; a pair the window refuses goes to
	 * blit_row's rdc_port_span_pair, as every row otherwise would.
	 */
	kind = rdc_rop_reads_dst(dp->st.rop) ? RDC_BUS_RMW : RDC_BUS_WRITE;
	if (fast)
		rdc_port_window_open(hw, &win);
	for (k = 0; k < h; k++) {
		int64_t row = back ? h - 1 - k : k;
		int64_t done;

		for (done = 0; done < w; done += RDC_DP_CHUNK) {
			uint32_t n = (uint32_t)RDC_MIN(w - done,
						       (int64_t)RDC_DP_CHUNK);
			int64_t off = back ? w - done - n : done;
			uint64_t b0 = (uint64_t)(sx + off) * bpp;
			uint64_t b1 = b0 + (uint64_t)n * bpp;
			uint32_t addr = ss->base +
					(uint32_t)(sy + row) * ss->stride +
					(uint32_t)(b0 / 8);
			const uint8_t *p;
			uint32_t i;

			if (fast) {
				uint32_t len = n * (bpp / 8);
				uint32_t daddr =
					ds->base +
					(uint32_t)(dy + row) * ds->stride +
					(uint32_t)(dx + off) * (bpp / 8);

				if (rdc_port_window_pair(hw, &win, addr, daddr,
							 len, kind)) {
					blit_bytes(dp, win.vram + daddr,
						   win.vram + addr, len);
					hw->perf.pixels += n;
					continue;
				}
				rdc_port_window_close(hw, &win);
				blit_row(dp, addr, (int32_t)(dy + row),
					 (int32_t)(dx + off), n);
				rdc_port_window_open(hw, &win);
				continue;
			}
			p = rdc_port_span(dp->hw, addr,
					  (uint32_t)((b1 + 7) / 8 - b0 / 8),
					  RDC_BUS_READ);
			if (!p)
				continue;
			for (i = 0; i < n; i++)
				dp->px[i] = px_ld(p, bpp,
						  (uint32_t)(b0 & 7) + i * bpp);
			blit_span(dp, (int32_t)(dy + row), (int32_t)(dx + off),
				  n);
		}
	}
	if (fast)
		rdc_port_window_close(hw, &win);
}

/*
 * Rows of pixels produced from command data: get(x) gives pixel x of row r
 * (relative to the rectangle) and whether it is drawn.  Shared by
 * HOST_BLIT, MONO and TEXT.
 */
struct row_src {
	unsigned int kind;
	const uint32_t *data;
	uint32_t wpr; /* words a data row */
	unsigned int bpp;
	uint32_t fg, bg;
	bool transparent;
};

enum { SRC_HOST, SRC_MONO, SRC_TEXT };

/* Byte k (8 pixels, bit 7 leftmost) of row r of a MONO or TEXT source. */
static inline uint32_t bits_byte(const struct row_src *rs, uint32_t r,
				 uint32_t k)
{
	if (rs->kind == SRC_MONO)
		return word_byte(rs->data + (size_t)r * rs->wpr, k);
	return rdc_font8x16[word_byte(rs->data, k) * 16 + r];
}

/*
 * Stage pixels [bx, bx + n) of row r of a MONO or TEXT source as FG/BG
 * in dp->px (set bits in dp->on): a byte of bits is fetched once for its
 * eight pixels.
 */
static void bits_expand(struct rdc_dp *dp, const struct row_src *rs,
			uint32_t r, uint32_t bx, uint32_t n)
{
	uint32_t i = 0, fg = rs->fg, bg = rs->bg;

	while (i < n) {
		uint32_t byte = bits_byte(rs, r, (bx + i) / 8);
		unsigned int b = (bx + i) % 8;

		for (; b < 8 && i < n; b++, i++) {
			uint32_t set = (byte >> (7 - b)) & 1;

			dp->px[i] = set ? fg : bg;
			dp->on[i] = (uint8_t)set;
		}
	}
}

/*
 * Pixels [bx, bx + n) of row r of a MONO or TEXT source as XRGB8888 at q,
 * FG and BG both written: with `table`, whole bytes of bits as two
 * 4-pixel groups from dp->nibble_px (nibble_fill); otherwise, and at the
 * ragged ends, pixel by pixel.
 */
#define BIT_PX(q, k)                                                           \
	rdc_st32((q) + 4 * (k), bg ^ (diff & -((byte >> (7 - (k))) & 1)))

static inline void bits_write32(struct rdc_dp *dp, uint8_t *q,
				const struct row_src *rs, uint32_t r,
				uint32_t bx, uint32_t n, bool table)
{
	uint32_t i = 0, bg = rs->bg, diff = rs->fg ^ rs->bg;
	unsigned int b;

	if (table && bx % 8 == 0) /* whole bytes from the first pixel */
		for (; n - i >= 8; i += 8, q += 32) {
			uint32_t byte = bits_byte(rs, r, (bx + i) / 8);

			rdc_memcpy(q, dp->nibble_px[byte >> 4], 16);
			rdc_memcpy(q + 16, dp->nibble_px[byte & 15], 16);
		}
	while (i < n) {
		uint32_t byte = bits_byte(rs, r, (bx + i) / 8);

		b = (bx + i) % 8;
		/* a set bit turns BG into FG: bg ^ (diff & -bit) */
		if (b == 0 && n - i >= 8) {
			if (table) {
				rdc_memcpy(q, dp->nibble_px[byte >> 4], 16);
				rdc_memcpy(q + 16, dp->nibble_px[byte & 15],
					   16);
				q += 32;
			} else {
				/* written out: constant shifts, no loop */
				BIT_PX(q, 0);
				BIT_PX(q, 1);
				BIT_PX(q, 2);
				BIT_PX(q, 3);
				BIT_PX(q, 4);
				BIT_PX(q, 5);
				BIT_PX(q, 6);
				BIT_PX(q, 7);
				q += 32;
			}
			i += 8;
			continue;
		}
		for (; b < 8 && i < n; b++, i++, q += 4)
			rdc_st32(q, bg ^ (diff & -((byte >> (7 - b)) & 1)));
	}
}

/*
 * bits_write32 for `rows` rows of exactly one whole byte of a MONO
 * source (bx a multiple of 8, n 8, with the table), the console's 8-pixel
 * glyph rows: the row loop without a call or the ragged-end tests per row.
 */
static inline void mono8_rows32(const struct rdc_dp *dp, uint8_t *q,
				uint32_t stride, const struct row_src *rs,
				uint32_t r, uint32_t bx, uint32_t rows)
{
	const uint32_t *d = rs->data + (size_t)r * rs->wpr;
	uint32_t k;

	for (k = 0; k < rows; k++, q += stride, d += rs->wpr) {
		uint32_t byte = word_byte(d, bx / 8);

		rdc_memcpy(q, dp->nibble_px[byte >> 4], 16);
		rdc_memcpy(q + 16, dp->nibble_px[byte & 15], 16);
	}
}

/*
 * dp->nibble_px for FG and BG (group v's pixel k is FG if bit 3 - k is
 * set), unless it holds them already.  False where the `n` pixels to draw
 * with it (all rows: an 8x16 glyph is 128) are too few to repay building
 * it (a byte of bits is two lookups instead of eight selects; the table
 * is 64 stores).
 */
#define NIBBLE_MIN_PX 32u

static bool nibble_fill(struct rdc_dp *dp, uint32_t fg, uint32_t bg,
			uint64_t n)
{
	uint8_t pair[4][8]; /* pair[u]: pixel k is FG if bit 1 - k of u */
	unsigned int v;

	if (dp->nibble_ok && dp->nibble_fg == fg && dp->nibble_bg == bg)
		return true;
	if (n < NIBBLE_MIN_PX)
		return false;
	/* from the four 2-pixel pairs: 8 stores and 32 copies, not 64 */
	for (v = 0; v < 4; v++) {
		rdc_st32(pair[v], v & 2 ? fg : bg);
		rdc_st32(pair[v] + 4, v & 1 ? fg : bg);
	}
	for (v = 0; v < 16; v++) {
		rdc_memcpy(dp->nibble_px[v], pair[v >> 2], 8);
		rdc_memcpy(dp->nibble_px[v] + 8, pair[v & 3], 8);
	}
	dp->nibble_fg = fg;
	dp->nibble_bg = bg;
	dp->nibble_ok = true;
	return true;
}

/*
 * Opaque MONO and TEXT rows in XRGB8888 with ROP COPY, the console's
 * case: the rows [ya, yb) of pixels [xa, xb) are charged as one span
 * each in a port window (rdc_port_window_rows) and expanded straight into
 * VRAM; a row the scanout interrupts is charged on its own by
 * rdc_port_span, as span_emit would.  Same spans, same order, same bytes.
 */
static void rows_text32(struct rdc_dp *dp, int32_t x, int32_t y, int64_t xa,
			int64_t xb, int64_t ya, int64_t yb,
			const struct row_src *rs)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_hw *hw = dp->hw;
	uint32_t n = (uint32_t)(xb - xa), bx = (uint32_t)(xa - x);
	uint32_t addr, rows, done, r, k;
	struct rdc_port_window w;
	uint64_t pixels = 0;
	bool table, mono8;
	uint8_t *p;

	if (ya >= yb)
		return;
	table = nibble_fill(dp, rs->fg, rs->bg,
			    (uint64_t)n * (uint64_t)(yb - ya));
	mono8 = table && rs->kind == SRC_MONO && n == 8 && bx % 8 == 0;
	addr = s->base + (uint32_t)ya * s->stride + (uint32_t)xa * 4;
	rows = (uint32_t)(yb - ya);
	r = (uint32_t)(ya - y);
	rdc_port_window_open(hw, &w);
	while (rows) {
		done = rdc_port_window_rows(hw, &w, addr, n * 4, s->stride,
					    rows);
		if (mono8) {
			mono8_rows32(dp, w.vram + addr, s->stride, rs, r, bx,
				     done);
			r += done;
			addr += done * s->stride;
		} else {
			for (k = 0; k < done; k++, r++, addr += s->stride)
				bits_write32(dp, w.vram + addr, rs, r, bx, n,
					     table);
		}
		pixels += (uint64_t)done * n;
		rows -= done;
		if (!rows)
			break;
		/* the span span_emit would charge, then the same bytes */
		rdc_port_window_close(hw, &w);
		hw->perf.pixels += pixels;
		pixels = 0;
		p = rdc_port_span(hw, addr, n * 4, RDC_BUS_WRITE);
		if (p) {
			bits_write32(dp, p, rs, r, bx, n, table);
			hw->perf.pixels += n;
		}
		rdc_port_window_open(hw, &w);
		r++;
		addr += s->stride;
		rows--;
	}
	rdc_port_window_close(hw, &w);
	hw->perf.pixels += pixels;
}

static void rows_draw(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		      uint32_t h, const struct row_src *rs)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int64_t xa = RDC_MAX((int64_t)x, (int64_t)c.x0);
	int64_t xb = RDC_MIN((int64_t)x + w, (int64_t)c.x1); /* exclusive */
	int64_t ya = RDC_MAX((int64_t)y, (int64_t)c.y0);
	int64_t yb = RDC_MIN((int64_t)y + h, (int64_t)c.y1);
	int64_t row, col;

	if (rs->kind != SRC_HOST && !rs->transparent && !dp->ref_paths &&
	    dp->st.rop == RDC_ROP_COPY && dp->st.dst.format == RDC_FMT_XRGB8888 &&
	    xa < xb && xb - xa <= (int64_t)RDC_DP_CHUNK) {
		rows_text32(dp, x, y, xa, xb, ya, yb, rs);
		return;
	}

	for (row = ya; row < yb; row++) {
		uint32_t r = (uint32_t)(row - y);

		for (col = xa; col < xb; col += RDC_DP_CHUNK) {
			uint32_t n = (uint32_t)RDC_MIN(xb - col,
						       (int64_t)RDC_DP_CHUNK);
			uint32_t i;

			if (rs->kind != SRC_HOST && !dp->ref_paths) {
				bits_expand(dp, rs, r, (uint32_t)(col - x), n);
				span_emit(dp, (int32_t)row, (int32_t)col, n, 0,
					  dp->px, rs->transparent ? dp->on : NULL);
				continue;
			}
			for (i = 0; i < n; i++) {
				uint32_t bx = (uint32_t)(col - x) + i;
				uint32_t bit;
				bool set;

				switch (rs->kind) {
				case SRC_HOST:
					dp->px[i] = word_px(rs->data +
							    (size_t)r * rs->wpr,
							    rs->bpp,
							    bx * rs->bpp);
					dp->on[i] = 1;
					continue;
				case SRC_MONO:
					bit = word_byte(rs->data +
							(size_t)r * rs->wpr,
							bx / 8);
					break;
				default: /* SRC_TEXT: r is the glyph row */
					bit = rdc_font8x16[word_byte(rs->data,
								     bx / 8) *
								   16 + r];
					break;
				}
				set = (bit >> (7 - bx % 8)) & 1;
				dp->px[i] = set ? rs->fg : rs->bg;
				dp->on[i] = set;
			}
			if (rs->kind == SRC_HOST)
				blit_span(dp, (int32_t)row, (int32_t)col, n);
			else
				span_emit(dp, (int32_t)row, (int32_t)col, n, 0,
					  dp->px, rs->transparent ? dp->on : NULL);
		}
	}
}

void rdc_dp_host_blit(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		      uint32_t h, const uint32_t *data)
{
	unsigned int fmt = dp->st.dst.format;
	struct row_src rs = {
		.kind = SRC_HOST, .data = data,
		.wpr = rdc_dp_words_per_row(fmt, w),
		.bpp = rdc_format_bpp(fmt),
	};

	if (blit_drawn(dp))
		rows_draw(dp, x, y, w, h, &rs);
}

void rdc_dp_mono(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, const uint32_t *data, bool transparent)
{
	struct row_src rs = {
		.kind = SRC_MONO, .data = data,
		.wpr = rdc_dp_words_per_row(RDC_FMT_I1, w),
		.fg = dp->st.fg, .bg = dp->st.bg, .transparent = transparent,
	};

	rows_draw(dp, x, y, w, h, &rs);
}

#define RDC_GLYPH_W 8
#define RDC_GLYPH_H 16

/* One span per glyph row across the whole string. */
void rdc_dp_text(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t count,
		 const uint32_t *chars, bool transparent)
{
	struct row_src rs = {
		.kind = SRC_TEXT, .data = chars,
		.fg = dp->st.fg, .bg = dp->st.bg, .transparent = transparent,
	};

	rows_draw(dp, x, y, count * RDC_GLYPH_W, RDC_GLYPH_H, &rs);
}

void rdc_dp_readback_pack(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
			  uint32_t row, uint32_t word, uint32_t n,
			  uint32_t *out)
{
	const struct rdc_surface *s = &dp->st.src;
	unsigned int bpp = rdc_format_bpp(s->format);
	uint64_t byte0 = (uint64_t)word * 4, byte1 = byte0 + (uint64_t)n * 4;
	int64_t k0 = (int64_t)(byte0 * 8 / bpp);
	int64_t k1 = RDC_MIN((int64_t)((byte1 * 8 + bpp - 1) / bpp),
			     (int64_t)w);
	int64_t sy = (int64_t)y + row, va, vb, k;
	const uint8_t *p = NULL;
	uint64_t pbit0 = 0;

	rdc_memset(out, 0, (size_t)n * 4);
	if (sy < 0 || sy >= s->height)
		return;
	/* the part of pixels [k0, k1) that lies on the surface */
	va = RDC_MAX(k0, -(int64_t)x);
	vb = RDC_MIN(k1, (int64_t)s->width - x);
	if (va >= vb)
		return;
	pbit0 = (uint64_t)(x + va) * bpp;
	p = rdc_port_span(dp->hw,
			  s->base + (uint32_t)sy * s->stride +
				  (uint32_t)(pbit0 / 8),
			  (uint32_t)(((uint64_t)(x + vb) * bpp + 7) / 8 -
				     pbit0 / 8),
			  RDC_BUS_READ);
	if (!p)
		return;
	for (k = va; k < vb; k++) {
		uint32_t v = px_ld(p, bpp,
				   (uint32_t)((pbit0 & 7) + (k - va) * bpp));
		uint64_t kb = (uint64_t)k * bpp;
		unsigned int i;

		if (bpp < 8) {
			uint64_t byte = kb / 8 - byte0;

			out[byte / 4] |= (v << (8 - bpp - (kb & 7)))
					 << (8 * (byte % 4));
			continue;
		}
		for (i = 0; i < bpp / 8; i++) {
			uint64_t byte = kb / 8 + i;

			if (byte < byte0 || byte >= byte1)
				continue;
			byte -= byte0;
			out[byte / 4] |= ((v >> (8 * i)) & 0xff)
					 << (8 * (byte % 4));
		}
	}
}
