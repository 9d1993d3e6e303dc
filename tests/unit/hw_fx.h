/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The hw-sim unit tests' one simulated chip: an RDC-1 (struct rdc_hw)
 * with its VRAM and the two frame buffers the CRTC converts into,
 * allocated together.  A test that keeps more state embeds it:
 *
 *	struct fx {
 *		struct hw_fx sim;
 *		int frames;
 *	};
 *
 * and sets it up in its cmocka setup (hw_fx_init), or takes the plain
 * one with hw_fx_setup / hw_fx_teardown.
 */
#ifndef RDC_TEST_HW_FX_H
#define RDC_TEST_HW_FX_H

#include "hw.h"

struct hw_fx {
	struct rdc_hw hw;
	uint8_t *vram;	    /* vram_size bytes, zeroed */
	uint32_t *f0, *f1;  /* frame_cap pixels each */
	uint32_t vram_size; /* as given to rdc_hw_init */
	uint32_t frame_cap;
};

/*
 * Allocate x's memory and rdc_hw_init the chip on it, at the default
 * core clock: 0, or -1 out of memory (nothing left allocated).
 */
int hw_fx_init(struct hw_fx *x, uint32_t vram_size, uint32_t frame_cap);
/* rdc_hw_init again on the same memory (VRAM as it is): a new chip. */
void hw_fx_reinit(struct hw_fx *x);
void hw_fx_fini(struct hw_fx *x);

/* A cmocka state that is only a fixture (*state: struct hw_fx *). */
int hw_fx_setup(void **state, uint32_t vram_size, uint32_t frame_cap);
int hw_fx_teardown(void **state);

#endif /* RDC_TEST_HW_FX_H */
