// SPDX-License-Identifier: GPL-2.0-only
/*
 * Anti-aliasing coverage and reference rasterisers (see ref_aa.h).
 */
#include "ref_aa.h"

/* The largest value whose square a uint64_t holds, plus one. */
#define ISQRT_TOP_BIT (1ull << 62)
/* Gradient components are shrunk below this so their squares add up. */
#define COV_GRAD_BITS 31
/* Distances are in 1/COV_ONE pixel. */
#define COV_ONE 256u

uint64_t rdc_aa_isqrt(uint64_t v)
{
	uint64_t r = 0, bit = ISQRT_TOP_BIT;

	while (bit > v)
		bit >>= 2;
	while (bit) {
		if (v >= r + bit) {
			v -= r + bit;
			r = (r >> 1) + bit;
		} else {
			r >>= 1;
		}
		bit >>= 2;
	}
	return r;
}

uint32_t rdc_aa_ellipse_cov(uint32_t rx, uint32_t ry, uint32_t x, uint32_t y)
{
	int64_t rx2 = (int64_t)rx * rx, ry2 = (int64_t)ry * ry, f;
	uint64_t gx, gy, g, af, d;
	unsigned int k = 0;

	if (!rx || !ry || x > rx + 1 || y > ry + 1)
		return 0;
	/* |terms| < 2^57 for radii up to RDC_SIZE_MAX + 1 */
	f = (int64_t)x * x * ry2 + (int64_t)y * y * rx2 - rx2 * ry2;
	/* grad F / 2 = (x ry^2, y rx^2); its length from shrunk parts */
	gx = (uint64_t)x * (uint64_t)ry2;
	gy = (uint64_t)y * (uint64_t)rx2;
	while ((gx | gy) >> COV_GRAD_BITS) {
		gx >>= 1;
		gy >>= 1;
		k++;
	}
	g = rdc_aa_isqrt(gx * gx + gy * gy) << k;
	if (!g)
		return 0;
	af = (uint64_t)(f < 0 ? -f : f);
	/* d = |F| / (2 g) pixels; from 1 pixel on, no coverage */
	if (af >= 2 * g)
		return 0;
	d = af * (COV_ONE / 2) / g;
	return (uint32_t)(((COV_ONE - d) * RDC_AA_FULL + COV_ONE / 2) /
			  COV_ONE);
}

void rdc_ref_aa_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
		     rdc_ref_aa_fn plot, void *ctx)
{
	int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
	int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
	bool xmajor = adx >= ady && adx > 0;
	int64_t n = xmajor ? adx : ady, m = xmajor ? ady : adx, i;
	int64_t sv;

	if ((xmajor && dx < 0) || (!xmajor && dy < 0)) {
		rdc_ref_aa_line(x1, y1, x0, y0, plot, ctx);
		return;
	}
	sv = xmajor ? (dy < 0 ? -1 : 1) : (dx < 0 ? -1 : 1);
	for (i = 0; i <= n; i++) {
		int64_t j = n ? i * m / n : 0, r = n ? i * m % n : 0;
		uint32_t f = n ? (uint32_t)((RDC_AA_FULL * r + n / 2) / n) : 0;
		int32_t u = (xmajor ? x0 : y0) + (int32_t)i;
		int32_t v = (xmajor ? y0 : x0) + (int32_t)(sv * j);
		int32_t w = v + (int32_t)sv;

		if (RDC_AA_FULL - f) {
			if (xmajor)
				plot(ctx, u, v, RDC_AA_FULL - f);
			else
				plot(ctx, v, u, RDC_AA_FULL - f);
		}
		if (f) {
			if (xmajor)
				plot(ctx, u, w, f);
			else
				plot(ctx, w, u, f);
		}
	}
}

void rdc_ref_aa_ellipse(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
			rdc_ref_aa_fn plot, void *ctx)
{
	int32_t x, y, bx = (int32_t)rx + 1, by = (int32_t)ry + 1;

	if (!rx || !ry) {
		rdc_ref_aa_line(cx - (int32_t)rx, cy - (int32_t)ry,
				cx + (int32_t)rx, cy + (int32_t)ry, plot, ctx);
		return;
	}
	for (y = -by; y <= by; y++) {
		for (x = -bx; x <= bx; x++) {
			uint32_t cov = rdc_aa_ellipse_cov(
				rx, ry, (uint32_t)(x < 0 ? -x : x),
				(uint32_t)(y < 0 ? -y : y));

			if (cov)
				plot(ctx, cx + x, cy + y, cov);
		}
	}
}
