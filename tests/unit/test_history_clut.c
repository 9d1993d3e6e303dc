// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The CLUT entry a pixel shows and the raster-list entry that wrote it
 * (rdc_history_clut, `rdcctl why`): a palette split on sim: and through a
 * stepped rdcd gives the same answers, and the colour each names is the
 * one the chip's frame shows at that pixel.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "test_history_common.h"
#include "test_net_common.h"

static const char *const args_stepped[] = { "--stepped", NULL };

/*
 * CLUT entry 5 is written by the host, then by the list at its top (list
 * entry 0) and from line 240 (4); 6 at the top (1) and from column 400 of
 * line 299 (7); 8 only from line 240 (5), so above it shows the frame
 * before's; 7 by nobody on the list.
 */
static const char split[] = "mode 640x480 i8\n"
			    "load-clut 5 #101010 #202020 #303030 #404040\n"
			    "fg 5\n"
			    "fill 0 0 320 480\n"
			    "fg 6\n"
			    "fill 320 0 160 480\n"
			    "fg 7\n"
			    "fill 480 0 120 480\n"
			    "fg 8\n"
			    "fill 600 0 40 480\n"
			    "raster 0x100000\n"
			    "raster-clut 5 #0000ff\n" /* entry 0 */
			    "raster-clut 6 #ff00ff\n" /* 1 */
			    "raster-wait 240\n"	      /* 2 */
			    "raster-reg FB_BASE 0\n"  /* 3 */
			    "raster-clut 5 #ff0000\n" /* 4 */
			    "raster-clut 8 #abcdef\n" /* 5 */
			    "raster-wait 299 400\n"   /* 6 */
			    "raster-clut 6 #00ff00\n" /* 7 */
			    "raster-end\n"	      /* 8 */
			    "wait-vblank\nwait-vblank\n";

struct probe {
	uint32_t x, y, index, source, entry, beam_x, beam_y, value;
};

static const struct probe probes[] = {
	{ 10, 10, 5, RDC_HISTORY_CLUT_LIST, 0, 0, 0, 0x0000ff },
	{ 10, 239, 5, RDC_HISTORY_CLUT_LIST, 0, 0, 0, 0x0000ff },
	{ 10, 240, 5, RDC_HISTORY_CLUT_LIST, 4, 0, 240, 0xff0000 },
	{ 10, 479, 5, RDC_HISTORY_CLUT_LIST, 4, 0, 240, 0xff0000 },
	{ 400, 298, 6, RDC_HISTORY_CLUT_LIST, 1, 0, 0, 0xff00ff },
	{ 399, 299, 6, RDC_HISTORY_CLUT_LIST, 1, 0, 0, 0xff00ff },
	{ 400, 299, 6, RDC_HISTORY_CLUT_LIST, 7, 400, 299, 0x00ff00 },
	{ 320, 300, 6, RDC_HISTORY_CLUT_LIST, 7, 400, 299, 0x00ff00 },
	{ 610, 100, 8, RDC_HISTORY_CLUT_LIST_PREV, 5, 0, 240, 0xabcdef },
	{ 610, 300, 8, RDC_HISTORY_CLUT_LIST, 5, 0, 240, 0xabcdef },
	{ 500, 100, 7, RDC_HISTORY_CLUT_HOST, 0, 0, 0, 0 },
};

static void check(const char *uri, int grab)
{
	struct rdc_script_result res;
	struct rdc_history_clut c;
	rdc_history *h = NULL;
	rdc_dev *dev = NULL;
	uint32_t *pix = calloc(640 * 480, sizeof(*pix)), w = 0, ht = 0;

	assert_non_null(pix);
	assert_int_equal(rdc_open(uri, &dev), 0);
	assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0, &h), 0);
	history_script_res(dev, split, &res);
	assert_int_equal(rdc_script_frame_wait(dev, &res), 0);
	if (grab)
		assert_int_equal(rdc_frame_grab(dev, pix, 640 * 480, &w, &ht),
				 0);
	for (size_t i = 0; i < RDC_ARRAY_SIZE(probes); i++) {
		const struct probe *p = &probes[i];

		assert_int_equal(rdc_history_clut(h, p->x, p->y, &c), 0);
		assert_int_equal(c.size, sizeof(c));
		assert_int_equal(c.x, p->x);
		assert_int_equal(c.y, p->y);
		assert_int_equal(c.format, RDC_FMT_I8);
		assert_int_equal(c.index, p->index);
		assert_int_equal(c.source, p->source);
		if (p->source == RDC_HISTORY_CLUT_HOST)
			continue;
		assert_int_equal(c.entry, p->entry);
		assert_int_equal(c.addr, 0x100000 + 8 * p->entry);
		assert_int_equal(c.beam_x, p->beam_x);
		assert_int_equal(c.beam_y, p->beam_y);
		assert_int_equal(c.value, p->value);
		/* the colour the chip shows there is the one named */
		if (grab)
			assert_int_equal(pix[p->y * 640 + p->x] & 0xffffff,
					 p->value);
	}
	if (grab)
		assert_int_equal(pix[100 * 640 + 500] & 0xffffff, 0x303030);
	assert_int_equal(rdc_history_clut(h, 640, 0, &c), RDC_E_RANGE);
	assert_int_equal(rdc_history_clut(h, 0, 0, NULL), RDC_E_INVAL);
	/* direct colour: no CLUT entry */
	history_script(dev, "mode 640x480 xrgb8888\nwait-vblank\n");
	assert_int_equal(rdc_history_clut(h, 0, 0, &c), 1);
	/* the list off: the host's */
	history_script(dev, "mode 640x480 i8\nraster off\n");
	assert_int_equal(rdc_history_clut(h, 10, 10, &c), 0);
	assert_int_equal(c.source, RDC_HISTORY_CLUT_HOST);
	rdc_history_close(h);
	rdc_close(dev);
	free(pix);
}

static void test_history_clut_sim(void **state)
{
	(void)state;
	check("sim:", 1);
}

/* The same answers through the daemon's registers and VRAM. */
static void test_history_clut_rdcd(void **state)
{
	struct netd d;

	(void)state;
	if (netd_start(&d, args_stepped)) {
		netd_dump_log(&d);
		fail_msg("rdcd did not start");
	}
	check(d.unix_uri, 1);
	assert_int_equal(netd_stop(&d), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_history_clut_sim),
		cmocka_unit_test(test_history_clut_rdcd),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
