// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd's DisplayLink listener (`--listen udl:DIR`): the RDC-1 as a USB
 * device that Linux's udl DRM driver drives (docs/usb.md, "DisplayLink
 * personality").  The same FunctionFS plumbing as ffs.c, another
 * personality on top:
 *
 *   ep0   descriptors (vendor interface ff/00/00, bulk OUT endpoints of
 *         which the last is the data endpoint, 0x01 on the host) and
 *         events; the vendor requests udl makes: channel select (OUT 0x12,
 *         16 bytes) and EDID bytes (IN 0x02, the byte at wValue >> 8);
 *         our statistics (IN 0x52); everything else stalls.
 *   out   bulk OUT -> the decoder (udl_decode.c) -> rdc_proto.h requests
 *         (SUBMIT of display-processor words, PINS_SET for blanking) on
 *         the session's socket, which serve.c serves like any client
 *         asking for control.
 *   reply the session's socket -> replies, checked and counted (the
 *         DisplayLink protocol has no way back to the host).
 *
 * A session runs from ENABLE to DISABLE/UNBIND: the decoder starts fresh
 * (udl sends the mode again when it enables the pipe) and the session's
 * socket is a new client of rdcd, as in ffs.c.  The host is not trusted:
 * the decoder bounds everything to VRAM and the daemon checks every
 * request again.
 */
#include <endian.h>
#include <errno.h>
#include <linux/usb/ch9.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "ffs_dev.h"
#include "rdcd.h"
#include "udl_decode.h"

/* udl's transfers are PAGE_SIZE * 16 - 512 bytes (a multiple of 512, so
 * without a short packet): reading exactly that keeps reads aligned to
 * them.  Shorter transfers end on a short packet. */
#define UDL_READ (65536u - 512u)
/* Words per SUBMIT before it is sent (the protocol allows 256 K). */
#define UDL_SUBMIT_WORDS   (64u << 10)
#define UDL_STAGE	   (UDL_SUBMIT_WORDS * 4u + 4096u)
#define UDL_PAD_DEFAULT	   3u /* dummy_hcd: ep2out, ep7out, ep12out, ep1out */
#define UDL_PAD_MAX	   8u
#define UDL_INTF_STR	   "RDC-1 (DisplayLink command set)"
#define UDL_KICK	   (SIGRTMIN + 5)
#define UDL_CLAIM_EVERY_NS 1000000000ull
#define UDL_EDID_INDEX	   0xa1u /* udl's wIndex for EDID reads */

static const uint8_t udl_channel_std[16] = { 0x57, 0xcd, 0xdc, 0xa7, 0x1c, 0x88,
					     0x5e, 0x15, 0x60, 0xfe, 0xc6, 0x97,
					     0x16, 0x3d, 0x47, 0xf2 };

enum { T_OUT, T_REPLY, T_EP0, T_N };

struct rdcd_udl {
	struct ffs_dev v; /* ep0, threads, sessions */
	unsigned int pad;
	uint32_t vram_size;
	uint8_t edid[RDC_UDL_EDID_SIZE];
	int epd; /* the data endpoint's file */

	/* under v.lock */
	bool controlling;
	struct rdc_udl_stats stats; /* a copy, after each transfer */
	uint64_t replies_bad;

	/* the out thread's */
	struct rdc_udl dec;
	uint8_t *in, *stage;
	size_t stage_len, sub_off; /* sub_off: open SUBMIT's header, or 0 */
	bool sub_open, broken;
	int ofd;
	uint32_t seq;
	uint64_t claim_ns;
};

static uint64_t udl_now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

/* ---- Descriptors ----------------------------------------------------------- */

static uint8_t *udl_put_le32(uint8_t *p, uint32_t v)
{
	rdc_proto_put32(p, v);
	return p + 4;
}

static uint8_t *udl_put_intf(uint8_t *p, unsigned int neps)
{
	struct usb_interface_descriptor i = {
		.bLength = USB_DT_INTERFACE_SIZE,
		.bDescriptorType = USB_DT_INTERFACE,
		.bNumEndpoints = (uint8_t)neps,
		.bInterfaceClass = USB_CLASS_VENDOR_SPEC,
		.bInterfaceSubClass = 0, /* what udl matches */
		.bInterfaceProtocol = 0,
		.iInterface = 1,
	};

	memcpy(p, &i, USB_DT_INTERFACE_SIZE);
	return p + USB_DT_INTERFACE_SIZE;
}

static uint8_t *udl_put_ep(uint8_t *p, unsigned int num, unsigned int maxp)
{
	struct usb_endpoint_descriptor_no_audio e = {
		.bLength = USB_DT_ENDPOINT_SIZE,
		.bDescriptorType = USB_DT_ENDPOINT,
		.bEndpointAddress = (uint8_t)(num | USB_DIR_OUT),
		.bmAttributes = USB_ENDPOINT_XFER_BULK,
		.wMaxPacketSize = htole16((uint16_t)maxp),
	};

	memcpy(p, &e, USB_DT_ENDPOINT_SIZE);
	return p + USB_DT_ENDPOINT_SIZE;
}

/*
 * udl sends to bulk OUT endpoint 1 and nowhere else; the UDC numbers
 * endpoints as it likes, in descriptor order.  So `pad` endpoints come
 * first to take the numbers the UDC hands out before 1 (dummy_hcd: 2, 7,
 * 12), and the data endpoint last; the ep0 thread checks what it got.
 */
static size_t udl_descs(uint8_t *buf, unsigned int pad)
{
	uint8_t *p = buf + 12;
	unsigned int neps = pad + 1;

	udl_put_le32(buf, FUNCTIONFS_DESCRIPTORS_MAGIC_V2);
	udl_put_le32(buf + 8, FUNCTIONFS_HAS_FS_DESC | FUNCTIONFS_HAS_HS_DESC |
				      FUNCTIONFS_ALL_CTRL_RECIP);
	p = udl_put_le32(p, 1 + neps);
	p = udl_put_le32(p, 1 + neps);
	for (unsigned int speed = 0; speed < 2; speed++) {
		p = udl_put_intf(p, neps);
		for (unsigned int i = 0; i < neps; i++)
			p = udl_put_ep(p, 1 + i, speed ? 512u : 64u);
	}
	udl_put_le32(buf + 4, (uint32_t)(p - buf));
	return (size_t)(p - buf);
}

static const struct {
	struct usb_functionfs_strings_head head;
	struct {
		__le16 code;
		char str1[sizeof(UDL_INTF_STR)];
	} __attribute__((packed)) lang0;
} __attribute__((packed)) udl_strings = {
	.head = {
		.magic = __cpu_to_le32(FUNCTIONFS_STRINGS_MAGIC),
		.length = __cpu_to_le32(sizeof(udl_strings)),
		.str_count = __cpu_to_le32(1),
		.lang_count = __cpu_to_le32(1),
	},
	.lang0 = {__cpu_to_le16(0x0409), UDL_INTF_STR},
};

/* ---- Sessions ---------------------------------------------------------------- */

/* Lock held: drop the current session, if any. */
static void udl_session_end(struct rdcd_udl *u, const char *why)
{
	if (!ffs_dev_session_end(&u->v, NULL))
		return;
	rdcd_log(u->v.d, RDCD_LOG_INFO,
		 "udl:%s: session %u ended (%s): %llu bytes, %llu commands, "
		 "%llu errors",
		 u->v.dir, u->v.session, why,
		 (unsigned long long)u->stats.bytes,
		 (unsigned long long)u->stats.cmds,
		 (unsigned long long)u->stats.errors);
}

/* Lock held: a new session, handed to rdcd's loop through `wake`. */
static void udl_session_start(struct rdcd_udl *u)
{
	if (!ffs_dev_session_start(&u->v))
		return;
	u->controlling = false;
	memset(&u->stats, 0, sizeof(u->stats));
}

/* ---- The out thread: bulk OUT -> decoder -> requests -------------------------- */

static bool udl_write_all(int fd, const uint8_t *p, size_t n)
{
	while (n) {
		ssize_t k = send(fd, p, n, MSG_NOSIGNAL);

		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0)
			return false;
		p += k;
		n -= (size_t)k;
	}
	return true;
}

static void udl_msg_hdr(struct rdcd_udl *u, uint8_t *p, uint16_t type,
			uint32_t len)
{
	struct rdc_proto_hdr h = { .len = len, .type = type, .seq = ++u->seq };

	rdc_proto_hdr_encode(p, &h);
}

static void udl_sub_close(struct rdcd_udl *u)
{
	if (!u->sub_open)
		return;
	udl_msg_hdr(u, u->stage + u->sub_off, RDC_MSG_SUBMIT,
		    (uint32_t)(u->stage_len - u->sub_off - RDC_PROTO_HDR_SIZE));
	u->sub_open = false;
}

/* Everything staged to rdcd; a broken socket ends this session's output. */
static void udl_flush(struct rdcd_udl *u)
{
	udl_sub_close(u);
	if (u->stage_len && !u->broken &&
	    !udl_write_all(u->ofd, u->stage, u->stage_len))
		u->broken = true;
	u->stage_len = 0;
}

/* Room for n more bytes in the stage. */
static void udl_room(struct rdcd_udl *u, size_t n)
{
	if (u->stage_len + n > UDL_STAGE)
		udl_flush(u);
}

static void udl_simple_msg(struct rdcd_udl *u, uint16_t type, const uint8_t *pl,
			   uint32_t len)
{
	udl_sub_close(u);
	udl_room(u, RDC_PROTO_HDR_SIZE + len);
	udl_msg_hdr(u, u->stage + u->stage_len, type, len);
	memcpy(u->stage + u->stage_len + RDC_PROTO_HDR_SIZE, pl, len);
	u->stage_len += RDC_PROTO_HDR_SIZE + len;
}

/* Ask for control again (at most once a second) if we lost it. */
static void udl_maybe_claim(struct rdcd_udl *u)
{
	bool ctl;
	uint64_t now;

	pthread_mutex_lock(&u->v.lock);
	ctl = u->controlling;
	pthread_mutex_unlock(&u->v.lock);
	now = udl_now_ns();
	if (ctl || now - u->claim_ns < UDL_CLAIM_EVERY_NS)
		return;
	u->claim_ns = now;
	udl_simple_msg(u, RDC_MSG_CLAIM, NULL, 0);
}

static void udl_out_words(void *ctx, const uint32_t *w, size_t n)
{
	struct rdcd_udl *u = ctx;

	if (!u->sub_open) {
		udl_maybe_claim(u);
		udl_room(u, RDC_PROTO_HDR_SIZE + 4 * n);
		u->sub_off = u->stage_len;
		u->stage_len += RDC_PROTO_HDR_SIZE;
		u->sub_open = true;
	} else if ((u->stage_len - u->sub_off) / 4 + n > UDL_SUBMIT_WORDS ||
		   u->stage_len + 4 * n > UDL_STAGE) {
		udl_flush(u);
		udl_out_words(ctx, w, n);
		return;
	}
	for (size_t i = 0; i < n; i++)
		rdc_proto_put32(u->stage + u->stage_len + 4 * i, w[i]);
	u->stage_len += 4 * n;
}

static void udl_out_blank(void *ctx, bool dark)
{
	struct rdcd_udl *u = ctx;
	uint8_t pl[8];

	rdc_proto_put32(pl, RDC_PIN_BL_EN);
	rdc_proto_put32(pl + 4, dark ? 0 : RDC_PIN_BL_EN);
	udl_simple_msg(u, RDC_MSG_PINS_SET, pl, sizeof(pl));
}

/* A new session: HELLO asking for control, then the decoder's setup. */
static void udl_out_begin(struct rdcd_udl *u, int fd)
{
	struct rdc_proto_hello h = {
		.magic = RDC_PROTO_MAGIC,
		.version = RDC_PROTO_VERSION,
		.flags = RDC_HELLO_CONTROL,
	};
	struct rdc_udl_out out = { udl_out_words, udl_out_blank, u };
	uint8_t pl[RDC_PROTO_HELLO_FIXED];
	size_t n = rdc_proto_hello_encode(pl, sizeof(pl), &h);

	u->ofd = fd;
	u->broken = false;
	u->stage_len = 0;
	u->sub_open = false;
	u->claim_ns = udl_now_ns();
	udl_simple_msg(u, RDC_MSG_HELLO, pl, (uint32_t)n);
	rdc_udl_init(&u->dec, u->vram_size, &out);
	udl_flush(u);
}

static void *udl_out_thread(void *arg)
{
	struct rdcd_udl *u = arg;
	uint32_t begun = 0, idle = 0;
	bool begun_valid = false, idle_valid = false;

	ffs_dev_thread_signals(&u->v);
	pthread_mutex_lock(&u->v.lock);
	while (!u->v.stop) {
		uint32_t g = u->v.gen;
		int fd = u->v.bfd, err;
		ssize_t n;

		u->v.seen[T_OUT] = g;
		if (fd < 0 || (idle_valid && idle == g)) {
			pthread_cond_broadcast(&u->v.cond);
			pthread_cond_wait(&u->v.cond, &u->v.lock);
			continue;
		}
		pthread_mutex_unlock(&u->v.lock);
		if (!begun_valid || begun != g) {
			udl_out_begin(u, fd);
			begun = g;
			begun_valid = true;
		}
		n = read(u->epd, u->in, UDL_READ);
		err = n < 0 ? errno : 0;
		if (n > 0) {
			rdc_udl_feed(&u->dec, u->in, (size_t)n);
			udl_flush(u);
		}
		pthread_mutex_lock(&u->v.lock);
		if (g != u->v.gen || u->v.stop)
			continue;
		u->stats = u->dec.st;
		if (n < 0 && err != EINTR) {
			/* ESHUTDOWN: disabled; the ep0 thread ends the session */
			rdcd_log(u->v.d, RDCD_LOG_DEBUG, "udl:%s: bulk OUT: %s",
				 u->v.dir, strerror(err));
			idle = g;
			idle_valid = true;
		} else if (u->broken) {
			rdcd_log(u->v.d, RDCD_LOG_ERR,
				 "udl:%s: rdcd closed session %u", u->v.dir,
				 u->v.session);
			idle = g;
			idle_valid = true;
		}
	}
	u->v.exited[T_OUT] = true;
	pthread_cond_broadcast(&u->v.cond);
	pthread_mutex_unlock(&u->v.lock);
	return NULL;
}

/* ---- The reply thread ------------------------------------------------------------ */

static bool udl_read_full(int fd, uint8_t *p, size_t n)
{
	while (n) {
		ssize_t k = read(fd, p, n);

		if (k < 0 && errno == EINTR)
			return false; /* kicked: the session may be over */
		if (k <= 0)
			return false;
		p += k;
		n -= (size_t)k;
	}
	return true;
}

/* One reply: false when the stream ended. */
static bool udl_reply(struct rdcd_udl *u, int fd)
{
	uint8_t hdr[RDC_PROTO_HDR_SIZE], pl[64];
	struct rdc_proto_hdr h;
	uint64_t left;

	if (!udl_read_full(fd, hdr, sizeof(hdr)))
		return false;
	rdc_proto_hdr_decode(hdr, &h);
	if (h.len > RDC_PROTO_MAX_REPLY)
		return false;
	for (left = h.len; left;) {
		size_t k = left < sizeof(pl) ? (size_t)left : sizeof(pl);

		if (!udl_read_full(fd, pl, k))
			return false;
		if (h.type == RDC_MSG_HELLO && left == h.len &&
		    k >= RDC_PROTO_HELLO_REPLY_SIZE) {
			struct rdc_proto_hello_reply r;

			if (!rdc_proto_hello_reply_decode(pl, k, &r)) {
				bool ctl = r.flags & RDC_HELLO_CONTROL;

				pthread_mutex_lock(&u->v.lock);
				u->controlling = ctl;
				pthread_mutex_unlock(&u->v.lock);
				if (!ctl)
					rdcd_log(
						u->v.d, RDCD_LOG_WARN,
						"udl:%s: another client controls "
						"the RDC-1: the host's drawing "
						"waits for control",
						u->v.dir);
			}
		}
		left -= k;
	}
	if (!(h.flags & RDC_MSGF_REPLY))
		return true; /* an event: none is asked for */
	pthread_mutex_lock(&u->v.lock);
	if (h.type == RDC_MSG_CLAIM && h.status == RDC_ST_OK)
		u->controlling = true;
	if (h.status == RDC_ST_BUSY)
		u->controlling = false;
	if (h.status != RDC_ST_OK && !(u->replies_bad++ % 1000))
		rdcd_log(u->v.d, RDCD_LOG_WARN,
			 "udl:%s: rdcd answered request type %u with status "
			 "%u (%llu so far)",
			 u->v.dir, h.type, h.status,
			 (unsigned long long)u->replies_bad);
	pthread_mutex_unlock(&u->v.lock);
	return true;
}

static void *udl_reply_thread(void *arg)
{
	struct rdcd_udl *u = arg;
	uint32_t done = 0;
	bool done_valid = false;

	ffs_dev_thread_signals(&u->v);
	pthread_mutex_lock(&u->v.lock);
	while (!u->v.stop) {
		uint32_t g = u->v.gen;
		int fd = u->v.bfd;
		bool ok;

		u->v.seen[T_REPLY] = g;
		if (fd < 0 || (done_valid && done == g)) {
			pthread_cond_broadcast(&u->v.cond);
			pthread_cond_wait(&u->v.cond, &u->v.lock);
			continue;
		}
		pthread_mutex_unlock(&u->v.lock);
		ok = udl_reply(u, fd);
		pthread_mutex_lock(&u->v.lock);
		if (!ok && g == u->v.gen) {
			done = g;
			done_valid = true;
		}
	}
	u->v.exited[T_REPLY] = true;
	pthread_cond_broadcast(&u->v.cond);
	pthread_mutex_unlock(&u->v.lock);
	return NULL;
}

/* ---- ep0 ---------------------------------------------------------------------------- */

static void udl_check_endpoint(struct rdcd_udl *u)
{
	struct usb_endpoint_descriptor desc;
	int r = ioctl(u->epd, FUNCTIONFS_ENDPOINT_DESC, &desc);

	if (r < 0)
		rdcd_log(u->v.d, RDCD_LOG_WARN,
			 "udl:%s: cannot read the data endpoint's address: %s",
			 u->v.dir, strerror(errno));
	else if (desc.bEndpointAddress != (1 | USB_DIR_OUT))
		rdcd_log(u->v.d, RDCD_LOG_ERR,
			 "udl:%s: the UDC made the data endpoint 0x%02x, but "
			 "udl sends to 0x01: try udl:%s?pad=N with another N "
			 "(now %u)",
			 u->v.dir, desc.bEndpointAddress, u->v.dir, u->pad);
	else
		rdcd_log(u->v.d, RDCD_LOG_DEBUG,
			 "udl:%s: data endpoint 0x01 (after %u padding)",
			 u->v.dir, u->pad);
}

static void udl_stall(struct rdcd_udl *u, const struct usb_ctrlrequest *s)
{
	uint8_t b = 0;
	ssize_t r;

	rdcd_log(u->v.d, RDCD_LOG_INFO,
		 "udl:%s: control request %02x/%02x wValue %04x wIndex %04x "
		 "(wLength %u) not served: stall",
		 u->v.dir, s->bRequestType, s->bRequest, le16toh(s->wValue),
		 le16toh(s->wIndex), le16toh(s->wLength));
	r = s->bRequestType & USB_DIR_IN ? read(u->v.ep0, &b, 0) :
					   write(u->v.ep0, &b, 0);
	(void)r;
}

static void udl_setup(struct rdcd_udl *u, const struct usb_ctrlrequest *s)
{
	bool in = s->bRequestType & USB_DIR_IN;
	bool vendor = (s->bRequestType & USB_TYPE_MASK) == USB_TYPE_VENDOR;
	uint16_t wlen = le16toh(s->wLength), wval = le16toh(s->wValue);
	ssize_t r = 0;

	if (vendor && !in && s->bRequest == RDC_UDL_REQ_CHANNEL && wlen &&
	    wlen <= 64) {
		uint8_t key[64];

		r = read(u->v.ep0, key, wlen); /* the data stage */
		if (r == (ssize_t)sizeof(udl_channel_std) &&
		    !memcmp(key, udl_channel_std, sizeof(key[0]) * 16))
			rdcd_log(u->v.d, RDCD_LOG_DEBUG,
				 "udl:%s: standard channel selected", u->v.dir);
		else
			rdcd_log(u->v.d, RDCD_LOG_INFO,
				 "udl:%s: channel select with %zd unknown "
				 "bytes: the command set stays the same",
				 u->v.dir, r);
	} else if (vendor && in && s->bRequest == RDC_UDL_REQ_EDID &&
		   le16toh(s->wIndex) == UDL_EDID_INDEX && wlen >= 1) {
		uint8_t ans[2] = { 0, u->edid[wval >> 8] }; /* status, byte */

		r = write(u->v.ep0, ans, wlen < 2 ? wlen : 2);
	} else if (vendor && in && s->bRequest == RDC_UDL_REQ_STATS &&
		   wlen >= 1) {
		uint8_t st[RDC_UDL_STATS_SIZE];

		pthread_mutex_lock(&u->v.lock);
		rdc_udl_stats_encode(st, &u->stats);
		pthread_mutex_unlock(&u->v.lock);
		r = write(u->v.ep0, st, wlen < sizeof(st) ? wlen : sizeof(st));
	} else {
		udl_stall(u, s);
		return;
	}
	if (r < 0 && errno != EIDRM)
		rdcd_log(u->v.d, RDCD_LOG_WARN, "udl:%s: ep0: %s", u->v.dir,
			 strerror(errno));
}

static void udl_event(struct ffs_dev *v, const struct usb_functionfs_event *e)
{
	struct rdcd_udl *u = (struct rdcd_udl *)v;

	switch (e->type) {
	case FUNCTIONFS_BIND:
	case FUNCTIONFS_UNBIND:
	case FUNCTIONFS_DISABLE:
		pthread_mutex_lock(&u->v.lock);
		u->v.enabled = false;
		udl_session_end(u, e->type == FUNCTIONFS_BIND ? "bound again" :
				   e->type == FUNCTIONFS_UNBIND ? "unbound" :
								  "disabled");
		pthread_mutex_unlock(&u->v.lock);
		break;
	case FUNCTIONFS_ENABLE:
		udl_check_endpoint(u);
		pthread_mutex_lock(&u->v.lock);
		u->v.enabled = true;
		udl_session_end(u, "configured again");
		udl_session_start(u);
		pthread_mutex_unlock(&u->v.lock);
		break;
	case FUNCTIONFS_SETUP:
		udl_setup(u, &e->u.setup);
		break;
	default:
		break;
	}
}

/* ---- The listener ------------------------------------------------------------------- */

void rdcd_udl_close(struct rdcd_udl *u)
{
	if (!u)
		return;
	ffs_dev_stop(&u->v, true);
	if (u->epd >= 0)
		close(u->epd);
	ffs_dev_fini(&u->v);
	free(u->in);
	free(u->stage);
	free(u);
}

/* DIR[?pad=N] */
static int udl_parse(struct rdcd_udl *u, const char *spec)
{
	const char *q = strchr(spec, '?');
	size_t len = q ? (size_t)(q - spec) : strlen(spec);

	if (!len || len >= sizeof(u->v.dir))
		return -1;
	memcpy(u->v.dir, spec, len);
	u->v.dir[len] = 0;
	u->pad = UDL_PAD_DEFAULT;
	if (q) {
		char *end;
		unsigned long v;

		if (strncmp(q + 1, "pad=", 4))
			return -1;
		v = strtoul(q + 5, &end, 10);
		if (*end || end == q + 5 || v > UDL_PAD_MAX)
			return -1;
		u->pad = (unsigned int)v;
	}
	return 0;
}

int rdcd_udl_open(const struct rdcd *d, const char *spec, struct rdcd_udl **out)
{
	static void *(*const fn[T_N])(void *) = {
		[T_OUT] = udl_out_thread,
		[T_REPLY] = udl_reply_thread,
		[T_EP0] = ffs_dev_ep0_thread,
	};
	uint8_t descs[12 + 8 +
		      2 * (USB_DT_INTERFACE_SIZE +
			   (UDL_PAD_MAX + 1) * USB_DT_ENDPOINT_SIZE)];
	uint32_t preset = RDC_PRESET_COUNT;
	struct rdcd_udl *u;
	char name[16];
	size_t dlen;

	*out = NULL;
	u = calloc(1, sizeof(*u));
	if (!u)
		return -1;
	ffs_dev_init(&u->v, d, "udl", UDL_KICK, T_EP0, udl_event);
	u->epd = -1;
	if (udl_parse(u, spec)) {
		rdcd_log(d, RDCD_LOG_ERR,
			 "udl:%s: want udl:DIR[?pad=N] (a functionfs mount; N "
			 "0..%u endpoints before the data endpoint)",
			 spec, UDL_PAD_MAX);
		goto fail;
	}
	u->vram_size = d->vram_size;
	/* the mode rdcd started with comes first in the EDID */
	if (rdc_reg_read(d->dev, RDC_REG_MODE_PRESET, &preset))
		preset = RDC_PRESET_COUNT;
	rdc_udl_edid(u->edid, preset, u->vram_size);
	u->in = malloc(UDL_READ);
	u->stage = malloc(UDL_STAGE);
	if (!u->in || !u->stage || u->v.wake < 0 || u->v.stopfd < 0) {
		rdcd_log(d, RDCD_LOG_ERR, "udl:%s: out of memory or fds",
			 u->v.dir);
		goto fail;
	}
	dlen = udl_descs(descs, u->pad);
	if (ffs_dev_open_ep0(&u->v, descs, dlen, &udl_strings,
			     sizeof(udl_strings),
			     "scripts/rdc-gadget.sh --personality udl"))
		goto fail;
	snprintf(name, sizeof(name), "ep%u", u->pad + 1);
	u->epd = ffs_dev_open_file(&u->v, name);
	if (u->epd < 0) {
		rdcd_log(d, RDCD_LOG_ERR, "udl:%s: %s/%s: %s", u->v.dir,
			 u->v.dir, name, strerror(errno));
		goto fail;
	}
	if (ffs_dev_start(&u->v, fn, u))
		goto fail;
	*out = u;
	return u->v.wake;
fail:
	rdcd_udl_close(u);
	return -1;
}

void rdcd_udl_accept(struct rdcd *d, struct rdcd_udl *u)
{
	ffs_dev_accept(d, &u->v, "udl");
}
