// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web sink: the live display in a browser (docs/web.md).
 *
 * A small HTTP server on its own thread serves the page (web/, built into
 * the library: no file is ever read at a client's request) and one
 * WebSocket, /ws, that carries the picture and the device's state.  The
 * caller's thread only compares each frame with the last and notes, per
 * viewer, which rows changed and between which columns; the server thread
 * sends each viewer those rectangles as zlib-compressed RGBA when its
 * socket has room, so a slow viewer gets fewer, larger updates and never
 * holds up the source, and a picture that does not change sends nothing.
 *
 * Safe by default: loopback unless an address is given; with a token
 * (token=FILE) every viewer must present it, and an address other than
 * loopback needs one (rdcd's rule for tcp:; the address and the file
 * read as rdc_tcp_listen and rdc_token_read, rdc_server.h, read them).  Failed tokens from one
 * address are refused for a while, as rdcd does.  A loopback server only
 * answers requests whose Host names loopback, and a WebSocket only from
 * its own page's origin, so another web site (or a DNS name rebound to
 * 127.0.0.1) cannot watch through the user's browser.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>
#include <zlib.h>

#include "rdc_priv.h"
#include "sink_priv.h"
#include "web_proto.h"

/* Connections at once (page loads and viewers); a new one beyond this
 * evicts the oldest that is not a viewer yet, else the viewer whose
 * socket has taken nothing for longest (WEB_DEADLINE_NS at least), or
 * is refused. */
#define WEB_MAX_CONNS 16
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
	/* damage since the last update sent, per row: columns [x0, x1),
	 * x1 == 0 for a clean row (guarded by the sink's mutex) */
	uint32_t *dx0, *dx1;
	uint32_t dh;
	bool dirty, status_due, sync_due;
	uint64_t status_ns;
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
};

static uint64_t web_now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

static void web_wake(struct web_sink *w)
{
	uint64_t one = 1;

	if (write(w->wake_fd, &one, sizeof(one)) < 0) {
		/* EAGAIN: already awake */
	}
}

/* ---- Output ------------------------------------------------------------ */

static bool conn_queue(struct web_conn *c, const void *p, size_t n)
{
	if (c->out_off == c->out_len)
		c->out_off = c->out_len = 0;
	if (c->out_len + n > c->out_cap) {
		size_t cap = c->out_len + n;
		uint8_t *nb = realloc(c->out, cap);

		if (!nb)
			return false;
		c->out = nb;
		c->out_cap = cap;
	}
	memcpy(c->out + c->out_len, p, n);
	c->out_len += n;
	return true;
}

static bool conn_ws_send(struct web_conn *c, uint8_t op, const void *p,
			 size_t n)
{
	uint8_t hdr[WEB_WS_HDR_MAX];
	size_t hl = rdc_web_ws_header(hdr, op, n);

	return conn_queue(c, hdr, hl) && conn_queue(c, p, n);
}

static void conn_ws_close(struct web_conn *c, unsigned int code)
{
	uint8_t b[2] = { (uint8_t)(code >> 8), (uint8_t)code };

	if (c->closing)
		return;
	conn_ws_send(c, WEB_WS_CLOSE, b, sizeof(b));
	c->closing = true;
}

static void conn_http_error(struct web_conn *c, int code, const char *why)
{
	char b[256];
	int n = snprintf(b, sizeof(b),
			 "HTTP/1.1 %d %s\r\n"
			 "Content-Type: text/plain; charset=utf-8\r\n"
			 "Content-Length: %zu\r\n"
			 "Cache-Control: no-store\r\n"
			 "Connection: close\r\n\r\n%s\n",
			 code, why, strlen(why) + 1, why);

	if (n > 0 && (size_t)n < sizeof(b))
		conn_queue(c, b, (size_t)n);
	c->closing = true;
}

static void conn_flush(struct web_conn *c)
{
	while (c->out_off < c->out_len) {
		ssize_t n = send(c->fd, c->out + c->out_off,
				 c->out_len - c->out_off, MSG_NOSIGNAL);

		if (n < 0) {
			if (errno == EINTR)
				continue;
			if (errno != EAGAIN && errno != EWOULDBLOCK)
				c->dead = true;
			return;
		}
		c->out_off += (size_t)n;
		c->sent_ns = web_now_ns();
	}
	c->out_off = c->out_len = 0;
	c->sent_ns = web_now_ns();
	if (c->closing)
		c->dead = true;
}

/* ---- Damage (under the mutex) ------------------------------------------ */

static void conn_damage_all(struct web_sink *w, struct web_conn *c)
{
	for (uint32_t y = 0; y < c->dh; y++) {
		c->dx0[y] = 0;
		c->dx1[y] = w->w;
	}
	c->dirty = c->dh > 0;
	c->status_due = c->sync_due = true;
	c->status_ns = 0;
}

static bool conn_damage_size(struct web_sink *w, struct web_conn *c)
{
	uint32_t *a, *b;

	if (c->dh == w->h && c->dx0)
		return true;
	a = realloc(c->dx0, (w->h ? w->h : 1) * sizeof(*a));
	if (a)
		c->dx0 = a;
	b = realloc(c->dx1, (w->h ? w->h : 1) * sizeof(*b));
	if (b)
		c->dx1 = b;
	if (!a || !b) {
		c->dh = 0;
		return false;
	}
	c->dh = w->h;
	return true;
}

/* ---- Status ------------------------------------------------------------ */

static const char *const web_fmt_names[RDC_FMT_COUNT] = {
	"I1", "I2", "I4", "I8", "RGB565", "RGB888", "XRGB8888",
};

static size_t web_status_json(const struct web_sink *w, char *b, size_t cap)
{
	const struct rdc_sink_status *st = &w->st;
	int n;

	n = snprintf(b, cap,
		     "{\"type\":\"status\",\"seq\":%llu,\"width\":%u,"
		     "\"height\":%u,\"interval\":[%u,%u]",
		     (unsigned long long)w->seq, w->w, w->h, w->inum, w->iden);
	if (w->have_st && (st->have & RDC_SINK_HAVE_TIME))
		n += snprintf(b + n, cap - (size_t)n,
			      ",\"time\":%llu,\"core_hz\":%u",
			      (unsigned long long)st->time, st->core_hz);
	if (w->have_st && (st->have & RDC_SINK_HAVE_PINS))
		n += snprintf(b + n, cap - (size_t)n, ",\"pins\":%u", st->pins);
	if (w->have_st && (st->have & RDC_SINK_HAVE_IRQ))
		n += snprintf(b + n, cap - (size_t)n,
			      ",\"irq_status\":%u,\"irq_enable\":%u",
			      st->irq_status, st->irq_enable);
	if (w->have_st && (st->have & RDC_SINK_HAVE_FORMAT) &&
	    st->format < RDC_FMT_COUNT)
		n += snprintf(b + n, cap - (size_t)n, ",\"format\":\"%s\"",
			      web_fmt_names[st->format]);
	n += snprintf(b + n, cap - (size_t)n, "}");
	return (size_t)n < cap ? (size_t)n : 0;
}

/* ---- The next message for a viewer ------------------------------------- */

/*
 * Take the next band of damage: consecutive dirty rows, their columns'
 * union, at most WEB_BAND_BYTES of RGBA; copy it out of the frame.
 */
static bool web_take_band(struct web_sink *w, struct web_conn *c, uint32_t r[4])
{
	uint32_t y = 0, x0 = UINT32_MAX, x1 = 0, y1;

	while (y < c->dh && !c->dx1[y])
		y++;
	if (y == c->dh) {
		c->dirty = false;
		return false;
	}
	for (y1 = y; y1 < c->dh && c->dx1[y1]; y1++) {
		uint32_t nx0 = RDC_MIN(x0, c->dx0[y1]);
		uint32_t nx1 = RDC_MAX(x1, c->dx1[y1]);

		if (y1 > y &&
		    (size_t)(nx1 - nx0) * (y1 - y + 1) * 4 > WEB_BAND_BYTES)
			break;
		x0 = nx0;
		x1 = nx1;
	}
	for (uint32_t yy = y; yy < y1; yy++) {
		const uint32_t *src = w->fb + (size_t)yy * w->w + x0;
		uint8_t *dst = w->rgba + (size_t)(yy - y) * (x1 - x0) * 4;

		for (uint32_t x = 0; x < x1 - x0; x++) {
			dst[4 * x] = (uint8_t)(src[x] >> 16);
			dst[4 * x + 1] = (uint8_t)(src[x] >> 8);
			dst[4 * x + 2] = (uint8_t)src[x];
			dst[4 * x + 3] = 0xff;
		}
		c->dx0[yy] = c->dx1[yy] = 0;
	}
	r[0] = x0;
	r[1] = y;
	r[2] = x1 - x0;
	r[3] = y1 - y;
	return true;
}

static void put32le(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

static bool web_send_rect(struct web_sink *w, struct web_conn *c,
			  const uint32_t r[4])
{
	uLong raw = (uLong)r[2] * r[3] * 4;
	uLongf zlen;
	size_t need = WEB_RECT_HDR + compressBound(raw);

	if (need > w->zcap) {
		uint8_t *nz = realloc(w->zbuf, need);

		if (!nz)
			return false;
		w->zbuf = nz;
		w->zcap = need;
	}
	put32le(w->zbuf, WEB_RECT_TYPE);
	for (int i = 0; i < 4; i++)
		put32le(w->zbuf + 4 + 4 * i, r[i]);
	zlen = (uLongf)(w->zcap - WEB_RECT_HDR);
	if (compress2(w->zbuf + WEB_RECT_HDR, &zlen, w->rgba, raw, 1) != Z_OK)
		return false;
	return conn_ws_send(c, WEB_WS_BINARY, w->zbuf, WEB_RECT_HDR + zlen);
}

/* Queue one message for a viewer whose queue is empty. */
static void web_pump(struct web_sink *w, struct web_conn *c, uint64_t now)
{
	char json[WEB_JSON_MAX];
	size_t jn = 0;
	uint32_t r[4];
	bool rect = false;

	pthread_mutex_lock(&w->mu);
	if (c->dh != w->h && conn_damage_size(w, c))
		conn_damage_all(w, c);
	if (c->status_due && c->dirty && c->status_ns == 0) {
		/* a new size goes before its pixels */
		jn = web_status_json(w, json, sizeof(json));
		c->status_due = false;
		c->status_ns = now;
	} else if (c->dirty) {
		rect = web_take_band(w, c, r);
		c->sync_due |= rect;
	}
	if (!jn && !rect &&
	    (c->sync_due ||
	     (c->status_due && now >= c->status_ns + WEB_STATUS_NS))) {
		/* the picture is complete up to seq: say so at once */
		jn = web_status_json(w, json, sizeof(json));
		c->status_due = c->sync_due = false;
		c->status_ns = now;
	}
	pthread_mutex_unlock(&w->mu);
	if (rect) {
		if (!web_send_rect(w, c, r))
			c->dead = true;
	} else if (jn && !conn_ws_send(c, WEB_WS_TEXT, json, jn)) {
		c->dead = true;
	}
}

/* ---- Requests ---------------------------------------------------------- */

/* The Host a loopback server answers: a loopback name or address. */
static bool web_host_loopback(const char *host)
{
	char h[WEB_FIELD_MAX];
	const char *end;
	struct in_addr a4;
	size_t n;

	if (host[0] == '[') {
		end = strchr(host, ']');
		if (!end)
			return false;
		return (size_t)(end - host) == 4 && !strncmp(host, "[::1", 4) &&
		       (!end[1] || end[1] == ':');
	}
	end = strchr(host, ':');
	n = end ? (size_t)(end - host) : strlen(host);
	if (n >= sizeof(h))
		return false;
	memcpy(h, host, n);
	h[n] = '\0';
	if (!strcasecmp(h, "localhost"))
		return true;
	return inet_pton(AF_INET, h, &a4) == 1 &&
	       (ntohl(a4.s_addr) >> 24) == 127;
}

static const char web_headers[] =
	"Cache-Control: no-store\r\n"
	"X-Content-Type-Options: nosniff\r\n"
	"X-Frame-Options: DENY\r\n"
	"Referrer-Policy: no-referrer\r\n"
	"Content-Security-Policy: default-src 'none'; script-src 'self'; "
	"style-src 'self'; img-src 'self'; connect-src 'self'; "
	"frame-ancestors 'none'\r\n"
	"Connection: close\r\n";

static void web_request(struct web_sink *w, struct web_conn *c,
			const struct web_req *r)
{
	struct web_file f;
	char b[512], accept[WEB_WS_ACCEPT_SZ], origin[WEB_FIELD_MAX + 8];
	bool head = !strcmp(r->method, "HEAD");
	int n;

	if (strcmp(r->method, "GET") && !head) {
		conn_http_error(c, 405, "Method Not Allowed");
		return;
	}
	if (!r->has_host && r->http_minor >= 1) {
		conn_http_error(c, 400, "Bad Request (no Host)");
		return;
	}
	if (w->loopback && (!r->has_host || !web_host_loopback(r->host))) {
		conn_http_error(c, 403, "Forbidden (Host is not loopback)");
		return;
	}
	snprintf(origin, sizeof(origin), "http://%s", r->host);
	if (r->has_origin && strcasecmp(origin, r->origin)) {
		conn_http_error(c, 403, "Forbidden (another origin)");
		return;
	}
	if (!strcmp(r->path, "/ws")) {
		if (!r->upgrade_ws || !r->conn_upgrade || !r->has_key ||
		    !rdc_web_ws_key_ok(r->key) || head) {
			conn_http_error(c, 400,
					"Bad Request (not a WebSocket "
					"handshake)");
			return;
		}
		if (r->ws_version != 13) {
			static const char v[] =
				"HTTP/1.1 426 Upgrade Required\r\n"
				"Sec-WebSocket-Version: 13\r\n"
				"Content-Length: 0\r\nConnection: close\r\n\r\n";

			conn_queue(c, v, sizeof(v) - 1);
			c->closing = true;
			return;
		}
		rdc_web_ws_accept(r->key, accept);
		n = snprintf(b, sizeof(b),
			     "HTTP/1.1 101 Switching Protocols\r\n"
			     "Upgrade: websocket\r\nConnection: Upgrade\r\n"
			     "Sec-WebSocket-Accept: %s\r\n\r\n",
			     accept);
		conn_queue(c, b, (size_t)n);
		c->ws = true;
		c->deadline_ns = web_now_ns() + WEB_DEADLINE_NS;
		return;
	}
	if (!rdc_web_page_find(r->path, &f)) {
		conn_http_error(c, 404, "Not Found");
		return;
	}
	n = snprintf(b, sizeof(b),
		     "HTTP/1.1 200 OK\r\nContent-Type: %s\r\n"
		     "Content-Length: %zu\r\n%s\r\n",
		     f.type, f.len, web_headers);
	if (conn_queue(c, b, (size_t)n) && !head)
		conn_queue(c, f.data, f.len);
	c->closing = true;
}

/* ---- Tokens ------------------------------------------------------------ */

static bool web_token_ok(struct web_sink *w, struct web_conn *c,
			 const uint8_t *p, size_t n)
{
	uint64_t now = web_now_ns();

	if (!w->have_token)
		return true;
	if (rdc_auth_locked(&w->auth, c->peer, now))
		return false;
	if (rdc_auth_token_equal(w->token, w->token_len, p, n)) {
		rdc_auth_passed(&w->auth, c->peer);
		return true;
	}
	rdc_auth_failed(&w->auth, c->peer, now);
	return false;
}

/* A whole message from a viewer: the first is its token, the rest are
 * not looked at. */
static void web_message(struct web_sink *w, struct web_conn *c)
{
	if (c->authed)
		return;
	if (!web_token_ok(w, c, c->msg, c->msg_len)) {
		conn_ws_close(c, WEB_WS_CLOSE_AUTH);
		return;
	}
	pthread_mutex_lock(&w->mu);
	c->authed = true;
	w->nviewers++;
	if (conn_damage_size(w, c))
		conn_damage_all(w, c);
	else
		c->dead = true;
	pthread_mutex_unlock(&w->mu);
}

/* Frames from a viewer, as many as are whole in c->in. */
static void web_ws_input(struct web_sink *w, struct web_conn *c)
{
	size_t off = 0;

	while (!c->closing && !c->dead) {
		struct web_ws_frame f;
		int ret = rdc_web_ws_parse(c->in + off, c->in_len - off,
					   WEB_MSG_MAX, &f);
		uint8_t *p;

		if (ret < 0) {
			conn_ws_close(c, (unsigned int)-ret);
			break;
		}
		if (!ret || c->in_len - off < f.hdr_len + f.len)
			break;
		p = c->in + off + f.hdr_len;
		rdc_web_ws_unmask(p, (size_t)f.len, f.mask, 0);
		off += f.hdr_len + (size_t)f.len;
		switch (f.opcode) {
		case WEB_WS_PING:
			conn_ws_send(c, WEB_WS_PONG, p, (size_t)f.len);
			continue;
		case WEB_WS_PONG:
			continue;
		case WEB_WS_CLOSE:
			conn_ws_close(c, WEB_WS_CLOSE_NORMAL);
			continue;
		case WEB_WS_CONT:
			if (!c->in_msg) {
				conn_ws_close(c, WEB_WS_CLOSE_PROTOCOL);
				continue;
			}
			break;
		default:
			if (c->in_msg) {
				conn_ws_close(c, WEB_WS_CLOSE_PROTOCOL);
				continue;
			}
			c->in_msg = true;
			c->msg_len = 0;
		}
		if (c->msg_len + f.len > WEB_MSG_MAX) {
			conn_ws_close(c, WEB_WS_CLOSE_TOO_BIG);
			continue;
		}
		memcpy(c->msg + c->msg_len, p, (size_t)f.len);
		c->msg_len += (size_t)f.len;
		if (f.fin) {
			c->in_msg = false;
			web_message(w, c);
		}
	}
	memmove(c->in, c->in + off, c->in_len - off);
	c->in_len -= off;
}

static void web_read(struct web_sink *w, struct web_conn *c)
{
	for (;;) {
		ssize_t n;

		if (c->in_len == sizeof(c->in)) {
			/* a head that does not end, a frame too big: the
			 * parsers have said so; nothing more is read */
			break;
		}
		n = recv(c->fd, c->in + c->in_len, sizeof(c->in) - c->in_len,
			 0);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
			return;
		if (n <= 0) {
			c->dead = true;
			return;
		}
		if (c->closing)
			continue; /* dropped: only the queue matters now */
		c->in_len += (size_t)n;
		if (!c->ws) {
			struct web_req r;
			size_t used = 0;
			int ret = rdc_web_req_parse((const char *)c->in,
						    c->in_len, &r, &used);

			if (ret == WEB_REQ_MORE)
				continue;
			if (ret == WEB_REQ_TOO_BIG) {
				conn_http_error(c, 431,
						"Request Header Fields Too "
						"Large");
				continue;
			}
			if (ret) {
				conn_http_error(c, 400, "Bad Request");
				continue;
			}
			web_request(w, c, &r);
			memmove(c->in, c->in + used, c->in_len - used);
			c->in_len -= used;
			if (!c->ws)
				continue;
		}
		web_ws_input(w, c);
	}
	if (!c->closing)
		c->dead = true;
}

/* ---- Connections ------------------------------------------------------- */

static void conn_free(struct web_sink *w, struct web_conn *c)
{
	struct web_conn **pp;

	pthread_mutex_lock(&w->mu);
	for (pp = &w->conns; *pp; pp = &(*pp)->next)
		if (*pp == c) {
			*pp = c->next;
			break;
		}
	w->nconns--;
	if (c->authed)
		w->nviewers--;
	pthread_mutex_unlock(&w->mu);
	close(c->fd);
	free(c->out);
	free(c->dx0);
	free(c->dx1);
	free(c);
}

static void web_accept(struct web_sink *w)
{
	for (;;) {
		struct sockaddr_storage ss;
		socklen_t sl = sizeof(ss);
		int fd = accept4(w->lfd, (struct sockaddr *)&ss, &sl,
				 SOCK_NONBLOCK | SOCK_CLOEXEC);
		struct web_conn *c, *victim = NULL;
		int one = 1;

		if (fd < 0)
			return;
		if (w->nconns >= WEB_MAX_CONNS) {
			/* the oldest that is not watching yet makes room;
			 * else the viewer stuck longest on a full socket */
			for (c = w->conns; c; c = c->next)
				if (!c->authed)
					victim = c;
			for (c = victim ? NULL : w->conns; c; c = c->next)
				if (c->out_off < c->out_len &&
				    web_now_ns() >
					    c->sent_ns + WEB_DEADLINE_NS &&
				    (!victim || c->sent_ns < victim->sent_ns))
					victim = c;
			if (!victim) {
				close(fd);
				continue;
			}
			conn_free(w, victim);
		}
		c = calloc(1, sizeof(*c));
		if (!c) {
			close(fd);
			return;
		}
		setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
		c->fd = fd;
		c->sent_ns = web_now_ns();
		c->deadline_ns = c->sent_ns + WEB_DEADLINE_NS;
		if (ss.ss_family == AF_INET)
			inet_ntop(AF_INET,
				  &((struct sockaddr_in *)&ss)->sin_addr,
				  c->peer, sizeof(c->peer));
		else if (ss.ss_family == AF_INET6)
			inet_ntop(AF_INET6,
				  &((struct sockaddr_in6 *)&ss)->sin6_addr,
				  c->peer, sizeof(c->peer));
		pthread_mutex_lock(&w->mu);
		c->next = w->conns; /* newest first */
		w->conns = c;
		w->nconns++;
		pthread_mutex_unlock(&w->mu);
	}
}

static void *web_thread(void *arg)
{
	struct web_sink *w = arg;
	struct pollfd pfd[2 + WEB_MAX_CONNS];
	struct web_conn *cl[WEB_MAX_CONNS];
	sigset_t all;

	sigfillset(&all);
	pthread_sigmask(SIG_BLOCK, &all, NULL);
	for (;;) {
		unsigned int n = 2, nc = 0;
		uint64_t now = web_now_ns(), next = UINT64_MAX;
		int tmo = -1;
		bool stop;

		pthread_mutex_lock(&w->mu);
		stop = w->stop;
		pthread_mutex_unlock(&w->mu);
		if (stop)
			break;
		pfd[0] = (struct pollfd){ .fd = w->wake_fd, .events = POLLIN };
		pfd[1] = (struct pollfd){ .fd = w->lfd, .events = POLLIN };
		for (struct web_conn *c = w->conns, *nx; c; c = nx) {
			nx = c->next;
			if (c->authed && !c->closing &&
			    c->out_off == c->out_len)
				web_pump(w, c, now);
			if (c->out_off < c->out_len)
				conn_flush(c);
			if (c->dead)
				conn_free(w, c); /* a last answer went */
		}
		for (struct web_conn *c = w->conns; c; c = c->next) {
			if (!c->authed && !c->closing)
				next = RDC_MIN(next, c->deadline_ns);
			pthread_mutex_lock(&w->mu);
			if (c->authed && c->status_due && !c->dirty &&
			    !c->sync_due)
				next = RDC_MIN(next,
					       c->status_ns + WEB_STATUS_NS);
			pthread_mutex_unlock(&w->mu);
			if (nc == WEB_MAX_CONNS)
				continue;
			cl[nc++] = c;
			pfd[n++] = (struct pollfd){
				.fd = c->fd,
				.events = (short)(POLLIN |
						  (c->out_off < c->out_len ?
							   POLLOUT :
							   0)),
			};
		}
		if (next != UINT64_MAX)
			tmo = next <= now ?
				      0 :
				      (int)RDC_MIN((next - now) / 1000000u + 1,
						   (uint64_t)1000);
		for (unsigned int i = 0; i < nc; i++)
			if (cl[i]->authed && !cl[i]->closing &&
			    cl[i]->out_off == cl[i]->out_len) {
				pthread_mutex_lock(&w->mu);
				if (cl[i]->dirty || cl[i]->sync_due)
					tmo = 0; /* more to send at once */
				pthread_mutex_unlock(&w->mu);
			}
		if (poll(pfd, n, tmo) < 0 && errno != EINTR)
			break;
		if (pfd[0].revents & POLLIN) {
			uint64_t v;

			if (read(w->wake_fd, &v, sizeof(v)) < 0) {
				/* EAGAIN: nothing */
			}
		}
		now = web_now_ns();
		for (unsigned int i = 0; i < nc; i++) {
			struct web_conn *c = cl[i];

			if (pfd[2 + i].revents & POLLOUT)
				conn_flush(c);
			if (pfd[2 + i].revents & (POLLIN | POLLHUP | POLLERR))
				web_read(w, c);
			if (!c->authed && !c->closing &&
			    now >= c->deadline_ns) {
				if (c->ws)
					conn_ws_close(c, WEB_WS_CLOSE_TIMEOUT);
				else
					c->dead = true;
			}
		}
		/* after the others: making room may free one of cl[] */
		if (pfd[1].revents & POLLIN)
			web_accept(w);
		for (struct web_conn *c = w->conns, *nx; c; c = nx) {
			nx = c->next;
			if (c->dead)
				conn_free(w, c);
		}
	}
	while (w->conns)
		conn_free(w, w->conns);
	return NULL;
}

/* ---- The sink ---------------------------------------------------------- */

int rdc_sink_have_web(void)
{
	return 1;
}

static int web_frame(rdc_sink *s, const struct rdc_frame *f)
{
	struct web_sink *w = s->priv;
	size_t row = (size_t)f->width * sizeof(uint32_t);
	bool changed = false;

	pthread_mutex_lock(&w->mu);
	if (f->width != w->w || f->height != w->h) {
		uint32_t *fb = malloc((size_t)f->width * f->height * 4);

		if (!fb) {
			pthread_mutex_unlock(&w->mu);
			return RDC_E_NOMEM;
		}
		free(w->fb);
		w->fb = fb;
		w->w = f->width;
		w->h = f->height;
		for (uint32_t y = 0; y < f->height; y++)
			memcpy(fb + (size_t)y * f->width,
			       f->xrgb + (size_t)y * f->stride, row);
		/* (no room for a viewer's damage: its thread tries again) */
		for (struct web_conn *c = w->conns; c; c = c->next)
			if (c->authed && conn_damage_size(w, c))
				conn_damage_all(w, c);
		changed = true;
	} else {
		for (uint32_t y = 0; y < f->height; y++) {
			const uint32_t *src = f->xrgb + (size_t)y * f->stride;
			uint32_t *dst = w->fb + (size_t)y * w->w;
			uint32_t x0 = 0, x1 = f->width;

			if (!memcmp(src, dst, row))
				continue;
			while (src[x0] == dst[x0])
				x0++;
			while (src[x1 - 1] == dst[x1 - 1])
				x1--;
			memcpy(dst + x0, src + x0, (x1 - x0) * sizeof(*dst));
			for (struct web_conn *c = w->conns; c; c = c->next) {
				if (!c->authed || c->dh != w->h)
					continue;
				if (!c->dx1[y]) {
					c->dx0[y] = x0;
					c->dx1[y] = x1;
				} else {
					c->dx0[y] = RDC_MIN(c->dx0[y], x0);
					c->dx1[y] = RDC_MAX(c->dx1[y], x1);
				}
				c->dirty = true;
			}
			changed = true;
		}
	}
	w->seq = f->seq;
	w->inum = f->interval_num;
	w->iden = f->interval_den;
	for (struct web_conn *c = w->conns; c; c = c->next)
		c->status_due = true;
	if (w->nviewers)
		web_wake(w);
	pthread_mutex_unlock(&w->mu);
	if (changed)
		s->st.written++;
	return 0;
}

static int web_status(rdc_sink *s, const struct rdc_sink_status *st)
{
	struct web_sink *w = s->priv;

	pthread_mutex_lock(&w->mu);
	w->st = *st;
	w->have_st = true;
	pthread_mutex_unlock(&w->mu);
	return 0;
}

static int web_url(const rdc_sink *s, char *buf, size_t len)
{
	const struct web_sink *w = s->priv;

	if ((size_t)snprintf(buf, len, "%s", w->url) >= len)
		return RDC_E_RANGE;
	return 0;
}

static void web_close(rdc_sink *s)
{
	struct web_sink *w = s->priv;

	if (!w)
		return;
	if (w->thr_started) {
		pthread_mutex_lock(&w->mu);
		w->stop = true;
		pthread_mutex_unlock(&w->mu);
		web_wake(w);
		pthread_join(w->thr, NULL);
	}
	if (w->lfd >= 0)
		close(w->lfd);
	if (w->wake_fd >= 0)
		close(w->wake_fd);
	pthread_mutex_destroy(&w->mu);
	free(w->fb);
	free(w->rgba);
	free(w->zbuf);
	memset(w->token, 0, sizeof(w->token));
	free(w);
	s->priv = NULL;
}

/* Listen on [ADDR:]PORT: PORT alone, as :PORT, is 127.0.0.1's. */
static int web_listen(struct web_sink *w, const char *spec)
{
	char hostport[RDC_TCP_HOST_MAX + 8], why[320], name[RDC_TCP_NAME_MAX];
	struct sockaddr_storage ss;
	int fd;

	if ((size_t)snprintf(hostport, sizeof(hostport), "%s%s",
			     strchr(spec, ':') ? "" : ":",
			     spec) >= sizeof(hostport))
		return rdc_err_detail(RDC_E_URI, "web sink: %.200s: too long",
				      spec);
	fd = rdc_tcp_listen(hostport, 16, &ss);
	if (fd < 0) {
		snprintf(why, sizeof(why), "%s", rdc_last_error_detail(fd));
		return rdc_err_detail(fd, "web sink: %s", why);
	}
	w->lfd = fd;
	w->loopback = rdc_tcp_is_loopback(&ss);
	if (!w->loopback && !w->have_token)
		return rdc_err_detail(RDC_E_AUTH,
				      "web sink: %s is not loopback: a token "
				      "is required (token=FILE; rdcd --token)",
				      spec);
	rdc_tcp_name(&ss, name);
	snprintf(w->url, sizeof(w->url), "http://%s/", name);
	return 0;
}

static int web_open(rdc_sink *s, const char *args)
{
	struct web_sink *w = calloc(1, sizeof(*w));
	char *dup = strdup(args), *cur, *key, *val;
	const char *token = NULL;
	int ret = 0;

	if (!w || !dup) {
		free(w);
		free(dup);
		return RDC_E_NOMEM;
	}
	w->lfd = w->wake_fd = -1;
	pthread_mutex_init(&w->mu, NULL);
	s->priv = w;
	cur = strchr(dup, ',');
	if (cur)
		*cur++ = '\0';
	while (!ret && (ret = rdc_sink_opt_next(&cur, &key, &val)) > 0) {
		ret = 0;
		if (!strcmp(key, "token") && *val)
			token = val;
		else
			ret = RDC_E_URI;
	}
	if (!ret && token) {
		ret = rdc_token_read("web sink: token", token, w->token,
				     &w->token_len);
		w->have_token = !ret;
	}
	if (!ret) {
		w->rgba = malloc(WEB_BAND_BYTES);
		if (!w->rgba)
			ret = RDC_E_NOMEM;
	}
	if (!ret)
		ret = web_listen(w, dup);
	if (!ret) {
		w->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
		if (w->wake_fd < 0)
			ret = rdc_err_detail(RDC_E_IO, "web sink: eventfd: %s",
					     strerror(errno));
	}
	if (!ret) {
		if (pthread_create(&w->thr, NULL, web_thread, w))
			ret = RDC_E_NOMEM;
		else
			w->thr_started = true;
	}
	free(dup);
	if (ret)
		web_close(s);
	return ret;
}

const struct rdc_sink_ops rdc_sink_web_ops = {
	.kind = "web",
	.open = web_open,
	.frame = web_frame,
	.status = web_status,
	.url = web_url,
	.close = web_close,
};
