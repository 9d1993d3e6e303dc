// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The chip's signal trace points (RDC_TRACE_PINS, LINE, DP, FIFO): TE edges
 * at the times the mode's timing gives for many frames, also across one
 * long rdc_hw_run_until that skips converting frames; IRQ edges on status,
 * enable, W1C and reset; the input pins; one event per change and none
 * without one; line starts per frame; DP busy and FIFO level against the
 * registers; and a trace that does not move a cycle or a pixel.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "hw.h"
#include "hw_fx.h"
#include "dp.h"

#define VRAM_SIZE (1u << 20)
#define FRAME_CAP (320u * 200u)
#define CORE_HZ	  100000000ull
#define FRAMES	  12u

struct ev {
	uint64_t t;
	unsigned int e;
	uint32_t a, b;
	uint32_t fifo; /* hw->fifo_count when the event fired */
};

struct fx {
	struct hw_fx sim;
	struct rdc_dp dp;
	struct ev *ev;
	size_t n, cap;
	uint64_t last_t;
	int disorder; /* an event came before the one logged last */
};

static bool signal_event(unsigned int e)
{
	return e == RDC_TRACE_PINS || e == RDC_TRACE_LINE ||
	       e == RDC_TRACE_DP || e == RDC_TRACE_FIFO ||
	       e == RDC_TRACE_VBLANK;
}

static void on_trace(void *ctx, uint64_t time, unsigned int event, uint32_t a,
		     uint32_t b)
{
	struct fx *f = ctx;

	if (time < f->last_t)
		f->disorder = 1;
	f->last_t = time;
	if (!signal_event(event))
		return;
	if (f->n == f->cap) {
		f->cap = f->cap ? 2 * f->cap : 4096;
		f->ev = realloc(f->ev, f->cap * sizeof(*f->ev));
		assert_non_null(f->ev);
	}
	f->ev[f->n++] = (struct ev){ time, event, a, b, f->sim.hw.fifo_count };
}

static int setup(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));

	if (!f || hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP)) {
		free(f);
		return -1;
	}
	rdc_dp_init(&f->dp, &f->sim.hw);
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fx *f = *state;

	free(f->ev);
	hw_fx_fini(&f->sim);
	free(f);
	return 0;
}

/* Start scanout in a preset at hw->now, then trace from there. */
static void start_preset(struct fx *f, uint32_t preset)
{
	rdc_hw_write(&f->sim.hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(&f->sim.hw, RDC_REG_MODE_PRESET, preset);
	rdc_hw_write(&f->sim.hw, RDC_REG_FB_STRIDE, 0);
	rdc_hw_write(&f->sim.hw, RDC_REG_FB_FORMAT, RDC_FMT_I8);
	/* power-on's 640x480 does not fit FRAME_CAP: forget that refusal */
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_write(&f->sim.hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	assert_int_equal(rdc_hw_read(&f->sim.hw, RDC_REG_ERR_CODE),
			 RDC_ERR_NONE);
	rdc_hw_set_trace(&f->sim.hw, on_trace, f);
}

/* Line n's start within a frame: the mode's arithmetic, written out here. */
static uint64_t line_at(const struct rdc_timing *t, uint32_t n)
{
	return (uint64_t)n * t->h_total * CORE_HZ /
	       ((uint64_t)t->pixclk_khz * 1000);
}

/* Every PINS event changes something and says exactly what. */
static void check_pins_chain(const struct fx *f, uint32_t start_level)
{
	uint32_t level = start_level;
	size_t i;

	assert_false(f->disorder);
	for (i = 0; i < f->n; i++) {
		const struct ev *e = &f->ev[i];

		if (i)
			assert_true(e->t >= f->ev[i - 1].t);
		if (e->e != RDC_TRACE_PINS)
			continue;
		assert_int_not_equal(e->b, 0);
		assert_int_equal(e->a, level ^ e->b);
		level = e->a;
	}
}

/*
 * TE edges for FRAMES frames of 320x200@70 in one run_until call: it rises
 * at each line V_DISPLAY and falls at each frame start, to the cycle.
 */
static void run_te(struct fx *f, bool listener, uint64_t slice)
{
	struct rdc_timing t;
	uint64_t t0, frame, end;
	size_t i, k = 0;
	uint32_t pins0;

	assert_int_equal(rdc_preset_timing(RDC_PRESET_320x200_70, &t), 0);
	start_preset(f, RDC_PRESET_320x200_70);
	t0 = f->sim.hw.now;
	pins0 = rdc_hw_pins(&f->sim.hw);
	assert_int_equal(pins0 & RDC_PIN_TE, 0);
	frame = line_at(&t, t.v_total);
	end = t0 + FRAMES * frame + frame / 2;
	if (slice == RDC_NEVER) {
		rdc_hw_run_until(&f->sim.hw, end);
	} else {
		while (f->sim.hw.now < end)
			rdc_hw_run_until(&f->sim.hw,
					 RDC_MIN(f->sim.hw.now + slice, end));
	}
	check_pins_chain(f, pins0);
	for (i = 0; i < f->n; i++) {
		const struct ev *e = &f->ev[i];
		uint64_t want = t0 + (k / 2 + (k & 1)) * frame;

		if (e->e != RDC_TRACE_PINS)
			continue;
		/* only TE moves: no IRQ is enabled */
		assert_int_equal(e->b, RDC_PIN_TE);
		if (!(k & 1))
			want += line_at(&t, t.v_display);
		assert_int_equal(e->t, want);
		assert_int_equal(!!(e->a & RDC_PIN_TE), !(k & 1));
		k++;
	}
	assert_int_equal(k, 2 * FRAMES);
	(void)listener;
}

static void on_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t n)
{
	(void)ctx;
	(void)xrgb;
	(void)w;
	(void)h;
	(void)n;
}

static void test_te_one_long_run(void **state)
{
	run_te(*state, false, RDC_NEVER);
}

static void test_te_with_listener(void **state)
{
	struct fx *f = *state;

	rdc_hw_set_frame_fn(&f->sim.hw, on_frame, f);
	run_te(f, true, RDC_NEVER);
}

/* Host slices that do not fall on line starts change no time stamp. */
static void test_te_sliced(void **state)
{
	run_te(*state, false, 12345);
}

static void test_line_events(void **state)
{
	struct fx *f = *state;
	struct rdc_timing t;
	uint64_t t0, frame;
	/* line 0 started with scanout, before the trace was attached */
	uint32_t want_line = 1, frame_no = 0, per_frame = 1;
	size_t i;

	assert_int_equal(rdc_preset_timing(RDC_PRESET_320x200_70, &t), 0);
	start_preset(f, RDC_PRESET_320x200_70);
	t0 = f->sim.hw.now;
	frame = line_at(&t, t.v_total);
	rdc_hw_run_until(&f->sim.hw, t0 + 5 * frame - 1);
	for (i = 0; i < f->n; i++) {
		const struct ev *e = &f->ev[i];

		if (e->e != RDC_TRACE_LINE)
			continue;
		assert_int_equal(e->a, want_line);
		assert_int_equal(e->b, want_line >= t.v_display);
		assert_int_equal(e->t, t0 + frame_no * frame +
					       line_at(&t, want_line));
		per_frame++;
		if (++want_line == t.v_total) {
			assert_int_equal(per_frame, t.v_total);
			per_frame = 0;
			want_line = 0;
			frame_no++;
		}
	}
	assert_int_equal(frame_no, 5);
	assert_int_equal(want_line, 0);
}

static const struct ev *next_pins(const struct fx *f, size_t *i)
{
	for (; *i < f->n; (*i)++)
		if (f->ev[*i].e == RDC_TRACE_PINS)
			return &f->ev[(*i)++];
	return NULL;
}

static size_t count_pins(const struct fx *f)
{
	size_t i, k = 0;

	for (i = 0; i < f->n; i++)
		k += f->ev[i].e == RDC_TRACE_PINS;
	return k;
}

static void test_irq_edges(void **state)
{
	struct fx *f = *state;
	struct rdc_timing t;
	const struct ev *e;
	uint64_t t0, vb, tw, te, td;
	uint32_t pins0;
	size_t i = 0;

	assert_int_equal(rdc_preset_timing(RDC_PRESET_320x200_70, &t), 0);
	start_preset(f, RDC_PRESET_320x200_70);
	t0 = f->sim.hw.now;
	pins0 = rdc_hw_pins(&f->sim.hw);
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK);
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_ENABLE,
		     RDC_IRQ_VBLANK); /* again */
	assert_int_equal(count_pins(f), 0);

	/* the vblank raises TE and IRQ at the same step: one event */
	vb = t0 + line_at(&t, t.v_display);
	rdc_hw_run_until(&f->sim.hw, vb + 1000);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, vb);
	assert_int_equal(e->b, RDC_PIN_TE | RDC_PIN_IRQ);

	/* W1C of a bit not set: nothing; of VBLANK: IRQ falls now */
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_STATUS, RDC_IRQ_FENCE);
	assert_null(next_pins(f, &i));
	tw = f->sim.hw.now;
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_STATUS, RDC_IRQ_VBLANK);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, tw);
	assert_int_equal(e->b, RDC_PIN_IRQ);
	assert_int_equal(e->a & RDC_PIN_IRQ, 0);

	/* a pending but masked source: the enable write raises the pin */
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_ENABLE, 0);
	rdc_hw_write(&f->sim.hw, RDC_REG_LINE_COMPARE, 210);
	rdc_hw_run_until(&f->sim.hw, t0 + line_at(&t, 211));
	assert_true(rdc_hw_read(&f->sim.hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_LINE);
	assert_null(next_pins(f, &i));
	f->sim.hw.now += 7;
	te = f->sim.hw.now;
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_LINE);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, te);
	assert_int_equal(e->b, RDC_PIN_IRQ);
	assert_true(e->a & RDC_PIN_IRQ);
	/* enabling more while it is high moves nothing */
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_ENABLE,
		     RDC_IRQ_LINE | RDC_IRQ_FENCE);
	assert_null(next_pins(f, &i));

	/* the raster IRQ of the next frame comes at its line's start */
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->b, RDC_PIN_IRQ);
	rdc_hw_write(&f->sim.hw, RDC_REG_LINE_COMPARE, 17);
	rdc_hw_run_until(&f->sim.hw, t0 + 2 * line_at(&t, t.v_total));
	e = next_pins(f, &i); /* TE falls at the frame start */
	assert_non_null(e);
	assert_int_equal(e->t, t0 + line_at(&t, t.v_total));
	assert_int_equal(e->b, RDC_PIN_TE);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, t0 + line_at(&t, t.v_total) + line_at(&t, 17));
	assert_int_equal(e->b, RDC_PIN_IRQ);
	/* VBLANK is not enabled: TE alone rises, then falls */
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, t0 + line_at(&t, t.v_total) +
				       line_at(&t, t.v_display));
	assert_int_equal(e->b, RDC_PIN_TE);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, t0 + 2 * line_at(&t, t.v_total));
	assert_int_equal(e->b, RDC_PIN_TE);

	/* a soft reset drops IRQ (status and enable) and starts a frame */
	f->sim.hw.now += 3;
	td = f->sim.hw.now;
	rdc_hw_write(&f->sim.hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, td);
	assert_int_equal(e->b, RDC_PIN_IRQ);
	assert_null(next_pins(f, &i));
	check_pins_chain(f, pins0);
}

static void test_input_pins(void **state)
{
	struct fx *f = *state;
	const uint32_t all_in = RDC_PIN_RESET_N | RDC_PIN_BL_EN;
	const struct ev *e;
	uint32_t pins0;
	size_t i = 0;

	start_preset(f, RDC_PRESET_320x200_70);
	pins0 = rdc_hw_pins(&f->sim.hw);
	assert_int_equal(pins0, all_in);
	rdc_hw_set_pins(&f->sim.hw, all_in); /* no change */
	assert_int_equal(count_pins(f), 0);

	f->sim.hw.now += 100;
	rdc_hw_set_pins(&f->sim.hw, RDC_PIN_RESET_N);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->t, f->sim.hw.now);
	assert_int_equal(e->b, RDC_PIN_BL_EN);
	assert_int_equal(e->a, RDC_PIN_RESET_N);
	rdc_hw_set_pins(&f->sim.hw, RDC_PIN_RESET_N);
	assert_null(next_pins(f, &i));

	/* into reset during vblank: RESET_N and TE fall together */
	rdc_hw_run_until(&f->sim.hw, rdc_port_next_vblank(&f->sim.hw) + 10);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->b, RDC_PIN_TE);
	rdc_hw_set_pins(&f->sim.hw, 0);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->b, RDC_PIN_RESET_N | RDC_PIN_TE);
	assert_int_equal(e->a, 0);
	/* held in reset, time passes with no edge */
	rdc_hw_run_until(&f->sim.hw, f->sim.hw.now + 10000000);
	assert_null(next_pins(f, &i));
	rdc_hw_set_pins(&f->sim.hw, all_in);
	e = next_pins(f, &i);
	assert_non_null(e);
	assert_int_equal(e->b, all_in);
	check_pins_chain(f, pins0);
}

/* ---- DP and FIFO ---------------------------------------------------- */

static void push(struct fx *f, uint32_t w)
{
	rdc_hw_write(&f->sim.hw, RDC_REG_FIFO_DATA, w);
}

static void push_fill(struct fx *f, int x, int y, uint32_t w, uint32_t h)
{
	push(f, RDC_CMD(RDC_OP_FILL_RECT, 0, 2));
	push(f, RDC_XY(x, y));
	push(f, RDC_WH(w, h));
}

/*
 * Replays the FIFO events against the level the chip had when each fired,
 * and checks the DP events alternate.  Returns the DP's last level.
 */
static int check_dp_fifo(const struct fx *f, uint32_t fifo0, int dp0)
{
	uint32_t level = fifo0;
	int dp = dp0;
	size_t i;

	for (i = 0; i < f->n; i++) {
		const struct ev *e = &f->ev[i];

		if (e->e == RDC_TRACE_FIFO) {
			assert_int_not_equal(e->a, level);
			assert_int_equal(e->a, e->fifo);
			level = e->a;
		} else if (e->e == RDC_TRACE_DP) {
			assert_int_equal(e->a, !dp);
			dp = (int)e->a;
		}
	}
	assert_int_equal(level, RDC_FIFO_DEPTH -
					rdc_hw_read((struct rdc_hw *)&f->sim.hw,
						    RDC_REG_FIFO_FREE));
	return dp;
}

static const struct ev *find(const struct fx *f, size_t from, unsigned int e)
{
	for (size_t i = from; i < f->n; i++)
		if (f->ev[i].e == e)
			return &f->ev[i];
	return NULL;
}

static void test_dp_fifo(void **state)
{
	struct fx *f = *state;
	const struct ev *e;
	uint64_t tp, busy0;
	size_t i, pushes = 0, pops = 0;

	start_preset(f, RDC_PRESET_320x200_70);
	push(f, RDC_CMD(RDC_OP_SET_FG, 0, 1));
	push(f, 5);
	push_fill(f, 0, 0, 320, 100);
	push_fill(f, 10, 10, 50, 50);
	/* pushes: one level up each, at the time of the write */
	for (i = 0; i < f->n; i++) {
		assert_int_equal(f->ev[i].e, RDC_TRACE_FIFO);
		assert_int_equal(f->ev[i].a, i + 1);
		assert_int_equal(f->ev[i].t, f->sim.hw.now);
	}
	assert_int_equal(f->n, 8);
	tp = f->sim.hw.now;
	busy0 = f->sim.hw.perf.busy;
	assert_true(rdc_hw_run_until_idle(&f->sim.hw, tp + 10000000));
	assert_int_equal(check_dp_fifo(f, 0, 0), 0);

	/* the DP starts at the first pop, at once, and ends when idle */
	e = find(f, 0, RDC_TRACE_DP);
	assert_non_null(e);
	assert_int_equal(e->a, 1);
	assert_int_equal(e->t, tp);
	for (i = 0; i < f->n; i++) {
		pushes += f->ev[i].e == RDC_TRACE_FIFO && f->ev[i].t == tp &&
			  f->ev[i].a;
		pops += f->ev[i].e == RDC_TRACE_FIFO && f->ev[i].t > tp;
	}
	assert_int_equal(pushes, 8);
	assert_true(pops >= 3); /* one header pop per command at least */
	e = find(f, (size_t)(e - f->ev) + 1, RDC_TRACE_DP);
	assert_non_null(e);
	assert_int_equal(e->a, 0);
	assert_int_equal(e->t, f->sim.hw.now);
	/* busy from start to end: every command cycle inside the span */
	assert_int_equal(f->sim.hw.perf.busy - busy0, f->sim.hw.now - tp);
	assert_int_equal(rdc_hw_read(&f->sim.hw, RDC_REG_STATUS) &
				 RDC_STATUS_DP_BUSY,
			 0);
	assert_null(find(f, (size_t)(e - f->ev) + 1, RDC_TRACE_DP));
}

/* A DP waiting for a vblank stays busy; a host slice ends no DP span. */
static void test_dp_wait_and_slices(void **state)
{
	struct fx *f = *state;
	const struct ev *e;
	uint64_t tp, vb;
	size_t i, dp_events = 0;

	start_preset(f, RDC_PRESET_320x200_70);
	for (i = 0; i < 40; i++)
		push_fill(f, (int)i, (int)i, 100, 20);
	push(f, RDC_CMD(RDC_OP_WAIT_VBLANK, 0, 0));
	push_fill(f, 0, 0, 8, 8);
	tp = f->sim.hw.now;
	vb = rdc_port_next_vblank(&f->sim.hw);
	while (!rdc_hw_run_until_idle(&f->sim.hw, f->sim.hw.now + 997))
		;
	assert_true(f->sim.hw.now > vb);
	assert_int_equal(check_dp_fifo(f, 0, 0), 0);
	for (i = 0; i < f->n; i++)
		dp_events += f->ev[i].e == RDC_TRACE_DP;
	assert_int_equal(dp_events, 2);
	e = find(f, 0, RDC_TRACE_DP);
	assert_int_equal(e->t, tp);
	e = find(f, (size_t)(e - f->ev) + 1, RDC_TRACE_DP);
	assert_int_equal(e->a, 0);
	assert_int_equal(e->t, f->sim.hw.now);
}

/* A halt on error ends the DP span; a reset empties the FIFO. */
static void test_dp_halt_and_reset(void **state)
{
	struct fx *f = *state;
	const struct ev *e;
	size_t i;

	start_preset(f, RDC_PRESET_320x200_70);
	rdc_hw_write(&f->sim.hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN |
			     RDC_CONTROL_HALT_ON_ERR);
	push(f, RDC_CMD(RDC_OP_SET_ROP, 0, 1));
	push(f, 0xff); /* out of range: halts */
	push_fill(f, 0, 0, 8, 8);
	rdc_hw_run_until_idle(&f->sim.hw, f->sim.hw.now + 1000000);
	assert_true(rdc_hw_read(&f->sim.hw, RDC_REG_STATUS) &
		    RDC_STATUS_DP_HALTED);
	assert_int_equal(check_dp_fifo(f, 0, 0), 0);
	e = find(f, 0, RDC_TRACE_DP);
	e = find(f, (size_t)(e - f->ev) + 1, RDC_TRACE_DP);
	assert_non_null(e);
	assert_int_equal(e->a, 0);
	assert_int_equal(e->t, f->sim.hw.now);

	/* the fill waits in the FIFO; a soft reset empties it */
	assert_int_equal(
		RDC_FIFO_DEPTH - rdc_hw_read(&f->sim.hw, RDC_REG_FIFO_FREE), 3);
	i = f->n;
	rdc_hw_write(&f->sim.hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	e = find(f, i, RDC_TRACE_FIFO);
	assert_non_null(e);
	assert_int_equal(e->a, 0);
	assert_int_equal(e->t, f->sim.hw.now);
	assert_null(find(f, i, RDC_TRACE_DP));
	assert_int_equal(check_dp_fifo(f, 0, 0), 0);
}

/* ---- a trace changes nothing --------------------------------------- */

static uint64_t workload(struct fx *f, bool traced, uint32_t *crc)
{
	const uint32_t *px;
	uint32_t w, h, c = 0;
	size_t i;

	start_preset(f, RDC_PRESET_320x200_70);
	if (!traced)
		rdc_hw_set_trace(&f->sim.hw, NULL, NULL);
	rdc_hw_write(&f->sim.hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_ALL);
	for (i = 0; i < 60; i++) {
		push(f, RDC_CMD(RDC_OP_SET_FG, 0, 1));
		push(f, (uint32_t)i * 7);
		push_fill(f, (int)(i * 5), (int)(i * 3), 64, 40);
	}
	while (!rdc_hw_run_until_idle(&f->sim.hw, f->sim.hw.now + 5000))
		;
	rdc_hw_run_until(&f->sim.hw, rdc_port_next_vblank(&f->sim.hw));
	px = rdc_hw_frame(&f->sim.hw, &w, &h);
	assert_non_null(px);
	for (i = 0; i < (size_t)w * h; i++)
		c = (c << 5 | c >> 27) ^ px[i];
	*crc = c;
	return f->sim.hw.now;
}

static void test_trace_changes_nothing(void **state)
{
	struct fx *a = *state, *b;
	uint32_t ca, cb;
	uint64_t ta, tb;

	assert_int_equal(setup((void **)&b), 0);
	ta = workload(a, true, &ca);
	tb = workload(b, false, &cb);
	assert_true(a->n > 0);
	assert_int_equal(b->n, 0);
	assert_int_equal(ta, tb);
	assert_int_equal(ca, cb);
	assert_int_equal(a->sim.hw.perf.busy, b->sim.hw.perf.busy);
	assert_int_equal(a->sim.hw.perf.stall, b->sim.hw.perf.stall);
	check_pins_chain(a, RDC_PIN_RESET_N | RDC_PIN_BL_EN);
	teardown((void **)&b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_te_one_long_run, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_te_with_listener, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_te_sliced, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_line_events, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_irq_edges, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_input_pins, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_dp_fifo, setup, teardown),
		cmocka_unit_test_setup_teardown(test_dp_wait_and_slices, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_dp_halt_and_reset, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_trace_changes_nothing,
						setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
