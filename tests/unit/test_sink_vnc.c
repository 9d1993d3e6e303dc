// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The vnc sink seen by a minimal RFB 3.8 client written from RFC 6143:
 * the first update carries the whole frame, pixel for pixel; after a
 * change to a few rows, the next incremental update covers those rows
 * only.  Without libvncserver the sink must say RDC_E_NOSYS.
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
#include <unistd.h>

#include <cmocka.h>

#include "rdc_sink.h"

#define VW 40
#define VH 30
/* Each step lets the server run once and waits a little for its bytes:
 * a bound on the exchange, not a timing check. */
#define PUMP_STEPS   2000
#define PUMP_WAIT_MS 5

#define RFB_SEC_NONE	       1
#define RFB_MSG_SET_ENCODINGS  2
#define RFB_MSG_UPDATE_REQUEST 3
#define RFB_ENC_RAW	       0

struct vc {
	rdc_sink *s;
	int fd;
};

/* A TCP port nobody listens on right now. */
static int free_port(void)
{
	struct sockaddr_in a = { .sin_family = AF_INET };
	socklen_t len = sizeof(a);
	int fd = socket(AF_INET, SOCK_STREAM, 0), port;

	assert_true(fd >= 0);
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	assert_int_equal(bind(fd, (struct sockaddr *)&a, sizeof(a)), 0);
	assert_int_equal(getsockname(fd, (struct sockaddr *)&a, &len), 0);
	port = ntohs(a.sin_port);
	close(fd);
	return port;
}

static void rx(struct vc *c, void *buf, size_t n)
{
	uint8_t *p = buf;

	for (int i = 0; n && i < PUMP_STEPS; i++) {
		struct pollfd pfd = { .fd = c->fd, .events = POLLIN };
		ssize_t got;

		assert_int_equal(rdc_sink_poll(c->s), 0);
		if (poll(&pfd, 1, PUMP_WAIT_MS) <= 0)
			continue;
		got = recv(c->fd, p, n, 0);
		assert_true(got > 0);
		p += got;
		n -= (size_t)got;
	}
	assert_int_equal(n, 0);
}

static void tx(struct vc *c, const void *buf, size_t n)
{
	assert_int_equal(send(c->fd, buf, n, 0), (ssize_t)n);
}

static uint32_t be32(const uint8_t *b)
{
	return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 |
	       (uint32_t)b[2] << 8 | b[3];
}

static uint16_t be16(const uint8_t *b)
{
	return (uint16_t)(b[0] << 8 | b[1]);
}

static void request(struct vc *c, int incremental)
{
	uint8_t m[10] = { RFB_MSG_UPDATE_REQUEST,
			  (uint8_t)incremental,
			  0,
			  0,
			  0,
			  0,
			  0,
			  VW,
			  0,
			  VH };

	tx(c, m, sizeof(m));
}

/*
 * Read one FramebufferUpdate of raw rectangles into fb (VW x VH, pixels
 * decoded with the server's format); returns the lowest and highest row
 * any rectangle touched.
 */
static void read_update(struct vc *c, uint32_t *fb, const uint8_t *pf,
			uint32_t *ymin, uint32_t *ymax)
{
	uint8_t hdr[4], r[12];
	unsigned rs = pf[10], gs = pf[11], bs = pf[12];

	rx(c, hdr, sizeof(hdr));
	assert_int_equal(hdr[0], 0); /* FramebufferUpdate */
	*ymin = UINT32_MAX;
	*ymax = 0;
	for (unsigned i = 0; i < be16(hdr + 2); i++) {
		uint32_t x, y, w, h;

		rx(c, r, sizeof(r));
		x = be16(r), y = be16(r + 2), w = be16(r + 4), h = be16(r + 6);
		assert_int_equal(be32(r + 8), RFB_ENC_RAW);
		assert_true(x + w <= VW && y + h <= VH);
		for (uint32_t yy = y; yy < y + h; yy++) {
			for (uint32_t xx = x; xx < x + w; xx++) {
				uint8_t p[4];
				uint32_t v;

				rx(c, p, 4);
				/* 32 bpp, little-endian as declared */
				assert_int_equal(pf[2], 0);
				v = (uint32_t)p[0] | (uint32_t)p[1] << 8 |
				    (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
				fb[yy * VW + xx] = ((v >> rs) & 0xff) << 16 |
						   ((v >> gs) & 0xff) << 8 |
						   ((v >> bs) & 0xff);
			}
		}
		if (h && y < *ymin)
			*ymin = y;
		if (h && y + h - 1 > *ymax)
			*ymax = y + h - 1;
	}
}

static void test_vnc_updates(void **state)
{
	static uint32_t px[VW * VH], seen[VW * VH];
	struct rdc_frame f = {
		.xrgb = px, .width = VW, .height = VH, .stride = VW, .seq = 0
	};
	struct sockaddr_in a = { .sin_family = AF_INET };
	uint8_t ver[12], b[64], pf[16];
	uint8_t enc[8] = {
		RFB_MSG_SET_ENCODINGS, 0, 0, 1, 0, 0, 0, RFB_ENC_RAW
	};
	uint32_t ymin, ymax, n;
	char spec[32];
	struct vc c;
	int port;

	(void)state;
	if (!rdc_sink_have_vnc()) {
		rdc_sink *s = NULL;

		assert_int_equal(rdc_sink_open("vnc:5999", &s), RDC_E_NOSYS);
		skip();
	}
	for (uint32_t i = 0; i < VW * VH; i++)
		px[i] = (i * 2654435761u) >> 8;
	port = free_port();
	snprintf(spec, sizeof(spec), "vnc:%d", port);
	assert_int_equal(rdc_sink_open(spec, &c.s), 0);
	assert_int_equal(rdc_sink_frame(c.s, &f), 0); /* starts the server */

	c.fd = socket(AF_INET, SOCK_STREAM, 0);
	a.sin_port = htons((uint16_t)port);
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	assert_int_equal(connect(c.fd, (struct sockaddr *)&a, sizeof(a)), 0);

	rx(&c, ver, sizeof(ver));
	assert_memory_equal(ver, "RFB 003.", 8);
	tx(&c, "RFB 003.008\n", 12);
	rx(&c, b, 1); /* number of security types */
	assert_true(b[0] >= 1);
	rx(&c, b + 1, b[0]);
	assert_non_null(memchr(b + 1, RFB_SEC_NONE, b[0]));
	b[0] = RFB_SEC_NONE;
	tx(&c, b, 1);
	rx(&c, b, 4); /* SecurityResult: OK */
	assert_int_equal(be32(b), 0);
	b[0] = 1; /* ClientInit: shared */
	tx(&c, b, 1);
	rx(&c, b, 4); /* ServerInit */
	assert_int_equal(be16(b), VW);
	assert_int_equal(be16(b + 2), VH);
	rx(&c, pf, sizeof(pf));
	assert_int_equal(pf[0], 32);
	rx(&c, b, 4);
	n = be32(b);
	assert_true(n < sizeof(b));
	rx(&c, b, n);
	tx(&c, enc, sizeof(enc));

	request(&c, 0);
	read_update(&c, seen, pf, &ymin, &ymax);
	assert_memory_equal(seen, px, sizeof(px));

	/* Change rows 11..13; the next frame's update is those rows. */
	for (uint32_t x = 0; x < VW; x++)
		for (uint32_t y = 11; y <= 13; y++)
			px[y * VW + x] ^= 0x00808080;
	f.seq = 1;
	request(&c, 1);
	assert_int_equal(rdc_sink_frame(c.s, &f), 0);
	read_update(&c, seen, pf, &ymin, &ymax);
	assert_int_equal(ymin, 11);
	assert_int_equal(ymax, 13);
	assert_memory_equal(seen, px, sizeof(px));

	/* A mode change: the server takes the new size (viewers without
	 * DesktopSize are let go by libvncserver), and the next frame of
	 * that size is taken too. */
	f.width = VW / 2;
	f.height = VH / 3;
	f.stride = VW;
	assert_int_equal(rdc_sink_frame(c.s, &f), 0);
	assert_int_equal(rdc_sink_frame(c.s, &f), 0);
	assert_int_equal(rdc_sink_poll(c.s), 0);

	close(c.fd);
	rdc_sink_close(c.s);
}

static void test_vnc_bad_specs(void **state)
{
	rdc_sink *s = NULL;
	int want = rdc_sink_have_vnc() ? RDC_E_URI : RDC_E_NOSYS;

	(void)state;
	assert_int_equal(rdc_sink_open("vnc:", &s), want);
	assert_int_equal(rdc_sink_open("vnc:0", &s), want);
	assert_int_equal(rdc_sink_open("vnc:65536", &s), want);
	assert_int_equal(rdc_sink_open("vnc:5900,listen=nowhere", &s), want);
	assert_null(s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_vnc_updates),
		cmocka_unit_test(test_vnc_bad_specs),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
