/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Plain reference polygon fill: every pixel centre tested against every
 * edge, no edge table, no clipping, no bus (see ref.h).
 */
#ifndef RDC_REF_POLY_H
#define RDC_REF_POLY_H

#include "ref.h"

/*
 * Is pixel (px, py)'s centre inside the polygon of n points xy[2i],
 * xy[2i + 1] (even-odd, or non-zero winding), with the top-left rule for
 * centres on an edge?
 */
bool rdc_ref_poly_inside(const int32_t *xy, uint32_t n, bool nonzero,
			 int32_t px, int32_t py);
/* Plot every inside pixel of the bounding box. */
void rdc_ref_fill_poly(const int32_t *xy, uint32_t n, bool nonzero,
		       rdc_ref_plot_fn plot, void *ctx);

#endif /* RDC_REF_POLY_H */
