// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* LINE: clipped midpoint lines, drawn as runs (span.c). */
#include "raster.h"

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
 * dp_runs_flush would make for it, in a window of its own.  *pixels is
 * the perf count not yet added, added before any port call that could
 * let someone look at it.
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
		dp_run_write(dp, p, r, dp->st.fg);
	rdc_port_window_open(hw, w);
}

/*
 * rdc_dp_line_steps' loop with its runs queued: the same runs, clipped
 * the same way, as dp_span_fill / dp_col_fill would draw them.
 */
static void line_queue(struct rdc_dp *dp, const struct rdc_rect *c, bool xmajor,
		       int32_t u0, int32_t v0, int32_t sv, int64_t n, int64_t m,
		       int64_t ilo, int64_t ihi, int64_t j, int64_t rem)
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
	 * window refuses takes the port call dp_runs_flush would make.
	 */
	bool direct = bytes == 4 && !rdc_rop_reads_dst(dp->st.rop);
	struct rdc_port_window w = { 0 };
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
			dp_runs_flush(dp);
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
			dp_runs_flush(dp);
			nruns = 0;
		}
	}
	if (direct) {
		rdc_port_window_close(dp->hw, &w);
		dp->hw->perf.pixels += pixels;
		return;
	}
	dp->nruns = nruns;
	dp_runs_flush(dp);
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
			ilo = RDC_MAX(ilo, dp_div_ceil(2 * n * jlo - n, 2 * m));
		/* j(i) <= jhi  <=>  2im < 2n(jhi + 1) - n */
		ihi = RDC_MIN(ihi,
			      dp_div_ceil(2 * n * (jhi + 1) - n, 2 * m) - 1);
	} else if (jlo > 0) {
		return; /* j is always 0 */
	}
	if (ilo > ihi)
		return;

	if (n > 0) {
		j = dp_div_floor(2 * ilo * m + n, 2 * n);
		rem = 2 * ilo * m + n - j * 2 * n;
	} else {
		j = 0;
		rem = 0;
	}
	run = ilo;
	if (dp_runs_ok(dp)) {
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
				dp_span_fill(dp, &c, v, u0 + (int32_t)run,
					     u0 + (int32_t)i, fg);
			else
				dp_col_fill(dp, &c, v, u0 + (int32_t)run,
					    u0 + (int32_t)i, fg);
			run = i + 1;
			j = nj;
		}
	}
}
