// SPDX-License-Identifier: GPL-2.0-only
/*
 * Reference stroker pieces and arcs.  The convex fill tests each pixel
 * centre against edge functions (the fast path walks scan-line crossings);
 * the arc orders directions by a pseudo-angle compared as exact fractions
 * (the fast path intersects half-planes by cross products).
 */
#include "ref_lines.h"
#include "dp_int.h"

static int64_t rl_cross(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
	return ax * by - ay * bx;
}

void rdc_ref_convex(const int64_t *xy, uint32_t n, unsigned int frac,
		    rdc_ref_plot_fn plot, void *ctx)
{
	int64_t one = (int64_t)1 << frac, area = 0, x0, y0, x1, y1, x, y;
	uint32_t i;

	if (n < 3)
		return;
	x0 = x1 = xy[0];
	y0 = y1 = xy[1];
	for (i = 0; i < n; i++) {
		const int64_t *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);

		area += rl_cross(a[0], a[1], b[0], b[1]);
		x0 = RDC_MIN(x0, a[0]);
		x1 = RDC_MAX(x1, a[0]);
		y0 = RDC_MIN(y0, a[1]);
		y1 = RDC_MAX(y1, a[1]);
	}
	if (!area)
		return;
	for (y = y0 / one - 1; y <= y1 / one + 1; y++) {
		for (x = x0 / one - 1; x <= x1 / one + 1; x++) {
			bool in = true;

			for (i = 0; i < n && in; i++) {
				const int64_t *a = xy + 2 * i;
				const int64_t *b = xy + 2 * ((i + 1) % n);
				int64_t dx = b[0] - a[0], dy = b[1] - a[1];
				int64_t e = rl_cross(dx, dy, x * one - a[0],
						     y * one - a[1]);
				/* inward normal (nx, ny) = s (-dy, dx) */
				int64_t nx = area > 0 ? -dy : dy;
				int64_t ny = area > 0 ? dx : -dx;

				if (area < 0)
					e = -e;
				if (e < 0 || (e == 0 && !(nx > 0 ||
							  (nx == 0 && ny > 0))))
					in = false;
			}
			if (in)
				plot(ctx, (int32_t)x, (int32_t)y);
		}
	}
}

void rdc_ref_dash_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
		       uint32_t bits, uint32_t len, uint32_t offset,
		       rdc_ref_plot_fn plot, void *ctx)
{
	int32_t adx = x1 > x0 ? x1 - x0 : x0 - x1;
	int32_t ady = y1 > y0 ? y1 - y0 : y0 - y1;
	int64_t n = RDC_MAX(adx, ady), i;
	bool xmajor = adx >= ady && adx > 0;
	bool rev = (xmajor && x1 < x0) || (!xmajor && y1 < y0);
	int32_t sx = x0, sy = y0, ex = x1, ey = y1;

	/* the canonical start, as the line itself picks it */
	if (rev) {
		sx = x1;
		sy = y1;
		ex = x0;
		ey = y0;
	}
	for (i = 0; i <= n; i++) {
		/*
		 * step i of the canonical line, i.e. step n - i from (x0, y0)
		 * when reversed: j(i) = floor((2 i m + n) / (2 n))
		 */
		int64_t k = rev ? n - i : i, j, m, u, v;

		if (len && !((bits >> ((uint64_t)(k + offset) % len)) & 1))
			continue;
		if (xmajor) {
			m = ey > sy ? ey - sy : sy - ey;
			j = n ? (2 * i * m + n) / (2 * n) : 0;
			u = sx + i;
			v = sy + (ey >= sy ? j : -j);
		} else {
			m = ex > sx ? ex - sx : sx - ex;
			j = n ? (2 * i * m + n) / (2 * n) : 0;
			v = sy + i;
			u = sx + (ex >= sx ? j : -j);
		}
		plot(ctx, (int32_t)u, (int32_t)v);
	}
}

/*
 * Pseudo-angle of (x, y), y up, as quadrant q and fraction num / den in [0, 1):
 * monotone in the true angle.
 */
struct rl_angle {
	int q;
	int64_t num, den;
};

static struct rl_angle rl_pseudo(int64_t x, int64_t y)
{
	struct rl_angle a;

	if (y >= 0 && x > 0) {
		a.q = 0;
		a.num = y;
		a.den = x + y;
	} else if (x <= 0 && y > 0) {
		a.q = 1;
		a.num = -x;
		a.den = -x + y;
	} else if (y <= 0 && x < 0) {
		a.q = 2;
		a.num = -y;
		a.den = -x - y;
	} else {
		a.q = 3;
		a.num = x;
		a.den = x - y;
	}
	return a;
}

/* -1, 0, 1 as a is before, with, after b */
static int rl_cmp(struct rl_angle a, struct rl_angle b)
{
	int64_t l, r;

	if (a.q != b.q)
		return a.q < b.q ? -1 : 1;
	l = a.num * b.den;
	r = b.num * a.den;
	return l < r ? -1 : l > r;
}

struct rl_arc {
	rdc_ref_plot_fn plot;
	void *ctx;
	int32_t cx, cy;
	uint32_t mode;
	bool full;
	int64_t sx, sy, ex, ey;
	struct rl_angle as, ae;
};

static void rl_arc_plot(void *p, int32_t x, int32_t y)
{
	struct rl_arc *r = p;
	/* the vectors' scale: 2^14 per pixel, as the end points */
	int64_t dx = (int64_t)(x - r->cx) * (1 << 14);
	int64_t dy = -(int64_t)(y - r->cy) * (1 << 14);
	struct rl_angle a;
	bool in;

	if (r->full) {
		in = true;
	} else if (r->mode == RDC_ARC_CHORD) {
		in = rl_cross(r->ex - r->sx, r->ey - r->sy, dx - r->sx,
			      dy - r->sy) <= 0;
	} else if (!dx && !dy) {
		in = true;
	} else {
		a = rl_pseudo(dx, dy);
		if (rl_cmp(r->as, r->ae) <= 0)
			in = rl_cmp(r->as, a) <= 0 && rl_cmp(a, r->ae) <= 0;
		else
			in = rl_cmp(r->as, a) <= 0 || rl_cmp(a, r->ae) <= 0;
	}
	if (in)
		r->plot(r->ctx, x, y);
}

void rdc_ref_arc(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
		 uint32_t start, uint32_t end, uint32_t mode,
		 rdc_ref_plot_fn plot, void *ctx)
{
	struct rl_arc r = { plot, ctx, cx, cy, mode, false, 0, 0, 0, 0,
			    { 0, 0, 1 }, { 0, 0, 1 } };

	if (!rx || !ry)
		return;
	start &= 0xffff;
	end &= 0xffff;
	r.full = start == end;
	r.sx = (int64_t)rx * dp_cos(start) / 4;
	r.sy = (int64_t)ry * dp_sin(start) / 4;
	r.ex = (int64_t)rx * dp_cos(end) / 4;
	r.ey = (int64_t)ry * dp_sin(end) / 4;
	r.as = rl_pseudo(r.sx, r.sy);
	r.ae = rl_pseudo(r.ex, r.ey);
	rdc_ref_ellipse(cx, cy, rx, ry, mode != RDC_ARC_OUTLINE, rl_arc_plot,
			&r);
}
