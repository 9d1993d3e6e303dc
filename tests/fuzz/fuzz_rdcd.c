// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target for rdcd's request handling (userspace/rdcd/serve.c
 * and the parts serve.h lists), in process: the daemon's own objects
 * except rdcd.c (its main and poll loop), a sim: device with small VRAM,
 * and up to FZ_CLIENTS clients on socketpairs.  The input is a list of records: connect, disconnect, raw
 * bytes from a client, a well-formed message of any type with any
 * payload, a HELLO, time moved by a bounded amount, a few turns of the
 * loop.  Between records the harness turns the loop as rdcd_loop does
 * (read, flush, move time, finish pending requests, free the dead).
 *
 * Everything a client gets back is read and checked: every message is a
 * reply or an event with a header within the caps; every complete request
 * gets exactly one reply, in order, with its type and seq, and a payload
 * of the size its type and status say; HELLO replies describe this
 * daemon; frames decode (RDC_ENC_DELTA against the client's copy of the
 * frame before), IRQ events carry 12 bytes, events come only after a
 * subscription asked for them; after a reply that closes the connection
 * (RDC_ST_TOOBIG, a refused HELLO) no other reply comes.  When the input
 * ends and every client was given time to be served, a client that is
 * neither waiting on the device nor closed has no request left unanswered.
 *
 * The work per input is bounded: VRAM of 64 or 256 KiB, time moved at
 * most FZ_TIME_UNIT * 256 cycles per record and FZ_MAX_CYCLES per input,
 * STEP cycles under 2^20 and WAIT budgets from 2^16 to 2^22 cycles (the
 * harness rewrites those bytes on the way out), every wait inside the
 * simulator cut to FZ_MAX_WAIT cycles (rdc_hw_wait_begin is wrapped at
 * link time, -Wl,--wrap: a display list that jumps to itself would run
 * for the whole default budget), at most FZ_MAX_RECORDS records.  The
 * daemon's host clock (rdcd_wall_ns) is the harness's: it moves with the
 * input.  Built and run by `make fuzz`.
 */
#define RDC_CORE_INTERNAL /* the fuzz target reaches into the core: hw.h, dp.h */
#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <poll.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "hw.h"
#include "rdcd.h"

#define FZ_CLIENTS	 4
#define FZ_MAX_RECORDS	 512
#define FZ_EXPECT	 1024 /* requests in flight per client */
#define FZ_TIME_UNIT	 4096u
#define FZ_MAX_WAIT	 4000000u   /* 40 ms at the default clock */
#define FZ_MAX_CYCLES	 100000000u /* 1 simulated second per input */
#define FZ_SETTLE_TURNS	 64
#define FZ_SETTLE_CYCLES (1u << 17) /* 64 of them: 2^23, over any wait */
#define FZ_SOCKBUF	 (4 << 20)
#define FZ_MAX_PIXELS	 RDC_PROTO_MAX_FRAME_PIXELS
#define FZ_CONNS	 64 /* the daemon's clients: ours, and ours gone */
#define FZ_WALL_START	 (1000ull * 1000000000ull)
#define FZ_WALL_TURN_NS	 (200ull * 1000000ull)

static const uint8_t fz_token[] = "fuzz-token";

#define fz_assert(c) \
	do { \
		if (!(c)) { \
			fprintf(stderr, "fuzz_rdcd: %s:%d: %s\n", __FILE__, \
				__LINE__, #c); \
			abort(); \
		} \
	} while (0)

/* A request the client sent, whose reply it still waits for. */
struct fz_req {
	uint16_t type;
	bool complete; /* its last byte went out */
	uint32_t seq, len;
	uint8_t pl[12]; /* the first payload bytes */
};

/* The client's view of its outgoing stream, cut into messages. */
struct fz_out {
	uint8_t hdr[RDC_PROTO_HDR_SIZE];
	size_t hdr_got;
	struct rdc_proto_hdr h;
	uint32_t body_got;
	uint8_t pl[12];
	bool dead; /* a header over the cap: the daemon reads no more */
};

struct fz_client {
	bool used;
	int fd;			 /* our end */
	struct rdcd_client *srv; /* the daemon's, NULL once freed */
	bool hung_up;		 /* we closed our end */
	bool closed;		 /* a reply said the daemon hangs up */
	bool eof;
	struct fz_out out;
	struct fz_req exp[FZ_EXPECT];
	unsigned int exp_head, exp_n;
	bool exp_lost; /* more than FZ_EXPECT in flight: order unchecked */
	uint32_t seq;
	/* incoming */
	uint8_t ihdr[RDC_PROTO_HDR_SIZE];
	size_t ihdr_got;
	struct rdc_proto_hdr ih;
	uint8_t *ibody;
	size_t ibody_got;
	/* subscription as the replies told it */
	uint32_t sub_events, sub_enc;
	uint32_t *prev;
	uint32_t prev_w, prev_h;
};

struct fz {
	struct rdcd d;
	struct fz_client cl[FZ_CLIENTS];
};

static uint32_t fz_pix[FZ_MAX_PIXELS];

void __real_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);
void __wrap_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);

void __wrap_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w)
{
	if (w->budget > FZ_MAX_WAIT)
		w->budget = FZ_MAX_WAIT;
	__real_rdc_hw_wait_begin(hw, w);
}
static char fz_logbuf[512];
static bool fz_verbose; /* FUZZ_RDCD_VERBOSE=1: every message received */

/*
 * rdcd.c's host clock, simulated: it moves only when the input says
 * (FZ_WALL_TURN_NS per turn of a "turns" record, and with simulated time),
 * so HELLO deadlines, token back-off and the like are reproducible.
 */
static uint64_t fz_wall;

uint64_t rdcd_wall_ns(void)
{
	return fz_wall;
}

/* rdcd.c's logger: formatted (so the arguments are checked), not shown. */
void rdcd_log(const struct rdcd *d, int level, const char *fmt, ...)
{
	va_list ap;

	if (level > d->log_level)
		return;
	va_start(ap, fmt);
	vsnprintf(fz_logbuf, sizeof(fz_logbuf), fmt, ap);
	va_end(ap);
}

/* ---- What the client sends ----------------------------------------------- */

static struct fz_req *fz_last(struct fz_client *c)
{
	return &c->exp[(c->exp_head + c->exp_n - 1) % FZ_EXPECT];
}

/*
 * Follow the outgoing bytes, cutting messages as the daemon does.  With
 * `commit`, each request is queued for its reply as soon as its header is
 * whole (the daemon may refuse it then: RDC_ST_TOOBIG) and marked
 * complete with its last byte.  STEP cycles and WAIT budgets are cut on
 * the way (see the top of the file).
 */
static void fz_track(struct fz_client *c, struct fz_out *o, uint8_t *b,
		     size_t n, bool commit)
{
	while (n && !o->dead) {
		bool done;

		if (o->hdr_got < RDC_PROTO_HDR_SIZE) {
			o->hdr[o->hdr_got++] = *b++;
			n--;
			if (o->hdr_got < RDC_PROTO_HDR_SIZE)
				continue;
			rdc_proto_hdr_decode(o->hdr, &o->h);
			o->body_got = 0;
			memset(o->pl, 0, sizeof(o->pl));
			/* the daemon reads nothing after this one */
			o->dead = o->h.len > RDC_PROTO_MAX_REQUEST;
			if (commit && c->exp_n == FZ_EXPECT)
				c->exp_lost = true;
			if (commit && !c->exp_lost) {
				struct fz_req *r;

				c->exp_n++;
				r = fz_last(c);
				memset(r, 0, sizeof(*r));
				r->type = o->h.type;
				r->seq = o->h.seq;
				r->len = o->h.len;
			}
			done = !o->h.len;
		} else {
			uint32_t at = o->body_got;

			/* STEP: under 2^20 cycles; WAIT: 2^16 to 2^22 */
			if (o->h.type == RDC_MSG_STEP && at == 2)
				*b &= 0x0f;
			if (o->h.type == RDC_MSG_WAIT && at == 2)
				*b = (uint8_t)((*b & 0x3f) | 1);
			if ((o->h.type == RDC_MSG_STEP ||
			     o->h.type == RDC_MSG_WAIT) &&
			    at >= 3 && at < 8)
				*b = 0;
			if (at < sizeof(o->pl))
				o->pl[at] = *b;
			b++;
			n--;
			done = ++o->body_got == o->h.len;
		}
		if (!done || o->dead)
			continue;
		if (commit && !c->exp_lost) {
			fz_last(c)->complete = true;
			memcpy(fz_last(c)->pl, o->pl, sizeof(o->pl));
		}
		o->hdr_got = 0;
	}
}

/* ---- What the client gets ------------------------------------------------ */

static void fz_check_frame(struct fz_client *c, const uint8_t *p, size_t len,
			   bool event)
{
	struct rdc_proto_frame f;
	uint32_t *pix = fz_pix;

	fz_assert(!rdc_proto_frame_hdr_decode(p, len, &f));
	fz_assert(f.encoding < RDC_ENC_COUNT_);
	fz_assert((uint64_t)f.width * f.height <= FZ_MAX_PIXELS);
	if (event) {
		size_t px = (size_t)f.width * f.height;

		/* the subscribed encoding, or raw when it would not be
		 * smaller */
		fz_assert(f.encoding == c->sub_enc ||
			  f.encoding == RDC_ENC_RAW);
		if (c->sub_enc == RDC_ENC_DELTA) {
			if (!c->prev || c->prev_w != f.width ||
			    c->prev_h != f.height) {
				free(c->prev);
				c->prev = calloc(px + 1, 4);
				fz_assert(c->prev);
				c->prev_w = f.width;
				c->prev_h = f.height;
			}
			pix = c->prev;
		}
	} else {
		fz_assert(f.encoding ==
			  rdc_proto_get32(c->exp[c->exp_head].pl));
	}
	fz_assert(!rdc_proto_frame_decode(pix, f.width, f.height, f.encoding,
					  p + RDC_PROTO_FRAME_HDR,
					  len - RDC_PROTO_FRAME_HDR));
}

static void fz_check_reply(struct fz *z, struct fz_client *c,
			   const struct rdc_proto_hdr *h, const uint8_t *p)
{
	const struct fz_req *r;
	struct rdc_proto_hello_reply hr;
	uint32_t want = 0;

	fz_assert(!c->closed);
	fz_assert(h->status < RDC_ST_COUNT_);
	if (c->exp_lost && !c->exp_n)
		return;
	fz_assert(c->exp_n > 0);
	r = &c->exp[c->exp_head];
	fz_assert(h->type == r->type && h->seq == r->seq);
	/* refused on its header alone: over the cap, or before HELLO over
	 * what a HELLO can be */
	if (h->status == RDC_ST_TOOBIG)
		fz_assert(r->len > RDC_PROTO_MAX_REQUEST ||
			  r->len > RDC_PROTO_HELLO_FIXED + RDC_PROTO_MAX_TOKEN);
	else
		fz_assert(r->complete);
	if (h->status == RDC_ST_OK) {
		switch (r->type) {
		case RDC_MSG_HELLO:
			fz_assert(
				!rdc_proto_hello_reply_decode(p, h->len, &hr));
			fz_assert(hr.version == RDC_PROTO_VERSION);
			fz_assert(hr.vram_size == z->d.vram_size);
			fz_assert(hr.run_mode == (uint32_t)z->d.mode);
			fz_assert(!c->srv || hr.client_id == c->srv->id);
			fz_assert(!(hr.caps & ~RDC_CAP_ALL));
			want = h->len;
			break;
		case RDC_MSG_REG_READ:
		case RDC_MSG_PINS_SET:
			want = 4;
			break;
		case RDC_MSG_VRAM_READ:
			want = rdc_proto_get32(r->pl + 4);
			break;
		case RDC_MSG_STATS:
			want = RDC_PROTO_STATS_SIZE;
			break;
		case RDC_MSG_FRAME_GRAB:
			fz_check_frame(c, p, h->len, false);
			want = h->len;
			break;
		case RDC_MSG_HIST_READ: {
			/* a page no larger than asked, every entry sound */
			struct rdc_proto_hist_page pg;
			struct rdc_proto_hist_entry e;

			fz_assert(!rdc_proto_hist_page_decode(
				p, h->len, rdc_proto_get32(r->pl + 8), &pg));
			fz_assert(rdc_proto_get64(r->pl) + pg.n <= pg.count);
			for (uint32_t i = 0; i < pg.n; i++)
				fz_assert(!rdc_proto_hist_entry_decode(
					p + RDC_PROTO_HIST_PAGE_HDR +
						(size_t)i *
							RDC_PROTO_HIST_ENTRY_SIZE,
					&e));
			want = h->len;
			break;
		}
		case RDC_MSG_SUBSCRIBE:
			c->sub_events = rdc_proto_get32(r->pl);
			c->sub_enc = rdc_proto_get32(r->pl + 8);
			free(c->prev);
			c->prev = NULL;
			break;
		default:
			break;
		}
	} else if (r->type == RDC_MSG_FRAME_GRAB && h->status == RDC_ST_RANGE) {
		want = RDC_PROTO_FRAME_HDR;
	}
	fz_assert(h->len == want);
	/* the replies after which the daemon hangs up */
	if (h->status == RDC_ST_TOOBIG ||
	    (r->type == RDC_MSG_HELLO && h->status != RDC_ST_OK &&
	     h->status != RDC_ST_ORDER))
		c->closed = true;
	c->exp_head = (c->exp_head + 1) % FZ_EXPECT;
	c->exp_n--;
}

static void fz_check_msg(struct fz *z, struct fz_client *c)
{
	const struct rdc_proto_hdr *h = &c->ih;

	if (fz_verbose)
		fprintf(stderr,
			"client %td: type %u flags %u seq %u status %u len "
			"%u\n",
			c - z->cl, h->type, h->flags, h->seq, h->status,
			h->len);
	if (h->flags == RDC_MSGF_REPLY) {
		fz_check_reply(z, c, h, c->ibody);
		return;
	}
	fz_assert(h->flags == RDC_MSGF_EVENT);
	fz_assert(h->seq == 0 && h->status == RDC_ST_OK);
	switch (h->type) {
	case RDC_MSG_EV_IRQ:
		fz_assert(c->sub_events & RDC_SUB_IRQ);
		fz_assert(h->len == 12);
		fz_assert(rdc_proto_get32(c->ibody) != 0);
		break;
	case RDC_MSG_EV_FRAME:
		fz_assert(c->sub_events & RDC_SUB_FRAMES);
		fz_check_frame(c, c->ibody, h->len, true);
		break;
	default:
		fz_assert(!"unknown event");
	}
}

/* `last`: the daemon is shutting down (its last replies may be cut). */
static void fz_receive(struct fz *z, struct fz_client *c, bool last)
{
	static uint8_t buf[1 << 16];

	while (c->used && !c->eof) {
		ssize_t k = recv(c->fd, buf, sizeof(buf), MSG_DONTWAIT);
		const uint8_t *b = buf;

		if (k < 0) {
			fz_assert(errno == EAGAIN || errno == EWOULDBLOCK ||
				  errno == EINTR || errno == ECONNRESET);
			if (errno == ECONNRESET)
				c->eof = true;
			return;
		}
		if (!k) {
			/* the daemon hung up: never inside a message,
			 * unless we hung up first (it stops writing to a
			 * client it read the end of) */
			fz_assert(!c->ihdr_got || last || c->hung_up);
			c->eof = true;
			return;
		}
		while (k) {
			size_t n;

			if (c->ihdr_got < RDC_PROTO_HDR_SIZE) {
				n = RDC_MIN((size_t)k,
					    RDC_PROTO_HDR_SIZE - c->ihdr_got);
				memcpy(c->ihdr + c->ihdr_got, b, n);
				c->ihdr_got += n;
				b += n;
				k -= (ssize_t)n;
				if (c->ihdr_got < RDC_PROTO_HDR_SIZE)
					continue;
				rdc_proto_hdr_decode(c->ihdr, &c->ih);
				/* (a reply echoes the request's type, known
				 * or not) */
				fz_assert(c->ih.len <= RDC_PROTO_MAX_REPLY);
				free(c->ibody);
				c->ibody = malloc(c->ih.len + 1u);
				fz_assert(c->ibody);
				c->ibody_got = 0;
			} else {
				n = RDC_MIN((size_t)k,
					    c->ih.len - c->ibody_got);
				memcpy(c->ibody + c->ibody_got, b, n);
				c->ibody_got += n;
				b += n;
				k -= (ssize_t)n;
			}
			if (c->ibody_got == c->ih.len) {
				fz_check_msg(z, c);
				c->ihdr_got = 0;
			}
		}
	}
}

/* ---- The loop ------------------------------------------------------------ */

static struct fz_client *fz_of(struct fz *z, const struct rdcd_client *s)
{
	for (unsigned int i = 0; i < FZ_CLIENTS; i++)
		if (z->cl[i].used && z->cl[i].srv == s)
			return &z->cl[i];
	return NULL;
}

/* rdcd.c's advance job: simulated time up to adv_target. */
static void fz_advance_job(struct rdcd *d, void *arg)
{
	(void)arg;
	if (d->adv_target > d->hw->now)
		fz_assert(!rdc_sim_step(d->dev, d->adv_target - d->hw->now));
}

/*
 * One turn of rdcd_loop: HELLO deadlines, poll the daemon's ends as it
 * does (without waiting), serve, move time (`cycles` in the paced and
 * fast modes; the controller's pending request in stepped mode), answer,
 * release held requests, bound the queues, free the dead; then read.
 * Without rdcd_chip_open every run on the chip ends at once.
 */
static void fz_turn(struct fz *z, uint64_t cycles)
{
	struct pollfd pfd[FZ_CONNS];
	struct rdcd_client *cl[FZ_CONNS];
	struct rdcd *d = &z->d;
	unsigned int n = 0;
	bool moved;

	rdcd_hello_deadlines(d);
	for (struct rdcd_client *s = d->clients; s; s = s->next) {
		fz_assert(n < FZ_CONNS);
		cl[n] = s;
		pfd[n].fd = s->fd;
		pfd[n].events =
			(short)((rdcd_client_wants_read(s) ? POLLIN : 0) |
				(s->out_head ? POLLOUT : 0));
		pfd[n++].revents = 0;
	}
	fz_assert(poll(pfd, n, 0) >= 0);
	for (unsigned int i = 0; i < n; i++) {
		if (pfd[i].revents & POLLOUT)
			rdcd_client_flush(d, cl[i]);
		if (pfd[i].revents & (POLLIN | POLLHUP | POLLERR))
			rdcd_client_read(d, cl[i]);
		if ((pfd[i].revents & (POLLHUP | POLLERR)) &&
		    !(pfd[i].revents & POLLIN))
			cl[i]->dead = true;
	}
	if (d->mode == RDC_RUN_STEPPED) {
		moved = rdcd_stepped_start(d) == 0;
	} else {
		moved = cycles != 0;
		if (moved) {
			/* simulated time at the default clock, 10 ns a cycle */
			fz_wall += cycles * 10u;
			d->adv_target = d->hw->now + cycles;
			fz_assert(!rdcd_chip_run(d, fz_advance_job, NULL));
		}
	}
	if (moved)
		rdcd_after_advance(d);
	rdcd_release_held(d);
	for (struct rdcd_client *s = d->clients; s; s = s->next)
		if (s->out_head)
			rdcd_client_flush(d, s);
	rdcd_out_bound(d);
	for (struct rdcd_client *s = d->clients, *next; s; s = next) {
		next = s->next;
		if (s->dead) {
			struct fz_client *c = fz_of(z, s);

			rdcd_client_free(d, s);
			if (c)
				c->srv = NULL;
		}
	}
	for (unsigned int i = 0; i < FZ_CLIENTS; i++)
		if (z->cl[i].used)
			fz_receive(z, &z->cl[i], false);
}

static void fz_connect(struct fz *z, bool tcp)
{
	int sv[2], sz = FZ_SOCKBUF;
	struct fz_client *c = NULL;

	for (unsigned int i = 0; i < FZ_CLIENTS && !c; i++)
		if (!z->cl[i].used)
			c = &z->cl[i];
	if (!c)
		return;
	fz_assert(!socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, sv));
	setsockopt(sv[0], SOL_SOCKET, SO_SNDBUF, &sz, sizeof(sz));
	setsockopt(sv[1], SOL_SOCKET, SO_RCVBUF, &sz, sizeof(sz));
	memset(c, 0, sizeof(*c));
	c->used = true;
	c->fd = sv[0];
	c->srv = rdcd_client_new(&z->d, sv[1], tcp, tcp ? "tcp fuzz" : "local");
	fz_assert(c->srv);
}

/* Our end goes away; what the daemon does about it is its business. */
static void fz_drop(struct fz_client *c)
{
	close(c->fd);
	free(c->ibody);
	free(c->prev);
	c->ibody = NULL;
	c->prev = NULL;
	c->used = false;
}

static void fz_send(struct fz *z, struct fz_client *c, uint8_t *b, size_t n)
{
	for (int tries = 0; n && tries < 8 && !c->hung_up; tries++) {
		struct fz_out probe = c->out;
		ssize_t k;

		fz_track(c, &probe, b, n, false); /* patch only */
		k = send(c->fd, b, n, MSG_DONTWAIT | MSG_NOSIGNAL);
		if (k < 0) {
			if (errno != EAGAIN && errno != EWOULDBLOCK)
				return; /* the daemon hung up */
			k = 0;
		}
		fz_track(c, &c->out, b, (size_t)k, true);
		b += k;
		n -= (size_t)k;
		if (n)
			fz_turn(z, 0);
	}
}

static void fz_message(struct fz *z, struct fz_client *c, uint16_t type,
		       const uint8_t *pl, uint32_t len)
{
	static uint8_t buf[RDC_PROTO_HDR_SIZE + 65536];
	struct rdc_proto_hdr h = { .len = len, .type = type, .seq = c->seq++ };

	rdc_proto_hdr_encode(buf, &h);
	memcpy(buf + RDC_PROTO_HDR_SIZE, pl, len);
	fz_send(z, c, buf, RDC_PROTO_HDR_SIZE + len);
}

static void fz_hello(struct fz *z, struct fz_client *c, uint8_t how)
{
	uint8_t pl[RDC_PROTO_HELLO_FIXED + sizeof(fz_token)];
	struct rdc_proto_hello h = {
		.magic = RDC_PROTO_MAGIC,
		.version = RDC_PROTO_VERSION,
		.caps = RDC_CAP_ALL,
		.flags = how & 1 ? RDC_HELLO_CONTROL : 0,
		.token = fz_token,
		/* a token, right or one byte short */
		.token_len = how & 2 ? sizeof(fz_token) - 1 - (how >> 7) : 0,
	};
	size_t n = rdc_proto_hello_encode(pl, sizeof(pl), &h);

	fz_assert(n);
	fz_message(z, c, RDC_MSG_HELLO, pl, (uint32_t)n);
}

/*
 * No reply may stay owed to a client the daemon can still serve.  Time
 * moves enough for every wait to end (STEP targets and WAIT budgets are
 * bounded, see fz_track); a SUBMIT may still wait for FIFO room.
 */
static void fz_settle(struct fz *z)
{
	for (int i = 0; i < FZ_SETTLE_TURNS; i++)
		fz_turn(z, FZ_SETTLE_CYCLES);
	for (unsigned int i = 0; i < FZ_CLIENTS; i++) {
		struct fz_client *c = &z->cl[i];

		if (!c->used || !c->srv || c->closed || c->exp_lost ||
		    c->srv->closing || c->srv->dead || c->hung_up)
			continue;
		/* waits and steps have ended: only a SUBMIT may wait on */
		fz_assert(c->srv->pend == RDCD_PEND_NONE ||
			  c->srv->pend == RDCD_PEND_SUBMIT);
		if (c->srv->pend == RDCD_PEND_NONE)
			fz_assert(!c->exp_n ||
				  (c->exp_n == 1 && !fz_last(c)->complete));
	}
}

static uint8_t fz_byte(const uint8_t **p, const uint8_t *end)
{
	return *p < end ? *(*p)++ : 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static struct fz z;
	const uint8_t *p = data, *end = data + size;
	uint8_t cfg = fz_byte(&p, end);
	unsigned int records = 0;
	uint64_t spent = 0, last = 0;

	fz_verbose = getenv("FUZZ_RDCD_VERBOSE") != NULL;
	fz_wall = FZ_WALL_START;
	memset(&z, 0, sizeof(z));
	z.d.log_level = RDCD_LOG_DEBUG;
	z.d.mode = (enum rdc_run_mode)(cfg % 3);
	z.d.vram_size = cfg & 4 ? 256u << 10 : 64u << 10;
	if (cfg & 8) {
		memcpy(z.d.token, fz_token, sizeof(fz_token) - 1);
		z.d.token_len = sizeof(fz_token) - 1;
		z.d.have_token = true;
	}
	fz_assert(!rdcd_device_open(&z.d));
	while (p < end && records++ < FZ_MAX_RECORDS && spent < FZ_MAX_CYCLES) {
		uint8_t op = fz_byte(&p, end);
		struct fz_client *c = &z.cl[(op >> 3) % FZ_CLIENTS];
		uint8_t buf[2048];
		uint32_t n;

		switch (op & 7) {
		case 0:
			fz_connect(&z, op & 0x80);
			break;
		case 1: /* hang up: the daemon finds out on its next read */
			if (c->used && !c->hung_up) {
				shutdown(c->fd, SHUT_WR);
				c->hung_up = true;
			}
			break;
		case 2: /* raw bytes, anything at all */
			n = fz_byte(&p, end) | (uint32_t)(op >> 5) << 8;
			n = (uint32_t)RDC_MIN((size_t)n, (size_t)(end - p));
			memcpy(buf, p, n);
			p += n;
			if (c->used)
				fz_send(&z, c, buf, n);
			break;
		case 3: { /* a message of any type, len telling the truth */
			uint16_t type = fz_byte(&p, end) % RDC_MSG_TYPE_MAX_;

			n = fz_byte(&p, end) | (uint32_t)(op >> 5) << 8;
			n = (uint32_t)RDC_MIN((size_t)n, (size_t)(end - p));
			memcpy(buf, p, n);
			p += n;
			if (c->used)
				fz_message(&z, c, type, buf, n);
			break;
		}
		case 4:
			n = fz_byte(&p, end);
			if (c->used)
				fz_hello(&z, c, (uint8_t)n);
			break;
		case 5: /* time moves (stepped: pending waits go on) */
			fz_turn(&z, (uint64_t)(fz_byte(&p, end) + 1u) *
					    FZ_TIME_UNIT);
			break;
		case 6: /* host time passes, simulated time does not */
			for (n = (op >> 3) % 32 + 1; n; n--) {
				fz_wall += FZ_WALL_TURN_NS;
				fz_turn(&z, 0);
			}
			break;
		default: /* our end goes away at once */
			if (c->used)
				fz_drop(c);
			break;
		}
		fz_turn(&z, 0);
		/* simulated time spent (a power cycle starts at 0 again) */
		spent += z.d.hw->now >= last ? z.d.hw->now - last : z.d.hw->now;
		last = z.d.hw->now;
	}
	fz_settle(&z);
	/* as rdcd's main: last replies out, clients freed, device closed */
	while (z.d.clients) {
		rdcd_client_flush(&z.d, z.d.clients);
		rdcd_client_free(&z.d, z.d.clients);
	}
	for (unsigned int i = 0; i < FZ_CLIENTS; i++) {
		if (!z.cl[i].used)
			continue;
		z.cl[i].srv = NULL;
		fz_receive(&z, &z.cl[i], true);
		fz_drop(&z.cl[i]);
	}
	rdcd_device_close(&z.d);
	return 0;
}
