// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * CONVOLVE: a 3x3 convolution blit from SRC to DST (smoothing,
 * sharpening, Sobel edges).
 *
 * Each channel is filtered in its own width (5:6:5, 8:8:8, or the index
 * of an indexed format).  Taps outside the SRC surface take the nearest
 * edge pixel (clamp to edge).  The SRC rows are held three at a time,
 * each read once as one span, and the destination is walked away from
 * the source (bottom up when it lies below), so an overlapping or
 * in-place filter reads only pixels it has not yet written.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "img_int.h"

static const int32_t sobel_x[9] = { -1, 0, 1, -2, 0, 2, -1, 0, 1 };
static const int32_t sobel_y[9] = { -1, -2, -1, 0, 0, 0, 1, 2, 1 };

struct conv {
	const struct rdc_surface *src;
	int32_t sx, w; /* columns [sx, sx + w) of SRC */
	int32_t k[9];
	int64_t div;
	int32_t bias;
	uint32_t mode, abs;
	struct img_chan ch[3];
	uint32_t nch, keep; /* channels; bits outside them (the X byte) */
};

/* floor(n / d) for d > 0 */
static int64_t floor_div(int64_t n, int64_t d)
{
	return n >= 0 ? n / d : -((-n + d - 1) / d);
}

/*
 * SRC row `row` (inside the surface) in one of the three slots: slot i
 * holds columns sx - 1 .. sx + w, the ends clamped to the surface.  The
 * slot taken is one whose row is not in need[].
 */
static uint32_t *conv_row(struct rdc_dp *dp, const struct conv *cv, int32_t row,
			  const int32_t *need)
{
	struct rdc_dp_img *im = &dp->img;
	int32_t xa = RDC_MAX(cv->sx - 1, 0);
	int32_t xb = RDC_MIN(cv->sx + cv->w + 1, (int32_t)cv->src->width);
	uint32_t i, slot = 0, *buf;

	for (i = 0; i < 3; i++)
		if (im->conv_row[i] == row)
			return im->u.conv[i];
	for (i = 0; i < 3; i++) {
		if (im->conv_row[i] != need[0] && im->conv_row[i] != need[1] &&
		    im->conv_row[i] != need[2]) {
			slot = i;
			break;
		}
	}
	buf = im->u.conv[slot];
	im->conv_row[slot] = row;
	if (!rdc_dp_read_row(dp, cv->src, row, xa, (uint32_t)(xb - xa),
			     buf + (xa - (cv->sx - 1))))
		return NULL;
	if (cv->sx == 0)
		buf[0] = buf[1];
	if (cv->sx + cv->w == (int32_t)cv->src->width)
		buf[cv->w + 1] = buf[cv->w];
	return buf;
}

static uint32_t conv_pixel(const struct conv *cv, uint32_t *const *rows,
			   int32_t i)
{
	uint32_t c, out = rows[1][i + 1] & cv->keep, m, t;
	int64_t s, gx, gy, v;
	uint32_t tap[9];

	for (c = 0; c < cv->nch; c++) {
		m = (1u << cv->ch[c].bits) - 1;
		for (t = 0; t < 9; t++)
			tap[t] = rows[t / 3][i + (int32_t)(t % 3)] >>
					 cv->ch[c].shift &
				 m;
		if (cv->mode == RDC_CONV_SOBEL) {
			gx = 0;
			gy = 0;
			for (t = 0; t < 9; t++) {
				gx += sobel_x[t] * (int64_t)tap[t];
				gy += sobel_y[t] * (int64_t)tap[t];
			}
			s = (gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy);
		} else {
			s = 0;
			for (t = 0; t < 9; t++)
				s += cv->k[t] * (int64_t)tap[t];
			if (cv->abs && s < 0)
				s = -s;
		}
		/* s / div rounded to nearest, halves up; then the bias */
		v = floor_div(2 * s + cv->div, 2 * cv->div) + cv->bias;
		v = v < 0 ? 0 : v > m ? m : v;
		out |= (uint32_t)v << cv->ch[c].shift;
	}
	return out;
}

uint32_t dp_cmd_convolve(struct rdc_dp *dp, uint32_t fl, uint32_t len,
			 const uint32_t *a)
{
	const struct rdc_surface *src = &dp->st.src, *dst = &dp->st.dst;
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	const struct img_chan *ch;
	int32_t sx, sy, dx, dy, w, h, d, j, jj, i, n, need[3];
	uint32_t *rows[3], scale, t, r;
	struct conv cv;

	cv.mode = fl & RDC_CONV_MODE;
	cv.abs = fl & RDC_CONV_ABS;
	if ((fl & ~(RDC_CONV_MODE | RDC_CONV_ABS)) ||
	    cv.mode > RDC_CONV_SOBEL || (cv.mode == RDC_CONV_SOBEL && cv.abs))
		return RDC_ERR_ARG;
	if (len != (cv.mode == RDC_CONV_KERNEL ? RDC_CONV_KERNEL_WORDS :
						 RDC_CONV_SOBEL_WORDS))
		return RDC_ERR_LENGTH;
	sx = RDC_X(a[0]);
	sy = RDC_Y(a[0]);
	dx = RDC_X(a[1]);
	dy = RDC_Y(a[1]);
	w = (int32_t)RDC_W(a[2]);
	h = (int32_t)RDC_H(a[2]);
	if (sx < RDC_COORD_MIN || sx > RDC_COORD_MAX || sy < RDC_COORD_MIN ||
	    sy > RDC_COORD_MAX || dx < RDC_COORD_MIN || dx > RDC_COORD_MAX ||
	    dy < RDC_COORD_MIN || dy > RDC_COORD_MAX ||
	    w > (int32_t)RDC_IMG_MAX_WIDTH || h > RDC_SIZE_MAX)
		return RDC_ERR_RANGE;
	if (cv.mode == RDC_CONV_KERNEL) {
		for (r = 0; r < 3; r++) {
			if (a[3 + r] >> 24)
				return RDC_ERR_ARG;
			for (t = 0; t < 3; t++)
				cv.k[3 * r + t] =
					(int8_t)(uint8_t)(a[3 + r] >> (8 * t));
		}
	}
	scale = a[len - 1];
	cv.div = FIELD_GET(RDC_CONV_DIV, scale);
	cv.bias = (int16_t)FIELD_GET(RDC_CONV_BIAS, scale);
	if (!cv.div)
		return RDC_ERR_ARG;
	if (src->format != dst->format)
		return RDC_ERR_ARG;

	/* the source rectangle on SRC and the destination in the clip */
	if (sx < 0) {
		dx -= sx;
		w += sx;
		sx = 0;
	}
	if (sy < 0) {
		dy -= sy;
		h += sy;
		sy = 0;
	}
	w = RDC_MIN(w, (int32_t)src->width - sx);
	h = RDC_MIN(h, (int32_t)src->height - sy);
	if (dx < c.x0) {
		d = c.x0 - dx;
		sx += d;
		dx += d;
		w -= d;
	}
	if (dy < c.y0) {
		d = c.y0 - dy;
		sy += d;
		dy += d;
		h -= d;
	}
	w = RDC_MIN(w, c.x1 - dx);
	h = RDC_MIN(h, c.y1 - dy);
	if (w <= 0 || h <= 0)
		return RDC_ERR_NONE;

	cv.src = src;
	cv.sx = sx;
	cv.w = w;
	ch = img_channels(src->format, &cv.nch);
	if (ch) {
		for (t = 0; t < cv.nch; t++)
			cv.ch[t] = ch[t];
		cv.keep = ~((1u << (ch[0].shift + ch[0].bits)) - 1);
	} else {
		cv.nch = 1;
		cv.ch[0].shift = 0;
		cv.ch[0].bits = rdc_format_bpp(src->format);
		cv.keep = 0;
	}
	for (t = 0; t < 3; t++)
		dp->img.conv_row[t] = -1;

	for (jj = 0; jj < h; jj++) {
		/* away from the source: bottom up when DST lies below it */
		j = dy > sy ? h - 1 - jj : jj;
		need[0] = RDC_MAX(sy + j - 1, 0);
		need[1] = sy + j;
		need[2] = RDC_MIN(sy + j + 1, (int32_t)src->height - 1);
		for (t = 0; t < 3; t++) {
			rows[t] = conv_row(dp, &cv, need[t], need);
			if (!rows[t])
				return RDC_ERR_SURFACE;
		}
		for (i = 0; i < w; i += n) {
			n = RDC_MIN(w - i, (int32_t)RDC_DP_CHUNK);
			for (d = 0; d < n; d++)
				dp->px[d] = conv_pixel(&cv, rows, i + d);
			rdc_dp_span_px(dp, dy + j, dx + i, (uint32_t)n, 0,
				       dp->px, NULL);
		}
	}
	return RDC_ERR_NONE;
}
