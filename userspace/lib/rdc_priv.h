/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * librdc internals: the device object and the backend table.
 *
 * A backend is a table of operations in the style of libusb's
 * usbi_os_backend.  The core (core.c) implements the public API on top of
 * these operations alone and never asks which backend it talks to; a new
 * transport is a new file with one struct rdc_backend and a line in the
 * table in core.c.
 */
#ifndef RDC_PRIV_H
#define RDC_PRIV_H

#include <stdbool.h>

#include "rdc_chip.h"
#include "rdc_base.h"
#include "rdc_regs.h"
#include "rdc.h"
#include "rdc_server.h"

/*
 * A wait condition, evaluated by the backend on its side of the transport
 * (so a remote device can wait without a round trip per check).  The wait
 * ends when ANY of the terms holds.  The tests are the core's (enum
 * rdc_wait_test, RDC_WAIT_TEST_TERMS in hw-sim/hw.h); the wire carries
 * their values, and rdcfb's ioctl its own RDCFB_WAIT_* (fbdev.c maps them).
 */
struct rdc_wait_term {
	enum rdc_wait_test kind;
	uint32_t reg, mask, value;
};

struct rdc_wait {
	struct rdc_wait_term term[RDC_WAIT_TEST_TERMS];
	/* Fail with RDC_E_HALTED if the DP halts: set for conditions that
	 * only the DP can make true. */
	bool needs_dp;
	/* Simulated-time budget in core cycles; 0 = the default. */
	uint64_t budget;
};

/* The chip's form of a wait (hw-sim/wait.c), budget defaulted. */
static inline void rdc_wait_to_hw(const struct rdc_wait *w,
				  struct rdc_hw_wait *out)
{
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		const struct rdc_wait_term *t = &w->term[i];

		out->term[i] = (struct rdc_wait_cond){
			/* an unknown test is an unused term */
			.test = (unsigned int)t->kind <= RDC_WAIT_TEST_EQ ?
					(uint32_t)t->kind :
					RDC_WAIT_TEST_NONE,
			.reg = t->reg,
			.mask = t->mask,
			.value = t->value,
		};
	}
	out->needs_dp = w->needs_dp;
	out->budget = w->budget ? w->budget : RDC_WAIT_BUDGET_DEFAULT;
}

struct rdc_backend {
	/* URI scheme without the colon, e.g. "sim". */
	const char *scheme;

	/*
	 * Connect; `opts` is the URI after "scheme:".  Set dev->priv.
	 * Returns 0 or a negative enum rdc_error (RDC_E_URI for bad options).
	 * NULL: the scheme is known but not available in this build
	 * (rdc_open returns RDC_E_NOSYS).
	 */
	int (*open)(rdc_dev *dev, const char *opts);
	/* Disconnect and free dev->priv. */
	void (*close)(rdc_dev *dev);

	int (*reg_read)(rdc_dev *dev, uint32_t reg, uint32_t *val);
	int (*reg_write)(rdc_dev *dev, uint32_t reg, uint32_t val);
	/* RDC_E_RANGE when [addr, addr + len) leaves VRAM. */
	int (*vram_read)(rdc_dev *dev, uint32_t addr, void *buf, size_t len);
	int (*vram_write)(rdc_dev *dev, uint32_t addr, const void *buf,
			  size_t len);

	/*
	 * Optional: push `n` command words, honouring back-pressure.  NULL:
	 * the core writes FIFO_DATA itself, waiting on FIFO_FREE.
	 */
	int (*submit)(rdc_dev *dev, const uint32_t *words, size_t n);

	/*
	 * Let the device run until `w` holds: 0, RDC_E_TIMEOUT past the
	 * budget, RDC_E_HALTED (w->needs_dp), or a transport error.
	 */
	int (*wait)(rdc_dev *dev, const struct rdc_wait *w);

	/*
	 * Optional (simulators only, else RDC_E_NOSYS): advance simulated
	 * time by `cycles` whatever happens.
	 */
	int (*step)(rdc_dev *dev, uint64_t cycles);

	/*
	 * Copy the last complete frame (XRGB8888, width * height words) to
	 * buf.  Returns 0; 1 if no frame has completed yet (the core waits
	 * and retries); RDC_E_RANGE if cap < width * height, with *width and
	 * *height set.
	 */
	int (*frame_grab)(rdc_dev *dev, uint32_t *buf, size_t cap,
			  uint32_t *width, uint32_t *height);

	/*
	 * Optional (remote devices, else RDC_E_NOSYS): ask for events
	 * (RDC_EVENT_*) and frames, see rdc_subscribe; and take the next one,
	 * waiting up to timeout_ms of wall time (RDC_E_TIMEOUT).
	 */
	int (*subscribe)(rdc_dev *dev, uint32_t events, uint32_t every,
			 uint32_t encoding);
	int (*event_next)(rdc_dev *dev, struct rdc_event *ev, uint32_t *buf,
			  size_t cap, int timeout_ms);

	/*
	 * Pins (pins.c, rdc_pins_* in rdc.h).  pins_set is optional: drive
	 * the inputs in `mask` (RDC_PINS_IN bits, checked by the core) to
	 * `levels`; NULL: RDC_E_NOSYS.  pins_get and pins_wait are optional
	 * too: NULL reads the register PINS and waits on it through wait()
	 * (rdc_pins_wait_regs), which is right for any backend whose
	 * registers are the chip's.  pins_wait gets `pins` and `edges`
	 * checked and a budget in simulated cycles (budget_cycles) or wall
	 * time (timeout_us), whichever its device counts in.
	 */
	int (*pins_set)(rdc_dev *dev, uint32_t mask, uint32_t levels);
	int (*pins_get)(rdc_dev *dev, uint32_t *levels);
	int (*pins_wait)(rdc_dev *dev, uint32_t pins, uint32_t edges,
			 uint64_t budget_cycles, uint64_t timeout_us,
			 struct rdc_pin_edge *ev);

	/*
	 * Optional: call fn for every device of this scheme the machine
	 * reaches (rdc_list); returns how many, or a negative error.
	 */
	int (*list)(rdc_found_fn fn, void *arg);

	/*
	 * Optional (a device rdcd serves; NULL: history.c's own, on the
	 * chip of a sim: handle, or RDC_E_NOSYS): a pixel history the other
	 * side keeps (rdc_proto.h, HIST_*).  hist_open watches x, y, w, h
	 * (rdc_history_open's arguments); hist_read copies up to `max`
	 * entries from index `first` into e and sets *n, *count (the
	 * entries kept so far) and *dropped; hist_set sets a
	 * RDC_HIST_SET_* value; hist_close ends it.
	 */
	int (*hist_open)(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
			 uint32_t h, uint32_t flags);
	int (*hist_read)(rdc_dev *dev, uint64_t first, uint32_t max,
			 struct rdc_history_entry *e, uint32_t *n,
			 uint64_t *count, uint64_t *dropped);
	int (*hist_set)(rdc_dev *dev, uint32_t what, uint32_t value);
	int (*hist_close)(rdc_dev *dev);

	/*
	 * Optional: where the chip's run has got to beyond its registers
	 * (rdc_hw_resume_get), for the start of a trace (record.c): sim:
	 * reads its chip, fbdev: and drm: ask the module (RDCFB_IOC_STATE,
	 * DRM_IOCTL_RDC_STATE).
	 */
	int (*resume_get)(rdc_dev *dev, struct rdc_hw_resume *s);
};

/* Backends (one file each). */
extern const struct rdc_backend rdc_backend_sim;
extern const struct rdc_backend rdc_backend_unix;  /* net_sock.c */
extern const struct rdc_backend rdc_backend_tcp;   /* net_sock.c */
extern const struct rdc_backend rdc_backend_fbdev; /* fbdev.c, rdcfb.ko */
extern const struct rdc_backend rdc_backend_usb;   /* usb.c, libusb */
extern const struct rdc_backend rdc_backend_drm;   /* drm.c, rdcdrm.ko */

/* rdc_sim_hw, the trace recorder (rdc_rec_*), rdc_vcd_new: rdc_server.h. */

struct rdc_dev {
	const struct rdc_backend *be;
	void *priv;	    /* the backend's */
	uint32_t fence_seq; /* last FENCE value handed out */

	/* command-stream watcher (core.c, rdc_track_words) */
	uint32_t scan_op, scan_left, scan_n, scan_args[4];
	uint32_t dst_format, src_format;

	/* pixel history (history.c): the open one, and the .rdl line whose
	 * statement runs */
	struct rdc_history *hist;
	uint32_t src_line;
};

/* The chip behind a sim: handle, with a trace recorder attached or not
 * (record.c); NULL for any other backend. */
struct rdc_hw *rdc_dev_chip(rdc_dev *dev);
/* The device closes under its history (history.c). */
void rdc_history_detach(rdc_dev *dev);

/*
 * rdc_submit of words that hold whole commands (a batch's), `surfaces`
 * false when none of them is a SET_DST or SET_SRC (core.c).
 */
int rdc_submit_whole(rdc_dev *dev, const uint32_t *words, size_t n,
		     bool surfaces);
/* Run a wait with one term (core.c). */
int rdc_wait_one(rdc_dev *dev, enum rdc_wait_test kind, uint32_t reg,
		 uint32_t mask, uint32_t value, bool needs_dp);
/*
 * The FIFO_DATA loop (core.c): rdc_fifo_feed_step (rdc_server.h) until
 * every word is in, waiting in the device's own time for the room each
 * step asks for.  A backend whose device takes words in bulk gives its
 * own push and keeps the same waits.
 */
int rdc_fifo_feed(rdc_dev *dev, const uint32_t *words, size_t n,
		  rdc_fifo_push_fn push);
/*
 * Pins through the register PINS and wait() (pins.c): the next wanted
 * edge within `budget` simulated cycles, ev->time the simulated time the
 * wait saw it.
 */
int rdc_pins_wait_regs(rdc_dev *dev, uint32_t pins, uint32_t edges,
		       uint64_t budget, struct rdc_pin_edge *ev);
/* CLOCK_MONOTONIC in nanoseconds (pins.c). */
uint64_t rdc_pins_wall_ns(void);

/*
 * Record the detail of a failure for rdc_last_error_detail (core.c):
 * formats it into the thread's buffer and returns `err`, so a failing
 * path reads `return rdc_err_detail(RDC_E_FILE, "%s: %s", path,
 * strerror(errno));`.  errno is kept.  rdc_err_detail_clear forgets it.
 */
int rdc_err_detail(int err, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
void rdc_err_detail_clear(void);

/* RDC_E_DEVICE if the device has a pending error, else 0 (core.c). */
int rdc_check_error(rdc_dev *dev);

/*
 * The HOST_BLIT commands of rdc_host_blit for a w x h rectangle of `fmt`
 * pixels (core.c): `emit` gets each command, its header included, and
 * its error ends the encoding.  The .rdl `list` keeps them for VRAM.
 */
int rdc_host_blit_encode(uint32_t fmt, int x, int y, uint32_t w, uint32_t h,
			 const void *pixels, size_t pitch,
			 int (*emit)(void *ctx, const uint32_t *cmd, size_t n),
			 void *ctx);

/* The last complete frame in a malloc'd buffer (core.c). */
int rdc_frame_alloc(rdc_dev *dev, uint32_t **pix, uint32_t *width,
		    uint32_t *height);
/*
 * Hand a structure the library filled (`full`, n bytes, the library's
 * sizeof) to the caller's `out`, whose first member `size` says how large
 * the caller's is (rdc.h, "Structures that grow"): the bytes both know
 * are copied, the caller's `size` kept, members only the caller knows
 * zeroed (version.c).
 */
void rdc_struct_out(void *out, const void *full, size_t n);
/* zlib CRC-32 of XRGB8888 pixels as little-endian bytes (core.c). */
uint32_t rdc_crc32_xrgb(const uint32_t *pix, size_t n);

#endif /* RDC_PRIV_H */
