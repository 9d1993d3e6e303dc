// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcctl pen: hold the RDC-1's light pen at a pixel, or lift it, through
 * the registers LPEN_POS and LPEN_CTRL on any librdc device, then watch a
 * whole frame and say whether the pen saw light and where it latched.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pen.h"
#include "rdc.h"
#include "report.h"

const char rdcctl_pen_usage[] =
	"  pen X Y [--threshold N]    hold the light pen at pixel (X, Y),\n"
	"                             watch a frame and print the latch;\n"
	"                             lit: luma above N (0-255, default 0)\n"
	"  pen off                    lift the light pen\n";

/* A decimal in [0, max], or -1. */
static long pen_number(const char *s, long max)
{
	char *end;
	long v;

	if (!s || s[0] < '0' || s[0] > '9')
		return -1;
	errno = 0;
	v = strtol(s, &end, 10);
	return errno || *end || v > max ? -1 : v;
}

/*
 * From the LPEN_CTRL write to the second vblank after it: one frame whole
 * has passed the pen.
 */
static int pen_watch(rdc_dev *dev, uint32_t *irq, uint32_t *latch)
{
	int ret = rdc_reg_write(dev, RDC_REG_IRQ_STATUS, RDC_IRQ_LPEN);

	if (!ret)
		ret = rdc_vblank_wait(dev);
	if (!ret)
		ret = rdc_vblank_wait(dev);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_IRQ_STATUS, irq);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_LPEN_LATCH, latch);
	return ret;
}

int rdcctl_pen_main(int argc, char **argv)
{
	const char *uri = "sim:";
	long x = -1, y = -1, threshold = 0;
	uint32_t irq = 0, latch = 0;
	bool off = false, bad = false;
	rdc_dev *dev;
	int i, n, words = 0, ret;

	i = rdcctl_command_at(argc, argv, "pen", &uri);
	if (i < 0)
		return -1;
	argc -= i + 1;
	argv += i + 1;
	for (n = 0; n < argc; n++) {
		const char *a = argv[n];

		if (!strcmp(a, "--threshold")) {
			threshold = pen_number(n + 1 < argc ? argv[++n] : NULL,
					       255);
			if (threshold < 0) {
				fprintf(stderr, "rdcctl: pen: --threshold "
						"wants 0-255\n");
				return 2;
			}
		} else if (!words && !strcmp(a, "off")) {
			off = true;
			words++;
		} else if (!words) {
			x = pen_number(a, 0xffff);
			words++;
		} else if (words == 1 && !off) {
			y = pen_number(a, 0xffff);
			words++;
		} else {
			bad = true;
		}
	}
	if (bad || (off ? words != 1 : words != 2 || x < 0 || y < 0)) {
		fprintf(stderr, "rdcctl: pen wants X Y (0-65535) or off\n");
		return 2;
	}
	ret = rdcctl_open(uri, &dev);
	if (ret)
		return 1;
	if (off) {
		ret = rdc_reg_write(dev, RDC_REG_LPEN_CTRL, 0);
	} else {
		ret = rdc_reg_write(dev, RDC_REG_LPEN_POS,
				    (uint32_t)y << 16 | (uint32_t)x);
		if (!ret)
			ret = rdc_reg_write(
				dev, RDC_REG_LPEN_CTRL,
				RDC_LPEN_CTRL_EN |
					FIELD_PREP(RDC_LPEN_CTRL_THRESHOLD,
						   (uint32_t)threshold));
		if (!ret)
			ret = pen_watch(dev, &irq, &latch);
		if (!ret && (irq & RDC_IRQ_LPEN))
			printf("pen %ld %ld: lit, latched at %u,%u\n", x, y,
			       (unsigned int)FIELD_GET(RDC_BEAM_X, latch),
			       (unsigned int)FIELD_GET(RDC_BEAM_Y, latch));
		else if (!ret)
			printf("pen %ld %ld: dark\n", x, y);
	}
	if (ret)
		rdcctl_error("pen", ret);
	rdc_close(dev);
	return ret ? 1 : 0;
}
