// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: the .rdl interpreter: statements, colours, accounting, errors
 * with line numbers, and garbage input. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <zlib.h>

#include "rdc.h"
#include "script_fx.h"

static uint32_t reg(rdc_dev *dev, uint32_t r)
{
	uint32_t v = 0;

	assert_int_equal(rdc_reg_read(dev, r, &v), 0);
	return v;
}

static void test_basic_drawing(void **state)
{
	rdc_dev *dev = *state;
	uint32_t px[3];

	assert_int_equal(run(dev, "# comment\n"
				  "mode 320x200 xrgb8888   # trailing\n"
				  "\n"
				  "fg 0x00123456\n"
				  "fill 0 0 3 1\n"
				  "fg #abcdef\n"
				  "pixel 1 0\n"),
			 0);
	assert_int_equal(rdc_vram_read(dev, 0, px, sizeof(px)), 0);
	assert_int_equal(px[0] & 0xffffff, 0x123456);
	assert_int_equal(px[1] & 0xffffff, 0xabcdef);
	assert_int_equal(px[2] & 0xffffff, 0x123456);
	assert_int_equal(res.error_line, 0);
}

/* #rrggbb rounds to the nearest 5:6:5 value. */
static void test_colour_rgb565(void **state)
{
	rdc_dev *dev = *state;
	uint8_t px[2];

	assert_int_equal(run(dev, "mode 320x200 rgb565\n"
				  "fg #ff8040\n"
				  "pixel 0 0\n"),
			 0);
	assert_int_equal(rdc_vram_read(dev, 0, px, 2), 0);
	/* red 0xff -> 31, green 0x80 -> 128*63/255 = 31.6 -> 32,
	 * blue 0x40 -> 64*31/255 = 7.8 -> 8 */
	assert_int_equal(px[0] | px[1] << 8, (31 << 11) | (32 << 5) | 8);
}

/* The per-class numbers are exactly what the counters say. */
static void test_accounting_exact(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev, "fill 0 0 100 10\n"), 0);
	assert_int_equal(res.op_count[RDC_OP_FILL_RECT], 1);
	assert_int_equal(res.op_cycles[RDC_OP_FILL_RECT],
			 reg(dev, RDC_REG_PERF_LAST_CYCLES));
	assert_int_equal(run(dev, "fg 1\nline 0 0 10 10\nline 0 0 20 3\n"
				  "fg 2\n"),
			 0);
	assert_int_equal(res.op_count[RDC_OP_LINE], 2);
	assert_int_equal(res.op_count[RDC_OP_SET_FG], 2);
	assert_int_equal(res.op_count[RDC_OP_FILL_RECT], 0);
	assert_true(res.op_cycles[RDC_OP_LINE] > 0);
	{
		uint64_t sum = 0, busy0, busy1;
		uint32_t lo, hi;

		lo = reg(dev, RDC_REG_PERF_BUSY_LO);
		hi = reg(dev, RDC_REG_PERF_BUSY_HI);
		busy0 = (uint64_t)hi << 32 | lo;
		assert_int_equal(run(dev, "circle 50 50 20\nrect 1 1 30 30\n"
					  "text 0 0 \"abc\"\n"),
				 0);
		lo = reg(dev, RDC_REG_PERF_BUSY_LO);
		hi = reg(dev, RDC_REG_PERF_BUSY_HI);
		busy1 = (uint64_t)hi << 32 | lo;
		for (int i = 0; i < 256; i++)
			sum += res.op_cycles[i];
		assert_int_equal(sum, busy1 - busy0);
	}
	assert_string_equal(rdc_op_name(RDC_OP_FILL_RECT), "fill-rect");
	assert_null(rdc_op_name(0x99));
}

/* `readback` records the CRC of what rdc_readback returns. */
static void test_readback_statement(void **state)
{
	rdc_dev *dev = *state;
	uint8_t buf[8 * 4 * 4];

	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n"
				  "host-blit 0 0 8 4 pattern noise 5\n"
				  "readback 0 0 8 4\n"),
			 0);
	assert_int_equal(res.readbacks, 1);
	assert_int_equal(res.readback_words, 32);
	assert_int_equal(rdc_readback(dev, 0, 0, 8, 4, buf, sizeof(buf)),
			 (int)sizeof(buf));
	assert_int_equal(res.readback_crc,
			 (uint32_t)crc32(0, buf, sizeof(buf)));
	{
		char s[128];

		snprintf(s, sizeof(s), "readback 0 0 8 4 0x%08x\n",
			 res.readback_crc);
		assert_int_equal(run(dev, s), 0);
		snprintf(s, sizeof(s), "\nreadback 0 0 8 4 0x%08x\n",
			 res.readback_crc ^ 1);
		assert_int_equal(run(dev, s), RDC_E_DEVICE);
		assert_int_equal(res.error_line, 2);
	}
}

static void test_registers_and_host(void **state)
{
	rdc_dev *dev = *state;
	uint64_t t0, t1;

	assert_int_equal(run(dev, "reg LINE_COMPARE 123\n"
				  "expect LINE_COMPARE 123\n"
				  "cmd-reg LINE_COMPARE 0x50\n"
				  "expect line_compare 80\n"
				  "palette 10 #010203 0x040506\n"
				  "reg CLUT_INDEX 10\n"
				  "expect CLUT_DATA 0x010203\n"
				  "expect CLUT_DATA 0x040506\n"
				  "load-clut 20 #ffffff\n"
				  "reg CLUT_INDEX 20\n"
				  "expect CLUT_DATA 0xffffff\n"
				  "fence 77\n"
				  "expect FENCE 77\n"),
			 0);
	assert_int_equal(run(dev, "expect LINE_COMPARE 1\n"), RDC_E_DEVICE);
	assert_int_equal(res.error_line, 1);
	assert_int_equal(rdc_sim_time(dev, &t0), 0);
	assert_int_equal(run(dev, "step 5000\n"), 0);
	assert_int_equal(rdc_sim_time(dev, &t1), 0);
	assert_true(t1 >= t0 + 5000);
	assert_int_equal(run(dev, "vsync\n"), 0);
	assert_int_equal(res.frame_ready, 1);
	assert_int_equal(run(dev, "vsync\nnop\n"), 0);
	assert_int_equal(res.frame_ready, 0);
	assert_int_equal(run(dev, "wait-frame\nfinish\nwait-vblank\n"
				  "wait-line 10\nnop 5\n"),
			 0);
	assert_int_equal(res.op_count[RDC_OP_NOP], 1);
}

/* A device error stops the script at its line, with the device's code. */
static void test_device_error_line(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev, "fill 0 0 1 1\n\ncmd 0x7f\nfill 0 0 2 2\n"),
			 RDC_E_DEVICE);
	assert_int_equal(res.error_line, 3);
	assert_non_null(strstr(res.error_msg, "OPCODE"));
	assert_int_equal(res.op_count[RDC_OP_FILL_RECT], 1);
	assert_int_equal(rdc_dev_error(dev, NULL, NULL), 0);
	assert_int_equal(run(dev, "raw 0x21000002 0 0x00050005\n"), 0);
	assert_int_equal(res.op_count[RDC_OP_LINE], 1);
}

static const struct {
	const char *text;
	uint32_t line;
} bad_scripts[] = {
	{ "bogus\n", 1 },
	{ "fill 0 0 1 1\nfill 1 2 3\n", 2 },
	{ "\n\nfill a b c d\n", 3 },
	{ "line 0 0 40000 0\n", 1 },
	{ "line 0 0 0x 0\n", 1 },
	{ "pixel 1 --2\n", 1 },
	{ "fg #12345\n", 1 },
	{ "fg #1234567\n", 1 },
	{ "text 0 0 \"unterminated\n", 1 },
	{ "text 0 0 \"bad \\q escape\"\n", 1 },
	{ "text 0 0 \"x\\x4\"\n", 1 },
	{ "text 0 0 unquoted\n", 1 },
	{ "text 0 0 \"a\"b\n", 1 },
	{ "text 0 0 \"a\" opaque\n", 1 },
	{ "mono 0 0 8 2 ff\n", 1 },
	{ "mono 0 0 8 1 fg\n", 1 },
	{ "mono 0 0 8 1 f\n", 1 },
	{ "mono 0 0 8 1 ff ff\n", 1 },
	{ "rop frobnicate\n", 1 },
	{ "mode 123x456\n", 1 },
	{ "mode 640x480 rgb999\n", 1 },
	{ "reg NOPE 1\n", 1 },
	{ "reg CONTROL\n", 1 },
	{ "host-blit 0 0 2 2 data 1 2 3\n", 1 },
	{ "host-blit 0 0 2 2 pattern wat\n", 1 },
	{ "host-blit 0 0 2 2 something\n", 1 },
	{ "host-blit 0 0 0 2 pattern gradient\n", 1 },
	{ "host-blit 0 0 2 2 pattern checker 0 1 2\n", 1 },
	{ "clip 1 2\n", 1 },
	{ "dst 0 0 0\n", 1 },
	{ "dst 0 0 10 10 i9\n", 1 },
	{ "mode 320x200 i8\nfg #ff0000\n", 2 },
	{ "load-clut 0 0x1000000\n", 1 },
	{ "palette 256 0\n", 1 },
	{ "step -1\n", 1 },
	{ "step 99999999999999\n", 1 },
	{ "polyline 1 2 3 4 5\n", 1 },
	{ "nop 99999999\n", 1 },
	{ "nop 4097\n", 1 },
	{ "mono 0 0 512 300 00\n", 1 },
	{ "cmd 0x100\n", 1 },
	{ "readback 0 0 1\n", 1 },
	{ "expect FENCE\n", 1 },
	{ "screenshot\n", 1 },
	{ "fill 0 0 1 1 \\\n 2\n", 1 },
	{ "fill 0 0 \\\n 1 1\nfill \\\n 0\n", 3 },
	{ "\"fill\" 0 0 1 1\n", 1 },
	{ "fill 0 0 1 1\r\nbad\r\n", 2 },
	{ "wait-vblank 1\n", 1 },
	{ "fill 0 0 1 1 # ok\n#\n  # x\n\tfill 0 0 0x10 -1\n", 4 },
};

static void test_parse_errors(void **state)
{
	rdc_dev *dev = *state;

	for (size_t i = 0; i < sizeof(bad_scripts) / sizeof(*bad_scripts);
	     i++) {
		int ret = run(dev, bad_scripts[i].text);

		if (ret != RDC_E_PARSE || res.error_line != bad_scripts[i].line)
			print_error("script %zu \"%s\": ret %d line %u: %s\n",
				    i, bad_scripts[i].text, ret, res.error_line,
				    res.error_msg);
		assert_int_equal(ret, RDC_E_PARSE);
		assert_int_equal(res.error_line, bad_scripts[i].line);
		assert_true(strlen(res.error_msg) > 0);
	}
	/* commands longer than the DP takes are refused before sending */
	{
		size_t cap = 20 * (RDC_CMD_MAX_ARGS + 1) + 64, len;
		char *t = malloc(cap);

		assert_non_null(t);
		len = (size_t)snprintf(t, cap, "nop\npolyline");
		for (int i = 0; i <= RDC_CMD_MAX_ARGS; i++)
			len += (size_t)snprintf(t + len, cap - len, " %d %d",
						i % 300, i % 200);
		t[len++] = '\n';
		assert_int_equal(rdc_script_run(dev, t, len, &res),
				 RDC_E_PARSE);
		assert_int_equal(res.error_line, 2);
		len = (size_t)snprintf(t, cap, "text 0 0 \"");
		memset(t + len, 'a', 4 * RDC_CMD_MAX_ARGS);
		len += 4 * RDC_CMD_MAX_ARGS;
		len += (size_t)snprintf(t + len, cap - len, "\"\n");
		assert_int_equal(rdc_script_run(dev, t, len, &res),
				 RDC_E_PARSE);
		assert_int_equal(res.error_line, 1);
		free(t);
	}
	/* a NUL byte inside the text */
	assert_int_equal(rdc_script_run(dev, "nop\nn\0p\n", 8, &res),
			 RDC_E_PARSE);
	assert_int_equal(res.error_line, 2);
}

static void test_good_variants(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev,
			     "rop GXxor\nrop and_reverse\nrop 3\n"
			     "rop copy-inverted\nrop copy\n"
			     "mode 640x480@60 i8 0x1000\n"
			     "mode 1 RGB565\n"
			     "clip off\nclip 0 0 10 10\n"
			     "dst screen\nsrc screen\n"
			     "dst 0x100000 64 16 16 i4\n"
			     "fill 0 0 16 16\n"
			     "dst screen\n"
			     "fill 0 0 \\\n  5 5\n"
			     "text 1 1 \"\\x41\\n\\t\\\\\\\"\\0\" transparent\n"
			     "mono 0 0 16 2 transparent ffff 0000\n"
			     "host-blit 0 0 2 1 data #ff0000 0x1f\n"
			     "polyline 0 0 5 5 10 0\n"
			     "ellipse 20 20 5 3\nfill-ellipse 20 20 3 5\n"
			     "circle 30 30 4\nfill-circle 30 30 2\n"
			     "blit 0 0 40 40 8 8\n"
			     "nop\n"),
			 0);
	assert_int_equal(run(dev, ""), 0);
	assert_int_equal(rdc_script_run(dev, NULL, 0, &res), 0);
	assert_int_equal(rdc_script_run(dev, "nop", 3, NULL), 0);
	assert_int_equal(rdc_script_run_file(dev, "/nonexistent/x.rdl", &res),
			 RDC_E_FILE);
	assert_true(strlen(res.error_msg) > 0);
}

static uint32_t fz = 2463534242u;

static uint32_t fuzz_rnd(void)
{
	fz ^= fz << 13;
	fz ^= fz >> 17;
	fz ^= fz << 5;
	return fz;
}

static void check_result(int ret, size_t len)
{
	assert_true(ret <= 0 && ret > RDC_E_COUNT_);
	if (ret) {
		assert_true(res.error_line >= 1 && res.error_line <= len + 1);
		assert_non_null(
			memchr(res.error_msg, 0, sizeof(res.error_msg)));
	}
}

/* Random bytes, then random words from the language: never a crash. */
static void test_fuzz(void **state)
{
	static const char *const vocab[] = {
		"fill",	       "line",	     "pixel",	"rect",	    "circle",
		"fill-circle", "ellipse",    "text",	"mono",	    "host-blit",
		"blit",	       "fg",	     "bg",	"rop",	    "clip",
		"polyline",    "load-clut",  "palette", "readback", "nop",
		"fence",       "dst",	     "src",	"mode",	    "expect",
		"pattern",     "data",	     "checker", "noise",    "gradient",
		"transparent", "off",	     "screen",	"xor",	    "i1",
		"i4",	       "rgb565",     "320x200", "0",	    "1",
		"-1",	       "7",	     "300",	"0xffff",   "65535",
		"-32768",      "99999",	     "#ff0000", "#",	    "\"",
		"\"hi\"",      "\\",	     "\\x",	"\n",	    "\n",
		"\n",	       "\t",	     "0x",	"ff",	    "#00ff00",
		"FENCE",       "CLUT_INDEX",
	};
	rdc_dev *dev = *state;
	char buf[512];

	for (int iter = 0; iter < 300; iter++) {
		size_t len = fuzz_rnd() % sizeof(buf);

		for (size_t i = 0; i < len; i++)
			buf[i] = (char)fuzz_rnd();
		check_result(rdc_script_run(dev, buf, len, &res), len);
	}
	for (int iter = 0; iter < 300; iter++) {
		size_t len = 0;
		int words = (int)(fuzz_rnd() % 24);

		for (int k = 0; k < words; k++) {
			const char *w = vocab[fuzz_rnd() %
					      (sizeof(vocab) / sizeof(*vocab))];
			size_t wl = strlen(w);

			if (len + wl + 1 >= sizeof(buf))
				break;
			memcpy(buf + len, w, wl);
			len += wl;
			buf[len++] = (fuzz_rnd() & 3) ? ' ' : '\n';
		}
		check_result(rdc_script_run(dev, buf, len, &res), len);
		/* leave no device error behind for the next round */
		assert_int_equal(rdc_dev_error(dev, NULL, NULL), 0);
	}
}

/*
 * A '#' word after a keyword that is not #rrggbb is an error at its line
 * and column, not a comment that swallows the rest of the statement.
 */
static void test_colour_typo(void **state)
{
	rdc_dev *dev = *state;
	static const struct {
		const char *text;
		uint32_t line, col;
		const char *word;
	} bad[] = {
		{ "mode 320x200 xrgb8888\nfg #gg0000\n", 2, 4, "'#gg0000'" },
		{ "fill 0 0 1 1 #box\n", 1, 14, "'#box'" },
		{ "fg #ff00\n", 1, 4, "'#ff00'" },
		{ "fill 0 0 1 1\nline 0 0 \\\n  5 5 \\\n\t #12345g\n", 4, 3,
		  "'#12345g'" },
		{ "fill 0 0 1 1\r\nfg  #0000000\r\n", 2, 5, "'#0000000'" },
	};

	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		int ret = run(dev, bad[i].text);

		if (ret != RDC_E_PARSE || res.error_line != bad[i].line ||
		    res.error_col != bad[i].col)
			print_error("script %zu: ret %d at %u:%u: %s\n", i, ret,
				    res.error_line, res.error_col,
				    res.error_msg);
		assert_int_equal(ret, RDC_E_PARSE);
		assert_int_equal(res.error_line, bad[i].line);
		assert_int_equal(res.error_col, bad[i].col);
		assert_non_null(strstr(res.error_msg, bad[i].word));
	}
	/* the count of arguments reads as English */
	assert_int_equal(run(dev, "fill 0\n"), RDC_E_PARSE);
	assert_non_null(strstr(res.error_msg, "fill: 1 argument (takes 4)"));
	assert_int_equal(run(dev, "fill 0 0\n"), RDC_E_PARSE);
	assert_non_null(strstr(res.error_msg, "fill: 2 arguments (takes 4)"));
	/* comments: at a statement's start, or '#' before a blank */
	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n#ffffff is white\n"
				  "fg #ffffff # white\n#\nfg 0 #\n"),
			 0);
	assert_int_equal(res.error_col, 0);
}

#define T(f) cmocka_unit_test_setup_teardown(f, dev_setup, dev_teardown)

int main(void)
{
	const struct CMUnitTest tests[] = {
		T(test_basic_drawing),	    T(test_colour_rgb565),
		T(test_accounting_exact),   T(test_readback_statement),
		T(test_registers_and_host), T(test_device_error_line),
		T(test_parse_errors),	    T(test_colour_typo),
		T(test_good_variants),	    T(test_fuzz),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
