// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* LINE: clipped midpoint lines, drawn as runs (span.c). */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
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

static inline void line_run(struct rdc_dp *dp, struct rdc_port_window *w,
			    const struct rdc_port_run *r, const uint8_t *pair,
			    uint64_t *pixels)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t stride = dp->st.dst.stride;

	if (r->count == 1 ? rdc_port_window_span(hw, w, r->addr, r->len) :
			    rdc_port_window_column(hw, w, r, stride)) {
		*pixels += run_store32(w->vram + r->addr, r, stride, pair,
				       rdc_ld32(pair));
		return;
	}
	dp_run_refused(dp, w, r, RDC_BUS_WRITE, pixels);
}

/*
 * A middle run of k steps at a that line_fast's window refuses (a
 * scanout event falls in it): dp_run_refused, as
 * rdc_dp_line_steps' loop would take it, t and row the window's as the
 * runs before left them.  True when line_fast may go on in the window
 * reopened after it: open, not past its limit, and the open row the one
 * the run ended in (no fetch in between), so that the next run starts
 * with a row miss as line_fast's loops take it.
 */
static rdc_noinline bool line_cut(struct rdc_dp *dp, struct rdc_port_window *w,
				  uint32_t a, uint32_t k, bool xmajor,
				  uint64_t *pixels)
{
	uint32_t stride = dp->st.dst.stride;
	struct rdc_port_run r = {
		.addr = a,
		.len = xmajor ? 4 * k : 4,
		.count = xmajor ? 1 : k,
	};
	uint32_t last = xmajor ? a + 4 * k - 1 : a + (k - 1) * stride;

	dp_run_refused(dp, w, &r, RDC_BUS_WRITE, pixels);
	return w->open && w->t <= w->lim && w->row == last / RDC_DRAM_ROW_BYTES;
}

#define LINE_AHEAD 4 /* rows: see line_q32 */

/*
 * q pixels of colour v2 (a pixel twice, VRAM byte order) from p: a span,
 * or (column) one pixel every `stride` bytes.  A line's middle runs are
 * all q or q + 1 long, so these branches mostly go the same way for all
 * of them; all pixels are the same, so 8-byte stores may overlap.  (Runs
 * of q pixels plus a (q + 1)th stored to VRAM or to a scratch word
 * through a selected address, with no branch on the run's length, were
 * slower: about 1.2 against 1.0 CPU s of rdc-bench line with scanout
 * off.)
 */
static rdc_always_inline void line_q32(uint8_t *p, uint32_t q, uint64_t v2,
				       bool column, uint32_t stride)
{
	uint32_t len = q * 4, k;

	if (column) {
		/*
		 * A column's pixels are a cache line each: ask for the line
		 * LINE_AHEAD rows down while this one is stored.
		 */
		for (k = 0; k < q; k++, p += stride) {
			rdc_memcpy(p, &v2, 4);
			__builtin_prefetch(
				(const void *)((uintptr_t)p +
					       LINE_AHEAD * (uintptr_t)stride),
				1);
		}
	} else if (q == 1) {
		rdc_memcpy(p, &v2, 4);
	} else if (q <= 4) {
		rdc_memcpy(p, &v2, 8);
		rdc_memcpy(p + len - 8, &v2, 8);
	} else if (q <= 8) {
		rdc_memcpy(p, &v2, 8);
		rdc_memcpy(p + 8, &v2, 8);
		rdc_memcpy(p + len - 16, &v2, 8);
		rdc_memcpy(p + len - 8, &v2, 8);
	} else {
		for (k = 0; k + 8 < len; k += 8)
			rdc_memcpy(p + k, &v2, 8);
		rdc_memcpy(p + len - 8, &v2, 8);
	}
}

/*
 * rdc_bus_cost of the k pixels (4k bytes) from a written as RDC_BUS_WRITE
 * (no PARTIAL flags), for a a multiple of 4 and a + 4k below 2^32, miss0
 * the open row's miss (1 when it is not a's row): the same sum in 32 bits
 * with what those allow folded in.  With two pixels a beat, the span's
 * first beat is partial (head) when a is odd in pixels, its last (tail)
 * when a + 4k is, and its beats are (k - tail + head) / 2 + tail; a span
 * within one beat has at most one partial edge, so the beats merged are
 * head + tail; both edges share a turnaround only within one burst.
 */
_Static_assert(RDC_BUS_BYTES == 8, "two 4-byte pixels a beat");
_Static_assert((RDC_BUS_BURST_BYTES & (RDC_BUS_BURST_BYTES - 1)) == 0,
	       "bursts a power of two bytes");

static rdc_always_inline uint64_t span_cost32(uint32_t a, uint32_t k,
					      uint32_t miss0)
{
	uint32_t e = a + 4 * k - 1;
	uint32_t head = a / 4 & 1, tail = head ^ (k & 1);
	uint32_t misses =
		e / RDC_DRAM_ROW_BYTES - a / RDC_DRAM_ROW_BYTES + miss0;
	uint32_t one_burst = (a ^ e) < RDC_BUS_BURST_BYTES;
	uint32_t turns = head + tail - (head & tail & one_burst);

	return (uint64_t)((k + 3 * (head + tail)) / 2) * RDC_T_BEAT +
	       (uint64_t)misses * RDC_T_ROW_MISS + (uint64_t)turns * RDC_T_TURN;
}

/*
 * A run of k pixels from a with DRAM row `row` open: an x-major run is a
 * span, a column k pixels of pp (a pixel and a row miss) each, less the
 * miss its first pixel does not pay where it is in the open row.
 */
static rdc_always_inline uint64_t run_cost_from(uint32_t a, uint32_t k,
						bool xmajor, uint64_t pp,
						uint32_t row)
{
	if (xmajor)
		return span_cost32(a, k, a / RDC_DRAM_ROW_BYTES != row);
	return (uint64_t)k * pp -
	       (a / RDC_DRAM_ROW_BYTES == row ? RDC_T_ROW_MISS : 0);
}

/*
 * span_cost32(a, k, 1) of a line's middle runs, k = q + more, from a
 * table made once a line: c[2p + more] for a run starting at pixel p of
 * its burst (p = a / 4 % 8) holds the beats, the row miss and the
 * turnarounds, less the one both edges share where the run ends in the
 * burst it starts in (p + k <= 8); a run that crosses a DRAM row (a and
 * its last byte e differ above the row's bits: a run no longer than a
 * row crosses one boundary at most) adds a row miss.  With h = p & 1 and
 * t = h ^ (k & 1) as span_cost32's head and tail.  Half of span_cost32's
 * instructions in x-major line_fast, whose runs are a few pixels each.
 */
#define RUN_BURST_PX (RDC_BUS_BURST_BYTES / 4)

struct run_costs {
	uint32_t c[2 * RUN_BURST_PX];
	uint32_t most; /* no run costs more: the largest base and a row miss */
};

#define RUN_COSTS_MAX_Q (RDC_DRAM_ROW_BYTES / 4 - 1) /* q + 1 pixels a row */

static inline void run_costs_fill(struct run_costs *rc, uint32_t q)
{
	uint32_t base[4], shared[4], p, more;

	for (p = 0; p < 2; p++) {
		for (more = 0; more < 2; more++) {
			uint32_t k = q + more, t = p ^ (k & 1);

			base[2 * p + more] =
				(k + 3 * (p + t)) / 2 * RDC_T_BEAT +
				RDC_T_ROW_MISS + (p + t) * RDC_T_TURN;
			shared[2 * p + more] = (p & t) * RDC_T_TURN;
		}
	}
	/* unrolled, the tests on p folded: a line's cost, not a run's */
#pragma GCC unroll 8
	for (p = 0; p < RUN_BURST_PX; p++) {
		uint32_t h = p & 1;

		rc->c[2 * p] =
			base[2 * h] -
			(shared[2 * h] & -(uint32_t)(p + q <= RUN_BURST_PX));
		rc->c[2 * p + 1] =
			base[2 * h + 1] -
			(shared[2 * h + 1] & -(uint32_t)(p + q < RUN_BURST_PX));
	}
	/* no c[] is above its base (a bound is all a stretch needs) */
	rc->most =
		RDC_MAX(RDC_MAX(base[0], base[1]), RDC_MAX(base[2], base[3])) +
		RDC_T_ROW_MISS;
}

static rdc_always_inline uint64_t run_cost32(const struct run_costs *rc,
					     uint32_t a, uint32_t k,
					     uint32_t more)
{
	uint32_t x = a ^ (a + 4 * k - 1);

	/* (a select, not a branch: runs alternate between the cases) */
	return rc->c[(a / 4 % RUN_BURST_PX) * 2 + more] +
	       (x >= RDC_DRAM_ROW_BYTES) * RDC_T_ROW_MISS;
}

/*
 * A pixel's cost in an open row, the same at any 4-aligned address: a
 * constant, folded where it is used (line_fast's pixel of a column is
 * this and a row miss).
 */
static rdc_always_inline uint32_t line_one(void)
{
	uint32_t open = 0;

	return (uint32_t)rdc_bus_cost(&open, 0, 4, RDC_BUS_WRITE, 1);
}

/* What line_fast needs of a line, fixed while it runs. */
struct line_fixed {
	uint8_t *vram;
	uint64_t lim, v2;
	uint64_t lo, hi; /* the bytes the line may write (the write barrier) */
	uint32_t q, vstep, stride;
	int64_t rr, d0, d1; /* rem < rr: a run of q + 1; rem += d1 or d0 */
	/*
	 * line_stretches32's, where d0 < 0: sdd = dd = -d0 and
	 * d1 = tq * dd + tr, or with flip (stretches of runs of q + 1)
	 * sdd = d1 and dd = tq * d1 + tr; sdd = 0 where d0 = 0
	 */
	int64_t sdd, tq, tr;
	bool flip;
};

/* Where a line is: the next run's first step, its minor offset, rem. */
struct line_pos {
	int64_t run, j, rem;
	uint32_t addr;
};

/*
 * line_fast's run of k pixels at a that the window refuses: charged and
 * written across the line starts that fall in it, in the window, each
 * burst as rdc_port_span / rdc_port_column would charge it (a column
 * pixel is a burst; a span's pixels are cut at burst boundaries): those
 * that end by the window's limit, then the event (rdc_port_window_event)
 * and on from its fetch's end.  Where an event is not one the window can
 * take, the rest goes to line_cut.  w->t and w->row are the window's as
 * the first `done` pixels (charged, not written) left them.  Returns
 * what line_cut does; when true, the window (a reopened one too) has
 * seen the line's writes (rdc_scan_window_hit).
 */
static rdc_noinline bool line_events(struct rdc_dp *dp,
				     struct rdc_port_window *w,
				     const struct line_fixed *f, uint32_t a,
				     uint32_t k, uint32_t done, bool xmajor,
				     uint64_t *pixels)
{
	const uint32_t umul = xmajor ? 4 : f->stride;
	const uint64_t pp = line_one() + RDC_T_ROW_MISS;
	uint32_t a0 = a, k0 = k, e;
	uint64_t budget, c0;

	a += done * umul;
	k -= done;

	while (k) {
		budget = w->lim - w->t;
		if (xmajor) {
			/* the pixels of this burst */
			e = RDC_MIN(k, (uint32_t)(RDC_BUS_BURST_BYTES -
						  a % RDC_BUS_BURST_BYTES) /
					       4);
			c0 = run_cost_from(a, e, true, pp, w->row);
			if (c0 > budget)
				e = 0;
			else
				w->row = (a + 4 * e - 1) / RDC_DRAM_ROW_BYTES;
		} else {
			c0 = line_one() + (a / RDC_DRAM_ROW_BYTES != w->row ?
						   RDC_T_ROW_MISS :
						   0);
			e = c0 > budget ?
				    0 :
				    (uint32_t)RDC_MIN((uint64_t)k,
						      1 + (budget - c0) / pp);
			if (e) {
				c0 += (uint64_t)(e - 1) * pp;
				w->row = (a + (e - 1) * umul) /
					 RDC_DRAM_ROW_BYTES;
			}
		}
		if (e) {
			w->t += c0;
			a += e * umul;
			k -= e;
			continue;
		}
		if (!rdc_port_window_event(dp->hw, w) || w->t > w->lim) {
			/* what is charged written, the rest the port's */
			if (a != a0)
				line_q32(f->vram + a0, k0 - k, f->v2, !xmajor,
					 umul);
			*pixels += k0 - k;
			if (!line_cut(dp, w, a, k, xmajor, pixels))
				return false;
			rdc_scan_window_hit(dp->hw, w, f->lo, f->hi);
			return true;
		}
		rdc_scan_window_hit(dp->hw, w, f->lo, f->hi);
	}
	line_q32(f->vram + a0, k0, f->v2, !xmajor, umul);
	*pixels += k0;
	return true;
}

/*
 * line_events inline where the run's pixels before the event are known
 * without its pass per burst: the first `before` (a column's that end by
 * the limit; none of a span within one burst, which as a whole does
 * not).  Those charged, the event taken, and the rest charged from the
 * fetch's end in one sum where it fits: what line_events' loop charges,
 * without the call and the loop for the line start that falls in most
 * long lines.  Else line_events or line_cut from where it stands.
 */
static rdc_always_inline bool line_event(struct rdc_dp *dp,
					 struct rdc_port_window *w,
					 const struct line_fixed *f, uint32_t a,
					 uint32_t k, uint32_t before,
					 bool xmajor, uint64_t *pixels)
{
	const uint32_t umul = xmajor ? 4 : f->stride;
	const uint64_t pp = line_one() + RDC_T_ROW_MISS;
	const uint32_t b = a + before * umul, rest = k - before;
	uint64_t cost;

	if (before) {
		w->t += before * pp;
		w->row = (b - umul) / RDC_DRAM_ROW_BYTES;
	}
	if (!rdc_port_window_event(dp->hw, w) || w->t > w->lim) {
		if (before)
			line_q32(f->vram + a, before, f->v2, !xmajor, umul);
		*pixels += before;
		if (!line_cut(dp, w, b, rest, xmajor, pixels))
			return false;
		rdc_scan_window_hit(dp->hw, w, f->lo, f->hi);
		return true;
	}
	rdc_scan_window_hit(dp->hw, w, f->lo, f->hi);
	cost = run_cost_from(b, rest, xmajor, pp, w->row);
	if (cost > w->lim - w->t)
		return line_events(dp, w, f, a, k, before, xmajor, pixels);
	w->t += cost;
	w->row =
		(b + (rest - 1) * umul + (xmajor ? 3 : 0)) / RDC_DRAM_ROW_BYTES;
	line_q32(f->vram + a, k, f->v2, !xmajor, umul);
	*pixels += k;
	return true;
}

/*
 * line_stretches_q's runs of q from p to pe, s0 apart: stored, and each
 * charged to *budget where `charge` (a span's stretch not charged
 * whole).  `charge` a constant in each call: neither loop tests it.
 * (vram and v2 by value: read through f, the stores to p might change
 * them, so they would be loaded again for every run.)
 */
static rdc_always_inline uint8_t *
line_runs(uint8_t *vram, uint64_t v2, const struct run_costs *rc, uint8_t *p,
	  uint8_t *pe, ptrdiff_t s0, uint32_t q, bool flip, bool column,
	  uint32_t umul, bool charge, uint64_t *budget)
{
	for (; p != pe; p += s0) {
		if (charge)
			*budget -=
				run_cost32(rc, (uint32_t)(p - vram), q, flip);
		line_q32(p, q, v2, column, umul);
	}
	return p;
}

/*
 * line_fast's middle runs a stretch at a time: a stretch is the t runs of
 * q pixels (rem >= 0 before each: rem -= dd) and the run of q + 1 after
 * them (rem < 0: rem += d1), t from rem, so that a pass takes the
 * run-slicing steps once for several runs.  With rem before the run of
 * q + 1 rn (-dd <= rn < 0), the next t is tq + (rn + tr >= 0) for
 * d1 = tq * dd + tr: floor((rn + d1) / dd) + 1 without a division, and
 * the next rn rn + tr, less dd where that is not negative: a midpoint
 * step of its own, one level up, with no product in the loop.
 *
 * Where runs of q + 1 are the more (d1 < dd: n / m's fraction over a
 * half), such a stretch is mostly one run or two, so `flip`'s are the
 * other way round: runs of q + 1 (q here) and the run of q after them,
 * in rem' = -1 - rem, for which a run of q + 1 is rem' >= 0 (rem' -= d1)
 * and a run of q rem' < 0 (rem' += dd): the same steps, dd and d1
 * swapped (f->sdd, and tq and tr of dd).  Random lines have about 40%
 * fewer stretches so.
 *
 * A span's stretch is charged here.  For q == 1, where random lines'
 * runs are one pixel or two and most of a line's cost is the steps, a
 * run of one costs the same at any address (rc->c[0]: a beat, a row
 * miss, a turnaround), so the stretch is charged whole.  So is one of
 * runs of two from an even pixel (one whole beat: rc->c[flip], pixel
 * 0's), as all of a stretch's runs of q start on an even pixel where its
 * first does (the stride a whole number of beats, q even).  Other
 * stretches are charged a run at a time as they are stored, once known
 * to fit at rc->most a run.  Where the window cannot take it so, the
 * stretch stops for line_fast's loop to take the rest run by run, as it
 * takes the events.  A column's stretches line_fast charges (line_one
 * and a row miss a pixel), and `end` is then also where the window's
 * budget ends.  A stretch whose last run would not start before `end`
 * stops too.
 *
 * The stretch that stops so has its runs of q that the window takes
 * and that start before `end` (a span's that fit; a column's before
 * `part`, flip's before `end`) stored here, in its pointer loop:
 * line_fast's loop, a run a pass, then mostly has only the run the line
 * start falls in to take, or none.  Where n is a multiple of m (dd 0:
 * all runs of q, a diagonal's of one), the line is one such stretch.
 */
static rdc_always_inline void
line_stretches_q(const struct line_fixed *f, const struct run_costs *rc,
		 bool column, uint32_t q, bool flip, uint32_t umul, int64_t end,
		 int64_t part, int64_t *runp, int64_t *remp, uint32_t *ap,
		 uint64_t *budgetp)
{
	uint8_t *const vram = f->vram;
	const uint64_t v2 = f->v2;
	const uint32_t step0 = q * umul + f->vstep, qb = flip ? q - 1 : q + 1;
	/* the steps, signed */
	const ptrdiff_t s0 = (int32_t)step0,
			s1 = flip ? s0 - (ptrdiff_t)umul : s0 + (ptrdiff_t)umul;
	const int64_t dd = f->sdd, tq = f->tq, tr = f->tr;
	int64_t run = *runp, rem = flip ? -1 - *remp : *remp, t, rn, u;
	int64_t k, n = 0;
	uint64_t budget = *budgetp, cost;
	uint8_t *p = vram + *ap, *pe;
	bool whole; /* the stretch's runs of q all cost rc->c[flip] */

	/* -dd <= rem < d1 here: 0 <= rem + rr < 2m with rr = dd */
	if (dd == 0) /* all runs of q: more than start before end */
		t = RDC_MAX(end - run, (int64_t)0) + 1;
	else
		t = rem < 0 ? 0 : rem / dd + 1;
	rn = rem - t * dd; /* rem before the run of q + 1 */
	while (run + t * q < end) {
		/* where the run of q + 1 starts */
		pe = p + t * s0;
		whole = !column &&
			(q == 1 || (q == 2 && ((p - vram) & 4) == 0));
		if (whole) {
			cost = (uint64_t)t * rc->c[flip] +
			       run_cost32(rc, (uint32_t)(pe - vram), qb, !flip);
			if (cost > budget)
				break;
			budget -= cost;
		} else if (!column && (uint64_t)(t + 1) * rc->most > budget) {
			break;
		}
		if (column || whole)
			p = line_runs(vram, v2, rc, p, pe, s0, q, flip, column,
				      umul, false, &budget);
		else
			p = line_runs(vram, v2, rc, p, pe, s0, q, flip, column,
				      umul, true, &budget);
		if (!column && !whole)
			budget -=
				run_cost32(rc, (uint32_t)(p - vram), qb, !flip);
		line_q32(p, qb, v2, column, umul);
		run += t * q + qb;
		p += s1;
		/* the next rn: rn + d1 - t * dd, d1 - tq * dd being tr */
		u = rn + tr;
		t = tq + (u >= 0);
		rn = u >= 0 ? u - dd : u;
	}
	/*
	 * The runs of q before the last that the window takes: a column's
	 * that start before part (of q + 1: end), a span's that start
	 * before end and fit (all t where the budget stopped the stretch;
	 * a run of one c[0]).
	 */
	if (flip || !column)
		part = end;
	k = part > run ? RDC_MIN(t, (part - run + q - 1) / q) : 0;
	if (column) {
		n = k;
	} else if (q == 1) {
		n = (int64_t)RDC_MIN((uint64_t)k, budget / rc->c[0]);
		budget -= (uint64_t)n * rc->c[0];
	} else {
		for (; n < k; n++) {
			cost = run_cost32(rc, (uint32_t)(p + n * s0 - vram), q,
					  flip);
			if (cost > budget)
				break;
			budget -= cost;
		}
	}
	for (pe = p + n * s0; p != pe; p += s0)
		line_q32(p, q, v2, column, umul);
	run += n * q;
	t -= n;
	*runp = run;
	*remp = flip ? -1 - (rn + t * dd) : rn + t * dd;
	*ap = (uint32_t)(p - vram);
	*budgetp = budget;
}

/* line_stretches_q for q, its runs of q and q + 1, flipped or not */
static rdc_always_inline void
line_stretches_k(const struct line_fixed *f, const struct run_costs *rc,
		 bool column, uint32_t q, uint32_t umul, int64_t end,
		 int64_t part, int64_t *runp, int64_t *remp, uint32_t *ap,
		 uint64_t *budgetp)
{
	if (!f->flip)
		line_stretches_q(f, rc, column, q, false, umul, end, part, runp,
				 remp, ap, budgetp);
	else
		line_stretches_q(f, rc, column, q + 1, true, umul, end, part,
				 runp, remp, ap, budgetp);
}

/*
 * q from 1 to 7, the most of them, a constant in each call: line_q32's
 * tests on a run's length go from the loops (a span's run, of 8 pixels
 * at most, is one store, two or four, a column's loop unrolled), and
 * whether a stretch may be charged whole is known.
 */
static rdc_always_inline void
line_stretches32(const struct line_fixed *f, const struct run_costs *rc,
		 bool column, uint32_t umul, int64_t end, int64_t part,
		 int64_t *runp, int64_t *remp, uint32_t *ap, uint64_t *budgetp)
{
	/* each case the same call with its own constant q */
#define STRETCHES_Q(k) \
	case k: \
		line_stretches_k(f, rc, column, k, umul, end, part, runp, \
				 remp, ap, budgetp); \
		break
	switch (f->q) {
		STRETCHES_Q(1);
		STRETCHES_Q(2);
		STRETCHES_Q(3);
		STRETCHES_Q(4);
		STRETCHES_Q(5);
		STRETCHES_Q(6);
		STRETCHES_Q(7);
	default:
		line_stretches_k(f, rc, column, f->q, umul, end, part, runp,
				 remp, ap, budgetp);
	}
#undef STRETCHES_Q
}

/*
 * The middle runs of a direct line (each of q or q + 1 steps, rem < 2m),
 * while the run cannot reach the last step ihi and the port window takes
 * it: each charged as rdc_port_window_span / _column would (the same
 * cost, the same test against the window's limit), then written.  Stops
 * before a run the window refuses, which the caller then takes through
 * line_run.
 *
 * The stride is over a DRAM row plus a beat, so after the first run
 * every run starts in a row the one before did not end in (a row miss):
 * a span costs span_cost32 with miss0 1, and a column (one beat a pixel,
 * a row each) line_one plus a row miss a pixel, so the window's test on
 * each run is a bound on the step where the runs must end.  Few values
 * live in the loops, so that they stay in registers: the budget left
 * before the limit rather than the time and the limit, rem less rr, and j
 * found again at the end from rem (rem = 2m * run + n - 2n * j all along).
 */
static rdc_always_inline void line_fast(struct rdc_dp *dp,
					struct rdc_port_window *w,
					const struct line_fixed *f, bool xmajor,
					int64_t ihi, int64_t n, int64_t m,
					struct line_pos *pos, uint64_t *pixels)
{
	const uint32_t q = f->q, vstep = f->vstep;
	const uint32_t umul = xmajor ? 4 : f->stride;
	const uint32_t step0 = q * umul + vstep, step1 = step0 + umul;
	const uint64_t v2 = f->v2, pp = line_one() + RDC_T_ROW_MISS;
	const int64_t rr = f->rr, d0 = f->d0, d1 = f->d1, end = ihi - q;
	uint8_t *const vram = f->vram;
	int64_t run0 = pos->run;
	int64_t run = run0, rem = pos->rem, run1, k;
	uint64_t lim = f->lim, budget = lim - w->t, cost;
	uint32_t a = pos->addr, row = w->row;
	bool more, last;

	rdc_scan_window_hit(dp->hw, w, f->lo, f->hi);

	/*
	 * The first run, as rdc_dp_line_steps' loop makes it: rem may be
	 * 2m or more, the run may be the last, and the open row may be its
	 * own.
	 */
	if (rem < 2 * m)
		k = (int64_t)q + (rem < rr);
	else
		k = (2 * n - rem + 2 * m - 1) / (2 * m);
	last = run + k - 1 >= ihi;
	if (last)
		k = ihi - run + 1;
	cost = run_cost_from(a, (uint32_t)k, xmajor, pp, row);
	if (cost > budget)
		return;
	budget -= cost;
	line_q32(vram + a, (uint32_t)k, v2, !xmajor, umul);
	if (last) {
		row = (a + ((uint32_t)k - 1) * umul + (xmajor ? 3 : 0)) /
		      RDC_DRAM_ROW_BYTES;
		run = ihi + 1;
		goto out;
	}
	rem += 2 * m * k - 2 * n - rr;
	run += k;
	a += (uint32_t)k * umul + vstep;
	run1 = run;

	if (xmajor) {
		struct run_costs rc;
		const bool table = q <= RUN_COSTS_MAX_Q;
		/* (n a multiple of m: all runs of q, one stretch) */
		const bool stretches = table && d0 <= 0;
		bool stretch = stretches;

		if (table)
			run_costs_fill(&rc, q);
		while (run < end) {
			if (stretch) {
				line_stretches32(f, &rc, false, 4, end, 0, &run,
						 &rem, &a, &budget);
				if (run >= end)
					break;
				/* run by run up to the event that stopped it */
				stretch = false;
			}
			more = rem < 0;
			k = q + more;
			cost = table ? run_cost32(&rc, a, (uint32_t)k, more) :
				       span_cost32(a, (uint32_t)k, 1);
			if (cost > budget) {
				/* the run an event falls in, and on after it */
				w->t = lim - budget;
				w->row = (a - vstep - 1) / RDC_DRAM_ROW_BYTES;
				*pixels += (uint64_t)(run - run0);
				if ((a ^ (a + 4 * (uint32_t)k - 1)) <
				    RDC_BUS_BURST_BYTES)
					more = line_event(dp, w, f, a,
							  (uint32_t)k, 0, true,
							  pixels);
				else
					more = line_events(dp, w, f, a,
							   (uint32_t)k, 0, true,
							   pixels);
				rem += k > q ? d1 : d0;
				run += k;
				a += k > q ? step1 : step0;
				run0 = run;
				if (!more)
					goto cut;
				lim = w->lim;
				budget = lim - w->t;
				stretch = stretches;
				continue;
			}
			budget -= cost;
			line_q32(vram + a, (uint32_t)k, v2, false, 4);
			rem += more ? d1 : d0;
			run += k;
			a += more ? step1 : step0;
		}
	} else {
		/* the runs end by step runmax: `budget / pp` pixels more */
		uint64_t left = budget / pp;
		int64_t runmax = left > (uint64_t)(ihi - run) ?
					 ihi + 1 :
					 run + (int64_t)left;
		/* (n a multiple of m: all runs of q, one stretch) */
		const bool stretches = d0 <= 0;
		bool stretch = stretches;

		while (run < end) {
			if (stretch) {
				/* its runs of q that end by runmax */
				line_stretches32(f, NULL, true, umul,
						 RDC_MIN(end, runmax - q),
						 RDC_MIN(end, runmax - q + 1),
						 &run, &rem, &a, &budget);
				if (run >= end)
					break;
				stretch = false;
			}
			more = rem < 0;
			k = q + more;
			if (run + k > runmax) {
				/* the run an event falls in, and on after it */
				budget -= pp * (uint64_t)(run - run1);
				w->t = lim - budget;
				w->row =
					(a - vstep - umul) / RDC_DRAM_ROW_BYTES;
				*pixels += (uint64_t)(run - run0);
				/* `budget / pp` pixels fit before the event */
				more = line_event(dp, w, f, a, (uint32_t)k,
						  (uint32_t)(runmax - run),
						  false, pixels);
				rem += k > q ? d1 : d0;
				run += k;
				a += k > q ? step1 : step0;
				run0 = run;
				if (!more)
					goto cut;
				lim = w->lim;
				budget = lim - w->t;
				run1 = run;
				left = budget / pp;
				runmax = left > (uint64_t)(ihi - run) ?
						 ihi + 1 :
						 run + (int64_t)left;
				stretch = stretches;
				continue;
			}
			line_q32(vram + a, (uint32_t)k, v2, true, umul);
			rem += more ? d1 : d0;
			run += k;
			a += more ? step1 : step0;
		}
		budget -= pp * (uint64_t)(run - run1);
	}
	/* the last pixel written, a + vstep before the next run's first */
	row = (a - vstep - (xmajor ? 1 : umul)) / RDC_DRAM_ROW_BYTES;
	/* the run or two left once no run of q + 1 fits before ihi */
	while (run >= end && run <= ihi) {
		k = (int64_t)q + (rem < 0);
		last = run + k - 1 >= ihi;
		if (last)
			k = ihi - run + 1;
		cost = xmajor ? span_cost32(a, (uint32_t)k, 1) :
				(uint64_t)k * pp;
		if (cost > budget)
			break;
		budget -= cost;
		line_q32(vram + a, (uint32_t)k, v2, !xmajor, umul);
		row = (a + ((uint32_t)k - 1) * umul + (xmajor ? 3 : 0)) /
		      RDC_DRAM_ROW_BYTES;
		if (last) {
			run = ihi + 1;
			goto out;
		}
		rem += 2 * m * k - 2 * n;
		run += k;
		a += (uint32_t)k * umul + vstep;
	}
	pos->rem = rem + rr;
	pos->j = (2 * m * run + n - pos->rem) / (2 * n);
	pos->addr = a;
out:
	w->t = lim - budget;
	w->row = row;
	pos->run = run;
	*pixels += (uint64_t)(run - run0);
	return;
cut:
	/* stopped after a cut: the window is as line_cut left it */
	pos->rem = rem + rr;
	pos->j = (2 * m * run + n - pos->rem) / (2 * n);
	pos->addr = a;
	pos->run = run;
}

/* line_fast for each axis, out of line: its loop keeps its registers. */
static rdc_noinline void line_fast_x(struct rdc_dp *dp,
				     struct rdc_port_window *w,
				     const struct line_fixed *f, int64_t ihi,
				     int64_t n, int64_t m, struct line_pos *pos,
				     uint64_t *pixels)
{
	line_fast(dp, w, f, true, ihi, n, m, pos, pixels);
}

static rdc_noinline void line_fast_y(struct rdc_dp *dp,
				     struct rdc_port_window *w,
				     const struct line_fixed *f, int64_t ihi,
				     int64_t n, int64_t m, struct line_pos *pos,
				     uint64_t *pixels)
{
	line_fast(dp, w, f, false, ihi, n, m, pos, pixels);
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
	 * window refuses goes to dp_run_refused, as in dp_runs_flush.
	 */
	bool direct = bytes == 4 && !rdc_rop_reads_dst(dp->st.rop);
	bool fast = false;
	struct rdc_port_window w = { 0 };
	struct rdc_port_run one;
	struct line_fixed f; /* set where fast: line_fast's only */
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
	if (direct) {
		if (nruns)
			dp_runs_flush(dp);
		nruns = 0;
		fg = rdc_rop_apply(dp->st.rop, dp->st.fg, 0);
		rdc_st32(pair, fg);
		rdc_st32(pair + 4, fg);
		rdc_port_window_open(dp->hw, &w);
		/*
		 * line_fast for the middle runs: not on the reference paths
		 * (test_perf_paths; dp_runs_ok, as is every pixel 4-byte
		 * aligned), without a VRAM watcher (it sees each run as
		 * rdc_port_window_span / _column does), with a column's
		 * pixels in one beat each and the line's bounding box in
		 * VRAM (no run refused for its address).
		 */
		if (m > 0 && !dp->hw->vram_hook &&
		    stride % RDC_BUS_BYTES == 0 &&
		    stride > RDC_DRAM_ROW_BYTES + RDC_BUS_BYTES) {
			int64_t jz =
				ihi == n ? m : /* j(n) */
					   dp_div_floor(2 * ihi * m + n, 2 * n);
			int64_t va = v0 + sv * j, vz = v0 + sv * jz;
			uint64_t lo = base + (uint64_t)(u0 + ilo) * umul +
				      (uint64_t)RDC_MIN(va, vz) * vmul;
			uint64_t hi = base + (uint64_t)(u0 + ihi) * umul +
				      (uint64_t)RDC_MAX(va, vz) * vmul;

			fast = RDC_MIN(va, vz) >= 0 && u0 + ilo >= 0 &&
			       lo <= hi && hi + 4 <= dp->hw->vram_size;
			f.lo = lo;
			f.hi = hi + 4;
		}
	}
	if (fast) {
		f.vram = w.vram;
		f.lim = w.lim;
		rdc_memcpy(&f.v2, pair, 8);
		f.q = (uint32_t)q;
		f.vstep = (uint32_t)sv * vmul;
		f.stride = stride;
		f.rr = rr;
		f.d0 = 2 * m * q - 2 * n;
		f.d1 = f.d0 + 2 * m;
		f.flip = false;
		f.sdd = f.tq = f.tr = 0;
		if (f.d0 < 0) {
			int64_t sd1;

			f.flip = f.d1 < -f.d0;
			f.sdd = f.flip ? f.d1 : -f.d0;
			sd1 = f.flip ? -f.d0 : f.d1;
			f.tq = sd1 / f.sdd;
			f.tr = sd1 - f.tq * f.sdd;
		}
	}

	for (; i <= ihi; i++, j++) {
		int32_t v, a, b;
		struct rdc_port_run *r;

		if (fast && w.open && w.t <= w.lim) {
			struct line_pos pos = {
				.run = i,
				.j = j,
				.rem = rem,
				.addr = base +
					(uint32_t)(v0 + sv * (int32_t)j) *
						vmul +
					(uint32_t)(u0 + (int32_t)i) * umul,
			};

			if (xmajor)
				line_fast_x(dp, &w, &f, ihi, n, m, &pos,
					    &pixels);
			else
				line_fast_y(dp, &w, &f, ihi, n, m, &pos,
					    &pixels);
			if (pos.run > ihi)
				break;
			i = pos.run;
			j = pos.j;
			rem = pos.rem;
		}
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
			f.vram = w.vram;
			f.lim = w.lim;
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
	struct rdc_rect c = rdc_dp_clip_bounds(dp); /* empty: returns below */
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
		/*
		 * j(i) <= jhi  <=>  2im < 2n(jhi + 1) - n; no bound when
		 * jhi >= m = j(n) (the line ends inside)
		 */
		if (jhi < m)
			ihi = RDC_MIN(
				ihi,
				dp_div_ceil(2 * n * (jhi + 1) - n, 2 * m) - 1);
	} else if (jlo > 0) {
		return; /* j is always 0 */
	}
	if (ilo > ihi)
		return;

	if (n > 0 && ilo > 0) {
		j = dp_div_floor(2 * ilo * m + n, 2 * n);
		rem = 2 * ilo * m + n - j * 2 * n;
	} else if (n > 0) {
		j = 0; /* j(0) */
		rem = n;
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
