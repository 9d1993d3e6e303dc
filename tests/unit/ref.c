// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Reference rasterisers (see ref.h).  Written for obviousness: lines and
 * rectangles are the textbook loops; circles and ellipses test each pixel
 * of their bounding box against the documented inequality.
 */
#include "ref.h"

void rdc_ref_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
		  rdc_ref_plot_fn plot, void *ctx)
{
	int32_t dx = x1 - x0, dy = y1 - y0, sx, sy, i;
	int32_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
	int64_t d;
	/* Canonical direction: along the major axis, increasing. */
	bool xmajor = adx >= ady && adx > 0;

	if ((xmajor && dx < 0) || (!xmajor && dy < 0)) {
		rdc_ref_line(x1, y1, x0, y0, plot, ctx);
		return;
	}
	sx = dx < 0 ? -1 : 1;
	sy = dy < 0 ? -1 : 1;
	if (xmajor) {
		/* Bresenham; a tie (d == 0) steps the minor axis. */
		d = 2 * (int64_t)ady - adx;
		for (i = 0; i <= adx; i++) {
			plot(ctx, x0, y0);
			if (d >= 0) {
				y0 += sy;
				d -= 2 * (int64_t)adx;
			}
			d += 2 * (int64_t)ady;
			x0 += sx;
		}
	} else {
		d = 2 * (int64_t)adx - ady;
		for (i = 0; i <= ady; i++) {
			plot(ctx, x0, y0);
			if (d >= 0) {
				x0 += sx;
				d -= 2 * (int64_t)ady;
			}
			d += 2 * (int64_t)adx;
			y0 += sy;
		}
	}
}

void rdc_ref_rect(int32_t x, int32_t y, uint32_t w, uint32_t h, bool fill,
		  rdc_ref_plot_fn plot, void *ctx)
{
	uint32_t i, j;

	for (j = 0; j < h; j++)
		for (i = 0; i < w; i++)
			if (fill || i == 0 || j == 0 || i == w - 1 ||
			    j == h - 1)
				plot(ctx, x + (int32_t)i, y + (int32_t)j);
}

/*
 * Conics, pixel by pixel from the inequalities of docs/commands.md: every
 * pixel of the bounding box is tested on its own, with 128-bit products,
 * so no stepping, no symmetry and no region switch can leave one out.
 * Offsets (x, y) are from the centre; only |x| and |y| matter.
 */
typedef __int128 ref_wide;

static int64_t ref_abs(int64_t v)
{
	return v < 0 ? -v : v;
}

bool rdc_ref_ellipse_fill_has(uint32_t rx, uint32_t ry, int64_t x, int64_t y)
{
	ref_wide a = ref_abs(x), b = ref_abs(y), a2 = (ref_wide)rx * rx,
		 b2 = (ref_wide)ry * ry, r4 = 4 * a2 * b2;

	if (!rx || !ry) /* the line between the extreme points */
		return (!ry && b == 0 && a <= rx) || (!rx && a == 0 && b <= ry);
	/* half a pixel towards the centre, vertically or horizontally */
	return 4 * b2 * a * a + a2 * (2 * b - 1) * (2 * b - 1) <= r4 ||
	       b2 * (2 * a - 1) * (2 * a - 1) + 4 * a2 * b * b <= r4;
}

bool rdc_ref_ellipse_has(uint32_t rx, uint32_t ry, int64_t x, int64_t y)
{
	int64_t a = ref_abs(x), b = ref_abs(y);

	if (!rdc_ref_ellipse_fill_has(rx, ry, a, b))
		return false;
	if (!rx || !ry)
		return true;
	/* a fill pixel with the next one outwards, across or down, outside */
	return !rdc_ref_ellipse_fill_has(rx, ry, a + 1, b) ||
	       !rdc_ref_ellipse_fill_has(rx, ry, a, b + 1);
}

/* 4a^2 + (2b + 1)^2 > 4r^2: the midpoint above (a, b) is outside */
static bool ref_circle_above_out(uint32_t r, ref_wide a, ref_wide b)
{
	return 4 * a * a + (2 * b + 1) * (2 * b + 1) > 4 * (ref_wide)r * r;
}

bool rdc_ref_circle_has(uint32_t r, int64_t x, int64_t y)
{
	/* the octant 0 <= a <= b that (x, y) folds onto */
	int64_t a = RDC_MIN(ref_abs(x), ref_abs(y));
	int64_t b = RDC_MAX(ref_abs(x), ref_abs(y));

	/* column a takes the least b >= 0 whose upper midpoint is outside */
	return ref_circle_above_out(r, a, b) &&
	       (b == 0 || !ref_circle_above_out(r, a, b - 1));
}

bool rdc_ref_circle_fill_has(uint32_t r, int64_t x, int64_t y)
{
	int64_t a;

	/* between the outline's extreme pixels of the row */
	for (a = r; a >= ref_abs(x); a--)
		if (rdc_ref_circle_has(r, a, y))
			return true;
	return false;
}

void rdc_ref_circle(int32_t cx, int32_t cy, uint32_t r, bool fill,
		    rdc_ref_plot_fn plot, void *ctx)
{
	int64_t x, y, n = r;

	for (y = -n; y <= n; y++)
		for (x = -n; x <= n; x++)
			if (fill ? rdc_ref_circle_fill_has(r, x, y) :
				   rdc_ref_circle_has(r, x, y))
				plot(ctx, cx + (int32_t)x, cy + (int32_t)y);
}

void rdc_ref_ellipse(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
		     bool fill, rdc_ref_plot_fn plot, void *ctx)
{
	int64_t x, y;

	for (y = -(int64_t)ry; y <= (int64_t)ry; y++)
		for (x = -(int64_t)rx; x <= (int64_t)rx; x++)
			if (fill ? rdc_ref_ellipse_fill_has(rx, ry, x, y) :
				   rdc_ref_ellipse_has(rx, ry, x, y))
				plot(ctx, cx + (int32_t)x, cy + (int32_t)y);
}
