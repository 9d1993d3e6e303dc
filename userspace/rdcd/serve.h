/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcd's serving of clients, in parts (rdcd.h declares what the loop
 * calls):
 *
 *   serve.c     the device, the clients' lives, reading their requests
 *   dispatch.c  a request to its handler (one table), the plain requests
 *   pending.c   WAIT, STEP and SUBMIT: stepped on the chip, or checked
 *   frames.c    frames to subscribers and sinks, FRAME_GRAB, IRQ events
 *   hist.c      the pixel history (HIST_*)
 *   out.c       the clients' output queues, replies, status codes
 */
#ifndef RDCD_SERVE_H
#define RDCD_SERVE_H

#include "rdcd.h"

/* serve.c */
int rdcd_power_cycle(struct rdcd *d);
/* Connections from listener `lis` that have (not) said HELLO. */
unsigned int rdcd_count_lis(const struct rdcd *d, int lis, bool hello,
			    const struct rdcd_client **oldest);

/* dispatch.c */
/* Registers whose read changes the device (or means nothing). */
bool rdcd_reg_read_changes(uint32_t reg);
bool rdcd_reg_ok(uint32_t reg);
/* The whole request in h and *body (which a handler may take over). */
void rdcd_dispatch(struct rdcd *d, struct rdcd_client *c,
		   const struct rdc_proto_hdr *h, uint8_t **body);
/* Does this request touch the chip (so must wait while it runs a slice)? */
bool rdcd_touches_chip(const struct rdcd *d, const struct rdc_proto_hdr *h,
		       const uint8_t *pl);

/* pending.c */
int rdcd_wait_from_proto(const uint8_t *pl, size_t len, struct rdc_hw_wait *w);
/* Paced and fast modes: progress on c's pending request; true when it
 * finished and was answered. */
bool rdcd_pending_step(struct rdcd *d, struct rdcd_client *c);
/* Before a reset: end the runs and pending requests it replaces. */
void rdcd_reset_pending(struct rdcd *d, struct rdcd_client *c, bool power);

/* frames.c */
/* A DELTA subscriber's copy of the last frame it was sent, gone. */
void rdcd_prev_free(struct rdcd *d, struct rdcd_client *c);
void rdcd_frame_grab(struct rdcd *d, struct rdcd_client *c,
		     const struct rdc_proto_hdr *h, const uint8_t *pl);
/* Rising IRQ_STATUS bits since the last look, to their subscribers. */
void rdcd_irq_events(struct rdcd *d);

/* hist.c */
void rdcd_hist(struct rdcd *d, struct rdcd_client *c,
	       const struct rdc_proto_hdr *h, const uint8_t *pl);

/* out.c */
void rdcd_queue(struct rdcd *d, struct rdcd_client *c, struct rdcd_obuf *b);
/* A message of `payload` bytes, its header to be written. */
struct rdcd_obuf *rdcd_obuf_new(size_t payload);
/* A message gone: its shared part with its last reference. */
void rdcd_obuf_free(struct rdcd_obuf *b);
/* What queueing b adds to d->out_total: a shared frame's pixels count
 * only for the first queue that holds them. */
size_t rdcd_obuf_cost(const struct rdcd_obuf *b);
void rdcd_obuf_hdr(struct rdcd_obuf *b, uint16_t type, uint16_t flags,
		   uint32_t seq, uint32_t status);
/* Everything queued for c, gone (it is being disconnected). */
void rdcd_client_drop_output(struct rdcd *d, struct rdcd_client *c);
/* A reply with `n` payload bytes copied from p (NULL: zeroes); returns
 * where the payload is, or NULL (out of memory: the client is closed). */
uint8_t *rdcd_reply(struct rdcd *d, struct rdcd_client *c,
		    const struct rdc_proto_hdr *req, uint32_t status,
		    const void *p, size_t n);
/* A reply of no payload whose status is librdc error err's (0: OK). */
void rdcd_reply_err(struct rdcd *d, struct rdcd_client *c,
		    const struct rdc_proto_hdr *req, int err);
/* An error after which the stream cannot go on: reply, then hang up. */
void rdcd_fatal(struct rdcd *d, struct rdcd_client *c,
		const struct rdc_proto_hdr *req, uint32_t status);

#endif /* RDCD_SERVE_H */
