/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * rdcd internals: the daemon state, its clients, and the functions the
 * event loop (rdcd.c) and the request handlers (serve.c) share.
 */
#ifndef RDCD_H
#define RDCD_H

#include <stdbool.h>
#include <stdint.h>
#include <sys/un.h>

#include "rdc_priv.h"
#include "rdc_proto.h"
#include "rdc_sink.h"

#define RDCD_MAX_LISTEN 8
#define RDCD_MAX_CLIENTS 128
/* Requests handled per client per loop turn, so one cannot starve others. */
#define RDCD_REQ_PER_TURN 64
/* Replies queued for a client before the daemon stops reading from it. */
#define RDCD_OUT_HIGH (4u << 20)
/* Frame events queued per client; beyond this frames are dropped for it. */
#define RDCD_MAX_QUEUED_FRAMES 2u
/* Longest wait or step a client may ask for: one simulated minute. */
#define RDCD_MAX_BUDGET_S 60u
/* Listeners on the chip's trace hook (trace.c). */
#define RDCD_MAX_TRACE 4
/* Frame sinks (--v4l2, --png, --vnc, --sink). */
#define RDCD_MAX_SINKS 8
/* Stepped mode: simulated cycles a pending wait runs per turn of the loop
 * (1 ms of the default core clock) before the others are served again. */
#define RDCD_WAIT_PIECE (RDC_DEFAULT_CORE_HZ / 1000u)

enum rdcd_log_level { RDCD_LOG_ERR, RDCD_LOG_WARN, RDCD_LOG_INFO,
		      RDCD_LOG_DEBUG };

struct rdcd_obuf {
	struct rdcd_obuf *next;
	size_t len, off;
	bool frame;
	uint8_t data[];
};

enum rdcd_pending { RDCD_PEND_NONE, RDCD_PEND_SUBMIT, RDCD_PEND_WAIT,
		    RDCD_PEND_STEP };

struct rdcd_client {
	struct rdcd_client *next;
	int fd;
	uint32_t id;
	bool tcp, hello, dead, closing;
	char peer[64];

	/* input: a header, then its payload */
	uint8_t hdrbuf[RDC_PROTO_HDR_SIZE];
	size_t hdr_got, body_got;
	struct rdc_proto_hdr hdr;
	uint8_t *body;

	/* output queue */
	struct rdcd_obuf *out_head, *out_tail;
	size_t out_bytes;
	uint32_t out_frames;

	/* a request that waits for the device */
	enum rdcd_pending pend;
	struct rdc_proto_hdr pend_hdr;
	uint8_t *pend_words; /* SUBMIT payload, little-endian words */
	size_t pend_n, pend_done;
	struct rdc_wait pend_wait;
	struct rdc_hw_wait pend_hw; /* stepped mode: the wait moves time */
	uint64_t pend_start, pend_target;

	/* subscription */
	uint32_t sub_events, sub_every, sub_enc;
	uint64_t frame_tick, frames_sent, frames_dropped;
	uint32_t *prev; /* the last frame queued (RDC_ENC_DELTA base) */
	uint32_t prev_w, prev_h;
};

struct rdcd_ffs;

struct rdcd_listener {
	int fd;
	bool tcp, need_token;
	char path[sizeof(((struct sockaddr_un *)0)->sun_path)];
	char uri[160];
	struct rdcd_ffs *ffs; /* ffs: (USB device): fd wakes for a session */
};

struct rdcd {
	/* the device: a sim: handle, maybe wrapped by a recorder */
	rdc_dev *dev;
	struct rdc_hw *hw;
	struct rdc_rec *rec;
	uint32_t vram_size;
	enum rdc_run_mode mode;

	struct rdcd_listener lis[RDCD_MAX_LISTEN];
	unsigned int nlis;
	struct rdcd_client *clients;
	unsigned int nclients;
	uint32_t next_id;
	struct rdcd_client *ctl; /* the controlling client, or NULL */

	uint8_t token[RDC_PROTO_MAX_TOKEN];
	uint32_t token_len;
	bool have_token;

	int log_level;
	uint32_t last_irq;
	uint64_t frames;

	/* every frame also goes to these */
	rdc_sink *sinks[RDCD_MAX_SINKS];
	unsigned int nsinks;

	/* the chip's trace hook, fanned out (trace.c) */
	struct {
		rdc_trace_fn fn;
		void *ctx;
	} trace[RDCD_MAX_TRACE];
	unsigned int ntrace;

	/* --gpio-sim: the pins on a gpio-sim chip (gpiosim.c), or NULL */
	struct rdcd_gpiosim *gpiosim;

	/* pacing: simulated time pace_sim0 was wall time pace_wall0 */
	uint64_t pace_wall0_ns, pace_sim0;
};

void rdcd_log(const struct rdcd *d, int level, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

/* serve.c */
int rdcd_device_open(struct rdcd *d);
void rdcd_device_close(struct rdcd *d);
struct rdcd_client *rdcd_client_new(struct rdcd *d, int fd, bool tcp,
				    const char *peer);
void rdcd_client_free(struct rdcd *d, struct rdcd_client *c);
bool rdcd_client_wants_read(const struct rdcd_client *c);
void rdcd_client_read(struct rdcd *d, struct rdcd_client *c);
void rdcd_client_flush(struct rdcd *d, struct rdcd_client *c);
/* After simulated time moved: finish pending requests, push IRQ events. */
void rdcd_after_advance(struct rdcd *d);
bool rdcd_has_pending(const struct rdcd *d);

/*
 * ffs.c: the FunctionFS listener (ffs:DIR, the RDC-1 as a USB device).
 * rdcd_ffs_open: writes the descriptors to DIR/ep0 and starts the bridge
 * threads; returns the fd to poll (readable when a host configured the
 * device), or -1.  rdcd_ffs_accept: a client for the new USB session.
 * rdcd_ffs_close: stops the threads (the gadget leaves its UDC).
 */
int rdcd_ffs_open(const struct rdcd *d, const char *dir,
		  struct rdcd_ffs **out);
void rdcd_ffs_accept(struct rdcd *d, struct rdcd_ffs *f);
void rdcd_ffs_close(struct rdcd_ffs *f);

/*
 * trace.c: listeners on the chip's trace hook (RDC_TRACE_*), kept across
 * power cycles.  rdcd_trace_add: 0 or RDC_E_NOMEM when RDCD_MAX_TRACE are
 * in use.  rdcd_trace_attach: (re)install the hook on d->hw.
 */
int rdcd_trace_add(struct rdcd *d, rdc_trace_fn fn, void *ctx);
void rdcd_trace_remove(struct rdcd *d, rdc_trace_fn fn, void *ctx);
void rdcd_trace_attach(struct rdcd *d);

/*
 * gpiosim.c: --gpio-sim NAME makes the gpio-sim chip NAME and bridges the
 * pins to it: open (0 or -1, logged), poll once per loop turn (the loop
 * turns at least every RDCD_GPIOSIM_POLL_MS), new_chip after a power
 * cycle (the levels the consumer drives, again, to the new chip), close
 * (takes the chip down).  All do nothing without --gpio-sim.
 */
#define RDCD_GPIOSIM_POLL_MS 5
int rdcd_gpiosim_open(struct rdcd *d, const char *name);
void rdcd_gpiosim_poll(struct rdcd *d);
void rdcd_gpiosim_new_chip(struct rdcd *d);
void rdcd_gpiosim_close(struct rdcd *d);

#endif /* RDCD_H */
