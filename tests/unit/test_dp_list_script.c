// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The .rdl side of display lists, anti-aliasing, alpha and colour key:
 * `list ADDR` ... `end` stores encoded commands in VRAM without running
 * them, `call` runs them, the statements' errors, and the batch encoders'
 * words.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "script_fx.h"

#define LADDR 0x80000u

static uint32_t px(rdc_dev *dev, uint32_t x, uint32_t y)
{
	uint32_t v = 0;

	assert_int_equal(rdc_vram_read(dev, (y * 320 + x) * 4, &v, 4), 0);
	return v;
}

/* The list's words are exactly the commands' encodings, and nothing is
 * drawn until the call. */
static void test_list_stores(void **state)
{
	rdc_dev *dev = *state;
	uint32_t w[8];
	const uint32_t want[8] = {
		RDC_CMD(RDC_OP_SET_FG, 0, 1),
		0x00ff0000u,
		RDC_CMD(RDC_OP_PIXEL, 0, 1),
		RDC_XY(3, 4),
		RDC_CMD(RDC_OP_RET, 0, 0),
		RDC_CMD(RDC_OP_SET_ALPHA, 0, 1),
		77,
		RDC_CMD(RDC_OP_SET_COLORKEY, RDC_COLORKEY_ENABLE, 1),
	};

	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n"
				  "list 0x80000\n"
				  "fg #ff0000\n"
				  "pixel 3 4\n"
				  "ret\n"
				  "alpha 77\n"
				  "colorkey #00ff00\n"
				  "end\n"),
			 0);
	assert_int_equal(rdc_vram_read(dev, LADDR, w, sizeof(w)), 0);
	assert_memory_equal(w, want, sizeof(want));
	assert_int_equal(px(dev, 3, 4), 0);
	assert_int_equal(run(dev, "call 0x80000\n"), 0);
	assert_int_equal(px(dev, 3, 4), 0x00ff0000u);
	/* the call and the list's three commands all ran */
	assert_int_equal(res.op_count[RDC_OP_CALL], 4);
}

/*
 * host-blit in a list is kept, not drawn: the list holds exactly the
 * HOST_BLIT commands rdc_host_blit would send (split in pieces when
 * large), and calling it draws what the statement draws outside a list.
 */
static void test_list_host_blit(void **state)
{
	rdc_dev *dev = *state, *ref;
	static uint32_t got[300 * 20], want[300 * 20];
	const uint32_t head[5] = {
		RDC_CMD(RDC_OP_HOST_BLIT, 0, 2 + 2 * 2),
		RDC_XY(5, 6),
		RDC_WH(2, 2),
		0x00ff0000u,
		0x0000ff00u,
	};
	uint32_t w[5], cmds0, cmds1;

	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n"), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_PERF_CMDS, &cmds0), 0);
	assert_int_equal(run(dev, "list 0x80000\n"
				  "host-blit 5 6 2 2 data #ff0000 #00ff00 "
				  "#0000ff #ffffff\n"
				  "host-blit 10 40 300 20 pattern noise 7\n"
				  "ret\n"
				  "end\n"),
			 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_PERF_CMDS, &cmds1), 0);
	assert_int_equal(cmds1, cmds0);
	assert_int_equal(res.op_count[RDC_OP_HOST_BLIT], 0);
	assert_int_equal(px(dev, 5, 6), 0);
	assert_int_equal(px(dev, 10, 40), 0);
	assert_int_equal(rdc_vram_read(dev, LADDR, w, sizeof(w)), 0);
	assert_memory_equal(w, head, sizeof(head));

	assert_int_equal(run(dev, "call 0x80000\n"), 0);
	/* the call, two pieces of the large blit, the small one, RET */
	assert_int_equal(res.op_count[RDC_OP_CALL], 5);
	assert_int_equal(px(dev, 5, 6), 0x00ff0000u);
	assert_int_equal(px(dev, 6, 7), 0x00ffffffu);

	/* the same statement outside a list, on a second device */
	assert_int_equal(rdc_open("sim:vram=4M", &ref), 0);
	assert_int_equal(run(ref, "mode 320x200 xrgb8888\n"
				  "host-blit 10 40 300 20 pattern noise 7\n"),
			 0);
	for (uint32_t y = 0; y < 20; y++) {
		assert_int_equal(rdc_vram_read(dev, ((40 + y) * 320 + 10) * 4,
					       got + y * 300, 300 * 4),
				 0);
		assert_int_equal(rdc_vram_read(ref, ((40 + y) * 320 + 10) * 4,
					       want + y * 300, 300 * 4),
				 0);
	}
	assert_memory_equal(got, want, sizeof(want));
	assert_int_not_equal(want[0] | want[300 * 20 - 1], 0);
	rdc_close(ref);
}

static void test_list_errors(void **state)
{
	rdc_dev *dev = *state;

	assert_int_not_equal(run(dev, "list 0x80000\nfg 1\n"), 0);
	assert_int_equal(res.error_line, 1);
	assert_non_null(strstr(res.error_msg, "without end"));
	assert_int_not_equal(run(dev, "end\n"), 0);
	assert_int_not_equal(run(dev, "list 0x80002\nend\n"), 0);
	assert_int_not_equal(run(dev, "list 0x80000\nlist 0x90000\n"), 0);
	assert_int_not_equal(run(dev, "list 0x80000\nreg CONTROL 1\nend\n"), 0);
	assert_int_equal(res.error_line, 2);
	assert_int_not_equal(run(dev, "list 0x80000\nraw 0\nend\n"), 0);
	/* a list past the end of VRAM is refused when written */
	assert_int_not_equal(run(dev, "list 0x3ffffc\nfg 1\nend\n"), 0);
	/* a device error inside a called list reaches the script */
	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n"
				  "list 0x80000\nret\nend\n"
				  "call 0x80000\n"),
			 0);
	assert_int_not_equal(run(dev, "ret\n"), 0);
	assert_non_null(strstr(res.error_msg, "STACK"));
}

/* The AA, alpha and key statements reach the device. */
static void test_statements(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n"
				  "fg #ffffff\n"
				  "aa-line 0 0 10 0\n"
				  "aa-circle 100 100 10\n"
				  "aa-ellipse 200 100 10 0\n"
				  "aa-ramp 16\n"
				  "alpha 128\n"
				  "colorkey #000000\n"
				  "colorkey off\n"
				  "alpha 255\n"),
			 0);
	assert_int_equal(px(dev, 5, 0), 0x00ffffffu);
	assert_int_equal(px(dev, 100, 90), 0x00ffffffu);
	assert_int_equal(px(dev, 195, 100), 0x00ffffffu);
	assert_int_equal(res.op_count[RDC_OP_AA_LINE], 1);
	assert_int_not_equal(run(dev, "aa-ramp 1\n"), 0);
	assert_int_not_equal(run(dev, "alpha 256\n"), 0);
	assert_int_not_equal(run(dev, "aa-line 1 2 3\n"), 0);
	assert_int_not_equal(run(dev, "colorkey\n"), 0);
}

static void test_batch_words(void **state)
{
	rdc_batch *b = rdc_batch_new();
	const uint32_t *w;
	size_t n;
	const uint32_t want[] = {
		RDC_CMD(RDC_OP_AA_LINE, 0, 2),
		RDC_XY(1, 2),
		RDC_XY(-3, 4),
		RDC_CMD(RDC_OP_AA_CIRCLE, 0, 2),
		RDC_XY(5, 6),
		7,
		RDC_CMD(RDC_OP_AA_ELLIPSE, 0, 2),
		RDC_XY(8, 9),
		RDC_WH(10, 11),
		RDC_CMD(RDC_OP_SET_AA_RAMP, 0, 1),
		12,
		RDC_CMD(RDC_OP_SET_ALPHA, 0, 1),
		13,
		RDC_CMD(RDC_OP_SET_COLORKEY, RDC_COLORKEY_ENABLE, 1),
		14,
		RDC_CMD(RDC_OP_SET_COLORKEY, 0, 1),
		0,
		RDC_CMD(RDC_OP_CALL, 0, 1),
		0x1000,
		RDC_CMD(RDC_OP_RET, 0, 0),
		RDC_CMD(RDC_OP_JUMP, 0, 1),
		0x2000,
	};

	(void)state;
	assert_non_null(b);
	assert_int_equal(rdc_batch_aa_line(b, 1, 2, -3, 4), 0);
	assert_int_equal(rdc_batch_aa_circle(b, 5, 6, 7), 0);
	assert_int_equal(rdc_batch_aa_ellipse(b, 8, 9, 10, 11), 0);
	assert_int_equal(rdc_batch_aa_ramp(b, 12), 0);
	assert_int_equal(rdc_batch_alpha(b, 13), 0);
	assert_int_equal(rdc_batch_colorkey(b, 14, 1), 0);
	assert_int_equal(rdc_batch_colorkey(b, 0, 0), 0);
	assert_int_equal(rdc_batch_call(b, 0x1000), 0);
	assert_int_equal(rdc_batch_ret(b), 0);
	assert_int_equal(rdc_batch_jump(b, 0x2000), 0);
	w = rdc_batch_words(b, &n);
	assert_int_equal(n, sizeof(want) / sizeof(want[0]));
	assert_memory_equal(w, want, sizeof(want));
	rdc_batch_free(b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_list_stores, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_list_host_blit, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_list_errors, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_statements, dev_setup,
						dev_teardown),
		cmocka_unit_test(test_batch_words),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
