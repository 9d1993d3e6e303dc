// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Traces: record every operation that can change a simulated RDC-1, with
 * the simulated time it happened at; replay.c plays them back.  This file
 * holds the recorder (rdcd's, rdc_server.h, and the client's,
 * rdc_record_start) and describes the file's layout.
 *
 * The chip is deterministic, so the backend operations in the same order
 * on a fresh chip reproduce everything: recording wraps the sim: backend's
 * table (the core and rdcd keep calling through dev->be as before) and
 * replay calls the same operations.  Time is recorded too, to detect a
 * trace that does not match the build that replays it.
 *
 * File format, little-endian:
 *   "RDCTRACE" u32 version u32 vram_size [u32 flags: version 3 on]
 *   records: u8 op, u64 time (before the operation), then by op:
 *     REG_WRITE   u32 reg, u32 value
 *     REG_READ    u32 reg, u32 value read (reads can pop RDATA)
 *     VRAM_WRITE  u32 addr, u32 len, len bytes
 *     WAIT        the RDC_MSG_WAIT payload (rdc_proto.h), i32 result
 *     STEP        u64 cycles
 *     POWER       (a new chip from here on)
 *     END         (time is the final time)
 *     PINS        u32 mask, u32 levels: the inputs in mask (RDC_PINS_IN)
 *                 driven to levels (version 2 on)
 *     SUBMIT      u32 n, n command words, i32 result (version 3 on)
 *     STATE       u32 what, [core section], u32 n, n (u32 reg, u32 value),
 *                 u32 256, the CLUT, u32 zlen, VRAM deflated (version 4
 *                 on, the first record only)
 *
 * Version 1 is version 2 without PINS: such traces still replay.
 * Version 3 adds the flags word and SUBMIT.  A recorder on a device
 * without a chip in this process (fbdev:, unix:, tcp:, usb:: the client
 * side of rdc_record_start) cannot know the device's time without asking
 * for it, which would be an operation of its own, paid for with a round
 * trip (an ioctl) per record and still not exact on a paced device, whose
 * time moves between the question and the operation.  So it writes an
 * untimed trace: flag REC_F_UNTIMED (version 3 on), every time 0; replay runs
 * its operations in order and compares what they return, not when.  Such
 * a device takes command words in bulk (its backend's submit: the FIFO
 * is fed on the other side), and SUBMIT records them as the client gave
 * them; replay feeds them to sim: as rdc_submit does there.  A timed
 * trace of rdcd's is written as version 2 as before.
 *
 * Version 4 adds STATE, the first record of rdc_record_start's traces
 * (timed or not): the device a client opens has usually run (rdcfb.ko's
 * since the module loaded), and replay starts from a fresh chip, so the
 * recorder writes where the device is (rec_state_put) and replay puts
 * its chip there (rdc_hw_resume) before the first operation.
 * The same layout, as a table: docs/protocol.md, "Traces".
 *
 * The file is flushed whenever a client gets an answer (after REG_READ,
 * WAIT, POWER and END records): a replay while the recorder still runs
 * sees every operation up to the last answer, and a trace that stops
 * without END (the recorder still running, or killed) is replayed up to
 * its last complete record and reported as truncated.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "kchip.h"
#include "rdc_priv.h"
#include "rdc_proto.h"
#include "record.h"
#include "record_limits.h"

struct rdc_server_rec {
	FILE *f;
	int err;
	const struct rdc_backend *inner;
	void *inner_priv;
	struct rdc_hw *hw; /* NULL: an untimed trace, or after a power cycle */
	bool untimed;
	/* rdc_record_start's: ends with the handle (rdc_close) */
	bool owned;
	/* the wrapper's table: the inner backend's optional operations that
	 * it has, passed through or recorded */
	struct rdc_backend be;
	/* time moved on the chip directly since moved_from (rdc_server_rec_time_moved) */
	bool moved;
	uint64_t moved_from;
};

static const struct rdc_backend rdc_backend_rec;

static uint64_t rec_now(const struct rdc_server_rec *r)
{
	return r->hw ? rdc_hw_now(r->hw) : 0;
}

static void rec_put(struct rdc_server_rec *r, const void *p, size_t n)
{
	if (n && fwrite(p, 1, n, r->f) != n)
		r->err = RDC_E_FILE;
}

/* A client is about to see an answer: what led to it goes to the file. */
static void rec_sync(struct rdc_server_rec *r)
{
	if (fflush(r->f))
		r->err = RDC_E_FILE;
}

/* A STEP record for time that moved at `t`, outside the handle. */
static void rec_step_put(struct rdc_server_rec *r, uint64_t t, uint64_t cycles)
{
	uint8_t b[17];

	b[0] = REC_STEP;
	rdc_proto_put64(b + 1, t);
	rdc_proto_put64(b + 9, cycles);
	rec_put(r, b, sizeof(b));
}

/* STEP records for `cycles` from `t`, none longer than a replay takes. */
static void rec_steps_put(struct rdc_server_rec *r, uint64_t t, uint64_t cycles)
{
	while (cycles) {
		uint64_t k = RDC_MIN(cycles, REC_MAX_CYCLES);

		rec_step_put(r, t, k);
		if (!r->untimed)
			t += k;
		cycles -= k;
	}
}

/* Time that moved outside the handle, as a step, before the next record. */
static void rec_flush_moved(struct rdc_server_rec *r)
{
	if (r->moved && r->hw && rdc_hw_now(r->hw) > r->moved_from)
		rec_steps_put(r, r->moved_from,
			      rdc_hw_now(r->hw) - r->moved_from);
	r->moved = false;
}

static void rec_head(struct rdc_server_rec *r, uint8_t op)
{
	uint8_t b[9];

	rec_flush_moved(r);
	b[0] = op;
	rdc_proto_put64(b + 1, rec_now(r));
	rec_put(r, b, sizeof(b));
}

static void rec_u32x2(struct rdc_server_rec *r, uint8_t op, uint32_t a,
		      uint32_t v)
{
	uint8_t b[8];

	rec_head(r, op);
	rdc_proto_put32(b, a);
	rdc_proto_put32(b + 4, v);
	rec_put(r, b, sizeof(b));
}

static struct rdc_server_rec *rec_open(const char *path, uint32_t vram_size,
				       uint32_t version, uint32_t flags,
				       int *err)
{
	struct rdc_server_rec *r = calloc(1, sizeof(*r));
	uint8_t b[12];

	if (!r) {
		*err = RDC_E_NOMEM;
		return NULL;
	}
	r->f = fopen(path, "wb");
	if (!r->f) {
		*err = rdc_err_detail(RDC_E_FILE, "%s: %s", path,
				      strerror(errno));
		free(r);
		return NULL;
	}
	r->untimed = flags & REC_F_UNTIMED;
	rec_put(r, REC_MAGIC, REC_MAGIC_LEN);
	rdc_proto_put32(b, version);
	rdc_proto_put32(b + 4, vram_size);
	rdc_proto_put32(b + 8, flags);
	rec_put(r, b, version >= REC_VERSION_FLAGS ? 12 : 8);
	rec_sync(r);
	return r;
}

struct rdc_server_rec *rdc_server_rec_open(const char *path, uint32_t vram_size)
{
	int err;

	return rec_open(path, vram_size, REC_VERSION, 0, &err);
}

/* The wrapper's table for `inner`: what it lacks, the wrapper lacks. */
static void rec_table(struct rdc_server_rec *r, const struct rdc_backend *inner)
{
	r->be = rdc_backend_rec;
	r->be.scheme = inner->scheme;
	/*
	 * A device that takes words in bulk gets them so, as a SUBMIT
	 * record.  sim:'s submit is its FIFO loop, whose register writes
	 * and waits the recorder sees one by one when it runs the core's
	 * (timed traces stay version 2).
	 */
	if (r->untimed && inner->submit)
		r->be.submit = rdc_backend_rec.submit;
	else
		r->be.submit = NULL;
	r->be.subscribe = inner->subscribe ? rdc_backend_rec.subscribe : NULL;
	r->be.event_next = inner->event_next ? rdc_backend_rec.event_next :
					       NULL;
	if (!inner->hist_open) {
		r->be.hist_open = NULL;
		r->be.hist_read = NULL;
		r->be.hist_set = NULL;
		r->be.hist_close = NULL;
	}
	if (!inner->pins_set)
		r->be.pins_set = NULL;
	if (!inner->pins_get)
		r->be.pins_get = NULL;
	if (!inner->pins_wait)
		r->be.pins_wait = NULL;
	if (!inner->step)
		r->be.step = NULL;
	if (!inner->frame_grab)
		r->be.frame_grab = NULL;
}

void rdc_server_rec_attach(struct rdc_server_rec *r, rdc_dev *dev)
{
	r->inner = dev->be;
	r->inner_priv = dev->priv;
	r->hw = r->untimed ? NULL : rdc_sim_hw(dev);
	rec_table(r, r->inner);
	dev->be = &r->be;
	dev->priv = r;
}

/* Is `dev` wrapped by a recorder? */
static struct rdc_server_rec *rec_of(rdc_dev *dev)
{
	if (dev && dev->be && dev->be->close == rdc_backend_rec.close)
		return dev->priv;
	return NULL;
}

struct rdc_hw *rdc_dev_chip(rdc_dev *dev)
{
	struct rdc_server_rec *r = rec_of(dev);

	return r ? r->hw : rdc_sim_hw(dev);
}

void rdc_server_rec_power(struct rdc_server_rec *r)
{
	rec_head(r, REC_POWER);
	rec_sync(r);
	r->hw = NULL;
}

int rdc_server_rec_close(struct rdc_server_rec *r, rdc_dev *dev)
{
	int ret;

	if (!r)
		return 0;
	if (rec_of(dev) == r)
		rec_head(r, REC_END);
	if (fclose(r->f))
		r->err = RDC_E_FILE;
	ret = r->err;
	if (rec_of(dev) == r) {
		/* unwrap: the handle goes on without a recorder */
		dev->be = r->inner;
		dev->priv = r->inner_priv;
	}
	free(r);
	return ret;
}

/* Run one operation of the wrapped backend. */
#define REC_INNER(dev, r, call) \
	({ \
		int ret_; \
		(dev)->priv = (r)->inner_priv; \
		ret_ = (r)->inner->call; \
		(dev)->priv = (r); \
		ret_; \
	})

static void rec_be_close(rdc_dev *dev)
{
	struct rdc_server_rec *r = dev->priv;

	/* rdc_record_start's recorder ends with the handle: END first,
	 * with the time the chip is at */
	if (r->owned)
		rec_head(r, REC_END);
	dev->priv = r->inner_priv;
	r->inner->close(dev);
	dev->be = r->inner;
	r->hw = NULL;
	if (r->owned) {
		fclose(r->f);
		free(r);
	}
}

static int rec_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val)
{
	struct rdc_server_rec *r = dev->priv;
	uint8_t b[17];
	uint64_t t;
	int ret;

	rec_flush_moved(r);
	t = rec_now(r);
	ret = REC_INNER(dev, r, reg_read(dev, reg, val));

	b[0] = REC_REG_READ;
	rdc_proto_put64(b + 1, t);
	rdc_proto_put32(b + 9, reg);
	rdc_proto_put32(b + 13, ret ? 0 : *val);
	rec_put(r, b, sizeof(b));
	rec_sync(r);
	return ret;
}

static int rec_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val)
{
	struct rdc_server_rec *r = dev->priv;
	int ret;

	if (!r->untimed) {
		rec_u32x2(r, REC_REG_WRITE, reg, val);
		return REC_INNER(dev, r, reg_write(dev, reg, val));
	}
	/* A device on the other side may refuse a write (rdcfb's checks,
	 * an observer's handle): a refused one changed nothing. */
	ret = REC_INNER(dev, r, reg_write(dev, reg, val));
	if (!ret)
		rec_u32x2(r, REC_REG_WRITE, reg, val);
	return ret;
}

static int rec_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, vram_read(dev, addr, buf, len));
}

static int rec_vram_write(rdc_dev *dev, uint32_t addr, const void *buf,
			  size_t len)
{
	struct rdc_server_rec *r = dev->priv;
	int ret = REC_INNER(dev, r, vram_write(dev, addr, buf, len));

	/* Only writes that happened: a refused one changed nothing. */
	if (!ret) {
		rec_u32x2(r, REC_VRAM_WRITE, addr, (uint32_t)len);
		rec_put(r, buf, len);
	}
	return ret;
}

static int rec_wait(rdc_dev *dev, const struct rdc_wait *w)
{
	struct rdc_server_rec *r = dev->priv;
	struct rdc_proto_wait pw = { .budget = w->budget,
				     .needs_dp = w->needs_dp };
	uint8_t b[RDC_PROTO_WAIT_SIZE + 4];
	int ret;

	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		pw.term[i].kind = w->term[i].kind;
		pw.term[i].reg = w->term[i].reg;
		pw.term[i].mask = w->term[i].mask;
		pw.term[i].value = w->term[i].value;
	}
	rec_head(r, REC_WAIT);
	ret = REC_INNER(dev, r, wait(dev, w));
	rdc_proto_wait_encode(b, &pw);
	rdc_proto_put32(b + RDC_PROTO_WAIT_SIZE, (uint32_t)ret);
	rec_put(r, b, sizeof(b));
	rec_sync(r);
	return ret;
}

/*
 * A pin change is an input like a register write: at the same simulated
 * time on the same chip it has the same effect (rdc_hw_set_pins).  Only
 * changes that happened are written, as for VRAM.
 */
static int rec_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	struct rdc_server_rec *r = dev->priv;
	uint64_t t;
	int ret;

	rec_flush_moved(r);
	t = rec_now(r);
	ret = REC_INNER(dev, r, pins_set(dev, mask, levels));
	if (!ret) {
		uint8_t b[17];

		b[0] = REC_PINS;
		rdc_proto_put64(b + 1, t);
		rdc_proto_put32(b + 9, mask);
		rdc_proto_put32(b + 13, levels);
		rec_put(r, b, sizeof(b));
	}
	return ret;
}

/*
 * A device's own pin reads (fbdev: its GPIO lines) go to it unrecorded:
 * they change nothing on the chip, and a replay reads the register PINS.
 */
static int rec_pins_get(rdc_dev *dev, uint32_t *levels)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, pins_get(dev, levels));
}

static int rec_pins_wait(rdc_dev *dev, uint32_t pins, uint32_t edges,
			 uint64_t budget_cycles, uint64_t timeout_us,
			 struct rdc_pin_edge *ev)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r,
			 pins_wait(dev, pins, edges, budget_cycles, timeout_us,
				   ev));
}

static int rec_step(rdc_dev *dev, uint64_t cycles)
{
	struct rdc_server_rec *r = dev->priv;
	int ret;

	if (!r->untimed) {
		rec_flush_moved(r);
		rec_steps_put(r, rec_now(r), cycles);
		return REC_INNER(dev, r, step(dev, cycles));
	}
	/* a paced device refuses to step (RDC_E_NOSYS): nothing moved */
	ret = REC_INNER(dev, r, step(dev, cycles));
	if (!ret) {
		rec_flush_moved(r);
		rec_steps_put(r, 0, cycles);
	}
	return ret;
}

/*
 * Words to a device that takes them in bulk (untimed traces only), in
 * records of at most REC_SUBMIT_MAX words cut at command boundaries as
 * the fbdev: and drm: backends cut theirs (rdc_kchip_piece), each
 * submitted in turn with its result.
 */
static int rec_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	struct rdc_server_rec *r = dev->priv;
	int ret = 0;

	while (n && !ret) {
		size_t k = rdc_kchip_piece(words, n, REC_SUBMIT_MAX);
		uint8_t b[4];

		rec_head(r, REC_SUBMIT);
		rdc_proto_put32(b, (uint32_t)k);
		rec_put(r, b, sizeof(b));
		for (size_t i = 0; i < k; i++) {
			rdc_proto_put32(b, words[i]);
			rec_put(r, b, sizeof(b));
		}
		ret = REC_INNER(dev, r, submit(dev, words, k));
		rdc_proto_put32(b, (uint32_t)ret);
		rec_put(r, b, sizeof(b));
		words += k;
		n -= k;
	}
	rec_sync(r);
	return ret;
}

void rdc_server_rec_sync(struct rdc_server_rec *rec)
{
	if (!rec)
		return;
	rec_flush_moved(rec);
	rec_sync(rec);
}

void rdc_server_rec_time_moved(struct rdc_server_rec *rec, uint64_t from)
{
	if (rec && !rec->moved) {
		rec->moved = true;
		rec->moved_from = from;
	}
}

static int rec_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap,
			  uint32_t *width, uint32_t *height)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, frame_grab(dev, buf, cap, width, height));
}

/* Not recorded: they change nothing on the chip. */
static int rec_subscribe(rdc_dev *dev, uint32_t events, uint32_t every,
			 uint32_t encoding)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, subscribe(dev, events, every, encoding));
}

static int rec_event_next(rdc_dev *dev, struct rdc_event *ev, uint32_t *buf,
			  size_t cap, int timeout_ms)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, event_next(dev, ev, buf, cap, timeout_ms));
}

static int rec_hist_open(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
			 uint32_t h, uint32_t flags)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, hist_open(dev, x, y, w, h, flags));
}

static int rec_hist_read(rdc_dev *dev, uint64_t first, uint32_t max,
			 struct rdc_history_entry *e, uint32_t *n,
			 uint64_t *count, uint64_t *dropped)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r,
			 hist_read(dev, first, max, e, n, count, dropped));
}

static int rec_hist_set(rdc_dev *dev, uint32_t what, uint32_t value)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, hist_set(dev, what, value));
}

static int rec_hist_close(rdc_dev *dev)
{
	struct rdc_server_rec *r = dev->priv;

	return REC_INNER(dev, r, hist_close(dev));
}

/* The template of every recorder's table (rec_table). */
static const struct rdc_backend rdc_backend_rec = {
	.scheme = "sim",
	.close = rec_be_close,
	.reg_read = rec_reg_read,
	.reg_write = rec_reg_write,
	.vram_read = rec_vram_read,
	.vram_write = rec_vram_write,
	.wait = rec_wait,
	.step = rec_step,
	.frame_grab = rec_frame_grab,
	.pins_set = rec_pins_set,
	.pins_get = rec_pins_get,
	.pins_wait = rec_pins_wait,
	/*
	 * No pins_get or pins_wait: the core reads PINS and waits through
	 * reg_read and wait, which are recorded (the inner pins_wait would
	 * move time behind the trace's back; fbdev:'s reads the GPIO lines,
	 * the same levels as PINS).
	 */
	.submit = rec_submit,
	.subscribe = rec_subscribe,
	.event_next = rec_event_next,
	.hist_open = rec_hist_open,
	.hist_read = rec_hist_read,
	.hist_set = rec_hist_set,
	.hist_close = rec_hist_close,
};

/* ---- The client's recorder (rdc.h) ---------------------------------------- */

/*
 * The STATE record: where the device is as the recording starts, read
 * through its own backend before the recorder wraps it (none of it is the
 * client's).  Work the DP still has queued runs first (a wait for it to
 * go idle, as rdc_idle_wait's), so that the start is a point where the
 * DP has nothing in hand: a kernel's chip on a stepped clock keeps the
 * console's commands queued until somebody waits.  Then the core's state
 * (the backend's resume_get, where it has one), the registers of
 * rec_state_regs, the CLUT and VRAM, deflated.
 */
static int rec_state_put(struct rdc_server_rec *r, rdc_dev *dev, uint32_t vram)
{
	const struct rdc_backend *be = dev->be;
	struct rdc_wait w = { .needs_dp = true };
	struct rdc_hw_resume hs;
	uint32_t what = 0, v, clut_index = 0, regs[REC_STATE_REGS][2];
	uint8_t *img = NULL, *z = NULL, b[REC_STATE_CORE_LEN];
	uLongf zlen;
	int ret = 0;

	w.term[0].kind = RDC_WAIT_TEST_EQ;
	w.term[0].reg = RDC_REG_STATUS;
	w.term[0].mask = RDC_STATUS_IDLE_MASK | RDC_STATUS_FIFO_EMPTY;
	w.term[0].value = RDC_STATUS_FIFO_EMPTY;
	w.budget = RDC_WAIT_BUDGET_DEFAULT;
	if (be->wait)
		(void)be->wait(dev, &w); /* a halted DP is part of the state */
	if (be->resume_get && !be->resume_get(dev, &hs))
		what |= REC_STATE_CORE;
	for (size_t i = 0; i < REC_STATE_REGS && !ret; i++) {
		regs[i][0] = rec_state_regs[i];
		ret = be->reg_read(dev, rec_state_regs[i], &regs[i][1]);
		if (rec_state_regs[i] == RDC_REG_CLUT_INDEX)
			clut_index = regs[i][1];
	}
	if (ret)
		return ret;

	b[0] = REC_STATE;
	rdc_proto_put64(b + 1, what & REC_STATE_CORE ? hs.now : 0);
	rdc_proto_put32(b + 9, what);
	rec_put(r, b, 13);
	if (what & REC_STATE_CORE) {
		rdc_proto_put64(b, hs.now);
		rdc_proto_put64(b + 8, hs.frame_start);
		rdc_proto_put64(b + 16, hs.frame_count);
		rdc_proto_put64(b + 24, hs.perf.busy);
		rdc_proto_put64(b + 32, hs.perf.stall);
		rdc_proto_put64(b + 40, hs.perf.pixels);
		rdc_proto_put32(b + 48, hs.perf.cmds);
		rdc_proto_put32(b + 52, hs.perf.last_cycles);
		rdc_proto_put32(b + 56, hs.perf.last_opcode);
		rdc_proto_put32(b + 60, hs.fence);
		rdc_proto_put32(b + 64, hs.irq_status);
		rdc_proto_put32(b + 68, hs.err_code);
		rdc_proto_put32(b + 72, hs.err_info);
		rdc_proto_put32(b + 76, hs.open_row);
		rdc_proto_put32(b + 80,
				(hs.scanning ? REC_STATE_SCANNING : 0) |
					(hs.dp_active ? REC_STATE_DP_ACTIVE :
							0) |
					(hs.gamma ? REC_STATE_GAMMA : 0));
		for (size_t i = 0; i < REC_STATE_INFORCE; i++)
			rdc_proto_put32(b + 84 + 4 * i,
					*rec_state_inforce(&hs, i));
		rdc_proto_put32(b + 152, hs.perf.culled);
		rec_put(r, b, REC_STATE_CORE_LEN);
	}
	rdc_proto_put32(b, (uint32_t)REC_STATE_REGS);
	rec_put(r, b, 4);
	for (size_t i = 0; i < REC_STATE_REGS; i++) {
		rdc_proto_put32(b, regs[i][0]);
		rdc_proto_put32(b + 4, regs[i][1]);
		rec_put(r, b, 8);
	}
	/* CLUT_DATA reads step CLUT_INDEX: from 0, then put it back */
	rdc_proto_put32(b, REC_STATE_CLUT);
	rec_put(r, b, 4);
	ret = be->reg_write(dev, RDC_REG_CLUT_INDEX, 0);
	for (uint32_t i = 0; i < REC_STATE_CLUT && !ret; i++) {
		ret = be->reg_read(dev, RDC_REG_CLUT_DATA, &v);
		rdc_proto_put32(b, v);
		rec_put(r, b, 4);
	}
	if (!ret)
		ret = be->reg_write(dev, RDC_REG_CLUT_INDEX, clut_index);

	zlen = compressBound(vram);
	img = ret ? NULL : malloc(vram);
	z = img ? malloc(zlen) : NULL;
	if (!ret && !z)
		ret = RDC_E_NOMEM;
	for (uint32_t a = 0; !ret && a < vram; a += RDC_MIN(vram - a, 1u << 20))
		ret = be->vram_read(dev, a, img + a,
				    RDC_MIN(vram - a, 1u << 20));
	if (!ret && compress2(z, &zlen, img, vram, 1) != Z_OK)
		ret = RDC_E_NOMEM;
	if (!ret) {
		rdc_proto_put32(b, (uint32_t)zlen);
		rec_put(r, b, 4);
		rec_put(r, z, zlen);
		rec_sync(r);
	}
	free(img);
	free(z);
	return ret;
}

int rdc_record_start(rdc_dev *dev, const char *path)
{
	struct rdc_server_rec *r;
	uint32_t vram = 0;
	int ret;

	rdc_err_detail_clear();
	if (!dev || !path || !*path)
		return rdc_err_detail(RDC_E_INVAL, "rdc_record_start: %s",
				      !dev ? "no device" : "no file name");
	if (rec_of(dev))
		return rdc_err_detail(RDC_E_BUSY,
				      "%s: the device is already recorded "
				      "(rdc_record_stop ends it)",
				      path);
	/* before the recorder: this read is not the client's */
	ret = dev->be->reg_read(dev, RDC_REG_VRAM_SIZE, &vram);
	if (ret)
		return ret;
	if (!vram || vram > REC_MAX_VRAM_WRITE)
		return rdc_err_detail(RDC_E_PROTO,
				      "%s: the device reports %u bytes of "
				      "VRAM",
				      path, vram);
	r = rec_open(path, vram, REC_VERSION_STATE,
		     rdc_sim_hw(dev) ? 0 : REC_F_UNTIMED, &ret);
	if (!r)
		return ret;
	ret = rec_state_put(r, dev, vram);
	if (ret) {
		rdc_server_rec_close(r, NULL);
		return ret;
	}
	if (r->err) {
		ret = rdc_err_detail(r->err, "%s: %s", path, strerror(errno));
		rdc_server_rec_close(r, NULL);
		return ret;
	}
	r->owned = true;
	rdc_server_rec_attach(r, dev);
	return 0;
}

int rdc_record_stop(rdc_dev *dev)
{
	struct rdc_server_rec *r = rec_of(dev);

	if (!r || !r->owned)
		return rdc_err_detail(RDC_E_INVAL,
				      "rdc_record_stop: the device is not "
				      "recorded (rdc_record_start)");
	return rdc_server_rec_close(r, dev);
}
