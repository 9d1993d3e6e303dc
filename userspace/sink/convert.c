// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * XRGB8888 to the V4L2 formats the v4l2 sink offers.  Each converter
 * walks a row at a time with no per-pixel branches; where the host has
 * SSE2, xrgb32, rgb24 and yuyv do most of the row four pixels or four
 * pixel pairs at a time with exactly the plain loop's results, which
 * finish the row (test_sink_convert.c holds them to each other).
 * bench/sink_bench.c measures them against memcpy.
 */
#include <linux/videodev2.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "sink_priv.h"

#define XRGB_R(p) (((p) >> 16) & 0xffu)
#define XRGB_G(p) (((p) >> 8) & 0xffu)
#define XRGB_B(p) ((p)&0xffu)

/*
 * BT.601 limited range in 8-bit fixed point (ITU-R BT.601 coefficients
 * times 256, rounded so that each row of the matrix sums to 219 or 0):
 *   Y = (( 66 R + 129 G +  25 B + 128) >> 8) +  16
 *   U = ((-38 R -  74 G + 112 B + 128) >> 8) + 128
 *   V = ((112 R -  94 G -  18 B + 128) >> 8) + 128
 * The offsets are folded in before the shift so the shifted value is never
 * negative.
 */
#define YUV_SHIFT 8
#define YUV_ROUND (1 << (YUV_SHIFT - 1))
#define YUV_Y_OFF 16
#define YUV_C_OFF 128

static inline uint8_t yuv_y(int r, int g, int b)
{
	return (uint8_t)(((66 * r + 129 * g + 25 * b + YUV_ROUND) >>
			  YUV_SHIFT) +
			 YUV_Y_OFF);
}

/* U and V of a pair from its summed components: one more bit of shift. */
static inline uint8_t yuv_u2(int r2, int g2, int b2)
{
	return (uint8_t)((-38 * r2 - 74 * g2 + 112 * b2 + 2 * YUV_ROUND +
			  (YUV_C_OFF << (YUV_SHIFT + 1))) >>
			 (YUV_SHIFT + 1));
}

static inline uint8_t yuv_v2(int r2, int g2, int b2)
{
	return (uint8_t)((112 * r2 - 94 * g2 - 18 * b2 + 2 * YUV_ROUND +
			  (YUV_C_OFF << (YUV_SHIFT + 1))) >>
			 (YUV_SHIFT + 1));
}

static const struct {
	const char *name;
	uint32_t fourcc;
	uint32_t bytes_pp;
} sink_fmts[RDC_SINK_FMT_COUNT] = {
	[RDC_SINK_FMT_BGR32] = { "bgr32", V4L2_PIX_FMT_BGR32, 4 },
	[RDC_SINK_FMT_XRGB32] = { "xrgb32", V4L2_PIX_FMT_XRGB32, 4 },
	[RDC_SINK_FMT_RGB24] = { "rgb24", V4L2_PIX_FMT_RGB24, 3 },
	[RDC_SINK_FMT_YUYV] = { "yuyv", V4L2_PIX_FMT_YUYV, 2 },
};

int rdc_sink_fmt_by_name(const char *name)
{
	for (int i = 0; name && i < RDC_SINK_FMT_COUNT; i++)
		if (!strcasecmp(name, sink_fmts[i].name))
			return i;
	return -1;
}

const char *rdc_sink_fmt_name(int fmt)
{
	return fmt >= 0 && fmt < RDC_SINK_FMT_COUNT ? sink_fmts[fmt].name :
						      NULL;
}

uint32_t rdc_sink_fmt_fourcc(int fmt)
{
	return fmt >= 0 && fmt < RDC_SINK_FMT_COUNT ? sink_fmts[fmt].fourcc : 0;
}

uint32_t rdc_sink_fmt_fourcc_alt(int fmt)
{
	/* The deprecated RGB32 ('RGB4') has XRGB32's byte order, and is the
	 * only name v4l2loopback 0.12.7 knows it by. */
	return fmt == RDC_SINK_FMT_XRGB32 ? V4L2_PIX_FMT_RGB32 : 0;
}

int rdc_sink_fmt_by_fourcc(uint32_t fourcc)
{
	for (int i = 0; i < RDC_SINK_FMT_COUNT; i++)
		if (fourcc == sink_fmts[i].fourcc ||
		    (fourcc && fourcc == rdc_sink_fmt_fourcc_alt(i)))
			return i;
	return -1;
}

size_t rdc_sink_fmt_bytesperline(int fmt, uint32_t width)
{
	if (fmt < 0 || fmt >= RDC_SINK_FMT_COUNT)
		return 0;
	if (fmt == RDC_SINK_FMT_YUYV)
		width += width & 1;
	return (size_t)width * sink_fmts[fmt].bytes_pp;
}

static void row_bgr32(uint8_t *d, const uint32_t *s, uint32_t w)
{
	/* Host-order 0x00RRGGBB words are B, G, R, X bytes on little-endian
	 * hosts: the frame already is BGR32. */
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	memcpy(d, s, (size_t)w * 4);
#else
	for (uint32_t x = 0; x < w; x++) {
		d[4 * x + 0] = (uint8_t)XRGB_B(s[x]);
		d[4 * x + 1] = (uint8_t)XRGB_G(s[x]);
		d[4 * x + 2] = (uint8_t)XRGB_R(s[x]);
		d[4 * x + 3] = 0;
	}
#endif
}

static void row_xrgb32(uint8_t *d, const uint32_t *s, uint32_t w)
{
	uint32_t x = 0;

#if defined(__SSE2__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	/*
	 * gcc does not vectorise the byte swap below: four pixels at a time,
	 * B << 24 | G << 16 | R << 8 from 0x00RRGGBB with 32-bit lane shifts.
	 */
	const __m128i g_mask = _mm_set1_epi32(0x00ff0000);
	const __m128i r_mask = _mm_set1_epi32(0x0000ff00);

	for (; x + 4 <= w; x += 4) {
		__m128i v = _mm_loadu_si128((const __m128i *)(s + x));
		__m128i o = _mm_or_si128(
			_mm_slli_epi32(v, 24),
			_mm_or_si128(
				_mm_and_si128(_mm_slli_epi32(v, 8), g_mask),
				_mm_and_si128(_mm_srli_epi32(v, 8), r_mask)));

		_mm_storeu_si128((__m128i *)(d + 4 * (size_t)x), o);
	}
#endif
	/* X, R, G, B in memory is 0x00RRGGBB stored big-endian. */
	for (; x < w; x++) {
		uint32_t be = __builtin_bswap32(s[x] & 0x00ffffffu);

#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
		be = s[x] & 0x00ffffffu;
#endif
		memcpy(d + 4 * x, &be, 4);
	}
}

static void row_rgb24(uint8_t *d, const uint32_t *s, uint32_t w)
{
	uint32_t x = 0;

#if defined(__SSE2__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	/*
	 * Four pixels at a time: each lane becomes R | G << 8 | B << 16, two
	 * lanes join into 6 bytes in each 64-bit half, and the halves go out
	 * as two 8-byte stores 6 bytes apart.  The 2 bytes past the 12 are
	 * the next pixel's, which is written after, so a pixel must follow.
	 */
	const __m128i ff = _mm_set1_epi32(0xff), ff00 = _mm_set1_epi32(0xff00);
	const __m128i lo = _mm_set1_epi64x(0x0000000000ffffffll);
	const __m128i hi = _mm_set1_epi64x(0x0000ffffff000000ll);

	for (; x + 5 <= w; x += 4) {
		__m128i v = _mm_loadu_si128((const __m128i *)(s + x));
		__m128i p = _mm_or_si128(
			_mm_or_si128(_mm_and_si128(_mm_srli_epi32(v, 16), ff),
				     _mm_and_si128(v, ff00)),
			_mm_slli_epi32(_mm_and_si128(v, ff), 16));
		__m128i q =
			_mm_or_si128(_mm_and_si128(p, lo),
				     _mm_and_si128(_mm_srli_epi64(p, 8), hi));

		_mm_storel_epi64((__m128i *)(d + 3 * (size_t)x), q);
		_mm_storel_epi64((__m128i *)(d + 3 * (size_t)x + 6),
				 _mm_unpackhi_epi64(q, q));
	}
#endif
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	/* One 4-byte store a pixel (R, G, B, then a byte the next pixel
	 * overwrites); the last pixel of the row goes byte by byte so
	 * nothing lands past the row. */
	for (; x + 1 < w; x++) {
		uint32_t v = __builtin_bswap32(s[x]) >> 8;

		memcpy(d + 3 * x, &v, 4);
	}
#endif
	for (; x < w; x++) {
		d[3 * x + 0] = (uint8_t)XRGB_R(s[x]);
		d[3 * x + 1] = (uint8_t)XRGB_G(s[x]);
		d[3 * x + 2] = (uint8_t)XRGB_B(s[x]);
	}
}

#if defined(__SSE2__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
/* One channel of eight pixels (two vectors of four) as 16-bit lanes. */
static inline __m128i yuyv_chan(__m128i a, __m128i b, int shift)
{
	const __m128i m = _mm_set1_epi32(0xff);

	return _mm_packs_epi32(_mm_and_si128(_mm_srli_epi32(a, shift), m),
			       _mm_and_si128(_mm_srli_epi32(b, shift), m));
}

/* The 16-bit lanes summed in pairs, into 32-bit lanes. */
static inline __m128i yuyv_pair_sum(__m128i c)
{
	return _mm_add_epi32(_mm_and_si128(c, _mm_set1_epi32(0xffff)),
			     _mm_srli_epi32(c, 16));
}

/* c * k in 32-bit lanes holding at most 16 bits, for k * c < 2^16 */
static inline __m128i yuyv_mul(__m128i c, int k)
{
	return _mm_mullo_epi16(c, _mm_set1_epi32(k));
}

/*
 * Four pairs at a time, exactly the scalar formulas: Y in 16-bit lanes
 * (the sum stays under 2^16 and shifts logically), U and V of each pair
 * in 32-bit lanes.  Returns the pairs done.
 */
static uint32_t yuyv_sse2(uint8_t *d, const uint32_t *s, uint32_t pairs)
{
	const __m128i c_off =
		_mm_set1_epi32(2 * YUV_ROUND + (YUV_C_OFF << (YUV_SHIFT + 1)));
	uint32_t i = 0;

	for (; i + 4 <= pairs; i += 4) {
		__m128i v0 = _mm_loadu_si128((const __m128i *)(s + 2 * i));
		__m128i v1 = _mm_loadu_si128((const __m128i *)(s + 2 * i + 4));
		__m128i r = yuyv_chan(v0, v1, 16), g = yuyv_chan(v0, v1, 8);
		__m128i b = yuyv_chan(v0, v1, 0);
		__m128i r2 = yuyv_pair_sum(r), g2 = yuyv_pair_sum(g);
		__m128i b2 = yuyv_pair_sum(b), y, u, v;

		y = _mm_add_epi16(_mm_mullo_epi16(r, _mm_set1_epi16(66)),
				  _mm_mullo_epi16(g, _mm_set1_epi16(129)));
		y = _mm_add_epi16(y, _mm_mullo_epi16(b, _mm_set1_epi16(25)));
		y = _mm_srli_epi16(_mm_add_epi16(y, _mm_set1_epi16(YUV_ROUND)),
				   YUV_SHIFT);
		y = _mm_add_epi16(y, _mm_set1_epi16(YUV_Y_OFF));
		u = _mm_add_epi32(yuyv_mul(b2, 112), c_off);
		u = _mm_sub_epi32(u, _mm_add_epi32(yuyv_mul(r2, 38),
						   yuyv_mul(g2, 74)));
		v = _mm_add_epi32(yuyv_mul(r2, 112), c_off);
		v = _mm_sub_epi32(v, _mm_add_epi32(yuyv_mul(g2, 94),
						   yuyv_mul(b2, 18)));
		u = _mm_srli_epi32(u, YUV_SHIFT + 1);
		v = _mm_srli_epi32(v, YUV_SHIFT + 1);
		_mm_storeu_si128(
			(__m128i *)(d + 4 * (size_t)i),
			_mm_or_si128(y, _mm_or_si128(_mm_slli_epi32(u, 8),
						     _mm_slli_epi32(v, 24))));
	}
	return i;
}
#endif

static void row_yuyv(uint8_t *d, const uint32_t *s, uint32_t w)
{
	uint32_t pairs = w / 2, i = 0;

#if defined(__SSE2__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	i = yuyv_sse2(d, s, pairs);
#endif
	/* Whole pairs, then an odd last pixel, paired with itself. */
	for (; i < pairs; i++) {
		uint32_t p0 = s[2 * i], p1 = s[2 * i + 1];
		int r0 = (int)XRGB_R(p0), g0 = (int)XRGB_G(p0);
		int b0 = (int)XRGB_B(p0), r1 = (int)XRGB_R(p1);
		int g1 = (int)XRGB_G(p1), b1 = (int)XRGB_B(p1);
		uint32_t m = (uint32_t)yuv_y(r0, g0, b0) |
			     (uint32_t)yuv_u2(r0 + r1, g0 + g1, b0 + b1) << 8 |
			     (uint32_t)yuv_y(r1, g1, b1) << 16 |
			     (uint32_t)yuv_v2(r0 + r1, g0 + g1, b0 + b1) << 24;

#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
		m = __builtin_bswap32(m);
#endif
		memcpy(d + 4 * i, &m, 4);
	}
	if (w & 1) {
		uint32_t p = s[w - 1];
		int r = (int)XRGB_R(p), g = (int)XRGB_G(p), b = (int)XRGB_B(p);
		uint8_t m[4] = { yuv_y(r, g, b), yuv_u2(2 * r, 2 * g, 2 * b),
				 yuv_y(r, g, b), yuv_v2(2 * r, 2 * g, 2 * b) };

		memcpy(d + 4 * pairs, m, sizeof(m));
	}
}

int rdc_sink_convert(int fmt, void *dst, size_t dst_bpl,
		     const struct rdc_frame *f)
{
	void (*row)(uint8_t * d, const uint32_t *s, uint32_t w);
	size_t bpl = rdc_sink_fmt_bytesperline(fmt, f ? f->width : 0);

	if (!dst || !f || !f->xrgb || !bpl || dst_bpl < bpl ||
	    f->stride < f->width)
		return RDC_E_INVAL;
	switch (fmt) {
	case RDC_SINK_FMT_BGR32:
		row = row_bgr32;
		break;
	case RDC_SINK_FMT_XRGB32:
		row = row_xrgb32;
		break;
	case RDC_SINK_FMT_RGB24:
		row = row_rgb24;
		break;
	default:
		row = row_yuyv;
		break;
	}
	for (uint32_t y = 0; y < f->height; y++)
		row((uint8_t *)dst + y * dst_bpl, f->xrgb + y * f->stride,
		    f->width);
	return 0;
}
