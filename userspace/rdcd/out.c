// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: what goes out to a client.  Replies and events queue in each
 * client's buffers and leave as its socket takes them; every queue
 * counts against one bound for all (RDCD_OUT_TOTAL; a frame shared by
 * several queues once), which the slowest reader pays for.  librdc errors become wire status codes here.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/uio.h>

#include "serve.h"

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

size_t rdcd_obuf_cost(const struct rdcd_obuf *b)
{
	if (!b->shared)
		return b->len;
	return b->hlen + (b->shared->queued ? 0 : b->shared->len);
}

/* b leaves its queue: what it took of d->out_total, back. */
static void rdcd_unqueue(struct rdcd *d, struct rdcd_obuf *b)
{
	if (!b->shared) {
		d->out_total -= b->len;
		return;
	}
	d->out_total -= b->hlen;
	if (!--b->shared->queued)
		d->out_total -= b->shared->len;
}

void rdcd_queue(struct rdcd *d, struct rdcd_client *c, struct rdcd_obuf *b)
{
	d->out_total += rdcd_obuf_cost(b);
	if (b->shared)
		b->shared->queued++;
	b->next = NULL;
	if (c->out_tail) {
		c->out_tail->next = b;
	} else {
		c->out_head = b;
		c->out_since_ns = rdcd_wall_ns();
	}
	c->out_tail = b;
	c->out_bytes += b->len;
	if (b->frame) {
		c->out_frames++;
		c->out_frame_bytes += b->len;
	}
}

struct rdcd_obuf *rdcd_obuf_new(size_t payload)
{
	struct rdcd_obuf *b = malloc(sizeof(*b) + RDC_PROTO_HDR_SIZE + payload);

	if (b) {
		b->len = RDC_PROTO_HDR_SIZE + payload;
		b->hlen = b->len;
		b->off = 0;
		b->frame = false;
		b->shared = NULL;
	}
	return b;
}

void rdcd_obuf_free(struct rdcd_obuf *b)
{
	if (b->shared && !--b->shared->refs)
		free(b->shared);
	free(b);
}

void rdcd_obuf_hdr(struct rdcd_obuf *b, uint16_t type, uint16_t flags,
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

/* Everything queued for c, gone (it is being disconnected). */
void rdcd_client_drop_output(struct rdcd *d, struct rdcd_client *c)
{
	while (c->out_head) {
		struct rdcd_obuf *b = c->out_head;

		c->out_head = b->next;
		rdcd_unqueue(d, b);
		rdcd_obuf_free(b);
	}
	c->out_tail = NULL;
	c->out_bytes = 0;
	c->out_frame_bytes = 0;
	c->out_frames = 0;
}

void rdcd_out_bound(struct rdcd *d)
{
	while (d->out_total > RDCD_OUT_TOTAL) {
		struct rdcd_client *slow = NULL;

		/*
		 * Frames alone never take the total over (they are dropped
		 * first), replies do: the slowest reader holding some goes.
		 * One holding frames only would free little, its frames
		 * being shared.
		 */
		for (struct rdcd_client *c = d->clients; c; c = c->next)
			if (!c->dead && c->out_bytes > c->out_frame_bytes &&
			    (!slow || c->out_since_ns < slow->out_since_ns))
				slow = c;
		for (struct rdcd_client *c = slow ? NULL : d->clients; c;
		     c = c->next)
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

void rdcd_client_flush(struct rdcd *d, struct rdcd_client *c)
{
	while (c->out_head && !c->dead) {
		struct rdcd_obuf *b = c->out_head;
		struct iovec iov[2];
		struct msghdr m = { .msg_iov = iov };
		ssize_t k;

		/* the message's own bytes, then the frame it shares */
		if (b->off < b->hlen)
			iov[m.msg_iovlen++] = (struct iovec){
				.iov_base = b->data + b->off,
				.iov_len = b->hlen - b->off,
			};
		if (b->shared) {
			size_t at = b->off > b->hlen ? b->off - b->hlen : 0;

			iov[m.msg_iovlen++] = (struct iovec){
				.iov_base = b->shared->data + at,
				.iov_len = b->shared->len - at,
			};
		}
		k = sendmsg(c->fd, &m, MSG_NOSIGNAL | MSG_DONTWAIT);

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
		rdcd_unqueue(d, b);
		if (b->frame) {
			c->out_frames--;
			c->out_frame_bytes -= b->len;
		}
		rdcd_obuf_free(b);
	}
	if (!c->out_head && c->closing)
		c->dead = true;
}

/* A reply with `n` payload bytes copied from p (may be NULL: zeroes). */
uint8_t *rdcd_reply(struct rdcd *d, struct rdcd_client *c,
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

void rdcd_reply_err(struct rdcd *d, struct rdcd_client *c,
		    const struct rdc_proto_hdr *req, int err)
{
	rdcd_reply(d, c, req, rdcd_status_from_error(err), NULL, 0);
}

/*
 * An error after which the stream cannot go on: reply, then hang up
 * (rdcd_reply does, as rdc_proto_reply_closes says).
 */
void rdcd_fatal(struct rdcd *d, struct rdcd_client *c,
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
