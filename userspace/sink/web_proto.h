/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The web sink's side of HTTP/1.1 and WebSocket (RFC 6455): the parts it
 * reads from a client, as pure functions over a buffer (no I/O), so that
 * they can be tested and fuzzed alone.  Everything a client sends is
 * capped: a request head at WEB_HDR_MAX bytes, each field the sink keeps
 * at its array's size, a WebSocket message at the caller's cap.
 */
#ifndef RDC_WEB_PROTO_H
#define RDC_WEB_PROTO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The longest request head (request line and header fields) taken. */
#define WEB_HDR_MAX	 8192
#define WEB_PATH_MAX	 256
#define WEB_FIELD_MAX	 256
#define WEB_WS_KEY_LEN	 24 /* base64 of 16 bytes */
#define WEB_WS_ACCEPT_SZ 29 /* base64 of a SHA-1, and a NUL */
/* A WebSocket frame header: 2 bytes, 8 of length, 4 of mask at most. */
#define WEB_WS_HDR_MAX 14

struct web_req {
	char method[8];
	char path[WEB_PATH_MAX]; /* the target without its query */
	char host[WEB_FIELD_MAX];
	char origin[WEB_FIELD_MAX];
	char key[WEB_WS_KEY_LEN + 1];
	bool has_host, has_origin, has_key;
	bool upgrade_ws;   /* Upgrade: websocket */
	bool conn_upgrade; /* Connection: ..., upgrade, ... */
	unsigned int ws_version;
	unsigned int http_minor; /* HTTP/1.x */
};

enum web_req_result {
	WEB_REQ_OK = 0,
	WEB_REQ_MORE = 1,     /* no end of the head yet */
	WEB_REQ_BAD = -1,     /* malformed: 400 */
	WEB_REQ_TOO_BIG = -2, /* head or a kept field too long: 431 */
};

/*
 * Parse a request head from buf[0..len).  WEB_REQ_OK with *used the
 * head's bytes (up to and with the blank line), WEB_REQ_MORE while no
 * blank line has come in WEB_HDR_MAX bytes, else an error.  Lines end in
 * CRLF; a NUL, a bare CR or LF, a folded line, a second Host, a field
 * name that is not a token or a target that does not start with '/' make
 * it malformed.
 */
int rdc_web_req_parse(const char *buf, size_t len, struct web_req *r,
		      size_t *used);

/* Whether a Sec-WebSocket-Key is 24 characters of base64 for 16 bytes. */
bool rdc_web_ws_key_ok(const char *key);
/* Sec-WebSocket-Accept for a key: base64(SHA-1(key GUID)). */
void rdc_web_ws_accept(const char *key, char out[WEB_WS_ACCEPT_SZ]);

/* SHA-1 (FIPS 180-4) of a buffer; the handshake's only use of it. */
void rdc_web_sha1(const void *data, size_t len, uint8_t out[20]);
/* Base64 (RFC 4648) of n bytes into out (4 * ((n + 2) / 3) + 1 bytes). */
void rdc_web_base64(const uint8_t *in, size_t n, char *out);

enum web_ws_opcode {
	WEB_WS_CONT = 0x0,
	WEB_WS_TEXT = 0x1,
	WEB_WS_BINARY = 0x2,
	WEB_WS_CLOSE = 0x8,
	WEB_WS_PING = 0x9,
	WEB_WS_PONG = 0xa,
};

/* Close codes (RFC 6455 7.4.1) and the sink's own. */
#define WEB_WS_CLOSE_NORMAL   1000
#define WEB_WS_CLOSE_GOING    1001
#define WEB_WS_CLOSE_PROTOCOL 1002
#define WEB_WS_CLOSE_TOO_BIG  1009
#define WEB_WS_CLOSE_AUTH     4001 /* the token was wrong */
#define WEB_WS_CLOSE_TIMEOUT  4002 /* no hello in time */

struct web_ws_frame {
	bool fin;
	uint8_t opcode;
	uint8_t mask[4];
	uint64_t len;	/* payload bytes */
	size_t hdr_len; /* header bytes before the payload */
};

/*
 * Parse a client's frame header from buf[0..len): 1 with *f set, 0 when
 * more bytes are needed, or minus a close code: WEB_WS_CLOSE_PROTOCOL
 * for reserved bits, an unknown opcode, an unmasked frame (a client must
 * mask), a fragmented or long (> 125) control frame, a length not in its
 * shortest form or with the top bit set; WEB_WS_CLOSE_TOO_BIG for a
 * payload over max.
 */
int rdc_web_ws_parse(const uint8_t *buf, size_t len, uint64_t max,
		     struct web_ws_frame *f);
/* Unmask n payload bytes that start `off` bytes into the payload. */
void rdc_web_ws_unmask(uint8_t *p, size_t n, const uint8_t mask[4],
		       uint64_t off);
/* A server's (unmasked, final) frame header for a payload; its length. */
size_t rdc_web_ws_header(uint8_t out[WEB_WS_HDR_MAX], uint8_t opcode,
			 uint64_t len);

/* The page's files (web/), built into the library (web_page.c). */
struct web_file {
	const char *path; /* "/", "/rdc.js", ... */
	const char *type; /* Content-Type */
	const uint8_t *data;
	size_t len;
};

/* The file at a request's path into *f; false for any other path (no
 * listing, no file system). */
bool rdc_web_page_find(const char *path, struct web_file *f);

#endif /* RDC_WEB_PROTO_H */
