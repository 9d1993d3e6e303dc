// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The textbook point-in-polygon test at pixel centres.  Edge (x0, y0) ->
 * (x1, y1) takes part in row py when its y range [min, max) holds the
 * centre py + 1/2; it counts for the pixel when the crossing lies at or
 * left of the centre px + 1/2, i.e. (comparing doubled coordinates, with
 * the edge ordered downwards, dy > 0)
 *   (2 px + 1 - 2 x0) dy >= (2 py + 1 - 2 y0) dx,
 * adding its direction to the winding number.
 */
#include "ref_poly.h"

bool rdc_ref_poly_inside(const int32_t *xy, uint32_t n, bool nonzero,
			 int32_t px, int32_t py)
{
	int64_t cy2 = 2 * (int64_t)py + 1, cx2 = 2 * (int64_t)px + 1;
	int32_t wind = 0, cross = 0;
	uint32_t i;

	for (i = 0; i < n; i++) {
		uint32_t j = i + 1 == n ? 0 : i + 1;
		int64_t x0 = xy[2 * i], y0 = xy[2 * i + 1];
		int64_t x1 = xy[2 * j], y1 = xy[2 * j + 1];
		int32_t dir = 1;

		if (y0 == y1)
			continue;
		if (y0 > y1) {
			int64_t t;

			t = x0, x0 = x1, x1 = t;
			t = y0, y0 = y1, y1 = t;
			dir = -1;
		}
		if (cy2 < 2 * y0 || cy2 >= 2 * y1)
			continue;
		if ((cx2 - 2 * x0) * (y1 - y0) >= (cy2 - 2 * y0) * (x1 - x0)) {
			wind += dir;
			cross++;
		}
	}
	return nonzero ? wind != 0 : (cross & 1);
}

void rdc_ref_fill_poly(const int32_t *xy, uint32_t n, bool nonzero,
		       rdc_ref_plot_fn plot, void *ctx)
{
	int32_t x0, y0, x1, y1, x, y;
	uint32_t i;

	if (!n)
		return;
	x0 = x1 = xy[0];
	y0 = y1 = xy[1];
	for (i = 1; i < n; i++) {
		x0 = RDC_MIN(x0, xy[2 * i]);
		x1 = RDC_MAX(x1, xy[2 * i]);
		y0 = RDC_MIN(y0, xy[2 * i + 1]);
		y1 = RDC_MAX(y1, xy[2 * i + 1]);
	}
	for (y = y0; y <= y1; y++)
		for (x = x0; x <= x1; x++)
			if (rdc_ref_poly_inside(xy, n, nonzero, x, y))
				plot(ctx, x, y);
}
