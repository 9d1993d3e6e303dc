// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The protocol client (rdc_client.h): an RDC-1 served by rdcd, reached
 * with the protocol of rdc_proto.h over a byte transport: a stream socket
 * (the "unix:" and "tcp:" backends, net_sock.c) or a USB interface
 * (usb.c).  Every operation is one request and its reply (a wait too: the
 * daemon evaluates the condition), so the device behaves as sim: does,
 * one round trip later.
 *
 * Events (frames, interrupts) arrive between replies.  A frame is decoded
 * as soon as it is read, because row-delta frames build on the previous
 * one; the application sees the newest (older undelivered frames are
 * counted as dropped) and up to NET_IRQ_QUEUE interrupt events.
 */
#include <stdlib.h>
#include <string.h>
#include <sys/uio.h>

#include "rdc_client.h"
#include "rdc_priv.h"
#include "rdc_proto.h"

#define NET_IRQ_QUEUE 64u
#define NET_TOKEN_ENV "RDC_TOKEN_FILE"

_Static_assert(RDC_FRAME_RAW == RDC_ENC_RAW && RDC_FRAME_RLE == RDC_ENC_RLE &&
		       RDC_FRAME_DELTA == RDC_ENC_DELTA,
	       "rdc.h and rdc_proto.h frame encodings differ");
_Static_assert(RDC_EVENT_FRAME == RDC_SUB_FRAMES &&
		       RDC_EVENT_IRQ == RDC_SUB_IRQ,
	       "rdc.h and rdc_proto.h event bits differ");

struct net {
	struct rdc_xport *x; /* NULL once the stream is dead */
	int dead;	     /* what later calls return then */
	uint32_t seq;
	uint32_t vram_chunk, submit_words; /* request sizes that fit */
	struct rdc_proto_hello_reply hello;
	/* the newest frame event, decoded (also the base for DELTA) */
	uint32_t *frame;
	uint32_t fw, fh;
	bool frame_pending;
	struct rdc_event frame_ev;
	uint32_t local_dropped;
	/* interrupt events not yet taken */
	struct rdc_event irq[NET_IRQ_QUEUE];
	unsigned int irq_head, irq_n;
	/* a pixel history open on the daemon, and the .rdl line its entries
	 * carry there */
	bool hist_open;
	uint32_t hist_line;
};

static struct net *net_of(rdc_dev *dev)
{
	return dev->priv;
}

/*
 * The daemon's status codes as librdc errors: the only place that maps
 * them.  RDC_ST_NOFRAME is not an error (frame_grab's "no frame yet").
 */
static int net_status_to_error(uint32_t status)
{
	switch (status) {
	case RDC_ST_OK:
		return 0;
	case RDC_ST_INVAL:
		return RDC_E_INVAL;
	case RDC_ST_NOMEM:
		return RDC_E_NOMEM;
	case RDC_ST_NOSYS:
	case RDC_ST_TYPE:
		return RDC_E_NOSYS;
	case RDC_ST_TIMEOUT:
		return RDC_E_TIMEOUT;
	case RDC_ST_HALTED:
		return RDC_E_HALTED;
	case RDC_ST_RANGE:
		return RDC_E_RANGE;
	case RDC_ST_BUSY:
		return RDC_E_BUSY;
	case RDC_ST_AUTH:
		return RDC_E_AUTH;
	case RDC_ST_DEVICE:
		return RDC_E_DEVICE;
	case RDC_ST_RESET:
		return RDC_E_RESET;
	case RDC_ST_NOFRAME:
		return 1;
	case RDC_ST_MALFORMED:
	case RDC_ST_VERSION:
	case RDC_ST_TOOBIG:
	case RDC_ST_ORDER:
	default:
		return RDC_E_PROTO;
	}
}

static int net_send_msg(struct net *n, uint16_t type, const void *a,
			size_t alen, const void *b, size_t blen)
{
	uint8_t hdr[RDC_PROTO_HDR_SIZE];
	struct rdc_proto_hdr h = {
		.len = (uint32_t)(alen + blen),
		.type = type,
		.seq = ++n->seq,
	};
	struct iovec iov[3] = {
		{ hdr, sizeof(hdr) },
		{ (void *)a, alen },
		{ (void *)b, blen },
	};

	rdc_proto_hdr_encode(hdr, &h);
	return n->x->ops->send(n->x, iov, 3);
}

/* Read exactly len bytes; timeout_ms < 0 waits as long as the transport does. */
static int net_read_all(struct net *n, void *buf, size_t len, int timeout_ms)
{
	uint8_t *p = buf;

	while (len) {
		ssize_t k = n->x->ops->recv(n->x, p, len, timeout_ms);

		if (k < 0)
			return (int)k;
		if (k == 0 || (size_t)k > len)
			return RDC_E_IO;
		p += k;
		len -= (size_t)k;
	}
	return 0;
}

/* One message: header and a malloc'd payload (NULL when empty). */
static int net_read_msg(struct net *n, struct rdc_proto_hdr *h, uint8_t **pl,
			int timeout_ms)
{
	uint8_t hdr[RDC_PROTO_HDR_SIZE];
	int ret;

	*pl = NULL;
	ret = net_read_all(n, hdr, sizeof(hdr), timeout_ms);
	if (ret)
		return ret;
	rdc_proto_hdr_decode(hdr, h);
	if (h->len > RDC_PROTO_MAX_REPLY)
		return RDC_E_PROTO;
	if (!h->len)
		return 0;
	*pl = malloc(h->len);
	if (!*pl)
		return RDC_E_NOMEM;
	/* the rest of a started message comes without a deadline */
	ret = net_read_all(n, *pl, h->len, -1);
	if (ret) {
		free(*pl);
		*pl = NULL;
	}
	return ret;
}

static void net_irq_event(struct net *n, const uint8_t *pl, size_t len)
{
	struct rdc_event *ev;

	if (len != 12)
		return;
	if (n->irq_n == NET_IRQ_QUEUE) {
		/* keep the newest */
		n->irq_head = (n->irq_head + 1) % NET_IRQ_QUEUE;
		n->irq_n--;
	}
	ev = &n->irq[(n->irq_head + n->irq_n++) % NET_IRQ_QUEUE];
	memset(ev, 0, sizeof(*ev));
	ev->type = RDC_EVENT_IRQ;
	ev->irq = rdc_proto_get32(pl);
	ev->time = rdc_proto_get64(pl + 4);
}

static int net_frame_event(struct net *n, const uint8_t *pl, size_t len)
{
	struct rdc_proto_frame f;

	if (rdc_proto_frame_hdr_decode(pl, len, &f))
		return RDC_E_PROTO;
	if (f.width != n->fw || f.height != n->fh || !n->frame) {
		uint32_t *p =
			calloc((size_t)f.width * f.height + 1, sizeof(*p));

		if (!p)
			return RDC_E_NOMEM;
		free(n->frame);
		n->frame = p;
		n->fw = f.width;
		n->fh = f.height;
	}
	if (rdc_proto_frame_decode(n->frame, f.width, f.height, f.encoding,
				   pl + RDC_PROTO_FRAME_HDR,
				   len - RDC_PROTO_FRAME_HDR))
		return RDC_E_PROTO;
	if (n->frame_pending)
		n->local_dropped++;
	n->frame_pending = true;
	memset(&n->frame_ev, 0, sizeof(n->frame_ev));
	n->frame_ev.type = RDC_EVENT_FRAME;
	n->frame_ev.number = f.number;
	n->frame_ev.width = f.width;
	n->frame_ev.height = f.height;
	n->frame_ev.dropped = f.dropped + n->local_dropped;
	return 0;
}

static int net_event(struct net *n, const struct rdc_proto_hdr *h,
		     const uint8_t *pl)
{
	if (h->type == RDC_MSG_EV_FRAME)
		return net_frame_event(n, pl, h->len);
	if (h->type == RDC_MSG_EV_IRQ)
		net_irq_event(n, pl, h->len);
	return 0;
}

/*
 * The stream is out of step or gone: nothing more can be trusted on it.
 * Returns what the failing call reports; later calls report RDC_E_GONE if
 * the device went away, else RDC_E_IO.
 */
static int net_kill(struct net *n, int ret)
{
	if (ret != RDC_E_NOMEM && ret != RDC_E_PROTO && ret != RDC_E_GONE)
		ret = RDC_E_IO;
	if (n->x) {
		n->x->ops->close(n->x);
		n->x = NULL;
	}
	n->dead = ret == RDC_E_GONE ? RDC_E_GONE : RDC_E_IO;
	return ret;
}

/*
 * One request and its reply.  The reply payload goes to *out (malloc'd,
 * the caller frees) when out is not NULL, else must be empty.  Returns
 * the mapped status, or a transport error.
 */
static int net_call2(struct net *n, uint16_t type, const void *a, size_t alen,
		     const void *b, size_t blen, uint8_t **out,
		     uint32_t *out_len)
{
	uint32_t seq;
	int ret;

	if (!n->x)
		return n->dead;
	ret = net_send_msg(n, type, a, alen, b, blen);
	if (ret)
		goto dead;
	seq = n->seq;
	for (;;) {
		struct rdc_proto_hdr h;
		uint8_t *pl;

		ret = net_read_msg(n, &h, &pl, -1);
		if (ret)
			goto dead;
		if (h.flags & RDC_MSGF_EVENT) {
			ret = net_event(n, &h, pl);
			free(pl);
			if (ret)
				goto dead;
			continue;
		}
		if (!(h.flags & RDC_MSGF_REPLY) || h.seq != seq ||
		    h.type != type) {
			free(pl);
			ret = RDC_E_PROTO;
			goto dead;
		}
		if (out) {
			*out = pl;
			*out_len = h.len;
		} else {
			free(pl);
		}
		return net_status_to_error(h.status);
	}
dead:
	return net_kill(n, ret);
}

static int net_call(struct net *n, uint16_t type, const void *a, size_t alen,
		    uint8_t **out, uint32_t *out_len)
{
	return net_call2(n, type, a, alen, NULL, 0, out, out_len);
}

/* ---- Opening ------------------------------------------------------------ */

int rdc_client_parse_opts(const char *q, struct rdc_client_opts *o)
{
	const char *env = getenv(NET_TOKEN_ENV);

	memset(o, 0, sizeof(*o));
	if (env && strlen(env) < sizeof(o->token_file))
		strcpy(o->token_file, env);
	for (const char *p = q; p && *p;) {
		const char *end = strchr(p, '&');
		size_t len = end ? (size_t)(end - p) : strlen(p);

		if (len == 7 && !strncmp(p, "observe", 7)) {
			o->observe = true;
		} else if (len > 6 && !strncmp(p, "token=", 6) &&
			   len - 6 < sizeof(o->token_file)) {
			memcpy(o->token_file, p + 6, len - 6);
			o->token_file[len - 6] = 0;
		} else {
			return RDC_E_URI;
		}
		p = end ? end + 1 : NULL;
	}
	return 0;
}

/* No file: no token (a UNIX socket's clients need none). */
static int net_read_token(const char *path, uint8_t *tok, uint32_t *len)
{
	*len = 0;
	return *path ? rdc_token_read("token", path, tok, len) : 0;
}

int rdc_client_open(rdc_dev *dev, struct rdc_xport *x,
		    const struct rdc_client_opts *o)
{
	uint8_t token[RDC_PROTO_MAX_TOKEN],
		msg[RDC_PROTO_HELLO_FIXED + RDC_PROTO_MAX_TOKEN];
	struct rdc_proto_hello h = {
		.magic = RDC_PROTO_MAGIC,
		.version = RDC_PROTO_VERSION,
		.caps = RDC_CAP_ALL,
		.token = token,
		.flags = o->observe ? 0 : RDC_HELLO_CONTROL,
	};
	uint32_t max = x->max_request &&
				       x->max_request < RDC_PROTO_MAX_REQUEST ?
			       x->max_request :
			       RDC_PROTO_MAX_REQUEST;
	struct net *n;
	uint8_t *pl = NULL;
	uint32_t plen = 0;
	size_t mlen;
	int ret;

	ret = net_read_token(o->token_file, token, &h.token_len);
	if (ret) {
		x->ops->close(x);
		return ret;
	}
	n = calloc(1, sizeof(*n));
	if (!n) {
		x->ops->close(x);
		return RDC_E_NOMEM;
	}
	n->x = x;
	/* a VRAM write is its address and the bytes; a submit is words */
	n->vram_chunk = RDC_MIN(RDC_PROTO_VRAM_CHUNK, (max - 4) & ~3u);
	n->submit_words = RDC_MIN(RDC_PROTO_MAX_SUBMIT_WORDS, max / 4);
	mlen = rdc_proto_hello_encode(msg, sizeof(msg), &h);
	ret = net_call(n, RDC_MSG_HELLO, msg, mlen, &pl, &plen);
	if (!ret && rdc_proto_hello_reply_decode(pl, plen, &n->hello))
		ret = RDC_E_PROTO;
	if (!ret && !o->observe && !(n->hello.flags & RDC_HELLO_CONTROL))
		ret = RDC_E_BUSY;
	free(pl);
	if (ret) {
		if (n->x)
			n->x->ops->close(n->x);
		free(n);
		return ret;
	}
	dev->priv = n;
	return 0;
}

const struct rdc_proto_hello_reply *rdc_client_hello(rdc_dev *dev)
{
	return &net_of(dev)->hello;
}

void rdc_client_close(rdc_dev *dev)
{
	struct net *n = net_of(dev);

	if (n->x)
		n->x->ops->close(n->x);
	free(n->frame);
	free(n);
	dev->priv = NULL;
}

/* ---- Operations ---------------------------------------------------------- */

/*
 * With a pixel history open, the daemon's entries carry the .rdl line
 * this side runs (dev->src_line, which the script runner sets): before a
 * request that can make the chip write, the line, if it changed.
 */
static int net_hist_line(rdc_dev *dev)
{
	struct net *n = net_of(dev);
	uint8_t b[RDC_PROTO_HIST_SET_SIZE];
	int ret;

	if (!n->hist_open || dev->src_line == n->hist_line)
		return 0;
	rdc_proto_put32(b, RDC_HIST_SET_LINE);
	rdc_proto_put32(b + 4, dev->src_line);
	ret = net_call(n, RDC_MSG_HIST_SET, b, sizeof(b), NULL, NULL);
	if (!ret)
		n->hist_line = dev->src_line;
	return ret;
}

int rdc_client_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val)
{
	uint8_t b[4], *pl = NULL;
	uint32_t len = 0;
	int ret;

	rdc_proto_put32(b, reg);
	ret = net_call(net_of(dev), RDC_MSG_REG_READ, b, 4, &pl, &len);
	if (!ret && len != 4)
		ret = RDC_E_PROTO;
	if (!ret)
		*val = rdc_proto_get32(pl);
	free(pl);
	return ret;
}

int rdc_client_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val)
{
	uint8_t b[8];
	int ret = net_hist_line(dev);

	if (ret)
		return ret;

	rdc_proto_put32(b, reg);
	rdc_proto_put32(b + 4, val);
	return net_call(net_of(dev), RDC_MSG_REG_WRITE, b, 8, NULL, NULL);
}

int rdc_client_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len)
{
	uint8_t *out = buf;

	if (len > UINT32_MAX || addr > UINT32_MAX - len)
		return RDC_E_RANGE;
	while (len) {
		uint32_t k = (uint32_t)RDC_MIN(len, RDC_PROTO_VRAM_CHUNK);
		uint8_t b[8], *pl = NULL;
		uint32_t got = 0;
		int ret;

		rdc_proto_put32(b, addr);
		rdc_proto_put32(b + 4, k);
		ret = net_call(net_of(dev), RDC_MSG_VRAM_READ, b, 8, &pl, &got);
		if (!ret && got != k)
			ret = RDC_E_PROTO;
		if (!ret)
			memcpy(out, pl, k);
		free(pl);
		if (ret)
			return ret;
		out += k;
		addr += k;
		len -= k;
	}
	return 0;
}

int rdc_client_vram_write(rdc_dev *dev, uint32_t addr, const void *buf,
			  size_t len)
{
	const uint8_t *in = buf;
	int hret;

	if (len > UINT32_MAX || addr > UINT32_MAX - len)
		return RDC_E_RANGE;
	hret = net_hist_line(dev);
	if (hret)
		return hret;
	/* Chunks are exact: a host aperture write takes no simulated time. */
	do {
		uint32_t k = (uint32_t)RDC_MIN(len, net_of(dev)->vram_chunk);
		uint8_t b[4];
		int ret;

		rdc_proto_put32(b, addr);
		ret = net_call2(net_of(dev), RDC_MSG_VRAM_WRITE, b, 4, in, k,
				NULL, NULL);
		if (ret)
			return ret;
		in += k;
		addr += k;
		len -= k;
	} while (len);
	return 0;
}

int rdc_client_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	uint32_t max = net_of(dev)->submit_words;
	uint8_t *b;
	int ret = net_hist_line(dev);

	if (ret)
		return ret;

	b = malloc(RDC_MIN(n, max) * 4 + 1);
	if (!b)
		return RDC_E_NOMEM;
	/*
	 * The daemon pushes each message's words as rdc_submit would on
	 * sim: (FIFO_FREE, then waits), so splitting changes nothing.
	 */
	while (n && !ret) {
		size_t k = RDC_MIN(n, max);

		for (size_t i = 0; i < k; i++)
			rdc_proto_put32(b + 4 * i, words[i]);
		ret = net_call(net_of(dev), RDC_MSG_SUBMIT, b, k * 4, NULL,
			       NULL);
		words += k;
		n -= k;
	}
	free(b);
	return ret;
}

int rdc_client_wait(rdc_dev *dev, const struct rdc_wait *w)
{
	struct rdc_proto_wait pw = { .budget = w->budget,
				     .needs_dp = w->needs_dp };
	uint8_t b[RDC_PROTO_WAIT_SIZE];
	int ret = net_hist_line(dev);

	if (ret)
		return ret;
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		pw.term[i].kind = w->term[i].kind;
		pw.term[i].reg = w->term[i].reg;
		pw.term[i].mask = w->term[i].mask;
		pw.term[i].value = w->term[i].value;
	}
	rdc_proto_wait_encode(b, &pw);
	return net_call(net_of(dev), RDC_MSG_WAIT, b, sizeof(b), NULL, NULL);
}

int rdc_client_step(rdc_dev *dev, uint64_t cycles)
{
	uint8_t b[8];
	int ret = net_hist_line(dev);

	if (ret)
		return ret;

	rdc_proto_put64(b, cycles);
	return net_call(net_of(dev), RDC_MSG_STEP, b, 8, NULL, NULL);
}

int rdc_client_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	uint8_t b[8], *pl = NULL;
	uint32_t len = 0;
	int ret = net_hist_line(dev);

	if (ret)
		return ret;
	rdc_proto_put32(b, mask);
	rdc_proto_put32(b + 4, levels);
	ret = net_call(net_of(dev), RDC_MSG_PINS_SET, b, 8, &pl, &len);
	if (!ret && len != 4)
		ret = RDC_E_PROTO;
	free(pl);
	return ret;
}

int rdc_client_hist_open(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
			 uint32_t h, uint32_t flags)
{
	struct rdc_proto_hist_open o = { x, y, w, h, flags };
	struct net *n = net_of(dev);
	uint8_t b[RDC_PROTO_HIST_OPEN_SIZE];
	int ret;

	rdc_proto_hist_open_encode(b, &o);
	ret = net_call(n, RDC_MSG_HIST_OPEN, b, sizeof(b), NULL, NULL);
	if (!ret) {
		n->hist_open = true;
		n->hist_line = 0; /* the daemon's new history starts there */
	}
	return ret;
}

int rdc_client_hist_read(rdc_dev *dev, uint64_t first, uint32_t max,
			 struct rdc_history_entry *e, uint32_t *n,
			 uint64_t *count, uint64_t *dropped)
{
	struct rdc_proto_hist_page pg = { 0 };
	uint8_t b[RDC_PROTO_HIST_READ_SIZE], *pl = NULL;
	uint32_t len = 0;
	int ret;

	rdc_proto_put64(b, first);
	rdc_proto_put32(b + 8, max);
	ret = net_call(net_of(dev), RDC_MSG_HIST_READ, b, sizeof(b), &pl, &len);
	if (!ret && rdc_proto_hist_page_decode(pl, len, max, &pg))
		ret = RDC_E_PROTO;
	for (uint32_t i = 0; !ret && i < pg.n; i++) {
		struct rdc_proto_hist_entry pe;

		if (rdc_proto_hist_entry_decode(
			    pl + RDC_PROTO_HIST_PAGE_HDR +
				    (size_t)i * RDC_PROTO_HIST_ENTRY_SIZE,
			    &pe)) {
			ret = RDC_E_PROTO;
			break;
		}
		e[i] = (struct rdc_history_entry){
			.size = sizeof(e[i]),
			.x = pe.x,
			.y = pe.y,
			.format = pe.format,
			.before = pe.before,
			.after = pe.after,
			.cycle = pe.cycle,
			.frame = pe.frame,
			.fetched = pe.fetched,
			.opcode = pe.opcode,
			.cmd_index = pe.cmd_index,
			.source = pe.source,
			.line = pe.line,
			.cmd_addr = pe.cmd_addr,
			.depth = pe.depth,
			.rop = pe.rop,
			.alpha = pe.alpha,
			.colorkey = pe.colorkey,
			.colorkey_on = pe.colorkey_on,
			.pattern = pe.pattern,
			.fg = pe.fg,
			.bg = pe.bg,
		};
		_Static_assert(sizeof(e[i].calls) == sizeof(pe.calls),
			       "rdc.h and rdc_proto.h call chains differ");
		memcpy(e[i].calls, pe.calls, sizeof(pe.calls));
	}
	if (!ret) {
		*n = pg.n;
		*count = pg.count;
		*dropped = pg.dropped;
	}
	free(pl);
	return ret;
}

int rdc_client_hist_set(rdc_dev *dev, uint32_t what, uint32_t value)
{
	uint8_t b[RDC_PROTO_HIST_SET_SIZE];

	rdc_proto_put32(b, what);
	rdc_proto_put32(b + 4, value);
	return net_call(net_of(dev), RDC_MSG_HIST_SET, b, sizeof(b), NULL,
			NULL);
}

int rdc_client_hist_close(rdc_dev *dev)
{
	struct net *n = net_of(dev);

	n->hist_open = false;
	return net_call(n, RDC_MSG_HIST_END, NULL, 0, NULL, NULL);
}

int rdc_client_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap,
			  uint32_t *width, uint32_t *height)
{
	struct rdc_proto_frame f = { 0 };
	uint8_t b[8], *pl = NULL;
	uint32_t len = 0;
	int ret;

	rdc_proto_put32(b, RDC_ENC_RAW);
	rdc_proto_put32(b + 4, (uint32_t)RDC_MIN(cap, UINT32_MAX));
	ret = net_call(net_of(dev), RDC_MSG_FRAME_GRAB, b, 8, &pl, &len);
	if (ret == 0 || ret == RDC_E_RANGE) {
		if (rdc_proto_frame_hdr_decode(pl, len, &f))
			ret = RDC_E_PROTO;
		else {
			*width = f.width;
			*height = f.height;
		}
	}
	if (!ret && (cap < (size_t)f.width * f.height ||
		     rdc_proto_frame_decode(buf, f.width, f.height, f.encoding,
					    pl + RDC_PROTO_FRAME_HDR,
					    len - RDC_PROTO_FRAME_HDR)))
		ret = RDC_E_PROTO;
	free(pl);
	return ret;
}

int rdc_client_subscribe(rdc_dev *dev, uint32_t events, uint32_t every,
			 uint32_t encoding)
{
	uint8_t b[12];

	rdc_proto_put32(b, events);
	rdc_proto_put32(b + 4, every);
	rdc_proto_put32(b + 8, encoding);
	return net_call(net_of(dev), RDC_MSG_SUBSCRIBE, b, 12, NULL, NULL);
}

static int net_take_event(struct net *n, struct rdc_event *ev, uint32_t *buf,
			  size_t cap)
{
	if (n->irq_n) {
		*ev = n->irq[n->irq_head];
		n->irq_head = (n->irq_head + 1) % NET_IRQ_QUEUE;
		n->irq_n--;
		return 1;
	}
	if (n->frame_pending) {
		size_t px = (size_t)n->fw * n->fh;

		n->frame_pending = false;
		*ev = n->frame_ev;
		if (cap < px)
			return RDC_E_RANGE;
		memcpy(buf, n->frame, px * sizeof(*buf));
		return 1;
	}
	return 0;
}

int rdc_client_event_next(rdc_dev *dev, struct rdc_event *ev, uint32_t *buf,
			  size_t cap, int timeout_ms)
{
	struct net *n = net_of(dev);

	/* a device that went away takes its undelivered events along */
	if (!n->x && n->dead == RDC_E_GONE)
		return RDC_E_GONE;
	for (;;) {
		struct rdc_proto_hdr h;
		uint8_t *pl;
		int ret = net_take_event(n, ev, buf, cap);

		if (ret)
			return ret < 0 ? ret : 0;
		if (!n->x)
			return n->dead;
		ret = net_read_msg(n, &h, &pl, timeout_ms);
		if (ret == RDC_E_TIMEOUT)
			return ret;
		if (!ret && !(h.flags & RDC_MSGF_EVENT))
			ret = RDC_E_PROTO; /* a reply nobody asked for */
		if (!ret)
			ret = net_event(n, &h, pl);
		free(pl);
		if (ret)
			return net_kill(n, ret);
	}
}
