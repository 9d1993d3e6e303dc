/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The web sink's two halves (docs/web.md): the HTTP and WebSocket server
 * on its own thread (web_server.c: connections, requests, the viewers'
 * tokens and input) and the sink (web.c: frames into damage, damage and
 * status into messages, opening and closing).  What they share: the
 * state below and the calls across.  Not for other files.
 */
#ifndef RDC_WEB_H
#define RDC_WEB_H

#include <netinet/in.h>
#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rdc_priv.h"
#include "sink_priv.h"
#include "web_proto.h"

/*
 * Viewers at once, and connections that are not viewers yet (page loads,
 * handshakes, tokens).  A new connection is always taken: beyond
 * WEB_MAX_PENDING the oldest that is not a viewer yet goes; with every
 * viewer's place taken, the viewer whose socket has taken nothing for
 * longest (WEB_DEADLINE_NS at least) goes, else the one that has watched
 * longest.  Viewers share every message (the log below), so each costs
 * its socket and a copy of what it is sent.
 */
#define WEB_MAX_VIEWERS 400
#define WEB_MAX_PENDING 16
#define WEB_MAX_CONNS	(WEB_MAX_VIEWERS + WEB_MAX_PENDING)
/* The log of messages every viewer is sent: at most this many, and this
 * many bytes; a viewer left behind starts again from a snapshot. */
#define WEB_LOG_MSGS  4096u
#define WEB_LOG_BYTES (16u << 20)
/* A request head, or a viewer's first message, must come in this time. */
#define WEB_DEADLINE_NS (5ull * 1000000000ull)
/* The largest message a viewer may send (its token, pings). */
#define WEB_MSG_MAX 1024
/* Raw RGBA bytes in one update rectangle: a viewer's queue holds at most
 * one rectangle, compressed. */
#define WEB_BAND_BYTES (256u << 10)
/* Status alone (the frame counter moving on an unchanged picture) goes
 * at most this often. */
#define WEB_STATUS_NS (250ull * 1000000ull)
/* The binary message: type, x, y, w, h (u32 little-endian), then the
 * rectangle's RGBA rows through zlib. */
#define WEB_RECT_TYPE 1u
#define WEB_RECT_HDR  20u
#define WEB_JSON_MAX  512
#define NS_PER_S      1000000000ull

struct web_conn {
	struct web_conn *next;
	int fd;
	bool ws;      /* handshake done */
	bool authed;  /* a viewer: said its token (or none was needed) */
	bool closing; /* send what is queued, then close */
	bool dead;
	char peer[INET6_ADDRSTRLEN];
	uint64_t deadline_ns;
	/* input: a request head, then WebSocket frames */
	uint8_t in[WEB_HDR_MAX];
	size_t in_len;
	uint8_t msg[WEB_MSG_MAX];
	size_t msg_len;
	bool in_msg;
	/* output */
	uint8_t *out;
	size_t out_len, out_off, out_cap;
	uint64_t sent_ns; /* the queue last moved (or was empty) */
	/* a viewer's next message (the server thread's): the snapshot's
	 * snap_i-th while snap, then the log's at pos */
	bool snap;
	uint64_t snap_gen;
	size_t snap_i;
	uint64_t pos;
	uint64_t since_ns; /* a viewer since */
};

/* One WebSocket message (header and payload), made once for all. */
struct web_msg {
	size_t len;
	uint8_t data[];
};

struct web_sink {
	int lfd, wake_fd;
	pthread_t thr;
	bool thr_started;
	bool loopback;
	char url[96];
	uint8_t token[RDC_PROTO_MAX_TOKEN];
	uint32_t token_len;
	bool have_token;
	struct rdc_auth auth; /* failed tokens, by peer address */
	uint8_t *rgba; /* the server thread's: one band (WEB_BAND_BYTES) */
	uint8_t *zbuf;
	size_t zcap;
	/* What every viewer is sent, in order (the server thread's): the
	 * log, log[pos % WEB_LOG_MSGS] for pos in [log_first, log_end); and
	 * a snapshot, the whole picture as of log position snap_pos, for a
	 * new viewer or one the log left behind.  The size the log last
	 * told, and when it last told a status. */
	struct web_msg *log[WEB_LOG_MSGS];
	uint64_t log_first, log_end;
	size_t log_bytes;
	struct web_msg **snap;
	size_t nsnap, snap_cap;
	uint64_t snap_pos, snap_gen;
	uint32_t log_w, log_h;
	uint64_t status_ns;
	uint64_t encodings; /* rectangles compressed (tests) */

	pthread_mutex_t mu; /* everything below */
	bool stop;
	uint32_t *fb; /* the last frame */
	uint32_t w, h;
	uint64_t seq;
	uint32_t inum, iden;
	struct rdc_sink_status st;
	bool have_st;
	struct web_conn *conns;
	unsigned int nconns, nviewers;
	/* damage not in the log yet, per row: columns [x0, x1), x1 == 0 for
	 * a clean row; a status is due (the frame moved on), a status saying
	 * the picture is whole is due (damage went into the log) */
	uint32_t *dx0, *dx1;
	uint32_t dh;
	bool dirty, status_due, sync_due;
};

/* CLOCK_MONOTONIC in nanoseconds. */
uint64_t rdc_web_now_ns(void);
/* Wake the server thread (a new frame, or stop). */
void rdc_web_wake(struct web_sink *w);
/* The server thread: serves w->lfd until w->stop. */
void *rdc_web_serve(void *arg);
/* Queue a WebSocket message of opcode `op` for c; false without memory. */
bool rdc_web_conn_send(struct web_conn *c, uint8_t op, const void *p, size_t n);
/* Queue n bytes already framed as WebSocket messages. */
bool rdc_web_conn_send_raw(struct web_conn *c, const void *p, size_t n);

/*
 * The sink's side, called by the server thread.  rdc_web_pump queues the
 * next message for a viewer whose queue is empty (making it, once for
 * all viewers, if none has asked for it yet).  rdc_web_next: 0 if the
 * viewer has more to be sent now, else when a status will be due
 * (UINT64_MAX: never).  rdc_web_log_free: the log and snapshot, gone.
 */
void rdc_web_pump(struct web_sink *w, struct web_conn *c, uint64_t now);
uint64_t rdc_web_next(struct web_sink *w, const struct web_conn *c);
void rdc_web_log_free(struct web_sink *w);

#endif /* RDC_WEB_H */
