// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The raster list through librdc's sim backend and .rdl: the demo's sky
 * split at line 240 in frames 0, 1 and 100 after the script (and every
 * frame between, the same picture), with scanout eager and on demand;
 * the raster statements' entries in VRAM as docs/hardware.md encodes
 * them; their parse errors; and a bad list's device error.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "rdc_regs.h"

#define W 640u
#define H 480u

static struct rdc_script_result res;
static uint32_t frame[W * H];

static uint32_t grab(rdc_dev *dev)
{
	uint32_t w = 0, h = 0, crc = 0;

	assert_int_equal(rdc_frame_grab(dev, frame, W * H, &w, &h), 0);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	return crc;
}

/*
 * The demo's background at x = 630: sky ramp entries 16 + y / 15 above
 * line 240 (#001040 at the top, #1e4c7c in rows 225-239), the sunset ramp
 * from line 240 (#b04820 in rows 240-254, #fb7511 at the bottom).
 */
static void assert_split(void)
{
	assert_int_equal(frame[5 * W + 630] & 0xffffff, 0x001040);
	assert_int_equal(frame[239 * W + 630] & 0xffffff, 0x1e4c7c);
	assert_int_equal(frame[240 * W + 630] & 0xffffff, 0xb04820);
	assert_int_equal(frame[479 * W + 630] & 0xffffff, 0xfb7511);
}

static void demo_frames(const char *uri)
{
	rdc_dev *dev;
	uint32_t crc0;

	assert_int_equal(rdc_open(uri, &dev), 0);
	assert_int_equal(rdc_script_run_file(dev, "examples/demo.rdl", &res),
			 0);
	assert_int_equal(rdc_script_frame_wait(dev, &res), 0);
	crc0 = grab(dev); /* frame 0: the script's picture */
	assert_split();
	for (int k = 1; k <= 100; k++) {
		assert_int_equal(rdc_vblank_wait(dev), 0);
		if (k != 1 && k != 100 && k % 9)
			continue;
		assert_int_equal(grab(dev), crc0);
		assert_split();
	}
	rdc_close(dev);
}

static void test_demo_every_frame(void **state)
{
	(void)state;
	demo_frames("sim:");
	demo_frames("sim:scanout=demand");
}

static uint32_t rd32(rdc_dev *dev, uint32_t addr)
{
	uint32_t v = 0;

	assert_int_equal(rdc_vram_read(dev, addr, &v, 4), 0);
	return v;
}

static void test_statements(void **state)
{
	static const char text[] = "mode 640x480 i8\n"
				   "raster 0x100000\n"
				   "raster-clut 7 #102030 #405060\n"
				   "raster-wait 100 3\n"
				   "raster-reg FB_BASE 0x400\n"
				   "raster-end\n"
				   "expect RASTER_BASE 0x100000\n"
				   "expect RASTER_CTRL 1\n"
				   "wait-frame\n"
				   "expect RASTER_STATUS 0x50000\n"
				   "expect FB_BASE 0\n"
				   "raster off\n"
				   "expect RASTER_CTRL 0\n";
	const uint32_t want[] = {
		3u << 28 | 7,
		0x102030,
		3u << 28 | 8,
		0x405060,
		1u << 28,
		100u << 16 | 3,
		2u << 28 | RDC_REG_FB_BASE,
		0x400,
		0,
		0,
	};
	rdc_dev *dev;

	(void)state;
	assert_int_equal(rdc_open("sim:vram=2M", &dev), 0);
	assert_int_equal(rdc_script_run(dev, text, strlen(text), &res), 0);
	for (uint32_t i = 0; i < sizeof(want) / sizeof(*want); i++)
		assert_int_equal(rd32(dev, 0x100000 + 4 * i), want[i]);

	/* parse errors: outside `raster`, alignment, ranges */
	assert_int_equal(rdc_script_run(dev, "raster-wait 3\n", 14, &res),
			 RDC_E_PARSE);
	assert_int_equal(rdc_script_run(dev, "raster 0x1004\n", 14, &res),
			 RDC_E_PARSE);
	assert_int_equal(rdc_script_run(dev,
					"raster 0x1000\nraster-clut 255 1 2\n",
					35, &res),
			 RDC_E_PARSE);
	assert_int_equal(rdc_script_run(dev,
					"raster 0x1000\nraster-wait 70000\n",
					32, &res),
			 RDC_E_PARSE);
	assert_int_equal(rdc_script_run(dev, "raster-end\n", 11, &res),
			 RDC_E_PARSE);

	/* a register off the chip's list: the list stops, error RASTER */
	{
		static const char bad[] = "raster 0x1000\n"
					  "raster-reg CONTROL 0\n"
					  "raster-end\n"
					  "wait-frame\n"
					  "expect ERR_CODE 12\n"
					  "expect ERR_INFO 0x1000\n"
					  "expect RASTER_CTRL 0\n";

		assert_int_equal(rdc_script_run(dev, bad, strlen(bad), &res),
				 0);
	}
	rdc_close(dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_demo_every_frame),
		cmocka_unit_test(test_statements),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
