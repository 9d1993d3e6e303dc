// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * DECODE: an RLE, DPCM, BTC, HUFF, DPCMQ or DCT image stream in VRAM
 * (rdc_image.h) decoded into DST.
 *
 * The stream is distrusted: every byte comes through a reader bounded by
 * the header's payload size, itself bounded by the command's size
 * argument, so nothing past the stream is read.  All but BTC are decoded
 * twice: once to check the stream (nothing written), then to draw it, so
 * a corrupt stream is rejected with RDC_ERR_DATA before any pixel
 * changes, as every rejected command.  A BTC stream's size says whether
 * it is whole, and any bytes are valid levels and bitmaps.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "img_int.h"

/* A bounded byte and bit reader over the payload. */
struct img_in {
	uint32_t addr, end;  /* next VRAM byte to read; end of the payload */
	uint32_t pos, len;   /* bytes of dp->img.in used, held */
	uint32_t acc, nbits; /* bits not yet used, most significant first */
};

struct dec {
	uint32_t codec, ch, w, h, payload;
	int32_t x, y; /* where the image's top-left pixel lands in DST */
	struct rdc_rect clip;
	bool emit; /* false: the check pass */
};

static void in_start(struct img_in *r, uint32_t addr, uint32_t bytes)
{
	r->addr = addr;
	r->end = addr + bytes;
	r->pos = 0;
	r->len = 0;
	r->acc = 0;
	r->nbits = 0;
}

/* The next piece of at most RDC_DP_IMG_IN_CHUNK bytes, as one read span. */
static bool in_fill(struct rdc_dp *dp, struct img_in *r)
{
	const uint8_t *p;
	uint32_t n;

	if (r->addr >= r->end)
		return false;
	n = RDC_MIN(r->end - r->addr, RDC_DP_IMG_IN_CHUNK);
	p = rdc_port_span(dp->hw, r->addr, n, RDC_BUS_READ);
	if (!p)
		return false;
	rdc_memcpy(dp->img.in, p, n);
	r->addr += n;
	r->pos = 0;
	r->len = n;
	return true;
}

static bool in_byte(struct rdc_dp *dp, struct img_in *r, uint32_t *b)
{
	if (r->pos == r->len && !in_fill(dp, r))
		return false;
	*b = dp->img.in[r->pos++];
	return true;
}

/* Bytes of the payload not yet taken. */
static uint32_t in_left(const struct img_in *r)
{
	return r->end - r->addr + r->len - r->pos;
}

/* n <= 16 bits, most significant first. */
static bool in_bits(struct rdc_dp *dp, struct img_in *r, uint32_t n,
		    uint32_t *v)
{
	uint32_t b;

	while (r->nbits < n) {
		if (!in_byte(dp, r, &b))
			return false;
		r->acc = r->acc << 8 | b;
		r->nbits += 8;
	}
	*v = n ? r->acc >> (r->nbits - n) & ((1u << n) - 1) : 0;
	r->nbits -= n;
	return true;
}

/*
 * Columns [col, col + n) of the image's row `row` (samples s, from col
 * on) into DST, clipped, through the ROP.
 */
static void emit_seg(struct rdc_dp *dp, const struct dec *d, uint32_t row,
		     uint32_t col, uint32_t n, const uint8_t *s)
{
	uint32_t fmt = dp->st.dst.format, i, k;
	int32_t y = d->y + (int32_t)row, x0, x1, x;
	const uint8_t *p;

	if (!d->emit || y < d->clip.y0 || y >= d->clip.y1)
		return;
	x0 = RDC_MAX(d->x + (int32_t)col, d->clip.x0);
	x1 = RDC_MIN(d->x + (int32_t)(col + n), d->clip.x1);
	for (x = x0; x < x1; x += (int32_t)k) {
		k = (uint32_t)RDC_MIN(x1 - x, (int32_t)RDC_DP_CHUNK);
		p = s + (uint32_t)(x - d->x - (int32_t)col) * d->ch;
		for (i = 0; i < k; i++, p += d->ch) {
			if (d->ch == 3)
				dp->px[i] = img_pack_rgb(fmt, p[0], p[1], p[2]);
			else if (rdc_format_indexed(fmt))
				dp->px[i] = p[0];
			else
				dp->px[i] = img_pack_rgb(fmt, p[0], p[0], p[0]);
		}
		rdc_dp_span_px(dp, y, x, k, 0, dp->px, NULL);
	}
}

/* Row `row` of the image (samples s) into DST. */
static void emit_row(struct rdc_dp *dp, const struct dec *d, uint32_t row,
		     const uint8_t *s)
{
	emit_seg(dp, d, row, 0, d->w, s);
}

/*
 * An RLE packet's header: lit literals follow, or a run of px; false at
 * the end of the data.
 */
static bool rle_packet(struct rdc_dp *dp, const struct dec *d, struct img_in *r,
		       uint32_t *run, uint32_t *lit, uint32_t *px)
{
	uint32_t c, k;

	if (!in_byte(dp, r, &c))
		return false;
	if (c < RDC_IMG_RLE_LITERAL_MAX) {
		*lit = c + 1;
		return true;
	}
	*run = c - 126;
	for (k = 0; k < d->ch; k++)
		if (!in_byte(dp, r, &px[k]))
			return false;
	return true;
}

static uint32_t dec_rle(struct rdc_dp *dp, const struct dec *d,
			struct img_in *r)
{
	uint8_t *row = dp->img.u.dec[0];
	uint32_t run = 0, lit = 0, px[3] = { 0 }, c, x, y, k, i;

	for (y = 0; y < d->h; y++) {
		for (x = 0, i = 0; x < d->w; x++, i += d->ch) {
			if (!run && !lit &&
			    !rle_packet(dp, d, r, &run, &lit, px))
				return RDC_ERR_DATA;
			if (lit) {
				for (k = 0; k < d->ch; k++) {
					if (!in_byte(dp, r, &c))
						return RDC_ERR_DATA;
					row[i + k] = (uint8_t)c;
				}
				lit--;
			} else {
				for (k = 0; k < d->ch; k++)
					row[i + k] = (uint8_t)px[k];
				run--;
			}
		}
		emit_row(dp, d, y, row);
	}
	/* a packet past the last pixel, or bytes after it */
	return run || lit || in_left(r) ? RDC_ERR_DATA : RDC_ERR_NONE;
}

/* The median edge detector (LOCO-I): a left, b above, c above-left. */
static uint32_t med(uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t lo = RDC_MIN(a, b), hi = RDC_MAX(a, b);

	if (c >= hi)
		return lo;
	if (c <= lo)
		return hi;
	return a + b - c;
}

/*
 * DPCM (step 0: lossless, residuals mod 256) and DPCMQ (step 1..255:
 * quantised residuals, the sum clamped) share the predictor and codes.
 */
static uint32_t dec_dpcm(struct rdc_dp *dp, const struct dec *d,
			 struct img_in *r, uint32_t step)
{
	uint32_t x, y, k, q, m, bit, p, i, n = d->w * d->ch, ch = d->ch;
	uint32_t ebits = step ? RDC_IMG_DPCMQ_MBITS : 8;
	uint32_t mmax = step ? RDC_IMG_DPCMQ_MMAX : 255;
	int32_t v;
	uint8_t *cur, *prev;

	for (y = 0; y < d->h; y++) {
		cur = dp->img.u.dec[y & 1];
		prev = dp->img.u.dec[(y & 1) ^ 1];
		if (!in_bits(dp, r, RDC_IMG_DPCM_KBITS, &k))
			return RDC_ERR_DATA;
		for (i = 0; i < n; i++) {
			x = i / ch;
			if (!y)
				p = x ? cur[i - ch] : 128;
			else if (!x)
				p = prev[i];
			else
				p = med(cur[i - ch], prev[i], prev[i - ch]);
			for (q = 0; q < RDC_IMG_DPCM_ESCAPE; q++) {
				if (!in_bits(dp, r, 1, &bit))
					return RDC_ERR_DATA;
				if (!bit)
					break;
			}
			if (q == RDC_IMG_DPCM_ESCAPE) {
				if (!in_bits(dp, r, ebits, &m))
					return RDC_ERR_DATA;
			} else {
				if (!in_bits(dp, r, k, &m))
					return RDC_ERR_DATA;
				m |= q << k;
				if (m > mmax) /* no encoder writes it */
					return RDC_ERR_DATA;
			}
			/* zigzag back: 0, -1, 1, -2, ... */
			v = m & 1 ? -(int32_t)((m + 1) / 2) : (int32_t)(m / 2);
			if (!step) {
				cur[i] = (uint8_t)(p + (uint32_t)v);
				continue;
			}
			v = (int32_t)p + v * (int32_t)step;
			cur[i] = (uint8_t)RDC_MIN(RDC_MAX(v, 0), 255);
		}
		emit_row(dp, d, y, cur);
	}
	return in_left(r) ? RDC_ERR_DATA : RDC_ERR_NONE;
}

static uint32_t dec_btc(struct rdc_dp *dp, const struct dec *d,
			struct img_in *r)
{
	uint8_t *blk = dp->img.u.dec[0], *row = dp->img.u.dec[1];
	uint32_t bw = (d->w + 3) / 4, bh = (d->h + 3) / 4, bytes, by, ry, x, c,
		 i, b;
	const uint8_t *e;

	bytes = bw * d->ch * RDC_IMG_BTC_BYTES;
	for (by = 0; by < bh; by++) {
		for (i = 0; i < bytes; i++) {
			if (!in_byte(dp, r, &b))
				return RDC_ERR_DATA;
			blk[i] = (uint8_t)b;
		}
		for (ry = 0; ry < 4 && by * 4 + ry < d->h; ry++) {
			for (x = 0, i = 0; x < d->w; x++) {
				e = blk + (x / 4) * d->ch * RDC_IMG_BTC_BYTES;
				for (c = 0; c < d->ch; c++, i++) {
					b = rdc_ld16(e + 4 * c + 2) >>
						    (ry * 4 + x % 4) &
					    1;
					row[i] = e[4 * c + b];
				}
			}
			emit_row(dp, d, by * 4 + ry, row);
		}
	}
	return in_left(r) ? RDC_ERR_DATA : RDC_ERR_NONE;
}

/*
 * A canonical code's table (rdc_image.h) into h, as JPEG's decoder
 * tables: per length the first and last code and the index of the first
 * one's symbol.  False for no symbols, more than 256, or codes that
 * overflow their length.
 */
static bool huff_load(struct rdc_dp *dp, struct img_in *r,
		      struct rdc_dp_huff *h)
{
	uint32_t n[RDC_IMG_HUFF_LENS + 1], l, i, code = 0, k = 0, b;

	for (l = 1; l <= RDC_IMG_HUFF_LENS; l++) {
		if (!in_byte(dp, r, &n[l]))
			return false;
		k += n[l];
	}
	if (!k || k > RDC_IMG_HUFF_SYMS)
		return false;
	for (i = 0; i < k; i++) {
		if (!in_byte(dp, r, &b))
			return false;
		h->sym[i] = (uint8_t)b;
	}
	for (l = 1, k = 0; l <= RDC_IMG_HUFF_LENS; l++) {
		h->mincode[l] = code;
		h->valptr[l] = k;
		code += n[l];
		k += n[l];
		if (code > 1u << l)
			return false;
		h->maxcode[l] = n[l] ? (int32_t)code - 1 : -1;
		code <<= 1;
	}
	return true;
}

/* The next code's symbol, one bit at a time; false past the stream. */
static bool huff_sym(struct rdc_dp *dp, struct img_in *r,
		     const struct rdc_dp_huff *h, uint32_t *sym)
{
	uint32_t code = 0, l, bit;

	for (l = 1; l <= RDC_IMG_HUFF_LENS; l++) {
		if (!in_bits(dp, r, 1, &bit))
			return false;
		code = code << 1 | bit;
		if (code >= h->mincode[l] && (int32_t)code <= h->maxcode[l]) {
			*sym = h->sym[h->valptr[l] + code - h->mincode[l]];
			return true;
		}
	}
	return false; /* no code of 16 bits or fewer */
}

static uint32_t dec_huff(struct rdc_dp *dp, const struct dec *d,
			 struct img_in *r)
{
	uint8_t *row = dp->img.u.huff.row;
	struct rdc_dp_huff *h = &dp->img.u.huff.code;
	uint32_t n = d->w * d->ch, y, i, v;

	if (!huff_load(dp, r, h))
		return RDC_ERR_DATA;
	for (y = 0; y < d->h; y++) {
		for (i = 0; i < n; i++) {
			if (!huff_sym(dp, r, h, &v))
				return RDC_ERR_DATA;
			row[i] = (uint8_t)v;
		}
		emit_row(dp, d, y, row);
	}
	return in_left(r) ? RDC_ERR_DATA : RDC_ERR_NONE;
}

/* Natural (row-major) index of the zigzag order's k-th coefficient. */
static const uint8_t dct_zigzag[RDC_IMG_DCT_QBYTES] = {
	0,  1,	8,  16, 9,  2,	3,  10, 17, 24, 32, 25, 18, 11, 4,  5,
	12, 19, 26, 33, 40, 48, 41, 34, 27, 20, 13, 6,	7,  14, 21, 28,
	35, 42, 49, 56, 57, 50, 43, 36, 29, 22, 15, 23, 30, 37, 44, 51,
	58, 59, 52, 45, 38, 31, 39, 46, 53, 60, 61, 54, 47, 55, 62, 63,
};

/*
 * dct_cos[x][u] = round(2^13 * C(u) / 2 * cos((2x + 1) u pi / 16)): the
 * 1D IDCT is g(x) = sum_u dct_cos[x][u] F(u) / 2^13.
 */
static const int16_t dct_cos[8][8] = {
	{ 2896, 4017, 3784, 3406, 2896, 2276, 1567, 799 },
	{ 2896, 3406, 1567, -799, -2896, -4017, -3784, -2276 },
	{ 2896, 2276, -1567, -4017, -2896, 799, 3784, 3406 },
	{ 2896, 799, -3784, -2276, 2896, 3406, -1567, -4017 },
	{ 2896, -799, -3784, 2276, 2896, -3406, -1567, 4017 },
	{ 2896, -2276, -1567, 4017, -2896, -799, 3784, -3406 },
	{ 2896, -3406, 1567, 799, -2896, 4017, -3784, 2276 },
	{ 2896, -4017, 3784, -3406, 2896, -2276, 1567, -799 },
};

/*
 * The 8x8 IDCT of blk (row-major F(u, v) at [8v + u]) in 32-bit integers:
 * rows, kept with 3 fraction bits, then columns.  With |F| <= 2048 and
 * sum_u |dct_cos[x][u]| <= 21,641, the row pass stays within 43,282 * 8
 * and the column sums within 2^30.  Samples level-shifted by 128 into
 * out (stride `pitch` bytes, every `ch`-th byte).
 */
static void dct_idct(const int32_t *blk, uint8_t *out, uint32_t pitch,
		     uint32_t ch)
{
	int32_t t[64], sum, v;
	uint32_t x, y, u;

	for (y = 0; y < 8; y++) {
		for (x = 0; x < 8; x++) {
			for (u = 0, sum = 0; u < 8; u++)
				sum += dct_cos[x][u] * blk[8 * y + u];
			t[8 * y + x] = (sum + (1 << 9)) >> 10;
		}
	}
	for (x = 0; x < 8; x++) {
		for (y = 0; y < 8; y++) {
			for (u = 0, sum = 0; u < 8; u++)
				sum += dct_cos[y][u] * t[8 * u + x];
			v = ((sum + (1 << 15)) >> 16) + 128;
			out[y * pitch + x * ch] =
				(uint8_t)RDC_MIN(RDC_MAX(v, 0), 255);
		}
	}
}

/* s bits as a signed value (JPEG's EXTEND); false past the stream. */
static bool dct_value(struct rdc_dp *dp, struct img_in *r, uint32_t s,
		      int32_t *v)
{
	uint32_t b;

	if (!in_bits(dp, r, s, &b))
		return false;
	*v = s && !(b >> (s - 1)) ? (int32_t)b - (int32_t)(1u << s) + 1 :
				    (int32_t)b;
	return true;
}

/* One block of channel c: its coefficients into blk, dequantised. */
static uint32_t dct_block(struct rdc_dp *dp, struct img_in *r, uint32_t c)
{
	int32_t *blk = dp->img.u.dct.blk, v;
	uint32_t k, sym, run, s;

	if (!huff_sym(dp, r, &dp->img.u.dct.dc, &s) || s > 11 ||
	    !dct_value(dp, r, s, &v))
		return RDC_ERR_DATA;
	v += dp->img.u.dct.pred[c];
	if (v > (int32_t)RDC_IMG_DCT_DC_MAX || v < -(int32_t)RDC_IMG_DCT_DC_MAX)
		return RDC_ERR_DATA;
	dp->img.u.dct.pred[c] = v;
	rdc_memset(blk, 0, sizeof(dp->img.u.dct.blk));
	blk[0] = v;
	for (k = 1; k < RDC_IMG_DCT_QBYTES; k++) {
		if (!huff_sym(dp, r, &dp->img.u.dct.ac, &sym))
			return RDC_ERR_DATA;
		run = sym >> 4;
		s = sym & 15;
		if (sym == RDC_IMG_DCT_EOB)
			break;
		if (sym == RDC_IMG_DCT_ZRL) {
			k += 15;
			continue;
		}
		k += run;
		if (!s || s > 10 || k >= RDC_IMG_DCT_QBYTES ||
		    !dct_value(dp, r, s, &v))
			return RDC_ERR_DATA;
		blk[dct_zigzag[k]] = v;
	}
	if (k > RDC_IMG_DCT_QBYTES) /* a ZRL past the last coefficient */
		return RDC_ERR_DATA;
	for (k = 0; k < RDC_IMG_DCT_QBYTES; k++) {
		v = blk[dct_zigzag[k]] * dp->img.u.dct.q[k];
		blk[dct_zigzag[k]] =
			RDC_MIN(RDC_MAX(v, -RDC_IMG_DCT_COEF_MAX - 1),
				RDC_IMG_DCT_COEF_MAX);
	}
	return RDC_ERR_NONE;
}

/*
 * Bands of 8 rows, each decoded into strips of RDC_DP_DCT_STRIP pixels
 * (64 blocks) that are written as a row span each once complete.  The
 * check pass parses the codes only.
 */
static uint32_t dec_dct(struct rdc_dp *dp, const struct dec *d,
			struct img_in *r)
{
	uint32_t bw = (d->w + 7) / 8, bh = (d->h + 7) / 8, bx, by, c, k, b, y;
	uint32_t pitch = RDC_DP_DCT_STRIP * 3, x0, err;
	uint8_t *strip = &dp->img.u.dct.strip[0][0];

	for (k = 0; k < RDC_IMG_DCT_QBYTES; k++) {
		if (!in_byte(dp, r, &b) || !b)
			return RDC_ERR_DATA;
		dp->img.u.dct.q[k] = (uint8_t)b;
	}
	if (!huff_load(dp, r, &dp->img.u.dct.dc) ||
	    !huff_load(dp, r, &dp->img.u.dct.ac))
		return RDC_ERR_DATA;
	for (c = 0; c < 3; c++)
		dp->img.u.dct.pred[c] = 0;
	for (by = 0; by < bh; by++) {
		for (bx = 0; bx < bw; bx++) {
			x0 = bx * 8 % RDC_DP_DCT_STRIP;
			for (c = 0; c < d->ch; c++) {
				err = dct_block(dp, r, c);
				if (err)
					return err;
				if (d->emit)
					dct_idct(dp->img.u.dct.blk,
						 strip + x0 * d->ch + c, pitch,
						 d->ch);
			}
			if (bx + 1 < bw && (x0 + 8) % RDC_DP_DCT_STRIP)
				continue;
			/* the strip is complete: its rows into DST */
			x0 = bx * 8 / RDC_DP_DCT_STRIP * RDC_DP_DCT_STRIP;
			for (y = 0; y < 8 && by * 8 + y < d->h; y++)
				emit_seg(dp, d, by * 8 + y, x0,
					 RDC_MIN(d->w - x0, RDC_DP_DCT_STRIP),
					 strip + y * pitch);
		}
	}
	return in_left(r) ? RDC_ERR_DATA : RDC_ERR_NONE;
}

static uint32_t dec_run(struct rdc_dp *dp, const struct dec *d, uint32_t base)
{
	struct img_in r;
	uint32_t step;

	in_start(&r, base, d->payload);
	switch (d->codec) {
	case RDC_IMG_RLE:
		return dec_rle(dp, d, &r);
	case RDC_IMG_DPCM:
		return dec_dpcm(dp, d, &r, 0);
	case RDC_IMG_DPCMQ:
		if (!in_byte(dp, &r, &step) || !step)
			return RDC_ERR_DATA;
		return dec_dpcm(dp, d, &r, step);
	case RDC_IMG_HUFF:
		return dec_huff(dp, d, &r);
	case RDC_IMG_DCT:
		return dec_dct(dp, d, &r);
	default:
		return dec_btc(dp, d, &r);
	}
}

uint32_t dp_cmd_decode(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	uint32_t addr = a[0], size = a[1], err;
	const uint8_t *h;
	struct dec d;
	uint64_t blocks;

	if (fl)
		return RDC_ERR_ARG;
	if (RDC_X(a[2]) < RDC_COORD_MIN || RDC_X(a[2]) > RDC_COORD_MAX ||
	    RDC_Y(a[2]) < RDC_COORD_MIN || RDC_Y(a[2]) > RDC_COORD_MAX ||
	    (uint64_t)addr + size > dp->hw->vram_size)
		return RDC_ERR_RANGE;
	if (size < RDC_IMG_HDR_BYTES)
		return RDC_ERR_DATA;
	h = rdc_port_span(dp->hw, addr, RDC_IMG_HDR_BYTES, RDC_BUS_READ);
	if (!h)
		return RDC_ERR_RANGE;
	d.codec = h[RDC_IMG_OFF_CODEC];
	d.ch = h[RDC_IMG_OFF_CHANNELS];
	d.w = rdc_ld16(h + RDC_IMG_OFF_WIDTH);
	d.h = rdc_ld16(h + RDC_IMG_OFF_HEIGHT);
	d.payload = rdc_ld32(h + RDC_IMG_OFF_PAYLOAD);
	if (rdc_ld32(h + RDC_IMG_OFF_MAGIC) != RDC_IMG_MAGIC ||
	    rdc_ld16(h + RDC_IMG_OFF_RESERVED) || d.codec < RDC_IMG_RLE ||
	    d.codec >= RDC_IMG_CODEC_END || (d.ch != 1 && d.ch != 3) || !d.w ||
	    d.w > RDC_IMG_MAX_WIDTH || !d.h || d.h > RDC_IMG_MAX_HEIGHT ||
	    d.payload > size - RDC_IMG_HDR_BYTES)
		return RDC_ERR_DATA;
	if (d.codec == RDC_IMG_BTC) {
		blocks = (uint64_t)((d.w + 3) / 4) * ((d.h + 3) / 4);
		if (d.payload != blocks * d.ch * RDC_IMG_BTC_BYTES)
			return RDC_ERR_DATA;
	}
	/* three channels need an RGB destination */
	if (d.ch == 3 && rdc_format_indexed(dp->st.dst.format))
		return RDC_ERR_ARG;
	d.x = RDC_X(a[2]);
	d.y = RDC_Y(a[2]);
	d.clip = rdc_dp_eff_clip(dp);
	addr += RDC_IMG_HDR_BYTES;
	if (d.codec != RDC_IMG_BTC) {
		d.emit = false;
		err = dec_run(dp, &d, addr);
		if (err)
			return err;
	}
	d.emit = true;
	return dec_run(dp, &d, addr);
}
