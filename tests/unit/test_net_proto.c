// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Wire protocol encoding (userspace/lib/proto.c): byte layouts written out
 * by hand from docs/protocol.md, limits, and decoders that refuse what
 * does not add up.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc_proto.h"

static void test_header_layout(void **state)
{
	static const uint8_t want[RDC_PROTO_HDR_SIZE] = {
		0x04, 0x03, 0x02, 0x01, /* len */
		0x06, 0x00,		/* type SUBMIT */
		0x01, 0x00,		/* flags REPLY */
		0x78, 0x56, 0x34, 0x12, /* seq */
		0x0b, 0x00, 0x00, 0x00, /* status TOOBIG */
	};
	struct rdc_proto_hdr h = { .len = 0x01020304,
				   .type = RDC_MSG_SUBMIT,
				   .flags = RDC_MSGF_REPLY,
				   .seq = 0x12345678,
				   .status = RDC_ST_TOOBIG },
			     g;
	uint8_t b[RDC_PROTO_HDR_SIZE];

	(void)state;
	rdc_proto_hdr_encode(b, &h);
	assert_memory_equal(b, want, sizeof(want));
	rdc_proto_hdr_decode(b, &g);
	assert_int_equal(g.len, h.len);
	assert_int_equal(g.type, h.type);
	assert_int_equal(g.flags, h.flags);
	assert_int_equal(g.seq, h.seq);
	assert_int_equal(g.status, h.status);
}

static void test_header_check(void **state)
{
	struct rdc_proto_hdr h = { .type = RDC_MSG_PING };

	(void)state;
	assert_int_equal(rdc_proto_hdr_check(&h, 100), 0);
	h.len = 101;
	assert_int_equal(rdc_proto_hdr_check(&h, 100), RDC_ST_TOOBIG);
	h.len = 0;
	for (uint32_t t = 0; t < 70; t++) {
		bool known = (t >= RDC_MSG_HELLO && t <= RDC_MSG_HIST_SET) ||
			     t == RDC_MSG_EV_FRAME || t == RDC_MSG_EV_IRQ;

		h.type = (uint16_t)t;
		assert_int_equal(rdc_proto_hdr_check(&h, 100),
				 known ? 0 : RDC_ST_TYPE);
	}
}

static void test_request_sizes(void **state)
{
	static const struct {
		uint16_t type;
		uint32_t len;
		int want;
	} cases[] = {
		{ RDC_MSG_REG_READ, 4, 0 },
		{ RDC_MSG_REG_READ, 8, RDC_ST_MALFORMED },
		{ RDC_MSG_REG_WRITE, 8, 0 },
		{ RDC_MSG_REG_WRITE, 4, RDC_ST_MALFORMED },
		{ RDC_MSG_VRAM_WRITE, 3, RDC_ST_MALFORMED },
		{ RDC_MSG_VRAM_WRITE, 4, 0 },
		{ RDC_MSG_VRAM_WRITE, 4 + RDC_PROTO_VRAM_CHUNK, 0 },
		{ RDC_MSG_VRAM_WRITE, 5 + RDC_PROTO_VRAM_CHUNK,
		  RDC_ST_MALFORMED },
		{ RDC_MSG_SUBMIT, 0, 0 },
		{ RDC_MSG_SUBMIT, 6, RDC_ST_MALFORMED },
		{ RDC_MSG_SUBMIT, 4 * RDC_PROTO_MAX_SUBMIT_WORDS, 0 },
		{ RDC_MSG_SUBMIT, 4 * RDC_PROTO_MAX_SUBMIT_WORDS + 4,
		  RDC_ST_MALFORMED },
		{ RDC_MSG_WAIT, RDC_PROTO_WAIT_SIZE, 0 },
		{ RDC_MSG_WAIT, RDC_PROTO_WAIT_SIZE - 1, RDC_ST_MALFORMED },
		{ RDC_MSG_PING, 0, 0 },
		{ RDC_MSG_PING, 1, RDC_ST_MALFORMED },
		{ RDC_MSG_PINS_SET, 8, 0 },
		{ RDC_MSG_PINS_SET, 4, RDC_ST_MALFORMED },
		{ RDC_MSG_PINS_SET, 12, RDC_ST_MALFORMED },
		{ RDC_MSG_HIST_OPEN, 20, 0 },
		{ RDC_MSG_HIST_OPEN, 16, RDC_ST_MALFORMED },
		{ RDC_MSG_HIST_OPEN, 24, RDC_ST_MALFORMED },
		{ RDC_MSG_HIST_READ, 12, 0 },
		{ RDC_MSG_HIST_READ, 8, RDC_ST_MALFORMED },
		{ RDC_MSG_HIST_END, 0, 0 },
		{ RDC_MSG_HIST_END, 4, RDC_ST_MALFORMED },
		{ RDC_MSG_HIST_SET, 8, 0 },
		{ RDC_MSG_HIST_SET, 4, RDC_ST_MALFORMED },
		{ RDC_MSG_EV_FRAME, 24, RDC_ST_TYPE },
		{ RDC_MSG_SUBMIT, RDC_PROTO_MAX_REQUEST + 1, RDC_ST_TOOBIG },
	};

	(void)state;
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		struct rdc_proto_hdr h = { .type = cases[i].type,
					   .len = cases[i].len };

		assert_int_equal(rdc_proto_request_check(&h), cases[i].want);
	}
}

/*
 * A pixel history page: each entry field by field at its offset, and a
 * page whose count of entries does not match its length, or exceeds what
 * was asked, refused.
 */
static void test_hist_page(void **state)
{
	struct rdc_proto_hist_entry e = {
		.x = 1, .y = 2, .format = 3, .before = 4, .after = 5,
		.cycle = 0x0102030405060708ull, .frame = 9, .fetched = -1,
		.opcode = 10, .cmd_index = 11, .source = 2, .line = 12,
		.cmd_addr = 13, .depth = 8, .calls = { 20, 21, 22, 23, 24, 25, 26, 27 },
		.rop = 14, .alpha = 15, .colorkey = 16, .colorkey_on = 1,
		.pattern = 3, .fg = 17, .bg = 18,
	}, g;
	struct rdc_proto_hist_page pg = { .count = 5, .dropped = 7, .n = 2 };
	uint8_t b[RDC_PROTO_HIST_PAGE_HDR + 2 * RDC_PROTO_HIST_ENTRY_SIZE];
	uint8_t *q = b + RDC_PROTO_HIST_PAGE_HDR;

	(void)state;
	rdc_proto_hist_page_encode(b, &pg);
	rdc_proto_hist_entry_encode(q, &e);
	rdc_proto_hist_entry_encode(q + RDC_PROTO_HIST_ENTRY_SIZE, &e);
	assert_int_equal(rdc_proto_get64(q + 20), e.cycle);
	assert_int_equal(rdc_proto_get32(q + 36), 0xffffffffu);
	assert_int_equal(rdc_proto_get32(q + 60), 8);
	assert_int_equal(rdc_proto_get32(q + 64 + 28), 27);
	assert_int_equal(rdc_proto_get32(q + 120), 18);
	memset(&g, 0, sizeof(g));
	assert_int_equal(rdc_proto_hist_entry_decode(q, &g), 0);
	assert_memory_equal(&g.calls, &e.calls, sizeof(e.calls));
	assert_int_equal(g.cycle, e.cycle);
	assert_int_equal(g.fetched, -1);
	assert_int_equal(g.bg, 18);
	memset(&pg, 0, sizeof(pg));
	assert_int_equal(rdc_proto_hist_page_decode(b, sizeof(b), 2, &pg), 0);
	assert_int_equal(pg.count, 5);
	assert_int_equal(pg.dropped, 7);
	assert_int_equal(pg.n, 2);
	/* more than asked, cut short, a byte over, shorter than its header */
	assert_int_equal(rdc_proto_hist_page_decode(b, sizeof(b), 1, &pg),
			 RDC_ST_MALFORMED);
	assert_int_equal(rdc_proto_hist_page_decode(b, sizeof(b) - 1, 2, &pg),
			 RDC_ST_MALFORMED);
	assert_int_equal(rdc_proto_hist_page_decode(b, sizeof(b) + 0, 9, &pg),
			 0);
	assert_int_equal(rdc_proto_hist_page_decode(b, 19, 9, &pg),
			 RDC_ST_MALFORMED);
	/* more entries than the history keeps */
	rdc_proto_put64(b, 1);
	assert_int_equal(rdc_proto_hist_page_decode(b, sizeof(b), 2, &pg),
			 RDC_ST_MALFORMED);
	/* a chain deeper than the DP's, an unknown source, a bad fetched */
	rdc_proto_put32(q + 60, 9);
	assert_int_equal(rdc_proto_hist_entry_decode(q, &g), RDC_ST_MALFORMED);
	rdc_proto_put32(q + 60, 0);
	rdc_proto_put32(q + 48, 4);
	assert_int_equal(rdc_proto_hist_entry_decode(q, &g), RDC_ST_MALFORMED);
	rdc_proto_put32(q + 48, 0);
	rdc_proto_put32(q + 36, 2);
	assert_int_equal(rdc_proto_hist_entry_decode(q, &g), RDC_ST_MALFORMED);
}

static void test_hello(void **state)
{
	uint8_t b[RDC_PROTO_HELLO_FIXED + RDC_PROTO_MAX_TOKEN + 1];
	struct rdc_proto_hello h = { .magic = RDC_PROTO_MAGIC,
				     .version = RDC_PROTO_VERSION,
				     .caps = 3,
				     .flags = RDC_HELLO_CONTROL,
				     .token_len = 3,
				     .token = (const uint8_t *)"abc" },
			       g;
	size_t n;

	(void)state;
	n = rdc_proto_hello_encode(b, sizeof(b), &h);
	assert_int_equal(n, RDC_PROTO_HELLO_FIXED + 3);
	/* "RDC1" as bytes */
	assert_memory_equal(b, "RDC1", 4);
	assert_int_equal(rdc_proto_hello_decode(b, n, &g), 0);
	assert_int_equal(g.flags, RDC_HELLO_CONTROL);
	assert_int_equal(g.token_len, 3);
	assert_memory_equal(g.token, "abc", 3);
	/* a token longer than the payload, or than the limit */
	assert_int_equal(rdc_proto_hello_decode(b, n - 1, &g),
			 RDC_ST_MALFORMED);
	rdc_proto_put32(b + 16, RDC_PROTO_MAX_TOKEN + 1);
	assert_int_equal(rdc_proto_hello_decode(b, sizeof(b), &g),
			 RDC_ST_MALFORMED);
	/* wrong magic, wrong version */
	b[0] = 'X';
	assert_int_equal(rdc_proto_hello_decode(b, n, &g), RDC_ST_VERSION);
	b[0] = 'R';
	rdc_proto_put32(b + 4, RDC_PROTO_VERSION + 1);
	assert_int_equal(rdc_proto_hello_decode(b, n, &g), RDC_ST_VERSION);
	assert_int_equal(rdc_proto_hello_decode(b, 5, &g), RDC_ST_MALFORMED);
	/* an oversized token is not encoded */
	h.token_len = RDC_PROTO_MAX_TOKEN + 1;
	assert_int_equal(rdc_proto_hello_encode(b, sizeof(b), &h), 0);
}

static void test_wait_stats(void **state)
{
	struct rdc_proto_wait w = { .budget = 0x1122334455667788ull,
				    .needs_dp = 1,
				    .term = { { 2, 0x14, 0xff, 7 },
					      { 3, 0x18, 1, 1 } } },
			      g;
	struct rdc_proto_stats s = { .time = 1,
				     .busy = 2,
				     .frames = 5,
				     .cmds = 6,
				     .clients = 9,
				     .frames_dropped = 11 },
			       t;
	uint8_t b[RDC_PROTO_STATS_SIZE];

	(void)state;
	rdc_proto_wait_encode(b, &w);
	assert_int_equal(b[0], 0x88);
	assert_int_equal(b[7], 0x11);
	assert_int_equal(b[12], 2); /* first term's kind */
	assert_int_equal(rdc_proto_wait_decode(b, RDC_PROTO_WAIT_SIZE, &g), 0);
	assert_memory_equal(&g.term, &w.term, sizeof(w.term));
	assert_true(g.budget == w.budget);
	b[8] = 2; /* needs_dp must be 0 or 1 */
	assert_int_equal(rdc_proto_wait_decode(b, RDC_PROTO_WAIT_SIZE, &g),
			 RDC_ST_INVAL);
	rdc_proto_stats_encode(b, &s);
	assert_int_equal(rdc_proto_stats_decode(b, sizeof(b), &t), 0);
	assert_true(t.frames == 5 && t.cmds == 6 && t.clients == 9 &&
		    t.frames_dropped == 11 && t.busy == 2);
	assert_int_equal(rdc_proto_stats_decode(b, sizeof(b) - 1, &t),
			 RDC_ST_MALFORMED);
}

static void test_rle_layout(void **state)
{
	const uint32_t pix[4] = { 0xaabbcc, 0xaabbcc, 0xaabbcc, 0x010203 };
	static const uint8_t want[16] = {
		3, 0, 0, 0, 0xcc, 0xbb, 0xaa, 0, /* 3 x 0x00aabbcc */
		1, 0, 0, 0, 0x03, 0x02, 0x01, 0, /* 1 x 0x00010203 */
	};
	uint8_t b[64];
	uint32_t out[4];

	(void)state;
	assert_int_equal(rdc_proto_frame_encode(b, sizeof(b), RDC_ENC_RLE, pix,
						NULL, 4, 1),
			 16);
	assert_memory_equal(b, want, 16);
	assert_int_equal(rdc_proto_frame_decode(out, 4, 1, RDC_ENC_RLE, b, 16),
			 0);
	assert_memory_equal(out, pix, sizeof(pix));
	/* too little room: 0, the caller sends raw */
	assert_int_equal(
		rdc_proto_frame_encode(b, 15, RDC_ENC_RLE, pix, NULL, 4, 1), 0);
	/* runs that overflow the frame, a zero run, trailing bytes */
	b[0] = 4;
	assert_int_equal(rdc_proto_frame_decode(out, 4, 1, RDC_ENC_RLE, b, 16),
			 -1);
	b[0] = 0;
	assert_int_equal(rdc_proto_frame_decode(out, 4, 1, RDC_ENC_RLE, b, 16),
			 -1);
	b[0] = 3;
	assert_int_equal(rdc_proto_frame_decode(out, 4, 1, RDC_ENC_RLE, b, 17),
			 -1);
	assert_int_equal(rdc_proto_frame_decode(out, 4, 1, RDC_ENC_RLE, b, 8),
			 -1);
}

static void test_delta_layout(void **state)
{
	/* 2x2: row 0 unchanged, row 1 changed */
	const uint32_t prev[4] = { 1, 2, 3, 4 }, cur[4] = { 1, 2, 5, 5 };
	static const uint8_t want[16] = {
		0, 0, 0, 0,		/* row 0: as before */
		1, 0, 0, 0,		/* row 1: one run */
		2, 0, 0, 0, 5, 0, 0, 0, /* 2 x 5 */
	};
	uint32_t out[4] = { 1, 2, 3, 4 };
	uint8_t b[64];

	(void)state;
	assert_int_equal(rdc_proto_frame_encode(b, sizeof(b), RDC_ENC_DELTA,
						cur, prev, 2, 2),
			 16);
	assert_memory_equal(b, want, 16);
	assert_int_equal(
		rdc_proto_frame_decode(out, 2, 2, RDC_ENC_DELTA, b, 16), 0);
	assert_memory_equal(out, cur, sizeof(cur));
	/* more runs than pixels in a row */
	b[4] = 3;
	assert_int_equal(
		rdc_proto_frame_decode(out, 2, 2, RDC_ENC_DELTA, b, 16), -1);
}

static void test_frame_roundtrip(void **state)
{
	enum { W = 97, H = 61 };
	static uint32_t a[W * H], prev[W * H], out[W * H];
	static uint8_t b[W * H * 8 + 4 * H];
	uint32_t seed = 12345;

	(void)state;
	for (int round = 0; round < 20; round++) {
		for (size_t i = 0; i < W * H; i++) {
			seed = seed * 1103515245u + 12345u;
			/* runs of various lengths, some rows repeated */
			prev[i] = a[i];
			if ((seed >> 16) % 8 == 0)
				a[i] = (seed >> 8) & 0xffffff;
		}
		for (uint32_t enc = 0; enc < RDC_ENC_COUNT_; enc++) {
			size_t n = rdc_proto_frame_encode(b, sizeof(b), enc, a,
							  prev, W, H);

			assert_true(n > 0);
			memcpy(out, prev, sizeof(out));
			assert_int_equal(rdc_proto_frame_decode(out, W, H, enc,
								b, n),
					 0);
			assert_memory_equal(out, a, sizeof(a));
		}
	}
	assert_int_equal(
		rdc_proto_frame_decode(out, W, H, RDC_ENC_COUNT_, b, 0), -1);
}

static void test_frame_header(void **state)
{
	struct rdc_proto_frame f = { .width = 640,
				     .height = 480,
				     .encoding = RDC_ENC_DELTA,
				     .dropped = 3,
				     .number = 1ull << 40 },
			       g;
	uint8_t b[RDC_PROTO_FRAME_HDR];

	(void)state;
	rdc_proto_frame_hdr_encode(b, &f);
	assert_int_equal(rdc_proto_frame_hdr_decode(b, sizeof(b), &g), 0);
	assert_memory_equal(&f, &g, sizeof(f));
	assert_int_equal(rdc_proto_frame_hdr_decode(b, sizeof(b) - 1, &g),
			 RDC_ST_MALFORMED);
	rdc_proto_put32(b, 4096); /* 4096 x 4096: over the pixel limit */
	rdc_proto_put32(b + 4, 4096);
	assert_int_equal(rdc_proto_frame_hdr_decode(b, sizeof(b), &g),
			 RDC_ST_MALFORMED);
}

static void test_default_path(void **state)
{
	char buf[256];

	(void)state;
	setenv("XDG_RUNTIME_DIR", "/run/user/4242", 1);
	assert_int_equal(rdc_proto_default_path(buf, sizeof(buf)), 0);
	assert_string_equal(buf, "/run/user/4242/rdc/rdc.sock");
	assert_int_equal(rdc_proto_default_path(buf, 10), -1);
	unsetenv("XDG_RUNTIME_DIR");
	assert_int_equal(rdc_proto_default_path(buf, sizeof(buf)), 0);
	assert_true(!strncmp(buf, "/tmp/rdc-", 9));
	assert_non_null(strstr(buf, "/rdc.sock"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_header_layout),
		cmocka_unit_test(test_header_check),
		cmocka_unit_test(test_request_sizes),
		cmocka_unit_test(test_hist_page),
		cmocka_unit_test(test_hello),
		cmocka_unit_test(test_wait_stats),
		cmocka_unit_test(test_rle_layout),
		cmocka_unit_test(test_delta_layout),
		cmocka_unit_test(test_frame_roundtrip),
		cmocka_unit_test(test_frame_header),
		cmocka_unit_test(test_default_path),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
