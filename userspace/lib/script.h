/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The .rdl interpreter inside librdc: script.c (the statements, their
 * table and rdc_script_run's loop over lines), script_img.c and
 * script_3d.c (more statements), script_lex.c (tokens and values),
 * script_run.c (running a statement's batch; errors) and script_names.c
 * (names).  Calls go that way only.  Not part of the public API.
 */
#ifndef RDC_SCRIPT_H
#define RDC_SCRIPT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rdc_priv.h"

/* Limits that keep hostile scripts from exhausting memory or time. */
#define RDL_MAX_LINE	   (4u << 20) /* bytes in one logical line */
#define RDL_MAX_FILE	   (64u << 20)
#define RDL_MAX_BLIT_BYTES (64u << 20)
#define RDL_MAX_STEP	   RDC_WAIT_BUDGET_DEFAULT
#define RDL_MAX_LIST_WORDS (1u << 20) /* one `list` block */

struct rdl_tok {
	const char *s; /* NUL-terminated; unescaped for quoted strings */
	size_t len;
	bool quoted;
};

struct rdl {
	rdc_dev *dev;
	struct rdc_script_result *res;
	rdc_batch *b;
	uint32_t line;		   /* first physical line of the statement */
	const char *src, *src_end; /* the statement's text, for columns */
	struct rdl_tok *tok;
	size_t ntok, tok_cap;
	char *buf; /* the logical line, tokens point into it */
	size_t buf_cap;
	/* `list ADDR` ... `end`: command words kept for VRAM, not run */
	bool list_on;
	uint32_t list_addr, list_line;
	uint32_t *list_w;
	size_t list_n, list_cap;
	/* `raster ADDR` ... `raster-end`: the raster list being written */
	bool raster_on;
	uint32_t raster_base, raster_addr, raster_n;
};

/* script_run.c: errors, and running a statement's batch */
int rdl_err(struct rdl *r, int code, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* An error at `at` in r->buf, with its physical line and column. */
int rdl_err_at(struct rdl *r, const char *at, int code, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
/* A library call failed: describe it, with the device's code if any. */
int rdl_fail(struct rdl *r, const char *what, int ret);
uint32_t rdl_dst_format(struct rdl *r);
/* The counters that the accounting reads around a statement. */
int rdl_counters(struct rdl *r, uint64_t *busy, uint32_t *cmds);
void rdl_account(struct rdl *r, uint32_t op, uint64_t busy0, uint32_t cmds0,
		 uint64_t busy1, uint32_t cmds1);
/* The statement's batch, encoded with result `enc`: run it, or list it. */
int rdl_encoded(struct rdl *r, uint32_t op, int enc);

/* script_lex.c: tokens, and the value of token i */
int rdl_tokenize(struct rdl *r);
int rdl_hex(char c);
int rdl_int(struct rdl *r, size_t i, int64_t lo, int64_t hi, int64_t *out);
int rdl_u32(struct rdl *r, size_t i, uint32_t *out);
int rdl_size(struct rdl *r, size_t i, uint32_t *out);
int rdl_coords(struct rdl *r, size_t first, size_t n, int *out);
uint32_t rdl_rgb_to_pixel(uint32_t rgb, uint32_t fmt);
int rdl_colour(struct rdl *r, size_t i, uint32_t fmt, uint32_t *out);
int rdl_rgb(struct rdl *r, size_t i, uint32_t *out);
int rdl_format(struct rdl *r, size_t i, uint32_t *out);
int rdl_reg(struct rdl *r, size_t i, uint32_t *out);
bool rdl_word(struct rdl *r, size_t i, const char *w);

/*
 * script.c: statement i's keyword and argument counts (max UINT32_MAX:
 * any number), NULL past the last; docs/rdl.md is checked against it.
 */
const char *rdl_stmt_info(size_t i, uint32_t *min, uint32_t *max);

/* script_names.c */
extern const char *const rdl_fmt_names[RDC_FMT_COUNT];
int rdl_rop_by_name(const char *s);

/*
 * script_lex.c: a decimal number (sign, fraction) times `scale`, rounded
 * to nearest, in [lo, hi]; degrees to 1/65536 turn modulo a turn
 */
#define RDL_FIX_ONE 65536 /* 1.0 in 15.16 */
int rdl_fixed(struct rdl *r, size_t i, int64_t scale, int64_t lo, int64_t hi,
	      int64_t *out);
int rdl_angle(struct rdl *r, size_t i, uint32_t *out);
/* script_raster.c: the raster list's statements */
int rdl_st_raster(struct rdl *r, uint32_t op);
int rdl_st_raster_wait(struct rdl *r, uint32_t op);
int rdl_st_raster_reg(struct rdl *r, uint32_t op);
int rdl_st_raster_clut(struct rdl *r, uint32_t op);
int rdl_st_raster_end(struct rdl *r, uint32_t op);
/* script_pen.c: the light pen's statements */
int rdl_st_lpen(struct rdl *r, uint32_t op);
int rdl_st_lpen_expect(struct rdl *r, uint32_t op);

#endif /* RDC_SCRIPT_H */
