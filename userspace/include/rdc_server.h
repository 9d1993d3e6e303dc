/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * librdc's interface for a program that serves the simulated RDC-1 itself,
 * as rdcd does: the chip behind a sim: handle (rdc_chip.h: time, register
 * reads, the run loop, host waits, pins, the last frame and the frame,
 * trace and poll hooks), trace recording (rdcd --record), VCD dumps of
 * a chip the program hooks itself (rdcd --vcd), and what a server on the
 * network needs: token checks, TCP addresses and token files.
 *
 * Internal: these functions are exported under the symbol version
 * RDC_PRIVATE_<version> of the exact release (scripts/librdc-map.sh), so
 * a program built on them runs only with the librdc it was built with;
 * they and the structures of rdc_chip.h may change in any release.  A
 * program that draws, reads registers and grabs frames needs <rdc.h>
 * alone.
 */
#ifndef RDC_SERVER_H
#define RDC_SERVER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rdc.h"
#include "rdc_chip.h"
#include "rdc_proto.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * A wait's result (hw-sim/wait.c) as the library's error, the one mapping
 * every user-space host of the chip uses (sim:, rdcd): 0 a term holds,
 * RDC_E_HALTED the DP halted on a needs-DP wait, RDC_E_TIMEOUT the budget
 * ran out, 1 not yet (RDC_HW_WAIT_MORE).
 */
static inline int rdc_wait_result_error(enum rdc_hw_wait_result r)
{
	switch (r) {
	case RDC_HW_WAIT_DONE:
		return 0;
	case RDC_HW_WAIT_MORE:
		return 1;
	case RDC_HW_WAIT_HALTED:
		return RDC_E_HALTED;
	default:
		return RDC_E_TIMEOUT;
	}
}

/*
 * The host's FIFO feed, one step, as every host of the chip feeds it
 * (rdc_submit, rdcd's SUBMIT), so that the same words give the same
 * register reads, waits and cycles everywhere: read FIFO_FREE; with room,
 * `push` hands over up to that many of the `n` words (NULL: FIFO_DATA
 * writes, a word each) and the step returns how many went in; without,
 * it returns 0 and sets *room to the wait that comes next, FIFO_FREE at
 * least half a FIFO (or the words left, if fewer), which needs the DP.
 * Negative: an error.  `push` returns the words taken or an error.
 */
typedef int (*rdc_fifo_push_fn)(rdc_dev *dev, const uint32_t *words,
				uint32_t n);
int rdc_fifo_feed_step(rdc_dev *dev, const uint32_t *words, size_t n,
		       rdc_fifo_push_fn push, struct rdc_wait_cond *room);

/*
 * The chip behind a "sim:" handle, NULL for any other backend: rdcd owns
 * its device through a sim: handle and hooks frames and time here.
 */
struct rdc_hw *rdc_sim_hw(rdc_dev *dev);

/*
 * The server's trace recorder (record.c; rdcd --record): wrap the sim:
 * handle a server owns so that every operation that can change the
 * device, whoever asked for it, is appended to a file with its simulated
 * time; rdc_replay_file (rdc.h) plays such a file back.  A client records
 * only its own calls, untimed, with rdc_record_start (rdc.h).
 */
struct rdc_server_rec;
struct rdc_server_rec *rdc_server_rec_open(const char *path,
					   uint32_t vram_size);
/* Wrap `dev` (a sim: handle); the wrapper stays until rdc_close(dev). */
void rdc_server_rec_attach(struct rdc_server_rec *rec, rdc_dev *dev);
/* Note a power cycle: the handle is closed and a fresh one attached. */
void rdc_server_rec_power(struct rdc_server_rec *rec);
/* Write the end record (`dev` attached, or NULL), flush and free. */
int rdc_server_rec_close(struct rdc_server_rec *rec, rdc_dev *dev);
/*
 * Time moved on the chip directly, not through the wrapped handle, from
 * simulated time `from` on (rdcd runs long waits in pieces): the trace
 * writes it as a step, in its place, before its next record.  NULL rec:
 * nothing.
 */
void rdc_server_rec_time_moved(struct rdc_server_rec *rec, uint64_t from);
/*
 * A client is about to get an answer that depends on time moved outside
 * the handle (a wait rdcd ran on the chip): write that time as its step
 * now and flush, so a replay of the file so far reaches the same point.
 * The recorder does this itself after REG_READ and WAIT records.  NULL
 * rec: nothing.
 */
void rdc_server_rec_sync(struct rdc_server_rec *rec);

/*
 * Pixel history in a program that serves the device (rdcd): the entries
 * made from now on carry `line` as their .rdl line (a client's script
 * runs on the other side of a socket, and says where it is).
 */
void rdc_history_set_line(rdc_history *h, uint32_t line);
/*
 * A history whose device was closed goes on on another sim: device (a
 * replayed trace's power cycle, rdcd's new chip): RDC_E_INVAL if it is
 * attached or dev is not sim: (a trace recorder on it is fine),
 * RDC_E_BUSY if dev has one.
 */
int rdc_history_attach(rdc_history *h, rdc_dev *dev);

/*
 * The VCD writer (docs/vcd.md) for a program that owns the chip's trace
 * hook itself: it puts rdc_vcd_trace on the hook, or fans events out to
 * it, instead of letting rdc_vcd_open take the hook of a sim: handle.
 *
 * rdc_vcd_new starts a dump at `path` (created or truncated) of the chip
 * *hw points to.  *hw is read again at every event: a program that
 * replaces its chip (a power cycle) keeps one file, whose time goes on
 * from where the old chip stopped, and the new chip's levels are written
 * at that time.  Returns 0 and *out, RDC_E_INVAL, RDC_E_NOMEM or
 * RDC_E_FILE.  Nothing is hooked: the caller routes the chip's trace
 * events to rdc_vcd_trace(*out, ...) and closes with rdc_vcd_close after
 * unhooking it.
 */
int rdc_vcd_new(const char *path, struct rdc_hw *const *hw, rdc_vcd **out);
/* An rdc_trace_fn: the signal events become value changes. */
void rdc_vcd_trace(void *vcd, uint64_t time, unsigned int event, uint32_t a,
		   uint32_t b);

/*
 * Tokens for a server on the network (rdcd's tcp:, the web sink): a
 * constant-time comparison, and a table of the addresses that failed.
 * After RDC_AUTH_FREE_FAILS failures an address is refused without a look
 * at its token for a second, doubling at each further failure up to
 * RDC_AUTH_BACKOFF_MAX_S; a success forgets it.  The table keeps
 * RDC_AUTH_TABLE addresses, the least recent making room.  Not locked:
 * one thread uses a table.
 */
#define RDC_AUTH_FREE_FAILS    3
#define RDC_AUTH_BACKOFF_MAX_S 64
#define RDC_AUTH_TABLE	       32
#define RDC_AUTH_PEER_MAX      64

struct rdc_auth {
	struct rdc_auth_peer {
		char peer[RDC_AUTH_PEER_MAX];
		uint32_t fails;
		uint64_t last_ns, until_ns;
	} t[RDC_AUTH_TABLE];
};

/* Whether got[0 .. n) is the token want[0 .. len), in time that depends
 * on len only. */
bool rdc_auth_token_equal(const uint8_t *want, size_t len, const uint8_t *got,
			  size_t n);
/* Whether `peer` is refused at now_ns (monotonic nanoseconds). */
bool rdc_auth_locked(const struct rdc_auth *a, const char *peer,
		     uint64_t now_ns);
/* A wrong token from `peer` at now_ns. */
void rdc_auth_failed(struct rdc_auth *a, const char *peer, uint64_t now_ns);
/* The right token from `peer`: its failures are forgotten. */
void rdc_auth_passed(struct rdc_auth *a, const char *peer);

/*
 * TCP addresses and token files (tcp.c): one rule for rdcd's tcp: and
 * --token, the web sink's [ADDR:]PORT and token=FILE, and the client's
 * tcp:HOST:PORT?token=FILE (docs/protocol.md, "Addresses and tokens").
 *
 * An address is HOST:PORT, [IPV6]:PORT, or :PORT, which is
 * 127.0.0.1:PORT.  A token file is a regular file (opened without
 * blocking, so a FIFO is refused, not waited on) whose contents without
 * trailing newlines, carriage returns and spaces are 1 to
 * RDC_PROTO_MAX_TOKEN bytes; anything else is refused, never cut.
 * Failures return a negative enum rdc_error with a detail
 * (rdc_last_error_detail) that names the address or the file.
 */
struct sockaddr_storage; /* <sys/socket.h>, which the caller includes */

#define RDC_TCP_HOST_MAX 256 /* a host name's bytes, its NUL included */
#define RDC_TCP_NAME_MAX 64  /* "[IPV6]:PORT" of a bound address, and NUL */

/*
 * Split `hostport` into `host` (a string of at most RDC_TCP_HOST_MAX
 * bytes: "127.0.0.1" for :PORT, an IPv6 address without its brackets)
 * and *port, which points into hostport: 0 or RDC_E_URI.
 */
int rdc_tcp_split(const char *hostport, char host[RDC_TCP_HOST_MAX],
		  const char **port);
/*
 * A listening TCP socket on `hostport` (PORT 0: the kernel picks one),
 * non-blocking and close-on-exec, with SO_REUSEADDR: its descriptor and
 * *bound, the address it has; or RDC_E_URI (the address) or RDC_E_IO.
 */
int rdc_tcp_listen(const char *hostport, int backlog,
		   struct sockaddr_storage *bound);
/* Whether `ss` is a loopback address (127/8, ::1, ::ffff:127/104). */
bool rdc_tcp_is_loopback(const struct sockaddr_storage *ss);
/* "ADDR:PORT", or "[IPV6]:PORT", of `ss` (numeric) into name. */
void rdc_tcp_name(const struct sockaddr_storage *ss,
		  char name[RDC_TCP_NAME_MAX]);
/*
 * Read the token in the file `path` into tok (RDC_PROTO_MAX_TOKEN bytes)
 * and *len: 0 or RDC_E_FILE, whose detail starts with `what` and the
 * path ("--token /tmp: a directory, not a regular file: refused").
 */
int rdc_token_read(const char *what, const char *path,
		   uint8_t tok[RDC_PROTO_MAX_TOKEN], uint32_t *len);

#ifdef __cplusplus
}
#endif

#endif /* RDC_SERVER_H */
