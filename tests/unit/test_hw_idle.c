// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdc_hw_run_until_idle: the host regains control at the exact cycle the
 * display processor runs out of work, and not a cycle later.
 */
#include "test_dp_common.h"

/* A fill ends exactly where the DP's own accounting says it ended. */
static void test_idle_stops_at_last_cycle(void **state)
{
	struct tdp *t = *state;
	uint64_t start = t->hw.now, busy0 = t->hw.perf.busy;

	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(3, 5), RDC_WH(200, 100));
	assert_int_equal(rdc_hw_run_until_idle(&t->hw, start + 10000000), 1);
	assert_true(tdp_idle(t));
	/* Scanout is off: nothing but the fill took time. */
	assert_true(t->hw.perf.busy > busy0);
	assert_int_equal(t->hw.now - start, t->hw.perf.busy - busy0);
	assert_int_equal(t->hw.now - start, t->hw.perf.last_cycles);
}

/* With nothing to do, it returns at once without moving time. */
static void test_idle_without_work(void **state)
{
	struct tdp *t = *state;
	uint64_t start = t->hw.now;

	assert_int_equal(rdc_hw_run_until_idle(&t->hw, start + 5000), 1);
	assert_int_equal(t->hw.now, start);
}

/* A WAIT_LINE is not idleness: time runs to the line, then it stops. */
static void test_idle_after_wait_line(void **state)
{
	struct tdp *t = *state;
	uint64_t line_at, start;

	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	start = t->hw.now;
	line_at = rdc_port_next_line(&t->hw, 100);
	assert_true(line_at != RDC_NEVER && line_at > start);
	TDP_CMD(t, RDC_OP_WAIT_LINE, 100);
	assert_int_equal(rdc_hw_run_until_idle(&t->hw, line_at + 1000000), 1);
	assert_true(t->hw.now >= line_at);
	/* The command was fetched and decoded before the wait began. */
	assert_int_equal(t->hw.now, line_at);
	/* A budget that ends first is reported as such. */
	TDP_CMD(t, RDC_OP_WAIT_LINE, 200);
	assert_int_equal(rdc_hw_run_until_idle(&t->hw, t->hw.now + 10), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_idle_stops_at_last_cycle),
		TDP_TEST(test_idle_without_work),
		TDP_TEST(test_idle_after_wait_line),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
