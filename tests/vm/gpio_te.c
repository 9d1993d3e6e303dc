// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * gpio_te: what tests/vm/tests/rdcfb-gpio.sh does to rdcfb's GPIO lines
 * (libgpiod v2) and its /dev/fbN (the private ioctls) that a shell cannot.
 *
 *   gpio_te dirty DEV            leave registers off their reset values and
 *                                the DP busy with queued fills
 *   gpio_te reset DEV held|released
 *                                registers at their reset values, DP idle,
 *                                RESET_N as said; held: writes are ignored
 *   gpio_te frames DEV N         stepped clock: run N frames (STEP); print
 *                                FRAME_COUNT before and after
 *   gpio_te irq DEV N            stepped clock: N times, enable the vblank
 *                                IRQ, run a frame (the IRQ pin rises), clear
 *                                it (the pin falls)
 *   gpio_te period DEV           print the mode's frame time in ns
 *   gpio_te black DEV            exit 0 if the latest frame is all black
 *   gpio_te crc DEV              print the latest frame's CRC
 *   gpio_te jitter DEV CHIP N    paced clock: N rising edges of TE; the
 *                                periods against the mode's frame time
 *                                (min / median / max), the phase against
 *                                the ideal grid, lost edges: TAP comments
 *   gpio_te present DEV CHIP N   paced clock: N full-screen fills, each
 *                                submitted on TE's rising edge, then N at
 *                                random moments; every following frame
 *                                grabbed and checked for one colour: TAP
 *
 * CHIP is the GPIO chip's label (rdcfb.0-pins); lines are found by name.
 */
#include <errno.h>
#include <fcntl.h>
#include <gpiod.h>
#include <glob.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include "rdc_chip.h"
#include "rdc_regs.h"
#include "rdcfb_ioctl.h"
#include "tap.h"

#define NS_PER_S	1000000000ull
#define EDGE_TIMEOUT_NS (2 * NS_PER_S)
#define WAIT_TIMEOUT_MS 2000u
#define EVENT_BUF	64
/* The present test's mode: 320x200 with a vertical blanking as long as
 * the picture (200 lines of 63.5 us), so a fill started on TE lands in
 * it even when the edge reaches user space milliseconds late.
 */
#define PRESENT_W	      320u
#define PRESENT_H	      200u
#define PRESENT_V_TOTAL	      400u
#define PRESENT_SETTLE_FRAMES 3u
#define DIRTY_FILLS	      16

static int fd = -1;

static int die(const char *what)
{
	fprintf(stderr, "%s: %s\n", what, strerror(errno));
	exit(1);
}

static uint32_t rd(uint32_t reg)
{
	struct rdcfb_reg r = { .reg = reg };

	if (ioctl(fd, RDCFB_IOC_REG_READ, &r))
		die("REG_READ");
	return r.val;
}

static void wr(uint32_t reg, uint32_t val)
{
	struct rdcfb_reg r = { .reg = reg, .val = val };

	if (ioctl(fd, RDCFB_IOC_REG_WRITE, &r))
		die("REG_WRITE");
}

static int submit(const uint32_t *w, uint32_t n)
{
	struct rdcfb_submit s = { .words = (uintptr_t)w, .count = n };

	return ioctl(fd, RDCFB_IOC_SUBMIT, &s);
}

/* Until FRAME_COUNT >= value (wrapping), on either clock. */
static int wait_frame(uint32_t value)
{
	struct rdcfb_wait w = {
		.term[0] = { .kind = RDCFB_WAIT_WRAP_GE,
			     .reg = RDC_REG_FRAME_COUNT,
			     .mask = ~0u,
			     .value = value },
		.timeout_ms = WAIT_TIMEOUT_MS,
	};

	return ioctl(fd, RDCFB_IOC_WAIT, &w);
}

/* The latest frame into px (cap pixels); its size and seq. */
static int grab(uint32_t *px, uint32_t cap, struct rdcfb_frame *f)
{
	memset(f, 0, sizeof(*f));
	f->pixels = (uintptr_t)px;
	f->cap = cap;
	return ioctl(fd, RDCFB_IOC_FRAME, f);
}

/* Core cycles of one frame of the mode in force, as the CRTC counts. */
static uint64_t frame_cycles(void)
{
	uint64_t h = rd(RDC_REG_H_TOTAL), v = rd(RDC_REG_V_TOTAL);
	uint64_t pclk = rd(RDC_REG_PIXCLK_KHZ), core = rd(RDC_REG_CORE_KHZ);

	return pclk ? v * h * core / pclk : 0;
}

static uint64_t frame_ns(void)
{
	return frame_cycles() * NS_PER_S / (rd(RDC_REG_CORE_KHZ) * 1000ull);
}

/* ---- Registers ------------------------------------------------------------ */

static int cmd_dirty(void)
{
	static uint32_t w[DIRTY_FILLS * 3];
	uint32_t i;

	wr(RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK | RDC_IRQ_LINE);
	wr(RDC_REG_LINE_COMPARE, 10);
	wr(RDC_REG_FIFO_LOWWATER, 3);
	for (i = 0; i < DIRTY_FILLS; i++) {
		w[3 * i] = RDC_CMD(RDC_OP_FILL_RECT, 0, 2);
		w[3 * i + 1] = RDC_XY(0, 0);
		w[3 * i + 2] = RDC_WH(PRESENT_W, PRESENT_H);
	}
	if (submit(w, DIRTY_FILLS * 3))
		die("SUBMIT");
	printf("IRQ_ENABLE %#x LINE_COMPARE %u FIFO_FREE %u STATUS %#x\n",
	       rd(RDC_REG_IRQ_ENABLE), rd(RDC_REG_LINE_COMPARE),
	       rd(RDC_REG_FIFO_FREE), rd(RDC_REG_STATUS));
	return 0;
}

static int expect(const char *name, uint32_t got, uint32_t want)
{
	if (got == want)
		return 0;
	printf("%s: %#x, want %#x\n", name, got, want);
	return 1;
}

static int reset_values(void)
{
	uint32_t st = rd(RDC_REG_STATUS);
	int bad = 0;

	bad += expect("CONTROL", rd(RDC_REG_CONTROL), RDC_CONTROL_RESET_VALUE);
	bad += expect("IRQ_ENABLE", rd(RDC_REG_IRQ_ENABLE), 0);
	bad += expect("IRQ_STATUS", rd(RDC_REG_IRQ_STATUS), 0);
	bad += expect("LINE_COMPARE", rd(RDC_REG_LINE_COMPARE),
		      RDC_LINE_COMPARE_RESET);
	bad += expect("FIFO_LOWWATER", rd(RDC_REG_FIFO_LOWWATER),
		      RDC_FIFO_LOWWATER_RESET);
	bad += expect("FIFO_FREE", rd(RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH);
	bad += expect("PERF_CMDS", rd(RDC_REG_PERF_CMDS), 0);
	bad += expect("FB_BASE", rd(RDC_REG_FB_BASE), 0);
	/* the DP idle, its queue empty */
	bad += expect("STATUS & DP",
		      st & (RDC_STATUS_DP_BUSY | RDC_STATUS_DP_HALTED |
			    RDC_STATUS_DP_WAIT),
		      0);
	bad += expect("STATUS & FIFO_EMPTY", st & RDC_STATUS_FIFO_EMPTY,
		      RDC_STATUS_FIFO_EMPTY);
	return bad;
}

static int cmd_reset(const char *how)
{
	int held = !strcmp(how, "held");
	uint32_t pins = rd(RDC_REG_PINS);
	int bad = reset_values();

	printf("PINS %#x FRAME_COUNT %u STATUS %#x\n", pins,
	       rd(RDC_REG_FRAME_COUNT), rd(RDC_REG_STATUS));
	bad += expect("PINS & RESET_N", pins & RDC_PIN_RESET_N,
		      held ? 0 : RDC_PIN_RESET_N);
	if (held) {
		/* writes are ignored while RESET_N holds the chip */
		wr(RDC_REG_IRQ_ENABLE, RDC_IRQ_ALL);
		wr(RDC_REG_LINE_COMPARE, 10);
		bad += expect("TE held low", pins & RDC_PIN_TE, 0);
		bad += reset_values();
	}
	return bad ? 1 : 0;
}

static int cmd_frames(const char *count)
{
	struct rdcfb_step st = { .cycles = frame_cycles() *
					   strtoull(count, NULL, 0) };
	uint32_t f0 = rd(RDC_REG_FRAME_COUNT);

	if (!st.cycles)
		return 1;
	if (ioctl(fd, RDCFB_IOC_STEP, &st))
		die("STEP");
	printf("FRAME_COUNT %u %u\n", f0, rd(RDC_REG_FRAME_COUNT));
	return 0;
}

static int cmd_irq(const char *count)
{
	unsigned int n = strtoul(count, NULL, 0), i;
	struct rdcfb_step st = { .cycles = frame_cycles() };

	wr(RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	wr(RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK);
	for (i = 0; i < n; i++) {
		if (ioctl(fd, RDCFB_IOC_STEP, &st))
			die("STEP");
		if (!(rd(RDC_REG_PINS) & RDC_PIN_IRQ)) {
			printf("IRQ low after a frame with vblank enabled\n");
			return 1;
		}
		wr(RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	}
	wr(RDC_REG_IRQ_ENABLE, 0);
	printf("%u IRQ pulses\n", n);
	return 0;
}

static uint32_t *frame_buf(uint32_t *cap)
{
	*cap = RDC_CRTC_MAX_DISPLAY * RDC_CRTC_MAX_DISPLAY;
	return calloc(*cap, sizeof(uint32_t));
}

static int cmd_black(void)
{
	struct rdcfb_frame f;
	uint32_t cap, *px = frame_buf(&cap), i, lit = 0;

	if (!px || grab(px, cap, &f))
		die("FRAME");
	for (i = 0; i < f.width * f.height; i++)
		lit += px[i] != 0;
	printf("frame %u %ux%u crc %08x: %u pixels not black\n", f.seq, f.width,
	       f.height, f.crc32, lit);
	free(px);
	return lit ? 1 : 0;
}

static int cmd_crc(void)
{
	struct rdcfb_frame f = { 0 };

	if (ioctl(fd, RDCFB_IOC_FRAME, &f))
		die("FRAME");
	printf("%08x\n", f.crc32);
	return 0;
}

/* ---- GPIO ------------------------------------------------------------------ */

/* The chip labelled `label`, found among /dev/gpiochip*. */
static struct gpiod_chip *chip_by_label(const char *label)
{
	struct gpiod_chip *chip = NULL;
	glob_t g;
	size_t i;

	if (glob("/dev/gpiochip*", 0, NULL, &g))
		return NULL;
	for (i = 0; i < g.gl_pathc && !chip; i++) {
		struct gpiod_chip *c = gpiod_chip_open(g.gl_pathv[i]);
		struct gpiod_chip_info *info = c ? gpiod_chip_get_info(c) :
						   NULL;

		if (info && !strcmp(gpiod_chip_info_get_label(info), label))
			chip = c;
		else if (c)
			gpiod_chip_close(c);
		if (info)
			gpiod_chip_info_free(info);
	}
	globfree(&g);
	return chip;
}

/* TE as an input with rising-edge events, monotonic timestamps. */
static struct gpiod_line_request *request_te(const char *label)
{
	struct gpiod_chip *chip = chip_by_label(label);
	struct gpiod_line_settings *ls = gpiod_line_settings_new();
	struct gpiod_line_config *lc = gpiod_line_config_new();
	struct gpiod_request_config *rc = gpiod_request_config_new();
	struct gpiod_line_request *req = NULL;
	int off;

	if (!chip || !ls || !lc || !rc) {
		fprintf(stderr, "no GPIO chip labelled %s\n", label);
		exit(1);
	}
	off = gpiod_chip_get_line_offset_from_name(chip, "TE");
	if (off < 0)
		die("line TE");
	gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_INPUT);
	gpiod_line_settings_set_edge_detection(ls, GPIOD_LINE_EDGE_RISING);
	gpiod_line_settings_set_event_clock(ls, GPIOD_LINE_CLOCK_MONOTONIC);
	if (gpiod_line_config_add_line_settings(lc, (unsigned int *)&off, 1,
						ls))
		die("line config");
	gpiod_request_config_set_consumer(rc, "gpio_te");
	req = gpiod_chip_request_lines(chip, rc, lc);
	if (!req)
		die("request TE");
	gpiod_request_config_free(rc);
	gpiod_line_config_free(lc);
	gpiod_line_settings_free(ls);
	gpiod_chip_close(chip);
	return req;
}

/*
 * The next rising edge: its timestamp and line sequence number.  Returns
 * 0, or -1 after EDGE_TIMEOUT_NS without one.
 */
static int next_edge(struct gpiod_line_request *req,
		     struct gpiod_edge_event_buffer *buf, uint64_t *ts,
		     unsigned long *seq)
{
	struct gpiod_edge_event *ev;
	int r = gpiod_line_request_wait_edge_events(req, EDGE_TIMEOUT_NS);

	if (r <= 0)
		return -1;
	if (gpiod_line_request_read_edge_events(req, buf, 1) != 1)
		return -1;
	ev = gpiod_edge_event_buffer_get_event(buf, 0);
	*ts = gpiod_edge_event_get_timestamp_ns(ev);
	*seq = gpiod_edge_event_get_line_seqno(ev);
	return 0;
}

/* Throw away the edges already queued. */
static void drain(struct gpiod_line_request *req,
		  struct gpiod_edge_event_buffer *buf)
{
	while (gpiod_line_request_wait_edge_events(req, 0) > 0)
		if (gpiod_line_request_read_edge_events(req, buf, EVENT_BUF) <=
		    0)
			break;
}

static int cmp_s64(const void *a, const void *b)
{
	int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;

	return (x > y) - (x < y);
}

static void stats(const char *what, int64_t *v, size_t n)
{
	qsort(v, n, sizeof(*v), cmp_s64);
	printf("# %s (us): min %.1f median %.1f p99 %.1f max %.1f\n", what,
	       v[0] / 1e3, v[n / 2] / 1e3, v[n * 99 / 100] / 1e3,
	       v[n - 1] / 1e3);
}

static int cmd_jitter(const char *label, const char *count)
{
	struct gpiod_edge_event_buffer *buf =
		gpiod_edge_event_buffer_new(EVENT_BUF);
	struct gpiod_line_request *req = request_te(label);
	size_t n = strtoul(count, NULL, 0), i, gaps = 0, late = 0;
	uint64_t *t = calloc(n, sizeof(*t)), period = frame_ns();
	int64_t *d = calloc(n, sizeof(*d)), *ph = calloc(n, sizeof(*ph));
	unsigned long seq, prev_seq = 0;
	uint32_t f0 = 0, f1;
	size_t long_gaps = 0;

	if (!buf || !t || !d || !ph || n < 3 || !period)
		return 1;
	for (i = 0; i < n; i++) {
		if (next_edge(req, buf, &t[i], &seq)) {
			tap(0, "TE edge %zu of %zu within 2 s", i + 1, n);
			return tap_done();
		}
		if (!i)
			f0 = rd(RDC_REG_FRAME_COUNT);
		else if (seq != prev_seq + 1)
			gaps += seq - prev_seq - 1;
		prev_seq = seq;
	}
	f1 = rd(RDC_REG_FRAME_COUNT);
	for (i = 1; i < n; i++) {
		d[i - 1] = (int64_t)(t[i] - t[i - 1]) - (int64_t)period;
		/* a late edge, or a lost one: FRAME_COUNT tells which */
		long_gaps += t[i] - t[i - 1] > period * 3 / 2;
		ph[i - 1] = (int64_t)(t[i] - t[0]) - (int64_t)(i * period);
		late += d[i - 1] > (int64_t)period / 10;
	}
	tap(1, "%zu TE rising edges in %.3f s", n, (t[n - 1] - t[0]) / 1e9);
	printf("# frame time %.1f us (%.3f Hz); mean period %.1f us\n",
	       period / 1e3, 1e9 / period,
	       (t[n - 1] - t[0]) / 1e3 / (double)(n - 1));
	stats("period - frame time", d, n - 1);
	stats("phase against the ideal grid", ph, n - 1);
	printf("# lost edges: %lld by FRAME_COUNT (%u..%u), %zu by the line "
	       "sequence numbers; %zu periods more than 10%% long, %zu over "
	       "1.5 frames\n",
	       (long long)(f1 - f0) - (long long)(n - 1), f0, f1, gaps, late,
	       long_gaps);
	gpiod_line_request_release(req);
	gpiod_edge_event_buffer_free(buf);
	free(t);
	free(d);
	free(ph);
	return tap_done();
}

/* ---- Present on TE --------------------------------------------------------- */

static void program_present_mode(void)
{
	wr(RDC_REG_MODE_PRESET, RDC_PRESET_320x200_70);
	wr(RDC_REG_V_TOTAL, PRESENT_V_TOTAL);
	wr(RDC_REG_FB_FORMAT, RDC_FMT_XRGB8888);
	wr(RDC_REG_FB_BASE, 0);
	wr(RDC_REG_FB_STRIDE, PRESENT_W * 4);
	wr(RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	wait_frame(rd(RDC_REG_FRAME_COUNT) + PRESENT_SETTLE_FRAMES);
}

/* A full-screen fill of colour c on the scanout surface. */
static int fill(uint32_t c)
{
	const uint32_t w[] = {
		RDC_CMD(RDC_OP_SET_DST, 0, 4),
		0,
		PRESENT_W * 4,
		RDC_WH(PRESENT_W, PRESENT_H),
		RDC_FMT_XRGB8888,
		RDC_CMD(RDC_OP_SET_ROP, 0, 1),
		RDC_ROP_COPY,
		RDC_CMD(RDC_OP_SET_FG, 0, 1),
		c,
		RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
		RDC_XY(0, 0),
		RDC_WH(PRESENT_W, PRESENT_H),
	};

	return submit(w, sizeof(w) / sizeof(w[0]));
}

static uint32_t colour_of(unsigned int i)
{
	return 0x00204080u + 0x00030507u * (i + 1);
}

struct tear {
	unsigned int torn, wrong, late, checked, missed;
};

/*
 * After a fill submitted while frame `f` + 1 was due: grab that frame and
 * check that it is one colour, and that colour `c`.  A grab that came after
 * a later frame completed is counted as late and not judged.
 */
static void judge(uint32_t f, uint32_t c, uint32_t *px, uint32_t cap,
		  struct tear *t)
{
	struct rdcfb_frame fr;
	uint32_t i, n;

	if (wait_frame(f + 1) || grab(px, cap, &fr)) {
		t->late++;
		return;
	}
	if (rd(RDC_REG_FRAME_COUNT) != f + 1) {
		t->late++;
		return;
	}
	t->checked++;
	n = fr.width * fr.height;
	for (i = 1; i < n && px[i] == px[0]; i++)
		;
	if (i < n)
		t->torn++;
	else if (px[0] != (c & 0x00ffffffu))
		t->wrong++;
}

static int cmd_present(const char *label, const char *count)
{
	struct gpiod_edge_event_buffer *buf =
		gpiod_edge_event_buffer_new(EVENT_BUF);
	struct gpiod_line_request *req;
	unsigned int n = strtoul(count, NULL, 0), i;
	struct tear te = { 0 }, free_run = { 0 };
	uint32_t cap, *px = frame_buf(&cap), f, vblank_cycles, st0, st1;
	uint64_t ts, period, cycles;
	unsigned long seq;

	if (!buf || !px || !n)
		return 1;
	program_present_mode();
	period = frame_ns();
	vblank_cycles =
		(uint32_t)(frame_cycles() * (PRESENT_V_TOTAL - PRESENT_H) /
			   PRESENT_V_TOTAL);
	/* the fill's cost, measured on the DP */
	wait_frame(rd(RDC_REG_FRAME_COUNT) + 1);
	if (fill(0))
		die("SUBMIT");
	wait_frame(rd(RDC_REG_FRAME_COUNT) + 1);
	cycles = rd(RDC_REG_PERF_LAST_CYCLES);
	printf("# full-screen fill %ux%u: %llu DP cycles; vertical blanking "
	       "%u cycles; frame %.1f us\n",
	       PRESENT_W, PRESENT_H, (unsigned long long)cycles, vblank_cycles,
	       period / 1e3);
	tap(cycles && cycles < vblank_cycles,
	    "the fill fits in vertical blanking in simulated time");

	req = request_te(label);
	for (i = 0; i < n; i++) {
		drain(req, buf);
		if (next_edge(req, buf, &ts, &seq)) {
			te.late++;
			continue;
		}
		/*
		 * The fill starts at the simulated time its words go in.
		 * FRAME_COUNT unchanged around two VBLANK readings around the
		 * submit brackets that time in one vertical blanking; when
		 * not, the host saw TE too late (a loaded TCG host can be
		 * late by more than the blanking) and missed its window,
		 * which is counted apart.
		 */
		f = rd(RDC_REG_FRAME_COUNT);
		st0 = rd(RDC_REG_STATUS);
		if (fill(colour_of(i)))
			die("SUBMIT");
		st1 = rd(RDC_REG_STATUS);
		if (!(st0 & st1 & RDC_STATUS_VBLANK) ||
		    rd(RDC_REG_FRAME_COUNT) != f) {
			te.missed++;
			continue;
		}
		judge(f, colour_of(i), px, cap, &te);
	}
	gpiod_line_request_release(req);

	srand(1);
	for (i = 0; i < n; i++) {
		struct timespec d = { 0, (long)((uint64_t)rand() % period) };

		nanosleep(&d, NULL);
		f = rd(RDC_REG_FRAME_COUNT);
		if (fill(colour_of(i)))
			die("SUBMIT");
		judge(f, colour_of(i), px, cap, &free_run);
	}
	printf("# on TE: %u frames checked, %u torn, %u of another colour, "
	       "%u not judged (grabbed late); %u windows missed (TE seen after "
	       "the blanking)\n",
	       te.checked, te.torn, te.wrong, te.late, te.missed);
	printf("# at random moments: %u frames checked, %u torn, %u of "
	       "another colour, %u not judged\n",
	       free_run.checked, free_run.torn, free_run.wrong, free_run.late);
	tap(te.checked && !te.torn && !te.wrong,
	    "presented on TE: %u of %u frames checked, 0 torn (%u)", te.checked,
	    n, te.torn);
	tap(free_run.torn > 0,
	    "presented at random moments: frames tear (%u of %u)",
	    free_run.torn, free_run.checked);
	gpiod_edge_event_buffer_free(buf);
	free(px);
	return tap_done();
}

int main(int argc, char **argv)
{
	if (argc < 3) {
		fprintf(stderr,
			"usage: gpio_te dirty|reset|frames|irq|period|black|crc|"
			"jitter|present DEV [ARGS]\n");
		return 2;
	}
	fd = open(argv[2], O_RDWR);
	if (fd < 0)
		die(argv[2]);
	if (!strcmp(argv[1], "dirty"))
		return cmd_dirty();
	if (!strcmp(argv[1], "reset") && argc == 4)
		return cmd_reset(argv[3]);
	if (!strcmp(argv[1], "frames") && argc == 4)
		return cmd_frames(argv[3]);
	if (!strcmp(argv[1], "irq") && argc == 4)
		return cmd_irq(argv[3]);
	if (!strcmp(argv[1], "period")) {
		printf("%llu\n", (unsigned long long)frame_ns());
		return 0;
	}
	if (!strcmp(argv[1], "black"))
		return cmd_black();
	if (!strcmp(argv[1], "crc"))
		return cmd_crc();
	if (!strcmp(argv[1], "jitter") && argc == 5)
		return cmd_jitter(argv[3], argv[4]);
	if (!strcmp(argv[1], "present") && argc == 5)
		return cmd_present(argv[3], argv[4]);
	fprintf(stderr, "gpio_te: bad arguments\n");
	return 2;
}
