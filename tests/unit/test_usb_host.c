// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The libusb-free half of the usb: backend (userspace/lib/usb_host.c):
 * usb: addresses, and the reassembly of bulk IN chunks and interrupt
 * transfers into whole protocol messages, with what a hostile device may
 * send.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "usb_host.h"

static int parse(const char *s, struct rdc_usb_addr *a)
{
	return rdc_usb_addr_parse(s, strlen(s), a);
}

static void test_addr_forms(void **state)
{
	struct rdc_usb_addr a;

	(void)state;
	assert_int_equal(parse("", &a), 0);
	assert_int_equal(a.kind, RDC_USB_ADDR_FIRST);
	assert_int_equal(a.vid, RDC_USB_VID);
	assert_int_equal(a.pid, RDC_USB_PID);

	assert_int_equal(parse("1d6b:0104", &a), 0);
	assert_int_equal(a.kind, RDC_USB_ADDR_IDS);
	assert_int_equal(a.vid, 0x1d6b);
	assert_int_equal(a.pid, 0x0104);
	assert_int_equal(parse("ABCD:1", &a), 0);
	assert_int_equal(a.vid, 0xabcd);
	assert_int_equal(a.pid, 1);

	assert_int_equal(parse("3-1.4.2", &a), 0);
	assert_int_equal(a.kind, RDC_USB_ADDR_PATH);
	assert_int_equal(a.bus, 3);
	assert_int_equal(a.nports, 3);
	assert_int_equal(a.ports[0], 1);
	assert_int_equal(a.ports[1], 4);
	assert_int_equal(a.ports[2], 2);
	assert_int_equal(parse("1-1", &a), 0);
	assert_int_equal(a.nports, 1);

	assert_int_equal(parse("serial=rdc 0042", &a), 0);
	assert_int_equal(a.kind, RDC_USB_ADDR_SERIAL);
	assert_string_equal(a.serial, "rdc 0042");
	assert_int_equal(a.vid, RDC_USB_VID);

	/* only up to '?': the caller cuts the options off */
	assert_int_equal(rdc_usb_addr_parse("1-2?observe", 3, &a), 0);
	assert_int_equal(a.ports[0], 2);
}

static void test_addr_bad(void **state)
{
	static const char *const bad[] = {
		"1209",	   "1209:",  ":0001", "12345:1",
		"1:12345", "12g9:1", "1:2:3", "0-1",
		"256-1",   "1-",     "1-0",   "1-1.",
		"1-1..2",  "1-256",  "-1",    "1-1.2.3.4.5.6.7.8",
		"serial=", "x",	     "1 - 1", "serial=a&b",
		"1-1x",	   "+1-1",   "1--1",
	};
	struct rdc_usb_addr a;
	char big[300];

	(void)state;
	for (size_t i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
		if (parse(bad[i], &a) != RDC_E_URI)
			print_error("accepted '%s'\n", bad[i]);
		assert_int_equal(parse(bad[i], &a), RDC_E_URI);
	}
	memset(big, 'a', sizeof(big));
	memcpy(big, "serial=", 7);
	big[sizeof(big) - 1] = 0;
	assert_int_equal(parse(big, &a), RDC_E_URI);
	/* seven ports is the deepest USB goes */
	assert_int_equal(parse("1-1.2.3.4.5.6.7", &a), 0);
	assert_int_equal(a.nports, 7);
}

static void test_path_format(void **state)
{
	static const uint8_t ports[] = { 1, 4, 2 };
	char buf[32];

	(void)state;
	assert_int_equal(rdc_usb_path_format(buf, sizeof(buf), 3, ports, 3), 0);
	assert_string_equal(buf, "3-1.4.2");
	assert_int_equal(rdc_usb_path_format(buf, 6, 3, ports, 3), -1);
}

/* ---- Reassembly ------------------------------------------------------------
 */

static size_t put_msg(uint8_t *p, uint16_t type, uint16_t flags, uint32_t seq,
		      const void *pl, uint32_t len)
{
	struct rdc_proto_hdr h = {
		.len = len, .type = type, .flags = flags, .seq = seq
	};

	rdc_proto_hdr_encode(p, &h);
	if (len)
		memcpy(p + RDC_PROTO_HDR_SIZE, pl, len);
	return RDC_PROTO_HDR_SIZE + len;
}

static void put_event(uint8_t *ev, uint32_t bits, uint64_t time)
{
	uint8_t pl[12];

	rdc_proto_put32(pl, bits);
	rdc_proto_put64(pl + 4, time);
	put_msg(ev, RDC_MSG_EV_IRQ, RDC_MSGF_EVENT, 0, pl, 12);
}

/* Reads of `step` bytes until nothing comes: the bytes read. */
static size_t read_all(struct rdc_usb_rx *rx, uint8_t *out, size_t cap,
		       size_t step)
{
	size_t got = 0;

	for (;;) {
		ssize_t k = rdc_usb_rx_read(rx, out + got,
					    RDC_MIN(step, cap - got));

		assert_true(k >= 0);
		if (!k)
			return got;
		got += (size_t)k;
	}
}

/* Any cut of the bulk stream and any read size give the same messages. */
static void test_rx_chunks(void **state)
{
	static uint8_t stream[20000], out[20000];
	struct rdc_usb_rx rx;
	size_t n = 0;
	uint32_t seed = 12345;

	(void)state;
	for (uint32_t i = 0; i < 40; i++) {
		uint8_t pl[700];
		uint32_t len = (i * 97) % sizeof(pl);

		for (uint32_t k = 0; k < len; k++)
			pl[k] = (uint8_t)(i + k * 3);
		n += put_msg(stream + n, RDC_MSG_VRAM_READ, RDC_MSGF_REPLY,
			     i + 1, pl, len);
	}
	for (int round = 0; round < 50; round++) {
		size_t in = 0, got = 0;

		assert_int_equal(rdc_usb_rx_init(&rx, 4096), 0);
		while (in < n || got < n) {
			size_t chunk, step;

			seed = seed * 1103515245u + 12345u;
			chunk = RDC_MIN((size_t)(seed >> 8) % 1500,
					RDC_MIN(n - in, rdc_usb_rx_room(&rx)));
			assert_int_equal(
				rdc_usb_rx_bulk(&rx, stream + in, chunk), 0);
			in += chunk;
			step = (size_t)(seed >> 20) % 300 + 1;
			got += read_all(&rx, out + got, n - got, step);
		}
		assert_memory_equal(out, stream, n);
		rdc_usb_rx_free(&rx);
	}
}

/* Interrupt events come between bulk messages, never inside one. */
static void test_rx_events_between(void **state)
{
	uint8_t msg[RDC_PROTO_HDR_SIZE + 100], ev[RDC_USB_EVENT_SIZE];
	uint8_t out[400], pl[100];
	struct rdc_usb_rx rx;
	size_t m, got;
	struct rdc_proto_hdr h;

	(void)state;
	memset(pl, 0x5a, sizeof(pl));
	m = put_msg(msg, RDC_MSG_EV_FRAME, RDC_MSGF_EVENT, 0, pl, sizeof(pl));
	put_event(ev, RDC_IRQ_VBLANK, 777);
	assert_int_equal(rdc_usb_rx_init(&rx, 1024), 0);
	/* half a message in, then an event: the message finishes first */
	assert_int_equal(rdc_usb_rx_bulk(&rx, msg, 40), 0);
	got = read_all(&rx, out, sizeof(out), 7);
	assert_int_equal(got, 40);
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, sizeof(ev)), 0);
	assert_int_equal(rdc_usb_rx_read(&rx, out + got, 50), 0);
	assert_int_equal(rdc_usb_rx_bulk(&rx, msg + 40, m - 40), 0);
	got += read_all(&rx, out + got, sizeof(out) - got, 13);
	assert_int_equal(got, m + sizeof(ev));
	assert_memory_equal(out, msg, m);
	assert_memory_equal(out + m, ev, sizeof(ev));
	rdc_proto_hdr_decode(out + m, &h);
	assert_int_equal(h.type, RDC_MSG_EV_IRQ);
	/* at a boundary an event goes before bulk bytes waiting */
	assert_int_equal(rdc_usb_rx_bulk(&rx, msg, m), 0);
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, sizeof(ev)), 0);
	got = read_all(&rx, out, sizeof(out), 5);
	assert_int_equal(got, m + sizeof(ev));
	assert_memory_equal(out, ev, sizeof(ev));
	assert_memory_equal(out + sizeof(ev), msg, m);
	assert_int_equal(rx.ev_queued, 2);
	rdc_usb_rx_free(&rx);
}

static void test_rx_bad_interrupts(void **state)
{
	uint8_t ev[RDC_USB_EVENT_SIZE + 8], bad[RDC_USB_EVENT_SIZE];
	uint8_t out[64];
	struct rdc_usb_rx rx;
	struct rdc_proto_hdr h;

	(void)state;
	assert_int_equal(rdc_usb_rx_init(&rx, 256), 0);
	put_event(ev, 1, 2);
	/* short, long, empty */
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, RDC_USB_EVENT_SIZE - 1), 1);
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, RDC_USB_EVENT_SIZE + 8), 1);
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, 0), 1);
	/* the right size, a wrong header */
	memcpy(bad, ev, sizeof(bad));
	rdc_proto_hdr_decode(bad, &h);
	h.type = RDC_MSG_EV_FRAME;
	rdc_proto_hdr_encode(bad, &h);
	assert_int_equal(rdc_usb_rx_intr(&rx, bad, sizeof(bad)), 1);
	h.type = RDC_MSG_EV_IRQ;
	h.flags = RDC_MSGF_REPLY;
	rdc_proto_hdr_encode(bad, &h);
	assert_int_equal(rdc_usb_rx_intr(&rx, bad, sizeof(bad)), 1);
	h.flags = RDC_MSGF_EVENT;
	h.len = 13;
	rdc_proto_hdr_encode(bad, &h);
	assert_int_equal(rdc_usb_rx_intr(&rx, bad, sizeof(bad)), 1);
	assert_int_equal(rx.ev_bad, 6);
	/* nothing of them reaches the reader */
	assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)), 0);
	/* a good one does */
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, RDC_USB_EVENT_SIZE), 0);
	assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)),
			 RDC_USB_EVENT_SIZE);
	assert_memory_equal(out, ev, RDC_USB_EVENT_SIZE);
	rdc_usb_rx_free(&rx);
}

/* A full queue loses the oldest events, counted, never a torn one. */
static void test_rx_event_overflow(void **state)
{
	uint8_t ev[RDC_USB_EVENT_SIZE], out[RDC_USB_EVENT_SIZE];
	struct rdc_usb_rx rx;
	unsigned int total = RDC_USB_RX_EVENTS + 10;

	(void)state;
	assert_int_equal(rdc_usb_rx_init(&rx, 256), 0);
	for (unsigned int i = 0; i < total; i++) {
		put_event(ev, i, i);
		assert_int_equal(rdc_usb_rx_intr(&rx, ev, sizeof(ev)), 0);
	}
	assert_int_equal(rx.ev_lost, 10);
	/* half of the oldest kept one read; more arrive; it stays whole */
	assert_int_equal(rdc_usb_rx_read(&rx, out, 10), 10);
	put_event(ev, 999, 999);
	assert_int_equal(rdc_usb_rx_intr(&rx, ev, sizeof(ev)), 0);
	assert_int_equal(rx.ev_lost, 11);
	assert_int_equal(rdc_usb_rx_read(&rx, out + 10, sizeof(out) - 10),
			 sizeof(out) - 10);
	assert_int_equal(rdc_proto_get32(out + RDC_PROTO_HDR_SIZE), 10);
	for (unsigned int i = 11; i < total; i++) {
		assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)),
				 sizeof(out));
		assert_int_equal(rdc_proto_get32(out + RDC_PROTO_HDR_SIZE), i);
	}
	assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)), 0);
	rdc_usb_rx_free(&rx);
}

/* A header over the caps, or neither reply nor event: nothing passes. */
static void test_rx_bad_bulk(void **state)
{
	static const struct {
		uint32_t len;
		uint16_t flags;
	} bad[] = {
		{ RDC_PROTO_MAX_REPLY + 1, RDC_MSGF_REPLY },
		{ 0xffffffffu, RDC_MSGF_EVENT },
		{ 4, 0 },
		{ 4, RDC_MSGF_REPLY | RDC_MSGF_EVENT },
	};
	uint8_t msg[RDC_PROTO_HDR_SIZE + 4] = { 0 }, out[64];
	struct rdc_usb_rx rx;

	(void)state;
	for (size_t i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
		struct rdc_proto_hdr h = { .len = bad[i].len,
					   .type = RDC_MSG_PING,
					   .flags = bad[i].flags };
		uint8_t ev[RDC_USB_EVENT_SIZE];

		assert_int_equal(rdc_usb_rx_init(&rx, 256), 0);
		rdc_proto_hdr_encode(msg, &h);
		assert_int_equal(rdc_usb_rx_bulk(&rx, msg, sizeof(msg)), 0);
		assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)),
				 RDC_E_PROTO);
		/* and it stays broken; events queued before still come */
		put_event(ev, 1, 1);
		assert_int_equal(rdc_usb_rx_intr(&rx, ev, sizeof(ev)), 0);
		assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)),
				 sizeof(ev));
		assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)),
				 RDC_E_PROTO);
		rdc_usb_rx_free(&rx);
	}
	/* the exact cap passes */
	assert_int_equal(rdc_usb_rx_init(&rx, 256), 0);
	{
		struct rdc_proto_hdr h = { .len = RDC_PROTO_MAX_REPLY,
					   .type = RDC_MSG_FRAME_GRAB,
					   .flags = RDC_MSGF_REPLY };

		rdc_proto_hdr_encode(msg, &h);
	}
	assert_int_equal(rdc_usb_rx_bulk(&rx, msg, sizeof(msg)), 0);
	assert_int_equal(rdc_usb_rx_read(&rx, out, sizeof(out)), sizeof(msg));
	/* more than the room is refused, and breaks the stream */
	assert_int_equal(rdc_usb_rx_bulk(&rx, out, 300), RDC_E_PROTO);
	rdc_usb_rx_free(&rx);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_addr_forms),
		cmocka_unit_test(test_addr_bad),
		cmocka_unit_test(test_path_format),
		cmocka_unit_test(test_rx_chunks),
		cmocka_unit_test(test_rx_events_between),
		cmocka_unit_test(test_rx_bad_interrupts),
		cmocka_unit_test(test_rx_event_overflow),
		cmocka_unit_test(test_rx_bad_bulk),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
