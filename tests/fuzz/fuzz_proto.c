// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target for the wire protocol's parser (userspace/lib/proto.c):
 * the input is a byte stream cut into messages exactly as rdcd and librdc
 * cut theirs, and every payload goes through the decoder of its type,
 * requests and replies alike, frames included.  A frame that decodes goes
 * back through every encoder (RDC_ENC_DELTA against no previous frame and
 * against the frame decoded before it), with exact, ample and too little
 * room, and must decode to itself again; so must every pixel history
 * entry of a HIST_READ reply (the header's seq stands for the most the
 * request asked for).  Built and run by `make fuzz`
 * (short) and `make fuzz-long`; docs/protocol.md has more.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rdc_proto.h"

#define RDC_MIN(a, b)	  ((a) < (b) ? (a) : (b))
#define RDC_ARRAY_SIZE(a) (sizeof(a) / sizeof((a)[0]))

/* Decoded frames are capped so that a run stays fast and small. */
#define FUZZ_MAX_PIXELS	    (256u * 256u)
#define FUZZ_ENC_MAX_PIXELS 512u

static uint32_t fuzz_pix[FUZZ_MAX_PIXELS];
static uint32_t fuzz_prev[FUZZ_MAX_PIXELS], fuzz_back[FUZZ_MAX_PIXELS];
static uint8_t fuzz_enc[FUZZ_MAX_PIXELS * 4 * 2];

/*
 * pix (w x h) through the encoder in `enc` against `prev` (may be NULL),
 * with room for `cap` bytes: what it writes fits and decodes back to pix
 * (for RDC_ENC_DELTA, over a copy of prev: the receiver's last frame).
 * A result of 0 means "does not fit": then a raw frame goes instead.
 */
static void fuzz_roundtrip(const uint32_t *pix, const uint32_t *prev,
			   uint32_t w, uint32_t h, uint32_t enc, size_t cap)
{
	size_t px = (size_t)w * h;
	size_t n = rdc_proto_frame_encode(fuzz_enc, cap, enc, pix, prev, w, h);

	if (n > cap)
		abort();
	if (!n) {
		/* raw always fits in w * h * 4 bytes (empty frames: 0) */
		if (enc == RDC_ENC_RAW && px && cap >= px * 4)
			abort();
		return;
	}
	if (enc == RDC_ENC_DELTA && prev)
		memcpy(fuzz_back, prev, px * 4);
	else
		memset(fuzz_back, 0xa5, px * 4);
	if (rdc_proto_frame_decode(fuzz_back, w, h, enc, fuzz_enc, n) ||
	    memcmp(fuzz_back, pix, px * 4))
		abort();
}

/*
 * Every encoding of a frame that decoded: against no previous frame, the
 * frame before it when the size matches (DELTA's rows "as before"), and
 * with the room exact, plenty, or cut short by `cut`.
 */
static void fuzz_encoders(const uint32_t *pix, uint32_t w, uint32_t h,
			  uint32_t cut)
{
	static uint32_t prev_w, prev_h;
	size_t raw = (size_t)w * h * 4;
	const size_t caps[] = { raw, sizeof(fuzz_enc),
				raw - RDC_MIN(raw, cut) };

	for (uint32_t enc = 0; enc < RDC_ENC_COUNT_ + 1; enc++) {
		for (size_t i = 0; i < RDC_ARRAY_SIZE(caps); i++) {
			fuzz_roundtrip(pix, NULL, w, h, enc, caps[i]);
			if (prev_w == w && prev_h == h)
				fuzz_roundtrip(pix, fuzz_prev, w, h, enc,
					       caps[i]);
		}
	}
	memcpy(fuzz_prev, pix, raw);
	prev_w = w;
	prev_h = h;
}

static void fuzz_frame(const uint8_t *p, size_t len, uint32_t cut)
{
	struct rdc_proto_frame f;

	if (rdc_proto_frame_hdr_decode(p, len, &f))
		return;
	if ((uint64_t)f.width * f.height > FUZZ_MAX_PIXELS)
		return;
	/* DELTA decodes over the last frame: start from a known one */
	memset(fuzz_pix, 0, sizeof(uint32_t) * f.width * f.height);
	if (rdc_proto_frame_decode(fuzz_pix, f.width, f.height, f.encoding,
				   p + RDC_PROTO_FRAME_HDR,
				   len - RDC_PROTO_FRAME_HDR))
		return;
	/* what decodes must encode and decode back to itself (small frames:
	 * a run stays fast) */
	if ((uint64_t)f.width * f.height <= FUZZ_ENC_MAX_PIXELS)
		fuzz_encoders(fuzz_pix, f.width, f.height, cut);
}

static void fuzz_payload(const struct rdc_proto_hdr *h, const uint8_t *p,
			 size_t len)
{
	struct rdc_proto_hello hello;
	struct rdc_proto_hello_reply hr;
	struct rdc_proto_wait w;
	struct rdc_proto_stats st;
	struct rdc_proto_hist_open ho;
	struct rdc_proto_hist_page pg;
	struct rdc_proto_hist_entry he;
	uint8_t ebuf[RDC_PROTO_HIST_ENTRY_SIZE];

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
		fuzz_frame(p, len, h->seq);
		break;
	case RDC_MSG_HIST_OPEN:
		rdc_proto_hist_open_decode(p, len, &ho);
		break;
	case RDC_MSG_HIST_READ:
		if (!(h->flags & RDC_MSGF_REPLY))
			break;
		/* a page: its entries, and back through the encoder */
		if (rdc_proto_hist_page_decode(p, len, h->seq, &pg))
			break;
		if (pg.n > h->seq ||
		    len != RDC_PROTO_HIST_PAGE_HDR +
				    (size_t)pg.n * RDC_PROTO_HIST_ENTRY_SIZE)
			abort();
		for (uint32_t i = 0; i < pg.n; i++) {
			const uint8_t *q =
				p + RDC_PROTO_HIST_PAGE_HDR +
				(size_t)i * RDC_PROTO_HIST_ENTRY_SIZE;

			if (rdc_proto_hist_entry_decode(q, &he))
				continue;
			rdc_proto_hist_entry_encode(ebuf, &he);
			if (memcmp(ebuf, q, RDC_PROTO_HIST_ENTRY_SIZE))
				abort();
		}
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
