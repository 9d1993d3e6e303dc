// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Illumination (Foley & van Dam 16.1-16.2), per vertex or per face, in
 * world coordinates and fixed point:
 *
 *   I = Ia ka + sum over lights Ip (kd (N . L) + ks (R . V)^n)
 *
 * per channel, with Ia the ambient light and Ip a directional light's
 * colour (0..255), ka, kd, ks the material's reflectances (0..255 for
 * 0..1), N the unit normal, L the unit direction towards the light, R = 2
 * (N . L) N - L its mirror direction and V the unit direction towards
 * the viewer (from the point to the centre of projection, or the
 * parallel view's constant one).  A light with N . L <= 0 adds nothing;
 * the specular term needs R . V > 0.  Two-sided lighting turns N towards
 * the viewer first.  Cosines are taken to 16 fractional bits, the power
 * by squaring with a rounding per product (within 2^-12 of the exact
 * power for every n <= 255); the sum is exact in 64 bits and rounded once
 * to 0..255, clamped.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "geom3d_int.h"

#define L_FRAC	     16
#define L_ONE	     (1 << L_FRAC)
#define L_CH(rgb, k) (((rgb) >> (16 - 8 * (k))) & 0xffu)

static int64_t udot(const int32_t *a, const int32_t *b)
{
	return (int64_t)a[0] * b[0] + (int64_t)a[1] * b[1] +
	       (int64_t)a[2] * b[2];
}

/* a 2.30 x 2.30 dot product as a 16-bit fraction, rounded */
static int64_t cos16(const int32_t *a, const int32_t *b)
{
	int64_t d = udot(a, b);
	int64_t h = (int64_t)1 << (2 * G3_UNIT_SHIFT - L_FRAC - 1);

	return (d + h) >> (2 * G3_UNIT_SHIFT - L_FRAC);
}

static int64_t pow16(int64_t x, uint32_t n)
{
	int64_t r = L_ONE;

	while (n) {
		if (n & 1)
			r = (r * x + L_ONE / 2) >> L_FRAC;
		n >>= 1;
		if (n)
			x = (x * x + L_ONE / 2) >> L_FRAC;
	}
	return r;
}

uint32_t g3_light(const struct rdc_dp *dp, const int32_t *pw, const int32_t *n,
		  bool two_sided)
{
	const struct rdc_dp_3d *g = &dp->g3;
	int64_t acc[3], t[3];
	int32_t v[3], nn[3];
	uint32_t out = 0;
	int i, k;

	if (g->persp) {
		for (i = 0; i < 3; i++)
			t[i] = (int64_t)g->eye[i] - pw[i];
		if (!g3_normalize(t, v))
			rdc_memcpy(v, n, sizeof(v));
	} else {
		rdc_memcpy(v, g->eye, sizeof(v));
	}
	rdc_memcpy(nn, n, sizeof(nn));
	if (two_sided && udot(nn, v) < 0)
		for (i = 0; i < 3; i++)
			nn[i] = -nn[i];
	for (k = 0; k < 3; k++)
		acc[k] = (int64_t)L_CH(g->ambient, k) * L_CH(g->mat_amb, k) *
			 L_ONE;
	for (i = 0; i < RDC_LIGHTS; i++) {
		const struct rdc_dp_light *l = &g->light[i];
		int64_t nl, rv, s = 0;
		int32_t r[3];
		int j;

		if (!l->on)
			continue;
		nl = cos16(nn, l->dir);
		if (nl <= 0)
			continue;
		nl = RDC_MIN(nl, (int64_t)L_ONE);
		if (g->mat_spec) {
			/* |R| is 1: the difference fits, its terms may not */
			for (j = 0; j < 3; j++)
				r[j] = (int32_t)(((2 * nl * nn[j]) >> L_FRAC) -
						 l->dir[j]);
			rv = cos16(r, v);
			if (rv > 0)
				s = pow16(RDC_MIN(rv, (int64_t)L_ONE),
					  g->mat_shine);
		}
		for (k = 0; k < 3; k++)
			acc[k] += (int64_t)L_CH(l->rgb, k) *
				  ((int64_t)L_CH(g->mat_diff, k) * nl +
				   (int64_t)L_CH(g->mat_spec, k) * s);
	}
	for (k = 0; k < 3; k++) {
		int64_t c = g3_div_round(acc[k], (int64_t)255 * L_ONE);

		out |= (uint32_t)RDC_MIN(RDC_MAX(c, (int64_t)0), (int64_t)255)
		       << (16 - 8 * k);
	}
	return out;
}

uint32_t g3_light_cycles(const struct rdc_dp *dp)
{
	uint32_t c = RDC_T_LIGHT3;
	int i;

	for (i = 0; i < RDC_LIGHTS; i++)
		if (dp->g3.light[i].on)
			c += RDC_T_LIGHT3_EACH;
	return c;
}

uint32_t g3_pixel(const struct rdc_dp *dp, uint32_t rgb)
{
	unsigned int fmt = dp->st.dst.format, bpp = rdc_format_bpp(fmt);
	uint32_t r = L_CH(rgb, 0), gr = L_CH(rgb, 1), b = L_CH(rgb, 2);
	uint32_t mask = bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
	uint32_t lum, k;

	if (fmt == RDC_FMT_RGB565)
		return ((r * 31 + 127) / 255) << 11 |
		       ((gr * 63 + 127) / 255) << 5 | ((b * 31 + 127) / 255);
	if (!rdc_format_indexed(fmt))
		return rgb & 0xffffffu;
	/* indexed: the AA ramp from FG (brightest) to FG + ramp - 1 */
	lum = (77 * r + 150 * gr + 29 * b + 128) >> 8;
	k = ((255 - lum) * (dp->st.aa_ramp - 1) + 127) / 255;
	return (dp->st.fg + k) & mask;
}
