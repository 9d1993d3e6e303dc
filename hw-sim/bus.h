/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The RDC-1 VRAM bus cost model: the one place its formulas live.
 * docs/hardware.md quotes this comment; tests assert it.
 *
 * VRAM is one bank of DRAM behind a bus RDC_BUS_BYTES wide, clocked by the
 * core clock.  All costs are in core cycles.
 *
 *   beat    one bus word: bytes [k*B, (k+1)*B) for B = RDC_BUS_BYTES.
 *   row     one DRAM page: bytes [r*P, (r+1)*P) for P = RDC_DRAM_ROW_BYTES.
 *           The bank keeps one row open: an access to another row pays
 *           RDC_T_ROW_MISS (precharge + activate) before its beat.
 *   burst   at most RDC_BUS_BURST_BEATS consecutive beats, the unit of bus
 *           arbitration.  A span of bytes [a, a+n) is split into bursts at
 *           multiples of RDC_BUS_BURST_BEATS * B.
 *
 * One burst of `beats` beats that crosses into `misses` new rows costs
 *
 *   write:  beats * T_BEAT + misses * T_ROW_MISS
 *           + (rmw_beats ? T_TURN + rmw_beats * T_BEAT : 0)
 *   read:   beats * T_BEAT + misses * T_ROW_MISS
 *
 * where rmw_beats = beats for an RMW access (a ROP that reads the
 * destination), otherwise the number of partially written beats (the
 * first and last beat of a span not aligned to B, or whose edge byte is
 * only partly written, as sub-byte pixels are): those are read, merged and
 * written back.  `misses` counts the bursts's row changes, the first one
 * included when the open row differs.  A column access (rdc_port_column)
 * is `count` one-burst spans.
 *
 * Scanout: at the start of each active line (line < V_DISPLAY) the CRTC
 * reads the line's ceil(H_DISPLAY * bpp / 8) bytes starting at
 * FB_BASE + line * FB_STRIDE as read bursts by the formula above; the bus
 * is the CRTC's for that fetch window [line_start, line_start + cost).  A
 * DP burst that would overlap a fetch window waits until the window ends
 * (the wait counts as stall cycles).  Outside active lines (vertical
 * blanking) the DP has the bus to itself, so drawing in vblank is faster.
 * The fetch leaves its last row open.  A fetch that finds the previous
 * one still on the bus (a line that takes longer to read than to show)
 * starts when it ends; lines whose bytes would leave VRAM are not fetched
 * (they show black) and take no bus time.  With the ARGB8888 cursor on
 * the line, the window goes on with the cursor row's S * 4 bytes at
 * CURSOR_BASE + (line - y) * S * 4, read by the same formula from the row
 * the line's read left open (a row leaving VRAM is not read); the 2 bpp
 * cursor's image, copied at vblank, is not charged.  Raster-list entries
 * (RASTER_BASE) are 8-byte reads by the same formula, in the window of the
 * line on which the list reaches them, ahead of the line's read; a blank
 * line whose list runs opens a window of its entries alone.
 *
 * Command fetch: a FIFO word costs RDC_T_FIFO_WORD; ring words are VRAM
 * reads by the formula.  Each command costs RDC_T_DECODE once it is fetched.
 */
#ifndef RDC_BUS_H
#define RDC_BUS_H

#define RDC_BUS_BYTES	    8u	/* 64-bit bus */
#define RDC_BUS_BURST_BEATS 16u /* 128 bytes a burst */
#define RDC_DRAM_ROW_BYTES  2048u
#define RDC_T_BEAT	    1u
#define RDC_T_ROW_MISS	    6u
#define RDC_T_TURN	    2u /* read-to-write turnaround of an RMW burst */
#define RDC_T_FIFO_WORD	    1u
#define RDC_T_DECODE	    4u

/*
 * The formulas as code, inline for the DP's run loops (bus.c charges
 * every access with them).
 */
#include "hw.h"

#define RDC_BUS_BURST_BYTES ((uint64_t)RDC_BUS_BURST_BEATS * RDC_BUS_BYTES)

/*
 * Cost of bytes [a, a + n) split into `bursts` bursts, from open row *row;
 * leaves *row at the last row touched.  The caller strips the PARTIAL
 * flags from pieces that do not hold the span's first / last byte.
 */
static inline uint64_t rdc_bus_cost(uint32_t *row, uint64_t a, uint64_t n,
				    unsigned int kind, uint64_t bursts)
{
	uint64_t e = a + n - 1;
	uint64_t beats = e / RDC_BUS_BYTES - a / RDC_BUS_BYTES + 1;
	uint64_t ra = a / RDC_DRAM_ROW_BYTES, re = e / RDC_DRAM_ROW_BYTES;
	uint64_t misses = re - ra + (ra != *row);
	uint64_t c = beats * RDC_T_BEAT + misses * RDC_T_ROW_MISS;
	uint64_t head, tail, turns, merged;

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
	/*
	 * One beat is merged once however many edges; both edges in one
	 * burst share its turnaround.  (Selects, not branches: spans of a
	 * line alternate between the cases.)
	 */
	turns = bursts == 1 ? (head | tail) : head + tail;
	merged = beats == 1 ? (head | tail) : head + tail;
	return c + turns * RDC_T_TURN + merged * RDC_T_BEAT;
}

static inline uint64_t rdc_bus_bursts(uint64_t a, uint64_t n)
{
	return (a + n - 1) / RDC_BUS_BURST_BYTES - a / RDC_BUS_BURST_BYTES + 1;
}

/*
 * A column whose elements are one beat each, all at the same offset in
 * their beat: every element costs what the first costs in an open row,
 * plus a row miss for each change of row.  Addresses grow, so the rows
 * changed are all rows from the first to the last when the stride is
 * below a row (none is skipped), else one per element.  The same sum the
 * element-by-element walk gives, in closed form.
 */
static inline uint64_t rdc_bus_column_cost(uint32_t *row, uint64_t a,
					   uint64_t stride, uint32_t count,
					   uint32_t len, unsigned int kind)
{
	uint64_t ra = a / RDC_DRAM_ROW_BYTES;
	uint64_t rz = (a + (count - 1) * stride) / RDC_DRAM_ROW_BYTES;
	uint32_t open = (uint32_t)ra;
	uint64_t one = rdc_bus_cost(&open, a, len, kind, 1);
	uint64_t misses = (ra != *row) +
			  (stride >= RDC_DRAM_ROW_BYTES ? count - 1 : rz - ra);

	*row = (uint32_t)rz;
	return count * one + misses * RDC_T_ROW_MISS;
}

/*
 * A DP write to [lo, hi) charged in a window: scanout on demand drops the
 * lines it reaches that wait unconverted at the window's close (the DP
 * writes the bytes before, but nothing can look in between).
 */
static inline void rdc_scan_window_hit(const struct rdc_hw *hw,
				       struct rdc_port_window *w, uint64_t lo,
				       uint64_t hi)
{
	if (lo < hw->scan_hi && hi > hw->scan_lo)
		w->scan_hit = true;
}

/* A DP write charged in a window, to the VRAM write watcher if any. */
void rdc_vram_watch_call(const struct rdc_hw *hw, uint64_t t, uint32_t addr,
			 uint32_t len, uint32_t count, uint32_t stride);
static inline void rdc_vram_watch(const struct rdc_hw *hw, uint64_t t,
				  uint32_t addr, uint32_t len, uint32_t count,
				  uint32_t stride)
{
	if (hw->vram_hook &&
	    rdc_vram_watched(hw, addr,
			     addr + (uint64_t)(count - 1) * stride + len))
		rdc_vram_watch_call(hw, t, addr, len, count, stride);
}

/*
 * rdc_port_window_charge for a column of one-beat elements a whole
 * number of beats apart (the closed form above) written as RDC_BUS_WRITE,
 * inline; other columns take the call.
 */
static inline bool rdc_port_window_column(const struct rdc_hw *hw,
					  struct rdc_port_window *w,
					  const struct rdc_port_run *r,
					  uint32_t stride)
{
	uint64_t a = r->addr, t;
	uint32_t row = w->row;

	if (a % RDC_BUS_BYTES + r->len > RDC_BUS_BYTES ||
	    stride % RDC_BUS_BYTES)
		return rdc_port_window_charge(hw, w, r, stride, RDC_BUS_WRITE);
	if (!w->open || !r->len || !r->count ||
	    a + (uint64_t)(r->count - 1) * stride + r->len > hw->vram_size)
		return false;
	t = w->t + rdc_bus_column_cost(&row, a, stride, r->count, r->len,
				       RDC_BUS_WRITE);
	if (t > w->lim)
		return false;
	w->t = t;
	w->row = row;
	rdc_scan_window_hit(hw, w, a,
			    a + (uint64_t)(r->count - 1) * stride + r->len);
	rdc_vram_watch(hw, t, r->addr, r->len, r->count, stride);
	return true;
}

/*
 * rdc_port_span_pair's read of [raddr, + len) then write of [waddr,
 * + len) as `kind`, in the window: both charged, or neither (the pair
 * then goes to rdc_port_span_pair).  For blits, a pair a row.
 */
static inline bool rdc_port_window_pair(const struct rdc_hw *hw,
					struct rdc_port_window *w,
					uint32_t raddr, uint32_t waddr,
					uint32_t len, unsigned int kind)
{
	uint32_t row = w->row;
	uint64_t t;

	if (!w->open || !len || (uint64_t)raddr + len > hw->vram_size ||
	    (uint64_t)waddr + len > hw->vram_size)
		return false;
	t = w->t + rdc_bus_cost(&row, raddr, len, RDC_BUS_READ,
				rdc_bus_bursts(raddr, len));
	t += rdc_bus_cost(&row, waddr, len, kind, rdc_bus_bursts(waddr, len));
	if (t > w->lim)
		return false;
	w->t = t;
	w->row = row;
	rdc_scan_window_hit(hw, w, waddr, (uint64_t)waddr + len);
	rdc_vram_watch(hw, t, waddr, len, 1, 0);
	return true;
}

/*
 * rdc_port_window_charge for a span (a run of count 1) written as
 * RDC_BUS_WRITE, inline: the runs of a line are many and short.
 */
static inline bool rdc_port_window_span(const struct rdc_hw *hw,
					struct rdc_port_window *w,
					uint32_t addr, uint32_t len)
{
	uint64_t a = addr, t;
	uint32_t row = w->row;

	if (!w->open || !len || a + len > hw->vram_size)
		return false;
	t = w->t +
	    rdc_bus_cost(&row, a, len, RDC_BUS_WRITE, rdc_bus_bursts(a, len));
	if (t > w->lim)
		return false;
	w->t = t;
	w->row = row;
	rdc_scan_window_hit(hw, w, addr, (uint64_t)addr + len);
	rdc_vram_watch(hw, t, addr, len, 1, 0);
	return true;
}

/*
 * The cost of the span `stride` bytes (a whole number of DRAM rows) on
 * from [a, a + len), which cost c0 from open row row0 and left row1
 * open: the same beats, bursts and edges (every offset is kept), and a
 * row miss unless it starts in the row the one before ended in.
 */
static inline uint64_t rdc_bus_cost_next_row(uint64_t c0, uint64_t a,
					     uint32_t stride, uint32_t row0,
					     uint32_t row1)
{
	uint64_t ra = a / RDC_DRAM_ROW_BYTES;

	return c0 - (ra != row0) * RDC_T_ROW_MISS +
	       (ra + stride / RDC_DRAM_ROW_BYTES != row1) * RDC_T_ROW_MISS;
}

/*
 * rdc_port_window_rows_through, inline when all `count` rows (a whole
 * number of DRAM rows apart, no VRAM watcher) fit in VRAM and before the
 * limit: the closed form, each row after the first costing what the
 * second does.  A glyph's rows, one command each, mostly fit.
 */
static inline uint32_t rdc_port_window_rows_all(struct rdc_hw *hw,
						struct rdc_port_window *w,
						uint32_t addr, uint32_t len,
						uint32_t stride, uint32_t count)
{
	uint64_t a = addr, end = a + (uint64_t)(count - 1) * stride + len;
	uint32_t r0 = w->row;
	uint64_t c0, c1, t;

	if (!w->open || stride % RDC_DRAM_ROW_BYTES || count < 2 || !len ||
	    hw->vram_hook || end > hw->vram_size)
		return rdc_port_window_rows_through(hw, w, addr, len, stride,
						    count);
	c0 = rdc_bus_cost(&r0, a, len, RDC_BUS_WRITE, rdc_bus_bursts(a, len));
	c1 = rdc_bus_cost_next_row(c0, a, stride, w->row, r0);
	t = w->t + c0 + (uint64_t)(count - 1) * c1;
	if (t > w->lim)
		return rdc_port_window_rows_costed(hw, w, addr, len, stride,
						   count, c0, c1);
	w->t = t;
	w->row = (uint32_t)((end - 1) / RDC_DRAM_ROW_BYTES);
	rdc_scan_window_hit(hw, w, a, end);
	return count;
}

#endif /* RDC_BUS_H */
