// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The RDC-1 chip: creation and reset, the register file, interrupts, pins,
 * host VRAM access and the run loop.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"

#define HZ_PER_KHZ 1000u
#define RGB_MASK   0x00ffffffu
#define CONTROL_RW_BITS \
	(RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN | RDC_CONTROL_RING_EN | \
	 RDC_CONTROL_HALT_ON_ERR | RDC_CONTROL_CLUT_LATCH | \
	 RDC_CONTROL_CURSOR_EN | RDC_CONTROL_GAMMA_EN)
#define PINS_IN (RDC_PIN_RESET_N | RDC_PIN_BL_EN)

void rdc_hw_init(struct rdc_hw *hw, const struct rdc_hw_config *cfg,
		 uint8_t *vram, uint32_t *frame0, uint32_t *frame1,
		 uint32_t frame_cap)
{
	rdc_memset(hw, 0, sizeof(*hw));
	hw->vram = vram;
	hw->vram_size = vram ? cfg->vram_size : 0;
	hw->core_hz = cfg->core_hz ? cfg->core_hz : RDC_DEFAULT_CORE_HZ;
	hw->frame[0] = frame0;
	hw->frame[1] = frame1;
	hw->frame_cap = frame0 && frame1 ? frame_cap : 0;
	if (hw->frame_cap) {
		rdc_memset(frame0, 0, (size_t)frame_cap * sizeof(*frame0));
		rdc_memset(frame1, 0, (size_t)frame_cap * sizeof(*frame1));
	}
	/* out of power-on reset, backlight on */
	hw->pins_in = PINS_IN;
	rdc_hw_reset(hw);
}

void rdc_hw_reset(struct rdc_hw *hw)
{
	rdc_trace(hw, RDC_TRACE_RESET, 0, 0);
	hw->vram_watch_lo = 0;
	hw->vram_watch_hi = ~0u;
	hw->control = RDC_CONTROL_RESET_VALUE;
	hw->irq_status = 0;
	hw->irq_enable = 0;
	hw->err_code = RDC_ERR_NONE;
	hw->err_info = 0;
	hw->perf_hi_snap = 0;
	hw->perf_snap_reg = 0;
	hw->bus.open_row = ~0u;
	rdc_memset(&hw->perf, 0, sizeof(hw->perf));
	rdc_clut_reset(hw);
	rdc_cmdq_reset(hw);
	hw->dp_status = 0;
	hw->dp_resume = 0;
	hw->have_frame = 0;
	hw->front_w = 0;
	hw->front_h = 0;
	hw->frame_back = 0;
	hw->frame_ok[0] = hw->frame_ok[1] = true;
	hw->pend_lo[0] = hw->pend_hi[0] = hw->pend_lo[1] = hw->pend_hi[1] = 0;
	hw->scan_lo = hw->scan_hi = 0;
	rdc_crtc_reset(hw);
	if (!hw->in_reset)
		rdc_crtc_start(hw);
	if (hw->dp_ops && hw->dp_ops->reset)
		hw->dp_ops->reset(hw->dp);
	rdc_dp_active(hw, 0);
	rdc_pins_update(hw, hw->now);
}

/* ---- interrupts and errors ---------------------------------------------- */

void rdc_port_irq(struct rdc_hw *hw, uint32_t bits)
{
	rdc_irq_raise(hw, bits);
	rdc_pins_update(hw, hw->now);
}

void rdc_port_error(struct rdc_hw *hw, uint32_t code, uint32_t info)
{
	hw->err_code = code;
	hw->err_info = info;
	rdc_port_irq(hw, RDC_IRQ_ERROR);
	rdc_trace(hw, RDC_TRACE_ERROR, code, info);
}

void rdc_port_fence(struct rdc_hw *hw, uint32_t value)
{
	hw->fence = value;
	rdc_port_irq(hw, RDC_IRQ_FENCE);
}

static bool irq_line(const struct rdc_hw *hw)
{
	return (hw->irq_status & hw->irq_enable) != 0;
}

/* ---- pins --------------------------------------------------------------- */

uint32_t rdc_hw_pins(struct rdc_hw *hw)
{
	rdc_crtc_catch_up(hw, hw->now);
	return rdc_pins_level(hw);
}

/*
 * RESET_N low resets the chip and holds it there: registers read their
 * reset values, writes are ignored, neither the DP nor scanout runs.
 * Releasing it resets again, so the first frame starts at the release.
 */
void rdc_hw_set_pins(struct rdc_hw *hw, uint32_t pins_in)
{
	bool hold = !(pins_in & RDC_PIN_RESET_N);

	rdc_crtc_catch_up(hw, hw->now);
	if ((hw->pins_in ^ pins_in) & RDC_PIN_BL_EN)
		rdc_scan_changed(hw);
	hw->pins_in = pins_in & PINS_IN;
	if (hold != (bool)hw->in_reset) {
		hw->in_reset = hold;
		rdc_hw_reset(hw);
	}
	rdc_pins_update(hw, hw->now);
}

/* ---- connections -------------------------------------------------------- */

void rdc_hw_set_dp(struct rdc_hw *hw, const struct rdc_dp_ops *ops, void *dp)
{
	hw->dp_ops = ops;
	hw->dp = dp;
}

void rdc_hw_set_frame_fn(struct rdc_hw *hw, rdc_frame_fn fn, void *ctx)
{
	/* frames skipped so far were never shown: nothing to catch up */
	hw->frame_fn = fn;
	hw->frame_ctx = ctx;
	rdc_scan_update(hw);
}

void rdc_hw_set_on_demand(struct rdc_hw *hw, bool on)
{
	rdc_crtc_catch_up(hw, hw->now);
	hw->on_demand = on;
	rdc_scan_update(hw);
}

void rdc_hw_consumer_attach(struct rdc_hw *hw)
{
	rdc_crtc_catch_up(hw, hw->now);
	hw->consumers++;
	rdc_scan_update(hw);
}

void rdc_hw_consumer_detach(struct rdc_hw *hw)
{
	rdc_crtc_catch_up(hw, hw->now);
	if (hw->consumers)
		hw->consumers--;
	rdc_scan_update(hw);
}

size_t rdc_hw_size(void)
{
	return sizeof(struct rdc_hw);
}

uint32_t rdc_hw_vram_size(const struct rdc_hw *hw)
{
	return hw->vram_size;
}

uint32_t rdc_hw_core_hz(const struct rdc_hw *hw)
{
	return hw->core_hz;
}

const uint8_t *rdc_hw_vram(const struct rdc_hw *hw)
{
	return hw->vram;
}

void rdc_hw_perf(const struct rdc_hw *hw, struct rdc_perf *p)
{
	*p = hw->perf;
}

void rdc_hw_state(const struct rdc_hw *hw, struct rdc_hw_state *s)
{
	s->control = hw->control;
	s->irq_status = hw->irq_status;
	s->irq_enable = hw->irq_enable;
	s->dp_status = hw->dp_status;
	s->fence = hw->fence;
	s->pins_in = hw->pins_in;
	s->pins_out = hw->pins_out;
	s->fifo_count = hw->fifo_count;
	s->in_reset = hw->in_reset;
	s->dp_active = hw->dp_active;
	s->scanning = hw->crtc.running;
	s->in_vblank = hw->crtc.in_vblank;
	s->frame_start = hw->crtc.frame_start;
	s->frame_cycles = hw->crtc.frame_cycles;
	s->frame_count = hw->crtc.frame_count;
	s->fb_base = hw->crtc.fb_base;
	s->fb_stride = hw->crtc.fb_stride;
	s->fb_format = hw->crtc.fb_format;
	s->width = hw->crtc.shadow.h_display;
	s->height = hw->crtc.shadow.v_display;
	s->next_line = hw->crtc.next_line;
}

void rdc_hw_resume_get(const struct rdc_hw *hw, struct rdc_hw_resume *s)
{
	s->now = hw->now;
	s->frame_start = hw->crtc.running ? hw->crtc.frame_start : hw->now;
	s->frame_count = hw->crtc.frame_count;
	s->perf = hw->perf;
	s->fence = hw->fence;
	s->irq_status = hw->irq_status;
	s->err_code = hw->err_code;
	s->err_info = hw->err_info;
	s->open_row = hw->bus.open_row;
	s->scanning = hw->crtc.running;
	s->dp_active = hw->dp_active;
	s->timing = hw->crtc.cur;
	s->fb_base = hw->crtc.cur_base;
	s->fb_stride = hw->crtc.cur_stride;
	s->fb_format = hw->crtc.cur_format;
	s->cursor_ctrl = hw->crtc.cur_cursor_ctrl;
	s->cursor_base = hw->crtc.cur_cursor_base;
	s->raster_base = hw->crtc.cur_raster_base;
	s->raster_ctrl = hw->crtc.cur_raster_ctrl;
	s->gamma = hw->crtc.cur_gamma;
}

/*
 * The frame restarts at frame_start (a SCANOUT_EN turned on then, which
 * latches what the host wrote) and runs to `now` as it ran there; what the
 * run cannot know, the counters, comes from `s` at the end.
 */
int rdc_hw_resume(struct rdc_hw *hw, const struct rdc_hw_resume *s)
{
	if (s->now < hw->now || s->frame_start > s->now ||
	    s->frame_start < hw->now || hw->dp_active || hw->in_reset)
		return -1;
	if (hw->crtc.running)
		rdc_crtc_stop(hw);
	/* no fetch of the fresh chip's holds the bus into the new frame */
	hw->crtc.fetch_end = 0;
	if (s->scanning && (hw->control & RDC_CONTROL_SCANOUT_EN)) {
		hw->now = s->frame_start;
		rdc_crtc_start(hw);
		rdc_hw_run_until(hw, s->now);
	}
	hw->now = s->now;
	hw->crtc.frame_count = s->frame_count;
	hw->perf = s->perf;
	hw->fence = s->fence;
	hw->irq_status = s->irq_status & RDC_IRQ_ALL;
	hw->err_code = s->err_code;
	hw->err_info = s->err_info;
	hw->bus.open_row = s->open_row;
	rdc_pins_update(hw, hw->now);
	return 0;
}

void rdc_hw_get_trace(const struct rdc_hw *hw, rdc_trace_fn *fn, void **ctx)
{
	*fn = hw->trace_fn;
	*ctx = hw->trace_ctx;
}

bool rdc_hw_vram_hooked(const struct rdc_hw *hw)
{
	return hw->vram_hook != NULL;
}

uint64_t rdc_hw_next_vblank(struct rdc_hw *hw)
{
	return rdc_port_next_vblank(hw);
}

uint64_t rdc_hw_next_line(struct rdc_hw *hw, uint32_t line)
{
	return rdc_port_next_line(hw, line);
}

bool rdc_hw_scanout_watched(const struct rdc_hw *hw)
{
	return !hw->lazy;
}

void rdc_hw_vram_touched(struct rdc_hw *hw, uint32_t addr, uint32_t len)
{
	rdc_crtc_catch_up(hw, hw->now);
	rdc_scan_check(hw, addr, (uint64_t)addr + len);
}

void rdc_hw_set_trace(struct rdc_hw *hw, rdc_trace_fn fn, void *ctx)
{
	hw->trace_fn = fn;
	hw->trace_ctx = ctx;
}

void rdc_hw_set_vram_hook(struct rdc_hw *hw, rdc_vram_hook_fn fn, void *ctx)
{
	hw->vram_hook = fn;
	hw->vram_hook_ctx = ctx;
	hw->vram_watch_lo = 0;
	hw->vram_watch_hi = ~0u;
}

void rdc_hw_set_vram_watch(struct rdc_hw *hw, uint32_t lo, uint32_t hi)
{
	hw->vram_watch_lo = lo;
	hw->vram_watch_hi = hi;
}

void rdc_hw_set_poll(struct rdc_hw *hw, void (*fn)(void *ctx), void *ctx)
{
	hw->poll_fn = fn;
	hw->poll_ctx = ctx;
	hw->poll_count = 0;
}

const uint32_t *rdc_hw_frame(struct rdc_hw *hw, uint32_t *width,
			     uint32_t *height)
{
	if (!hw->have_frame || !hw->frame_ok[hw->frame_back ^ 1]) {
		if (width)
			*width = 0;
		if (height)
			*height = 0;
		return NULL;
	}
	if (width)
		*width = hw->front_w;
	if (height)
		*height = hw->front_h;
	rdc_scan_front(hw);
	return hw->frame[hw->frame_back ^ 1];
}

uint64_t rdc_hw_now(const struct rdc_hw *hw)
{
	return hw->now;
}

void rdc_hw_timing(const struct rdc_hw *hw, struct rdc_timing *t)
{
	*t = hw->crtc.cur;
}

/* ---- host VRAM aperture ------------------------------------------------- */

int rdc_hw_vram_read(struct rdc_hw *hw, uint32_t addr, void *buf, uint32_t len)
{
	if ((uint64_t)addr + len > hw->vram_size)
		return -1;
	if (!len)
		return 0;
	rdc_memcpy(buf, hw->vram + addr, len);
	return 0;
}

int rdc_hw_vram_write(struct rdc_hw *hw, uint32_t addr, const void *buf,
		      uint32_t len)
{
	if ((uint64_t)addr + len > hw->vram_size)
		return -1;
	if (!len)
		return 0;
	/* lines the beam has passed keep the old bytes */
	rdc_crtc_catch_up(hw, hw->now);
	rdc_scan_check(hw, addr, (uint64_t)addr + len);
	if (hw->vram_hook && rdc_vram_watched(hw, addr, (uint64_t)addr + len))
		rdc_vram_hook_call(hw, hw->now, addr, len, 1, 0,
				   RDC_VRAM_BY_HOST);
	rdc_memcpy(hw->vram + addr, buf, len);
	rdc_trace(hw, RDC_TRACE_VRAM_WRITE, addr, len);
	return 0;
}

/* ---- run loop ----------------------------------------------------------- */

static int hw_run(struct rdc_hw *hw, uint64_t t, bool stop_idle)
{
	int idle = 0;

	if (rdc_crtc_due(hw, hw->now))
		rdc_crtc_catch_up(hw, hw->now);
	while (hw->now < t) {
		uint64_t wake = RDC_NEVER;

		rdc_port_poll(hw);
		if (hw->in_reset) {
			hw->now = t;
			return 0;
		}
		if (hw->dp_ops && hw->dp_ops->run &&
		    (hw->control & RDC_CONTROL_DP_EN)) {
			/* runs on in a command or list it was in */
			if (hw->dp_status & RDC_STATUS_DP_BUSY)
				rdc_dp_active(hw, 1);
			wake = hw->dp_ops->run(hw->dp, t);
			/*
			 * Out of work: a DP stopped at `t` with words waiting
			 * returns a wake time and stays busy.
			 */
			if (wake == RDC_NEVER &&
			    !(hw->dp_status & RDC_STATUS_DP_BUSY))
				rdc_dp_active(hw, 0);
		}
		if (hw->now >= t)
			break;
		if (stop_idle && wake == RDC_NEVER) {
			idle = 1;
			break;
		}
		/*
		 * A DP that claims it can progress now but returned anyway
		 * gets one idle cycle, so a confused DP cannot hang the host.
		 */
		if (wake <= hw->now)
			wake = hw->now + 1;
		rdc_port_idle_until(hw, RDC_MIN(wake, t));
	}
	if (rdc_crtc_due(hw, hw->now))
		rdc_crtc_catch_up(hw, hw->now);
	return idle;
}

void rdc_hw_run_until(struct rdc_hw *hw, uint64_t t)
{
	hw_run(hw, t, false);
}

int rdc_hw_run_until_idle(struct rdc_hw *hw, uint64_t t)
{
	return hw_run(hw, t, true);
}

/* ---- register file ------------------------------------------------------ */

static uint32_t snap_lo(struct rdc_hw *hw, uint64_t v, uint32_t hi_reg)
{
	hw->perf_hi_snap = (uint32_t)(v >> 32);
	hw->perf_snap_reg = hi_reg;
	return (uint32_t)v;
}

/* A HI read after its LO returns the snapshot, else the live value. */
static uint32_t snap_hi(struct rdc_hw *hw, uint64_t v, uint32_t hi_reg)
{
	if (hw->perf_snap_reg == hi_reg) {
		hw->perf_snap_reg = 0;
		return hw->perf_hi_snap;
	}
	return (uint32_t)(v >> 32);
}

static uint32_t timing_reg(struct rdc_timing *t, uint32_t reg, uint32_t **p)
{
	switch (reg) {
	case RDC_REG_H_TOTAL:
		*p = &t->h_total;
		break;
	case RDC_REG_H_DISPLAY:
		*p = &t->h_display;
		break;
	case RDC_REG_H_SYNC_START:
		*p = &t->h_sync_start;
		break;
	case RDC_REG_H_SYNC_END:
		*p = &t->h_sync_end;
		break;
	case RDC_REG_V_TOTAL:
		*p = &t->v_total;
		break;
	case RDC_REG_V_DISPLAY:
		*p = &t->v_display;
		break;
	case RDC_REG_V_SYNC_START:
		*p = &t->v_sync_start;
		break;
	case RDC_REG_V_SYNC_END:
		*p = &t->v_sync_end;
		break;
	case RDC_REG_PIXCLK_KHZ:
		*p = &t->pixclk_khz;
		break;
	case RDC_REG_CRTC_FLAGS:
		*p = &t->flags;
		break;
	default:
		return 0;
	}
	return 1;
}

static uint32_t status_reg(struct rdc_hw *hw)
{
	uint32_t s = hw->dp_status &
		     (RDC_STATUS_DP_BUSY | RDC_STATUS_DP_HALTED |
		      RDC_STATUS_DP_WAIT);

	if (!hw->fifo_count)
		s |= RDC_STATUS_FIFO_EMPTY;
	if (hw->fifo_count >= RDC_FIFO_DEPTH)
		s |= RDC_STATUS_FIFO_FULL;
	if (hw->ring_head == hw->ring_tail)
		s |= RDC_STATUS_RING_EMPTY;
	s |= rdc_crtc_status(hw);
	if (irq_line(hw))
		s |= RDC_STATUS_IRQ;
	if (hw->crtc.lpen_hit)
		s |= RDC_STATUS_LPEN;
	return s;
}

static uint32_t reg_read(struct rdc_hw *hw, uint32_t reg)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t *p, x, y, v;

	/*
	 * FIFO_FREE, which a host feeding the FIFO reads before every
	 * push: the catch-up only where a scanout event is due (as the
	 * call would find), and no dispatch.
	 */
	if (reg == RDC_REG_FIFO_FREE) {
		if (rdc_crtc_due(hw, hw->now))
			rdc_crtc_catch_up(hw, hw->now);
		return RDC_FIFO_DEPTH - hw->fifo_count;
	}
	rdc_crtc_catch_up(hw, hw->now);
	if (timing_reg(&c->shadow, reg, &p))
		return *p;
	switch (reg) {
	case RDC_REG_ID:
		return RDC_ID_VALUE;
	case RDC_REG_VERSION:
		return RDC_VERSION_VALUE;
	case RDC_REG_VRAM_SIZE:
		return hw->vram_size;
	case RDC_REG_CORE_KHZ:
		return hw->core_hz / HZ_PER_KHZ;
	case RDC_REG_CONTROL:
		return hw->control;
	case RDC_REG_STATUS:
		return status_reg(hw);
	case RDC_REG_IRQ_STATUS:
		return hw->irq_status;
	case RDC_REG_IRQ_ENABLE:
		return hw->irq_enable;
	case RDC_REG_ERR_CODE:
		return hw->err_code;
	case RDC_REG_ERR_INFO:
		return hw->err_info;
	case RDC_REG_PINS:
		return rdc_hw_pins(hw);
	case RDC_REG_FB_BASE:
		return c->fb_base;
	case RDC_REG_FB_STRIDE:
		return c->fb_stride;
	case RDC_REG_FB_FORMAT:
		return c->fb_format;
	case RDC_REG_LINE_COMPARE:
		return c->line_compare;
	case RDC_REG_BEAM:
		rdc_hw_beam(hw, &x, &y);
		return FIELD_PREP(RDC_BEAM_X, x) | FIELD_PREP(RDC_BEAM_Y, y);
	case RDC_REG_FRAME_COUNT:
		return (uint32_t)c->frame_count;
	case RDC_REG_MODE_PRESET:
		return c->preset;
	case RDC_REG_RASTER_BASE:
		return c->raster_base;
	case RDC_REG_RASTER_CTRL:
		return c->raster_ctrl;
	case RDC_REG_RASTER_STATUS:
		rdc_crtc_catch_up(hw, hw->now);
		return rdc_crtc_raster_status(hw);
	case RDC_REG_LPEN_POS:
		return c->lpen_pos;
	case RDC_REG_LPEN_CTRL:
		return c->lpen_ctrl;
	case RDC_REG_LPEN_LATCH:
		return c->lpen_latch;
	case RDC_REG_CLUT_INDEX:
		return hw->clut_index;
	case RDC_REG_CLUT_DATA:
		v = hw->clut_shadow[hw->clut_index];
		hw->clut_index = (hw->clut_index + 1) % RDC_CLUT_ENTRIES;
		return v;
	case RDC_REG_CURSOR_BASE:
		return c->cursor_base;
	case RDC_REG_CURSOR_POS:
		return c->cursor_pos;
	case RDC_REG_CURSOR_FG:
		return c->cursor_fg;
	case RDC_REG_CURSOR_BG:
		return c->cursor_bg;
	case RDC_REG_CURSOR_CTRL:
		return c->cursor_ctrl;
	case RDC_REG_FIFO_DATA:
		return 0;
	case RDC_REG_FIFO_FREE:
		return RDC_FIFO_DEPTH - hw->fifo_count;
	case RDC_REG_FIFO_LOWWATER:
		return hw->fifo_lowwater;
	case RDC_REG_RING_BASE:
		return hw->ring_base;
	case RDC_REG_RING_SIZE:
		return hw->ring_size;
	case RDC_REG_RING_HEAD:
		return hw->ring_head;
	case RDC_REG_RING_TAIL:
		return hw->ring_tail;
	case RDC_REG_FENCE:
		return hw->fence;
	case RDC_REG_RDATA:
		return rdc_rdata_pop(hw);
	case RDC_REG_RDATA_COUNT:
		return hw->rdata_count;
	case RDC_REG_TIME_LO:
		return snap_lo(hw, hw->now, RDC_REG_TIME_HI);
	case RDC_REG_TIME_HI:
		return snap_hi(hw, hw->now, reg);
	case RDC_REG_PERF_BUSY_LO:
		return snap_lo(hw, hw->perf.busy, RDC_REG_PERF_BUSY_HI);
	case RDC_REG_PERF_BUSY_HI:
		return snap_hi(hw, hw->perf.busy, reg);
	case RDC_REG_PERF_STALL_LO:
		return snap_lo(hw, hw->perf.stall, RDC_REG_PERF_STALL_HI);
	case RDC_REG_PERF_STALL_HI:
		return snap_hi(hw, hw->perf.stall, reg);
	case RDC_REG_PERF_PIXELS_LO:
		return snap_lo(hw, hw->perf.pixels, RDC_REG_PERF_PIXELS_HI);
	case RDC_REG_PERF_PIXELS_HI:
		return snap_hi(hw, hw->perf.pixels, reg);
	case RDC_REG_PERF_CMDS:
		return hw->perf.cmds;
	case RDC_REG_PERF_LAST_CYCLES:
		return hw->perf.last_cycles;
	case RDC_REG_PERF_LAST_OPCODE:
		return hw->perf.last_opcode;
	case RDC_REG_PERF_CULLED:
		return hw->perf.culled;
	case RDC_REG_PERF_CTRL:
		return 0;
	default:
		break;
	}
	/* unaligned, outside the window, or a hole in the map */
	if (!hw->in_reset)
		rdc_port_error(hw, RDC_ERR_REG, reg);
	return 0;
}

uint32_t rdc_hw_read(struct rdc_hw *hw, uint32_t reg)
{
	uint32_t v = reg_read(hw, reg);

	rdc_trace(hw, RDC_TRACE_REG_READ, reg, v);
	return v;
}

static void control_write(struct rdc_hw *hw, uint32_t val)
{
	uint32_t old = hw->control;

	if (val & RDC_CONTROL_SOFT_RESET) {
		rdc_hw_reset(hw);
		return;
	}
	if (val & RDC_CONTROL_RESUME)
		hw->dp_resume = 1;
	hw->control = val & CONTROL_RW_BITS;
	if ((old ^ hw->control) & RDC_CONTROL_CURSOR_EN)
		rdc_scan_changed(hw);
	if (!(hw->control & RDC_CONTROL_DP_EN))
		rdc_dp_active(hw, 0);
	if ((old ^ hw->control) & RDC_CONTROL_SCANOUT_EN) {
		if (hw->control & RDC_CONTROL_SCANOUT_EN)
			rdc_crtc_start(hw);
		else
			rdc_crtc_stop(hw);
	}
	if ((old ^ hw->control) & RDC_CONTROL_RING_EN)
		rdc_ring_validate(hw, RDC_REG_CONTROL);
}

static void preset_write(struct rdc_hw *hw, uint32_t val)
{
	struct rdc_crtc *c = &hw->crtc;
	struct rdc_timing t;

	if (rdc_preset_timing(val, &t)) {
		rdc_port_error(hw, RDC_ERR_MODE, RDC_REG_MODE_PRESET);
		return;
	}
	c->shadow = t;
	c->preset = val;
	c->shadow_dirty = 1;
	if (c->fb_format < RDC_FMT_COUNT)
		c->fb_stride =
			(rdc_format_row_bytes(c->fb_format, t.h_display) + 3) &
			~3u;
}

/* Registers a REG_WRITE command may reach as well as the host. */
static bool crtc_side_write(struct rdc_hw *hw, uint32_t reg, uint32_t val)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t *p;

	/* the framebuffer may move: the VRAM watcher looks again */
	hw->vram_watch_lo = 0;
	hw->vram_watch_hi = ~0u;
	if (timing_reg(&c->shadow, reg, &p)) {
		*p = val;
		c->shadow_dirty = 1;
		return true;
	}
	switch (reg) {
	case RDC_REG_IRQ_STATUS:
		hw->irq_status &= ~val;
		if (val & RDC_IRQ_ERROR) {
			hw->err_code = RDC_ERR_NONE;
			hw->err_info = 0;
		}
		rdc_pins_update(hw, hw->now);
		return true;
	case RDC_REG_IRQ_ENABLE:
		hw->irq_enable = val & RDC_IRQ_ALL;
		rdc_pins_update(hw, hw->now);
		return true;
	case RDC_REG_FB_BASE:
		c->fb_base = val;
		return true;
	case RDC_REG_FB_STRIDE:
		c->fb_stride = val;
		return true;
	case RDC_REG_FB_FORMAT:
		c->fb_format = val;
		c->shadow_dirty = 1;
		return true;
	case RDC_REG_LINE_COMPARE:
		c->line_compare = val;
		return true;
	case RDC_REG_MODE_PRESET:
		preset_write(hw, val);
		return true;
	case RDC_REG_RASTER_BASE:
		c->raster_base = val & RDC_RASTER_BASE_MASK;
		return true;
	case RDC_REG_RASTER_CTRL:
		c->raster_ctrl = val & RDC_RASTER_CTRL_MASK;
		c->rl_error = 0;
		return true;
	case RDC_REG_CLUT_INDEX:
		hw->clut_index = val % RDC_CLUT_ENTRIES;
		return true;
	case RDC_REG_CLUT_DATA:
		rdc_port_clut_write(hw, hw->clut_index, val);
		hw->clut_index = (hw->clut_index + 1) % RDC_CLUT_ENTRIES;
		return true;
	case RDC_REG_CURSOR_BASE:
		c->cursor_base = val;
		return true;
	case RDC_REG_CURSOR_POS:
		if (c->cursor_pos != val)
			rdc_scan_changed(hw);
		c->cursor_pos = val;
		return true;
	case RDC_REG_CURSOR_FG:
		if (c->cursor_fg != (val & RGB_MASK))
			rdc_scan_changed(hw);
		c->cursor_fg = val & RGB_MASK;
		return true;
	case RDC_REG_CURSOR_BG:
		if (c->cursor_bg != (val & RGB_MASK))
			rdc_scan_changed(hw);
		c->cursor_bg = val & RGB_MASK;
		return true;
	case RDC_REG_CURSOR_CTRL:
		/* an unknown format is refused whole; other bits drop */
		if (FIELD_GET(RDC_CURSOR_CTRL_FMT, val) >= RDC_CURSOR_FMT_COUNT)
			rdc_port_error(hw, RDC_ERR_REG, reg);
		else
			c->cursor_ctrl = val & RDC_CURSOR_CTRL_MASK;
		return true;
	default:
		return false;
	}
}

void rdc_hw_write(struct rdc_hw *hw, uint32_t reg, uint32_t val)
{
	if (hw->in_reset)
		return;
	rdc_crtc_catch_up(hw, hw->now);
	rdc_trace(hw, RDC_TRACE_REG_WRITE, reg, val);
	if (crtc_side_write(hw, reg, val))
		return;
	switch (reg) {
	case RDC_REG_CONTROL:
		control_write(hw, val);
		return;
	case RDC_REG_FIFO_DATA:
		rdc_fifo_push(hw, val);
		return;
	case RDC_REG_FIFO_LOWWATER:
		hw->fifo_lowwater = RDC_MIN(val, RDC_FIFO_DEPTH);
		return;
	case RDC_REG_LPEN_POS:
	case RDC_REG_LPEN_CTRL: /* an input of the host's, not of the DP's */
		rdc_crtc_lpen_write(hw, reg, val);
		return;
	case RDC_REG_RING_BASE:
		hw->ring_base = val;
		rdc_ring_validate(hw, reg);
		return;
	case RDC_REG_RING_SIZE:
		hw->ring_size = val;
		rdc_ring_validate(hw, reg);
		return;
	case RDC_REG_RING_HEAD:
		if (hw->control & RDC_CONTROL_RING_EN)
			break; /* the DP owns HEAD while the ring runs */
		hw->ring_head = val;
		rdc_ring_validate(hw, reg);
		return;
	case RDC_REG_RING_TAIL:
		hw->ring_tail = val;
		rdc_ring_validate(hw, reg);
		return;
	case RDC_REG_PERF_CTRL:
		if (val & RDC_PERF_CTRL_CLEAR)
			rdc_memset(&hw->perf, 0, sizeof(hw->perf));
		return;
	default:
		break;
	}
	/* read-only, unaligned, outside the window, or a hole in the map */
	rdc_port_error(hw, RDC_ERR_REG, reg);
}

int rdc_port_reg_write(struct rdc_hw *hw, uint32_t reg, uint32_t val)
{
	rdc_crtc_catch_up(hw, hw->now);
	return crtc_side_write(hw, reg, val) ? 0 : -1;
}
