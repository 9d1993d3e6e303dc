// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: VRAM access bounds, modes, host blit against readback and VRAM,
 * frame grabs. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <zlib.h>

#include "rdc.h"

#define VRAM_4M (4u << 20)

static int dev_setup(void **state)
{
	rdc_dev *dev;

	if (rdc_open("sim:vram=4M", &dev))
		return -1;
	*state = dev;
	return 0;
}

static int dev_teardown(void **state)
{
	rdc_close(*state);
	return 0;
}

static uint32_t reg(rdc_dev *dev, uint32_t r)
{
	uint32_t v = 0;

	assert_int_equal(rdc_reg_read(dev, r, &v), 0);
	return v;
}

static void test_vram_bounds(void **state)
{
	rdc_dev *dev = *state;
	uint8_t buf[16] = { 1, 2, 3, 4, 5, 6, 7, 8 }, back[16];

	assert_int_equal(reg(dev, RDC_REG_VRAM_SIZE), VRAM_4M);
	assert_int_equal(rdc_vram_write(dev, VRAM_4M - 8, buf, 8), 0);
	assert_int_equal(rdc_vram_read(dev, VRAM_4M - 8, back, 8), 0);
	assert_memory_equal(buf, back, 8);
	assert_int_equal(rdc_vram_write(dev, VRAM_4M - 8, buf, 9), RDC_E_RANGE);
	assert_int_equal(rdc_vram_read(dev, VRAM_4M - 7, back, 8), RDC_E_RANGE);
	assert_int_equal(rdc_vram_read(dev, VRAM_4M, back, 1), RDC_E_RANGE);
	assert_int_equal(rdc_vram_read(dev, UINT32_MAX, back, 2), RDC_E_RANGE);
	assert_int_equal(rdc_vram_read(dev, VRAM_4M, back, 0), 0);
	assert_int_equal(rdc_vram_read(dev, 0, NULL, 4), RDC_E_INVAL);
	/* a refused access changes nothing */
	assert_int_equal(rdc_vram_read(dev, VRAM_4M - 8, back, 8), 0);
	assert_memory_equal(buf, back, 8);
}

static void test_mode_set(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_800x600_60,
				      RDC_FMT_RGB888, 0x1000),
			 0);
	/* 800 pixels * 3 bytes, already a multiple of 4 */
	assert_int_equal(reg(dev, RDC_REG_FB_STRIDE), 2400);
	assert_int_equal(reg(dev, RDC_REG_FB_BASE), 0x1000);
	assert_int_equal(reg(dev, RDC_REG_FB_FORMAT), RDC_FMT_RGB888);
	assert_int_equal(reg(dev, RDC_REG_H_DISPLAY), 800);
	assert_int_equal(reg(dev, RDC_REG_V_DISPLAY), 600);
	/* 320 pixels at 1 bpp: 40 bytes; at 2 bpp 80 */
	assert_int_equal(
		rdc_mode_set(dev, RDC_PRESET_320x200_70, RDC_FMT_I1, 0), 0);
	assert_int_equal(reg(dev, RDC_REG_FB_STRIDE), 40);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_COUNT, RDC_FMT_I8, 0),
			 RDC_E_INVAL);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_COUNT,
				      0),
			 RDC_E_INVAL);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_I8,
				      2),
			 RDC_E_INVAL);
	/* 1920 * 1080 * 4 bytes do not fit 4 MiB */
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_1920x1080_60,
				      RDC_FMT_XRGB8888, 0),
			 RDC_E_RANGE);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_I8,
				      VRAM_4M - 1024),
			 RDC_E_RANGE);
}

static uint32_t seed = 12345;

static uint8_t rnd8(void)
{
	seed = seed * 1103515245u + 12345u;
	return (uint8_t)(seed >> 16);
}

/*
 * Host blit random bytes, read them back through the DP and through the
 * VRAM aperture, per format.  x is a multiple of 32 so rows start on a
 * byte in every format.
 */
static void roundtrip_at(rdc_dev *dev, uint32_t fmt, uint32_t x, uint32_t w,
			 uint32_t h)
{
	const uint32_t y = 7;
	uint32_t row = rdc_format_row_bytes(fmt, w);
	uint32_t padded = (row + 3) & ~3u;
	uint32_t stride = reg(dev, RDC_REG_FB_STRIDE);
	uint8_t *src = malloc((size_t)row * h);
	uint8_t *rb = calloc(h, padded);
	uint8_t *vr = malloc(row);
	int n;

	assert_non_null(src);
	assert_non_null(rb);
	assert_non_null(vr);
	for (size_t i = 0; i < (size_t)row * h; i++)
		src[i] = rnd8();
	/* a partial last byte of a sub-byte row is not pixels: keep it 0 so
	 * the comparisons below see only what was drawn */
	if (rdc_format_bpp(fmt) < 8 && (w * rdc_format_bpp(fmt)) % 8)
		for (uint32_t r = 0; r < h; r++)
			src[r * row + row - 1] &=
				(uint8_t)(0xff00 >>
					  ((w * rdc_format_bpp(fmt)) % 8));
	assert_int_equal(rdc_host_blit(dev, (int)x, (int)y, w, h, src, row), 0);
	n = rdc_readback(dev, (int)x, (int)y, w, h, rb, (size_t)padded * h);
	assert_int_equal(n, (int)(padded * h));
	for (uint32_t r = 0; r < h; r++) {
		assert_memory_equal(rb + (size_t)r * padded,
				    src + (size_t)r * row, row);
		/* the aperture holds the rows packed at x: compare whole
		 * bytes only when x starts one */
		if (x * rdc_format_bpp(fmt) % 32)
			continue;
		assert_int_equal(
			rdc_vram_read(dev,
				      (y + r) * stride +
					      x * rdc_format_bpp(fmt) / 8,
				      vr, row),
			0);
		assert_memory_equal(vr, src + (size_t)r * row, row);
	}
	free(src);
	free(rb);
	free(vr);
}

static void roundtrip(rdc_dev *dev, uint32_t fmt, uint32_t w, uint32_t h)
{
	roundtrip_at(dev, fmt, 64, w, h);
}

static void test_host_blit_readback_formats(void **state)
{
	rdc_dev *dev = *state;

	for (uint32_t fmt = 0; fmt < RDC_FMT_COUNT; fmt++) {
		assert_int_equal(
			rdc_mode_set(dev, RDC_PRESET_640x480_60, fmt, 0), 0);
		roundtrip(dev, fmt, 40, 9);
		roundtrip(dev, fmt, 8, 1);
		/* 200 rows of 400 pixels: many commands, many RDATA refills */
		roundtrip(dev, fmt, 400, 200);
		/* rows that start and end inside a byte or a word */
		roundtrip_at(dev, fmt, 3, 13, 5);
		roundtrip_at(dev, fmt, 33, 1, 2);
	}
}

/*
 * Host blit 4 pixels of 16 bits to (0, 0) of the DST surface at `base`,
 * RGB565 rows 64 bytes apart: how many bytes they took there says the
 * format the handle believed DST had (2 each as RGB565, 4 as XRGB8888).
 */
static uint32_t blit_bytes_at(rdc_dev *dev, uint32_t base)
{
	const uint16_t px[8] = { 0x1111, 0x2222, 0x3333, 0x4444,
				 0x5555, 0x6666, 0x7777, 0x8888 };
	uint8_t zero[32] = { 0 }, vr[32];
	uint32_t n = 0;

	assert_int_equal(rdc_vram_write(dev, base, zero, sizeof(zero)), 0);
	assert_int_equal(rdc_host_blit(dev, 0, 0, 4, 1, px, sizeof(px)), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_vram_read(dev, base, vr, sizeof(vr)), 0);
	for (uint32_t i = 0; i < sizeof(vr); i++)
		n = vr[i] ? i + 1 : n;
	return n;
}

/*
 * The DST format host blits encode for follows the SET_DST words sent:
 * in a batch, in a batch without one (nothing changes), and in raw words
 * a batch's words finish.
 */
static void test_dst_format_tracked(void **state)
{
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();
	const uint32_t base = 0x100000, nop[16] = { RDC_FMT_RGB565 };
	const uint32_t hdr[3] = { RDC_CMD(RDC_OP_SET_DST, 0, 4), base, 64 };

	assert_non_null(b);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60,
				      RDC_FMT_XRGB8888, 0),
			 0);
	assert_int_equal(rdc_batch_dst(b, base, 64, 16, 4, RDC_FMT_RGB565), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(blit_bytes_at(dev, base), 8);
	/* a batch with no SET_DST leaves the format as it was */
	assert_int_equal(rdc_batch_fg(b, 0xff), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 0, 2, 4, 1), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(blit_bytes_at(dev, base), 8);
	assert_int_equal(rdc_batch_dst(b, base, 64, 16, 4, RDC_FMT_XRGB8888),
			 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(blit_bytes_at(dev, base), 16);
	/*
	 * A SET_DST begun in raw words: a batch's first two words, a NOP's
	 * header (16 words, flags 4) and its first word, are its size (16
	 * by 4) and format.
	 */
	assert_int_equal(rdc_submit(dev, hdr, 3), 0);
	assert_int_equal(rdc_batch_cmd(b, RDC_OP_NOP, 4, nop, 16), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(blit_bytes_at(dev, base), 8);
	rdc_batch_free(b);
}

/* Wider than one HOST_BLIT command can carry: split in columns. */
static void test_host_blit_wide_split(void **state)
{
	enum { W = 5000, H = 3 };
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();
	uint32_t *px = malloc(W * H * 4), *vr = malloc(W * 4);
	uint32_t cmds0;

	assert_non_null(px);
	assert_non_null(vr);
	for (uint32_t i = 0; i < W * H; i++)
		px[i] = i * 2654435761u;
	assert_int_equal(
		rdc_batch_dst(b, 0x10000, W * 4, W, H, RDC_FMT_XRGB8888), 0);
	assert_int_equal(rdc_batch_clip(b, 0, 0, W, H), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	cmds0 = reg(dev, RDC_REG_PERF_CMDS);
	assert_int_equal(rdc_host_blit(dev, 0, 0, W, H, px, W * 4), 0);
	assert_int_equal(rdc_finish(dev), 0);
	/* 4094 argument words a command: a piece is at most 4064 pixels */
	assert_true(reg(dev, RDC_REG_PERF_CMDS) - cmds0 >= 3 + 1);
	for (uint32_t r = 0; r < H; r++) {
		assert_int_equal(
			rdc_vram_read(dev, 0x10000 + r * W * 4, vr, W * 4), 0);
		assert_memory_equal(vr, px + r * W, W * 4);
	}
	assert_int_equal(rdc_host_blit(dev, 0, 0, 4, 4, px, 15), RDC_E_INVAL);
	assert_int_equal(rdc_host_blit(dev, 0, 0, 4, 4, NULL, 16), RDC_E_INVAL);
	rdc_batch_free(b);
	free(px);
	free(vr);
}

static void test_readback_small_buffer(void **state)
{
	rdc_dev *dev = *state;
	uint8_t buf[64];

	assert_int_equal(rdc_readback(dev, 0, 0, 16, 16, buf, sizeof(buf)),
			 RDC_E_RANGE);
	/* what did not fit was drained, not left for the next caller */
	assert_int_equal(reg(dev, RDC_REG_RDATA_COUNT), 0);
	assert_int_equal(rdc_readback(dev, 0, 0, 4, 4, buf, sizeof(buf)), 64);
	/* a rectangle the device refuses */
	assert_int_equal(rdc_readback(dev, 0, 0, RDC_SIZE_MAX + 1, 1, buf,
				      sizeof(buf)),
			 RDC_E_DEVICE);
	assert_int_equal(rdc_dev_error(dev, NULL, NULL), 0);
}

static void test_frame_grab(void **state)
{
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();
	uint32_t w = 0, h = 0, *pix, crc1 = 0, crc2 = 0;

	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_XRGB8888, 0),
			 0);
	assert_int_equal(rdc_batch_fg(b, 0xff0000), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 0, 0, 320, 200), 0);
	assert_int_equal(rdc_batch_fg(b, 0x0000ff), 0);
	assert_int_equal(rdc_batch_pixel(b, 5, 6), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	/* size query */
	assert_int_equal(rdc_frame_grab(dev, NULL, 0, &w, &h), RDC_E_RANGE);
	assert_int_equal(w, 320);
	assert_int_equal(h, 200);
	pix = malloc(320 * 200 * 4);
	assert_non_null(pix);
	w = h = 0;
	assert_int_equal(rdc_frame_grab(dev, pix, 320 * 200 - 1, &w, &h),
			 RDC_E_RANGE);
	assert_int_equal(w, 320);
	assert_int_equal(rdc_frame_grab(dev, pix, 320 * 200, &w, &h), 0);
	assert_int_equal(pix[0] & 0xffffff, 0xff0000);
	assert_int_equal(pix[6 * 320 + 5] & 0xffffff, 0x0000ff);
	assert_int_equal(pix[199 * 320 + 319] & 0xffffff, 0xff0000);
	/* the CRC is zlib's over the little-endian words */
	assert_int_equal(rdc_frame_crc(dev, &crc1), 0);
	{
		uint8_t *bytes = malloc(320 * 200 * 4);

		assert_non_null(bytes);
		for (size_t i = 0; i < 320 * 200; i++) {
			bytes[4 * i] = (uint8_t)pix[i];
			bytes[4 * i + 1] = (uint8_t)(pix[i] >> 8);
			bytes[4 * i + 2] = (uint8_t)(pix[i] >> 16);
			bytes[4 * i + 3] = (uint8_t)(pix[i] >> 24);
		}
		crc2 = (uint32_t)crc32(0, bytes, 320 * 200 * 4);
		free(bytes);
	}
	assert_int_equal(crc1, crc2);
	rdc_batch_free(b);
	free(pix);
}

/* A mode set in vertical blanking is latched a frame later; the fresh
 * frame rdc_frame_wait waits for has it. */
static void test_mode_set_in_vblank(void **state)
{
	rdc_dev *dev = *state;
	uint32_t w = 0, h = 0;

	assert_int_equal(
		rdc_mode_set(dev, RDC_PRESET_320x200_70, RDC_FMT_RGB565, 0), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_grab(dev, NULL, 0, &w, &h), RDC_E_RANGE);
	assert_int_equal(w, 320);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_true(reg(dev, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	assert_int_equal(
		rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_I8, 0), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_grab(dev, NULL, 0, &w, &h), RDC_E_RANGE);
	assert_int_equal(w, 640);
	assert_int_equal(h, 480);
}

#define T(f) cmocka_unit_test_setup_teardown(f, dev_setup, dev_teardown)

int main(void)
{
	const struct CMUnitTest tests[] = {
		T(test_vram_bounds),
		T(test_mode_set),
		T(test_host_blit_readback_formats),
		T(test_dst_format_tracked),
		T(test_host_blit_wide_split),
		T(test_readback_small_buffer),
		T(test_frame_grab),
		T(test_mode_set_in_vblank),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
