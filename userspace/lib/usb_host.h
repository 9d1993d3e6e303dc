/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The half of the usb: backend that needs no libusb, so that unit tests
 * and the fuzz target (tests/fuzz/fuzz_usb.c) drive it directly:
 *
 *  - the address part of a usb: URI;
 *  - reassembly: what the device sends (bulk IN transfer chunks, and
 *    interrupt IN transfers each holding one RDC_MSG_EV_IRQ message, see
 *    rdc_usb.h) becomes one byte stream of whole rdc_proto.h messages for
 *    the protocol client.  Interrupt events join the stream only between
 *    two bulk messages.  Nothing from the device is trusted: a bulk
 *    header is checked (length cap, reply-or-event flags) before any byte
 *    of it is passed on, and an interrupt transfer that is not exactly one
 *    well-formed EV_IRQ message is dropped and counted.
 */
#ifndef RDC_USB_HOST_H
#define RDC_USB_HOST_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/types.h>

#include "rdc_proto.h"
#include "rdc_usb.h"

/* ---- usb: addresses ------------------------------------------------------ */

#define RDC_USB_MAX_PORTS 7 /* USB 3 tiers below the root hub */

enum rdc_usb_addr_kind {
	RDC_USB_ADDR_FIRST,  /* "": the first RDC-1 with the default IDs */
	RDC_USB_ADDR_IDS,    /* "VID:PID", hex */
	RDC_USB_ADDR_PATH,   /* "BUS-PORT[.PORT...]", decimal */
	RDC_USB_ADDR_SERIAL, /* "serial=S" (default IDs) */
};

struct rdc_usb_addr {
	enum rdc_usb_addr_kind kind;
	uint16_t vid, pid; /* the IDs to match (not for PATH) */
	uint8_t bus, nports, ports[RDC_USB_MAX_PORTS];
	char serial[128];
};

/*
 * Parse the address (a usb: URI after "usb:" and before any '?'), `len`
 * bytes of `s`: 0 or RDC_E_URI.
 */
int rdc_usb_addr_parse(const char *s, size_t len, struct rdc_usb_addr *a);

/* "BUS-PORT.PORT..." into buf: 0, or -1 if it does not fit. */
int rdc_usb_path_format(char *buf, size_t cap, uint8_t bus,
			const uint8_t *ports, unsigned int nports);

/* ---- Reassembly ------------------------------------------------------------
 */

#define RDC_USB_RX_EVENTS 64 /* interrupt events held for the reader */

struct rdc_usb_rx {
	/* bulk bytes received and not yet read: a ring */
	uint8_t *buf;
	size_t cap, head, len;
	/* the reader's place: bytes of the current bulk message still due */
	uint64_t left;
	/* interrupt events waiting for a message boundary */
	uint8_t ev[RDC_USB_RX_EVENTS][RDC_USB_EVENT_SIZE];
	unsigned int ev_head, ev_n, ev_off;
	/* counters: interrupt transfers dropped as malformed, events lost to
	 * a full queue (the oldest goes), events queued */
	uint64_t ev_bad, ev_lost, ev_queued;
	int err; /* 0, or RDC_E_PROTO once the bulk stream broke */
};

/* A ring of `cap` bytes: 0 or RDC_E_NOMEM. */
int rdc_usb_rx_init(struct rdc_usb_rx *rx, size_t cap);
void rdc_usb_rx_free(struct rdc_usb_rx *rx);
/* Bytes a bulk chunk may bring now. */
size_t rdc_usb_rx_room(const struct rdc_usb_rx *rx);
/*
 * A completed bulk IN transfer's bytes: 0, or RDC_E_PROTO (sticky) if
 * they exceed the room (the caller never asks for more than it has).
 */
int rdc_usb_rx_bulk(struct rdc_usb_rx *rx, const void *data, size_t len);
/*
 * A completed interrupt IN transfer: 0 if queued, 1 if dropped as
 * malformed (counted in ev_bad).
 */
int rdc_usb_rx_intr(struct rdc_usb_rx *rx, const void *data, size_t len);
/*
 * Up to len bytes of whole messages: the count (0: nothing ready yet), or
 * RDC_E_PROTO once the bulk stream broke (a header over the caps).
 */
ssize_t rdc_usb_rx_read(struct rdc_usb_rx *rx, void *out, size_t len);

#endif /* RDC_USB_HOST_H */
