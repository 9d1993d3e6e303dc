// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Host waits on a register condition (see hw.h).  One implementation for
 * every host of the core, so that a script waiting through librdc's sim:
 * backend and the same script waiting through the kernel driver end their
 * waits at the same cycle and give the same frames and cycle counts.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"

/*
 * The register a condition tests.  FIFO_FREE, which the host's FIFO
 * feeding waits on, is read as the register file would (a catch-up of
 * the CRTC, then the value) without its dispatch; a traced chip reads it
 * through the register file, so that the trace still shows the read.
 */
static rdc_always_inline uint32_t cond_read(struct rdc_hw *hw, uint32_t reg)
{
	if (reg != RDC_REG_FIFO_FREE || hw->trace_fn)
		return rdc_hw_read(hw, reg);
	if (rdc_crtc_due(hw, hw->now))
		rdc_crtc_catch_up(hw, hw->now);
	return RDC_FIFO_DEPTH - hw->fifo_count;
}

/*
 * Inline in the wait's loop, which checks its terms between every two
 * slices of running: a FIFO feed's wait checks as often as the DP runs
 * a command.
 */
static rdc_always_inline bool cond_holds(struct rdc_hw *hw,
					 const struct rdc_wait_cond *c)
{
	uint32_t v;

	if (c->test == RDC_WAIT_TEST_NONE)
		return false;
	v = cond_read(hw, c->reg) & c->mask;
	switch (c->test) {
	case RDC_WAIT_TEST_GE:
		return v >= c->value;
	case RDC_WAIT_TEST_WRAP_GE:
		return (int32_t)(v - c->value) >= 0;
	case RDC_WAIT_TEST_EQ:
		return v == c->value;
	default:
		return false;
	}
}

bool rdc_hw_cond_holds(struct rdc_hw *hw, const struct rdc_wait_cond *c)
{
	return cond_holds(hw, c);
}

/*
 * STATUS's DP_HALTED bit, read as the register file would (a catch-up of
 * the CRTC, then the bit) without working out the beam position for the
 * rest of the register; a traced chip reads the register, so that the
 * trace still shows the read.
 */
static rdc_always_inline bool dp_halted(struct rdc_hw *hw)
{
	if (hw->trace_fn)
		return rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED;
	if (rdc_crtc_due(hw, hw->now))
		rdc_crtc_catch_up(hw, hw->now);
	return hw->dp_status & RDC_STATUS_DP_HALTED;
}

static rdc_always_inline enum rdc_hw_wait_result
wait_check(struct rdc_hw *hw, const struct rdc_hw_wait *w)
{
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++)
		if (cond_holds(hw, &w->term[i]))
			return RDC_HW_WAIT_DONE;
	/*
	 * STATUS reflects the DP as of its last run: after a RESUME it
	 * reads halted until the chip has run, so judge only then.
	 */
	if (w->needs_dp && hw->now != w->start && dp_halted(hw))
		return RDC_HW_WAIT_HALTED;
	if (hw->now - w->start >= w->budget)
		return RDC_HW_WAIT_TIMEOUT;
	return RDC_HW_WAIT_MORE;
}

enum rdc_hw_wait_result rdc_hw_wait_check(struct rdc_hw *hw,
					  const struct rdc_hw_wait *w)
{
	return wait_check(hw, w);
}

void rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w)
{
	w->start = hw->now;
	w->slice = RDC_WAIT_SLICE_FIRST;
}

enum rdc_hw_wait_result rdc_hw_wait_run(struct rdc_hw *hw,
					struct rdc_hw_wait *w, uint64_t work)
{
	uint64_t from = hw->now;

	for (;;) {
		uint64_t before = hw->now;
		enum rdc_hw_wait_result res = wait_check(hw, w);

		if (res != RDC_HW_WAIT_MORE)
			return res;
		/*
		 * A wait on the DP stops where it runs out of work, so the
		 * host resumes at that cycle; only a DP already idle (the
		 * condition needs something else: vblank, the budget) lets
		 * time run a whole slice.
		 */
		if (!w->needs_dp ||
		    (rdc_hw_run_until_idle(hw, hw->now + w->slice) &&
		     hw->now == before))
			rdc_hw_run_until(hw, hw->now + w->slice);
		if (w->slice < RDC_WAIT_SLICE_MAX)
			w->slice *= 2;
		/* between two checks, so a resumed wait goes on unchanged */
		if (work != RDC_NEVER && hw->now - from >= work)
			return RDC_HW_WAIT_MORE;
	}
}

#define RDC_PACE_NS_PER_S 1000000000ull

uint64_t rdc_pace_target(struct rdc_pace *p, uint64_t wall_ns, uint64_t now,
			 uint32_t hz, uint64_t lag)
{
	uint64_t target, d;

	if (!p->wall0_ns || wall_ns < p->wall0_ns) {
		p->wall0_ns = wall_ns;
		p->sim0 = now;
	}
	/* in two parts, so that no product passes 64 bits however long */
	d = wall_ns - p->wall0_ns;
	target = p->sim0 + d / RDC_PACE_NS_PER_S * hz +
		 d % RDC_PACE_NS_PER_S * hz / RDC_PACE_NS_PER_S;
	if (target > now + lag || now > target + lag) {
		p->wall0_ns = wall_ns;
		p->sim0 = now;
		target = now;
	}
	return target;
}
