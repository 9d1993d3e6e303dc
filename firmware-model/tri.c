// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Triangles, flat or Gouraud shaded, with an optional 16-bit depth buffer.
 *
 * A triangle covers exactly the pixels FILL_POLYGON gives its three
 * vertices (same scan conversion, same top-left rule), so triangles that
 * share an edge cover each pixel once.  Colour channels (the index in
 * indexed formats) and depth are interpolated linearly over the plane of
 * the three vertices and sampled exactly at each pixel centre:
 *
 *   a(px, py) = a0 + round(((a1 - a0) (X (y2 - y0) - (x2 - x0) Y)
 *                           + (a2 - a0) ((x1 - x0) Y - X (y1 - y0)))
 *                          / (2 area2)),
 *   X = 2 px + 1 - 2 x0,  Y = 2 py + 1 - 2 y0,
 *   area2 = (x1 - x0) (y2 - y0) - (x2 - x0) (y1 - y0),
 *
 * in 64-bit integers, stepped along the row, and clamped to the vertices'
 * range.
 *
 * Depth: the depth surface holds 16-bit little-endian values at
 * z_base + y * z_stride + 2 x for DST pixel (x, y).  With RDC_Z_TEST a
 * pixel is drawn only where its z is below the stored one; with
 * RDC_Z_WRITE a drawn pixel stores its z.  Each run of at most
 * RDC_DP_CHUNK pixels costs one depth span (read for TEST, write for
 * WRITE, read-modify-write for both) and, if any pixel passes, one DST
 * span (read-modify-write when only some pass).
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define TRI_VERTS DP_TRI_VERTS
#define TRI_WORDS 3 /* xy, colour, z */
#define Z_MAX	  0xffffu
#define Z_BYTES	  2u
#define CH_MAX	  DP_TRI_CH_MAX

static bool zbuf_fits(const struct rdc_dp *dp, uint32_t base, uint32_t stride)
{
	const struct rdc_surface *d = &dp->st.dst;
	uint64_t row = (uint64_t)d->width * Z_BYTES;

	return stride >= row &&
	       (uint64_t)base + (uint64_t)(d->height - 1) * stride + row <=
		       dp->hw->vram_size;
}

uint32_t dp_cmd_set_zbuf(struct rdc_dp *dp, uint32_t flags, uint32_t len,
			 const uint32_t *a)
{
	if (flags & ~(RDC_Z_TEST | RDC_Z_WRITE))
		return RDC_ERR_ARG;
	if (len == 0) {
		if (flags)
			return RDC_ERR_ARG;
		dp->st.z_base = 0;
		dp->st.z_stride = 0;
		dp->st.z_flags = 0;
		return RDC_ERR_NONE;
	}
	if (len != 2)
		return RDC_ERR_LENGTH;
	if (!zbuf_fits(dp, a[0], a[1]))
		return RDC_ERR_SURFACE;
	dp->st.z_base = a[0];
	dp->st.z_stride = a[1];
	dp->st.z_flags = flags;
	return RDC_ERR_NONE;
}

uint32_t dp_cmd_clear_z(struct rdc_dp *dp, const uint32_t *a)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	const struct rdc_dp_state *st = &dp->st;
	int32_t y;

	if (a[0] > Z_MAX)
		return RDC_ERR_RANGE;
	if (!st->z_stride || !zbuf_fits(dp, st->z_base, st->z_stride))
		return RDC_ERR_SURFACE;
	if (c.x0 >= c.x1)
		return RDC_ERR_NONE;
	for (y = c.y0; y < c.y1; y++) {
		uint32_t n = (uint32_t)(c.x1 - c.x0), i;
		uint8_t *p =
			rdc_port_span(dp->hw,
				      st->z_base + (uint32_t)y * st->z_stride +
					      (uint32_t)c.x0 * Z_BYTES,
				      n * Z_BYTES, RDC_BUS_WRITE);

		if (!p)
			continue;
		for (i = 0; i < n; i++)
			rdc_st16(p + i * Z_BYTES, a[0]);
	}
	return RDC_ERR_NONE;
}

/* Channel layout of DST: (shift, width) per colour channel. */
static unsigned int channels(unsigned int fmt, unsigned int *shift,
			     unsigned int *width)
{
	static const unsigned int s565[3] = { 11, 5, 0 }, w565[3] = { 5, 6, 5 };
	static const unsigned int s888[3] = { 16, 8, 0 }, w888[3] = { 8, 8, 8 };
	unsigned int i;

	if (rdc_format_indexed(fmt)) {
		shift[0] = 0;
		width[0] = rdc_format_bpp(fmt);
		return 1;
	}
	for (i = 0; i < 3; i++) {
		shift[i] = fmt == RDC_FMT_RGB565 ? s565[i] : s888[i];
		width[i] = fmt == RDC_FMT_RGB565 ? w565[i] : w888[i];
	}
	return 3;
}

/* Channel k's plane numerator at the centre of pixel (px, py). */
static int64_t plane_num(const struct dp_tri *t, unsigned int k, int32_t px,
			 int32_t py)
{
	int64_t X = 2 * (int64_t)px + 1 - 2 * (int64_t)t->x[0];
	int64_t Y = 2 * (int64_t)py + 1 - 2 * (int64_t)t->y[0];
	int64_t ex1 = (int64_t)t->x[1] - t->x[0],
		ey1 = (int64_t)t->y[1] - t->y[0];
	int64_t ex2 = (int64_t)t->x[2] - t->x[0],
		ey2 = (int64_t)t->y[2] - t->y[0];

	return t->d1[k] * (X * ey2 - ex2 * Y) + t->d2[k] * (ex1 * Y - X * ey1);
}

static int64_t plane_step(const struct dp_tri *t, unsigned int k)
{
	int64_t ey1 = (int64_t)t->y[1] - t->y[0];
	int64_t ey2 = (int64_t)t->y[2] - t->y[0];

	return 2 * (t->d1[k] * ey2 - t->d2[k] * ey1);
}

static void tri_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb,
		     void *ctx)
{
	const struct dp_tri *t = ctx;
	const struct rdc_dp_state *st = &dp->st;
	uint32_t *zv = dp->flood_row[0];
	int64_t num[CH_MAX], step[CH_MAX];
	unsigned int k, zk = t->nch - 1;
	int32_t x;

	for (k = 0; k < t->nch; k++) {
		num[k] = plane_num(t, k, xa, y);
		step[k] = plane_step(t, k);
	}
	for (x = xa; x <= xb; x += (int32_t)RDC_DP_CHUNK) {
		uint32_t n = (uint32_t)RDC_MIN((int64_t)xb - x + 1,
					       (int64_t)RDC_DP_CHUNK);
		uint32_t i, pass = n;
		bool zon = st->z_stride && (t->ztest || t->zwrite);

		for (i = 0; i < n; i++) {
			uint32_t c = 0;

			for (k = 0; k < t->nch; k++) {
				int64_t v = t->a0[k] +
					    dp_div_round(num[k], 2 * t->area2);

				v = RDC_MAX(v, t->lo[k]);
				v = RDC_MIN(v, t->hi[k]);
				num[k] += step[k];
				if (k == zk)
					zv[i] = (uint32_t)v;
				else
					c |= (uint32_t)v << t->shift[k];
			}
			dp->px[i] = t->gouraud ? c : t->flat;
			dp->on[i] = 1;
		}
		if (zon) {
			unsigned int kind = t->ztest && t->zwrite ?
						    RDC_BUS_RMW :
					    t->ztest ? RDC_BUS_READ :
						       RDC_BUS_WRITE;
			uint8_t *p = rdc_port_span(
				dp->hw,
				st->z_base + (uint32_t)y * st->z_stride +
					(uint32_t)x * Z_BYTES,
				n * Z_BYTES, kind);

			if (!p)
				continue;
			for (i = 0; i < n; i++) {
				uint8_t *q = p + i * Z_BYTES;

				if (t->ztest && zv[i] >= rdc_ld16(q)) {
					dp->on[i] = 0;
					pass--;
					continue;
				}
				if (t->zwrite)
					rdc_st16(q, zv[i]);
			}
		}
		if (!pass)
			continue;
		rdc_dp_span_px(dp, y, x, n, 0, dp->px,
			       pass == n ? NULL : dp->on);
	}
}

bool dp_zbuf_ready(const struct rdc_dp *dp)
{
	const struct rdc_dp_state *st = &dp->st;

	return !(st->z_stride && st->z_flags) ||
	       zbuf_fits(dp, st->z_base, st->z_stride);
}

void dp_tri_draw(struct rdc_dp *dp, const int32_t *x, const int32_t *y,
		 const uint32_t *col, const uint32_t *z, bool gouraud)
{
	int32_t *xy = dp->poly_xy;
	struct dp_tri t;
	unsigned int i;

	if (!dp_tri_setup(dp, x, y, col, z, gouraud, &t))
		return; /* no pixel centre inside */
	for (i = 0; i < TRI_VERTS; i++) {
		xy[2 * i] = x[i];
		xy[2 * i + 1] = y[i];
	}
	dp_poly_scan(dp, xy, TRI_VERTS, false, tri_span, &t);
}

bool dp_tri_setup(const struct rdc_dp *dp, const int32_t *x, const int32_t *y,
		  const uint32_t *col, const uint32_t *z, bool gouraud,
		  struct dp_tri *t)
{
	const struct rdc_dp_state *st = &dp->st;
	unsigned int k, i;

	for (i = 0; i < TRI_VERTS; i++) {
		t->x[i] = x[i];
		t->y[i] = y[i];
	}
	t->gouraud = gouraud;
	t->ztest = st->z_flags & RDC_Z_TEST;
	t->zwrite = st->z_flags & RDC_Z_WRITE;
	t->flat = col[0];
	t->area2 = ((int64_t)t->x[1] - t->x[0]) * ((int64_t)t->y[2] - t->y[0]) -
		   ((int64_t)t->x[2] - t->x[0]) * ((int64_t)t->y[1] - t->y[0]);
	if (!t->area2)
		return false;
	t->nch = channels(st->dst.format, t->shift, t->width) + 1;
	for (k = 0; k < t->nch; k++) {
		int64_t v[TRI_VERTS];

		for (i = 0; i < TRI_VERTS; i++) {
			if (k + 1 == t->nch)
				v[i] = z[i];
			else
				v[i] = (col[i] >> t->shift[k]) &
				       ((1u << t->width[k]) - 1);
		}
		t->a0[k] = v[0];
		t->d1[k] = v[1] - v[0];
		t->d2[k] = v[2] - v[0];
		t->lo[k] = RDC_MIN(RDC_MIN(v[0], v[1]), v[2]);
		t->hi[k] = RDC_MAX(RDC_MAX(v[0], v[1]), v[2]);
	}
	return true;
}

/* The same values tri_span steps to, taken at one pixel. */
static int64_t sample(const struct dp_tri *t, unsigned int k, int32_t px,
		      int32_t py)
{
	int64_t v =
		t->a0[k] + dp_div_round(plane_num(t, k, px, py), 2 * t->area2);

	v = RDC_MAX(v, t->lo[k]);
	return RDC_MIN(v, t->hi[k]);
}

uint32_t dp_tri_depth(const struct dp_tri *t, int32_t px, int32_t py)
{
	return (uint32_t)sample(t, t->nch - 1, px, py);
}

uint32_t dp_tri_pixel(const struct dp_tri *t, int32_t px, int32_t py)
{
	uint32_t c = 0;
	unsigned int k;

	if (!t->gouraud)
		return t->flat;
	for (k = 0; k + 1 < t->nch; k++)
		c |= (uint32_t)sample(t, k, px, py) << t->shift[k];
	return c;
}

uint32_t dp_cmd_triangle(struct rdc_dp *dp, uint32_t flags, const uint32_t *a)
{
	unsigned int bpp = rdc_format_bpp(dp->st.dst.format), i;
	uint32_t mask = bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
	int32_t tx[TRI_VERTS], ty[TRI_VERTS];
	uint32_t col[TRI_VERTS], z[TRI_VERTS];

	if (flags & ~RDC_TRI_GOURAUD)
		return RDC_ERR_ARG;
	for (i = 0; i < TRI_VERTS; i++) {
		const uint32_t *v = a + i * TRI_WORDS;
		int32_t x = RDC_X(v[0]), y = RDC_Y(v[0]);

		if (x < RDC_COORD_MIN || x > RDC_COORD_MAX ||
		    y < RDC_COORD_MIN || y > RDC_COORD_MAX || v[2] > Z_MAX ||
		    !dp_xform(dp, &x, &y))
			return RDC_ERR_RANGE;
		tx[i] = x;
		ty[i] = y;
		col[i] = v[1] & mask;
		z[i] = v[2];
	}
	if (!dp_zbuf_ready(dp))
		return RDC_ERR_SURFACE;
	dp_tri_draw(dp, tx, ty, col, z, flags & RDC_TRI_GOURAUD);
	return RDC_ERR_NONE;
}
