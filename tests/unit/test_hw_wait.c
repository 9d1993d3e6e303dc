// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Host waits (hw-sim/wait.c): a wait run in pieces ends at the same cycle
 * as the same wait run in one go, and budgets and a halted DP end it the
 * documented way.
 */
#include "test_dp_common.h"

/* Some work for the DP, a fence after it, scanout on: a busy chip. */
static void wait_program(struct tdp *t)
{
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	TDP_CMD(t, RDC_OP_SET_FG, 0x00ff8000);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(10, 20), RDC_WH(300, 200));
	TDP_CMD(t, RDC_OP_CIRCLE, RDC_XY(320, 240), 100);
	TDP_CMD(t, RDC_OP_FENCE, 7);
}

static void wait_fence(struct rdc_hw_wait *w)
{
	*w = (struct rdc_hw_wait){
		.term[0] = { RDC_WAIT_TEST_GE, RDC_REG_FENCE, ~0u, 7 },
		.needs_dp = true,
		.budget = 100000000,
	};
}

static void wait_frames(struct rdc_hw *hw, struct rdc_hw_wait *w, uint32_t n)
{
	*w = (struct rdc_hw_wait){
		.term[0] = { RDC_WAIT_TEST_WRAP_GE, RDC_REG_FRAME_COUNT, ~0u,
			     rdc_hw_read(hw, RDC_REG_FRAME_COUNT) + n },
		.budget = 100000000,
	};
}

/* Run a wait to its end in pieces of pseudo-random size. */
static enum rdc_hw_wait_result
wait_in_pieces(struct rdc_hw *hw, struct rdc_hw_wait *w, uint32_t *seed)
{
	enum rdc_hw_wait_result r;
	unsigned int pieces = 0;

	rdc_hw_wait_begin(hw, w);
	do {
		r = rdc_hw_wait_run(hw, w, (uint64_t)tdp_range(seed, 1, 3000));
		pieces++;
	} while (r == RDC_HW_WAIT_MORE);
	assert_true(pieces > 1); /* it really was cut */
	return r;
}

static void test_wait_pieces_same_cycle(void **state)
{
	struct tdp *a = *state, *b = tdp_new();
	struct rdc_hw_wait wa, wb;
	uint32_t seed = 0x5eed;

	wait_program(a);
	wait_program(b);
	assert_int_equal(a->hw.now, b->hw.now);

	wait_fence(&wa);
	rdc_hw_wait_begin(&a->hw, &wa);
	assert_int_equal(rdc_hw_wait_run(&a->hw, &wa, RDC_NEVER),
			 RDC_HW_WAIT_DONE);
	wait_fence(&wb);
	assert_int_equal(wait_in_pieces(&b->hw, &wb, &seed), RDC_HW_WAIT_DONE);
	assert_int_equal(rdc_hw_read(&a->hw, RDC_REG_FENCE), 7);
	assert_int_equal(a->hw.now, b->hw.now);
	assert_int_equal(a->hw.perf.busy, b->hw.perf.busy);

	wait_frames(&a->hw, &wa, 2);
	rdc_hw_wait_begin(&a->hw, &wa);
	assert_int_equal(rdc_hw_wait_run(&a->hw, &wa, RDC_NEVER),
			 RDC_HW_WAIT_DONE);
	wait_frames(&b->hw, &wb, 2);
	assert_int_equal(wait_in_pieces(&b->hw, &wb, &seed), RDC_HW_WAIT_DONE);
	assert_int_equal(a->hw.now, b->hw.now);
	assert_memory_equal(a->vram, b->vram, TDP_VRAM_SIZE);
	tdp_free(b);
}

/*
 * A fence wait ends at the cycle the DP ran out of work, the one
 * rdc_hw_run_until_idle stops at on a twin chip: not a slice later.
 */
static void test_wait_fence_exact(void **state)
{
	struct tdp *a = *state, *b = tdp_new();
	struct tdp *c[2] = { a, b };
	struct rdc_hw_wait w;

	/* one command before the fence: each run overshoots into a whole one */
	for (unsigned int i = 0; i < 2; i++) {
		rdc_hw_write(&c[i]->hw, RDC_REG_CONTROL,
			     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
		TDP_CMD(c[i], RDC_OP_FILL_RECT, RDC_XY(10, 20), RDC_WH(30, 20));
		TDP_CMD(c[i], RDC_OP_FENCE, 7);
	}
	wait_fence(&w);
	rdc_hw_wait_begin(&a->hw, &w);
	assert_int_equal(rdc_hw_wait_run(&a->hw, &w, RDC_NEVER),
			 RDC_HW_WAIT_DONE);
	assert_int_equal(rdc_hw_run_until_idle(&b->hw, b->hw.now + 100000000),
			 1);
	assert_int_equal(rdc_hw_read(&b->hw, RDC_REG_FENCE), 7);
	assert_int_equal(a->hw.now, b->hw.now);
	tdp_free(b);
}

static void test_wait_budget(void **state)
{
	struct tdp *t = *state;
	struct rdc_hw_wait w = {
		.term[0] = { RDC_WAIT_TEST_EQ, RDC_REG_FENCE, ~0u, 12345 },
		.budget = 50000,
	};

	rdc_hw_wait_begin(&t->hw, &w);
	assert_int_equal(rdc_hw_wait_run(&t->hw, &w, RDC_NEVER),
			 RDC_HW_WAIT_TIMEOUT);
	assert_true(t->hw.now - w.start >= 50000);
	/* the last slice may overshoot, by less than one slice */
	assert_true(t->hw.now - w.start < 50000 + RDC_WAIT_SLICE_MAX);
}

static void test_wait_halted(void **state)
{
	struct tdp *t = *state;
	struct rdc_hw_wait w;

	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_HALT_ON_ERR);
	tdp_push(t, RDC_CMD(0x7f, 0, 0)); /* no such opcode */
	TDP_CMD(t, RDC_OP_FENCE, 7);
	wait_fence(&w);
	rdc_hw_wait_begin(&t->hw, &w);
	assert_int_equal(rdc_hw_wait_run(&t->hw, &w, RDC_NEVER),
			 RDC_HW_WAIT_HALTED);
	assert_int_equal(tdp_err(t), RDC_ERR_OPCODE);
	assert_int_not_equal(rdc_hw_read(&t->hw, RDC_REG_FENCE), 7);
}

/* Unused terms and unknown tests never hold. */
static void test_wait_terms(void **state)
{
	struct tdp *t = *state;
	struct rdc_wait_cond none = { RDC_WAIT_TEST_NONE, RDC_REG_ID, 0, 0 };
	struct rdc_wait_cond bad = { 99, RDC_REG_ID, 0, 0 };
	struct rdc_wait_cond eq = { RDC_WAIT_TEST_EQ, RDC_REG_ID, ~0u,
				    RDC_ID_VALUE };
	struct rdc_wait_cond wrap = { RDC_WAIT_TEST_WRAP_GE, RDC_REG_ID, 0,
				      0x80000001u };

	assert_false(rdc_hw_cond_holds(&t->hw, &none));
	assert_false(rdc_hw_cond_holds(&t->hw, &bad));
	assert_true(rdc_hw_cond_holds(&t->hw, &eq));
	/* 0 - 0x80000001 is 0x7fffffff: ahead, as serial numbers go */
	assert_true(rdc_hw_cond_holds(&t->hw, &wrap));
	wrap.value = 1;
	assert_false(rdc_hw_cond_holds(&t->hw, &wrap));
}

/*
 * The paced clock (rdc_pace_target): wall time maps to simulated time at
 * the core clock, exactly, however long it runs (a 64-bit product of
 * nanoseconds and hertz passes 2^64 after 184 s at 100 MHz), and a chip
 * more than `lag` behind or ahead starts afresh from where it is.
 */
static void test_pace(void **state)
{
	const uint64_t hz = RDC_DEFAULT_CORE_HZ, s = 1000000000ull;
	const uint64_t lag = hz / 10;
	struct rdc_pace p = { 0 };
	uint64_t t;

	(void)state;
	assert_int_equal(rdc_pace_target(&p, 5 * s, 1000, hz, lag), 1000);
	assert_int_equal(rdc_pace_target(&p, 6 * s, 1000 + hz - 7, hz, lag),
			 1000 + hz);
	/* 3,600 s on, the chip keeping up: no product overflows */
	t = rdc_pace_target(&p, 3605 * s + 5, 1000 + 3600 * hz, hz, lag);
	assert_int_equal(t, 1000 + 3600 * hz + 0);
	/* 250 ms of wall more than the chip did: it is behind, start afresh */
	t = rdc_pace_target(&p, 3605 * s + 250000000ull, 1000 + 3600 * hz, hz,
			    lag);
	assert_int_equal(t, 1000 + 3600 * hz);
	assert_int_equal(p.wall0_ns, 3605 * s + 250000000ull);
	assert_int_equal(p.sim0, 1000 + 3600 * hz);
	/* then it follows wall time again from there */
	t = rdc_pace_target(&p, 3605 * s + 260000000ull, 1000 + 3600 * hz, hz,
			    lag);
	assert_int_equal(t, 1000 + 3600 * hz + hz / 100);
	/* a chip run 200 ms ahead of its mapping starts afresh too */
	t = rdc_pace_target(&p, 3605 * s + 270000000ull,
			    1000 + 3600 * hz + hz / 5 + hz / 100, hz, lag);
	assert_int_equal(t, 1000 + 3600 * hz + hz / 5 + hz / 100);
	/* within the lag either way, the mapping holds */
	t = rdc_pace_target(&p, 3605 * s + 280000000ull,
			    1000 + 3600 * hz + hz / 5, hz, lag);
	assert_int_equal(t, 1000 + 3600 * hz + hz / 5 + hz / 50);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_wait_pieces_same_cycle),
		TDP_TEST(test_wait_fence_exact),
		TDP_TEST(test_wait_budget),
		TDP_TEST(test_wait_halted),
		TDP_TEST(test_wait_terms),
		cmocka_unit_test(test_pace),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
