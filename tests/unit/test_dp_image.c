// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * DECODE: streams written by librdc's encoders (rdc_image_encode) and
 * decoded by the DP.  RLE and DPCM must give back the original samples
 * exactly; BTC must equal this file's own decoding of the stream (parsed
 * from rdc_image.h's description) and stay within the stated error of
 * the original.  Corrupt streams must give RDC_ERR_DATA with nothing
 * drawn, and seeded random mutations must give DATA or a picture, never
 * a write outside the image's rectangle or a read outside VRAM (ASan).
 */
#include "tdp_image.h"
#include "rdc.h"

static uint8_t *encode(uint32_t codec, const uint8_t *px, uint32_t w,
		       uint32_t h, uint32_t ch, size_t *len)
{
	size_t cap = rdc_image_bound(codec, w, h, ch);
	uint8_t *out = malloc(cap);

	assert_non_null(out);
	assert_int_equal(rdc_image_encode(codec, px, w, h, ch, (size_t)w * ch,
					  out, cap, len),
			 0);
	assert_true(*len <= cap);
	return out;
}

static const uint32_t sizes[][2] = { { 1, 1 }, { 7, 5 },     { 129, 3 },
				     { 4, 4 }, { 300, 200 }, { 33, 1 },
				     { 1, 40 } };

static void roundtrip(void **state, uint32_t codec)
{
	struct tdp *t = *state;
	static const uint32_t fmts[][2] = {
		{ RDC_FMT_I8, 1 },     { RDC_FMT_XRGB8888, 3 },
		{ RDC_FMT_RGB888, 3 }, { RDC_FMT_XRGB8888, 1 },
		{ RDC_FMT_RGB565, 3 },
	};
	uint32_t si, fi, w, h, ch, fmt;
	int kind;

	for (si = 0; si < RDC_ARRAY_SIZE(sizes); si++) {
		for (fi = 0; fi < RDC_ARRAY_SIZE(fmts); fi++) {
			for (kind = 0; kind < 4; kind++) {
				struct rdc_surface s;
				uint8_t *img, *st;
				size_t len;

				w = sizes[si][0];
				h = sizes[si][1];
				fmt = fmts[fi][0];
				ch = fmts[fi][1];
				s = dst_surface(fmt);
				img = malloc((size_t)w * h * ch);
				assert_non_null(img);
				gen_image(img, w, h, ch, kind, si * 77 + fi);
				st = encode(codec, img, w, h, ch, &len);
				prep_dst(t, &s);
				decode_at(t, st, len, (uint32_t)len, 5, 3);
				assert_int_equal(tdp_err(t), RDC_ERR_NONE);
				check_exact(t, &s, img, RDC_MIN(w, DST_W - 5),
					    RDC_MIN(h, DST_H - 3), ch, 5, 3);
				/* nothing left of or above the image */
				assert_int_equal(t->vram[s.base], SENTINEL);
				free(st);
				free(img);
			}
		}
	}
}

static void test_rle_roundtrip(void **state)
{
	roundtrip(state, RDC_IMG_RLE);
}

static void test_dpcm_roundtrip(void **state)
{
	roundtrip(state, RDC_IMG_DPCM);
}

/*
 * BTC against this file's decoding of the stream, and against the
 * original: every sample within its block's range, every block's mean
 * within 1/2.
 */
static void test_btc(void **state)
{
	struct tdp *t = *state;
	static const uint32_t whs[][2] = {
		{ 4, 4 }, { 5, 7 }, { 64, 48 }, { 1, 1 }, { 130, 9 }
	};
	uint32_t i, ch, x, y, c, kind;

	for (i = 0; i < RDC_ARRAY_SIZE(whs); i++) {
		for (ch = 1; ch <= 3; ch += 2) {
			for (kind = 0; kind < 4; kind++) {
				uint32_t w = whs[i][0], h = whs[i][1];
				uint32_t bw = (w + 3) / 4, bh = (h + 3) / 4;
				struct rdc_surface s =
					dst_surface(ch == 1 ? RDC_FMT_I8 :
							      RDC_FMT_XRGB8888);
				uint8_t *img = malloc((size_t)w * h * ch);
				uint8_t *dec = malloc((size_t)w * h * ch);
				uint8_t *st;
				size_t len;

				assert_non_null(img);
				assert_non_null(dec);
				gen_image(img, w, h, ch, (int)kind, i + 5);
				st = encode(RDC_IMG_BTC, img, w, h, ch, &len);
				assert_int_equal(len, 16 + bw * bh * ch * 4);
				/* the reference decoding */
				for (y = 0; y < h; y++) {
					for (x = 0; x < w; x++) {
						for (c = 0; c < ch; c++) {
							const uint8_t *e =
								st + 16 +
								(((y / 4) * bw +
								  x / 4) *
									 ch +
								 c) * 4;
							uint32_t bm = e[2] |
								      e[3] << 8;
							uint32_t bit =
								(y % 4) * 4 +
								x % 4;

							dec[((size_t)y * w +
							     x) * ch +
							    c] = e[(bm >> bit) &
								   1];
						}
					}
				}
				prep_dst(t, &s);
				decode_at(t, st, len, (uint32_t)len, 0, 0);
				assert_int_equal(tdp_err(t), RDC_ERR_NONE);
				check_exact(t, &s, dec, w, h, ch, 0, 0);
				/* the stated error against the original */
				for (y = 0; y < bh; y++) {
					for (x = 0; x < bw; x++) {
						for (c = 0; c < ch; c++) {
							int lo = 255, hi = 0;
							int so = 0, sd = 0,
							    n = 0;
							uint32_t px, py;

							for (py = y * 4;
							     py < h &&
							     py < y * 4 + 4;
							     py++)
								for (px = x * 4;
								     px < w &&
								     px < x * 4 + 4;
								     px++) {
									size_t k =
										((size_t)py *
											 w +
										 px) * ch +
										c;

									lo = RDC_MIN(
										lo,
										img[k]);
									hi = RDC_MAX(
										hi,
										img[k]);
									so += img[k];
									sd += dec[k];
									n++;
								}
							assert_true(
								2 * abs(so -
									sd) <=
								n);
							for (py = y * 4;
							     py < h &&
							     py < y * 4 + 4;
							     py++)
								for (px = x * 4;
								     px < w &&
								     px < x * 4 + 4;
								     px++) {
									size_t k =
										((size_t)py *
											 w +
										 px) * ch +
										c;

									assert_true(
										abs(img[k] -
										    dec[k]) <=
										hi - lo);
								}
						}
					}
				}
				free(st);
				free(dec);
				free(img);
			}
		}
	}
}

/* The clip and DST's edges cut the image; the rest is not touched. */
static void test_decode_clip(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = dst_surface(RDC_FMT_I8);
	uint32_t w = 50, h = 40, x, y;
	uint8_t img[50 * 40];
	uint8_t *st;
	size_t len;

	gen_image(img, w, h, 1, 1, 9);
	st = encode(RDC_IMG_DPCM, img, w, h, 1, &len);
	prep_dst(t, &s);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(30, 25));
	decode_at(t, st, len, (uint32_t)len, -10, -5);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	for (y = 0; y < 40; y++) {
		for (x = 0; x < 60; x++) {
			uint32_t got = tdp_get(t->vram, &s, x, y);

			if (x < 30 && y < 25 && x + 10 < w && y + 5 < h)
				assert_int_equal(got,
						 img[(y + 5) * w + x + 10]);
			else
				assert_int_equal(got, SENTINEL);
		}
	}
	free(st);
}

/* Expect err from DECODE of stream, with DST untouched and the DP fine. */
static void expect_bad(struct tdp *t, const uint8_t *stream, size_t len,
		       uint32_t addr, uint32_t size, uint32_t flags,
		       uint32_t err)
{
	struct rdc_surface s = dst_surface(RDC_FMT_I8);
	const uint32_t args[] = { addr, size, RDC_XY(0, 0) };
	size_t i;

	prep_dst(t, &s);
	tdp_clear_err(t);
	if (len)
		memcpy(t->vram + addr, stream, len);
	tdp_cmd(t, RDC_OP_DECODE, flags, 3, args);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), err);
	for (i = 0; i < (size_t)s.stride * s.height; i++)
		if (t->vram[i] != SENTINEL)
			fail_msg("byte %zu written by a rejected DECODE", i);
	tdp_clear_err(t);
	/* and the DP goes on */
	TDP_CMD(t, RDC_OP_SET_FG, 7);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(2, 1));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(t->vram[1], 7);
}

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

static void test_decode_corrupt(void **state)
{
	struct tdp *t = *state;
	uint8_t img[64 * 16], *st, b[4096];
	size_t len;
	uint32_t codec;

	gen_image(img, 64, 16, 1, 0, 3);
	for (codec = RDC_IMG_RLE; codec <= RDC_IMG_BTC; codec++) {
		st = encode(codec, img, 64, 16, 1, &len);
		assert_true(len <= sizeof(b));
		/* header fields */
		memcpy(b, st, len);
		b[0] ^= 1;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		memcpy(b, st, len);
		b[4] = 0;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		b[4] = RDC_IMG_CODEC_END;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		memcpy(b, st, len);
		b[5] = 2;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		memcpy(b, st, len);
		b[6] = 1;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		memcpy(b, st, len);
		b[8] = 0;
		b[9] = 0;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		b[8] = 0x01; /* 4097 */
		b[9] = 0x10;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		memcpy(b, st, len);
		b[10] = 0;
		b[11] = 0;
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		/* the payload longer than the size allows */
		memcpy(b, st, len);
		expect_bad(t, b, len, STREAM_BASE, (uint32_t)len - 1, 0,
			   RDC_ERR_DATA);
		put32(b + 12, 0xffffffffu);
		expect_bad(t, b, len, STREAM_BASE, 0x100000, 0, RDC_ERR_DATA);
		/* truncated: the header says one byte less */
		memcpy(b, st, len);
		put32(b + 12, (uint32_t)len - 17);
		expect_bad(t, b, len - 1, STREAM_BASE, (uint32_t)len, 0,
			   RDC_ERR_DATA);
		/* a byte too many */
		memcpy(b, st, len);
		b[len] = 0;
		put32(b + 12, (uint32_t)len - 15);
		expect_bad(t, b, len + 1, STREAM_BASE, (uint32_t)len + 1, 0,
			   RDC_ERR_DATA);
		/* no payload at all */
		memcpy(b, st, len);
		put32(b + 12, 0);
		expect_bad(t, b, 16, STREAM_BASE, 16, 0, RDC_ERR_DATA);
		/* the command's own arguments */
		expect_bad(t, st, len, STREAM_BASE, 15, 0, RDC_ERR_DATA);
		expect_bad(t, st, 0, TDP_VRAM_SIZE - 8, 16, 0, RDC_ERR_RANGE);
		expect_bad(t, st, 0, STREAM_BASE, 0xffffffffu, 0,
			   RDC_ERR_RANGE);
		expect_bad(t, st, len, STREAM_BASE, (uint32_t)len, 1,
			   RDC_ERR_ARG);
		free(st);
	}
	/* an RLE run past the last pixel */
	memset(b, 0, sizeof(b));
	put32(b, RDC_IMG_MAGIC);
	b[4] = RDC_IMG_RLE;
	b[5] = 1;
	b[8] = 4; /* 4 x 1 */
	b[10] = 1;
	put32(b + 12, 2);
	b[16] = 128 + 3; /* a run of 5 */
	b[17] = 9;
	expect_bad(t, b, 18, STREAM_BASE, 18, 0, RDC_ERR_DATA);
	/* a literal past the last pixel */
	b[16] = 4; /* 5 pixels */
	put32(b + 12, 6);
	expect_bad(t, b, 22, STREAM_BASE, 22, 0, RDC_ERR_DATA);
	/* and exactly to the last pixel is fine */
	b[16] = 3;
	put32(b + 12, 5);
	decode_at(t, b, 21, 21, 0, 0);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(t->vram[3], b[20]);
	/* a DPCM code longer than a byte (q = 15, k = 7) */
	memset(b + 16, 0, 8);
	b[8] = 1;
	put32(b + 12, 4);
	b[4] = RDC_IMG_DPCM;
	b[16] = 0xff;	     /* k = 7, then 5 ones */
	b[17] = 0xff;	     /* 8 more ones */
	b[18] = 0xc0 | 0x00; /* 2 more ones (15), a zero, 5 of 7 bits */
	b[19] = 0x00;
	expect_bad(t, b, 20, STREAM_BASE, 20, 0, RDC_ERR_DATA);
	/* three channels into an indexed DST */
	gen_image(img, 8, 8, 3, 0, 1);
	st = encode(RDC_IMG_RLE, img, 8, 8, 3, &len);
	expect_bad(t, st, len, STREAM_BASE, (uint32_t)len, 0, RDC_ERR_ARG);
	free(st);
}

/*
 * Seeded random mutations: bytes changed, the payload size changed,
 * streams cut short.  The stream sits at the end of VRAM with the size
 * reaching it, so a read past it would leave VRAM (ASan's business).
 * DATA or a picture; never a byte outside the image's rectangle.
 */
static void test_decode_fuzz(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = dst_surface(RDC_FMT_XRGB8888);
	uint32_t seed = 0x1234567u, iter, codec, n, i, x, y, ch;
	uint32_t ok = 0, bad = 0;
	uint8_t img[48 * 20 * 3], *st, *save;

	save = malloc(TDP_VRAM_SIZE);
	assert_non_null(save);
	for (iter = 0; iter < 400; iter++) {
		size_t len;
		uint32_t at, w, h, err, size;

		codec = RDC_IMG_RLE + iter % 3;
		ch = (iter / 3) % 2 ? 3 : 1;
		gen_image(img, 48, 20, ch, (int)(iter % 4), iter);
		st = encode(codec, img, 48, 20, ch, &len);
		n = 1 + rng_next(&seed) % 6;
		for (i = 0; i < n; i++) {
			switch (rng_next(&seed) % 4) {
			case 0: /* a payload byte */
			case 1:
				if (len <= 16)
					break;
				st[16 + rng_next(&seed) % (len - 16)] ^=
					(uint8_t)(1 + rng_next(&seed) % 255);
				break;
			case 2: /* a header byte */
				st[rng_next(&seed) % 16] ^=
					(uint8_t)(1u << (rng_next(&seed) % 8));
				break;
			default: /* cut short */
				len -= rng_next(&seed) % (len - 15);
				break;
			}
		}
		at = TDP_VRAM_SIZE - (uint32_t)len;
		prep_dst(t, &s);
		memset(t->vram + STREAM_BASE, 0, at - STREAM_BASE);
		memcpy(t->vram + at, st, len);
		memcpy(save, t->vram, TDP_VRAM_SIZE);
		tdp_clear_err(t);
		size = (uint32_t)len;
		TDP_CMD(t, RDC_OP_DECODE, at, size, RDC_XY(2, 1));
		tdp_drain(t);
		err = tdp_err(t);
		assert_true(err == RDC_ERR_NONE || err == RDC_ERR_DATA ||
			    err == RDC_ERR_ARG);
		/* the rectangle the header (as decoded) names */
		w = st[8] | st[9] << 8;
		h = st[10] | st[11] << 8;
		for (i = 0; i < TDP_VRAM_SIZE; i++) {
			if (t->vram[i] == save[i])
				continue;
			assert_int_equal(err, RDC_ERR_NONE);
			assert_true(i < (uint32_t)s.stride * s.height);
			y = i / s.stride;
			x = (i % s.stride) / 4;
			assert_true(x >= 2 && x < 2 + w && y >= 1 && y < 1 + h);
		}
		if (err == RDC_ERR_NONE)
			ok++;
		else
			bad++;
		free(st);
		/* the DP still works */
		tdp_clear_err(t);
		TDP_CMD(t, RDC_OP_FENCE, iter);
		tdp_drain(t);
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_FENCE), iter);
	}
	print_message("decode fuzz: %u pictures, %u rejected\n", ok, bad);
	assert_true(ok > 0 && bad > 0);
	free(save);
}

/*
 * The documented cost: the header as one 16-byte read; the payload in
 * 256-byte read spans, twice for RLE and DPCM (check, then draw), once
 * for BTC; one write span per visible image row.  Payloads here fit one
 * span, so the order is header, payload (check), payload, rows.
 */
static void test_decode_cycles(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = dst_surface(RDC_FMT_I8);
	uint32_t w = 16, h = 12, codec, open, pass, y, pay;
	uint8_t img[16 * 12], *st;
	size_t len;

	for (codec = RDC_IMG_RLE; codec <= RDC_IMG_BTC; codec++) {
		uint64_t want = 4 * RDC_T_FIFO_WORD + RDC_T_DECODE;

		gen_image(img, w, h, 1, codec == RDC_IMG_RLE ? 2 : 1, 4);
		st = encode(codec, img, w, h, 1, &len);
		pay = (uint32_t)len - 16;
		assert_true(pay <= 256);
		memcpy(t->vram + STREAM_BASE, st, len);
		tdp_set_surface(t, RDC_OP_SET_DST, &s);
		tdp_drain(t);
		open = t->hw.bus.open_row;
		want += tdp_bus_span(&open, STREAM_BASE, 16, TDP_BUS_READ);
		for (pass = codec == RDC_IMG_BTC; pass < 2; pass++)
			want += tdp_bus_span(&open, STREAM_BASE + 16, pay,
					     TDP_BUS_READ);
		for (y = 0; y < h; y++)
			want += tdp_bus_span(&open, (uint64_t)y * s.stride, w,
					     TDP_BUS_WRITE);
		TDP_CMD(t, RDC_OP_DECODE, STREAM_BASE, (uint32_t)len,
			RDC_XY(0, 0));
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
				 want);
		free(st);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_rle_roundtrip),
		TDP_TEST(test_dpcm_roundtrip),
		TDP_TEST(test_btc),
		TDP_TEST(test_decode_clip),
		TDP_TEST(test_decode_corrupt),
		TDP_TEST(test_decode_fuzz),
		TDP_TEST(test_decode_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
