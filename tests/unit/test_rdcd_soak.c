// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd soaked by careless and hostile clients at once, for a bounded
 * time: subscribers that never read and ask for VRAM they never take,
 * clients that hang up in the middle of a message, silent half-open
 * connections, and a controller that keeps the display processor in long
 * flood fills.  Meanwhile a well-behaved client's register round trip
 * must stay under ROUND_TRIP_BOUND_MS (generous: the point is that nobody
 * can stop the daemon serving, not how fast a loaded machine is), and
 * rdcd's peak RSS under its documented limit (docs/protocol.md).  The
 * measured figures are printed.
 */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "rdc_priv.h"
#include "test_net_common.h"

#define SOAK_MS		    12000
#define ROUND_TRIP_BOUND_MS 2000
#define DOC_RSS_LIMIT_KB    (560ul << 10)
#define STALLERS	    60
#define SILENT		    24

struct ctl_arg {
	const struct netd *d;
	volatile int stop;
	int fills;
};

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

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

/* The controller: flood fills of a 1 bpp comb, one after another. */
static void *controller(void *p)
{
	struct ctl_arg *a = p;
	rdc_dev *dev = NULL;
	rdc_batch *b;

	if (rdc_open(a->d->unix_uri, &dev))
		return NULL;
	b = rdc_batch_new();
	while (!a->stop && b) {
		rdc_batch_reset(b);
		rdc_batch_dst(b, 0, 512 / 8, 512, 256, RDC_FMT_I1);
		rdc_batch_fg(b, 0);
		rdc_batch_fill_rect(b, 0, 0, 512, 256);
		rdc_batch_fg(b, 1);
		for (int x = 0; x < 512; x += 2)
			rdc_batch_line(b, x, 0, x, 254);
		rdc_batch_flood(b, 1, 0, 0, 0);
		if (rdc_batch_submit(dev, b) || rdc_finish(dev))
			break;
		a->fills++;
	}
	rdc_batch_free(b);
	rdc_close(dev);
	return NULL;
}

static unsigned long vm_hwm_kb(pid_t pid)
{
	char path[64], line[256];
	unsigned long kb = 0;
	FILE *f;

	snprintf(path, sizeof(path), "/proc/%d/status", (int)pid);
	f = fopen(path, "r");
	if (!f)
		return 0;
	while (fgets(line, sizeof(line), f))
		if (!strncmp(line, "VmHWM:", 6))
			kb = strtoul(line + 6, NULL, 10);
	fclose(f);
	return kb;
}

static int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return x < y ? -1 : x > y;
}

static void test_soak(void **state)
{
	static const char *const args[] = { "--fast", "-q", "--mode", "640x480",
					    NULL };
	static uint64_t rt[200000];
	int stall[STALLERS], silent[SILENT];
	struct ctl_arg ca = { 0 };
	uint64_t t0, worst;
	size_t nrt = 0;
	unsigned long hwm;
	uint32_t seq = 1, churn = 0;
	pthread_t th;
	uint8_t p[12], v[4];
	struct netd d;
	const char *old = getenv("ASAN_OPTIONS");
	char asan[512];
	int good;

	(void)state;
	/* the sanitizer's quarantine of freed memory is not the daemon's */
	snprintf(asan, sizeof(asan), "%s%squarantine_size_mb=8", old ? old : "",
		 old && *old ? ":" : "");
	setenv("ASAN_OPTIONS", asan, 1);
	assert_int_equal(netd_start(&d, args), 0);
	ca.d = &d;
	good = hello_fd(&d, 0);
	assert_true(good >= 0);
	for (int i = 0; i < STALLERS; i++) {
		stall[i] = hello_fd(&d, 0);
		assert_true(stall[i] >= 0);
		rdc_proto_put32(p, RDC_SUB_FRAMES | RDC_SUB_IRQ);
		rdc_proto_put32(p + 4, 1);
		rdc_proto_put32(p + 8, i % 2 ? RDC_ENC_RAW : RDC_ENC_DELTA);
		assert_int_equal(netd_call(stall[i], RDC_MSG_SUBSCRIBE, 1, p,
					   12, NULL, 0),
				 RDC_ST_OK);
		for (uint32_t k = 0; k < 6; k++) {
			rdc_proto_put32(p, k << 20);
			rdc_proto_put32(p + 4, 1u << 20);
			netd_send(stall[i], RDC_MSG_VRAM_READ, 2 + k, p, 8);
		}
	}
	for (int i = 0; i < SILENT; i++) {
		silent[i] = netd_connect(d.sock);
		assert_true(silent[i] >= 0);
		assert_int_equal(send(silent[i], "R", 1, MSG_NOSIGNAL), 1);
	}
	assert_int_equal(pthread_create(&th, NULL, controller, &ca), 0);

	t0 = now_ns();
	while (now_ns() - t0 < (uint64_t)SOAK_MS * 1000000ull &&
	       nrt < sizeof(rt) / sizeof(rt[0])) {
		uint64_t a;
		int fd;

		/* a client that hangs up in the middle of a message */
		fd = hello_fd(&d, 0);
		if (fd >= 0) {
			uint8_t h[RDC_PROTO_HDR_SIZE];
			struct rdc_proto_hdr hdr = {
				.len = 100000, .type = RDC_MSG_VRAM_WRITE
			};

			rdc_proto_hdr_encode(h, &hdr);
			netd_write(fd, h, sizeof(h));
			netd_write(fd, "half", 4);
			close(fd);
			churn++;
		}
		/* one of the silent ones reconnects */
		close(silent[churn % SILENT]);
		silent[churn % SILENT] = netd_connect(d.sock);
		/* the well-behaved client's round trip */
		rdc_proto_put32(p, RDC_REG_FRAME_COUNT);
		a = now_ns();
		assert_int_equal(netd_call(good, RDC_MSG_REG_READ, seq++, p, 4,
					   v, 4),
				 RDC_ST_OK);
		rt[nrt++] = now_ns() - a;
	}
	ca.stop = 1;
	pthread_join(th, NULL);
	hwm = vm_hwm_kb(d.pid);
	qsort(rt, nrt, sizeof(rt[0]), cmp_u64);
	worst = rt[nrt - 1];
	fprintf(stderr,
		"# soak %d ms: %zu round trips, median %.3f ms, p99 %.3f ms, "
		"worst %.3f ms (bound %d ms); %u mid-message hang-ups, %d "
		"silent, %d stalled subscribers, %d flood fills; rdcd VmHWM "
		"%lu kB (documented limit %lu kB)\n",
		SOAK_MS, nrt, rt[nrt / 2] / 1e6, rt[nrt * 99 / 100] / 1e6,
		worst / 1e6, ROUND_TRIP_BOUND_MS, churn, SILENT, STALLERS,
		ca.fills, hwm, DOC_RSS_LIMIT_KB);
	assert_true(worst < (uint64_t)ROUND_TRIP_BOUND_MS * 1000000ull);
	assert_true(hwm > 0 && hwm < DOC_RSS_LIMIT_KB);
	assert_true(ca.fills >= 1);
	for (int i = 0; i < STALLERS; i++)
		close(stall[i]);
	for (int i = 0; i < SILENT; i++)
		if (silent[i] >= 0)
			close(silent[i]);
	close(good);
	assert_int_equal(netd_stop(&d), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_soak),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
