/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Display-processor internals shared by the decoder (dp.c) and the
 * rasterisers (raster.c).  Arguments reaching these functions have been
 * range-checked by the decoder: coordinates in [RDC_COORD_MIN,
 * RDC_COORD_MAX], sizes and radii in [0, RDC_SIZE_MAX], surfaces inside
 * VRAM.  Everything is clipped here against rdc_dp_eff_clip().
 */
#ifndef RDC_DP_INT_H
#define RDC_DP_INT_H

#include "dp.h"

/* The clip rectangle intersected with the destination surface. */
struct rdc_rect rdc_dp_eff_clip(const struct rdc_dp *dp);

void rdc_dp_pixel(struct rdc_dp *dp, int32_t x, int32_t y);
/* skip_first/skip_last leave out the endpoint pixel (x0, y0) / (x1, y1);
 * POLYLINE uses them so shared vertices are drawn once. */
void rdc_dp_line(struct rdc_dp *dp, int32_t x0, int32_t y0, int32_t x1,
		 int32_t y1, bool skip_first, bool skip_last);
void rdc_dp_rect(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, bool fill);
void rdc_dp_circle(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t r,
		   bool fill);
void rdc_dp_ellipse(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t rx,
		    uint32_t ry, bool fill);
void rdc_dp_blit(struct rdc_dp *dp, int32_t sx, int32_t sy, int32_t dx,
		 int32_t dy, uint32_t w, uint32_t h);
/* data: h rows of `wpr` words each (wpr from rdc_dp_words_per_row). */
void rdc_dp_host_blit(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		      uint32_t h, const uint32_t *data);
void rdc_dp_mono(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, const uint32_t *data, bool transparent);
void rdc_dp_text(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t count,
		 const uint32_t *chars, bool transparent);
/*
 * Pack words [word, word + n) of READBACK row `row` (SRC-format pixels of
 * the w x h rectangle at x, y; pixels off the surface read as 0) into out.
 */
void rdc_dp_readback_pack(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
			  uint32_t row, uint32_t word, uint32_t n,
			  uint32_t *out);

/* Words a row of w pixels of `fmt` occupies, padded to a word. */
static inline uint32_t rdc_dp_words_per_row(unsigned int fmt, uint32_t w)
{
	return (uint32_t)(((uint64_t)w * rdc_format_bpp(fmt) + 31) / 32);
}

#endif /* RDC_DP_INT_H */
