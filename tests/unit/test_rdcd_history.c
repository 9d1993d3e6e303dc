// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Pixel history through rdcd (docs/history.md, docs/protocol.md's
 * HIST_*), over real sockets: a client gets the entries sim: gives for the
 * same script, field by field, .rdl lines included; a history larger than
 * a page read a page at a time; one history at a time (BUSY); malformed,
 * truncated, oversized and out-of-range requests refused while another
 * client is served; a client that goes with its history open frees it;
 * the history goes on across a power cycle and under --record.
 */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "test_history_common.h"
#include "test_net_common.h"

static const char *const args_stepped[] = { "--stepped", NULL };

/* The fill / XOR blit / text scene of docs/history.md. */
static const char scene[] = HISTORY_SCENE;

static void start(struct netd *d, const char *const *args)
{
	if (netd_start(d, args)) {
		netd_dump_log(d);
		fail_msg("rdcd did not start");
	}
}

static void stop(struct netd *d)
{
	assert_int_equal(netd_stop(d), 0);
}

/* The whole history of `text` run on `uri` over x, y, w, h. */
static size_t history_of(const char *uri, const char *text, uint32_t x,
			 uint32_t y, uint32_t w, uint32_t h,
			 struct rdc_history_entry **out, uint64_t *time)
{
	rdc_history *hist = NULL;
	rdc_dev *dev = NULL;
	size_t n;

	assert_int_equal(rdc_open(uri, &dev), 0);
	assert_int_equal(rdc_history_open(dev, x, y, w, h, 0, &hist), 0);
	history_script(dev, text);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_sim_time(dev, time), 0);
	n = rdc_history_count(hist);
	*out = calloc(n + 1, sizeof(**out));
	assert_non_null(*out);
	for (size_t i = 0; i < n; i++)
		assert_int_equal(rdc_history_get(hist, i, &(*out)[i]), 0);
	assert_int_equal(rdc_history_get(hist, n, &(*out)[n]), RDC_E_RANGE);
	assert_int_equal(rdc_history_dropped(hist), 0);
	rdc_history_close(hist);
	rdc_close(dev);
	return n;
}

/*
 * The scene through a fresh stepped rdcd: the entries sim: gives, every
 * field (the .rdl line the client ran included), at the same cycles; and
 * the pixel docs/history.md works out by hand: red, then black, then the
 * glyph's background.
 */
static void test_rdcd_history_same_as_sim(void **state)
{
	static const uint32_t rects[][4] = { { 14, 12, 1, 1 },
					     { 8, 8, 32, 32 } };
	struct netd d;

	(void)state;
	for (size_t r = 0; r < RDC_ARRAY_SIZE(rects); r++) {
		struct rdc_history_entry *es, *en;
		uint64_t ts, tn;
		size_t ns, nn;

		ns = history_of("sim:", scene, rects[r][0], rects[r][1],
				rects[r][2], rects[r][3], &es, &ts);
		start(&d, args_stepped);
		nn = history_of(d.unix_uri, scene, rects[r][0], rects[r][1],
				rects[r][2], rects[r][3], &en, &tn);
		stop(&d);
		assert_int_equal(nn, ns);
		assert_int_equal(tn, ts);
		for (size_t i = 0; i < ns; i++)
			assert_entry_equal(&en[i], &es[i]);
		if (r == 0) {
			assert_int_equal(nn, 3);
			assert_int_equal(en[0].line, 3);
			assert_int_equal(en[0].opcode, RDC_OP_FILL_RECT);
			assert_int_equal(en[0].after, 0xff0000);
			assert_int_equal(en[1].line, 6);
			assert_int_equal(en[1].opcode, RDC_OP_BLIT);
			assert_int_equal(en[1].rop, RDC_ROP_XOR);
			assert_int_equal(en[1].before, 0xff0000);
			assert_int_equal(en[1].after, 0);
			assert_int_equal(en[2].line, 9);
			assert_int_equal(en[2].opcode, RDC_OP_TEXT);
		} else {
			/* the fill's 1024 pixels, then the blit's 256 */
			assert_true(nn > 1024 + 256);
		}
		free(es);
		free(en);
	}
}

/*
 * A fill of the whole 640x480 screen: 307,200 entries, many pages.
 * Through librdc (pages of its own size), and raw: a page is never more
 * than asked, nor than RDC_PROTO_HIST_PAGE, and covers what is kept; a
 * client asking for many pages at once does not keep the daemon from
 * another.
 */
static void test_rdcd_history_pages(void **state)
{
	static const char fill[] = "mode 640x480 xrgb8888\n"
				   "fg #123456\n"
				   "fill 0 0 640 480\n";
	const size_t want = 640u * 480u;
	struct rdc_history_entry e;
	struct rdc_proto_hdr hdr;
	rdc_history *h = NULL;
	rdc_dev *dev = NULL;
	struct netd d;
	uint8_t b[RDC_PROTO_HIST_OPEN_SIZE], *page;
	uint32_t asks[] = { 1, 10, 4096, RDC_PROTO_HIST_PAGE };
	int fd;

	(void)state;
	page = malloc(RDC_PROTO_HIST_PAGE_HDR +
		      (size_t)RDC_PROTO_HIST_PAGE * RDC_PROTO_HIST_ENTRY_SIZE);
	assert_non_null(page);
	start(&d, args_stepped);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_history_open(dev, 0, 0, RDC_HISTORY_SCREEN,
					  RDC_HISTORY_SCREEN, 0, &h),
			 0);
	history_script(dev, fill);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_history_count(h), want);
	/* every pixel once, row by row, black to the colour, line 3 */
	for (size_t i = 0; i < want; i++) {
		assert_int_equal(rdc_history_get(h, i, &e), 0);
		if (e.x != i % 640 || e.y != i / 640 || e.before != 0 ||
		    e.after != 0x123456 || e.line != 3 ||
		    e.opcode != RDC_OP_FILL_RECT)
			fail_msg("entry %zu: (%u,%u) 0x%x -> 0x%x line %u op "
				 "0x%x",
				 i, e.x, e.y, e.before, e.after, e.line,
				 e.opcode);
	}
	/* backwards across a page too */
	assert_int_equal(rdc_history_get(h, 5000, &e), 0);
	assert_int_equal(e.x, 5000 % 640);
	assert_int_equal(rdc_history_get(h, 10, &e), 0);
	assert_int_equal(e.x, 10);

	/* raw: the same pages, bounded */
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, 0, NULL, NULL), RDC_ST_OK);
	/* the history is another client's */
	memset(b, 0, sizeof(b));
	rdc_proto_put64(b, 0);
	rdc_proto_put32(b + 8, 1);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 2, b, 12, NULL, 0),
			 RDC_ST_INVAL);
	rdc_history_close(h);
	h = NULL;
	{
		struct rdc_proto_hist_open o = { 0, 0, 640, 480, 0 };

		rdc_proto_hist_open_encode(b, &o);
		assert_int_equal(netd_call(fd, RDC_MSG_HIST_OPEN, 3, b,
					   sizeof(b), NULL, 0),
				 RDC_ST_OK);
	}
	history_script(dev, "fg #654321\nfill 0 0 640 480\n");
	assert_int_equal(rdc_finish(dev), 0);
	for (size_t k = 0; k < RDC_ARRAY_SIZE(asks); k++) {
		struct rdc_proto_hist_page pg;
		struct rdc_proto_hist_entry pe;
		uint64_t first = want - asks[k] / 2;

		rdc_proto_put64(b, first);
		rdc_proto_put32(b + 8, asks[k]);
		assert_int_equal(netd_send(fd, RDC_MSG_HIST_READ,
					   (uint32_t)(10 + k), b, 12),
				 0);
		assert_int_equal(
			netd_reply(fd, &hdr, page,
				   RDC_PROTO_HIST_PAGE_HDR +
					   (size_t)RDC_PROTO_HIST_PAGE *
						   RDC_PROTO_HIST_ENTRY_SIZE),
			0);
		assert_int_equal(hdr.status, RDC_ST_OK);
		assert_int_equal(rdc_proto_hist_page_decode(page, hdr.len,
							    asks[k], &pg),
				 0);
		assert_int_equal(pg.count, want);
		/* from first to the end: half of what was asked */
		assert_int_equal(pg.n, asks[k] / 2);
		if (pg.n) {
			assert_int_equal(rdc_proto_hist_entry_decode(
						 page + RDC_PROTO_HIST_PAGE_HDR,
						 &pe),
					 0);
			assert_int_equal(pe.x, first % 640);
			assert_int_equal(pe.before, 0x123456);
			assert_int_equal(pe.after, 0x654321);
		}
		/* from the start: exactly what was asked */
		rdc_proto_put64(b, 0);
		assert_int_equal(netd_send(fd, RDC_MSG_HIST_READ, 20, b, 12),
				 0);
		assert_int_equal(
			netd_reply(fd, &hdr, page,
				   RDC_PROTO_HIST_PAGE_HDR +
					   (size_t)RDC_PROTO_HIST_PAGE *
						   RDC_PROTO_HIST_ENTRY_SIZE),
			0);
		assert_int_equal(rdc_proto_hist_page_decode(page, hdr.len,
							    asks[k], &pg),
				 0);
		assert_int_equal(pg.n, asks[k]);
	}
	/*
	 * 40 pages asked for at once and not read (40 MiB of replies): the
	 * daemon queues a few MiB for this client and reads no more of its
	 * requests meanwhile, while the other client is served.
	 */
	for (uint32_t k = 0; k < 40; k++) {
		rdc_proto_put64(b, (uint64_t)k * RDC_PROTO_HIST_PAGE % want);
		rdc_proto_put32(b + 8, RDC_PROTO_HIST_PAGE);
		assert_int_equal(
			netd_send(fd, RDC_MSG_HIST_READ, 100 + k, b, 12), 0);
	}
	history_script(dev, "fill 0 0 4 4\n");
	assert_int_equal(rdc_finish(dev), 0);
	for (uint32_t k = 0; k < 40; k++) {
		assert_int_equal(netd_reply(fd, &hdr, NULL, 0), 0);
		assert_int_equal(hdr.seq, 100 + k);
		assert_int_equal(hdr.status, RDC_ST_OK);
		assert_true(hdr.len > RDC_PROTO_HIST_PAGE_HDR);
	}
	close(fd);
	rdc_close(dev);
	free(page);
	stop(&d);
}

/* A HIST_OPEN from fd; the reply's status. */
static int raw_open(int fd, uint32_t seq, uint32_t x, uint32_t y, uint32_t w,
		    uint32_t h, uint32_t flags)
{
	struct rdc_proto_hist_open o = { x, y, w, h, flags };
	uint8_t b[RDC_PROTO_HIST_OPEN_SIZE];

	rdc_proto_hist_open_encode(b, &o);
	return netd_call(fd, RDC_MSG_HIST_OPEN, seq, b, sizeof(b), NULL, 0);
}

/* One history at a time, from any client; free again once closed. */
static void test_rdcd_history_busy(void **state)
{
	char uri[200];
	rdc_history *h1 = NULL, *h2 = NULL;
	rdc_dev *a = NULL, *b = NULL;
	struct netd d;

	(void)state;
	start(&d, args_stepped);
	snprintf(uri, sizeof(uri), "%s?observe", d.unix_uri);
	assert_int_equal(rdc_open(d.unix_uri, &a), 0);
	assert_int_equal(rdc_open(uri, &b), 0);
	/* an observer may keep the history (it changes nothing) */
	assert_int_equal(rdc_history_open(b, 0, 0, 8, 8, 0, &h2), 0);
	assert_int_equal(rdc_history_open(a, 0, 0, 8, 8, 0, &h1), RDC_E_BUSY);
	assert_null(h1);
	assert_int_equal(rdc_history_open(b, 0, 0, 8, 8, 0, &h1), RDC_E_BUSY);
	/* the daemon keeps no write log */
	rdc_history_close(h2);
	assert_int_equal(rdc_history_open(a, 0, 0, 8, 8, RDC_HISTORY_WRITES,
					  &h1),
			 RDC_E_NOSYS);
	assert_int_equal(rdc_history_open(a, 0, 0, 8, 8, 0, &h1), 0);
	assert_int_equal(rdc_history_set_limit(h1, 10), 0);
	assert_int_equal(rdc_history_set_limit(h1, (size_t)1 << 30),
			 RDC_E_RANGE);
	history_script(a, "mode 640x480 xrgb8888\nfill 0 0 8 8\n");
	assert_int_equal(rdc_finish(a), 0);
	assert_int_equal(rdc_history_count(h1), 10);
	assert_int_equal(rdc_history_dropped(h1), 54);
	/* its device closes first: what was kept comes over */
	rdc_close(a);
	assert_int_equal(rdc_history_count(h1), 10);
	assert_int_equal(rdc_history_dropped(h1), 54);
	rdc_history_close(h1);
	/* and the daemon's history went with the connection */
	assert_int_equal(rdc_history_open(b, 0, 0, 8, 8, 0, &h2), 0);
	rdc_history_close(h2);
	rdc_close(b);
	stop(&d);
}

/* The other client: a register read and a page of its history. */
struct served {
	rdc_dev *dev;
	rdc_history *h;
};

static void assert_served(struct served *s)
{
	struct rdc_history_entry e;
	uint32_t v = 0;

	assert_int_equal(rdc_reg_read(s->dev, RDC_REG_ID, &v), 0);
	assert_int_equal(v, RDC_ID_VALUE);
	assert_true(rdc_history_count(s->h) > 0);
	assert_int_equal(rdc_history_get(s->h, 0, &e), 0);
	assert_int_equal(e.after, 0xff0000);
}

/*
 * Bad requests from one client, each answered with an error, while
 * another keeps its history and is answered between them; one hangs up
 * mid-message, one announces more than the daemon takes.
 */
static void test_rdcd_history_malformed(void **state)
{
	struct served s = { 0 };
	struct netd d;
	uint8_t b[64];
	int fd, fd2;

	(void)state;
	start(&d, args_stepped);
	assert_int_equal(rdc_open(d.unix_uri, &s.dev), 0);
	assert_int_equal(rdc_history_open(s.dev, 8, 8, 4, 4, 0, &s.h), 0);
	history_script(s.dev, "mode 640x480 xrgb8888\nfg #ff0000\n"
			      "fill 0 0 64 64\n");
	assert_int_equal(rdc_finish(s.dev), 0);
	assert_served(&s);

	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, 0, NULL, NULL), RDC_ST_OK);
	memset(b, 0, sizeof(b));
	/* wrong sizes for their types */
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_OPEN, 2, b, 19, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_OPEN, 3, b, 0, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 4, b, 8, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_SET, 5, b, 12, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_END, 6, b, 1, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_served(&s);
	/* someone else's history: BUSY; none of its own to read or end */
	assert_int_equal(raw_open(fd, 7, 0, 0, 1, 1, 0), RDC_ST_BUSY);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 8, b, 12, NULL, 0),
			 RDC_ST_INVAL);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_END, 9, NULL, 0, NULL, 0),
			 RDC_ST_INVAL);
	rdc_proto_put32(b, 1);
	rdc_proto_put32(b + 4, 5);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_SET, 10, b, 8, NULL, 0),
			 RDC_ST_INVAL);
	assert_served(&s);

	/* the other's history closed: bad arguments of this one's own */
	rdc_history_close(s.h);
	s.h = NULL;
	assert_int_equal(raw_open(fd, 11, 0, 0, 0, 1, 0), RDC_ST_INVAL);
	assert_int_equal(raw_open(fd, 12, 0, 0, 1, 0, 0), RDC_ST_INVAL);
	assert_int_equal(raw_open(fd, 13, 0, 0, 1, 1, 0x80), RDC_ST_INVAL);
	assert_int_equal(raw_open(fd, 14, 0, 0, 1, 1, 1), RDC_ST_NOSYS);
	/* a rectangle past every screen is no error: it sees nothing */
	assert_int_equal(raw_open(fd, 15, 0xffffffff, 0xffffffff, 0xffffffff,
				  0xffffffff, 0),
			 RDC_ST_OK);
	assert_int_equal(raw_open(fd, 16, 0, 0, 1, 1, 0), RDC_ST_BUSY);
	/* pages too large, past the end; limits out of range */
	rdc_proto_put64(b, 0);
	rdc_proto_put32(b + 8, 0xffffffff);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 17, b, 12, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put32(b + 8, RDC_PROTO_HIST_PAGE + 1);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 18, b, 12, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put64(b, 1);
	rdc_proto_put32(b + 8, 1);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 19, b, 12, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put64(b, ~0ull);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 20, b, 12, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put32(b, 1);
	rdc_proto_put32(b + 4, 0);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_SET, 21, b, 8, NULL, 0),
			 RDC_ST_INVAL);
	rdc_proto_put32(b + 4, 0xffffffff);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_SET, 22, b, 8, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put32(b, 99);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_SET, 23, b, 8, NULL, 0),
			 RDC_ST_INVAL);
	/* and then it works: an empty page of an empty history */
	rdc_proto_put64(b, 0);
	rdc_proto_put32(b + 8, 5);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_READ, 24, b, 12, b + 16,
				   RDC_PROTO_HIST_PAGE_HDR),
			 RDC_ST_OK);
	assert_int_equal(rdc_proto_get64(b + 16), 0);
	assert_int_equal(rdc_proto_get32(b + 32), 0);
	assert_int_equal(netd_call(fd, RDC_MSG_HIST_END, 25, NULL, 0, NULL, 0),
			 RDC_ST_OK);
	assert_int_equal(rdc_history_open(s.dev, 8, 8, 4, 4, 0, &s.h), 0);
	history_script(s.dev, "fill 0 0 64 64\n");
	assert_int_equal(rdc_finish(s.dev), 0);
	assert_served(&s);

	/* a request announcing more than any: TOOBIG, and closed */
	{
		struct rdc_proto_hdr h = { .len = RDC_PROTO_MAX_REQUEST + 1,
					   .type = RDC_MSG_HIST_READ,
					   .seq = 30 };
		struct rdc_proto_hdr r;

		rdc_proto_hdr_encode(b, &h);
		assert_int_equal(netd_write(fd, b, RDC_PROTO_HDR_SIZE), 0);
		assert_int_equal(netd_reply(fd, &r, NULL, 0), 0);
		assert_int_equal(r.status, RDC_ST_TOOBIG);
		assert_true(netd_closed(fd));
	}
	close(fd);
	assert_served(&s);

	/* a HIST_OPEN cut short, and the client gone */
	fd2 = netd_connect(d.sock);
	assert_true(fd2 >= 0);
	assert_int_equal(netd_hello(fd2, 0, NULL, NULL), RDC_ST_OK);
	{
		struct rdc_proto_hdr h = { .len = RDC_PROTO_HIST_OPEN_SIZE,
					   .type = RDC_MSG_HIST_OPEN,
					   .seq = 2 };

		rdc_proto_hdr_encode(b, &h);
		memset(b + RDC_PROTO_HDR_SIZE, 0, 8);
		assert_int_equal(netd_write(fd2, b, RDC_PROTO_HDR_SIZE + 8), 0);
	}
	assert_served(&s);
	close(fd2);
	assert_served(&s);
	rdc_history_close(s.h);
	rdc_close(s.dev);
	stop(&d);
}

/*
 * A client that goes with its history open frees it: the next HIST_OPEN
 * succeeds once the daemon has seen the hang-up (it answers BUSY until
 * then; the loop is bounded, and only a failing daemon waits it out).
 */
static void test_rdcd_history_client_dies(void **state)
{
	rdc_history *h = NULL;
	rdc_dev *dev = NULL;
	struct netd d;
	int fd, ret = RDC_E_BUSY;

	(void)state;
	start(&d, args_stepped);
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, 0, NULL, NULL), RDC_ST_OK);
	assert_int_equal(raw_open(fd, 2, 0, 0, RDC_HISTORY_SCREEN,
				  RDC_HISTORY_SCREEN, 0),
			 RDC_ST_OK);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0, &h), RDC_E_BUSY);
	/* a screenful of entries waiting for it */
	history_script(dev, "mode 640x480 xrgb8888\nfill 0 0 640 480\n");
	assert_int_equal(rdc_finish(dev), 0);
	close(fd);
	for (int i = 0; i < NETD_IO_MS / 10 && ret == RDC_E_BUSY; i++) {
		ret = rdc_history_open(dev, 0, 0, 1, 1, 0, &h);
		if (ret == RDC_E_BUSY)
			netd_sleep_ms(10);
	}
	assert_int_equal(ret, 0);
	assert_true(netd_log_has(&d, "its pixel history closed with it"));
	history_script(dev, "fill 0 0 1 1\n");
	assert_int_equal(rdc_history_count(h), 1);
	rdc_history_close(h);
	rdc_close(dev);
	/* under ASan: nothing of the history leaked */
	stop(&d);
}

/*
 * Under --record the history is served as without it (the recorder
 * wraps the daemon's device first), and goes on across a power cycle: a
 * raw client opens it, power-cycles the chip and gives control up; the
 * scene another client then draws on the new chip is in it, as on sim:
 * (but for the .rdl line, which only the history's own client tells).
 */
static void test_rdcd_history_record_power(void **state)
{
	char trace[160];
	const char *args[] = { "--stepped", "--record", trace, NULL };
	struct rdc_history_entry *es, *en;
	struct rdc_proto_hist_page pg;
	struct rdc_proto_hdr hdr;
	uint8_t b[16],
		page[RDC_PROTO_HIST_PAGE_HDR + 8 * RDC_PROTO_HIST_ENTRY_SIZE];
	rdc_dev *dev = NULL;
	uint64_t ts, tn;
	size_t ns, nn;
	struct netd d;
	int fd;

	(void)state;
	snprintf(trace, sizeof(trace), "/tmp/rdcd-history-XXXXXX");
	fd = mkstemp(trace);
	assert_true(fd >= 0);
	close(fd);
	ns = history_of("sim:", scene, 8, 8, 32, 32, &es, &ts);
	start(&d, args);
	nn = history_of(d.unix_uri, scene, 8, 8, 32, 32, &en, &tn);
	assert_int_equal(nn, ns);
	for (size_t i = 0; i < ns; i++)
		assert_entry_equal(&en[i], &es[i]);
	free(es);
	free(en);

	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, RDC_HELLO_CONTROL, NULL, NULL),
			 RDC_ST_OK);
	assert_int_equal(raw_open(fd, 2, 14, 12, 1, 1, 0), RDC_ST_OK);
	rdc_proto_put32(b, RDC_RESET_POWER);
	assert_int_equal(netd_call(fd, RDC_MSG_RESET, 3, b, 4, NULL, 0),
			 RDC_ST_OK);
	assert_int_equal(netd_call(fd, RDC_MSG_RELEASE, 4, NULL, 0, NULL, 0),
			 RDC_ST_OK);
	ns = history_of("sim:", scene, 14, 12, 1, 1, &es, &ts);
	assert_int_equal(ns, 3);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	history_script(dev, scene);
	assert_int_equal(rdc_finish(dev), 0);
	rdc_close(dev);
	rdc_proto_put64(b, 0);
	rdc_proto_put32(b + 8, 8);
	assert_int_equal(netd_send(fd, RDC_MSG_HIST_READ, 5, b, 12), 0);
	assert_int_equal(netd_reply(fd, &hdr, page, sizeof(page)), 0);
	assert_int_equal(hdr.status, RDC_ST_OK);
	assert_int_equal(rdc_proto_hist_page_decode(page, hdr.len, 8, &pg), 0);
	assert_int_equal(pg.n, 3);
	for (uint32_t i = 0; i < pg.n; i++) {
		struct rdc_proto_hist_entry pe;

		assert_int_equal(rdc_proto_hist_entry_decode(
					 page + RDC_PROTO_HIST_PAGE_HDR +
						 i * RDC_PROTO_HIST_ENTRY_SIZE,
					 &pe),
				 0);
		assert_int_equal(pe.line, 0);
		assert_int_equal(pe.cycle, es[i].cycle);
		assert_int_equal(pe.opcode, es[i].opcode);
		assert_int_equal(pe.cmd_index, es[i].cmd_index);
		assert_int_equal(pe.before, es[i].before);
		assert_int_equal(pe.after, es[i].after);
		assert_int_equal(pe.rop, es[i].rop);
		assert_int_equal(pe.fg, es[i].fg);
	}
	free(es);
	close(fd);
	stop(&d);
	unlink(trace);
}

/* Run $(O)/san/rdcctl with `args`: its stdout in out, the exit status. */
static int rdcctl(const char *args, char *out, size_t cap)
{
	char daemon[4200], cmd[8192];
	size_t n = 0;
	FILE *p;
	int st;

	assert_int_equal(netd_daemon_path(daemon, sizeof(daemon)), 0);
	/* .../rdcd -> .../rdcctl */
	snprintf(cmd, sizeof(cmd), "%.*sctl %s", (int)strlen(daemon) - 1,
		 daemon, args);
	p = popen(cmd, "r");
	assert_non_null(p);
	while (n + 1 < cap) {
		size_t k = fread(out + n, 1, cap - 1 - n, p);

		if (!k)
			break;
		n += k;
	}
	out[n] = 0;
	st = pclose(p);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void write_file(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	assert_non_null(f);
	assert_int_equal(fputs(text, f) >= 0, 1);
	assert_int_equal(fclose(f), 0);
}

/*
 * rdcctl why and run --history against a running rdcd print what they
 * print on sim:, text and JSON; and diff tells two scripts whose VRAM
 * writes agree but whose frames do not (a palette) at which frame.
 */
static void test_rdcd_history_rdcctl(void **state)
{
	static char a[65536], b[65536];
	char dir[] = "/tmp/rdcd-history-XXXXXX", path[96], p2[96], args[512];
	struct netd d;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/scene.rdl", dir);
	write_file(path, scene);
	snprintf(args, sizeof(args), "why 14 12 %s", path);
	assert_int_equal(rdcctl(args, a, sizeof(a)), 0);
	assert_non_null(strstr(a, "scene.rdl:6 blit (command 7, fifo)"));
	start(&d, args_stepped);
	snprintf(args, sizeof(args), "--connect %s why 14 12 %s", d.unix_uri,
		 path);
	assert_int_equal(rdcctl(args, b, sizeof(b)), 0);
	stop(&d);
	assert_string_equal(b, a);

	snprintf(args, sizeof(args), "run %s --history 10,10,6,6 --json", path);
	assert_int_equal(rdcctl(args, a, sizeof(a)), 0);
	start(&d, args_stepped);
	snprintf(args, sizeof(args),
		 "--connect %s run %s --history 10,10,6,6 --json", d.unix_uri,
		 path);
	assert_int_equal(rdcctl(args, b, sizeof(b)), 0);
	stop(&d);
	assert_true(strlen(a) > 1000);
	assert_string_equal(b, a);

	/* the same writes, another palette entry: frames part */
	write_file(path, "mode 640x480 i8\npalette 0 #000000 #ff0000\n"
			 "fg 1\nfill 0 0 10 10\nwait-frame\n"
			 "palette 1 #00ff00\nwait-frame\nwait-frame\n");
	snprintf(p2, sizeof(p2), "%s/b.rdl", dir);
	write_file(p2, "mode 640x480 i8\npalette 0 #000000 #ff0000\n"
		       "fg 1\nfill 0 0 10 10\nwait-frame\n"
		       "palette 1 #0000ff\nwait-frame\nwait-frame\n");
	snprintf(args, sizeof(args), "diff %s %s", path, p2);
	assert_int_equal(rdcctl(args, a, sizeof(a)), 3);
	assert_non_null(strstr(a, "VRAM writes: the same"));
	assert_non_null(strstr(a, "first frame that differs: frame "));
	assert_non_null(strstr(a, "frame: 100 pixels differ in 0,0 .. 9,9"));
	snprintf(args, sizeof(args), "diff %s %s", p2, p2);
	assert_int_equal(rdcctl(args, a, sizeof(a)), 0);
	assert_null(strstr(a, "first frame that differs"));
	unlink(path);
	unlink(p2);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rdcd_history_same_as_sim),
		cmocka_unit_test(test_rdcd_history_pages),
		cmocka_unit_test(test_rdcd_history_busy),
		cmocka_unit_test(test_rdcd_history_malformed),
		cmocka_unit_test(test_rdcd_history_client_dies),
		cmocka_unit_test(test_rdcd_history_record_power),
		cmocka_unit_test(test_rdcd_history_rdcctl),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
