// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target: the web sink's parsers (userspace/sink/web_proto.c)
 * on whatever a client could send.  The first byte picks the parser: a
 * request head (and the handshake key it carries), or a run of WebSocket
 * frames walked as the sink walks them, each payload unmasked in place.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "web_proto.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_WS_MAX 1024

static void fuzz_req(const uint8_t *data, size_t size)
{
	struct web_req r;
	char accept[WEB_WS_ACCEPT_SZ];
	size_t used = 0;
	/* a copy of exactly `size` bytes: reads past it are caught */
	char *buf = malloc(size ? size : 1);

	if (!buf)
		return;
	memcpy(buf, data, size);
	if (rdc_web_req_parse(buf, size, &r, &used) == WEB_REQ_OK) {
		if (used > size || !used)
			abort();
		if (r.path[0] != '/' || strlen(r.path) >= sizeof(r.path))
			abort();
		if (r.has_key && rdc_web_ws_key_ok(r.key))
			rdc_web_ws_accept(r.key, accept);
	}
	free(buf);
}

static void fuzz_ws(const uint8_t *data, size_t size)
{
	uint8_t *buf = malloc(size ? size : 1);
	size_t off = 0;

	if (!buf)
		return;
	memcpy(buf, data, size);
	for (;;) {
		struct web_ws_frame f;
		int ret = rdc_web_ws_parse(buf + off, size - off, FUZZ_WS_MAX,
					   &f);

		if (ret <= 0)
			break;
		if (f.len > FUZZ_WS_MAX || f.hdr_len > WEB_WS_HDR_MAX)
			abort();
		if (size - off < f.hdr_len + f.len)
			break;
		rdc_web_ws_unmask(buf + off + f.hdr_len, (size_t)f.len, f.mask,
				  0);
		off += f.hdr_len + (size_t)f.len;
	}
	free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (!size)
		return 0;
	if (data[0] & 1)
		fuzz_ws(data + 1, size - 1);
	else
		fuzz_req(data + 1, size - 1);
	return 0;
}
