// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target for trace replay (userspace/lib/record.c): the input
 * is a trace file (rdcd --record, rdc_record_start; docs/protocol.md,
 * "Traces"), replayed by rdc_replay_file on fresh sim: devices, and once
 * more with a pixel history open (rdc_replay_history), as `rdcctl
 * replay`, `why` and `diff` read them.  Seeds: tests/fuzz/seeds/trace
 * (timed traces of golden scenes, version 2, untimed ones, version 3
 * with SUBMIT records, and a client's on a 64 KiB sim:, version 4 with
 * its STATE record: registers, CLUT, deflated VRAM, the core's state).
 *
 * Checked: the replay ends with 0 or an RDC_E_* code; on success the
 * records counted do not exceed what the input could hold, and a history
 * comes back exactly when the replay succeeded.
 *
 * Checked too: replay's own bound (record.c, docs/protocol.md "Traces"):
 * no record makes the chip run, or a wait last, more than one simulated
 * minute, and no replay makes more than 1 + 256 chips (POWER records) -
 * seen through the stand-ins below.  Seeds bound-*.trace ask for more.
 *
 * Bounded work per input: the header's VRAM size is at most 8 MiB here
 * (a larger one is cut down in the input, so the sizes the format allows
 * are still read), and the link replaces rdc_hw_run_until and
 * rdc_hw_wait_begin (-Wl,--wrap, see the Makefile) with stand-ins that
 * move time by at most FZ_MAX_STEP cycles and cut waits to FZ_MAX_WAIT,
 * once they have checked the bound above.
 */
#define RDC_CORE_INTERNAL /* the fuzz target reaches into the core: hw.h, dp.h */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "hw.h"
#include "rdc.h"

#define FZ_MAX_STEP 4000000u /* 40 ms of the default core clock */
#define FZ_MAX_WAIT 4000000u
#define FZ_MAX_VRAM (8u << 20)
#define FZ_HDR_VRAM 12u /* "RDCTRACE", u32 version, u32 vram_size */
/* replay's documented bounds: a record, the chips of one replay */
#define FZ_DOC_CYCLES (60ull * 100000000ull)
#define FZ_DOC_CHIPS  (1u + 256u)

static unsigned int fz_chips; /* of the replay running */

#define fz_assert(c) \
	do { \
		if (!(c)) { \
			fprintf(stderr, "fuzz_trace: %s:%d: %s\n", __FILE__, \
				__LINE__, #c); \
			abort(); \
		} \
	} while (0)

void __real_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);
void __wrap_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);
void __real_rdc_hw_run_until(struct rdc_hw *hw, uint64_t t);
void __wrap_rdc_hw_run_until(struct rdc_hw *hw, uint64_t t);
void __real_rdc_hw_set_frame_fn(struct rdc_hw *hw, rdc_frame_fn fn, void *ctx);
void __wrap_rdc_hw_set_frame_fn(struct rdc_hw *hw, rdc_frame_fn fn, void *ctx);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* replay watches each chip it makes (the first, and one a POWER) */
void __wrap_rdc_hw_set_frame_fn(struct rdc_hw *hw, rdc_frame_fn fn, void *ctx)
{
	if (fn)
		fz_assert(++fz_chips <= FZ_DOC_CHIPS);
	__real_rdc_hw_set_frame_fn(hw, fn, ctx);
}

void __wrap_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w)
{
	fz_assert(w->budget <= FZ_DOC_CYCLES);
	if (w->budget > FZ_MAX_WAIT || !w->budget)
		w->budget = FZ_MAX_WAIT;
	__real_rdc_hw_wait_begin(hw, w);
}

void __wrap_rdc_hw_run_until(struct rdc_hw *hw, uint64_t t)
{
	fz_assert(t <= hw->now || t - hw->now <= FZ_DOC_CYCLES);
	if (t > hw->now + FZ_MAX_STEP)
		t = hw->now + FZ_MAX_STEP;
	__real_rdc_hw_run_until(hw, t);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static int fd = -1;
	struct rdc_replay_result res;
	rdc_history *h = NULL;
	char path[64];
	uint8_t *in;
	int ret;

	if (fd < 0) {
		fd = memfd_create("fuzz_trace", 0);
		if (fd < 0)
			abort();
	}
	in = malloc(size ? size : 1);
	if (!in)
		return 0;
	memcpy(in, data, size);
	if (size >= FZ_HDR_VRAM + 4) {
		uint32_t v = (uint32_t)in[FZ_HDR_VRAM] |
			     (uint32_t)in[FZ_HDR_VRAM + 1] << 8 |
			     (uint32_t)in[FZ_HDR_VRAM + 2] << 16 |
			     (uint32_t)in[FZ_HDR_VRAM + 3] << 24;

		if (v > FZ_MAX_VRAM) {
			v = v % FZ_MAX_VRAM;
			for (int i = 0; i < 4; i++)
				in[FZ_HDR_VRAM + i] = (uint8_t)(v >> (8 * i));
		}
	}
	if (ftruncate(fd, 0) || pwrite(fd, in, size, 0) != (ssize_t)size)
		abort();
	free(in);
	snprintf(path, sizeof(path), "/proc/self/fd/%d", fd);

	memset(&res, 0, sizeof(res));
	fz_chips = 0;
	ret = rdc_replay_file(path, &res, NULL);
	fz_assert(ret <= 0);
	/* a record is at least its op and time: 9 bytes */
	if (!ret)
		fz_assert(res.records <= size / 9 + 1);

	memset(&res, 0, sizeof(res));
	fz_chips = 0;
	ret = rdc_replay_history(path, 0, 0, 8, 8, 0, &h, &res, NULL);
	fz_assert(ret <= 0);
	fz_assert(!ret == (h != NULL));
	rdc_history_close(h);
	return 0;
}
