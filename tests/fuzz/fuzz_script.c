// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target for the .rdl interpreter (userspace/lib/script.c): the
 * input is a script, run by rdc_script_run on a fresh sim: device with
 * 4 MiB of VRAM (a quarter of rdcd's default): what the seeds use fits
 * (640x480 and 800x600 in XRGB8888, the image scenes' tables at 2 MiB,
 * the 3D scenes' Z buffer up to 3.1 MiB); more is refused as it would be
 * on such a device.  FUZZ_SCRIPT_VERBOSE=1 prints each input's error.  Every
 * statement kind is reachable, `list ... end` blocks included; the seeds are
 * the .rdl files of examples/ and tests/golden/scenes/ and, for what those
 * never use, tests/fuzz/seeds/script; script.dict lists the keywords.
 *
 * Checked: the run ends with 0 or an RDC_E_* code; an error names a line
 * of the script (1-based, at most one past the last) and carries a
 * NUL-terminated message; a lexical error's column lies within its line's
 * text; the counters stay consistent (a readback's word count is zero
 * when no readback ran).
 *
 * Bounded work per input: the link replaces five library calls
 * (-Wl,--wrap, see the Makefile) with stand-ins: rdc_png_write checks its
 * arguments and writes nothing (`screenshot` would otherwise create files
 * anywhere), rdc_sim_step and rdc_sim_run_until move time by at most
 * FZ_MAX_STEP cycles (`step` takes up to ten simulated seconds), and
 * rdc_hw_wait_begin cuts every wait in the simulator to FZ_MAX_WAIT cycles
 * (a display list that jumps to itself would keep the DP busy for the
 * default budget of ten simulated seconds: minutes of fuzzing time), and
 * fopen reads only regular files of at most FZ_MAX_FILE bytes.
 */
#define RDC_CORE_INTERNAL /* the fuzz target reaches into the core: hw.h, dp.h */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hw.h"
#include "rdc.h"

#define FZ_MAX_STEP 4000000u /* 40 ms of the default core clock */
#define FZ_MAX_WAIT 4000000u
#define FZ_MAX_FILE (1 << 20)

#define fz_assert(c) \
	do { \
		if (!(c)) { \
			fprintf(stderr, "fuzz_script: %s:%d: %s\n", __FILE__, \
				__LINE__, #c); \
			abort(); \
		} \
	} while (0)

void __real_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);
void __wrap_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w);
int __real_rdc_sim_step(rdc_dev *dev, uint64_t cycles);
int __wrap_rdc_sim_step(rdc_dev *dev, uint64_t cycles);
int __wrap_rdc_sim_run_until(rdc_dev *dev, uint64_t t);
int __wrap_rdc_png_write(const char *path, const uint32_t *xrgb, uint32_t w,
			 uint32_t h, size_t pitch);
FILE *__real_fopen(const char *path, const char *mode);
FILE *__wrap_fopen(const char *path, const char *mode);

/*
 * `vram-load ADDR FILE` reads any file it is named: here only regular
 * files of at most FZ_MAX_FILE bytes (a FIFO or a device could block the
 * run).  Opening to write goes through: libFuzzer writes its corpus and
 * crash files so, and no statement writes but `screenshot` (above).
 */
FILE *__wrap_fopen(const char *path, const char *mode)
{
	struct stat st;

	if (!strchr(mode, 'w') && !strchr(mode, 'a') &&
	    (stat(path, &st) || !S_ISREG(st.st_mode) ||
	     st.st_size > FZ_MAX_FILE)) {
		errno = EACCES;
		return NULL;
	}
	return __real_fopen(path, mode);
}

void __wrap_rdc_hw_wait_begin(struct rdc_hw *hw, struct rdc_hw_wait *w)
{
	if (w->budget > FZ_MAX_WAIT)
		w->budget = FZ_MAX_WAIT;
	__real_rdc_hw_wait_begin(hw, w);
}

int __wrap_rdc_sim_step(rdc_dev *dev, uint64_t cycles)
{
	return __real_rdc_sim_step(dev,
				   cycles < FZ_MAX_STEP ? cycles : FZ_MAX_STEP);
}

int __wrap_rdc_sim_run_until(rdc_dev *dev, uint64_t t)
{
	uint64_t now;
	int ret = rdc_sim_time(dev, &now);

	if (ret)
		return ret;
	return t > now ? __wrap_rdc_sim_step(dev, t - now) : 0;
}

/* What rdc_png_write would read, read; nothing written. */
int __wrap_rdc_png_write(const char *path, const uint32_t *xrgb, uint32_t w,
			 uint32_t h, size_t pitch)
{
	volatile uint32_t sum = 0;

	fz_assert(path && xrgb && w && h && pitch >= w);
	fz_assert(strlen(path) < (1u << 22));
	for (uint32_t y = 0; y < h; y++)
		for (uint32_t x = 0; x < w; x++)
			sum += xrgb[(size_t)y * pitch + x];
	(void)sum;
	return 0;
}

static uint32_t fz_lines(const uint8_t *data, size_t size)
{
	uint32_t n = 1;

	for (size_t i = 0; i < size; i++)
		n += data[i] == '\n';
	return n;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static struct rdc_script_result res;
	rdc_dev *dev;
	int ret;

	fz_assert(!rdc_open("sim:vram=4M", &dev));
	ret = rdc_script_run(dev, (const char *)data, size, &res);
	if (ret && getenv("FUZZ_SCRIPT_VERBOSE"))
		fprintf(stderr, "line %u col %u: %s (%s)\n", res.error_line,
			res.error_col, res.error_msg, rdc_strerror(ret));
	fz_assert(ret <= 0 && rdc_strerror(ret));
	fz_assert(memchr(res.error_msg, 0, sizeof(res.error_msg)));
	if (ret) {
		fz_assert(res.error_line >= 1 &&
			  res.error_line <= fz_lines(data, size));
		fz_assert(res.error_msg[0]);
	} else {
		fz_assert(!res.error_line && !res.error_col);
		ret = rdc_script_frame_wait(dev, &res);
		fz_assert(ret <= 0);
	}
	if (res.error_col)
		fz_assert(ret == RDC_E_PARSE && res.error_col <= size + 1);
	if (!res.readbacks)
		fz_assert(!res.readback_words && !res.readback_crc);
	rdc_close(dev);
	return 0;
}
