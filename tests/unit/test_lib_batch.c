// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: every batch encoder against the command encodings of rdc_regs.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"

static rdc_batch *b;

static int batch_setup(void **state)
{
	(void)state;
	b = rdc_batch_new();
	return b ? 0 : -1;
}

static int batch_teardown(void **state)
{
	(void)state;
	rdc_batch_free(b);
	return 0;
}

static void expect_words(const uint32_t *want, size_t n)
{
	size_t have = 0;
	const uint32_t *w = rdc_batch_words(b, &have);

	assert_int_equal(have, n);
	assert_memory_equal(w, want, n * sizeof(*w));
	rdc_batch_reset(b);
}

/* The encodings written out by hand from the field layout: opcode in
 * bits 31:24, flags 23:16, length 15:0; x in 15:0, y in 31:16. */
static void test_encoding_literals(void **state)
{
	(void)state;
	assert_int_equal(RDC_CMD(0x24, 0, 2), 0x24000002u);
	assert_int_equal(RDC_CMD(0x33, 1, 6), 0x33010006u);
	assert_int_equal(RDC_XY(-1, 2), 0x0002ffffu);
	assert_int_equal(RDC_XY(100, -100), 0xff9c0064u);
	assert_int_equal(RDC_WH(640, 480), 0x01e00280u);

	assert_int_equal(rdc_batch_fill_rect(b, 10, 20, 30, 40), 0);
	expect_words(
		(const uint32_t[]){ 0x24000002u, 0x0014000au, 0x0028001eu }, 3);
	assert_int_equal(rdc_batch_line(b, -5, -6, 7, 8), 0);
	expect_words(
		(const uint32_t[]){ 0x21000002u, 0xfffafffbu, 0x00080007u }, 3);
}

static void test_control_encoders(void **state)
{
	static const uint32_t clut[3] = { 0xff0000, 0x00ff00, 0x0000ff };

	(void)state;
	assert_int_equal(rdc_batch_nop(b), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_NOP, 0, 0) }, 1);
	assert_int_equal(rdc_batch_fence(b, 0xdeadbeef), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_FENCE, 0, 1),
					 0xdeadbeef },
		     2);
	assert_int_equal(rdc_batch_wait_vblank(b), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_WAIT_VBLANK, 0, 0) },
		     1);
	assert_int_equal(rdc_batch_wait_line(b, 240), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_WAIT_LINE, 0, 1), 240 },
		     2);
	assert_int_equal(rdc_batch_reg_write(b, RDC_REG_CLUT_INDEX, 7), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_REG_WRITE, 0, 2),
					 RDC_REG_CLUT_INDEX, 7 },
		     3);
	assert_int_equal(rdc_batch_load_clut(b, 16, clut, 3), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_LOAD_CLUT, 0, 4), 16,
					 0xff0000, 0x00ff00, 0x0000ff },
		     5);
	assert_int_equal(rdc_batch_load_clut(b, 0, clut, RDC_CLUT_ENTRIES + 1),
			 RDC_E_INVAL);
}

static void test_state_encoders(void **state)
{
	(void)state;
	assert_int_equal(rdc_batch_fg(b, 0x123456), 0);
	assert_int_equal(rdc_batch_bg(b, 7), 0);
	assert_int_equal(rdc_batch_rop(b, RDC_ROP_XOR), 0);
	assert_int_equal(rdc_batch_clip(b, 1, 2, 300, 200), 0);
	assert_int_equal(
		rdc_batch_dst(b, 0x1000, 1280, 320, 200, RDC_FMT_XRGB8888), 0);
	assert_int_equal(rdc_batch_src(b, 0x2000, 40, 320, 200, RDC_FMT_I1), 0);
	expect_words(
		(const uint32_t[]){ RDC_CMD(RDC_OP_SET_FG, 0, 1), 0x123456,
				    RDC_CMD(RDC_OP_SET_BG, 0, 1), 7,
				    RDC_CMD(RDC_OP_SET_ROP, 0, 1), RDC_ROP_XOR,
				    RDC_CMD(RDC_OP_SET_CLIP, 0, 2),
				    RDC_XY(1, 2), RDC_XY(300, 200),
				    RDC_CMD(RDC_OP_SET_DST, 0, 4), 0x1000, 1280,
				    RDC_WH(320, 200), RDC_FMT_XRGB8888,
				    RDC_CMD(RDC_OP_SET_SRC, 0, 4), 0x2000, 40,
				    RDC_WH(320, 200), RDC_FMT_I1 },
		19);
}

static void test_primitive_encoders(void **state)
{
	static const int pts[] = { 0, 0, 10, -10, 20, 0 };

	(void)state;
	assert_int_equal(rdc_batch_pixel(b, 3, 4), 0);
	assert_int_equal(rdc_batch_polyline(b, pts, 3), 0);
	assert_int_equal(rdc_batch_rect(b, 1, 2, 3, 4), 0);
	assert_int_equal(rdc_batch_circle(b, 50, 60, 7), 0);
	assert_int_equal(rdc_batch_fill_circle(b, -50, 60, 8), 0);
	assert_int_equal(rdc_batch_ellipse(b, 5, 6, 70, 30), 0);
	assert_int_equal(rdc_batch_fill_ellipse(b, 5, 6, 30, 70), 0);
	assert_int_equal(rdc_batch_blit(b, 1, 2, 3, 4, 5, 6), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_PIXEL, 0, 1),
					 RDC_XY(3, 4),
					 RDC_CMD(RDC_OP_POLYLINE, 0, 3),
					 RDC_XY(0, 0),
					 RDC_XY(10, -10),
					 RDC_XY(20, 0),
					 RDC_CMD(RDC_OP_RECT, 0, 2),
					 RDC_XY(1, 2),
					 RDC_WH(3, 4),
					 RDC_CMD(RDC_OP_CIRCLE, 0, 2),
					 RDC_XY(50, 60),
					 7,
					 RDC_CMD(RDC_OP_FILL_CIRCLE, 0, 2),
					 RDC_XY(-50, 60),
					 8,
					 RDC_CMD(RDC_OP_ELLIPSE, 0, 2),
					 RDC_XY(5, 6),
					 RDC_WH(70, 30),
					 RDC_CMD(RDC_OP_FILL_ELLIPSE, 0, 2),
					 RDC_XY(5, 6),
					 RDC_WH(30, 70),
					 RDC_CMD(RDC_OP_BLIT, 0, 3),
					 RDC_XY(1, 2),
					 RDC_XY(3, 4),
					 RDC_WH(5, 6) },
		     25);
}

static void test_mono_padding(void **state)
{
	/* 12 pixels: 2 bytes a row, padded to one word, byte 0 in bits 7:0 */
	static const uint8_t bits[] = { 0xab, 0xc0, 0x12, 0x30 };
	/* 40 pixels: 5 bytes a row, two words */
	static const uint8_t wide[] = { 1, 2, 3, 4, 5 };

	(void)state;
	assert_int_equal(rdc_batch_mono(b, 7, 8, 12, 2, bits, 0), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_MONO, 0, 4),
					 RDC_XY(7, 8), RDC_WH(12, 2),
					 0x0000c0abu, 0x00003012u },
		     5);
	assert_int_equal(rdc_batch_mono(b, 0, 0, 40, 1, wide, 1), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_MONO,
						 RDC_MONO_TRANSPARENT, 4),
					 RDC_XY(0, 0), RDC_WH(40, 1),
					 0x04030201u, 0x00000005u },
		     5);
	/* with its colours: fg and bg between wh and the rows */
	assert_int_equal(rdc_batch_mono_colors(b, 7, 8, 12, 2, bits,
					       0x00112233u, 0x00445566u, 1),
			 0);
	expect_words(
		(const uint32_t[]){
			RDC_CMD(RDC_OP_MONO,
				RDC_MONO_TRANSPARENT | RDC_MONO_COLORS, 6),
			RDC_XY(7, 8), RDC_WH(12, 2), 0x00112233u, 0x00445566u,
			0x0000c0abu, 0x00003012u },
		7);
	assert_int_equal(rdc_batch_mono_colors(b, 0, 0, 8, 1, NULL, 1, 2, 0),
			 RDC_E_INVAL);

	/* 8 pixels wide, 18 rows: a byte a row, each in its own word */
	uint8_t glyph[18];
	uint32_t want[3 + 18];

	for (size_t r = 0; r < 18; r++) {
		glyph[r] = (uint8_t)(0x81 + 7 * r);
		want[3 + r] = glyph[r];
	}
	want[0] = RDC_CMD(RDC_OP_MONO, 0, 2 + 18);
	want[1] = RDC_XY(3, 4);
	want[2] = RDC_WH(8, 18);
	assert_int_equal(rdc_batch_mono(b, 3, 4, 8, 18, glyph, 0), 0);
	expect_words(want, 3 + 18);
}

/*
 * rdc_batch_fg_next: a drawing command that takes RDC_DRAW_FG carries
 * the colour; another command, rdc_batch_cmd or a reset keeps the
 * SET_FG (or nothing) as it is.
 */
static void test_fg_next(void **state)
{
	(void)state;
	assert_int_equal(rdc_batch_fg_next(b, 0x00abcdefu), 0);
	assert_int_equal(rdc_batch_line(b, 1, 2, 3, 4), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_LINE, RDC_DRAW_FG, 3),
					 0x00abcdefu, RDC_XY(1, 2),
					 RDC_XY(3, 4) },
		     4);
	/* the flags of the command itself stay */
	rdc_batch_reset(b);
	static const int tri[] = { 0, 0, 9, 0, 0, 9 };
	assert_int_equal(rdc_batch_fg_next(b, 5), 0);
	assert_int_equal(rdc_batch_fill_polygon(b, tri, 3, 1), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_FILL_POLYGON,
						 RDC_DRAW_FG | RDC_FILL_NONZERO,
						 4),
					 5, RDC_XY(0, 0), RDC_XY(9, 0),
					 RDC_XY(0, 9) },
		     5);
	/* a command that does not take it: SET_FG, then the command */
	rdc_batch_reset(b);
	assert_int_equal(rdc_batch_fg_next(b, 7), 0);
	assert_int_equal(rdc_batch_blit(b, 0, 0, 8, 8, 2, 2), 0);
	assert_int_equal(rdc_batch_line(b, 0, 0, 1, 1), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_SET_FG, 0, 1), 7,
					 RDC_CMD(RDC_OP_BLIT, 0, 3),
					 RDC_XY(0, 0), RDC_XY(8, 8),
					 RDC_WH(2, 2),
					 RDC_CMD(RDC_OP_LINE, 0, 2),
					 RDC_XY(0, 0), RDC_XY(1, 1) },
		     9);
	/* rdc_batch_cmd's words are the ones asked for */
	rdc_batch_reset(b);
	static const uint32_t px = RDC_XY(3, 3);
	assert_int_equal(rdc_batch_fg_next(b, 7), 0);
	assert_int_equal(rdc_batch_cmd(b, RDC_OP_PIXEL, 0, &px, 1), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_SET_FG, 0, 1), 7,
					 RDC_CMD(RDC_OP_PIXEL, 0, 1), px },
		     4);
	/* a plain SET_FG after a reset is not carried */
	rdc_batch_reset(b);
	assert_int_equal(rdc_batch_fg_next(b, 7), 0);
	rdc_batch_reset(b);
	assert_int_equal(rdc_batch_fg(b, 8), 0);
	assert_int_equal(rdc_batch_pixel(b, 1, 1), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_SET_FG, 0, 1), 8,
					 RDC_CMD(RDC_OP_PIXEL, 0, 1),
					 RDC_XY(1, 1) },
		     4);
}

static void test_text_packing(void **state)
{
	(void)state;
	assert_int_equal(rdc_batch_text(b, 1, 2, "Hello", 5, 0), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_TEXT, 0, 4),
					 RDC_XY(1, 2), 5, 0x6c6c6548u,
					 0x0000006fu },
		     5);
	assert_int_equal(rdc_batch_text(b, 0, 0, "", 0, 1), 0);
	expect_words((const uint32_t[]){ RDC_CMD(RDC_OP_TEXT,
						 RDC_MONO_TRANSPARENT, 2),
					 RDC_XY(0, 0), 0 },
		     3);
}

static void test_raw_and_limits(void **state)
{
	static const uint32_t args[2] = { 1, 2 };
	size_t n;

	(void)state;
	assert_int_equal(rdc_batch_cmd(b, 0x7f, 0x5a, args, 2), 0);
	expect_words((const uint32_t[]){ 0x7f5a0002u, 1, 2 }, 3);
	assert_int_equal(rdc_batch_cmd(b, 1, 0, NULL, 1), RDC_E_INVAL);
	assert_int_equal(rdc_batch_cmd(b, 1, 0, args, RDC_CMD_LENGTH + 1),
			 RDC_E_INVAL);
	assert_int_equal(rdc_batch_polyline(b, NULL, 2), RDC_E_INVAL);
	assert_int_equal(rdc_batch_text(b, 0, 0, NULL, 3, 0), RDC_E_INVAL);
	rdc_batch_words(b, &n);
	assert_int_equal(n, 0);
	assert_int_equal(rdc_batch_fg(NULL, 1), RDC_E_INVAL);
	/* growth keeps earlier words */
	for (uint32_t i = 0; i < 5000; i++)
		assert_int_equal(rdc_batch_fence(b, i), 0);
	{
		const uint32_t *w = rdc_batch_words(b, &n);

		assert_int_equal(n, 10000);
		for (uint32_t i = 0; i < 5000; i++)
			assert_int_equal(w[2 * i + 1], i);
	}
	rdc_batch_reset(b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_encoding_literals,
						batch_setup, batch_teardown),
		cmocka_unit_test_setup_teardown(test_control_encoders,
						batch_setup, batch_teardown),
		cmocka_unit_test_setup_teardown(test_state_encoders,
						batch_setup, batch_teardown),
		cmocka_unit_test_setup_teardown(test_primitive_encoders,
						batch_setup, batch_teardown),
		cmocka_unit_test_setup_teardown(test_mono_padding, batch_setup,
						batch_teardown),
		cmocka_unit_test_setup_teardown(test_fg_next, batch_setup,
						batch_teardown),
		cmocka_unit_test_setup_teardown(test_text_packing, batch_setup,
						batch_teardown),
		cmocka_unit_test_setup_teardown(test_raw_and_limits,
						batch_setup, batch_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
