/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The simulated RDC-1 as a program sees it that runs the chip without
 * owning its insides: an opaque struct rdc_hw and the host calls a server
 * of the chip needs (rdcd, through librdc's sim: handle and rdc_server.h):
 * simulated time, register reads, the run loop, host waits, the pins, the
 * last frame, the timing in force, and the frame, trace and poll hooks.
 *
 * hw.h, the chip's whole interface, includes this header: the types here
 * are the chip's own, and the calls declared again below are checked
 * against hw.h's declarations wherever both are seen.  Self-contained for
 * the kernel, freestanding builds and user space, where librdc installs
 * it (no unprefixed macros); the structures may change in any release.
 */
#ifndef RDC_CHIP_H
#define RDC_CHIP_H

#ifdef __KERNEL__
#include <linux/types.h>
#else
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define RDC_DEFAULT_CORE_HZ 100000000u
/* A host wait's default budget: ten simulated seconds at the default clock */
#define RDC_WAIT_BUDGET_DEFAULT (10ull * RDC_DEFAULT_CORE_HZ)

struct rdc_hw;

/*
 * Called with each complete frame at the start of vertical blanking;
 * frame_number counts from 0 (FRAME_COUNT reads frame_number + 1 then).
 * Without a listener the chip skips converting frames that are replaced
 * before anyone could look at them with rdc_hw_frame (a long
 * rdc_hw_run_until); with one, every frame is converted and handed over
 * (but for one that scanout on demand dropped before the listener came:
 * see rdc_hw_set_on_demand).
 */
typedef void (*rdc_frame_fn)(void *ctx, const uint32_t *xrgb, uint32_t width,
			     uint32_t height, uint64_t frame_number);

/*
 * Trace points, for tests, replay logs, waveforms and debugging
 * (rdc_hw_set_trace).  `time` is the simulated cycle the event happens at,
 * also for scanout events processed late (a line start is stamped with its
 * own start time, not with the time the chip caught up to), and the events
 * come in time order.  The signal events fire on changes only:
 *  - PINS: once for every change of the pin levels, TE (high from the
 *    start of line V_DISPLAY to the start of line 0), IRQ (IRQ_STATUS &
 *    IRQ_ENABLE != 0: raised, W1C clear, enable write, reset), RESET_N and
 *    BL_EN (rdc_hw_set_pins); pins that change at the same step (TE and
 *    IRQ at a vblank) come as one event with both bits in b.
 *  - LINE: at every line start, also of frames not converted (a long
 *    rdc_hw_run_until); V_TOTAL of them a frame.
 *  - DP: 1 when the DP takes a command word while idle (or runs on in a
 *    command or display list it was in), 0 when it runs out of work it can
 *    do: queues empty and no command in progress, or halted (DP_EN off and
 *    a reset count too).  A DP stopped in the middle of a command (waiting
 *    for FIFO words, RDATA space, a vblank) stays 1, as STATUS.DP_BUSY.
 *  - FIFO: the command FIFO's level after every push, pop or reset that
 *    changes it (a pop is stamped at the end of its fetch).
 */
enum rdc_trace_event {
	RDC_TRACE_REG_READ,   /* a = offset, b = value read */
	RDC_TRACE_REG_WRITE,  /* a = offset, b = value written (host) */
	RDC_TRACE_VRAM_WRITE, /* a = address, b = bytes (host aperture) */
	RDC_TRACE_VBLANK,     /* a = frame number (low 32 bits) */
	RDC_TRACE_ERROR,      /* a = enum rdc_err, b = ERR_INFO */
	RDC_TRACE_RESET,      /* chip reset (power-on, SOFT_RESET, RESET_N) */
	RDC_TRACE_PINS, /* a = pin levels (RDC_PIN_*) now, b = pins changed */
	RDC_TRACE_LINE, /* a = beam line starting, b = 1 in vertical blanking */
	RDC_TRACE_DP,	/* a = 1: the DP starts work, 0: it goes idle */
	RDC_TRACE_FIFO, /* a = command FIFO level in words */
};

typedef void (*rdc_trace_fn)(void *ctx, uint64_t time, unsigned int event,
			     uint32_t a, uint32_t b);

/* Timing of one mode, as in the CRTC registers. */
struct rdc_timing {
	uint32_t h_total, h_display, h_sync_start, h_sync_end;
	uint32_t v_total, v_display, v_sync_start, v_sync_end;
	uint32_t pixclk_khz, flags;
};

/*
 * Host waits (hw-sim/wait.c): let the chip run until a register condition
 * holds, the way every host of the core waits (librdc's sim: backend, the
 * kernel driver), so the same waits end at the same cycle everywhere.
 * The wait ends when ANY term holds.  Between checks the chip runs a slice
 * of simulated time that starts at RDC_WAIT_SLICE_FIRST cycles and doubles
 * up to RDC_WAIT_SLICE_MAX; a wait that needs the DP (a fence, the FIFO
 * draining) runs with rdc_hw_run_until_idle, so it ends at the exact
 * cycle the DP ran out of work.
 */
enum rdc_wait_test {
	RDC_WAIT_TEST_NONE,    /* unused term */
	RDC_WAIT_TEST_GE,      /* (reg & mask) >= value, unsigned */
	RDC_WAIT_TEST_WRAP_GE, /* (int32_t)((reg & mask) - value) >= 0 */
	RDC_WAIT_TEST_EQ,      /* (reg & mask) == value */
};

#define RDC_WAIT_TEST_TERMS  2
#define RDC_WAIT_SLICE_FIRST 16u
#define RDC_WAIT_SLICE_MAX   16384u

struct rdc_wait_cond {
	uint32_t test; /* enum rdc_wait_test */
	uint32_t reg, mask, value;
};

struct rdc_hw_wait {
	struct rdc_wait_cond term[RDC_WAIT_TEST_TERMS];
	bool needs_dp;	 /* RDC_HW_WAIT_HALTED if the DP halts */
	uint64_t budget; /* simulated cycles from the start */
	/* progress, set by rdc_hw_wait_begin */
	uint64_t start, slice;
};

enum rdc_hw_wait_result {
	RDC_HW_WAIT_DONE,    /* a term holds */
	RDC_HW_WAIT_MORE,    /* `work` cycles ran: call rdc_hw_wait_run again */
	RDC_HW_WAIT_TIMEOUT, /* the budget ran out */
	RDC_HW_WAIT_HALTED,  /* needs_dp and the DP halted */
};

/* Whether one term holds now (reads the register as the host would). */
bool rdc_hw_cond_holds(struct rdc_hw *hw, const struct rdc_wait_cond *c);
/* Start a wait at hw->now (terms, needs_dp and budget already set). */
void rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);
/*
 * One look at a wait at hw->now, moving no time, in the order every host
 * judges it: DONE if a term holds, else HALTED if it needs the DP, the
 * chip has run since w->start and the DP is halted, else TIMEOUT once
 * w->budget cycles have passed since w->start; RDC_HW_WAIT_MORE: not
 * yet.  rdc_hw_wait_run checks with it; a host that moves time itself
 * (rdcd's paced waits, the driver's) calls it between its own steps.
 */
enum rdc_hw_wait_result rdc_hw_wait_check(struct rdc_hw *hw,
					  const struct rdc_hw_wait *w);
/*
 * Go on with a wait for at most about `work` cycles (RDC_NEVER: until it
 * ends).  Stopping and resuming never changes where the wait ends: a
 * caller that must not hold a lock for long (a kernel spinlock, a daemon
 * serving others) runs it in pieces and gets the same cycle.
 */
enum rdc_hw_wait_result rdc_hw_wait_run(struct rdc_hw *hw,
					struct rdc_hw_wait *w, uint64_t work);

/*
 * The paced clock, as every host that paces the chip runs it (rdcd, the
 * kernel chip host): simulated time follows wall time at `hz` cycles a
 * second from the pair (wall0_ns, sim0).  rdc_pace_target gives the time
 * the chip should have reached at wall time `wall_ns`; a chip at `now`
 * that is more than `lag` cycles behind (a host too slow to keep up) or
 * ahead (work that ran the chip at once) starts the mapping afresh from
 * (wall_ns, now): it keeps the rate and drops the debt, and the target is
 * `now`.  wall0_ns == 0 is a clock not started yet: it starts there.
 */
struct rdc_pace {
	uint64_t wall0_ns, sim0;
};

uint64_t rdc_pace_target(struct rdc_pace *p, uint64_t wall_ns, uint64_t now,
			 uint32_t hz, uint64_t lag);

/* Simulated time: core cycles since power-on. */
uint64_t rdc_hw_now(const struct rdc_hw *hw);
/* The CRTC timing in force (what the last vblank latched). */
void rdc_hw_timing(const struct rdc_hw *hw, struct rdc_timing *t);
/* The timing of a preset; 0, or -1 for an unknown preset. */
int rdc_preset_timing(uint32_t preset, struct rdc_timing *t);

/*
 * Scanout on demand.  The CRTC fetches every line at its time and charges
 * the bus for it whatever the setting, so cycles, tearing, interrupts and
 * TE never depend on it; what it decides is whether fetched lines are
 * converted (format, CLUT, gamma, cursor) into the XRGB8888 frame.
 *
 * Off (after rdc_hw_init and every reset keeps the setting): as before,
 * every frame that anyone could look at is converted as its lines are
 * fetched.  On: lines are converted at their fetch only while a frame
 * consumer is attached or a frame listener is set.  With neither, they
 * wait unconverted, and an idle display costs only the bus bookkeeping:
 *  - a look (rdc_hw_frame, an attach, a listener set) converts the lines
 *    still waiting, bit for bit as at their fetch;
 *  - a change to what a waiting line would show (a write to its VRAM
 *    bytes or the ARGB8888 cursor's, by the DP or the host; a CLUT entry
 *    in force; CURSOR_POS, CURSOR_FG, CURSOR_BG, CONTROL.CURSOR_EN; BL_EN;
 *    a vblank latch that changes the framebuffer, format, gamma, cursor or
 *    CLUT; a mode change; scanout restarted) drops its frame instead:
 *    rdc_hw_frame returns NULL for a dropped frame, and a listener is not
 *    called with one;
 *  - so after an attach, the frame being scanned (if nothing dropped it)
 *    and every one after it are there, and each is bit-identical to the
 *    frame scanout off gives.
 *
 * A consumer is whatever looks at frames: a sink, a frame subscriber, a
 * CRC, a frame grab that must not fail.  Attaches are counted; each
 * detach undoes one.  The kernel chip host turns it on once after
 * rdc_hw_init and attaches for each consumer it has (rdcfb: an open
 * reader or a mapping of VRAM; rdcdrm: a CRC source, a plane's frame
 * read back), under the lock it holds around every call here.  Bytes
 * written behind the chip's back (user space writing a mapping of VRAM)
 * pass no barrier: a host that lets that happen keeps a consumer
 * attached meanwhile, or reports each write with rdc_hw_vram_touched
 * before anything looks again.
 */
void rdc_hw_set_on_demand(struct rdc_hw *hw, bool on);
void rdc_hw_consumer_attach(struct rdc_hw *hw);
void rdc_hw_consumer_detach(struct rdc_hw *hw);
/* Fetched lines are converted as they are fetched (always, when off). */
bool rdc_hw_scanout_watched(const struct rdc_hw *hw);
/* Bytes [addr, addr + len) of VRAM changed outside rdc_hw_vram_write. */
void rdc_hw_vram_touched(struct rdc_hw *hw, uint32_t addr, uint32_t len);

/* Reset values of registers rdc_regs.h gives none for (rdc_hw_reset). */
#define RDC_FIFO_LOWWATER_RESET 64u /* FIFO_LOWWATER after reset */
/* LINE_COMPARE after reset: beyond any V_TOTAL, so RDC_IRQ_LINE never fires */
#define RDC_LINE_COMPARE_RESET RDC_CRTC_MAX_TOTAL
#define RDC_CURSOR_FG_RESET    0x00ffffffu
#define RDC_CURSOR_BG_RESET    0x00000000u
#define RDC_NEVER	       UINT64_MAX /* "no such time" */

struct rdc_hw_config {
	uint32_t vram_size; /* bytes, multiple of 4 */
	uint32_t core_hz;   /* 0 = RDC_DEFAULT_CORE_HZ */
};

/*
 * Performance counters (RDC_REG_PERF_*).  The chip's bus model counts
 * `stall`; the display processor maintains the others (it knows where a
 * command starts and ends and how many pixels it wrote).
 */
struct rdc_perf {
	uint64_t busy;	 /* cycles the DP spent executing commands */
	uint64_t stall;	 /* of which, cycles waiting behind scanout fetches */
	uint64_t pixels; /* pixels written by the DP */
	uint32_t cmds;	 /* commands executed */
	uint32_t last_cycles; /* cycles of the last command */
	uint32_t last_opcode;
	uint32_t culled; /* meshes culled by their RDC_MESH_BOUNDS box */
};

/*
 * A VRAM write is about to land (rdc_hw_set_vram_hook): `count` runs of
 * `len` bytes, `stride` bytes apart from `addr`, by the DP (who = 0) or the
 * host aperture (who = 1), whose bus access ended at `time`.  Called
 * before the bytes change: the DP writes them after the port call that
 * charged them returns and before its next port call; the host's are
 * copied right after the call.  RDC_VRAM_MORE in `who`: another run of
 * the same port call (rdc_port_runs, a port window's runs), whose runs
 * are all written after it returns.  Nothing may be written from the hook.
 */
#define RDC_VRAM_BY_DP	 0u
#define RDC_VRAM_BY_HOST 1u
#define RDC_VRAM_MORE	 2u
typedef void (*rdc_vram_hook_fn)(void *ctx, uint64_t time, uint32_t addr,
				 uint32_t len, uint32_t count, uint32_t stride,
				 unsigned int who);

/* ---- Host side ----------------------------------------------------------- */

/*
 * Sizes of the memory the caller hands to rdc_hw_init: VRAM of cfg->vram_size
 * bytes and two frame buffers of frame_cap pixels each; frame_cap must hold
 * the largest mode the host will set (RDC_CRTC_MAX_DISPLAY^2 covers any).
 */
void rdc_hw_init(struct rdc_hw *hw, const struct rdc_hw_config *cfg,
		 uint8_t *vram, uint32_t *frame0, uint32_t *frame1,
		 uint32_t frame_cap);
/*
 * Power-on reset: registers to their reset values, 640x480@60 XRGB8888 at
 * VRAM 0 (stride 2560) in force at once (the frame starts at hw->now),
 * queues empty, counters zero, time kept.  VRAM is not cleared.  Reset
 * values not in rdc_regs.h: FIFO_LOWWATER RDC_FIFO_LOWWATER_RESET,
 * LINE_COMPARE RDC_LINE_COMPARE_RESET (never matches), CURSOR_* 0 with
 * CURSOR_FG/BG RDC_CURSOR_FG/BG_RESET, ring registers 0.  The CLUT holds
 * the 16 VGA text colours (0-15), a 6x6x6 colour cube with levels 0x33
 * apart (16 + 36 r + 6 g + b), and a grey ramp 8, 18, ... 238 (232-255).
 * If frame_cap cannot hold 640x480 the reset raises RDC_ERR_MODE and
 * scanout waits for a valid mode: program one, then clear and set
 * CONTROL.SCANOUT_EN.  rdc_hw_init drives RESET_N and BL_EN high.
 */
void rdc_hw_reset(struct rdc_hw *hw);

/*
 * Register access at hw->now.  Bad offsets (outside the window, unaligned,
 * holes) and writes to R registers are logged as RDC_ERR_REG with the
 * offset in ERR_INFO, and otherwise ignored; such a read returns 0.  Where
 * rdc_regs.h is silent:
 *  - Timing validation at latch, beyond rdc_regs.h's ordering: DISPLAY >= 1
 *    (at most RDC_CRTC_MAX_DISPLAY), V_DISPLAY < V_TOTAL (there is a
 *    vertical blanking), PIXCLK_KHZ in [RDC_PIXCLK_MIN_KHZ,
 *    RDC_PIXCLK_MAX_KHZ], a line lasts at least one core cycle, and
 *    H_DISPLAY * V_DISPLAY fits frame_cap.  A refusal is RDC_ERR_MODE with
 *    ERR_INFO = RDC_REG_H_TOTAL, reported once per programming.  An
 *    unknown FB_FORMAT is refused at latch the same way with ERR_INFO =
 *    RDC_REG_FB_FORMAT (the old format stays).  An unknown MODE_PRESET is
 *    RDC_ERR_MODE with ERR_INFO = RDC_REG_MODE_PRESET.
 *  - A new timing latched at vblank goes in force at the next frame start
 *    (the rest of this frame's blanking keeps the old one).  Turning
 *    SCANOUT_EN on latches everything at once and starts a frame at
 *    hw->now; turning it off stops all scanout events (a fetch already on
 *    the bus completes).
 *  - CLUT_DATA reads return the last value written to the entry, also in
 *    latched mode before the vblank applies it.
 *  - The ring is checked when RING_EN is set and at every ring register
 *    write while it is set; a failure is RDC_ERR_RING with the offset of
 *    the register written in ERR_INFO.  A RING_HEAD write while RING_EN is
 *    set is refused with RDC_ERR_REG.  STATUS.RING_EMPTY is HEAD == TAIL.
 *  - FIFO_LOWWATER is clamped to RDC_FIFO_DEPTH.
 *  - A LO read snapshots its own HI register; a HI read returns the
 *    snapshot if its LO was the last LO read, else the live value.
 *  - CONTROL.RESUME sets dp_resume for the DP to find.
 *  - While RESET_N is low, writes are ignored and reads return the reset
 *    values; releasing RESET_N resets the chip again.
 * Scanout events that fall at the very time of an access (a register
 * write, a host VRAM write, a DP access) happen before it.
 */
uint32_t rdc_hw_read(struct rdc_hw *hw, uint32_t reg);
void rdc_hw_write(struct rdc_hw *hw, uint32_t reg, uint32_t val);
/*
 * Command words for FIFO_DATA in bulk: the same as rdc_hw_write of each
 * word in turn at hw->now (trace points included), except that it stops
 * at a full FIFO instead of overflowing.  Returns how many words were
 * taken (all of them while RESET_N holds the chip, which ignores writes).
 */
uint32_t rdc_hw_fifo_push(struct rdc_hw *hw, const uint32_t *words, uint32_t n);

/*
 * Host access to VRAM through the aperture, at hw->now (not charged to the DP).
 * Return 0, or -1 if the range leaves VRAM (nothing is copied).
 */
int rdc_hw_vram_read(struct rdc_hw *hw, uint32_t addr, void *buf, uint32_t len);
int rdc_hw_vram_write(struct rdc_hw *hw, uint32_t addr, const void *buf,
		      uint32_t len);

/*
 * Advance simulated time to at least t, running the DP and scanout
 * interleaved (see rdc_dp_ops.run for overshoot): the DP runs, then the
 * chip idles to min(its wake time, t), and so on.  A DP that returns a
 * wake time not after hw->now gets one idle cycle, so it cannot hang the
 * loop.
 */
void rdc_hw_run_until(struct rdc_hw *hw, uint64_t t);
/*
 * The same, but stop at the exact cycle the DP runs out of work it can do
 * without the host (queues empty, waiting for RDATA space, halted or
 * disabled): returns 1 then, 0 once t is reached.  A host that waits for
 * the DP to finish resumes at the cycle it finished.
 */
int rdc_hw_run_until_idle(struct rdc_hw *hw, uint64_t t);

/* Drive the input pins (RDC_PIN_RESET_N, RDC_PIN_BL_EN). */
void rdc_hw_set_pins(struct rdc_hw *hw, uint32_t pins_in);
uint32_t rdc_hw_pins(struct rdc_hw *hw);

/* Connect a frame listener and a tracer. */
void rdc_hw_set_frame_fn(struct rdc_hw *hw, rdc_frame_fn fn, void *ctx);
void rdc_hw_set_trace(struct rdc_hw *hw, rdc_trace_fn fn, void *ctx);
/*
 * Watch VRAM writes (pixel history): fn sees every write the DP or the host
 * makes, once per span, column or run, never per pixel.  It changes no
 * cycle and no byte.  NULL (the default) turns it off; the write paths
 * then test one pointer.
 */
void rdc_hw_set_vram_hook(struct rdc_hw *hw, rdc_vram_hook_fn fn, void *ctx);
/*
 * From the hook: only writes that reach bytes [lo, hi) matter to it now
 * (0, 0: none).  Until a CRTC register write (FB_*, timing, preset) or a
 * reset, which widen it to all of VRAM, the chip calls it for no other.
 */
void rdc_hw_set_vram_watch(struct rdc_hw *hw, uint32_t lo, uint32_t hi);

/*
 * A host that must not wait for a long command (a daemon serving others,
 * a kernel that must reschedule) gets fn(ctx) called every RDC_POLL_EVERY
 * VRAM accesses or compute steps of the DP, and at every turn of the run
 * loop: always where the DP holds no pointer into VRAM and hw->now is
 * current.  fn may suspend the caller (switch stacks) and resume it
 * later; the chip is then mid-command and nothing but reads may touch it
 * meanwhile.  It changes no cycle and no pixel.  NULL turns it off.
 */
#define RDC_POLL_EVERY 64u
void rdc_hw_set_poll(struct rdc_hw *hw, void (*fn)(void *ctx), void *ctx);

/*
 * The last complete frame and its size: NULL before the first, and for
 * a frame that scanout on demand dropped (rdc_hw_set_on_demand).  Lines
 * of it that wait unconverted are converted first: a look.
 */
const uint32_t *rdc_hw_frame(struct rdc_hw *hw, uint32_t *width,
			     uint32_t *height);

/* Beam position at hw->now (y >= V_DISPLAY in vertical blanking). */
void rdc_hw_beam(struct rdc_hw *hw, uint32_t *x, uint32_t *y);

/* ---- What a host reads of the chip (struct rdc_hw is opaque) ---------- */

/* Bytes of memory struct rdc_hw takes: the host allocates them. */
size_t rdc_hw_size(void);
uint32_t rdc_hw_vram_size(const struct rdc_hw *hw);
uint32_t rdc_hw_core_hz(const struct rdc_hw *hw);
/* VRAM as the chip has it, to read (pixel history); write through the API. */
const uint8_t *rdc_hw_vram(const struct rdc_hw *hw);
void rdc_hw_perf(const struct rdc_hw *hw, struct rdc_perf *p);

/*
 * The chip's state as it stands at hw->now, without a register read (which
 * a trace would record): the host's own bookkeeping (interrupt lines,
 * pacing, waveforms) reads it here.
 */
struct rdc_hw_state {
	uint32_t control, irq_status, irq_enable, dp_status, fence;
	uint32_t pins_in, pins_out; /* RDC_PIN_* */
	uint32_t fifo_count;	    /* command FIFO level, words */
	bool in_reset;		    /* RESET_N held low */
	bool dp_active;		    /* the DP has work or is inside a command */
	bool scanning;		    /* a mode is in force and scanout runs */
	bool in_vblank;		    /* beam in vertical blanking (TE) */
	uint64_t frame_start;	    /* when line 0 of this frame started */
	uint64_t frame_cycles;	    /* core cycles a frame lasts */
	uint64_t frame_count;	    /* vblanks since reset */
	/* the screen as programmed (latched at the next vblank) */
	uint32_t fb_base, fb_stride, fb_format;
	uint32_t width, height; /* H_DISPLAY, V_DISPLAY */
	uint32_t next_line;	/* lines before it were fetched this frame */
};

void rdc_hw_state(const struct rdc_hw *hw, struct rdc_hw_state *s);
/*
 * Where a chip's run has got to beyond what its registers read back, for
 * a trace that starts on a chip that has run (librdc's recorder on a
 * device of the kernel's or a daemon's): replay starts a fresh chip there
 * with rdc_hw_resume.  frame_start is when line 0 of the frame being
 * scanned started (now while scanout is stopped).
 */
struct rdc_hw_resume {
	uint64_t now, frame_start, frame_count;
	struct rdc_perf perf;
	uint32_t fence, irq_status, err_code, err_info;
	uint32_t open_row; /* the DRAM row the bus has open (bus.h) */
	bool scanning;	   /* a mode is in force and scanout runs */
	bool dp_active;	   /* the DP has work or is inside a command */
	/*
	 * What the CRTC has in force, latched at the last vblank (its
	 * registers read what was written for the next one): the timing,
	 * FB_BASE/STRIDE/FORMAT, CURSOR_CTRL/BASE, RASTER_BASE/CTRL and
	 * CONTROL.GAMMA_EN.
	 */
	struct rdc_timing timing;
	uint32_t fb_base, fb_stride, fb_format;
	uint32_t cursor_ctrl, cursor_base;
	uint32_t raster_base, raster_ctrl;
	bool gamma;
};

void rdc_hw_resume_get(const struct rdc_hw *hw, struct rdc_hw_resume *s);
/*
 * Move an idle chip (its DP without work, RESET_N high) whose registers,
 * CLUT and VRAM the host has written as they were to `s` (the latched
 * registers as s has them in force): with scanout on, the frame restarts
 * at s->frame_start (everything written is latched, as turning
 * SCANOUT_EN on does) and runs to s->now; the host then writes the
 * latched registers' values for the next vblank.  After the run the
 * counters, FENCE, IRQ_STATUS, ERR_* and the bus's open row are s's.
 * Returns -1 (nothing changed) if s->frame_start is before hw->now or
 * after s->now, or the chip is not idle.  The run is s->now -
 * s->frame_start cycles: the caller bounds it.
 */
int rdc_hw_resume(struct rdc_hw *hw, const struct rdc_hw_resume *s);
/* The tracer set (rdc_hw_set_trace), so that another can chain to it. */
void rdc_hw_get_trace(const struct rdc_hw *hw, rdc_trace_fn *fn, void **ctx);
/* Whether a VRAM watcher is set (rdc_hw_set_vram_hook). */
bool rdc_hw_vram_hooked(const struct rdc_hw *hw);
/*
 * When the next vertical blanking starts / the beam next starts `line`
 * (RDC_NEVER while scanout is stopped or line >= V_TOTAL): always after
 * hw->now.
 */
uint64_t rdc_hw_next_vblank(struct rdc_hw *hw);
uint64_t rdc_hw_next_line(struct rdc_hw *hw, uint32_t line);

#ifdef __cplusplus
}
#endif

#endif /* RDC_CHIP_H */
