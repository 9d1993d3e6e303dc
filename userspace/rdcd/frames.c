// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: frames and interrupts fanned out.  Every frame the chip completes
 * goes to each subscriber (raw, RLE or DELTA, at its own rate, dropped
 * for a slow reader alone) and to the frame sinks; FRAME_GRAB takes the
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

static void rdcd_frame_to_client(struct rdcd *d, struct rdcd_client *c,
				 const uint32_t *xrgb, uint32_t w, uint32_t h,
				 uint64_t number)
{
	struct rdc_proto_frame f = { .number = number };
	const uint32_t *prev = NULL;
	struct rdcd_obuf *b;
	size_t px = (size_t)w * h;
	uint32_t enc = c->sub_enc;

	if (c->dead || !(c->sub_events & RDC_SUB_FRAMES))
		return;
	if (c->frame_tick++ % c->sub_every)
		return;
	/*
	 * A slow reader loses frames, alone: the device never waits.  A
	 * queue already holding its share of replies takes no frame either,
	 * nor one that would take everyone's queues over their bound.
	 */
	if (c->out_frames >= RDCD_MAX_QUEUED_FRAMES ||
	    (c->out_head && c->out_bytes >= RDCD_OUT_HIGH) ||
	    d->out_total >= RDCD_OUT_TOTAL) {
		c->frames_dropped++;
		return;
	}
	if (enc == RDC_ENC_DELTA) {
		if (c->prev && (c->prev_w != w || c->prev_h != h))
			rdcd_prev_free(d, c);
		if (c->prev) {
			prev = c->prev;
		} else if (d->prev_total + px * 4 > RDCD_PREV_TOTAL) {
			/* no room for another base: this frame in RLE */
			enc = RDC_ENC_RLE;
		} else {
			c->prev = malloc(px * 4 + 4);
			if (!c->prev) {
				c->frames_dropped++;
				return;
			}
			c->prev_bytes = px * 4;
			d->prev_total += c->prev_bytes;
		}
	}
	f.dropped = (uint32_t)c->frames_dropped;
	b = rdcd_frame_msg(xrgb, prev, w, h, enc, &f);
	if (!b || d->out_total + b->len > RDCD_OUT_TOTAL) {
		free(b);
		c->frames_dropped++;
		return;
	}
	if (enc == RDC_ENC_DELTA) {
		memcpy(c->prev, xrgb, px * 4);
		c->prev_w = w;
		c->prev_h = h;
	}
	rdcd_obuf_hdr(b, RDC_MSG_EV_FRAME, RDC_MSGF_EVENT, 0, RDC_ST_OK);
	b->frame = true;
	rdcd_queue(d, c, b);
	c->frames_sent++;
	rdcd_log(d, RDCD_LOG_DEBUG, "client %u: frame %llu queued", c->id,
		 (unsigned long long)number);
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

	d->frames++;
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		rdcd_frame_to_client(d, c, xrgb, w, h, number);
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
