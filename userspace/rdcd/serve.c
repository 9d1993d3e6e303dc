// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: the device, the clients and their requests.
 *
 * The daemon's RDC-1 is librdc's sim: backend, driven through the same
 * backend operations a sim: application uses, so a request does to the
 * chip exactly what the library call would do in process.  In stepped mode
 * a wait, step or submit moves time itself (as on sim:), on the chip's
 * stack a slice of host time at a time (chip.c); in paced and fast modes
 * time belongs to the loop and such requests stay pending until the
 * device lets them finish.  Either way the client's socket is read one
 * request ahead only, so that a RESET can end what is pending.
 *
 * Clients are distrusted: every length is checked against rdc_proto.h's
 * limits before anything is allocated, and a bad request gets an error
 * reply and a log line, never the daemon's end.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "rdcd.h"

/* librdc errors as wire status codes: the one place that maps them. */
static uint32_t rdcd_status_from_error(int err)
{
	switch (err) {
	case 0:
		return RDC_ST_OK;
	case RDC_E_NOMEM:
		return RDC_ST_NOMEM;
	case RDC_E_NOSYS:
		return RDC_ST_NOSYS;
	case RDC_E_TIMEOUT:
		return RDC_ST_TIMEOUT;
	case RDC_E_HALTED:
		return RDC_ST_HALTED;
	case RDC_E_RANGE:
		return RDC_ST_RANGE;
	case RDC_E_BUSY:
		return RDC_ST_BUSY;
	case RDC_E_DEVICE:
		return RDC_ST_DEVICE;
	case RDC_E_RESET:
		return RDC_ST_RESET;
	default:
		return RDC_ST_INVAL;
	}
}

static const char *rdcd_status_name(uint32_t st)
{
	static const char *const names[RDC_ST_COUNT_] = {
		"ok",
		"invalid argument",
		"out of memory",
		"not supported",
		"timeout",
		"halted",
		"out of range",
		"malformed payload",
		"busy (not in control)",
		"bad token",
		"bad magic or version",
		"message too big",
		"no frame yet",
		"unknown type",
		"out of order",
		"device error",
		"ended by a reset",
	};

	return st < RDC_ST_COUNT_ ? names[st] : "?";
}

/* ---- Frames -------------------------------------------------------------- */

static void rdcd_queue(struct rdcd *d, struct rdcd_client *c,
		       struct rdcd_obuf *b)
{
	b->next = NULL;
	if (c->out_tail) {
		c->out_tail->next = b;
	} else {
		c->out_head = b;
		c->out_since_ns = rdcd_wall_ns();
	}
	c->out_tail = b;
	c->out_bytes += b->len;
	d->out_total += b->len;
	if (b->frame) {
		c->out_frames++;
		c->out_frame_bytes += b->len;
	}
}

static struct rdcd_obuf *rdcd_obuf_new(size_t payload)
{
	struct rdcd_obuf *b = malloc(sizeof(*b) + RDC_PROTO_HDR_SIZE + payload);

	if (b) {
		b->len = RDC_PROTO_HDR_SIZE + payload;
		b->off = 0;
		b->frame = false;
	}
	return b;
}

static void rdcd_obuf_hdr(struct rdcd_obuf *b, uint16_t type, uint16_t flags,
			  uint32_t seq, uint32_t status)
{
	struct rdc_proto_hdr h = {
		.len = (uint32_t)(b->len - RDC_PROTO_HDR_SIZE),
		.type = type,
		.flags = flags,
		.seq = seq,
		.status = status,
	};

	rdc_proto_hdr_encode(b->data, &h);
}

/*
 * A frame message (event or FRAME_GRAB reply) in `enc`, falling back to
 * raw when compression would not be smaller.  NULL if out of memory.
 */
static struct rdcd_obuf *rdcd_frame_msg(const uint32_t *pix,
					const uint32_t *prev, uint32_t w,
					uint32_t h, uint32_t enc,
					struct rdc_proto_frame *f)
{
	size_t raw = (size_t)w * h * 4, n;
	struct rdcd_obuf *b = rdcd_obuf_new(RDC_PROTO_FRAME_HDR + raw);
	uint8_t *data;

	if (!b)
		return NULL;
	data = b->data + RDC_PROTO_HDR_SIZE + RDC_PROTO_FRAME_HDR;
	n = enc == RDC_ENC_RAW ?
		    0 :
		    rdc_proto_frame_encode(data, raw, enc, pix, prev, w, h);
	if (!n) {
		enc = RDC_ENC_RAW;
		n = rdc_proto_frame_encode(data, raw, enc, pix, NULL, w, h);
	}
	f->width = w;
	f->height = h;
	f->encoding = enc;
	rdc_proto_frame_hdr_encode(b->data + RDC_PROTO_HDR_SIZE, f);
	b->len = RDC_PROTO_HDR_SIZE + RDC_PROTO_FRAME_HDR + n;
	if (n < raw) {
		struct rdcd_obuf *s = realloc(b, sizeof(*b) + b->len);

		if (s)
			b = s;
	}
	return b;
}

/* A DELTA subscriber's copy of the last frame it was sent, gone. */
static void rdcd_prev_free(struct rdcd *d, struct rdcd_client *c)
{
	free(c->prev);
	c->prev = NULL;
	d->prev_total -= c->prev_bytes;
	c->prev_bytes = 0;
}

static void rdcd_frame_to_client(struct rdcd *d, struct rdcd_client *c,
				 const uint32_t *xrgb, uint32_t w, uint32_t h,
				 uint64_t number)
{
	struct rdc_proto_frame f = { .number = number };
	const uint32_t *prev = NULL;
	struct rdcd_obuf *b;
	size_t px = (size_t)w * h;
	uint32_t enc = c->sub_enc;

	if (c->dead || !(c->sub_events & RDC_SUB_FRAMES))
		return;
	if (c->frame_tick++ % c->sub_every)
		return;
	/*
	 * A slow reader loses frames, alone: the device never waits.  A
	 * queue already holding its share of replies takes no frame either,
	 * nor one that would take everyone's queues over their bound.
	 */
	if (c->out_frames >= RDCD_MAX_QUEUED_FRAMES ||
	    (c->out_head && c->out_bytes >= RDCD_OUT_HIGH) ||
	    d->out_total >= RDCD_OUT_TOTAL) {
		c->frames_dropped++;
		return;
	}
	if (enc == RDC_ENC_DELTA) {
		if (c->prev && (c->prev_w != w || c->prev_h != h))
			rdcd_prev_free(d, c);
		if (c->prev) {
			prev = c->prev;
		} else if (d->prev_total + px * 4 > RDCD_PREV_TOTAL) {
			/* no room for another base: this frame in RLE */
			enc = RDC_ENC_RLE;
		} else {
			c->prev = malloc(px * 4 + 4);
			if (!c->prev) {
				c->frames_dropped++;
				return;
			}
			c->prev_bytes = px * 4;
			d->prev_total += c->prev_bytes;
		}
	}
	f.dropped = (uint32_t)c->frames_dropped;
	b = rdcd_frame_msg(xrgb, prev, w, h, enc, &f);
	if (!b || d->out_total + b->len > RDCD_OUT_TOTAL) {
		free(b);
		c->frames_dropped++;
		return;
	}
	if (enc == RDC_ENC_DELTA) {
		memcpy(c->prev, xrgb, px * 4);
		c->prev_w = w;
		c->prev_h = h;
	}
	rdcd_obuf_hdr(b, RDC_MSG_EV_FRAME, RDC_MSGF_EVENT, 0, RDC_ST_OK);
	b->frame = true;
	rdcd_queue(d, c, b);
	c->frames_sent++;
	rdcd_log(d, RDCD_LOG_DEBUG, "client %u: frame %llu queued", c->id,
		 (unsigned long long)number);
}

/* Sinks never stall the device: they drop what they cannot take. */
static void rdcd_frame_to_sinks(struct rdcd *d, const uint32_t *xrgb,
				uint32_t w, uint32_t h, uint64_t number)
{
	struct rdc_timing tm, *t = &tm;
	struct rdc_frame f = { .xrgb = xrgb,
			       .width = w,
			       .height = h,
			       .stride = w,
			       .seq = number };

	rdc_hw_timing(d->hw, t);
	if (rdc_sink_interval_timing(t->h_total, t->v_total, t->pixclk_khz,
				     &f.interval_num, &f.interval_den))
		f.interval_num = f.interval_den = 0;
	for (unsigned int i = 0; i < d->nsinks; i++) {
		int ret = rdc_sink_frame(d->sinks[i], &f);

		if (ret)
			rdcd_log(d, RDCD_LOG_WARN, "%s sink: frame %llu: %s",
				 rdc_sink_kind(d->sinks[i]),
				 (unsigned long long)number, rdc_strerror(ret));
	}
}

/*
 * THE frame path: the chip calls this with every frame it completes, at
 * the start of vertical blanking.  Everything that consumes frames
 * (subscribers; frame sinks) is fed from here.
 */
static void rdcd_on_frame(void *ctx, const uint32_t *xrgb, uint32_t w,
			  uint32_t h, uint64_t number)
{
	struct rdcd *d = ctx;

	d->frames++;
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		rdcd_frame_to_client(d, c, xrgb, w, h, number);
	if (d->nsinks)
		rdcd_frame_to_sinks(d, xrgb, w, h, number);
}

void rdcd_watch(struct rdcd *d)
{
	bool on = d->nclients || d->nsinks;

	if (!d->hw || on == d->watched)
		return;
	rdc_hw_set_frame_fn(d->hw, on ? rdcd_on_frame : NULL, d);
	d->watched = on;
}

/* ---- Device -------------------------------------------------------------- */

int rdcd_device_open(struct rdcd *d)
{
	char uri[48];
	int ret;

	snprintf(uri, sizeof(uri), "sim:vram=%u", d->vram_size);
	ret = rdc_open(uri, &d->dev);
	if (ret)
		return ret;
	d->hw = rdc_sim_hw(d->dev);
	if (d->rec)
		rdc_rec_attach(d->rec, d->dev);
	rdc_hw_set_on_demand(d->hw, true);
	d->watched = false;
	rdcd_watch(d);
	rdcd_trace_attach(d);
	rdcd_chip_attach(d);
	d->last_irq = 0;
	/* a power cycle's new chip: the pixel history goes on, on it */
	if (d->hist) {
		ret = rdc_history_attach(d->hist, d->dev);
		if (ret)
			rdcd_log(d, RDCD_LOG_ERR,
				 "pixel history: not kept on the new chip: %s",
				 rdc_strerror(ret));
	}
	return 0;
}

void rdcd_device_close(struct rdcd *d)
{
	if (d->rec && rdc_rec_close(d->rec, d->dev))
		rdcd_log(d, RDCD_LOG_ERR, "trace: write error");
	d->rec = NULL;
	rdc_close(d->dev);
	d->dev = NULL;
	d->hw = NULL;
}

static int rdcd_power_cycle(struct rdcd *d)
{
	int ret;

	if (d->rec)
		rdc_rec_power(d->rec);
	rdc_close(d->dev);
	d->dev = NULL;
	ret = rdcd_device_open(d);
	if (!ret)
		rdcd_gpiosim_new_chip(
			d); /* before time moves on the new chip */
	return ret;
}

/* ---- Clients ------------------------------------------------------------- */

void rdcd_log_limited(struct rdcd *d, struct rdcd_ratelog *rl, int level,
		      const char *fmt, ...)
{
	uint64_t now = rdcd_wall_ns();
	char line[256];
	va_list ap;

	if (rl->last_ns && now - rl->last_ns < 1000000000ull) {
		rl->quiet++;
		return;
	}
	va_start(ap, fmt);
	vsnprintf(line, sizeof(line), fmt, ap);
	va_end(ap);
	if (rl->quiet)
		rdcd_log(d, level, "%s (and %u more like it)", line, rl->quiet);
	else
		rdcd_log(d, level, "%s", line);
	rl->last_ns = now;
	rl->quiet = 0;
}

static void rdcd_client_drop_output(struct rdcd *d, struct rdcd_client *c);

/* Connections from listener `lis` that have (not) said HELLO. */
static unsigned int rdcd_count_lis(const struct rdcd *d, int lis, bool hello,
				   const struct rdcd_client **oldest)
{
	unsigned int n = 0;

	for (const struct rdcd_client *c = d->clients; c; c = c->next) {
		if (c->dead || c->lis != lis || c->hello != hello)
			continue;
		n++;
		if (oldest && (!*oldest || c->conn_ns < (*oldest)->conn_ns))
			*oldest = c;
	}
	return n;
}

struct rdcd_client *rdcd_client_new(struct rdcd *d, int fd, bool tcp,
				    const char *peer)
{
	const struct rdcd_client *oldest = NULL;
	struct rdcd_client *c;

	/* Silent connections never lock anyone out: the oldest one goes. */
	if (rdcd_count_lis(d, d->accept_lis, false, &oldest) >=
	    RDCD_MAX_PENDING) {
		struct rdcd_client *o = (struct rdcd_client *)oldest;

		rdcd_log_limited(
			d, &d->connlog, RDCD_LOG_WARN,
			"%u connections without HELLO on one listener: "
			"closing the oldest, client %u (%s)",
			RDCD_MAX_PENDING, o->id, o->peer);
		o->dead = true;
	}
	c = calloc(1, sizeof(*c));
	if (!c)
		return NULL;
	c->fd = fd;
	c->tcp = tcp;
	c->lis = d->accept_lis;
	c->conn_ns = rdcd_wall_ns();
	c->id = ++d->next_id;
	snprintf(c->peer, sizeof(c->peer), "%s", peer);
	c->next = d->clients;
	d->clients = c;
	rdcd_log(d, RDCD_LOG_DEBUG, "client %u connected (%s)", c->id, c->peer);
	return c;
}

uint64_t rdcd_hello_deadlines(struct rdcd *d)
{
	const uint64_t limit = (uint64_t)RDCD_HELLO_MS * 1000000ull;
	uint64_t now = rdcd_wall_ns(), next = UINT64_MAX;

	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		if (c->hello || c->dead || c->closing)
			continue;
		if (now - c->conn_ns >= limit) {
			rdcd_log_limited(
				d, &d->connlog, RDCD_LOG_INFO,
				"client %u (%s): no HELLO within %u ms: "
				"closing",
				c->id, c->peer, RDCD_HELLO_MS);
			c->dead = true;
		} else if (limit - (now - c->conn_ns) < next) {
			next = limit - (now - c->conn_ns);
		}
	}
	return next;
}

void rdcd_out_bound(struct rdcd *d)
{
	while (d->out_total > RDCD_OUT_TOTAL) {
		struct rdcd_client *slow = NULL;

		for (struct rdcd_client *c = d->clients; c; c = c->next)
			if (!c->dead && c->out_head &&
			    (!slow || c->out_since_ns < slow->out_since_ns))
				slow = c;
		if (!slow)
			return;
		rdcd_log(d, RDCD_LOG_WARN,
			 "client %u (%s): %zu bytes unread, %zu queued in all "
			 "(bound %u): disconnecting the slowest reader",
			 slow->id, slow->peer, slow->out_bytes, d->out_total,
			 RDCD_OUT_TOTAL);
		rdcd_client_drop_output(d, slow);
		slow->dead = true;
	}
}

/* Everything queued for c, gone (it is being disconnected). */
static void rdcd_client_drop_output(struct rdcd *d, struct rdcd_client *c)
{
	while (c->out_head) {
		struct rdcd_obuf *b = c->out_head;

		c->out_head = b->next;
		d->out_total -= b->len;
		free(b);
	}
	c->out_tail = NULL;
	c->out_bytes = 0;
	c->out_frame_bytes = 0;
	c->out_frames = 0;
}

void rdcd_client_free(struct rdcd *d, struct rdcd_client *c)
{
	struct rdcd_client **pp;

	for (pp = &d->clients; *pp; pp = &(*pp)->next) {
		if (*pp == c) {
			*pp = c->next;
			break;
		}
	}
	if (c->hello) {
		d->nclients--;
		rdcd_watch(d);
	}
	if (d->ctl == c) {
		d->ctl = NULL;
		rdcd_log(d, RDCD_LOG_INFO, "client %u left; nobody in control",
			 c->id);
	}
	if (c->pend != RDCD_PEND_NONE)
		rdcd_log(d, RDCD_LOG_WARN,
			 "client %u: left with a request pending", c->id);
	if (d->hist_client == c) {
		rdc_history_close(d->hist);
		d->hist = NULL;
		d->hist_client = NULL;
		rdcd_log(d, RDCD_LOG_INFO,
			 "client %u: its pixel history closed with it", c->id);
	}

	rdcd_log(d, c->hello ? RDCD_LOG_INFO : RDCD_LOG_DEBUG,
		 "client %u disconnected", c->id);
	close(c->fd);
	rdcd_client_drop_output(d, c);
	free(c->body);
	free(c->pend_words);
	rdcd_prev_free(d, c);
	free(c);
}

/* A whole request waits in hdr/body. */
static bool rdcd_have_request(const struct rdcd_client *c)
{
	return c->hdr_got == RDC_PROTO_HDR_SIZE && c->body_got == c->hdr.len;
}

bool rdcd_client_wants_read(const struct rdcd_client *c)
{
	/* frames do not count: they are bounded on their own */
	return !c->dead && !c->closing && !c->held &&
	       !(c->pend != RDCD_PEND_NONE && rdcd_have_request(c)) &&
	       c->out_bytes - c->out_frame_bytes < RDCD_OUT_HIGH;
}

void rdcd_client_flush(struct rdcd *d, struct rdcd_client *c)
{
	while (c->out_head && !c->dead) {
		struct rdcd_obuf *b = c->out_head;
		ssize_t k = send(c->fd, b->data + b->off, b->len - b->off,
				 MSG_NOSIGNAL | MSG_DONTWAIT);

		if (k < 0) {
			if (errno == EINTR)
				continue;
			if (errno == EAGAIN || errno == EWOULDBLOCK)
				return;
			rdcd_log(d, RDCD_LOG_INFO, "client %u: send: %s", c->id,
				 strerror(errno));
			c->dead = true;
			return;
		}
		b->off += (size_t)k;
		c->out_since_ns = rdcd_wall_ns();
		if (b->off < b->len)
			return;
		c->out_head = b->next;
		if (!c->out_head)
			c->out_tail = NULL;
		c->out_bytes -= b->len;
		d->out_total -= b->len;
		if (b->frame) {
			c->out_frames--;
			c->out_frame_bytes -= b->len;
		}
		free(b);
	}
	if (!c->out_head && c->closing)
		c->dead = true;
}

/* A reply with `n` payload bytes copied from p (may be NULL: zeroes). */
static uint8_t *rdcd_reply(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *req, uint32_t status,
			   const void *p, size_t n)
{
	struct rdcd_obuf *b = rdcd_obuf_new(n);

	if (!b) {
		rdcd_log(d, RDCD_LOG_ERR, "client %u: out of memory", c->id);
		c->dead = true;
		return NULL;
	}
	rdcd_obuf_hdr(b, req->type, RDC_MSGF_REPLY, req->seq, status);
	if (rdc_proto_reply_closes(req->type, status))
		c->closing = true; /* once this reply is out */
	if (n && p)
		memcpy(b->data + RDC_PROTO_HDR_SIZE, p, n);
	else if (n)
		memset(b->data + RDC_PROTO_HDR_SIZE, 0, n);
	rdcd_queue(d, c, b);
	/* not worth a line: the answers of ordinary polling and sizing */
	if (status != RDC_ST_OK && status != RDC_ST_NOFRAME &&
	    status != RDC_ST_TIMEOUT && status != RDC_ST_AUTH &&
	    !(status == RDC_ST_RANGE && req->type == RDC_MSG_FRAME_GRAB))
		rdcd_log(d, RDCD_LOG_INFO, "client %u: request %u (seq %u): %s",
			 c->id, req->type, req->seq, rdcd_status_name(status));
	return b->data + RDC_PROTO_HDR_SIZE;
}

static void rdcd_reply_err(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *req, int err)
{
	rdcd_reply(d, c, req, rdcd_status_from_error(err), NULL, 0);
}

/*
 * An error after which the stream cannot go on: reply, then hang up
 * (rdcd_reply does, as rdc_proto_reply_closes says).
 */
static void rdcd_fatal(struct rdcd *d, struct rdcd_client *c,
		       const struct rdc_proto_hdr *req, uint32_t status)
{
	if (status == RDC_ST_AUTH)
		rdcd_log_limited(d, &d->authlog, RDCD_LOG_WARN,
				 "client %u (%s): %s; closing", c->id, c->peer,
				 rdcd_status_name(status));
	else
		rdcd_log(d, RDCD_LOG_WARN, "client %u (%s): %s; closing", c->id,
			 c->peer, rdcd_status_name(status));
	rdcd_reply(d, c, req, status, NULL, 0);
}

/* ---- Requests ------------------------------------------------------------ */

/* Registers whose read changes the device (or means nothing). */
static bool rdcd_reg_read_changes(uint32_t reg)
{
	return rdc_reg_read_has_effect(reg);
}

static bool rdcd_reg_ok(uint32_t reg)
{
	return reg < RDC_REG_WINDOW && !(reg & 3);
}

static void rdcd_hello(struct rdcd *d, struct rdcd_client *c,
		       const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	struct rdc_proto_hello hello;
	struct rdc_proto_hello_reply r = {
		.version = RDC_PROTO_VERSION,
		.run_mode = d->mode,
		.vram_size = d->vram_size,
		.client_id = c->id,
	};
	uint8_t out[RDC_PROTO_HELLO_REPLY_SIZE];
	uint32_t st;

	if (c->hello) {
		rdcd_reply(d, c, h, RDC_ST_ORDER, NULL, 0);
		return;
	}
	st = (uint32_t)rdc_proto_hello_decode(pl, h->len, &hello);
	if (st) {
		rdcd_fatal(d, c, h, st);
		return;
	}
	if (c->tcp && d->have_token) {
		if (rdc_auth_locked(&d->auth, c->peer, rdcd_wall_ns())) {
			rdcd_fatal(d, c, h, RDC_ST_AUTH);
			return;
		}
		if (!rdc_auth_token_equal(d->token, d->token_len, hello.token,
					  hello.token_len)) {
			rdc_auth_failed(&d->auth, c->peer, rdcd_wall_ns());
			rdcd_fatal(d, c, h, RDC_ST_AUTH);
			return;
		}
		rdc_auth_passed(&d->auth, c->peer);
	}
	if (d->nclients >= RDCD_MAX_CLIENTS ||
	    rdcd_count_lis(d, c->lis, true, NULL) >=
		    RDCD_MAX_CLIENTS_PER_LISTENER) {
		rdcd_fatal(d, c, h, RDC_ST_BUSY);
		return;
	}
	c->hello = true;
	d->nclients++;
	rdcd_watch(d);
	rdcd_log(d, RDCD_LOG_INFO, "client %u said HELLO (%s)", c->id, c->peer);
	r.caps = RDC_CAP_ALL &
		 ~(d->mode == RDC_RUN_STEPPED ? 0u : RDC_CAP_STEP);
	r.caps &= hello.caps | RDC_CAP_STEP;
	if ((hello.flags & RDC_HELLO_CONTROL) && !d->ctl) {
		d->ctl = c;
		rdcd_log(d, RDCD_LOG_INFO, "client %u has control", c->id);
	}
	r.flags = d->ctl == c ? RDC_HELLO_CONTROL : 0;
	r.core_hz = RDC_DEFAULT_CORE_HZ;
	rdc_proto_hello_reply_encode(out, &r);
	rdcd_reply(d, c, h, RDC_ST_OK, out, sizeof(out));
}

/* A wait's budget as every backend of librdc defaults it: 0 = ten seconds. */
static uint64_t rdcd_wait_budget(uint64_t budget)
{
	return budget ? budget : RDC_WAIT_BUDGET_DEFAULT;
}

static int rdcd_wait_from_proto(const uint8_t *pl, size_t len,
				struct rdc_hw_wait *w)
{
	struct rdc_proto_wait pw;
	int st = rdc_proto_wait_decode(pl, len, &pw);

	if (st)
		return st;
	memset(w, 0, sizeof(*w));
	if (pw.budget > (uint64_t)RDCD_MAX_BUDGET_S * RDC_DEFAULT_CORE_HZ)
		return RDC_ST_RANGE;
	w->budget = rdcd_wait_budget(pw.budget);
	w->needs_dp = pw.needs_dp;
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		if (pw.term[i].kind > RDC_WAIT_TEST_EQ)
			return RDC_ST_INVAL;
		if (pw.term[i].kind != RDC_WAIT_TEST_NONE &&
		    (!rdcd_reg_ok(pw.term[i].reg) ||
		     rdcd_reg_read_changes(pw.term[i].reg)))
			return RDC_ST_INVAL;
		w->term[i].test = pw.term[i].kind;
		w->term[i].reg = pw.term[i].reg;
		w->term[i].mask = pw.term[i].mask;
		w->term[i].value = pw.term[i].value;
	}
	return 0;
}

static bool rdcd_halted(struct rdcd *d)
{
	return rdc_hw_read(d->hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED;
}

/*
 * Stepped mode: the controller's wait moves time itself, on the chip's
 * stack, a piece at a time with a yield point between (chip.c), so that
 * everyone else is served meanwhile; where it ends does not depend on the
 * pieces (hw-sim/wait.c).  The trace records the time it moved as steps,
 * between whatever the others did meanwhile.  A client that left stops
 * its wait: nobody is there to answer.
 */
static int rdcd_stepped_wait_run(struct rdcd *d, struct rdcd_client *c,
				 struct rdc_hw_wait *w)
{
	for (;;) {
		rdc_rec_time_moved(d->rec, rdc_hw_now(d->hw));
		switch (rdc_hw_wait_run(d->hw, w, RDCD_WAIT_PIECE)) {
		case RDC_HW_WAIT_MORE:
			break;
		case RDC_HW_WAIT_DONE:
			return 0;
		case RDC_HW_WAIT_HALTED:
			return RDC_E_HALTED;
		default:
			return RDC_E_TIMEOUT;
		}
		if (c->dead)
			return RDC_E_IO;
		rdcd_chip_yield_point(d);
	}
}

/*
 * Stepped mode: a SUBMIT feeds the FIFO as sim:'s rdc_submit does (the
 * same reads of FIFO_FREE, the same waits for half a FIFO of room, so the
 * same cycles), except that the waits of one SUBMIT share one budget of
 * RDCD_SUBMIT_BUDGET_S simulated seconds: then TIMEOUT, the words not yet
 * taken dropped.  Each wait gets sim:'s default budget or what is left.
 */
static int rdcd_stepped_submit(struct rdcd *d, struct rdcd_client *c)
{
	const uint64_t total =
		(uint64_t)RDCD_SUBMIT_BUDGET_S * RDC_DEFAULT_CORE_HZ;
	uint64_t start = rdc_hw_now(d->hw);

	while (c->pend_done < c->pend_n) {
		size_t left = c->pend_n - c->pend_done, k;
		uint32_t room, w[RDC_FIFO_DEPTH];
		int ret;

		if (c->dead)
			return RDC_E_IO;
		ret = rdc_reg_read(d->dev, RDC_REG_FIFO_FREE, &room);
		if (ret)
			return ret;
		if (!room) {
			struct rdc_hw_wait *rw = &c->pend_hw;
			const struct rdc_wait_cond room_cond = {
				.test = RDC_WAIT_TEST_GE,
				.reg = RDC_REG_FIFO_FREE,
				.mask = ~0u,
				.value = left < RDC_FIFO_DEPTH / 2 ?
						 (uint32_t)left :
						 RDC_FIFO_DEPTH / 2,
			};
			uint64_t used = rdc_hw_now(d->hw) - start;

			if (used >= total)
				return RDC_E_TIMEOUT;
			*rw = (struct rdc_hw_wait){
				.term[0] = room_cond,
				.needs_dp = true,
				.budget = rdcd_wait_budget(RDC_MIN(
					RDC_WAIT_BUDGET_DEFAULT, total - used)),
			};
			rdc_hw_wait_begin(d->hw, &c->pend_hw);
			ret = rdcd_stepped_wait_run(d, c, &c->pend_hw);
			if (ret)
				return ret;
			continue;
		}
		k = RDC_MIN(RDC_MIN((size_t)room, (size_t)RDC_FIFO_DEPTH),
			    left);
		for (size_t i = 0; i < k; i++)
			w[i] = rdc_proto_get32(c->pend_words +
					       4 * (c->pend_done + i));
		ret = rdc_submit(d->dev, w, k);
		if (ret)
			return ret;
		c->pend_done += k;
	}
	return 0;
}

/* The pending request is over: answer it (unless its client left). */
static void rdcd_pending_end(struct rdcd *d, struct rdcd_client *c, int ret)
{
	if (!c->dead)
		rdcd_reply_err(d, c, &c->pend_hdr, ret);
	c->pend = RDCD_PEND_NONE;
	free(c->pend_words);
	c->pend_words = NULL;
}

/* Stepped mode, on the chip's stack: the controller's request, whole. */
static void rdcd_stepped_job(struct rdcd *d, void *arg)
{
	struct rdcd_client *c = arg;
	int ret = 0;

	switch (c->pend) {
	case RDCD_PEND_WAIT:
		ret = rdcd_stepped_wait_run(d, c, &c->pend_hw);
		break;
	case RDCD_PEND_SUBMIT:
		ret = rdcd_stepped_submit(d, c);
		break;
	case RDCD_PEND_STEP:
		while (rdc_hw_now(d->hw) < c->pend_target && !c->dead) {
			rdc_rec_time_moved(d->rec, rdc_hw_now(d->hw));
			rdc_hw_run_until(d->hw, RDC_MIN(rdc_hw_now(d->hw) +
								RDCD_WAIT_PIECE,
							c->pend_target));
			rdcd_chip_yield_point(d);
		}
		break;
	default:
		break;
	}
	/* the answer depends on the time moved: a live trace has it first */
	rdc_rec_sync(d->rec);
	rdcd_pending_end(d, c, ret);
	d->chip_client = NULL;
}

int rdcd_stepped_start(struct rdcd *d)
{
	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		if (c->pend == RDCD_PEND_NONE)
			continue;
		d->chip_client = c;
		return rdcd_chip_run(d, rdcd_stepped_job, c);
	}
	return -1;
}

/*
 * Paced and fast modes: progress on a pending request after the loop
 * moved time.  Returns true when it finished and was answered.  A SUBMIT
 * that cannot get FIFO room (the DP in an endless list) ends with TIMEOUT
 * after RDCD_SUBMIT_BUDGET_S of simulated or of host time, whichever
 * comes first.
 */
static bool rdcd_pending_step(struct rdcd *d, struct rdcd_client *c)
{
	int ret = 0;

	switch (c->pend) {
	case RDCD_PEND_SUBMIT:
		while (c->pend_done < c->pend_n) {
			uint32_t room, w[RDC_FIFO_DEPTH];
			size_t k;

			ret = rdc_reg_read(d->dev, RDC_REG_FIFO_FREE, &room);
			if (ret || !room)
				break;
			k = RDC_MIN(RDC_MIN((size_t)room, RDC_FIFO_DEPTH),
				    c->pend_n - c->pend_done);
			for (size_t i = 0; i < k; i++)
				w[i] = rdc_proto_get32(c->pend_words +
						       4 * (c->pend_done + i));
			ret = rdc_submit(d->dev, w, k);
			if (ret)
				break;
			c->pend_done += k;
		}
		if (!ret && c->pend_done < c->pend_n) {
			uint64_t sim = (uint64_t)RDCD_SUBMIT_BUDGET_S *
				       RDC_DEFAULT_CORE_HZ;
			uint64_t wall =
				(uint64_t)RDCD_SUBMIT_BUDGET_S * 1000000000ull;

			if (rdcd_halted(d))
				ret = RDC_E_HALTED;
			else if (rdc_hw_now(d->hw) - c->pend_start >= sim ||
				 rdcd_wall_ns() - c->pend_wall_ns >= wall)
				ret = RDC_E_TIMEOUT;
			else
				return false;
		}
		break;
	case RDCD_PEND_WAIT: {
		struct rdc_hw_wait w = c->pend_wait;

		/* time moves with the daemon's clock: only the checks here */
		w.start = c->pend_start;
		switch (rdc_hw_wait_check(d->hw, &w)) {
		case RDC_HW_WAIT_DONE:
			break;
		case RDC_HW_WAIT_HALTED:
			ret = RDC_E_HALTED;
			break;
		case RDC_HW_WAIT_TIMEOUT:
			ret = RDC_E_TIMEOUT;
			break;
		default:
			return false;
		}
		break;
	}
	case RDCD_PEND_STEP:
		if (rdc_hw_now(d->hw) < c->pend_target)
			return false;
		break;
	default:
		return false;
	}
	rdcd_pending_end(d, c, ret);
	return true;
}

bool rdcd_feed_pending(struct rdcd *d)
{
	bool more = false;

	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		if (c->pend != RDCD_PEND_SUBMIT || c->dead)
			continue;
		if (!rdcd_pending_step(d, c))
			more = true;
	}
	return more;
}

bool rdcd_has_pending(const struct rdcd *d)
{
	for (const struct rdcd_client *c = d->clients; c; c = c->next)
		if (c->pend != RDCD_PEND_NONE)
			return true;
	return false;
}

static void rdcd_irq_events(struct rdcd *d)
{
	uint32_t st = rdc_hw_read(d->hw, RDC_REG_IRQ_STATUS);
	uint32_t rising = st & ~d->last_irq;
	uint8_t ev[12];

	d->last_irq = st;
	if (!rising)
		return;
	rdc_proto_put32(ev, rising);
	rdc_proto_put64(ev + 4, rdc_hw_now(d->hw));
	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		struct rdcd_obuf *b;

		if (c->dead || !(c->sub_events & RDC_SUB_IRQ))
			continue;
		/* small, but bounded all the same */
		if (c->out_bytes > RDCD_OUT_HIGH)
			continue;
		b = rdcd_obuf_new(sizeof(ev));
		if (!b)
			continue;
		rdcd_obuf_hdr(b, RDC_MSG_EV_IRQ, RDC_MSGF_EVENT, 0, RDC_ST_OK);
		memcpy(b->data + RDC_PROTO_HDR_SIZE, ev, sizeof(ev));
		rdcd_queue(d, c, b);
	}
}

void rdcd_after_advance(struct rdcd *d)
{
	/* (stepped: the chip's run answered its request itself) */
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		if (d->mode != RDC_RUN_STEPPED && c->pend != RDCD_PEND_NONE &&
		    !c->dead)
			rdcd_pending_step(d, c);
	rdcd_irq_events(d);
}

static void rdcd_stats(struct rdcd *d, struct rdcd_client *c,
		       const struct rdc_proto_hdr *h)
{
	struct rdc_proto_stats ps = { 0 };
	struct rdc_stats st;
	uint8_t out[RDC_PROTO_STATS_SIZE];
	int ret = rdc_stats_get(d->dev, &st);

	if (ret) {
		rdcd_reply_err(d, c, h, ret);
		return;
	}
	ps.time = st.time;
	ps.busy = st.busy;
	ps.stall = st.stall;
	ps.pixels = st.pixels;
	ps.frames = st.frames;
	ps.cmds = st.cmds;
	ps.last_cycles = st.last_cycles;
	ps.last_opcode = st.last_opcode;
	ps.clients = d->nclients;
	ps.frames_sent = c->frames_sent;
	ps.frames_dropped = c->frames_dropped;
	rdc_proto_stats_encode(out, &ps);
	rdcd_reply(d, c, h, RDC_ST_OK, out, sizeof(out));
}

static void rdcd_frame_grab(struct rdcd *d, struct rdcd_client *c,
			    const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	uint32_t enc = rdc_proto_get32(pl), max = rdc_proto_get32(pl + 4);
	uint32_t w = 0, ht = 0;
	const uint32_t *pix = rdc_hw_frame(d->hw, &w, &ht);
	/* FRAME_COUNT counts the frame that just completed */
	struct rdc_proto_frame f = {
		.number = rdc_hw_read(d->hw, RDC_REG_FRAME_COUNT) - 1u
	};
	struct rdcd_obuf *b;
	uint8_t fh[RDC_PROTO_FRAME_HDR];

	if (enc >= RDC_ENC_COUNT_) {
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	if (!pix) {
		rdcd_reply(d, c, h, RDC_ST_NOFRAME, NULL, 0);
		return;
	}
	if ((uint64_t)w * ht > max) {
		f.width = w;
		f.height = ht;
		rdc_proto_frame_hdr_encode(fh, &f);
		rdcd_reply(d, c, h, RDC_ST_RANGE, fh, sizeof(fh));
		return;
	}
	b = rdcd_frame_msg(pix, NULL, w, ht, enc, &f);
	if (!b) {
		rdcd_reply_err(d, c, h, RDC_E_NOMEM);
		return;
	}
	rdcd_obuf_hdr(b, h->type, RDC_MSGF_REPLY, h->seq, RDC_ST_OK);
	rdcd_queue(d, c, b);
}

/* ---- Pixel history (docs/history.md) -------------------------------------- */

/* A page of the client's history: entries [first, first + n). */
static void rdcd_hist_read(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	uint64_t first = rdc_proto_get64(pl), count;
	uint32_t max = rdc_proto_get32(pl + 8);
	struct rdc_proto_hist_page pg = { 0 };
	uint8_t *out;

	/* the client's buffer and the page bound, as VRAM_READ's length */
	if (max > RDC_PROTO_HIST_PAGE) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	count = rdc_history_count(d->hist);
	if (first > count) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	pg.count = count;
	pg.dropped = rdc_history_dropped(d->hist);
	pg.n = (uint32_t)RDC_MIN((uint64_t)max, count - first);
	out = rdcd_reply(d, c, h, RDC_ST_OK, NULL,
			 RDC_PROTO_HIST_PAGE_HDR +
				 (size_t)pg.n * RDC_PROTO_HIST_ENTRY_SIZE);
	if (!out)
		return;
	for (uint32_t i = 0; i < pg.n; i++) {
		struct rdc_history_entry e;
		struct rdc_proto_hist_entry pe;

		if (rdc_history_get(d->hist, first + i, &e)) {
			pg.n = i; /* cannot happen: counted above */
			break;
		}
		pe = (struct rdc_proto_hist_entry){
			.x = e.x,
			.y = e.y,
			.format = e.format,
			.before = e.before,
			.after = e.after,
			.cycle = e.cycle,
			.frame = e.frame,
			.fetched = e.fetched,
			.opcode = e.opcode,
			.cmd_index = e.cmd_index,
			.source = e.source,
			.line = e.line,
			.cmd_addr = e.cmd_addr,
			.depth = e.depth,
			.rop = e.rop,
			.alpha = e.alpha,
			.colorkey = e.colorkey,
			.colorkey_on = e.colorkey_on,
			.pattern = e.pattern,
			.fg = e.fg,
			.bg = e.bg,
		};
		memcpy(pe.calls, e.calls, sizeof(pe.calls));
		rdc_proto_hist_entry_encode(
			out + RDC_PROTO_HIST_PAGE_HDR +
				(size_t)i * RDC_PROTO_HIST_ENTRY_SIZE,
			&pe);
	}
	rdc_proto_hist_page_encode(out, &pg);
}

/*
 * HIST_*: one history on the chip at a time, the client's that opened it
 * (BUSY for anyone else), closed by HIST_END or when that client goes.
 */
static void rdcd_hist(struct rdcd *d, struct rdcd_client *c,
		      const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	struct rdc_proto_hist_open o;
	uint32_t what, value;
	int ret;

	if (h->type != RDC_MSG_HIST_OPEN && d->hist_client != c) {
		rdcd_log(d, RDCD_LOG_INFO, "client %u: no pixel history open",
			 c->id);
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	switch (h->type) {
	case RDC_MSG_HIST_OPEN:
		rdc_proto_hist_open_decode(pl, h->len, &o);
		if (d->hist) {
			rdcd_log(d, RDCD_LOG_INFO,
				 "client %u: client %u keeps the pixel history",
				 c->id, d->hist_client->id);
			rdcd_reply(d, c, h, RDC_ST_BUSY, NULL, 0);
			break;
		}
		if (o.flags & RDC_HISTORY_WRITES) {
			/* a write log of millions of accesses: not kept here */
			rdcd_reply(d, c, h, RDC_ST_NOSYS, NULL, 0);
			break;
		}
		if (o.flags || !o.w || !o.h) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		}
		ret = rdc_history_open(d->dev, o.x, o.y, o.w, o.h, 0, &d->hist);
		if (!ret)
			ret = rdc_history_set_limit(d->hist,
						    RDC_PROTO_HIST_LIMIT_MAX);
		if (ret) {
			rdc_history_close(d->hist);
			d->hist = NULL;
			rdcd_reply_err(d, c, h, ret);
			break;
		}
		d->hist_client = c;
		rdcd_log(d, RDCD_LOG_INFO,
			 "client %u: pixel history of %u,%u %ux%u", c->id, o.x,
			 o.y, o.w, o.h);
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	case RDC_MSG_HIST_READ:
		rdcd_hist_read(d, c, h, pl);
		break;
	case RDC_MSG_HIST_SET:
		what = rdc_proto_get32(pl);
		value = rdc_proto_get32(pl + 4);
		if (what == RDC_HIST_SET_LINE) {
			rdc_history_set_line(d->hist, value);
		} else if (what != RDC_HIST_SET_LIMIT || !value) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		} else if (value > RDC_PROTO_HIST_LIMIT_MAX) {
			rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
			break;
		} else {
			rdc_history_set_limit(d->hist, value);
		}
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	default: /* RDC_MSG_HIST_END */
		rdc_history_close(d->hist);
		d->hist = NULL;
		d->hist_client = NULL;
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	}
}

/* Does this request need control of the device? */
static bool rdcd_needs_control(const struct rdcd *d,
			       const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	switch (h->type) {
	case RDC_MSG_REG_WRITE:
	case RDC_MSG_VRAM_WRITE:
	case RDC_MSG_SUBMIT:
	case RDC_MSG_STEP:
	case RDC_MSG_RESET:
	case RDC_MSG_PINS_SET:
		return true;
	case RDC_MSG_WAIT:
		/* in stepped mode a wait moves time */
		return d->mode == RDC_RUN_STEPPED;
	case RDC_MSG_REG_READ:
		return rdcd_reg_read_changes(rdc_proto_get32(pl));
	default:
		return false;
	}
}

/* The HI register whose value a read of `reg` snapshots, or 0. */
static uint32_t rdcd_snap_hi(uint32_t reg)
{
	switch (reg) {
	case RDC_REG_TIME_LO:
	case RDC_REG_PERF_BUSY_LO:
	case RDC_REG_PERF_STALL_LO:
	case RDC_REG_PERF_PIXELS_LO:
		return reg + 4;
	default:
		return 0;
	}
}

/* A chip reset drops the snapshots, the clients' as the chip's. */
static void rdcd_snap_forget(struct rdcd *d)
{
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		c->snap_reg = 0;
}

/*
 * A client's register read.  The chip keeps one *_HI snapshot, taken by
 * a *_LO read (docs/hardware.md); several clients reading 64-bit
 * counters would take each other's.  So each client has its own: a LO
 * read here reads its HI on the chip at once (the chip's snapshot used
 * up: the chip's state is as after a whole 64-bit read, and a trace
 * holds both reads), and that client's HI read is answered from it.
 */
static int rdcd_reg_read(struct rdcd *d, struct rdcd_client *c, uint32_t reg,
			 uint32_t *v)
{
	uint32_t hi = rdcd_snap_hi(reg);
	int ret;

	if (c->snap_reg && reg == c->snap_reg) {
		*v = c->snap_val;
		c->snap_reg = 0;
		return 0;
	}
	ret = rdc_reg_read(d->dev, reg, v);
	if (!ret && hi) {
		c->snap_reg = 0;
		if (!rdc_reg_read(d->dev, hi, &c->snap_val))
			c->snap_reg = hi;
	}
	return ret;
}

static void rdcd_submit(struct rdcd *d, struct rdcd_client *c,
			const struct rdc_proto_hdr *h, uint8_t **pl)
{
	size_t n = h->len / 4;

	c->pend = RDCD_PEND_SUBMIT;
	c->pend_hdr = *h;
	c->pend_words = *pl; /* taken over */
	*pl = NULL;
	c->pend_n = n;
	c->pend_done = 0;
	c->pend_start = rdc_hw_now(d->hw);
	c->pend_wall_ns = rdcd_wall_ns();
	/* stepped: the loop's next turn runs it on the chip */
	if (d->mode != RDC_RUN_STEPPED)
		rdcd_pending_step(d, c);
}

/*
 * Drive RESET_N and BL_EN as a wire to the chip would; the reply is the
 * four levels after.  A trace records the change (record.c).
 */
static void rdcd_pins_set(struct rdcd *d, struct rdcd_client *c,
			  const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	uint32_t mask = rdc_proto_get32(pl), levels = rdc_proto_get32(pl + 4);
	uint8_t out[4];
	uint32_t pins = 0;
	int ret;

	if (mask & ~RDC_PINS_IN) {
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	ret = rdc_pins_set(d->dev, mask, levels);
	if (!ret)
		ret = rdc_pins_get(d->dev, &pins);
	if (ret) {
		rdcd_reply_err(d, c, h, ret);
		return;
	}
	if (mask)
		rdcd_log(d, RDCD_LOG_DEBUG, "client %u: pins %#x", c->id, pins);
	rdc_proto_put32(out, pins);
	rdcd_reply(d, c, h, RDC_ST_OK, out, sizeof(out));
	rdcd_irq_events(d);
}

/*
 * Before a reset: a run of the chip stops where it is (the reset replaces
 * what it was doing); the resetting client's own pending request ends
 * with RESET (it asked for it: the way to abort a submit stuck behind an
 * endless display list); after a power cycle time starts again at 0, so
 * every other client's pending wait, step or submit ends with RESET too.
 * A soft reset keeps time: the others' waits go on, on the reset chip.
 */
static void rdcd_reset_pending(struct rdcd *d, struct rdcd_client *c,
			       bool power)
{
	if (rdcd_chip_busy(d)) {
		rdcd_chip_abort(d);
		d->chip_client = NULL;
	}
	for (struct rdcd_client *o = d->clients; o; o = o->next)
		if (o->pend != RDCD_PEND_NONE && (o == c || power))
			rdcd_pending_end(d, o, RDC_E_RESET);
}

static void rdcd_dispatch(struct rdcd *d, struct rdcd_client *c,
			  const struct rdc_proto_hdr *h, uint8_t **body)
{
	const uint8_t *pl = *body;
	uint8_t out[8];
	uint32_t v = 0;
	int ret, st;

	if (h->type == RDC_MSG_HELLO) {
		rdcd_hello(d, c, h, pl);
		return;
	}
	if (!c->hello) {
		rdcd_reply(d, c, h, RDC_ST_ORDER, NULL, 0);
		return;
	}
	st = rdc_proto_request_check(h);
	if (st) {
		rdcd_reply(d, c, h, (uint32_t)st, NULL, 0);
		return;
	}
	if (rdcd_needs_control(d, h, pl) && d->ctl != c) {
		rdcd_reply(d, c, h, RDC_ST_BUSY, NULL, 0);
		return;
	}
	switch (h->type) {
	case RDC_MSG_REG_READ:
		ret = rdcd_reg_read(d, c, rdc_proto_get32(pl), &v);
		rdc_proto_put32(out, v);
		if (ret)
			rdcd_reply_err(d, c, h, ret);
		else
			rdcd_reply(d, c, h, RDC_ST_OK, out, 4);
		break;
	case RDC_MSG_REG_WRITE:
		if (rdc_proto_get32(pl) == RDC_REG_CONTROL &&
		    (rdc_proto_get32(pl + 4) & RDC_CONTROL_SOFT_RESET))
			rdcd_snap_forget(d);
		ret = rdc_reg_write(d->dev, rdc_proto_get32(pl),
				    rdc_proto_get32(pl + 4));
		rdcd_reply_err(d, c, h, ret);
		/* a W1C of IRQ_STATUS (or a reset) lowers bits: the next raise
		 * of one of them is an event again */
		rdcd_irq_events(d);
		break;
	case RDC_MSG_VRAM_READ: {
		uint32_t addr = rdc_proto_get32(pl),
			 len = rdc_proto_get32(pl + 4);
		uint8_t *p;

		if (len > RDC_PROTO_VRAM_CHUNK) {
			rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
			break;
		}
		if ((uint64_t)addr + len > d->vram_size) {
			rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
			break;
		}
		p = rdcd_reply(d, c, h, RDC_ST_OK, NULL, len);
		if (p && rdc_vram_read(d->dev, addr, p, len))
			memset(p, 0, len); /* checked above: cannot happen */
		break;
	}
	case RDC_MSG_VRAM_WRITE:
		ret = rdc_vram_write(d->dev, rdc_proto_get32(pl), pl + 4,
				     h->len - 4);
		rdcd_reply_err(d, c, h, ret);
		break;
	case RDC_MSG_SUBMIT:
		rdcd_submit(d, c, h, body);
		break;
	case RDC_MSG_WAIT: {
		struct rdc_hw_wait w;

		st = rdcd_wait_from_proto(pl, h->len, &w);
		if (st) {
			rdcd_reply(d, c, h, (uint32_t)st, NULL, 0);
			break;
		}
		c->pend = RDCD_PEND_WAIT;
		c->pend_hdr = *h;
		c->pend_wait = w;
		c->pend_start = rdc_hw_now(d->hw);
		c->pend_wall_ns = rdcd_wall_ns();
		if (d->mode == RDC_RUN_STEPPED) {
			c->pend_hw = w;
			rdc_hw_wait_begin(d->hw, &c->pend_hw);
		} else if (rdcd_pending_step(d, c)) {
			rdcd_irq_events(d);
		}
		break;
	}
	case RDC_MSG_STEP: {
		uint64_t cyc = rdc_proto_get64(pl);

		if (cyc > (uint64_t)RDCD_MAX_BUDGET_S * RDC_DEFAULT_CORE_HZ) {
			rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
			break;
		}
		c->pend = RDCD_PEND_STEP;
		c->pend_hdr = *h;
		c->pend_target = rdc_hw_now(d->hw) + cyc;
		c->pend_start = rdc_hw_now(d->hw);
		c->pend_wall_ns = rdcd_wall_ns();
		if (d->mode != RDC_RUN_STEPPED)
			rdcd_pending_step(d, c);
		break;
	}
	case RDC_MSG_FRAME_GRAB:
		rdcd_frame_grab(d, c, h, pl);
		break;
	case RDC_MSG_SUBSCRIBE: {
		uint32_t ev = rdc_proto_get32(pl),
			 every = rdc_proto_get32(pl + 4);
		uint32_t enc = rdc_proto_get32(pl + 8);

		if ((ev & ~(RDC_SUB_FRAMES | RDC_SUB_IRQ)) ||
		    enc >= RDC_ENC_COUNT_ ||
		    ((ev & RDC_SUB_FRAMES) && !every)) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		}
		c->sub_events = ev;
		c->sub_every = every ? every : 1;
		c->sub_enc = enc;
		c->frame_tick = 0;
		rdcd_prev_free(d, c);
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	}
	case RDC_MSG_STATS:
		rdcd_stats(d, c, h);
		break;
	case RDC_MSG_RESET:
		v = rdc_proto_get32(pl);
		if (v != RDC_RESET_SOFT && v != RDC_RESET_POWER) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		}
		rdcd_reset_pending(d, c, v == RDC_RESET_POWER);
		rdcd_snap_forget(d);
		if (v == RDC_RESET_SOFT) {
			ret = rdc_reset(d->dev);
		} else {
			ret = rdcd_power_cycle(d);
			if (ret) {
				rdcd_log(d, RDCD_LOG_ERR,
					 "power cycle failed: %s",
					 rdc_strerror(ret));
				rdcd_reply_err(d, c, h, ret);
				break;
			}
			d->pace_sim0 = 0;
			d->pace_wall0_ns = 0;
		}
		rdcd_log(d, RDCD_LOG_INFO, "client %u: reset (%s)", c->id,
			 v == RDC_RESET_POWER ? "power" : "soft");
		rdcd_reply_err(d, c, h, ret);
		break;
	case RDC_MSG_CLAIM:
		if (!d->ctl) {
			d->ctl = c;
			rdcd_log(d, RDCD_LOG_INFO, "client %u has control",
				 c->id);
		}
		rdcd_reply(d, c, h, d->ctl == c ? RDC_ST_OK : RDC_ST_BUSY, NULL,
			   0);
		break;
	case RDC_MSG_RELEASE:
		if (d->ctl == c) {
			d->ctl = NULL;
			rdcd_log(d, RDCD_LOG_INFO, "client %u released control",
				 c->id);
		}
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	case RDC_MSG_PING:
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	case RDC_MSG_PINS_SET:
		/* RESET_N moved resets the chip */
		if (rdc_proto_get32(pl) & RDC_PIN_RESET_N)
			rdcd_snap_forget(d);
		rdcd_pins_set(d, c, h, pl);
		break;
	case RDC_MSG_HIST_OPEN:
	case RDC_MSG_HIST_READ:
	case RDC_MSG_HIST_SET:
	case RDC_MSG_HIST_END:
		rdcd_hist(d, c, h, pl);
		break;
	default:
		rdcd_reply(d, c, h, RDC_ST_TYPE, NULL, 0);
		break;
	}
}

/* Does this request touch the chip (so must wait while it runs a slice)? */
static bool rdcd_touches_chip(const struct rdcd *d,
			      const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	switch (h->type) {
	case RDC_MSG_REG_WRITE:
	case RDC_MSG_VRAM_WRITE:
	case RDC_MSG_SUBMIT:
	case RDC_MSG_WAIT:
	case RDC_MSG_STEP:
	case RDC_MSG_PINS_SET:
	case RDC_MSG_RESET:
		return true;
	case RDC_MSG_HIST_OPEN:
	case RDC_MSG_HIST_READ:
	case RDC_MSG_HIST_SET:
	case RDC_MSG_HIST_END:
		/* a history's entries are complete between commands only */
		return true;
	case RDC_MSG_REG_READ:
		/* a trace replays reads between commands, never inside */
		return (d->rec && !rdcd_chip_between(d)) || h->len < 4 ||
		       rdcd_reg_read_changes(rdc_proto_get32(pl));
	case RDC_MSG_VRAM_READ:
	case RDC_MSG_STATS:
		return d->rec && !rdcd_chip_between(d);
	default:
		return false;
	}
}

/*
 * May the whole request in c's buffer be handled now?  Not while c has a
 * request pending (requests are answered in order), except the
 * controller's RESET, which ends it; not, while the chip is inside a run
 * (chip.c), if it would touch the chip, except a RESET, which stops the
 * run.  Such a request is held, and its client not read further.
 */
static bool rdcd_may_dispatch(const struct rdcd *d, const struct rdcd_client *c)
{
	const struct rdc_proto_hdr *h = &c->hdr;
	/* only a RESET that will act may overtake: one of an unknown kind
	 * is answered in its turn */
	bool reset = c->hello && d->ctl == c && h->type == RDC_MSG_RESET &&
		     h->len == 4 && !h->flags && !h->status &&
		     rdc_proto_get32(c->body) <= RDC_RESET_POWER;

	if (!c->hello)
		return true;
	if (c->pend != RDCD_PEND_NONE)
		return reset;
	if (rdcd_chip_busy(d) && !reset)
		return !rdcd_touches_chip(d, h, c->body);
	return true;
}

static void rdcd_take_request(struct rdcd *d, struct rdcd_client *c)
{
	rdcd_dispatch(d, c, &c->hdr, &c->body);
	free(c->body);
	c->body = NULL;
	c->body_cap = 0;
	c->hdr_got = 0;
	c->body_got = 0;
}

/* A header refused on its length: before HELLO nothing larger than a
 * HELLO. */
static bool rdcd_too_big(const struct rdcd_client *c)
{
	return c->hdr.len > RDC_PROTO_MAX_REQUEST ||
	       (!c->hello &&
		c->hdr.len > RDC_PROTO_HELLO_FIXED + RDC_PROTO_MAX_TOKEN);
}

/* A request's payload buffer grows with what arrives, from this size. */
#define RDCD_BODY_FIRST 4096u

/* Read what is there and handle complete requests, a few per turn. */
void rdcd_client_read(struct rdcd *d, struct rdcd_client *c)
{
	for (int turn = 0; turn < RDCD_REQ_PER_TURN;) {
		ssize_t k;

		if (!rdcd_client_wants_read(c))
			return;
		if (c->hdr_got < RDC_PROTO_HDR_SIZE) {
			k = recv(c->fd, c->hdrbuf + c->hdr_got,
				 RDC_PROTO_HDR_SIZE - c->hdr_got, MSG_DONTWAIT);
		} else {
			if (c->body_got == c->body_cap) {
				size_t cap = RDC_MAX(c->body_cap * 2,
						     (size_t)RDCD_BODY_FIRST);
				uint8_t *nb;

				cap = RDC_MIN(cap, (size_t)c->hdr.len);
				nb = realloc(c->body, cap);
				if (!nb) {
					rdcd_log(d, RDCD_LOG_ERR,
						 "client %u: out of memory",
						 c->id);
					c->dead = true;
					return;
				}
				c->body = nb;
				c->body_cap = cap;
			}
			k = recv(c->fd, c->body + c->body_got,
				 c->body_cap - c->body_got, MSG_DONTWAIT);
		}
		if (k < 0) {
			if (errno == EINTR)
				continue;
			if (errno != EAGAIN && errno != EWOULDBLOCK) {
				rdcd_log(d, RDCD_LOG_INFO,
					 "client %u: recv: %s", c->id,
					 strerror(errno));
				c->dead = true;
			}
			return;
		}
		if (k == 0) {
			if (c->hdr_got || c->body_got)
				rdcd_log(d, RDCD_LOG_WARN,
					 "client %u: hung up mid-message",
					 c->id);
			c->dead = true;
			return;
		}
		if (c->hdr_got < RDC_PROTO_HDR_SIZE) {
			c->hdr_got += (size_t)k;
			if (c->hdr_got < RDC_PROTO_HDR_SIZE)
				continue;
			rdc_proto_hdr_decode(c->hdrbuf, &c->hdr);
			if (rdcd_too_big(c)) {
				/* replies in request order: after the pending
				 * one (rdcd_release_held) */
				if (c->pend != RDCD_PEND_NONE)
					c->held = true;
				else
					rdcd_fatal(d, c, &c->hdr,
						   RDC_ST_TOOBIG);
				return;
			}
			c->body_got = 0;
			if (c->hdr.len)
				continue;
		} else {
			c->body_got += (size_t)k;
			if (c->body_got < c->hdr.len)
				continue;
		}
		if (!rdcd_may_dispatch(d, c)) {
			c->held = true;
			return;
		}
		rdcd_take_request(d, c);
		turn++;
	}
}

void rdcd_release_held(struct rdcd *d)
{
	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		if (!c->held || c->dead)
			continue;
		if (rdcd_too_big(c)) { /* no payload read: only this */
			if (c->pend == RDCD_PEND_NONE) {
				c->held = false;
				rdcd_fatal(d, c, &c->hdr, RDC_ST_TOOBIG);
			}
			continue;
		}
		if (!rdcd_may_dispatch(d, c))
			continue;
		c->held = false;
		rdcd_take_request(d, c);
		rdcd_client_read(d, c);
	}
}
