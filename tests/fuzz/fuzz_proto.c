// SPDX-License-Identifier: GPL-2.0-only
/*
 * libFuzzer target for the wire protocol's parser (userspace/lib/proto.c):
 * the input is a byte stream cut into messages exactly as rdcd and librdc
 * cut theirs, and every payload goes through the decoder of its type,
 * requests and replies alike, frames included.  Built and run by
 * `make fuzz` (short) and `make fuzz-long`; docs/protocol.md has more.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rdc_proto.h"

/* Decoded frames are capped so that a run stays fast and small. */
#define FUZZ_MAX_PIXELS (256u * 256u)

static uint32_t fuzz_pix[FUZZ_MAX_PIXELS];
static uint8_t fuzz_enc[FUZZ_MAX_PIXELS * 4 * 2];

static void fuzz_frame(const uint8_t *p, size_t len)
{
	struct rdc_proto_frame f;
	size_t n;

	if (rdc_proto_frame_hdr_decode(p, len, &f))
		return;
	if ((uint64_t)f.width * f.height > FUZZ_MAX_PIXELS)
		return;
	if (rdc_proto_frame_decode(fuzz_pix, f.width, f.height, f.encoding,
				   p + RDC_PROTO_FRAME_HDR,
				   len - RDC_PROTO_FRAME_HDR))
		return;
	/* what decodes must encode and decode back to itself */
	n = rdc_proto_frame_encode(fuzz_enc, sizeof(fuzz_enc), RDC_ENC_RLE,
				   fuzz_pix, NULL, f.width, f.height);
	if ((f.width && f.height && !n) ||
	    rdc_proto_frame_decode(fuzz_pix, f.width, f.height, RDC_ENC_RLE,
				   fuzz_enc, n))
		abort();
}

static void fuzz_payload(const struct rdc_proto_hdr *h, const uint8_t *p,
			 size_t len)
{
	struct rdc_proto_hello hello;
	struct rdc_proto_hello_reply hr;
	struct rdc_proto_wait w;
	struct rdc_proto_stats st;

	switch (h->type) {
	case RDC_MSG_HELLO:
		if (h->flags & RDC_MSGF_REPLY)
			rdc_proto_hello_reply_decode(p, len, &hr);
		else if (!rdc_proto_hello_decode(p, len, &hello) &&
			 hello.token_len &&
			 hello.token + hello.token_len > p + len)
			abort();
		break;
	case RDC_MSG_WAIT:
		rdc_proto_wait_decode(p, len, &w);
		break;
	case RDC_MSG_STATS:
		rdc_proto_stats_decode(p, len, &st);
		break;
	case RDC_MSG_FRAME_GRAB:
	case RDC_MSG_EV_FRAME:
		fuzz_frame(p, len);
		break;
	default:
		break;
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	while (size >= RDC_PROTO_HDR_SIZE) {
		struct rdc_proto_hdr h;
		size_t len;

		rdc_proto_hdr_decode(data, &h);
		data += RDC_PROTO_HDR_SIZE;
		size -= RDC_PROTO_HDR_SIZE;
		if (rdc_proto_hdr_check(&h, RDC_PROTO_MAX_REPLY) ==
		    RDC_ST_TOOBIG)
			return 0; /* both sides hang up here */
		rdc_proto_request_check(&h);
		/* the payload as far as the input goes: truncation too */
		len = h.len < size ? h.len : size;
		fuzz_payload(&h, data, len);
		data += len;
		size -= len;
	}
	return 0;
}
