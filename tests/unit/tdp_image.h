/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * What the DECODE tests share (test_dp_image.c, test_dp_codec.c): the
 * test pictures, the destination surface, the pixel a sample becomes,
 * and running DECODE on a stream in VRAM.
 */
#ifndef TDP_IMAGE_H
#define TDP_IMAGE_H

#include "test_dp_common.h"

#define DST_W	    320u
#define DST_H	    240u
#define STREAM_BASE 0x200000u
#define SENTINEL    0x5au

static inline uint32_t rng_next(uint32_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 17;
	*s ^= *s << 5;
	return *s;
}

/*
 * Test pictures: 0 flat rectangles, 1 a smooth gradient with a little
 * noise, 2 noise, 3 a checkerboard of 3-pixel cells, 4 one grey.
 */
static inline void gen_image(uint8_t *px, uint32_t w, uint32_t h, uint32_t ch,
			     int kind, uint32_t seed)
{
	uint32_t x, y, c, s = seed | 1, v;

	for (y = 0; y < h; y++) {
		for (x = 0; x < w; x++) {
			for (c = 0; c < ch; c++) {
				if (kind == 0)
					v = (x / 13) * 37 + (y / 9) * 71 +
					    c * 50;
				else if (kind == 1)
					v = x * 255 / w + y * (c + 1) +
					    (rng_next(&s) & 3);
				else if (kind == 2)
					v = rng_next(&s);
				else if (kind == 3)
					v = ((x / 3 + y / 3) & 1) ? 200 - c :
								    20 + c;
				else
					v = 99;
				px[((size_t)y * w + x) * ch + c] =
					(uint8_t)(v & 0xff);
			}
		}
	}
}

static inline struct rdc_surface dst_surface(uint32_t fmt)
{
	struct rdc_surface s = { 0, 0, DST_W, DST_H, fmt };

	s.stride = (DST_W * tdp_bpp(fmt) + 7) / 8;
	s.stride = (s.stride + 3) & ~3u;
	return s;
}

/* The pixel a sample (or R, G, B) becomes in fmt, as rdc_image.h says. */
static inline uint32_t want_px(uint32_t fmt, const uint8_t *p, uint32_t ch)
{
	uint32_t r = p[0], g = ch == 3 ? p[1] : p[0], b = ch == 3 ? p[2] : p[0];

	if (fmt <= RDC_FMT_I8)
		return p[0] & tdp_mask(fmt);
	if (fmt == RDC_FMT_RGB565)
		return (r >> 3) << 11 | (g >> 2) << 5 | (b >> 3);
	return r << 16 | g << 8 | b;
}

static inline void prep_dst(struct tdp *t, const struct rdc_surface *s)
{
	memset(t->vram + s->base, SENTINEL, (size_t)s->stride * s->height);
	tdp_set_surface(t, RDC_OP_SET_DST, s);
}

static inline void decode_at(struct tdp *t, const uint8_t *stream, size_t len,
			     uint32_t size, int32_t x, int32_t y)
{
	memcpy(t->vram + STREAM_BASE, stream, len);
	TDP_CMD(t, RDC_OP_DECODE, STREAM_BASE, size, RDC_XY(x, y));
	tdp_drain(t);
}

/* The DST rectangle at (x0, y0) holds img (w x h, ch) exactly. */
static inline void check_exact(struct tdp *t, const struct rdc_surface *s,
			       const uint8_t *img, uint32_t w, uint32_t h,
			       uint32_t ch, int32_t x0, int32_t y0)
{
	uint32_t x, y;

	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++)
			if (tdp_get(t->vram, s, x0 + x, y0 + y) !=
			    want_px(s->format, img + ((size_t)y * w + x) * ch,
				    ch))
				fail_msg("pixel (%u, %u) of %ux%ux%u in format "
					 "%u",
					 x, y, w, h, ch, s->format);
}

#endif /* TDP_IMAGE_H */
