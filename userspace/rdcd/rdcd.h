/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcd internals: the daemon state, its clients, and the functions the
 * event loop (rdcd.c) and the request handlers (serve.c and the parts
 * serve.h lists) share.
 */
#ifndef RDCD_H
#define RDCD_H

#include <stdbool.h>
#include <stdint.h>
#include <sys/socket.h>
#include <sys/un.h>

#include "rdc_server.h"
#include "rdc_proto.h"
#include "rdc_sink.h"

#define RDCD_MAX_LISTEN 8
/* Connections that said HELLO, over every listener. */
#define RDCD_MAX_CLIENTS 128
/* Of those, at most this many from one listener: a flood on one leaves
 * room for the others. */
#define RDCD_MAX_CLIENTS_PER_LISTENER 96
/*
 * Connections that have not said HELLO yet, per listener: a new one beyond
 * RDCD_MAX_PENDING closes the oldest that has sent nothing for
 * RDCD_HELLO_GRACE_MS; if all are younger, up to RDCD_MAX_PENDING_YOUNG
 * are kept (a HELLO may be on its way), and beyond that the oldest that
 * has sent nothing goes.  So silent connections never lock anyone out, and
 * a flood of them does not close a client whose HELLO is waiting.  A
 * listener's backlog is taken RDCD_MAX_PENDING at a time, each then read
 * before the next are let in.  Each must say HELLO within RDCD_HELLO_MS
 * and may send nothing larger.
 */
#define RDCD_MAX_PENDING       8
#define RDCD_MAX_PENDING_YOUNG 32
#define RDCD_HELLO_GRACE_MS    200
#define RDCD_HELLO_MS	       5000
/* Failed tokens: after RDC_AUTH_FREE_FAILS from one address, that address
 * is refused for a second, doubling at each further failure up to a minute
 * (rdc_auth_*, rdc_server.h); failed-token log lines are kept to one a
 * second. */
/* Requests handled per client per loop turn, so one cannot starve others. */
#define RDCD_REQ_PER_TURN 64
/* Replies queued for a client before the daemon stops reading from it. */
#define RDCD_OUT_HIGH (4u << 20)
/* Frame events queued per client; beyond this frames are dropped for it.
 * A frame is queued only into a queue under RDCD_OUT_HIGH, or an empty one. */
#define RDCD_MAX_QUEUED_FRAMES 2u
/*
 * Everything queued for every client together, a frame shared by several
 * queues counted once.  A frame that would take the total over it is
 * dropped; replies that do make the slowest reader with replies waiting
 * (the longest without taking anything) be disconnected until it fits.
 */
#define RDCD_OUT_TOTAL (64u << 20)
/* DELTA subscribers' copies of their last frame, in all; past it a
 * subscriber without one gets RLE frames until there is room. */
#define RDCD_PREV_TOTAL (64u << 20)
/* Longest wait or step a client may ask for: one simulated minute. */
#define RDCD_MAX_BUDGET_S 60u
/* Listeners on the chip's trace hook (trace.c). */
#define RDCD_MAX_TRACE 4
/* Frame sinks (--v4l2, --png, --vnc, --sink). */
#define RDCD_MAX_SINKS 8
/* Stepped mode: simulated cycles a pending wait runs per turn of the loop
 * (1 ms of the default core clock) before the others are served again. */
#define RDCD_WAIT_PIECE (RDC_DEFAULT_CORE_HZ / 1000u)
/* Host time the chip runs before the loop serves the sockets again, in
 * every mode, even inside one long display-processor command (chip.c). */
#define RDCD_SLICE_US 2000u
/* The most simulated time one SUBMIT may spend waiting for FIFO room in
 * all; then TIMEOUT (the words not yet taken are dropped). */
#define RDCD_SUBMIT_BUDGET_S RDCD_MAX_BUDGET_S

enum rdcd_log_level {
	RDCD_LOG_ERR,
	RDCD_LOG_WARN,
	RDCD_LOG_INFO,
	RDCD_LOG_DEBUG
};

/*
 * One encoding of one frame's pixels, made once and shared by every
 * subscriber that takes that frame in that encoding (frames.c); freed
 * with its last reference.
 */
struct rdcd_shared {
	unsigned int refs;
	unsigned int queued; /* queues holding it: counted once in out_total */
	uint32_t enc;	     /* what it holds: RLE falls back to RAW */
	size_t len;
	uint8_t data[];
};

/* A message queued for a client: data[0..hlen), then shared's bytes. */
struct rdcd_obuf {
	struct rdcd_obuf *next;
	size_t len, off, hlen;
	bool frame;
	struct rdcd_shared *shared; /* or NULL: all of it is in data */
	uint8_t data[];
};

enum rdcd_pending {
	RDCD_PEND_NONE,
	RDCD_PEND_SUBMIT,
	RDCD_PEND_WAIT,
	RDCD_PEND_STEP
};

struct rdcd_client {
	struct rdcd_client *next;
	int fd;
	uint32_t id;
	bool tcp, hello, dead, closing;
	/* this client's *_HI snapshot: the HI register its last *_LO read
	 * belongs to (0: none) and that HI's value then (dispatch.c) */
	uint32_t snap_reg, snap_val;
	/* a complete request waits in hdr/body until the chip is between
	 * commands (it changes the device) */
	bool held;
	int lis;	  /* index of the listener it came from, -1: none */
	uint64_t conn_ns; /* when it connected (HELLO deadline) */
	uint64_t rx_ns;	  /* before HELLO: when something last arrived */
	uint64_t out_since_ns; /* last progress sending, or when queued */
	char peer[64];

	/* input: a header, then its payload */
	uint8_t hdrbuf[RDC_PROTO_HDR_SIZE];
	size_t hdr_got, body_got, body_cap;
	struct rdc_proto_hdr hdr;
	uint8_t *body; /* grows with what arrives, up to hdr.len */

	/* output queue */
	struct rdcd_obuf *out_head, *out_tail;
	size_t out_bytes, out_frame_bytes;
	uint32_t out_frames;

	/* a request that waits for the device */
	enum rdcd_pending pend;
	struct rdc_proto_hdr pend_hdr;
	uint8_t *pend_words; /* SUBMIT payload, little-endian words */
	size_t pend_n, pend_done;
	struct rdc_hw_wait pend_wait;
	struct rdc_hw_wait pend_hw; /* stepped mode: the wait moves time */
	uint64_t pend_start, pend_target;
	uint64_t pend_wall_ns; /* host time it began */

	/* subscription */
	uint32_t sub_events, sub_every, sub_enc;
	uint64_t frame_tick, frames_sent, frames_dropped;
	uint32_t *prev; /* the last frame queued (RDC_ENC_DELTA base) */
	size_t prev_bytes;
	uint32_t prev_w, prev_h;
};

struct rdcd_ffs;
struct rdcd_udl;

struct rdcd_listener {
	int fd;
	bool tcp, need_token;
	char path[sizeof(((struct sockaddr_un *)0)->sun_path)];
	/* the socket file bound at path: removed at exit only if still ours */
	uint64_t path_dev, path_ino;
	char uri[160];
	struct rdcd_ffs *ffs; /* ffs: (USB device): fd wakes for a session */
	struct rdcd_udl *udl; /* udl: (DisplayLink personality): the same */
};

struct rdcd {
	/* the device: a sim: handle, maybe wrapped by a recorder */
	rdc_dev *dev;
	struct rdc_hw *hw;
	struct rdc_server_rec *rec;
	uint32_t vram_size;
	enum rdc_run_mode mode;

	struct rdcd_listener lis[RDCD_MAX_LISTEN];
	unsigned int nlis;
	struct rdcd_client *clients;
	unsigned int nclients; /* that said HELLO */
	int accept_lis;	   /* listener whose connection is being made, or -1 */
	size_t out_total;  /* bytes queued for every client (RDCD_OUT_TOTAL) */
	size_t prev_total; /* bytes of every client's DELTA base */
	/* what runs on the chip's stack: the paced/fast loop's advance to
	 * adv_target, or (stepped) chip_client's pending request */
	uint64_t adv_target;
	struct rdcd_client *chip_client;
	uint32_t next_id;
	struct rdcd_client *ctl; /* the controlling client, or NULL */

	uint8_t token[RDC_PROTO_MAX_TOKEN];
	uint32_t token_len;
	bool have_token;
	struct rdc_auth auth; /* failed tokens, by peer address */
	/* lines that a flood could repeat: at most one a second each */
	struct rdcd_ratelog {
		uint64_t last_ns;
		uint32_t quiet; /* not logged since */
	} authlog, connlog;

	/* the chip runs on its own stack, a slice at a time (chip.c) */
	struct rdcd_chip *chip;

	int log_level;
	uint32_t last_irq;
	uint64_t frames;
	/* for subscribers: frame encodings made, frames queued and dropped
	 * (logged at exit) */
	uint64_t sub_encodings, sub_queued, sub_dropped;
	/* the chip converts frames: a client or a sink may look (rdcd_watch) */
	bool watched;

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

	/* the pixel history one client keeps on the chip (HIST_*), or NULL;
	 * it follows the chip across power cycles and ends with its client */
	rdc_history *hist;
	struct rdcd_client *hist_client;

	struct rdc_pace pace; /* the paced clock (rdc_pace_target) */
};

void rdcd_log(const struct rdcd *d, int level, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
uint64_t rdcd_wall_ns(void);

/*
 * systemd.c: socket activation and readiness (docs/protocol.md, "Under
 * systemd").  rdcd_systemd_passed: did systemd pass this process
 * listening sockets (LISTEN_PID, LISTEN_FDS; read once, then taken out
 * of the environment)?  rdcd_systemd_add: --listen systemd[:NAME], the
 * passed sockets (those named NAME) as listeners; -1, logged, when there
 * are none or one is not a listening stream socket.  rdcd_systemd_done:
 * close the passed sockets no listener took.  rdcd_systemd_notify: a
 * state ("READY=1") to $NOTIFY_SOCKET, if set.
 */
bool rdcd_systemd_passed(void);
int rdcd_systemd_add(struct rdcd *d, const char *name);
void rdcd_systemd_done(struct rdcd *d);
void rdcd_systemd_notify(const struct rdcd *d, const char *state);

/* serve.c and its parts (serve.h) */
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
/*
 * Scanout on demand: the chip converts frames only while a client (which
 * may grab or subscribe at any time) or a sink is there; an idle rdcd
 * with neither only keeps the simulated time.  Before the chip runs and
 * when a client comes or goes.
 */
void rdcd_watch(struct rdcd *d);
bool rdcd_has_pending(const struct rdcd *d);
/* Paced and fast modes, inside the loop's advance: refill the FIFO from
 * the pending SUBMITs; true while one still has words left. */
bool rdcd_feed_pending(struct rdcd *d);
/* Close connections past their HELLO deadline; ns until the next one is
 * due (UINT64_MAX: none). */
uint64_t rdcd_hello_deadlines(struct rdcd *d);
/* Stepped mode: run the controller's pending request on the chip's
 * stack (chip.c): -1 nothing to run, 0 it ended, 1 it goes on. */
int rdcd_stepped_start(struct rdcd *d);
/* A log line through a rate limit: at most one a second per limiter. */
void rdcd_log_limited(struct rdcd *d, struct rdcd_ratelog *rl, int level,
		      const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
/* Disconnect the slowest readers while d->out_total is over its bound. */
void rdcd_out_bound(struct rdcd *d);
/* Requests held while the chip was inside a command: handle them now. */
void rdcd_release_held(struct rdcd *d);

/*
 * chip.c: everything that moves simulated time runs on the chip's own
 * stack and yields back to the loop after RDCD_SLICE_US of host time, at
 * a VRAM access of the display processor if need be (hw-sim's poll
 * hook), so no command, however long, keeps the loop from the sockets.
 * rdcd_chip_run: start fn(d, arg) there; 0 when it finished, 1 when it
 * yielded (rdcd_chip_busy is then true; go on with rdcd_chip_resume
 * until it returns 0).  While it is suspended nothing may change the
 * device; reads are fine.  rdcd_chip_abort: end a suspended run at once
 * (a reset is about to replace the device's state); the device may then
 * hold a half-done command.  Without rdcd_chip_open (an in-process
 * harness), fn runs to its end at once.
 */
typedef void (*rdcd_chip_fn)(struct rdcd *d, void *arg);
int rdcd_chip_open(struct rdcd *d);
void rdcd_chip_close(struct rdcd *d);
int rdcd_chip_run(struct rdcd *d, rdcd_chip_fn fn, void *arg);
int rdcd_chip_resume(struct rdcd *d);
bool rdcd_chip_busy(const struct rdcd *d);
void rdcd_chip_abort(struct rdcd *d);
/* (Re)attach the poll hook to d->hw (after a power cycle's new chip). */
void rdcd_chip_attach(struct rdcd *d);
/* In a chip function: yield if the slice is spent (as the poll hook). */
void rdcd_chip_yield_point(struct rdcd *d);
/*
 * Is the run suspended at such a yield point, between pieces of time,
 * rather than inside a DP command?  There a trace can replay a read (the
 * time moved so far is recorded as a step before it).
 */
bool rdcd_chip_between(const struct rdcd *d);

/*
 * ffs.c: the FunctionFS listener (ffs:DIR, the RDC-1 as a USB device).
 * rdcd_ffs_open: writes the descriptors to DIR/ep0 and starts the bridge
 * threads; returns the fd to poll (readable when a host configured the
 * device), or -1.  rdcd_ffs_accept: a client for the new USB session.
 * rdcd_ffs_close: stops the threads (the gadget leaves its UDC).
 */
int rdcd_ffs_open(const struct rdcd *d, const char *dir, struct rdcd_ffs **out);
void rdcd_ffs_accept(struct rdcd *d, struct rdcd_ffs *f);
void rdcd_ffs_close(struct rdcd_ffs *f);

/*
 * udl.c: the DisplayLink personality (udl:DIR[?pad=N]), which Linux's udl
 * DRM driver drives; the same three calls as ffs.c's.
 */
int rdcd_udl_open(const struct rdcd *d, const char *spec,
		  struct rdcd_udl **out);
void rdcd_udl_accept(struct rdcd *d, struct rdcd_udl *u);
void rdcd_udl_close(struct rdcd_udl *u);

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

/* web.c: the web sink's part in rdcd */
/* A --web spec gets rdcd's --token (the same rule as tcp:); 0 or an
 * enum rdc_error. */
int rdcd_web_token(char **spec, const char *token_path);
/* Log a sink's address (a web page's) once it is open. */
void rdcd_web_log(const struct rdcd *d, const rdc_sink *s);
/* The device's time, pins and IRQ status to the sinks that show them;
 * between runs of the chip. */
void rdcd_web_status(struct rdcd *d);

#endif /* RDCD_H */
