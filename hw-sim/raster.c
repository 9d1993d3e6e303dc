// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The CRTC's raster list (RASTER_BASE, RASTER_CTRL, RASTER_STATUS;
 * docs/hardware.md): register and CLUT writes at beam positions, fetched
 * from VRAM entry by entry in the line's fetch window and run by the CRTC
 * every frame (crtc.c calls rdc_raster_run at the line starts the list
 * waits for).
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

static void raster_set(struct rdc_hw *hw, uint32_t *p, uint32_t val)
{
	if (*p == val)
		return;
	raster_settle(hw);
	*p = val;
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

/*
 * Line n starts at `when`, the list waiting for it: fetch and run entries
 * until a WAIT for a later line, the END, or a bad entry.  Each entry is
 * an 8-byte read in the fetch window, ahead of the line's own read.
 */
void rdc_raster_run(struct rdc_hw *hw, uint32_t n, uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;

	while (c->rl_wait <= n) {
		uint64_t a = c->rl_addr, start;
		uint32_t w0, w1, y, x;

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
			y = FIELD_GET(RDC_RL_Y, w1);
			x = FIELD_GET(RDC_RL_X, w1);
			if (y >= c->cur.v_total)
				c->rl_wait = RDC_NEVER_LINE;
			else if (y > n || (y == n && x))
				c->rl_wait = x ? y + 1 : y;
			break;
		case RDC_RL_REG:
			if (!raster_reg(hw, FIELD_GET(RDC_RL_ARG, w0), w1)) {
				raster_fail(hw, a);
				return;
			}
			break;
		case RDC_RL_CLUT:
			raster_set(hw,
				   &hw->clut[FIELD_GET(RDC_RL_ARG, w0) %
					     RDC_CLUT_ENTRIES],
				   w1 & RGB_MASK);
			break;
		default:
			raster_fail(hw, a);
			return;
		}
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
