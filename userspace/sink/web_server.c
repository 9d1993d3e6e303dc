// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web sink's server (web.h): a small HTTP server on its own thread
 * that serves the page (web/, built into the library: no file is ever
 * read at a client's request) and one WebSocket, /ws, whose viewers get
 * what the sink's side queues for them (rdc_web_pump) when their socket
 * has room, so a slow viewer gets fewer, larger updates and never holds
 * up the source.
 *
 * With a token every viewer must present it as its first message; failed
 * tokens from one address are refused for a while, as rdcd does.  A
 * loopback server only answers requests whose Host names loopback, and a
 * WebSocket only from its own page's origin, so another web site (or a
 * DNS name rebound to 127.0.0.1) cannot watch through the user's browser.
 * The parsers are web_proto.c's.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "web.h"

uint64_t rdc_web_now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

void rdc_web_wake(struct web_sink *w)
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

bool rdc_web_conn_send_raw(struct web_conn *c, const void *p, size_t n)
{
	return conn_queue(c, p, n);
}

bool rdc_web_conn_send(struct web_conn *c, uint8_t op, const void *p, size_t n)
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
	rdc_web_conn_send(c, WEB_WS_CLOSE, b, sizeof(b));
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
		c->sent_ns = rdc_web_now_ns();
	}
	c->out_off = c->out_len = 0;
	c->sent_ns = rdc_web_now_ns();
	if (c->closing)
		c->dead = true;
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
		c->deadline_ns = rdc_web_now_ns() + WEB_DEADLINE_NS;
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
	uint64_t now = rdc_web_now_ns();

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
	pthread_mutex_unlock(&w->mu);
	/* the whole picture first, then the log */
	c->snap = true;
	c->snap_gen = 0;
	c->since_ns = rdc_web_now_ns();
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
			rdc_web_conn_send(c, WEB_WS_PONG, p, (size_t)f.len);
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
		if (w->nconns - w->nviewers >= WEB_MAX_PENDING) {
			/* the oldest that is not watching yet makes room */
			for (c = w->conns; c; c = c->next)
				if (!c->authed)
					victim = c;
		} else if (w->nconns >= WEB_MAX_CONNS) {
			/*
			 * Every viewer's place is taken: a person opening the
			 * page still gets in.  The viewer stuck longest on a
			 * full socket makes room, else the one that has
			 * watched longest.
			 */
			uint64_t now = rdc_web_now_ns();

			for (c = w->conns; c; c = c->next)
				if (c->authed && c->out_off < c->out_len &&
				    now > c->sent_ns + WEB_DEADLINE_NS &&
				    (!victim || c->sent_ns < victim->sent_ns))
					victim = c;
			for (c = victim ? NULL : w->conns; c; c = c->next)
				if (c->authed &&
				    (!victim || c->since_ns < victim->since_ns))
					victim = c;
		}
		if (victim)
			conn_free(w, victim);
		c = calloc(1, sizeof(*c));
		if (!c) {
			close(fd);
			return;
		}
		setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
		c->fd = fd;
		c->sent_ns = rdc_web_now_ns();
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

void *rdc_web_serve(void *arg)
{
	struct web_sink *w = arg;
	struct pollfd pfd[2 + WEB_MAX_CONNS];
	struct web_conn *cl[WEB_MAX_CONNS];
	sigset_t all;

	sigfillset(&all);
	pthread_sigmask(SIG_BLOCK, &all, NULL);
	for (;;) {
		unsigned int n = 2, nc = 0;
		uint64_t now = rdc_web_now_ns(), next = UINT64_MAX;
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
				rdc_web_pump(w, c, now);
			if (c->out_off < c->out_len)
				conn_flush(c);
			if (c->dead)
				conn_free(w, c); /* a last answer went */
		}
		for (struct web_conn *c = w->conns; c; c = c->next) {
			if (!c->authed && !c->closing)
				next = RDC_MIN(next, c->deadline_ns);
			if (c->authed && !c->closing &&
			    c->out_off == c->out_len)
				next = RDC_MIN(next, rdc_web_next(w, c));
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
		if (poll(pfd, n, tmo) < 0 && errno != EINTR)
			break;
		if (pfd[0].revents & POLLIN) {
			uint64_t v;

			if (read(w->wake_fd, &v, sizeof(v)) < 0) {
				/* EAGAIN: nothing */
			}
		}
		now = rdc_web_now_ns();
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
