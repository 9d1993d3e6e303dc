// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd's FunctionFS listener (`--listen ffs:DIR`): the RDC-1 as a USB
 * device (rdc_usb.h, docs/usb.md).
 *
 * FunctionFS endpoint files do not poll and block in read and write, so
 * the USB side lives in four small threads and reaches rdcd's loop as an
 * ordinary stream socket: each USB session is a socketpair whose daemon
 * end is served by serve.c like any unix: or tcp: client.
 *
 *   ep0   descriptors and strings at start; then events: ENABLE starts a
 *         session (the listener's eventfd wakes the loop, which accepts
 *         the daemon end), DISABLE and UNBIND end it, the vendor RESET
 *         request ends it and starts another, INFO is answered here.
 *   out   bulk OUT -> the session's socket (a byte stream: no sizes are
 *         taken from the host here; serve.c checks every message).
 *   in    the session's socket -> bulk IN, except RDC_MSG_EV_IRQ
 *         messages, which it recognises by their header and hands to
 *   irq   -> interrupt IN, one event per transfer, from a bounded queue
 *         (a host that never reads it loses the oldest events, and its
 *         replies on bulk IN are not held up).
 *
 * A session ends by shutting its socket down (serve.c then frees the
 * client and whatever control it had) and by waking every thread out of
 * its blocking call with a signal, so no byte of an ended session reaches
 * the next one: the generation counter `gen` tells a thread its session
 * is gone, and the ep0 thread waits until each has seen the new one.  When
 * rdcd hangs up on a session itself (a fatal protocol error), the bulk
 * endpoints are halted: the host sees a stall and sends RESET.
 */
#include <endian.h>
#include <errno.h>
#include <linux/usb/ch9.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ffs_dev.h"
#include "rdc_usb.h"
#include "rdcd.h"

/* Bytes moved per read or write on the bulk endpoints and the socket. */
#define FFS_BUF (64u << 10)
/* Interrupt events queued for the interrupt endpoint. */
#define FFS_IRQ_QUEUE 64u
/* The interface string (the device strings come from the gadget). */
#define FFS_INTF_STR "RDC-1 display controller"
/* The signal that wakes a thread out of a blocking read or write. */
#define FFS_KICK (SIGRTMIN + 4)

enum ffs_ep { FFS_EP_OUT, FFS_EP_IN, FFS_EP_IRQ, FFS_NEP };
enum ffs_thread { FFS_T_OUT, FFS_T_IN, FFS_T_IRQ, FFS_T_EP0, FFS_NT };
/* The data threads: those a session's end must wait for. */
#define FFS_NDATA FFS_T_EP0

struct rdcd_ffs {
	struct ffs_dev v; /* ep0, threads, sessions (v.session: REQ_INFO) */
	int ep[FFS_NEP];

	/* under v.lock */
	bool dead; /* rdcd hung up on this session */

	uint8_t irq[FFS_IRQ_QUEUE][RDC_USB_EVENT_SIZE];
	unsigned int irq_head, irq_n;
	uint64_t irq_dropped;

	uint8_t *outbuf, *inbuf, *stage;
};

/* ---- Descriptors -------------------------------------------------------- */

/* htole16/32 are not constant expressions: these are, for the tables. */
#if __BYTE_ORDER == __LITTLE_ENDIAN
#define FFS_LE16(x) ((__le16)(x))
#define FFS_LE32(x) ((__le32)(x))
#else
#define FFS_LE16(x) ((__le16)__builtin_bswap16(x))
#define FFS_LE32(x) ((__le32)__builtin_bswap32(x))
#endif

/* clang-format off */
struct ffs_intf_descs {
	struct usb_interface_descriptor intf;
	struct usb_endpoint_descriptor_no_audio out, in, irq;
} __attribute__((packed));

static const struct {
	struct usb_functionfs_descs_head_v2 head;
	__le32 fs_count, hs_count;
	struct ffs_intf_descs fs, hs;
} __attribute__((packed)) ffs_descs = {
	.head = {
		.magic = FFS_LE32(FUNCTIONFS_DESCRIPTORS_MAGIC_V2),
		.length = FFS_LE32(sizeof(ffs_descs)),
		/* ALL_CTRL_RECIP: vendor requests addressed to the device
		 * reach us too (rdc_usb.h accepts both recipients) */
		.flags = FFS_LE32(FUNCTIONFS_HAS_FS_DESC |
				 FUNCTIONFS_HAS_HS_DESC |
				 FUNCTIONFS_ALL_CTRL_RECIP),
	},
	.fs_count = FFS_LE32(4),
	.hs_count = FFS_LE32(4),
#define FFS_INTF                                                               \
	{                                                                      \
		.bLength = USB_DT_INTERFACE_SIZE,                              \
		.bDescriptorType = USB_DT_INTERFACE,                           \
		.bNumEndpoints = FFS_NEP,                                      \
		.bInterfaceClass = RDC_USB_CLASS,                              \
		.bInterfaceSubClass = RDC_USB_SUBCLASS,                        \
		.bInterfaceProtocol = RDC_USB_PROTOCOL,                        \
		.iInterface = 1,                                               \
	}
#define FFS_EP(addr, type, maxp, interval)                                     \
	{                                                                      \
		.bLength = USB_DT_ENDPOINT_SIZE,                               \
		.bDescriptorType = USB_DT_ENDPOINT,                            \
		.bEndpointAddress = (addr),                                    \
		.bmAttributes = (type),                                        \
		.wMaxPacketSize = FFS_LE16(maxp),                              \
		.bInterval = (interval),                                       \
	}
	.fs = {
		.intf = FFS_INTF,
		.out = FFS_EP(1 | USB_DIR_OUT, USB_ENDPOINT_XFER_BULK,
			      RDC_USB_BULK_FS, 0),
		.in = FFS_EP(2 | USB_DIR_IN, USB_ENDPOINT_XFER_BULK,
			     RDC_USB_BULK_FS, 0),
		.irq = FFS_EP(3 | USB_DIR_IN, USB_ENDPOINT_XFER_INT,
			      RDC_USB_INTR_MAXP, RDC_USB_INTR_INTERVAL_FS),
	},
	.hs = {
		.intf = FFS_INTF,
		.out = FFS_EP(1 | USB_DIR_OUT, USB_ENDPOINT_XFER_BULK,
			      RDC_USB_BULK_HS, 0),
		.in = FFS_EP(2 | USB_DIR_IN, USB_ENDPOINT_XFER_BULK,
			     RDC_USB_BULK_HS, 0),
		.irq = FFS_EP(3 | USB_DIR_IN, USB_ENDPOINT_XFER_INT,
			      RDC_USB_INTR_MAXP, RDC_USB_INTR_INTERVAL_HS),
	},
#undef FFS_INTF
#undef FFS_EP
};

static const struct {
	struct usb_functionfs_strings_head head;
	struct {
		__le16 code;
		char str1[sizeof(FFS_INTF_STR)];
	} __attribute__((packed)) lang0;
} __attribute__((packed)) ffs_strings = {
	.head = {
		.magic = FFS_LE32(FUNCTIONFS_STRINGS_MAGIC),
		.length = FFS_LE32(sizeof(ffs_strings)),
		.str_count = FFS_LE32(1),
		.lang_count = FFS_LE32(1),
	},
	.lang0 = {FFS_LE16(0x0409), FFS_INTF_STR},
};
/* clang-format on */

/* ---- Threads and sessions ------------------------------------------------ */

/* Lock held, with the generation just moved on: no session is dead. */
static void ffs_session_reset(struct ffs_dev *v)
{
	struct rdcd_ffs *f = (struct rdcd_ffs *)v;

	f->dead = false;
	f->irq_n = 0;
}

/* Lock held: drop the current session, if any. */
static void ffs_session_end(struct rdcd_ffs *f, const char *why)
{
	if (ffs_dev_session_end(&f->v, ffs_session_reset))
		rdcd_log(f->v.d, RDCD_LOG_INFO, "ffs:%s: session %u ended (%s)",
			 f->v.dir, f->v.session, why);
}

/* Lock held: a new session, handed to rdcd's loop through `wake`. */
static void ffs_session_start(struct rdcd_ffs *f)
{
	if (ffs_dev_session_start(&f->v))
		f->dead = false;
}

/*
 * Lock held: rdcd hung up on the session (or its stream broke): halt both
 * bulk endpoints so the host sees a stall and resets.  The threads that
 * own those endpoints do the halting (FunctionFS halts an endpoint on I/O
 * in the wrong direction, under the endpoint file's own lock): the out
 * thread is woken from its read for it; the in thread first sends what
 * rdcd wrote before it hung up (its last reply says why), then halts.
 */
static void ffs_session_dead(struct rdcd_ffs *f, uint32_t gen)
{
	if (gen != f->v.gen || f->dead)
		return;
	rdcd_log(f->v.d, RDCD_LOG_INFO,
		 "ffs:%s: rdcd closed session %u: halting bulk endpoints",
		 f->v.dir, f->v.session);
	f->dead = true;
	pthread_cond_broadcast(&f->v.cond);
	if (f->v.running[FFS_T_OUT])
		pthread_kill(f->v.th[FFS_T_OUT], FFS_KICK);
}

/*
 * Halt an endpoint of session `gen`: a read on an IN endpoint file, a
 * write on OUT.  An IN endpoint refuses (EAGAIN) while its FIFO still
 * holds bytes the host has not collected (the last reply), so that is
 * retried until the host took them or the session ended.
 */
static void ffs_halt(struct rdcd_ffs *f, enum ffs_ep ep, uint32_t gen)
{
	uint8_t b = 0;
	ssize_t r;

	for (;;) {
		bool gone;

		r = ep == FFS_EP_OUT ? write(f->ep[ep], &b, 0) :
				       read(f->ep[ep], &b, 0);
		if (r >= 0 || errno != EAGAIN)
			break;
		pthread_mutex_lock(&f->v.lock);
		gone = gen != f->v.gen || f->v.stop;
		pthread_mutex_unlock(&f->v.lock);
		if (gone)
			return;
		usleep(10000);
	}
	if (r < 0 && errno != EBADMSG && errno != EINTR)
		rdcd_log(f->v.d, RDCD_LOG_WARN, "ffs:%s: halting ep%d: %s",
			 f->v.dir, ep + 1, strerror(errno));
	else
		rdcd_log(f->v.d, RDCD_LOG_DEBUG, "ffs:%s: ep%d halted (%zd)",
			 f->v.dir, ep + 1, r);
}

/* Write all of p to fd (a blocking socket); false if it broke. */
static bool ffs_write_all(int fd, const uint8_t *p, size_t n)
{
	while (n) {
		ssize_t k = write(fd, p, n);

		if (k <= 0)
			return false;
		p += k;
		n -= (size_t)k;
	}
	return true;
}

/* bulk OUT -> socket */
static void *ffs_out_thread(void *arg)
{
	struct rdcd_ffs *f = arg;
	uint32_t halted = 0;
	bool halt_valid = false;

	ffs_dev_thread_signals(&f->v);
	pthread_mutex_lock(&f->v.lock);
	while (!f->v.stop) {
		uint32_t g = f->v.gen;
		int fd = f->v.bfd, err;
		ssize_t n;
		bool ok = true;

		f->v.seen[FFS_T_OUT] = g;
		if (fd < 0 || (halt_valid && halted == g)) {
			pthread_cond_broadcast(&f->v.cond);
			pthread_cond_wait(&f->v.cond, &f->v.lock);
			continue;
		}
		if (f->dead) {
			pthread_mutex_unlock(&f->v.lock);
			ffs_halt(f, FFS_EP_OUT, g);
			pthread_mutex_lock(&f->v.lock);
			halted = g;
			halt_valid = true;
			continue;
		}
		pthread_mutex_unlock(&f->v.lock);
		n = read(f->ep[FFS_EP_OUT], f->outbuf, FFS_BUF);
		err = n < 0 ? errno : 0;
		if (n > 0)
			ok = ffs_write_all(fd, f->outbuf, (size_t)n);
		pthread_mutex_lock(&f->v.lock);
		if (g != f->v.gen || f->v.stop)
			continue; /* that session is gone: so are its bytes */
		if (n < 0 && err != EINTR) {
			/* ESHUTDOWN: disabled; the ep0 thread hears of it */
			rdcd_log(f->v.d, RDCD_LOG_DEBUG, "ffs:%s: bulk OUT: %s",
				 f->v.dir, strerror(err));
			halted = g;
			halt_valid = true;
		} else if (!ok) {
			ffs_session_dead(f, g);
		}
	}
	f->v.exited[FFS_T_OUT] = true;
	pthread_cond_broadcast(&f->v.cond);
	pthread_mutex_unlock(&f->v.lock);
	return NULL;
}

/* Lock held: queue an interrupt event, dropping the oldest when full. */
static void ffs_irq_push(struct rdcd_ffs *f, const uint8_t *ev)
{
	if (f->irq_n == FFS_IRQ_QUEUE) {
		f->irq_head = (f->irq_head + 1) % FFS_IRQ_QUEUE;
		f->irq_n--;
		if (!(f->irq_dropped++ % 1000))
			rdcd_log(f->v.d, RDCD_LOG_INFO,
				 "ffs:%s: the host does not read interrupt "
				 "events: dropping",
				 f->v.dir);
	}
	memcpy(f->irq[(f->irq_head + f->irq_n) % FFS_IRQ_QUEUE], ev,
	       RDC_USB_EVENT_SIZE);
	f->irq_n++;
	pthread_cond_broadcast(&f->v.cond);
}

/*
 * One write on bulk IN.  Never a multiple of the full-speed packet size
 * (hence of the high-speed one): such a write would end on a full packet
 * and a host read longer than it would wait for more, so its last byte
 * goes in a write of its own (rdc_usb.h).
 */
static int ffs_in_write(struct rdcd_ffs *f, const uint8_t *p, size_t n)
{
	while (n) {
		size_t k = n;
		ssize_t r;

		if (!(k % RDC_USB_BULK_FS))
			k--;
		r = write(f->ep[FFS_EP_IN], p, k);
		if (r <= 0)
			return r < 0 ? -errno : -EIO;
		p += r;
		n -= (size_t)r;
	}
	return 0;
}

/* The daemon's byte stream as it goes to the host: where messages are. */
struct ffs_parse {
	uint8_t hdr[RDC_PROTO_HDR_SIZE];
	size_t hgot;
	uint64_t left; /* payload bytes of the current message still to come */
	bool irq;
	uint8_t ev[RDC_USB_EVENT_SIZE];
	size_t evgot;
};

/*
 * Split `n` bytes from the daemon into bulk bytes (to f->stage, `*staged`
 * of FFS_BUF used) and interrupt events.  Returns false if the stream
 * makes no sense (the daemon is trusted, but its lengths are still
 * bounded).
 */
static bool ffs_parse(struct rdcd_ffs *f, struct ffs_parse *ps,
		      const uint8_t *p, size_t n, size_t *staged)
{
	while (n) {
		size_t take;

		if (!ps->left) {
			struct rdc_proto_hdr h;

			take = RDC_PROTO_HDR_SIZE - ps->hgot;
			if (take > n)
				take = n;
			memcpy(ps->hdr + ps->hgot, p, take);
			ps->hgot += take;
			p += take;
			n -= take;
			if (ps->hgot < RDC_PROTO_HDR_SIZE)
				break;
			ps->hgot = 0;
			rdc_proto_hdr_decode(ps->hdr, &h);
			if (h.len > RDC_PROTO_MAX_REPLY)
				return false;
			ps->left = h.len;
			ps->irq = h.type == RDC_MSG_EV_IRQ &&
				  (h.flags & RDC_MSGF_EVENT) &&
				  h.len == RDC_USB_EVENT_SIZE -
						   RDC_PROTO_HDR_SIZE;
			if (ps->irq) {
				memcpy(ps->ev, ps->hdr, RDC_PROTO_HDR_SIZE);
				ps->evgot = RDC_PROTO_HDR_SIZE;
			} else {
				memcpy(f->stage + *staged, ps->hdr,
				       RDC_PROTO_HDR_SIZE);
				*staged += RDC_PROTO_HDR_SIZE;
			}
			continue;
		}
		take = n < ps->left ? n : (size_t)ps->left;
		if (ps->irq) {
			memcpy(ps->ev + ps->evgot, p, take);
			ps->evgot += take;
			if (ps->evgot == RDC_USB_EVENT_SIZE) {
				pthread_mutex_lock(&f->v.lock);
				ffs_irq_push(f, ps->ev);
				pthread_mutex_unlock(&f->v.lock);
			}
		} else {
			memcpy(f->stage + *staged, p, take);
			*staged += take;
		}
		ps->left -= take;
		p += take;
		n -= take;
	}
	return true;
}

/* socket -> bulk IN and the interrupt queue */
static void *ffs_in_thread(void *arg)
{
	struct rdcd_ffs *f = arg;
	struct ffs_parse ps = { 0 };
	uint32_t mine = 0, halted = 0, ended = 0;
	bool halt_valid = false, end_valid = false;

	ffs_dev_thread_signals(&f->v);
	pthread_mutex_lock(&f->v.lock);
	while (!f->v.stop) {
		uint32_t g = f->v.gen;
		int fd = f->v.bfd, err = 0;
		size_t staged = 0;
		ssize_t n;

		f->v.seen[FFS_T_IN] = g;
		if (g != mine) {
			memset(&ps, 0, sizeof(ps)); /* a new stream */
			mine = g;
		}
		if (fd < 0 || (halt_valid && halted == g)) {
			pthread_cond_broadcast(&f->v.cond);
			pthread_cond_wait(&f->v.cond, &f->v.lock);
			continue;
		}
		if (end_valid && ended == g) {
			/* rdcd's stream ended and all of it went out */
			pthread_mutex_unlock(&f->v.lock);
			ffs_halt(f, FFS_EP_IN, g);
			pthread_mutex_lock(&f->v.lock);
			halted = g;
			halt_valid = true;
			continue;
		}
		pthread_mutex_unlock(&f->v.lock);
		/* at most FFS_BUF - HDR, so a header always fits beside it */
		n = read(fd, f->inbuf, FFS_BUF - RDC_PROTO_HDR_SIZE);
		if (n < 0 && errno == EINTR)
			err = EINTR;
		else if (n <= 0)
			err = EPIPE; /* rdcd hung up (ECONNRESET if unread) */
		else if (!ffs_parse(f, &ps, f->inbuf, (size_t)n, &staged))
			err = EPROTO;
		else if (staged)
			err = -ffs_in_write(f, f->stage, staged);
		pthread_mutex_lock(&f->v.lock);
		if (g != f->v.gen || f->v.stop || !err)
			continue;
		if (err == EPIPE || err == EPROTO || err == EINTR) {
			/* EINTR with the session alive: bytes may be lost */
			if (err == EPROTO)
				rdcd_log(f->v.d, RDCD_LOG_ERR,
					 "ffs:%s: rdcd's stream is corrupt",
					 f->v.dir);
			ffs_session_dead(f, g);
			ended = g;
			end_valid = true;
		} else {
			/* ESHUTDOWN: disabled; the ep0 thread hears of it */
			rdcd_log(f->v.d, RDCD_LOG_DEBUG, "ffs:%s: bulk IN: %s",
				 f->v.dir, strerror(err));
			halted = g;
			halt_valid = true;
		}
	}
	f->v.exited[FFS_T_IN] = true;
	pthread_cond_broadcast(&f->v.cond);
	pthread_mutex_unlock(&f->v.lock);
	return NULL;
}

/* interrupt queue -> interrupt IN, one event per transfer */
static void *ffs_irq_thread(void *arg)
{
	struct rdcd_ffs *f = arg;
	uint32_t broken = 0;
	bool broken_valid = false;

	ffs_dev_thread_signals(&f->v);
	pthread_mutex_lock(&f->v.lock);
	while (!f->v.stop) {
		uint32_t g = f->v.gen;
		uint8_t ev[RDC_USB_EVENT_SIZE];
		ssize_t n;

		f->v.seen[FFS_T_IRQ] = g;
		if (f->v.bfd < 0 || !f->irq_n ||
		    (broken_valid && broken == g)) {
			pthread_cond_broadcast(&f->v.cond);
			pthread_cond_wait(&f->v.cond, &f->v.lock);
			continue;
		}
		memcpy(ev, f->irq[f->irq_head], sizeof(ev));
		f->irq_head = (f->irq_head + 1) % FFS_IRQ_QUEUE;
		f->irq_n--;
		pthread_mutex_unlock(&f->v.lock);
		n = write(f->ep[FFS_EP_IRQ], ev, sizeof(ev));
		if (n < 0 && errno != EINTR) {
			/* ESHUTDOWN: disabled; wait for the next session */
			rdcd_log(f->v.d, RDCD_LOG_DEBUG,
				 "ffs:%s: interrupt IN: %s", f->v.dir,
				 strerror(errno));
			broken = g;
			broken_valid = true;
		}
		pthread_mutex_lock(&f->v.lock);
	}
	f->v.exited[FFS_T_IRQ] = true;
	pthread_cond_broadcast(&f->v.cond);
	pthread_mutex_unlock(&f->v.lock);
	return NULL;
}

/* ---- ep0: events and control requests ---------------------------------- */

static bool ffs_is_ours(const struct usb_ctrlrequest *s)
{
	uint8_t recip = s->bRequestType & USB_RECIP_MASK;

	return (s->bRequestType & USB_TYPE_MASK) == USB_TYPE_VENDOR &&
	       (recip == USB_RECIP_INTERFACE || recip == USB_RECIP_DEVICE);
}

static void ffs_setup(struct rdcd_ffs *f, const struct usb_ctrlrequest *s)
{
	bool in = s->bRequestType & USB_DIR_IN;
	uint16_t wlen = le16toh(s->wLength);
	uint8_t b = 0;
	ssize_t r;

	if (ffs_is_ours(s) && s->bRequest == RDC_USB_REQ_RESET && !in &&
	    !wlen) {
		pthread_mutex_lock(&f->v.lock);
		ffs_session_end(f, "reset by the host");
		if (f->v.enabled)
			ffs_session_start(f);
		pthread_mutex_unlock(&f->v.lock);
		/* the status stage: only now may the host send again */
		r = read(f->v.ep0, &b, 0);
	} else if (ffs_is_ours(s) && s->bRequest == RDC_USB_REQ_INFO && in) {
		uint8_t info[RDC_USB_INFO_SIZE];

		rdc_proto_put32(info, RDC_PROTO_MAGIC);
		rdc_proto_put32(info + 4, RDC_PROTO_VERSION);
		rdc_proto_put32(info + 8, RDC_PROTO_MAX_REQUEST);
		pthread_mutex_lock(&f->v.lock);
		rdc_proto_put32(info + 12, f->v.session);
		pthread_mutex_unlock(&f->v.lock);
		r = write(f->v.ep0, info,
			  wlen < sizeof(info) ? wlen : sizeof(info));
	} else {
		rdcd_log(f->v.d, RDCD_LOG_INFO,
			 "ffs:%s: control request %02x/%02x (wLength %u) not "
			 "ours: stall",
			 f->v.dir, s->bRequestType, s->bRequest, wlen);
		/* I/O against the request's direction stalls it */
		r = in ? read(f->v.ep0, &b, 0) : write(f->v.ep0, &b, 0);
		if (r < 0 && errno == EL2HLT)
			r = 0;
	}
	if (r < 0 && errno != EIDRM)
		rdcd_log(f->v.d, RDCD_LOG_WARN, "ffs:%s: ep0: %s", f->v.dir,
			 strerror(errno));
}

static void ffs_event(struct ffs_dev *v, const struct usb_functionfs_event *e)
{
	struct rdcd_ffs *f = (struct rdcd_ffs *)v;

	switch (e->type) {
	case FUNCTIONFS_BIND:
		/* an UNBIND just before may have been folded into this one */
		pthread_mutex_lock(&f->v.lock);
		f->v.enabled = false;
		ffs_session_end(f, "bound again");
		pthread_mutex_unlock(&f->v.lock);
		rdcd_log(f->v.d, RDCD_LOG_INFO, "ffs:%s: bound to a UDC",
			 f->v.dir);
		break;
	case FUNCTIONFS_UNBIND:
	case FUNCTIONFS_DISABLE:
		pthread_mutex_lock(&f->v.lock);
		f->v.enabled = false;
		ffs_session_end(f, e->type == FUNCTIONFS_UNBIND ? "unbound" :
								  "disabled");
		pthread_mutex_unlock(&f->v.lock);
		if (e->type == FUNCTIONFS_UNBIND)
			rdcd_log(f->v.d, RDCD_LOG_INFO, "ffs:%s: unbound",
				 f->v.dir);
		break;
	case FUNCTIONFS_ENABLE:
		pthread_mutex_lock(&f->v.lock);
		f->v.enabled = true;
		ffs_session_end(f, "configured again");
		ffs_session_start(f);
		pthread_mutex_unlock(&f->v.lock);
		break;
	case FUNCTIONFS_SETUP:
		ffs_setup(f, &e->u.setup);
		break;
	case FUNCTIONFS_SUSPEND:
	case FUNCTIONFS_RESUME:
		rdcd_log(f->v.d, RDCD_LOG_DEBUG, "ffs:%s: %s", f->v.dir,
			 e->type == FUNCTIONFS_SUSPEND ? "suspend" : "resume");
		break;
	default:
		break;
	}
}

/* ---- The listener ----------------------------------------------------- */

void rdcd_ffs_close(struct rdcd_ffs *f)
{
	if (!f)
		return;
	ffs_dev_stop(&f->v, false);
	for (unsigned int i = 0; i < FFS_NEP; i++)
		if (f->ep[i] >= 0)
			close(f->ep[i]);
	ffs_dev_fini(&f->v);
	free(f->outbuf);
	free(f->inbuf);
	free(f->stage);
	free(f);
}

int rdcd_ffs_open(const struct rdcd *d, const char *dir, struct rdcd_ffs **out)
{
	static void *(*const fn[FFS_NT])(void *) = {
		[FFS_T_OUT] = ffs_out_thread,
		[FFS_T_IN] = ffs_in_thread,
		[FFS_T_IRQ] = ffs_irq_thread,
		[FFS_T_EP0] = ffs_dev_ep0_thread,
	};
	struct rdcd_ffs *f;

	*out = NULL;
	if (!*dir || strlen(dir) >= sizeof(f->v.dir)) {
		rdcd_log(d, RDCD_LOG_ERR,
			 "ffs:%s: want ffs:DIR (a functionfs mount)", dir);
		return -1;
	}
	f = calloc(1, sizeof(*f));
	if (!f)
		return -1;
	ffs_dev_init(&f->v, d, "ffs", FFS_KICK, FFS_NDATA, ffs_event);
	strcpy(f->v.dir, dir);
	for (unsigned int i = 0; i < FFS_NEP; i++)
		f->ep[i] = -1;

	f->outbuf = malloc(FFS_BUF);
	f->inbuf = malloc(FFS_BUF);
	f->stage = malloc(FFS_BUF);
	if (!f->outbuf || !f->inbuf || !f->stage || f->v.wake < 0 ||
	    f->v.stopfd < 0) {
		rdcd_log(d, RDCD_LOG_ERR, "ffs:%s: out of memory or fds", dir);
		goto fail;
	}
	if (ffs_dev_open_ep0(&f->v, &ffs_descs, sizeof(ffs_descs), &ffs_strings,
			     sizeof(ffs_strings), "scripts/rdc-gadget.sh"))
		goto fail;
	for (unsigned int i = 0; i < FFS_NEP; i++) {
		char name[8];

		snprintf(name, sizeof(name), "ep%u", i + 1);
		f->ep[i] = ffs_dev_open_file(&f->v, name);
		if (f->ep[i] < 0) {
			rdcd_log(d, RDCD_LOG_ERR, "ffs:%s: %s: %s", dir, name,
				 strerror(errno));
			goto fail;
		}
	}
	if (ffs_dev_start(&f->v, fn, f))
		goto fail;
	*out = f;
	return f->v.wake;
fail:
	rdcd_ffs_close(f);
	return -1;
}

void rdcd_ffs_accept(struct rdcd *d, struct rdcd_ffs *f)
{
	ffs_dev_accept(d, &f->v, "usb");
}
