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

/* The same calls as hw.h declares (and documents there). */
uint32_t rdc_hw_read(struct rdc_hw *hw, uint32_t reg);
void rdc_hw_run_until(struct rdc_hw *hw, uint64_t t);
uint32_t rdc_hw_pins(struct rdc_hw *hw);
const uint32_t *rdc_hw_frame(struct rdc_hw *hw, uint32_t *width,
			     uint32_t *height);
void rdc_hw_set_frame_fn(struct rdc_hw *hw, rdc_frame_fn fn, void *ctx);
void rdc_hw_set_trace(struct rdc_hw *hw, rdc_trace_fn fn, void *ctx);
void rdc_hw_set_poll(struct rdc_hw *hw, void (*fn)(void *ctx), void *ctx);

#ifdef __cplusplus
}
#endif

#endif /* RDC_CHIP_H */
