// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Colour lookup table.  clut[] is what scanout uses; clut_shadow[] is what
 * the CLUT_DATA port reads back (the last value written to each entry).
 * Immediate writes go to both; latched writes (RDC_CONTROL_CLUT_LATCH) go
 * to the shadow only and the whole shadow is copied in at vblank, so a
 * palette change made during a frame shows from the next frame on.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"

#define RGB_MASK 0x00ffffffu

/* The 16 colours of the IBM VGA text palette, entries 0..15. */
static const uint32_t rdc_vga16[16] = {
	0x000000, 0x0000aa, 0x00aa00, 0x00aaaa, 0xaa0000, 0xaa00aa,
	0xaa5500, 0xaaaaaa, 0x555555, 0x5555ff, 0x55ff55, 0x55ffff,
	0xff5555, 0xff55ff, 0xffff55, 0xffffff,
};

#define CUBE_FIRST  16u /* 6x6x6 colour cube, entries 16..231 */
#define CUBE_LEVELS 6u
#define CUBE_STEP   0x33u /* 0, 0x33, ..., 0xff: the "web-safe" levels */
#define GREY_FIRST  (CUBE_FIRST + CUBE_LEVELS * CUBE_LEVELS * CUBE_LEVELS)
#define GREY_BASE   8u /* grey ramp 232..255: 8, 18, ..., 238 as xterm */
#define GREY_STEP   10u

void rdc_clut_reset(struct rdc_hw *hw)
{
	uint32_t i;

	for (i = 0; i < CUBE_FIRST; i++)
		hw->clut[i] = rdc_vga16[i];
	for (i = CUBE_FIRST; i < GREY_FIRST; i++) {
		uint32_t k = i - CUBE_FIRST;
		uint32_t r = k / (CUBE_LEVELS * CUBE_LEVELS);
		uint32_t g = k / CUBE_LEVELS % CUBE_LEVELS;
		uint32_t b = k % CUBE_LEVELS;

		hw->clut[i] = (r * CUBE_STEP) << 16 | (g * CUBE_STEP) << 8 |
			      b * CUBE_STEP;
	}
	for (i = GREY_FIRST; i < RDC_CLUT_ENTRIES; i++) {
		uint32_t v = GREY_BASE + GREY_STEP * (i - GREY_FIRST);

		hw->clut[i] = v << 16 | v << 8 | v;
	}
	rdc_memcpy(hw->clut_shadow, hw->clut, sizeof(hw->clut));
	hw->clut_dirty = 0;
	hw->clut_index = 0;
}

void rdc_clut_latch(struct rdc_hw *hw)
{
	if (!hw->clut_dirty)
		return;
	rdc_memcpy(hw->clut, hw->clut_shadow, sizeof(hw->clut));
	hw->clut_dirty = 0;
}

void rdc_port_clut_write(struct rdc_hw *hw, uint32_t index, uint32_t rgb)
{
	index %= RDC_CLUT_ENTRIES;
	rgb &= RGB_MASK;
	/* lines fetched before this moment keep the old colour */
	rdc_crtc_catch_up(hw, hw->now);
	hw->clut_shadow[index] = rgb;
	if (hw->control & RDC_CONTROL_CLUT_LATCH) {
		hw->clut_dirty = 1;
	} else if (hw->clut[index] != rgb) {
		rdc_scan_changed(hw);
		hw->clut[index] = rgb;
	}
}
