// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: submission with back-pressure, fences, vblank and idle waits,
 * device errors, halts, timeouts, simulated time and counters. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"

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

static uint64_t now(rdc_dev *dev)
{
	uint64_t t = 0;

	assert_int_equal(rdc_sim_time(dev, &t), 0);
	return t;
}

static void test_small_submit_does_not_run(void **state)
{
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();
	uint64_t t0 = now(dev);

	/* fits the FIFO: nothing makes the host wait, so no time passes */
	for (int i = 0; i < 10; i++)
		assert_int_equal(rdc_batch_pixel(b, i, i), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(now(dev), t0);
	assert_int_equal(reg(dev, RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH - 20);
	assert_int_equal(rdc_finish(dev), 0);
	assert_true(now(dev) > t0);
	assert_int_equal(reg(dev, RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH);
	rdc_batch_free(b);
}

static void test_back_pressure(void **state)
{
	enum { NPIX = 3000 }; /* 6000 words, many FIFOs full */
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();
	uint32_t cmds0 = reg(dev, RDC_REG_PERF_CMDS);
	uint64_t t0 = now(dev);
	size_t n;

	for (int i = 0; i < NPIX; i++)
		assert_int_equal(rdc_batch_pixel(b, i % 640, i / 640), 0);
	rdc_batch_words(b, &n);
	assert_true(n > 4 * RDC_FIFO_DEPTH);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	/* the host had to wait for the DP to drain the FIFO */
	assert_true(now(dev) > t0);
	assert_true(reg(dev, RDC_REG_PERF_CMDS) - cmds0 >=
		    NPIX - RDC_FIFO_DEPTH / 2);
	assert_int_equal(rdc_finish(dev), 0);
	/* every pixel and the fence ran; none was dropped */
	assert_int_equal(reg(dev, RDC_REG_PERF_CMDS) - cmds0, NPIX + 1);
	assert_int_equal(reg(dev, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	rdc_batch_free(b);
}

static void test_fence_wait(void **state)
{
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();

	assert_int_equal(rdc_batch_fill_rect(b, 0, 0, 100, 100), 0);
	assert_int_equal(rdc_batch_fence(b, 1000), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_fence_wait(dev, 1000), 0);
	assert_int_equal(reg(dev, RDC_REG_FENCE), 1000);
	/* an earlier value is already passed (wrapping compare) */
	assert_int_equal(rdc_fence_wait(dev, 999), 0);
	/* rdc_finish hands out fresh values */
	assert_int_equal(rdc_finish(dev), 0);
	{
		uint32_t f1 = reg(dev, RDC_REG_FENCE);

		assert_int_equal(rdc_finish(dev), 0);
		assert_int_equal(reg(dev, RDC_REG_FENCE), f1 + 1);
	}
	rdc_batch_free(b);
}

static void test_vblank_wait(void **state)
{
	rdc_dev *dev = *state;
	uint32_t y = 0, vdisp, fc0;

	fc0 = reg(dev, RDC_REG_FRAME_COUNT);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(reg(dev, RDC_REG_FRAME_COUNT), fc0 + 1);
	assert_true(reg(dev, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	vdisp = reg(dev, RDC_REG_V_DISPLAY);
	assert_int_equal(rdc_sim_beam(dev, NULL, &y), 0);
	assert_true(y >= vdisp);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(reg(dev, RDC_REG_FRAME_COUNT), fc0 + 2);
	/* even from vblank, a frame with fresh latched state is two away */
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(reg(dev, RDC_REG_FRAME_COUNT), fc0 + 4);
}

static void test_frame_wait_from_active(void **state)
{
	rdc_dev *dev = *state;
	uint32_t fc0;

	assert_int_equal(rdc_vblank_wait(dev), 0);
	/* step into the active lines of the next frame */
	while (reg(dev, RDC_REG_STATUS) & RDC_STATUS_VBLANK)
		assert_int_equal(rdc_sim_step(dev, 1000), 0);
	fc0 = reg(dev, RDC_REG_FRAME_COUNT);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(reg(dev, RDC_REG_FRAME_COUNT), fc0 + 2);
}

static void test_device_error_skip(void **state)
{
	rdc_dev *dev = *state;
	const uint32_t bad = RDC_CMD(0x7f, 0, 0);
	uint32_t code = 0, info = 0;

	assert_int_equal(rdc_submit(dev, &bad, 1), 0);
	assert_int_equal(rdc_finish(dev), RDC_E_DEVICE);
	assert_int_equal(rdc_dev_error(dev, &code, &info), 0);
	assert_int_equal(code, RDC_ERR_OPCODE);
	assert_int_equal(info, bad);
	/* reading cleared it; the DP skipped the command and goes on */
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(reg(dev, RDC_REG_IRQ_STATUS) & RDC_IRQ_ERROR, 0);
}

static void test_halted(void **state)
{
	rdc_dev *dev = *state;
	const uint32_t bad = RDC_CMD(0x7f, 0, 0);
	uint32_t code = 0;

	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL,
				       RDC_CONTROL_RESET_VALUE |
					       RDC_CONTROL_HALT_ON_ERR),
			 0);
	assert_int_equal(rdc_submit(dev, &bad, 1), 0);
	assert_int_equal(rdc_finish(dev), RDC_E_HALTED);
	assert_true(reg(dev, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED);
	assert_int_equal(rdc_dev_error(dev, &code, NULL), 0);
	assert_int_equal(code, RDC_ERR_OPCODE);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL,
				       RDC_CONTROL_RESET_VALUE |
					       RDC_CONTROL_RESUME),
			 0);
	assert_int_equal(rdc_finish(dev), 0);
}

static void test_timeout(void **state)
{
	rdc_dev *dev = *state;
	uint64_t t0;

	/* DP and scanout off: nothing will ever execute the fence */
	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL, 0), 0);
	t0 = now(dev);
	assert_int_equal(rdc_finish(dev), RDC_E_TIMEOUT);
	/* the budget is ten simulated seconds at the core clock */
	assert_true(now(dev) - t0 >= 10ull * 100000000ull);
	assert_int_equal(rdc_vblank_wait(dev), RDC_E_TIMEOUT);
	assert_int_equal(rdc_reset(dev), 0);
	assert_int_equal(rdc_finish(dev), 0);
}

static void test_idle_wait_and_counters(void **state)
{
	rdc_dev *dev = *state;
	rdc_batch *b = rdc_batch_new();
	struct rdc_stats s0, s1;
	uint32_t hz = 0;

	assert_int_equal(rdc_idle_wait(dev), 0);
	assert_int_equal(rdc_stats_get(dev, &s0), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 10, 10, 12, 7), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_idle_wait(dev), 0);
	assert_int_equal(rdc_stats_get(dev, &s1), 0);
	/* no fence was added: the last command is the fill */
	assert_int_equal(s1.last_opcode, RDC_OP_FILL_RECT);
	assert_int_equal(s1.cmds - s0.cmds, 1);
	assert_int_equal(s1.pixels - s0.pixels, 12 * 7);
	assert_int_equal(s1.busy - s0.busy, s1.last_cycles);
	assert_true(s1.time > s0.time);
	assert_int_equal(rdc_sim_core_hz(dev, &hz), 0);
	assert_int_equal(hz, 100000000u);
	rdc_batch_free(b);
}

static void test_step_and_run_until(void **state)
{
	rdc_dev *dev = *state;
	uint64_t t0 = now(dev);

	assert_int_equal(rdc_sim_step(dev, 12345), 0);
	assert_true(now(dev) >= t0 + 12345);
	assert_int_equal(rdc_sim_run_until(dev, t0 + 100000), 0);
	assert_true(now(dev) >= t0 + 100000);
	/* the past is a no-op */
	t0 = now(dev);
	assert_int_equal(rdc_sim_run_until(dev, 5), 0);
	assert_int_equal(now(dev), t0);
}

#define T(f) cmocka_unit_test_setup_teardown(f, dev_setup, dev_teardown)

int main(void)
{
	const struct CMUnitTest tests[] = {
		T(test_small_submit_does_not_run),
		T(test_back_pressure),
		T(test_fence_wait),
		T(test_vblank_wait),
		T(test_frame_wait_from_active),
		T(test_device_error_skip),
		T(test_halted),
		T(test_timeout),
		T(test_idle_wait_and_counters),
		T(test_step_and_run_until),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
