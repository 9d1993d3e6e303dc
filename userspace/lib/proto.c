// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Wire protocol encoding and decoding (rdc_proto.h), shared by rdcd and
 * librdc's socket backends.  Decoders trust nothing: every length is
 * checked before a byte is read.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "rdc_proto.h"

void rdc_proto_hdr_encode(uint8_t *p, const struct rdc_proto_hdr *h)
{
	rdc_proto_put32(p, h->len);
	p[4] = (uint8_t)h->type;
	p[5] = (uint8_t)(h->type >> 8);
	p[6] = (uint8_t)h->flags;
	p[7] = (uint8_t)(h->flags >> 8);
	rdc_proto_put32(p + 8, h->seq);
	rdc_proto_put32(p + 12, h->status);
}

void rdc_proto_hdr_decode(const uint8_t *p, struct rdc_proto_hdr *h)
{
	h->len = rdc_proto_get32(p);
	h->type = (uint16_t)(p[4] | p[5] << 8);
	h->flags = (uint16_t)(p[6] | p[7] << 8);
	h->seq = rdc_proto_get32(p + 8);
	h->status = rdc_proto_get32(p + 12);
}

int rdc_proto_hdr_check(const struct rdc_proto_hdr *h, uint32_t max_len)
{
	if (h->len > max_len)
		return RDC_ST_TOOBIG;
	if (h->type == 0 || h->type >= RDC_MSG_TYPE_MAX_ ||
	    (h->type > RDC_MSG_REQUEST_LAST && h->type < RDC_MSG_EV_FRAME))
		return RDC_ST_TYPE;
	return 0;
}

bool rdc_proto_reply_closes(uint32_t type, uint32_t status)
{
	if (status == RDC_ST_TOOBIG)
		return true;
	return type == RDC_MSG_HELLO && status != RDC_ST_OK &&
	       status != RDC_ST_ORDER;
}

int rdc_proto_request_check(const struct rdc_proto_hdr *h)
{
	uint32_t len = h->len;

	if (len > RDC_PROTO_MAX_REQUEST)
		return RDC_ST_TOOBIG;
	switch (h->type) {
	case RDC_MSG_HELLO:
		return len >= RDC_PROTO_HELLO_FIXED ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_REG_READ:
	case RDC_MSG_RESET:
		return len == 4 ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_REG_WRITE:
	case RDC_MSG_VRAM_READ:
	case RDC_MSG_STEP:
	case RDC_MSG_FRAME_GRAB:
	case RDC_MSG_PINS_SET:
		return len == 8 ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_VRAM_WRITE:
		return len >= 4 && len - 4 <= RDC_PROTO_VRAM_CHUNK ?
			       0 :
			       RDC_ST_MALFORMED;
	case RDC_MSG_SUBMIT:
		return !(len & 3) && len / 4 <= RDC_PROTO_MAX_SUBMIT_WORDS ?
			       0 :
			       RDC_ST_MALFORMED;
	case RDC_MSG_WAIT:
		return len == RDC_PROTO_WAIT_SIZE ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_SUBSCRIBE:
		return len == 12 ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_HIST_OPEN:
		return len == RDC_PROTO_HIST_OPEN_SIZE ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_HIST_READ:
		return len == RDC_PROTO_HIST_READ_SIZE ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_HIST_SET:
		return len == RDC_PROTO_HIST_SET_SIZE ? 0 : RDC_ST_MALFORMED;
	case RDC_MSG_STATS:
	case RDC_MSG_CLAIM:
	case RDC_MSG_RELEASE:
	case RDC_MSG_PING:
	case RDC_MSG_HIST_END:
		return len == 0 ? 0 : RDC_ST_MALFORMED;
	default:
		return RDC_ST_TYPE;
	}
}

size_t rdc_proto_hello_encode(uint8_t *p, size_t cap,
			      const struct rdc_proto_hello *h)
{
	size_t n = RDC_PROTO_HELLO_FIXED + h->token_len;

	if (h->token_len > RDC_PROTO_MAX_TOKEN || cap < n)
		return 0;
	rdc_proto_put32(p, h->magic);
	rdc_proto_put32(p + 4, h->version);
	rdc_proto_put32(p + 8, h->caps);
	rdc_proto_put32(p + 12, h->flags);
	rdc_proto_put32(p + 16, h->token_len);
	if (h->token_len)
		memcpy(p + RDC_PROTO_HELLO_FIXED, h->token, h->token_len);
	return n;
}

int rdc_proto_hello_decode(const uint8_t *p, size_t len,
			   struct rdc_proto_hello *h)
{
	if (len < RDC_PROTO_HELLO_FIXED)
		return RDC_ST_MALFORMED;
	h->magic = rdc_proto_get32(p);
	h->version = rdc_proto_get32(p + 4);
	h->caps = rdc_proto_get32(p + 8);
	h->flags = rdc_proto_get32(p + 12);
	h->token_len = rdc_proto_get32(p + 16);
	if (h->magic != RDC_PROTO_MAGIC || h->version != RDC_PROTO_VERSION)
		return RDC_ST_VERSION;
	if (h->token_len > RDC_PROTO_MAX_TOKEN ||
	    len != RDC_PROTO_HELLO_FIXED + h->token_len)
		return RDC_ST_MALFORMED;
	h->token = p + RDC_PROTO_HELLO_FIXED;
	return 0;
}

void rdc_proto_hello_reply_encode(uint8_t *p,
				  const struct rdc_proto_hello_reply *r)
{
	rdc_proto_put32(p, r->version);
	rdc_proto_put32(p + 4, r->caps);
	rdc_proto_put32(p + 8, r->flags);
	rdc_proto_put32(p + 12, r->run_mode);
	rdc_proto_put32(p + 16, r->vram_size);
	rdc_proto_put32(p + 20, r->core_hz);
	rdc_proto_put32(p + 24, r->client_id);
}

int rdc_proto_hello_reply_decode(const uint8_t *p, size_t len,
				 struct rdc_proto_hello_reply *r)
{
	if (len != RDC_PROTO_HELLO_REPLY_SIZE)
		return RDC_ST_MALFORMED;
	r->version = rdc_proto_get32(p);
	r->caps = rdc_proto_get32(p + 4);
	r->flags = rdc_proto_get32(p + 8);
	r->run_mode = rdc_proto_get32(p + 12);
	r->vram_size = rdc_proto_get32(p + 16);
	r->core_hz = rdc_proto_get32(p + 20);
	r->client_id = rdc_proto_get32(p + 24);
	return 0;
}

void rdc_proto_wait_encode(uint8_t *p, const struct rdc_proto_wait *w)
{
	rdc_proto_put64(p, w->budget);
	rdc_proto_put32(p + 8, w->needs_dp);
	for (unsigned int i = 0; i < RDC_PROTO_WAIT_TERMS; i++) {
		uint8_t *t = p + 12 + 16 * i;

		rdc_proto_put32(t, w->term[i].kind);
		rdc_proto_put32(t + 4, w->term[i].reg);
		rdc_proto_put32(t + 8, w->term[i].mask);
		rdc_proto_put32(t + 12, w->term[i].value);
	}
}

int rdc_proto_wait_decode(const uint8_t *p, size_t len,
			  struct rdc_proto_wait *w)
{
	if (len != RDC_PROTO_WAIT_SIZE)
		return RDC_ST_MALFORMED;
	w->budget = rdc_proto_get64(p);
	w->needs_dp = rdc_proto_get32(p + 8);
	for (unsigned int i = 0; i < RDC_PROTO_WAIT_TERMS; i++) {
		const uint8_t *t = p + 12 + 16 * i;

		w->term[i].kind = rdc_proto_get32(t);
		w->term[i].reg = rdc_proto_get32(t + 4);
		w->term[i].mask = rdc_proto_get32(t + 8);
		w->term[i].value = rdc_proto_get32(t + 12);
	}
	return w->needs_dp > 1 ? RDC_ST_INVAL : 0;
}

void rdc_proto_stats_encode(uint8_t *p, const struct rdc_proto_stats *s)
{
	rdc_proto_put64(p, s->time);
	rdc_proto_put64(p + 8, s->busy);
	rdc_proto_put64(p + 16, s->stall);
	rdc_proto_put64(p + 24, s->pixels);
	rdc_proto_put64(p + 32, s->frames);
	rdc_proto_put32(p + 40, s->cmds);
	rdc_proto_put32(p + 44, s->last_cycles);
	rdc_proto_put32(p + 48, s->last_opcode);
	rdc_proto_put32(p + 52, s->clients);
	rdc_proto_put64(p + 56, s->frames_sent);
	rdc_proto_put64(p + 64, s->frames_dropped);
}

int rdc_proto_stats_decode(const uint8_t *p, size_t len,
			   struct rdc_proto_stats *s)
{
	if (len != RDC_PROTO_STATS_SIZE)
		return RDC_ST_MALFORMED;
	s->time = rdc_proto_get64(p);
	s->busy = rdc_proto_get64(p + 8);
	s->stall = rdc_proto_get64(p + 16);
	s->pixels = rdc_proto_get64(p + 24);
	s->frames = rdc_proto_get64(p + 32);
	s->cmds = rdc_proto_get32(p + 40);
	s->last_cycles = rdc_proto_get32(p + 44);
	s->last_opcode = rdc_proto_get32(p + 48);
	s->clients = rdc_proto_get32(p + 52);
	s->frames_sent = rdc_proto_get64(p + 56);
	s->frames_dropped = rdc_proto_get64(p + 64);
	return 0;
}

void rdc_proto_frame_hdr_encode(uint8_t *p, const struct rdc_proto_frame *f)
{
	rdc_proto_put32(p, f->width);
	rdc_proto_put32(p + 4, f->height);
	rdc_proto_put32(p + 8, f->encoding);
	rdc_proto_put32(p + 12, f->dropped);
	rdc_proto_put64(p + 16, f->number);
}

int rdc_proto_frame_hdr_decode(const uint8_t *p, size_t len,
			       struct rdc_proto_frame *f)
{
	if (len < RDC_PROTO_FRAME_HDR)
		return RDC_ST_MALFORMED;
	f->width = rdc_proto_get32(p);
	f->height = rdc_proto_get32(p + 4);
	f->encoding = rdc_proto_get32(p + 8);
	f->dropped = rdc_proto_get32(p + 12);
	f->number = rdc_proto_get64(p + 16);
	if (f->encoding >= RDC_ENC_COUNT_ ||
	    (uint64_t)f->width * f->height > RDC_PROTO_MAX_FRAME_PIXELS)
		return RDC_ST_MALFORMED;
	return 0;
}

void rdc_proto_hist_open_encode(uint8_t *p, const struct rdc_proto_hist_open *o)
{
	rdc_proto_put32(p, o->x);
	rdc_proto_put32(p + 4, o->y);
	rdc_proto_put32(p + 8, o->w);
	rdc_proto_put32(p + 12, o->h);
	rdc_proto_put32(p + 16, o->flags);
}

int rdc_proto_hist_open_decode(const uint8_t *p, size_t len,
			       struct rdc_proto_hist_open *o)
{
	if (len != RDC_PROTO_HIST_OPEN_SIZE)
		return RDC_ST_MALFORMED;
	o->x = rdc_proto_get32(p);
	o->y = rdc_proto_get32(p + 4);
	o->w = rdc_proto_get32(p + 8);
	o->h = rdc_proto_get32(p + 12);
	o->flags = rdc_proto_get32(p + 16);
	return 0;
}

void rdc_proto_hist_page_encode(uint8_t *p,
				const struct rdc_proto_hist_page *pg)
{
	rdc_proto_put64(p, pg->count);
	rdc_proto_put64(p + 8, pg->dropped);
	rdc_proto_put32(p + 16, pg->n);
}

int rdc_proto_hist_page_decode(const uint8_t *p, size_t len, uint32_t max,
			       struct rdc_proto_hist_page *pg)
{
	if (len < RDC_PROTO_HIST_PAGE_HDR)
		return RDC_ST_MALFORMED;
	pg->count = rdc_proto_get64(p);
	pg->dropped = rdc_proto_get64(p + 8);
	pg->n = rdc_proto_get32(p + 16);
	if (pg->n > max || pg->n > RDC_PROTO_HIST_PAGE || pg->n > pg->count ||
	    len - RDC_PROTO_HIST_PAGE_HDR !=
		    (size_t)pg->n * RDC_PROTO_HIST_ENTRY_SIZE)
		return RDC_ST_MALFORMED;
	return 0;
}

void rdc_proto_hist_entry_encode(uint8_t *p,
				 const struct rdc_proto_hist_entry *e)
{
	const uint32_t head[5] = { e->x, e->y, e->format, e->before, e->after };
	const uint32_t mid[7] = { (uint32_t)e->fetched,
				  e->opcode,
				  e->cmd_index,
				  e->source,
				  e->line,
				  e->cmd_addr,
				  e->depth };
	const uint32_t tail[7] = { e->rop,	   e->alpha,   e->colorkey,
				   e->colorkey_on, e->pattern, e->fg,
				   e->bg };
	unsigned int i;

	for (i = 0; i < 5; i++)
		rdc_proto_put32(p + 4 * i, head[i]);
	rdc_proto_put64(p + 20, e->cycle);
	rdc_proto_put64(p + 28, e->frame);
	for (i = 0; i < 7; i++)
		rdc_proto_put32(p + 36 + 4 * i, mid[i]);
	for (i = 0; i < RDC_PROTO_HIST_CALLS; i++)
		rdc_proto_put32(p + 64 + 4 * i, e->calls[i]);
	for (i = 0; i < 7; i++)
		rdc_proto_put32(p + 96 + 4 * i, tail[i]);
}

int rdc_proto_hist_entry_decode(const uint8_t *p,
				struct rdc_proto_hist_entry *e)
{
	unsigned int i;

	e->x = rdc_proto_get32(p);
	e->y = rdc_proto_get32(p + 4);
	e->format = rdc_proto_get32(p + 8);
	e->before = rdc_proto_get32(p + 12);
	e->after = rdc_proto_get32(p + 16);
	e->cycle = rdc_proto_get64(p + 20);
	e->frame = rdc_proto_get64(p + 28);
	e->fetched = (int32_t)rdc_proto_get32(p + 36);
	e->opcode = rdc_proto_get32(p + 40);
	e->cmd_index = rdc_proto_get32(p + 44);
	e->source = rdc_proto_get32(p + 48);
	e->line = rdc_proto_get32(p + 52);
	e->cmd_addr = rdc_proto_get32(p + 56);
	e->depth = rdc_proto_get32(p + 60);
	for (i = 0; i < RDC_PROTO_HIST_CALLS; i++)
		e->calls[i] = rdc_proto_get32(p + 64 + 4 * i);
	e->rop = rdc_proto_get32(p + 96);
	e->alpha = rdc_proto_get32(p + 100);
	e->colorkey = rdc_proto_get32(p + 104);
	e->colorkey_on = rdc_proto_get32(p + 108);
	e->pattern = rdc_proto_get32(p + 112);
	e->fg = rdc_proto_get32(p + 116);
	e->bg = rdc_proto_get32(p + 120);
	if (e->depth > RDC_PROTO_HIST_CALLS || e->source > 3 ||
	    e->fetched < -1 || e->fetched > 1)
		return RDC_ST_MALFORMED;
	return 0;
}

/*
 * Run-length data is a list of runs, each a u32 count (>= 1) and a u32
 * pixel.  RDC_ENC_RLE covers the frame in one list; RDC_ENC_DELTA starts
 * each row with a u32: 0 for "as in the previous frame", else the number
 * of runs that follow and cover the row exactly.
 */
static size_t rle_encode(uint8_t *out, size_t cap, const uint32_t *pix,
			 size_t n, uint32_t *runs)
{
	size_t o = 0;

	*runs = 0;
	for (size_t i = 0; i < n;) {
		size_t j = i + 1;

		while (j < n && pix[j] == pix[i])
			j++;
		if (cap - o < 8)
			return 0;
		rdc_proto_put32(out + o, (uint32_t)(j - i));
		rdc_proto_put32(out + o + 4, pix[i]);
		o += 8;
		(*runs)++;
		i = j;
	}
	return o;
}

size_t rdc_proto_frame_encode(uint8_t *out, size_t cap, uint32_t enc,
			      const uint32_t *pix, const uint32_t *prev,
			      uint32_t w, uint32_t h)
{
	size_t n = (size_t)w * h, o = 0;
	uint32_t runs = 0; /* an empty row (w == 0) has none */

	switch (enc) {
	case RDC_ENC_RAW:
		if (cap < n * 4)
			return 0;
		if (!n)
			return 0;
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
		/* the wire order already: frames are big, skip the loop */
		memcpy(out, pix, n * 4);
#else
		for (size_t i = 0; i < n; i++)
			rdc_proto_put32(out + 4 * i, pix[i]);
#endif
		return n * 4;
	case RDC_ENC_RLE:
		return rle_encode(out, cap, pix, n, &runs);
	case RDC_ENC_DELTA:
		for (uint32_t y = 0; y < h; y++) {
			const uint32_t *row = pix + (size_t)y * w;
			size_t k;

			if (cap - o < 4)
				return 0;
			if (prev &&
			    !memcmp(row, prev + (size_t)y * w, (size_t)w * 4)) {
				rdc_proto_put32(out + o, 0);
				o += 4;
				continue;
			}
			k = w ? rle_encode(out + o + 4, cap - o - 4, row, w,
					   &runs) :
				0;
			if (w && !k)
				return 0;
			rdc_proto_put32(out + o, runs);
			o += 4 + k;
		}
		return o;
	default:
		return 0;
	}
}

/* Decode `runs` runs (or until `n` pixels if runs is 0) into pix[0..n). */
static int rle_decode(uint32_t *pix, size_t n, const uint8_t *d, size_t len,
		      size_t *used, uint32_t runs)
{
	size_t o = 0, i = 0;
	uint32_t r = 0;

	while (runs ? r < runs : i < n) {
		uint32_t count, v;

		if (len - o < 8)
			return -1;
		count = rdc_proto_get32(d + o);
		v = rdc_proto_get32(d + o + 4);
		o += 8;
		if (!count || count > n - i)
			return -1;
		for (uint32_t k = 0; k < count; k++)
			pix[i++] = v;
		r++;
	}
	if (i != n)
		return -1;
	*used = o;
	return 0;
}

int rdc_proto_frame_decode(uint32_t *pix, uint32_t w, uint32_t h, uint32_t enc,
			   const uint8_t *data, size_t len)
{
	size_t n = (size_t)w * h, o = 0, used;

	switch (enc) {
	case RDC_ENC_RAW:
		if (len != n * 4)
			return -1;
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
		if (n)
			memcpy(pix, data, n * 4);
#else
		for (size_t i = 0; i < n; i++)
			pix[i] = rdc_proto_get32(data + 4 * i);
#endif
		return 0;
	case RDC_ENC_RLE:
		if (n == 0)
			return len ? -1 : 0;
		if (rle_decode(pix, n, data, len, &used, 0) || used != len)
			return -1;
		return 0;
	case RDC_ENC_DELTA:
		for (uint32_t y = 0; y < h; y++) {
			uint32_t runs;

			if (len - o < 4)
				return -1;
			runs = rdc_proto_get32(data + o);
			o += 4;
			if (!runs)
				continue;
			/* a row has at most w runs */
			if (runs > w ||
			    rle_decode(pix + (size_t)y * w, w, data + o,
				       len - o, &used, runs))
				return -1;
			o += used;
		}
		return o == len ? 0 : -1;
	default:
		return -1;
	}
}

int rdc_proto_default_path(char *buf, size_t cap)
{
	const char *xdg = getenv("XDG_RUNTIME_DIR");
	int n;

	if (xdg && *xdg)
		n = snprintf(buf, cap, "%s/rdc/rdc.sock", xdg);
	else
		n = snprintf(buf, cap, "/tmp/rdc-%u/rdc.sock",
			     (unsigned int)getuid());
	return n < 0 || (size_t)n >= cap ? -1 : 0;
}
