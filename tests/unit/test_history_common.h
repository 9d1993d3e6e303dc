/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * What the pixel-history tests share: the scene of docs/history.md, and
 * two entries compared field by field (include after cmocka.h and rdc.h).
 */
#ifndef TEST_HISTORY_COMMON_H
#define TEST_HISTORY_COMMON_H

#include <string.h>

/* The fill / XOR blit / text scene of docs/history.md, lines 1 to 9. */
#define HISTORY_SCENE \
	"mode 640x480 xrgb8888\n" /* 1 */ \
	"fg #ff0000\n" \
	"fill 8 8 32 32\n" /* 3 */ \
	"rop xor\n" \
	"fg #00ffff\n" \
	"blit 8 8 12 10 16 16\n" /* 6 */ \
	"rop copy\n" \
	"fg #ffffff\n" \
	"text 12 10 \"A\"\n" /* 9 */

/* Every field of two entries (not their padding). */
static inline void assert_entry_equal(const struct rdc_history_entry *a,
				      const struct rdc_history_entry *b)
{
	assert_int_equal(a->x, b->x);
	assert_int_equal(a->y, b->y);
	assert_int_equal(a->format, b->format);
	assert_int_equal(a->before, b->before);
	assert_int_equal(a->after, b->after);
	assert_int_equal(a->cycle, b->cycle);
	assert_int_equal(a->frame, b->frame);
	assert_int_equal(a->fetched, b->fetched);
	assert_int_equal(a->opcode, b->opcode);
	assert_int_equal(a->cmd_index, b->cmd_index);
	assert_int_equal(a->source, b->source);
	assert_int_equal(a->line, b->line);
	assert_int_equal(a->cmd_addr, b->cmd_addr);
	assert_int_equal(a->depth, b->depth);
	assert_memory_equal(a->calls, b->calls, sizeof(a->calls));
	assert_int_equal(a->rop, b->rop);
	assert_int_equal(a->alpha, b->alpha);
	assert_int_equal(a->colorkey, b->colorkey);
	assert_int_equal(a->colorkey_on, b->colorkey_on);
	assert_int_equal(a->pattern, b->pattern);
	assert_int_equal(a->fg, b->fg);
	assert_int_equal(a->bg, b->bg);
}

/* Runs an .rdl text on dev; it must succeed (the error is printed).  The
 * result goes to *out if out is not NULL. */
static inline void history_script_res(rdc_dev *dev, const char *text,
				      struct rdc_script_result *out)
{
	struct rdc_script_result mine, *res = out ? out : &mine;
	int ret;

	memset(res, 0, sizeof(*res));
	ret = rdc_script_run(dev, text, strlen(text), res);
	if (ret)
		print_error("line %u: %s\n", res->error_line, res->error_msg);
	assert_int_equal(ret, 0);
}

static inline void history_script(rdc_dev *dev, const char *text)
{
	history_script_res(dev, text, NULL);
}

#endif
