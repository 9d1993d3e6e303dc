/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The message-level client of the rdcd protocol (rdc_proto.h), in net.c,
 * and the byte transports it runs over: a stream socket (unix:, tcp:, in
 * net_sock.c) and a USB interface's bulk endpoints (usb:, in usb.c).  The
 * client does HELLO, requests and replies, events, frame decoding and the
 * status mapping; a transport only moves bytes.
 */
#ifndef RDC_CLIENT_H
#define RDC_CLIENT_H

#include <stdbool.h>
#include <sys/types.h>
#include <sys/uio.h>

#include "rdc_priv.h"
#include "rdc_proto.h"

struct rdc_xport;

struct rdc_xport_ops {
	/* Write every byte of the n buffers: 0 or a negative rdc_error. */
	int (*send)(struct rdc_xport *x, const struct iovec *iov, int n);
	/*
	 * Read 1..len bytes, waiting up to timeout_ms of wall time (< 0:
	 * until bytes come or the transport fails): the count,
	 * RDC_E_TIMEOUT, or another negative rdc_error (RDC_E_GONE when the
	 * device went away).
	 */
	ssize_t (*recv)(struct rdc_xport *x, void *buf, size_t len,
			int timeout_ms);
	/* Disconnect and free x. */
	void (*close)(struct rdc_xport *x);
};

struct rdc_xport {
	const struct rdc_xport_ops *ops;
	/*
	 * Largest request payload the other side takes (0: the protocol's
	 * RDC_PROTO_MAX_REQUEST); VRAM writes and submits are split to fit.
	 */
	uint32_t max_request;
};

/* URI options after '?', joined by '&': "observe", "token=FILE". */
struct rdc_client_opts {
	char token_file[256];
	bool observe;
};

/* Parse `q` (may be NULL or empty): 0 or RDC_E_URI. */
int rdc_client_parse_opts(const char *q, struct rdc_client_opts *o);

/*
 * Say HELLO over x and hang the client off dev->priv, which then owns x.
 * On failure x is closed and the error returned.
 */
int rdc_client_open(rdc_dev *dev, struct rdc_xport *x,
		    const struct rdc_client_opts *o);
/* The daemon's HELLO reply (run mode, VRAM size...) of an open client. */
const struct rdc_proto_hello_reply *rdc_client_hello(rdc_dev *dev);

void rdc_client_close(rdc_dev *dev);
int rdc_client_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val);
int rdc_client_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val);
int rdc_client_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len);
int rdc_client_vram_write(rdc_dev *dev, uint32_t addr, const void *buf,
			  size_t len);
int rdc_client_submit(rdc_dev *dev, const uint32_t *words, size_t n);
int rdc_client_wait(rdc_dev *dev, const struct rdc_wait *w);
int rdc_client_step(rdc_dev *dev, uint64_t cycles);
int rdc_client_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap,
			  uint32_t *width, uint32_t *height);
/* Drive RESET_N/BL_EN (RDC_MSG_PINS_SET). */
int rdc_client_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels);
int rdc_client_subscribe(rdc_dev *dev, uint32_t events, uint32_t every,
			 uint32_t encoding);
int rdc_client_event_next(rdc_dev *dev, struct rdc_event *ev, uint32_t *buf,
			  size_t cap, int timeout_ms);

/* Pixel history kept by the daemon (rdc_backend's hist_*). */
int rdc_client_hist_open(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
			 uint32_t h, uint32_t flags);
int rdc_client_hist_read(rdc_dev *dev, uint64_t first, uint32_t max,
			 struct rdc_history_entry *e, uint32_t *n,
			 uint64_t *count, uint64_t *dropped);
int rdc_client_hist_set(rdc_dev *dev, uint32_t what, uint32_t value);
int rdc_client_hist_close(rdc_dev *dev);

/* The operations every backend built on the client shares. */
#define RDC_CLIENT_OPS \
	.close = rdc_client_close, .reg_read = rdc_client_reg_read, \
	.reg_write = rdc_client_reg_write, .vram_read = rdc_client_vram_read, \
	.vram_write = rdc_client_vram_write, .submit = rdc_client_submit, \
	.wait = rdc_client_wait, .step = rdc_client_step, \
	.frame_grab = rdc_client_frame_grab, \
	.subscribe = rdc_client_subscribe, \
	.event_next = rdc_client_event_next, .pins_set = rdc_client_pins_set, \
	.hist_open = rdc_client_hist_open, .hist_read = rdc_client_hist_read, \
	.hist_set = rdc_client_hist_set, .hist_close = rdc_client_hist_close

#endif /* RDC_CLIENT_H */
