// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The usb: backend's host pipeline without libusb: the protocol client
 * (net.c, rdc_client.h) over a transport whose bytes come through the USB
 * reassembly (usb_host.c) in chunks of random size, as bulk IN transfers
 * would bring them, with interrupt events mixed in; a scripted device
 * answers.  Checks that replies and interrupt events arrive as on a
 * socket, and that a device that goes away gives RDC_E_GONE for the call
 * in progress and at once for every later call, without touching the
 * transport again.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "rdc_client.h"
#include "usb_host.h"

#define FAKE_REG_XOR 0x5a5a0000u

struct fake {
	struct rdc_xport x;
	struct rdc_usb_rx rx;
	uint8_t pending[4096]; /* replies not yet "transferred" */
	size_t npending;
	uint32_t seed;
	bool gone;	     /* unplugged */
	bool gone_mid_reply; /* unplug after half of the next reply */
	unsigned int calls;  /* send and recv calls */
	unsigned int closed;
	unsigned int requests;
};

static struct fake fake;

static uint32_t fake_rand(void)
{
	fake.seed = fake.seed * 1103515245u + 12345u;
	return fake.seed >> 8;
}

static void fake_reply(const struct rdc_proto_hdr *req, const void *pl,
		       uint32_t len)
{
	struct rdc_proto_hdr h = { .len = len,
				   .type = req->type,
				   .flags = RDC_MSGF_REPLY,
				   .seq = req->seq };

	assert_true(fake.npending + RDC_PROTO_HDR_SIZE + len <=
		    sizeof(fake.pending));
	rdc_proto_hdr_encode(fake.pending + fake.npending, &h);
	if (len)
		memcpy(fake.pending + fake.npending + RDC_PROTO_HDR_SIZE, pl,
		       len);
	fake.npending += RDC_PROTO_HDR_SIZE + len;
}

/* The device: one request at a time, in one send (the client's way). */
static int fake_send(struct rdc_xport *x, const struct iovec *iov, int n)
{
	uint8_t msg[256], out[RDC_PROTO_HELLO_REPLY_SIZE];
	struct rdc_proto_hdr h;
	size_t len = 0;

	(void)x;
	fake.calls++;
	if (fake.gone)
		return RDC_E_GONE;
	for (int i = 0; i < n; i++) {
		assert_true(len + iov[i].iov_len <= sizeof(msg));
		if (iov[i].iov_len)
			memcpy(msg + len, iov[i].iov_base, iov[i].iov_len);
		len += iov[i].iov_len;
	}
	assert_true(len >= RDC_PROTO_HDR_SIZE);
	rdc_proto_hdr_decode(msg, &h);
	assert_int_equal(h.len, len - RDC_PROTO_HDR_SIZE);
	fake.requests++;
	switch (h.type) {
	case RDC_MSG_HELLO: {
		struct rdc_proto_hello_reply r = {
			.version = RDC_PROTO_VERSION,
			.caps = RDC_CAP_ALL,
			.flags = RDC_HELLO_CONTROL,
			.run_mode = RDC_RUN_STEPPED,
			.vram_size = 1u << 20,
			.core_hz = 100000000u,
		};

		rdc_proto_hello_reply_encode(out, &r);
		fake_reply(&h, out, RDC_PROTO_HELLO_REPLY_SIZE);
		break;
	}
	case RDC_MSG_REG_READ:
		rdc_proto_put32(out, rdc_proto_get32(msg + 16) ^ FAKE_REG_XOR);
		fake_reply(&h, out, 4);
		break;
	default:
		fake_reply(&h, NULL, 0);
		break;
	}
	return 0;
}

static void fake_irq(uint32_t bits, uint64_t time)
{
	struct rdc_proto_hdr h = { .len = 12,
				   .type = RDC_MSG_EV_IRQ,
				   .flags = RDC_MSGF_EVENT };
	uint8_t ev[RDC_USB_EVENT_SIZE];

	rdc_proto_hdr_encode(ev, &h);
	rdc_proto_put32(ev + 16, bits);
	rdc_proto_put64(ev + 20, time);
	assert_int_equal(rdc_usb_rx_intr(&fake.rx, ev, sizeof(ev)), 0);
}

/* As usb.c's recv: the ring first, then "transfers", then the failure. */
static ssize_t fake_recv(struct rdc_xport *x, void *buf, size_t len,
			 int timeout_ms)
{
	(void)x;
	fake.calls++;
	for (;;) {
		ssize_t n = rdc_usb_rx_read(&fake.rx, buf, len);
		size_t chunk;

		if (n)
			return n;
		if (fake.gone || !fake.npending)
			return fake.gone ? RDC_E_GONE :
					   (timeout_ms >= 0 ? RDC_E_TIMEOUT :
							      RDC_E_IO);
		chunk = (size_t)fake_rand() % 9 + 1;
		chunk = RDC_MIN(fake.npending, chunk);
		if (fake.gone_mid_reply) {
			chunk = fake.npending / 2;
			fake.gone = true;
		}
		assert_int_equal(rdc_usb_rx_bulk(&fake.rx, fake.pending, chunk),
				 0);
		memmove(fake.pending, fake.pending + chunk,
			fake.npending - chunk);
		fake.npending -= chunk;
		/* an interrupt transfer completes now and then */
		if (fake_rand() % 5 == 0)
			fake_irq(RDC_IRQ_VBLANK, fake.requests);
	}
}

static void fake_close(struct rdc_xport *x)
{
	(void)x;
	fake.closed++;
}

static const struct rdc_xport_ops fake_ops = {
	.send = fake_send,
	.recv = fake_recv,
	.close = fake_close,
};

static int fake_open(rdc_dev *dev, const char *opts)
{
	struct rdc_client_opts o;

	(void)opts;
	assert_int_equal(rdc_client_parse_opts(NULL, &o), 0);
	return rdc_client_open(dev, &fake.x, &o);
}

static const struct rdc_backend fake_be = {
	.scheme = "fake",
	.open = fake_open,
	RDC_CLIENT_OPS,
};

static rdc_dev *fake_dev(uint32_t seed)
{
	rdc_dev *dev = calloc(1, sizeof(*dev));

	memset(&fake, 0, sizeof(fake));
	fake.x.ops = &fake_ops;
	fake.seed = seed;
	assert_int_equal(rdc_usb_rx_init(&fake.rx, 1024), 0);
	assert_non_null(dev);
	dev->be = &fake_be;
	assert_int_equal(fake_be.open(dev, ""), 0);
	return dev;
}

static void fake_dev_close(rdc_dev *dev)
{
	rdc_close(dev);
	rdc_usb_rx_free(&fake.rx);
}

/* Replies through any chunking, events in between: all as on a socket. */
static void test_client_replies_and_events(void **state)
{
	for (uint32_t seed = 1; seed < 20; seed++) {
		rdc_dev *dev = fake_dev(seed);
		unsigned int irqs = 0;
		uint64_t last = 0;

		(void)state;
		assert_int_equal(rdc_subscribe(dev, RDC_EVENT_IRQ, 0, 0), 0);
		for (uint32_t r = 0; r < 200; r += 4) {
			uint32_t v = 0;

			assert_int_equal(rdc_reg_read(dev, r, &v), 0);
			assert_int_equal(v, r ^ FAKE_REG_XOR);
			assert_int_equal(rdc_reg_write(dev, r, v), 0);
		}
		fake_irq(RDC_IRQ_FENCE, 1000);
		for (;;) {
			struct rdc_event ev;
			int ret = rdc_event_next(dev, &ev, NULL, 0, 0);

			if (ret == RDC_E_TIMEOUT)
				break;
			assert_int_equal(ret, 0);
			assert_int_equal(ev.type, RDC_EVENT_IRQ);
			assert_true(ev.time >= last);
			last = ev.time;
			irqs++;
		}
		/* the last one at least; older ones as the queue kept them */
		assert_true(irqs >= 1);
		assert_int_equal(last, 1000);
		assert_int_equal(fake.rx.ev_bad, 0);
		fake_dev_close(dev);
		assert_int_equal(fake.closed, 1);
	}
}

static void expect_all_gone(rdc_dev *dev)
{
	unsigned int calls = fake.calls;
	uint32_t v, words[4] = { 0 };
	uint8_t b[16] = { 0 };
	struct rdc_event ev;
	uint64_t t;

	assert_int_equal(rdc_reg_read(dev, 0, &v), RDC_E_GONE);
	assert_int_equal(rdc_reg_write(dev, 0, 0), RDC_E_GONE);
	assert_int_equal(rdc_vram_read(dev, 0, b, sizeof(b)), RDC_E_GONE);
	assert_int_equal(rdc_vram_write(dev, 0, b, sizeof(b)), RDC_E_GONE);
	assert_int_equal(rdc_submit(dev, words, 4), RDC_E_GONE);
	assert_int_equal(rdc_finish(dev), RDC_E_GONE);
	assert_int_equal(rdc_vblank_wait(dev), RDC_E_GONE);
	assert_int_equal(rdc_sim_time(dev, &t), RDC_E_GONE);
	assert_int_equal(rdc_subscribe(dev, RDC_EVENT_FRAME, 1, 0), RDC_E_GONE);
	assert_int_equal(rdc_event_next(dev, &ev, NULL, 0, 1000), RDC_E_GONE);
	/* none of them went near the transport */
	assert_int_equal(fake.calls, calls);
	assert_int_equal(fake.closed, 1);
	assert_string_equal(rdc_strerror(RDC_E_GONE), "device gone");
}

static void test_client_gone_between_calls(void **state)
{
	rdc_dev *dev = fake_dev(7);
	uint32_t v;

	(void)state;
	assert_int_equal(rdc_reg_read(dev, 8, &v), 0);
	fake.gone = true;
	assert_int_equal(rdc_reg_read(dev, 8, &v), RDC_E_GONE);
	expect_all_gone(dev);
	fake_dev_close(dev);
	assert_int_equal(fake.closed, 1);
}

static void test_client_gone_mid_reply(void **state)
{
	rdc_dev *dev = fake_dev(9);
	uint32_t v;

	(void)state;
	fake.gone_mid_reply = true;
	assert_int_equal(rdc_reg_read(dev, 8, &v), RDC_E_GONE);
	expect_all_gone(dev);
	fake_dev_close(dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_client_replies_and_events),
		cmocka_unit_test(test_client_gone_between_calls),
		cmocka_unit_test(test_client_gone_mid_reply),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
