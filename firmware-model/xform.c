// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The transform unit: a homogeneous 3x3 matrix in signed 15.16 fixed point
 * applied to the vertices of the geometric primitives, and the
 * window-to-viewport command that builds one.
 *
 * Vertices are integers, the matrix entries 15.16, so the numerators and
 * the denominator w of the projective division are all 15.16 and their
 * quotient is in pixels.  Products of a 32-bit entry and a 16-bit
 * coordinate fit 48 bits; three of them summed fit 64 bits with room.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define XF_ONE (1 << 16) /* 1.0 in 15.16 */
/*
 * Widest input coordinate dp_xform accepts: keeps |entry * coordinate| below
 * 2^51, so three such terms cannot overflow 64 bits.
 */
#define XF_IN_MAX (1 << 20)
/* int32_t's range, spelled out: the kernel has no XF_S32_MAX */
#define XF_S32_MAX ((int64_t)0x7fffffff)
#define XF_S32_MIN (-XF_S32_MAX - 1)

void dp_xform_reset(struct rdc_dp_state *st)
{
	rdc_memset(st->xf, 0, sizeof(st->xf));
	st->xf[0][0] = XF_ONE;
	st->xf[1][1] = XF_ONE;
	st->xf[2][2] = XF_ONE;
	st->xf_identity = true;
}

static bool xf_is_identity(const int32_t m[3][3])
{
	int r, c;

	for (r = 0; r < 3; r++)
		for (c = 0; c < 3; c++)
			if (m[r][c] != (r == c ? XF_ONE : 0))
				return false;
	return true;
}

bool dp_xform(const struct rdc_dp *dp, int32_t *x, int32_t *y)
{
	const int32_t(*m)[3] = dp->st.xf;
	int64_t px = *x, py = *y, w, nx, ny, rx, ry;

	if (dp->st.xf_identity)
		return *x >= RDC_COORD_MIN && *x <= RDC_COORD_MAX &&
		       *y >= RDC_COORD_MIN && *y <= RDC_COORD_MAX;
	if (px < -XF_IN_MAX || px > XF_IN_MAX || py < -XF_IN_MAX ||
	    py > XF_IN_MAX)
		return false;
	w = m[2][0] * px + m[2][1] * py + m[2][2];
	if (w <= 0)
		return false;
	nx = m[0][0] * px + m[0][1] * py + m[0][2];
	ny = m[1][0] * px + m[1][1] * py + m[1][2];
	rx = dp_div_round(nx, w);
	ry = dp_div_round(ny, w);
	if (rx < RDC_COORD_MIN || rx > RDC_COORD_MAX || ry < RDC_COORD_MIN ||
	    ry > RDC_COORD_MAX)
		return false;
	*x = (int32_t)rx;
	*y = (int32_t)ry;
	return true;
}

/* |m| * v in pixels, rounded; false past RDC_SIZE_MAX. */
static bool scale_size(int32_t m, uint32_t *v)
{
	int64_t s = m < 0 ? -(int64_t)m : m;
	int64_t r = dp_div_round(s * *v, XF_ONE);

	if (r > RDC_SIZE_MAX)
		return false;
	*v = (uint32_t)r;
	return true;
}

bool dp_xform_size(const struct rdc_dp *dp, uint32_t *w, uint32_t *h)
{
	uint32_t sw = *w, sh = *h;

	if (dp->st.xf_identity)
		return *w <= RDC_SIZE_MAX && *h <= RDC_SIZE_MAX;
	if (!scale_size(dp->st.xf[0][0], &sw) ||
	    !scale_size(dp->st.xf[1][1], &sh))
		return false;
	*w = sw;
	*h = sh;
	return true;
}

uint32_t dp_cmd_set_transform(struct rdc_dp *dp, uint32_t len,
			      const uint32_t *a)
{
	int r, c;

	if (len == 0) {
		dp_xform_reset(&dp->st);
		return RDC_ERR_NONE;
	}
	if (len != 9)
		return RDC_ERR_LENGTH;
	for (r = 0; r < 3; r++)
		for (c = 0; c < 3; c++)
			dp->st.xf[r][c] = (int32_t)a[r * 3 + c];
	dp->st.xf_identity = xf_is_identity(dp->st.xf);
	return RDC_ERR_NONE;
}

/*
 * One axis of the window-to-viewport map: world w0 goes to pixel v0 and w1
 * to pixel v1, so scale = (v1 - v0) / (w1 - w0) and offset = v0 - scale *
 * w0, both in 15.16.  w0/w1 are 15.16 themselves, hence the extra 2^16.
 */
static bool vp_axis(int32_t w0, int32_t w1, int32_t v0, int32_t v1,
		    int32_t *scale, int32_t *offset)
{
	int64_t dw = (int64_t)w1 - w0, s, o;

	if (dw < 0) {
		dw = -dw;
		s = dp_div_round(-((int64_t)v1 - v0) * XF_ONE * XF_ONE, dw);
	} else {
		s = dp_div_round(((int64_t)v1 - v0) * XF_ONE * XF_ONE, dw);
	}
	if (s < XF_S32_MIN || s > XF_S32_MAX)
		return false;
	o = (int64_t)v0 * XF_ONE - dp_div_round(s * w0, XF_ONE);
	if (o < XF_S32_MIN || o > XF_S32_MAX)
		return false;
	*scale = (int32_t)s;
	*offset = (int32_t)o;
	return true;
}

uint32_t dp_cmd_set_viewport(struct rdc_dp *dp, uint32_t len, const uint32_t *a)
{
	int32_t wx0 = (int32_t)a[0], wy0 = (int32_t)a[1];
	int32_t wx1 = (int32_t)a[2], wy1 = (int32_t)a[3];
	int32_t sx, ox, sy, oy;

	if (len != 6)
		return RDC_ERR_LENGTH;
	if (RDC_X(a[4]) < RDC_COORD_MIN || RDC_X(a[4]) > RDC_COORD_MAX ||
	    RDC_Y(a[4]) < RDC_COORD_MIN || RDC_Y(a[4]) > RDC_COORD_MAX ||
	    RDC_X(a[5]) < RDC_COORD_MIN || RDC_X(a[5]) > RDC_COORD_MAX ||
	    RDC_Y(a[5]) < RDC_COORD_MIN || RDC_Y(a[5]) > RDC_COORD_MAX)
		return RDC_ERR_RANGE;
	if (wx0 == wx1 || wy0 == wy1)
		return RDC_ERR_ARG;
	/*
	 * World y grows upwards, screen y downwards: the window's bottom edge
	 * wy0 lands on the viewport's bottom row y1.
	 */
	if (!vp_axis(wx0, wx1, RDC_X(a[4]), RDC_X(a[5]), &sx, &ox) ||
	    !vp_axis(wy0, wy1, RDC_Y(a[5]), RDC_Y(a[4]), &sy, &oy))
		return RDC_ERR_RANGE;
	rdc_memset(dp->st.xf, 0, sizeof(dp->st.xf));
	dp->st.xf[0][0] = sx;
	dp->st.xf[0][2] = ox;
	dp->st.xf[1][1] = sy;
	dp->st.xf[1][2] = oy;
	dp->st.xf[2][2] = XF_ONE;
	dp->st.xf_identity = xf_is_identity(dp->st.xf);
	return RDC_ERR_NONE;
}

bool dp_xform_vec(const struct rdc_dp *dp, int32_t *x, int32_t *y)
{
	const int32_t(*m)[3] = dp->st.xf;
	int64_t vx = *x, vy = *y, rx, ry;

	if (dp->st.xf_identity)
		return true;
	if (m[2][2] <= 0 || vx < -XF_IN_MAX || vx > XF_IN_MAX ||
	    vy < -XF_IN_MAX || vy > XF_IN_MAX)
		return false;
	rx = dp_div_round(m[0][0] * vx + m[0][1] * vy, m[2][2]);
	ry = dp_div_round(m[1][0] * vx + m[1][1] * vy, m[2][2]);
	if (rx < -XF_IN_MAX || rx > XF_IN_MAX || ry < -XF_IN_MAX ||
	    ry > XF_IN_MAX)
		return false;
	*x = (int32_t)rx;
	*y = (int32_t)ry;
	return true;
}
