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

#include "serve.h"

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
		rdc_server_rec_attach(d->rec, d->dev);
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
	if (d->rec && rdc_server_rec_close(d->rec, d->dev))
		rdcd_log(d, RDCD_LOG_ERR, "trace: write error");
	d->rec = NULL;
	rdc_close(d->dev);
	d->dev = NULL;
	d->hw = NULL;
}

int rdcd_power_cycle(struct rdcd *d)
{
	int ret;

	if (d->rec)
		rdc_server_rec_power(d->rec);
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

/* Connections from listener `lis` that have (not) said HELLO. */
unsigned int rdcd_count_lis(const struct rdcd *d, int lis, bool hello,
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

/*
 * Is something waiting to be read from c (its HELLO, likely)?  A peer
 * that hung up is closed here: its place is free.
 */
static bool rdcd_something_waiting(struct rdcd_client *c)
{
	uint8_t b;
	ssize_t k = recv(c->fd, &b, 1, MSG_PEEK | MSG_DONTWAIT);

	if (k == 0 || (k < 0 && errno != EAGAIN && errno != EWOULDBLOCK &&
		       errno != EINTR))
		c->dead = true;
	return k > 0;
}

/*
 * Room for a new connection without HELLO on listener `lis`.  Beyond
 * RDCD_MAX_PENDING, the one silent longest (nothing waiting, nothing
 * arrived) goes if that is RDCD_HELLO_GRACE_MS or more; if all are
 * younger, they stay up to RDCD_MAX_PENDING_YOUNG, and beyond that the
 * one silent longest goes all the same, or else the oldest.  What waits
 * is looked at, not read: a HELLO is answered in its turn.
 */
static void rdcd_pending_room(struct rdcd *d, int lis)
{
	const uint64_t grace = (uint64_t)RDCD_HELLO_GRACE_MS * 1000000ull;
	struct rdcd_client *silent = NULL, *any = NULL;
	uint64_t now = rdcd_wall_ns();
	unsigned int n = 0;

	if (rdcd_count_lis(d, lis, false, NULL) < RDCD_MAX_PENDING)
		return;
	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		bool waiting;

		if (c->dead || c->hello || c->lis != lis)
			continue;
		waiting = rdcd_something_waiting(c);
		if (c->dead)
			continue;
		n++;
		if (!any || c->conn_ns < any->conn_ns)
			any = c;
		if (!waiting && (!silent || c->rx_ns < silent->rx_ns))
			silent = c;
	}
	if (n < RDCD_MAX_PENDING)
		return; /* some had hung up */
	if (n < RDCD_MAX_PENDING_YOUNG &&
	    (!silent || now - silent->rx_ns < grace))
		return;
	if (!silent)
		silent = any;
	rdcd_log_limited(d, &d->connlog, RDCD_LOG_WARN,
			 "%u connections without HELLO on one listener: "
			 "closing the oldest silent one, client %u (%s)",
			 n, silent->id, silent->peer);
	silent->dead = true;
}

struct rdcd_client *rdcd_client_new(struct rdcd *d, int fd, bool tcp,
				    const char *peer)
{
	struct rdcd_client *c;

	rdcd_pending_room(d, d->accept_lis);
	c = calloc(1, sizeof(*c));
	if (!c)
		return NULL;
	c->fd = fd;
	c->tcp = tcp;
	c->lis = d->accept_lis;
	c->conn_ns = rdcd_wall_ns();
	c->rx_ns = c->conn_ns;
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

/* ---- Reading requests ---------------------------------------------------- */

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
		if (!c->hello)
			c->rx_ns = rdcd_wall_ns(); /* not silent (admission) */
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
