/* SPDX-License-Identifier: GPL-2.0-only */
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

/* bus.c: charge a VRAM access at hw->now, racing scanout; advances now. */
void rdc_bus_charge(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		    unsigned int kind);
/*
 * Cost of one read of [addr, addr + len) as bursts, from open row *row; *row is
 * left at the last row touched.  Used by the scanout fetch.
 */
uint64_t rdc_bus_read_cost(uint32_t *row, uint64_t addr, uint64_t len);

/* crtc.c */
void rdc_crtc_reset(struct rdc_hw *hw);
void rdc_crtc_catch_up(struct rdc_hw *hw, uint64_t t);

/*
 * Does a scanout event fall at or before t?  If not, rdc_crtc_catch_up(hw,
 * t) does nothing, and callers on hot paths skip the call.
 */
static inline bool rdc_crtc_due(const struct rdc_hw *hw, uint64_t t)
{
	return hw->crtc.running && hw->crtc.next_line_time <= t;
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

void rdc_crtc_start(struct rdc_hw *hw);
void rdc_crtc_stop(struct rdc_hw *hw);
/* Does the next scanout event open a fetch window (an active line)? */
int rdc_crtc_next_fetches(const struct rdc_hw *hw);
uint32_t rdc_crtc_status(struct rdc_hw *hw);

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
