// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Host-side image encoders for the DP's DECODE command: RLE (PackBits on
 * pixels), DPCM (median predictor, Rice codes with a parameter chosen
 * per row), BTC (absolute-moment block truncation coding, 4x4), HUFF
 * (a canonical Huffman code of the samples, built for each picture),
 * DPCMQ (DPCM's predictor and codes on quantised residuals) and DCT (as
 * JPEG's baseline: 8x8 DCT, quantisation, Huffman codes built for each
 * picture).  The
 * stream formats are rdc_image.h's; this file never calls the firmware.
 */
#include <errno.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#include "rdc_priv.h"

#define IMG_LUMA(r, g, b) ((77u * (r) + 150u * (g) + 29u * (b) + 128u) >> 8)

static void img_put16(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static void img_put32(uint8_t *p, uint32_t v)
{
	img_put16(p, v);
	img_put16(p + 2, v >> 16);
}

#define HUFF_TABLE_MAX (RDC_IMG_HUFF_LENS + RDC_IMG_HUFF_SYMS)

/* DC: 16 + 11 bits; 63 AC codes of 16 + 10 bits; an EOB or ZRL's 16 */
#define DCT_BLOCK_BITS (27u + 63u * 26u + 16u)

static int img_args_ok(uint32_t w, uint32_t h, uint32_t channels)
{
	return w >= 1 && w <= RDC_IMG_MAX_WIDTH && h >= 1 &&
	       h <= RDC_IMG_MAX_HEIGHT && (channels == 1 || channels == 3);
}

size_t rdc_image_bound(uint32_t codec, uint32_t w, uint32_t h,
		       uint32_t channels)
{
	uint64_t n = (uint64_t)w * h, p;

	if (!img_args_ok(w, h, channels))
		return 0;
	switch (codec) {
	case RDC_IMG_RLE: /* all literals: a control byte per 128 pixels */
		p = n * channels +
		    (n + RDC_IMG_RLE_LITERAL_MAX - 1) / RDC_IMG_RLE_LITERAL_MAX;
		break;
	case RDC_IMG_DPCM: /* every sample escaped */
		p = ((uint64_t)h * (RDC_IMG_DPCM_KBITS +
				    (uint64_t)w * channels *
					    (RDC_IMG_DPCM_ESCAPE + 8)) +
		     7) /
		    8;
		break;
	case RDC_IMG_BTC:
		p = (uint64_t)((w + 3) / 4) * ((h + 3) / 4) * channels *
		    RDC_IMG_BTC_BYTES;
		break;
	case RDC_IMG_DPCMQ: /* the step, every sample escaped */
		p = 1 + ((uint64_t)h * (RDC_IMG_DPCM_KBITS +
					(uint64_t)w * channels *
						(RDC_IMG_DPCM_ESCAPE +
						 RDC_IMG_DPCMQ_MBITS)) +
			 7) / 8;
		break;
	case RDC_IMG_DCT: /* tables; per block 64 codes of 16 + 11 bits */
		p = RDC_IMG_DCT_QBYTES + 2 * HUFF_TABLE_MAX +
		    ((uint64_t)((w + 7) / 8) * ((h + 7) / 8) * channels *
			     DCT_BLOCK_BITS +
		     7) / 8;
		break;
	case RDC_IMG_HUFF: /* the table, every code 16 bits */
		p = HUFF_TABLE_MAX + n * channels * RDC_IMG_HUFF_LENS / 8;
		break;
	default:
		return 0;
	}
	return (size_t)(RDC_IMG_HDR_BYTES + p);
}

struct img_src {
	const uint8_t *px;
	uint32_t w, h, ch;
	size_t pitch;
};

/* Sample c of pixel i in raster order. */
static uint8_t img_at(const struct img_src *s, uint64_t i, uint32_t c)
{
	return s->px[(size_t)(i / s->w) * s->pitch +
		     (size_t)(i % s->w) * s->ch + c];
}

static int img_same(const struct img_src *s, uint64_t i, uint64_t j)
{
	for (uint32_t c = 0; c < s->ch; c++)
		if (img_at(s, i, c) != img_at(s, j, c))
			return 0;
	return 1;
}

/* Equal pixels from i on, at most `max`. */
static uint32_t img_run(const struct img_src *s, uint64_t i, uint64_t n,
			uint32_t max)
{
	uint32_t r = 1;

	while (r < max && i + r < n && img_same(s, i, i + r))
		r++;
	return r;
}

static size_t enc_rle(const struct img_src *s, uint8_t *o)
{
	uint64_t n = (uint64_t)s->w * s->h, i = 0, j;
	size_t k = 0;
	uint32_t r, c;

	while (i < n) {
		r = img_run(s, i, n, RDC_IMG_RLE_RUN_MAX);
		if (r >= 2) {
			o[k++] = (uint8_t)(r + 126);
			for (c = 0; c < s->ch; c++)
				o[k++] = img_at(s, i, c);
			i += r;
			continue;
		}
		/* a literal up to the next run of three or more */
		for (j = i + 1; j < n && j - i < RDC_IMG_RLE_LITERAL_MAX; j++)
			if (img_run(s, j, n, 3) >= 3)
				break;
		o[k++] = (uint8_t)(j - i - 1);
		for (; i < j; i++)
			for (c = 0; c < s->ch; c++)
				o[k++] = img_at(s, i, c);
	}
	return k;
}

struct bitw {
	uint8_t *o;
	size_t k;
	uint32_t acc, n;
};

static void bits_put(struct bitw *b, uint32_t v, uint32_t n)
{
	while (n--) {
		b->acc = b->acc << 1 | ((v >> n) & 1);
		if (++b->n == 8) {
			b->o[b->k++] = (uint8_t)b->acc;
			b->acc = 0;
			b->n = 0;
		}
	}
}

static uint32_t dpcm_pred(const struct img_src *s, uint32_t x, uint32_t y,
			  uint32_t c)
{
	const uint8_t *row = s->px + (size_t)y * s->pitch;
	const uint8_t *up = row - s->pitch;
	uint32_t a, b, d, lo, hi;

	if (!y)
		return x ? row[(x - 1) * s->ch + c] : 128;
	if (!x)
		return up[c];
	a = row[(x - 1) * s->ch + c];
	b = up[x * s->ch + c];
	d = up[(x - 1) * s->ch + c];
	lo = a < b ? a : b;
	hi = a < b ? b : a;
	if (d >= hi)
		return lo;
	if (d <= lo)
		return hi;
	return a + b - d;
}

/* A Rice code's bits; `ebits` after an escape (8: DPCM, 9: DPCMQ). */
static uint32_t rice_bits(uint32_t m, uint32_t k, uint32_t ebits)
{
	uint32_t q = m >> k;

	return q < RDC_IMG_DPCM_ESCAPE ? q + 1 + k :
					 RDC_IMG_DPCM_ESCAPE + ebits;
}

/* The row's residuals res[0..n) with the k that codes them shortest. */
static void rice_row(struct bitw *b, const uint16_t *res, uint32_t n,
		     uint32_t ebits)
{
	uint32_t k, i, bk = 0;
	uint64_t cost, best = UINT64_MAX;

	for (k = 0; k <= RDC_IMG_DPCM_KMAX; k++) {
		cost = 0;
		for (i = 0; i < n; i++)
			cost += rice_bits(res[i], k, ebits);
		if (cost < best) {
			best = cost;
			bk = k;
		}
	}
	bits_put(b, bk, RDC_IMG_DPCM_KBITS);
	for (i = 0; i < n; i++) {
		uint32_t q = res[i] >> bk;

		if (q < RDC_IMG_DPCM_ESCAPE) {
			bits_put(b, (1u << q) - 1, q);
			bits_put(b, 0, 1);
			bits_put(b, res[i], bk);
		} else {
			bits_put(b, (1u << RDC_IMG_DPCM_ESCAPE) - 1,
				 RDC_IMG_DPCM_ESCAPE);
			bits_put(b, res[i], ebits);
		}
	}
}

static size_t enc_dpcm(const struct img_src *s, uint8_t *o, uint16_t *res)
{
	struct bitw b = { .o = o };
	uint32_t n = s->w * s->ch, x, y, i;

	for (y = 0; y < s->h; y++) {
		for (i = 0; i < n; i++) {
			x = i / s->ch;
			int e = (int)s->px[(size_t)y * s->pitch + i] -
				(int)dpcm_pred(s, x, y, i % s->ch);
			int8_t se = (int8_t)(uint8_t)(e & 0xff);

			res[i] = (uint16_t)(se >= 0 ? 2 * se : -2 * se - 1);
		}
		rice_row(&b, res, n, 8);
	}
	if (b.n)
		bits_put(&b, 0, 8 - b.n);
	return b.k;
}

/*
 * DPCMQ: the prediction from the decoded picture (rec, which the decoder
 * will have), the residual quantised to nearest with halves toward 0.
 */
static size_t enc_dpcmq(const struct img_src *s, uint8_t *o, uint16_t *res,
			uint8_t *rec, uint32_t step)
{
	struct img_src r = { rec, s->w, s->h, s->ch, (size_t)s->w * s->ch };
	struct bitw b = { .o = o + 1 };
	uint32_t n = s->w * s->ch, x, y, i, p;
	int e, q, v;

	o[0] = (uint8_t)step;
	for (y = 0; y < s->h; y++) {
		for (i = 0; i < n; i++) {
			x = i / s->ch;
			p = dpcm_pred(&r, x, y, i % s->ch);
			e = (int)s->px[(size_t)y * s->pitch + i] - (int)p;
			q = (abs(e) + ((int)step - 1) / 2) / (int)step;
			q = e < 0 ? -q : q;
			v = (int)p + q * (int)step;
			rec[(size_t)y * n + i] = (uint8_t)(v < 0   ? 0 :
							   v > 255 ? 255 :
								     v);
			res[i] = (uint16_t)(q >= 0 ? 2 * q : -2 * q - 1);
		}
		rice_row(&b, res, n, RDC_IMG_DPCMQ_MBITS);
	}
	if (b.n)
		bits_put(&b, 0, 8 - b.n);
	return 1 + b.k;
}

/*
 * AMBTC: the pixels at or above the block's mean take the rounded mean of
 * that group, the others the rounded mean of theirs.
 */
static size_t enc_btc(const struct img_src *s, uint8_t *o)
{
	uint32_t bw = (s->w + 3) / 4, bh = (s->h + 3) / 4, bx, by, c, i;
	size_t k = 0;

	for (by = 0; by < bh; by++) {
		for (bx = 0; bx < bw; bx++) {
			for (c = 0; c < s->ch; c++) {
				uint32_t v[16], in[16], n = 0, sum = 0;
				uint32_t hs = 0, hn = 0, ls = 0, ln = 0;
				uint32_t bits = 0, lo, hi;

				for (i = 0; i < 16; i++) {
					uint32_t x = bx * 4 + i % 4;
					uint32_t y = by * 4 + i / 4;

					in[i] = x < s->w && y < s->h;
					if (!in[i])
						continue;
					v[i] = s->px[(size_t)y * s->pitch +
						     x * s->ch + c];
					sum += v[i];
					n++;
				}
				for (i = 0; i < 16; i++) {
					if (!in[i])
						continue;
					if (v[i] * n >= sum) {
						hs += v[i];
						hn++;
						bits |= 1u << i;
					} else {
						ls += v[i];
						ln++;
					}
				}
				hi = (2 * hs + hn) / (2 * hn);
				lo = ln ? (2 * ls + ln) / (2 * ln) : hi;
				o[k++] = (uint8_t)lo;
				o[k++] = (uint8_t)hi;
				o[k++] = (uint8_t)bits;
				o[k++] = (uint8_t)(bits >> 8);
			}
		}
	}
	return k;
}

/*
 * Huffman code lengths (at most RDC_IMG_HUFF_LENS) for freq[0..n), 0 for
 * an unused symbol; a lone symbol gets length 1.  Lengths come from
 * merging the two lightest trees until one is left; if a code is longer
 * than 16 bits, the counts are halved (a used symbol keeps at least 1)
 * and the code built again.
 */
static void huff_lengths(const uint64_t *freq, uint32_t n, uint8_t *len)
{
	uint64_t f[RDC_IMG_HUFF_SYMS], w[2 * RDC_IMG_HUFF_SYMS];
	int32_t up[2 * RDC_IMG_HUFF_SYMS];
	uint8_t live[2 * RDC_IMG_HUFF_SYMS];
	uint32_t i, k, m, used, a, b, d, top;
	int32_t j;

	for (i = 0; i < n; i++)
		f[i] = freq[i];
	for (;;) {
		m = 0;
		used = 0;
		for (i = 0; i < n; i++) {
			w[i] = f[i];
			live[i] = f[i] != 0;
			up[i] = -1;
			used += live[i];
			len[i] = 0;
		}
		if (used <= 1) {
			for (i = 0; i < n; i++)
				len[i] = f[i] ? 1 : 0;
			return;
		}
		m = n;
		for (k = 1; k < used; k++) {
			/* the two lightest live trees, a then b */
			a = b = UINT32_MAX;
			for (i = 0; i < m; i++) {
				if (!live[i])
					continue;
				if (a == UINT32_MAX || w[i] < w[a]) {
					b = a;
					a = i;
				} else if (b == UINT32_MAX || w[i] < w[b]) {
					b = i;
				}
			}
			w[m] = w[a] + w[b];
			live[m] = 1;
			up[m] = -1;
			live[a] = live[b] = 0;
			up[a] = up[b] = (int32_t)m;
			m++;
		}
		top = 0;
		for (i = 0; i < n; i++) {
			if (!f[i])
				continue;
			for (d = 0, j = up[i]; j >= 0; j = up[j])
				d++;
			len[i] = (uint8_t)(d > 255 ? 255 : d);
			top = d > top ? d : top;
		}
		if (top <= RDC_IMG_HUFF_LENS)
			return;
		for (i = 0; i < n; i++)
			f[i] = f[i] ? (f[i] >> 1) | 1 : 0;
	}
}

/*
 * The canonical code of those lengths: the table (counts, then symbols
 * by length and value) into o, each symbol's code into code[].  Returns
 * the table's size.
 */
static size_t huff_table(const uint8_t *len, uint32_t n, uint16_t *code,
			 uint8_t *o)
{
	uint32_t l, i, c = 0;
	size_t k = RDC_IMG_HUFF_LENS;

	memset(o, 0, RDC_IMG_HUFF_LENS);
	for (l = 1; l <= RDC_IMG_HUFF_LENS; l++) {
		for (i = 0; i < n; i++) {
			if (len[i] != l)
				continue;
			o[l - 1]++;
			o[k++] = (uint8_t)i;
			code[i] = (uint16_t)c++;
		}
		c <<= 1;
	}
	return k;
}

static size_t enc_huff(const struct img_src *s, uint8_t *o)
{
	uint64_t freq[RDC_IMG_HUFF_SYMS] = { 0 };
	uint8_t len[RDC_IMG_HUFF_SYMS];
	uint16_t code[RDC_IMG_HUFF_SYMS];
	uint32_t n = s->w * s->ch, x, y, v;
	struct bitw b = { .o = o };

	for (y = 0; y < s->h; y++)
		for (x = 0; x < n; x++)
			freq[s->px[(size_t)y * s->pitch + x]]++;
	huff_lengths(freq, RDC_IMG_HUFF_SYMS, len);
	b.k = huff_table(len, RDC_IMG_HUFF_SYMS, code, o);
	for (y = 0; y < s->h; y++) {
		for (x = 0; x < n; x++) {
			v = s->px[(size_t)y * s->pitch + x];
			bits_put(&b, code[v], len[v]);
		}
	}
	if (b.n)
		bits_put(&b, 0, 8 - b.n);
	return b.k;
}

/* C(u) / 2 * cos((2x + 1) u pi / 16) at [x][u], C(0) = 1 / sqrt(2) */
static const double dct_k[8][8] = {
	{ 0.35355339059327379, 0.49039264020161522, 0.46193976625564337,
	  0.41573480615127262, 0.35355339059327379, 0.27778511650980114,
	  0.19134171618254492, 0.09754516100806417 },
	{ 0.35355339059327379, 0.41573480615127262, 0.19134171618254492,
	  -0.09754516100806410, -0.35355339059327373, -0.49039264020161522,
	  -0.46193976625564342, -0.27778511650980109 },
	{ 0.35355339059327379, 0.27778511650980114, -0.19134171618254486,
	  -0.49039264020161522, -0.35355339059327384, 0.09754516100806415,
	  0.46193976625564326, 0.41573480615127273 },
	{ 0.35355339059327379, 0.09754516100806417, -0.46193976625564337,
	  -0.27778511650980109, 0.35355339059327368, 0.41573480615127273,
	  -0.19134171618254495, -0.49039264020161533 },
	{ 0.35355339059327379, -0.09754516100806410, -0.46193976625564342,
	  0.27778511650980092, 0.35355339059327384, -0.41573480615127256,
	  -0.19134171618254528, 0.49039264020161522 },
	{ 0.35355339059327379, -0.27778511650980098, -0.19134171618254517,
	  0.49039264020161522, -0.35355339059327334, -0.09754516100806401,
	  0.46193976625564337, -0.41573480615127251 },
	{ 0.35355339059327379, -0.41573480615127267, 0.19134171618254500,
	  0.09754516100806439, -0.35355339059327356, 0.49039264020161533,
	  -0.46193976625564320, 0.27778511650980076 },
	{ 0.35355339059327379, -0.49039264020161522, 0.46193976625564326,
	  -0.41573480615127256, 0.35355339059327329, -0.27778511650980076,
	  0.19134171618254478, -0.09754516100806429 },
};

/* JPEG's luminance table (ITU T.81 K.1), natural order */
static const uint8_t dct_base[64] = {
	16, 11, 10, 16, 24,  40,  51,  61,  12, 12, 14, 19, 26,	 58,  60,  55,
	14, 13, 16, 24, 40,  57,  69,  56,  14, 17, 22, 29, 51,	 87,  80,  62,
	18, 22, 37, 56, 68,  109, 103, 77,  24, 35, 55, 64, 81,	 104, 113, 92,
	49, 64, 78, 87, 103, 121, 120, 101, 72, 92, 95, 98, 112, 100, 103, 99,
};

/* Natural index of the zigzag order's k-th coefficient. */
static const uint8_t dct_zz[64] = {
	0,  1,	8,  16, 9,  2,	3,  10, 17, 24, 32, 25, 18, 11, 4,  5,
	12, 19, 26, 33, 40, 48, 41, 34, 27, 20, 13, 6,	7,  14, 21, 28,
	35, 42, 49, 56, 57, 50, 43, 36, 29, 22, 15, 23, 30, 37, 44, 51,
	58, 59, 52, 45, 38, 31, 39, 46, 53, 60, 61, 54, 47, 55, 62, 63,
};

/* Bits of |v| (JPEG's category). */
static uint32_t dct_cat(int v)
{
	uint32_t s = 0, a = (uint32_t)abs(v);

	while (a) {
		s++;
		a >>= 1;
	}
	return s;
}

/* JPEG's bits of v in its category s: v, or v + 2^s - 1 if negative. */
static uint32_t dct_bits(int v, uint32_t s)
{
	return (uint32_t)(v < 0 ? v + (1 << s) - 1 : v);
}

/*
 * DCT: the quantisation table from IJG's quality scaling of JPEG's
 * luminance table, every block's FDCT quantised (pixels past the edge
 * repeat the last column and row), then two passes over the quantised
 * blocks: count the DC and AC symbols, build their codes, write.
 */
static size_t enc_dct(const struct img_src *s, uint8_t *o, int16_t *qc,
		      uint32_t quality)
{
	uint32_t bw = (s->w + 7) / 8, bh = (s->h + 7) / 8, nb, b, c, k, q[64];
	uint32_t scale = quality < 50 ? 5000 / quality : 200 - 2 * quality;
	uint32_t x, y, u, v, run, sym, cat, pass;
	uint64_t fdc[RDC_IMG_HUFF_SYMS], fac[RDC_IMG_HUFF_SYMS];
	uint8_t ldc[RDC_IMG_HUFF_SYMS], lac[RDC_IMG_HUFF_SYMS];
	uint16_t cdc[RDC_IMG_HUFF_SYMS], cac[RDC_IMG_HUFF_SYMS];
	struct bitw bits = { .o = o };
	double f[64], F;
	int pred[3], d, val;

	for (k = 0; k < 64; k++) {
		q[k] = (dct_base[dct_zz[k]] * scale + 50) / 100;
		q[k] = q[k] < 1 ? 1 : q[k] > 255 ? 255 : q[k];
		o[k] = (uint8_t)q[k];
	}
	nb = bw * bh * s->ch;
	for (b = 0; b < nb; b++) {
		uint32_t bx = b / s->ch % bw, by = b / s->ch / bw;

		c = b % s->ch;
		for (y = 0; y < 8; y++) {
			uint32_t py = by * 8 + y < s->h ? by * 8 + y : s->h - 1;

			for (x = 0; x < 8; x++) {
				uint32_t px = bx * 8 + x < s->w ? bx * 8 + x :
								  s->w - 1;

				f[8 * y + x] = s->px[(size_t)py * s->pitch +
						     (size_t)px * s->ch + c] -
					       128.0;
			}
		}
		for (k = 0; k < 64; k++) {
			u = dct_zz[k] % 8;
			v = dct_zz[k] / 8;
			F = 0;
			for (y = 0; y < 8; y++)
				for (x = 0; x < 8; x++)
					F += f[8 * y + x] * dct_k[x][u] *
					     dct_k[y][v];
			F /= q[k];
			val = (int)(F < 0 ? F - 0.5 : F + 0.5);
			val = val > 1023 ? 1023 : val < -1023 ? -1023 : val;
			qc[(size_t)b * 64 + k] = (int16_t)val;
		}
	}
	for (pass = 0; pass < 2; pass++) {
		if (pass) {
			huff_lengths(fdc, RDC_IMG_HUFF_SYMS, ldc);
			huff_lengths(fac, RDC_IMG_HUFF_SYMS, lac);
			bits.k = RDC_IMG_DCT_QBYTES;
			bits.k += huff_table(ldc, RDC_IMG_HUFF_SYMS, cdc,
					     o + bits.k);
			bits.k += huff_table(lac, RDC_IMG_HUFF_SYMS, cac,
					     o + bits.k);
		} else {
			memset(fdc, 0, sizeof(fdc));
			memset(fac, 0, sizeof(fac));
		}
		pred[0] = pred[1] = pred[2] = 0;
		for (b = 0; b < nb; b++) {
			const int16_t *z = qc + (size_t)b * 64;

			c = b % s->ch;
			d = z[0] - pred[c];
			pred[c] = z[0];
			cat = dct_cat(d);
			if (pass) {
				bits_put(&bits, cdc[cat], ldc[cat]);
				bits_put(&bits, dct_bits(d, cat), cat);
			} else {
				fdc[cat]++;
			}
			for (k = 1, run = 0; k < 64; k++) {
				if (!z[k]) {
					run++;
					continue;
				}
				for (; run >= 16; run -= 16) {
					if (pass)
						bits_put(&bits,
							 cac[RDC_IMG_DCT_ZRL],
							 lac[RDC_IMG_DCT_ZRL]);
					else
						fac[RDC_IMG_DCT_ZRL]++;
				}
				cat = dct_cat(z[k]);
				sym = run << 4 | cat;
				run = 0;
				if (pass) {
					bits_put(&bits, cac[sym], lac[sym]);
					bits_put(&bits, dct_bits(z[k], cat),
						 cat);
				} else {
					fac[sym]++;
				}
			}
			if (run) {
				if (pass)
					bits_put(&bits, cac[RDC_IMG_DCT_EOB],
						 lac[RDC_IMG_DCT_EOB]);
				else
					fac[RDC_IMG_DCT_EOB]++;
			}
		}
	}
	if (bits.n)
		bits_put(&bits, 0, 8 - bits.n);
	return bits.k;
}

static int img_encode(uint32_t codec, uint32_t level, const uint8_t *px,
		      uint32_t w, uint32_t h, uint32_t channels, size_t pitch,
		      uint8_t *out, size_t cap, size_t *len)
{
	struct img_src s = { px, w, h, channels, pitch };
	size_t bound = rdc_image_bound(codec, w, h, channels), payload;
	uint8_t *tmp, *rec = NULL;
	uint16_t *res = NULL;

	if (!bound || !px || !len || (!out && cap) ||
	    pitch < (size_t)w * channels)
		return RDC_E_INVAL;
	/* encode into a buffer of the bound, then copy what fits */
	tmp = malloc(bound);
	if (codec == RDC_IMG_DPCM || codec == RDC_IMG_DPCMQ)
		res = malloc((size_t)w * channels * sizeof(*res));
	if (codec == RDC_IMG_DPCMQ)
		rec = malloc((size_t)w * h * channels);
	if (codec == RDC_IMG_DCT) /* the quantised blocks */
		rec = malloc((size_t)((w + 7) / 8) * ((h + 7) / 8) * channels *
			     64 * sizeof(int16_t));
	if (!tmp ||
	    ((codec == RDC_IMG_DPCM || codec == RDC_IMG_DPCMQ) && !res) ||
	    ((codec == RDC_IMG_DPCMQ || codec == RDC_IMG_DCT) && !rec)) {
		free(tmp);
		free(res);
		free(rec);
		return RDC_E_NOMEM;
	}
	switch (codec) {
	case RDC_IMG_RLE:
		payload = enc_rle(&s, tmp + RDC_IMG_HDR_BYTES);
		break;
	case RDC_IMG_DPCM:
		payload = enc_dpcm(&s, tmp + RDC_IMG_HDR_BYTES, res);
		break;
	case RDC_IMG_HUFF:
		payload = enc_huff(&s, tmp + RDC_IMG_HDR_BYTES);
		break;
	case RDC_IMG_DPCMQ:
		payload =
			enc_dpcmq(&s, tmp + RDC_IMG_HDR_BYTES, res, rec, level);
		break;
	case RDC_IMG_DCT:
		payload = enc_dct(&s, tmp + RDC_IMG_HDR_BYTES, (int16_t *)rec,
				  level);
		break;
	default:
		payload = enc_btc(&s, tmp + RDC_IMG_HDR_BYTES);
		break;
	}
	free(res);
	free(rec);
	memset(tmp, 0, RDC_IMG_HDR_BYTES);
	img_put32(tmp + RDC_IMG_OFF_MAGIC, RDC_IMG_MAGIC);
	tmp[RDC_IMG_OFF_CODEC] = (uint8_t)codec;
	tmp[RDC_IMG_OFF_CHANNELS] = (uint8_t)channels;
	img_put16(tmp + RDC_IMG_OFF_WIDTH, w);
	img_put16(tmp + RDC_IMG_OFF_HEIGHT, h);
	img_put32(tmp + RDC_IMG_OFF_PAYLOAD, (uint32_t)payload);
	*len = RDC_IMG_HDR_BYTES + payload;
	if (*len > cap) {
		free(tmp);
		return RDC_E_RANGE;
	}
	memcpy(out, tmp, *len);
	free(tmp);
	return 0;
}

int rdc_image_encode(uint32_t codec, const uint8_t *px, uint32_t w, uint32_t h,
		     uint32_t channels, size_t pitch, uint8_t *out, size_t cap,
		     size_t *len)
{
	uint32_t level = codec == RDC_IMG_DPCMQ ? RDC_IMAGE_STEP_DEFAULT :
			 codec == RDC_IMG_DCT	? RDC_IMAGE_QUALITY_DEFAULT :
						  0;

	return img_encode(codec, level, px, w, h, channels, pitch, out, cap,
			  len);
}

int rdc_image_encode_lossy(uint32_t codec, uint32_t level, const uint8_t *px,
			   uint32_t w, uint32_t h, uint32_t channels,
			   size_t pitch, uint8_t *out, size_t cap, size_t *len)
{
	if ((codec != RDC_IMG_DPCMQ && codec != RDC_IMG_DCT) || level < 1 ||
	    level > (codec == RDC_IMG_DCT ? 100u : 255u))
		return RDC_E_INVAL;
	return img_encode(codec, level, px, w, h, channels, pitch, out, cap,
			  len);
}

int rdc_image_samples(const uint32_t *xrgb, uint32_t w, uint32_t h,
		      size_t pitch, uint32_t channels, uint8_t *out)
{
	if (!xrgb || !out || !img_args_ok(w, h, channels) || pitch < w)
		return RDC_E_INVAL;
	for (uint32_t y = 0; y < h; y++) {
		for (uint32_t x = 0; x < w; x++) {
			uint32_t p = xrgb[(size_t)y * pitch + x];
			uint32_t r = (p >> 16) & 0xff, g = (p >> 8) & 0xff;
			uint32_t b = p & 0xff;
			uint8_t *o = out + ((size_t)y * w + x) * channels;

			if (channels == 1) {
				o[0] = (uint8_t)IMG_LUMA(r, g, b);
			} else {
				o[0] = (uint8_t)r;
				o[1] = (uint8_t)g;
				o[2] = (uint8_t)b;
			}
		}
	}
	return 0;
}

int rdc_image_png_read(const char *path, uint32_t **xrgb, uint32_t *w,
		       uint32_t *h)
{
	png_image img;
	uint32_t *buf;
	uint8_t *rgb;

	if (!path || !xrgb || !w || !h)
		return RDC_E_INVAL;
	memset(&img, 0, sizeof(img));
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&img, path))
		return rdc_err_detail(RDC_E_FILE, "%s: %s", path, img.message);
	if (!img.width || !img.height || img.width > RDC_IMG_MAX_WIDTH ||
	    img.height > RDC_IMG_MAX_HEIGHT) {
		png_image_free(&img);
		return rdc_err_detail(RDC_E_RANGE, "%s: %ux%u (at most %ux%u)",
				      path, img.width, img.height,
				      RDC_IMG_MAX_WIDTH, RDC_IMG_MAX_HEIGHT);
	}
	img.format = PNG_FORMAT_RGB;
	rgb = malloc((size_t)img.width * img.height * 3);
	buf = malloc((size_t)img.width * img.height * 4);
	if (!rgb || !buf) {
		free(rgb);
		free(buf);
		png_image_free(&img);
		return RDC_E_NOMEM;
	}
	if (!png_image_finish_read(&img, NULL, rgb, 0, NULL)) {
		free(rgb);
		free(buf);
		return rdc_err_detail(RDC_E_FILE, "%s: %s", path, img.message);
	}
	for (size_t i = 0; i < (size_t)img.width * img.height; i++)
		buf[i] = (uint32_t)rgb[3 * i] << 16 |
			 (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2];
	free(rgb);
	*xrgb = buf;
	*w = img.width;
	*h = img.height;
	return 0;
}
