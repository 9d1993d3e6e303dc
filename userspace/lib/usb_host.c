// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * usb: addresses and the reassembly of what an RDC-1 sends over USB
 * (usb_host.h).  No libusb: usb.c feeds this from its transfer callbacks,
 * tests and the fuzz target feed it directly.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rdc.h"
#include "usb_host.h"

/* ---- Addresses -------------------------------------------------------------
 */

/* A number of at most `max` in base 10 or 16 from s[*i], digits only. */
static int addr_num(const char *s, size_t len, size_t *i, unsigned int base,
		    unsigned int maxdig, unsigned long max, unsigned long *out)
{
	unsigned long v = 0;
	size_t start = *i;

	while (*i < len && *i - start < maxdig + 1) {
		char c = s[*i];
		unsigned int d;

		if (c >= '0' && c <= '9')
			d = (unsigned int)(c - '0');
		else if (base == 16 && c >= 'a' && c <= 'f')
			d = (unsigned int)(c - 'a' + 10);
		else if (base == 16 && c >= 'A' && c <= 'F')
			d = (unsigned int)(c - 'A' + 10);
		else
			break;
		v = v * base + d;
		(*i)++;
	}
	if (*i == start || *i - start > maxdig || v > max)
		return RDC_E_URI;
	*out = v;
	return 0;
}

int rdc_usb_addr_parse(const char *s, size_t len, struct rdc_usb_addr *a)
{
	size_t i = 0;
	unsigned long v, w;

	memset(a, 0, sizeof(*a));
	a->vid = RDC_USB_VID;
	a->pid = RDC_USB_PID;
	if (!len) {
		a->kind = RDC_USB_ADDR_FIRST;
		return 0;
	}
	if (len > 7 && !strncmp(s, "serial=", 7)) {
		if (len - 7 >= sizeof(a->serial))
			return RDC_E_URI;
		for (i = 7; i < len; i++)
			if ((unsigned char)s[i] < 0x20 || s[i] == 0x7f ||
			    s[i] == '&')
				return RDC_E_URI;
		memcpy(a->serial, s + 7, len - 7);
		a->kind = RDC_USB_ADDR_SERIAL;
		return 0;
	}
	if (memchr(s, ':', len)) {
		if (addr_num(s, len, &i, 16, 4, 0xffff, &v) || i >= len ||
		    s[i++] != ':' || addr_num(s, len, &i, 16, 4, 0xffff, &w) ||
		    i != len)
			return RDC_E_URI;
		a->kind = RDC_USB_ADDR_IDS;
		a->vid = (uint16_t)v;
		a->pid = (uint16_t)w;
		return 0;
	}
	if (addr_num(s, len, &i, 10, 3, 255, &v) || !v || i >= len ||
	    s[i++] != '-')
		return RDC_E_URI;
	a->kind = RDC_USB_ADDR_PATH;
	a->bus = (uint8_t)v;
	for (;;) {
		if (a->nports == RDC_USB_MAX_PORTS ||
		    addr_num(s, len, &i, 10, 3, 255, &v) || !v)
			return RDC_E_URI;
		a->ports[a->nports++] = (uint8_t)v;
		if (i == len)
			return 0;
		if (s[i++] != '.')
			return RDC_E_URI;
	}
}

int rdc_usb_path_format(char *buf, size_t cap, uint8_t bus,
			const uint8_t *ports, unsigned int nports)
{
	size_t o;
	int n = snprintf(buf, cap, "%u", bus);

	if (n < 0 || (size_t)n >= cap)
		return -1;
	o = (size_t)n;
	for (unsigned int i = 0; i < nports; i++) {
		n = snprintf(buf + o, cap - o, "%c%u", i ? '.' : '-', ports[i]);
		if (n < 0 || (size_t)n >= cap - o)
			return -1;
		o += (size_t)n;
	}
	return 0;
}

/* ---- Reassembly ------------------------------------------------------------
 */

int rdc_usb_rx_init(struct rdc_usb_rx *rx, size_t cap)
{
	memset(rx, 0, sizeof(*rx));
	if (cap < RDC_PROTO_HDR_SIZE)
		return RDC_E_INVAL;
	rx->buf = malloc(cap);
	if (!rx->buf)
		return RDC_E_NOMEM;
	rx->cap = cap;
	return 0;
}

void rdc_usb_rx_free(struct rdc_usb_rx *rx)
{
	free(rx->buf);
	rx->buf = NULL;
	rx->cap = rx->len = rx->head = 0;
}

size_t rdc_usb_rx_room(const struct rdc_usb_rx *rx)
{
	return rx->cap - rx->len;
}

int rdc_usb_rx_bulk(struct rdc_usb_rx *rx, const void *data, size_t len)
{
	size_t tail, k;

	if (len > rdc_usb_rx_room(rx)) {
		rx->err = RDC_E_PROTO;
		return rx->err;
	}
	tail = (rx->head + rx->len) % rx->cap;
	k = RDC_MIN(len, rx->cap - tail);
	memcpy(rx->buf + tail, data, k);
	memcpy(rx->buf, (const uint8_t *)data + k, len - k);
	rx->len += len;
	return 0;
}

/* Copy n bytes from the ring's head at offset `off` (no consuming). */
static void rx_peek(const struct rdc_usb_rx *rx, size_t off, void *out,
		    size_t n)
{
	size_t from = (rx->head + off) % rx->cap;
	size_t k = RDC_MIN(n, rx->cap - from);

	memcpy(out, rx->buf + from, k);
	memcpy((uint8_t *)out + k, rx->buf, n - k);
}

static void rx_take(struct rdc_usb_rx *rx, void *out, size_t n)
{
	rx_peek(rx, 0, out, n);
	rx->head = (rx->head + n) % rx->cap;
	rx->len -= n;
}

int rdc_usb_rx_intr(struct rdc_usb_rx *rx, const void *data, size_t len)
{
	struct rdc_proto_hdr h;
	unsigned int slot;

	if (len != RDC_USB_EVENT_SIZE) {
		rx->ev_bad++;
		return 1;
	}
	rdc_proto_hdr_decode(data, &h);
	if (h.len != RDC_USB_EVENT_SIZE - RDC_PROTO_HDR_SIZE ||
	    h.type != RDC_MSG_EV_IRQ || h.flags != RDC_MSGF_EVENT) {
		rx->ev_bad++;
		return 1;
	}
	if (rx->ev_n == RDC_USB_RX_EVENTS) {
		rx->ev_lost++;
		/* the oldest goes, unless the reader is half through it */
		if (rx->ev_off)
			return 0;
		rx->ev_head = (rx->ev_head + 1) % RDC_USB_RX_EVENTS;
		rx->ev_n--;
	}
	slot = (rx->ev_head + rx->ev_n++) % RDC_USB_RX_EVENTS;
	memcpy(rx->ev[slot], data, RDC_USB_EVENT_SIZE);
	rx->ev_queued++;
	return 0;
}

/* At a message boundary: check the next bulk header before passing it on. */
static int rx_next_msg(struct rdc_usb_rx *rx)
{
	uint8_t hb[RDC_PROTO_HDR_SIZE];
	struct rdc_proto_hdr h;
	uint16_t kind;

	rx_peek(rx, 0, hb, sizeof(hb));
	rdc_proto_hdr_decode(hb, &h);
	kind = h.flags & (RDC_MSGF_REPLY | RDC_MSGF_EVENT);
	if (h.len > RDC_PROTO_MAX_REPLY ||
	    (kind != RDC_MSGF_REPLY && kind != RDC_MSGF_EVENT)) {
		rx->err = RDC_E_PROTO;
		return rx->err;
	}
	rx->left = RDC_PROTO_HDR_SIZE + (uint64_t)h.len;
	return 0;
}

ssize_t rdc_usb_rx_read(struct rdc_usb_rx *rx, void *out, size_t len)
{
	uint8_t *o = out;
	size_t done = 0;

	while (done < len) {
		size_t k;

		if (!rx->left) {
			if (rx->ev_n) {
				uint8_t *ev = rx->ev[rx->ev_head];

				k = RDC_MIN(RDC_USB_EVENT_SIZE - rx->ev_off,
					    len - done);
				memcpy(o + done, ev + rx->ev_off, k);
				done += k;
				rx->ev_off += (unsigned int)k;
				if (rx->ev_off == RDC_USB_EVENT_SIZE) {
					rx->ev_off = 0;
					rx->ev_head = (rx->ev_head + 1) %
						      RDC_USB_RX_EVENTS;
					rx->ev_n--;
				}
				continue;
			}
			if (rx->err || rx->len < RDC_PROTO_HDR_SIZE ||
			    rx_next_msg(rx))
				break;
		}
		k = (size_t)RDC_MIN(rx->left,
				    (uint64_t)RDC_MIN(rx->len, len - done));
		if (!k)
			break;
		rx_take(rx, o + done, k);
		done += k;
		rx->left -= k;
	}
	if (!done && rx->err)
		return rx->err;
	return (ssize_t)done;
}
