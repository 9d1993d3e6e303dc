// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web sink: its HTTP and WebSocket parsers against the RFCs' own
 * examples and against malformed input, and the live server seen by a
 * minimal WebSocket client written from RFC 6455: the first update is
 * the whole frame, pixel for pixel; an unchanged frame sends no pixels;
 * a change sends the changed rectangle only; only the page's own paths
 * are answered; hostile requests and frames get an error and the server
 * goes on serving; the token rule holds.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <setjmp.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cmocka.h>

#include "rdc_sink.h"
#include "web_proto.h"

/* How long one read may wait before the test fails: a bound, not a
 * measurement (a loaded host under ASan). */
#define WAIT_MS 60000
#define FW	64
#define FH	48

/* ---- Pure parts ------------------------------------------------------ */

static void hex(const uint8_t *p, size_t n, char *out)
{
	for (size_t i = 0; i < n; i++)
		sprintf(out + 2 * i, "%02x", p[i]);
}

static void test_sha1(void **state)
{
	static const struct {
		const char *in, *out;
	} v[] = {
		/* FIPS 180-2 appendix A and B, and the empty string */
		{ "abc", "a9993e364706816aba3e25717850c26c9cd0d89d" },
		{ "", "da39a3ee5e6b4b0d3255bfef95601890afd80709" },
		{ "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq",
		  "84983e441c3bd26ebaae4aa1f95129e5e54670f1" },
	};
	uint8_t sum[20];
	char h[41];

	(void)state;
	for (size_t i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
		rdc_web_sha1(v[i].in, strlen(v[i].in), sum);
		hex(sum, sizeof(sum), h);
		assert_string_equal(h, v[i].out);
	}
}

static void test_base64_accept(void **state)
{
	static const char *const v[][2] = {
		/* RFC 4648, section 10 */
		{ "f", "Zg==" },	 { "fo", "Zm8=" },
		{ "foo", "Zm9v" },	 { "foob", "Zm9vYg==" },
		{ "fooba", "Zm9vYmE=" }, { "foobar", "Zm9vYmFy" },
	};
	char out[16], acc[WEB_WS_ACCEPT_SZ];

	(void)state;
	for (size_t i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
		rdc_web_base64((const uint8_t *)v[i][0], strlen(v[i][0]), out);
		assert_string_equal(out, v[i][1]);
	}
	/* RFC 6455, section 1.3 */
	assert_true(rdc_web_ws_key_ok("dGhlIHNhbXBsZSBub25jZQ=="));
	rdc_web_ws_accept("dGhlIHNhbXBsZSBub25jZQ==", acc);
	assert_string_equal(acc, "s3pPLMBiTxaQ9kYGzzhZRbK+xOo=");
	assert_false(rdc_web_ws_key_ok("dGhlIHNhbXBsZSBub25jZQ="));
	assert_false(rdc_web_ws_key_ok("dGhlIHNhbXBsZSBub25jZR=="));
	assert_false(rdc_web_ws_key_ok("dGhlIHNhbXBsZSBub25j*Q=="));
}

static const char good_req[] = "GET /ws?x=1 HTTP/1.1\r\n"
			       "Host: 127.0.0.1:8080\r\n"
			       "Upgrade: websocket\r\n"
			       "Connection: keep-alive, Upgrade\r\n"
			       "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
			       "Origin: http://127.0.0.1:8080\r\n"
			       "Sec-WebSocket-Version: 13\r\n"
			       "\r\n";

static void test_req_parse(void **state)
{
	struct web_req r;
	size_t used = 0, n = strlen(good_req);

	(void)state;
	assert_int_equal(rdc_web_req_parse(good_req, n, &r, &used), WEB_REQ_OK);
	assert_int_equal(used, n);
	assert_string_equal(r.method, "GET");
	assert_string_equal(r.path, "/ws");
	assert_string_equal(r.host, "127.0.0.1:8080");
	assert_string_equal(r.origin, "http://127.0.0.1:8080");
	assert_string_equal(r.key, "dGhlIHNhbXBsZSBub25jZQ==");
	assert_true(r.upgrade_ws && r.conn_upgrade && r.has_key);
	assert_int_equal(r.ws_version, 13);
	/* every prefix is "more" */
	for (size_t k = 0; k < n; k++)
		assert_int_equal(rdc_web_req_parse(good_req, k, &r, &used),
				 WEB_REQ_MORE);
}

static void test_req_parse_bad(void **state)
{
	static const struct {
		const char *req;
		int want;
	} v[] = {
		{ "GET / HTTP/1.1\nHost: a\n\n", WEB_REQ_BAD },
		{ "GET / HTTP/1.1\r\nHost: a\r\n b\r\n\r\n", WEB_REQ_BAD },
		{ "GET / HTTP/1.1\r\nHost: a\r\nHost: b\r\n\r\n", WEB_REQ_BAD },
		{ "get / HTTP/1.1\r\n\r\n", WEB_REQ_BAD },
		{ "GET x HTTP/1.1\r\n\r\n", WEB_REQ_BAD },
		{ "GET / HTTP/2.0\r\n\r\n", WEB_REQ_BAD },
		{ "GET /  HTTP/1.1\r\n\r\n", WEB_REQ_BAD },
		{ "GET / HTTP/1.1\r\nBad Name: x\r\n\r\n", WEB_REQ_BAD },
		{ "GET / HTTP/1.1\r\nX: a\rb\r\n\r\n", WEB_REQ_BAD },
		{ "GET / HTTP/1.1\r\nX: a\x01\r\n\r\n", WEB_REQ_BAD },
		{ "GET / HTTP/1.1\r\n: x\r\n\r\n", WEB_REQ_BAD },
		{ "\r\n\r\n", WEB_REQ_BAD },
		{ "GETTINGLONG / HTTP/1.1\r\n\r\n", WEB_REQ_BAD },
	};
	struct web_req r;
	size_t used;
	char *big;

	(void)state;
	for (size_t i = 0; i < sizeof(v) / sizeof(v[0]); i++)
		assert_int_equal(rdc_web_req_parse(v[i].req, strlen(v[i].req),
						   &r, &used),
				 v[i].want);
	/* a NUL inside */
	assert_int_equal(rdc_web_req_parse("GET /\0 HTTP/1.1\r\n\r\n", 20, &r,
					   &used),
			 WEB_REQ_BAD);
	/* a head that never ends, a Host and a path too long to keep */
	big = malloc(WEB_HDR_MAX + 64);
	assert_non_null(big);
	memset(big, 'a', WEB_HDR_MAX + 64);
	memcpy(big, "GET / HTTP/1.1\r\nX: ", 19);
	assert_int_equal(rdc_web_req_parse(big, WEB_HDR_MAX + 64, &r, &used),
			 WEB_REQ_TOO_BIG);
	memset(big, 'a', WEB_HDR_MAX + 64);
	memcpy(big, "GET / HTTP/1.1\r\nHost: ", 22);
	memcpy(big + 22 + WEB_FIELD_MAX, "\r\n\r\n", 4);
	assert_int_equal(rdc_web_req_parse(big, 26 + WEB_FIELD_MAX, &r, &used),
			 WEB_REQ_TOO_BIG);
	memset(big, 'a', WEB_HDR_MAX + 64);
	memcpy(big, "GET /", 5);
	memcpy(big + 5 + WEB_PATH_MAX, " HTTP/1.1\r\n\r\n", 13);
	assert_int_equal(rdc_web_req_parse(big, 18 + WEB_PATH_MAX, &r, &used),
			 WEB_REQ_TOO_BIG);
	free(big);
}

static void test_ws_parse(void **state)
{
	/* RFC 6455, section 5.7: a masked "Hello" */
	uint8_t hello[] = { 0x81, 0x85, 0x37, 0xfa, 0x21, 0x3d,
			    0x7f, 0x9f, 0x4d, 0x51, 0x58 };
	static const struct {
		uint8_t b[14];
		size_t n;
		int want;
	} v[] = {
		{ { 0x81, 0x05, 'H' },
		  3,
		  -WEB_WS_CLOSE_PROTOCOL }, /* unmasked */
		{ { 0xc1, 0x80, 0, 0, 0, 0 }, 6, -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x83, 0x80, 0, 0, 0, 0 }, 6, -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x09, 0x80, 0, 0, 0, 0 }, 6, -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x89, 0xfe, 0, 126, 0, 0, 0, 0 },
		  8,
		  -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x82, 0xfe, 0, 125, 0, 0, 0, 0 },
		  8,
		  -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x82, 0xff, 0x80, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
		  14,
		  -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x82, 0xff, 0, 0, 0, 0, 0, 0, 0xff, 0xff, 0, 0, 0, 0 },
		  14,
		  -WEB_WS_CLOSE_PROTOCOL },
		{ { 0x82, 0xff, 0, 0, 0, 0x10, 0, 0, 0, 0, 0, 0, 0, 0 },
		  14,
		  -WEB_WS_CLOSE_TOO_BIG },
		{ { 0x82, 0xfe, 0x10, 0, 0, 0, 0, 0 },
		  8,
		  -WEB_WS_CLOSE_TOO_BIG },
		{ { 0x82, 0xfe, 0x10 }, 3, 0 },
		{ { 0x82 }, 1, 0 },
	};
	struct web_ws_frame f;

	(void)state;
	for (size_t k = 0; k < 6; k++)
		assert_int_equal(rdc_web_ws_parse(hello, k, 1024, &f), 0);
	assert_int_equal(rdc_web_ws_parse(hello, sizeof(hello), 1024, &f), 1);
	assert_true(f.fin);
	assert_int_equal(f.opcode, WEB_WS_TEXT);
	assert_int_equal(f.len, 5);
	assert_int_equal(f.hdr_len, 6);
	rdc_web_ws_unmask(hello + 6, 5, f.mask, 0);
	assert_memory_equal(hello + 6, "Hello", 5);
	for (size_t i = 0; i < sizeof(v) / sizeof(v[0]); i++)
		assert_int_equal(rdc_web_ws_parse(v[i].b, v[i].n, 1024, &f),
				 v[i].want);
}

static void test_page_paths(void **state)
{
	static const char *const no[] = {
		"/..",	       "/../web/index.html",
		"/web/",       "/web/rdc.js",
		"/index.htm",  "//rdc.js",
		"/rdc.js/",    "/RDC.JS",
		"/etc/passwd", "",
	};
	struct web_file f;

	(void)state;
	assert_true(rdc_web_page_find("/", &f));
	assert_non_null(memmem(f.data, f.len, "<canvas", 7));
	assert_true(rdc_web_page_find("/index.html", &f));
	assert_true(rdc_web_page_find("/rdc.js", &f));
	assert_non_null(memmem(f.data, f.len, "WebSocket", 9));
	assert_true(rdc_web_page_find("/rdc.css", &f));
	for (size_t i = 0; i < sizeof(no) / sizeof(no[0]); i++)
		assert_false(rdc_web_page_find(no[i], &f));
}

/* ---- A client ------------------------------------------------------- */

static int web_port(rdc_sink *s)
{
	char url[128];
	const char *colon;

	assert_int_equal(rdc_sink_url(s, url, sizeof(url)), 0);
	assert_true(!strncmp(url, "http://127.0.0.1:", 17));
	colon = strrchr(url, ':');
	return atoi(colon + 1);
}

static int tcp_connect(int port)
{
	struct sockaddr_in a = { .sin_family = AF_INET,
				 .sin_port = htons((uint16_t)port) };
	int fd = socket(AF_INET, SOCK_STREAM, 0);

	assert_true(fd >= 0);
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	assert_int_equal(connect(fd, (struct sockaddr *)&a, sizeof(a)), 0);
	return fd;
}

static void tx(int fd, const void *p, size_t n)
{
	assert_int_equal(send(fd, p, n, MSG_NOSIGNAL), (ssize_t)n);
}

/* Read exactly n bytes; false at the end of the stream. */
static bool rx(int fd, void *buf, size_t n)
{
	uint8_t *p = buf;

	while (n) {
		struct pollfd pfd = { .fd = fd, .events = POLLIN };
		ssize_t got;

		assert_int_equal(poll(&pfd, 1, WAIT_MS), 1);
		got = recv(fd, p, n, 0);
		if (got <= 0)
			return false;
		p += got;
		n -= (size_t)got;
	}
	return true;
}

/* Everything until the server closes: an HTTP answer. */
static size_t rx_all(int fd, char *buf, size_t cap)
{
	size_t n = 0;

	for (;;) {
		struct pollfd pfd = { .fd = fd, .events = POLLIN };
		ssize_t got;

		assert_int_equal(poll(&pfd, 1, WAIT_MS), 1);
		got = recv(fd, buf + n, cap - 1 - n, 0);
		if (got <= 0)
			break;
		n += (size_t)got;
		assert_true(n < cap - 1);
	}
	buf[n] = '\0';
	return n;
}

static void http(int port, const char *req, char *buf, size_t cap)
{
	int fd = tcp_connect(port);

	tx(fd, req, strlen(req));
	rx_all(fd, buf, cap);
	close(fd);
}

static void ws_handshake(int fd, int port, const char *origin)
{
	char req[512], head[1024];
	size_t n = 0;

	snprintf(req, sizeof(req),
		 "GET /ws HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n"
		 "Upgrade: websocket\r\nConnection: Upgrade\r\n"
		 "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
		 "Sec-WebSocket-Version: 13\r\nOrigin: %s\r\n\r\n",
		 port, origin);
	tx(fd, req, strlen(req));
	/* byte by byte to the blank line: a frame may follow at once */
	while (n < 4 || memcmp(head + n - 4, "\r\n\r\n", 4)) {
		assert_true(n < sizeof(head) - 1);
		assert_true(rx(fd, head + n, 1));
		n++;
	}
	head[n] = '\0';
	assert_non_null(strstr(head, "HTTP/1.1 101 "));
	assert_non_null(strstr(
		head, "Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo="));
}

static int ws_open(int port, const char *token)
{
	char origin[64];
	int fd = tcp_connect(port);

	snprintf(origin, sizeof(origin), "http://127.0.0.1:%d", port);
	ws_handshake(fd, port, origin);
	/* a client's frame: masked */
	{
		uint8_t f[6 + 64] = { 0x81, (uint8_t)(0x80 | strlen(token)),
				      1,    2,
				      3,    4 };
		size_t n = strlen(token);

		assert_true(n < 64);
		for (size_t i = 0; i < n; i++)
			f[6 + i] = (uint8_t)token[i] ^ f[2 + (i & 3)];
		tx(fd, f, 6 + n);
	}
	return fd;
}

/* One server frame; its payload (malloc'd) and length.  -1 at the end
 * of the stream. */
static int ws_recv(int fd, uint8_t **payload, size_t *len)
{
	uint8_t h[10];
	uint64_t n;

	if (!rx(fd, h, 2))
		return -1;
	assert_int_equal(h[0] & 0xf0, 0x80); /* final, no extension */
	assert_int_equal(h[1] & 0x80, 0);    /* a server does not mask */
	n = h[1] & 0x7f;
	if (n == 126) {
		assert_true(rx(fd, h + 2, 2));
		n = (uint64_t)h[2] << 8 | h[3];
	} else if (n == 127) {
		assert_true(rx(fd, h + 2, 8));
		n = 0;
		for (int i = 0; i < 8; i++)
			n = n << 8 | h[2 + i];
	}
	assert_true(n < (64u << 20));
	*payload = malloc(n + 1);
	assert_non_null(*payload);
	assert_true(rx(fd, *payload, (size_t)n));
	(*payload)[n] = '\0';
	*len = (size_t)n;
	return h[0] & 0x0f;
}

static uint32_t get32(const uint8_t *p)
{
	return p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	       (uint32_t)p[3] << 24;
}

struct view {
	uint32_t px[FW * FH];
	uint32_t rect[4]; /* the last rectangle */
	unsigned int rects;
};

/* Apply one rectangle message to the view. */
static void view_rect(struct view *v, const uint8_t *p, size_t n)
{
	uLongf raw;
	uint8_t *rgba;

	assert_true(n >= 20);
	assert_int_equal(get32(p), 1);
	for (int i = 0; i < 4; i++)
		v->rect[i] = get32(p + 4 + 4 * i);
	assert_true(v->rect[0] + v->rect[2] <= FW);
	assert_true(v->rect[1] + v->rect[3] <= FH);
	raw = (uLongf)v->rect[2] * v->rect[3] * 4;
	rgba = malloc(raw);
	assert_non_null(rgba);
	assert_int_equal(uncompress(rgba, &raw, p + 20, n - 20), Z_OK);
	assert_int_equal(raw, (uLongf)v->rect[2] * v->rect[3] * 4);
	for (uint32_t y = 0; y < v->rect[3]; y++)
		for (uint32_t x = 0; x < v->rect[2]; x++) {
			const uint8_t *q = rgba + 4 * (y * v->rect[2] + x);

			assert_int_equal(q[3], 0xff);
			v->px[(v->rect[1] + y) * FW + v->rect[0] + x] =
				(uint32_t)q[0] << 16 | (uint32_t)q[1] << 8 |
				q[2];
		}
	free(rgba);
	v->rects++;
}

/* Read until the status that says frame `seq` is drawn whole. */
static void view_sync(struct view *v, int fd, uint64_t seq)
{
	char want[64];

	snprintf(want, sizeof(want), "\"seq\":%llu,", (unsigned long long)seq);
	v->rects = 0;
	for (;;) {
		uint8_t *p;
		size_t n;
		int op = ws_recv(fd, &p, &n);

		assert_true(op > 0);
		if (op == WEB_WS_BINARY)
			view_rect(v, p, n);
		else
			assert_int_equal(op, WEB_WS_TEXT);
		if (op == WEB_WS_TEXT && strstr((char *)p, want) && v->rects) {
			free(p);
			return;
		}
		free(p);
	}
}

static void frame_init(uint32_t *px, uint32_t seed)
{
	for (int i = 0; i < FW * FH; i++) {
		seed = seed * 1103515245u + 12345u;
		px[i] = (seed >> 8) & 0xffffff;
	}
}

static void feed(rdc_sink *s, const uint32_t *px, uint64_t seq)
{
	struct rdc_frame f = { .xrgb = px,
			       .width = FW,
			       .height = FH,
			       .stride = FW,
			       .seq = seq,
			       .interval_num = 1,
			       .interval_den = 60 };

	assert_int_equal(rdc_sink_frame(s, &f), 0);
}

static void test_live(void **state)
{
	static uint32_t a[FW * FH], b[FW * FH];
	static struct view v;
	struct rdc_sink_status st = { .size = sizeof(st),
				      .have = RDC_SINK_HAVE_PINS |
					      RDC_SINK_HAVE_TIME,
				      .pins = 0xd,
				      .time = 12345,
				      .core_hz = 100000000 };
	rdc_sink *s;
	uint8_t *p;
	size_t n;
	int fd, op;

	(void)state;
	assert_int_equal(rdc_sink_open("web:0", &s), 0);
	assert_string_equal(rdc_sink_kind(s), "web");
	assert_int_equal(rdc_sink_have_web(), 1);
	frame_init(a, 1);
	assert_int_equal(rdc_sink_status_set(s, &st), 0);
	feed(s, a, 10);
	fd = ws_open(web_port(s), "");
	/* the first message says the size, before any pixel */
	op = ws_recv(fd, &p, &n);
	assert_int_equal(op, WEB_WS_TEXT);
	assert_non_null(strstr((char *)p, "\"width\":64,\"height\":48"));
	assert_non_null(strstr((char *)p, "\"pins\":13"));
	assert_non_null(strstr((char *)p, "\"time\":12345"));
	free(p);
	memset(v.px, 0xee, sizeof(v.px));
	view_sync(&v, fd, 10);
	assert_memory_equal(v.px, a, sizeof(a));

	/* the same picture again, then a change in two rows */
	memcpy(b, a, sizeof(b));
	feed(s, b, 11);
	for (int x = 5; x < 10; x++)
		b[10 * FW + x] ^= 0x00ff00;
	b[11 * FW + 7] ^= 0x0000ff;
	feed(s, b, 12);
	view_sync(&v, fd, 12);
	assert_memory_equal(v.px, b, sizeof(b));
	/* only the damage went: one rectangle, x 5..9, rows 10..11 */
	assert_int_equal(v.rects, 1);
	assert_int_equal(v.rect[0], 5);
	assert_int_equal(v.rect[1], 10);
	assert_int_equal(v.rect[2], 5);
	assert_int_equal(v.rect[3], 2);
	close(fd);
	rdc_sink_close(s);
}

static void test_http(void **state)
{
	static const struct {
		const char *req, *want;
	} v[] = {
		{ "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", "200 OK" },
		{ "GET /index.html HTTP/1.1\r\nHost: localhost:1\r\n\r\n",
		  "200 OK" },
		{ "GET /rdc.js HTTP/1.1\r\nHost: [::1]:1\r\n\r\n", "200 OK" },
		{ "GET /rdc.css HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n",
		  "200 OK" },
		/* no Host at all: nothing says it is meant for loopback */
		{ "GET /rdc.css HTTP/1.0\r\n\r\n", "403 " },
		{ "GET /../../etc/passwd HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
		  "404 " },
		{ "GET /web/ HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", "404 " },
		{ "POST / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", "405 " },
		{ "GET / HTTP/1.1\r\n\r\n", "400 " },
		/* DNS rebinding: a name that is not loopback */
		{ "GET / HTTP/1.1\r\nHost: evil.example:1\r\n\r\n", "403 " },
		{ "GET / HTTP/1.1\r\nHost: 127.0.0.1.evil.example\r\n\r\n",
		  "403 " },
		/* another site's page opening the WebSocket */
		{ "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket"
		  "\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
		  "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
		  "Origin: http://evil.example\r\n\r\n",
		  "403 " },
		{ "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", "400 " },
		{ "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket"
		  "\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 8\r\n"
		  "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n",
		  "426 " },
		/* a TLS ClientHello's first bytes (no NUL: strlen) */
		{ "\x16\x03\x01\x02\x01\x01\xfc\x03\x03\r\n\r\n", "400 " },
	};
	static char buf[1 << 16];
	rdc_sink *s;
	int port;

	(void)state;
	assert_int_equal(rdc_sink_open("web:127.0.0.1:0", &s), 0);
	port = web_port(s);
	for (size_t i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
		http(port, v[i].req, buf, sizeof(buf));
		if (!strstr(buf, v[i].want))
			fail_msg("%s: got '%.80s', want '%s'", v[i].req, buf,
				 v[i].want);
	}
	http(port, "HEAD / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", buf,
	     sizeof(buf));
	assert_non_null(strstr(buf, "200 OK"));
	assert_null(strstr(buf, "<canvas"));
	assert_non_null(strstr(buf, "Content-Security-Policy: "));
	rdc_sink_close(s);
}

/* Wait for the server's close frame; its code. */
static unsigned int ws_close_code(int fd)
{
	for (;;) {
		uint8_t *p;
		size_t n;
		int op = ws_recv(fd, &p, &n);
		unsigned int code;

		assert_true(op > 0);
		if (op != WEB_WS_CLOSE) {
			free(p);
			continue;
		}
		assert_int_equal(n, 2);
		code = (unsigned int)p[0] << 8 | p[1];
		free(p);
		return code;
	}
}

static void test_hostile(void **state)
{
	static uint32_t a[FW * FH];
	static struct view v;
	static char buf[1 << 16];
	static uint8_t junk[WEB_HDR_MAX + 100];
	int conns[20], port, fd, watcher;
	rdc_sink *s;

	(void)state;
	assert_int_equal(rdc_sink_open("web:0", &s), 0);
	port = web_port(s);
	frame_init(a, 7);
	feed(s, a, 1);
	watcher = ws_open(port, "");
	view_sync(&v, watcher, 1);

	/* a head that never ends */
	memset(junk, 'x', sizeof(junk));
	memcpy(junk, "GET / HTTP/1.1\r\n", 16);
	fd = tcp_connect(port);
	tx(fd, junk, sizeof(junk));
	rx_all(fd, buf, sizeof(buf));
	assert_non_null(strstr(buf, "431 "));
	close(fd);

	/* an unmasked frame, a huge one, a fragmented ping, a bad opcode */
	{
		static const uint8_t bad[][14] = {
			{ 0x81, 0x01, 'x' },
			{ 0x82, 0xff, 0, 0, 1, 0, 0, 0, 0, 0, 1, 2, 3, 4 },
			{ 0x09, 0x80, 1, 2, 3, 4 },
			{ 0x8b, 0x80, 1, 2, 3, 4 },
		};
		static const size_t len[] = { 3, 14, 6, 6 };
		static const unsigned int code[] = { WEB_WS_CLOSE_PROTOCOL,
						     WEB_WS_CLOSE_TOO_BIG,
						     WEB_WS_CLOSE_PROTOCOL,
						     WEB_WS_CLOSE_PROTOCOL };

		for (size_t i = 0; i < 4; i++) {
			fd = ws_open(port, "");
			tx(fd, bad[i], len[i]);
			assert_int_equal(ws_close_code(fd), code[i]);
			close(fd);
		}
	}
	/* a message over the cap, in continuation frames */
	fd = ws_open(port, "");
	{
		uint8_t f[6 + 125] = { 0x01, 0x80 | 125, 0, 0, 0, 0 };

		tx(fd, f, sizeof(f));
		f[0] = 0x00;
		for (int i = 0; i < 8; i++)
			tx(fd, f, sizeof(f));
	}
	assert_int_equal(ws_close_code(fd), WEB_WS_CLOSE_TOO_BIG);
	close(fd);

	/* more silent connections than the server keeps: the oldest go, a
	 * new viewer and the one watching all along still get pictures */
	for (int i = 0; i < 20; i++)
		conns[i] = tcp_connect(port);
	fd = ws_open(port, "");
	a[0] ^= 0xffffff;
	feed(s, a, 2);
	memset(v.px, 0, sizeof(v.px));
	view_sync(&v, fd, 2);
	assert_memory_equal(v.px, a, sizeof(a));
	view_sync(&v, watcher, 2);
	assert_memory_equal(v.px, a, sizeof(a));
	for (int i = 0; i < 20; i++)
		close(conns[i]);
	close(fd);
	close(watcher);
	rdc_sink_close(s);
}

/*
 * 200 viewers watch, and the 201st still gets in and gets the picture;
 * a change then reaches every one of them (before: 16 viewers took every
 * place, and the 17th was closed before its upgrade).
 */
#define MANY_VIEWERS 200

static void test_many_viewers(void **state)
{
	static uint32_t a[FW * FH], b[FW * FH];
	static int fds[MANY_VIEWERS + 1];
	static struct view v;
	rdc_sink *s;
	int port;

	(void)state;
	assert_int_equal(rdc_sink_open("web:0", &s), 0);
	port = web_port(s);
	frame_init(a, 7);
	feed(s, a, 1);
	for (int i = 0; i <= MANY_VIEWERS; i++) {
		fds[i] = ws_open(port, "");
		memset(v.px, 0, sizeof(v.px));
		view_sync(&v, fds[i], 1);
		assert_memory_equal(v.px, a, sizeof(a));
	}
	memcpy(b, a, sizeof(b));
	for (int x = 3; x < 9; x++)
		a[20 * FW + x] ^= 0xffffff;
	feed(s, a, 2);
	for (int i = 0; i <= MANY_VIEWERS; i++) {
		memcpy(v.px, b, sizeof(v.px));
		view_sync(&v, fds[i], 2);
		assert_memory_equal(v.px, a, sizeof(a));
		close(fds[i]);
	}
	rdc_sink_close(s);
}

static void test_token(void **state)
{
	static uint32_t a[FW * FH];
	static struct view v;
	char path[] = "/tmp/rdc-web-token-XXXXXX", spec[128], url[128];
	int tfd = mkstemp(path), fd, port;
	rdc_sink *s;

	(void)state;
	assert_true(tfd >= 0);
	assert_int_equal(write(tfd, "s3cret\n", 7), 7);
	close(tfd);

	/* not loopback: a token is required */
	assert_int_equal(rdc_sink_open("web:0.0.0.0:0", &s), RDC_E_AUTH);
	snprintf(spec, sizeof(spec), "web:0.0.0.0:0,token=%s", path);
	assert_int_equal(rdc_sink_open(spec, &s), 0);
	assert_int_equal(rdc_sink_url(s, url, sizeof(url)), 0);
	assert_true(!strncmp(url, "http://0.0.0.0:", 15));
	rdc_sink_close(s);

	snprintf(spec, sizeof(spec), "web:0,token=%s", path);
	assert_int_equal(rdc_sink_open(spec, &s), 0);
	port = web_port(s);
	frame_init(a, 3);
	feed(s, a, 5);
	fd = ws_open(port, "wrong");
	assert_int_equal(ws_close_code(fd), WEB_WS_CLOSE_AUTH);
	close(fd);
	fd = ws_open(port, "");
	assert_int_equal(ws_close_code(fd), WEB_WS_CLOSE_AUTH);
	close(fd);
	fd = ws_open(port, "s3cret");
	view_sync(&v, fd, 5);
	assert_memory_equal(v.px, a, sizeof(a));
	close(fd);
	rdc_sink_close(s);
	unlink(path);
}

static void test_specs(void **state)
{
	static const char *const bad[] = {
		"web:",	       "web:x",	       "web:70000", "web:1.2.3.4.5:80",
		"web:0,foo=1", "web:0,token=", "web::x",
	};
	char path[64], fifo[64], spec[128];
	rdc_sink *s;
	FILE *f;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		assert_int_not_equal(rdc_sink_open(bad[i], &s), 0);
	assert_int_equal(rdc_sink_open("web:0,token=/nonexistent/rdc-token",
				       &s),
			 RDC_E_FILE);

	/* :PORT is 127.0.0.1, as rdcd's tcp::PORT (it was refused) */
	assert_int_equal(rdc_sink_open("web::0", &s), 0);
	web_port(s);
	rdc_sink_close(s);

	/*
	 * The token file's rule is rdcd's: a directory is refused by what
	 * it is (it was "empty"), a FIFO at once (it waited for a writer),
	 * a file too long naming it.
	 */
	assert_int_equal(rdc_sink_open("web:0,token=/tmp", &s), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "token /tmp: a directory, not a regular file"));
	snprintf(fifo, sizeof(fifo), "/tmp/rdc-web-fifo-%d", (int)getpid());
	unlink(fifo);
	assert_int_equal(mkfifo(fifo, 0600), 0);
	snprintf(spec, sizeof(spec), "web:0,token=%s", fifo);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "a FIFO, not a regular file"));
	unlink(fifo);
	snprintf(path, sizeof(path), "/tmp/rdc-web-long-%d", (int)getpid());
	f = fopen(path, "w");
	assert_non_null(f);
	for (int i = 0; i < 257; i++)
		fputc('a', f);
	fclose(f);
	snprintf(spec, sizeof(spec), "web:0,token=%s", path);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), path));
	unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sha1),
		cmocka_unit_test(test_base64_accept),
		cmocka_unit_test(test_req_parse),
		cmocka_unit_test(test_req_parse_bad),
		cmocka_unit_test(test_ws_parse),
		cmocka_unit_test(test_page_paths),
		cmocka_unit_test(test_live),
		cmocka_unit_test(test_http),
		cmocka_unit_test(test_hostile),
		cmocka_unit_test(test_many_viewers),
		cmocka_unit_test(test_token),
		cmocka_unit_test(test_specs),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
