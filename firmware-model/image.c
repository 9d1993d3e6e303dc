// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Image processing on the display processor: HISTOGRAM, MAP_BUILD,
 * MAP_APPLY, MAP_CLUT and THRESHOLD, and the command entry of the image
 * commands (DECODE is in decode.c, CONVOLVE in filter.c).
 *
 * Point operations (the map, the threshold) read a DST row piece and
 * write it back through rdc_dp_span_px, so the ROP and the clip apply as
 * to any drawing.  Tables live in VRAM: the host or a HISTOGRAM writes
 * them, MAP_BUILD turns a histogram into a map, and the map is applied to
 * pixels (any format) or to the CLUT (indexed formats, grey images).
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"
#include "img_int.h"

/* ---- pixels and channels -------------------------------------------- */

static const struct img_chan img_rgb565[3] = { { 11, 5 }, { 5, 6 }, { 0, 5 } };
static const struct img_chan img_rgb888[3] = { { 16, 8 }, { 8, 8 }, { 0, 8 } };

const struct img_chan *img_channels(uint32_t fmt, uint32_t *n)
{
	*n = 3;
	if (fmt == RDC_FMT_RGB565)
		return img_rgb565;
	if (fmt == RDC_FMT_RGB888 || fmt == RDC_FMT_XRGB8888)
		return img_rgb888;
	*n = 0;
	return NULL;
}

uint32_t img_widen(uint32_t v, uint32_t bits)
{
	if (bits == 5)
		return v << 3 | v >> 2;
	if (bits == 6)
		return v << 2 | v >> 4;
	return v;
}

/* The 8-bit value HISTOGRAM and THRESHOLD see (RDC_CHAN_*). */
uint32_t img_intensity(uint32_t fmt, uint32_t px, uint32_t sel)
{
	const struct img_chan *c;
	uint32_t n, v[3], i;

	c = img_channels(fmt, &n);
	if (!c)
		return px;
	for (i = 0; i < 3; i++)
		v[i] = img_widen(px >> c[i].shift & ((1u << c[i].bits) - 1),
				 c[i].bits);
	if (sel != RDC_CHAN_LUMA)
		return v[sel - RDC_CHAN_RED];
	return (77 * v[0] + 150 * v[1] + 29 * v[2] + 128) >> 8;
}

/* 8-bit R, G, B to a pixel of fmt (RGB formats: truncated to 5:6:5). */
uint32_t img_pack_rgb(uint32_t fmt, uint32_t r, uint32_t g, uint32_t b)
{
	if (fmt == RDC_FMT_RGB565)
		return (r >> 3) << 11 | (g >> 2) << 5 | b >> 3;
	return r << 16 | g << 8 | b;
}

/* A table in VRAM: 4-aligned and inside it. */
static bool table_ok(const struct rdc_dp *dp, uint32_t addr, uint32_t bytes)
{
	return addr % 4 == 0 && (uint64_t)addr + bytes <= dp->hw->vram_size;
}

static bool read_table(struct rdc_dp *dp, uint32_t addr, uint8_t *out,
		       uint32_t bytes)
{
	const uint8_t *p = rdc_port_span(dp->hw, addr, bytes, RDC_BUS_READ);

	if (!p)
		return false;
	rdc_memcpy(out, p, bytes);
	return true;
}

/*
 * The rectangle [x, x + w) x [y, y + h) cut to the effective clip, as
 * [r->x0, r->x1) x [r->y0, r->y1); false when nothing is left.
 */
static bool dst_rect(const struct rdc_dp *dp, const uint32_t *a,
		     struct rdc_rect *r)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	int32_t x = RDC_X(a[0]), y = RDC_Y(a[0]);

	r->x0 = RDC_MAX(x, c.x0);
	r->y0 = RDC_MAX(y, c.y0);
	r->x1 = RDC_MIN(x + (int32_t)RDC_W(a[1]), c.x1);
	r->y1 = RDC_MIN(y + (int32_t)RDC_H(a[1]), c.y1);
	return r->x0 < r->x1 && r->y0 < r->y1;
}

static bool xy_wh_ok(const uint32_t *a)
{
	return RDC_X(a[0]) >= RDC_COORD_MIN && RDC_X(a[0]) <= RDC_COORD_MAX &&
	       RDC_Y(a[0]) >= RDC_COORD_MIN && RDC_Y(a[0]) <= RDC_COORD_MAX &&
	       RDC_W(a[1]) <= RDC_SIZE_MAX && RDC_H(a[1]) <= RDC_SIZE_MAX;
}

/* ---- HISTOGRAM ------------------------------------------------------- */

static uint32_t cmd_histogram(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	const struct rdc_surface *s = &dp->st.src;
	uint32_t sel = fl & RDC_CHAN_SEL, *hist = dp->img.hist, i, n;
	int32_t x0, x1, y0, y1, y, x;
	uint8_t *p;

	if (fl & ~(RDC_CHAN_SEL | RDC_HIST_ACCUM))
		return RDC_ERR_ARG;
	if (rdc_format_indexed(s->format) && sel != RDC_CHAN_LUMA)
		return RDC_ERR_ARG;
	if (!xy_wh_ok(a))
		return RDC_ERR_RANGE;
	if (!table_ok(dp, a[2], RDC_DP_HIST_BINS * 4))
		return RDC_ERR_RANGE;
	/* the rectangle on the SRC surface, as READBACK and BLIT see it */
	x0 = RDC_MAX(RDC_X(a[0]), 0);
	y0 = RDC_MAX(RDC_Y(a[0]), 0);
	x1 = RDC_MIN(RDC_X(a[0]) + (int32_t)RDC_W(a[1]), (int32_t)s->width);
	y1 = RDC_MIN(RDC_Y(a[0]) + (int32_t)RDC_H(a[1]), (int32_t)s->height);
	rdc_memset(hist, 0, RDC_DP_HIST_BINS * 4);
	for (y = y0; y < y1; y++) {
		for (x = x0; x < x1; x += (int32_t)n) {
			n = (uint32_t)RDC_MIN(x1 - x, (int32_t)RDC_DP_CHUNK);
			if (!rdc_dp_read_row(dp, s, y, x, n, dp->px))
				return RDC_ERR_SURFACE;
			for (i = 0; i < n; i++)
				hist[img_intensity(s->format, dp->px[i], sel) &
				     0xff]++;
		}
	}
	if (fl & RDC_HIST_ACCUM) {
		p = rdc_port_span(dp->hw, a[2], RDC_DP_HIST_BINS * 4,
				  RDC_BUS_RMW);
		if (!p)
			return RDC_ERR_RANGE;
		for (i = 0; i < RDC_DP_HIST_BINS; i++)
			rdc_st32(p + 4 * i, rdc_ld32(p + 4 * i) + hist[i]);
		return RDC_ERR_NONE;
	}
	p = rdc_port_span(dp->hw, a[2], RDC_DP_HIST_BINS * 4, RDC_BUS_WRITE);
	if (!p)
		return RDC_ERR_RANGE;
	for (i = 0; i < RDC_DP_HIST_BINS; i++)
		rdc_st32(p + 4 * i, hist[i]);
	return RDC_ERR_NONE;
}

/* ---- MAP_BUILD ------------------------------------------------------- */

static void map_stretch(uint8_t *map, uint32_t lo, uint32_t hi)
{
	uint32_t v;

	for (v = 0; v < RDC_DP_HIST_BINS; v++) {
		if (lo >= hi)
			map[v] = (uint8_t)v; /* nothing to stretch */
		else if (v <= lo)
			map[v] = 0;
		else if (v >= hi)
			map[v] = 255;
		else
			map[v] = (uint8_t)((255 * (v - lo) + (hi - lo) / 2) /
					   (hi - lo));
	}
}

static uint32_t cmd_map_build(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	uint32_t *hist = dp->img.hist, lo, hi, v;
	uint8_t *map = dp->img.map, *p;
	uint64_t n = 0, cdf = 0;

	if (fl >= RDC_MAP_MODE_COUNT)
		return RDC_ERR_ARG;
	if (fl == RDC_MAP_STRETCH &&
	    (a[2] > 0xffff || (a[2] & 0xff) >= a[2] >> 8))
		return RDC_ERR_ARG;
	if (fl == RDC_MAP_EQUALIZE && a[2])
		return RDC_ERR_ARG;
	if ((fl != RDC_MAP_STRETCH &&
	     !table_ok(dp, a[0], RDC_DP_HIST_BINS * 4)) ||
	    !table_ok(dp, a[1], RDC_DP_HIST_BINS))
		return RDC_ERR_RANGE;
	if (fl != RDC_MAP_STRETCH) {
		p = rdc_port_span(dp->hw, a[0], RDC_DP_HIST_BINS * 4,
				  RDC_BUS_READ);
		if (!p)
			return RDC_ERR_RANGE;
		for (v = 0; v < RDC_DP_HIST_BINS; v++) {
			hist[v] = rdc_ld32(p + 4 * v);
			n += hist[v];
		}
	}
	switch (fl) {
	case RDC_MAP_STRETCH:
		map_stretch(map, a[2] & 0xff, a[2] >> 8);
		break;
	case RDC_MAP_STRETCH_AUTO:
		lo = 0;
		hi = 0;
		for (v = RDC_DP_HIST_BINS; v-- > 0;)
			if (hist[v] > a[2])
				lo = v;
		for (v = 0; v < RDC_DP_HIST_BINS; v++)
			if (hist[v] > a[2])
				hi = v;
		map_stretch(map, lo, hi);
		break;
	default: /* RDC_MAP_EQUALIZE: s_k = (L - 1) sum_{j <= k} n_j / n */
		for (v = 0; v < RDC_DP_HIST_BINS; v++) {
			cdf += hist[v];
			map[v] = n ? (uint8_t)((255 * cdf + n / 2) / n) :
				     (uint8_t)v;
		}
		break;
	}
	p = rdc_port_span(dp->hw, a[1], RDC_DP_HIST_BINS, RDC_BUS_WRITE);
	if (!p)
		return RDC_ERR_RANGE;
	rdc_memcpy(p, map, RDC_DP_HIST_BINS);
	return RDC_ERR_NONE;
}

/* ---- MAP_APPLY, THRESHOLD: read a DST piece, write it back ------------- */

static uint32_t map_pixel(const uint8_t *map, uint32_t fmt, uint32_t px)
{
	const struct img_chan *c;
	uint32_t n, i, m, v, out;

	c = img_channels(fmt, &n);
	if (!c)
		return map[px & 0xff];
	out = px & ~((1u << (c[0].shift + c[0].bits)) - 1); /* X byte kept */
	for (i = 0; i < n; i++) {
		m = (1u << c[i].bits) - 1;
		v = map[img_widen(px >> c[i].shift & m, c[i].bits)];
		out |= (v >> (8 - c[i].bits)) << c[i].shift;
	}
	return out;
}

static uint32_t point_op(struct rdc_dp *dp, uint32_t op, uint32_t sel,
			 const uint32_t *a)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_rect r;
	uint32_t n, i, level = a[2];
	int32_t y, x;

	if (!dst_rect(dp, a, &r))
		return RDC_ERR_NONE;
	for (y = r.y0; y < r.y1; y++) {
		for (x = r.x0; x < r.x1; x += (int32_t)n) {
			n = (uint32_t)RDC_MIN(r.x1 - x, (int32_t)RDC_DP_CHUNK);
			if (!rdc_dp_read_px(dp, y, x, n, dp->px))
				return RDC_ERR_SURFACE;
			for (i = 0; i < n; i++) {
				if (op == RDC_OP_MAP_APPLY)
					dp->px[i] = map_pixel(dp->img.map,
							      s->format,
							      dp->px[i]);
				else
					dp->px[i] = img_intensity(s->format,
								  dp->px[i],
								  sel) >=
								    level ?
							    dp->st.fg :
							    dp->st.bg;
			}
			rdc_dp_span_px(dp, y, x, n, 0, dp->px, NULL);
		}
	}
	return RDC_ERR_NONE;
}

static uint32_t cmd_map_apply(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	if (fl)
		return RDC_ERR_ARG;
	if (!xy_wh_ok(a) || !table_ok(dp, a[2], RDC_DP_HIST_BINS))
		return RDC_ERR_RANGE;
	if (!read_table(dp, a[2], dp->img.map, RDC_DP_HIST_BINS))
		return RDC_ERR_RANGE;
	return point_op(dp, RDC_OP_MAP_APPLY, 0, a);
}

static uint32_t cmd_threshold(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	uint32_t sel = fl & RDC_CHAN_SEL;

	if (fl & ~RDC_CHAN_SEL)
		return RDC_ERR_ARG;
	if (rdc_format_indexed(dp->st.dst.format) && sel != RDC_CHAN_LUMA)
		return RDC_ERR_ARG;
	if (!xy_wh_ok(a) || a[2] > 255)
		return RDC_ERR_RANGE;
	return point_op(dp, RDC_OP_THRESHOLD, sel, a);
}

static uint32_t cmd_map_clut(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	uint32_t i;

	if (fl)
		return RDC_ERR_ARG;
	if (!table_ok(dp, a[0], RDC_DP_HIST_BINS) ||
	    !read_table(dp, a[0], dp->img.map, RDC_DP_HIST_BINS))
		return RDC_ERR_RANGE;
	for (i = 0; i < RDC_CLUT_ENTRIES; i++)
		rdc_port_clut_write(dp->hw, i, dp->img.map[i] * 0x010101u);
	return RDC_ERR_NONE;
}

uint32_t dp_cmd_image(struct rdc_dp *dp, uint32_t op, uint32_t fl, uint32_t len,
		      const uint32_t *a)
{
	switch (op) {
	case RDC_OP_DECODE:
		return dp_cmd_decode(dp, fl, a);
	case RDC_OP_HISTOGRAM:
		return cmd_histogram(dp, fl, a);
	case RDC_OP_MAP_BUILD:
		return cmd_map_build(dp, fl, a);
	case RDC_OP_MAP_APPLY:
		return cmd_map_apply(dp, fl, a);
	case RDC_OP_MAP_CLUT:
		return cmd_map_clut(dp, fl, a);
	case RDC_OP_CONVOLVE:
		return dp_cmd_convolve(dp, fl, len, a);
	case RDC_OP_THRESHOLD:
		return cmd_threshold(dp, fl, a);
	default:
		return RDC_ERR_OPCODE;
	}
}
