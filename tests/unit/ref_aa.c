// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Anti-aliasing reference rasterisers (see ref_aa.h).  The coverage is
 * computed afresh from the definition, exactly, in 128-bit integers.
 */
#include "ref_aa.h"

typedef unsigned __int128 ref_u128;

/* Distances are in 1/REF_COV_ONE pixel. */
#define REF_COV_ONE 256u

/*
 * d = |F| / |grad F| with F and the gradient's square exact in 128 bits:
 * the largest k with k |grad F| <= 256 |F| is the largest k with
 * k^2 (grad F)^2 <= 65536 F^2, found by bisection on k in 0..256.
 */
uint32_t rdc_ref_aa_ellipse_cov(uint32_t rx, uint32_t ry, uint32_t x,
				uint32_t y)
{
	__int128 rx2 = (__int128)rx * rx, ry2 = (__int128)ry * ry, f;
	ref_u128 gx, gy, g2, f2;
	uint32_t lo = 0, hi = REF_COV_ONE;

	if (!rx || !ry || x > rx + 1 || y > ry + 1)
		return 0;
	f = (__int128)x * x * ry2 + (__int128)y * y * rx2 - rx2 * ry2;
	gx = 2 * (ref_u128)x * (ref_u128)ry2;
	gy = 2 * (ref_u128)y * (ref_u128)rx2;
	g2 = gx * gx + gy * gy;
	f2 = (ref_u128)(f * f);
	/* at the centre of a degenerate gradient, or a pixel away: none */
	if (!g2 || f2 >= g2)
		return 0;
	/* now f2 < g2 < 2^90, so 65536 f2 fits */
	while (lo < hi) {
		uint32_t k = (lo + hi + 1) / 2;

		if ((ref_u128)k * k * g2 <= 65536 * f2)
			lo = k;
		else
			hi = k - 1;
	}
	return ((REF_COV_ONE - lo) * RDC_AA_FULL + REF_COV_ONE / 2) /
	       REF_COV_ONE;
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
			uint32_t cov = rdc_ref_aa_ellipse_cov(
				rx, ry, (uint32_t)(x < 0 ? -x : x),
				(uint32_t)(y < 0 ? -y : y));

			if (cov)
				plot(ctx, cx + x, cy + y, cov);
		}
	}
}
