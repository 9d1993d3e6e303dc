// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The .rdl tests' fixture: a sim: device with 4 MiB of VRAM as cmocka's
 * state, and run() of a script's text into `res`, which the test reads.
 * With SCRIPT_FX_SAY_ERRORS defined, run() prints a failing script's
 * line and message (cmocka.h first).
 */
#ifndef RDC_TEST_SCRIPT_FX_H
#define RDC_TEST_SCRIPT_FX_H

#include <string.h>

#include "rdc.h"

static struct rdc_script_result res;

static int dev_setup(void **state)
{
	rdc_dev *dev;

	if (rdc_open("sim:vram=4M", &dev))
		return -1;
	*state = dev;
	return 0;
}

static int dev_teardown(void **state)
{
	rdc_close(*state);
	return 0;
}

static int run(rdc_dev *dev, const char *text)
{
	int ret = rdc_script_run(dev, text, strlen(text), &res);

#ifdef SCRIPT_FX_SAY_ERRORS
	if (ret)
		print_message("line %u: %s\n", res.error_line, res.error_msg);
#endif
	return ret;
}

#endif /* RDC_TEST_SCRIPT_FX_H */
