/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Plain reference rasterisers for the tests: the textbook per-pixel form
 * of each algorithm the display processor implements, with no clipping,
 * no bus and no attempt at speed.  They emit pixel positions through a
 * callback, possibly more than once; tests compare the display processor's
 * output against the set of positions they produce.
 */
#ifndef RDC_REF_H
#define RDC_REF_H

#include "rdc_base.h"

typedef void (*rdc_ref_plot_fn)(void *ctx, int32_t x, int32_t y);

/* Both endpoints included, same pixels for (a, b) and (b, a). */
void rdc_ref_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
		  rdc_ref_plot_fn plot, void *ctx);
void rdc_ref_rect(int32_t x, int32_t y, uint32_t w, uint32_t h, bool fill,
		  rdc_ref_plot_fn plot, void *ctx);
/*
 * CIRCLE, FILL_CIRCLE, ELLIPSE, FILL_ELLIPSE: the pixels of the bounding box
 * that pass the *_has test for their offset from the centre.
 */
void rdc_ref_circle(int32_t cx, int32_t cy, uint32_t r, bool fill,
		    rdc_ref_plot_fn plot, void *ctx);
void rdc_ref_ellipse(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
		     bool fill, rdc_ref_plot_fn plot, void *ctx);
/* Is offset (x, y) from the centre a pixel of the circle / its fill? */
bool rdc_ref_circle_has(uint32_t r, int64_t x, int64_t y);
bool rdc_ref_circle_fill_has(uint32_t r, int64_t x, int64_t y);
/* ... of the ellipse / its fill (a zero radius: the line) */
bool rdc_ref_ellipse_has(uint32_t rx, uint32_t ry, int64_t x, int64_t y);
bool rdc_ref_ellipse_fill_has(uint32_t rx, uint32_t ry, int64_t x, int64_t y);

#endif /* RDC_REF_H */
