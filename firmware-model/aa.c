// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Anti-aliased lines (Wu), circles and ellipses.
 *
 * Each pixel gets an 8-bit coverage (docs/commands.md defines it) and is mixed
 * with what VRAM already holds: in RGB formats FG is blended over the
 * destination with weight coverage / 255 per channel; in indexed formats
 * the pixel takes the CLUT index FG + k from a ramp of SET_AA_RAMP
 * entries, FG itself at full coverage and FG + ramp - 1 at the faintest
 * (the ramp is meant to run from the FG colour to the background).  The
 * result then goes through the ROP with the destination, as any FG does.
 *
 * Pixels are produced in runs along a row (one RDC_BUS_RMW span each) or a
 * column (one rdc_port_column each), trimmed of uncovered ends, so the bus
 * charges whole bursts.  The tests hold per-pixel reference versions
 * (tests/unit/ref_aa.c).
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define RDC_AA_FULL 255u /* coverage of a pixel the shape covers fully */
/* Gradient components are shrunk below this so their squares add up. */
#define COV_GRAD_BITS 31
/* Distances are in 1/COV_ONE pixel. */
#define COV_ONE 256u

/*
 * Coverage of the pixel at offset (x, y) >= 0 from the centre of the
 * ellipse with radii rx, ry >= 1 (docs/commands.md): a tent of the
 * pixel's distance d to the curve, 255 * (1 - d) rounded (0 from d = 1
 * on), with d the first-order (Sampson) distance |F| / |grad F| of
 * F = x^2 ry^2 + y^2 rx^2 - rx^2 ry^2, exact for circles, in 1/256 pixel.
 * Pixels outside |x| <= rx + 1, |y| <= ry + 1 have no coverage.  The
 * gradient is scaled, up or down, to 31 bits a component before its
 * length is taken, so |grad F| has 30 good bits however small the radii.
 */
static uint32_t aa_ellipse_cov(uint32_t rx, uint32_t ry, uint32_t x, uint32_t y)
{
	int64_t rx2 = (int64_t)rx * rx, ry2 = (int64_t)ry * ry, f;
	uint64_t gx, gy, num, den, d;
	unsigned int down = 0, up = 0;

	if (!rx || !ry || x > rx + 1 || y > ry + 1)
		return 0;
	/* |terms| < 2^57 for radii up to RDC_SIZE_MAX + 1 */
	f = (int64_t)x * x * ry2 + (int64_t)y * y * rx2 - rx2 * ry2;
	/* grad F / 2 = (x ry^2, y rx^2) */
	gx = (uint64_t)x * (uint64_t)ry2;
	gy = (uint64_t)y * (uint64_t)rx2;
	if (!(gx | gy))
		return 0;
	while ((gx | gy) >> COV_GRAD_BITS) {
		gx >>= 1;
		gy >>= 1;
		down++;
	}
	while (!((gx | gy) >> (COV_GRAD_BITS - 1))) {
		gx <<= 1;
		gy <<= 1;
		up++;
	}
	/* d = |F| / (2 |grad F / 2|) = num / (2 den) pixels */
	num = (uint64_t)(f < 0 ? -f : f);
	/* scaled up, |grad F / 2| was below 2^31: d >= 1 for |F| >= 2^32 */
	if (up && num >> 32)
		return 0;
	num <<= up;
	den = dp_isqrt(gx * gx + gy * gy) << down;
	/* from 1 pixel on, no coverage */
	if (num >= 2 * den)
		return 0;
	d = num * (COV_ONE / 2) / den;
	return (uint32_t)(((COV_ONE - d) * RDC_AA_FULL + COV_ONE / 2) /
			  COV_ONE);
}

uint32_t rdc_dp_blend(unsigned int fmt, uint32_t src, uint32_t dst, uint32_t a)
{
	/* channel fields (shift, width), most significant first */
	static const uint8_t f565[][2] = { { 11, 5 }, { 5, 6 }, { 0, 5 } };
	static const uint8_t f888[][2] = {
		{ 24, 8 }, { 16, 8 }, { 8, 8 }, { 0, 8 }
	};
	const uint8_t(*f)[2];
	unsigned int n, i;
	uint32_t r = 0;

	switch (fmt) {
	case RDC_FMT_RGB565:
		f = f565, n = RDC_ARRAY_SIZE(f565);
		break;
	case RDC_FMT_RGB888:
		f = f888 + 1, n = RDC_ARRAY_SIZE(f888) - 1;
		break;
	case RDC_FMT_XRGB8888:
		/* the X byte is mixed as a fourth channel */
		f = f888, n = RDC_ARRAY_SIZE(f888);
		break;
	default:
		return a >= RDC_ALPHA_THRESHOLD ? src : dst;
	}
	for (i = 0; i < n; i++) {
		uint32_t m = (1u << f[i][1]) - 1;
		uint32_t s = (src >> f[i][0]) & m, d = (dst >> f[i][0]) & m;

		r |= ((s * a + d * (RDC_ALPHA_OPAQUE - a) +
		       RDC_ALPHA_OPAQUE / 2) /
		      RDC_ALPHA_OPAQUE)
		     << f[i][0];
	}
	return r;
}

static uint32_t fmt_mask(unsigned int bpp)
{
	return bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
}

/* The value a pixel of coverage cov (1..255) over d becomes. */
static uint32_t aa_value(const struct rdc_dp *dp, uint32_t cov, uint32_t d,
			 uint32_t mask)
{
	const struct rdc_dp_state *st = &dp->st;
	uint32_t v;

	if (rdc_format_indexed(st->dst.format))
		v = st->fg + ((RDC_AA_FULL - cov) * (st->aa_ramp - 1) +
			      RDC_AA_FULL / 2) /
				     RDC_AA_FULL;
	else
		v = rdc_dp_blend(st->dst.format, st->fg, d, cov);
	return rdc_rop_apply(st->rop, v & mask, d) & mask;
}

/*
 * rdc_dp_blend's mix of two 8-bit channels at once, in the 16-bit lanes of
 * a word (LANES): each lane's s a + d (255 - a) + 127 is at most 65152,
 * so nothing carries between lanes, and for x <= 65152 the quotient
 * x / 255 is exactly (x + 1 + (x >> 8)) >> 8 (checked for every such x).
 */
#define LANES	 0x00ff00ffu
#define LANE_ONE 0x00010001u

static inline uint32_t blend_lanes(uint32_t s, uint32_t d, uint32_t a)
{
	uint32_t x = s * a + d * (RDC_ALPHA_OPAQUE - a) +
		     (RDC_ALPHA_OPAQUE / 2) * LANE_ONE;

	return ((x + LANE_ONE + ((x >> 8) & LANES)) >> 8) & LANES;
}

/*
 * aa_value for XRGB8888, the common case: rdc_dp_blend's four 8-bit
 * channels (X included) two at a time, then the ROP.  Same arithmetic
 * (tests compare it with rdc_dp_blend through the per-pixel path).
 */
static inline uint32_t aa_value32(uint32_t fg, unsigned int rop, uint32_t cov,
				  uint32_t d)
{
	uint32_t v = blend_lanes(fg & LANES, d & LANES, cov) |
		     blend_lanes((fg >> 8) & LANES, (d >> 8) & LANES, cov) << 8;

	return rdc_rop_apply(rop, v, d);
}

/* The pixels of a run at p, step bytes apart, in XRGB8888. */
static uint32_t aa_run32(const struct rdc_dp *dp, uint8_t *p, size_t step,
			 const uint8_t *cov, uint32_t n)
{
	uint32_t fg = dp->st.fg, i, cnt = 0;
	unsigned int rop = dp->st.rop;

	if (rop == RDC_ROP_COPY) { /* the ROP out of the loop */
		for (i = 0; i < n; i++, p += step) {
			if (!cov[i])
				continue;
			rdc_st32(p, aa_value32(fg, RDC_ROP_COPY, cov[i],
					       rdc_ld32(p)));
			cnt++;
		}
		return cnt;
	}
	for (i = 0; i < n; i++, p += step) {
		if (!cov[i])
			continue;
		rdc_st32(p, aa_value32(fg, rop, cov[i], rdc_ld32(p)));
		cnt++;
	}
	return cnt;
}

/*
 * How the bus sees a run of n pixels: a blend reads the destination; an
 * indexed ramp is a plain write unless the ROP reads the destination or
 * uncovered pixels inside the run must be kept.
 */
static unsigned int aa_kind(const struct rdc_dp *dp, const uint8_t *cov,
			    uint32_t n, bool head, bool tail)
{
	uint32_t i;

	if (!rdc_format_indexed(dp->st.dst.format) ||
	    rdc_rop_reads_dst(dp->st.rop))
		return RDC_BUS_RMW;
	for (i = 0; i < n; i++)
		if (!cov[i])
			return RDC_BUS_RMW;
	return RDC_BUS_WRITE | (head ? RDC_BUS_HEAD_PARTIAL : 0) |
	       (tail ? RDC_BUS_TAIL_PARTIAL : 0);
}

/* Pixels [xa, xa + n) of row y with coverages cov[], clipped here. */
static void aa_span(struct rdc_dp *dp, const struct rdc_rect *c, int32_t y,
		    int32_t xa, uint32_t n, const uint8_t *cov)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);
	uint32_t mask = fmt_mask(bpp), i, cnt = 0, first;
	int64_t lo = xa, hi = (int64_t)xa + n;
	uint64_t bit0, bit1;
	uint8_t *p;

	if (y < c->y0 || y >= c->y1)
		return;
	lo = RDC_MAX(lo, (int64_t)c->x0);
	hi = RDC_MIN(hi, (int64_t)c->x1);
	while (lo < hi && !cov[lo - xa])
		lo++;
	while (hi > lo && !cov[hi - 1 - xa])
		hi--;
	if (lo >= hi)
		return;
	cov += lo - xa;
	n = (uint32_t)(hi - lo);
	bit0 = (uint64_t)lo * bpp;
	bit1 = (uint64_t)hi * bpp;
	p = rdc_port_span(dp->hw,
			  s->base + (uint32_t)y * s->stride +
				  (uint32_t)(bit0 / 8),
			  (uint32_t)((bit1 + 7) / 8 - bit0 / 8),
			  aa_kind(dp, cov, n, bit0 & 7, bit1 & 7));
	if (!p)
		return;
	if (s->format == RDC_FMT_XRGB8888 && !dp->ref_paths) {
		dp->hw->perf.pixels += aa_run32(dp, p, 4, cov, n);
		return;
	}
	first = (uint32_t)(bit0 & 7);
	for (i = 0; i < n; i++) {
		uint32_t bit = first + i * bpp;

		if (!cov[i])
			continue;
		rdc_dp_px_store(p, bpp, bit,
				aa_value(dp, cov[i],
					 rdc_dp_px_load(p, bpp, bit), mask));
		cnt++;
	}
	dp->hw->perf.pixels += cnt;
}

/* Pixels [ya, ya + n) of column x with coverages cov[], clipped here. */
static void aa_col(struct rdc_dp *dp, const struct rdc_rect *c, int32_t x,
		   int32_t ya, uint32_t n, const uint8_t *cov)
{
	const struct rdc_surface *s = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(s->format);
	uint32_t mask = fmt_mask(bpp), i, cnt = 0, bit;
	int64_t lo = ya, hi = (int64_t)ya + n;
	bool sub = bpp < 8;
	uint8_t *p;

	if (x < c->x0 || x >= c->x1)
		return;
	lo = RDC_MAX(lo, (int64_t)c->y0);
	hi = RDC_MIN(hi, (int64_t)c->y1);
	while (lo < hi && !cov[lo - ya])
		lo++;
	while (hi > lo && !cov[hi - 1 - ya])
		hi--;
	if (lo >= hi)
		return;
	cov += lo - ya;
	n = (uint32_t)(hi - lo);
	bit = (uint32_t)x * bpp;
	p = rdc_port_column(dp->hw,
			    s->base + (uint32_t)lo * s->stride + bit / 8,
			    s->stride, n, (bpp + 7) / 8,
			    aa_kind(dp, cov, n, sub, sub));
	if (!p)
		return;
	if (s->format == RDC_FMT_XRGB8888 && !dp->ref_paths) {
		dp->hw->perf.pixels += aa_run32(dp, p, s->stride, cov, n);
		return;
	}
	for (i = 0; i < n; i++) {
		uint8_t *q = p + (size_t)i * s->stride;

		if (!cov[i])
			continue;
		rdc_dp_px_store(q, bpp, bit & 7,
				aa_value(dp, cov[i],
					 rdc_dp_px_load(q, bpp, bit & 7),
					 mask));
		cnt++;
	}
	dp->hw->perf.pixels += cnt;
}

/*
 * Wu line, as docs/commands.md defines it.  Steps sharing the minor offset
 * j form two parallel runs (offsets j and j + 1) written when j changes, or
 * when RDC_DP_CHUNK steps have gathered.  The remainder i m mod n is carried
 * from step to step, so no error accumulates, and the major-axis clip
 * starts the loop at the first visible step with the exact remainder.
 */
static void aa_line(struct rdc_dp *dp, int32_t x0, int32_t y0, int32_t x1,
		    int32_t y1)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int64_t adx = x1 > x0 ? (int64_t)x1 - x0 : (int64_t)x0 - x1;
	int64_t ady = y1 > y0 ? (int64_t)y1 - y0 : (int64_t)y0 - y1;
	bool xmajor = adx >= ady && adx > 0;
	int64_t n, m, i, j, rem, run, ilo, ihi, cu0, cu1;
	int64_t fq = 0, fr = 0, dq = 0, dr = 0;
	int32_t u0, v0, sv;
	uint8_t *hi = dp->aa_cov[0], *lo = dp->aa_cov[1];
	uint32_t k = 0;

	if (c.x0 >= c.x1 || c.y0 >= c.y1)
		return;
	if ((xmajor && x1 < x0) || (!xmajor && y1 < y0)) {
		int32_t t;

		t = x0, x0 = x1, x1 = t;
		t = y0, y0 = y1, y1 = t;
	}
	if (xmajor) {
		u0 = x0, v0 = y0, n = adx, m = ady, sv = y1 < y0 ? -1 : 1;
		cu0 = c.x0, cu1 = c.x1 - 1;
	} else {
		u0 = y0, v0 = x0, n = ady, m = adx, sv = x1 < x0 ? -1 : 1;
		cu0 = c.y0, cu1 = c.y1 - 1;
	}
	ilo = RDC_MAX((int64_t)0, cu0 - u0);
	ihi = RDC_MIN(n, cu1 - u0);
	if (ilo > ihi)
		return;
	j = n ? ilo * m / n : 0;
	rem = n ? ilo * m % n : 0;
	/*
	 * f = (RDC_AA_FULL rem + n / 2) / n, carried as its quotient and
	 * remainder from step to step as rem is: the same values without a
	 * division a step.
	 */
	if (n) {
		fq = (RDC_AA_FULL * rem + n / 2) / n;
		fr = (RDC_AA_FULL * rem + n / 2) % n;
		dq = RDC_AA_FULL * m / n;
		dr = RDC_AA_FULL * m % n;
	}
	run = ilo;
	for (i = ilo; i <= ihi; i++) {
		uint32_t f = (uint32_t)fq;
		int64_t nj = j;

		hi[k] = (uint8_t)(RDC_AA_FULL - f);
		lo[k] = (uint8_t)f;
		k++;
		if (i < ihi) {
			rem += m;
			fq += dq;
			fr += dr;
			if (fr >= n) {
				fr -= n;
				fq++;
			}
			if (rem >= n) {
				rem -= n;
				fq -= RDC_AA_FULL;
				nj++;
			}
		}
		if (nj != j || i == ihi || k == RDC_DP_CHUNK) {
			int32_t va = v0 + sv * (int32_t)j,
				ua = u0 + (int32_t)run;

			if (xmajor) {
				aa_span(dp, &c, va, ua, k, hi);
				aa_span(dp, &c, va + sv, ua, k, lo);
			} else {
				aa_col(dp, &c, va, ua, k, hi);
				aa_col(dp, &c, va + sv, ua, k, lo);
			}
			run = i + 1;
			k = 0;
			j = nj;
		}
	}
}

/* Pixels cx + [a, b] of row y, at row offset t from the centre. */
static void aa_ell_span(struct rdc_dp *dp, const struct rdc_rect *c, int32_t y,
			int32_t cx, int32_t a, int32_t b, uint32_t rx,
			uint32_t ry, uint32_t t)
{
	int64_t xa = RDC_MAX((int64_t)cx + a, (int64_t)c->x0);
	int64_t xb = RDC_MIN((int64_t)cx + b, (int64_t)c->x1 - 1);
	uint8_t *cov = dp->aa_cov[0];

	while (xa <= xb) {
		uint32_t n = (uint32_t)RDC_MIN(xb - xa + 1,
					       (int64_t)RDC_DP_CHUNK),
			 i;

		for (i = 0; i < n; i++) {
			int64_t dx = xa + i - cx;

			cov[i] = (uint8_t)aa_ellipse_cov(
				rx, ry, (uint32_t)(dx < 0 ? -dx : dx), t);
		}
		aa_span(dp, c, y, (int32_t)xa, n, cov);
		xa += n;
	}
}

/*
 * AA ellipse (and circle) row by row.  Row offset t's covered pixels with
 * x >= 0 form one run around where the curve crosses the row (or around
 * x = 0 past the top), found by walking out from the crossing until the
 * coverage drops to 0; the run is mirrored to the left half (one span when
 * it reaches x = 0) and to row -t.  So each pixel is visited once.
 */
static void aa_ellipse(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t rx,
		       uint32_t ry)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int64_t rx2 = (int64_t)rx * rx, ry2 = (int64_t)ry * ry;
	uint32_t t;

	if (!rx || !ry) {
		aa_line(dp, cx - (int32_t)rx, cy - (int32_t)ry,
			cx + (int32_t)rx, cy + (int32_t)ry);
		return;
	}
	if (c.x0 >= c.x1 || c.y0 >= c.y1 || (int64_t)cx + rx + 1 < c.x0 ||
	    (int64_t)cx - rx - 1 >= c.x1 || (int64_t)cy + ry + 1 < c.y0 ||
	    (int64_t)cy - ry - 1 >= c.y1)
		return;
	for (t = 0; t <= ry + 1; t++) {
		int32_t rows[2] = { cy - (int32_t)t, cy + (int32_t)t };
		uint32_t xs = 0, xl, xr, r, nrows = t ? 2 : 1;

		if ((rows[0] < c.y0 || rows[0] >= c.y1) &&
		    (rows[1] < c.y0 || rows[1] >= c.y1))
			continue;
		if (t <= ry)
			xs = (uint32_t)dp_isqrt(
				(uint64_t)rx2 *
				(uint64_t)(ry2 - (int64_t)t * t) /
				(uint64_t)ry2);
		xs = RDC_MIN(xs, rx + 1);
		if (aa_ellipse_cov(rx, ry, xs, t)) {
			xl = xs;
			while (xl > 0 && aa_ellipse_cov(rx, ry, xl - 1, t))
				xl--;
		} else {
			xl = xs + 1;
		}
		xr = xs;
		while (xr <= rx && aa_ellipse_cov(rx, ry, xr + 1, t))
			xr++;
		if (xl > xr)
			continue;
		for (r = 0; r < nrows; r++) {
			if (!xl) {
				aa_ell_span(dp, &c, rows[r], cx, -(int32_t)xr,
					    (int32_t)xr, rx, ry, t);
				continue;
			}
			aa_ell_span(dp, &c, rows[r], cx, -(int32_t)xr,
				    -(int32_t)xl, rx, ry, t);
			aa_ell_span(dp, &c, rows[r], cx, (int32_t)xl,
				    (int32_t)xr, rx, ry, t);
		}
	}
}

uint32_t rdc_dp_aa_cmd(struct rdc_dp *dp, uint32_t op, const uint32_t *a)
{
	int32_t x0 = RDC_X(a[0]), y0 = RDC_Y(a[0]);
	int32_t x1 = RDC_X(a[1]), y1 = RDC_Y(a[1]);
	uint32_t rx, ry;

	switch (op) {
	case RDC_OP_AA_LINE:
		if (!dp_xform(dp, &x0, &y0) || !dp_xform(dp, &x1, &y1))
			return RDC_ERR_RANGE;
		aa_line(dp, x0, y0, x1, y1);
		return RDC_ERR_NONE;
	case RDC_OP_AA_CIRCLE:
		rx = a[1];
		ry = a[1];
		break;
	default:
		rx = RDC_W(a[1]);
		ry = RDC_H(a[1]);
		break;
	}
	if (rx > RDC_SIZE_MAX || ry > RDC_SIZE_MAX || !dp_xform(dp, &x0, &y0) ||
	    !dp_xform_size(dp, &rx, &ry))
		return RDC_ERR_RANGE;
	aa_ellipse(dp, x0, y0, rx, ry);
	return RDC_ERR_NONE;
}
