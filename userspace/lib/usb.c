// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The "usb:" backend: an RDC-1 attached over USB (rdc_usb.h), reached with
 * libusb-1.0.  The protocol client is net.c's (rdc_client.h); this file is
 * its byte transport over the interface's endpoints:
 *
 *  - bulk IN: USB_IN_N transfers always in flight while the reassembly
 *    ring (usb_host.c) has room for what they may bring, so frames
 *    stream without a gap; the client reads the ring;
 *  - interrupt IN: one transfer always in flight; each completion is one
 *    EV_IRQ message, checked and queued by usb_host.c;
 *  - bulk OUT: a request goes out in chunks of USB_OUT_CHUNK, up to
 *    USB_OUT_N in flight, each ending with a zero-length packet when its
 *    length is a multiple of wMaxPacketSize.
 *
 * There is no thread: libusb's events are handled inside the calls that
 * wait, in slices of at most USB_SLICE_MS, so every wait notices a device
 * that went away.  A transfer that ends with LIBUSB_TRANSFER_NO_DEVICE, a
 * hotplug "left" callback, or an I/O error on a device that no longer
 * answers makes the transport fail with RDC_E_GONE, and the client then
 * returns RDC_E_GONE from every later call at once.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rdc_client.h"
#include "rdc_priv.h"
#include "usb_host.h"

#ifdef RDC_HAVE_USB
#include <libusb.h>

#define USB_IN_N	  4
#define USB_IN_SIZE	  (64u * 1024u) /* a multiple of every bulk maxp */
#define USB_OUT_N	  4
#define USB_OUT_CHUNK	  (64u * 1024u)
#define USB_RX_CAP	  (8u << 20) /* a few raw frames of the biggest mode */
#define USB_SLICE_MS	  100
#define USB_CTRL_MS	  2000
#define USB_OUT_MS	  30000 /* an OUT chunk the device never takes */
#define USB_DRAIN_MS	  50
#define USB_DRAIN_MAX	  (16u << 20)
#define USB_CLOSE_MS	  3000
#define USB_GONE_CHECK_MS 1000 /* after an I/O error: is it unplugging? */
/* Smallest request payload a device may declare: a register write. */
#define USB_MIN_REQUEST 64u

struct usb_xport {
	struct rdc_xport x;
	libusb_context *ctx;
	libusb_device_handle *h;
	libusb_device *dev;
	int iface;
	uint8_t ep_out, ep_in, ep_intr;
	uint16_t maxp_out;
	bool zlp_flag; /* LIBUSB_TRANSFER_ADD_ZERO_PACKET works */

	struct libusb_transfer *in[USB_IN_N];
	bool in_busy[USB_IN_N];
	struct libusb_transfer *intr;
	bool intr_busy, intr_halted;
	uint8_t intr_buf[RDC_USB_INTR_MAXP];
	struct libusb_transfer *out[USB_OUT_N];
	bool out_busy[USB_OUT_N];

	struct rdc_usb_rx rx;
	int err;      /* sticky: RDC_E_GONE, RDC_E_IO or RDC_E_PROTO */
	bool session; /* ours: RESET on close ends it */
	bool hp_on;
	libusb_hotplug_callback_handle hp;
};

static uint64_t usb_now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u;
}

static int usb_err(int lu)
{
	switch (lu) {
	case LIBUSB_SUCCESS:
		return 0;
	case LIBUSB_ERROR_NO_DEVICE:
		return RDC_E_GONE;
	case LIBUSB_ERROR_NO_MEM:
		return RDC_E_NOMEM;
	case LIBUSB_ERROR_BUSY:
		return RDC_E_BUSY;
	case LIBUSB_ERROR_OVERFLOW:
		return RDC_E_PROTO;
	default:
		return RDC_E_IO;
	}
}

static void usb_fail(struct usb_xport *u, int err)
{
	if (!u->err || err == RDC_E_GONE)
		u->err = err;
}

static int usb_transfer_err(enum libusb_transfer_status st)
{
	switch (st) {
	case LIBUSB_TRANSFER_NO_DEVICE:
		return RDC_E_GONE;
	case LIBUSB_TRANSFER_OVERFLOW:
		return RDC_E_PROTO;
	default:
		return RDC_E_IO;
	}
}

/* ---- Transfers -------------------------------------------------------------
 */

static void LIBUSB_CALL usb_in_done(struct libusb_transfer *t)
{
	struct usb_xport *u = t->user_data;

	for (unsigned int i = 0; i < USB_IN_N; i++)
		if (u->in[i] == t)
			u->in_busy[i] = false;
	if (t->status == LIBUSB_TRANSFER_COMPLETED) {
		/* room was reserved at submission: a refusal is our bug or a
		 * length the kernel should have stopped */
		if (t->actual_length < 0 || t->actual_length > t->length ||
		    rdc_usb_rx_bulk(&u->rx, t->buffer,
				    (size_t)t->actual_length))
			usb_fail(u, RDC_E_PROTO);
	} else if (t->status != LIBUSB_TRANSFER_CANCELLED) {
		usb_fail(u, usb_transfer_err(t->status));
	}
}

static void LIBUSB_CALL usb_intr_done(struct libusb_transfer *t)
{
	struct usb_xport *u = t->user_data;

	u->intr_busy = false;
	if (t->status == LIBUSB_TRANSFER_COMPLETED) {
		if (t->actual_length >= 0 && t->actual_length <= t->length)
			rdc_usb_rx_intr(&u->rx, t->buffer,
					(size_t)t->actual_length);
	} else if (t->status == LIBUSB_TRANSFER_NO_DEVICE) {
		usb_fail(u, RDC_E_GONE);
	} else if (t->status == LIBUSB_TRANSFER_STALL) {
		u->intr_halted = true; /* cleared from the pump, not here */
	} else if (t->status != LIBUSB_TRANSFER_CANCELLED) {
		/* events are lost, the stream is not: leave the replies be */
		u->intr_halted = true;
	}
}

static void LIBUSB_CALL usb_out_done(struct libusb_transfer *t)
{
	struct usb_xport *u = t->user_data;

	for (unsigned int i = 0; i < USB_OUT_N; i++)
		if (u->out[i] == t)
			u->out_busy[i] = false;
	if (t->status == LIBUSB_TRANSFER_COMPLETED) {
		if (t->actual_length != t->length)
			usb_fail(u, RDC_E_IO);
	} else if (t->status != LIBUSB_TRANSFER_CANCELLED) {
		usb_fail(u, usb_transfer_err(t->status));
	}
}

static int LIBUSB_CALL usb_hotplug_left(libusb_context *ctx, libusb_device *dev,
					libusb_hotplug_event ev, void *arg)
{
	struct usb_xport *u = arg;

	(void)ctx;
	if (ev == LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT && dev == u->dev)
		usb_fail(u, RDC_E_GONE);
	return 0;
}

/* Keep the IN transfers in flight while their data has room. */
static void usb_refill(struct usb_xport *u)
{
	unsigned int busy = 0;

	if (u->err)
		return;
	for (unsigned int i = 0; i < USB_IN_N; i++)
		busy += u->in_busy[i];
	for (unsigned int i = 0; i < USB_IN_N && !u->err; i++) {
		int r;

		if (u->in_busy[i] ||
		    rdc_usb_rx_room(&u->rx) < (size_t)(busy + 1) * USB_IN_SIZE)
			continue;
		r = libusb_submit_transfer(u->in[i]);
		if (r) {
			usb_fail(u, usb_err(r));
			return;
		}
		u->in_busy[i] = true;
		busy++;
	}
	if (!u->intr_busy && !u->err) {
		int r;

		if (u->intr_halted) {
			/* one try per pump; events are not worth a failure */
			u->intr_halted = false;
			if (libusb_clear_halt(u->h, u->ep_intr) ==
			    LIBUSB_ERROR_NO_DEVICE) {
				usb_fail(u, RDC_E_GONE);
				return;
			}
		}
		r = libusb_submit_transfer(u->intr);
		if (r == LIBUSB_ERROR_NO_DEVICE)
			usb_fail(u, RDC_E_GONE);
		else if (!r)
			u->intr_busy = true;
	}
}

/* Handle libusb's events for at most ms. */
static void usb_pump(struct usb_xport *u, int ms)
{
	struct timeval tv = { ms / 1000, (ms % 1000) * 1000 };
	int r;

	usb_refill(u);
	r = libusb_handle_events_timeout_completed(u->ctx, &tv, NULL);
	if (r && r != LIBUSB_ERROR_INTERRUPTED && r != LIBUSB_ERROR_TIMEOUT)
		usb_fail(u, usb_err(r));
	usb_refill(u);
}

/*
 * The transport failed with an I/O error: if the device is on its way
 * out (an unplug fails transfers before the port reports it), call it
 * gone.  Bounded by USB_GONE_CHECK_MS.
 */
static int usb_settle(struct usb_xport *u)
{
	uint64_t end = usb_now_ms() + USB_GONE_CHECK_MS;

	while (u->err == RDC_E_IO && usb_now_ms() < end) {
		int cfg;

		if (libusb_get_configuration(u->h, &cfg) ==
		    LIBUSB_ERROR_NO_DEVICE) {
			usb_fail(u, RDC_E_GONE);
			break;
		}
		usb_pump(u, 50);
	}
	return u->err;
}

/* ---- The transport
 * ----------------------------------------------------------- */

static ssize_t usb_recv(struct rdc_xport *x, void *buf, size_t len,
			int timeout_ms)
{
	struct usb_xport *u = (struct usb_xport *)x;
	uint64_t end = timeout_ms >= 0 ? usb_now_ms() + (uint64_t)timeout_ms :
					 0;

	for (;;) {
		ssize_t n = rdc_usb_rx_read(&u->rx, buf, len);
		int ms = USB_SLICE_MS;

		if (n < 0)
			usb_fail(u, (int)n);
		if (n > 0)
			return n;
		if (u->err)
			return usb_settle(u);
		if (timeout_ms >= 0) {
			uint64_t now = usb_now_ms();

			if (now >= end)
				return RDC_E_TIMEOUT;
			ms = (int)RDC_MIN(end - now, (uint64_t)USB_SLICE_MS);
		}
		usb_pump(u, ms);
	}
}

static int usb_send(struct rdc_xport *x, const struct iovec *iov, int n)
{
	struct usb_xport *u = (struct usb_xport *)x;
	size_t total = 0, sent = 0;
	int vi = 0;
	size_t voff = 0;
	bool zlp_due = false;

	for (int i = 0; i < n; i++)
		total += iov[i].iov_len;
	for (;;) {
		unsigned int busy = 0;

		for (unsigned int i = 0; i < USB_OUT_N && !u->err; i++) {
			struct libusb_transfer *t = u->out[i];
			size_t k = 0;
			int r;

			if (u->out_busy[i] || (sent == total && !zlp_due))
				continue;
			if (!zlp_due) {
				size_t want = RDC_MIN(total - sent,
						      (size_t)USB_OUT_CHUNK);

				while (k < want) {
					size_t c =
						RDC_MIN(want - k,
							iov[vi].iov_len - voff);

					memcpy(t->buffer + k,
					       (const uint8_t *)iov[vi].iov_base +
						       voff,
					       c);
					k += c;
					voff += c;
					if (voff == iov[vi].iov_len) {
						vi++;
						voff = 0;
					}
				}
				sent += k;
			}
			zlp_due = false;
			t->length = (int)k;
			t->flags = 0;
			if (k && k % u->maxp_out == 0) {
				if (u->zlp_flag)
					t->flags =
						LIBUSB_TRANSFER_ADD_ZERO_PACKET;
				else
					zlp_due = true;
			}
			r = libusb_submit_transfer(t);
			if (r == LIBUSB_ERROR_NOT_SUPPORTED && t->flags) {
				/* no URB_ZERO_PACKET: an empty transfer after
				 */
				u->zlp_flag = false;
				t->flags = 0;
				zlp_due = true;
				r = libusb_submit_transfer(t);
			}
			if (r) {
				usb_fail(u, usb_err(r));
				break;
			}
			u->out_busy[i] = true;
		}
		for (unsigned int i = 0; i < USB_OUT_N; i++)
			busy += u->out_busy[i];
		if (u->err && !busy)
			return usb_settle(u);
		if (!busy && sent == total && !zlp_due)
			return 0;
		if (u->err) {
			for (unsigned int i = 0; i < USB_OUT_N; i++)
				if (u->out_busy[i])
					libusb_cancel_transfer(u->out[i]);
		}
		usb_pump(u, USB_SLICE_MS);
	}
}

static int usb_vendor(struct usb_xport *u, bool in, uint8_t req, uint8_t *data,
		      uint16_t len);

static void usb_xport_free(struct usb_xport *u)
{
	uint64_t end = usb_now_ms() + USB_CLOSE_MS;
	bool busy;

	do {
		busy = u->intr_busy;
		if (u->intr_busy)
			libusb_cancel_transfer(u->intr);
		for (unsigned int i = 0; i < USB_IN_N; i++) {
			if (u->in_busy[i])
				libusb_cancel_transfer(u->in[i]);
			busy |= u->in_busy[i];
		}
		for (unsigned int i = 0; i < USB_OUT_N; i++) {
			if (u->out_busy[i])
				libusb_cancel_transfer(u->out[i]);
			busy |= u->out_busy[i];
		}
		if (busy) {
			struct timeval tv = { 0, 50000 };

			u->err = u->err ? u->err : RDC_E_IO; /* no refill */
			libusb_handle_events_timeout_completed(u->ctx, &tv,
							       NULL);
		}
	} while (busy && usb_now_ms() < end);
	/*
	 * A transfer still in flight cannot be freed; libusb_close reaps it
	 * (the kernel has given the URB back by the time close returns).
	 */
	if (!busy) {
		for (unsigned int i = 0; i < USB_IN_N; i++)
			libusb_free_transfer(u->in[i]);
		for (unsigned int i = 0; i < USB_OUT_N; i++) {
			if (u->out[i])
				free(u->out[i]->buffer);
			libusb_free_transfer(u->out[i]);
		}
		libusb_free_transfer(u->intr);
	}
	if (u->hp_on)
		libusb_hotplug_deregister_callback(u->ctx, u->hp);
	/* end the session: what it holds (control) goes at once */
	if (u->session && u->err != RDC_E_GONE)
		usb_vendor(u, false, RDC_USB_REQ_RESET, NULL, 0);
	if (u->h) {
		libusb_release_interface(u->h, u->iface);
		libusb_close(u->h);
	}
	if (u->dev)
		libusb_unref_device(u->dev);
	if (u->ctx)
		libusb_exit(u->ctx);
	rdc_usb_rx_free(&u->rx);
	free(u);
}

static void usb_close(struct rdc_xport *x)
{
	usb_xport_free((struct usb_xport *)x);
}

static const struct rdc_xport_ops usb_ops = {
	.send = usb_send,
	.recv = usb_recv,
	.close = usb_close,
};

/* ---- Finding the device
 * ------------------------------------------------------ */

struct usb_iface {
	int number;
	uint8_t ep_out, ep_in, ep_intr;
	uint16_t maxp_out, maxp_in, maxp_intr;
};

/*
 * The RDC-1 interface of `dev` (class, subclass and protocol of
 * rdc_usb.h, alternate setting 0, one bulk OUT, one bulk IN and one
 * interrupt IN endpoint with sane packet sizes): 0, or RDC_E_IO.
 */
static int usb_find_iface(libusb_device *dev, struct usb_iface *f)
{
	struct libusb_config_descriptor *cfg = NULL;
	int ret = RDC_E_IO;

	if (libusb_get_active_config_descriptor(dev, &cfg) &&
	    libusb_get_config_descriptor(dev, 0, &cfg))
		return RDC_E_IO;
	for (int i = 0; i < cfg->bNumInterfaces && ret; i++) {
		const struct libusb_interface *it = &cfg->interface[i];
		const struct libusb_interface_descriptor *d;

		if (it->num_altsetting < 1)
			continue;
		d = &it->altsetting[0];
		if (d->bInterfaceClass != RDC_USB_CLASS ||
		    d->bInterfaceSubClass != RDC_USB_SUBCLASS ||
		    d->bInterfaceProtocol != RDC_USB_PROTOCOL)
			continue;
		memset(f, 0, sizeof(*f));
		f->number = d->bInterfaceNumber;
		for (int e = 0; e < d->bNumEndpoints; e++) {
			const struct libusb_endpoint_descriptor *ep =
				&d->endpoint[e];
			uint8_t type = ep->bmAttributes & 3u;
			bool in = ep->bEndpointAddress & LIBUSB_ENDPOINT_IN;
			uint16_t mp = ep->wMaxPacketSize & 0x7ffu;

			if (type == LIBUSB_TRANSFER_TYPE_BULK && !in) {
				f->ep_out = ep->bEndpointAddress;
				f->maxp_out = mp;
			} else if (type == LIBUSB_TRANSFER_TYPE_BULK) {
				f->ep_in = ep->bEndpointAddress;
				f->maxp_in = mp;
			} else if (type == LIBUSB_TRANSFER_TYPE_INTERRUPT &&
				   in) {
				f->ep_intr = ep->bEndpointAddress;
				f->maxp_intr = mp;
			}
		}
		/* an event must fit one packet; bulk sizes divide our
		 * transfer sizes */
		if (f->ep_out && f->ep_in && f->ep_intr && f->maxp_out &&
		    f->maxp_in && USB_IN_SIZE % f->maxp_in == 0 &&
		    f->maxp_intr >= RDC_USB_EVENT_SIZE &&
		    f->maxp_intr <= RDC_USB_INTR_MAXP)
			ret = 0;
	}
	libusb_free_config_descriptor(cfg);
	return ret;
}

static bool usb_path_is(libusb_device *dev, const struct rdc_usb_addr *a)
{
	uint8_t ports[RDC_USB_MAX_PORTS];
	int n = libusb_get_port_numbers(dev, ports, RDC_USB_MAX_PORTS);

	return n == a->nports && libusb_get_bus_number(dev) == a->bus &&
	       !memcmp(ports, a->ports, (size_t)n);
}

/* The serial string of an opened device into buf ("" if it has none). */
static void usb_serial(libusb_device_handle *h,
		       const struct libusb_device_descriptor *dd, char *buf,
		       size_t cap)
{
	int n = 0;

	if (dd->iSerialNumber)
		n = libusb_get_string_descriptor_ascii(h, dd->iSerialNumber,
						       (unsigned char *)buf,
						       (int)cap - 1);
	buf[n > 0 ? RDC_MIN((size_t)n, cap - 1) : 0] = 0;
}

/* ---- Opening
 * ------------------------------------------------------------------ */

/* Vendor request on the interface; IN if `data` is to be filled. */
static int usb_vendor(struct usb_xport *u, bool in, uint8_t req, uint8_t *data,
		      uint16_t len)
{
	uint8_t type = (in ? LIBUSB_ENDPOINT_IN : LIBUSB_ENDPOINT_OUT) |
		       LIBUSB_REQUEST_TYPE_VENDOR;
	int r = libusb_control_transfer(u->h, type | LIBUSB_RECIPIENT_INTERFACE,
					req, 0, (uint16_t)u->iface, data, len,
					USB_CTRL_MS);

	/* rdc_usb.h's bmRequestType values name the device as recipient */
	if (r == LIBUSB_ERROR_PIPE)
		r = libusb_control_transfer(u->h, type, req, 0,
					    (uint16_t)u->iface, data, len,
					    USB_CTRL_MS);
	return r;
}

/*
 * INFO (magic, version, the device's request cap), then RESET for a
 * clean session: halts cleared, stale IN data drained.
 */
static int usb_session(struct usb_xport *u)
{
	uint8_t info[RDC_USB_INFO_SIZE], junk[4096];
	uint32_t max_req;
	size_t drained = 0;
	int r = usb_vendor(u, true, RDC_USB_REQ_INFO, info, sizeof(info));

	if (r < 0)
		return usb_err(r);
	if (r != (int)sizeof(info) ||
	    rdc_proto_get32(info) != RDC_PROTO_MAGIC ||
	    rdc_proto_get32(info + 4) != RDC_PROTO_VERSION)
		return RDC_E_PROTO;
	max_req = rdc_proto_get32(info + 8);
	if (max_req < USB_MIN_REQUEST)
		return RDC_E_PROTO;
	u->x.max_request = RDC_MIN(max_req, RDC_PROTO_MAX_REQUEST);
	r = usb_vendor(u, false, RDC_USB_REQ_RESET, NULL, 0);
	if (r < 0)
		return usb_err(r);
	libusb_clear_halt(u->h, u->ep_out);
	libusb_clear_halt(u->h, u->ep_in);
	libusb_clear_halt(u->h, u->ep_intr);
	for (int ep = 0; ep < 2; ep++) {
		int got;

		do {
			got = 0;
			r = ep ? libusb_interrupt_transfer(u->h, u->ep_intr,
							   junk, sizeof(junk),
							   &got, USB_DRAIN_MS) :
				 libusb_bulk_transfer(u->h, u->ep_in, junk,
						      sizeof(junk), &got,
						      USB_DRAIN_MS);
			drained += (size_t)got;
		} while (!r && got > 0 && drained < USB_DRAIN_MAX);
		if (r == LIBUSB_ERROR_NO_DEVICE)
			return RDC_E_GONE;
	}
	return drained < USB_DRAIN_MAX ? 0 : RDC_E_PROTO;
}

static int usb_alloc(struct usb_xport *u)
{
	for (unsigned int i = 0; i < USB_IN_N; i++) {
		uint8_t *b = malloc(USB_IN_SIZE);

		u->in[i] = libusb_alloc_transfer(0);
		if (!u->in[i] || !b) {
			free(b);
			return RDC_E_NOMEM;
		}
		libusb_fill_bulk_transfer(u->in[i], u->h, u->ep_in, b,
					  (int)USB_IN_SIZE, usb_in_done, u, 0);
		u->in[i]->flags = LIBUSB_TRANSFER_FREE_BUFFER;
	}
	for (unsigned int i = 0; i < USB_OUT_N; i++) {
		uint8_t *b = malloc(USB_OUT_CHUNK);

		u->out[i] = libusb_alloc_transfer(0);
		if (!u->out[i] || !b) {
			free(b);
			return RDC_E_NOMEM;
		}
		libusb_fill_bulk_transfer(u->out[i], u->h, u->ep_out, b, 0,
					  usb_out_done, u, USB_OUT_MS);
	}
	u->intr = libusb_alloc_transfer(0);
	if (!u->intr)
		return RDC_E_NOMEM;
	libusb_fill_interrupt_transfer(u->intr, u->h, u->ep_intr, u->intr_buf,
				       sizeof(u->intr_buf), usb_intr_done, u,
				       0);
	return rdc_usb_rx_init(&u->rx, USB_RX_CAP);
}

/* Does `dev` answer to address `a`?  *f gets its RDC-1 interface. */
static bool usb_matches(libusb_device *dev, const struct rdc_usb_addr *a,
			struct usb_iface *f)
{
	struct libusb_device_descriptor dd;
	libusb_device_handle *h;
	char serial[sizeof(a->serial)];

	if (libusb_get_device_descriptor(dev, &dd) || usb_find_iface(dev, f))
		return false;
	if (a->kind == RDC_USB_ADDR_PATH)
		return usb_path_is(dev, a);
	if (dd.idVendor != a->vid || dd.idProduct != a->pid)
		return false;
	if (a->kind != RDC_USB_ADDR_SERIAL)
		return true;
	if (libusb_open(dev, &h))
		return false;
	usb_serial(h, &dd, serial, sizeof(serial));
	libusb_close(h);
	return !strcmp(serial, a->serial);
}

static int usb_connect(struct usb_xport *u, const struct rdc_usb_addr *a)
{
	libusb_device **list;
	struct usb_iface f;
	ssize_t n;
	int r;

	n = libusb_get_device_list(u->ctx, &list);
	if (n < 0)
		return usb_err((int)n);
	for (ssize_t i = 0; i < n && !u->dev; i++)
		if (usb_matches(list[i], a, &f))
			u->dev = libusb_ref_device(list[i]);
	libusb_free_device_list(list, 1);
	if (!u->dev)
		return RDC_E_IO; /* no such device */
	r = libusb_open(u->dev, &u->h);
	if (r)
		return usb_err(r);
	u->iface = f.number;
	u->ep_out = f.ep_out;
	u->ep_in = f.ep_in;
	u->ep_intr = f.ep_intr;
	u->maxp_out = f.maxp_out;
	u->zlp_flag = true;
	libusb_set_auto_detach_kernel_driver(u->h, 1);
	r = libusb_claim_interface(u->h, u->iface);
	if (r) {
		libusb_close(u->h);
		u->h = NULL;
		return usb_err(r);
	}
	if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
		struct libusb_device_descriptor dd;

		libusb_get_device_descriptor(u->dev, &dd);
		u->hp_on = !libusb_hotplug_register_callback(
			u->ctx, LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT, 0,
			dd.idVendor, dd.idProduct, LIBUSB_HOTPLUG_MATCH_ANY,
			usb_hotplug_left, u, &u->hp);
	}
	r = usb_session(u);
	u->session = !r;
	if (!r)
		r = usb_alloc(u);
	return r;
}

static int usb_open(rdc_dev *dev, const char *opts)
{
	const char *q = strchr(opts, '?');
	size_t alen = q ? (size_t)(q - opts) : strlen(opts);
	struct rdc_client_opts o;
	struct rdc_usb_addr a;
	struct usb_xport *u;
	int ret;

	ret = rdc_usb_addr_parse(opts, alen, &a);
	if (!ret)
		ret = rdc_client_parse_opts(q ? q + 1 : NULL, &o);
	if (ret)
		return ret;
	u = calloc(1, sizeof(*u));
	if (!u)
		return RDC_E_NOMEM;
	u->x.ops = &usb_ops;
	ret = libusb_init(&u->ctx) ? RDC_E_IO : usb_connect(u, &a);
	if (ret) {
		if (!u->ctx)
			free(u);
		else
			usb_xport_free(u);
		return ret;
	}
	usb_refill(u);
	return rdc_client_open(dev, &u->x, &o);
}

/* ---- Listing
 * -------------------------------------------------------------------- */

static int usb_list(rdc_found_fn fn, void *arg)
{
	libusb_context *ctx;
	libusb_device **list;
	ssize_t n;
	int found = 0;

	if (libusb_init(&ctx))
		return RDC_E_IO;
	n = libusb_get_device_list(ctx, &list);
	for (ssize_t i = 0; i < n; i++) {
		struct libusb_device_descriptor dd;
		struct rdc_found fd;
		struct usb_iface f;
		libusb_device_handle *h;
		uint8_t ports[RDC_USB_MAX_PORTS];
		char path[40], serial[128] = "";
		int np;

		if (libusb_get_device_descriptor(list[i], &dd) ||
		    usb_find_iface(list[i], &f))
			continue;
		np = libusb_get_port_numbers(list[i], ports, RDC_USB_MAX_PORTS);
		if (np < 1 ||
		    rdc_usb_path_format(path, sizeof(path),
					libusb_get_bus_number(list[i]), ports,
					(unsigned int)np))
			continue;
		if (!libusb_open(list[i], &h)) {
			usb_serial(h, &dd, serial, sizeof(serial));
			libusb_close(h);
		} else {
			snprintf(serial, sizeof(serial), "(unreadable)");
		}
		memset(&fd, 0, sizeof(fd));
		snprintf(fd.uri, sizeof(fd.uri), "usb:%s", path);
		snprintf(fd.info, sizeof(fd.info),
			 "USB %04x:%04x bus %u port %.24s serial %.64s",
			 dd.idVendor, dd.idProduct,
			 libusb_get_bus_number(list[i]), strchr(path, '-') + 1,
			 serial[0] ? serial : "(none)");
		fn(&fd, arg);
		found++;
	}
	if (n >= 0)
		libusb_free_device_list(list, 1);
	libusb_exit(ctx);
	return n < 0 ? usb_err((int)n) : found;
}

const struct rdc_backend rdc_backend_usb = {
	.scheme = "usb",
	.open = usb_open,
	.list = usb_list,
	RDC_CLIENT_OPS,
};

#else /* !RDC_HAVE_USB */

/* Known but not built: rdc_open answers RDC_E_NOSYS. */
const struct rdc_backend rdc_backend_usb = { .scheme = "usb" };

#endif
