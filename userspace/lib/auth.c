// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Tokens for servers on the network (rdc_server.h): the comparison, and
 * the back-off of addresses that keep sending wrong ones.
 */
#include <stdio.h>
#include <string.h>

#include "rdc_server.h"

bool rdc_auth_token_equal(const uint8_t *want, size_t len, const uint8_t *got,
			  size_t n)
{
	int diff = n != len;

	/* constant time: the token is a secret */
	for (size_t i = 0; i < len; i++)
		diff |= (i < n ? got[i] : 0) ^ want[i];
	return !diff;
}

/* An address longer than the table's width is known by its first
 * RDC_AUTH_PEER_MAX - 1 characters, as it is kept. */
static struct rdc_auth_peer *auth_find(const struct rdc_auth *a,
				       const char *peer)
{
	for (unsigned int i = 0; i < RDC_AUTH_TABLE; i++)
		if (a->t[i].peer[0] &&
		    !strncmp(a->t[i].peer, peer, RDC_AUTH_PEER_MAX - 1))
			return (struct rdc_auth_peer *)&a->t[i];
	return NULL;
}

bool rdc_auth_locked(const struct rdc_auth *a, const char *peer,
		     uint64_t now_ns)
{
	const struct rdc_auth_peer *p = auth_find(a, peer);

	return p && p->until_ns > now_ns;
}

void rdc_auth_failed(struct rdc_auth *a, const char *peer, uint64_t now_ns)
{
	struct rdc_auth_peer *p = auth_find(a, peer);

	if (!p) {
		p = &a->t[0];
		for (unsigned int i = 1; i < RDC_AUTH_TABLE; i++)
			if (a->t[i].last_ns < p->last_ns)
				p = &a->t[i];
		memset(p, 0, sizeof(*p));
		snprintf(p->peer, sizeof(p->peer), "%s", peer);
	}
	p->last_ns = now_ns;
	if (++p->fails >= RDC_AUTH_FREE_FAILS) {
		uint32_t sh = p->fails - RDC_AUTH_FREE_FAILS;
		uint64_t s = sh >= 6 ? RDC_AUTH_BACKOFF_MAX_S : 1ull << sh;

		p->until_ns = now_ns + s * 1000000000ull;
	}
}

void rdc_auth_passed(struct rdc_auth *a, const char *peer)
{
	struct rdc_auth_peer *p = auth_find(a, peer);

	if (p)
		memset(p, 0, sizeof(*p));
}
