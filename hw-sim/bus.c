// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The VRAM bus: the cost model of bus.h and the DP's VRAM port.
 *
 * Costs are additive over bursts, so a span that no scanout event can
 * interrupt is charged in closed form (a handful of shifts); only a span
 * that a fetch window or another scanout event falls into is walked burst
 * by burst.  That keeps a full-screen fill within a few microseconds of
 * host time beyond the memset the DP does itself.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"

/*
 * One burst [a, a + n) starting no earlier than *tp: wait while the CRTC
 * owns the bus, and do not start a burst that a fetch window opening
 * before its end would overlap.  Scanout events that do not fetch (blank
 * lines, vblank) are processed as their time comes; they see VRAM as it
 * was before this access.
 */
static void bus_burst(struct rdc_hw *hw, uint64_t *tp, uint64_t a, uint64_t n,
		      unsigned int kind)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t t = *tp;

	for (;;) {
		uint32_t row = hw->bus.open_row;
		uint64_t cost, ev;

		if (t < c->fetch_end) {
			hw->perf.stall += c->fetch_end - t;
			t = c->fetch_end;
		}
		if (c->next_line_time <= t) {
			rdc_crtc_catch_up(hw, t);
			continue;
		}
		cost = rdc_bus_cost(&row, a, n, kind, 1);
		ev = c->next_line_time;
		if (ev >= t + cost) {
			hw->bus.open_row = row;
			*tp = t + cost;
			return;
		}
		if (rdc_crtc_next_quiet(hw)) {
			/* the catch-up to ev now, and the wait for its fetch */
			if (rdc_crtc_quiet_line(hw)) {
				hw->perf.stall += ev - t;
				t = ev;
			}
			continue;
		}
		if (rdc_crtc_next_fetches(hw)) {
			hw->perf.stall += ev - t;
			t = ev;
			continue;
		}
		rdc_crtc_catch_up(hw, ev);
	}
}

/*
 * Is the bus the DP's from t for `cost` cycles, with no scanout event
 * (fetch window, line start) inside?  Then an access is charged in closed
 * form, exactly as the burst walk would charge it.
 */
static inline bool bus_quiet(const struct rdc_crtc *c, uint64_t t,
			     uint64_t cost)
{
	return t >= c->fetch_end && c->next_line_time >= t + cost;
}

void rdc_bus_charge(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		    unsigned int kind)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t a = addr, end = (uint64_t)addr + len;
	uint64_t t = hw->now;

	if (c->next_line_time <= t)
		rdc_crtc_catch_up(hw, t);
	while (a < end) {
		uint64_t be;
		unsigned int k = kind;

		if (a != addr)
			k &= ~RDC_BUS_HEAD_PARTIAL;
		if (t >= c->fetch_end && c->next_line_time > t) {
			uint32_t row = hw->bus.open_row;
			uint64_t cost =
				rdc_bus_cost(&row, a, end - a, k,
					     rdc_bus_bursts(a, end - a));

			if (c->next_line_time >= t + cost) {
				hw->bus.open_row = row;
				t += cost;
				break;
			}
		}
		/*
		 * An event falls inside: the bursts that end by it are
		 * charged one at a time here, as bus_burst would charge them
		 * (costs add up over bursts); the one it falls inside goes to
		 * bus_burst.
		 */
		for (;;) {
			unsigned int kb = k;

			be = RDC_MIN(end, (a / RDC_BUS_BURST_BYTES + 1) *
						  RDC_BUS_BURST_BYTES);
			if (be != end)
				kb &= ~RDC_BUS_TAIL_PARTIAL;
			if (t >= c->fetch_end && c->next_line_time > t) {
				uint32_t row = hw->bus.open_row;
				uint64_t cost =
					rdc_bus_cost(&row, a, be - a, kb, 1);

				if (c->next_line_time >= t + cost) {
					hw->bus.open_row = row;
					t += cost;
					a = be;
					k &= ~RDC_BUS_HEAD_PARTIAL;
					if (a < end)
						continue;
					break;
				}
			}
			bus_burst(hw, &t, a, be - a, kb);
			a = be;
			break;
		}
	}
	hw->now = t;
}

uint8_t *rdc_port_span(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		       unsigned int kind)
{
	rdc_port_poll(hw);
	if (!len || (uint64_t)addr + len > hw->vram_size)
		return NULL;
	rdc_bus_charge(hw, addr, len, kind);
	if ((kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ)
		rdc_scan_check(hw, addr, (uint64_t)addr + len);
	if (hw->vram_hook && (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ &&
	    rdc_vram_watched(hw, addr, (uint64_t)addr + len))
		rdc_vram_hook_call(hw, hw->now, addr, len, 1, 0,
				   RDC_VRAM_BY_DP);
	return hw->vram + addr;
}

uint8_t *rdc_port_span_pair(struct rdc_hw *hw, uint32_t raddr, uint32_t waddr,
			    uint32_t len, unsigned int kind,
			    const uint8_t **src)
{
	*src = rdc_port_span(hw, raddr, len, RDC_BUS_READ);
	if (!*src)
		return NULL;
	return rdc_port_span(hw, waddr, len, kind);
}

/*
 * rdc_port_column's charge from hw->now, the column in VRAM: each element
 * as rdc_bus_charge would charge it (one burst).
 */
static void bus_column(struct rdc_hw *hw, uint32_t addr, uint32_t stride,
		       uint32_t count, uint32_t len, unsigned int kind)
{
	uint64_t a = addr, t = hw->now;
	uint32_t i;
	bool uniform;

	rdc_crtc_catch_up(hw, t);
	/*
	 * Elements of one beat each, a DRAM row or more apart: once one is
	 * charged, every element after it opens a new row and costs what
	 * the next one does, so those that end by the next scanout event
	 * are charged together (a steep line's column that an event cuts
	 * is hundreds of them).
	 */
	uniform = stride % RDC_BUS_BYTES == 0 && stride >= RDC_DRAM_ROW_BYTES &&
		  a % RDC_BUS_BYTES + len <= RDC_BUS_BYTES;
	for (i = 0; i < count; i++, a += stride) {
		struct rdc_crtc *c = &hw->crtc;
		uint32_t row = hw->bus.open_row;
		uint64_t cost, k;

		/* bus_burst's first step, without the call */
		if (t >= c->fetch_end && c->next_line_time > t) {
			cost = rdc_bus_cost(&row, a, len, kind, 1);
			if (!bus_quiet(c, t, cost)) {
				bus_burst(hw, &t, a, len, kind);
				continue;
			}
			k = 1;
			if (uniform && i &&
			    hw->bus.open_row ==
				    (a - stride) / RDC_DRAM_ROW_BYTES) {
				k = c->running ?
					    (c->next_line_time - t) / cost :
					    count - i;
				k = RDC_MIN(k, (uint64_t)(count - i));
				row = (uint32_t)((a + (k - 1) * stride) /
						 RDC_DRAM_ROW_BYTES);
			}
			hw->bus.open_row = row;
			t += k * cost;
			i += (uint32_t)k - 1;
			a += (k - 1) * stride;
			continue;
		}
		bus_burst(hw, &t, a, len, kind);
	}
	hw->now = t;
}

uint8_t *rdc_port_column(struct rdc_hw *hw, uint32_t addr, uint32_t stride,
			 uint32_t count, uint32_t len, unsigned int kind)
{
	uint64_t end = addr + (uint64_t)(count - 1) * stride + len;

	rdc_port_poll(hw);
	if (!count || !len || end > hw->vram_size)
		return NULL;
	bus_column(hw, addr, stride, count, len, kind);
	if ((kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ)
		rdc_scan_check(hw, addr, end);
	if (hw->vram_hook && (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ &&
	    rdc_vram_watched(hw, addr, end))
		rdc_vram_hook_call(hw, hw->now, addr, len, count, stride,
				   RDC_VRAM_BY_DP);
	return hw->vram + addr;
}

/* Cost of a column run of rdc_port_runs, RDC_NEVER if it is refused. */
static rdc_noinline uint64_t runs_column_cost(const struct rdc_hw *hw,
					      const struct rdc_port_run *r,
					      uint64_t stride,
					      unsigned int kind, uint32_t *row)
{
	uint64_t a = r->addr, cost = 0;
	uint32_t k;

	if (!r->len || !r->count ||
	    a + (r->count - 1) * stride + r->len > hw->vram_size)
		return RDC_NEVER;
	if (a % RDC_BUS_BYTES + r->len <= RDC_BUS_BYTES &&
	    stride % RDC_BUS_BYTES == 0)
		return rdc_bus_column_cost(row, a, stride, r->count, r->len,
					   kind);
	for (k = 0; k < r->count; k++, a += stride)
		cost += rdc_bus_cost(row, a, r->len, kind, 1);
	return cost;
}

/*
 * Runs r[0, n) of rdc_port_runs from *tp, while each ends by `lim` (the
 * next scanout event; the caller has checked that no fetch window is
 * open): costs in closed form, *row and *tp advanced, runs charged
 * returned.  An event cannot fall inside a run that ends by lim, and none
 * is processed meanwhile, so lim holds for the whole batch.  Inlined with
 * kind a constant, the cost formula loses its switch.
 */
static rdc_always_inline uint32_t runs_charge(const struct rdc_hw *hw,
					      const struct rdc_port_run *r,
					      uint32_t n, uint64_t stride,
					      unsigned int kind, uint32_t *row,
					      uint64_t *tp, uint64_t lim)
{
	const uint64_t size = hw->vram_size;
	uint64_t t = *tp;
	uint32_t rw = *row, i;

	for (i = 0; i < n; i++) {
		uint64_t a = r[i].addr, len = r[i].len, cost;
		uint32_t nrw = rw;

		if (r[i].count == 1) {
			if (!len || a + len > size)
				break;
			cost = rdc_bus_cost(&nrw, a, len, kind,
					    rdc_bus_bursts(a, len));
		} else if (len && a % RDC_BUS_BYTES + len <= RDC_BUS_BYTES &&
			   stride % RDC_BUS_BYTES == 0 && r[i].count &&
			   a + (r[i].count - 1) * stride + len <= size) {
			/* one-beat columns (outlines) inline, in closed form */
			cost = rdc_bus_column_cost(&nrw, a, stride, r[i].count,
						   (uint32_t)len, kind);
		} else {
			/* out of line: keeps the span loop in registers */
			cost = runs_column_cost(hw, &r[i], stride, kind, &nrw);
			if (cost == RDC_NEVER)
				break;
		}
		if (t + cost > lim)
			break;
		t += cost;
		rw = nrw;
	}
	*row = rw;
	*tp = t;
	return i;
}

/* rdc_vram_watch's call, out of line: the hot paths keep one test. */
rdc_noinline void rdc_vram_watch_call(const struct rdc_hw *hw, uint64_t t,
				      uint32_t addr, uint32_t len,
				      uint32_t count, uint32_t stride)
{
	rdc_vram_hook_call(hw, t, addr, len, count, stride, RDC_VRAM_BY_DP);
}

/* Does one of the runs charged reach lines scanout has not converted? */
static rdc_noinline bool runs_scan_hit(const struct rdc_hw *hw,
				       const struct rdc_port_run *r, uint32_t n,
				       uint32_t stride)
{
	uint32_t i;

	for (i = 0; i < n; i++) {
		uint64_t s = r[i].count > 1 ? stride : 0;

		if (r[i].count &&
		    rdc_scan_hits(hw, r[i].addr,
				  r[i].addr + (r[i].count - 1) * s + r[i].len))
			return true;
	}
	return false;
}

/* The runs charged, to the VRAM write watcher (off the hot path). */
static rdc_noinline void runs_watched(const struct rdc_hw *hw,
				      const struct rdc_port_run *r, uint32_t n,
				      uint32_t stride, uint64_t t)
{
	unsigned int more = 0;
	uint32_t i;

	for (i = 0; i < n; i++) {
		uint32_t s = r[i].count > 1 ? stride : 0;

		if (!r[i].count ||
		    !rdc_vram_watched(hw, r[i].addr,
				      r[i].addr +
					      (uint64_t)(r[i].count - 1) * s +
					      r[i].len))
			continue;
		rdc_vram_hook_call(hw, t, r[i].addr, r[i].len, r[i].count, s,
				   RDC_VRAM_BY_DP | more);
		more = RDC_VRAM_MORE;
	}
}

uint8_t *rdc_port_runs(struct rdc_hw *hw, const struct rdc_port_run *r,
		       uint32_t n, uint32_t stride, unsigned int kind,
		       uint32_t *done)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t t, lim;
	uint32_t row;

	rdc_port_poll(hw);
	t = hw->now;
	row = hw->bus.open_row;
	if (c->next_line_time <= t)
		rdc_crtc_catch_up(hw, t);
	lim = c->next_line_time;
	*done = 0;
	if (t < c->fetch_end)
		return hw->vram;
	if (kind == RDC_BUS_WRITE)
		*done = runs_charge(hw, r, n, stride, RDC_BUS_WRITE, &row, &t,
				    lim);
	else
		*done = runs_charge(hw, r, n, stride, kind, &row, &t, lim);
	hw->bus.open_row = row;
	hw->now = t;
	if (hw->scan_hi && (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ &&
	    runs_scan_hit(hw, r, *done, stride))
		rdc_scan_drop_all(hw);
	if (hw->vram_hook && (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ)
		runs_watched(hw, r, *done, stride, t);
	return hw->vram;
}

void rdc_port_window_sync(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;

	rdc_port_poll(hw);
	if (c->next_line_time <= hw->now)
		rdc_crtc_catch_up(hw, hw->now);
}

bool rdc_port_window_charge(const struct rdc_hw *hw, struct rdc_port_window *w,
			    const struct rdc_port_run *r, uint32_t stride,
			    unsigned int kind)
{
	uint64_t t = w->t;
	uint32_t row = w->row, done;

	if (!w->open)
		return false;
	if (kind == RDC_BUS_WRITE)
		done = runs_charge(hw, r, 1, stride, RDC_BUS_WRITE, &row, &t,
				   w->lim);
	else
		done = runs_charge(hw, r, 1, stride, kind, &row, &t, w->lim);
	if (!done)
		return false;
	w->t = t;
	w->row = row;
	if (hw->scan_hi && (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ &&
	    runs_scan_hit(hw, r, 1, stride))
		w->scan_hit = true;
	if (hw->vram_hook && (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ)
		runs_watched(hw, r, 1, stride, t);
	return true;
}

/*
 * Rows a whole number of DRAM rows apart: from the second on, every row
 * has the same offset in its beat, burst and DRAM row, and the same
 * relation to the row the last one left open, so each costs what the
 * second does.  rows_costs: the first's cost c0 from open row `row`, the
 * others' c1, and how many of the count rows from a (the first in VRAM)
 * are in VRAM.  rows_fit: of `most` such rows, those that end by the
 * window's limit charged in closed form; how many.
 */
static rdc_always_inline uint64_t rows_costs(const struct rdc_hw *hw,
					     uint32_t row, uint64_t a,
					     uint32_t len, uint32_t stride,
					     uint32_t count, uint64_t *c0,
					     uint64_t *c1)
{
	uint32_t row0 = row;

	*c0 = rdc_bus_cost(&row, a, len, RDC_BUS_WRITE, rdc_bus_bursts(a, len));
	*c1 = rdc_bus_cost_next_row(*c0, a, stride, row0, row);
	if ((uint64_t)(count - 1) * stride > hw->vram_size - len - a)
		return (hw->vram_size - len - a) / stride + 1;
	return count;
}

static rdc_always_inline uint64_t rows_fit(const struct rdc_hw *hw,
					   struct rdc_port_window *w,
					   uint64_t a, uint32_t len,
					   uint32_t stride, uint64_t most,
					   uint64_t c0, uint64_t c1)
{
	uint64_t n = most, end;

	if (w->t + c0 > w->lim)
		return 0;
	/* (divided only when not all fit: a glyph's rows mostly do) */
	if ((n - 1) * c1 > w->lim - w->t - c0)
		n = 1 + (w->lim - w->t - c0) / c1;
	end = a + (n - 1) * stride + len;
	w->t += c0 + (n - 1) * c1;
	w->row = (uint32_t)((end - 1) / RDC_DRAM_ROW_BYTES);
	rdc_scan_window_hit(hw, w, a, end);
	return n;
}

uint32_t rdc_port_window_rows(const struct rdc_hw *hw,
			      struct rdc_port_window *w, uint32_t addr,
			      uint32_t len, uint32_t stride, uint32_t count)
{
	uint64_t t = w->t, a = addr;
	uint32_t row = w->row, i;

	if (!w->open)
		return 0;
	if (stride % RDC_DRAM_ROW_BYTES == 0 && count > 1 && len &&
	    a + len <= hw->vram_size) {
		/* in closed form (rows_fit) */
		uint64_t c0, c1, most, n;

		most = rows_costs(hw, row, a, len, stride, count, &c0, &c1);
		n = rows_fit(hw, w, a, len, stride, most, c0, c1);
		if (n && hw->vram_hook &&
		    rdc_vram_watched(hw, addr, a + (n - 1) * stride + len))
			rdc_vram_hook_call(hw, w->t, addr, len, (uint32_t)n,
					   stride, RDC_VRAM_BY_DP);
		return (uint32_t)n;
	}
	/* runs_charge's span case, the runs made on the way */
	for (i = 0; i < count; i++, a += stride) {
		uint32_t nrw = row;
		uint64_t cost;

		if (!len || a + len > hw->vram_size)
			break;
		cost = rdc_bus_cost(&nrw, a, len, RDC_BUS_WRITE,
				    rdc_bus_bursts(a, len));
		if (t + cost > w->lim)
			break;
		t += cost;
		row = nrw;
	}
	w->t = t;
	w->row = row;
	if (i)
		rdc_scan_window_hit(hw, w, addr,
				    addr + (uint64_t)(i - 1) * stride + len);
	if (hw->vram_hook && i &&
	    rdc_vram_watched(hw, addr, addr + (uint64_t)(i - 1) * stride + len))
		rdc_vram_hook_call(hw, t, addr, len, i, stride, RDC_VRAM_BY_DP);
	return i;
}

/* The writes of count pairs, wa + i * wstep, to the write barrier. */
static inline void pairs_scan_hit(const struct rdc_hw *hw,
				  struct rdc_port_window *w, int64_t wa,
				  int64_t wstep, uint32_t len, uint32_t count)
{
	int64_t last = wa + (int64_t)(count ? count - 1 : 0) * wstep;

	if (count)
		rdc_scan_window_hit(hw, w, (uint64_t)RDC_MIN(wa, last),
				    (uint64_t)RDC_MAX(wa, last) + len);
}

/*
 * rows_costs and rows_fit for read/write pairs whose rows both move by
 * the same whole number of DRAM rows: c0 the first pair's cost from open
 * row `row` (returned), c1 each other's, and of those the reads' r0 and
 * r1; of `most` pairs, those that end by the window's limit charged.  A
 * write costs the same in every pair, as it follows its own read; the
 * next read keeps the first's offsets, so only its first row miss can
 * differ (rdc_bus_cost_next_row, for a step of either sign).
 */
static rdc_always_inline uint64_t pairs_costs(uint32_t row, int64_t ra,
					      int64_t wa, int64_t step,
					      uint32_t len, unsigned int kind,
					      uint64_t *c1, uint64_t *r0,
					      uint64_t *r1)
{
	const uint64_t first = (uint64_t)ra / RDC_DRAM_ROW_BYTES;
	const uint32_t row0 = row;
	uint64_t cw;

	*r0 = rdc_bus_cost(&row, (uint64_t)ra, len, RDC_BUS_READ,
			   rdc_bus_bursts((uint64_t)ra, len));
	cw = rdc_bus_cost(&row, (uint64_t)wa, len, kind,
			  rdc_bus_bursts((uint64_t)wa, len));
	*r1 = *r0 - (first != row0) * RDC_T_ROW_MISS +
	      ((uint64_t)(ra + step) / RDC_DRAM_ROW_BYTES != row) *
		      RDC_T_ROW_MISS;
	*c1 = *r1 + cw;
	return *r0 + cw;
}

static rdc_always_inline uint64_t pairs_fit(const struct rdc_hw *hw,
					    struct rdc_port_window *w,
					    int64_t wa, int64_t step,
					    uint32_t len, uint64_t most,
					    uint64_t c0, uint64_t c1)
{
	uint64_t n;

	if (w->t + c0 > w->lim)
		return 0;
	n = RDC_MIN(most, 1 + (w->lim - w->t - c0) / c1);
	w->t += c0 + (n - 1) * c1;
	w->row = (uint32_t)((uint64_t)(wa + (int64_t)(n - 1) * step + len - 1) /
			    RDC_DRAM_ROW_BYTES);
	pairs_scan_hit(hw, w, wa, step, len, (uint32_t)n);
	return n;
}

uint32_t rdc_port_window_pairs(const struct rdc_hw *hw,
			       struct rdc_port_window *w, uint32_t raddr,
			       uint32_t waddr, uint32_t len, int64_t rstep,
			       int64_t wstep, uint32_t count, unsigned int kind)
{
	int64_t ra = raddr, wa = waddr, size = (int64_t)hw->vram_size;
	uint64_t t = w->t;
	uint32_t row = w->row, i;

	if (!w->open || !len || !count)
		return 0;
	if (rstep == wstep && rstep % RDC_DRAM_ROW_BYTES == 0 && count > 1 &&
	    RDC_MIN(ra, ra + (count - 1) * rstep) >= 0 &&
	    RDC_MIN(wa, wa + (count - 1) * wstep) >= 0 &&
	    RDC_MAX(ra, ra + (count - 1) * rstep) + len <= size &&
	    RDC_MAX(wa, wa + (count - 1) * wstep) + len <= size) {
		/* in closed form (pairs_fit, as rows_fit) */
		uint64_t c1, r0, r1,
			c0 = pairs_costs(row, ra, wa, rstep, len, kind, &c1,
					 &r0, &r1);

		return (uint32_t)pairs_fit(hw, w, wa, wstep, len, count, c0,
					   c1);
	}
	/* rdc_port_window_pair's charge, pair by pair */
	for (i = 0; i < count; i++, ra += rstep, wa += wstep) {
		uint32_t nrw = row;
		uint64_t c;

		if (ra < 0 || wa < 0 || ra + len > size || wa + len > size)
			break;
		c = rdc_bus_cost(&nrw, (uint64_t)ra, len, RDC_BUS_READ,
				 rdc_bus_bursts((uint64_t)ra, len));
		c += rdc_bus_cost(&nrw, (uint64_t)wa, len, kind,
				  rdc_bus_bursts((uint64_t)wa, len));
		if (t + c > w->lim)
			break;
		t += c;
		row = nrw;
	}
	w->t = t;
	w->row = row;
	pairs_scan_hit(hw, w, waddr, wstep, len, i);
	return i;
}

/*
 * rdc_port_window_event once its tests have passed: the window open, no
 * VRAM watcher, w->t by the limit and the line start there quiet.
 */
static rdc_always_inline void window_take(struct rdc_hw *hw,
					  struct rdc_port_window *w)
{
	struct rdc_crtc *c = &hw->crtc;

	/* what the window's close would do, then bus_burst's wait */
	if (w->scan_hit)
		rdc_scan_drop_all(hw);
	w->scan_hit = false;
	hw->bus.open_row = w->row;
	if (rdc_crtc_quiet_line(hw)) {
		hw->perf.stall += c->fetch_end - w->t;
		w->t = c->fetch_end;
		w->row = hw->bus.open_row;
	}
	w->lim = c->next_line_time;
}

bool rdc_port_window_event(struct rdc_hw *hw, struct rdc_port_window *w)
{
	if (!w->open || w->t > w->lim || hw->vram_hook ||
	    !rdc_crtc_next_quiet(hw))
		return false;
	window_take(hw, w);
	return true;
}

/*
 * The whole bursts from a of the span [a, end) as `k`, from open row
 * *row, that fit in `budget` cycles when the span as a whole does not:
 * bus_burst's walk, a burst at a time (the one ending at end keeps the
 * TAIL flag, the others lose it; HEAD goes after the first), in closed
 * form.  Past the first burst every burst before the last is whole and
 * aligned, costing `full` plus a row miss where it opens a DRAM row: at
 * most rem / full of them fit, fewer while their misses make them
 * dearer (a few steps: a miss is under a burst's cost).  The last never
 * fits, as the span does not: nor does the first when it is the last,
 * and where it is not, it ends on a burst's edge without the TAIL flag.
 * Returns where the bursts that fit end (a if none does), their cost in
 * *cost and the row they leave in *row.
 */
static rdc_always_inline uint64_t bursts_within(uint32_t *row, uint64_t a,
						uint64_t end, unsigned int k,
						uint64_t budget, uint64_t *cost)
{
	const unsigned int km = k &
				~(RDC_BUS_HEAD_PARTIAL | RDC_BUS_TAIL_PARTIAL);
	uint64_t b1 = (a / RDC_BUS_BURST_BYTES + 1) * RDC_BUS_BURST_BYTES;
	uint32_t r = *row, zero = 0, rj = 0;
	uint64_t c1 = 0, full, j, rb, re, cj = 0;

	if (b1 < end)
		c1 = rdc_bus_cost(&r, a, b1 - a, k & ~RDC_BUS_TAIL_PARTIAL, 1);
	if (b1 >= end || c1 > budget) {
		*cost = 0;
		return a;
	}
	full = rdc_bus_cost(&zero, 0, RDC_BUS_BURST_BYTES, km, 1);
	/* the bursts after the first and before the one holding end - 1 */
	j = RDC_MIN((end - 1) / RDC_BUS_BURST_BYTES - b1 / RDC_BUS_BURST_BYTES,
		    (budget - c1) / full);
	rb = b1 / RDC_DRAM_ROW_BYTES;
	for (; j; j--) {
		/* rdc_bus_cost of the j bursts from b1, aligned and whole */
		re = (b1 + j * RDC_BUS_BURST_BYTES - 1) / RDC_DRAM_ROW_BYTES;
		rj = (uint32_t)re;
		cj = j * full + (re - rb + (rb != r)) * RDC_T_ROW_MISS;
		if (cj <= budget - c1)
			break;
	}
	*row = j ? rj : r;
	*cost = c1 + (j ? cj : 0);
	return b1 + j * RDC_BUS_BURST_BYTES;
}

/*
 * The span [start, end) as `kind`, charged in the window as
 * rdc_bus_charge would charge it: the rest whole where it ends by the
 * limit, else the bursts that end by it (bursts_within), then the line
 * start, which rdc_port_window_event takes.  Returns where it stopped:
 * end, or the first byte not charged when an event is one the window
 * cannot take.  The callers have just seen that the window would take
 * the first (window_goes_on, rdc_port_window_cross), and bursts_within
 * keeps w->t by the limit: that one is taken without asking again.
 *
 * `whole` is the span's cost from w->row where the caller knows it (and
 * that it does not fit), else RDC_NEVER.  The rest's cost after an event
 * follows from it: costs add up over bursts and the rest starts on a
 * burst's edge, so only its first row miss changes, the row open before
 * it being the one the fetch left.
 */
static rdc_always_inline uint64_t window_span(struct rdc_hw *hw,
					      struct rdc_port_window *w,
					      uint64_t start, uint64_t end,
					      unsigned int kind, uint64_t whole)
{
	const uint32_t last = (uint32_t)((end - 1) / RDC_DRAM_ROW_BYTES);
	uint64_t a = start, be, cost;
	unsigned int k = kind;
	bool first = true;
	uint32_t row;

	if (whole == RDC_NEVER) {
		row = w->row;
		whole = rdc_bus_cost(&row, a, end - a, k,
				     rdc_bus_bursts(a, end - a));
		if (w->t + whole <= w->lim) {
			w->t += whole;
			w->row = row;
			return end;
		}
	}
	for (;; first = false) {
		/* whole: [a, end) from w->row, which does not fit */
		row = w->row;
		be = bursts_within(&row, a, end, k, w->lim - w->t, &cost);
		/* [be, end) from `row`, less its first row miss */
		whole -= cost +
			 (be / RDC_DRAM_ROW_BYTES != row) * RDC_T_ROW_MISS;
		if (be != a) {
			w->t += cost;
			w->row = row;
			a = be;
			k &= ~RDC_BUS_HEAD_PARTIAL;
		}
		if (first)
			window_take(hw, w);
		else if (!rdc_port_window_event(hw, w))
			return a;
		if (w->t > w->lim)
			return a;
		whole += (a / RDC_DRAM_ROW_BYTES != w->row) * RDC_T_ROW_MISS;
		if (w->t + whole <= w->lim) {
			w->t += whole;
			w->row = last;
			return end;
		}
	}
}

bool rdc_port_window_cross(struct rdc_hw *hw, struct rdc_port_window *w,
			   const struct rdc_port_run *r, uint32_t stride,
			   unsigned int kind)
{
	uint64_t end = r->addr + (uint64_t)(r->count - 1) * stride + r->len;
	uint64_t a = r->addr;

	if (w->parted == RDC_PARTED_RUN || w->parted == RDC_PARTED_WRITE) {
		/* a _through call's run, where window_span stopped */
		w->parted = 0;
		a = w->part;
		if (a != r->addr)
			kind &= ~RDC_BUS_HEAD_PARTIAL;
		goto rest;
	}
	if (!w->open || !r->len || !r->count || end > hw->vram_size ||
	    hw->vram_hook || w->t >= w->lim || !rdc_crtc_next_quiet(hw))
		return false;
	if (r->count == 1) {
		/* inlined with the kind a constant, the cost loses its switch */
		if (kind == RDC_BUS_WRITE)
			a = window_span(hw, w, a, end, RDC_BUS_WRITE,
					RDC_NEVER);
		else if (kind == RDC_BUS_READ)
			a = window_span(hw, w, a, end, RDC_BUS_READ, RDC_NEVER);
		else
			a = window_span(hw, w, a, end, kind, RDC_NEVER);
		if (a == end)
			goto done;
		if (a != r->addr)
			kind &= ~RDC_BUS_HEAD_PARTIAL;
	}
rest:
	/* the rest as the port call between the window's close and reopening */
	rdc_port_window_close(hw, w);
	if (r->count == 1)
		rdc_bus_charge(hw, (uint32_t)a, (uint32_t)(end - a), kind);
	else
		bus_column(hw, r->addr, stride, r->count, r->len, kind);
	rdc_port_window_open(hw, w);
done:
	if ((kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ &&
	    rdc_scan_hits(hw, r->addr, end))
		w->scan_hit = true;
	return true;
}

/*
 * window_goes_on in a _through call that began lazy with no watcher: only
 * the host changes either, and it does not run inside a port call (a
 * quiet line start calls no hook).  *quiet is the call's
 * rdc_crtc_quiet_until, 0 at its start: the line starts the call takes
 * are all quiet, so it holds until next_line reaches it.
 */
static inline bool window_still_goes_on(const struct rdc_hw *hw,
					const struct rdc_port_window *w,
					uint32_t *quiet)
{
	if (w->t >= w->lim)
		return false;
	if (hw->crtc.next_line < *quiet)
		return true;
	*quiet = rdc_crtc_quiet_until(hw);
	return hw->crtc.next_line < *quiet;
}

/*
 * The _through calls go on past the window's limit while lines wait
 * unconverted (a frame converted at its fetch would read the runs before
 * the caller writes them) and the line start there only fetches.
 */
static inline bool window_goes_on(const struct rdc_hw *hw,
				  const struct rdc_port_window *w,
				  uint32_t *quiet)
{
	return hw->lazy && !hw->vram_hook && window_still_goes_on(hw, w, quiet);
}

/*
 * Span [a, end) as `kind` across the line start, as
 * rdc_port_window_cross charges it (`whole`: its cost, known not to fit
 * before it, or RDC_NEVER): true, or false where it stopped at an event
 * the window cannot take, charged up to w->part and w->parted set to
 * `parted`.
 */
static rdc_always_inline bool
span_through(struct rdc_hw *hw, struct rdc_port_window *w, uint64_t a,
	     uint64_t end, unsigned int kind, uint64_t whole, uint8_t parted)
{
	w->part = window_span(hw, w, a, end, kind, whole);
	if (w->part != end) {
		w->parted = parted;
		return false;
	}
	if ((kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ)
		rdc_scan_window_hit(hw, w, a, end);
	return true;
}

/*
 * rdc_port_window_rows_through once its tests have passed (lazy among
 * them), the first row's cost c0 and the others' c1 known, `most` of
 * them in VRAM.
 */
static rdc_always_inline uint32_t rows_through(struct rdc_hw *hw,
					       struct rdc_port_window *w,
					       uint64_t a, uint32_t len,
					       uint32_t stride, uint64_t most,
					       uint64_t c0, uint64_t c1)
{
	uint64_t done = 0;
	uint32_t quiet = 0;

	for (;;) {
		uint64_t n =
			rows_fit(hw, w, a, len, stride, most - done, c0, c1);

		done += n;
		a += n * stride;
		/* the row the line start falls in: it does not fit */
		if (done == most || !window_still_goes_on(hw, w, &quiet) ||
		    !span_through(hw, w, a, a + len, RDC_BUS_WRITE, n ? c1 : c0,
				  RDC_PARTED_RUN))
			return (uint32_t)done;
		done++;
		a += stride;
		if (done == most)
			return (uint32_t)done;
		/* the row it leaves open is its own: the next costs c1 */
		c0 = c1;
	}
}

uint32_t rdc_port_window_rows_through(struct rdc_hw *hw,
				      struct rdc_port_window *w, uint32_t addr,
				      uint32_t len, uint32_t stride,
				      uint32_t count)
{
	uint64_t a = addr, c0, c1, most;

	/* else, and where there is no closed form, rows up to the limit */
	if (!hw->lazy || !w->open || hw->vram_hook ||
	    stride % RDC_DRAM_ROW_BYTES || count < 2 || !len ||
	    a + len > hw->vram_size)
		return rdc_port_window_rows(hw, w, addr, len, stride, count);
	most = rows_costs(hw, w->row, a, len, stride, count, &c0, &c1);
	return rows_through(hw, w, a, len, stride, most, c0, c1);
}

uint32_t rdc_port_window_rows_costed(struct rdc_hw *hw,
				     struct rdc_port_window *w, uint32_t addr,
				     uint32_t len, uint32_t stride,
				     uint32_t count, uint64_t c0, uint64_t c1)
{
	if (!hw->lazy) /* rows up to the limit */
		return (uint32_t)rows_fit(hw, w, addr, len, stride, count, c0,
					  c1);
	return rows_through(hw, w, addr, len, stride, count, c0, c1);
}

/*
 * rdc_port_window_pairs_through once its tests have passed, inlined
 * there with the kind a constant: the costs of the pairs, and of the
 * spans a line start falls in, lose their switch.
 */
static rdc_always_inline uint32_t pairs_through(
	struct rdc_hw *hw, struct rdc_port_window *w, int64_t ra, int64_t wa,
	uint32_t len, int64_t step, uint32_t count, unsigned int kind)
{
	uint64_t c0, c1, r0, r1, n, cw;
	uint32_t done = 0, quiet = 0;

	c0 = pairs_costs(w->row, ra, wa, step, len, kind, &c1, &r0, &r1);
	cw = c1 - r1;
	for (;;) {
		n = pairs_fit(hw, w, wa, step, len, count - done, c0, c1);
		done += (uint32_t)n;
		ra += (int64_t)n * step;
		wa += (int64_t)n * step;
		/*
		 * The pair the line start falls in: its read, as cross does
		 * (whole where it fits), from the row the pair before left
		 * unless it is the first.
		 */
		if (n)
			r0 = r1;
		/* not lazy, the pairs stop at the limit */
		if (done == count || !hw->lazy ||
		    !window_still_goes_on(hw, w, &quiet))
			return done;
		if (w->t + r0 <= w->lim) {
			w->t += r0;
			w->row = (uint32_t)(((uint64_t)ra + len - 1) /
					    RDC_DRAM_ROW_BYTES);
		} else if (!span_through(hw, w, (uint64_t)ra,
					 (uint64_t)ra + len, RDC_BUS_READ, r0,
					 RDC_PARTED_RUN)) {
			return done;
		}
		/* its write, from the read's row: whole where it fits */
		if (w->t + cw <= w->lim) {
			w->t += cw;
			w->row = (uint32_t)(((uint64_t)wa + len - 1) /
					    RDC_DRAM_ROW_BYTES);
			rdc_scan_window_hit(hw, w, (uint64_t)wa,
					    (uint64_t)wa + len);
		} else if (!window_still_goes_on(hw, w, &quiet)) {
			w->parted = RDC_PARTED_READ;
			return done;
		} else if (!span_through(hw, w, (uint64_t)wa,
					 (uint64_t)wa + len, kind, cw,
					 RDC_PARTED_WRITE)) {
			return done;
		}
		done++;
		ra += step;
		wa += step;
		if (done == count)
			return done;
		/* the row the write leaves open is its own: c1 from here */
		c0 = c1;
		r0 = r1;
	}
}

uint32_t rdc_port_window_pairs_through(struct rdc_hw *hw,
				       struct rdc_port_window *w,
				       uint32_t raddr, uint32_t waddr,
				       uint32_t len, int64_t rstep,
				       int64_t wstep, uint32_t count,
				       unsigned int kind)
{
	const int64_t step = rstep, size = (int64_t)hw->vram_size;
	int64_t ra = raddr, wa = waddr;
	int64_t last = count ? (int64_t)(count - 1) * step : 0;

	if (!w->open || hw->vram_hook || !len || count < 2 || wstep != step ||
	    step % RDC_DRAM_ROW_BYTES || RDC_MIN(ra, ra + last) < 0 ||
	    RDC_MIN(wa, wa + last) < 0 || RDC_MAX(ra, ra + last) + len > size ||
	    RDC_MAX(wa, wa + last) + len > size)
		return rdc_port_window_pairs(hw, w, raddr, waddr, len, rstep,
					     wstep, count, kind);
	/* a blit's two kinds: COPY's writes, and the other ROPs' */
	if (kind == RDC_BUS_WRITE)
		return pairs_through(hw, w, ra, wa, len, step, count,
				     RDC_BUS_WRITE);
	if (kind == RDC_BUS_RMW)
		return pairs_through(hw, w, ra, wa, len, step, count,
				     RDC_BUS_RMW);
	return pairs_through(hw, w, ra, wa, len, step, count, kind);
}

uint32_t rdc_port_window_runs(struct rdc_hw *hw, struct rdc_port_window *w,
			      const struct rdc_port_run *r, uint32_t n,
			      uint32_t stride, unsigned int kind)
{
	const bool writes = (kind & RDC_BUS_KIND_MASK) != RDC_BUS_READ;
	uint32_t done = 0, k, quiet = 0;

	if (!w->open)
		return 0;
	for (;;) {
		/* inlined with the kind a constant, the cost loses its switch */
		if (kind == RDC_BUS_WRITE)
			k = runs_charge(hw, r + done, n - done, stride,
					RDC_BUS_WRITE, &w->row, &w->t, w->lim);
		else
			k = runs_charge(hw, r + done, n - done, stride, kind,
					&w->row, &w->t, w->lim);
		if (k && hw->scan_hi && writes &&
		    runs_scan_hit(hw, r + done, k, stride))
			w->scan_hit = true;
		if (k && hw->vram_hook && writes)
			runs_watched(hw, r + done, k, stride, w->t);
		done += k;
		/* the span the line start falls in: it does not fit */
		if (done == n || !window_goes_on(hw, w, &quiet) ||
		    r[done].count != 1 || !r[done].len ||
		    (uint64_t)r[done].addr + r[done].len > hw->vram_size ||
		    !span_through(hw, w, r[done].addr,
				  (uint64_t)r[done].addr + r[done].len, kind,
				  RDC_NEVER, RDC_PARTED_RUN))
			return done;
		done++;
	}
}

void rdc_port_window_close(struct rdc_hw *hw, const struct rdc_port_window *w)
{
	hw->bus.open_row = w->row;
	hw->now = w->t;
	/* the bytes are written now, but nothing has looked since */
	if (w->scan_hit)
		rdc_scan_drop_all(hw);
}

void rdc_port_compute_slow(struct rdc_hw *hw, uint32_t cycles)
{
	rdc_port_poll(hw);
	rdc_hw_idle_to(hw, hw->now + cycles);
}
