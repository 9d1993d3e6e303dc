/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Shared scaffolding for the display-processor tests: a chip with the DP
 * attached, command pushing through the FIFO register port, a pixel model
 * written from rdc_regs.h's format description (not from the DP's code),
 * and a seeded xorshift32.  Header-only so no symbol leaks into the other
 * test programs.
 */
#ifndef TEST_DP_COMMON_H
#define TEST_DP_COMMON_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "hw.h"
#include "bus.h"
#include "dp.h"

#define TDP_VRAM_SIZE (4u << 20)
#define TDP_FRAME_CAP (1024u * 768u)
/* cycles of simulated time a test may run while waiting for the DP */
#define TDP_RUN_STEP  100000u
#define TDP_RUN_LIMIT 4000u

struct tdp {
	struct rdc_hw hw;
	struct rdc_dp dp;
	uint8_t *vram;
	uint32_t *frame[2];
};

/* A chip of TDP_VRAM_SIZE bytes clocked at core_hz (0: the default). */
static inline struct tdp *tdp_new_clocked(uint32_t core_hz)
{
	const struct rdc_hw_config cfg = { .vram_size = TDP_VRAM_SIZE,
					   .core_hz = core_hz };
	struct tdp *t = calloc(1, sizeof(*t));

	assert_non_null(t);
	t->vram = calloc(1, TDP_VRAM_SIZE);
	t->frame[0] = calloc(TDP_FRAME_CAP, 4);
	t->frame[1] = calloc(TDP_FRAME_CAP, 4);
	assert_non_null(t->vram);
	assert_non_null(t->frame[0]);
	assert_non_null(t->frame[1]);
	rdc_hw_init(&t->hw, &cfg, t->vram, t->frame[0], t->frame[1],
		    TDP_FRAME_CAP);
	rdc_dp_init(&t->dp, &t->hw);
	return t;
}

static inline struct tdp *tdp_new(void)
{
	struct tdp *t = tdp_new_clocked(0);

	/* No scanout: the DP owns the bus, so costs are the bare formulas. */
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	/* let a scanout fetch that was under way at power-on finish */
	rdc_hw_run_until(&t->hw, TDP_RUN_STEP);
	return t;
}

static inline void tdp_free(struct tdp *t)
{
	free(t->frame[1]);
	free(t->frame[0]);
	free(t->vram);
	free(t);
}

/* cmocka fixtures, so a failing test does not leak its chip */
static inline int tdp_setup(void **state)
{
	*state = tdp_new();
	return 0;
}

static inline int tdp_teardown(void **state)
{
	tdp_free(*state);
	return 0;
}

#define TDP_TEST(fn) \
	cmocka_unit_test_setup_teardown(fn, tdp_setup, tdp_teardown)

static inline int tdp_idle(struct tdp *t)
{
	uint32_t st = rdc_hw_read(&t->hw, RDC_REG_STATUS);

	return (st & RDC_STATUS_FIFO_EMPTY) && !(st & RDC_STATUS_IDLE_MASK);
}

/* Run until the FIFO is drained and the DP idle (or halted). */
static inline void tdp_drain(struct tdp *t)
{
	unsigned int i;

	for (i = 0; i < TDP_RUN_LIMIT; i++) {
		if (tdp_idle(t))
			return;
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
		if (rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED)
			return;
	}
	fail_msg("DP did not go idle");
}

/* Push one word, running the chip while the FIFO is full. */
static inline void tdp_push(struct tdp *t, uint32_t w)
{
	unsigned int i;

	for (i = 0; i < TDP_RUN_LIMIT; i++) {
		if (rdc_hw_read(&t->hw, RDC_REG_FIFO_FREE))
			break;
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	}
	rdc_hw_write(&t->hw, RDC_REG_FIFO_DATA, w);
}

static inline void tdp_cmd(struct tdp *t, uint32_t op, uint32_t flags,
			   unsigned int n, const uint32_t *args)
{
	unsigned int i;

	tdp_push(t, RDC_CMD(op, flags, n));
	for (i = 0; i < n; i++)
		tdp_push(t, args[i]);
}

#define TDP_CMD(t, op, ...) \
	do { \
		const uint32_t tdp_a_[] = { __VA_ARGS__ }; \
		tdp_cmd((t), (op), 0, RDC_ARRAY_SIZE(tdp_a_), tdp_a_); \
	} while (0)

static inline void tdp_set_surface(struct tdp *t, uint32_t op,
				   const struct rdc_surface *s)
{
	TDP_CMD(t, op, s->base, s->stride, RDC_WH(s->width, s->height),
		s->format);
}

static inline uint32_t tdp_err(struct tdp *t)
{
	return rdc_hw_read(&t->hw, RDC_REG_ERR_CODE);
}

static inline void tdp_clear_err(struct tdp *t)
{
	rdc_hw_write(&t->hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

/* ---- pixel model, straight from the format comment in rdc_regs.h ---- */

static inline uint32_t tdp_bpp(uint32_t fmt)
{
	static const uint32_t bpp[] = { 1, 2, 4, 8, 16, 24, 32 };

	return bpp[fmt];
}

static inline uint32_t tdp_mask(uint32_t fmt)
{
	return tdp_bpp(fmt) == 32 ? 0xffffffffu : (1u << tdp_bpp(fmt)) - 1;
}

static inline uint32_t tdp_get(const uint8_t *vram, const struct rdc_surface *s,
			       int32_t x, int32_t y)
{
	const uint8_t *row = vram + s->base + (size_t)y * s->stride;
	uint32_t bpp = tdp_bpp(s->format), v = 0, i;

	if (bpp < 8) {
		uint32_t per = 8 / bpp, byte = row[x / per];
		uint32_t slot = x % per; /* 0 = most significant bits */

		return (byte >> (8 - bpp * (slot + 1))) & tdp_mask(s->format);
	}
	for (i = 0; i < bpp / 8; i++)
		v |= (uint32_t)row[x * (bpp / 8) + i] << (8 * i);
	return v;
}

static inline void tdp_put(uint8_t *vram, const struct rdc_surface *s,
			   int32_t x, int32_t y, uint32_t v)
{
	uint8_t *row = vram + s->base + (size_t)y * s->stride;
	uint32_t bpp = tdp_bpp(s->format), i;

	v &= tdp_mask(s->format);
	if (bpp < 8) {
		uint32_t per = 8 / bpp, slot = x % per;
		uint32_t sh = 8 - bpp * (slot + 1);

		row[x / per] = (uint8_t)((row[x / per] &
					  ~(tdp_mask(s->format) << sh)) |
					 (v << sh));
		return;
	}
	for (i = 0; i < bpp / 8; i++)
		row[x * (bpp / 8) + i] = (uint8_t)(v >> (8 * i));
}

/* The ROP truth table of rdc_regs.h, bit by bit. */
static inline uint32_t tdp_rop(uint32_t rop, uint32_t s, uint32_t d)
{
	uint32_t r = 0, b;

	for (b = 0; b < 32; b++) {
		uint32_t sb = (s >> b) & 1, db = (d >> b) & 1;
		uint32_t n = ((!sb) << 1) | !db;

		r |= ((rop >> n) & 1u) << b;
	}
	return r;
}

static inline uint32_t tdp_rand(uint32_t *s)
{
	uint32_t x = *s;

	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	*s = x;
	return x;
}

/* Uniform-ish integer in [lo, hi]. */
static inline int32_t tdp_range(uint32_t *s, int32_t lo, int32_t hi)
{
	return lo + (int32_t)(tdp_rand(s) % (uint32_t)(hi - lo + 1));
}

static inline uint32_t tdp_fnv(uint32_t h, const void *p, size_t n)
{
	const uint8_t *b = p;
	size_t i;

	for (i = 0; i < n; i++)
		h = (h ^ b[i]) * 16777619u;
	return h;
}

/*
 * The VRAM bus cost of one span: hw-sim/bus.h's formula transcribed beat
 * by beat, independently of bus.h's own code, the one model the cycle
 * tests hold the chip against.  Bytes [a, a + n) go in bursts at
 * multiples of RDC_BUS_BURST_BEATS * RDC_BUS_BYTES; a burst costs beats *
 * T_BEAT + misses * T_ROW_MISS (*open is the open DRAM row, updated),
 * plus T_TURN + rmw_beats * T_BEAT when any of its beats is
 * read-modify-written: every beat of an RMW span; of a write, its first
 * and last beat when partly written (not aligned to the bus, or
 * head_partial / tail_partial: sub-byte pixels at the edges).
 */
enum { TDP_BUS_READ, TDP_BUS_WRITE, TDP_BUS_RMW };

static inline uint64_t tdp_bus_edges(uint32_t *open, uint64_t a, uint64_t n,
				     int kind, int head_partial,
				     int tail_partial)
{
	const uint64_t burst = RDC_BUS_BURST_BEATS * RDC_BUS_BYTES;
	uint64_t end = a + n, first_beat = a / RDC_BUS_BYTES;
	uint64_t last_beat = (end - 1) / RDC_BUS_BYTES, cost = 0;
	int head = head_partial || a % RDC_BUS_BYTES;
	int tail = tail_partial || end % RDC_BUS_BYTES;

	while (a < end) {
		uint64_t be = (a / burst + 1) * burst, b, rmw = 0, beats = 0;

		if (be > end)
			be = end;
		for (b = a / RDC_BUS_BYTES; b <= (be - 1) / RDC_BUS_BYTES;
		     b++) {
			uint32_t row = (uint32_t)(b * RDC_BUS_BYTES /
						  RDC_DRAM_ROW_BYTES);

			beats++;
			if (row != *open) {
				cost += RDC_T_ROW_MISS;
				*open = row;
			}
			if (kind == TDP_BUS_RMW ||
			    (kind == TDP_BUS_WRITE &&
			     ((b == first_beat && head) ||
			      (b == last_beat && tail))))
				rmw++;
		}
		cost += beats * RDC_T_BEAT;
		if (rmw)
			cost += RDC_T_TURN + rmw * RDC_T_BEAT;
		a = be;
	}
	return cost;
}

/* tdp_bus_edges with the edges partial only where they are not aligned. */
static inline uint64_t tdp_bus_span(uint32_t *open, uint64_t a, uint64_t n,
				    int kind)
{
	return tdp_bus_edges(open, a, n, kind, 0, 0);
}

#endif /* TEST_DP_COMMON_H */
