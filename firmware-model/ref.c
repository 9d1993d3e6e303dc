// SPDX-License-Identifier: GPL-2.0-only
/*
 * Reference rasterisers (see ref.h).  Written for obviousness: each is the
 * textbook loop, plotting every pixel, symmetric points included twice
 * where the symmetry makes them coincide.
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

static void ref_hline(int32_t xa, int32_t xb, int32_t y, rdc_ref_plot_fn plot,
		      void *ctx)
{
	int32_t x;

	for (x = xa; x <= xb; x++)
		plot(ctx, x, y);
}

/* The four points (+-a, +-b); a fill covers the row between them. */
static void plot4(int32_t cx, int32_t cy, int32_t a, int32_t b, bool fill,
		  rdc_ref_plot_fn plot, void *ctx)
{
	if (fill) {
		ref_hline(cx - a, cx + a, cy + b, plot, ctx);
		ref_hline(cx - a, cx + a, cy - b, plot, ctx);
		return;
	}
	plot(ctx, cx + a, cy + b);
	plot(ctx, cx - a, cy + b);
	plot(ctx, cx + a, cy - b);
	plot(ctx, cx - a, cy - b);
}

/*
 * Midpoint circle in closed form: in the octant 0 <= x <= y, column x takes
 * the row y whose lower midpoint (x, y - 1/2) lies inside the circle and
 * whose upper midpoint (x, y + 1/2) does not, i.e. the least y >= 0 with
 * 4x^2 + (2y + 1)^2 > 4r^2 (never equal: the left side is odd).
 */
void rdc_ref_circle(int32_t cx, int32_t cy, uint32_t r, bool fill,
		    rdc_ref_plot_fn plot, void *ctx)
{
	int64_t x, y = r, rr4 = 4 * (int64_t)r * r;

	for (x = 0;; x++) {
		while (y > 0 && 4 * x * x + (2 * y - 1) * (2 * y - 1) > rr4)
			y--;
		if (x > y)
			break;
		plot4(cx, cy, (int32_t)x, (int32_t)y, fill, plot, ctx);
		plot4(cx, cy, (int32_t)y, (int32_t)x, fill, plot, ctx);
	}
}

/*
 * Midpoint ellipse, two regions (Hearn and Baker), the decision
 * parameters multiplied by 4 to keep them integers.
 */
void rdc_ref_ellipse(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
		     bool fill, rdc_ref_plot_fn plot, void *ctx)
{
	int64_t a2 = (int64_t)rx * rx, b2 = (int64_t)ry * ry;
	int64_t x = 0, y = ry, p;

	if (rx == 0 || ry == 0) {
		rdc_ref_line(cx - (int32_t)rx, cy - (int32_t)ry,
			     cx + (int32_t)rx, cy + (int32_t)ry, plot, ctx);
		return;
	}
	/* region 1: slope magnitude below 1, x steps every time */
	p = 4 * b2 - 4 * a2 * ry + a2;
	plot4(cx, cy, 0, (int32_t)y, fill, plot, ctx);
	while (b2 * x < a2 * y) {
		x++;
		if (p < 0) {
			p += 4 * b2 * (2 * x + 1);
		} else {
			y--;
			p += 4 * b2 * (2 * x + 1) - 8 * a2 * y;
		}
		plot4(cx, cy, (int32_t)x, (int32_t)y, fill, plot, ctx);
	}
	/* region 2: y steps every time */
	p = b2 * (2 * x + 1) * (2 * x + 1) + 4 * a2 * (y - 1) * (y - 1) -
	    4 * a2 * b2;
	while (y > 0) {
		y--;
		if (p > 0) {
			p += 4 * a2 - 8 * a2 * y;
		} else {
			x++;
			p += 4 * a2 - 8 * a2 * y + 8 * b2 * x;
		}
		plot4(cx, cy, (int32_t)x, (int32_t)y, fill, plot, ctx);
	}
}
