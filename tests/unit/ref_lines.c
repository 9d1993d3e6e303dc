// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Reference stroker pieces and arcs.  The convex fill tests each pixel
 * centre against edge functions (the fast path walks scan-line crossings);
 * the arc tests each pixel of the bounding box against the ellipse's
 * inequality (ref.c) and orders its direction against the end points by
 * exact cross products (the fast path intersects half-planes), with the
 * end points from a sine table of its own.
 */
#include "ref_lines.h"
#include "rdc_regs.h"

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
				if (e < 0 || (e == 0 &&
					      !(nx > 0 || (nx == 0 && ny > 0))))
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
 * sin(i / 1024 turn) by its Taylor series in double precision (no libm, so
 * nothing is shared with the DP's table): T(i) rounded to 16.16.
 */
static int64_t rl_table(uint32_t i)
{
	const double pi = 3.14159265358979323846;
	double x = pi * i / 512.0, term = x, sum = 0;
	int k;

	for (k = 1; k < 40; k += 2) {
		sum += term;
		term *= -x * x / ((k + 1) * (k + 2));
	}
	return (int64_t)(sum * 65536.0 + 0.5);
}

int64_t rdc_ref_sin(uint32_t a)
{
	/* a = 64 i + f in the first quarter, the others by symmetry */
	uint32_t quarter = (a >> 14) & 3, r = a & 0x3fff, i, f;
	int64_t t0, v;

	if (quarter == 1 || quarter == 3)
		r = 0x4000 - r;
	i = r / 64;
	f = r % 64;
	t0 = rl_table(i);
	v = f ? t0 + ((rl_table(i + 1) - t0) * (int64_t)f + 32) / 64 : t0;
	return quarter >= 2 ? -v : v;
}

typedef __int128 rl_wide;

static rl_wide rl_wcross(rl_wide ax, rl_wide ay, rl_wide bx, rl_wide by)
{
	return ax * by - ay * bx;
}

struct rl_arc {
	int64_t sx, sy, ex, ey; /* end points, y up, 1/16384 pixel */
	uint32_t sweep;
};

static void rl_arc_ends(struct rl_arc *r, uint32_t rx, uint32_t ry,
			uint32_t start, uint32_t end)
{
	/* truncated towards zero, as C's division does */
	r->sx = (int64_t)rx * rdc_ref_sin(start + 0x4000) / 4;
	r->sy = (int64_t)ry * rdc_ref_sin(start) / 4;
	r->ex = (int64_t)rx * rdc_ref_sin(end + 0x4000) / 4;
	r->ey = (int64_t)ry * rdc_ref_sin(end) / 4;
	r->sweep = (end - start) & 0xffff;
}

/* 0 for directions in [0, pi) counter-clockwise from s, 1 for [pi, 2 pi) */
static int rl_half(const struct rl_arc *r, rl_wide x, rl_wide y)
{
	rl_wide c = rl_wcross(r->sx, r->sy, x, y);

	return !(c > 0 || (c == 0 && r->sx * x + r->sy * y > 0));
}

/* Is direction (x, y) != 0 at most as far round from s as e is? */
static bool rl_not_past_end(const struct rl_arc *r, rl_wide x, rl_wide y)
{
	int hp = rl_half(r, x, y), he = rl_half(r, r->ex, r->ey);

	if (hp != he)
		return hp < he;
	return rl_wcross(r->ex, r->ey, x, y) <= 0;
}

/*
 * docs/commands.md's rule where the end points' rounding and the sweep
 * disagree: two half-planes, intersected up to half a turn (and cut to
 * s's side of the centre below it), joined above.
 */
static bool rl_half_planes(const struct rl_arc *r, rl_wide x, rl_wide y)
{
	bool a = rl_wcross(r->sx, r->sy, x, y) >= 0;
	bool b = rl_wcross(x, y, r->ex, r->ey) >= 0;

	if (r->sweep > 0x8000)
		return a || b;
	if (r->sweep < 0x8000 && rl_wcross(r->sx, r->sy, r->ex, r->ey) <= 0 &&
	    r->sx * x + r->sy * y < 0)
		return false;
	return a && b;
}

bool rdc_ref_arc_generic(uint32_t rx, uint32_t ry, uint32_t start, uint32_t end)
{
	struct rl_arc r;
	rl_wide c;

	rl_arc_ends(&r, rx, ry, start, end);
	c = rl_wcross(r.sx, r.sy, r.ex, r.ey);
	if (!r.sweep || !rx || !ry) /* (no sector, or nothing drawn) */
		return true;
	if (r.sweep < 0x8000)
		return c > 0;
	if (r.sweep == 0x8000)
		return c > 0 || (c == 0 && r.sx * r.ex + r.sy * r.ey < 0);
	return c < 0;
}

void rdc_ref_arc(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
		 uint32_t start, uint32_t end, uint32_t mode,
		 rdc_ref_plot_fn plot, void *ctx)
{
	bool generic = rdc_ref_arc_generic(rx, ry, start, end);
	struct rl_arc r;
	int64_t x, y;

	if (!rx || !ry)
		return;
	rl_arc_ends(&r, rx, ry, start, end);
	for (y = -(int64_t)ry; y <= (int64_t)ry; y++) {
		for (x = -(int64_t)rx; x <= (int64_t)rx; x++) {
			/* the pixel's centre, y up, on the end points' scale */
			rl_wide px = (rl_wide)x * 16384,
				py = -(rl_wide)y * 16384;
			bool in;

			if (mode == RDC_ARC_OUTLINE ?
				    !rdc_ref_ellipse_has(rx, ry, x, y) :
				    !rdc_ref_ellipse_fill_has(rx, ry, x, y))
				continue;
			if (!r.sweep)
				in = true;
			else if (mode == RDC_ARC_CHORD)
				in = rl_wcross(r.ex - r.sx, r.ey - r.sy,
					       px - r.sx, py - r.sy) <= 0;
			else if (!generic)
				in = rl_half_planes(&r, px, py);
			else /* the sector has its apex */
				in = (!x && !y) || rl_not_past_end(&r, px, py);
			if (in)
				plot(ctx, cx + (int32_t)x, cy + (int32_t)y);
		}
	}
}
