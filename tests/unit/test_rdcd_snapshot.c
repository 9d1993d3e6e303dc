// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd's clients each have their own *_HI snapshot: a 64-bit counter read
 * as LO then HI by one client is whole even when another client reads a
 * LO of its own in between (the chip keeps only one snapshot).  The time
 * is stepped across 2^32 cycles so that the two snapshots differ.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "rdc_regs.h"
#include "test_net_common.h"

static const char *const args_stepped[] = { "--stepped", NULL };

static uint32_t reg(rdc_dev *dev, uint32_t r)
{
	uint32_t v = 0xdeadbeef;

	assert_int_equal(rdc_reg_read(dev, r, &v), 0);
	return v;
}

static void test_snapshot_per_client(void **state)
{
	char uri[200];
	rdc_dev *a, *b;
	struct netd d;
	uint32_t lo, hi;

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	assert_int_equal(rdc_open(d.unix_uri, &a), 0);
	snprintf(uri, sizeof(uri), "%s?observe", d.unix_uri);
	assert_int_equal(rdc_open(uri, &b), 0);
	/* no scanout: stepping an idle chip 2^32 cycles is quick */
	assert_int_equal(rdc_reg_write(a, RDC_REG_CONTROL, RDC_CONTROL_DP_EN),
			 0);
	lo = reg(a, RDC_REG_TIME_LO);
	assert_int_equal(reg(a, RDC_REG_TIME_HI), 0);
	assert_int_equal(rdc_sim_step(a, 0xffffffffull - 5000 - lo), 0);

	/* b: the low word just below 2^32, its HI snapshot 0 */
	lo = reg(b, RDC_REG_TIME_LO);
	assert_true(lo > 0xffffffffu - 6000);
	/* a: across 2^32, its own snapshot 1 */
	assert_int_equal(rdc_sim_step(a, 10000), 0);
	assert_true(reg(a, RDC_REG_TIME_LO) < 10000);
	/* each gets the HI of its own LO read */
	assert_int_equal(reg(b, RDC_REG_TIME_HI), 0);
	assert_int_equal(reg(a, RDC_REG_TIME_HI), 1);
	/* used up: live values from here */
	assert_int_equal(reg(b, RDC_REG_TIME_HI), 1);
	assert_int_equal(reg(a, RDC_REG_TIME_HI), 1);

	/* a LO read of another counter replaces the snapshot, as on the
	 * chip: b's TIME_HI is live then */
	lo = reg(b, RDC_REG_TIME_LO);
	(void)reg(b, RDC_REG_PERF_BUSY_LO);
	assert_int_equal(reg(b, RDC_REG_TIME_HI), 1);
	assert_int_equal(reg(b, RDC_REG_PERF_BUSY_HI), 0);

	/* the library's 64-bit read from both, interleaved by nothing */
	{
		uint64_t ta = 0, tb = 0;

		assert_int_equal(rdc_sim_time(a, &ta), 0);
		assert_int_equal(rdc_sim_time(b, &tb), 0);
		assert_true(ta > 0xffffffffull && ta == tb);
	}

	/* a reset drops b's snapshot as it drops the chip's: b's HI read
	 * is live (time goes on across a soft reset) */
	(void)reg(b, RDC_REG_TIME_LO);
	assert_int_equal(rdc_reset(a), 0);
	hi = reg(b, RDC_REG_TIME_HI);
	assert_int_equal(hi, 1);

	rdc_close(b);
	rdc_close(a);
	assert_int_equal(netd_stop(&d), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_snapshot_per_client),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
