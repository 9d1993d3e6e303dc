// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* The hw-sim unit tests' simulated chip (see hw_fx.h). */
#include <stdlib.h>

#include "hw_fx.h"

int hw_fx_init(struct hw_fx *x, uint32_t vram_size, uint32_t frame_cap)
{
	x->vram = calloc(1, vram_size);
	x->f0 = calloc(frame_cap, sizeof(*x->f0));
	x->f1 = calloc(frame_cap, sizeof(*x->f1));
	if (!x->vram || !x->f0 || !x->f1) {
		hw_fx_fini(x);
		return -1;
	}
	x->vram_size = vram_size;
	x->frame_cap = frame_cap;
	hw_fx_reinit(x);
	return 0;
}

void hw_fx_reinit(struct hw_fx *x)
{
	struct rdc_hw_config cfg = { .vram_size = x->vram_size };

	rdc_hw_init(&x->hw, &cfg, x->vram, x->f0, x->f1, x->frame_cap);
}

void hw_fx_fini(struct hw_fx *x)
{
	free(x->vram);
	free(x->f0);
	free(x->f1);
	x->vram = NULL;
	x->f0 = x->f1 = NULL;
}

int hw_fx_setup(void **state, uint32_t vram_size, uint32_t frame_cap)
{
	struct hw_fx *x = calloc(1, sizeof(*x));

	if (!x || hw_fx_init(x, vram_size, frame_cap)) {
		free(x);
		return -1;
	}
	*state = x;
	return 0;
}

int hw_fx_teardown(void **state)
{
	struct hw_fx *x = *state;

	hw_fx_fini(x);
	free(x);
	return 0;
}
