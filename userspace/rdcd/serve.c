// SPDX-License-Identifier: GPL-2.0-only
/*
 * rdcd: the device, the clients and their requests.
 *
 * The daemon's RDC-1 is librdc's sim: backend, driven through the same
 * backend operations a sim: application uses, so a request does to the
 * chip exactly what the library call would do in process.  In stepped mode
 * a wait or submit runs to completion inside the request (simulated time
 * moves only then, as on sim:); in paced and fast modes time belongs to
 * the loop and such requests stay pending until the device lets them
 * finish, while the client's socket is not read (back-pressure).
 *
 * Clients are distrusted: every length is checked against rdc_proto.h's
 * limits before anything is allocated, and a bad request gets an error
 * reply and a log line, never the daemon's end.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "hw.h"
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
	default:
		return RDC_ST_INVAL;
	}
}

static const char *rdcd_status_name(uint32_t st)
{
	static const char *const names[RDC_ST_COUNT_] = {
		"ok",	    "invalid argument", "out of memory",
		"not supported", "timeout",	"halted",
		"out of range", "malformed payload", "busy (not in control)",
		"bad token", "bad magic or version", "message too big",
		"no frame yet", "unknown type", "out of order",
		"device error",
	};

	return st < RDC_ST_COUNT_ ? names[st] : "?";
}

/* ---- Frames -------------------------------------------------------------- */

static void rdcd_queue(struct rdcd_client *c, struct rdcd_obuf *b)
{
	b->next = NULL;
	if (c->out_tail)
		c->out_tail->next = b;
	else
		c->out_head = b;
	c->out_tail = b;
	c->out_bytes += b->len;
	if (b->frame)
		c->out_frames++;
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
	n = enc == RDC_ENC_RAW ? 0
			       : rdc_proto_frame_encode(data, raw, enc, pix,
							prev, w, h);
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

static void rdcd_frame_to_client(struct rdcd *d, struct rdcd_client *c,
				 const uint32_t *xrgb, uint32_t w, uint32_t h,
				 uint64_t number)
{
	struct rdc_proto_frame f = {.number = number};
	const uint32_t *prev = NULL;
	struct rdcd_obuf *b;
	size_t px = (size_t)w * h;

	if (c->dead || !(c->sub_events & RDC_SUB_FRAMES))
		return;
	if (c->frame_tick++ % c->sub_every)
		return;
	/* A slow reader loses frames, alone: the device never waits. */
	if (c->out_frames >= RDCD_MAX_QUEUED_FRAMES) {
		c->frames_dropped++;
		return;
	}
	if (c->sub_enc == RDC_ENC_DELTA) {
		if (c->prev && (c->prev_w != w || c->prev_h != h)) {
			free(c->prev);
			c->prev = NULL;
		}
		if (!c->prev) {
			c->prev = malloc(px * 4 + 4);
			if (!c->prev) {
				c->frames_dropped++;
				return;
			}
		} else {
			prev = c->prev;
		}
	}
	f.dropped = (uint32_t)c->frames_dropped;
	b = rdcd_frame_msg(xrgb, prev, w, h, c->sub_enc, &f);
	if (!b) {
		c->frames_dropped++;
		return;
	}
	if (c->sub_enc == RDC_ENC_DELTA) {
		memcpy(c->prev, xrgb, px * 4);
		c->prev_w = w;
		c->prev_h = h;
	}
	rdcd_obuf_hdr(b, RDC_MSG_EV_FRAME, RDC_MSGF_EVENT, 0, RDC_ST_OK);
	b->frame = true;
	rdcd_queue(c, b);
	c->frames_sent++;
	rdcd_log(d, RDCD_LOG_DEBUG, "client %u: frame %llu queued", c->id,
		 (unsigned long long)number);
}

/* Sinks never stall the device: they drop what they cannot take. */
static void rdcd_frame_to_sinks(struct rdcd *d, const uint32_t *xrgb,
				uint32_t w, uint32_t h, uint64_t number)
{
	const struct rdc_timing *t = &d->hw->crtc.cur;
	struct rdc_frame f = {.xrgb = xrgb, .width = w, .height = h,
			      .stride = w, .seq = number};

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
	rdc_hw_set_frame_fn(d->hw, rdcd_on_frame, d);
	rdcd_trace_attach(d);
	d->last_irq = 0;
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
		rdcd_gpiosim_new_chip(d); /* before time moves on the new chip */
	return ret;
}

/* ---- Clients ------------------------------------------------------------- */

struct rdcd_client *rdcd_client_new(struct rdcd *d, int fd, bool tcp,
				    const char *peer)
{
	struct rdcd_client *c = calloc(1, sizeof(*c));

	if (!c)
		return NULL;
	c->fd = fd;
	c->tcp = tcp;
	c->id = ++d->next_id;
	snprintf(c->peer, sizeof(c->peer), "%s", peer);
	c->next = d->clients;
	d->clients = c;
	d->nclients++;
	rdcd_log(d, RDCD_LOG_INFO, "client %u connected (%s)", c->id, c->peer);
	return c;
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
	d->nclients--;
	if (d->ctl == c) {
		d->ctl = NULL;
		rdcd_log(d, RDCD_LOG_INFO, "client %u left; nobody in control",
			 c->id);
	}
	if (c->pend != RDCD_PEND_NONE)
		rdcd_log(d, RDCD_LOG_WARN,
			 "client %u: left with a request pending", c->id);

	rdcd_log(d, RDCD_LOG_INFO, "client %u disconnected", c->id);
	close(c->fd);
	while (c->out_head) {
		struct rdcd_obuf *b = c->out_head;

		c->out_head = b->next;
		free(b);
	}
	free(c->body);
	free(c->pend_words);
	free(c->prev);
	free(c);
}

bool rdcd_client_wants_read(const struct rdcd_client *c)
{
	return !c->dead && !c->closing && c->pend == RDCD_PEND_NONE &&
	       c->out_bytes < RDCD_OUT_HIGH + (size_t)c->out_frames *
							RDC_PROTO_MAX_REPLY;
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
		if (b->off < b->len)
			return;
		c->out_head = b->next;
		if (!c->out_head)
			c->out_tail = NULL;
		c->out_bytes -= b->len;
		if (b->frame)
			c->out_frames--;
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
	if (n && p)
		memcpy(b->data + RDC_PROTO_HDR_SIZE, p, n);
	else if (n)
		memset(b->data + RDC_PROTO_HDR_SIZE, 0, n);
	rdcd_queue(c, b);
	/* not worth a line: the answers of ordinary polling and sizing */
	if (status != RDC_ST_OK && status != RDC_ST_NOFRAME &&
	    status != RDC_ST_TIMEOUT &&
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

/* An error after which the stream cannot go on: reply, then hang up. */
static void rdcd_fatal(struct rdcd *d, struct rdcd_client *c,
		       const struct rdc_proto_hdr *req, uint32_t status)
{
	rdcd_log(d, RDCD_LOG_WARN, "client %u (%s): %s; closing", c->id,
		 c->peer, rdcd_status_name(status));
	rdcd_reply(d, c, req, status, NULL, 0);
	c->closing = true;
}

/* ---- Requests ------------------------------------------------------------ */

/* Registers whose read changes the device. */
static bool rdcd_reg_read_changes(uint32_t reg)
{
	return reg == RDC_REG_RDATA || reg == RDC_REG_FIFO_DATA ||
	       reg == RDC_REG_PERF_CTRL;
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
	int diff = 0;

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
		/* constant time: the token is a secret */
		diff = hello.token_len != d->token_len;
		for (uint32_t i = 0; i < d->token_len; i++)
			diff |= (i < hello.token_len ? hello.token[i] : 0) ^
				d->token[i];
		if (diff) {
			rdcd_fatal(d, c, h, RDC_ST_AUTH);
			return;
		}
	}
	c->hello = true;
	r.caps = RDC_CAP_ALL & ~(d->mode == RDC_RUN_STEPPED ? 0u : RDC_CAP_STEP);
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

static int rdcd_wait_from_proto(const uint8_t *pl, size_t len,
				struct rdc_wait *w)
{
	struct rdc_proto_wait pw;
	int st = rdc_proto_wait_decode(pl, len, &pw);

	if (st)
		return st;
	memset(w, 0, sizeof(*w));
	if (pw.budget > (uint64_t)RDCD_MAX_BUDGET_S * RDC_DEFAULT_CORE_HZ)
		return RDC_ST_RANGE;
	w->budget = pw.budget;
	w->needs_dp = pw.needs_dp;
	for (unsigned int i = 0; i < RDC_WAIT_TERMS; i++) {
		if (pw.term[i].kind > RDC_WAIT_EQ)
			return RDC_ST_INVAL;
		if (pw.term[i].kind != RDC_WAIT_NONE &&
		    (!rdcd_reg_ok(pw.term[i].reg) ||
		     rdcd_reg_read_changes(pw.term[i].reg)))
			return RDC_ST_INVAL;
		w->term[i].kind = (enum rdc_wait_kind)pw.term[i].kind;
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
 * Stepped mode: the controlling client's wait moves time itself, a piece
 * per turn of the daemon's loop so that everyone else is served between
 * pieces; where it ends does not depend on the pieces (hw-sim/wait.c).
 * 1 while it goes on, else its result.  The trace records the time it
 * moved as steps, between whatever the others did meanwhile.
 */
static int rdcd_stepped_wait(struct rdcd *d, struct rdcd_client *c)
{
	int ret;

	rdc_rec_time_moved(d->rec, d->hw->now);
	switch (rdc_hw_wait_run(d->hw, &c->pend_hw, RDCD_WAIT_PIECE)) {
	case RDC_HW_WAIT_MORE:
		return 1;
	case RDC_HW_WAIT_DONE:
		ret = 0;
		break;
	case RDC_HW_WAIT_HALTED:
		ret = RDC_E_HALTED;
		break;
	default:
		ret = RDC_E_TIMEOUT;
		break;
	}
	return ret;
}

/*
 * Progress on a pending request.  Returns true when it finished and was
 * answered.
 */
static bool rdcd_pending_step(struct rdcd *d, struct rdcd_client *c)
{
	const struct rdc_proto_hdr *h = &c->pend_hdr;
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
			if (!rdcd_halted(d))
				return false;
			ret = RDC_E_HALTED;
		}
		break;
	case RDCD_PEND_WAIT: {
		struct rdc_hw_wait w;
		bool hold = false;

		if (d->mode == RDC_RUN_STEPPED) {
			ret = rdcd_stepped_wait(d, c);
			if (ret > 0)
				return false;
			break;
		}

		/* time moves with the daemon's clock: only the checks here */
		rdc_wait_to_hw(&c->pend_wait, &w);
		for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++)
			hold |= rdc_hw_cond_holds(d->hw, &w.term[i]);
		if (hold)
			break;
		if (w.needs_dp && d->hw->now != c->pend_start &&
		    rdcd_halted(d))
			ret = RDC_E_HALTED;
		else if (d->hw->now - c->pend_start >= w.budget)
			ret = RDC_E_TIMEOUT;
		else
			return false;
		break;
	}
	case RDCD_PEND_STEP:
		if (d->hw->now < c->pend_target)
			return false;
		break;
	default:
		return false;
	}
	rdcd_reply_err(d, c, h, ret);
	c->pend = RDCD_PEND_NONE;
	free(c->pend_words);
	c->pend_words = NULL;
	return true;
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
	rdc_proto_put64(ev + 4, d->hw->now);
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
		rdcd_queue(c, b);
	}
}

void rdcd_after_advance(struct rdcd *d)
{
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		if (c->pend != RDCD_PEND_NONE && !c->dead)
			rdcd_pending_step(d, c);
	rdcd_irq_events(d);
}

static void rdcd_stats(struct rdcd *d, struct rdcd_client *c,
		       const struct rdc_proto_hdr *h)
{
	struct rdc_proto_stats ps = {0};
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
		.number = rdc_hw_read(d->hw, RDC_REG_FRAME_COUNT) - 1u};
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
	rdcd_queue(c, b);
}

/* Does this request need control of the device? */
static bool rdcd_needs_control(const struct rdcd *d,
			       const struct rdc_proto_hdr *h,
			       const uint8_t *pl)
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

static void rdcd_submit(struct rdcd *d, struct rdcd_client *c,
			const struct rdc_proto_hdr *h, uint8_t **pl)
{
	size_t n = h->len / 4;

	if (d->mode == RDC_RUN_STEPPED) {
		uint32_t *w = malloc(n * 4 + 4);
		int ret;

		if (!w) {
			rdcd_reply_err(d, c, h, RDC_E_NOMEM);
			return;
		}
		for (size_t i = 0; i < n; i++)
			w[i] = rdc_proto_get32(*pl + 4 * i);
		ret = rdc_submit(d->dev, w, n);
		free(w);
		rdcd_reply_err(d, c, h, ret);
		rdcd_irq_events(d);
		return;
	}
	c->pend = RDCD_PEND_SUBMIT;
	c->pend_hdr = *h;
	c->pend_words = *pl; /* taken over */
	*pl = NULL;
	c->pend_n = n;
	c->pend_done = 0;
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
		ret = rdc_reg_read(d->dev, rdc_proto_get32(pl), &v);
		rdc_proto_put32(out, v);
		if (ret)
			rdcd_reply_err(d, c, h, ret);
		else
			rdcd_reply(d, c, h, RDC_ST_OK, out, 4);
		break;
	case RDC_MSG_REG_WRITE:
		ret = rdc_reg_write(d->dev, rdc_proto_get32(pl),
				    rdc_proto_get32(pl + 4));
		rdcd_reply_err(d, c, h, ret);
		break;
	case RDC_MSG_VRAM_READ: {
		uint32_t addr = rdc_proto_get32(pl), len = rdc_proto_get32(pl + 4);
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
		struct rdc_wait w;

		st = rdcd_wait_from_proto(pl, h->len, &w);
		if (st) {
			rdcd_reply(d, c, h, (uint32_t)st, NULL, 0);
			break;
		}
		c->pend = RDCD_PEND_WAIT;
		c->pend_hdr = *h;
		c->pend_wait = w;
		c->pend_start = d->hw->now;
		if (d->mode == RDC_RUN_STEPPED) {
			rdc_wait_to_hw(&w, &c->pend_hw);
			rdc_hw_wait_begin(d->hw, &c->pend_hw);
		}
		if (rdcd_pending_step(d, c))
			rdcd_irq_events(d);
		break;
	}
	case RDC_MSG_STEP: {
		uint64_t cyc = rdc_proto_get64(pl);

		if (cyc > (uint64_t)RDCD_MAX_BUDGET_S * RDC_DEFAULT_CORE_HZ) {
			rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
			break;
		}
		if (d->mode == RDC_RUN_STEPPED) {
			ret = rdc_sim_step(d->dev, cyc);
			rdcd_reply_err(d, c, h, ret);
			rdcd_irq_events(d);
			break;
		}
		c->pend = RDCD_PEND_STEP;
		c->pend_hdr = *h;
		c->pend_target = d->hw->now + cyc;
		rdcd_pending_step(d, c);
		break;
	}
	case RDC_MSG_FRAME_GRAB:
		rdcd_frame_grab(d, c, h, pl);
		break;
	case RDC_MSG_SUBSCRIBE: {
		uint32_t ev = rdc_proto_get32(pl), every = rdc_proto_get32(pl + 4);
		uint32_t enc = rdc_proto_get32(pl + 8);

		if ((ev & ~(RDC_SUB_FRAMES | RDC_SUB_IRQ)) ||
		    enc >= RDC_ENC_COUNT_ || ((ev & RDC_SUB_FRAMES) && !every)) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		}
		c->sub_events = ev;
		c->sub_every = every ? every : 1;
		c->sub_enc = enc;
		c->frame_tick = 0;
		free(c->prev);
		c->prev = NULL;
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	}
	case RDC_MSG_STATS:
		rdcd_stats(d, c, h);
		break;
	case RDC_MSG_RESET:
		v = rdc_proto_get32(pl);
		if (v == RDC_RESET_SOFT) {
			ret = rdc_reset(d->dev);
		} else if (v == RDC_RESET_POWER) {
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
		} else {
			ret = RDC_E_INVAL;
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
		rdcd_reply(d, c, h, d->ctl == c ? RDC_ST_OK : RDC_ST_BUSY,
			   NULL, 0);
		break;
	case RDC_MSG_RELEASE:
		if (d->ctl == c) {
			d->ctl = NULL;
			rdcd_log(d, RDCD_LOG_INFO,
				 "client %u released control", c->id);
		}
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	case RDC_MSG_PING:
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	case RDC_MSG_PINS_SET:
		rdcd_pins_set(d, c, h, pl);
		break;
	default:
		rdcd_reply(d, c, h, RDC_ST_TYPE, NULL, 0);
		break;
	}
}

/* Read what is there and handle complete requests, a few per turn. */
void rdcd_client_read(struct rdcd *d, struct rdcd_client *c)
{
	for (int turn = 0; turn < RDCD_REQ_PER_TURN;) {
		ssize_t k;

		if (!rdcd_client_wants_read(c))
			return;
		if (c->hdr_got < RDC_PROTO_HDR_SIZE) {
			k = recv(c->fd, c->hdrbuf + c->hdr_got,
				 RDC_PROTO_HDR_SIZE - c->hdr_got,
				 MSG_DONTWAIT);
		} else {
			k = c->hdr.len ? recv(c->fd, c->body + c->body_got,
					      c->hdr.len - c->body_got,
					      MSG_DONTWAIT)
				       : 0;
		}
		if (k < 0) {
			if (errno == EINTR)
				continue;
			if (errno != EAGAIN && errno != EWOULDBLOCK) {
				rdcd_log(d, RDCD_LOG_INFO, "client %u: recv: %s",
					 c->id, strerror(errno));
				c->dead = true;
			}
			return;
		}
		if (k == 0 && (c->hdr_got < RDC_PROTO_HDR_SIZE || c->hdr.len)) {
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
			if (c->hdr.len > RDC_PROTO_MAX_REQUEST) {
				rdcd_fatal(d, c, &c->hdr, RDC_ST_TOOBIG);
				return;
			}
			c->body_got = 0;
			c->body = c->hdr.len ? malloc(c->hdr.len) : NULL;
			if (c->hdr.len && !c->body) {
				rdcd_log(d, RDCD_LOG_ERR,
					 "client %u: out of memory", c->id);
				c->dead = true;
				return;
			}
			if (c->hdr.len)
				continue;
		} else {
			c->body_got += (size_t)k;
			if (c->body_got < c->hdr.len)
				continue;
		}
		rdcd_dispatch(d, c, &c->hdr, &c->body);
		free(c->body);
		c->body = NULL;
		c->hdr_got = 0;
		c->body_got = 0;
		turn++;
	}
}
