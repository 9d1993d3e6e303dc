// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * What a trace's records may carry and ask of a replay: the recorder
 * (record.c) writes within these bounds, replay (replay.c) refuses a
 * record beyond them.
 */
#ifndef RDC_RECORD_LIMITS_H
#define RDC_RECORD_LIMITS_H

#include "rdc_priv.h"

#define REC_MAX_VRAM_WRITE (256u << 20)
/* Words a SUBMIT record carries at most (a command is 4097 at most). */
#define REC_SUBMIT_MAX 65536u
/*
 * What one record may ask of the replay, as rdcd bounds a client's wait or
 * step: one simulated minute of the default core clock (a STEP's cycles, a
 * WAIT's budget, the time to an END).  The recorder writes longer steps in
 * pieces of at most this.  And at most REC_MAX_POWER power cycles, each a
 * new chip.  A trace that asks for more is refused (RDC_E_RANGE), naming
 * the record.
 */
#define REC_MAX_CYCLES (60ull * RDC_DEFAULT_CORE_HZ)
#define REC_MAX_POWER  256u

/*
 * A STATE record's registers, the ones it may name, in the order the
 * recorder writes them and replay writes them back: the preset first
 * (it loads the timing shadows and FB_STRIDE), CONTROL last (RING_HEAD
 * is refused once RING_EN is on).  CLUT_INDEX is put back after the
 * CLUT's entries.
 */
static const uint32_t rec_state_regs[] = {
	RDC_REG_MODE_PRESET,  RDC_REG_H_TOTAL,	     RDC_REG_H_DISPLAY,
	RDC_REG_H_SYNC_START, RDC_REG_H_SYNC_END,    RDC_REG_V_TOTAL,
	RDC_REG_V_DISPLAY,    RDC_REG_V_SYNC_START,  RDC_REG_V_SYNC_END,
	RDC_REG_PIXCLK_KHZ,   RDC_REG_CRTC_FLAGS,    RDC_REG_FB_BASE,
	RDC_REG_FB_STRIDE,    RDC_REG_FB_FORMAT,     RDC_REG_LINE_COMPARE,
	RDC_REG_RASTER_BASE,  RDC_REG_RASTER_CTRL,   RDC_REG_LPEN_POS,
	RDC_REG_LPEN_CTRL,    RDC_REG_CURSOR_BASE,   RDC_REG_CURSOR_POS,
	RDC_REG_CURSOR_FG,    RDC_REG_CURSOR_BG,     RDC_REG_CURSOR_CTRL,
	RDC_REG_IRQ_ENABLE,   RDC_REG_FIFO_LOWWATER, RDC_REG_RING_BASE,
	RDC_REG_RING_SIZE,    RDC_REG_RING_HEAD,     RDC_REG_RING_TAIL,
	RDC_REG_CLUT_INDEX,   RDC_REG_CONTROL,
};

#define REC_STATE_REGS (sizeof(rec_state_regs) / sizeof(rec_state_regs[0]))

/*
 * The core section's values in force (latched at the last vblank), in
 * its order, and the register each is the latched copy of.
 */
static const uint32_t rec_state_latched[] = {
	RDC_REG_H_TOTAL,      RDC_REG_H_DISPLAY,   RDC_REG_H_SYNC_START,
	RDC_REG_H_SYNC_END,   RDC_REG_V_TOTAL,	   RDC_REG_V_DISPLAY,
	RDC_REG_V_SYNC_START, RDC_REG_V_SYNC_END,  RDC_REG_PIXCLK_KHZ,
	RDC_REG_CRTC_FLAGS,   RDC_REG_FB_BASE,	   RDC_REG_FB_STRIDE,
	RDC_REG_FB_FORMAT,    RDC_REG_CURSOR_CTRL, RDC_REG_CURSOR_BASE,
	RDC_REG_RASTER_BASE,  RDC_REG_RASTER_CTRL,
};

#define REC_STATE_INFORCE \
	(sizeof(rec_state_latched) / sizeof(rec_state_latched[0]))

static inline uint32_t *rec_state_inforce(struct rdc_hw_resume *s, size_t i)
{
	uint32_t *const v[] = {
		&s->timing.h_total,
		&s->timing.h_display,
		&s->timing.h_sync_start,
		&s->timing.h_sync_end,
		&s->timing.v_total,
		&s->timing.v_display,
		&s->timing.v_sync_start,
		&s->timing.v_sync_end,
		&s->timing.pixclk_khz,
		&s->timing.flags,
		&s->fb_base,
		&s->fb_stride,
		&s->fb_format,
		&s->cursor_ctrl,
		&s->cursor_base,
		&s->raster_base,
		&s->raster_ctrl,
	};

	return v[i];
}

/* CLUT entries a STATE record carries: all of them */
#define REC_STATE_CLUT RDC_CLUT_ENTRIES
/* A STATE record's compressed VRAM: at most zlib's bound for the most a
 * trace's VRAM may be (its compressBound, written out) */
#define REC_STATE_MAX_Z \
	(REC_MAX_VRAM_WRITE + (REC_MAX_VRAM_WRITE >> 12) + \
	 (REC_MAX_VRAM_WRITE >> 14) + (REC_MAX_VRAM_WRITE >> 25) + 13u)

#endif /* RDC_RECORD_LIMITS_H */
