/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Reference points of BEZIER, HERMITE and BSPLINE (see ref.h): each step
 * of docs/commands.md evaluated exactly as a fraction of 64-bit integers
 * in the curve's Bernstein or basis-function form (the DP forward-
 * differences the power form in 32.32 fixed point) and rounded to the
 * nearest pixel, halves up.
 */
#ifndef RDC_REF_CURVE_H
#define RDC_REF_CURVE_H

#include "ref.h"

struct rdc_ref_curve_pt {
	int32_t x, y;
	/*
	 * a coordinate lies within 1/256 pixel of a half, where the DP's
	 * fixed-point error may round it the other way
	 */
	bool near_half;
};

/*
 * The points of the curve command op (RDC_OP_BEZIER, RDC_OP_HERMITE,
 * RDC_OP_BSPLINE) with the step flags `steps` (0: chosen from the control
 * polygon) and n control points xy[2i], xy[2i + 1] (HERMITE: p0, p1, t0,
 * t1), consecutive equal points merged.  Returns the number of points, at
 * most cap written to out.
 */
uint32_t rdc_ref_curve_points(uint32_t op, uint32_t steps, const int32_t *xy,
			      uint32_t n, struct rdc_ref_curve_pt *out,
			      uint32_t cap);

#endif /* RDC_REF_CURVE_H */
