// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Host-side image encoders for the DP's DECODE command: RLE (PackBits on
 * pixels), DPCM (median predictor, Rice codes with a parameter chosen
 * per row), BTC (absolute-moment block truncation coding, 4x4), HUFF
 * (a canonical Huffman code of the samples, built for each picture) and
 * DPCMQ (DPCM's predictor and codes on quantised residuals).  The
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
	if (!tmp ||
	    ((codec == RDC_IMG_DPCM || codec == RDC_IMG_DPCMQ) && !res) ||
	    (codec == RDC_IMG_DPCMQ && !rec)) {
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
	uint32_t level = codec == RDC_IMG_DPCMQ ? RDC_IMAGE_STEP_DEFAULT : 0;

	return img_encode(codec, level, px, w, h, channels, pitch, out, cap,
			  len);
}

int rdc_image_encode_lossy(uint32_t codec, uint32_t level, const uint8_t *px,
			   uint32_t w, uint32_t h, uint32_t channels,
			   size_t pitch, uint8_t *out, size_t cap, size_t *len)
{
	if (codec != RDC_IMG_DPCMQ || level < 1 || level > 255)
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
