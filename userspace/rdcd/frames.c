// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: frames and interrupts fanned out.  Every frame the chip completes
 * goes to each subscriber (raw, RLE or DELTA, at its own rate, dropped
 * for a slow reader alone; one RAW and one RLE encoding shared by all)
 * and to the frame sinks; FRAME_GRAB takes the
 * last one; rising IRQ_STATUS bits become events.
 */
#include <stdlib.h>
#include <string.h>

#include "serve.h"

/*
 * A frame message (event or FRAME_GRAB reply) in `enc`, falling back to
 * raw when compression would not be smaller.  NULL if out of memory.
 */
static struct rdcd_obuf *rdcd_frame_msg(const uint32_t *pix,
					const uint32_t *prev, uint32_t w,
					uint32_t h, uint32_t enc,
					struct rdc_proto_frame *f)
{
	size_t raw = (size_t)w * h * 4, n;
	struct rdcd_obuf *b = rdcd_obuf_new(RDC_PROTO_FRAME_HDR + raw);
	uint8_t *data;

	if (!b)
		return NULL;
	data = b->data + RDC_PROTO_HDR_SIZE + RDC_PROTO_FRAME_HDR;
	n = enc == RDC_ENC_RAW ?
		    0 :
		    rdc_proto_frame_encode(data, raw, enc, pix, prev, w, h);
	if (!n) {
		enc = RDC_ENC_RAW;
		n = rdc_proto_frame_encode(data, raw, enc, pix, NULL, w, h);
	}
	f->width = w;
	f->height = h;
	f->encoding = enc;
	rdc_proto_frame_hdr_encode(b->data + RDC_PROTO_HDR_SIZE, f);
	b->len = RDC_PROTO_HDR_SIZE + RDC_PROTO_FRAME_HDR + n;
	b->hlen = b->len;
	if (n < raw) {
		struct rdcd_obuf *s = realloc(b, sizeof(*b) + b->len);

		if (s)
			b = s;
	}
	return b;
}

/* A DELTA subscriber's copy of the last frame it was sent, gone. */
void rdcd_prev_free(struct rdcd *d, struct rdcd_client *c)
{
	free(c->prev);
	c->prev = NULL;
	d->prev_total -= c->prev_bytes;
	c->prev_bytes = 0;
}

/* The bytes of a frame event before its pixels. */
#define RDCD_FRAME_HDRS (RDC_PROTO_HDR_SIZE + RDC_PROTO_FRAME_HDR)

/*
 * The frame being handed out.  Its RAW and RLE encodings are made at
 * most once, for the first subscriber that takes one, and shared by all
 * the others; each holds a reference of its own until all are served.
 */
struct rdcd_frame_out {
	const uint32_t *xrgb;
	uint32_t w, h;
	uint64_t number;
	struct rdcd_shared *enc[RDC_ENC_DELTA];
};

/* The frame in `enc` (RAW or RLE), encoded now if nobody took it yet. */
static struct rdcd_shared *
rdcd_shared_get(struct rdcd *d, struct rdcd_frame_out *o, uint32_t enc)
{
	size_t raw = (size_t)o->w * o->h * 4, n = 0;
	struct rdcd_shared *s = o->enc[enc];

	if (s)
		return s;
	s = malloc(sizeof(*s) + raw);
	if (!s)
		return NULL;
	d->sub_encodings++;
	s->enc = enc;
	if (enc != RDC_ENC_RAW)
		n = rdc_proto_frame_encode(s->data, raw, enc, o->xrgb, NULL,
					   o->w, o->h);
	if (!n) {
		s->enc = RDC_ENC_RAW;
		n = rdc_proto_frame_encode(s->data, raw, RDC_ENC_RAW, o->xrgb,
					   NULL, o->w, o->h);
	}
	s->len = n;
	s->refs = 1;
	s->queued = 0;
	if (n < raw) {
		struct rdcd_shared *t = realloc(s, sizeof(*s) + n);

		if (t)
			s = t;
	}
	o->enc[enc] = s;
	return s;
}

/* A frame event whose pixels are s's, one more reference to them. */
static struct rdcd_obuf *rdcd_frame_shared_msg(struct rdcd_shared *s,
					       struct rdc_proto_frame *f)
{
	struct rdcd_obuf *b = rdcd_obuf_new(RDC_PROTO_FRAME_HDR);

	if (!b)
		return NULL;
	f->encoding = s->enc;
	rdc_proto_frame_hdr_encode(b->data + RDC_PROTO_HDR_SIZE, f);
	b->len = b->hlen + s->len;
	b->shared = s;
	s->refs++;
	return b;
}

static void rdcd_frame_to_client(struct rdcd *d, struct rdcd_client *c,
				 struct rdcd_frame_out *o)
{
	struct rdc_proto_frame f = { .number = o->number,
				     .width = o->w,
				     .height = o->h };
	const uint32_t *prev = NULL;
	struct rdcd_obuf *b;
	size_t px = (size_t)o->w * o->h;
	uint32_t enc = c->sub_enc;

	if (c->dead || !(c->sub_events & RDC_SUB_FRAMES))
		return;
	if (c->frame_tick++ % c->sub_every)
		return;
	/*
	 * A slow reader loses frames, alone: the device never waits.  A
	 * queue already holding its share of replies takes no frame either,
	 * nor one that would take everyone's queues over their bound.  All
	 * this is known before any work is done for this subscriber.
	 */
	if (c->out_frames >= RDCD_MAX_QUEUED_FRAMES ||
	    (c->out_head && c->out_bytes >= RDCD_OUT_HIGH) ||
	    d->out_total + RDCD_FRAME_HDRS > RDCD_OUT_TOTAL)
		goto drop;
	if (enc == RDC_ENC_DELTA) {
		if (c->prev && (c->prev_w != o->w || c->prev_h != o->h))
			rdcd_prev_free(d, c);
		if (c->prev) {
			prev = c->prev;
		} else if (d->prev_total + px * 4 > RDCD_PREV_TOTAL) {
			/* no room for another base: this frame in RLE */
			enc = RDC_ENC_RLE;
		} else {
			c->prev = malloc(px * 4 + 4);
			if (!c->prev)
				goto drop;
			c->prev_bytes = px * 4;
			d->prev_total += c->prev_bytes;
		}
	}
	f.dropped = (uint32_t)c->frames_dropped;
	if (enc == RDC_ENC_DELTA) {
		/* a base of its own, so an encoding of its own */
		d->sub_encodings++;
		b = rdcd_frame_msg(o->xrgb, prev, o->w, o->h, enc, &f);
		if (!b || d->out_total + b->len > RDCD_OUT_TOTAL) {
			free(b);
			goto drop;
		}
		memcpy(c->prev, o->xrgb, px * 4);
		c->prev_w = o->w;
		c->prev_h = o->h;
	} else {
		struct rdcd_shared *s = rdcd_shared_get(d, o, enc);

		if (!s)
			goto drop;
		b = rdcd_frame_shared_msg(s, &f);
		if (!b)
			goto drop;
		if (d->out_total + rdcd_obuf_cost(b) > RDCD_OUT_TOTAL) {
			rdcd_obuf_free(b);
			goto drop;
		}
	}
	rdcd_obuf_hdr(b, RDC_MSG_EV_FRAME, RDC_MSGF_EVENT, 0, RDC_ST_OK);
	b->frame = true;
	rdcd_queue(d, c, b);
	c->frames_sent++;
	d->sub_queued++;
	rdcd_log(d, RDCD_LOG_DEBUG, "client %u: frame %llu queued", c->id,
		 (unsigned long long)o->number);
	return;
drop:
	c->frames_dropped++;
	d->sub_dropped++;
}

/* Sinks never stall the device: they drop what they cannot take. */
static void rdcd_frame_to_sinks(struct rdcd *d, const uint32_t *xrgb,
				uint32_t w, uint32_t h, uint64_t number)
{
	struct rdc_timing tm, *t = &tm;
	struct rdc_frame f = { .xrgb = xrgb,
			       .width = w,
			       .height = h,
			       .stride = w,
			       .seq = number };

	rdc_hw_timing(d->hw, t);
	if (rdc_sink_interval_timing(t->h_total, t->v_total, t->pixclk_khz,
				     &f.interval_num, &f.interval_den))
		f.interval_num = f.interval_den = 0;
	for (unsigned int i = 0; i < d->nsinks; i++) {
		int ret = rdc_sink_frame(d->sinks[i], &f);

		if (ret)
			rdcd_log(d, RDCD_LOG_WARN, "%s sink: frame %llu: %s",
				 rdc_sink_kind(d->sinks[i]),
				 (unsigned long long)number, rdc_strerror(ret));
	}
}

/*
 * THE frame path: the chip calls this with every frame it completes, at
 * the start of vertical blanking.  Everything that consumes frames
 * (subscribers; frame sinks) is fed from here.
 */
static void rdcd_on_frame(void *ctx, const uint32_t *xrgb, uint32_t w,
			  uint32_t h, uint64_t number)
{
	struct rdcd *d = ctx;
	struct rdcd_frame_out o = {
		.xrgb = xrgb, .w = w, .h = h, .number = number
	};

	d->frames++;
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		rdcd_frame_to_client(d, c, &o);
	for (unsigned int i = 0; i < RDC_ENC_DELTA; i++)
		if (o.enc[i] && !--o.enc[i]->refs)
			free(o.enc[i]);
	if (d->nsinks)
		rdcd_frame_to_sinks(d, xrgb, w, h, number);
}

void rdcd_watch(struct rdcd *d)
{
	bool on = d->nclients || d->nsinks;

	if (!d->hw || on == d->watched)
		return;
	rdc_hw_set_frame_fn(d->hw, on ? rdcd_on_frame : NULL, d);
	d->watched = on;
}

void rdcd_frame_grab(struct rdcd *d, struct rdcd_client *c,
		     const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	uint32_t enc = rdc_proto_get32(pl), max = rdc_proto_get32(pl + 4);
	uint32_t w = 0, ht = 0;
	const uint32_t *pix = rdc_hw_frame(d->hw, &w, &ht);
	/* FRAME_COUNT counts the frame that just completed */
	struct rdc_proto_frame f = {
		.number = rdc_hw_read(d->hw, RDC_REG_FRAME_COUNT) - 1u
	};
	struct rdcd_obuf *b;
	uint8_t fh[RDC_PROTO_FRAME_HDR];

	if (enc >= RDC_ENC_COUNT_) {
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	if (!pix) {
		rdcd_reply(d, c, h, RDC_ST_NOFRAME, NULL, 0);
		return;
	}
	if ((uint64_t)w * ht > max) {
		f.width = w;
		f.height = ht;
		rdc_proto_frame_hdr_encode(fh, &f);
		rdcd_reply(d, c, h, RDC_ST_RANGE, fh, sizeof(fh));
		return;
	}
	b = rdcd_frame_msg(pix, NULL, w, ht, enc, &f);
	if (!b) {
		rdcd_reply_err(d, c, h, RDC_E_NOMEM);
		return;
	}
	rdcd_obuf_hdr(b, h->type, RDC_MSGF_REPLY, h->seq, RDC_ST_OK);
	rdcd_queue(d, c, b);
}

void rdcd_irq_events(struct rdcd *d)
{
	uint32_t st = rdc_hw_read(d->hw, RDC_REG_IRQ_STATUS);
	uint32_t rising = st & ~d->last_irq;
	uint8_t ev[12];

	d->last_irq = st;
	if (!rising)
		return;
	rdc_proto_put32(ev, rising);
	rdc_proto_put64(ev + 4, rdc_hw_now(d->hw));
	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		struct rdcd_obuf *b;

		if (c->dead || !(c->sub_events & RDC_SUB_IRQ))
			continue;
		/* small, but bounded all the same */
		if (c->out_bytes > RDCD_OUT_HIGH)
			continue;
		b = rdcd_obuf_new(sizeof(ev));
		if (!b)
			continue;
		rdcd_obuf_hdr(b, RDC_MSG_EV_IRQ, RDC_MSGF_EVENT, 0, RDC_ST_OK);
		memcpy(b->data + RDC_PROTO_HDR_SIZE, ev, sizeof(ev));
		rdcd_queue(d, c, b);
	}
}
