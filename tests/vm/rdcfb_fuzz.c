// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcfb_fuzz: rdcfb.ko's private ioctls under hostile input.  Thousands
 * of random and malformed SUBMIT buffers (random words, good headers with
 * bad lengths, counts past the cap, surfaces and display lists outside
 * VRAM, bad user pointers, reserved fields), REG_WRITE/REG_READ at bad
 * offsets, WAIT with bad kinds and flags, STEP and WAIT past
 * RDCFB_MAX_CYCLES (EINVAL, time unmoved), FRAME with bad buffers; every
 * malformed request must be refused with the errno rdcfb_ioctl.h gives it
 * and a refused SUBMIT must queue nothing.  Then a known scene drawn
 * through fbdev: must give the same frame as the same scene on an
 * in-process sim:.  Prints TAP.
 *
 *   rdcfb_fuzz --scene FILE.rdl [--device /dev/fbN] [--iterations N]
 *              [--seed S]
 *
 * Expects clock=stepped (nothing moves between two ioctls) and fbcon
 * unbound from the device.
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "rdc.h"
#include "rdcfb_ioctl.h"
#include "tap.h"

#define FUZZ_MAX_WORDS 512u /* random buffers are at most this long */
/* A wait's budget while fuzzing: short, the chip may be in any state. */
#define FUZZ_WAIT_BUDGET 20000u
#define FUZZ_WAIT_MS	 200u
#define FUZZ_STEP_MAX	 100000u
/* Reset the chip this often, so accepted junk cannot wedge the FIFO. */
#define FUZZ_RESET_EVERY 64u

static int fd = -1;
static uint64_t rng_state;

/* xorshift64*: the same sequence for the same --seed, on any host. */
static uint32_t rnd(void)
{
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return (uint32_t)((rng_state * 0x2545f4914f6cdd1dull) >> 32);
}

static uint32_t rnd_below(uint32_t n)
{
	return n ? rnd() % n : 0;
}

static int xioctl(unsigned long req, void *arg)
{
	int r;

	do {
		r = ioctl(fd, req, arg);
	} while (r < 0 && errno == EINTR);
	return r < 0 ? errno : 0;
}

static uint32_t reg(uint32_t r)
{
	struct rdcfb_reg rr = { .reg = r };

	return xioctl(RDCFB_IOC_REG_READ, &rr) ? 0xdeadbeef : rr.val;
}

static int reg_write(uint32_t r, uint32_t v)
{
	struct rdcfb_reg rr = { .reg = r, .val = v };

	return xioctl(RDCFB_IOC_REG_WRITE, &rr);
}

/* ---- Malformed buffers --------------------------------------------------- */

enum fuzz_kind {
	FZ_RANDOM,     /* random words: whatever the driver says, it survives */
	FZ_BAD_LENGTH, /* a fixed-length command with another length */
	FZ_TRUNCATED,  /* the last command runs past the buffer */
	FZ_SURFACE,    /* SET_DST/SET_SRC leaving VRAM */
	FZ_LIST,       /* CALL/JUMP outside VRAM or unaligned */
	FZ_TOO_LONG,   /* a header past RDC_CMD_MAX_ARGS */
	FZ_CLUT,       /* LOAD_CLUT past 256 entries */
	FZ_OPCODE,     /* an opcode the DP does not know */
	FZ_COUNT_CAP,  /* count > RDCFB_SUBMIT_MAX_WORDS */
	FZ_BAD_POINTER, /* words pointing at nothing */
	FZ_RESERVED,	/* flags or reserved nonzero */
	FZ_KINDS
};

static const char *const fuzz_names[FZ_KINDS] = {
	"random words",	 "bad lengths",	 "truncated",	    "surfaces",
	"display lists", "over-long",	 "LOAD_CLUT",	    "opcodes",
	"count > cap",	 "bad pointers", "reserved fields",
};

/* A valid first command, so the bad one is not at word 0. */
static uint32_t put_prefix(uint32_t *w)
{
	uint32_t n = 0;

	switch (rnd_below(3)) {
	case 0:
		break;
	case 1:
		w[n++] = RDC_CMD(RDC_OP_SET_FG, 0, 1);
		w[n++] = rnd();
		break;
	default:
		w[n++] = RDC_CMD(RDC_OP_NOP, 0, 2);
		w[n++] = rnd();
		w[n++] = rnd();
		break;
	}
	return n;
}

/* Fill w with a malformed buffer of `kind`; its word count. */
static uint32_t make_bad(enum fuzz_kind kind, uint32_t *w, uint32_t vram)
{
	uint32_t n = put_prefix(w), len;

	switch (kind) {
	case FZ_RANDOM:
		len = 1 + rnd_below(FUZZ_MAX_WORDS - n - 1);
		for (uint32_t i = 0; i < len; i++)
			w[n++] = rnd();
		break;
	case FZ_BAD_LENGTH: {
		static const uint32_t ops[][2] = {
			{ RDC_OP_FILL_RECT, 2 }, { RDC_OP_LINE, 2 },
			{ RDC_OP_SET_DST, 4 },	 { RDC_OP_FENCE, 1 },
			{ RDC_OP_BLIT, 3 },	 { RDC_OP_TRIANGLE, 9 },
		};
		uint32_t k = rnd_below(RDC_ARRAY_SIZE(ops));

		do {
			len = rnd_below(16);
		} while (len == ops[k][1]);
		w[n++] = RDC_CMD(ops[k][0], 0, len);
		for (uint32_t i = 0; i < len; i++)
			w[n++] = rnd() & 0x00ff00ffu;
		break;
	}
	case FZ_TRUNCATED:
		w[n++] = RDC_CMD(RDC_OP_POLYLINE, 0, 8 + rnd_below(64));
		for (uint32_t i = 0; i < 4; i++)
			w[n++] = RDC_XY(rnd_below(100), rnd_below(100));
		break;
	case FZ_SURFACE:
		w[n++] = RDC_CMD(rnd_below(2) ? RDC_OP_SET_DST : RDC_OP_SET_SRC,
				 0, 4);
		switch (rnd_below(3)) {
		case 0: /* starts past the end */
			w[n++] = vram + 4 * rnd_below(1024);
			w[n++] = 256;
			w[n++] = RDC_WH(64, 64);
			break;
		case 1: /* ends past the end */
			w[n++] = vram - 1024;
			w[n++] = 4096;
			w[n++] = RDC_WH(1024, 16 + rnd_below(1000));
			break;
		default: /* rows that wrap the 32-bit address space */
			w[n++] = 4 * rnd_below(1024);
			w[n++] = 0xfffffffcu;
			w[n++] = RDC_WH(16, 2 + rnd_below(16));
			break;
		}
		w[n++] = RDC_FMT_XRGB8888;
		break;
	case FZ_LIST:
		w[n++] =
			RDC_CMD(rnd_below(2) ? RDC_OP_CALL : RDC_OP_JUMP, 0, 1);
		w[n++] = rnd_below(2) ? vram + 4 * rnd_below(1u << 20) :
					(4 * rnd_below(vram / 4)) | 1 |
						rnd_below(2) << 1;
		break;
	case FZ_TOO_LONG:
		w[n++] = RDC_CMD(RDC_OP_NOP, 0,
				 RDC_CMD_MAX_ARGS + 1 + rnd_below(60000));
		break;
	case FZ_CLUT:
		len = RDC_CLUT_ENTRIES + 2 + rnd_below(100);
		w[n++] = RDC_CMD(RDC_OP_LOAD_CLUT, 0, len);
		for (uint32_t i = 0; i < len; i++)
			w[n++] = i;
		break;
	case FZ_OPCODE: {
		/*
		 * gaps in the opcode map, and the top of it: unknown by the
		 * table the DP and the driver's check both read
		 */
		uint32_t op;

		do {
			op = rnd_below(RDC_OP_COUNT);
		} while (rdc_cmd_args(op) != RDC_ARGS_UNKNOWN);
		w[n++] = RDC_CMD(op, 0, rnd_below(4));
		for (uint32_t i = 0; i < RDC_CMD_LEN(w[n - 1]); i++)
			w[n++] = 0;
		break;
	}
	default:
		break;
	}
	return n;
}

/* Counts of each outcome, per kind. */
struct tally {
	unsigned long accepted, refused, wrong_errno, queued_anyway,
		bad_word_out;
};

static int submit_raw(const void *words, uint32_t count, uint32_t flags,
		      uint32_t reserved, uint32_t *bad_word)
{
	struct rdcfb_submit s = {
		.words = (uintptr_t)words,
		.count = count,
		.flags = flags,
		.reserved = reserved,
		.bad_word = ~0u,
	};
	int e = xioctl(RDCFB_IOC_SUBMIT, &s);

	*bad_word = s.bad_word;
	return e;
}

static void fuzz_submit_one(enum fuzz_kind kind, uint32_t *w, uint32_t vram,
			    void *unmapped, struct tally *t)
{
	uint32_t n = 0, bad = 0, free0, free1, count;
	int e, want_refusal = kind != FZ_RANDOM;
	bool want_efault = false, want_einval = false, want_e2big = false;
	const void *ptr = w;

	free0 = reg(RDC_REG_FIFO_FREE);
	switch (kind) {
	case FZ_COUNT_CAP:
		count = RDCFB_SUBMIT_MAX_WORDS + 1 + rnd_below(1u << 30);
		want_e2big = true;
		e = submit_raw(w, count, 0, 0, &bad);
		break;
	case FZ_BAD_POINTER: {
		static const uintptr_t ptrs[] = { 0, 1, 0xfffffffffffff000ull,
						  0x00007ffffffff000ull };
		uint32_t k = rnd_below(RDC_ARRAY_SIZE(ptrs) + 1);

		ptr = k < RDC_ARRAY_SIZE(ptrs) ? (const void *)ptrs[k] :
						 unmapped;
		want_efault = true;
		e = submit_raw(ptr, 1 + rnd_below(64), 0, 0, &bad);
		break;
	}
	case FZ_RESERVED:
		w[0] = RDC_CMD(RDC_OP_NOP, 0, 0);
		want_einval = true;
		if (rnd_below(2))
			e = submit_raw(w, 1, 1u << rnd_below(32), 0, &bad);
		else
			e = submit_raw(w, 1, 0, 1u << rnd_below(32), &bad);
		break;
	default:
		n = make_bad(kind, w, vram);
		e = submit_raw(w, n, 0, 0, &bad);
		break;
	}
	free1 = reg(RDC_REG_FIFO_FREE);
	if (!e) {
		t->accepted++;
		if (want_refusal)
			t->wrong_errno++;
		return;
	}
	t->refused++;
	/* Nothing moves between the two reads on a stepped clock. */
	if (free1 != free0)
		t->queued_anyway++;
	if (want_efault)
		t->wrong_errno += e != EFAULT;
	else if (want_einval)
		t->wrong_errno += e != EINVAL;
	else if (want_e2big)
		t->wrong_errno += e != E2BIG;
	else if (kind == FZ_RANDOM)
		t->wrong_errno += e != EPROTO && e != EINVAL;
	else
		t->wrong_errno += e != EPROTO;
	if (e == EPROTO && n && bad >= n)
		t->bad_word_out++;
}

static int fuzz_submits(unsigned long iterations, uint32_t vram)
{
	static struct tally tally[FZ_KINDS];
	uint32_t *w = calloc(RDCFB_SUBMIT_MAX_WORDS, sizeof(*w));
	void *unmapped;
	int fails = 0;

	/* A page that surely is not mapped: mapped, then given back. */
	unmapped =
		mmap(NULL, 4096, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (!w || unmapped == MAP_FAILED)
		return -1;
	munmap(unmapped, 4096);
	for (unsigned long i = 0; i < iterations; i++) {
		enum fuzz_kind k = (enum fuzz_kind)rnd_below(FZ_KINDS);

		if (i % FUZZ_RESET_EVERY == 0)
			reg_write(RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
		fuzz_submit_one(k, w, vram, unmapped, &tally[k]);
	}
	for (int k = 0; k < FZ_KINDS; k++) {
		struct tally *t = &tally[k];
		int ok = !t->wrong_errno && !t->queued_anyway &&
			 !t->bad_word_out;

		tap(ok,
		    "SUBMIT %s: %lu refused, %lu accepted; wrong errno %lu, "
		    "queued though refused %lu, bad_word outside %lu",
		    fuzz_names[k], t->refused, t->accepted, t->wrong_errno,
		    t->queued_anyway, t->bad_word_out);
		fails += !ok;
	}
	free(w);
	return fails;
}

static uint64_t sim_now(void)
{
	struct rdcfb_counters c;

	return xioctl(RDCFB_IOC_COUNTERS, &c) ? 0 : c.now;
}

/*
 * A STEP and a WAIT (otherwise `wt`, one that never holds) asking for
 * more simulated time than RDCFB_MAX_CYCLES: 0 if both were refused with
 * EINVAL and time did not move, else the number that were not.
 */
static unsigned long fuzz_past_cap(const struct rdcfb_wait *wt)
{
	uint64_t past = RDCFB_MAX_CYCLES + 1 +
			(rnd_below(2) ?
				 0 :
				 ((uint64_t)rnd() << 32 | rnd()) %
					 (UINT64_MAX - RDCFB_MAX_CYCLES));
	struct rdcfb_step st = { .cycles = past };
	struct rdcfb_wait w = *wt;
	uint64_t t0 = sim_now();
	unsigned long bad = 0;

	bad += xioctl(RDCFB_IOC_STEP, &st) != EINVAL;
	w.budget = past;
	bad += xioctl(RDCFB_IOC_WAIT, &w) != EINVAL;
	bad += sim_now() != t0;
	return bad;
}

/* REG_*, WAIT, STEP, FRAME with bad arguments. */
static void fuzz_other(unsigned long iterations)
{
	unsigned long reg_bad = 0, wait_bad = 0, frame_bad = 0, step_bad = 0;
	unsigned long reg_ok = 0, wait_ok = 0, wait_reg_bad = 0;
	unsigned long cap_bad = 0, cap_ok = 0;
	static uint32_t small[16];

	for (unsigned long i = 0; i < iterations; i++) {
		struct rdcfb_reg r = { .reg = rnd() };
		struct rdcfb_wait wt;
		struct rdcfb_frame fr;
		struct rdcfb_step st;
		int e;

		if (i % FUZZ_RESET_EVERY == 0)
			reg_write(RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
		/* Offsets outside the window or unaligned: EINVAL. */
		if (rnd_below(2))
			r.reg = RDC_REG_WINDOW + (r.reg % (1u << 20));
		else
			r.reg = 4 * rnd_below(RDC_REG_WINDOW / 4) + 1 +
				rnd_below(3);
		e = xioctl(rnd_below(2) ? RDCFB_IOC_REG_READ :
					  RDCFB_IOC_REG_WRITE,
			   &r);
		reg_bad += e != EINVAL;

		/* Any value to any register: the chip survives it. */
		r.reg = 4 * rnd_below(RDC_REG_WINDOW / 4);
		r.val = rnd();
		if (r.reg != RDC_REG_CONTROL ||
		    !(r.val & RDC_CONTROL_SOFT_RESET))
			reg_ok += !xioctl(RDCFB_IOC_REG_WRITE, &r);
		else
			reg_ok++;

		/* WAIT: a bad kind, reserved flags or a bad register. */
		memset(&wt, 0, sizeof(wt));
		wt.term[0].kind = RDCFB_WAIT_GE;
		wt.term[0].reg = RDC_REG_FRAME_COUNT;
		wt.term[0].mask = ~0u;
		wt.term[0].value = ~0u;
		wt.budget = FUZZ_WAIT_BUDGET;
		wt.timeout_ms = FUZZ_WAIT_MS;
		switch (rnd_below(3)) {
		case 0:
			wt.term[rnd_below(2)].kind =
				RDCFB_WAIT_EQ + 1 + rnd_below(1000);
			wait_bad += xioctl(RDCFB_IOC_WAIT, &wt) != EINVAL;
			break;
		case 1:
			wt.flags = 1u << (1 + rnd_below(31));
			wait_bad += xioctl(RDCFB_IOC_WAIT, &wt) != EINVAL;
			break;
		default:
			/* on the term in use: a NONE term's fields are unread
			 */
			wt.term[0].reg =
				rnd_below(2) ?
					RDC_REG_WINDOW + rnd_below(4096) :
					RDC_REG_STATUS + 2;
			wait_reg_bad += xioctl(RDCFB_IOC_WAIT, &wt) != EINVAL;
			break;
		}
		/* and a good one that runs out of budget */
		wt.flags = 0;
		wt.term[0].kind = RDCFB_WAIT_EQ;
		wt.term[0].reg = RDC_REG_ID;
		wt.term[0].value = ~RDC_ID_VALUE;
		wt.term[1].kind = RDCFB_WAIT_NONE;
		wt.term[1].reg = 0;
		e = xioctl(RDCFB_IOC_WAIT, &wt);
		wait_ok += e == ETIMEDOUT;

		/* STEP: small, random */
		st.cycles = rnd_below(FUZZ_STEP_MAX);
		step_bad += xioctl(RDCFB_IOC_STEP, &st) != 0;

		/*
		 * Simulated time past the cap: EINVAL, and time stands still
		 * (a STEP or WAIT let through would run for minutes).
		 */
		cap_bad += fuzz_past_cap(&wt);
		/* the cap itself is a budget: a wait that holds at once */
		wt.term[0].value = RDC_ID_VALUE;
		wt.budget = RDCFB_MAX_CYCLES;
		cap_ok += xioctl(RDCFB_IOC_WAIT, &wt) == 0;

		/* FRAME: too small a buffer, or a bad pointer */
		memset(&fr, 0, sizeof(fr));
		fr.cap = RDC_ARRAY_SIZE(small);
		fr.pixels = rnd_below(2) ? (uintptr_t)small : 16;
		if (!rnd_below(4))
			fr.reserved = 1 + rnd();
		e = xioctl(RDCFB_IOC_FRAME, &fr);
		frame_bad += e == 0 && fr.seq && fr.width * fr.height > fr.cap;
	}
	tap(!reg_bad,
	    "REG_READ/REG_WRITE outside the window or unaligned: "
	    "EINVAL (%lu not)",
	    reg_bad);
	tap(reg_ok == iterations,
	    "REG_WRITE of any value to any register "
	    "(%lu of %lu taken)",
	    reg_ok, iterations);
	tap(!wait_bad, "WAIT with bad kinds or flags: EINVAL (%lu not)",
	    wait_bad);
	tap(!wait_reg_bad,
	    "WAIT on a register outside the window or unaligned: EINVAL "
	    "(%lu not)",
	    wait_reg_bad);
	tap(wait_ok == iterations,
	    "WAIT for what never comes: ETIMEDOUT "
	    "(%lu of %lu)",
	    wait_ok, iterations);
	tap(!step_bad, "STEP by up to %u cycles (%lu failed)", FUZZ_STEP_MAX,
	    step_bad);
	tap(!cap_bad,
	    "STEP and WAIT past RDCFB_MAX_CYCLES: EINVAL, time unmoved "
	    "(%lu not)",
	    cap_bad);
	tap(cap_ok == iterations,
	    "WAIT with a budget of RDCFB_MAX_CYCLES is taken (%lu of %lu)",
	    cap_ok, iterations);
	tap(!frame_bad,
	    "FRAME into too small a buffer never claims success "
	    "(%lu did)",
	    frame_bad);
}

/* ---- The known scene, on the device and on sim: -------------------------- */

static int scene_crc(const char *uri, const char *path, int zero_vram,
		     uint32_t *crc)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	rdc_dev *dev = NULL;
	int ret;

	if (!res)
		return RDC_E_NOMEM;
	ret = rdc_open(uri, &dev);
	if (!ret)
		ret = rdc_reset(dev);
	if (!ret && zero_vram) {
		uint32_t size = 0;
		static const uint8_t zero[65536];

		ret = rdc_reg_read(dev, RDC_REG_VRAM_SIZE, &size);
		for (uint32_t a = 0; !ret && a < size; a += sizeof(zero))
			ret = rdc_vram_write(dev, a, zero,
					     RDC_MIN(sizeof(zero), size - a));
	}
	if (!ret)
		ret = rdc_script_run_file(dev, path, res);
	if (!ret)
		ret = rdc_script_frame_wait(dev, res);
	if (!ret)
		ret = rdc_frame_crc(dev, crc);
	if (ret)
		printf("# %s %s: %s %s\n", uri, path, rdc_strerror(ret),
		       res->error_msg);
	rdc_close(dev);
	free(res);
	return ret;
}

static void check_scene(const char *dev, const char *scene, const char *when)
{
	char uri[256], sim_uri[64];
	uint32_t crc_dev = 0, crc_sim = 1;
	int r1, r2;

	snprintf(uri, sizeof(uri), "fbdev:%s", dev);
	snprintf(sim_uri, sizeof(sim_uri), "sim:vram=%u",
		 reg(RDC_REG_VRAM_SIZE));
	r1 = scene_crc(uri, scene, 1, &crc_dev);
	r2 = scene_crc(sim_uri, scene, 0, &crc_sim);
	tap(!r1 && !r2 && crc_dev == crc_sim,
	    "%s: the scene through fbdev: %08x, through sim: %08x", when,
	    crc_dev, crc_sim);
}

int main(int argc, char **argv)
{
	const char *dev = "/dev/fb0", *scene = NULL;
	unsigned long iterations = 10000;
	uint32_t vram;

	setvbuf(stdout, NULL, _IOLBF, 0);
	rng_state = 0x9e3779b97f4a7c15ull;
	for (int i = 1; i < argc; i++) {
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;

		if (!strcmp(argv[i], "--device") && v) {
			dev = v;
		} else if (!strcmp(argv[i], "--scene") && v) {
			scene = v;
		} else if (!strcmp(argv[i], "--iterations") && v) {
			iterations = strtoul(v, NULL, 0);
		} else if (!strcmp(argv[i], "--seed") && v) {
			rng_state = strtoull(v, NULL, 0) | 1;
		} else {
			fprintf(stderr, "usage: rdcfb_fuzz --scene FILE.rdl "
					"[--device DEV] [--iterations N] "
					"[--seed S]\n");
			return 2;
		}
		i++;
	}
	if (!scene) {
		fprintf(stderr, "rdcfb_fuzz: --scene is needed\n");
		return 2;
	}
	fd = open(dev, O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		printf("Bail out! %s: %s\n", dev, strerror(errno));
		return 1;
	}
	{
		struct fb_fix_screeninfo fix;

		if (ioctl(fd, FBIOGET_FSCREENINFO, &fix) ||
		    strncmp(fix.id, RDCFB_ID, sizeof(fix.id))) {
			printf("Bail out! %s is not an rdcfb device\n", dev);
			return 1;
		}
	}
	vram = reg(RDC_REG_VRAM_SIZE);
	printf("# %s: VRAM %u bytes, seed %#llx, %lu iterations\n", dev, vram,
	       (unsigned long long)rng_state, iterations);
	check_scene(dev, scene, "before");
	fuzz_submits(iterations, vram);
	fuzz_other(iterations / 10);
	reg_write(RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	check_scene(dev, scene, "after");
	close(fd);
	return tap_done();
}
