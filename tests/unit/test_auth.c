// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The token rule rdcd's tcp: and the web sink share (rdc_auth_*,
 * rdc_server.h), on a clock the test moves: three failures free, then a
 * second refused, doubling up to 64; a success forgets; the least recent
 * address makes room in a full table; the comparison is exact.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "rdc_server.h"

#define S 1000000000ull

static void test_backoff(void **state)
{
	static struct rdc_auth a;
	uint64_t t = 1000 * S;

	(void)state;
	memset(&a, 0, sizeof(a));
	for (int i = 0; i < RDC_AUTH_FREE_FAILS - 1; i++) {
		rdc_auth_failed(&a, "10.0.0.1", t);
		assert_false(rdc_auth_locked(&a, "10.0.0.1", t));
	}
	/* the third: a second */
	rdc_auth_failed(&a, "10.0.0.1", t);
	assert_true(rdc_auth_locked(&a, "10.0.0.1", t));
	assert_true(rdc_auth_locked(&a, "10.0.0.1", t + S - 1));
	assert_false(rdc_auth_locked(&a, "10.0.0.1", t + S));
	/* another address is not touched */
	assert_false(rdc_auth_locked(&a, "10.0.0.2", t));
	/* each further failure doubles, up to 64 s */
	for (uint64_t want = 2; want <= 256; want *= 2) {
		uint64_t w = want > RDC_AUTH_BACKOFF_MAX_S ?
				     RDC_AUTH_BACKOFF_MAX_S :
				     want;

		t += 1000 * S;
		rdc_auth_failed(&a, "10.0.0.1", t);
		assert_true(rdc_auth_locked(&a, "10.0.0.1", t + w * S - 1));
		assert_false(rdc_auth_locked(&a, "10.0.0.1", t + w * S));
	}
	/* a success forgets it all: three free failures again */
	rdc_auth_passed(&a, "10.0.0.1");
	assert_false(rdc_auth_locked(&a, "10.0.0.1", t));
	rdc_auth_failed(&a, "10.0.0.1", t);
	rdc_auth_failed(&a, "10.0.0.1", t);
	assert_false(rdc_auth_locked(&a, "10.0.0.1", t));
}

static void test_table_full(void **state)
{
	static struct rdc_auth a;
	char peer[32];

	(void)state;
	memset(&a, 0, sizeof(a));
	/* "old" fails first, then RDC_AUTH_TABLE - 1 others: the table is
	 * full, and "old" the least recent */
	for (int k = 0; k < RDC_AUTH_FREE_FAILS; k++)
		rdc_auth_failed(&a, "old", 10 * S);
	assert_true(rdc_auth_locked(&a, "old", 10 * S));
	for (int i = 1; i < RDC_AUTH_TABLE; i++) {
		snprintf(peer, sizeof(peer), "p%d", i);
		for (int k = 0; k < RDC_AUTH_FREE_FAILS; k++)
			rdc_auth_failed(&a, peer, 10 * S + (uint64_t)i);
	}
	assert_true(rdc_auth_locked(&a, "old", 10 * S));
	/* a newcomer takes the least recent place: "old"'s */
	rdc_auth_failed(&a, "new", 20 * S);
	assert_false(rdc_auth_locked(&a, "old", 10 * S));
	assert_true(rdc_auth_locked(&a, "p1", 10 * S + 1));
	/* a long address is kept cut to the table's width (not overrun)
	 * and still found: it backs off like any other */
	{
		char lng[2 * RDC_AUTH_PEER_MAX];

		memset(lng, 'x', sizeof(lng) - 1);
		lng[sizeof(lng) - 1] = 0;
		for (int k = 0; k < RDC_AUTH_FREE_FAILS; k++)
			rdc_auth_failed(&a, lng, 30 * S);
		assert_true(rdc_auth_locked(&a, lng, 30 * S));
	}
}

static void test_token_equal(void **state)
{
	const uint8_t tok[] = "s3cret-token";
	size_t n = sizeof(tok) - 1;

	(void)state;
	assert_true(rdc_auth_token_equal(tok, n,
					 (const uint8_t *)"s3cret-token", n));
	/* a prefix, a longer one, one byte off, nothing */
	assert_false(rdc_auth_token_equal(tok, n, tok, n - 1));
	assert_false(rdc_auth_token_equal(
		tok, n, (const uint8_t *)"s3cret-token!", n + 1));
	assert_false(rdc_auth_token_equal(tok, n,
					  (const uint8_t *)"s3cret-tokem", n));
	assert_false(rdc_auth_token_equal(tok, n, NULL, 0));
	/* the empty token is only the empty token */
	assert_true(rdc_auth_token_equal(tok, 0, NULL, 0));
	assert_false(rdc_auth_token_equal(tok, 0, tok, 1));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_backoff),
		cmocka_unit_test(test_table_full),
		cmocka_unit_test(test_token_equal),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
