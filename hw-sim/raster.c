// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The CRTC's raster list (RASTER_BASE, RASTER_CTRL, RASTER_STATUS;
 * docs/hardware.md): register and CLUT writes at beam positions, fetched
 * from VRAM entry by entry in the line's fetch window and run by the CRTC
 * every frame (crtc.c calls rdc_raster_run at the line starts and
 * columns the list waits for).
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"
#include "bus.h"

#define RGB_MASK 0x00ffffffu

/*
 * A raster-list write is about to change what converting a line reads:
 * lines that wait for a look are converted first, as they were fetched,
 * so that the frame stays whole (dropping them would lose it every frame).
 */
static void raster_settle(struct rdc_hw *hw)
{
	hw->crtc.rl_touched = 1;
	if (hw->pend_lo[0] != hw->pend_hi[0] ||
	    hw->pend_lo[1] != hw->pend_hi[1])
		rdc_scan_convert(hw, 3);
}

/* Write *p; false if it held val already (nothing changes). */
static bool raster_set(struct rdc_hw *hw, uint32_t *p, uint32_t val)
{
	if (*p == val)
		return false;
	raster_settle(hw);
	*p = val;
	return true;
}

/* A bad list: stop it for good (EN cleared) and raise the error. */
static void raster_fail(struct rdc_hw *hw, uint64_t addr)
{
	struct rdc_crtc *c = &hw->crtc;

	c->rl_wait = RDC_NEVER_LINE;
	c->rl_error = 1;
	c->raster_ctrl &= ~RDC_RASTER_CTRL_EN;
	c->cur_raster_ctrl &= ~RDC_RASTER_CTRL_EN;
	rdc_port_error(hw, RDC_ERR_RASTER, (uint32_t)addr);
}

/* One REG entry: the whitelist; false for a register it may not touch. */
static bool raster_reg(struct rdc_hw *hw, uint32_t reg, uint32_t val)
{
	struct rdc_crtc *c = &hw->crtc;

	switch (reg) {
	case RDC_REG_FB_BASE:
		raster_set(hw, &c->cur_base, val);
		return true;
	case RDC_REG_FB_STRIDE:
		raster_set(hw, &c->cur_stride, val);
		return true;
	case RDC_REG_CURSOR_POS:
		raster_set(hw, &c->cursor_pos, val);
		return true;
	case RDC_REG_CURSOR_FG:
		raster_set(hw, &c->cursor_fg, val & RGB_MASK);
		return true;
	case RDC_REG_CURSOR_BG:
		raster_set(hw, &c->cursor_bg, val & RGB_MASK);
		return true;
	default:
		return false;
	}
}

/* Has the beam, at column x of line n, reached the WAIT the list holds at? */
static inline bool raster_met(const struct rdc_crtc *c, uint32_t n, uint32_t x)
{
	return c->rl_wait < n || (c->rl_wait == n && c->rl_wait_x <= x);
}

/*
 * A WAIT for line y, column x: a column past the line's end is the next
 * line's start, and a line the frame does not have never comes.
 */
static void raster_wait(struct rdc_crtc *c, uint32_t y, uint32_t x)
{
	if (x >= c->cur.h_total) {
		y++;
		x = 0;
	}
	c->rl_wait = y >= c->cur.v_total ? RDC_NEVER_LINE : y;
	c->rl_wait_x = x;
}

/*
 * The beam is at column x of line n at `when` (x 0: the line starts, its
 * fetch to come), the list waiting for it: fetch and run entries until a
 * WAIT for a later position, the END, or a bad entry.  Each entry is an
 * 8-byte read in a fetch window at `when`: ahead of the line's own read
 * at its start, a window of its own at a column.  A WAIT for a later
 * column of this line makes that column the next scanout event, when it
 * comes before the next line's start; a CLUT write there changes the
 * line's pixels from that column on.
 */
void rdc_raster_run(struct rdc_hw *hw, uint32_t n, uint32_t x, uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;

	while (raster_met(c, n, x)) {
		uint64_t a = c->rl_addr, start;
		uint32_t w0, w1, k;

		if (!rdc_crtc_raster_fetches(hw, a, c->rl_count)) {
			raster_fail(hw, a);
			return;
		}
		start = RDC_MAX(when, c->fetch_end);
		c->fetch_end =
			start + rdc_bus_read_cost(&hw->bus.open_row, a,
						  RDC_RASTER_ENTRY_BYTES);
		w0 = rdc_ld32(hw->vram + a);
		w1 = rdc_ld32(hw->vram + a + 4);
		c->rl_addr = a + RDC_RASTER_ENTRY_BYTES;
		c->rl_count++;
		switch (FIELD_GET(RDC_RL_OP, w0)) {
		case RDC_RL_END:
			c->rl_wait = RDC_NEVER_LINE;
			return;
		case RDC_RL_WAIT:
			raster_wait(c, FIELD_GET(RDC_RL_Y, w1),
				    FIELD_GET(RDC_RL_X, w1));
			break;
		case RDC_RL_REG:
			if (!raster_reg(hw, FIELD_GET(RDC_RL_ARG, w0), w1)) {
				raster_fail(hw, a);
				return;
			}
			break;
		case RDC_RL_CLUT:
			k = FIELD_GET(RDC_RL_ARG, w0) % RDC_CLUT_ENTRIES;
			if (raster_set(hw, &hw->clut[k], w1 & RGB_MASK) && x)
				rdc_crtc_raster_split(hw, n, x);
			break;
		default:
			raster_fail(hw, a);
			return;
		}
	}
	if (c->rl_wait == n) {
		uint64_t t = rdc_crtc_column_time(hw, c->rl_wait_x);
		uint64_t next = c->rl_mid ? c->rl_next_line : c->next_line_time;

		/* a column the next line's start reaches first: met there */
		if (t >= next)
			return;
		c->rl_next_line = next;
		c->next_line_time = t;
		c->rl_mid = 1;
	}
}

uint32_t rdc_crtc_raster_status(struct rdc_hw *hw)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint32_t s = FIELD_PREP(RDC_RASTER_STATUS_COUNT,
				RDC_MIN(c->rl_count, 0xffffu));

	if (c->running && c->rl_wait != RDC_NEVER_LINE)
		s |= RDC_RASTER_STATUS_RUN;
	if (c->rl_error)
		s |= RDC_RASTER_STATUS_ERROR;
	return s;
}
