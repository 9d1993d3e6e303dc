// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * usb_raw: the RDC-1's USB device side (rdcd --listen ffs:, rdc_usb.h)
 * checked with libusb directly, not through librdc's usb: backend, so the
 * two sides are checked against the header independently.  Each command
 * prints TAP lines for what it checked and exits 0 only if all passed.
 *
 *   usb_raw [--vid V] [--pid P] [--serial S] COMMAND [ARGS]
 *
 *   descriptors       the interface: class, three endpoints, sizes
 *   basic             RESET, INFO, HELLO, PING, REG_READ, REG_WRITE
 *   irq               an IRQ event (vblank) on the interrupt endpoint
 *                     after SUBSCRIBE, and none of them on bulk IN
 *   reset             a half-sent request is dropped by RESET; the
 *                     session number moves on
 *   bench N           N PINGs and N REG_READs, a VRAM write: "# " figures
 *   zlp               whether a reply that is a multiple of the packet
 *                     size still ends its transfer (the split rule)
 *   hostile KIND      truncated | oversize | random | stall-frames |
 *                     exit-mid-message | long-submit | frames: a hostile or
 *                     careless host (see tests/vm/tests/usb-hostile.sh)
 *   watch SOCK FILE   a UNIX-socket client of the same rdcd: PING and
 *                     REG_READ in a loop until FILE exists; every answer
 *                     must be right
 *
 * And one question about the kernel rather than rdcd, answered with a
 * device side of this program's own:
 *
 *   ffs-zlp DIR       a FunctionFS function with one bulk IN endpoint
 *                     that writes 512 bytes, then 0 bytes, then 100
 *   zlp-probe         reads it: one 612-byte transfer means the 0-byte
 *                     write sent nothing, 512 then 100 means it sent a
 *                     zero-length packet
 */
#include <errno.h>
#include <fcntl.h>
#include <libusb.h>
#include <linux/usb/ch9.h>
#include <linux/usb/functionfs.h>
#include <poll.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

#include "rdc_proto.h"
#include "rdc_regs.h"
#include "rdc_usb.h"
#include "tap.h"

#define TMO_MS 10000u /* TCG is slow: generous, but a hang still fails */
#define RBUF   (1u << 20)
/* Largest payload this program keeps; bigger messages are skipped. */
#define MAX_KEEP (64u << 10)

struct link {
	/* USB */
	libusb_context *ctx;
	libusb_device_handle *h;
	int intf;
	uint8_t ep_out, ep_in, ep_irq;
	uint16_t maxp_out, maxp_in, maxp_irq;
	/* or a UNIX socket */
	int fd;
	/* the byte stream coming back */
	uint8_t *rbuf;
	size_t rlen, roff;
	uint32_t seq;
	unsigned int ev_irq_on_bulk, ev_frames;
};

static uint16_t opt_vid = RDC_USB_VID, opt_pid = RDC_USB_PID;
static const char *opt_serial;

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

/* ---- USB ----------------------------------------------------------------- */

static bool serial_matches(libusb_device_handle *h,
			   const struct libusb_device_descriptor *dd)
{
	unsigned char s[128];

	if (!opt_serial)
		return true;
	if (!dd->iSerialNumber ||
	    libusb_get_string_descriptor_ascii(h, dd->iSerialNumber, s,
					       sizeof(s)) < 0)
		return false;
	return !strcmp((char *)s, opt_serial);
}

/* Our interface and its endpoints; false if the device has none. */
static bool find_intf(struct link *l, libusb_device *dev)
{
	struct libusb_config_descriptor *cfg;
	bool found = false;

	if (libusb_get_active_config_descriptor(dev, &cfg))
		return false;
	for (int i = 0; i < cfg->bNumInterfaces && !found; i++) {
		const struct libusb_interface_descriptor *id =
			&cfg->interface[i].altsetting[0];

		if (id->bInterfaceClass != RDC_USB_CLASS ||
		    id->bInterfaceSubClass != RDC_USB_SUBCLASS ||
		    id->bInterfaceProtocol != RDC_USB_PROTOCOL)
			continue;
		for (int e = 0; e < id->bNumEndpoints; e++) {
			const struct libusb_endpoint_descriptor *ed =
				&id->endpoint[e];
			int type = ed->bmAttributes & 3;
			bool in = ed->bEndpointAddress & 0x80;

			if (type == LIBUSB_TRANSFER_TYPE_BULK && !in) {
				l->ep_out = ed->bEndpointAddress;
				l->maxp_out = ed->wMaxPacketSize;
			} else if (type == LIBUSB_TRANSFER_TYPE_BULK && in) {
				l->ep_in = ed->bEndpointAddress;
				l->maxp_in = ed->wMaxPacketSize;
			} else if (type == LIBUSB_TRANSFER_TYPE_INTERRUPT &&
				   in) {
				l->ep_irq = ed->bEndpointAddress;
				l->maxp_irq = ed->wMaxPacketSize;
			}
		}
		l->intf = id->bInterfaceNumber;
		found = l->ep_out && l->ep_in && l->ep_irq;
	}
	libusb_free_config_descriptor(cfg);
	return found;
}

static int usb_open(struct link *l)
{
	libusb_device **list;
	ssize_t n;
	int ret;

	memset(l, 0, sizeof(*l));
	l->fd = -1;
	l->rbuf = malloc(RBUF);
	if (!l->rbuf || libusb_init(&l->ctx))
		return -1;
	n = libusb_get_device_list(l->ctx, &list);
	for (ssize_t i = 0; i < n && !l->h; i++) {
		struct libusb_device_descriptor dd;

		if (libusb_get_device_descriptor(list[i], &dd) ||
		    dd.idVendor != opt_vid || dd.idProduct != opt_pid)
			continue;
		if (libusb_open(list[i], &l->h))
			continue;
		if (!serial_matches(l->h, &dd) || !find_intf(l, list[i])) {
			libusb_close(l->h);
			l->h = NULL;
		}
	}
	if (n >= 0)
		libusb_free_device_list(list, 1);
	if (!l->h) {
		fprintf(stderr,
			"usb_raw: no %04x:%04x%s%s with the RDC-1 interface\n",
			opt_vid, opt_pid, opt_serial ? " serial " : "",
			opt_serial ? opt_serial : "");
		return -1;
	}
	ret = libusb_claim_interface(l->h, l->intf);
	if (ret) {
		fprintf(stderr, "usb_raw: claim: %s\n", libusb_strerror(ret));
		return -1;
	}
	return 0;
}

static void link_close(struct link *l)
{
	if (l->h) {
		libusb_release_interface(l->h, l->intf);
		libusb_close(l->h);
	}
	if (l->ctx)
		libusb_exit(l->ctx);
	if (l->fd >= 0)
		close(l->fd);
	free(l->rbuf);
}

static int ctrl_reset(struct link *l)
{
	return libusb_control_transfer(l->h, 0x41, RDC_USB_REQ_RESET, 0,
				       (uint16_t)l->intf, NULL, 0, TMO_MS);
}

static int ctrl_info(struct link *l, uint32_t info[4])
{
	uint8_t b[RDC_USB_INFO_SIZE];
	int r = libusb_control_transfer(l->h, 0xc1, RDC_USB_REQ_INFO, 0,
					(uint16_t)l->intf, b, sizeof(b),
					TMO_MS);

	if (r != (int)sizeof(b))
		return r < 0 ? r : -1;
	for (int i = 0; i < 4; i++)
		info[i] = rdc_proto_get32(b + 4 * i);
	return 0;
}

/* After RESET: clear halts, throw away what the IN endpoints still hold. */
static void resync(struct link *l)
{
	uint8_t junk[4096];
	int got;

	libusb_clear_halt(l->h, l->ep_out);
	libusb_clear_halt(l->h, l->ep_in);
	libusb_clear_halt(l->h, l->ep_irq);
	while (!libusb_bulk_transfer(l->h, l->ep_in, junk, sizeof(junk), &got,
				     50) &&
	       got)
		;
	while (!libusb_interrupt_transfer(l->h, l->ep_irq, junk, 64, &got, 20))
		;
	l->rlen = l->roff = 0;
}

static int session_reset(struct link *l)
{
	int r = ctrl_reset(l);

	if (r < 0) {
		fprintf(stderr, "usb_raw: RESET: %s\n", libusb_strerror(r));
		return -1;
	}
	resync(l);
	return 0;
}

/* ---- Transport ----------------------------------------------------------- */

static int link_write(struct link *l, const uint8_t *p, size_t n)
{
	if (l->fd >= 0) {
		while (n) {
			ssize_t k = write(l->fd, p, n);

			if (k <= 0)
				return -1;
			p += k;
			n -= (size_t)k;
		}
		return 0;
	}
	while (n) {
		int got = 0, chunk = n > (256u << 10) ? (256 << 10) : (int)n;
		int r = libusb_bulk_transfer(l->h, l->ep_out, (uint8_t *)p,
					     chunk, &got, TMO_MS);

		if (r) {
			fprintf(stderr, "usb_raw: bulk OUT: %s\n",
				libusb_strerror(r));
			return r;
		}
		p += got;
		n -= (size_t)got;
	}
	return 0;
}

/* More bytes into rbuf; < 0 on error or timeout. */
static int link_fill(struct link *l, unsigned int tmo_ms)
{
	int got = 0;

	if (l->roff) {
		memmove(l->rbuf, l->rbuf + l->roff, l->rlen - l->roff);
		l->rlen -= l->roff;
		l->roff = 0;
	}
	if (l->rlen + 16384 > RBUF)
		return -1;
	if (l->fd >= 0) {
		struct pollfd p = { .fd = l->fd, .events = POLLIN };
		ssize_t k;

		if (poll(&p, 1, (int)tmo_ms) <= 0)
			return LIBUSB_ERROR_TIMEOUT;
		k = read(l->fd, l->rbuf + l->rlen, RBUF - l->rlen);
		if (k <= 0)
			return -1;
		l->rlen += (size_t)k;
		return 0;
	}
	/* a transfer of 16 KiB: completes on the device's short packets */
	int r = libusb_bulk_transfer(l->h, l->ep_in, l->rbuf + l->rlen, 16384,
				     &got, tmo_ms);

	if (r && !(r == LIBUSB_ERROR_TIMEOUT && got))
		return r;
	l->rlen += (size_t)got;
	return 0;
}

static uint32_t send_msg(struct link *l, uint16_t type, const void *pl,
			 uint32_t len)
{
	uint8_t *b = malloc(RDC_PROTO_HDR_SIZE + len);
	struct rdc_proto_hdr h = { .len = len, .type = type, .seq = ++l->seq };
	int r;

	if (!b)
		return 0;
	rdc_proto_hdr_encode(b, &h);
	if (len)
		memcpy(b + RDC_PROTO_HDR_SIZE, pl, len);
	r = link_write(l, b, RDC_PROTO_HDR_SIZE + len);
	free(b);
	return r ? 0 : h.seq;
}

/*
 * The next message: header into *h, up to `cap` payload bytes into out
 * (bigger payloads are consumed and dropped).  0, or < 0.
 */
static int recv_msg(struct link *l, struct rdc_proto_hdr *h, uint8_t *out,
		    size_t cap, unsigned int tmo_ms)
{
	size_t need;

	while (l->rlen - l->roff < RDC_PROTO_HDR_SIZE) {
		int r = link_fill(l, tmo_ms);

		if (r)
			return r;
	}
	rdc_proto_hdr_decode(l->rbuf + l->roff, h);
	if (h->len > RDC_PROTO_MAX_REPLY) {
		fprintf(stderr, "usb_raw: a message of %u bytes?\n", h->len);
		return -1;
	}
	l->roff += RDC_PROTO_HDR_SIZE;
	need = h->len;
	while (need) {
		size_t have = l->rlen - l->roff, take;

		if (!have) {
			int r = link_fill(l, tmo_ms);

			if (r)
				return r;
			continue;
		}
		take = have < need ? have : need;
		if (out && h->len <= cap)
			memcpy(out + (h->len - need), l->rbuf + l->roff, take);
		l->roff += take;
		need -= take;
	}
	return 0;
}

/* A request and its reply (events before it are counted and skipped). */
static int request(struct link *l, uint16_t type, const void *pl, uint32_t len,
		   uint8_t *out, size_t cap, uint32_t *status, uint32_t *rlen)
{
	uint32_t seq = send_msg(l, type, pl, len);
	struct rdc_proto_hdr h;

	if (!seq)
		return -1;
	for (;;) {
		int r = recv_msg(l, &h, out, cap, TMO_MS);

		if (r) {
			fprintf(stderr, "usb_raw: no reply to %u: %s\n", type,
				r < 0 && r > -100 ? libusb_strerror(r) : "?");
			return -1;
		}
		if (h.flags & RDC_MSGF_EVENT) {
			if (h.type == RDC_MSG_EV_IRQ)
				l->ev_irq_on_bulk++;
			else if (h.type == RDC_MSG_EV_FRAME)
				l->ev_frames++;
			continue;
		}
		if (!(h.flags & RDC_MSGF_REPLY) || h.seq != seq ||
		    h.type != type) {
			fprintf(stderr,
				"usb_raw: reply out of order: type %u seq %u "
				"flags %x (want %u/%u)\n",
				h.type, h.seq, h.flags, type, seq);
			return -1;
		}
		*status = h.status;
		if (rlen)
			*rlen = h.len;
		return 0;
	}
}

static int hello(struct link *l, bool control, struct rdc_proto_hello_reply *r)
{
	struct rdc_proto_hello hh = { .magic = RDC_PROTO_MAGIC,
				      .version = RDC_PROTO_VERSION,
				      .caps = RDC_CAP_ALL,
				      .flags = control ? RDC_HELLO_CONTROL :
							 0 };
	uint8_t pl[64], out[64];
	size_t n = rdc_proto_hello_encode(pl, sizeof(pl), &hh);
	uint32_t st, len;

	if (request(l, RDC_MSG_HELLO, pl, (uint32_t)n, out, sizeof(out), &st,
		    &len) ||
	    st != RDC_ST_OK || rdc_proto_hello_reply_decode(out, len, r))
		return -1;
	return 0;
}

static int reg_read(struct link *l, uint32_t reg, uint32_t *v)
{
	uint8_t pl[4], out[8];
	uint32_t st, len;

	rdc_proto_put32(pl, reg);
	if (request(l, RDC_MSG_REG_READ, pl, 4, out, sizeof(out), &st, &len) ||
	    st != RDC_ST_OK || len != 4)
		return -1;
	*v = rdc_proto_get32(out);
	return 0;
}

static int reg_write(struct link *l, uint32_t reg, uint32_t v)
{
	uint8_t pl[8];
	uint32_t st;

	rdc_proto_put32(pl, reg);
	rdc_proto_put32(pl + 4, v);
	if (request(l, RDC_MSG_REG_WRITE, pl, 8, NULL, 0, &st, NULL))
		return -1;
	return st == RDC_ST_OK ? 0 : -1;
}

static int simple(struct link *l, uint16_t type, const void *pl, uint32_t len)
{
	uint32_t st;

	if (request(l, type, pl, len, NULL, 0, &st, NULL))
		return -1;
	return (int)st;
}

static int ping(struct link *l)
{
	return simple(l, RDC_MSG_PING, NULL, 0);
}

/* A fresh session on the device, greeted. */
static int usb_session(struct link *l, bool control,
		       struct rdc_proto_hello_reply *r)
{
	if (usb_open(l) || session_reset(l))
		return -1;
	return hello(l, control, r);
}

/* ---- Commands ------------------------------------------------------------ */

static int cmd_descriptors(void)
{
	struct link l;
	struct libusb_device_descriptor dd;
	unsigned char s[128] = "";

	if (usb_open(&l))
		return 1;
	libusb_get_device_descriptor(libusb_get_device(l.h), &dd);
	tap(dd.idVendor == opt_vid && dd.idProduct == opt_pid,
	    "device %04x:%04x", dd.idVendor, dd.idProduct);
	if (dd.iProduct)
		libusb_get_string_descriptor_ascii(l.h, dd.iProduct, s,
						   sizeof(s));
	tap(strstr((char *)s, "RDC-1") != NULL, "product string '%s'", s);
	tap(l.ep_out && !(l.ep_out & 0x80), "bulk OUT endpoint 0x%02x",
	    l.ep_out);
	tap(l.ep_in & 0x80, "bulk IN endpoint 0x%02x", l.ep_in);
	tap(l.ep_irq & 0x80, "interrupt IN endpoint 0x%02x", l.ep_irq);
	int speed = libusb_get_device_speed(libusb_get_device(l.h));
	uint16_t bulk = speed == LIBUSB_SPEED_HIGH ? RDC_USB_BULK_HS :
						     RDC_USB_BULK_FS;

	tap(l.maxp_out == bulk && l.maxp_in == bulk,
	    "bulk wMaxPacketSize %u/%u at %s speed (want %u)", l.maxp_out,
	    l.maxp_in, speed == LIBUSB_SPEED_HIGH ? "high" : "full", bulk);
	tap(l.maxp_irq == RDC_USB_INTR_MAXP, "interrupt wMaxPacketSize %u",
	    l.maxp_irq);
	link_close(&l);
	return tap_done();
}

static int cmd_basic(void)
{
	struct rdc_proto_hello_reply hr;
	uint32_t info[4] = { 0 }, info2[4] = { 0 }, v = 0;
	struct link l;
	int r;

	if (usb_open(&l))
		return 1;
	/* (each step before its tap: argument order is unspecified) */
	r = ctrl_info(&l, info);
	tap(!r, "INFO answers");
	tap(info[0] == RDC_PROTO_MAGIC && info[1] == RDC_PROTO_VERSION &&
		    info[2] == RDC_PROTO_MAX_REQUEST,
	    "INFO: magic %08x version %u max request %u session %u", info[0],
	    info[1], info[2], info[3]);
	tap(!session_reset(&l), "RESET answers");
	r = ctrl_info(&l, info2);
	tap(!r && info2[3] == info[3] + 1, "RESET starts session %u", info2[3]);
	tap(!hello(&l, true, &hr), "HELLO");
	tap(hr.version == RDC_PROTO_VERSION && hr.run_mode == RDC_RUN_STEPPED &&
		    (hr.flags & RDC_HELLO_CONTROL),
	    "HELLO reply: version %u, stepped, in control (flags %x)",
	    hr.version, hr.flags);
	tap(ping(&l) == RDC_ST_OK, "PING");
	r = reg_read(&l, RDC_REG_ID, &v);
	tap(!r && v == RDC_ID_VALUE, "REG_READ ID = %08x", v);
	r = reg_write(&l, RDC_REG_CURSOR_FG, 0x00123456u);
	v = 0;
	r = r ? r : reg_read(&l, RDC_REG_CURSOR_FG, &v);
	tap(!r && v == 0x00123456u, "REG_WRITE CURSOR_FG, read back %08x", v);
	tap(simple(&l, 999, NULL, 0) == RDC_ST_TYPE,
	    "an unknown request type: RDC_ST_TYPE, session goes on");
	tap(ping(&l) == RDC_ST_OK, "PING after it");
	link_close(&l);
	return tap_done();
}

static int cmd_irq(void)
{
	struct rdc_proto_hello_reply hr;
	uint8_t sub[12], step[8], ev[64];
	struct rdc_proto_hdr h;
	struct link l;
	int got = 0, r;

	if (usb_session(&l, true, &hr))
		return 1;
	rdc_proto_put32(sub, RDC_SUB_IRQ);
	rdc_proto_put32(sub + 4, 0);
	rdc_proto_put32(sub + 8, RDC_ENC_RAW);
	tap(!reg_write(&l, RDC_REG_IRQ_STATUS, 0xffffffffu),
	    "clear IRQ_STATUS");
	tap(simple(&l, RDC_MSG_SUBSCRIBE, sub, 12) == RDC_ST_OK,
	    "SUBSCRIBE interrupts");
	/* two frame times: a vblank at least (rdcd runs a mode) */
	rdc_proto_put64(step, hr.core_hz / 30u);
	tap(simple(&l, RDC_MSG_STEP, step, 8) == RDC_ST_OK, "STEP 1/30 s");
	r = libusb_interrupt_transfer(l.h, l.ep_irq, ev, sizeof(ev), &got,
				      TMO_MS);
	tap(!r && got == RDC_USB_EVENT_SIZE,
	    "one transfer of %u bytes on the interrupt endpoint (got %d, %s)",
	    RDC_USB_EVENT_SIZE, got, libusb_strerror(r));
	rdc_proto_hdr_decode(ev, &h);
	tap(h.type == RDC_MSG_EV_IRQ && (h.flags & RDC_MSGF_EVENT) &&
		    h.len == RDC_USB_EVENT_SIZE - RDC_PROTO_HDR_SIZE,
	    "it is an EV_IRQ message (type %u flags %x len %u)", h.type,
	    h.flags, h.len);
	tap(rdc_proto_get32(ev + 16) & RDC_IRQ_VBLANK,
	    "with the vblank bit (status %08x, time %llu)",
	    rdc_proto_get32(ev + 16),
	    (unsigned long long)rdc_proto_get64(ev + 20));
	tap(ping(&l) == RDC_ST_OK && !l.ev_irq_on_bulk,
	    "no interrupt event on bulk IN (%u)", l.ev_irq_on_bulk);
	link_close(&l);
	return tap_done();
}

static int cmd_reset(void)
{
	struct rdc_proto_hello_reply hr;
	uint32_t a[4] = { 0 }, b[4] = { 0 };
	uint8_t half[8] = { 4, 0, 0, 0, RDC_MSG_REG_READ, 0, 0, 0 };
	struct link l;
	int r;

	if (usb_session(&l, true, &hr))
		return 1;
	r = ctrl_info(&l, a);
	tap(!r, "INFO: session %u", a[3]);
	tap(!link_write(&l, half, sizeof(half)), "half a request header sent");
	tap(!session_reset(&l), "RESET");
	r = ctrl_info(&l, b);
	tap(!r && b[3] == a[3] + 1, "INFO: session %u", b[3]);
	tap(!hello(&l, true, &hr) && (hr.flags & RDC_HELLO_CONTROL),
	    "HELLO on the new session: the half request is gone, control "
	    "was given up and taken again");
	tap(ping(&l) == RDC_ST_OK, "PING");
	/* a control request nobody defined stalls, the session goes on */
	tap(libusb_control_transfer(l.h, 0xc1, 0x7f, 0, (uint16_t)l.intf,
				    (uint8_t *)a, 4,
				    TMO_MS) == LIBUSB_ERROR_PIPE,
	    "an unknown vendor request stalls");
	tap(ping(&l) == RDC_ST_OK, "PING after the stall");
	tap(libusb_control_transfer(l.h, 0xc0, RDC_USB_REQ_INFO, 0, 0,
				    (uint8_t *)b, 16, TMO_MS) == 16,
	    "INFO with a device recipient answers too");
	link_close(&l);
	return tap_done();
}

static int cmd_bench(unsigned int n)
{
	struct rdc_proto_hello_reply hr;
	struct link l;
	double t0, t1, t2, t3;
	unsigned int ok = 0;
	uint32_t v, len = RDC_PROTO_VRAM_CHUNK;
	uint8_t *vw;

	if (usb_session(&l, true, &hr))
		return 1;
	t0 = now_s();
	for (unsigned int i = 0; i < n; i++)
		ok += ping(&l) == RDC_ST_OK;
	t1 = now_s();
	for (unsigned int i = 0; i < n; i++)
		ok += !reg_read(&l, RDC_REG_ID, &v) && v == RDC_ID_VALUE;
	t2 = now_s();
	tap(ok == 2 * n, "%u PINGs and %u REG_READs answered right", n, n);
	vw = calloc(1, 4 + len);
	tap(vw && simple(&l, RDC_MSG_VRAM_WRITE, vw, 4 + len) == RDC_ST_OK,
	    "VRAM_WRITE of %u bytes", len);
	t3 = now_s();
	free(vw);
	printf("# usb (dummy_hcd, TCG guest): %.0f PINGs/s, REG_READ round "
	       "trip %.0f us, VRAM_WRITE %.1f MB/s\n",
	       n / (t1 - t0), (t2 - t1) / n * 1e6, len / (t3 - t2) / 1e6);
	link_close(&l);
	return tap_done();
}

/* A reply of exactly 512 bytes: VRAM_READ of 512 - 16. */
static int cmd_zlp(void)
{
	struct rdc_proto_hello_reply hr;
	uint8_t pl[8], out[8192];
	struct link l;
	int got = 0, r;

	if (usb_session(&l, true, &hr))
		return 1;
	for (uint32_t size = l.maxp_in - 16; size <= 4u * l.maxp_in;
	     size += l.maxp_in) {
		rdc_proto_put32(pl, 0);
		rdc_proto_put32(pl + 4, size);
		/* one host transfer larger than the reply: must end short */
		struct rdc_proto_hdr h = { .len = 8,
					   .type = RDC_MSG_VRAM_READ,
					   .seq = ++l.seq };
		uint8_t req[24];

		rdc_proto_hdr_encode(req, &h);
		memcpy(req + 16, pl, 8);
		link_write(&l, req, sizeof(req));
		r = libusb_bulk_transfer(l.h, l.ep_in, out, sizeof(out), &got,
					 TMO_MS);
		/* the last byte may come in a transfer of its own */
		if (!r && got == (int)(size + 15)) {
			int more = 0;

			r = libusb_bulk_transfer(l.h, l.ep_in, out + got, 1,
						 &more, TMO_MS);
			got += more;
		}
		tap(!r && got == (int)(size + 16),
		    "a %u-byte reply (%u packets of %u) reaches a %zu-byte "
		    "read: %d bytes (%s)",
		    size + 16, (size + 16) / l.maxp_in, l.maxp_in, sizeof(out),
		    got, libusb_strerror(r));
		if (r)
			break;
	}
	link_close(&l);
	return tap_done();
}

/* ---- Hostile hosts ------------------------------------------------------- */

static int hostile(const char *kind, unsigned int seconds)
{
	struct rdc_proto_hello_reply hr;
	struct rdc_proto_hdr h;
	struct link l;
	uint8_t b[64];
	int r;

	if (!strcmp(kind, "random")) {
		/* no HELLO: random bytes from the first one */
		uint8_t *junk = malloc(65536);
		unsigned int seed = 12345;

		if (!junk || usb_open(&l) || session_reset(&l))
			return 1;
		for (size_t i = 0; i < 65536; i++) {
			seed = seed * 1103515245u + 12345u;
			junk[i] = (uint8_t)(seed >> 16);
		}
		r = link_write(&l, junk, 65536);
		free(junk);
		tap(!r || r == LIBUSB_ERROR_PIPE || r == LIBUSB_ERROR_TIMEOUT,
		    "64 KiB of random bytes: the device takes them or stalls "
		    "(%s)",
		    libusb_strerror(r));
		r = recv_msg(&l, &h, NULL, 0, 2000);
		tap(r == 0 ? h.status != RDC_ST_OK : r == LIBUSB_ERROR_PIPE,
		    "the answer is an error reply or a stall (%s, status %u)",
		    r ? libusb_strerror(r) : "a reply", r ? 0 : h.status);
		link_close(&l);
		return tap_done();
	}
	if (usb_session(&l, strcmp(kind, "truncated") != 0, &hr))
		return 1;
	if (!strcmp(kind, "truncated")) {
		/* REG_WRITE promising 8 bytes, sending 3, then nothing */
		struct rdc_proto_hdr t = { .len = 8,
					   .type = RDC_MSG_REG_WRITE,
					   .seq = 99 };

		rdc_proto_hdr_encode(b, &t);
		tap(!link_write(&l, b, RDC_PROTO_HDR_SIZE + 3),
		    "a truncated REG_WRITE sent");
		r = recv_msg(&l, &h, NULL, 0, 1000);
		tap(r == LIBUSB_ERROR_TIMEOUT, "no reply to it (%s)",
		    libusb_strerror(r));
	} else if (!strcmp(kind, "oversize")) {
		struct rdc_proto_hdr t = { .len = 0xfffffff0u,
					   .type = RDC_MSG_VRAM_WRITE,
					   .seq = 77 };

		rdc_proto_hdr_encode(b, &t);
		tap(!link_write(&l, b, RDC_PROTO_HDR_SIZE + 32),
		    "a VRAM_WRITE claiming 4 GiB sent");
		r = recv_msg(&l, &h, NULL, 0, TMO_MS);
		tap(!r && h.status == RDC_ST_TOOBIG && h.seq == 77,
		    "reply: message too big (status %u)", r ? 0 : h.status);
		r = recv_msg(&l, &h, NULL, 0, TMO_MS);
		tap(r == LIBUSB_ERROR_PIPE,
		    "then bulk IN stalls: rdcd hung up on this session (%s)",
		    libusb_strerror(r));
		r = link_write(&l, b, 16);
		tap(r == LIBUSB_ERROR_PIPE || !r,
		    "bulk OUT stalls or swallows (%s)", libusb_strerror(r));
	} else if (!strcmp(kind, "stall-frames")) {
		/* frames subscribed, time moved, IN never read */
		uint8_t sub[12], step[8];

		rdc_proto_put32(sub, RDC_SUB_FRAMES | RDC_SUB_IRQ);
		rdc_proto_put32(sub + 4, 1);
		rdc_proto_put32(sub + 8, RDC_ENC_RAW);
		tap(simple(&l, RDC_MSG_SUBSCRIBE, sub, 12) == RDC_ST_OK,
		    "SUBSCRIBE frames and interrupts");
		rdc_proto_put64(step, hr.core_hz / 60u);
		for (unsigned int i = 0; i < 30; i++) {
			struct rdc_proto_hdr t = { .len = 8,
						   .type = RDC_MSG_STEP,
						   .seq = ++l.seq };
			uint8_t m[24];

			rdc_proto_hdr_encode(m, &t);
			memcpy(m + 16, step, 8);
			if (link_write(&l, m, sizeof(m)))
				break;
		}
		tap(1, "30 STEPs sent (half a second of frames), nothing read");
		sleep(seconds);
	} else if (!strcmp(kind, "exit-mid-message")) {
		struct rdc_proto_hdr t = { .len = 4096,
					   .type = RDC_MSG_SUBMIT,
					   .seq = 5 };

		rdc_proto_hdr_encode(b, &t);
		tap(!link_write(&l, b, 40), "40 bytes of a 4 KiB SUBMIT sent");
		/* and gone: the handle closes with the request half sent */
	} else if (!strcmp(kind, "long-submit")) {
		uint32_t words = RDC_PROTO_MAX_SUBMIT_WORDS;
		uint8_t *w = calloc(words, 4);
		uint32_t st;

		if (!w)
			return 1;
		for (uint32_t i = 0; i + RDC_CMD_MAX_ARGS <= words;
		     i += RDC_CMD_MAX_ARGS)
			rdc_proto_put32(w + 4 * i,
					RDC_CMD(RDC_OP_NOP, 0,
						RDC_CMD_MAX_ARGS - 1));
		printf("# submitting %u words (until unplugged)\n", words);
		fflush(stdout);
		for (unsigned int i = 0; i < seconds * 10; i++)
			if (request(&l, RDC_MSG_SUBMIT, w, words * 4, NULL, 0,
				    &st, NULL))
				break;
		free(w);
		tap(1, "submitting ended");
	} else if (!strcmp(kind, "frames")) {
		/* frames subscribed, time moved and frames read */
		uint8_t sub[12], step[8];
		double end = now_s() + seconds;

		rdc_proto_put32(sub, RDC_SUB_FRAMES);
		rdc_proto_put32(sub + 4, 1);
		rdc_proto_put32(sub + 8, RDC_ENC_RLE);
		tap(simple(&l, RDC_MSG_SUBSCRIBE, sub, 12) == RDC_ST_OK,
		    "SUBSCRIBE frames");
		printf("# stepping and reading frames (until unplugged)\n");
		rdc_proto_put64(step, hr.core_hz / 60u);
		while (now_s() < end &&
		       simple(&l, RDC_MSG_STEP, step, 8) == RDC_ST_OK)
			;
		printf("# %u frames\n", l.ev_frames);
	} else {
		fprintf(stderr, "usb_raw: unknown hostile kind '%s'\n", kind);
		return 2;
	}
	link_close(&l);
	return tap_done();
}

/* ---- Zero-length packets from FunctionFS --------------------------------- */

/* clang-format off */
struct zlp_descs {
	struct usb_interface_descriptor intf;
	struct usb_endpoint_descriptor_no_audio in;
} __attribute__((packed));

#define ZLP_INTF                                                               \
	{                                                                      \
		.bLength = USB_DT_INTERFACE_SIZE,                              \
		.bDescriptorType = USB_DT_INTERFACE, .bNumEndpoints = 1,       \
		.bInterfaceClass = 0xff, .iInterface = 1,                      \
	}
#define ZLP_EP(maxp)                                                           \
	{                                                                      \
		.bLength = USB_DT_ENDPOINT_SIZE,                               \
		.bDescriptorType = USB_DT_ENDPOINT,                            \
		.bEndpointAddress = 1 | USB_DIR_IN,                            \
		.bmAttributes = USB_ENDPOINT_XFER_BULK,                        \
		.wMaxPacketSize = (maxp),                                      \
	}

/* (x86: little-endian, as FunctionFS wants) */
static const struct {
	struct usb_functionfs_descs_head_v2 head;
	__le32 fs_count, hs_count;
	struct zlp_descs fs, hs;
} __attribute__((packed)) zlp_descs = {
	.head = {.magic = FUNCTIONFS_DESCRIPTORS_MAGIC_V2,
		 .length = sizeof(zlp_descs),
		 .flags = FUNCTIONFS_HAS_FS_DESC | FUNCTIONFS_HAS_HS_DESC},
	.fs_count = 2,
	.hs_count = 2,
	.fs = {ZLP_INTF, ZLP_EP(64)},
	.hs = {ZLP_INTF, ZLP_EP(512)},
};

static const struct {
	struct usb_functionfs_strings_head head;
	struct {
		__le16 code;
		char str1[sizeof("zlp probe")];
	} __attribute__((packed)) lang0;
} __attribute__((packed)) zlp_strings = {
	.head = {.magic = FUNCTIONFS_STRINGS_MAGIC,
		 .length = sizeof(zlp_strings),
		 .str_count = 1,
		 .lang_count = 1},
	.lang0 = {0x0409, "zlp probe"},
};
/* clang-format on */

/* The device side: run before the gadget is bound; exits when done. */
static int cmd_ffs_zlp(const char *dir)
{
	char path[256];
	uint8_t buf[512];
	struct usb_functionfs_event ev[4];
	int ep0, ep1, enabled = 0;
	ssize_t w[3];

	alarm(60); /* a host that never reads must not hang the test */
	snprintf(path, sizeof(path), "%s/ep0", dir);
	ep0 = open(path, O_RDWR);
	if (ep0 < 0 ||
	    write(ep0, &zlp_descs, sizeof(zlp_descs)) != sizeof(zlp_descs) ||
	    write(ep0, &zlp_strings, sizeof(zlp_strings)) !=
		    sizeof(zlp_strings)) {
		perror("usb_raw: ffs-zlp: ep0");
		return 1;
	}
	snprintf(path, sizeof(path), "%s/ep1", dir);
	ep1 = open(path, O_RDWR);
	if (ep1 < 0) {
		perror("usb_raw: ffs-zlp: ep1");
		return 1;
	}
	while (!enabled) {
		struct pollfd p = { .fd = ep0, .events = POLLIN };
		ssize_t n;

		if (poll(&p, 1, 30000) <= 0) {
			fprintf(stderr, "usb_raw: ffs-zlp: never enabled\n");
			return 1;
		}
		n = read(ep0, ev, sizeof(ev));
		for (ssize_t i = 0; i < n / (ssize_t)sizeof(ev[0]); i++)
			enabled |= ev[i].type == FUNCTIONFS_ENABLE;
	}
	memset(buf, 0x5a, sizeof(buf));
	w[0] = write(ep1, buf, 512);
	w[1] = write(ep1, buf, 0);
	w[2] = write(ep1, buf, 100);
	printf("# ffs-zlp: writes of 512, 0, 100 bytes returned %zd, %zd, "
	       "%zd\n",
	       w[0], w[1], w[2]);
	sleep(1);
	close(ep1);
	close(ep0);
	return w[0] == 512 && w[1] == 0 && w[2] == 100 ? 0 : 1;
}

static int cmd_zlp_probe(void)
{
	libusb_context *ctx;
	libusb_device_handle *h = NULL;
	struct libusb_config_descriptor *cfg;
	uint8_t buf[4096], ep = 0;
	int got[2] = { 0, 0 }, r0, r1;

	/*
	 * Without udevd (as in the VM), libusb's device list is the one it
	 * found at libusb_init: look again with a new context each time.
	 */
	for (int i = 0; i < 100; i++) {
		if (libusb_init(&ctx))
			return 1;
		h = libusb_open_device_with_vid_pid(ctx, opt_vid, opt_pid);
		if (h)
			break;
		libusb_exit(ctx);
		usleep(100000);
	}
	if (!h && libusb_init(&ctx))
		return 1;
	if (!h) {
		libusb_device **list;
		ssize_t n = libusb_get_device_list(ctx, &list);

		fprintf(stderr,
			"usb_raw: zlp-probe: no %04x:%04x; there are:", opt_vid,
			opt_pid);
		for (ssize_t i = 0; i < n; i++) {
			struct libusb_device_descriptor dd;

			libusb_get_device_descriptor(list[i], &dd);
			fprintf(stderr, " %04x:%04x", dd.idVendor,
				dd.idProduct);
		}
		fprintf(stderr, "\n");
		return 1;
	}
	r0 = libusb_get_active_config_descriptor(libusb_get_device(h), &cfg);
	if (r0) {
		fprintf(stderr, "usb_raw: zlp-probe: config: %s\n",
			libusb_strerror(r0));
		return 1;
	}
	ep = cfg->interface[0].altsetting[0].endpoint[0].bEndpointAddress;
	libusb_free_config_descriptor(cfg);
	if (libusb_claim_interface(h, 0))
		return 1;
	r0 = libusb_bulk_transfer(h, ep, buf, sizeof(buf), &got[0], TMO_MS);
	r1 = got[0] == 612 ? 0 :
			     libusb_bulk_transfer(h, ep, buf, sizeof(buf),
						  &got[1], TMO_MS);
	tap(!r0 && !r1 && ((got[0] == 512 && got[1] == 100) || got[0] == 612),
	    "the host read %d then %d bytes", got[0], got[1]);
	printf("# finding: a 0-byte write() to a FunctionFS bulk IN endpoint "
	       "file %s\n",
	       got[0] == 512 ? "sends a zero-length packet (it ended a "
			       "512-byte transfer)" :
			       "sends nothing (512 and 100 bytes came as one "
			       "transfer)");
	libusb_release_interface(h, 0);
	libusb_close(h);
	libusb_exit(ctx);
	return tap_done();
}

/* A UNIX-socket client alongside: every answer right, until `stop` exists. */
static int cmd_watch(const char *sock, const char *stop)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	struct rdc_proto_hello_reply hr;
	unsigned long rounds = 0, bad = 0;
	struct link l = { .fd = -1 };
	struct stat st;

	l.rbuf = malloc(RBUF);
	l.fd = socket(AF_UNIX, SOCK_STREAM, 0);
	snprintf(sa.sun_path, sizeof(sa.sun_path), "%s", sock);
	if (!l.rbuf || l.fd < 0 ||
	    connect(l.fd, (struct sockaddr *)&sa, sizeof(sa)) ||
	    hello(&l, false, &hr)) {
		fprintf(stderr, "usb_raw: watch: cannot greet %s\n", sock);
		return 1;
	}
	while (stat(stop, &st)) {
		uint32_t v = 0;

		rounds++;
		if (ping(&l) != RDC_ST_OK || reg_read(&l, RDC_REG_ID, &v) ||
		    v != RDC_ID_VALUE) {
			bad++;
			fprintf(stderr, "usb_raw: watch: round %lu wrong\n",
				rounds);
			if (bad > 3)
				break;
		}
		usleep(20000);
	}
	tap(rounds && !bad,
	    "socket client: %lu rounds of PING and REG_READ, %lu wrong", rounds,
	    bad);
	link_close(&l);
	return tap_done();
}

int main(int argc, char **argv)
{
	int i = 1;

	setvbuf(stdout, NULL, _IOLBF, 0);
	for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
		if (!strcmp(argv[i], "--vid"))
			opt_vid = (uint16_t)strtoul(argv[i + 1], NULL, 16);
		else if (!strcmp(argv[i], "--pid"))
			opt_pid = (uint16_t)strtoul(argv[i + 1], NULL, 16);
		else if (!strcmp(argv[i], "--serial"))
			opt_serial = argv[i + 1];
		else
			break;
	}
	if (i >= argc) {
		fprintf(stderr, "usage: usb_raw [--vid V] [--pid P] [--serial "
				"S] COMMAND (see the source)\n");
		return 2;
	}
	if (!strcmp(argv[i], "descriptors"))
		return cmd_descriptors();
	if (!strcmp(argv[i], "basic"))
		return cmd_basic();
	if (!strcmp(argv[i], "irq"))
		return cmd_irq();
	if (!strcmp(argv[i], "reset"))
		return cmd_reset();
	if (!strcmp(argv[i], "zlp"))
		return cmd_zlp();
	if (!strcmp(argv[i], "bench") && i + 1 < argc)
		return cmd_bench((unsigned int)strtoul(argv[i + 1], NULL, 0));
	if (!strcmp(argv[i], "hostile") && i + 1 < argc)
		return hostile(argv[i + 1],
			       i + 2 < argc ? (unsigned int)atoi(argv[i + 2]) :
					      3);
	if (!strcmp(argv[i], "ffs-zlp") && i + 1 < argc)
		return cmd_ffs_zlp(argv[i + 1]);
	if (!strcmp(argv[i], "zlp-probe"))
		return cmd_zlp_probe();
	if (!strcmp(argv[i], "watch") && i + 2 < argc)
		return cmd_watch(argv[i + 1], argv[i + 2]);
	fprintf(stderr, "usb_raw: unknown command '%s'\n", argv[i]);
	return 2;
}
