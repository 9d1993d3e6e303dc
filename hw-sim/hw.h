/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The simulated RDC-1 chip: register file, VRAM and its bus, CLUT, CRTC with
 * scanout and cursor, command FIFO and ring, interrupts, pins, counters, and
 * the run loop that advances simulated time.
 *
 * The caller owns every byte of memory: struct rdc_hw, VRAM and the two
 * XRGB8888 frame buffers are handed in; the chip never allocates.  All
 * state lives in the struct; nothing is global; the same register writes
 * and commands give the same frames and cycle counts on every host.
 *
 * Three kinds of caller:
 *  - the host (librdc's sim backend, the kernel driver): rdc_hw_read/write,
 *    rdc_hw_vram_read/write, rdc_hw_run_until;
 *  - the display processor (firmware-model/): the "DP port" below;
 *  - tests: everything, plus the trace hook.
 */
#ifndef RDC_HW_H
#define RDC_HW_H

/*
 * struct rdc_hw and the DP port are the core's own: hosts see the chip
 * through rdc_chip.h, where it is opaque.  The core's sources and its
 * unit tests say so before they include this.
 */
#ifndef RDC_CORE_INTERNAL
#error "hw.h is private to hw-sim/ and firmware-model/: include rdc_chip.h"
#endif

/* the types and host waits a server of the chip sees, and their documentation */
#include "rdc_chip.h"
#include "rdc_base.h"
#include "rdc_regs.h"

struct rdc_hw;

/*
 * The display processor as the chip sees it (firmware-model/ fills this
 * in with rdc_dp_attach).  The chip calls run() from its run loop.
 */
struct rdc_dp_ops {
	/* Chip reset: drop any command in progress and reset drawing state. */
	void (*reset)(void *dp);
	/*
	 * Execute from hw->now.  Returns when the DP cannot progress, or once
	 * hw->now >= until (a command in progress finishes first, so now may
	 * pass until by at most one command).  The return value is the
	 * earliest simulated time at which the DP could progress without the
	 * host doing anything (a vblank or line it waits for), or RDC_NEVER
	 * if it waits for the host (empty queues, full RDATA, halted).
	 */
	uint64_t (*run)(void *dp, uint64_t until);
};

/* CRTC working state (what was latched at the last vblank). */
struct rdc_crtc {
	struct rdc_timing shadow, cur;		   /* registers / in force */
	uint32_t fb_base, fb_stride, fb_format;	   /* shadows */
	uint32_t cur_base, cur_stride, cur_format; /* latched */
	uint32_t line_compare;
	uint32_t preset;
	uint32_t cursor_base, cursor_pos, cursor_fg, cursor_bg;
	uint32_t cursor_ctrl;		      /* CURSOR_CTRL */
	uint8_t cursor_img[RDC_CURSOR_BYTES]; /* latched at vblank (2 bpp) */
	/* latched at vblank: CURSOR_CTRL, CURSOR_BASE, CONTROL.GAMMA_EN */
	uint32_t cur_cursor_ctrl, cur_cursor_base;
	int cur_gamma;
	/*
	 * A mode is in force and scanout is enabled.  While it is not,
	 * next_line_time and lpen_time are RDC_NEVER: a test of either
	 * against a time needs no test of this.
	 */
	int running;
	uint64_t frame_start;  /* time line 0 of this frame starts */
	uint64_t frame_cycles; /* core cycles a frame lasts */
	uint32_t next_line;    /* next line whose start is not yet processed */
	/*
	 * its start time (RDC_NEVER if stopped), or a raster-list WAIT's
	 * column before it (rl_mid): the next scanout event
	 */
	uint64_t next_line_time;
	uint64_t fetch_end; /* end of the current scanout fetch window */
	uint64_t frame_count;
	int mode_valid;	  /* `cur` holds a mode that passed validation */
	int in_vblank;	  /* beam in vertical blanking (TE pin level) */
	int shadow_dirty; /* timing/format shadows written since the latch */
	int mode_pending; /* `pending` goes in force at the next frame start */
	struct rdc_timing pending;
	/*
	 * next_line's start from frame_start, line_q + line_r / line_den
	 * cycles, and one line of `cur` as much: stepped a line at a time
	 * rather than divided out (crtc.c's line_offset, exactly).
	 */
	uint64_t line_q, line_r, step_q, step_r, line_den;
	/*
	 * Raster list: the registers, their latched copies, the next entry,
	 * entries fetched this frame, the line and column the list waits
	 * for (RDC_NEVER_LINE: done for this frame), RASTER_STATUS.ERROR,
	 * and whether it changed what converting a line reads this frame.
	 * A WAIT for a column of the current line is the next scanout event
	 * (rl_mid, in next_line_time; the line's start in rl_line_start),
	 * and the line's bytes as fetched at its start are kept,
	 * which the columns from there on are converted from again when a
	 * CLUT entry changes (rl_line_n: the line they are of, or
	 * RDC_NEVER_LINE).
	 */
	uint32_t raster_base, raster_ctrl;
	uint32_t cur_raster_base, cur_raster_ctrl;
	uint64_t rl_addr;
	uint32_t rl_count, rl_wait, rl_wait_x;
	int rl_error, rl_touched;
	int rl_mid; /* next_line_time is the column's, not a line's */
	uint64_t rl_next_line; /* then: the next line's start */
	uint64_t rl_line_start;
	uint32_t rl_line_n;
	uint8_t rl_line[RDC_CRTC_MAX_DISPLAY * 4];
	/*
	 * Light pen: LPEN_POS, LPEN_CTRL, LPEN_LATCH, STATUS.LPEN, the line
	 * whose fetch looks at the pen's pixel (RDC_NEVER_LINE: off) and the
	 * strobe to come on the current line (RDC_NEVER: none).
	 */
	uint32_t lpen_pos, lpen_ctrl, lpen_latch, lpen_line;
	int lpen_hit;
	uint64_t lpen_time;
};

/* The DRAM bus's state for the cost model (see bus.h). */
struct rdc_bus {
	uint32_t open_row; /* DRAM row of the last access; ~0u: none */
};

struct rdc_hw {
	/* configuration and memory handed in */
	uint8_t *vram;
	uint32_t vram_size;
	uint32_t core_hz;
	uint32_t *frame[2]; /* two XRGB8888 buffers, frame_cap pixels each */
	uint32_t frame_cap;
	unsigned int frame_back; /* buffer scanout is filling */

	uint64_t now; /* simulated time, core cycles */

	/* registers */
	uint32_t control, irq_status, irq_enable;
	uint32_t err_code, err_info;
	uint32_t pins_in;	/* RESET_N, BL_EN as driven from outside */
	uint32_t perf_hi_snap;	/* HI half snapshotted by a LO read */
	uint32_t perf_snap_reg; /* the HI register perf_hi_snap belongs to */
	int in_reset;		/* RESET_N held low */

	struct rdc_bus bus;
	struct rdc_crtc crtc;

	uint32_t clut[RDC_CLUT_ENTRIES];	/* in force, 0x00RRGGBB */
	uint32_t clut_shadow[RDC_CLUT_ENTRIES]; /* latched-mode writes */
	uint32_t clut_dirty; /* shadow has entries to apply at vblank */
	uint32_t clut_index;

	/* command FIFO (host -> DP) and readback FIFO (DP -> host) */
	uint32_t fifo[RDC_FIFO_DEPTH];
	uint32_t fifo_head, fifo_count, fifo_lowwater;
	uint32_t rdata[RDC_RDATA_DEPTH];
	uint32_t rdata_head, rdata_count;
	uint32_t ring_base, ring_size, ring_head, ring_tail;
	uint32_t fence;
	int ring_err; /* ring programming invalid: yields no words */

	struct rdc_perf perf;

	/* the display processor */
	const struct rdc_dp_ops *dp_ops;
	void *dp;
	uint32_t dp_status; /* RDC_STATUS_DP_* bits the DP reports */
	/*
	 * Set to 1 by a host CONTROL write with RDC_CONTROL_RESUME; the DP
	 * leaves its halted state when it sees it and clears it.
	 */
	uint32_t dp_resume;

	/* listeners */
	rdc_frame_fn frame_fn;
	void *frame_ctx;

	/* the last complete frame: frame[frame_back ^ 1] */
	int have_frame;
	uint32_t front_w, front_h;

	/*
	 * Scanout on demand (rdc_hw_set_on_demand): with it on and nobody
	 * looking (`lazy`: no consumer attached, no frame listener), lines
	 * are fetched and timed but not converted.  A buffer's frame stays
	 * showable (frame_ok) while nothing it fetched and has not
	 * converted, lines [pend_lo, pend_hi), has changed since: such lines
	 * are converted when somebody looks.  A write to VRAM bytes
	 * [scan_lo, scan_hi) (what pending lines read, the ARGB8888 cursor
	 * included), or to a register, CLUT entry or pin that converting them
	 * reads, drops them and their frame instead (the write barrier);
	 * scan_lo == scan_hi: nothing pending, one test on the write paths.
	 */
	bool on_demand, lazy;
	uint32_t consumers;
	bool frame_ok[2];
	uint32_t pend_lo[2], pend_hi[2];
	uint64_t scan_lo, scan_hi;

	rdc_trace_fn trace_fn; /* optional */
	void *trace_ctx;

	/*
	 * the VRAM write watcher (rdc_hw_set_vram_hook), optional, and the
	 * bytes [lo, hi) it watches (a CRTC register write or a reset widens
	 * them to everything until the watcher narrows them again)
	 */
	rdc_vram_hook_fn vram_hook;
	void *vram_hook_ctx;
	uint32_t vram_watch_lo, vram_watch_hi;

	/* the host's poll hook (rdc_hw_set_poll), optional */
	void (*poll_fn)(void *ctx);
	void *poll_ctx;
	uint32_t poll_count;
	/*
	 * Levels as last reported, kept with or without a tracer so that
	 * RDC_TRACE_PINS / RDC_TRACE_DP fire on changes only.
	 */
	uint32_t pins_out; /* RDC_PIN_* */
	int dp_active;	   /* the DP has work or is inside a command */
};

/* The timing of a preset; 0, or -1 for an unknown preset. */
int rdc_preset_timing(uint32_t preset, struct rdc_timing *t);

/*
 * ---- DP port: how the display processor reaches the chip ---------------- The
 * DP touches VRAM, the queues, the CLUT and the IRQs only through these.  Every
 * VRAM access is charged to simulated time by the bus model (bus.h) at hw->now
 * and advances hw->now; scanout is brought up to date first, so the access
 * races the beam exactly as the model says.
 */

/*
 * Access kinds for rdc_port_span/rdc_port_column; OR in the PARTIAL flags when
 * the first/last byte is only partly written (sub-byte pixels).
 */
#define RDC_BUS_READ	     0u
#define RDC_BUS_WRITE	     1u
#define RDC_BUS_RMW	     2u /* read then write every beat (ROP reads dst) */
#define RDC_BUS_KIND_MASK    3u
#define RDC_BUS_HEAD_PARTIAL 4u
#define RDC_BUS_TAIL_PARTIAL 8u

/*
 * The DP accesses bytes [addr, addr + len) of VRAM.  Returns a pointer to
 * them for the DP to read or write directly, valid until the next port call,
 * or NULL (nothing charged) if len is 0 or the range leaves VRAM.  The
 * access is charged in bursts; writes become visible to scanout when the
 * span completes (scanout fetches that the span waited behind see the old
 * bytes).
 */
uint8_t *rdc_port_span(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		       unsigned int kind);

/*
 * `count` accesses of `len` bytes each, `stride` bytes apart from addr (a
 * vertical run of pixels).  Returns the pointer to the first, or NULL
 * (nothing charged) if any leaves VRAM.  Charged as `count` separate
 * single-burst accesses (each one burst even if longer than a burst; the
 * PARTIAL flags apply to every element).  The access kind 3 is charged as
 * RDC_BUS_RMW.
 */
uint8_t *rdc_port_column(struct rdc_hw *hw, uint32_t addr, uint32_t stride,
			 uint32_t count, uint32_t len, unsigned int kind);

/*
 * A read of [raddr, raddr + len) then an access of `kind` to [waddr, waddr
 * + len), charged exactly as the two rdc_port_span calls would be (a copy
 * from one place of VRAM to another).  *src gets the read's pointer (NULL
 * if it failed: nothing charged, nothing written); the write's pointer is
 * returned (NULL if it failed, the read still charged).  Both stay valid
 * until the next port call, so the bytes can move without staging.
 */
uint8_t *rdc_port_span_pair(struct rdc_hw *hw, uint32_t raddr, uint32_t waddr,
			    uint32_t len, unsigned int kind,
			    const uint8_t **src);

/*
 * A run of accesses for rdc_port_runs: count == 1 is the span
 * rdc_port_span(addr, len), count > 1 the column rdc_port_column(addr,
 * stride, count, len).
 */
struct rdc_port_run {
	uint32_t addr, len, count;
};

/*
 * Charge runs r[0], r[1], ... in order, each exactly as its rdc_port_span
 * or rdc_port_column call would be, for as long as no scanout event (a
 * fetch window, a line start) can fall inside one: a run is charged
 * whole or not at all.  *done is set to how many runs were charged, and
 * the return value p addresses their bytes as p + addr (valid until the
 * next port call).  The caller writes their pixels (no fetch can have
 * seen any of them), passes the next run to rdc_port_span /
 * rdc_port_column itself (which wait for scanout, or refuse a run that
 * leaves VRAM), and calls again with the rest.  This is the plain form
 * of the port window's runs (rdc_port_window_runs), which charge as it
 * does, and what tests hold them against.
 */
uint8_t *rdc_port_runs(struct rdc_hw *hw, const struct rdc_port_run *r,
		       uint32_t n, uint32_t stride, unsigned int kind,
		       uint32_t *done);

/*
 * rdc_port_runs for a DP loop that makes its runs one at a time (lines):
 * rdc_port_window_open brings scanout up to hw->now and takes the bus
 * state into w; rdc_port_window_charge charges run r exactly as
 * rdc_port_runs would and returns true (its bytes are at w->vram +
 * r->addr, to be written before the next charge), or charges nothing and
 * returns false where rdc_port_runs would stop; rdc_port_window_close
 * puts the time and open row back.  No other port call may come between
 * open and close: a refused run goes, after the close, to rdc_port_span /
 * rdc_port_column, and a new window is opened after it.
 */
struct rdc_port_window {
	uint8_t *vram;
	uint64_t t, lim;
	uint32_t row;
	uint64_t part;	/* RDC_PARTED_RUN, _WRITE: charged up to here */
	uint8_t parted; /* a _through call stopped in a row: RDC_PARTED_* */
	bool open;	/* false: a fetch window holds the bus now */
	bool scan_hit;	/* a write reached lines scanout has not converted */
};

#define RDC_PARTED_RUN	 1u /* the refused row's first run, up to part */
#define RDC_PARTED_READ	 2u /* a pair's read charged, its write not */
#define RDC_PARTED_WRITE 3u /* a pair's read charged, its write to part */

/*
 * rdc_port_window_open is inline, as the DP opens a window for every
 * glyph: the call (rdc_port_window_sync: the poll, scanout brought up
 * to hw->now) only with a poll hook or a line start due.
 */
void rdc_port_window_sync(struct rdc_hw *hw);

static inline void rdc_port_window_open(struct rdc_hw *hw,
					struct rdc_port_window *w)
{
	const struct rdc_crtc *c = &hw->crtc;

	if (hw->poll_fn || c->next_line_time <= hw->now)
		rdc_port_window_sync(hw);
	w->vram = hw->vram;
	w->t = hw->now;
	w->row = hw->bus.open_row;
	w->lim = c->next_line_time;
	w->open = w->t >= c->fetch_end;
	w->scan_hit = false;
	w->parted = 0;
}

/*
 * rdc_port_window_open for a caller whose first act in the window is an
 * access: where a fetch holds the bus now, the window opens at its end,
 * the wait a stall, as that access's own wait in rdc_bus_charge would be
 * (the row it finds open is the fetch's either way).  Not with a poll
 * hook or a VRAM watcher, which the port calls serve.  A command that
 * begins in a fetch then draws in the window rather than through the
 * port calls.
 */
static inline void rdc_port_window_open_busy(struct rdc_hw *hw,
					     struct rdc_port_window *w)
{
	const struct rdc_crtc *c = &hw->crtc;

	rdc_port_window_open(hw, w);
	if (w->open || hw->poll_fn || hw->vram_hook)
		return;
	hw->perf.stall += c->fetch_end - w->t;
	w->t = c->fetch_end;
	w->open = true;
}

bool rdc_port_window_charge(const struct rdc_hw *hw, struct rdc_port_window *w,
			    const struct rdc_port_run *r, uint32_t stride,
			    unsigned int kind);
void rdc_port_window_close(struct rdc_hw *hw, const struct rdc_port_window *w);
/*
 * The DP's next burst, from w->t, cannot end by the window's limit, the
 * next scanout event: take that event as the burst would wait for it
 * (bus.h) and return true.  When it fetches, w->t becomes the end of the
 * fetch window (the wait counts as stall cycles) and w->row its open row;
 * w->lim becomes the event after it, which may come before w->t (a fetch
 * longer than a line: then nothing fits and the window must be closed).
 * The burst is then charged from there as any other.  False, nothing
 * done, where rdc_port_window_cross would refuse the event.
 */
bool rdc_port_window_event(struct rdc_hw *hw, struct rdc_port_window *w);
/*
 * Run r, which the window refused because a scanout event falls in it,
 * charged as the port call after the window's close would charge it
 * (rdc_port_span, or rdc_port_column with `stride`), the window staying
 * open: its bytes are at w->vram + r->addr, and w->t, w->lim and w->open
 * are the reopened window's.  False, nothing charged, where the close and
 * the port call must be made: the event does more than fetch a line
 * (rdc_crtc_next_quiet), a VRAM watcher is set, or r leaves VRAM.  With
 * w->parted RDC_PARTED_RUN or _WRITE, r is the run a _through call
 * stopped in: its rest is charged from w->part, after the close, and
 * true returned.
 */
bool rdc_port_window_cross(struct rdc_hw *hw, struct rdc_port_window *w,
			   const struct rdc_port_run *r, uint32_t stride,
			   unsigned int kind);
/*
 * rdc_port_window_charge for the spans [addr + i * stride, + len), i = 0,
 * 1, ... count - 1, as RDC_BUS_WRITE: how many of them, from the first,
 * it charged.
 */
uint32_t rdc_port_window_rows(const struct rdc_hw *hw,
			      struct rdc_port_window *w, uint32_t addr,
			      uint32_t len, uint32_t stride, uint32_t count);
/*
 * rdc_port_window_rows for a caller that writes the rows it is given
 * only after the call, and then hands the first row refused to
 * rdc_port_window_cross: while no frame is looked at (scanout on demand
 * with no consumer), nothing reads VRAM at a line start that only
 * fetches, so the rows go on through such line starts, the row each one
 * falls in charged across it as rdc_port_window_cross charges it.  The
 * cycles, the row left open and the write barrier are what the calls
 * one event at a time give.  A row stopped at an event the window
 * cannot take stays charged in part (w->parted, RDC_PARTED_RUN): the
 * caller's rdc_port_window_cross goes on from there.
 */
uint32_t rdc_port_window_rows_through(struct rdc_hw *hw,
				      struct rdc_port_window *w, uint32_t addr,
				      uint32_t len, uint32_t stride,
				      uint32_t count);
/*
 * rdc_port_window_rows_through for a caller that has made its tests
 * (the window open, no VRAM watcher, count >= 2 rows of len > 0 bytes a
 * whole number of DRAM rows apart, all in VRAM) and costed the first row
 * from w->row (c0) and each other (c1), as rdc_port_window_rows_all
 * has.
 */
uint32_t rdc_port_window_rows_costed(struct rdc_hw *hw,
				     struct rdc_port_window *w, uint32_t addr,
				     uint32_t len, uint32_t stride,
				     uint32_t count, uint64_t c0, uint64_t c1);
/*
 * rdc_port_runs in the window w, for a caller that writes the runs it is
 * given only after the call, and then hands the first run refused to
 * rdc_port_window_cross: the runs that end by the window's limit, and,
 * while no frame is looked at, on through the line starts that only
 * fetch as rdc_port_window_rows_through goes (a span a line start falls
 * in charged across it, or stopped in: w->parted, RDC_PARTED_RUN).  How
 * many of them, from the first, it charged; the VRAM watcher, if any, is
 * told of them as rdc_port_runs tells it.
 */
uint32_t rdc_port_window_runs(struct rdc_hw *hw, struct rdc_port_window *w,
			      const struct rdc_port_run *r, uint32_t n,
			      uint32_t stride, unsigned int kind);
/*
 * rdc_port_window_pair for the pairs (raddr + i * rstep, waddr + i * wstep),
 * i = 0, 1, ... count - 1, each len bytes: how many of them, from the
 * first, it charged.  Calls no VRAM watcher: with one set, a caller
 * charges pair by pair.
 */
uint32_t rdc_port_window_pairs(const struct rdc_hw *hw,
			       struct rdc_port_window *w, uint32_t raddr,
			       uint32_t waddr, uint32_t len, int64_t rstep,
			       int64_t wstep, uint32_t count,
			       unsigned int kind);
/*
 * rdc_port_window_pairs as rdc_port_window_rows_through goes on from
 * rdc_port_window_rows, for a caller that moves the pairs' bytes after
 * the call, in their order: the pair a line start falls in is charged
 * as the caller's rdc_port_window_cross (the read), then
 * rdc_port_window_charge or _cross (the write) would.  Where it stops in
 * a pair, w->parted says how far: RDC_PARTED_RUN, its read charged up to
 * w->part; RDC_PARTED_READ, its read charged; RDC_PARTED_WRITE, its
 * read charged and its write up to w->part.  Both steps the same whole
 * number of DRAM rows and every pair in VRAM; else, or with a VRAM
 * watcher, rdc_port_window_pairs.
 */
uint32_t rdc_port_window_pairs_through(struct rdc_hw *hw,
				       struct rdc_port_window *w,
				       uint32_t raddr, uint32_t waddr,
				       uint32_t len, int64_t rstep,
				       int64_t wstep, uint32_t count,
				       unsigned int kind);

/*
 * Does a scanout event (a line start, a light-pen strobe) fall at or
 * before t?  If not, rdc_crtc_catch_up(hw, t) does nothing, and callers
 * on hot paths skip the call.
 */
static inline bool rdc_crtc_due(const struct rdc_hw *hw, uint64_t t)
{
	return hw->crtc.next_line_time <= t || hw->crtc.lpen_time <= t;
}

/*
 * Charge `cycles` of DP-internal work (decode, setup); no bus use.
 * Inline because the DP charges a decode for every command: with no poll
 * hook and no scanout event due by the end, time just moves on (as
 * rdc_hw_idle_to would, rdc_crtc_due false); else the call that polls
 * and catches scanout up.
 */
void rdc_port_compute_slow(struct rdc_hw *hw, uint32_t cycles);

static inline void rdc_port_compute(struct rdc_hw *hw, uint32_t cycles)
{
	uint64_t t = hw->now + cycles;

	if (hw->poll_fn || rdc_crtc_due(hw, t)) {
		rdc_port_compute_slow(hw, cycles);
		return;
	}
	hw->now = t;
}

/* Command sources, in the order the DP takes a new command from them. */
#define RDC_SRC_FIFO 0u
#define RDC_SRC_RING 1u

/* Words waiting in a source (0 for a ring that is disabled or in error). */
uint32_t rdc_port_cmd_avail(struct rdc_hw *hw, unsigned int src);
/*
 * Pop up to n words from src into dst, charging the fetch (FIFO: 1 cycle a
 * word; ring: a VRAM read through the bus model).  Returns words popped.
 */
uint32_t rdc_port_cmd_pop(struct rdc_hw *hw, unsigned int src, uint32_t *dst,
			  uint32_t n);
/*
 * The FIFO's next command whole, header and arguments, when all its words
 * are waiting, it announces no more than max_args and one pop of them all
 * does what popping the header and then the rest does (the same cycles,
 * interrupts and scanout events: not when the header alone would cross
 * the low-water mark, a scanout event falls within the fetch, or the FIFO
 * is traced).  Returns the words popped, or 0 (nothing popped): pop the
 * header, then the rest.
 */
uint32_t rdc_port_cmd_pop_whole(struct rdc_hw *hw, uint32_t *dst,
				uint32_t max_args);

/* Readback FIFO: free words, and push up to n (returns words pushed). */
uint32_t rdc_port_rdata_space(struct rdc_hw *hw);
uint32_t rdc_port_rdata_push(struct rdc_hw *hw, const uint32_t *w, uint32_t n);

/* CLUT write from the command stream (honours RDC_CONTROL_CLUT_LATCH). */
void rdc_port_clut_write(struct rdc_hw *hw, uint32_t index, uint32_t rgb);

/*
 * REG_WRITE from the command stream: 0, or -1 if the register may not be
 * written from a command (queues, control, reset).
 */
int rdc_port_reg_write(struct rdc_hw *hw, uint32_t reg, uint32_t val);

/* Raise interrupt status bits; record an error (sets RDC_IRQ_ERROR). */
void rdc_port_irq(struct rdc_hw *hw, uint32_t bits);
void rdc_port_error(struct rdc_hw *hw, uint32_t code, uint32_t info);
void rdc_port_fence(struct rdc_hw *hw, uint32_t value);

/*
 * When the next vertical blanking starts / the beam next starts `line`
 * (RDC_NEVER while scanout is stopped or line >= V_TOTAL): always a time after
 * hw->now, so a vblank or line start at hw->now itself has passed.
 */
uint64_t rdc_port_next_vblank(struct rdc_hw *hw);
uint64_t rdc_port_next_line(struct rdc_hw *hw, uint32_t line);

/* Move simulated time to t (>= now) with the DP idle; scanout catches up. */
void rdc_port_idle_until(struct rdc_hw *hw, uint64_t t);

/* Connect the display processor (rdc_dp_init does). */
void rdc_hw_set_dp(struct rdc_hw *hw, const struct rdc_dp_ops *ops, void *dp);

/* Does a write to [addr, end) concern the watcher? */
static inline bool rdc_vram_watched(const struct rdc_hw *hw, uint32_t addr,
				    uint64_t end)
{
	return addr < hw->vram_watch_hi && end > hw->vram_watch_lo;
}

#endif /* RDC_HW_H */
