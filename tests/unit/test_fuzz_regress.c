// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Inputs the fuzz targets (tests/fuzz/) found to misbehave, each kept as
 * a plain test of the fixed behaviour.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "rdc_proto.h"
#include "test_net_common.h"

/*
 * fuzz_proto: a frame of width 0 (and some height) in RDC_ENC_DELTA
 * without a previous frame.  Every row is empty, so every row's run count
 * is 0; the encoder wrote whatever its run counter held from an earlier
 * call (here 3, from the 3x1 frame before), and the decoder rightly
 * refused the result.
 */
static void test_delta_empty_rows(void **state)
{
	const uint32_t pix[3] = { 1, 2, 3 };
	uint8_t out[64], out0[64];
	uint32_t back[1];
	size_t n0, n;

	(void)state;
	memset(out, 0xee, sizeof(out));
	/* back to back: the second call finds the first one's stack */
	n0 = rdc_proto_frame_encode(out0, sizeof(out0), RDC_ENC_DELTA, pix,
				    NULL, 3, 1);
	n = rdc_proto_frame_encode(out, sizeof(out), RDC_ENC_DELTA, pix, NULL,
				   0, 3);
	assert_int_equal(n0, 4 + 3 * 8);
	assert_int_equal(n, 3 * 4);
	for (unsigned int y = 0; y < 3; y++)
		assert_int_equal(rdc_proto_get32(out + 4 * y), 0);
	assert_int_equal(
		rdc_proto_frame_decode(back, 0, 3, RDC_ENC_DELTA, out, n), 0);
}

/*
 * fuzz_rdcd: a header over the size limit read (one request ahead) while
 * a STEP was pending.  The daemon answered it RDC_ST_TOOBIG at once and
 * hung up: a reply out of request order, and none for the STEP.  Now the
 * STEP is answered first, then the oversized request, then the daemon
 * hangs up.
 */
static void test_toobig_behind_pending(void **state)
{
	static const char *const args[] = { "-q", NULL }; /* paced */
	struct rdc_proto_hdr big = { .len = RDC_PROTO_MAX_REQUEST + 1,
				     .type = RDC_MSG_VRAM_WRITE,
				     .seq = 2 };
	uint8_t step[8], hb[RDC_PROTO_HDR_SIZE];
	struct rdc_proto_hdr h;
	struct netd d;
	int fd;

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, RDC_HELLO_CONTROL, NULL, NULL),
			 RDC_ST_OK);
	/* half a simulated second: pending for as long on the wall clock */
	rdc_proto_put64(step, 50000000u);
	assert_int_equal(netd_send(fd, RDC_MSG_STEP, 1, step, sizeof(step)), 0);
	rdc_proto_hdr_encode(hb, &big);
	assert_int_equal(netd_write(fd, hb, sizeof(hb)), 0);
	assert_int_equal(netd_reply(fd, &h, NULL, 0), 0);
	assert_int_equal(h.type, RDC_MSG_STEP);
	assert_int_equal(h.seq, 1);
	assert_int_equal(h.status, RDC_ST_OK);
	assert_int_equal(netd_reply(fd, &h, NULL, 0), 0);
	assert_int_equal(h.type, RDC_MSG_VRAM_WRITE);
	assert_int_equal(h.seq, 2);
	assert_int_equal(h.status, RDC_ST_TOOBIG);
	assert_true(netd_closed(fd));
	close(fd);
	assert_int_equal(netd_stop(&d), 0);
}

/*
 * fuzz_rdcd: a RESET of an unknown kind read one request ahead of a
 * pending STEP.  A RESET may overtake what is pending (it ends it, the
 * pending request answered first with RDC_ST_RESET); this one was
 * answered RDC_ST_INVAL at once, before the STEP: out of request order.
 * Now it waits its turn like any other request.
 */
static void test_bad_reset_behind_pending(void **state)
{
	static const char *const args[] = { "-q", NULL }; /* paced */
	uint8_t step[8], kind[4];
	struct rdc_proto_hdr h;
	struct netd d;
	int fd;

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, RDC_HELLO_CONTROL, NULL, NULL),
			 RDC_ST_OK);
	rdc_proto_put64(step, 50000000u); /* half a simulated second */
	rdc_proto_put32(kind, 7);
	assert_int_equal(netd_send(fd, RDC_MSG_STEP, 1, step, sizeof(step)), 0);
	assert_int_equal(netd_send(fd, RDC_MSG_RESET, 2, kind, sizeof(kind)),
			 0);
	assert_int_equal(netd_reply(fd, &h, NULL, 0), 0);
	assert_int_equal(h.type, RDC_MSG_STEP);
	assert_int_equal(h.seq, 1);
	assert_int_equal(h.status, RDC_ST_OK);
	assert_int_equal(netd_reply(fd, &h, NULL, 0), 0);
	assert_int_equal(h.type, RDC_MSG_RESET);
	assert_int_equal(h.seq, 2);
	assert_int_equal(h.status, RDC_ST_INVAL);
	/* and the connection goes on */
	assert_int_equal(netd_call(fd, RDC_MSG_PING, 3, NULL, 0, NULL, 0),
			 RDC_ST_OK);
	close(fd);
	assert_int_equal(netd_stop(&d), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_delta_empty_rows),
		cmocka_unit_test(test_toobig_behind_pending),
		cmocka_unit_test(test_bad_reset_behind_pending),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
