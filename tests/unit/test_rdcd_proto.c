// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd against hostile and careless clients, over real sockets: malformed,
 * truncated, oversized and out-of-order messages, hang-ups mid-message,
 * tokens, control passing between clients, and the daemon still serving
 * everyone else afterwards and exiting cleanly (under ASan: no leaks).
 */
#include <dirent.h>
#include <png.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "rdc_priv.h" /* the wait kinds the protocol carries */
#include "test_net_common.h"

static const char *const args_stepped[] = { "--stepped", "-v", NULL };

/* A fresh connection that says HELLO; -1 on failure. */
static int hello_fd(const struct netd *d, uint32_t flags)
{
	int fd = netd_connect(d->sock);

	if (fd < 0)
		return -1;
	if (netd_hello(fd, flags, NULL, NULL) != RDC_ST_OK) {
		close(fd);
		return -1;
	}
	return fd;
}

/* The daemon still answers a newcomer. */
static void assert_serving(const struct netd *d)
{
	int fd = hello_fd(d, 0);

	assert_true(fd >= 0);
	assert_int_equal(netd_call(fd, RDC_MSG_PING, 9, NULL, 0, NULL, 0),
			 RDC_ST_OK);
	close(fd);
}

static void test_bad_messages(void **state)
{
	struct rdc_proto_hello_reply hr;
	struct netd d;
	uint8_t b[64] = { 0 };
	int fd;

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);

	/* before HELLO: refused, but the connection stays */
	assert_int_equal(netd_call(fd, RDC_MSG_PING, 1, NULL, 0, NULL, 0),
			 RDC_ST_ORDER);
	assert_int_equal(netd_hello(fd, RDC_HELLO_CONTROL, NULL, &hr),
			 RDC_ST_OK);
	assert_int_equal(hr.flags, RDC_HELLO_CONTROL);
	assert_int_equal(hr.run_mode, RDC_RUN_STEPPED);
	assert_int_equal(hr.vram_size, 16u << 20);
	/* a second HELLO is out of order */
	assert_int_equal(netd_hello(fd, 0, NULL, NULL), RDC_ST_ORDER);

	/* wrong payload sizes for their types */
	assert_int_equal(netd_call(fd, RDC_MSG_REG_READ, 2, b, 3, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_WRITE, 3, b, 12, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_SUBMIT, 4, b, 6, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_WAIT, 5, b, 10, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(fd, RDC_MSG_PING, 6, b, 1, NULL, 0),
			 RDC_ST_MALFORMED);
	/* unknown types, and events sent as requests */
	assert_int_equal(netd_call(fd, 40, 7, b, 8, NULL, 0), RDC_ST_TYPE);
	assert_int_equal(netd_call(fd, RDC_MSG_EV_FRAME, 8, b, 8, NULL, 0),
			 RDC_ST_TYPE);
	assert_int_equal(netd_call(fd, 0, 9, NULL, 0, NULL, 0), RDC_ST_TYPE);
	/* arguments out of range */
	rdc_proto_put32(b, RDC_REG_WINDOW);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_READ, 10, b, 4, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put32(b, (16u << 20) - 4);
	rdc_proto_put32(b + 4, 8);
	assert_int_equal(netd_call(fd, RDC_MSG_VRAM_READ, 11, b, 8, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put32(b, 0xfffffffcu);
	assert_int_equal(netd_call(fd, RDC_MSG_VRAM_WRITE, 12, b, 12, NULL, 0),
			 RDC_ST_RANGE);
	memset(b, 0, sizeof(b));
	rdc_proto_put32(b + 12, 99); /* wait kind */
	assert_int_equal(netd_call(fd, RDC_MSG_WAIT, 13, b, RDC_PROTO_WAIT_SIZE,
				   NULL, 0),
			 RDC_ST_INVAL);
	rdc_proto_put64(b, ~0ull); /* step of forever */
	assert_int_equal(netd_call(fd, RDC_MSG_STEP, 14, b, 8, NULL, 0),
			 RDC_ST_RANGE);
	rdc_proto_put32(b, 7);
	assert_int_equal(netd_call(fd, RDC_MSG_RESET, 15, b, 4, NULL, 0),
			 RDC_ST_INVAL);
	/* and after all that, the connection works */
	rdc_proto_put32(b, RDC_REG_ID);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_READ, 16, b, 4, b + 8, 4),
			 RDC_ST_OK);
	assert_int_equal(rdc_proto_get32(b + 8), RDC_ID_VALUE);

	/* time moves by a step; a power cycle is a new chip at time 0 */
	rdc_proto_put64(b, 1000);
	assert_int_equal(netd_call(fd, RDC_MSG_STEP, 20, b, 8, NULL, 0),
			 RDC_ST_OK);
	rdc_proto_put32(b, RDC_REG_TIME_LO);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_READ, 21, b, 4, b + 8, 4),
			 RDC_ST_OK);
	assert_true(rdc_proto_get32(b + 8) >= 1000);
	rdc_proto_put32(b, RDC_RESET_POWER);
	assert_int_equal(netd_call(fd, RDC_MSG_RESET, 22, b, 4, NULL, 0),
			 RDC_ST_OK);
	rdc_proto_put32(b, RDC_REG_TIME_LO);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_READ, 23, b, 4, b + 8, 4),
			 RDC_ST_OK);
	assert_int_equal(rdc_proto_get32(b + 8), 0);

	/* oversized: answered, then the connection is closed */
	{
		uint8_t h[RDC_PROTO_HDR_SIZE];
		struct rdc_proto_hdr hdr = { .len = RDC_PROTO_MAX_REQUEST + 1,
					     .type = RDC_MSG_SUBMIT,
					     .seq = 17 };
		struct rdc_proto_hdr r;

		rdc_proto_hdr_encode(h, &hdr);
		assert_int_equal(netd_write(fd, h, sizeof(h)), 0);
		assert_int_equal(netd_reply(fd, &r, NULL, 0), 0);
		assert_int_equal(r.status, RDC_ST_TOOBIG);
		assert_int_equal(r.seq, 17);
		assert_true(netd_closed(fd));
	}
	close(fd);
	assert_serving(&d);

	/* a bad magic: answered and closed */
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	memset(b, 0, sizeof(b));
	assert_int_equal(netd_call(fd, RDC_MSG_HELLO, 1, b,
				   RDC_PROTO_HELLO_FIXED, NULL, 0),
			 RDC_ST_VERSION);
	assert_true(netd_closed(fd));
	close(fd);
	assert_serving(&d);

	/* a malformed HELLO (short, or a token_len that disagrees with the
	 * payload) is refused as any HELLO is: answered and closed */
	for (int k = 0; k < 2; k++) {
		fd = netd_connect(d.sock);
		assert_true(fd >= 0);
		memset(b, 0, sizeof(b));
		rdc_proto_put32(b, RDC_PROTO_MAGIC);
		rdc_proto_put32(b + 4, RDC_PROTO_VERSION);
		rdc_proto_put32(b + 16, 5); /* token_len, no token */
		assert_int_equal(netd_call(fd, RDC_MSG_HELLO, 1, b,
					   k ? RDC_PROTO_HELLO_FIXED : 12, NULL,
					   0),
				 RDC_ST_MALFORMED);
		assert_true(netd_closed(fd));
		close(fd);
	}
	assert_serving(&d);
	assert_true(netd_log_has(&d, "message too big"));
	assert_true(netd_log_has(&d, "bad magic or version"));
	assert_int_equal(netd_stop(&d), 0);
}

static void test_hangups(void **state)
{
	uint8_t h[RDC_PROTO_HDR_SIZE], b[64] = { 0 };
	struct rdc_proto_hdr hdr = { .len = 4096,
				     .type = RDC_MSG_SUBMIT,
				     .seq = 2 };
	struct netd d;
	int fd;

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	/* half a header */
	fd = netd_connect(d.sock);
	assert_true(fd >= 0);
	assert_int_equal(netd_write(fd, "\x10\x00\x00", 3), 0);
	close(fd);
	/* a header and part of its payload, from the controlling client */
	fd = hello_fd(&d, RDC_HELLO_CONTROL);
	assert_true(fd >= 0);
	rdc_proto_hdr_encode(h, &hdr);
	assert_int_equal(netd_write(fd, h, sizeof(h)), 0);
	assert_int_equal(netd_write(fd, b, sizeof(b)), 0);
	close(fd);
	/* a subscriber that leaves with a frame half sent */
	fd = hello_fd(&d, 0);
	assert_true(fd >= 0);
	rdc_proto_put32(b, RDC_SUB_FRAMES);
	rdc_proto_put32(b + 4, 1);
	rdc_proto_put32(b + 8, RDC_ENC_RAW);
	assert_int_equal(netd_call(fd, RDC_MSG_SUBSCRIBE, 3, b, 12, NULL, 0),
			 RDC_ST_OK);
	{
		rdc_dev *dev;

		/* control passed on: the first controller left */
		assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
		assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60,
					      RDC_FMT_XRGB8888, 0),
				 0);
		assert_int_equal(rdc_frame_wait(dev), 0);
		assert_int_equal(rdc_frame_wait(dev), 0);
		close(fd); /* unread frames pending */
		assert_int_equal(rdc_frame_wait(dev), 0);
		rdc_close(dev);
	}
	assert_serving(&d);
	assert_true(netd_log_has(&d, "hung up mid-message"));
	assert_int_equal(netd_stop(&d), 0);
}

static void test_control(void **state)
{
	rdc_dev *a = NULL, *b = NULL, *obs = NULL;
	uint8_t p[8];
	struct netd d;
	uint32_t v;
	int fd;

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	assert_int_equal(rdc_open(d.unix_uri, &a), 0);
	/* a second controller is refused; an observer is welcome */
	assert_int_equal(rdc_open(d.unix_uri, &b), RDC_E_BUSY);
	assert_null(b);
	{
		char uri[200];

		snprintf(uri, sizeof(uri), "%s?observe", d.unix_uri);
		assert_int_equal(rdc_open(uri, &obs), 0);
	}
	assert_int_equal(rdc_reg_write(a, RDC_REG_FENCE, 0), 0);
	assert_int_equal(rdc_reg_write(a, RDC_REG_CLUT_INDEX, 5), 0);
	/* observers read, but do not write, submit or move time */
	assert_int_equal(rdc_reg_read(obs, RDC_REG_CLUT_INDEX, &v), 0);
	assert_int_equal(v, 5);
	assert_int_equal(rdc_reg_write(obs, RDC_REG_CLUT_INDEX, 1), RDC_E_BUSY);
	assert_int_equal(rdc_finish(obs), RDC_E_BUSY);
	assert_int_equal(rdc_vblank_wait(obs), RDC_E_BUSY);
	assert_int_equal(rdc_reg_read(obs, RDC_REG_RDATA, &v), RDC_E_BUSY);
	/* reading CLUT_DATA advances CLUT_INDEX: the controller's alone */
	assert_int_equal(rdc_reg_read(obs, RDC_REG_CLUT_DATA, &v), RDC_E_BUSY);
	assert_int_equal(rdc_reg_read(obs, RDC_REG_CLUT_INDEX, &v), 0);
	assert_int_equal(v, 5);
	assert_int_equal(rdc_reg_read(a, RDC_REG_CLUT_DATA, &v), 0);
	assert_int_equal(rdc_reg_read(obs, RDC_REG_CLUT_INDEX, &v), 0);
	assert_int_equal(v, 6);
	/* control passes when its holder leaves */
	fd = hello_fd(&d, 0);
	assert_true(fd >= 0);
	assert_int_equal(netd_call(fd, RDC_MSG_CLAIM, 2, NULL, 0, NULL, 0),
			 RDC_ST_BUSY);
	rdc_close(a);
	/* the daemon sees the hang-up before our next request is read */
	for (int i = 0; i < 100; i++) {
		int st = netd_call(fd, RDC_MSG_CLAIM, 3, NULL, 0, NULL, 0);

		if (st == RDC_ST_OK)
			break;
		assert_int_equal(st, RDC_ST_BUSY);
		netd_sleep_ms(10);
	}
	rdc_proto_put32(p, RDC_REG_CLUT_INDEX);
	rdc_proto_put32(p + 4, 9);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_WRITE, 4, p, 8, NULL, 0),
			 RDC_ST_OK);
	assert_int_equal(rdc_reg_read(obs, RDC_REG_CLUT_INDEX, &v), 0);
	assert_int_equal(v, 9);
	/* ... or gives it up */
	assert_int_equal(netd_call(fd, RDC_MSG_RELEASE, 5, NULL, 0, NULL, 0),
			 RDC_ST_OK);
	assert_int_equal(netd_call(fd, RDC_MSG_REG_WRITE, 6, p, 8, NULL, 0),
			 RDC_ST_BUSY);
	assert_int_equal(rdc_open(d.unix_uri, &b), 0);
	assert_int_equal(rdc_reg_write(b, RDC_REG_CLUT_INDEX, 3), 0);
	rdc_close(b);
	rdc_close(obs);
	close(fd);
	assert_int_equal(netd_stop(&d), 0);
}

static void test_token(void **state)
{
	char tokfile[200], badfile[200], uri[400], args_tok[220];
	const char *args[] = { "--stepped", "--token", args_tok, NULL };
	rdc_dev *dev = NULL;
	struct netd d;
	FILE *f;
	int fd;

	(void)state;
	snprintf(tokfile, sizeof(tokfile), "/tmp/rdcd-tok-%d", (int)getpid());
	snprintf(badfile, sizeof(badfile), "/tmp/rdcd-bad-%d", (int)getpid());
	f = fopen(tokfile, "w");
	assert_non_null(f);
	fputs("s3cret-token\n", f);
	fclose(f);
	f = fopen(badfile, "w");
	assert_non_null(f);
	fputs("s3cret-tokem\n", f);
	fclose(f);
	snprintf(args_tok, sizeof(args_tok), "%s", tokfile);
	assert_int_equal(netd_start(&d, args), 0);

	/* TCP without a token, with a wrong one: refused */
	assert_int_equal(rdc_open(d.tcp_uri, &dev), RDC_E_AUTH);
	snprintf(uri, sizeof(uri), "%s?token=%s", d.tcp_uri, badfile);
	assert_int_equal(rdc_open(uri, &dev), RDC_E_AUTH);
	snprintf(uri, sizeof(uri), "%s?token=/nonexistent/tok", d.tcp_uri);
	assert_int_equal(rdc_open(uri, &dev), RDC_E_FILE);
	/* the right one */
	snprintf(uri, sizeof(uri), "%s?token=%s", d.tcp_uri, tokfile);
	assert_int_equal(rdc_open(uri, &dev), 0);
	rdc_close(dev);
	/* the environment variable works too */
	setenv("RDC_TOKEN_FILE", tokfile, 1);
	assert_int_equal(rdc_open(d.tcp_uri, &dev), 0);
	rdc_close(dev);
	unsetenv("RDC_TOKEN_FILE");
	/* tcp::PORT is 127.0.0.1:PORT, as rdcd's --listen has it */
	snprintf(uri, sizeof(uri), "tcp:%s?token=%s", strrchr(d.tcp_uri, ':'),
		 tokfile);
	assert_int_equal(rdc_open(uri, &dev), 0);
	rdc_close(dev);
	/*
	 * The token file's rule is rdcd's: a file longer than a HELLO's
	 * token is refused, naming it (it was cut to its first 256 bytes,
	 * which rdcd then refused as a wrong token), and so is a directory
	 * (it was read as no token).
	 */
	f = fopen(badfile, "w");
	assert_non_null(f);
	for (int i = 0; i < 300; i++)
		fputc('a', f);
	fclose(f);
	snprintf(uri, sizeof(uri), "%s?token=%s", d.tcp_uri, badfile);
	assert_int_equal(rdc_open(uri, &dev), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), badfile));
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "longer than 256 bytes"));
	snprintf(uri, sizeof(uri), "%s?token=/tmp", d.tcp_uri);
	assert_int_equal(rdc_open(uri, &dev), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "/tmp: a directory, not a regular file"));
	/* the UNIX socket is guarded by its file mode instead */
	fd = hello_fd(&d, 0);
	assert_true(fd >= 0);
	close(fd);
	{
		struct stat st;

		assert_int_equal(stat(d.sock, &st), 0);
		assert_int_equal(st.st_mode & 0777, 0600);
	}
	assert_true(netd_log_has(&d, "bad token"));
	assert_int_equal(netd_stop(&d), 0);
	unlink(tokfile);
	unlink(badfile);
}

/* A non-loopback TCP listener without a token: the daemon will not start. */
static void test_token_required(void **state)
{
	const char *args[] = { "--listen", "tcp:0.0.0.0:0", NULL };
	struct netd d;

	(void)state;
	assert_int_equal(netd_start(&d, args), -1);
	assert_int_equal(d.pid, 0); /* it exited by itself */
	assert_true(netd_log_has(&d, "--token FILE is required"));
	netd_stop(&d); /* cleans up */
}

/*
 * :PORT is 127.0.0.1 for --web as for --listen tcp: (the web sink
 * refused it, so rdcd did not start).
 */
static void test_listen_rule(void **state)
{
	const char *args[] = { "--stepped", "--listen", "tcp::0",
			       "--web",	    ":0",	NULL };
	char line[160];
	int tcp = 0;
	struct netd d;
	FILE *f;

	(void)state;
	if (netd_start(&d, args)) {
		netd_dump_log(&d);
		fail_msg("rdcd --listen tcp::0 --web :0 did not start");
	}
	f = fopen(d.ready, "r");
	assert_non_null(f);
	while (fgets(line, sizeof(line), f))
		tcp += !strncmp(line, "tcp:127.0.0.1:", 14);
	fclose(f);
	assert_int_equal(tcp, 2);
	assert_true(netd_log_has(&d, "web page at http://127.0.0.1:"));
	assert_int_equal(netd_stop(&d), 0);
}

#define LOAD_CLIENTS 64

/*
 * 64 clients at once on a free-running daemon: some subscribe to frames
 * and never read, some poll registers, one draws.  Nobody is starved, the
 * drawing's fences all arrive, the silent subscribers lose frames alone.
 */
static void test_many_clients(void **state)
{
	static const char *const args[] = { "--fast", "-q", NULL };
	/* observers and the flooder; the controller is the 64th */
	int fds[LOAD_CLIENTS - 1];
	const int flood = LOAD_CLIENTS - 2;
	uint8_t p[16];
	rdc_dev *dev = NULL;
	rdc_batch *b;
	struct netd d;
	uint32_t v;

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60,
				      RDC_FMT_XRGB8888, 0),
			 0);
	for (int i = 0; i < flood; i++) {
		fds[i] = hello_fd(&d, 0);
		assert_true(fds[i] >= 0);
		if (i % 2 == 0) {
			rdc_proto_put32(p, RDC_SUB_FRAMES | RDC_SUB_IRQ);
			rdc_proto_put32(p + 4, 1);
			rdc_proto_put32(p + 8, RDC_ENC_RAW);
			assert_int_equal(netd_call(fds[i], RDC_MSG_SUBSCRIBE, 2,
						   p, 12, NULL, 0),
					 RDC_ST_OK);
		}
	}
	/* the last one floods requests and never reads a reply */
	fds[flood] = hello_fd(&d, 0);
	assert_true(fds[flood] >= 0);
	{
		uint8_t ping[RDC_PROTO_HDR_SIZE];
		struct rdc_proto_hdr ph = { .type = RDC_MSG_PING };
		int flags = fcntl(fds[flood], F_GETFL);
		int sent = 0;

		rdc_proto_hdr_encode(ping, &ph);
		fcntl(fds[flood], F_SETFL, flags | O_NONBLOCK);
		/* until the daemon stops taking them: it throttles, not grows */
		for (int k = 0; k < 2000000; k++) {
			if (send(fds[flood], ping, sizeof(ping),
				 MSG_NOSIGNAL) != (ssize_t)sizeof(ping)) {
				netd_sleep_ms(1);
				if (send(fds[flood], ping, sizeof(ping),
					 MSG_NOSIGNAL) < 0)
					break;
			}
			sent++;
		}
		assert_true(sent < 2000000);
	}
	b = rdc_batch_new();
	assert_non_null(b);
	for (uint32_t round = 1; round <= 20; round++) {
		for (int i = 0; i < 50; i++) {
			assert_int_equal(
				rdc_batch_fg(b, round * 977u + (uint32_t)i), 0);
			assert_int_equal(rdc_batch_fill_rect(b, i * 11,
							     (int)round * 20,
							     30, 15),
					 0);
		}
		assert_int_equal(rdc_batch_fence(b, round), 0);
		assert_int_equal(rdc_batch_submit(dev, b), 0);
		/* the odd clients keep asking */
		for (int i = 1; i < flood; i += 2) {
			rdc_proto_put32(p, RDC_REG_FRAME_COUNT);
			assert_int_equal(netd_call(fds[i], RDC_MSG_REG_READ,
						   round, p, 4, NULL, 0),
					 RDC_ST_OK);
		}
		assert_int_equal(rdc_fence_wait(dev, round), 0);
	}
	/* everything acknowledged was executed */
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_PERF_CMDS, &v), 0);
	assert_true(v >= 20 * 101);
	/* frames kept coming while the silent ones sat on theirs */
	{
		uint32_t f0, f1;

		assert_int_equal(rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &f0),
				 0);
		assert_int_equal(rdc_vblank_wait(dev), 0);
		assert_int_equal(rdc_vblank_wait(dev), 0);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &f1),
				 0);
		assert_true(f1 - f0 >= 2);
	}
	/* a silent subscriber, drained now: it lost frames, for itself */
	{
		uint8_t st[RDC_PROTO_STATS_SIZE];
		struct rdc_proto_stats s;

		for (int k = 0; k < 40; k++)
			assert_int_equal(rdc_vblank_wait(dev), 0);
		assert_int_equal(netd_call(fds[0], RDC_MSG_STATS, 99, NULL, 0,
					   st, sizeof(st)),
				 RDC_ST_OK);
		assert_int_equal(rdc_proto_stats_decode(st, sizeof(st), &s), 0);
		assert_true(s.frames_dropped > 0);
		assert_true(s.frames_sent >= 1);
		assert_int_equal(s.clients, LOAD_CLIENTS);
	}
	rdc_batch_free(b);
	rdc_close(dev);
	for (int i = 0; i <= flood; i++)
		close(fds[i]);
	assert_int_equal(netd_stop(&d), 0);
}

/* Subscribed frames, in every encoding, decode to what frame_grab shows. */
static void test_subscribe(void **state)
{
	static const char *const args[] = { "--stepped", "-q", NULL };
	static uint32_t grab[640 * 480], ev_pix[640 * 480];
	uint32_t w, h, crc_grab = 0;
	rdc_dev *dev = NULL, *obs[3], *irq = NULL;
	struct rdc_event ev;
	struct netd d;
	rdc_batch *b;
	char uri[200];

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	snprintf(uri, sizeof(uri), "%s?observe", d.unix_uri);
	for (uint32_t enc = 0; enc < 3; enc++) {
		assert_int_equal(rdc_open(uri, &obs[enc]), 0);
		assert_int_equal(
			rdc_subscribe(obs[enc], RDC_EVENT_FRAME, 1, enc), 0);
	}
	assert_int_equal(rdc_subscribe(obs[0], RDC_EVENT_FRAME, 0, 0),
			 RDC_E_INVAL);
	assert_int_equal(rdc_open(uri, &irq), 0);
	assert_int_equal(rdc_subscribe(irq, RDC_EVENT_IRQ, 0, 0), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60,
				      RDC_FMT_XRGB8888, 0),
			 0);
	b = rdc_batch_new();
	assert_non_null(b);
	assert_int_equal(rdc_batch_fg(b, 0x00336699), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 10, 10, 300, 200), 0);
	assert_int_equal(rdc_batch_fg(b, 0x00ffcc00), 0);
	assert_int_equal(rdc_batch_circle(b, 320, 240, 100), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(
		rdc_frame_grab(dev, grab, RDC_ARRAY_SIZE(grab), &w, &h), 0);
	assert_int_equal(w, 640);
	/* the picture is not blank */
	assert_int_equal(grab[20 * 640 + 20], 0x00336699);
	for (size_t i = 0; i < RDC_ARRAY_SIZE(grab); i++)
		crc_grab = crc_grab * 31 + grab[i];
	for (uint32_t enc = 0; enc < 3; enc++) {
		uint64_t last = 0;
		int got = 0;

		/* the newest frame is the one grabbed (older ones first) */
		while (rdc_event_next(obs[enc], &ev, ev_pix,
				      RDC_ARRAY_SIZE(ev_pix), 2000) == 0) {
			assert_int_equal(ev.type, RDC_EVENT_FRAME);
			assert_true(ev.number >= last);
			last = ev.number;
			got++;
			if (!memcmp(ev_pix, grab, sizeof(grab)))
				break;
		}
		assert_true(got > 0);
		assert_memory_equal(ev_pix, grab, sizeof(grab));
		assert_int_equal(ev.width, 640);
		assert_int_equal(ev.height, 480);
		/* nothing dropped: they were read in time */
		assert_int_equal(ev.dropped, 0);
		rdc_close(obs[enc]);
	}
	/* interrupts: the fence of rdc_finish, the vblanks of frame_wait */
	{
		uint32_t seen = 0;

		while (rdc_event_next(irq, &ev, NULL, 0, 2000) == 0) {
			assert_int_equal(ev.type, RDC_EVENT_IRQ);
			assert_true(ev.time > 0);
			seen |= ev.irq;
		}
		assert_true(seen & RDC_IRQ_VBLANK);
		assert_true(seen & RDC_IRQ_FENCE);
	}
	rdc_close(irq);
	rdc_batch_free(b);
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);
}

/*
 * An interrupt the host acknowledged (IRQ_STATUS is write-one-to-clear)
 * and the chip raised again is a new event: one vblank event per frame
 * whose vblank was cleared in between, not one for the first only.
 */
static void test_irq_event_after_ack(void **state)
{
	const char *args[] = { "--stepped", "-q", NULL };
	rdc_dev *dev = NULL, *irq = NULL;
	struct rdc_event ev;
	struct netd d;
	char uri[200];
	int vblanks = 0;

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	snprintf(uri, sizeof(uri), "%s?observe", d.unix_uri);
	assert_int_equal(rdc_open(uri, &irq), 0);
	assert_int_equal(rdc_subscribe(irq, RDC_EVENT_IRQ, 0, 0), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_XRGB8888, 0),
			 0);
	for (int i = 0; i < 5; i++) {
		assert_int_equal(rdc_vblank_wait(dev), 0);
		assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_STATUS,
					       RDC_IRQ_VBLANK),
				 0);
	}
	while (rdc_event_next(irq, &ev, NULL, 0, 2000) == 0) {
		assert_int_equal(ev.type, RDC_EVENT_IRQ);
		if (ev.irq & RDC_IRQ_VBLANK)
			vblanks++;
	}
	assert_true(vblanks >= 5);
	rdc_close(irq);
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);
}

/* rdcd --record, then replay: the same frames and cycle counts. */
static void test_record_replay(void **state)
{
	char trace[200];
	const char *args[] = { "--stepped", "-q", "--record", trace, NULL };
	struct rdc_replay_result res;
	uint32_t crc = 0;
	uint64_t t = 0;
	rdc_dev *dev = NULL;
	rdc_batch *b;
	struct netd d;

	(void)state;
	snprintf(trace, sizeof(trace), "/tmp/rdcd-trace-%d", (int)getpid());
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_RGB565, 4096),
			 0);
	b = rdc_batch_new();
	assert_non_null(b);
	for (int i = 0; i < 200; i++) {
		assert_int_equal(rdc_batch_fg(b, (uint32_t)i * 331u), 0);
		assert_int_equal(rdc_batch_line(b, i, 0, 319 - i, 199), 0);
	}
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	{
		uint8_t v[100];

		for (int i = 0; i < 100; i++)
			v[i] = (uint8_t)(255 - i);
		assert_int_equal(rdc_vram_write(dev, 4096 + 640 * 50, v, 100),
				 0);
	}
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_sim_step(dev, 777), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	assert_int_equal(rdc_sim_time(dev, &t), 0);
	rdc_batch_free(b);
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);

	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.mismatches, 0);
	assert_true(res.records > 100);
	assert_int_equal(res.time, t);
	assert_int_equal(res.frame_crc, crc);
	assert_int_equal(res.width, 320);
	unlink(trace);
	/* a damaged trace is refused, not trusted */
	{
		FILE *f = fopen(trace, "wb");

		assert_non_null(f);
		fputs("RDCTRACE\x01\x00\x00\x00\x00\x00\x01\x00\x09", f);
		fclose(f);
		assert_int_equal(rdc_replay_file(trace, &res, NULL),
				 RDC_E_PARSE);
		unlink(trace);
		assert_int_equal(rdc_replay_file(trace, &res, NULL),
				 RDC_E_FILE);
	}
}

/*
 * Frames as a subscribed observer sees them, read on a thread of its own
 * while another client drives the device: each frame's CRC-32, in order,
 * until the reply to a STATS sent after the session (the daemon queues
 * replies behind the events before them), which says how many frames
 * the daemon sent and dropped for this client.
 */
#define LIVE_MAX_FRAMES 256

struct live_frames {
	int fd;
	uint32_t crc[LIVE_MAX_FRAMES];
	unsigned int n;
	uint32_t dropped;
	struct rdc_proto_stats st; /* the daemon's count for this client */
	int err;
};

static void *live_frames_read(void *arg)
{
	struct live_frames *lf = arg;
	static uint32_t pix[640 * 480];
	uint8_t *pl = malloc(RDC_PROTO_MAX_REPLY);

	if (!pl) {
		lf->err = -1;
		return NULL;
	}
	for (;;) {
		uint8_t hb[RDC_PROTO_HDR_SIZE];
		struct rdc_proto_hdr h;
		struct rdc_proto_frame f;

		if (netd_read(lf->fd, hb, sizeof(hb))) {
			lf->err = -1;
			break;
		}
		rdc_proto_hdr_decode(hb, &h);
		if (h.len > RDC_PROTO_MAX_REPLY ||
		    netd_read(lf->fd, pl, h.len)) {
			lf->err = -1;
			break;
		}
		if (!(h.flags & RDC_MSGF_EVENT)) {
			lf->err = h.type == RDC_MSG_STATS && !h.status &&
						  !rdc_proto_stats_decode(
							  pl, h.len, &lf->st) ?
					  0 :
					  -1;
			break;
		}
		if (h.type != RDC_MSG_EV_FRAME)
			continue;
		if (rdc_proto_frame_hdr_decode(pl, h.len, &f) ||
		    (size_t)f.width * f.height > RDC_ARRAY_SIZE(pix) ||
		    rdc_proto_frame_decode(pix, f.width, f.height, f.encoding,
					   pl + RDC_PROTO_FRAME_HDR,
					   h.len - RDC_PROTO_FRAME_HDR) ||
		    lf->n == LIVE_MAX_FRAMES) {
			lf->err = -1;
			break;
		}
		lf->crc[lf->n++] =
			rdc_crc32_xrgb(pix, (size_t)f.width * f.height);
		lf->dropped = f.dropped;
	}
	free(pl);
	return NULL;
}

/*
 * A trace's records, as docs/protocol.md and record.c describe them:
 * copy `in` to `out` with the header's version set to `version` and the
 * PINS records left out if `drop_pins`.  The number of PINS records in
 * `in`, or -1.
 */
enum { TR_PINS = 8, TR_END = 7 };

static int trace_copy(const char *in, const char *out, uint32_t version,
		      bool drop_pins)
{
	FILE *fi = fopen(in, "rb"), *fo = fopen(out, "wb");
	uint8_t hdr[16], rec[9], body[RDC_PROTO_WAIT_SIZE + 4], *vram = NULL;
	int pins = 0, ret = -1;

	if (!fi || !fo || fread(hdr, 1, sizeof(hdr), fi) != sizeof(hdr))
		goto out;
	rdc_proto_put32(hdr + 8, version);
	fwrite(hdr, 1, sizeof(hdr), fo);
	while (fread(rec, 1, sizeof(rec), fi) == sizeof(rec)) {
		size_t n = 8, extra = 0;

		switch (rec[0]) {
		case 1: /* REG_WRITE */
		case 2: /* REG_READ */
		case 3: /* VRAM_WRITE: u32 addr, u32 len, then len bytes */
		case 5: /* STEP */
		case TR_PINS:
			break;
		case 4: /* WAIT */
			n = RDC_PROTO_WAIT_SIZE + 4;
			break;
		case 6: /* POWER */
		case TR_END:
			n = 0;
			break;
		default:
			goto out;
		}
		if (n && fread(body, 1, n, fi) != n)
			goto out;
		if (rec[0] == 3) {
			extra = rdc_proto_get32(body + 4);
			free(vram);
			vram = malloc(extra + 1);
			if (!vram || fread(vram, 1, extra, fi) != extra)
				goto out;
		}
		if (rec[0] == TR_PINS)
			pins++;
		if (rec[0] == TR_PINS && drop_pins)
			continue;
		fwrite(rec, 1, sizeof(rec), fo);
		fwrite(body, 1, n, fo);
		if (extra)
			fwrite(vram, 1, extra, fo);
		if (rec[0] == TR_END) {
			ret = pins;
			break;
		}
	}
out:
	free(vram);
	if (fi)
		fclose(fi);
	if (fo && fclose(fo))
		ret = -1;
	return ret;
}

/*
 * Bands across the screen, one colour a row: long enough to be cut in
 * the middle, and small as RLE frames, so the daemon's socket holds all
 * of the session's and an observer that reads late loses none.
 */
static void pins_scene(rdc_batch *b, int n)
{
	for (int i = 0; i < n; i++) {
		assert_int_equal(rdc_batch_fg(b, 0x8000u + (uint32_t)i * 97u),
				 0);
		assert_int_equal(
			rdc_batch_fill_rect(b, 0, (i * 13) % 184, 320, 16), 0);
	}
}

/*
 * rdcd --record with the pins driven: RESET_N held low while the DP is in
 * the middle of drawing and released, BL_EN low for a few frames.  The
 * replay gives every frame an observer saw live (their CRCs in order),
 * the same final time and no mismatch in any time or register read; left
 * without its PINS records, the same trace does not.
 */
static void test_record_replay_pins(void **state)
{
	char trace[200], edited[220];
	const char *args[] = { "--stepped", "-q", "--record", trace, NULL };
	struct live_frames lf = { 0 };
	struct rdc_replay_result res;
	uint32_t v, lit = 0, dark = 0, again = 0;
	uint64_t t = 0;
	uint8_t sub[12];
	rdc_dev *dev = NULL;
	pthread_t th;
	rdc_batch *b;
	struct netd d;

	(void)state;
	snprintf(trace, sizeof(trace), "/tmp/rdcd-trace-p-%d", (int)getpid());
	snprintf(edited, sizeof(edited), "%s.edit", trace);
	assert_int_equal(netd_start(&d, args), 0);
	/* the observer first: every frame from the start is its */
	lf.fd = hello_fd(&d, 0);
	assert_true(lf.fd >= 0);
	rdc_proto_put32(sub, RDC_SUB_FRAMES);
	rdc_proto_put32(sub + 4, 1);
	rdc_proto_put32(sub + 8, RDC_ENC_RLE);
	assert_int_equal(netd_call(lf.fd, RDC_MSG_SUBSCRIBE, 1, sub,
				   sizeof(sub), NULL, 0),
			 RDC_ST_OK);
	assert_int_equal(pthread_create(&th, NULL, live_frames_read, &lf), 0);

	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_RGB565, 4096),
			 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	b = rdc_batch_new();
	assert_non_null(b);
	pins_scene(b, 400);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	/*
	 * RESET_N low with the DP mid-scene (part drawn, the rest of its
	 * words still in the FIFO): held, the chip forgets them
	 */
	assert_int_equal(rdc_sim_step(dev, 20000), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_STATUS, &v), 0);
	assert_false(v & RDC_STATUS_FIFO_EMPTY);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_RESET_N, 0), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_STATUS, &v), 0);
	assert_true(v & RDC_STATUS_FIFO_EMPTY);
	assert_int_equal(rdc_sim_step(dev, 300000), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_RESET_N, RDC_PIN_RESET_N),
			 0);
	/* released: the chip starts afresh, so the mode and scene again */
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_RGB565, 4096),
			 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_crc(dev, &lit), 0);
	/* BL_EN low for three frames: dark; high: the picture is back */
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, 0), 0);
	for (int i = 0; i < 3; i++)
		assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_crc(dev, &dark), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, RDC_PIN_BL_EN), 0);
	for (int i = 0; i < 2; i++)
		assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_crc(dev, &again), 0);
	assert_int_not_equal(dark, lit);
	assert_int_equal(again, lit);
	assert_int_equal(rdc_sim_step(dev, 4321), 0);
	assert_int_equal(rdc_sim_time(dev, &t), 0);
	rdc_batch_free(b);
	rdc_close(dev);

	/* the observer has every frame once the reply to STATS is in */
	assert_int_equal(netd_send(lf.fd, RDC_MSG_STATS, 2, NULL, 0), 0);
	assert_int_equal(pthread_join(th, NULL), 0);
	close(lf.fd);
	assert_int_equal(netd_stop(&d), 0);
	assert_int_equal(lf.err, 0);
	assert_int_equal(lf.dropped, 0);
	assert_int_equal(lf.st.frames_dropped, 0);
	assert_int_equal(lf.st.frames_sent, lf.n);
	assert_true(lf.n >= 6);
	assert_int_equal(lf.crc[lf.n - 1], lit);

	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.time, t);
	assert_int_equal(res.frames, lf.n);
	assert_int_equal(res.frame_crc, lit);
	assert_int_equal(res.frames_crc, rdc_crc32_xrgb(lf.crc, lf.n));

	/* one PINS record a change; without them the session is lost */
	assert_int_equal(trace_copy(trace, edited, 2, true), 4);
	assert_int_equal(rdc_replay_file(edited, &res, NULL), 0);
	assert_true(res.mismatches > 0);
	assert_int_not_equal(res.frames_crc, rdc_crc32_xrgb(lf.crc, lf.n));
	/* version 1 knows no PINS records; one without them still replays */
	assert_int_equal(trace_copy(trace, edited, 1, true), 4);
	assert_int_equal(rdc_replay_file(edited, &res, NULL), 0);
	assert_int_equal(trace_copy(trace, edited, 1, false), 4);
	assert_int_equal(rdc_replay_file(edited, &res, NULL), RDC_E_PARSE);
	assert_int_equal(trace_copy(trace, edited, 3, false), 4);
	assert_int_equal(rdc_replay_file(edited, &res, NULL), RDC_E_PARSE);
	unlink(edited);
	unlink(trace);
}

/*
 * Seeded random requests, sizes near the right ones, registers inside the
 * window half the time: whatever they do to the chip, every one is
 * answered in order and the daemon survives them (under the sanitizers).
 */
static void test_random_requests(void **state)
{
	static const uint32_t size_of[] = {
		[RDC_MSG_REG_READ] = 4,	  [RDC_MSG_REG_WRITE] = 8,
		[RDC_MSG_VRAM_READ] = 8,  [RDC_MSG_VRAM_WRITE] = 12,
		[RDC_MSG_SUBMIT] = 32,	  [RDC_MSG_WAIT] = RDC_PROTO_WAIT_SIZE,
		[RDC_MSG_STEP] = 8,	  [RDC_MSG_FRAME_GRAB] = 8,
		[RDC_MSG_SUBSCRIBE] = 12, [RDC_MSG_STATS] = 0,
		[RDC_MSG_RESET] = 4,	  [RDC_MSG_CLAIM] = 0,
		[RDC_MSG_RELEASE] = 0,	  [RDC_MSG_PING] = 0,
	};
	uint32_t seed = 20261122;
	uint8_t pl[64];
	struct netd d;
	int fd;

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	fd = hello_fd(&d, RDC_HELLO_CONTROL);
	assert_true(fd >= 0);
	for (uint32_t seq = 100; seq < 1100; seq++) {
		uint16_t type;
		uint32_t len;
		int st;

		seed = seed * 1103515245u + 12345u;
		type = (uint16_t)(2 + (seed >> 16) % 15); /* 2..16 */
		seed = seed * 1103515245u + 12345u;
		len = type < RDC_ARRAY_SIZE(size_of) ? size_of[type] : 4;
		if ((seed >> 16) % 8 == 0)
			len = (seed >> 20) % 48; /* a wrong size */
		for (size_t i = 0; i < sizeof(pl); i++) {
			seed = seed * 1103515245u + 12345u;
			pl[i] = (uint8_t)(seed >> 16);
		}
		if ((seed >> 8) & 1) /* a register inside the window */
			rdc_proto_put32(pl, (rdc_proto_get32(pl) & 0x3fc));
		if (type == RDC_MSG_WAIT || type == RDC_MSG_STEP)
			rdc_proto_put64(pl, 1 + seed % 5000); /* short */
		if (type == RDC_MSG_WAIT) {
			rdc_proto_put32(pl + 8, (seed >> 3) & 1);
			for (int t = 0; t < 2; t++) {
				uint8_t *term = pl + 12 + 16 * t;

				rdc_proto_put32(term,
						rdc_proto_get32(term) % 5);
				rdc_proto_put32(term + 4,
						rdc_proto_get32(term + 4) &
							0x3fc);
			}
		}
		st = netd_call(fd, type, seq, pl, len, NULL, 0);
		assert_true(st >= 0 && st < RDC_ST_COUNT_);
	}
	close(fd);
	assert_serving(&d);
	assert_int_equal(netd_stop(&d), 0);
}

/* Paced mode: time follows the wall clock; waits complete there too. */
static void test_paced(void **state)
{
	static const char *const args[] = { "-q", NULL };
	rdc_dev *dev = NULL;
	struct netd d;
	uint64_t t0, t1;

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_sim_time(dev, &t0), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_sim_step(dev, 1000), 0);
	assert_int_equal(rdc_sim_time(dev, &t1), 0);
	assert_true(t1 >= t0 + 1000);
	assert_int_equal(rdc_finish(dev), 0);
	{
		struct rdc_stats st;

		assert_int_equal(rdc_stats_get(dev, &st), 0);
		assert_true(st.frames >= 1);
	}
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);
}

/* Names of the PNG stills in `dir`: how many, and the last one found. */
static int png_stills(const char *dir, char *last, size_t cap)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	int n = 0;

	if (!d)
		return -1;
	while ((e = readdir(d))) {
		size_t len = strlen(e->d_name);

		if (len > 4 && !strcmp(e->d_name + len - 4, ".png")) {
			snprintf(last, cap, "%s/%s", dir, e->d_name);
			n++;
		}
	}
	closedir(d);
	return n;
}

/*
 * SIGUSR1 asks rdcd's sinks for the next frame as a still: with
 * `--png DIR,every=0` nothing is written until the signal, then exactly
 * one PNG holding the screen as the client drew it.
 */
static void test_snapshot_signal(void **state)
{
	char dir[] = "/tmp/rdcd-snap-XXXXXX", spec[64], path[256] = "";
	const char *args[] = { "--fast", "-q", "--mode", "320x200",
			       "--png",	 spec, NULL };
	png_image img = { .version = PNG_IMAGE_VERSION };
	uint32_t *pix;
	rdc_batch *b;
	rdc_dev *dev = NULL;
	struct netd d;
	int n = 0;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(spec, sizeof(spec), "%s,every=0", dir);
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	b = rdc_batch_new();
	assert_non_null(b);
	assert_int_equal(rdc_batch_fg(b, 0x00ff4020), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 0, 0, 320, 200), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(png_stills(dir, path, sizeof(path)), 0);

	assert_int_equal(kill(d.pid, SIGUSR1), 0);
	for (int waited = 0; waited < NETD_IO_MS && n < 1; waited += 20) {
		netd_sleep_ms(20);
		n = png_stills(dir, path, sizeof(path));
	}
	assert_int_equal(n, 1);
	/* the daemon keeps running frames: still just the one */
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(png_stills(dir, path, sizeof(path)), 1);

	assert_true(png_image_begin_read_from_file(&img, path));
	img.format = PNG_FORMAT_BGRA;
	assert_int_equal(img.width, 320);
	assert_int_equal(img.height, 200);
	pix = malloc(PNG_IMAGE_SIZE(img));
	assert_non_null(pix);
	assert_true(png_image_finish_read(&img, NULL, pix, 0, NULL));
	for (size_t i = 0; i < 320 * 200; i++)
		if ((pix[i] & 0x00ffffffu) != 0x00ff4020u)
			fail_msg("pixel %zu is %08x", i, pix[i]);
	free(pix);
	unlink(path);
	rmdir(dir);
	rdc_batch_free(b);
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);
}

/*
 * Stepped mode: a long wait of the controlling client moves time in
 * pieces, and the others are answered meanwhile (they see time move);
 * the controller hanging up mid-wait leaves a trace that still replays.
 */
static void test_stepped_wait_serves_others(void **state)
{
	char trace[200];
	const char *args[] = { "--stepped", "-q", "--record", trace, NULL };
	struct rdc_proto_wait pw = { .budget = 60ull * 100000000ull };
	struct rdc_replay_result res;
	uint8_t b[RDC_PROTO_WAIT_SIZE], v[4];
	uint32_t f0 = 0, f1 = 0;
	struct pollfd p;
	struct netd d;
	int ctl, obs;

	(void)state;
	snprintf(trace, sizeof(trace), "/tmp/rdcd-trace-w-%d", (int)getpid());
	assert_int_equal(netd_start(&d, args), 0);
	ctl = hello_fd(&d, RDC_HELLO_CONTROL);
	obs = hello_fd(&d, 0);
	assert_true(ctl >= 0 && obs >= 0);
	/* a fence value nobody writes: only the budget would end it */
	pw.term[0].kind = RDC_WAIT_TEST_EQ;
	pw.term[0].reg = RDC_REG_FENCE;
	pw.term[0].mask = ~0u;
	pw.term[0].value = 0xdeadbeefu;
	rdc_proto_wait_encode(b, &pw);
	assert_int_equal(netd_send(ctl, RDC_MSG_WAIT, 1, b, sizeof(b)), 0);

	rdc_proto_put32(b, RDC_REG_FRAME_COUNT);
	assert_int_equal(netd_call(obs, RDC_MSG_REG_READ, 2, b, 4, v, 4),
			 RDC_ST_OK);
	f0 = rdc_proto_get32(v);
	for (int waited = 0; waited < NETD_IO_MS && f1 <= f0; waited += 10) {
		netd_sleep_ms(10);
		assert_int_equal(netd_call(obs, RDC_MSG_REG_READ, 3, b, 4, v,
					   4),
				 RDC_ST_OK);
		f1 = rdc_proto_get32(v);
	}
	assert_true(f1 > f0); /* the wait is moving time, a piece at a time */
	p = (struct pollfd){ .fd = ctl, .events = POLLIN };
	assert_int_equal(poll(&p, 1, 0), 0); /* and has not answered yet */
	close(ctl);
	assert_serving(&d);
	close(obs);
	assert_int_equal(netd_stop(&d), 0);

	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.mismatches, 0);
	assert_true(res.time > 0);
	unlink(trace);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_bad_messages),
		cmocka_unit_test(test_hangups),
		cmocka_unit_test(test_control),
		cmocka_unit_test(test_token),
		cmocka_unit_test(test_token_required),
		cmocka_unit_test(test_listen_rule),
		cmocka_unit_test(test_many_clients),
		cmocka_unit_test(test_subscribe),
		cmocka_unit_test(test_irq_event_after_ack),
		cmocka_unit_test(test_record_replay),
		cmocka_unit_test(test_record_replay_pins),
		cmocka_unit_test(test_random_requests),
		cmocka_unit_test(test_paced),
		cmocka_unit_test(test_snapshot_signal),
		cmocka_unit_test(test_stepped_wait_serves_others),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
