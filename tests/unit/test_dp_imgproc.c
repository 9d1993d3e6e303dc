// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * HISTOGRAM, MAP_BUILD, MAP_APPLY, MAP_CLUT, CONVOLVE and THRESHOLD
 * against plain references written here from docs/commands.md (never the
 * DP's code): a direct count, the textbook equalisation formula checked
 * as an inequality, a straightforward 3x3 convolution loop over a copy of
 * the source taken before the command, on seeded random pictures in
 * every format.
 */
#include "test_dp_common.h"

#define TABLE  0x300000u
#define MAP    0x301000u
#define SURF_W 96u
#define SURF_H 64u

static uint32_t rng_next(uint32_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 17;
	*s ^= *s << 5;
	return *s;
}

static struct rdc_surface surf(uint32_t fmt, uint32_t base)
{
	struct rdc_surface s = { base, 0, SURF_W, SURF_H, fmt };

	s.stride = ((SURF_W * tdp_bpp(fmt) + 7) / 8 + 7) & ~7u;
	return s;
}

/* Random pixels; smooth ones (a gradient plus noise) when `smooth`. */
static void fill_random(struct tdp *t, const struct rdc_surface *s,
			uint32_t seed, int smooth)
{
	uint32_t x, y, v;

	for (y = 0; y < s->height; y++) {
		for (x = 0; x < s->width; x++) {
			v = rng_next(&seed);
			if (smooth)
				v = (x * 3 + y * 2) * 0x010101u +
				    (v & 0x070707u);
			tdp_put(t->vram, s, x, y, v);
		}
	}
}

/* Channels of an RGB format, from rdc_regs.h's format comment. */
static int chans(uint32_t fmt, uint32_t *shift, uint32_t *bits)
{
	if (fmt == RDC_FMT_RGB565) {
		shift[0] = 11, bits[0] = 5;
		shift[1] = 5, bits[1] = 6;
		shift[2] = 0, bits[2] = 5;
		return 3;
	}
	if (fmt >= RDC_FMT_RGB888) {
		shift[0] = 16, bits[0] = 8;
		shift[1] = 8, bits[1] = 8;
		shift[2] = 0, bits[2] = 8;
		return 3;
	}
	shift[0] = 0;
	bits[0] = tdp_bpp(fmt);
	return 1;
}

static uint32_t widen(uint32_t v, uint32_t bits)
{
	/* replicate the top bits into the new low ones */
	return bits == 8 ? v : (v << (8 - bits)) | (v >> (2 * bits - 8));
}

static uint32_t ref_value(uint32_t fmt, uint32_t px, uint32_t sel)
{
	uint32_t sh[3], b[3], v[3], i;

	if (chans(fmt, sh, b) == 1)
		return px;
	for (i = 0; i < 3; i++)
		v[i] = widen((px >> sh[i]) & ((1u << b[i]) - 1), b[i]);
	if (sel)
		return v[sel - 1];
	return (77 * v[0] + 150 * v[1] + 29 * v[2] + 128) >> 8;
}

static void read_hist(struct tdp *t, uint32_t *h)
{
	for (uint32_t i = 0; i < 256; i++)
		h[i] = t->vram[TABLE + 4 * i] |
		       t->vram[TABLE + 4 * i + 1] << 8 |
		       t->vram[TABLE + 4 * i + 2] << 16 |
		       (uint32_t)t->vram[TABLE + 4 * i + 3] << 24;
}

static void test_histogram(void **state)
{
	struct tdp *t = *state;
	static const uint32_t fmts[] = { RDC_FMT_I4, RDC_FMT_I8, RDC_FMT_RGB565,
					 RDC_FMT_RGB888, RDC_FMT_XRGB8888 };
	uint32_t fi, sel, want[256], got[256], x, y, i, accum;

	for (fi = 0; fi < RDC_ARRAY_SIZE(fmts); fi++) {
		struct rdc_surface s = surf(fmts[fi], 0);

		fill_random(t, &s, fi + 1, fi & 1);
		tdp_set_surface(t, RDC_OP_SET_SRC, &s);
		for (sel = 0; sel < 4; sel++) {
			if (fmts[fi] <= RDC_FMT_I8 && sel)
				break;
			for (accum = 0; accum < 2; accum++) {
				/* a region hanging off the surface's corner */
				memset(want, 0, sizeof(want));
				for (y = 40; y < SURF_H; y++)
					for (x = 50; x < SURF_W; x++)
						want[ref_value(fmts[fi],
							       tdp_get(t->vram,
								       &s, x, y),
							       sel)]++;
				if (accum) {
					for (i = 0; i < 256; i++) {
						t->vram[TABLE + 4 * i] =
							(uint8_t)i;
						t->vram[TABLE + 4 * i + 1] = 0;
						t->vram[TABLE + 4 * i + 2] = 0;
						t->vram[TABLE + 4 * i + 3] = 0;
						want[i] += i;
					}
				}
				tdp_push(t,
					 RDC_CMD(RDC_OP_HISTOGRAM,
						 sel | (accum ? RDC_HIST_ACCUM :
								0),
						 3));
				tdp_push(t, RDC_XY(50, 40));
				tdp_push(t, RDC_WH(100, 100));
				tdp_push(t, TABLE);
				tdp_drain(t);
				assert_int_equal(tdp_err(t), RDC_ERR_NONE);
				read_hist(t, got);
				for (i = 0; i < 256; i++)
					if (got[i] != want[i])
						fail_msg("format %u sel %u bin "
							 "%u: %u, want %u",
							 fmts[fi], sel, i,
							 got[i], want[i]);
			}
		}
	}
	/* errors: a channel of an indexed format, a table out of VRAM */
	{
		struct rdc_surface s = surf(RDC_FMT_I8, 0);

		tdp_set_surface(t, RDC_OP_SET_SRC, &s);
	}
	tdp_clear_err(t);
	tdp_push(t, RDC_CMD(RDC_OP_HISTOGRAM, RDC_CHAN_RED, 3));
	tdp_push(t, 0);
	tdp_push(t, RDC_WH(1, 1));
	tdp_push(t, TABLE);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_HISTOGRAM, 0, RDC_WH(1, 1), TDP_VRAM_SIZE - 1020);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_HISTOGRAM, 0, RDC_WH(1, 1), TABLE + 2);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
}

static void put_hist(struct tdp *t, const uint32_t *h)
{
	for (uint32_t i = 0; i < 256; i++)
		for (uint32_t b = 0; b < 4; b++)
			t->vram[TABLE + 4 * i + b] = (uint8_t)(h[i] >> (8 * b));
}

static void build(struct tdp *t, uint32_t mode, uint32_t param)
{
	tdp_push(t, RDC_CMD(RDC_OP_MAP_BUILD, mode, 3));
	tdp_push(t, TABLE);
	tdp_push(t, MAP);
	tdp_push(t, param);
	tdp_drain(t);
}

/*
 * Equalisation: s_k = (L - 1) * sum_{j <= k} n_j / n, L = 256, rounded to
 * nearest with halves up: |s n - 255 cdf| <= n / 2, and at exactly n / 2
 * s is the upper one.
 */
static void test_map_build(void **state)
{
	struct tdp *t = *state;
	uint32_t h[256], seed = 77, trial, k, lo, hi;
	const uint8_t *map = t->vram + MAP;

	for (trial = 0; trial < 40; trial++) {
		uint64_t n = 0, cdf = 0;

		for (k = 0; k < 256; k++) {
			/* sparse, peaked and flat histograms */
			h[k] = trial % 3 == 0 ?
				       (rng_next(&seed) % 7 == 0 ?
						rng_next(&seed) % 1000 :
						0) :
			       trial % 3 == 1 ?
				       (k > 90 && k < 120 ?
						rng_next(&seed) % 50000 :
						0) :
				       rng_next(&seed) % 100;
			n += h[k];
		}
		put_hist(t, h);
		build(t, RDC_MAP_EQUALIZE, 0);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		for (k = 0; k < 256; k++) {
			int64_t d;

			cdf += h[k];
			if (!n) {
				assert_int_equal(map[k], k);
				continue;
			}
			d = (int64_t)map[k] * (int64_t)n - 255 * (int64_t)cdf;
			assert_true(2 * (d < 0 ? -d : d) <= (int64_t)n);
			if (2 * d == -(int64_t)n)
				fail_msg("bin %u: half rounded down", k);
		}
		/* automatic stretch: the first and last bins above 3 */
		build(t, RDC_MAP_STRETCH_AUTO, 3);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		lo = 256;
		hi = 0;
		for (k = 0; k < 256; k++) {
			if (h[k] > 3) {
				lo = lo == 256 ? k : lo;
				hi = k;
			}
		}
		for (k = 0; k < 256; k++) {
			uint32_t want;

			if (lo >= hi)
				want = k;
			else if (k <= lo)
				want = 0;
			else if (k >= hi)
				want = 255;
			else
				want = (255 * (k - lo) + (hi - lo) / 2) /
				       (hi - lo);
			assert_int_equal(map[k], want);
		}
	}
	/* a given stretch: 50..150 */
	build(t, RDC_MAP_STRETCH, 50 | 150 << 8);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(map[50], 0);
	assert_int_equal(map[100], 128);
	assert_int_equal(map[150], 255);
	assert_int_equal(map[200], 255);
	build(t, RDC_MAP_STRETCH, 150 | 50 << 8);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	tdp_clear_err(t);
	build(t, 3, 0);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	tdp_clear_err(t);
	build(t, RDC_MAP_EQUALIZE, 1);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	tdp_clear_err(t);
}

static uint32_t ref_map(uint32_t fmt, const uint8_t *map, uint32_t px)
{
	uint32_t sh[3], b[3], n = chans(fmt, sh, b), i, out, m, v;

	if (n == 1)
		return map[px] & tdp_mask(fmt);
	out = fmt == RDC_FMT_XRGB8888 ? px & 0xff000000u : 0;
	for (i = 0; i < 3; i++) {
		m = (1u << b[i]) - 1;
		v = map[widen((px >> sh[i]) & m, b[i])];
		out |= (v >> (8 - b[i])) << sh[i];
	}
	return out;
}

/* MAP_APPLY and THRESHOLD in every format, with a clip. */
static void test_point_ops(void **state)
{
	struct tdp *t = *state;
	uint32_t fmt, seed = 5, x, y, i, op, sel;
	uint32_t *before = malloc(SURF_W * SURF_H * 4);

	assert_non_null(before);
	for (fmt = 0; fmt < RDC_FMT_COUNT; fmt++) {
		struct rdc_surface s = surf(fmt, 0);

		for (op = 0; op < 2; op++) {
			for (sel = 0; sel < (op && fmt > RDC_FMT_I8 ? 4u : 1u);
			     sel++) {
				const uint32_t fg = 0x12345678u,
					       bg = 0x9abcdef0u;
				uint32_t lvl = rng_next(&seed) & 0xff;

				fill_random(t, &s, fmt * 10 + op + sel, 0);
				for (i = 0; i < 256; i++)
					t->vram[MAP + i] =
						(uint8_t)rng_next(&seed);
				for (y = 0; y < SURF_H; y++)
					for (x = 0; x < SURF_W; x++)
						before[y * SURF_W + x] =
							tdp_get(t->vram, &s, x,
								y);
				tdp_set_surface(t, RDC_OP_SET_DST, &s);
				TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(3, 2),
					RDC_XY(80, 60));
				TDP_CMD(t, RDC_OP_SET_FG, fg);
				TDP_CMD(t, RDC_OP_SET_BG, bg);
				if (op == 0) {
					TDP_CMD(t, RDC_OP_MAP_APPLY,
						RDC_XY(-5, 1), RDC_WH(90, 70),
						MAP);
				} else {
					tdp_push(t, RDC_CMD(RDC_OP_THRESHOLD,
							    sel, 3));
					tdp_push(t, RDC_XY(-5, 1));
					tdp_push(t, RDC_WH(90, 70));
					tdp_push(t, lvl);
				}
				tdp_drain(t);
				assert_int_equal(tdp_err(t), RDC_ERR_NONE);
				for (y = 0; y < SURF_H; y++) {
					for (x = 0; x < SURF_W; x++) {
						uint32_t b =
							before[y * SURF_W + x];
						uint32_t want = b;

						if (x >= 3 && x < 80 &&
						    y >= 2 && y < 60 &&
						    x < 85 && y < 71) {
							if (op == 0)
								want = ref_map(
									fmt,
									t->vram +
										MAP,
									b);
							else
								want = (ref_value(
										fmt,
										b,
										sel) >= lvl ?
										fg :
										bg) &
								       tdp_mask(
									       fmt);
						}
						if (tdp_get(t->vram, &s, x,
							    y) != want)
							fail_msg(
								"fmt %u op %u "
								"sel %u (%u, "
								"%u): %x want "
								"%x",
								fmt, op, sel, x,
								y,
								tdp_get(t->vram,
									&s, x,
									y),
								want);
					}
				}
				TDP_CMD(t, RDC_OP_SET_CLIP,
					RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN),
					RDC_XY(RDC_COORD_MAX + 1,
					       RDC_COORD_MAX + 1));
			}
		}
	}
	free(before);
}

static void test_map_clut(void **state)
{
	struct tdp *t = *state;
	uint32_t i;

	for (i = 0; i < 256; i++)
		t->vram[MAP + i] = (uint8_t)(255 - i);
	TDP_CMD(t, RDC_OP_MAP_CLUT, MAP);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	rdc_hw_write(&t->hw, RDC_REG_CLUT_INDEX, 0);
	for (i = 0; i < 256; i++)
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_CLUT_DATA),
				 (255 - i) * 0x010101u);
	TDP_CMD(t, RDC_OP_MAP_CLUT, TDP_VRAM_SIZE - 100);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
}

/* floor(n / d), d > 0 */
static int64_t fdiv(int64_t n, int64_t d)
{
	int64_t q = n / d;

	return q * d > n ? q - 1 : q;
}

/* The reference: straight from the description, on a copy of SRC. */
static uint32_t ref_conv(const uint32_t *src, uint32_t fmt, int32_t x,
			 int32_t y, const int32_t *k, uint32_t mode,
			 uint32_t absf, int32_t div, int32_t bias)
{
	static const int32_t gx[9] = { -1, 0, 1, -2, 0, 2, -1, 0, 1 };
	static const int32_t gy[9] = { -1, -2, -1, 0, 0, 0, 1, 2, 1 };
	uint32_t sh[3], b[3], n = chans(fmt, sh, b), c, out, centre;
	int32_t dx, dy;

	centre = src[y * SURF_W + x];
	out = fmt == RDC_FMT_XRGB8888 ? centre & 0xff000000u : 0;
	for (c = 0; c < n; c++) {
		int64_t s = 0, sx = 0, sy = 0, v, max = (1 << b[c]) - 1;

		for (dy = -1; dy <= 1; dy++) {
			for (dx = -1; dx <= 1; dx++) {
				int32_t px = x + dx, py = y + dy;
				int64_t p;

				px = px < 0 ? 0 :
				     px >= (int32_t)SURF_W ?
					      (int32_t)SURF_W - 1 :
					      px;
				py = py < 0 ? 0 :
				     py >= (int32_t)SURF_H ?
					      (int32_t)SURF_H - 1 :
					      py;
				p = (src[py * SURF_W + px] >> sh[c]) & max;
				s += k[(dy + 1) * 3 + dx + 1] * p;
				sx += gx[(dy + 1) * 3 + dx + 1] * p;
				sy += gy[(dy + 1) * 3 + dx + 1] * p;
			}
		}
		if (mode == RDC_CONV_SOBEL)
			s = llabs(sx) + llabs(sy);
		else if (absf)
			s = llabs(s);
		v = fdiv(2 * s + div, 2 * (int64_t)div) + bias;
		v = v < 0 ? 0 : v > max ? max : v;
		out |= (uint32_t)v << sh[c];
	}
	return out;
}

static uint32_t krow(const int32_t *k)
{
	return (uint8_t)k[0] | (uint32_t)(uint8_t)k[1] << 8 |
	       (uint32_t)(uint8_t)k[2] << 16;
}

/*
 * Random kernels, divisors and biases, Sobel, every format, regions
 * that hang off the source, a clip, and in-place filtering (SRC = DST,
 * shifted up, down or not at all).
 */
static void test_convolve(void **state)
{
	struct tdp *t = *state;
	static const int32_t presets[][11] = {
		{ 1, 1, 1, 1, 1, 1, 1, 1, 1, 9, 0 },	       /* box */
		{ 1, 2, 1, 2, 4, 2, 1, 2, 1, 16, 0 },	       /* Gauss */
		{ 0, -1, 0, -1, 5, -1, 0, -1, 0, 1, 0 },       /* sharpen */
		{ -1, -1, -1, -1, 8, -1, -1, -1, -1, 1, 128 }, /* Laplace */
	};
	uint32_t seed = 99, trial, fmt, x, y, w, h;
	uint32_t *src = malloc(SURF_W * SURF_H * 4);
	uint32_t *dst = malloc(SURF_W * SURF_H * 4);

	assert_non_null(src);
	assert_non_null(dst);
	for (trial = 0; trial < 120; trial++) {
		struct rdc_surface s, d;
		int32_t k[9], div, bias, sx, sy, dx, dy, cx0, cy0, cx1, cy1, i;
		uint32_t mode = trial % 5 == 4 ? RDC_CONV_SOBEL :
						 RDC_CONV_KERNEL;
		uint32_t absf = mode == RDC_CONV_KERNEL && trial % 7 == 3;
		int inplace = trial % 4 == 1;

		fmt = trial % RDC_FMT_COUNT;
		s = surf(fmt, 0);
		d = inplace ? s : surf(fmt, 0x100000);
		fill_random(t, &s, trial + 1, trial & 1);
		fill_random(t, &d, trial + 1000, 0);
		if (trial < 16 && mode == RDC_CONV_KERNEL) {
			for (i = 0; i < 9; i++)
				k[i] = presets[trial % 4][i];
			div = presets[trial % 4][9];
			bias = presets[trial % 4][10];
		} else {
			for (i = 0; i < 9; i++)
				k[i] = (int32_t)(rng_next(&seed) % 256) - 128;
			div = 1 + (int32_t)(rng_next(&seed) % 300);
			bias = (int32_t)(rng_next(&seed) % 200) - 100;
		}
		sx = (int32_t)(rng_next(&seed) % 120) - 20;
		sy = (int32_t)(rng_next(&seed) % 80) - 10;
		w = rng_next(&seed) % 100;
		h = rng_next(&seed) % 70;
		if (inplace) {
			dx = sx;
			dy = sy + (int32_t)(rng_next(&seed) % 5) - 2;
		} else {
			dx = (int32_t)(rng_next(&seed) % 120) - 20;
			dy = (int32_t)(rng_next(&seed) % 80) - 10;
		}
		cx0 = (int32_t)(rng_next(&seed) % 20);
		cy0 = (int32_t)(rng_next(&seed) % 20);
		cx1 = cx0 + (int32_t)(rng_next(&seed) % 90);
		cy1 = cy0 + (int32_t)(rng_next(&seed) % 60);
		for (y = 0; y < SURF_H; y++) {
			for (x = 0; x < SURF_W; x++) {
				src[y * SURF_W + x] =
					tdp_get(t->vram, &s, x, y);
				dst[y * SURF_W + x] =
					tdp_get(t->vram, &d, x, y);
			}
		}
		/* the reference over the copies */
		for (y = 0; y < h; y++) {
			for (x = 0; x < w; x++) {
				int32_t ax = sx + (int32_t)x,
					ay = sy + (int32_t)y;
				int32_t bx = dx + (int32_t)x,
					by = dy + (int32_t)y;

				if (ax < 0 || ay < 0 || ax >= (int32_t)SURF_W ||
				    ay >= (int32_t)SURF_H || bx < cx0 ||
				    by < cy0 || bx >= cx1 || by >= cy1 ||
				    bx >= (int32_t)SURF_W ||
				    by >= (int32_t)SURF_H)
					continue;
				dst[by * SURF_W + bx] =
					ref_conv(src, fmt, ax, ay, k, mode,
						 absf, div, bias);
			}
		}
		tdp_set_surface(t, RDC_OP_SET_SRC, &s);
		tdp_set_surface(t, RDC_OP_SET_DST, &d);
		TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(cx0, cy0), RDC_XY(cx1, cy1));
		if (mode == RDC_CONV_KERNEL) {
			tdp_push(t, RDC_CMD(RDC_OP_CONVOLVE,
					    absf ? RDC_CONV_ABS : 0, 7));
			tdp_push(t, RDC_XY(sx, sy));
			tdp_push(t, RDC_XY(dx, dy));
			tdp_push(t, RDC_WH(w, h));
			tdp_push(t, krow(k));
			tdp_push(t, krow(k + 3));
			tdp_push(t, krow(k + 6));
		} else {
			tdp_push(t,
				 RDC_CMD(RDC_OP_CONVOLVE, RDC_CONV_SOBEL, 4));
			tdp_push(t, RDC_XY(sx, sy));
			tdp_push(t, RDC_XY(dx, dy));
			tdp_push(t, RDC_WH(w, h));
		}
		tdp_push(t, (uint32_t)div | (uint32_t)(uint16_t)bias << 16);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		for (y = 0; y < SURF_H; y++)
			for (x = 0; x < SURF_W; x++)
				if (tdp_get(t->vram, &d, x, y) !=
				    (dst[y * SURF_W + x] & tdp_mask(fmt)))
					fail_msg("trial %u fmt %u (%u, %u): %x "
						 "want %x",
						 trial, fmt, x, y,
						 tdp_get(t->vram, &d, x, y),
						 dst[y * SURF_W + x]);
	}
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN),
		RDC_XY(RDC_COORD_MAX + 1, RDC_COORD_MAX + 1));
	free(dst);
	free(src);
}

static void expect_conv(struct tdp *t, uint32_t flags, uint32_t n,
			const uint32_t *a, uint32_t err)
{
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_CONVOLVE, flags, n, a);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), err);
}

static void test_convolve_errors(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface a = surf(RDC_FMT_I8, 0), b = surf(RDC_FMT_RGB565, 0);
	const uint32_t ok[7] = { 0,	   0, RDC_WH(4, 4), 0x010101, 0x010101,
				 0x010101, 9 };
	uint32_t bad[7];

	tdp_set_surface(t, RDC_OP_SET_SRC, &a);
	tdp_set_surface(t, RDC_OP_SET_DST, &a);
	expect_conv(t, 0, 7, ok, RDC_ERR_NONE);
	expect_conv(t, 0, 6, ok, RDC_ERR_LENGTH);
	expect_conv(t, RDC_CONV_SOBEL, 7, ok, RDC_ERR_LENGTH);
	expect_conv(t, 2, 7, ok, RDC_ERR_ARG);
	expect_conv(t, RDC_CONV_SOBEL | RDC_CONV_ABS, 4, ok, RDC_ERR_ARG);
	expect_conv(t, 0x20, 7, ok, RDC_ERR_ARG);
	memcpy(bad, ok, sizeof(bad));
	bad[6] = 0; /* divisor 0 */
	expect_conv(t, 0, 7, bad, RDC_ERR_ARG);
	memcpy(bad, ok, sizeof(bad));
	bad[4] = 0x01000000; /* a bit above the three coefficients */
	expect_conv(t, 0, 7, bad, RDC_ERR_ARG);
	memcpy(bad, ok, sizeof(bad));
	bad[2] = RDC_WH(RDC_IMG_MAX_WIDTH + 1, 1);
	expect_conv(t, 0, 7, bad, RDC_ERR_RANGE);
	tdp_set_surface(t, RDC_OP_SET_DST, &b);
	expect_conv(t, 0, 7, ok, RDC_ERR_ARG);
}

/* The cycles of the command just pushed (it must succeed). */
static uint64_t cmd_cycles(struct tdp *t)
{
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	return rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
}

/* fetch (header and args through the FIFO) and decode */
static uint64_t fetch_cost(uint32_t args)
{
	return (1 + args) * RDC_T_FIFO_WORD + RDC_T_DECODE;
}

/* rows [y0, y0 + h) of s, columns [x0, x0 + w), as spans of `kind` */
static uint64_t rows_cost(uint32_t *open, const struct rdc_surface *s,
			  uint32_t x0, uint32_t y0, uint32_t w, uint32_t h,
			  int read_too)
{
	uint64_t c = 0;
	uint32_t bpp = tdp_bpp(s->format);

	for (uint32_t y = y0; y < y0 + h; y++) {
		uint64_t a = s->base + (uint64_t)y * s->stride + x0 * bpp / 8;

		if (read_too)
			c += tdp_bus_span(open, a, w * bpp / 8, TDP_BUS_READ);
		c += tdp_bus_span(open, a, w * bpp / 8, TDP_BUS_WRITE);
	}
	return c;
}

/*
 * docs/hardware.md's image formulas, span by span with the bus model of
 * test_dp_common.h (no scanout here): rectangles of whole bytes inside
 * the surface, the ROP a plain copy, so no write is read-modify-written
 * but at unaligned edges (and HISTOGRAM's accumulating table).
 */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = surf(RDC_FMT_XRGB8888, 0);
	struct rdc_surface d = surf(RDC_FMT_XRGB8888, 0x100000);
	const uint32_t x0 = 3, y0 = 5, w = 41, h = 17;
	uint32_t open, y, accum;
	uint64_t want;

	fill_random(t, &s, 3, 1);
	tdp_set_surface(t, RDC_OP_SET_SRC, &s);
	tdp_set_surface(t, RDC_OP_SET_DST, &s);
	tdp_drain(t);

	/* HISTOGRAM: the SRC rows, then the table written (RMW to add) */
	for (accum = 0; accum < 2; accum++) {
		open = t->hw.bus.open_row;
		want = fetch_cost(3);
		for (y = y0; y < y0 + h; y++)
			want += tdp_bus_span(&open,
					     (uint64_t)y * s.stride + x0 * 4,
					     w * 4, TDP_BUS_READ);
		want += tdp_bus_span(&open, TABLE, 1024,
				     accum ? TDP_BUS_RMW : TDP_BUS_WRITE);
		tdp_push(t, RDC_CMD(RDC_OP_HISTOGRAM,
				    accum ? RDC_HIST_ACCUM : 0, 3));
		tdp_push(t, RDC_XY(x0, y0));
		tdp_push(t, RDC_WH(w, h));
		tdp_push(t, TABLE);
		assert_int_equal(cmd_cycles(t), want);
	}

	/* MAP_BUILD: the histogram read (not for STRETCH), the map written */
	open = t->hw.bus.open_row;
	want = fetch_cost(3) + tdp_bus_span(&open, TABLE, 1024, TDP_BUS_READ) +
	       tdp_bus_span(&open, MAP, 256, TDP_BUS_WRITE);
	build(t, RDC_MAP_EQUALIZE, 0);
	assert_int_equal(cmd_cycles(t), want);
	open = t->hw.bus.open_row;
	want = fetch_cost(3) + tdp_bus_span(&open, MAP, 256, TDP_BUS_WRITE);
	build(t, RDC_MAP_STRETCH, 20 | 200 << 8);
	assert_int_equal(cmd_cycles(t), want);

	/* MAP_APPLY: the map, then each row read and written */
	open = t->hw.bus.open_row;
	want = fetch_cost(3) + tdp_bus_span(&open, MAP, 256, TDP_BUS_READ);
	want += rows_cost(&open, &s, x0, y0, w, h, 1);
	TDP_CMD(t, RDC_OP_MAP_APPLY, RDC_XY(x0, y0), RDC_WH(w, h), MAP);
	assert_int_equal(cmd_cycles(t), want);

	/* MAP_CLUT: the map */
	open = t->hw.bus.open_row;
	want = fetch_cost(1) + tdp_bus_span(&open, MAP, 256, TDP_BUS_READ);
	TDP_CMD(t, RDC_OP_MAP_CLUT, MAP);
	assert_int_equal(cmd_cycles(t), want);

	/* THRESHOLD: each row read and written */
	open = t->hw.bus.open_row;
	want = fetch_cost(3) + rows_cost(&open, &s, x0, y0, w, h, 1);
	TDP_CMD(t, RDC_OP_THRESHOLD, RDC_XY(x0, y0), RDC_WH(w, h), 128);
	assert_int_equal(cmd_cycles(t), want);

	/*
	 * CONVOLVE into another surface, top down: the SRC rows each read
	 * once when first needed (columns x0 - 1 .. x0 + w, the one above
	 * the first row and below the last included), each DST row written
	 * after the three it needs; then a rectangle at SRC's top-left
	 * corner, whose missing row and column above and left are clamped.
	 */
	tdp_set_surface(t, RDC_OP_SET_DST, &d);
	tdp_drain(t);
	for (int corner = 0; corner < 2; corner++) {
		uint32_t sx = corner ? 0 : x0, sy = corner ? 0 : y0;
		uint32_t ca = sx ? sx - 1 : 0, cw = sx + w + 1 - ca;
		int32_t next = sy ? (int32_t)sy - 1 : 0;

		open = t->hw.bus.open_row;
		want = fetch_cost(7);
		for (y = 0; y < h; y++) {
			/* SRC rows up to the one below this row */
			for (; next <= (int32_t)(sy + y + 1); next++)
				want += tdp_bus_span(&open,
						     (uint64_t)next * s.stride +
							     ca * 4,
						     cw * 4, TDP_BUS_READ);
			want += tdp_bus_span(
				&open,
				d.base + (uint64_t)(y0 + y) * d.stride + x0 * 4,
				w * 4, TDP_BUS_WRITE);
		}
		tdp_push(t, RDC_CMD(RDC_OP_CONVOLVE, RDC_CONV_KERNEL, 7));
		tdp_push(t, RDC_XY(sx, sy));
		tdp_push(t, RDC_XY(x0, y0));
		tdp_push(t, RDC_WH(w, h));
		tdp_push(t, 0x010201);
		tdp_push(t, 0x020402);
		tdp_push(t, 0x010201);
		tdp_push(t, 16);
		assert_int_equal(cmd_cycles(t), want);
	}
}

/*
 * MAP_APPLY's and THRESHOLD's bad input: flags, a map misaligned or past
 * VRAM, a level above 255, a channel of an indexed DST; nothing written,
 * and the next good command works.
 */
static void test_point_errors(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = surf(RDC_FMT_I8, 0);
	uint32_t h0;

	fill_random(t, &s, 11, 0);
	tdp_set_surface(t, RDC_OP_SET_DST, &s);
	tdp_drain(t);
	h0 = tdp_fnv(2166136261u, t->vram, SURF_W * SURF_H);
	{
		static const struct {
			uint32_t op, fl, a2, err;
		} bad[] = {
			{ RDC_OP_MAP_APPLY, 1, MAP, RDC_ERR_ARG },
			{ RDC_OP_MAP_APPLY, 0, MAP + 1, RDC_ERR_RANGE },
			{ RDC_OP_MAP_APPLY, 0, TDP_VRAM_SIZE - 128,
			  RDC_ERR_RANGE },
			{ RDC_OP_MAP_APPLY, 0, 0xfffffff0u, RDC_ERR_RANGE },
			{ RDC_OP_THRESHOLD, 0, 256, RDC_ERR_RANGE },
			{ RDC_OP_THRESHOLD, 0, 0xffffffffu, RDC_ERR_RANGE },
			{ RDC_OP_THRESHOLD, RDC_CHAN_RED, 100, RDC_ERR_ARG },
			{ RDC_OP_THRESHOLD, 0x10, 100, RDC_ERR_ARG },
		};

		for (uint32_t i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
			tdp_clear_err(t);
			tdp_push(t, RDC_CMD(bad[i].op, bad[i].fl, 3));
			tdp_push(t, RDC_XY(0, 0));
			tdp_push(t, RDC_WH(SURF_W, SURF_H));
			tdp_push(t, bad[i].a2);
			tdp_drain(t);
			if (tdp_err(t) != bad[i].err)
				fail_msg("case %u: error %u, want %u", i,
					 tdp_err(t), bad[i].err);
			assert_int_equal(tdp_fnv(2166136261u, t->vram,
						 SURF_W * SURF_H),
					 h0);
		}
	}
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_THRESHOLD, RDC_XY(0, 0), RDC_WH(SURF_W, SURF_H), 128);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_not_equal(tdp_fnv(2166136261u, t->vram, SURF_W * SURF_H),
			     h0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_histogram), TDP_TEST(test_map_build),
		TDP_TEST(test_point_ops), TDP_TEST(test_map_clut),
		TDP_TEST(test_convolve),  TDP_TEST(test_convolve_errors),
		TDP_TEST(test_cycles),	  TDP_TEST(test_point_errors),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
