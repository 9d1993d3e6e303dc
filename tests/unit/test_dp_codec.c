// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * DECODE of the entropy and lossy codecs: HUFF, DPCMQ and DCT streams
 * written by librdc's encoders and decoded by the DP, each against a
 * decoder of this file written from rdc_image.h's description alone and
 * in another way than the DP's: HUFF by a walk down an explicit code tree
 * one bit at a time, DPCMQ over the whole image with the predictor as a
 * median of three, DCT with a floating-point IDCT (the DP's integer IDCT
 * within 1 of it).  Corrupt streams give RDC_ERR_DATA with
 * nothing drawn; the cost is the documented one, to the cycle.
 */
#include <math.h>

#include "tdp_image.h"
#include "rdc.h"

static uint8_t *encode(uint32_t codec, uint32_t level, const uint8_t *px,
		       uint32_t w, uint32_t h, uint32_t ch, size_t *len)
{
	size_t cap = rdc_image_bound(codec, w, h, ch);
	uint8_t *out = malloc(cap);

	assert_non_null(out);
	if (level)
		assert_int_equal(rdc_image_encode_lossy(codec, level, px, w, h,
							ch, (size_t)w * ch, out,
							cap, len),
				 0);
	else
		assert_int_equal(rdc_image_encode(codec, px, w, h, ch,
						  (size_t)w * ch, out, cap,
						  len),
				 0);
	assert_true(*len <= cap);
	return out;
}

/* Expect err from DECODE of stream, with DST untouched and the DP fine. */
static void expect_bad(struct tdp *t, const uint8_t *stream, size_t len,
		       uint32_t err)
{
	struct rdc_surface s = dst_surface(RDC_FMT_XRGB8888);
	size_t i;

	prep_dst(t, &s);
	tdp_clear_err(t);
	decode_at(t, stream, len, (uint32_t)len, 0, 0);
	assert_int_equal(tdp_err(t), err);
	for (i = 0; i < (size_t)s.stride * s.height; i++)
		if (t->vram[i] != SENTINEL)
			fail_msg("byte %zu written by a rejected DECODE", i);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_FENCE, 77);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_FENCE), 77);
}

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/* A bit reader of this file's own: MSB first, false past the end. */
struct rbits {
	const uint8_t *p;
	size_t n, bit;
};

static int rbit(struct rbits *b)
{
	int v;

	if (b->bit >= 8 * b->n)
		return -1;
	v = b->p[b->bit / 8] >> (7 - b->bit % 8) & 1;
	b->bit++;
	return v;
}

static int rbits_get(struct rbits *b, uint32_t n, uint32_t *v)
{
	int bit;

	*v = 0;
	while (n--) {
		bit = rbit(b);
		if (bit < 0)
			return -1;
		*v = *v << 1 | (uint32_t)bit;
	}
	return 0;
}

/*
 * A code tree: node 0 the root, kid[i][bit] the next node (0: none),
 * leaf[i] the symbol + 1 of a leaf (0: inner node).
 */
struct rtree {
	uint16_t kid[2 * 65536][2];
	uint16_t leaf[2 * 65536];
	uint32_t nodes;
};

/* The table at p into t, codes counted up as rdc_image.h says; its size. */
static size_t rtree_load(struct rtree *t, const uint8_t *p, size_t n)
{
	uint32_t l, i, k = 0, code = 0, node, bit, d;

	memset(t, 0, sizeof(*t));
	t->nodes = 1;
	assert_true(n >= RDC_IMG_HUFF_LENS);
	for (l = 0; l < RDC_IMG_HUFF_LENS; l++)
		k += p[l];
	assert_true(k >= 1 && k <= 256 && n >= RDC_IMG_HUFF_LENS + k);
	k = 0;
	for (l = 1; l <= RDC_IMG_HUFF_LENS; l++) {
		for (i = 0; i < p[l - 1]; i++, k++, code++) {
			assert_true(code < 1u << l);
			node = 0;
			for (d = l; d--;) {
				bit = code >> d & 1;
				assert_int_equal(t->leaf[node], 0);
				if (!t->kid[node][bit])
					t->kid[node][bit] =
						(uint16_t)t->nodes++;
				node = t->kid[node][bit];
			}
			t->leaf[node] =
				(uint16_t)(p[RDC_IMG_HUFF_LENS + k] + 1);
		}
		code <<= 1;
	}
	return RDC_IMG_HUFF_LENS + k;
}

/* One symbol by walking the tree; -1 at the end or off the tree. */
static int rtree_sym(const struct rtree *t, struct rbits *b)
{
	uint32_t node = 0;
	int bit;

	while (!t->leaf[node]) {
		bit = rbit(b);
		if (bit < 0 || !t->kid[node][bit])
			return -1;
		node = t->kid[node][bit];
	}
	return t->leaf[node] - 1;
}

/*
 * HUFF decoded by the tree walk: the samples into out; with rowend, the
 * payload bytes the decoding has touched when each row is complete.
 */
static void ref_huff(const uint8_t *st, size_t len, uint8_t *out,
		     uint32_t *rowend)
{
	static struct rtree tree;
	uint32_t w = st[8] | st[9] << 8, h = st[10] | st[11] << 8, ch = st[5];
	size_t i, n = (size_t)w * h * ch, tab;
	struct rbits b;
	int v;

	assert_int_equal(st[4], RDC_IMG_HUFF);
	tab = rtree_load(&tree, st + 16, len - 16);
	b.p = st + 16 + tab;
	b.n = len - 16 - tab;
	b.bit = 0;
	for (i = 0; i < n; i++) {
		v = rtree_sym(&tree, &b);
		assert_true(v >= 0);
		out[i] = (uint8_t)v;
		if (rowend && (i + 1) % ((size_t)w * ch) == 0)
			rowend[i / ((size_t)w * ch)] =
				(uint32_t)(tab + (b.bit + 7) / 8);
	}
	/* only the zero padding of the last byte is left */
	assert_true(b.n * 8 - b.bit < 8);
	while ((v = rbit(&b)) >= 0)
		assert_int_equal(v, 0);
}

/* The median of three: LOCO-I's predictor is median(a, b, a + b - c). */
static int median3(int a, int b, int c)
{
	if (a > b) {
		int t = a;

		a = b;
		b = t;
	}
	return c < a ? a : c > b ? b : c;
}

/*
 * DPCMQ decoded over the whole image at once: each sample's neighbours
 * looked up in out[] by (x, y), the prediction as a median of three.
 */
static void ref_dpcmq(const uint8_t *st, size_t len, uint8_t *out,
		      uint32_t *rowend)
{
	uint32_t w = st[8] | st[9] << 8, h = st[10] | st[11] << 8, ch = st[5];
	uint32_t step = st[16], x, y, c, k, m, ones;
	struct rbits b = { st + 17, len - 17, 0 };
	int a, up, ul, p, e, v;

	assert_int_equal(st[4], RDC_IMG_DPCMQ);
	assert_true(step >= 1);
#define S(x, y, c) out[((size_t)(y)*w + (x)) * ch + (c)]
	for (y = 0; y < h; y++) {
		assert_int_equal(rbits_get(&b, 3, &k), 0);
		for (x = 0; x < w; x++) {
			for (c = 0; c < ch; c++) {
				for (ones = 0; ones < 16 && rbit(&b) == 1;)
					ones++;
				if (ones == 16) {
					assert_int_equal(rbits_get(&b, 9, &m),
							 0);
				} else {
					assert_int_equal(rbits_get(&b, k, &m),
							 0);
					m += ones << k;
				}
				e = m % 2 ? -(int)(m + 1) / 2 : (int)m / 2;
				a = x ? S(x - 1, y, c) : 0;
				up = y ? S(x, y - 1, c) : 0;
				ul = x && y ? S(x - 1, y - 1, c) : 0;
				if (!y)
					p = x ? a : 128;
				else if (!x)
					p = up;
				else
					p = median3(a, up, a + up - ul);
				v = p + e * (int)step;
				S(x, y, c) = (uint8_t)(v < 0   ? 0 :
						       v > 255 ? 255 :
								 v);
			}
		}
		if (rowend)
			rowend[y] = (uint32_t)(1 + (b.bit + 7) / 8);
	}
#undef S
	assert_true(b.n * 8 - b.bit < 8);
}

/*
 * DCT decoded with a floating-point IDCT: the zigzag order walked along
 * the diagonals, the tables as code trees, each block's samples the
 * IDCT's formula in doubles, rounded.  With ev, the writes: per band of
 * 8 rows and strip of 512 columns, the payload bytes touched when the
 * strip's last block is parsed.
 */
struct ev {
	uint32_t end, y, rows, x, n;
};

static uint32_t ref_dct(const uint8_t *st, size_t len, uint8_t *out,
			struct ev *ev)
{
	static struct rtree dc, ac;
	uint32_t w = st[8] | st[9] << 8, h = st[10] | st[11] << 8, ch = st[5];
	uint32_t bw = (w + 7) / 8, bh = (h + 7) / 8, bx, by, c, k, i, s, r;
	uint32_t zz[64], nev = 0, bits;
	const uint8_t *q = st + 16;
	struct rbits b;
	double F[64], cu[8][8];
	size_t off = 16 + 64;
	int pred[3] = { 0 }, v, sym;

	assert_int_equal(st[4], RDC_IMG_DCT);
	/* zigzag: diagonal d = u + v, odd ones downwards, even upwards */
	for (k = 0, i = 0; i < 15; i++)
		for (r = 0; r < 8; r++) {
			uint32_t row = i % 2 ? r : i - r, col = i - row;

			if (i % 2 == 0 && r > i)
				continue;
			if (i % 2 == 0) {
				row = i - r;
				col = r;
			}
			if (row > 7 || col > 7 || row + col != i)
				continue;
			zz[k++] = row * 8 + col;
		}
	assert_int_equal(k, 64);
	for (k = 0; k < 8; k++)
		for (i = 0; i < 8; i++)
			cu[k][i] = (i ? 1.0 : sqrt(0.5)) *
				   cos((2.0 * k + 1) * i * M_PI / 16);
	off += rtree_load(&dc, st + off, len - off);
	off += rtree_load(&ac, st + off, len - off);
	b.p = st + off;
	b.n = len - off;
	b.bit = 0;
	for (by = 0; by < bh; by++) {
		for (bx = 0; bx < bw; bx++) {
			for (c = 0; c < ch; c++) {
				int32_t z[64] = { 0 };

				sym = rtree_sym(&dc, &b);
				assert_true(sym >= 0 && sym <= 11);
				assert_int_equal(
					rbits_get(&b, (uint32_t)sym, &bits), 0);
				v = sym && bits < 1u << (sym - 1) ?
					    (int)bits - (1 << sym) + 1 :
					    (int)bits;
				pred[c] += v;
				z[0] = pred[c];
				for (k = 1; k < 64; k++) {
					sym = rtree_sym(&ac, &b);
					assert_true(sym >= 0);
					if (sym == 0)
						break;
					r = (uint32_t)sym >> 4;
					s = (uint32_t)sym & 15;
					if (sym == 0xf0) {
						k += 15;
						continue;
					}
					k += r;
					assert_true(s >= 1 && s <= 10 &&
						    k < 64);
					assert_int_equal(
						rbits_get(&b, s, &bits), 0);
					z[k] = bits < 1u << (s - 1) ?
						       (int)bits - (1 << s) +
							       1 :
						       (int)bits;
				}
				for (k = 0; k < 64; k++) {
					v = z[k] * q[k];
					v = v > 2047  ? 2047 :
					    v < -2048 ? -2048 :
							v;
					F[zz[k]] = v;
				}
				for (i = 0; i < 64; i++) {
					uint32_t x = i % 8, y = i / 8, u, vv;
					double f = 0;

					for (vv = 0; vv < 8; vv++)
						for (u = 0; u < 8; u++)
							f += cu[x][u] *
							     cu[y][vv] *
							     F[vv * 8 + u];
					f = floor(f / 4 + 128 + 0.5);
					f = f < 0 ? 0 : f > 255 ? 255 : f;
					if (bx * 8 + x < w && by * 8 + y < h)
						out[((size_t)(by * 8 + y) * w +
						     bx * 8 + x) *
							    ch +
						    c] = (uint8_t)f;
				}
			}
			if (ev && (bx + 1 == bw || (bx + 1) % 64 == 0)) {
				ev[nev].end =
					(uint32_t)(off - 16 + (b.bit + 7) / 8);
				ev[nev].y = by * 8;
				ev[nev].rows = RDC_MIN(8, h - by * 8);
				ev[nev].x = bx / 64 * 512;
				ev[nev].n = RDC_MIN(512, w - ev[nev].x);
				nev++;
			}
		}
	}
	assert_true(b.n * 8 - b.bit < 8);
	return nev;
}

/*
 * Any codec of this file by its reference: the samples, and the writes
 * (a row each for HUFF and DPCMQ) with the payload bytes touched before
 * each.
 */
static uint32_t ref_events(const uint8_t *st, size_t len, uint8_t *out,
			   struct ev *ev)
{
	uint32_t w = st[8] | st[9] << 8, h = st[10] | st[11] << 8, y;
	uint32_t *rowend = calloc(h, sizeof(*rowend));

	assert_non_null(rowend);
	switch (st[4]) {
	case RDC_IMG_HUFF:
		ref_huff(st, len, out, rowend);
		break;
	case RDC_IMG_DPCMQ:
		ref_dpcmq(st, len, out, rowend);
		break;
	default:
		free(rowend);
		return ref_dct(st, len, out, ev);
	}
	for (y = 0; y < h; y++) {
		ev[y].end = rowend[y];
		ev[y].y = y;
		ev[y].rows = 1;
		ev[y].x = 0;
		ev[y].n = w;
	}
	free(rowend);
	return h;
}

static const uint32_t sizes[][2] = { { 1, 1 },	 { 7, 5 },   { 129, 3 },
				     { 16, 16 }, { 300, 9 }, { 1, 40 } };

/* HUFF is lossless: the DP gives the original, as does the tree walk. */
static void test_huff_roundtrip(void **state)
{
	struct tdp *t = *state;
	static const uint32_t fmts[][2] = {
		{ RDC_FMT_I8, 1 },
		{ RDC_FMT_XRGB8888, 3 },
		{ RDC_FMT_RGB565, 3 },
	};
	uint32_t si, fi, w, h, ch;
	int kind;

	for (si = 0; si < RDC_ARRAY_SIZE(sizes); si++) {
		for (fi = 0; fi < RDC_ARRAY_SIZE(fmts); fi++) {
			for (kind = 0; kind < 5; kind++) {
				struct rdc_surface s = dst_surface(fmts[fi][0]);
				uint8_t *img, *ref, *st;
				size_t len, n;

				w = sizes[si][0];
				h = sizes[si][1];
				ch = fmts[fi][1];
				n = (size_t)w * h * ch;
				img = malloc(n);
				ref = malloc(n);
				assert_non_null(img);
				assert_non_null(ref);
				gen_image(img, w, h, ch, kind, si * 7 + fi);
				st = encode(RDC_IMG_HUFF, 0, img, w, h, ch,
					    &len);
				ref_huff(st, len, ref, NULL);
				assert_memory_equal(ref, img, n);
				prep_dst(t, &s);
				decode_at(t, st, len, (uint32_t)len, 5, 3);
				assert_int_equal(tdp_err(t), RDC_ERR_NONE);
				check_exact(t, &s, img, RDC_MIN(w, DST_W - 5),
					    h, ch, 5, 3);
				free(st);
				free(ref);
				free(img);
			}
		}
	}
}

/*
 * Long codes: symbol v appearing 2^(20 - v) times would need codes of
 * 1..19 bits; the encoder limits them to 16, and the tree walk and the
 * DP agree on the result.
 */
static void test_huff_long_codes(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = dst_surface(RDC_FMT_I8);
	uint32_t w = 256, h = 0, y, x, v, n;
	uint8_t *img, *ref, *st;
	size_t len;

	for (v = 0, n = 0; v < 20; v++)
		n += 1u << (20 - v);
	h = (n + w - 1) / w;
	img = calloc((size_t)w * h, 1);
	ref = malloc((size_t)w * h);
	assert_non_null(img);
	assert_non_null(ref);
	for (v = 0, x = 0; v < 20; v++)
		for (y = 0; y < 1u << (20 - v); y++)
			img[x++] = (uint8_t)v;
	st = encode(RDC_IMG_HUFF, 0, img, w, h, 1, &len);
	/* 20 symbols; unlimited, the two rarest codes would be 19 bits */
	for (x = 0, n = 0; x < 16; x++)
		n += st[16 + x];
	assert_int_equal(n, 20);
	assert_true(st[16 + 14] + st[16 + 15] > 0);
	ref_huff(st, len, ref, NULL);
	assert_memory_equal(ref, img, (size_t)w * h);
	assert_true(len < TDP_VRAM_SIZE - STREAM_BASE);
	prep_dst(t, &s);
	decode_at(t, st, len, (uint32_t)len, 0, 0);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	check_exact(t, &s, img, w, RDC_MIN(h, DST_H), 1, 0, 0);
	free(st);
	free(ref);
	free(img);
}

static void test_huff_corrupt(void **state)
{
	struct tdp *t = *state;
	uint8_t b[64];
	size_t len;

	/* 4 x 1 grey: two symbols, codes 0 and 1 */
	memset(b, 0, sizeof(b));
	put32(b, RDC_IMG_MAGIC);
	b[4] = RDC_IMG_HUFF;
	b[5] = 1;
	b[8] = 4;
	b[10] = 1;
	b[16] = 2;  /* two codes of length 1 */
	b[32] = 10; /* symbols 10 and 20 */
	b[33] = 20;
	b[34] = 0x50; /* 0101: 10 20 10 20 */
	len = 35;
	put32(b + 12, (uint32_t)len - 16);
	{
		struct rdc_surface s = dst_surface(RDC_FMT_I8);

		prep_dst(t, &s);
		decode_at(t, b, len, (uint32_t)len, 0, 0);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(t->vram[0], 10);
		assert_int_equal(t->vram[1], 20);
		assert_int_equal(t->vram[3], 20);
		assert_int_equal(t->vram[4], SENTINEL);
	}
	/* three codes of length 1 do not fit */
	b[16] = 3;
	b[34] = 30;
	b[35] = 0x50;
	put32(b + 12, 20);
	expect_bad(t, b, 36, RDC_ERR_DATA);
	/* no symbols */
	memset(b + 16, 0, 16);
	b[32] = 0x50;
	put32(b + 12, 17);
	expect_bad(t, b, 33, RDC_ERR_DATA);
	/* 257 symbols claimed (the counts say so; the stream is cut) */
	b[16 + 7] = 255;
	b[16 + 8] = 2;
	put32(b + 12, 17);
	expect_bad(t, b, 33, RDC_ERR_DATA);
	/* one code "0" of length 1, a "1" in the bits: no such code */
	memset(b + 16, 0, 16);
	b[16] = 1;
	b[32] = 7;
	b[33] = 0x10;
	put32(b + 12, 18);
	expect_bad(t, b, 34, RDC_ERR_DATA);
	/* ... with only "0" bits it decodes, and a byte more is bad */
	b[33] = 0x00;
	{
		struct rdc_surface s = dst_surface(RDC_FMT_I8);

		prep_dst(t, &s);
		decode_at(t, b, 34, 34, 0, 0);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(t->vram[3], 7);
	}
	b[34] = 0;
	put32(b + 12, 19);
	expect_bad(t, b, 35, RDC_ERR_DATA);
	/* cut inside the table */
	put32(b + 12, 10);
	expect_bad(t, b, 26, RDC_ERR_DATA);
}

/*
 * The documented cost: the header as one 16-byte read span, the payload
 * (tables and bits) in 256-byte read spans twice: all of it for the
 * check, then again while drawing, each span read when the decoding
 * first needs one of its bytes, so that rows written in between move
 * the open DRAM row; one write span per image row (DCT: per row of a
 * strip of 512 columns once the strip's blocks are decoded).  When the
 * reads happen comes from the reference decoders.
 */
static void check_cycles(struct tdp *t, uint32_t codec, uint32_t level,
			 uint32_t w, uint32_t h, uint32_t ch)
{
	struct rdc_surface s =
		dst_surface(ch == 1 ? RDC_FMT_I8 : RDC_FMT_XRGB8888);
	uint64_t want = 4 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	uint32_t open, y, pay, off, n, bpp = ch == 1 ? 1 : 4, nev, e;
	uint8_t *img = malloc((size_t)w * h * ch), *st;
	uint8_t *dec = malloc((size_t)w * h * ch);
	struct ev *ev = calloc(h + 64 * ((w + 511) / 512), sizeof(*ev));
	uint32_t got;
	size_t len;

	assert_non_null(img);
	assert_non_null(dec);
	assert_non_null(ev);
	/* as wide as the image: nothing clipped */
	s.width = RDC_MAX(w, DST_W);
	s.stride = (s.width * tdp_bpp(s.format) / 8 + 3) & ~3u;
	gen_image(img, w, h, ch, 1, 4);
	st = encode(codec, level, img, w, h, ch, &len);
	pay = (uint32_t)len - 16;
	nev = ref_events(st, len, dec, ev);
	memcpy(t->vram + STREAM_BASE, st, len);
	prep_dst(t, &s);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want += tdp_bus_span(&open, STREAM_BASE, 16, TDP_BUS_READ);
	for (off = 0; off < pay; off += n) {
		n = RDC_MIN(pay - off, 256u);
		want += tdp_bus_span(&open, STREAM_BASE + 16 + off, n,
				     TDP_BUS_READ);
	}
	for (e = 0, off = 0; e < nev; e++) {
		for (; off < ev[e].end; off += n) {
			n = RDC_MIN(pay - off, 256u);
			want += tdp_bus_span(&open, STREAM_BASE + 16 + off, n,
					     TDP_BUS_READ);
		}
		for (y = ev[e].y; y < ev[e].y + ev[e].rows; y++)
			want += tdp_bus_span(
				&open, (uint64_t)y * s.stride + ev[e].x * bpp,
				ev[e].n * bpp, TDP_BUS_WRITE);
	}
	assert_int_equal(off, pay);
	TDP_CMD(t, RDC_OP_DECODE, STREAM_BASE, (uint32_t)len, RDC_XY(0, 0));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	if (codec != RDC_IMG_DCT)
		check_exact(t, &s, dec, w, h, ch, 0, 0);
	got = (uint32_t)rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
	print_message("%ux%ux%u codec %u: %u payload bytes, %u cycles\n", w, h,
		      ch, codec, pay, got);
	assert_int_equal(got, want);
	free(ev);
	free(dec);
	free(st);
	free(img);
}

static void test_huff_cycles(void **state)
{
	check_cycles(*state, RDC_IMG_HUFF, 0, 16, 12, 1);
	check_cycles(*state, RDC_IMG_HUFF, 0, 100, 30, 3);
}

/*
 * DPCMQ: the DP gives what the reference decodes, every sample within
 * step / 2 of the original (step 1: the original); a larger step gives
 * a shorter stream on a picture with noise.
 */
static void test_dpcmq(void **state)
{
	struct tdp *t = *state;
	static const uint32_t steps[] = { 1, 2, 3, 4, 9, 32, 255 };
	uint32_t si, ti, ch, w, h;
	size_t i, n;
	int kind;

	for (si = 0; si < RDC_ARRAY_SIZE(sizes); si++) {
		for (ti = 0; ti < RDC_ARRAY_SIZE(steps); ti++) {
			for (ch = 1; ch <= 3; ch += 2) {
				for (kind = 0; kind < 5; kind++) {
					struct rdc_surface s = dst_surface(
						ch == 1 ? RDC_FMT_I8 :
							  RDC_FMT_XRGB8888);
					uint8_t *img, *ref, *st;
					size_t len;

					w = sizes[si][0];
					h = sizes[si][1];
					n = (size_t)w * h * ch;
					img = malloc(n);
					ref = malloc(n);
					assert_non_null(img);
					assert_non_null(ref);
					gen_image(img, w, h, ch, kind, si + ti);
					st = encode(RDC_IMG_DPCMQ, steps[ti],
						    img, w, h, ch, &len);
					ref_dpcmq(st, len, ref, NULL);
					for (i = 0; i < n; i++)
						assert_true(
							2 * (uint32_t)abs(
								    img[i] -
								    ref[i]) <=
							steps[ti]);
					prep_dst(t, &s);
					decode_at(t, st, len, (uint32_t)len, 5,
						  3);
					assert_int_equal(tdp_err(t),
							 RDC_ERR_NONE);
					check_exact(t, &s, ref,
						    RDC_MIN(w, DST_W - 5), h,
						    ch, 5, 3);
					free(st);
					free(ref);
					free(img);
				}
			}
		}
	}
}

static void test_dpcmq_ratio(void **state)
{
	uint8_t img[64 * 64], *st;
	size_t len, last = SIZE_MAX;
	uint32_t step;

	(void)state;
	gen_image(img, 64, 64, 1, 2, 11);
	for (step = 1; step <= 64; step *= 2) {
		st = encode(RDC_IMG_DPCMQ, step, img, 64, 64, 1, &len);
		assert_true(len < last);
		last = len;
		free(st);
	}
	/* the lossy levels are DPCMQ's alone */
	assert_int_equal(rdc_image_encode_lossy(RDC_IMG_DPCMQ, 0, img, 64, 64,
						1, 64, img, 0, &len),
			 RDC_E_INVAL);
	assert_int_equal(rdc_image_encode_lossy(RDC_IMG_DPCMQ, 256, img, 64, 64,
						1, 64, img, 0, &len),
			 RDC_E_INVAL);
	assert_int_equal(rdc_image_encode_lossy(RDC_IMG_DPCM, 4, img, 64, 64, 1,
						64, img, 0, &len),
			 RDC_E_INVAL);
}

static void test_dpcmq_corrupt(void **state)
{
	struct tdp *t = *state;
	uint8_t img[8 * 4], *st, b[256];
	size_t len;

	gen_image(img, 8, 4, 1, 1, 3);
	st = encode(RDC_IMG_DPCMQ, 5, img, 8, 4, 1, &len);
	assert_true(len + 1 <= sizeof(b));
	/* step 0 */
	memcpy(b, st, len);
	b[16] = 0;
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* cut short, a byte too many */
	memcpy(b, st, len);
	put32(b + 12, (uint32_t)len - 17);
	expect_bad(t, b, len - 1, RDC_ERR_DATA);
	memcpy(b, st, len);
	b[len] = 0;
	put32(b + 12, (uint32_t)len - 15);
	expect_bad(t, b, len + 1, RDC_ERR_DATA);
	/* 1 x 1: k = 7, 15 ones, a zero and 7 ones: m = 15 * 128 + 127 */
	memset(b, 0, 32);
	put32(b, RDC_IMG_MAGIC);
	b[4] = RDC_IMG_DPCMQ;
	b[5] = 1;
	b[8] = 1;
	b[10] = 1;
	b[16] = 3;
	b[17] = 0xff; /* 111 11111 */
	b[18] = 0xff; /* 8 more ones: 13 */
	b[19] = 0xcf; /* 11 0 01111: 15 ones, a zero, 4 of k's bits */
	b[20] = 0xe0; /* 111 */
	put32(b + 12, 5);
	expect_bad(t, b, 21, RDC_ERR_DATA);
	/* m = 511 after an escape is fine: q = -256, clamped to 0 */
	b[17] = 0x1f; /* k = 0, then 5 ones */
	b[18] = 0xff; /* 8 ones: 13 */
	b[19] = 0xff; /* 3 ones (16), then 5 of m's 9 bits */
	b[20] = 0xf0; /* 4 more of m, then padding */
	decode_at(t, b, 21, 21, 0, 0);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	free(st);
}

static void test_dpcmq_cycles(void **state)
{
	check_cycles(*state, RDC_IMG_DPCMQ, 4, 16, 12, 1);
	check_cycles(*state, RDC_IMG_DPCMQ, 2, 100, 30, 3);
}

/*
 * The largest difference of DST's rectangle at (0, 0) from ref (w x h,
 * ch samples), per sample; *off counts the samples that differ.
 */
static uint32_t max_diff(struct tdp *t, const struct rdc_surface *s,
			 const uint8_t *ref, uint32_t w, uint32_t h,
			 uint32_t ch, uint64_t *off)
{
	uint32_t x, y, c, px, v, m = 0, d;

	for (y = 0; y < h; y++) {
		for (x = 0; x < w; x++) {
			px = tdp_get(t->vram, s, x, y);
			for (c = 0; c < ch; c++) {
				v = ch == 1 ? px & 0xff :
					      px >> (16 - 8 * c) & 0xff;
				d = (uint32_t)abs(
					(int)v -
					ref[((size_t)y * w + x) * ch + c]);
				m = RDC_MAX(m, d);
				*off += d != 0;
			}
		}
	}
	return m;
}

/*
 * DCT against the floating-point IDCT: the DP's integer IDCT is within
 * 1 of it, sample by sample (the stated tolerance), and off at all for
 * at most 1 sample in 25 (1.6% here: a truncating IDCT is off for 45%),
 * at qualities 10..100; against the original, quality 100 on a smooth
 * picture is within 2.
 */
static void test_dct(void **state)
{
	struct tdp *t = *state;
	static const uint32_t qs[] = { 10, 50, 75, 90, 100 };
	static const uint32_t whs[][2] = { { 8, 8 },   { 1, 1 },    { 13, 9 },
					   { 64, 40 }, { 300, 17 }, { 7, 33 } };
	uint32_t qi, si, ch, w, h, m;
	uint64_t off = 0, all = 0;
	size_t i, n;
	int kind;

	for (si = 0; si < RDC_ARRAY_SIZE(whs); si++) {
		for (qi = 0; qi < RDC_ARRAY_SIZE(qs); qi++) {
			for (ch = 1; ch <= 3; ch += 2) {
				for (kind = 0; kind < 5; kind++) {
					struct rdc_surface s = dst_surface(
						ch == 1 ? RDC_FMT_I8 :
							  RDC_FMT_XRGB8888);
					uint8_t *img, *ref, *st;
					size_t len;

					w = whs[si][0];
					h = whs[si][1];
					n = (size_t)w * h * ch;
					img = malloc(n);
					ref = malloc(n);
					assert_non_null(img);
					assert_non_null(ref);
					gen_image(img, w, h, ch, kind, si + qi);
					st = encode(RDC_IMG_DCT, qs[qi], img, w,
						    h, ch, &len);
					ref_dct(st, len, ref, NULL);
					prep_dst(t, &s);
					decode_at(t, st, len, (uint32_t)len, 0,
						  0);
					assert_int_equal(tdp_err(t),
							 RDC_ERR_NONE);
					m = max_diff(t, &s, ref, w, h, ch,
						     &off);
					all += n;
					if (m > 1)
						fail_msg("%ux%ux%u q %u kind "
							 "%d: %u from the "
							 "float IDCT",
							 w, h, ch, qs[qi], kind,
							 m);
					if (qs[qi] == 100 && kind == 1)
						for (i = 0; i < n; i++)
							assert_true(
								abs(img[i] -
								    ref[i]) <=
								2);
					/* right of the image: untouched */
					if (w < DST_W)
						assert_int_equal(
							tdp_get(t->vram, &s, w,
								0),
							ch == 1 ? SENTINEL :
								  0x5a5a5a5au);
					free(st);
					free(ref);
					free(img);
				}
			}
		}
	}
	print_message("dct: %llu of %llu samples 1 off the float IDCT\n",
		      (unsigned long long)off, (unsigned long long)all);
	/* and rounds as the float IDCT does nearly always (1.6% off) */
	assert_true(off * 25 <= all);
}

/* A lower quality gives a shorter stream; levels out of 1..100 are bad. */
static void test_dct_quality(void **state)
{
	uint8_t img[64 * 48 * 3], *st;
	size_t len, last = SIZE_MAX;
	static const uint32_t qs[] = { 100, 90, 75, 50, 25, 5 };
	uint32_t i;

	(void)state;
	gen_image(img, 64, 48, 3, 1, 5);
	for (i = 0; i < RDC_ARRAY_SIZE(qs); i++) {
		st = encode(RDC_IMG_DCT, qs[i], img, 64, 48, 3, &len);
		assert_true(len < last);
		last = len;
		free(st);
	}
	assert_int_equal(rdc_image_encode_lossy(RDC_IMG_DCT, 101, img, 64, 48,
						3, 192, img, 0, &len),
			 RDC_E_INVAL);
}

/* A DCT stream of one grey 8x8 block by hand: tables, codes, bits. */
static size_t dct_one(uint8_t *b, uint32_t dcsym, uint32_t dcbits, uint32_t dcn,
		      const uint8_t *acsyms, uint32_t nac, const uint8_t *bits,
		      uint32_t nbits)
{
	size_t k = 16, i;

	memset(b, 0, 512);
	put32(b, RDC_IMG_MAGIC);
	b[4] = RDC_IMG_DCT;
	b[5] = 1;
	b[8] = 8;
	b[10] = 8;
	for (i = 0; i < 64; i++)
		b[k++] = 1;
	/* DC: one code "0" (length 1) for dcsym */
	b[k] = 1;
	k += 16;
	b[k++] = (uint8_t)dcsym;
	/* AC: nac codes of length 8, in order */
	b[k + 7] = (uint8_t)nac;
	k += 16;
	for (i = 0; i < nac; i++)
		b[k++] = acsyms[i];
	(void)dcbits;
	(void)dcn;
	for (i = 0; i < (nbits + 7) / 8; i++)
		b[k++] = bits[i];
	put32(b + 12, (uint32_t)k - 16);
	return k;
}

static void test_dct_corrupt(void **state)
{
	struct tdp *t = *state;
	uint8_t b[512], img[16 * 16], *st;
	/* AC symbols: EOB, ZRL, 0x01, 0x0b (s = 11), 0x30 (r 3, s 0), 0xf1 */
	static const uint8_t ac[] = { 0x00, 0xf0, 0x01, 0x0b, 0x30, 0xf1 };
	uint8_t bits[16];
	size_t len;

	/* DC category 0 ("0"), EOB (00000000): a flat grey block of 128 */
	memset(bits, 0, sizeof(bits));
	len = dct_one(b, 0, 0, 0, ac, 6, bits, 9);
	{
		struct rdc_surface s = dst_surface(RDC_FMT_I8);

		prep_dst(t, &s);
		decode_at(t, b, len, (uint32_t)len, 0, 0);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(t->vram[0], 128);
		assert_int_equal(t->vram[7 * s.stride + 7], 128);
		assert_int_equal(t->vram[8], SENTINEL);
	}
	/* a DC category of 12 */
	len = dct_one(b, 12, 0, 0, ac, 6, bits, 9);
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* an AC symbol of 11 bits: "0" then code 3 (00000011) */
	bits[0] = 0x01;
	bits[1] = 0x80;
	len = dct_one(b, 0, 0, 0, ac, 6, bits, 9);
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* r 3, s 0: neither EOB nor ZRL (code 4: 00000100) */
	bits[0] = 0x02;
	bits[1] = 0x00;
	expect_bad(t, b, dct_one(b, 0, 0, 0, ac, 6, bits, 9), RDC_ERR_DATA);
	/* four ZRLs run past coefficient 63 (code 1: 00000001) */
	memset(bits, 0, sizeof(bits));
	bits[0] = 0x00; /* "0" DC, then 7 bits of the first ZRL */
	bits[1] = 0x80; /* its last bit; the next ZRL starts */
	bits[2] = 0x80;
	bits[3] = 0x80;
	bits[4] = 0x80;
	len = dct_one(b, 0, 0, 0, ac, 6, bits, 33);
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* three ZRLs (to 49), then 15 zeros and a 1 would be coefficient 64 */
	memset(bits, 0, sizeof(bits));
	bits[0] = 0x00; /* "0" DC, 7 bits of ZRL */
	bits[1] = 0x80; /* ZRL ends, 7 bits of ZRL */
	bits[2] = 0x80;
	bits[3] = 0x82; /* ZRL ends, 0000010 of code 5 */
	bits[4] = 0xc0; /* 1 ends code 5, then its bit 1 */
	len = dct_one(b, 0, 0, 0, ac, 6, bits, 34);
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* a quantisation entry of 0 */
	memset(bits, 0, sizeof(bits));
	len = dct_one(b, 0, 0, 0, ac, 6, bits, 9);
	b[16 + 5] = 0;
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* a DC that steps past 2047: category 11, all ones, in each block */
	gen_image(img, 16, 16, 1, 1, 2);
	st = encode(RDC_IMG_DCT, 90, img, 16, 16, 1, &len);
	memcpy(b, st, len);
	put32(b + 12, (uint32_t)len - 17);
	expect_bad(t, b, len - 1, RDC_ERR_DATA);
	memcpy(b, st, len);
	b[len] = 0;
	put32(b + 12, (uint32_t)len - 15);
	expect_bad(t, b, len + 1, RDC_ERR_DATA);
	free(st);
}

/* Bits most significant first into b, from bit *at on. */
static void put_bits(uint8_t *b, uint32_t *at, uint32_t v, uint32_t n)
{
	while (n--) {
		if ((v >> n) & 1)
			b[*at / 8] |= (uint8_t)(0x80u >> (*at % 8));
		(*at)++;
	}
}

/*
 * The run of an AC symbol past coefficient 63: three ZRLs (to 49), j
 * coefficients of 1 (to 49 + j), then run 15 size 1, which would put a
 * coefficient at 64 + j, for every j that one block allows.  Each is
 * refused with DATA before the coefficient (-1) is stored: nothing
 * drawn, the block's 64 coefficients as the symbols before left them
 * (no -1 among them) and nothing of the DP's DCT state after them
 * written (its table and predictors as the stream left them, the bytes
 * after them untouched), wherever a store past the zigzag order's end
 * would land: a missing check cannot go unnoticed, ASan or not.
 */
static void test_dct_past_63(void **state)
{
	struct tdp *t = *state;
	static const uint8_t ac[] = { 0x00, 0xf0, 0x01, 0x0b, 0x30, 0xf1 };
	uint8_t *dct = (uint8_t *)&t->dp.img.u.dct;
	uint8_t *tail = (uint8_t *)&t->dp.img.u.dct.pred[3];
	size_t tail_len = (size_t)(dct + sizeof(t->dp.img.u) - tail);
	/* the zigzag order's natural indices (JPEG's) */
	static const uint8_t zz[64] = {
		0,  1,	8,  16, 9,  2,	3,  10, 17, 24, 32, 25, 18, 11, 4,  5,
		12, 19, 26, 33, 40, 48, 41, 34, 27, 20, 13, 6,	7,  14, 21, 28,
		35, 42, 49, 56, 57, 50, 43, 36, 29, 22, 15, 23, 30, 37, 44, 51,
		58, 59, 52, 45, 38, 31, 39, 46, 53, 60, 61, 54, 47, 55, 62, 63,
	};
	uint8_t b[512], bits[32];

	for (uint32_t j = 0; j <= 14; j++) {
		uint32_t at = 0;
		size_t len;

		memset(bits, 0, sizeof(bits));
		put_bits(bits, &at, 0, 1); /* DC category 0 */
		for (int z = 0; z < 3; z++)
			put_bits(bits, &at, 1, 8); /* ZRL */
		for (uint32_t i = 0; i < j; i++) {
			put_bits(bits, &at, 2, 8); /* 0x01 */
			put_bits(bits, &at, 1, 1);
		}
		put_bits(bits, &at, 5, 8); /* 0xf1: run 15, -1 */
		put_bits(bits, &at, 0, 1);
		len = dct_one(b, 0, 0, 0, ac, 6, bits, at);
		memset(tail, 0xa5, tail_len);
		expect_bad(t, b, len, RDC_ERR_DATA);
		/* the block as the refusal left it: no -1 anywhere */
		for (uint32_t k = 0; k < RDC_IMG_DCT_QBYTES; k++) {
			int32_t want = 0;

			for (uint32_t i = 0; i < j; i++)
				if (k == zz[49 + i])
					want = 1;
			assert_int_equal(t->dp.img.u.dct.blk[k], want);
		}
		for (uint32_t k = 0; k < RDC_IMG_DCT_QBYTES; k++)
			assert_int_equal(t->dp.img.u.dct.q[k], 1);
		for (uint32_t c = 0; c < 3; c++)
			assert_int_equal(t->dp.img.u.dct.pred[c], 0);
		for (size_t i = 0; i < tail_len; i++)
			if (tail[i] != 0xa5)
				fail_msg("j %u: byte %zu after the block's "
					 "coefficients written",
					 j, i);
	}
	/* two ZRLs (to 33), 15 coefficients, run 15: the last one, 63 */
	{
		uint32_t at = 0;
		size_t len;

		memset(bits, 0, sizeof(bits));
		put_bits(bits, &at, 0, 1);
		for (int z = 0; z < 2; z++)
			put_bits(bits, &at, 1, 8);
		for (uint32_t i = 0; i < 15; i++) {
			put_bits(bits, &at, 2, 8);
			put_bits(bits, &at, 1, 1);
		}
		put_bits(bits, &at, 5, 8);
		put_bits(bits, &at, 1, 1);
		len = dct_one(b, 0, 0, 0, ac, 6, bits, at);
		decode_at(t, b, len, (uint32_t)len, 0, 0);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		tdp_clear_err(t);
	}
}

static void test_dct_dc_limit(void **state)
{
	struct tdp *t = *state;
	uint8_t b[600], bits[64];
	static const uint8_t ac[] = { 0x00 };
	size_t len;
	uint32_t i, bit = 0;

	/*
	 * 16 x 8 grey: two blocks, DC category 11 each ("0" then 11 ones:
	 * +2047), then EOB ("0" of the AC table's one 8-bit code
	 * 00000000): 2047, then 4094 is past the limit.
	 */
	memset(bits, 0, sizeof(bits));
	for (i = 0; i < 2; i++) {
		bit++; /* the DC code "0" */
		for (uint32_t j = 0; j < 11; j++, bit++)
			bits[bit / 8] |= (uint8_t)(0x80 >> (bit % 8));
		bit += 8; /* EOB */
	}
	len = dct_one(b, 11, 0, 0, ac, 1, bits, bit);
	b[8] = 16;
	expect_bad(t, b, len, RDC_ERR_DATA);
	/* one block of +2047 decodes (white) */
	len = dct_one(b, 11, 0, 0, ac, 1, bits, 20);
	{
		struct rdc_surface s = dst_surface(RDC_FMT_I8);

		prep_dst(t, &s);
		decode_at(t, b, len, (uint32_t)len, 0, 0);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(t->vram[0], 255);
	}
}

static void test_dct_cycles(void **state)
{
	check_cycles(*state, RDC_IMG_DCT, 75, 16, 12, 1);
	check_cycles(*state, RDC_IMG_DCT, 90, 100, 30, 3);
	check_cycles(*state, RDC_IMG_DCT, 50, 600, 20, 1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_huff_roundtrip),
		TDP_TEST(test_huff_long_codes),
		TDP_TEST(test_huff_corrupt),
		TDP_TEST(test_huff_cycles),
		TDP_TEST(test_dpcmq),
		TDP_TEST(test_dpcmq_ratio),
		TDP_TEST(test_dpcmq_corrupt),
		TDP_TEST(test_dpcmq_cycles),
		TDP_TEST(test_dct),
		TDP_TEST(test_dct_quality),
		TDP_TEST(test_dct_corrupt),
		TDP_TEST(test_dct_past_63),
		TDP_TEST(test_dct_dc_limit),
		TDP_TEST(test_dct_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
