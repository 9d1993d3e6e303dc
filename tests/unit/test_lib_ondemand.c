// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc's sim:scanout=demand against plain sim:: the same drawing at the
 * same simulated times; with nothing looking the on-demand chip converts
 * no frame (its frame buffers stay as allocated), and a grab then gives
 * the picture plain sim: gives, also while the display processor is
 * still drawing when the grab begins.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hw.h"
#include "rdc.h"
#include "rdc_server.h"

#define W 640u
#define H 480u

static rdc_dev *open_dev(const char *uri)
{
	rdc_dev *dev = NULL;

	assert_int_equal(rdc_open(uri, &dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60,
				      RDC_FMT_XRGB8888, 0),
			 0);
	return dev;
}

/* n filled rectangles, seeded, queued (not waited for) */
static void draw(rdc_dev *dev, uint32_t seed, int n)
{
	rdc_batch *b = rdc_batch_new();

	assert_non_null(b);
	for (int i = 0; i < n; i++) {
		seed ^= seed << 13;
		seed ^= seed >> 17;
		seed ^= seed << 5;
		rdc_batch_fg(b, seed | 0xff000000u);
		rdc_batch_fill_rect(b, (int)(seed % W), (int)(seed / W % H),
				    1 + seed % 200, 1 + seed / 7 % 150);
	}
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	rdc_batch_free(b);
}

/* n full-screen fills: the display processor is busy for frames */
static void draw_long(rdc_dev *dev, int n)
{
	rdc_batch *b = rdc_batch_new();

	assert_non_null(b);
	for (int i = 0; i < n; i++) {
		rdc_batch_fg(b, 0xff000000u | (uint32_t)i * 0x10305u);
		rdc_batch_fill_rect(b, 0, 0, W, H);
	}
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	rdc_batch_free(b);
}

static bool all_zero(const uint32_t *p, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (p[i])
			return false;
	return true;
}

static uint32_t fa[W * H], fb[W * H];

static void grab_same(rdc_dev *a, rdc_dev *b)
{
	uint32_t wa, ha, wb, hb;

	assert_int_equal(rdc_frame_grab(a, fa, W * H, &wa, &ha), 0);
	assert_int_equal(rdc_frame_grab(b, fb, W * H, &wb, &hb), 0);
	assert_int_equal(wa, wb);
	assert_int_equal(ha, hb);
	assert_memory_equal(fa, fb, sizeof(fa));
}

static void test_nothing_converted_until_a_grab(void **state)
{
	rdc_dev *eager = open_dev("sim:"),
		*lazy = open_dev("sim:scanout=demand");
	struct rdc_hw *hw = rdc_sim_hw(lazy);
	uint64_t ta, tb;

	(void)state;
	assert_non_null(hw);
	for (int round = 0; round < 3; round++) {
		draw(eager, 0x1234u + (uint32_t)round, 300);
		draw(lazy, 0x1234u + (uint32_t)round, 300);
		assert_int_equal(rdc_finish(eager), 0);
		assert_int_equal(rdc_finish(lazy), 0);
		assert_int_equal(rdc_frame_wait(eager), 0);
		assert_int_equal(rdc_frame_wait(lazy), 0);
		assert_int_equal(rdc_sim_time(eager, &ta), 0);
		assert_int_equal(rdc_sim_time(lazy, &tb), 0);
		assert_int_equal(ta, tb);
	}
	/* frames came and went, and not one was converted */
	assert_true(all_zero(hw->frame[0], W * H));
	assert_true(all_zero(hw->frame[1], W * H));
	grab_same(eager, lazy);
	/*
	 * A grab while the display processor draws on: the frame just
	 * completed changed while nobody looked, so the grab waits for the
	 * next whole one; plain sim: shows the same frame at that time.
	 */
	draw_long(eager, 100);
	draw_long(lazy, 100);
	assert_int_equal(rdc_vblank_wait(eager), 0);
	assert_int_equal(rdc_vblank_wait(lazy), 0);
	assert_int_equal(rdc_sim_time(eager, &ta), 0);
	assert_int_equal(rdc_frame_grab(lazy, fb, W * H, NULL, NULL), 0);
	assert_int_equal(rdc_sim_time(lazy, &tb), 0);
	assert_true(tb > ta);
	assert_int_equal(rdc_sim_step(eager, tb - ta), 0);
	assert_int_equal(rdc_frame_grab(eager, fa, W * H, NULL, NULL), 0);
	assert_memory_equal(fa, fb, sizeof(fa));
	assert_int_equal(rdc_finish(eager), 0);
	assert_int_equal(rdc_finish(lazy), 0);
	assert_int_equal(rdc_frame_wait(eager), 0);
	assert_int_equal(rdc_frame_wait(lazy), 0);
	grab_same(eager, lazy);
	rdc_close(eager);
	rdc_close(lazy);
}

static void test_uri(void **state)
{
	rdc_dev *dev = NULL;

	(void)state;
	assert_int_equal(rdc_open("sim:scanout=demand,vram=1M", &dev), 0);
	assert_true(rdc_sim_hw(dev)->on_demand);
	rdc_close(dev);
	assert_int_equal(rdc_open("sim:vram=1M", &dev), 0);
	assert_false(rdc_sim_hw(dev)->on_demand);
	rdc_close(dev);
	assert_int_equal(rdc_open("sim:scanout=lazy", &dev), RDC_E_URI);
	assert_int_equal(rdc_open("sim:scanout=demandx", &dev), RDC_E_URI);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_nothing_converted_until_a_grab),
		cmocka_unit_test(test_uri),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
