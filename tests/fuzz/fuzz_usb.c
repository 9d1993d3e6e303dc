// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target for the host side of the USB framing
 * (userspace/lib/usb_host.c): the input is a script of what a device may
 * do (bulk IN chunks of any size and content, interrupt transfers well or
 * badly formed) and of how the protocol client reads (any sizes).  What
 * comes out must always be a stream of whole messages whose headers pass
 * the caps, with each interrupt event whole between two of them; every
 * payload then goes through the protocol decoders, frames included.  The
 * same bytes are also parsed as a usb: address (rdc_usb_addr_parse).
 * Built and run by `make fuzz` beside fuzz_proto.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rdc.h"
#include "usb_host.h"

#define FUZZ_RING	(64u * 1024u)
#define FUZZ_KEEP	(64u * 1024u) /* payload bytes kept for the decoders */
#define FUZZ_MAX_PIXELS (128u * 128u)

static uint32_t fuzz_pix[FUZZ_MAX_PIXELS];

/* The client's view: the stream cut into messages again. */
struct fuzz_reader {
	uint8_t hdr[RDC_PROTO_HDR_SIZE];
	size_t hdr_got;
	struct rdc_proto_hdr h;
	uint64_t left;
	uint8_t pl[FUZZ_KEEP];
	size_t pl_got;
};

static void fuzz_message(const struct rdc_proto_hdr *h, const uint8_t *p,
			 size_t len)
{
	struct rdc_proto_hello_reply hr;
	struct rdc_proto_stats st;
	struct rdc_proto_frame f;

	if (len < h->len)
		return; /* only part of it kept */
	switch (h->type) {
	case RDC_MSG_HELLO:
		rdc_proto_hello_reply_decode(p, len, &hr);
		break;
	case RDC_MSG_STATS:
		rdc_proto_stats_decode(p, len, &st);
		break;
	case RDC_MSG_EV_FRAME:
	case RDC_MSG_FRAME_GRAB:
		if (rdc_proto_frame_hdr_decode(p, len, &f) ||
		    (uint64_t)f.width * f.height > FUZZ_MAX_PIXELS)
			break;
		rdc_proto_frame_decode(fuzz_pix, f.width, f.height, f.encoding,
				       p + RDC_PROTO_FRAME_HDR,
				       len - RDC_PROTO_FRAME_HDR);
		break;
	default:
		break;
	}
}

static void fuzz_consume(struct fuzz_reader *r, const uint8_t *b, size_t n)
{
	while (n) {
		size_t k;

		if (r->hdr_got < RDC_PROTO_HDR_SIZE) {
			uint16_t kind;

			k = RDC_MIN(n, RDC_PROTO_HDR_SIZE - r->hdr_got);
			memcpy(r->hdr + r->hdr_got, b, k);
			r->hdr_got += k;
			b += k;
			n -= k;
			if (r->hdr_got < RDC_PROTO_HDR_SIZE)
				return;
			rdc_proto_hdr_decode(r->hdr, &r->h);
			kind = r->h.flags & (RDC_MSGF_REPLY | RDC_MSGF_EVENT);
			/* what the reassembly promises */
			if (r->h.len > RDC_PROTO_MAX_REPLY ||
			    (kind != RDC_MSGF_REPLY && kind != RDC_MSGF_EVENT))
				abort();
			r->left = r->h.len;
			r->pl_got = 0;
		} else {
			k = (size_t)RDC_MIN((uint64_t)n, r->left);
			if (r->pl_got < FUZZ_KEEP) {
				size_t c = RDC_MIN(k, FUZZ_KEEP - r->pl_got);

				memcpy(r->pl + r->pl_got, b, c);
				r->pl_got += c;
			}
			r->left -= k;
			b += k;
			n -= k;
		}
		if (r->hdr_got == RDC_PROTO_HDR_SIZE && !r->left) {
			fuzz_message(&r->h, r->pl, r->pl_got);
			r->hdr_got = 0;
		}
	}
}

/* A well-formed interrupt event from 12 bytes of input. */
static void fuzz_event(uint8_t *ev, const uint8_t *p)
{
	struct rdc_proto_hdr h = {
		.len = RDC_USB_EVENT_SIZE - RDC_PROTO_HDR_SIZE,
		.type = RDC_MSG_EV_IRQ,
		.flags = RDC_MSGF_EVENT,
	};

	rdc_proto_hdr_encode(ev, &h);
	memcpy(ev + RDC_PROTO_HDR_SIZE, p, 12);
}

/*
 * The same bytes as a usb: address: what parses is whole, and a path
 * formats back to text that parses to the same path.
 */
static void fuzz_addr(const uint8_t *data, size_t size)
{
	struct rdc_usb_addr a, b;
	char text[64];

	if (rdc_usb_addr_parse((const char *)data, RDC_MIN(size, 300), &a))
		return;
	if (a.kind > RDC_USB_ADDR_SERIAL || a.nports > RDC_USB_MAX_PORTS ||
	    !memchr(a.serial, 0, sizeof(a.serial)))
		abort();
	if (a.kind != RDC_USB_ADDR_PATH)
		return;
	if (rdc_usb_path_format(text, sizeof(text), a.bus, a.ports, a.nports) ||
	    rdc_usb_addr_parse(text, strlen(text), &b) ||
	    b.kind != RDC_USB_ADDR_PATH || b.bus != a.bus ||
	    b.nports != a.nports || memcmp(b.ports, a.ports, a.nports))
		abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static struct fuzz_reader r;
	static uint8_t out[8192];
	struct rdc_usb_rx rx;
	uint64_t good = 0;
	size_t i = 0;

	fuzz_addr(data, size);
	if (rdc_usb_rx_init(&rx, FUZZ_RING))
		return 0;
	memset(&r, 0, sizeof(r));
	while (i + 3 <= size) {
		uint8_t op = data[i] & 3;
		size_t arg = (size_t)data[i + 1] | (size_t)data[i + 2] << 8;
		ssize_t got;
		uint8_t ev[RDC_USB_EVENT_SIZE];

		i += 3;
		switch (op) {
		case 0: /* bulk chunk, never more than the room */
			arg = RDC_MIN(arg,
				      RDC_MIN(size - i, rdc_usb_rx_room(&rx)));
			if (rdc_usb_rx_bulk(&rx, data + i, arg))
				abort();
			i += arg;
			break;
		case 1: /* interrupt transfer, as the device made it */
			arg = RDC_MIN(arg % 80, size - i);
			if (!rdc_usb_rx_intr(&rx, data + i, arg))
				good++;
			i += arg;
			break;
		case 2: /* a well-formed event */
			if (size - i < 12)
				break;
			fuzz_event(ev, data + i);
			i += 12;
			if (rdc_usb_rx_intr(&rx, ev, sizeof(ev)))
				abort();
			good++;
			break;
		default: /* the client reads */
			got = rdc_usb_rx_read(&rx, out, arg % sizeof(out) + 1);
			if (got < 0) {
				if (got != RDC_E_PROTO)
					abort();
				break;
			}
			fuzz_consume(&r, out, (size_t)got);
			break;
		}
	}
	/* drain: everything queued comes out, bounded by what went in */
	for (int k = 0; k < 64; k++) {
		ssize_t got = rdc_usb_rx_read(&rx, out, sizeof(out));

		if (got <= 0)
			break;
		fuzz_consume(&r, out, (size_t)got);
	}
	/* every good event queued, or lost to a full queue and counted */
	if (rx.ev_queued > good || good - rx.ev_queued > rx.ev_lost ||
	    rx.ev_n > RDC_USB_RX_EVENTS || rx.len > rx.cap)
		abort();
	rdc_usb_rx_free(&rx);
	return 0;
}
