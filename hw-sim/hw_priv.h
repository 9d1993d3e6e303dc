/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Internal interfaces between the RDC-1 chip's blocks (hw.c, bus.c,
 * crtc.c, clut.c, cmdq.c).  Not for the host or the display processor:
 * they use hw.h.
 */
#ifndef RDC_HW_PRIV_H
#define RDC_HW_PRIV_H

#include "hw.h"
#include "bus.h"

static inline void rdc_trace(struct rdc_hw *hw, unsigned int event, uint32_t a,
			     uint32_t b)
{
	if (hw->trace_fn)
		hw->trace_fn(hw->trace_ctx, hw->now, event, a, b);
}

/*
 * The VRAM write watcher (rdc_hw_set_vram_hook), set: every call of it is
 * made here, as the trace's are (the firmware never sets either).
 */
static inline void rdc_vram_hook_call(const struct rdc_hw *hw, uint64_t t,
				      uint32_t addr, uint32_t len,
				      uint32_t count, uint32_t stride,
				      unsigned int who)
{
	hw->vram_hook(hw->vram_hook_ctx, t, addr, len, count, stride, who);
}

/* A trace point at its own time (a scanout event processed in a catch-up). */
static inline void rdc_trace_at(struct rdc_hw *hw, uint64_t time,
				unsigned int event, uint32_t a, uint32_t b)
{
	if (hw->trace_fn)
		hw->trace_fn(hw->trace_ctx, time, event, a, b);
}

/* Pin levels from the state, without catching up (hw.c's rdc_hw_pins does). */
static inline uint32_t rdc_pins_level(const struct rdc_hw *hw)
{
	uint32_t p = hw->pins_in;

	if (hw->crtc.in_vblank)
		p |= RDC_PIN_TE;
	if (hw->irq_status & hw->irq_enable)
		p |= RDC_PIN_IRQ;
	return p;
}

/*
 * After anything that may move a pin (vblank state, IRQ status or enable,
 * the inputs): one RDC_TRACE_PINS at `time` if the levels differ from the
 * last ones reported.
 */
static inline void rdc_pins_update(struct rdc_hw *hw, uint64_t time)
{
	uint32_t p = rdc_pins_level(hw), changed = p ^ hw->pins_out;

	if (!changed)
		return;
	hw->pins_out = p;
	rdc_trace_at(hw, time, RDC_TRACE_PINS, p, changed);
}

/* Raise IRQ status bits; the caller updates the pins (rdc_port_irq does). */
static inline void rdc_irq_raise(struct rdc_hw *hw, uint32_t bits)
{
	hw->irq_status |= bits & RDC_IRQ_ALL;
}

/* The DP's busy level for RDC_TRACE_DP, reported at hw->now on a change. */
static inline void rdc_dp_active(struct rdc_hw *hw, int active)
{
	if (hw->dp_active == active)
		return;
	hw->dp_active = active;
	rdc_trace(hw, RDC_TRACE_DP, (uint32_t)active, 0);
}

/* The command FIFO's level changed: RDC_TRACE_FIFO at hw->now. */
static inline void rdc_fifo_traced(struct rdc_hw *hw)
{
	rdc_trace(hw, RDC_TRACE_FIFO, hw->fifo_count, 0);
}

/* bus.c: charge a VRAM access at hw->now, racing scanout; advances now. */
void rdc_bus_charge(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		    unsigned int kind);
/*
 * Cost of one read of [addr, addr + len) as bursts, from open row *row; *row is
 * left at the last row touched.  Used by the scanout fetch.
 */
static inline uint64_t rdc_bus_read_cost(uint32_t *row, uint64_t addr,
					 uint64_t len)
{
	if (!len)
		return 0;
	return rdc_bus_cost(row, addr, len, RDC_BUS_READ,
			    rdc_bus_bursts(addr, len));
}

/* crtc.c */
void rdc_crtc_reset(struct rdc_hw *hw);
void rdc_crtc_catch_up(struct rdc_hw *hw, uint64_t t);

/*
 * Is the next scanout event a line's start that does nothing but fetch
 * (an active line) or nothing at all (a blank line after the vblank's)?
 * Not line 0 (the frame's start), not the vblank's, and no raster list,
 * line compare, light pen or trace (a stopped CRTC's times are both
 * RDC_NEVER: not before each other).  Then rdc_crtc_quiet_line takes it,
 * as rdc_crtc_catch_up to its time would, and says whether it opened a
 * fetch window.
 */
static inline bool rdc_crtc_next_quiet(const struct rdc_hw *hw)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint32_t n = c->next_line;

	return !c->rl_mid && n && n != c->cur.v_display && n < c->cur.v_total &&
	       c->rl_wait > n && n != c->line_compare && n != c->lpen_line &&
	       c->lpen_time > c->next_line_time && !hw->trace_fn;
}

/*
 * The line before which every line start from the next one on is quiet,
 * as long as only rdc_crtc_quiet_line takes them (next_line itself if
 * the next is not).  Of what rdc_crtc_next_quiet tests, a quiet line
 * start changes nothing but next_line, which steps by one towards the
 * first line that ends the run: the vblank's or the frame's end, the
 * raster list's WAIT, the line compare or the light pen's.  A strobe to
 * come ends it at the next line, where it is asked again.
 */
static inline uint32_t rdc_crtc_quiet_until(const struct rdc_hw *hw)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint32_t n = c->next_line, h;

	if (!rdc_crtc_next_quiet(hw))
		return n;
	if (c->lpen_time != RDC_NEVER)
		return n + 1;
	h = n < c->cur.v_display ? c->cur.v_display : c->cur.v_total;
	h = RDC_MIN(h, c->rl_wait);
	if (c->line_compare > n)
		h = RDC_MIN(h, c->line_compare);
	if (c->lpen_line > n)
		h = RDC_MIN(h, c->lpen_line);
	return h;
}

bool rdc_crtc_quiet_line(struct rdc_hw *hw);

/*
 * The host's poll hook, every RDC_POLL_EVERY calls (hw.h): at the entry of
 * a DP port access, where the DP holds no pointer into VRAM.
 */
static inline void rdc_port_poll(struct rdc_hw *hw)
{
	if (hw->poll_fn && ++hw->poll_count >= RDC_POLL_EVERY) {
		hw->poll_count = 0;
		hw->poll_fn(hw->poll_ctx);
	}
}

/* rdc_port_idle_until, inline for the chip's own hot paths. */
static inline void rdc_hw_idle_to(struct rdc_hw *hw, uint64_t t)
{
	if (t <= hw->now)
		return;
	if (rdc_crtc_due(hw, t))
		rdc_crtc_catch_up(hw, t);
	hw->now = t;
}

/*
 * Scanout on demand's write barrier (hw.h's struct rdc_hw says what
 * waits): rdc_scan_check before bytes [lo, hi) of VRAM change (or after,
 * before anything can look: dropping needs no old bytes), one test while
 * nothing waits; rdc_scan_changed when a register, CLUT entry or pin that
 * converting a line reads changes.
 */
void rdc_scan_write(struct rdc_hw *hw, uint64_t lo, uint64_t hi);
void rdc_scan_drop_all(struct rdc_hw *hw);
/* hw->lazy again after a consumer, listener or setting changed */
void rdc_scan_update(struct rdc_hw *hw);
/* convert what waits of the last complete frame (a look at it) */
void rdc_scan_front(struct rdc_hw *hw);

static inline bool rdc_scan_hits(const struct rdc_hw *hw, uint64_t lo,
				 uint64_t hi)
{
	return lo < hw->scan_hi && hi > hw->scan_lo;
}

static inline void rdc_scan_check(struct rdc_hw *hw, uint64_t lo, uint64_t hi)
{
	if (rdc_scan_hits(hw, lo, hi))
		rdc_scan_write(hw, lo, hi);
}

static inline void rdc_scan_changed(struct rdc_hw *hw)
{
	if (hw->pend_lo[0] != hw->pend_hi[0] ||
	    hw->pend_lo[1] != hw->pend_hi[1])
		rdc_scan_drop_all(hw);
}

void rdc_crtc_start(struct rdc_hw *hw);
void rdc_crtc_stop(struct rdc_hw *hw);
/* Does the next scanout event open a fetch window (an active line)? */
int rdc_crtc_next_fetches(const struct rdc_hw *hw);
uint32_t rdc_crtc_status(struct rdc_hw *hw);
uint32_t rdc_crtc_raster_status(struct rdc_hw *hw);
/*
 * raster.c: the beam is at column x of line n (0: the line's start) at
 * `when`, and the list waits for it: run it.
 */
void rdc_raster_run(struct rdc_hw *hw, uint32_t n, uint32_t x, uint64_t when);
/* crtc.c: the core cycle the beam reaches column x of the current line */
uint64_t rdc_crtc_column_time(const struct rdc_hw *hw, uint32_t x);
/* crtc.c: a CLUT entry changed at column x of line n: x on converted again */
void rdc_crtc_raster_split(struct rdc_hw *hw, uint32_t n, uint32_t x);
/* crtc.c: convert the lines of buffers `bufs` (bit 0, 1) that wait. */
void rdc_scan_convert(struct rdc_hw *hw, unsigned int bufs);
/* A line the raster list waits for that never comes (rl_wait). */
#define RDC_NEVER_LINE 0xffffffffu
/* A host write of LPEN_POS or LPEN_CTRL. */
void rdc_crtc_lpen_write(struct rdc_hw *hw, uint32_t reg, uint32_t val);

/* Entries a frame's raster list may fetch: RASTER_CTRL.LEN, 0 the most. */
static inline uint32_t rdc_crtc_raster_len(const struct rdc_hw *hw)
{
	uint32_t len = FIELD_GET(RDC_RASTER_CTRL_LEN, hw->crtc.cur_raster_ctrl);

	return !len || len > RDC_RASTER_MAX_ENTRIES ? RDC_RASTER_MAX_ENTRIES :
						      len;
}

/*
 * Would the raster list fetch its entry at `addr`, the frame's `count`th?
 * (Not when the entry leaves VRAM or the frame's entries are used up:
 * that stops the list with no bus time.)
 */
static inline bool rdc_crtc_raster_fetches(const struct rdc_hw *hw,
					   uint64_t addr, uint32_t count)
{
	return count < rdc_crtc_raster_len(hw) &&
	       addr + RDC_RASTER_ENTRY_BYTES <= hw->vram_size;
}

/* clut.c */
void rdc_clut_reset(struct rdc_hw *hw);
void rdc_clut_latch(struct rdc_hw *hw);

/* cmdq.c */
void rdc_cmdq_reset(struct rdc_hw *hw);
void rdc_fifo_push(struct rdc_hw *hw, uint32_t word);
uint32_t rdc_rdata_pop(struct rdc_hw *hw);
void rdc_ring_validate(struct rdc_hw *hw, uint32_t reg);
uint32_t rdc_ring_words(const struct rdc_hw *hw);

#endif /* RDC_HW_PRIV_H */
