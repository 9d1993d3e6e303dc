// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The workloads through the real command path: librdc sim: -> command
 * words -> display-processor firmware -> hw-sim, cycle counting on.  The
 * drawing workloads with scanout on, off, and on with no frame consumer;
 * scanout through the frame listener; realtime (rdcd's pipeline
 * unpaced) and teapot3d (a display list, frame after frame).
 */
#define RDC_CORE_INTERNAL /* the benchmark drives the core directly: hw.h, dp.h */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "hw.h"
#include "parts.h"
#include "rdc_priv.h"
#include "rdc_sink.h"

#define BATCH_WORDS 65536u /* submit once a batch holds this many words */
/* realtime: the frames, and each frame's drawing */
#define RT_FRAMES     RT_TARGET_FPS /* run this many frames ... */
#define RT_MAX_S      2.0	    /* ... or for this long at most */
#define RT_LINES      1000u
#define RT_FILLS      100u
#define RT_FILL_MAX   128u
#define RT_TEXT_ROWS  100u
#define RT_FIRST_CHAR 32u /* printable ASCII */
#define RT_CHARS      95u
/* A sink that discards: png writes only the frames asked for (never). */
#define RT_SINK "png:/nonexistent,every=0"
/*
 * teapot3d: examples/teapot.rdl's scene (run from the source tree), frame
 * after frame: the picture list into the buffer off screen, a flip, a
 * turn.  The figure that matters is the simulated chip's: frames a
 * simulated second its display processor draws, against the 60 Hz line.
 */
#define T3_SCRIPT "examples/teapot.rdl"
#define T3_FRAMES 120u
#define T3_DRAW	  0x410000u /* the picture list */
#define T3_BUF1	  0x130000u /* the second screen buffer */
#define T3_TURN	  1092u	    /* 6 degrees in 1/65536 turn */

/* ---- rdc: the workloads through librdc sim: ------------------------------ */

static void run_open(struct bench_run *r, uint32_t preset, uint32_t format,
		     size_t bytes)
{
	uint8_t *zero = bench_xcalloc(bytes, 1);
	int err = rdc_open("sim:", &r->dev);

	if (err)
		bench_die("open", err);
	r->b = rdc_batch_new();
	if (!r->b)
		bench_die("batch", RDC_E_NOMEM);
	err = rdc_mode_set(r->dev, preset, format, 0);
	if (!err)
		err = rdc_vram_write(r->dev, 0, zero, bytes);
	if (!err)
		err = rdc_finish(r->dev);
	if (err)
		bench_die("setup", err);
	free(zero);
}

static void run_close(struct bench_run *r)
{
	rdc_batch_free(r->b);
	rdc_close(r->dev);
}

/* Submit what the batch holds once it is big enough (or when forced). */
void bench_run_flush(struct bench_run *r, bool force)
{
	size_t n;
	int err;

	rdc_batch_words(r->b, &n);
	if (!n || (!force && n < BATCH_WORDS))
		return;
	err = rdc_batch_submit(r->dev, r->b);
	if (err)
		bench_die("submit", err);
}

void bench_run_finish(struct bench_run *r)
{
	int err;

	bench_run_flush(r, true);
	err = rdc_finish(r->dev);
	if (err)
		bench_die("finish", err);
}

static uint32_t run_crc(struct bench_run *r)
{
	uint8_t *buf = bench_xcalloc(BENCH_W * BENCH_H, 4);
	uint32_t crc;
	int err;

	err = rdc_vram_read(r->dev, 0, buf, BENCH_W * BENCH_H * 4);
	if (err)
		bench_die("vram read", err);
	crc = bench_surface_crc(buf, BENCH_W * 4);
	free(buf);
	return crc;
}

static void rdc_fills(struct bench_run *r, const uint32_t *a, uint32_t ops)
{
	uint32_t i;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		rdc_batch_fg_next(r->b, a[4]);
		rdc_batch_fill_rect(r->b, (int)a[0], (int)a[1], a[2], a[3]);
		bench_run_flush(r, false);
	}
}

static void rdc_draw(struct bench_run *r, const struct bench_input *in)
{
	const uint32_t *a = in->arg;
	uint32_t i;

	switch (in->kind) {
	case BENCH_FILL:
		rdc_fills(r, a, in->ops);
		return;
	default:
		break;
	}
	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		switch (in->kind) {
		case BENCH_BLIT:
		case BENCH_BLIT_XOR:
			rdc_batch_blit(r->b, (int)a[0], (int)a[1], (int)a[2],
				       (int)a[3], a[4], a[5]);
			break;
		case BENCH_LINE:
			rdc_batch_fg_next(r->b, a[4]);
			rdc_batch_line(r->b, (int)a[0], (int)a[1], (int)a[2],
				       (int)a[3]);
			break;
		case BENCH_AALINE:
			rdc_batch_fg_next(r->b, a[4]);
			rdc_batch_aa_line(r->b, (int)a[0], (int)a[1], (int)a[2],
					  (int)a[3]);
			break;
		case BENCH_CIRCLE:
			rdc_batch_fg_next(r->b, a[3]);
			rdc_batch_circle(r->b, (int)a[0], (int)a[1], a[2]);
			break;
		case BENCH_FILL_CIRCLE:
			rdc_batch_fg_next(r->b, a[3]);
			rdc_batch_fill_circle(r->b, (int)a[0], (int)a[1], a[2]);
			break;
		case BENCH_POLYGON:
			rdc_batch_fg_next(r->b, a[2]);
			rdc_batch_fill_polygon(r->b, in->xy + 2 * a[1], a[0],
					       0);
			break;
		case BENCH_TEXT:
			/* a glyph with its colours, as a console's are */
			rdc_batch_mono_colors(r->b, (int)a[3], (int)a[4],
					      BENCH_GLYPH_W, BENCH_GLYPH_H,
					      in->font + a[0] * BENCH_GLYPH_H,
					      a[1], a[2], 0);
			break;
		default:
			return;
		}
		bench_run_flush(r, false);
	}
}

/* What the chip hands over at each vblank: count it, pass it on. */
struct frames {
	rdc_sink *sink;
	uint64_t seen;
	uint32_t num, den;
	uint32_t crc;
	bool want_crc;
};

static void frames_fn(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		      uint64_t number)
{
	struct frames *f = ctx;
	struct rdc_frame fr = { .xrgb = xrgb,
				.width = w,
				.height = h,
				.stride = w,
				.seq = number,
				.interval_num = f->num,
				.interval_den = f->den };

	f->seen++;
	if (f->sink)
		rdc_sink_frame(f->sink, &fr);
	if (f->want_crc)
		f->crc = (uint32_t)crc32(0, (const uint8_t *)xrgb,
					 (uInt)w * h * 4);
}

/* CONTROL.SCANOUT_EN = 0: the CRTC stops, and with it its bus traffic. */
void bench_scanout_off(rdc_dev *dev)
{
	uint32_t ctl;

	if (rdc_reg_read(dev, RDC_REG_CONTROL, &ctl) ||
	    rdc_reg_write(dev, RDC_REG_CONTROL,
			  ctl & ~(uint32_t)RDC_CONTROL_SCANOUT_EN) ||
	    rdc_reg_read(dev, RDC_REG_CONTROL, &ctl) ||
	    (ctl & RDC_CONTROL_SCANOUT_EN))
		bench_die("scanout off", RDC_E_IO);
}

/*
 * scanout: every frame the CRTC converts through the CLUT is handed to
 * the frame listener, as in rdcd; 600 of them are timed.
 */
static void rdc_scanout(const struct bench_input *in, struct bench_rdc_res *res)
{
	struct frames f = { 0 };
	struct bench_run r;
	struct rdc_hw *hw;
	uint64_t c0, c1;
	double t0;

	run_open(&r, RDC_PRESET_1024x768_60, RDC_FMT_I8, BENCH_W * BENCH_H);
	rdc_batch_load_clut(r.b, 0, in->clut, BENCH_CLUT_SIZE);
	rdc_fills(&r, in->prefill, BENCH_FILL_OPS);
	bench_run_finish(&r);
	/* the mode is latched at a vblank: let it be in force first */
	if (rdc_frame_wait(r.dev))
		bench_die("frame wait", RDC_E_TIMEOUT);
	hw = rdc_sim_hw(r.dev);
	if (!hw)
		bench_die("sim hw", RDC_E_NOSYS);
	rdc_hw_set_frame_fn(hw, frames_fn, &f);
	rdc_sim_time(r.dev, &c0);
	t0 = bench_tic();
	while (f.seen < in->ops - 1)
		if (rdc_vblank_wait(r.dev))
			bench_die("vblank", RDC_E_TIMEOUT);
	f.want_crc = true; /* outside the drawing proper, but cheap */
	while (f.seen < in->ops)
		if (rdc_vblank_wait(r.dev))
			bench_die("vblank", RDC_E_TIMEOUT);
	res->wall = bench_toc(t0);
	rdc_sim_time(r.dev, &c1);
	res->cycles = c1 - c0;
	res->crc = f.crc;
	rdc_hw_set_frame_fn(hw, NULL, NULL);
	run_close(&r);
}

/*
 * The prefill (blit, scanout) is drawn through the device on every run,
 * untimed: loading a saved image instead would start the timed part at
 * another simulated time, and sim_cycles must not depend on the repeat.
 */
/*
 * scan false: CONTROL.SCANOUT_EN is cleared before the prefill, so the
 * drawing runs without the CRTC's reads of VRAM (and their bus stalls).
 * scan true: the frames the CRTC completes during the drawing are counted
 * (the frame listener), and the frame after it is the one whose CRC the
 * limit with scanout must reproduce.  lazy (with scan): scanout on with
 * no frame consumer (scanout on demand, hw-sim/rdc_chip.h): the same bus
 * and cycles, no frame converted; the frames are counted by FRAME_COUNT,
 * and the frame after the drawing is taken with a consumer attached.
 */
void bench_rdc_run(const struct bench_input *in, struct bench_rdc_res *res,
		   bool scan, bool lazy)
{
	uint32_t fc0 = 0, fc1 = 0;
	struct rdc_stats st0 = { 0 }, st1 = { 0 };
	struct frames f = { 0 };
	struct rdc_hw *hw;
	struct bench_run r;
	uint64_t c0, c1;
	double t0;

	if (in->kind == BENCH_SCANOUT) {
		rdc_scanout(in, res);
		return;
	}
	run_open(&r, RDC_PRESET_1024x768_60, RDC_FMT_XRGB8888,
		 BENCH_W * BENCH_H * 4);
	hw = rdc_sim_hw(r.dev);
	if (!hw)
		bench_die("sim hw", RDC_E_NOSYS);
	if (!scan)
		bench_scanout_off(r.dev);
	if (lazy)
		rdc_hw_set_on_demand(hw, true);
	if (in->prefill) {
		rdc_fills(&r, in->prefill, BENCH_FILL_OPS);
		if (in->kind == BENCH_BLIT_XOR)
			rdc_batch_rop(r.b, RDC_ROP_XOR);
		bench_run_finish(&r);
	}
	rdc_stats_get(r.dev, &st0);
	if (scan && !lazy)
		rdc_hw_set_frame_fn(hw, frames_fn, &f);
	if (lazy && rdc_reg_read(r.dev, RDC_REG_FRAME_COUNT, &fc0))
		bench_die("frame count", RDC_E_IO);
	rdc_sim_time(r.dev, &c0);
	t0 = bench_tic();
	rdc_draw(&r, in);
	bench_run_finish(&r);
	res->wall = bench_toc(t0);
	rdc_sim_time(r.dev, &c1);
	if (lazy && rdc_reg_read(r.dev, RDC_REG_FRAME_COUNT, &fc1))
		bench_die("frame count", RDC_E_IO);
	rdc_hw_set_frame_fn(hw, NULL, NULL);
	rdc_stats_get(r.dev, &st1);
	res->cycles = c1 - c0;
	res->sim_pixels = st1.pixels - st0.pixels;
	res->frames = lazy ? fc1 - fc0 : f.seen;
	res->frame_crc = 0;
	if (lazy)
		rdc_hw_consumer_attach(hw);
	if (scan &&
	    (rdc_frame_wait(r.dev) || rdc_frame_crc(r.dev, &res->frame_crc)))
		bench_die("frame crc", RDC_E_IO);
	if (lazy)
		rdc_hw_consumer_detach(hw);
	res->crc = run_crc(&r);
	run_close(&r);
}

/*
 * realtime: rdcd's pipeline unpaced.  Each frame's drawing (1,000 lines,
 * 100 fills, 100 text rows) is submitted, then simulated time runs on to
 * the next vblank; every frame the chip completes goes to a frame sink
 * that discards it (png with every=0 writes only on request).
 */
static const struct rt_mode rt_vga = { RT_PRESET, RT_W, RT_H, RT_TARGET_FPS,
				       RT_FRAMES };
static const struct rt_mode rt_1080 = { RDC_PRESET_1920x1080_60, 1920, 1080,
					RT_HZ, 2 * RT_HZ };
#define RT_MAX_COLS (1920 / BENCH_GLYPH_W)

const struct rt_mode *rt_mode_of(enum bench_kind k)
{
	return k == BENCH_REALTIME_1080 ? &rt_1080 : &rt_vga;
}

static void rt_frame(struct bench_run *r, struct bench_rng *g,
		     const struct rt_mode *m)
{
	char text[RT_MAX_COLS];
	uint32_t i, k, cols = m->w / BENCH_GLYPH_W, rows = m->h / BENCH_GLYPH_H;

	for (i = 0; i < RT_LINES; i++) {
		int x0 = (int)(bench_r32(g) % m->w),
		    y0 = (int)(bench_r32(g) % m->h);
		int x1 = (int)(bench_r32(g) % m->w),
		    y1 = (int)(bench_r32(g) % m->h);

		rdc_batch_fg_next(r->b, bench_r32(g) | BENCH_OPAQUE);
		rdc_batch_line(r->b, x0, y0, x1, y1);
	}
	for (i = 0; i < RT_FILLS; i++) {
		int x = (int)(bench_r32(g) % m->w),
		    y = (int)(bench_r32(g) % m->h);
		uint32_t w = 1 + bench_r32(g) % RT_FILL_MAX;
		uint32_t h = 1 + bench_r32(g) % RT_FILL_MAX;

		rdc_batch_fg_next(r->b, bench_r32(g) | BENCH_OPAQUE);
		rdc_batch_fill_rect(r->b, x, y, w, h);
	}
	for (i = 0; i < RT_TEXT_ROWS; i++) {
		for (k = 0; k < cols; k++)
			text[k] =
				(char)(RT_FIRST_CHAR + bench_r32(g) % RT_CHARS);
		rdc_batch_fg(r->b, bench_r32(g) | BENCH_OPAQUE);
		rdc_batch_bg(r->b, bench_r32(g) | BENCH_OPAQUE);
		rdc_batch_text(r->b, 0, (int)(i % rows * BENCH_GLYPH_H), text,
			       cols, 0);
	}
	bench_run_flush(r, true);
}

static uint64_t t3_busy(rdc_dev *dev)
{
	uint32_t lo = 0, hi = 0;

	/* reading LO snapshots HI */
	if (rdc_reg_read(dev, RDC_REG_PERF_BUSY_LO, &lo) ||
	    rdc_reg_read(dev, RDC_REG_PERF_BUSY_HI, &hi))
		bench_die("perf read", RDC_E_IO);
	return (uint64_t)hi << 32 | lo;
}

void bench_teapot3d(struct rt_res *res)
{
	struct rdc_script_result sres;
	struct bench_run r;
	uint64_t b0, b1;
	double t0;
	uint32_t i;
	int err;

	run_open(&r, RT_PRESET, RDC_FMT_XRGB8888, RT_W * RT_H * 4);
	memset(&sres, 0, sizeof(sres));
	err = rdc_script_run_file(r.dev, T3_SCRIPT, &sres);
	if (err) {
		fprintf(stderr,
			"rdc-bench: %s:%u: %s (run from the source "
			"tree)\n",
			T3_SCRIPT, sres.error_line, sres.error_msg);
		exit(1);
	}
	if (rdc_reg_read(r.dev, RDC_REG_CORE_KHZ, &res->khz))
		bench_die("core clock", RDC_E_IO);
	b0 = t3_busy(r.dev);
	t0 = bench_now();
	for (i = 0; i < T3_FRAMES; i++) {
		uint32_t buf = i & 1 ? 0 : T3_BUF1, turn = T3_TURN;

		rdc_batch_dst(r.b, buf, RT_W * 4, RT_W, RT_H, RDC_FMT_XRGB8888);
		rdc_batch_call(r.b, T3_DRAW);
		rdc_batch_reg_write(r.b, RDC_REG_FB_BASE, buf);
		rdc_batch_cmd(r.b, RDC_OP_ROTATE, RDC_AXIS_Z, &turn, 1);
		bench_run_finish(&r);
	}
	res->wall = bench_now() - t0;
	b1 = t3_busy(r.dev);
	res->frames = T3_FRAMES;
	res->drawn = T3_FRAMES;
	res->cycles = b1 - b0;
	if (rdc_frame_wait(r.dev) || rdc_frame_crc(r.dev, &res->crc))
		res->crc = 0;
	run_close(&r);
}

/* Frames the chip completed: FRAME_COUNT, for a run without a listener. */
static uint64_t rt_frame_count(rdc_dev *dev)
{
	uint32_t fc;

	if (rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &fc))
		bench_die("frame count", RDC_E_IO);
	return fc;
}

/*
 * lazy: the same drawing and time with no frame consumer at all (no
 * sink, no listener; scanout on demand): the bus is charged the same, no
 * frame is converted.  The frames are counted by FRAME_COUNT.
 */
void bench_realtime(struct rt_res *res, const struct rt_mode *m, bool lazy)
{
	struct frames f = { 0 };
	struct bench_rng g = { BENCH_SEED };
	struct rdc_hw *hw;
	struct bench_run r;
	uint64_t c0, c1, f0, seen;
	double t0;
	int err;

	run_open(&r, m->preset, RDC_FMT_XRGB8888, (size_t)m->w * m->h * 4);
	if (rdc_frame_wait(r.dev))
		bench_die("frame wait", RDC_E_TIMEOUT);
	hw = rdc_sim_hw(r.dev);
	if (!hw)
		bench_die("sim hw", RDC_E_NOSYS);
	if (lazy) {
		rdc_hw_set_on_demand(hw, true);
	} else {
		err = rdc_sink_open(RT_SINK, &f.sink);
		if (err)
			bench_die("sink", err);
		if (rdc_sink_interval(r.dev, &f.num, &f.den))
			f.num = f.den = 0;
		rdc_hw_set_frame_fn(hw, frames_fn, &f);
	}
	res->drawn = 0;
	rdc_sim_time(r.dev, &c0);
	f0 = lazy ? rt_frame_count(r.dev) : f.seen;
	t0 = bench_now();
	res->cpu = bench_cpu_now();
	do {
		rt_frame(&r, &g, m);
		res->drawn++;
		if (rdc_vblank_wait(r.dev))
			bench_die("vblank", RDC_E_TIMEOUT);
		res->wall = bench_now() - t0;
		seen = lazy ? rt_frame_count(r.dev) : f.seen;
	} while (seen - f0 < m->frames && res->wall < RT_MAX_S);
	res->cpu = bench_cpu_now() - res->cpu;
	rdc_sim_time(r.dev, &c1);
	res->frames = seen - f0;
	res->cycles = c1 - c0;
	rdc_hw_set_frame_fn(hw, NULL, NULL);
	if (lazy)
		rdc_hw_set_on_demand(hw, false); /* the CRC's frame: kept */
	if (rdc_frame_crc(r.dev, &res->crc))
		res->crc = 0;
	if (f.sink)
		rdc_sink_close(f.sink);
	run_close(&r);
}
