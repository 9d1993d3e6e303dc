// SPDX-License-Identifier: GPL-2.0-only
/*
 * The VRAM bus: the cost model of bus.h and the DP's VRAM port.
 *
 * Costs are additive over bursts, so a span that no scanout event can
 * interrupt is charged in closed form (a handful of shifts); only a span
 * that a fetch window or another scanout event falls into is walked burst
 * by burst.  That keeps a full-screen fill within a few microseconds of
 * host time beyond the memset the DP does itself.
 */
#include "hw_priv.h"

#define BURST_BYTES ((uint64_t)RDC_BUS_BURST_BEATS * RDC_BUS_BYTES)

/*
 * Cost of bytes [a, a + n) split into `bursts` bursts, from open row *row;
 * leaves *row at the last row touched.  The caller strips the PARTIAL
 * flags from pieces that do not hold the span's first / last byte.
 */
static inline uint64_t bus_cost(uint32_t *row, uint64_t a, uint64_t n,
				unsigned int kind, uint64_t bursts)
{
	uint64_t e = a + n - 1;
	uint64_t beats = e / RDC_BUS_BYTES - a / RDC_BUS_BYTES + 1;
	uint64_t ra = a / RDC_DRAM_ROW_BYTES, re = e / RDC_DRAM_ROW_BYTES;
	uint64_t misses = re - ra + (ra != *row);
	uint64_t c = beats * RDC_T_BEAT + misses * RDC_T_ROW_MISS;
	uint64_t head, tail;

	*row = (uint32_t)re;
	switch (kind & RDC_BUS_KIND_MASK) {
	case RDC_BUS_READ:
		return c;
	case RDC_BUS_WRITE:
		break;
	default: /* RMW, and the undefined kind 3 charged as the dearer RMW */
		return c + bursts * RDC_T_TURN + beats * RDC_T_BEAT;
	}
	head = (a % RDC_BUS_BYTES) || (kind & RDC_BUS_HEAD_PARTIAL);
	tail = ((e + 1) % RDC_BUS_BYTES) || (kind & RDC_BUS_TAIL_PARTIAL);
	if (beats == 1) /* one beat, merged once however many edges */
		return c + ((head || tail) ? RDC_T_TURN + RDC_T_BEAT : 0);
	if (bursts == 1) /* both edges in one burst share its turnaround */
		return c + ((head || tail) ? RDC_T_TURN : 0) +
		       (head + tail) * RDC_T_BEAT;
	return c + (head + tail) * (RDC_T_TURN + RDC_T_BEAT);
}

static inline uint64_t bursts_of(uint64_t a, uint64_t n)
{
	return (a + n - 1) / BURST_BYTES - a / BURST_BYTES + 1;
}

uint64_t rdc_bus_read_cost(uint32_t *row, uint64_t addr, uint64_t len)
{
	if (!len)
		return 0;
	return bus_cost(row, addr, len, RDC_BUS_READ, bursts_of(addr, len));
}

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
		if (c->running && c->next_line_time <= t) {
			rdc_crtc_catch_up(hw, t);
			continue;
		}
		cost = bus_cost(&row, a, n, kind, 1);
		ev = c->running ? c->next_line_time : RDC_NEVER;
		if (ev >= t + cost) {
			hw->bus.open_row = row;
			*tp = t + cost;
			return;
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
	return t >= c->fetch_end &&
	       (!c->running || c->next_line_time >= t + cost);
}

void rdc_bus_charge(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		    unsigned int kind)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t a = addr, end = (uint64_t)addr + len;
	uint64_t t = hw->now;

	if (c->running && c->next_line_time <= t)
		rdc_crtc_catch_up(hw, t);
	while (a < end) {
		uint64_t be;
		unsigned int k = kind;

		if (a != addr)
			k &= ~RDC_BUS_HEAD_PARTIAL;
		if (t >= c->fetch_end &&
		    (!c->running || c->next_line_time > t)) {
			uint32_t row = hw->bus.open_row;
			uint64_t cost = bus_cost(&row, a, end - a, k,
						 bursts_of(a, end - a));

			if (!c->running || c->next_line_time >= t + cost) {
				hw->bus.open_row = row;
				t += cost;
				break;
			}
		}
		be = RDC_MIN(end, (a / BURST_BYTES + 1) * BURST_BYTES);
		if (be != end)
			k &= ~RDC_BUS_TAIL_PARTIAL;
		bus_burst(hw, &t, a, be - a, k);
		a = be;
	}
	hw->now = t;
}

uint8_t *rdc_port_span(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		       unsigned int kind)
{
	if (!len || (uint64_t)addr + len > hw->vram_size)
		return NULL;
	rdc_bus_charge(hw, addr, len, kind);
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

uint8_t *rdc_port_column(struct rdc_hw *hw, uint32_t addr, uint32_t stride,
			 uint32_t count, uint32_t len, unsigned int kind)
{
	uint64_t a = addr, t;
	uint32_t i;

	if (!count || !len ||
	    a + (uint64_t)(count - 1) * stride + len > hw->vram_size)
		return NULL;
	t = hw->now;
	rdc_crtc_catch_up(hw, t);
	for (i = 0; i < count; i++, a += stride) {
		struct rdc_crtc *c = &hw->crtc;
		uint32_t row = hw->bus.open_row;
		uint64_t cost;

		/* bus_burst's first step, without the call */
		if (t >= c->fetch_end &&
		    (!c->running || c->next_line_time > t)) {
			cost = bus_cost(&row, a, len, kind, 1);
			if (bus_quiet(c, t, cost)) {
				hw->bus.open_row = row;
				t += cost;
				continue;
			}
		}
		bus_burst(hw, &t, a, len, kind);
	}
	hw->now = t;
	return hw->vram + addr;
}

/*
 * A column whose elements are one beat each, all at the same offset in
 * their beat: every element costs what the first costs in an open row,
 * plus a row miss for each change of row.  Addresses grow, so the rows
 * changed are all rows from the first to the last when the stride is
 * below a row (none is skipped), else one per element.  The same sum the
 * element-by-element walk gives, in closed form.
 */
static uint64_t column_cost(uint32_t *row, uint64_t a, uint64_t stride,
			    uint32_t count, uint32_t len, unsigned int kind)
{
	uint64_t ra = a / RDC_DRAM_ROW_BYTES;
	uint64_t rz = (a + (count - 1) * stride) / RDC_DRAM_ROW_BYTES;
	uint32_t open = (uint32_t)ra;
	uint64_t one = bus_cost(&open, a, len, kind, 1);
	uint64_t misses = (ra != *row) +
			  (stride >= RDC_DRAM_ROW_BYTES ? count - 1 : rz - ra);

	*row = (uint32_t)rz;
	return count * one + misses * RDC_T_ROW_MISS;
}

/*
 * Runs r[0, n) of rdc_port_runs from *tp, while each ends by `lim` (the
 * next scanout event; the caller has checked that no fetch window is
 * open): costs in closed form, *row and *tp advanced, runs charged
 * returned.  An event cannot fall inside a run that ends by lim, and none
 * is processed meanwhile, so lim holds for the whole batch.  Inlined with
 * kind a constant, the cost formula loses its switch.
 */
static inline uint32_t runs_charge(const struct rdc_hw *hw,
				   const struct rdc_port_run *r, uint32_t n,
				   uint64_t stride, unsigned int kind,
				   uint32_t *row, uint64_t *tp, uint64_t lim)
{
	uint64_t t = *tp;
	uint32_t rw = *row, i, k;

	for (i = 0; i < n; i++, r++) {
		uint64_t a = r->addr, cost = 0;
		uint32_t nrw = rw;

		if (r->count == 1) {
			if (!r->len || a + r->len > hw->vram_size)
				break;
			cost = bus_cost(&nrw, a, r->len, kind,
					bursts_of(a, r->len));
		} else if (!r->len || !r->count ||
			   a + (r->count - 1) * stride + r->len >
				   hw->vram_size) {
			break;
		} else if (a % RDC_BUS_BYTES + r->len <= RDC_BUS_BYTES &&
			   stride % RDC_BUS_BYTES == 0) {
			cost = column_cost(&nrw, a, stride, r->count, r->len,
					   kind);
		} else {
			for (k = 0; k < r->count; k++, a += stride)
				cost += bus_cost(&nrw, a, r->len, kind, 1);
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

uint8_t *rdc_port_runs(struct rdc_hw *hw, const struct rdc_port_run *r,
		       uint32_t n, uint32_t stride, unsigned int kind,
		       uint32_t *done)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t t = hw->now, lim;
	uint32_t row = hw->bus.open_row;

	if (c->running && c->next_line_time <= t)
		rdc_crtc_catch_up(hw, t);
	lim = c->running ? c->next_line_time : RDC_NEVER;
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
	return hw->vram;
}

void rdc_port_compute(struct rdc_hw *hw, uint32_t cycles)
{
	rdc_port_idle_until(hw, hw->now + cycles);
}
