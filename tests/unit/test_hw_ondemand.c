// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Scanout on demand (rdc_hw_set_on_demand): chips given the same drawing,
 * host writes, CLUT, cursor, gamma and backlight changes at the same
 * simulated times, one converting every frame (on demand off), one with a
 * consumer from the start, one that nobody watches until a consumer
 * attaches mid-stream.  Every frame a listener or rdc_hw_frame shows must
 * be bit-identical to the first chip's frame of the same number, the
 * chips must agree on every cycle (the bus is charged the same whether
 * frames are converted or not), and once a consumer attaches no frame
 * may go missing but the one being scanned then.  The write barrier is
 * checked on its own: a change to what a fetched but unconverted line
 * shows must never reach a frame that somebody then looks at.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "dp.h"
#include "hw.h"
#include "test_dp_common.h"

#define SCR_W	   320u
#define SCR_H	   200u
#define STRIDE	   (SCR_W * 4)
#define CURSOR_AT  (1u << 20) /* the ARGB8888 cursor image */
#define RASTER_AT  (2u << 20) /* the raster list, RL_ENTRIES long */
#define RL_ENTRIES 24u
#define MAX_FRAMES 64u
#define CHIPS	   3u

enum { EAGER, WATCHED, LATE };

struct od_chip {
	struct tdp *t;
	uint32_t crc[MAX_FRAMES];
	bool seen[MAX_FRAMES];
	uint32_t frames;
};

struct od {
	struct od_chip c[CHIPS];
	uint32_t seed;
};

static uint32_t frame_crc(const uint32_t *px, uint32_t w, uint32_t h)
{
	return tdp_fnv(2166136261u, px, (size_t)w * h * 4);
}

static void on_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t number)
{
	struct od_chip *c = ctx;

	assert_int_equal(w, SCR_W);
	assert_int_equal(h, SCR_H);
	c->frames++;
	if (number >= MAX_FRAMES)
		return;
	c->crc[number] = frame_crc(xrgb, w, h);
	c->seen[number] = true;
}

/* 320x200 XRGB8888 at 0, scanout and the DP on, an ARGB8888 cursor. */
static struct tdp *od_chip_new(void)
{
	struct tdp *t = tdp_new();
	struct rdc_hw *hw = &t->hw;
	uint32_t i;

	for (i = 0; i < SCR_W * SCR_H; i++)
		((uint32_t *)t->vram)[i] = i * 0x010203u;
	for (i = 0; i < 32 * 32; i++)
		((uint32_t *)(t->vram + CURSOR_AT))[i] = i & 1 ? 0x80402010u :
								 0xff00ff00u;
	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_320x200_70);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_XRGB8888);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, STRIDE);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CURSOR_AT);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL,
		     FIELD_PREP(RDC_CURSOR_CTRL_FMT, RDC_CURSOR_FMT_ARGB8888));
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(20, 30));
	/* a list that moves the base every 16 lines (random_step runs it) */
	for (i = 0; i + 1 < RL_ENTRIES; i += 2) {
		uint32_t *e = (uint32_t *)(t->vram + RASTER_AT + 8 * i);

		e[0] = FIELD_PREP(RDC_RL_OP, RDC_RL_WAIT);
		e[1] = FIELD_PREP(RDC_RL_Y, 8 * i);
		e[2] = FIELD_PREP(RDC_RL_OP, RDC_RL_REG) | RDC_REG_FB_BASE;
		e[3] = i % 3 * STRIDE * 2;
	}
	rdc_hw_write(hw, RDC_REG_RASTER_BASE, RASTER_AT); /* off: random_step */
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN |
			     RDC_CONTROL_CURSOR_EN);
	return t;
}

static int od_setup(void **state)
{
	struct od *o = calloc(1, sizeof(*o));
	uint32_t i;

	assert_non_null(o);
	for (i = 0; i < CHIPS; i++)
		o->c[i].t = od_chip_new();
	o->seed = 0x6f6e6465u;
	*state = o;
	return 0;
}

static int od_teardown(void **state)
{
	struct od *o = *state;
	uint32_t i;

	for (i = 0; i < CHIPS; i++)
		tdp_free(o->c[i].t);
	free(o);
	return 0;
}

static void all_run(struct od *o, uint64_t t)
{
	for (uint32_t i = 0; i < CHIPS; i++)
		rdc_hw_run_until(&o->c[i].t->hw, t);
}

static void all_write(struct od *o, uint32_t reg, uint32_t val)
{
	for (uint32_t i = 0; i < CHIPS; i++)
		rdc_hw_write(&o->c[i].t->hw, reg, val);
}

/* Commands straight into the FIFO, drawn while the beam runs. */
static void all_cmd(struct od *o, uint32_t op, unsigned int n,
		    const uint32_t *a)
{
	for (uint32_t i = 0; i < CHIPS; i++) {
		struct rdc_hw *hw = &o->c[i].t->hw;

		if (rdc_hw_read(hw, RDC_REG_FIFO_FREE) < n + 1)
			return; /* the same on every chip: they agree */
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, RDC_CMD(op, 0, n));
		for (unsigned int k = 0; k < n; k++)
			rdc_hw_write(hw, RDC_REG_FIFO_DATA, a[k]);
	}
}

/* Everything observable but the frames agrees on every chip. */
static void assert_same_bus(struct od *o)
{
	struct rdc_hw *a = &o->c[EAGER].t->hw;

	for (uint32_t i = 1; i < CHIPS; i++) {
		struct rdc_hw *b = &o->c[i].t->hw;

		assert_int_equal(a->now, b->now);
		assert_int_equal(a->perf.stall, b->perf.stall);
		assert_int_equal(a->perf.busy, b->perf.busy);
		assert_int_equal(a->crtc.fetch_end, b->crtc.fetch_end);
		assert_int_equal(a->bus.open_row, b->bus.open_row);
		assert_int_equal(rdc_hw_read(a, RDC_REG_FRAME_COUNT),
				 rdc_hw_read(b, RDC_REG_FRAME_COUNT));
		assert_memory_equal(o->c[EAGER].t->vram, o->c[i].t->vram,
				    TDP_VRAM_SIZE);
	}
}

/*
 * A look at chip i: what rdc_hw_frame gives, if anything, is the eager
 * chip's last frame.  Returns whether there was a frame.
 */
static bool look_same(struct od *o, unsigned int i)
{
	uint32_t wa, ha, wb, hb;
	const uint32_t *fa = rdc_hw_frame(&o->c[EAGER].t->hw, &wa, &ha);
	const uint32_t *fb = rdc_hw_frame(&o->c[i].t->hw, &wb, &hb);

	if (!fb)
		return false;
	assert_non_null(fa);
	assert_int_equal(wa, wb);
	assert_int_equal(ha, hb);
	assert_memory_equal(fa, fb, (size_t)wa * ha * 4);
	return true;
}

/*
 * Raster-list entry k, random, on every chip: a WAIT, a CLUT entry (seen
 * through gamma), the base or stride of the lines after it, the cursor;
 * the list's last entry stays END.
 */
static void raster_entry(struct od *o, uint32_t k)
{
	uint32_t e[2], i, op = tdp_range(&o->seed, 0, 5);

	e[1] = tdp_rand(&o->seed);
	switch (op) {
	case 0:
	case 1:
		e[0] = FIELD_PREP(RDC_RL_OP, RDC_RL_WAIT);
		e[1] = FIELD_PREP(RDC_RL_Y,
				  tdp_range(&o->seed, 0, SCR_H + 30)) |
		       FIELD_PREP(RDC_RL_X, tdp_range(&o->seed, 0, 2));
		break;
	case 2:
		e[0] = FIELD_PREP(RDC_RL_OP, RDC_RL_CLUT) |
		       FIELD_PREP(RDC_RL_ARG, e[1] >> 24);
		break;
	case 3:
		e[0] = FIELD_PREP(RDC_RL_OP, RDC_RL_REG) | RDC_REG_FB_BASE;
		e[1] = (uint32_t)tdp_range(&o->seed, 0, SCR_H) * STRIDE;
		break;
	case 4:
		e[0] = FIELD_PREP(RDC_RL_OP, RDC_RL_REG) | RDC_REG_FB_STRIDE;
		e[1] = e[1] & 1 ? STRIDE : 2 * STRIDE;
		break;
	default:
		e[0] = FIELD_PREP(RDC_RL_OP, RDC_RL_REG) |
		       (e[1] & 1 ? RDC_REG_CURSOR_POS : RDC_REG_CURSOR_FG);
		break;
	}
	for (i = 0; i < CHIPS; i++)
		assert_int_equal(rdc_hw_vram_write(&o->c[i].t->hw,
						   RASTER_AT + 8 * k, e, 8),
				 0);
}

/* One random change, the same on every chip, then some simulated time. */
static void random_step(struct od *o)
{
	uint32_t r = tdp_rand(&o->seed), i, v, a[2];
	uint64_t frame = o->c[EAGER].t->hw.crtc.frame_cycles;

	switch (r % 32) {
	case 0:
	case 1:
	case 2: /* a filled rectangle, on screen or off */
		a[0] = RDC_XY(tdp_range(&o->seed, -20, SCR_W),
			      tdp_range(&o->seed, -20, SCR_H * 2));
		a[1] = RDC_WH(tdp_range(&o->seed, 1, 120),
			      tdp_range(&o->seed, 1, 80));
		v = tdp_rand(&o->seed);
		all_cmd(o, RDC_OP_SET_FG, 1, &v);
		all_cmd(o, RDC_OP_FILL_RECT, 2, a);
		break;
	case 3:
	case 4: /* lines */
		v = tdp_rand(&o->seed);
		all_cmd(o, RDC_OP_SET_FG, 1, &v);
		for (i = 0; i < 8; i++) {
			a[0] = RDC_XY(tdp_range(&o->seed, 0, SCR_W - 1),
				      tdp_range(&o->seed, 0, SCR_H - 1));
			a[1] = RDC_XY(tdp_range(&o->seed, 0, SCR_W - 1),
				      tdp_range(&o->seed, 0, SCR_H - 1));
			all_cmd(o, RDC_OP_LINE, 2, a);
		}
		break;
	case 5: /* the host through the aperture */
		v = tdp_rand(&o->seed);
		a[0] = (uint32_t)tdp_range(&o->seed, 0, SCR_H * 2) * STRIDE +
		       (uint32_t)tdp_range(&o->seed, 0, SCR_W - 1) * 4;
		for (i = 0; i < CHIPS; i++)
			assert_int_equal(rdc_hw_vram_write(&o->c[i].t->hw, a[0],
							   &v, 4),
					 0);
		break;
	case 6: /* the cursor's image */
		v = tdp_rand(&o->seed);
		a[0] = CURSOR_AT + (uint32_t)tdp_range(&o->seed, 0, 1023) * 4;
		for (i = 0; i < CHIPS; i++)
			rdc_hw_vram_write(&o->c[i].t->hw, a[0], &v, 4);
		break;
	case 7:
		all_write(o, RDC_REG_CURSOR_POS,
			  RDC_XY(tdp_range(&o->seed, -40, SCR_W),
				 tdp_range(&o->seed, -40, SCR_H)));
		break;
	case 8: /* a CLUT entry, seen through gamma */
		all_write(o, RDC_REG_CLUT_INDEX, tdp_rand(&o->seed) & 0xff);
		all_write(o, RDC_REG_CLUT_DATA, tdp_rand(&o->seed));
		break;
	case 9:
		v = o->c[EAGER].t->hw.control ^
		    (r & 0x100 ? RDC_CONTROL_GAMMA_EN : RDC_CONTROL_CURSOR_EN);
		all_write(o, RDC_REG_CONTROL, v);
		break;
	case 10:
		v = o->c[EAGER].t->hw.pins_in ^ RDC_PIN_BL_EN;
		for (i = 0; i < CHIPS; i++)
			rdc_hw_set_pins(&o->c[i].t->hw, v);
		break;
	case 11: /* a 2 bpp cursor, its image latched at vblank */
		all_write(o, RDC_REG_CURSOR_CTRL,
			  FIELD_PREP(RDC_CURSOR_CTRL_FMT,
				     r & 0x100 ? RDC_CURSOR_FMT_2BPP :
						 RDC_CURSOR_FMT_ARGB8888));
		break;
	case 12:
	case 13:
	case 14: /* a raster list entry rewritten, racing the beam */
		raster_entry(o, tdp_range(&o->seed, 0, RL_ENTRIES - 2));
		break;
	case 15: /* the raster list on or off */
		all_write(o, RDC_REG_RASTER_BASE, RASTER_AT);
		all_write(o, RDC_REG_RASTER_CTRL,
			  r & 0x300 ? RDC_RASTER_CTRL_EN : 0);
		break;
	default: /* nothing: frames that wait and are looked at later */
		break;
	}
	all_run(o, o->c[EAGER].t->hw.now + tdp_rand(&o->seed) % (frame / 2));
}

/*
 * The run: LATE attaches a consumer (and a listener) at frame `attach`;
 * every frame the listeners were handed matches the eager chip's.
 */
static void run_attach(struct od *o, uint32_t attach, uint32_t frames)
{
	struct rdc_hw *e = &o->c[EAGER].t->hw, *w = &o->c[WATCHED].t->hw;
	struct rdc_hw *l = &o->c[LATE].t->hw;
	uint32_t looks = 0, i, n, first = 0;
	bool attached = false;

	rdc_hw_set_frame_fn(e, on_frame, &o->c[EAGER]);
	rdc_hw_set_on_demand(w, true);
	rdc_hw_set_frame_fn(w, on_frame, &o->c[WATCHED]);
	rdc_hw_set_on_demand(l, true);
	while ((n = rdc_hw_read(e, RDC_REG_FRAME_COUNT)) < frames) {
		if (!attached && n >= attach) {
			rdc_hw_consumer_attach(l);
			rdc_hw_set_frame_fn(l, on_frame, &o->c[LATE]);
			attached = true;
			first = n;
		}
		random_step(o);
		assert_same_bus(o);
		if (!attached && tdp_rand(&o->seed) % 4 == 0)
			looks += look_same(o, LATE);
		if (tdp_rand(&o->seed) % 4 == 0)
			look_same(o, WATCHED);
	}
	assert_true(attached);
	assert_true(o->c[LATE].frames + 1 >= frames - first);
	for (i = 0; i < frames; i++) {
		assert_true(o->c[EAGER].seen[i]);
		assert_true(o->c[WATCHED].seen[i]);
		assert_int_equal(o->c[WATCHED].crc[i], o->c[EAGER].crc[i]);
		if (i > first)
			assert_true(o->c[LATE].seen[i]);
		if (o->c[LATE].seen[i])
			assert_int_equal(o->c[LATE].crc[i], o->c[EAGER].crc[i]);
	}
	assert_true(o->c[LATE].frames > 0);
	/* looks at waiting frames happened, and some found one */
	if (attach > 4)
		assert_true(looks > 0);
}

static void test_attach_mid_stream(void **state)
{
	run_attach(*state, 12, 40);
}

static void test_attach_at_once(void **state)
{
	run_attach(*state, 0, 10);
}

/* Detached again, then attached: the frames after still match. */
static void test_detach_attach(void **state)
{
	struct od *o = *state;
	struct rdc_hw *l = &o->c[LATE].t->hw;
	uint32_t n;

	rdc_hw_set_on_demand(l, true);
	rdc_hw_consumer_attach(l);
	rdc_hw_consumer_attach(l);
	rdc_hw_consumer_detach(l);
	assert_false(l->lazy);
	rdc_hw_consumer_detach(l);
	assert_true(l->lazy);
	rdc_hw_set_frame_fn(&o->c[EAGER].t->hw, on_frame, &o->c[EAGER]);
	for (n = 0; n < 30;) {
		random_step(o);
		assert_same_bus(o);
		n = rdc_hw_read(&o->c[EAGER].t->hw, RDC_REG_FRAME_COUNT);
		if (n % 10 == 5 && !o->c[LATE].frames)
			rdc_hw_set_frame_fn(l, on_frame, &o->c[LATE]);
		if (n % 10 == 9) {
			rdc_hw_set_frame_fn(l, NULL, NULL);
			o->c[LATE].frames = 0;
		}
		look_same(o, LATE);
	}
	for (n = 0; n < 30; n++)
		if (o->c[LATE].seen[n])
			assert_int_equal(o->c[LATE].crc[n], o->c[EAGER].crc[n]);
}

/*
 * Nothing changes: the frame nobody converted is there when looked at,
 * as the eager chip's; and no line was converted before the look.
 */
static void test_idle_frame_waits(void **state)
{
	struct od *o = *state;
	struct rdc_hw *l = &o->c[LATE].t->hw;
	uint32_t *px = o->c[LATE].t->frame[0];

	rdc_hw_set_on_demand(l, true);
	memset(o->c[LATE].t->frame[0], 0x5a, SCR_W * SCR_H * 4);
	memset(o->c[LATE].t->frame[1], 0x5a, SCR_W * SCR_H * 4);
	all_run(o, l->now + 3 * l->crtc.frame_cycles);
	assert_int_equal(px[0], 0x5a5a5a5au);
	assert_int_equal(o->c[LATE].t->frame[1][0], 0x5a5a5a5au);
	assert_true(look_same(o, LATE));
	/* the back frame, half fetched, converts when a consumer attaches */
	all_run(o, rdc_port_next_line(l, SCR_H / 2));
	rdc_hw_consumer_attach(l);
	all_run(o, rdc_port_next_vblank(l) + 1);
	assert_true(look_same(o, LATE));
}

/*
 * A change that would alter a fetched line nobody converted: each kind,
 * at a moment when the front frame and half the back one wait.  What a
 * look then gives, if anything, is the frame as it was scanned.
 */
static void barrier_case(struct od *o, unsigned int kind)
{
	struct rdc_hw *l = &o->c[LATE].t->hw;
	uint32_t v = 0x00abcdefu, i;

	rdc_hw_set_on_demand(l, true);
	all_write(o, RDC_REG_CONTROL,
		  o->c[EAGER].t->hw.control | RDC_CONTROL_GAMMA_EN);
	all_run(o, l->now + 2 * l->crtc.frame_cycles);
	all_run(o, rdc_port_next_line(l, SCR_H / 2));
	switch (kind) {
	case 0: /* host VRAM: line 40, fetched in both frames */
		for (i = 0; i < CHIPS; i++)
			rdc_hw_vram_write(&o->c[i].t->hw, 40 * STRIDE + 40, &v,
					  4);
		break;
	case 1: /* the DP: a fill over line 10 */
		v = RDC_XY(0, 10);
		all_cmd(o, RDC_OP_FILL_RECT, 2,
			(const uint32_t[]){ v, RDC_WH(SCR_W, 1) });
		all_run(o, l->now + 200000);
		break;
	case 2: /* the CLUT, through gamma */
		all_write(o, RDC_REG_CLUT_INDEX, 0x10);
		all_write(o, RDC_REG_CLUT_DATA, v);
		break;
	case 3:
		all_write(o, RDC_REG_CURSOR_POS, RDC_XY(100, 20));
		break;
	case 4: /* the ARGB8888 cursor's image */
		for (i = 0; i < CHIPS; i++)
			rdc_hw_vram_write(&o->c[i].t->hw, CURSOR_AT + 8, &v, 4);
		break;
	case 5:
		for (i = 0; i < CHIPS; i++)
			rdc_hw_set_pins(&o->c[i].t->hw, RDC_PIN_RESET_N);
		break;
	case 6:
		all_write(o, RDC_REG_CONTROL,
			  o->c[EAGER].t->hw.control & ~RDC_CONTROL_CURSOR_EN);
		break;
	case 7: /* behind the chip's back, reported */
		for (i = 0; i < CHIPS; i++) {
			memcpy(o->c[i].t->vram + 5 * STRIDE, &v, 4);
			rdc_hw_vram_touched(&o->c[i].t->hw, 5 * STRIDE, 4);
		}
		break;
	case 8: /* latched at the vblank that ends the waiting frame */
		all_write(o, RDC_REG_CONTROL,
			  o->c[EAGER].t->hw.control & ~RDC_CONTROL_GAMMA_EN);
		all_run(o, rdc_port_next_vblank(l) + 1);
		break;
	case 9: /* a page flip */
		all_write(o, RDC_REG_FB_BASE, STRIDE);
		all_run(o, rdc_port_next_vblank(l) + 1);
		break;
	case 10:
		all_write(o, RDC_REG_CURSOR_CTRL,
			  FIELD_PREP(RDC_CURSOR_CTRL_FMT, RDC_CURSOR_FMT_2BPP));
		all_run(o, rdc_port_next_vblank(l) + 1);
		break;
	default:
		break;
	}
	assert_same_bus(o);
	look_same(o, LATE);
	/* and the back frame, completed: converted on attach if it was kept */
	rdc_hw_consumer_attach(l);
	all_run(o, rdc_port_next_vblank(l) + 1);
	look_same(o, LATE);
	all_run(o, rdc_port_next_vblank(l) + 1);
	assert_true(look_same(o, LATE));
}

static void test_barrier(void **state)
{
	for (unsigned int k = 0; k < 11; k++) {
		od_teardown(state);
		od_setup(state);
		barrier_case(*state, k);
	}
}

/* A write elsewhere in VRAM keeps the waiting frame. */
static void test_barrier_elsewhere(void **state)
{
	struct od *o = *state;
	struct rdc_hw *l = &o->c[LATE].t->hw;
	uint32_t v = 0x00abcdefu, i;

	rdc_hw_set_on_demand(l, true);
	all_run(o, l->now + 2 * l->crtc.frame_cycles);
	for (i = 0; i < CHIPS; i++)
		rdc_hw_vram_write(&o->c[i].t->hw, 3u << 20, &v, 4);
	assert_true(look_same(o, LATE));
}

/*
 * Rows a whole number of DRAM rows apart (RT_STRIDE) are charged in
 * closed form, and on a chip nobody watches, on through the line starts
 * that only fetch (rdc_port_window_rows_through, _pairs_through): the
 * rows are written after the charge, as nothing reads them at such a
 * line start.  Filled rectangles, copies, glyphs, circles and polygons
 * (queued runs, rdc_port_window_runs) on two chips, one converting each line at its
 * fetch, one on demand with no consumer, must agree on every cycle, the
 * row left open, every byte and every frame looked at.  At a core clock
 * of 40 MHz a line's fetch leaves the DP about 300 cycles of a line, so a
 * row takes up to two line starts; where the second is one the window
 * does not take (the line-compare line, the vblank's, a raster list's
 * WAIT), the row stops between them and rdc_port_window_cross goes on
 * with its rest.
 */
#define RT_W	  1024u
#define RT_H	  768u
#define RT_STRIDE 4096u
#define RT_LIST	  (3u << 20) /* the raster list, past the surface */

static void rt_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t number)
{
	(void)ctx;
	(void)xrgb;
	(void)w;
	(void)h;
	(void)number;
}

static struct tdp *rt_chip_new(uint32_t core_hz, bool lazy, bool waits)
{
	const struct rdc_surface dst = { .base = 0,
					 .stride = RT_STRIDE,
					 .width = RT_W,
					 .height = RT_H,
					 .format = RDC_FMT_XRGB8888 };
	struct tdp *t = tdp_new_clocked(core_hz);
	struct rdc_hw *hw = &t->hw;

	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_1024x768_60);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_XRGB8888);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, RT_STRIDE);
	rdc_hw_write(hw, RDC_REG_LINE_COMPARE, RT_H / 3);
	if (waits) {
		/* a raster list that waits for every fifth line, nothing more */
		uint32_t *e = (uint32_t *)(t->vram + RT_LIST);
		uint32_t i;

		for (i = 0; i < RT_H / 5; i++) {
			e[2 * i] = FIELD_PREP(RDC_RL_OP, RDC_RL_WAIT);
			e[2 * i + 1] = FIELD_PREP(RDC_RL_Y, 5 * i + 3);
		}
		e[2 * i] = FIELD_PREP(RDC_RL_OP, RDC_RL_END);
		rdc_hw_write(hw, RDC_REG_RASTER_BASE, RT_LIST);
		rdc_hw_write(hw, RDC_REG_RASTER_CTRL, RDC_RASTER_CTRL_EN);
	}
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	if (lazy)
		rdc_hw_set_on_demand(hw, true);
	else
		rdc_hw_set_frame_fn(hw, rt_frame, NULL);
	assert_int_equal(hw->lazy, lazy);
	tdp_set_surface(t, RDC_OP_SET_DST, &dst);
	tdp_set_surface(t, RDC_OP_SET_SRC, &dst);
	tdp_drain(t);
	return t;
}

static void rt_same(struct tdp *e, struct tdp *l, bool all)
{
	assert_int_equal(e->hw.now, l->hw.now);
	assert_int_equal(e->hw.perf.stall, l->hw.perf.stall);
	assert_int_equal(e->hw.perf.busy, l->hw.perf.busy);
	assert_int_equal(e->hw.perf.pixels, l->hw.perf.pixels);
	assert_int_equal(e->hw.crtc.fetch_end, l->hw.crtc.fetch_end);
	assert_int_equal(e->hw.bus.open_row, l->hw.bus.open_row);
	if (all)
		assert_memory_equal(e->vram, l->vram, TDP_VRAM_SIZE);
}

/* the two chips, freed by the teardown if a check fails */
static int rt_teardown(void **state)
{
	struct tdp **c = *state;

	if (c) {
		if (c[0])
			tdp_free(c[0]);
		if (c[1])
			tdp_free(c[1]);
		free(c);
	}
	return 0;
}

static void rt_run(void **state, uint32_t core_hz, bool waits, uint32_t seed)
{
	struct tdp **c;
	uint32_t i, k, a[2 + 2 + 4], wa, ha, wb, hb, looks = 0;
	const uint32_t *fa, *fb;
	uint64_t idle;

	rt_teardown(state);
	c = calloc(2, sizeof(*c));
	assert_non_null(c);
	*state = c;
	c[0] = rt_chip_new(core_hz, false, waits);
	c[1] = rt_chip_new(core_hz, true, waits);
	for (i = 0; i < 120; i++) {
		uint32_t r = tdp_rand(&seed);

		if (r % 4 == 0) { /* a glyph with its colours */
			a[0] = RDC_XY(tdp_range(&seed, -4, RT_W),
				      tdp_range(&seed, -8, RT_H));
			a[1] = RDC_WH(8, 16);
			for (k = 2; k < RDC_ARRAY_SIZE(a); k++)
				a[k] = tdp_rand(&seed);
			for (k = 0; k < 2; k++)
				tdp_cmd(c[k], RDC_OP_MONO, RDC_MONO_COLORS,
					RDC_ARRAY_SIZE(a), a);
		} else if (r % 4 == 3) { /* a copy, up or down, or xor */
			a[0] = r & 0x30 ? RDC_ROP_COPY : RDC_ROP_XOR;
			a[1] = RDC_XY(tdp_range(&seed, 0, RT_W - 1),
				      tdp_range(&seed, 0, RT_H - 1));
			a[2] = RDC_XY(tdp_range(&seed, 0, RT_W - 1),
				      tdp_range(&seed, 0, RT_H - 1));
			a[3] = RDC_WH(tdp_range(&seed, 1, RT_W),
				      tdp_range(&seed, 1, r % 5 ? 200 : RT_H));
			for (k = 0; k < 2; k++) {
				tdp_cmd(c[k], RDC_OP_SET_ROP, 0, 1, a);
				tdp_cmd(c[k], RDC_OP_BLIT, 0, 3, a + 1);
				TDP_CMD(c[k], RDC_OP_SET_ROP, RDC_ROP_COPY);
			}
		} else if (r % 3 == 0) { /* queued runs: circles, polygons */
			static const uint32_t ops[] = { RDC_OP_CIRCLE,
							RDC_OP_FILL_CIRCLE,
							RDC_OP_FILL_POLYGON };
			uint32_t op = ops[(r >> 8) % 3], n = 2;

			a[0] = tdp_rand(&seed);
			for (k = 1; k < 5; k++)
				a[k] = RDC_XY(tdp_range(&seed, -40, RT_W + 40),
					      tdp_range(&seed, -40, RT_H + 40));
			if (op == RDC_OP_FILL_POLYGON)
				n = 4;
			else
				a[2] = tdp_range(&seed, 1, 400);
			for (k = 0; k < 2; k++) {
				tdp_cmd(c[k], RDC_OP_SET_FG, 0, 1, a);
				tdp_cmd(c[k], op, 0, n, a + 1);
			}
		} else { /* a filled rectangle, up to the whole surface */
			a[0] = tdp_rand(&seed);
			a[1] = RDC_XY(tdp_range(&seed, -20, RT_W),
				      tdp_range(&seed, -20, RT_H));
			a[2] = RDC_WH(tdp_range(&seed, 1, r % 3 ? 300 : RT_W),
				      tdp_range(&seed, 1, r % 5 ? 200 : RT_H));
			for (k = 0; k < 2; k++) {
				tdp_cmd(c[k], RDC_OP_SET_FG, 0, 1, a);
				tdp_cmd(c[k], RDC_OP_FILL_RECT, 0, 2, a + 1);
			}
		}
		idle = c[0]->hw.now + tdp_rand(&seed) % 400000;
		for (k = 0; k < 2; k++) {
			tdp_drain(c[k]);
			rdc_hw_run_until(&c[k]->hw, idle);
		}
		rt_same(c[0], c[1], i % 16 == 15);
		if (r % 4 == 1) {
			/* a frame scanned with nothing drawn: kept */
			for (k = 0; k < 2; k++) {
				rdc_hw_run_until(
					&c[k]->hw,
					rdc_port_next_vblank(&c[k]->hw) + 1);
				rdc_hw_run_until(
					&c[k]->hw,
					rdc_port_next_vblank(&c[k]->hw) + 1);
			}
		} else if (r % 4 != 2) {
			continue;
		}
		/* a look: the lazy chip's frame, if kept, is the eager one's */
		fa = rdc_hw_frame(&c[0]->hw, &wa, &ha);
		fb = rdc_hw_frame(&c[1]->hw, &wb, &hb);
		if (r % 4 == 1)
			assert_non_null(fb);
		if (!fb)
			continue;
		assert_non_null(fa);
		assert_int_equal(wa, wb);
		assert_int_equal(ha, hb);
		assert_memory_equal(fa, fb, (size_t)wa * ha * 4);
		looks++;
	}
	/*
	 * Rows drawn, copied or filled as queued runs just ahead of the
	 * beam, which fetches them during the command: no write reaches a
	 * fetched line, so the frame is kept, and it shows the rows the beam
	 * found written.  Then the same behind the beam, over lines it has
	 * fetched: the write barrier drops the frame nobody has converted.
	 */
	for (i = 0; i < 12; i++) {
		/* behind: a few rows, that may end before the next line start */
		bool behind = i >= 6;
		uint32_t y = behind ? 40 + 80 * (i - 6) : 40 + 110 * i;
		uint32_t op = RDC_OP_FILL_RECT, n = 2, h = behind ? 6 : 160;
		const uint32_t *px = (const uint32_t *)c[0]->vram;

		a[0] = 0xff000000u | tdp_rand(&seed);
		a[1] = RDC_XY(0, y + 2);
		a[2] = RDC_WH(RT_W / 4, h);
		if (i % 3 == 1) { /* from the same rows, further right */
			op = RDC_OP_BLIT;
			n = 3;
			a[1] = RDC_XY(RT_W / 2, y + 2);
			a[2] = RDC_XY(0, y + 2);
			a[3] = RDC_WH(RT_W / 8, h);
		} else if (i % 3 == 2) { /* the same rectangle, as runs */
			op = RDC_OP_FILL_POLYGON;
			n = 4;
			a[2] = RDC_XY(RT_W / 4, y + 2);
			a[3] = RDC_XY(RT_W / 4, y + 2 + h);
			a[4] = RDC_XY(0, y + 2 + h);
		}
		for (k = 0; k < 2; k++) {
			rdc_hw_run_until(&c[k]->hw,
					 rdc_port_next_vblank(&c[k]->hw) + 1);
			tdp_cmd(c[k], RDC_OP_SET_FG, 0, 1, a);
			/* behind: after the line's fetch, in the DP's window */
			rdc_hw_run_until(
				&c[k]->hw,
				behind ?
					rdc_port_next_line(&c[k]->hw, y + 200) +
						600 :
					rdc_port_next_line(&c[k]->hw, y));
			tdp_cmd(c[k], op, 0, n, a + 1);
			tdp_drain(c[k]);
			rdc_hw_run_until(&c[k]->hw,
					 rdc_port_next_vblank(&c[k]->hw) + 1);
		}
		rt_same(c[0], c[1], false);
		fa = rdc_hw_frame(&c[0]->hw, &wa, &ha);
		fb = rdc_hw_frame(&c[1]->hw, &wb, &hb);
		assert_non_null(fa);
		if (behind) {
			assert_null(fb);
			continue;
		}
		assert_non_null(fb);
		assert_memory_equal(fa, fb, (size_t)wa * ha * 4);
		assert_int_equal(fa[(y + 100) * RT_W + 7],
				 px[(y + 100) * (RT_STRIDE / 4) + 7] &
					 0xffffffu);
	}
	rt_same(c[0], c[1], true);
	assert_true(looks > 0);
}

static void test_rows_through_line_starts(void **state)
{
	rt_run(state, 0, false, 0x726f7773u); /* the default 100 MHz */
	/* rows that outlast lines; line starts the window does not take */
	rt_run(state, 40000000u, false, 0x74687275u);
	rt_run(state, 40000000u, true, 0x77616974u);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_attach_mid_stream,
						od_setup, od_teardown),
		cmocka_unit_test_setup_teardown(test_attach_at_once, od_setup,
						od_teardown),
		cmocka_unit_test_setup_teardown(test_detach_attach, od_setup,
						od_teardown),
		cmocka_unit_test_setup_teardown(test_idle_frame_waits, od_setup,
						od_teardown),
		cmocka_unit_test_setup_teardown(test_barrier, od_setup,
						od_teardown),
		cmocka_unit_test_setup_teardown(test_barrier_elsewhere,
						od_setup, od_teardown),
		cmocka_unit_test_teardown(test_rows_through_line_starts,
					  rt_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
