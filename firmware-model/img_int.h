/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Helpers shared by the image commands (image.c, decode.c, filter.c).
 */
#ifndef RDC_DP_IMG_INT_H
#define RDC_DP_IMG_INT_H

#include "dp_int.h"

/* One colour channel of an RGB format: bits [shift, shift + bits). */
struct img_chan {
	uint32_t shift, bits;
};

/* The R, G, B channels of an RGB format (*n = 3), or NULL (*n = 0). */
const struct img_chan *img_channels(uint32_t fmt, uint32_t *n);
/* A 5- or 6-bit channel widened to 8 bits (v << 3 | v >> 2, ...). */
uint32_t img_widen(uint32_t v, uint32_t bits);
/* The 8-bit value of a pixel for RDC_CHAN_* sel (the index if indexed). */
uint32_t img_intensity(uint32_t fmt, uint32_t px, uint32_t sel);
/* 8-bit R, G, B as a pixel of an RGB format. */
uint32_t img_pack_rgb(uint32_t fmt, uint32_t r, uint32_t g, uint32_t b);

uint32_t dp_cmd_decode(struct rdc_dp *dp, uint32_t fl, const uint32_t *a);
uint32_t dp_cmd_convolve(struct rdc_dp *dp, uint32_t fl, uint32_t len,
			 const uint32_t *a);

#endif /* RDC_DP_IMG_INT_H */
