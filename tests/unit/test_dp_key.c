// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Colour key and global alpha in BLIT and HOST_BLIT against a model of
 * the documented order (key on the source pixel, then the ROP, then the
 * alpha blend over the destination), in every format; their bus cost;
 * bad arguments.
 */
#include "test_dp_common.h"

#define KS_W	 96
#define KS_H	 64
#define SRC_BASE 0x100000u
#define DST_BASE 0x200000u

static uint32_t km_fields(uint32_t fmt, uint32_t f[4][2])
{
	static const uint32_t f565[3][2] = { { 11, 5 }, { 5, 6 }, { 0, 5 } };
	static const uint32_t f888[4][2] = {
		{ 24, 8 }, { 16, 8 }, { 8, 8 }, { 0, 8 }
	};

	if (fmt == RDC_FMT_RGB565) {
		memcpy(f, f565, sizeof(f565));
		return 3;
	}
	memcpy(f, f888, sizeof(f888));
	if (fmt == RDC_FMT_RGB888) {
		memmove(f, f[1], 3 * sizeof(f[0]));
		return 3;
	}
	return 4;
}

/* Per channel s a / 255 + d (255 - a) / 255, rounded half up. */
static uint32_t km_blend(uint32_t fmt, uint32_t s, uint32_t d, uint32_t a)
{
	uint32_t f[4][2], r = 0, i, n = km_fields(fmt, f);

	for (i = 0; i < n; i++) {
		uint32_t m = (1u << f[i][1]) - 1;
		uint32_t num = ((s >> f[i][0]) & m) * a +
			       ((d >> f[i][0]) & m) * (255 - a);

		r |= (num / 255 + ((num % 255) * 2 >= 255)) << f[i][0];
	}
	return r;
}

struct kscene {
	uint32_t fmt, key, key_on, alpha, rop;
	struct rdc_surface src, dst;
	int32_t sx, sy, dx, dy;
	uint32_t w, h;
};

/* What one source pixel s does to destination pixel d (false: nothing). */
static bool km_pixel(const struct kscene *k, uint32_t s, uint32_t d,
		     uint32_t *out)
{
	uint32_t mask = tdp_mask(k->fmt), v;

	if (k->key_on && s == (k->key & mask))
		return false;
	v = tdp_rop(k->rop, s, d) & mask;
	if (k->fmt <= RDC_FMT_I8) {
		if (k->alpha < 128)
			return false;
	} else if (k->alpha != 255) {
		v = km_blend(k->fmt, v, d, k->alpha);
	}
	*out = v;
	return true;
}

static void kscene_random(struct kscene *k, uint32_t *seed)
{
	k->fmt = tdp_rand(seed) % RDC_FMT_COUNT;
	k->key_on = tdp_rand(seed) % 4 != 0;
	k->alpha = tdp_rand(seed) % 3 ? tdp_rand(seed) % 256 : 255;
	k->rop = tdp_rand(seed) % 3 ? RDC_ROP_COPY : tdp_rand(seed) % 16;
	k->src = (struct rdc_surface){ SRC_BASE, 0, KS_W, KS_H, k->fmt };
	k->dst = (struct rdc_surface){ DST_BASE, 0, KS_W, KS_H, k->fmt };
	k->src.stride = (KS_W * tdp_bpp(k->fmt) + 7) / 8;
	k->dst.stride = k->src.stride + 8;
	k->sx = tdp_range(seed, -10, KS_W - 5);
	k->sy = tdp_range(seed, -10, KS_H - 5);
	k->dx = tdp_range(seed, -10, KS_W - 5);
	k->dy = tdp_range(seed, -10, KS_H - 5);
	k->w = (uint32_t)tdp_range(seed, 1, KS_W);
	k->h = (uint32_t)tdp_range(seed, 1, KS_H);
}

/* Random surfaces whose pixels often equal the key. */
static void kscene_fill(struct tdp *t, struct kscene *k, uint32_t *seed)
{
	uint32_t mask = tdp_mask(k->fmt);
	int32_t x, y;

	k->key = tdp_rand(seed);
	for (y = 0; y < KS_H; y++)
		for (x = 0; x < KS_W; x++) {
			uint32_t v = tdp_rand(seed) % 3 ? tdp_rand(seed) :
							  k->key;

			tdp_put(t->vram, &k->src, x, y, v & mask);
			tdp_put(t->vram, &k->dst, x, y, tdp_rand(seed));
		}
}

static void kscene_state(struct tdp *t, const struct kscene *k)
{
	tdp_set_surface(t, RDC_OP_SET_SRC, &k->src);
	tdp_set_surface(t, RDC_OP_SET_DST, &k->dst);
	TDP_CMD(t, RDC_OP_SET_ROP, k->rop);
	TDP_CMD(t, RDC_OP_SET_ALPHA, k->alpha);
	tdp_cmd(t, RDC_OP_SET_COLORKEY, k->key_on ? RDC_COLORKEY_ENABLE : 0, 1,
		&k->key);
}

/* The whole expected VRAM after the blit, source pixel by source pixel. */
static void kscene_model(const struct kscene *k, uint8_t *m,
			 const uint8_t *src_of)
{
	uint32_t i, j;

	for (j = 0; j < k->h; j++)
		for (i = 0; i < k->w; i++) {
			int32_t sx = k->sx + (int32_t)i,
				sy = k->sy + (int32_t)j;
			int32_t dx = k->dx + (int32_t)i,
				dy = k->dy + (int32_t)j;
			uint32_t v;

			if (sx < 0 || sy < 0 || sx >= KS_W || sy >= KS_H ||
			    dx < 0 || dy < 0 || dx >= KS_W || dy >= KS_H)
				continue;
			if (km_pixel(k, tdp_get(src_of, &k->src, sx, sy),
				     tdp_get(m, &k->dst, dx, dy), &v))
				tdp_put(m, &k->dst, dx, dy, v);
		}
}

static void test_key_blit_vs_model(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0xb1177, n;
	uint8_t *m = malloc(TDP_VRAM_SIZE);

	assert_non_null(m);
	for (n = 0; n < 200; n++) {
		struct kscene k;

		kscene_random(&k, &seed);
		kscene_fill(t, &k, &seed);
		kscene_state(t, &k);
		tdp_drain(t);
		memcpy(m, t->vram, TDP_VRAM_SIZE);
		kscene_model(&k, m, t->vram);
		TDP_CMD(t, RDC_OP_BLIT, RDC_XY(k.sx, k.sy), RDC_XY(k.dx, k.dy),
			RDC_WH(k.w, k.h));
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		if (memcmp(m, t->vram, TDP_VRAM_SIZE))
			fail_msg("scene %u fmt %u key %u alpha %u rop %u", n,
				 k.fmt, k.key_on, k.alpha, k.rop);
	}
	free(m);
}

/* HOST_BLIT: the source is the command's data, in the DST format. */
static void test_key_host_vs_model(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0x4057, n;
	uint8_t *m = malloc(TDP_VRAM_SIZE);
	uint32_t *cmd = malloc((2 + KS_H * KS_W) * 4);

	assert_non_null(m);
	assert_non_null(cmd);
	for (n = 0; n < 150; n++) {
		struct kscene k;
		uint32_t wpr, j, i;

		kscene_random(&k, &seed);
		kscene_fill(t, &k, &seed);
		/* the command's rows are the source surface's, re-packed */
		k.sx = 0;
		k.sy = 0;
		k.w = RDC_MIN(k.w, (uint32_t)KS_W);
		wpr = (k.w * tdp_bpp(k.fmt) + 31) / 32;
		/* keep the command within RDC_CMD_MAX_ARGS */
		k.h = RDC_MIN(k.h, (RDC_CMD_MAX_ARGS - 2) / wpr);
		cmd[0] = RDC_XY(k.dx, k.dy);
		cmd[1] = RDC_WH(k.w, k.h);
		for (j = 0; j < k.h; j++)
			for (i = 0; i < wpr; i++) {
				const uint8_t *p = t->vram + k.src.base +
						   j * k.src.stride + i * 4;
				uint32_t b, w = 0;

				for (b = 0; b < 4; b++)
					if (i * 4 + b < k.src.stride)
						w |= (uint32_t)p[b] << (8 * b);
				cmd[2 + j * wpr + i] = w;
			}
		/* bits past w in a row's last word are padding: the model
		 * only reads the w pixels */
		kscene_state(t, &k);
		tdp_drain(t);
		memcpy(m, t->vram, TDP_VRAM_SIZE);
		kscene_model(&k, m, t->vram);
		tdp_cmd(t, RDC_OP_HOST_BLIT, 0, 2 + k.h * wpr, cmd);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		if (memcmp(m, t->vram, TDP_VRAM_SIZE))
			fail_msg("scene %u fmt %u key %u alpha %u rop %u", n,
				 k.fmt, k.key_on, k.alpha, k.rop);
	}
	free(cmd);
	free(m);
}

/* Alpha 255 with no key is the plain blit; alpha 0 leaves RGB alone. */
static void test_key_extremes(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = { 0, 2560, 640, 480, RDC_FMT_XRGB8888 };
	const uint32_t key = 0x00ff00ffu;

	tdp_put(t->vram, &s, 0, 0, 0x00102030u);
	tdp_put(t->vram, &s, 1, 0, key);
	tdp_put(t->vram, &s, 0, 1, 0x00aaaaaau);
	tdp_put(t->vram, &s, 1, 1, 0x00aaaaaau);
	TDP_CMD(t, RDC_OP_SET_ALPHA, 0);
	TDP_CMD(t, RDC_OP_BLIT, RDC_XY(0, 0), RDC_XY(0, 1), RDC_WH(2, 1));
	tdp_drain(t);
	assert_int_equal(tdp_get(t->vram, &s, 0, 1), 0x00aaaaaau);
	TDP_CMD(t, RDC_OP_SET_ALPHA, 128);
	tdp_cmd(t, RDC_OP_SET_COLORKEY, RDC_COLORKEY_ENABLE, 1, &key);
	TDP_CMD(t, RDC_OP_BLIT, RDC_XY(0, 0), RDC_XY(0, 1), RDC_WH(2, 1));
	tdp_drain(t);
	/* (0x10 * 128 + 0xaa * 127 + 127) / 255 = 0x5d, and so on */
	assert_int_equal(tdp_get(t->vram, &s, 0, 1), 0x005d656du);
	assert_int_equal(tdp_get(t->vram, &s, 1, 1), 0x00aaaaaau);
	TDP_CMD(t, RDC_OP_SET_ALPHA, 255);
	tdp_cmd(t, RDC_OP_SET_COLORKEY, 0, 1, &key);
	TDP_CMD(t, RDC_OP_BLIT, RDC_XY(0, 0), RDC_XY(0, 1), RDC_WH(2, 1));
	tdp_drain(t);
	assert_int_equal(tdp_get(t->vram, &s, 0, 1), 0x00102030u);
	assert_int_equal(tdp_get(t->vram, &s, 1, 1), key);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
}

static void test_key_bad_args(void **state)
{
	struct tdp *t = *state;
	const uint32_t two[2] = { 0, 0 };

	TDP_CMD(t, RDC_OP_SET_ALPHA, 256);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	assert_int_equal(t->dp.st.alpha, 255);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_SET_ALPHA, 0, 2, two);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_SET_COLORKEY, 0x80, 1, two);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	assert_int_equal(t->dp.st.colorkey_on, 0);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_SET_COLORKEY, RDC_COLORKEY_ENABLE, 0, NULL);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	assert_int_equal(t->dp.st.colorkey_on, 0);
}

/* Per row: the source read span, then the destination as one
 * read-modify-write span (blend or key), or a plain write (neither). */
static void test_key_cycles(void **state)
{
	struct tdp *t = *state;
	const uint32_t key = 1;
	uint32_t open, y, pass;

	for (pass = 0; pass < 3; pass++) {
		uint64_t want = 4 * RDC_T_FIFO_WORD + RDC_T_DECODE;

		TDP_CMD(t, RDC_OP_SET_ALPHA, pass == 1 ? 100 : 255);
		tdp_cmd(t, RDC_OP_SET_COLORKEY,
			pass == 2 ? RDC_COLORKEY_ENABLE : 0, 1, &key);
		tdp_drain(t);
		open = t->hw.bus.open_row;
		for (y = 0; y < 3; y++) {
			want += tdp_bus_span(&open, 8 * 4 + (uint64_t)y * 2560,
					     40 * 4, TDP_BUS_READ);
			want += tdp_bus_span(
				&open, 16 * 4 + (uint64_t)(100 + y) * 2560,
				40 * 4, pass ? TDP_BUS_RMW : TDP_BUS_WRITE);
		}
		TDP_CMD(t, RDC_OP_BLIT, RDC_XY(8, 0), RDC_XY(16, 100),
			RDC_WH(40, 3));
		tdp_drain(t);
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
				 want);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_key_blit_vs_model),
		TDP_TEST(test_key_host_vs_model),
		TDP_TEST(test_key_extremes),
		TDP_TEST(test_key_bad_args),
		TDP_TEST(test_key_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
