/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The rdcd wire protocol, shared by the daemon (userspace/rdcd) and
 * librdc's unix: and tcp: backends.  docs/protocol.md describes it in
 * prose; this header is the definition.
 *
 * Everything is little-endian.  A message is a 16-byte header followed by
 * `len` payload bytes:
 *
 *   off  size  field
 *   0    4     len     payload bytes (not counting the header)
 *   4    2     type    enum rdc_msg_type
 *   6    2     flags   RDC_MSGF_*
 *   8    4     seq     chosen by the client; replies echo it; events: 0
 *   12   4     status  enum rdc_status in replies and events, 0 in requests
 *
 * Every request gets exactly one reply, in request order, with the same
 * type, RDC_MSGF_REPLY and the request's seq.  Events (frames, interrupts)
 * carry RDC_MSGF_EVENT and may come between replies.  Structures are
 * never sent as memory images: rdc_proto_* in userspace/lib/proto.c encode
 * and decode field by field.
 */
#ifndef RDC_PROTO_H
#define RDC_PROTO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define RDC_PROTO_MAGIC	   0x31434452u /* "RDC1" little-endian, in HELLO */
#define RDC_PROTO_VERSION  1u	       /* bumped on incompatible changes */
#define RDC_PROTO_HDR_SIZE 16u

/* ---- Limits (the daemon rejects anything beyond them) ------------------ */
/* Largest request payload: a VRAM write chunk and its address. */
#define RDC_PROTO_VRAM_CHUNK  (1u << 20)
#define RDC_PROTO_MAX_REQUEST (RDC_PROTO_VRAM_CHUNK + 64u)
/* Command words per SUBMIT (librdc splits longer submissions). */
#define RDC_PROTO_MAX_SUBMIT_WORDS (RDC_PROTO_VRAM_CHUNK / 4u)
/* Largest reply or event: a raw frame of the biggest display and its
 * header fields (RLE never exceeds raw: see rdc_proto_frame_encode). */
#define RDC_PROTO_FRAME_HDR	   24u
#define RDC_PROTO_MAX_FRAME_PIXELS (2048u * 2048u)
#define RDC_PROTO_MAX_REPLY \
	(RDC_PROTO_FRAME_HDR + 4u * RDC_PROTO_MAX_FRAME_PIXELS + 64u)
#define RDC_PROTO_MAX_TOKEN 256u /* bytes of a HELLO token */

enum rdc_msg_type {
	RDC_MSG_HELLO = 1,	/* must be first; see struct rdc_proto_hello */
	RDC_MSG_REG_READ = 2,	/* u32 reg -> u32 value */
	RDC_MSG_REG_WRITE = 3,	/* u32 reg, u32 value */
	RDC_MSG_VRAM_READ = 4,	/* u32 addr, u32 len -> len bytes */
	RDC_MSG_VRAM_WRITE = 5, /* u32 addr, bytes */
	RDC_MSG_SUBMIT = 6,	/* u32 words[] (back-pressure: see docs) */
	RDC_MSG_WAIT = 7,	/* struct rdc_proto_wait */
	RDC_MSG_STEP = 8,	/* u64 cycles (in every run mode) */
	RDC_MSG_FRAME_GRAB = 9, /* u32 encoding, u32 max pixels -> frame */
	RDC_MSG_SUBSCRIBE = 10, /* u32 events, u32 every, u32 encoding */
	RDC_MSG_STATS = 11,	/* -> struct rdc_proto_stats */
	RDC_MSG_RESET = 12,	/* u32 RDC_RESET_* */
	RDC_MSG_CLAIM = 13,	/* take control if nobody has it */
	RDC_MSG_RELEASE = 14,	/* give control up */
	RDC_MSG_PING = 15,	/* empty -> empty */
	RDC_MSG_PINS_SET = 16,	/* u32 mask, u32 levels -> u32 pins */
	RDC_MSG_HIST_OPEN = 17, /* struct rdc_proto_hist_open */
	RDC_MSG_HIST_READ = 18, /* u64 first, u32 max -> a page (below) */
	RDC_MSG_HIST_END = 19,	/* end the client's pixel history */
	RDC_MSG_HIST_SET = 20,	/* u32 RDC_HIST_SET_*, u32 value */
	RDC_MSG_EV_FRAME = 64,	/* event: frame (RDC_PROTO_FRAME_HDR + data) */
	RDC_MSG_EV_IRQ = 65,	/* event: u32 new IRQ_STATUS bits, u64 time */
	RDC_MSG_TYPE_MAX_ = 66
};

#define RDC_MSGF_REPLY 0x0001u
#define RDC_MSGF_EVENT 0x0002u

/*
 * Status codes.  The daemon turns its errors into these in one place
 * (rdcd_status_from_error in userspace/rdcd/out.c); librdc turns them
 * back in one place (net_status_to_error in userspace/lib/net.c), where
 * codes past the last known one read as RDC_E_PROTO.  Which of them close
 * the connection: rdc_proto_reply_closes.
 */
enum rdc_status {
	RDC_ST_OK = 0,
	RDC_ST_INVAL = 1,     /* bad argument */
	RDC_ST_NOMEM = 2,     /* the daemon is out of memory */
	RDC_ST_NOSYS = 3,     /* request not offered (in this mode) */
	RDC_ST_TIMEOUT = 4,   /* wait budget exhausted */
	RDC_ST_HALTED = 5,    /* the DP halted during a wait or submit */
	RDC_ST_RANGE = 6,     /* address/size outside the device */
	RDC_ST_MALFORMED = 7, /* payload has the wrong size for its type */
	RDC_ST_BUSY = 8,      /* another client controls the device */
	RDC_ST_AUTH = 9,      /* missing or wrong token (connection closed) */
	RDC_ST_VERSION = 10,  /* bad magic or version (connection closed) */
	RDC_ST_TOOBIG = 11,   /* len over the limit (connection closed) */
	RDC_ST_NOFRAME = 12,  /* no frame completed yet */
	RDC_ST_TYPE = 13,     /* unknown message type */
	RDC_ST_ORDER = 14,    /* HELLO missing or repeated */
	RDC_ST_DEVICE = 15,   /* the device flagged an error */
	RDC_ST_RESET = 16,    /* a RESET ended the pending request */
	RDC_ST_COUNT_ = 17
};

/* HELLO flags and capabilities */
#define RDC_HELLO_CONTROL  0x1u /* request: want control; reply: granted */
#define RDC_CAP_FRAMES	   0x1u /* frame grab and subscription */
#define RDC_CAP_RLE	   0x2u /* RDC_ENC_RLE */
#define RDC_CAP_DELTA	   0x4u /* RDC_ENC_DELTA */
#define RDC_CAP_IRQ_EVENTS 0x8u
#define RDC_CAP_STEP	   0x10u /* the daemon runs stepped (time moves on waits) */
#define RDC_CAP_ALL	   0x1fu

/* The last request type: types up to here are requests. */
#define RDC_MSG_REQUEST_LAST RDC_MSG_HIST_SET

/* Daemon timing modes (HELLO reply) */
enum rdc_run_mode {
	RDC_RUN_PACED = 0,   /* simulated time follows the wall clock */
	RDC_RUN_FAST = 1,    /* as fast as the host allows */
	RDC_RUN_STEPPED = 2, /* only the controlling client's waits move it */
};

/* SUBSCRIBE events */
#define RDC_SUB_FRAMES 0x1u
#define RDC_SUB_IRQ    0x2u

/* Frame encodings */
enum rdc_frame_enc {
	RDC_ENC_RAW = 0,   /* width * height u32 XRGB8888 */
	RDC_ENC_RLE = 1,   /* runs of u32 count (>= 1), u32 pixel */
	RDC_ENC_DELTA = 2, /* rows RLE'd or "same as the previous frame" */
	RDC_ENC_COUNT_ = 3
};

/* RESET kinds */
#define RDC_RESET_SOFT	0u /* CONTROL.SOFT_RESET: time keeps running */
#define RDC_RESET_POWER 1u /* a new chip: VRAM zero, time 0 */

struct rdc_proto_hdr {
	uint32_t len;
	uint16_t type, flags;
	uint32_t seq, status;
};

struct rdc_proto_hello {
	uint32_t magic, version, caps, flags;
	uint32_t token_len;
	const uint8_t *token; /* points into the decoded payload */
};
#define RDC_PROTO_HELLO_FIXED 20u

struct rdc_proto_hello_reply {
	uint32_t version, caps, flags, run_mode;
	uint32_t vram_size, core_hz, client_id;
};
#define RDC_PROTO_HELLO_REPLY_SIZE 28u

/* A wait condition; the same meaning as struct rdc_wait in rdc_priv.h. */
#define RDC_PROTO_WAIT_TERMS 2u
struct rdc_proto_wait {
	uint64_t budget; /* simulated cycles, 0 = default */
	uint32_t needs_dp;
	struct {
		uint32_t kind, reg, mask, value;
	} term[RDC_PROTO_WAIT_TERMS];
};
#define RDC_PROTO_WAIT_SIZE (12u + 16u * RDC_PROTO_WAIT_TERMS)

struct rdc_proto_stats {
	uint64_t time, busy, stall, pixels, frames;
	uint32_t cmds, last_cycles, last_opcode, clients;
	/* for the asking client */
	uint64_t frames_sent, frames_dropped;
};
#define RDC_PROTO_STATS_SIZE 72u

/* The fixed part of a frame (EV_FRAME and FRAME_GRAB replies). */
struct rdc_proto_frame {
	uint32_t width, height, encoding;
	uint32_t dropped; /* frames this client lost so far (queue full) */
	uint64_t number;  /* frame number since reset */
};

/*
 * Pixel history (docs/history.md) kept by the daemon: one at a time on
 * its chip (BUSY for a second), owned by the client that opened it and
 * gone with it.  HIST_OPEN watches x, y, w, h of the screen (w, h not 0;
 * 0xffffffff: to the screen's edge); flags 0 (RDC_HISTORY_WRITES, the
 * write log, is not served: NOSYS).  HIST_READ answers a page: u64
 * entries kept so far, u64 entries not kept (over the limit), u32 n, then
 * n entries of RDC_PROTO_HIST_ENTRY_SIZE from index `first`, n at most
 * `max` and RDC_PROTO_HIST_PAGE; `first` past the entries kept is RANGE.
 */
#define RDC_PROTO_HIST_OPEN_SIZE  20u
#define RDC_PROTO_HIST_READ_SIZE  12u
#define RDC_PROTO_HIST_SET_SIZE	  8u
#define RDC_PROTO_HIST_PAGE_HDR	  20u
#define RDC_PROTO_HIST_ENTRY_SIZE 124u
#define RDC_PROTO_HIST_PAGE	  8192u /* entries a page at most (~1 MiB) */
#define RDC_PROTO_HIST_CALLS	  8u
#define RDC_PROTO_HIST_LIMIT_MAX  (1u << 20) /* entries a history keeps */
/* HIST_SET: what to set */
#define RDC_HIST_SET_LIMIT 1u /* entries kept, 1 .. RDC_PROTO_HIST_LIMIT_MAX */
#define RDC_HIST_SET_LINE  2u /* the .rdl line later entries carry */

struct rdc_proto_hist_open {
	uint32_t x, y, w, h, flags;
};

/* One entry, field by field as rdc.h's struct rdc_history_entry. */
struct rdc_proto_hist_entry {
	uint32_t x, y, format, before, after;
	uint64_t cycle, frame;
	int32_t fetched;
	uint32_t opcode, cmd_index, source, line, cmd_addr, depth;
	uint32_t calls[RDC_PROTO_HIST_CALLS];
	uint32_t rop, alpha, colorkey, colorkey_on, pattern, fg, bg;
};

struct rdc_proto_hist_page {
	uint64_t count, dropped;
	uint32_t n;
};

/* ---- Encoding and decoding (userspace/lib/proto.c) ---------------------- */
void rdc_proto_hdr_encode(uint8_t *p, const struct rdc_proto_hdr *h);
void rdc_proto_hdr_decode(const uint8_t *p, struct rdc_proto_hdr *h);
/*
 * Check a received header: 0, or the status to answer with
 * (RDC_ST_TOOBIG when len exceeds `max_len`, RDC_ST_TYPE for a type
 * outside enum rdc_msg_type).
 */
int rdc_proto_hdr_check(const struct rdc_proto_hdr *h, uint32_t max_len);

/*
 * Whether the daemon closes the connection after answering a request of
 * `type` with `status` (the one place that says so): after TOOBIG (the
 * stream cannot be resynchronised) and after a refused HELLO, whatever
 * the reason (MALFORMED, VERSION, AUTH, BUSY).  ORDER, the answer to a
 * second HELLO, and every other error leave the connection open.
 */
bool rdc_proto_reply_closes(uint32_t type, uint32_t status);

/*
 * Check a request's payload size against its type (HELLO excepted: see
 * rdc_proto_hello_decode): 0, RDC_ST_MALFORMED, RDC_ST_TOOBIG or
 * RDC_ST_TYPE (unknown, or an event type sent as a request).
 */
int rdc_proto_request_check(const struct rdc_proto_hdr *h);

size_t rdc_proto_hello_encode(uint8_t *p, size_t cap,
			      const struct rdc_proto_hello *h);
int rdc_proto_hello_decode(const uint8_t *p, size_t len,
			   struct rdc_proto_hello *h);
void rdc_proto_hello_reply_encode(uint8_t *p,
				  const struct rdc_proto_hello_reply *r);
int rdc_proto_hello_reply_decode(const uint8_t *p, size_t len,
				 struct rdc_proto_hello_reply *r);
void rdc_proto_wait_encode(uint8_t *p, const struct rdc_proto_wait *w);
int rdc_proto_wait_decode(const uint8_t *p, size_t len,
			  struct rdc_proto_wait *w);
void rdc_proto_stats_encode(uint8_t *p, const struct rdc_proto_stats *s);
int rdc_proto_stats_decode(const uint8_t *p, size_t len,
			   struct rdc_proto_stats *s);
void rdc_proto_frame_hdr_encode(uint8_t *p, const struct rdc_proto_frame *f);
int rdc_proto_frame_hdr_decode(const uint8_t *p, size_t len,
			       struct rdc_proto_frame *f);

void rdc_proto_hist_open_encode(uint8_t *p,
				const struct rdc_proto_hist_open *o);
int rdc_proto_hist_open_decode(const uint8_t *p, size_t len,
			       struct rdc_proto_hist_open *o);
void rdc_proto_hist_page_encode(uint8_t *p,
				const struct rdc_proto_hist_page *pg);
/*
 * A HIST_READ reply of len bytes: its header, checked against the entries
 * that follow (n of them, exactly) and against `max`, the most asked for.
 */
int rdc_proto_hist_page_decode(const uint8_t *p, size_t len, uint32_t max,
			       struct rdc_proto_hist_page *pg);
void rdc_proto_hist_entry_encode(uint8_t *p,
				 const struct rdc_proto_hist_entry *e);
/* RDC_ST_MALFORMED for a depth past RDC_PROTO_HIST_CALLS or a source
 * past the four known. */
int rdc_proto_hist_entry_decode(const uint8_t *p,
				struct rdc_proto_hist_entry *e);

/*
 * Encode w x h pixels into out (cap bytes) as `enc`; `prev` is the frame
 * this receiver got last (same size) for RDC_ENC_DELTA, or NULL (then
 * every row is sent).  Returns the bytes written, or 0 if they do not fit
 * (the caller sends RDC_ENC_RAW instead).
 */
size_t rdc_proto_frame_encode(uint8_t *out, size_t cap, uint32_t enc,
			      const uint32_t *pix, const uint32_t *prev,
			      uint32_t w, uint32_t h);
/*
 * Decode into pix (w * h words, holding the previous frame for
 * RDC_ENC_DELTA).  0, or -1 if the data is malformed (pix is then
 * partly written).
 */
int rdc_proto_frame_decode(uint32_t *pix, uint32_t w, uint32_t h, uint32_t enc,
			   const uint8_t *data, size_t len);

/* Little-endian helpers */
static inline void rdc_proto_put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

static inline uint32_t rdc_proto_get32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	       (uint32_t)p[3] << 24;
}

static inline void rdc_proto_put64(uint8_t *p, uint64_t v)
{
	rdc_proto_put32(p, (uint32_t)v);
	rdc_proto_put32(p + 4, (uint32_t)(v >> 32));
}

static inline uint64_t rdc_proto_get64(const uint8_t *p)
{
	return rdc_proto_get32(p) | (uint64_t)rdc_proto_get32(p + 4) << 32;
}

/*
 * The default UNIX socket path: $XDG_RUNTIME_DIR/rdc/rdc.sock, else
 * /tmp/rdc-$UID/rdc.sock.  Returns 0, or -1 if it does not fit `cap`.
 */
int rdc_proto_default_path(char *buf, size_t cap);

#endif /* RDC_PROTO_H */
