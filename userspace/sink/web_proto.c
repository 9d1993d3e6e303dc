// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * HTTP request heads and WebSocket frames as the web sink reads them
 * (web_proto.h).  Strict on purpose: the only clients are a browser and
 * tools, so anything outside the plain form of the protocol is refused
 * rather than guessed at.
 */
#include <string.h>
#include <strings.h>

#include "web_proto.h"

/* ---- SHA-1 and base64: the handshake's accept key ---------------------- */

static uint32_t rol32(uint32_t v, unsigned int n)
{
	return (v << n) | (v >> (32 - n));
}

static void sha1_block(uint32_t h[5], const uint8_t *p)
{
	uint32_t w[80], a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];

	for (int i = 0; i < 16; i++)
		w[i] = (uint32_t)p[4 * i] << 24 | (uint32_t)p[4 * i + 1] << 16 |
		       (uint32_t)p[4 * i + 2] << 8 | p[4 * i + 3];
	for (int i = 16; i < 80; i++)
		w[i] = rol32(w[i - 3] ^ w[i - 8] ^ w[i - 14] ^ w[i - 16], 1);
	for (int i = 0; i < 80; i++) {
		uint32_t f, k, t;

		if (i < 20) {
			f = (b & c) | (~b & d);
			k = 0x5a827999;
		} else if (i < 40) {
			f = b ^ c ^ d;
			k = 0x6ed9eba1;
		} else if (i < 60) {
			f = (b & c) | (b & d) | (c & d);
			k = 0x8f1bbcdc;
		} else {
			f = b ^ c ^ d;
			k = 0xca62c1d6;
		}
		t = rol32(a, 5) + f + e + k + w[i];
		e = d;
		d = c;
		c = rol32(b, 30);
		b = a;
		a = t;
	}
	h[0] += a;
	h[1] += b;
	h[2] += c;
	h[3] += d;
	h[4] += e;
}

void rdc_web_sha1(const void *data, size_t len, uint8_t out[20])
{
	uint32_t h[5] = { 0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476,
			  0xc3d2e1f0 };
	const uint8_t *p = data;
	uint8_t last[128] = { 0 };
	uint64_t bits = (uint64_t)len * 8;
	size_t rest, n;

	for (; len >= 64; p += 64, len -= 64)
		sha1_block(h, p);
	rest = len;
	memcpy(last, p, rest);
	last[rest] = 0x80;
	n = rest + 1 + 8 <= 64 ? 64 : 128;
	for (int i = 0; i < 8; i++)
		last[n - 1 - i] = (uint8_t)(bits >> (8 * i));
	sha1_block(h, last);
	if (n == 128)
		sha1_block(h, last + 64);
	for (int i = 0; i < 5; i++) {
		out[4 * i] = (uint8_t)(h[i] >> 24);
		out[4 * i + 1] = (uint8_t)(h[i] >> 16);
		out[4 * i + 2] = (uint8_t)(h[i] >> 8);
		out[4 * i + 3] = (uint8_t)h[i];
	}
}

static const char b64[] =
	"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

void rdc_web_base64(const uint8_t *in, size_t n, char *out)
{
	size_t i;

	for (i = 0; i + 2 < n; i += 3) {
		uint32_t v = (uint32_t)in[i] << 16 | (uint32_t)in[i + 1] << 8 |
			     in[i + 2];

		*out++ = b64[v >> 18];
		*out++ = b64[(v >> 12) & 63];
		*out++ = b64[(v >> 6) & 63];
		*out++ = b64[v & 63];
	}
	if (i < n) {
		uint32_t v = (uint32_t)in[i] << 16;

		if (i + 1 < n)
			v |= (uint32_t)in[i + 1] << 8;
		*out++ = b64[v >> 18];
		*out++ = b64[(v >> 12) & 63];
		*out++ = i + 1 < n ? b64[(v >> 6) & 63] : '=';
		*out++ = '=';
	}
	*out = '\0';
}

bool rdc_web_ws_key_ok(const char *key)
{
	size_t n = strnlen(key, WEB_WS_KEY_LEN + 1);

	if (n != WEB_WS_KEY_LEN || key[22] != '=' || key[23] != '=')
		return false;
	for (size_t i = 0; i < 22; i++)
		if (!key[i] || !strchr(b64, key[i]))
			return false;
	/* 16 bytes end 4 bits into the 22nd character: the rest are 0 */
	return ((strchr(b64, key[21]) - b64) & 15) == 0;
}

#define WEB_WS_GUID "258EAFA5-E914-47DA-95CA-C5AB0DC85B11"

void rdc_web_ws_accept(const char *key, char out[WEB_WS_ACCEPT_SZ])
{
	char buf[WEB_WS_KEY_LEN + sizeof(WEB_WS_GUID)];
	uint8_t sum[20];
	size_t n = strnlen(key, WEB_WS_KEY_LEN);

	memcpy(buf, key, n);
	memcpy(buf + n, WEB_WS_GUID, sizeof(WEB_WS_GUID) - 1);
	rdc_web_sha1(buf, n + sizeof(WEB_WS_GUID) - 1, sum);
	rdc_web_base64(sum, sizeof(sum), out);
}

/* ---- HTTP request heads ------------------------------------------------ */

static bool is_tchar(char c)
{
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
	       (c >= '0' && c <= '9') || (c && strchr("!#$%&'*+-.^_`|~", c));
}

/* Copy a field's value; false if it does not fit. */
static bool field_copy(char *dst, size_t cap, const char *v, size_t n)
{
	if (n >= cap)
		return false;
	memcpy(dst, v, n);
	dst[n] = '\0';
	return true;
}

/* Whether a comma-separated list holds `tok` (any case). */
static bool list_has(const char *v, size_t n, const char *tok)
{
	size_t tl = strlen(tok);

	for (size_t i = 0; i < n;) {
		size_t j = i, k;

		while (j < n && v[j] != ',')
			j++;
		k = j;
		while (i < k && (v[i] == ' ' || v[i] == '\t'))
			i++;
		while (k > i && (v[k - 1] == ' ' || v[k - 1] == '\t'))
			k--;
		if (k - i == tl && !strncasecmp(v + i, tok, tl))
			return true;
		i = j + 1;
	}
	return false;
}

static int req_line(const char *p, size_t n, struct web_req *r)
{
	const char *sp1 = memchr(p, ' ', n), *sp2, *end = p + n, *q;
	size_t plen;

	if (!sp1 || sp1 == p || (size_t)(sp1 - p) >= sizeof(r->method))
		return WEB_REQ_BAD;
	for (q = p; q < sp1; q++)
		if (*q < 'A' || *q > 'Z')
			return WEB_REQ_BAD;
	memcpy(r->method, p, (size_t)(sp1 - p));
	r->method[sp1 - p] = '\0';
	sp2 = memchr(sp1 + 1, ' ', (size_t)(end - sp1 - 1));
	if (!sp2 || sp1[1] != '/')
		return WEB_REQ_BAD;
	for (q = sp1 + 1; q < sp2; q++)
		if (*q <= ' ' || *q > '~')
			return WEB_REQ_BAD;
	if (end - sp2 != 9 || memcmp(sp2 + 1, "HTTP/1.", 7) || sp2[8] < '0' ||
	    sp2[8] > '9')
		return WEB_REQ_BAD;
	r->http_minor = (unsigned int)(sp2[8] - '0');
	plen = (size_t)(sp2 - sp1 - 1);
	q = memchr(sp1 + 1, '?', plen);
	if (q)
		plen = (size_t)(q - sp1 - 1);
	q = memchr(sp1 + 1, '#', plen);
	if (q)
		plen = (size_t)(q - sp1 - 1);
	return field_copy(r->path, sizeof(r->path), sp1 + 1, plen) ?
		       WEB_REQ_OK :
		       WEB_REQ_TOO_BIG;
}

static int req_field(const char *p, size_t n, struct web_req *r)
{
	const char *colon = memchr(p, ':', n), *v, *end = p + n;
	size_t name_len, vlen;

	if (!colon || colon == p)
		return WEB_REQ_BAD;
	for (const char *q = p; q < colon; q++)
		if (!is_tchar(*q))
			return WEB_REQ_BAD;
	name_len = (size_t)(colon - p);
	v = colon + 1;
	while (v < end && (*v == ' ' || *v == '\t'))
		v++;
	while (end > v && (end[-1] == ' ' || end[-1] == '\t'))
		end--;
	vlen = (size_t)(end - v);
	for (const char *q = v; q < end; q++)
		if ((unsigned char)*q < ' ' && *q != '\t')
			return WEB_REQ_BAD;
#define IS(name) \
	(name_len == sizeof(name) - 1 && !strncasecmp(p, name, name_len))
	if (IS("Host")) {
		if (r->has_host)
			return WEB_REQ_BAD;
		r->has_host = true;
		if (!field_copy(r->host, sizeof(r->host), v, vlen))
			return WEB_REQ_TOO_BIG;
	} else if (IS("Origin")) {
		if (r->has_origin)
			return WEB_REQ_BAD;
		r->has_origin = true;
		if (!field_copy(r->origin, sizeof(r->origin), v, vlen))
			return WEB_REQ_TOO_BIG;
	} else if (IS("Sec-WebSocket-Key")) {
		if (r->has_key)
			return WEB_REQ_BAD;
		r->has_key = true;
		if (!field_copy(r->key, sizeof(r->key), v, vlen))
			return WEB_REQ_BAD;
	} else if (IS("Sec-WebSocket-Version")) {
		r->ws_version = vlen == 2 && !memcmp(v, "13", 2) ? 13 : 0;
	} else if (IS("Upgrade")) {
		r->upgrade_ws |= list_has(v, vlen, "websocket");
	} else if (IS("Connection")) {
		r->conn_upgrade |= list_has(v, vlen, "upgrade");
	}
#undef IS
	return WEB_REQ_OK;
}

int rdc_web_req_parse(const char *buf, size_t len, struct web_req *r,
		      size_t *used)
{
	size_t scan = len < WEB_HDR_MAX ? len : WEB_HDR_MAX, pos = 0;
	bool first = true;
	int ret;

	memset(r, 0, sizeof(*r));
	for (;;) {
		const char *p = buf + pos;
		const char *lf = memchr(p, '\n', scan - pos);
		size_t n;

		if (!lf) {
			if (memchr(p, '\0', scan - pos))
				return WEB_REQ_BAD;
			return len >= WEB_HDR_MAX ? WEB_REQ_TOO_BIG :
						    WEB_REQ_MORE;
		}
		n = (size_t)(lf - p);
		if (!n || p[n - 1] != '\r')
			return WEB_REQ_BAD; /* a bare LF */
		n--;
		if (memchr(p, '\0', n) || memchr(p, '\r', n))
			return WEB_REQ_BAD;
		pos += n + 2;
		if (!n) {
			if (first)
				return WEB_REQ_BAD;
			*used = pos;
			return WEB_REQ_OK;
		}
		if (first)
			ret = req_line(p, n, r);
		else if (*p == ' ' || *p == '\t')
			ret = WEB_REQ_BAD; /* obsolete line folding */
		else
			ret = req_field(p, n, r);
		if (ret)
			return ret;
		first = false;
	}
}

/* ---- WebSocket frames -------------------------------------------------- */

int rdc_web_ws_parse(const uint8_t *buf, size_t len, uint64_t max,
		     struct web_ws_frame *f)
{
	size_t need = 2;
	uint64_t n;

	if (len < 2)
		return 0;
	if (buf[0] & 0x70)
		return -WEB_WS_CLOSE_PROTOCOL; /* no extension was agreed */
	f->fin = buf[0] & 0x80;
	f->opcode = buf[0] & 0x0f;
	switch (f->opcode) {
	case WEB_WS_CONT:
	case WEB_WS_TEXT:
	case WEB_WS_BINARY:
		break;
	case WEB_WS_CLOSE:
	case WEB_WS_PING:
	case WEB_WS_PONG:
		if (!f->fin || (buf[1] & 0x7f) > 125)
			return -WEB_WS_CLOSE_PROTOCOL;
		break;
	default:
		return -WEB_WS_CLOSE_PROTOCOL;
	}
	if (!(buf[1] & 0x80))
		return -WEB_WS_CLOSE_PROTOCOL;
	n = buf[1] & 0x7f;
	if (n == 126)
		need += 2;
	else if (n == 127)
		need += 8;
	if (len < need + 4)
		return 0;
	if (n == 126) {
		n = (uint64_t)buf[2] << 8 | buf[3];
		if (n < 126)
			return -WEB_WS_CLOSE_PROTOCOL;
	} else if (n == 127) {
		n = 0;
		for (int i = 0; i < 8; i++)
			n = n << 8 | buf[2 + i];
		if (n >> 63 || n <= 0xffff)
			return -WEB_WS_CLOSE_PROTOCOL;
	}
	if (n > max)
		return -WEB_WS_CLOSE_TOO_BIG;
	memcpy(f->mask, buf + need, 4);
	f->len = n;
	f->hdr_len = need + 4;
	return 1;
}

void rdc_web_ws_unmask(uint8_t *p, size_t n, const uint8_t mask[4],
		       uint64_t off)
{
	for (size_t i = 0; i < n; i++)
		p[i] ^= mask[(off + i) & 3];
}

size_t rdc_web_ws_header(uint8_t out[WEB_WS_HDR_MAX], uint8_t opcode,
			 uint64_t len)
{
	out[0] = (uint8_t)(0x80 | (opcode & 0x0f));
	if (len < 126) {
		out[1] = (uint8_t)len;
		return 2;
	}
	if (len <= 0xffff) {
		out[1] = 126;
		out[2] = (uint8_t)(len >> 8);
		out[3] = (uint8_t)len;
		return 4;
	}
	out[1] = 127;
	for (int i = 0; i < 8; i++)
		out[2 + i] = (uint8_t)(len >> (56 - 8 * i));
	return 10;
}
