/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Anti-aliasing references for the tests: the plain rasterisers visit
 * pixels one by one, in the textbook form, and report each with its 8-bit
 * coverage (1..RDC_AA_FULL).  The display processor (aa.c) gives the
 * same pixels and coverages for lines, and for circles and ellipses
 * coverages within the tolerance docs/commands.md states, working in
 * clipped spans.
 */
#ifndef RDC_REF_AA_H
#define RDC_REF_AA_H

#include "rdc_base.h"

#define RDC_AA_FULL 255u /* coverage of a pixel the shape covers fully */

typedef void (*rdc_ref_aa_fn)(void *ctx, int32_t x, int32_t y, uint32_t cov);

/*
 * Coverage of the pixel at offset (x, y) >= 0 from the centre of the
 * ellipse with radii rx, ry >= 1, as docs/commands.md defines it: a tent
 * of the pixel's distance d to the curve, ((256 - d) 255 + 128) / 256 for
 * d = floor(256 |F| / |grad F|) below 256 (0 from there on), F = x^2 ry^2
 * + y^2 rx^2 - rx^2 ry^2, here with d exact.  Pixels outside
 * |x| <= rx + 1, |y| <= ry + 1 have no coverage.
 */
uint32_t rdc_ref_aa_ellipse_cov(uint32_t rx, uint32_t ry, uint32_t x,
				uint32_t y);

/*
 * Wu line between integer endpoints, ends included, the same pixels for
 * (a, b) and (b, a).  Along the major axis (n = |major delta|, m = |minor
 * delta|, endpoints ordered so the major coordinate increases) step i in
 * [0, n] has minor offset j = floor(i m / n) and remainder r = i m mod n;
 * f = (255 r + n / 2) / n; the pixel at offset j gets 255 - f and the one
 * at j + 1 gets f (when nonzero).  Every step's coverages sum to 255.
 */
void rdc_ref_aa_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
		     rdc_ref_aa_fn plot, void *ctx);

/*
 * Every pixel of the bounding box with rdc_ref_aa_ellipse_cov > 0; a zero
 * radius gives the Wu line between the two extreme points.
 */
void rdc_ref_aa_ellipse(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
			rdc_ref_aa_fn plot, void *ctx);

#endif /* RDC_REF_AA_H */
