// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Display lists: CALL/RET/JUMP into command lists in VRAM, nesting to
 * RDC_CALL_DEPTH, the errors past it and outside a list, lists that leave
 * VRAM, errors unwinding to the top level, lists entered from the ring,
 * endless loops that still let time pass, reset, and the fetch cost.
 */
#include "test_dp_common.h"

#define LIST_A 0x200000u
#define LIST_B 0x201000u
#define LIST_C 0x202000u

static const struct rdc_surface screen = { 0, 2560, 640, 480,
					   RDC_FMT_XRGB8888 };

/* A list being assembled at a VRAM address. */
struct lst {
	struct tdp *t;
	uint32_t addr, pos;
};

static void lst_word(struct lst *l, uint32_t w)
{
	uint8_t *p = l->t->vram + l->addr + l->pos;

	p[0] = (uint8_t)w;
	p[1] = (uint8_t)(w >> 8);
	p[2] = (uint8_t)(w >> 16);
	p[3] = (uint8_t)(w >> 24);
	l->pos += 4;
}

static void lst_cmd(struct lst *l, uint32_t op, unsigned int n,
		    const uint32_t *a)
{
	unsigned int i;

	lst_word(l, RDC_CMD(op, 0, n));
	for (i = 0; i < n; i++)
		lst_word(l, a[i]);
}

#define LST(l, op, ...) \
	do { \
		const uint32_t lst_a_[] = { __VA_ARGS__ }; \
		lst_cmd((l), (op), RDC_ARRAY_SIZE(lst_a_), lst_a_); \
	} while (0)
#define LST0(l, op) lst_cmd((l), (op), 0, NULL)

static uint32_t px(struct tdp *t, int32_t x, int32_t y)
{
	return tdp_get(t->vram, &screen, x, y);
}

/* The same drawing from a list and from the FIFO gives the same VRAM. */
static void test_list_equals_fifo(void **state)
{
	struct tdp *t = *state, *u = tdp_new();
	struct lst l = { t, LIST_A, 0 };

	LST(&l, RDC_OP_SET_FG, 0x00ff8000u);
	LST(&l, RDC_OP_FILL_RECT, RDC_XY(10, 10), RDC_WH(50, 20));
	LST(&l, RDC_OP_SET_ROP, RDC_ROP_XOR);
	LST(&l, RDC_OP_LINE, RDC_XY(0, 0), RDC_XY(100, 77));
	LST(&l, RDC_OP_CIRCLE, RDC_XY(200, 100), 40);
	LST0(&l, RDC_OP_RET);
	TDP_CMD(t, RDC_OP_CALL, LIST_A);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(300, 300));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);

	TDP_CMD(u, RDC_OP_SET_FG, 0x00ff8000u);
	TDP_CMD(u, RDC_OP_FILL_RECT, RDC_XY(10, 10), RDC_WH(50, 20));
	TDP_CMD(u, RDC_OP_SET_ROP, RDC_ROP_XOR);
	TDP_CMD(u, RDC_OP_LINE, RDC_XY(0, 0), RDC_XY(100, 77));
	TDP_CMD(u, RDC_OP_CIRCLE, RDC_XY(200, 100), 40);
	TDP_CMD(u, RDC_OP_PIXEL, RDC_XY(300, 300));
	tdp_drain(u);
	/* the list itself lives beyond the screen */
	assert_memory_equal(t->vram, u->vram, 640 * 480 * 4);
	assert_int_not_equal(px(t, 300, 300), 0);
	/* CALL, the five list commands and RET all count */
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS),
			 rdc_hw_read(&u->hw, RDC_REG_PERF_CMDS) + 2);
	tdp_free(u);
}

/* A calls B calls C; each RET resumes its caller after the CALL. */
static void test_list_nested(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A, 0 }, b = { t, LIST_B, 0 };
	struct lst c = { t, LIST_C, 0 };

	LST(&a, RDC_OP_SET_FG, 1);
	LST(&a, RDC_OP_PIXEL, RDC_XY(1, 0));
	LST(&a, RDC_OP_CALL, LIST_B);
	LST(&a, RDC_OP_PIXEL, RDC_XY(4, 0));
	LST0(&a, RDC_OP_RET);
	LST(&b, RDC_OP_SET_FG, 2);
	LST(&b, RDC_OP_PIXEL, RDC_XY(2, 0));
	LST(&b, RDC_OP_CALL, LIST_C);
	LST(&b, RDC_OP_PIXEL, RDC_XY(3, 1));
	LST0(&b, RDC_OP_RET);
	LST(&c, RDC_OP_SET_FG, 3);
	LST(&c, RDC_OP_PIXEL, RDC_XY(3, 0));
	LST0(&c, RDC_OP_RET);
	LST(&c, RDC_OP_PIXEL, RDC_XY(9, 9)); /* never reached */

	TDP_CMD(t, RDC_OP_CALL, LIST_A);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(5, 0));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(px(t, 1, 0), 1);
	assert_int_equal(px(t, 2, 0), 2);
	assert_int_equal(px(t, 3, 0), 3);
	assert_int_equal(px(t, 3, 1), 3);
	assert_int_equal(px(t, 4, 0), 3);
	assert_int_equal(px(t, 5, 0), 3);
	assert_int_equal(px(t, 9, 9), 0);
	assert_int_equal(t->dp.list_depth, 0);
}

/*
 * A list that calls itself: RDC_CALL_DEPTH levels run, the next CALL is
 * RDC_ERR_STACK with ERR_INFO its header, and everything unwinds: the
 * pixels after the CALLs never draw, the FIFO's next command does.
 */
static void test_list_depth(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A, 0 };
	uint32_t i;

	LST(&a, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(1, 1));
	LST(&a, RDC_OP_BLIT, RDC_XY(0, 0), RDC_XY(1, 0), RDC_WH(639, 1));
	LST(&a, RDC_OP_CALL, LIST_A);
	LST(&a, RDC_OP_PIXEL, RDC_XY(0, 5));
	LST0(&a, RDC_OP_RET);
	TDP_CMD(t, RDC_OP_SET_FG, 7);
	TDP_CMD(t, RDC_OP_CALL, LIST_A);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(0, 6));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_STACK);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_INFO),
			 RDC_CMD(RDC_OP_CALL, 0, 1));
	assert_int_equal(t->dp.list_depth, 0);
	assert_int_equal(px(t, 0, 5), 0);
	assert_int_equal(px(t, 0, 6), 7);
	/* each of the RDC_CALL_DEPTH levels (and the failed one's caller)
	 * copied row 0 one step right: exactly that many pixels are set */
	for (i = 0; i < RDC_CALL_DEPTH + 1; i++)
		assert_int_equal(px(t, (int32_t)i, 0), 7);
	assert_int_equal(px(t, RDC_CALL_DEPTH + 1, 0), 0);
}

static void test_list_ret_top(void **state)
{
	struct tdp *t = *state;

	TDP_CMD(t, RDC_OP_SET_FG, 7);
	tdp_cmd(t, RDC_OP_RET, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(1, 1));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_STACK);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_INFO),
			 RDC_CMD(RDC_OP_RET, 0, 0));
	assert_int_equal(px(t, 1, 1), 7);
}

/* Bad addresses, lengths, a list running off VRAM, an error mid-list. */
static void test_list_bad(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A, 0 };
	struct lst e = { t, TDP_VRAM_SIZE - 8, 0 };
	const uint32_t two[2] = { LIST_A, 0 };

	TDP_CMD(t, RDC_OP_SET_FG, 7);
	TDP_CMD(t, RDC_OP_CALL, LIST_A + 2);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_JUMP, TDP_VRAM_SIZE);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_CALL, 0xfffffffcu);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_CALL, 0, 2, two);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_JUMP, 0, 0, NULL);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	tdp_clear_err(t);
	assert_int_equal(t->dp.list_depth, 0);

	/* the last two words of VRAM: a NOP, a PIXEL header, then the end */
	LST0(&e, RDC_OP_NOP);
	lst_word(&e, RDC_CMD(RDC_OP_PIXEL, 0, 1));
	TDP_CMD(t, RDC_OP_CALL, TDP_VRAM_SIZE - 8);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(2, 2));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_INFO), TDP_VRAM_SIZE);
	assert_int_equal(t->dp.list_depth, 0);
	assert_int_equal(px(t, 2, 2), 7);
	tdp_clear_err(t);

	/* a list that just stops: the word after the NOP is the end */
	e.pos = 0;
	lst_word(&e, RDC_CMD(RDC_OP_NOP, 0, 1));
	lst_word(&e, 0);
	TDP_CMD(t, RDC_OP_CALL, TDP_VRAM_SIZE - 8);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_INFO), TDP_VRAM_SIZE);
	tdp_clear_err(t);

	/* an error inside a nested list abandons both lists */
	LST(&a, RDC_OP_CALL, LIST_B);
	LST(&a, RDC_OP_PIXEL, RDC_XY(3, 3));
	LST0(&a, RDC_OP_RET);
	a.addr = LIST_B;
	a.pos = 0;
	LST(&a, RDC_OP_SET_ROP, 99);
	LST(&a, RDC_OP_PIXEL, RDC_XY(4, 4));
	LST0(&a, RDC_OP_RET);
	TDP_CMD(t, RDC_OP_CALL, LIST_A);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(5, 5));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	assert_int_equal(px(t, 3, 3), 0);
	assert_int_equal(px(t, 4, 4), 0);
	assert_int_equal(px(t, 5, 5), 7);
	assert_int_equal(t->dp.list_depth, 0);
	tdp_clear_err(t);

	/* a header announcing too many words inside a list */
	a.pos = 0;
	lst_word(&a, RDC_CMD(RDC_OP_NOP, 0, RDC_CMD_MAX_ARGS + 1));
	TDP_CMD(t, RDC_OP_CALL, LIST_B);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	assert_int_equal(t->dp.list_depth, 0);
}

/* With HALT_ON_ERR a bad command in a list halts the DP, lists dropped. */
static void test_list_halt(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A, 0 };

	LST(&a, RDC_OP_SET_FG, 9);
	LST(&a, RDC_OP_SET_ROP, 99);
	LST(&a, RDC_OP_PIXEL, RDC_XY(1, 1));
	LST0(&a, RDC_OP_RET);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_HALT_ON_ERR);
	TDP_CMD(t, RDC_OP_CALL, LIST_A);
	tdp_drain(t);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED);
	assert_int_equal(t->dp.list_depth, 0);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(2, 2));
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_HALT_ON_ERR |
			     RDC_CONTROL_RESUME);
	tdp_drain(t);
	assert_int_equal(px(t, 1, 1), 0);
	assert_int_equal(px(t, 2, 2), 9);
}

/*
 * JUMP from the FIFO enters a list; a list that JUMPs to itself runs
 * forever, but the chip's run loop still returns with time advanced and
 * the DP busy; reset empties the stack.
 */
static void test_list_jump_loop(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A, 0 };
	uint64_t t0;

	LST(&a, RDC_OP_SET_FG, 5);
	LST(&a, RDC_OP_PIXEL, RDC_XY(7, 7));
	LST(&a, RDC_OP_JUMP, LIST_A + 8);
	TDP_CMD(t, RDC_OP_JUMP, LIST_A);
	t0 = t->hw.now;
	rdc_hw_run_until(&t->hw, t0 + 50000);
	assert_true(t->hw.now >= t0 + 50000);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(px(t, 7, 7), 5);
	assert_int_equal(t->dp.list_depth, 1);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_BUSY);
	/* many passes ran: each a PIXEL and a JUMP */
	assert_true(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS) > 1000);

	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SOFT_RESET);
	rdc_hw_run_until(&t->hw, t->hw.now + 1000);
	assert_int_equal(t->dp.list_depth, 0);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	TDP_CMD(t, RDC_OP_SET_FG, 6);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(8, 8));
	tdp_drain(t);
	assert_int_equal(px(t, 8, 8), 6);
}

/* A CALL in the ring runs its list before the ring's next command; a
 * FIFO command waiting meanwhile runs only once the list has returned. */
static void test_list_ring(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A, 0 }, r = { t, 0x300000u, 0 };
	uint32_t i;

	LST(&a, RDC_OP_SET_FG, 3);
	LST(&a, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(4, 1));
	LST0(&a, RDC_OP_RET);
	LST(&r, RDC_OP_CALL, LIST_A);
	LST(&r, RDC_OP_FILL_RECT, RDC_XY(2, 0), RDC_WH(4, 1));
	tdp_drain(t);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(&t->hw, RDC_REG_RING_BASE, 0x300000u);
	rdc_hw_write(&t->hw, RDC_REG_RING_SIZE, 256);
	rdc_hw_write(&t->hw, RDC_REG_RING_HEAD, 0);
	rdc_hw_write(&t->hw, RDC_REG_RING_TAIL, r.pos);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_RING_EN);
	/* run until the ring's CALL has entered the list */
	for (i = 0; i < 1000 && !t->dp.list_depth; i++)
		rdc_hw_run_until(&t->hw, t->hw.now + 1);
	assert_int_equal(t->dp.list_depth, 1);
	/* now a FIFO command arrives */
	TDP_CMD(t, RDC_OP_SET_FG, 4);
	for (i = 0; i < 10; i++)
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(t->dp.list_depth, 0);
	/* list first (FG 3), then the FIFO's SET_FG 4, then the ring */
	assert_int_equal(px(t, 0, 0), 3);
	assert_int_equal(px(t, 1, 0), 3);
	assert_int_equal(px(t, 2, 0), 4);
	assert_int_equal(px(t, 5, 0), 4);
}

/* ---- cycle counts ------------------------------------------------------ */

/*
 * CALL from the FIFO: its two words and the decode.  Each list command:
 * a 4-byte read of its header, one read span of its arguments, the
 * decode.  Here FENCE (one argument), NOP with 40 arguments (crossing a
 * burst), RET.
 */
static void test_list_cycles(void **state)
{
	struct tdp *t = *state;
	struct lst a = { t, LIST_A + 64, 0 };
	uint32_t open, i, pc = LIST_A + 64;
	uint64_t want, busy;

	LST(&a, RDC_OP_FENCE, 5);
	lst_word(&a, RDC_CMD(RDC_OP_NOP, 0, 40));
	for (i = 0; i < 40; i++)
		lst_word(&a, i);
	LST0(&a, RDC_OP_RET);
	tdp_drain(t);
	rdc_hw_write(&t->hw, RDC_REG_PERF_CTRL, RDC_PERF_CTRL_CLEAR);
	open = t->hw.bus.open_row;
	want = 2 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	want += tdp_bus_span(&open, pc, 4, TDP_BUS_READ) +
		tdp_bus_span(&open, pc + 4, 4, TDP_BUS_READ) + RDC_T_DECODE;
	pc += 8;
	want += tdp_bus_span(&open, pc, 4, TDP_BUS_READ) +
		tdp_bus_span(&open, pc + 4, 40 * 4, TDP_BUS_READ) +
		RDC_T_DECODE;
	pc += 4 + 40 * 4;
	want += tdp_bus_span(&open, pc, 4, TDP_BUS_READ) + RDC_T_DECODE;
	TDP_CMD(t, RDC_OP_CALL, LIST_A + 64);
	tdp_drain(t);
	busy = rdc_hw_read(&t->hw, RDC_REG_PERF_BUSY_LO);
	assert_int_equal(busy, want);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS), 4);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_FENCE), 5);
	/* by hand: the RET's header read opens no new row and costs a beat */
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 RDC_T_BEAT + RDC_T_DECODE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_list_equals_fifo), TDP_TEST(test_list_nested),
		TDP_TEST(test_list_depth),	 TDP_TEST(test_list_ret_top),
		TDP_TEST(test_list_bad),	 TDP_TEST(test_list_halt),
		TDP_TEST(test_list_jump_loop),	 TDP_TEST(test_list_ring),
		TDP_TEST(test_list_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
