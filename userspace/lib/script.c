// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The .rdl script interpreter (the format is documented in docs/rdl.md).
 * rdc_script_run (at the end) reads a logical line, script_lex.c splits it
 * into tokens, and the statement's handler here (or in script_img.c or
 * script_3d.c, by the table below) reads its values, encodes its commands
 * and hands the batch to script_run.c, which runs it and charges its
 * cycles.  script_names.c holds the names of opcodes, registers, ROPs and
 * formats.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <zlib.h>

#include "script.h"
#include "script_3d.h"
#include "script_img.h"

/* Statement handlers get the tokens after the keyword at index 1. */
typedef int (*rdl_fn)(struct rdl *r, uint32_t op);

static int st_nop(struct rdl *r, uint32_t op)
{
	uint32_t n = 0;
	int ret = 0;

	if (r->ntok > 1)
		ret = rdl_size(r, 1, &n);
	if (ret)
		return ret;
	if (n > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "more than %d NOP words",
			       RDC_CMD_MAX_ARGS);
	{
		uint32_t *z = calloc(n + 1, sizeof(*z));

		if (!z)
			return rdl_err(r, RDC_E_NOMEM, "out of memory");
		ret = rdc_batch_cmd(r->b, op, 0, z, n);
		free(z);
	}
	return rdl_encoded(r, op, ret);
}

/* Commands whose arguments are all plain 32-bit numbers. */
static int st_words(struct rdl *r, uint32_t op)
{
	uint32_t a[RDC_CMD_MAX_ARGS];
	size_t n = r->ntok - 1;

	if (n > RDC_ARRAY_SIZE(a))
		return rdl_err(r, RDC_E_PARSE, "too many arguments");
	for (size_t i = 0; i < n; i++) {
		int ret = rdl_u32(r, i + 1, &a[i]);

		if (ret)
			return ret;
	}
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, a, n));
}

static int st_cmd_reg(struct rdl *r, uint32_t op)
{
	uint32_t reg, val;
	int ret = rdl_reg(r, 1, &reg);

	if (!ret)
		ret = rdl_u32(r, 2, &val);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_reg_write(r->b, reg, val));
}

static int st_load_clut(struct rdl *r, uint32_t op)
{
	uint32_t first, rgb[RDC_CLUT_ENTRIES];
	size_t n = r->ntok - 2;
	int ret = rdl_u32(r, 1, &first);

	if (ret)
		return ret;
	if (n > RDC_CLUT_ENTRIES)
		return rdl_err(r, RDC_E_PARSE, "more than %d CLUT entries",
			       RDC_CLUT_ENTRIES);
	for (size_t i = 0; i < n; i++) {
		ret = rdl_rgb(r, i + 2, &rgb[i]);
		if (ret)
			return ret;
	}
	return rdl_encoded(r, op, rdc_batch_load_clut(r->b, first, rgb, n));
}

static int st_colour(struct rdl *r, uint32_t op)
{
	uint32_t c;
	int ret = rdl_colour(r, 1, rdl_dst_format(r), &c);

	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, &c, 1));
}

static int st_rop(struct rdl *r, uint32_t op)
{
	int rop = rdl_rop_by_name(r->tok[1].s);
	uint32_t v;

	if (rop >= 0) {
		v = (uint32_t)rop;
	} else if (rdl_hex(r->tok[1].s[0]) >= 0 || r->tok[1].s[0] == '-') {
		int ret = rdl_u32(r, 1, &v);

		if (ret)
			return ret;
	} else {
		return rdl_err(r, RDC_E_PARSE, "unknown rop '%.40s'",
			       r->tok[1].s);
	}
	return rdl_encoded(r, op, rdc_batch_rop(r->b, v));
}

/* The scanout framebuffer as a surface (FB_* shadow registers). */
static int rdl_screen(struct rdl *r, uint32_t *base, uint32_t *stride,
		      uint32_t *w, uint32_t *h, uint32_t *fmt)
{
	int ret;

	ret = rdc_reg_read(r->dev, RDC_REG_FB_BASE, base);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_FB_STRIDE, stride);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_FB_FORMAT, fmt);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_H_DISPLAY, w);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_V_DISPLAY, h);
	return ret ? rdl_fail(r, "reading the framebuffer registers", ret) : 0;
}

static int st_clip(struct rdl *r, uint32_t op)
{
	int c[4];
	int ret;

	if (r->ntok == 2 && rdl_word(r, 1, "off")) {
		uint32_t base, stride, w, h, fmt;

		ret = rdl_screen(r, &base, &stride, &w, &h, &fmt);
		c[0] = c[1] = 0;
		c[2] = (int)RDC_MIN(w, (uint32_t)INT16_MAX);
		c[3] = (int)RDC_MIN(h, (uint32_t)INT16_MAX);
	} else if (r->ntok == 5) {
		ret = rdl_coords(r, 1, 4, c);
	} else {
		return rdl_err(r, RDC_E_PARSE,
			       "clip takes X0 Y0 X1 Y1 or 'off'");
	}
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_clip(r->b, c[0], c[1], c[2], c[3]));
}

static int st_surface(struct rdl *r, uint32_t op)
{
	uint32_t base, stride, w, h, fmt;
	int ret;

	if (r->ntok == 2 && rdl_word(r, 1, "screen")) {
		ret = rdl_screen(r, &base, &stride, &w, &h, &fmt);
	} else if (r->ntok == 6) {
		ret = rdl_u32(r, 1, &base);
		if (!ret)
			ret = rdl_u32(r, 2, &stride);
		if (!ret)
			ret = rdl_size(r, 3, &w);
		if (!ret)
			ret = rdl_size(r, 4, &h);
		if (!ret)
			ret = rdl_format(r, 5, &fmt);
	} else {
		return rdl_err(r, RDC_E_PARSE,
			       "%s takes BASE STRIDE W H FORMAT or 'screen'",
			       rdc_op_name(op));
	}
	if (ret)
		return ret;
	if (op == RDC_OP_SET_DST)
		ret = rdc_batch_dst(r->b, base, stride, w, h, fmt);
	else
		ret = rdc_batch_src(r->b, base, stride, w, h, fmt);
	return rdl_encoded(r, op, ret);
}

static int st_points(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 1;
	int *c;
	int ret;

	if (n % 2)
		return rdl_err(r, RDC_E_PARSE, "%s needs X Y pairs",
			       rdc_op_name(op));
	/* Longer is refused by the DP with only the header consumed, and
	 * the points would then run as commands: `raw` can do that. */
	if (n / 2 > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "more than %d points",
			       RDC_CMD_MAX_ARGS);
	c = malloc((n + 1) * sizeof(*c));
	if (!c)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_coords(r, 1, n, c);
	if (!ret) {
		switch (op) {
		case RDC_OP_PIXEL:
			ret = rdc_batch_pixel(r->b, c[0], c[1]);
			break;
		case RDC_OP_LINE:
			ret = rdc_batch_line(r->b, c[0], c[1], c[2], c[3]);
			break;
		case RDC_OP_POLYGON:
			ret = rdc_batch_polygon(r->b, c, n / 2);
			break;
		case RDC_OP_AA_LINE:
			ret = rdc_batch_aa_line(r->b, c[0], c[1], c[2], c[3]);
			break;
		default:
			ret = rdc_batch_polyline(r->b, c, n / 2);
			break;
		}
		ret = rdl_encoded(r, op, ret);
	}
	free(c);
	return ret;
}

/* X Y then `nsize` sizes: rect, fill-rect, circles, ellipses. */
static int st_shape(struct rdl *r, uint32_t op)
{
	int c[2];
	uint32_t s[2] = { 0, 0 };
	size_t nsize = r->ntok - 3;
	int ret = rdl_coords(r, 1, 2, c);

	for (size_t i = 0; !ret && i < nsize; i++)
		ret = rdl_size(r, 3 + i, &s[i]);
	if (ret)
		return ret;
	switch (op) {
	case RDC_OP_RECT:
		ret = rdc_batch_rect(r->b, c[0], c[1], s[0], s[1]);
		break;
	case RDC_OP_FILL_RECT:
		ret = rdc_batch_fill_rect(r->b, c[0], c[1], s[0], s[1]);
		break;
	case RDC_OP_CIRCLE:
		ret = rdc_batch_circle(r->b, c[0], c[1], s[0]);
		break;
	case RDC_OP_FILL_CIRCLE:
		ret = rdc_batch_fill_circle(r->b, c[0], c[1], s[0]);
		break;
	case RDC_OP_ELLIPSE:
		ret = rdc_batch_ellipse(r->b, c[0], c[1], s[0], s[1]);
		break;
	case RDC_OP_AA_CIRCLE:
		ret = rdc_batch_aa_circle(r->b, c[0], c[1], s[0]);
		break;
	case RDC_OP_AA_ELLIPSE:
		ret = rdc_batch_aa_ellipse(r->b, c[0], c[1], s[0], s[1]);
		break;
	default:
		ret = rdc_batch_fill_ellipse(r->b, c[0], c[1], s[0], s[1]);
		break;
	}
	return rdl_encoded(r, op, ret);
}

static int st_blit(struct rdl *r, uint32_t op)
{
	int c[4];
	uint32_t w, h;
	int ret = rdl_coords(r, 1, 4, c);

	if (!ret)
		ret = rdl_size(r, 5, &w);
	if (!ret)
		ret = rdl_size(r, 6, &h);
	if (ret)
		return ret;
	return rdl_encoded(r, op,
			   rdc_batch_blit(r->b, c[0], c[1], c[2], c[3], w, h));
}

/* Store pixel x of a packed row in format fmt (leftmost in the MSBs). */
static void rdl_put_pixel(uint8_t *row, uint32_t fmt, uint32_t x, uint32_t v)
{
	unsigned int bpp = rdc_format_bpp(fmt);

	rdc_px_put(row, bpp, (uint64_t)x * bpp, v);
}

/*
 * The `gradient` pattern.  Indexed: a ramp of indices across the width.
 * RGB: red grows to the right, green downwards, blue is half on.
 */
static uint32_t rdl_gradient(uint32_t fmt, uint32_t x, uint32_t y, uint32_t w,
			     uint32_t h)
{
	uint32_t red, grn;

	if (rdc_format_indexed(fmt))
		return (uint32_t)(((uint64_t)x << rdc_format_bpp(fmt)) / w);
	red = x * 255 / RDC_MAX(w - 1, 1u);
	grn = y * 255 / RDC_MAX(h - 1, 1u);
	return rdl_rgb_to_pixel(red << 16 | grn << 8 | 0x80, fmt);
}

/* Generated host-blit contents, in the destination format. */
static int rdl_pattern(struct rdl *r, size_t i, uint32_t fmt, uint32_t w,
		       uint32_t h, uint8_t *pix, size_t pitch)
{
	const char *name = i < r->ntok ? r->tok[i].s : "";
	uint32_t bpp = rdc_format_bpp(fmt);
	uint32_t maxv = bpp >= 32 ? 0xffffffu : (1u << bpp) - 1;
	int ret;

	if (!strcmp(name, "checker")) {
		uint32_t cell, c0, c1;

		ret = rdl_size(r, i + 1, &cell);
		if (!ret)
			ret = rdl_colour(r, i + 2, fmt, &c0);
		if (!ret)
			ret = rdl_colour(r, i + 3, fmt, &c1);
		if (ret)
			return ret;
		if (!cell)
			return rdl_err(r, RDC_E_PARSE, "checker cell size 0");
		for (uint32_t y = 0; y < h; y++)
			for (uint32_t x = 0; x < w; x++)
				rdl_put_pixel(pix + y * pitch, fmt, x,
					      ((x / cell + y / cell) & 1) ? c1 :
									    c0);
		return 0;
	}
	if (!strcmp(name, "gradient")) {
		for (uint32_t y = 0; y < h; y++)
			for (uint32_t x = 0; x < w; x++)
				rdl_put_pixel(pix + y * pitch, fmt, x,
					      rdl_gradient(fmt, x, y, w, h));
		return 0;
	}
	if (!strcmp(name, "noise")) {
		uint32_t seed;

		ret = rdl_u32(r, i + 1, &seed);
		if (ret)
			return ret;
		/* xorshift32: the same seed gives the same picture anywhere */
		seed = seed ? seed : 1;
		for (uint32_t y = 0; y < h; y++) {
			for (uint32_t x = 0; x < w; x++) {
				seed ^= seed << 13;
				seed ^= seed >> 17;
				seed ^= seed << 5;
				rdl_put_pixel(pix + y * pitch, fmt, x,
					      seed & maxv);
			}
		}
		return 0;
	}
	return rdl_err(r, RDC_E_PARSE,
		       "unknown pattern '%.40s' (checker, gradient, noise)",
		       name);
}

static int rdl_host_blit_keep(void *b, const uint32_t *cmd, size_t n)
{
	return rdc_batch_cmd(b, RDC_CMD_OP(cmd[0]), 0, cmd + 1, n - 1);
}

static int st_host_blit(struct rdl *r, uint32_t op)
{
	uint32_t fmt = rdl_dst_format(r), w, h;
	size_t pitch;
	uint8_t *pix;
	int c[2];
	int ret = rdl_coords(r, 1, 2, c);

	if (!ret)
		ret = rdl_size(r, 3, &w);
	if (!ret)
		ret = rdl_size(r, 4, &h);
	if (ret)
		return ret;
	if (fmt >= RDC_FMT_COUNT)
		return rdl_err(r, RDC_E_PARSE, "destination format unknown");
	if (!w || !h)
		return rdl_err(r, RDC_E_PARSE, "empty host-blit");
	pitch = rdc_format_row_bytes(fmt, w);
	if ((uint64_t)pitch * h > RDL_MAX_BLIT_BYTES)
		return rdl_err(r, RDC_E_PARSE, "host-blit too large");
	pix = calloc((size_t)h, pitch);
	if (!pix)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	if (rdl_word(r, 5, "pattern")) {
		ret = rdl_pattern(r, 6, fmt, w, h, pix, pitch);
	} else if (rdl_word(r, 5, "data")) {
		if (r->ntok - 6 != (uint64_t)w * h)
			ret = rdl_err(
				r, RDC_E_PARSE,
				"host-blit data: %zu values for %u pixels",
				r->ntok - 6, w * h);
		for (uint32_t k = 0; !ret && k < w * h; k++) {
			uint32_t v;

			ret = rdl_colour(r, 6 + k, fmt, &v);
			if (!ret)
				rdl_put_pixel(pix + (k / w) * pitch, fmt, k % w,
					      v);
		}
	} else {
		ret = rdl_err(r, RDC_E_PARSE,
			      "host-blit X Y W H then 'pattern NAME ...' or "
			      "'data PIXELS...'");
	}
	if (!ret && r->list_on) {
		/* the same commands as rdc_host_blit, kept in the list */
		ret = rdc_host_blit_encode(fmt, c[0], c[1], w, h, pix, pitch,
					   rdl_host_blit_keep, r->b);
		ret = rdl_encoded(r, op, ret);
	} else if (!ret) {
		uint64_t busy0, busy1;
		uint32_t cmds0, cmds1;

		ret = rdl_counters(r, &busy0, &cmds0);
		if (!ret) {
			ret = rdc_host_blit(r->dev, c[0], c[1], w, h, pix,
					    pitch);
			if (!ret)
				ret = rdc_idle_wait(r->dev);
			if (ret)
				ret = rdl_fail(r, "host-blit", ret);
		}
		if (!ret)
			ret = rdl_counters(r, &busy1, &cmds1);
		if (!ret)
			rdl_account(r, op, busy0, cmds0, busy1, cmds1);
	}
	free(pix);
	return ret;
}

/*
 * READBACK without the fence rdc_readback adds, so the statement's cycles
 * are the READBACK's alone: pop RDATA until the DP is idle and it is
 * empty.
 */
static int st_readback(struct rdl *r, uint32_t op)
{
	const uint32_t idle = RDC_STATUS_IDLE_MASK | RDC_STATUS_FIFO_EMPTY;
	struct rdc_wait wt = {
		.term = {
			{RDC_WAIT_TEST_GE, RDC_REG_RDATA_COUNT, ~0u, 1},
			{RDC_WAIT_TEST_EQ, RDC_REG_STATUS, idle,
			 RDC_STATUS_FIFO_EMPTY},
		},
		.needs_dp = true,
	};
	uint32_t crc = 0, words = 0, w, h, expect = 0, cmds0, cmds1;
	uint64_t busy0, busy1;
	int c[2];
	int ret = rdl_coords(r, 1, 2, c);

	if (!ret)
		ret = rdl_size(r, 3, &w);
	if (!ret)
		ret = rdl_size(r, 4, &h);
	if (!ret && r->ntok == 6)
		ret = rdl_u32(r, 5, &expect);
	if (!ret)
		ret = rdl_counters(r, &busy0, &cmds0);
	if (ret)
		return ret;
	crc = (uint32_t)crc32(0L, Z_NULL, 0);
	ret = rdc_submit(r->dev,
			 (const uint32_t[]){ RDC_CMD(RDC_OP_READBACK, 0, 2),
					     RDC_XY(c[0], c[1]), RDC_WH(w, h) },
			 3);
	for (;;) {
		uint32_t count = 0, status = 0;

		if (!ret)
			ret = r->dev->be->wait(r->dev, &wt);
		if (!ret)
			ret = rdc_reg_read(r->dev, RDC_REG_RDATA_COUNT, &count);
		for (; !ret && count; count--) {
			uint32_t v;
			uint8_t b[4];

			ret = rdc_reg_read(r->dev, RDC_REG_RDATA, &v);
			rdc_st32(b, v);
			crc = (uint32_t)crc32(crc, b, sizeof(b));
			words++;
		}
		if (!ret)
			ret = rdc_reg_read(r->dev, RDC_REG_STATUS, &status);
		if (!ret)
			ret = rdc_reg_read(r->dev, RDC_REG_RDATA_COUNT, &count);
		if (ret || ((status & idle) == RDC_STATUS_FIFO_EMPTY && !count))
			break;
	}
	if (!ret)
		ret = rdc_check_error(r->dev);
	if (ret)
		return rdl_fail(r, "readback", ret);
	ret = rdl_counters(r, &busy1, &cmds1);
	if (ret)
		return ret;
	rdl_account(r, op, busy0, cmds0, busy1, cmds1);
	r->res->readbacks++;
	r->res->readback_words = words;
	r->res->readback_crc = crc;
	if (r->ntok == 6 && crc != expect)
		return rdl_err(r, RDC_E_DEVICE,
			       "readback crc32 %08x, expected %08x", crc,
			       expect);
	return 0;
}

static int st_mono(struct rdl *r, uint32_t op)
{
	uint32_t w, h;
	size_t first = 5, need, have = 0;
	bool transparent = false;
	uint8_t *bits;
	int c[2];
	int ret = rdl_coords(r, 1, 2, c);

	if (!ret)
		ret = rdl_size(r, 3, &w);
	if (!ret)
		ret = rdl_size(r, 4, &h);
	if (ret)
		return ret;
	if (rdl_word(r, 5, "transparent")) {
		transparent = true;
		first++;
	}
	need = (size_t)(w + 7) / 8 * h;
	if (2 + ((size_t)(w + 7) / 8 + 3) / 4 * h > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE,
			       "mono bitmap too large for one command");
	bits = calloc(need + 1, 1);
	if (!bits)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	for (size_t i = first; i < r->ntok && !ret; i++) {
		const char *s = r->tok[i].s;

		if (r->tok[i].len % 2 || r->tok[i].quoted)
			ret = rdl_err(r, RDC_E_PARSE,
				      "mono: '%.40s' is not whole hex bytes",
				      s);
		for (; !ret && *s; s += 2) {
			int hi = rdl_hex(s[0]), lo = rdl_hex(s[1]);

			if (hi < 0 || lo < 0)
				ret = rdl_err(r, RDC_E_PARSE,
					      "mono: bad hex digit");
			else if (have >= need)
				ret = rdl_err(r, RDC_E_PARSE,
					      "mono: more than %zu bytes",
					      need);
			else
				bits[have++] = (uint8_t)(hi << 4 | lo);
		}
	}
	if (!ret && have != need)
		ret = rdl_err(r, RDC_E_PARSE,
			      "mono: %zu bytes given, %zu needed (H rows of "
			      "ceil(W/8))",
			      have, need);
	if (!ret)
		ret = rdl_encoded(r, op,
				  rdc_batch_mono(r->b, c[0], c[1], w, h, bits,
						 transparent));
	free(bits);
	return ret;
}

static int st_text(struct rdl *r, uint32_t op)
{
	bool transparent = rdl_word(r, 4, "transparent");
	int c[2];
	int ret = rdl_coords(r, 1, 2, c);

	if (ret)
		return ret;
	if (!r->tok[3].quoted)
		return rdl_err(r, RDC_E_PARSE, "text needs a \"string\"");
	if (r->ntok == 5 && !transparent)
		return rdl_err(r, RDC_E_PARSE, "text: '%.40s' after the string",
			       r->tok[4].s);
	if (2 + (r->tok[3].len + 3) / 4 > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "text too long for one command");
	return rdl_encoded(r, op,
			   rdc_batch_text(r->b, c[0], c[1], r->tok[3].s,
					  r->tok[3].len, transparent));
}

/* `raw WORD...`: words straight into the FIFO, headers included. */
static int st_raw(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 1;
	uint32_t *w = malloc((n + 1) * sizeof(*w));
	uint64_t busy0, busy1;
	uint32_t cmds0, cmds1;
	int ret = 0;

	(void)op;
	if (!w)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	for (size_t i = 0; i < n && !ret; i++)
		ret = rdl_u32(r, i + 1, &w[i]);
	if (!ret)
		ret = rdl_counters(r, &busy0, &cmds0);
	if (!ret) {
		ret = rdc_submit(r->dev, w, n);
		if (!ret)
			ret = rdc_idle_wait(r->dev);
		if (ret)
			ret = rdl_fail(r, "raw", ret);
	}
	if (!ret)
		ret = rdl_counters(r, &busy1, &cmds1);
	if (!ret)
		rdl_account(r, RDC_CMD_OP(w[0]), busy0, cmds0, busy1, cmds1);
	free(w);
	return ret;
}

/* `cmd OPCODE [ARG...]`: any opcode with its argument count. */
static int st_cmd(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 2;
	uint32_t *a = malloc((n + 1) * sizeof(*a));
	uint32_t code;
	int ret;

	(void)op;
	if (!a)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_u32(r, 1, &code);
	if (!ret && code > 0xff)
		ret = rdl_err(r, RDC_E_PARSE, "opcode above 0xff");
	for (size_t i = 0; i < n && !ret; i++)
		ret = rdl_u32(r, i + 2, &a[i]);
	if (!ret)
		ret = rdl_encoded(r, code, rdc_batch_cmd(r->b, code, 0, a, n));
	free(a);
	return ret;
}

/* ---- Host-side statements ----------------------------------------------- */

static int st_mode(struct rdl *r, uint32_t op)
{
	uint32_t fmt = RDC_FMT_XRGB8888, base = 0, preset;
	uint64_t busy0, busy1;
	uint32_t cmds0, cmds1;
	int p = rdc_preset_by_name(r->tok[1].s);
	int ret = 0;

	if (p < 0) {
		ret = rdl_u32(r, 1, &preset);
		if (ret)
			return rdl_err(r, RDC_E_PARSE, "unknown mode '%.40s'",
				       r->tok[1].s);
	} else {
		preset = (uint32_t)p;
	}
	if (r->ntok > 2)
		ret = rdl_format(r, 2, &fmt);
	if (!ret && r->ntok > 3)
		ret = rdl_u32(r, 3, &base);
	if (!ret)
		ret = rdl_counters(r, &busy0, &cmds0);
	if (ret)
		return ret;
	ret = rdc_mode_set(r->dev, preset, fmt, base);
	if (!ret)
		ret = rdc_idle_wait(r->dev);
	if (ret)
		return rdl_fail(r, "mode", ret);
	ret = rdl_counters(r, &busy1, &cmds1);
	if (!ret)
		rdl_account(r, op, busy0, cmds0, busy1, cmds1);
	return ret;
}

static int st_reg(struct rdl *r, uint32_t op)
{
	uint32_t reg, val;
	int ret = rdl_reg(r, 1, &reg);

	(void)op;
	if (!ret)
		ret = rdl_u32(r, 2, &val);
	if (ret)
		return ret;
	ret = rdc_reg_write(r->dev, reg, val);
	return ret ? rdl_fail(r, "reg", ret) : 0;
}

static int st_expect(struct rdl *r, uint32_t op)
{
	uint32_t reg, val, have;
	int ret = rdl_reg(r, 1, &reg);

	(void)op;
	if (!ret)
		ret = rdl_u32(r, 2, &val);
	if (ret)
		return ret;
	ret = rdc_reg_read(r->dev, reg, &have);
	if (ret)
		return rdl_fail(r, "expect", ret);
	if (have != val)
		return rdl_err(r, RDC_E_DEVICE,
			       "expect %s: read 0x%08x, expected 0x%08x",
			       r->tok[1].s, have, val);
	return 0;
}

static int st_palette(struct rdl *r, uint32_t op)
{
	uint32_t first, rgb;
	int ret = rdl_u32(r, 1, &first);

	(void)op;
	if (ret)
		return ret;
	if (first >= RDC_CLUT_ENTRIES)
		return rdl_err(r, RDC_E_PARSE, "palette index above 255");
	ret = rdc_reg_write(r->dev, RDC_REG_CLUT_INDEX, first);
	for (size_t i = 2; i < r->ntok && !ret; i++) {
		ret = rdl_rgb(r, i, &rgb);
		if (ret)
			return ret;
		ret = rdc_reg_write(r->dev, RDC_REG_CLUT_DATA, rgb);
	}
	return ret ? rdl_fail(r, "palette", ret) : 0;
}

static int st_step(struct rdl *r, uint32_t op)
{
	int64_t v;
	int ret = rdl_int(r, 1, 0, (int64_t)RDL_MAX_STEP, &v);

	(void)op;
	if (ret)
		return ret;
	ret = rdc_sim_step(r->dev, (uint64_t)v);
	return ret ? rdl_fail(r, "step", ret) : 0;
}

static int st_run_until(struct rdl *r, uint32_t op)
{
	uint64_t now;
	int64_t v;
	int ret = rdl_int(r, 1, 0, INT64_MAX >> 24, &v);

	(void)op;
	if (ret)
		return ret;
	ret = rdc_sim_time(r->dev, &now);
	if (!ret && (uint64_t)v > now && (uint64_t)v - now > RDL_MAX_STEP)
		return rdl_err(r, RDC_E_PARSE,
			       "run-until: more than %llu cycles ahead",
			       (unsigned long long)RDL_MAX_STEP);
	if (!ret)
		ret = rdc_sim_run_until(r->dev, (uint64_t)v);
	return ret ? rdl_fail(r, "run-until", ret) : 0;
}

static int st_wait_frame(struct rdl *r, uint32_t op)
{
	int ret = rdc_frame_wait(r->dev);

	(void)op;
	return ret ? rdl_fail(r, "wait-frame", ret) : 0;
}

static int st_vsync(struct rdl *r, uint32_t op)
{
	int ret = rdc_vblank_wait(r->dev);

	(void)op;
	if (ret)
		return rdl_fail(r, "vsync", ret);
	r->res->frame_ready = 1;
	return 0;
}

static int st_finish(struct rdl *r, uint32_t op)
{
	int ret = rdc_finish(r->dev);

	(void)op;
	return ret ? rdl_fail(r, "finish", ret) : 0;
}

static int st_reset(struct rdl *r, uint32_t op)
{
	int ret = rdc_reset(r->dev);

	(void)op;
	return ret ? rdl_fail(r, "reset", ret) : 0;
}

static int st_screenshot(struct rdl *r, uint32_t op)
{
	uint32_t *pix, w, h;
	int ret;

	(void)op;
	ret = rdc_frame_wait(r->dev);
	if (!ret)
		ret = rdc_frame_alloc(r->dev, &pix, &w, &h);
	if (ret)
		return rdl_fail(r, "screenshot", ret);
	ret = rdc_png_write(r->tok[1].s, pix, w, h, w);
	free(pix);
	if (ret)
		return rdl_err(r, ret, "screenshot: cannot write '%.80s': %s",
			       r->tok[1].s, rdc_strerror(ret));
	return 0;
}

/* ---- Pens, dashes, arcs, curves, transforms ------------------------------ */

/* pen WIDTH [butt|round|square] [miter|round|bevel] */
static int st_pen(struct rdl *r, uint32_t op)
{
	static const char *const caps[] = { "butt", "round", "square" };
	static const char *const joins[] = { "miter", "round", "bevel" };
	uint32_t cap = RDC_CAP_BUTT, join = RDC_JOIN_MITER, k;
	int64_t w;
	int ret = rdl_int(r, 1, 0, UINT8_MAX, &w);

	if (ret)
		return ret;
	if (r->ntok > 2) {
		for (k = 0; k < 3 && !rdl_word(r, 2, caps[k]); k++)
			;
		if (k == 3)
			return rdl_err(r, RDC_E_PARSE, "unknown cap '%.40s'",
				       r->tok[2].s);
		cap = k;
	}
	if (r->ntok > 3) {
		for (k = 0; k < 3 && !rdl_word(r, 3, joins[k]); k++)
			;
		if (k == 3)
			return rdl_err(r, RDC_E_PARSE, "unknown join '%.40s'",
				       r->tok[3].s);
		join = k;
	}
	return rdl_encoded(r, op, rdc_batch_pen(r->b, (uint32_t)w, cap, join));
}

/* dash PATTERN LENGTH [OFFSET] | dash off */
static int st_dash(struct rdl *r, uint32_t op)
{
	uint32_t bits;
	int64_t len, off = 0;
	int ret;

	if (rdl_word(r, 1, "off")) {
		if (r->ntok != 2)
			return rdl_err(r, RDC_E_PARSE,
				       "dash off: no arguments");
		return rdl_encoded(r, op, rdc_batch_dash(r->b, 0, 0, 0));
	}
	if (r->ntok < 3)
		return rdl_err(r, RDC_E_PARSE, "dash PATTERN LENGTH [OFFSET]");
	ret = rdl_u32(r, 1, &bits);
	if (!ret)
		ret = rdl_int(r, 2, 0, RDC_DASH_MAX_LEN, &len);
	if (!ret && r->ntok > 3)
		ret = rdl_int(r, 3, 0,
			      FIELD_GET(RDC_DASH_OFFSET, RDC_DASH_OFFSET),
			      &off);
	if (ret)
		return ret;
	return rdl_encoded(r, op,
			   rdc_batch_dash(r->b, bits, (uint32_t)len,
					  (uint32_t)off));
}

/* arc CX CY RX RY START END [pie|chord] */
static int st_arc(struct rdl *r, uint32_t op)
{
	int c[2];
	uint32_t rx, ry, a0, a1, mode = RDC_ARC_OUTLINE;
	int ret = rdl_coords(r, 1, 2, c);

	if (!ret)
		ret = rdl_size(r, 3, &rx);
	if (!ret)
		ret = rdl_size(r, 4, &ry);
	if (!ret)
		ret = rdl_angle(r, 5, &a0);
	if (!ret)
		ret = rdl_angle(r, 6, &a1);
	if (ret)
		return ret;
	if (r->ntok > 7) {
		if (rdl_word(r, 7, "pie"))
			mode = RDC_ARC_PIE;
		else if (rdl_word(r, 7, "chord"))
			mode = RDC_ARC_CHORD;
		else
			return rdl_err(r, RDC_E_PARSE,
				       "arc mode '%.40s': pie or chord",
				       r->tok[7].s);
	}
	return rdl_encoded(
		r, op, rdc_batch_arc(r->b, c[0], c[1], rx, ry, a0, a1, mode));
}

/* bezier|hermite X0 Y0 ... [steps N]; bspline takes 4 or more points */
static int st_curve(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 1;
	int64_t steps = 0;
	int *c;
	int ret;

	if (n >= 2 && rdl_word(r, r->ntok - 2, "steps")) {
		ret = rdl_int(r, r->ntok - 1, 1, RDC_CURVE_MAX_STEPS, &steps);
		if (ret)
			return ret;
		n -= 2;
	}
	if (n % 2 || n < 8 || (op != RDC_OP_BSPLINE && n != 8))
		return rdl_err(r, RDC_E_PARSE, "%s needs %s X Y pairs",
			       rdc_op_name(op),
			       op == RDC_OP_BSPLINE ? "4 or more" : "4");
	if (n / 2 > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "more than %d points",
			       RDC_CMD_MAX_ARGS);
	c = malloc(n * sizeof(*c));
	if (!c)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_coords(r, 1, n, c);
	if (!ret) {
		if (op == RDC_OP_BEZIER)
			ret = rdc_batch_bezier(r->b, c, (uint32_t)steps);
		else if (op == RDC_OP_HERMITE)
			ret = rdc_batch_hermite(r->b, c, (uint32_t)steps);
		else
			ret = rdc_batch_bspline(r->b, c, n / 2,
						(uint32_t)steps);
		ret = rdl_encoded(r, op, ret);
	}
	free(c);
	return ret;
}

/* transform M00 M01 M02 M10 M11 M12 M20 M21 M22 | transform identity */
static int st_transform(struct rdl *r, uint32_t op)
{
	int32_t m[9];
	int64_t v;

	if (rdl_word(r, 1, "identity") && r->ntok == 2)
		return rdl_encoded(r, op, rdc_batch_transform(r->b, NULL));
	if (r->ntok != 10)
		return rdl_err(r, RDC_E_PARSE,
			       "transform: 9 numbers or 'identity'");
	for (size_t i = 0; i < 9; i++) {
		int ret = rdl_fixed(r, 1 + i, RDL_FIX_ONE, INT32_MIN, INT32_MAX,
				    &v);

		if (ret)
			return ret;
		m[i] = (int32_t)v;
	}
	return rdl_encoded(r, op, rdc_batch_transform(r->b, m));
}

/* viewport WX0 WY0 WX1 WY1 X0 Y0 X1 Y1 */
static int st_viewport(struct rdl *r, uint32_t op)
{
	int64_t w[4];
	int c[4], ret = 0;

	for (size_t i = 0; !ret && i < 4; i++)
		ret = rdl_fixed(r, 1 + i, RDL_FIX_ONE, INT32_MIN, INT32_MAX,
				&w[i]);
	if (!ret)
		ret = rdl_coords(r, 5, 4, c);
	if (ret)
		return ret;
	return rdl_encoded(r, op,
			   rdc_batch_viewport(r->b, (int32_t)w[0],
					      (int32_t)w[1], (int32_t)w[2],
					      (int32_t)w[3], c[0], c[1], c[2],
					      c[3]));
}

/* fill-polygon [nonzero] X0 Y0 X1 Y1 X2 Y2 ... */
static int st_fill_polygon(struct rdl *r, uint32_t op)
{
	size_t first = rdl_word(r, 1, "nonzero") ? 2 : 1;
	size_t n = r->ntok - first;
	int *c;
	int ret;

	if (n % 2 || n < 6)
		return rdl_err(r, RDC_E_PARSE,
			       "fill-polygon needs 3 or more X Y pairs");
	if (n / 2 > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "more than %d points",
			       RDC_CMD_MAX_ARGS);
	c = malloc(n * sizeof(*c));
	if (!c)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_coords(r, first, n, c);
	if (!ret)
		ret = rdl_encoded(r, op,
				  rdc_batch_fill_polygon(r->b, c, n / 2,
							 first == 2));
	free(c);
	return ret;
}

/* flood X Y [8] [boundary COLOUR] */
static int st_flood(struct rdl *r, uint32_t op)
{
	uint32_t flags = 0, boundary = 0;
	size_t i = 3;
	int xy[2];
	int ret = rdl_coords(r, 1, 2, xy);

	if (ret)
		return ret;
	if (i < r->ntok && rdl_word(r, i, "8")) {
		flags |= RDC_FLOOD_8;
		i++;
	}
	if (i < r->ntok && rdl_word(r, i, "boundary")) {
		flags |= RDC_FLOOD_BOUNDARY;
		ret = rdl_colour(r, i + 1, rdl_dst_format(r), &boundary);
		if (ret)
			return ret;
		i += 2;
	}
	if (i != r->ntok)
		return rdl_err(r, RDC_E_PARSE,
			       "flood X Y [8] [boundary COLOUR]");
	return rdl_encoded(
		r, op, rdc_batch_flood(r->b, xy[0], xy[1], flags, boundary));
}

/* pattern none | mono HEX16 [transparent] | color C0 ... C63 */
static int st_pattern(struct rdl *r, uint32_t op)
{
	uint32_t px[64];
	uint8_t rows[8] = { 0 };
	const char *h;
	size_t k;

	if (rdl_word(r, 1, "none") && r->ntok == 2)
		return rdl_encoded(r, op, rdc_batch_pattern_none(r->b));
	if (rdl_word(r, 1, "mono") && (r->ntok == 3 || r->ntok == 4)) {
		if (r->ntok == 4 && !rdl_word(r, 3, "transparent"))
			return rdl_err(r, RDC_E_PARSE,
				       "pattern mono HEX16 [transparent]");
		h = r->tok[2].s;
		if (h[0] == '0' && (h[1] == 'x' || h[1] == 'X'))
			h += 2;
		for (k = 0; k < 16; k++) {
			int d = rdl_hex(h[k]);

			if (d < 0)
				break;
			rows[k / 2] = (uint8_t)(rows[k / 2] << 4 | d);
		}
		if (k != 16 || h[16])
			return rdl_err(r, RDC_E_PARSE,
				       "pattern mono: 16 hex digits, row 0 "
				       "first");
		return rdl_encoded(r, op,
				   rdc_batch_pattern_mono(r->b, rows,
							  r->ntok == 4));
	}
	if (rdl_word(r, 1, "color") && r->ntok == 2 + 64) {
		for (k = 0; k < 64; k++) {
			int ret =
				rdl_colour(r, 2 + k, rdl_dst_format(r), &px[k]);

			if (ret)
				return ret;
		}
		return rdl_encoded(r, op, rdc_batch_pattern_color(r->b, px));
	}
	return rdl_err(r, RDC_E_PARSE,
		       "pattern none | mono HEX16 [transparent] | "
		       "color C0 ... C63");
}

/* triangle [gouraud] X Y COLOUR Z  X Y COLOUR Z  X Y COLOUR Z */
static int st_triangle(struct rdl *r, uint32_t op)
{
	size_t first = rdl_word(r, 1, "gouraud") ? 2 : 1;
	uint32_t colour[3], z[3];
	int xy[6];

	if (r->ntok - first != 12)
		return rdl_err(r, RDC_E_PARSE,
			       "triangle [gouraud] then X Y COLOUR Z three "
			       "times");
	for (size_t v = 0; v < 3; v++) {
		size_t i = first + 4 * v;
		int64_t zv;
		int ret = rdl_coords(r, i, 2, &xy[2 * v]);

		if (!ret)
			ret = rdl_colour(r, i + 2, rdl_dst_format(r),
					 &colour[v]);
		if (!ret)
			ret = rdl_int(r, i + 3, 0, UINT16_MAX, &zv);
		if (ret)
			return ret;
		z[v] = (uint32_t)zv;
	}
	return rdl_encoded(r, op,
			   rdc_batch_triangle(r->b, xy, colour, z, first == 2));
}

/* zbuf BASE STRIDE [test] [write] | zbuf off */
static int st_zbuf(struct rdl *r, uint32_t op)
{
	uint32_t base, stride, flags = 0;
	int ret;

	if (rdl_word(r, 1, "off")) {
		if (r->ntok != 2)
			return rdl_err(r, RDC_E_PARSE,
				       "zbuf off: no arguments");
		return rdl_encoded(r, op, rdc_batch_zbuf_off(r->b));
	}
	if (r->ntok < 3)
		return rdl_err(r, RDC_E_PARSE,
			       "zbuf BASE STRIDE [test] [write] | zbuf off");
	ret = rdl_u32(r, 1, &base);
	if (!ret)
		ret = rdl_u32(r, 2, &stride);
	if (ret)
		return ret;
	for (size_t i = 3; i < r->ntok; i++) {
		if (rdl_word(r, i, "test"))
			flags |= RDC_Z_TEST;
		else if (rdl_word(r, i, "write"))
			flags |= RDC_Z_WRITE;
		else
			return rdl_err(r, RDC_E_PARSE,
				       "zbuf: '%.40s' is not test or write",
				       r->tok[i].s);
	}
	return rdl_encoded(r, op, rdc_batch_zbuf(r->b, base, stride, flags));
}

/* clear-z VALUE */
static int st_clear_z(struct rdl *r, uint32_t op)
{
	int64_t v;
	int ret = rdl_int(r, 1, 0, UINT16_MAX, &v);

	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_clear_z(r->b, (uint32_t)v));
}

/* colorkey COLOUR | colorkey off */
static int st_colorkey(struct rdl *r, uint32_t op)
{
	uint32_t key;
	int ret;

	if (rdl_word(r, 1, "off"))
		return rdl_encoded(r, op, rdc_batch_colorkey(r->b, 0, 0));
	ret = rdl_colour(r, 1, rdl_dst_format(r), &key);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_colorkey(r->b, key, 1));
}

/* list ADDR: the statements up to `end` go to VRAM at ADDR */
static int st_list(struct rdl *r, uint32_t op)
{
	uint32_t addr;
	int ret;

	(void)op;
	if (r->list_on)
		return rdl_err(r, RDC_E_PARSE,
			       "list inside the list begun on line %u",
			       r->list_line);
	ret = rdl_u32(r, 1, &addr);
	if (ret)
		return ret;
	if (addr % sizeof(uint32_t))
		return rdl_err(r, RDC_E_PARSE,
			       "list: address 0x%x is not 4-aligned", addr);
	r->list_on = true;
	r->list_addr = addr;
	r->list_line = r->line;
	r->list_n = 0;
	return 0;
}

static int st_end(struct rdl *r, uint32_t op)
{
	int ret;

	(void)op;
	if (!r->list_on)
		return rdl_err(r, RDC_E_PARSE, "end without list");
	r->list_on = false;
	if (!r->list_n)
		return 0;
	ret = rdc_vram_write(r->dev, r->list_addr, r->list_w,
			     r->list_n * sizeof(*r->list_w));
	if (ret)
		return rdl_fail(r, "list", ret);
	return 0;
}

#define RDL_ANY 0x7fffffffu
static const struct rdl_stmt {
	const char *name;
	rdl_fn fn;
	uint32_t op;	   /* command class the statement's cycles go to */
	uint32_t min, max; /* argument count */
} rdl_stmts[] = {
	/* device commands */
	{ "nop", st_nop, RDC_OP_NOP, 0, 1 },
	{ "fence", st_words, RDC_OP_FENCE, 1, 1 },
	{ "wait-vblank", st_words, RDC_OP_WAIT_VBLANK, 0, 0 },
	{ "wait-line", st_words, RDC_OP_WAIT_LINE, 1, 1 },
	{ "cmd-reg", st_cmd_reg, RDC_OP_REG_WRITE, 2, 2 },
	{ "load-clut", st_load_clut, RDC_OP_LOAD_CLUT, 2, RDL_ANY },
	{ "call", st_words, RDC_OP_CALL, 1, 1 },
	{ "ret", st_words, RDC_OP_RET, 0, 0 },
	{ "jump", st_words, RDC_OP_JUMP, 1, 1 },
	{ "fg", st_colour, RDC_OP_SET_FG, 1, 1 },
	{ "bg", st_colour, RDC_OP_SET_BG, 1, 1 },
	{ "rop", st_rop, RDC_OP_SET_ROP, 1, 1 },
	{ "clip", st_clip, RDC_OP_SET_CLIP, 1, 4 },
	{ "dst", st_surface, RDC_OP_SET_DST, 1, 5 },
	{ "src", st_surface, RDC_OP_SET_SRC, 1, 5 },
	{ "pixel", st_points, RDC_OP_PIXEL, 2, 2 },
	{ "line", st_points, RDC_OP_LINE, 4, 4 },
	{ "polyline", st_points, RDC_OP_POLYLINE, 4, RDL_ANY },
	{ "rect", st_shape, RDC_OP_RECT, 4, 4 },
	{ "fill-rect", st_shape, RDC_OP_FILL_RECT, 4, 4 },
	{ "fill", st_shape, RDC_OP_FILL_RECT, 4, 4 },
	{ "circle", st_shape, RDC_OP_CIRCLE, 3, 3 },
	{ "fill-circle", st_shape, RDC_OP_FILL_CIRCLE, 3, 3 },
	{ "ellipse", st_shape, RDC_OP_ELLIPSE, 4, 4 },
	{ "fill-ellipse", st_shape, RDC_OP_FILL_ELLIPSE, 4, 4 },
	{ "pen", st_pen, RDC_OP_SET_PEN, 1, 3 },
	{ "dash", st_dash, RDC_OP_SET_DASH, 1, 3 },
	{ "polygon", st_points, RDC_OP_POLYGON, 4, RDL_ANY },
	{ "arc", st_arc, RDC_OP_ARC, 6, 7 },
	{ "bezier", st_curve, RDC_OP_BEZIER, 8, 10 },
	{ "hermite", st_curve, RDC_OP_HERMITE, 8, 10 },
	{ "bspline", st_curve, RDC_OP_BSPLINE, 8, RDL_ANY },
	{ "transform", st_transform, RDC_OP_SET_TRANSFORM, 1, 9 },
	{ "viewport", st_viewport, RDC_OP_SET_VIEWPORT, 8, 8 },
	{ "fill-polygon", st_fill_polygon, RDC_OP_FILL_POLYGON, 6, RDL_ANY },
	{ "flood", st_flood, RDC_OP_FLOOD_FILL, 2, 5 },
	{ "pattern", st_pattern, RDC_OP_SET_PATTERN, 1, 65 },
	{ "triangle", st_triangle, RDC_OP_TRIANGLE, 12, 13 },
	{ "zbuf", st_zbuf, RDC_OP_SET_ZBUF, 1, 4 },
	{ "clear-z", st_clear_z, RDC_OP_CLEAR_Z, 1, 1 },
	{ "aa-line", st_points, RDC_OP_AA_LINE, 4, 4 },
	{ "aa-circle", st_shape, RDC_OP_AA_CIRCLE, 3, 3 },
	{ "aa-ellipse", st_shape, RDC_OP_AA_ELLIPSE, 4, 4 },
	{ "aa-ramp", st_words, RDC_OP_SET_AA_RAMP, 1, 1 },
	{ "alpha", st_words, RDC_OP_SET_ALPHA, 1, 1 },
	{ "colorkey", st_colorkey, RDC_OP_SET_COLORKEY, 1, 1 },
	{ "blit", st_blit, RDC_OP_BLIT, 6, 6 },
	{ "host-blit", st_host_blit, RDC_OP_HOST_BLIT, 6, RDL_ANY },
	{ "readback", st_readback, RDC_OP_READBACK, 4, 5 },
	{ "mono", st_mono, RDC_OP_MONO, 4, RDL_ANY },
	{ "text", st_text, RDC_OP_TEXT, 3, 4 },
	{ "cmd", st_cmd, RDC_OP_NOP, 1, RDC_CMD_MAX_ARGS + 1 },
	{ "raw", st_raw, RDC_OP_NOP, 1, RDL_ANY },
	{ "decode", rdl_st_decode, RDC_OP_DECODE, 3, 4 },
	{ "histogram", rdl_st_histogram, RDC_OP_HISTOGRAM, 5, 7 },
	{ "map-build", rdl_st_map_build, RDC_OP_MAP_BUILD, 3, 4 },
	{ "map-apply", rdl_st_map_apply, RDC_OP_MAP_APPLY, 5, 5 },
	{ "map-clut", st_words, RDC_OP_MAP_CLUT, 1, 1 },
	{ "convolve", rdl_st_convolve, RDC_OP_CONVOLVE, 7, 19 },
	{ "threshold", rdl_st_threshold, RDC_OP_THRESHOLD, 5, 6 },
	{ "matrix", rdl_st_matrix, RDC_OP_MATRIX_LOAD, 1, 12 },
	{ "matrix-mult", rdl_st_matrix, RDC_OP_MATRIX_MULT, 12, 12 },
	{ "translate", rdl_st_vec3, RDC_OP_TRANSLATE, 3, 3 },
	{ "scale", rdl_st_vec3, RDC_OP_SCALE, 1, 3 },
	{ "rotate", rdl_st_rotate, RDC_OP_ROTATE, 2, 2 },
	{ "push", st_words, RDC_OP_PUSH_MATRIX, 0, 0 },
	{ "pop", st_words, RDC_OP_POP_MATRIX, 0, 0 },
	{ "view", rdl_st_view, RDC_OP_SET_VIEW, 26, 26 },
	{ "viewport3", rdl_st_viewport3, RDC_OP_SET_VIEWPORT3, 4, 4 },
	{ "light", rdl_st_light, RDC_OP_SET_LIGHT, 2, 5 },
	{ "ambient", rdl_st_ambient, RDC_OP_SET_AMBIENT, 1, 1 },
	{ "material", rdl_st_material, RDC_OP_SET_MATERIAL, 4, 4 },
	{ "mesh", rdl_st_mesh, RDC_OP_MESH, 4, 11 },
	{ "patch", rdl_st_patch, RDC_OP_PATCH, 49, 55 },
	{ "bezier3", rdl_st_bezier3, RDC_OP_BEZIER3, 12, 14 },
	{ "bspline3", rdl_st_bspline3, RDC_OP_BSPLINE3, 12, RDL_ANY },
	/* host side (refused inside `list`, as are readback and raw) */
	{ "list", st_list, 0, 1, 1 },
	{ "end", st_end, 0, 0, 0 },
	{ "mode", st_mode, RDC_OP_SET_DST, 1, 3 },
	{ "reg", st_reg, 0, 2, 2 },
	{ "expect", st_expect, 0, 2, 2 },
	{ "palette", st_palette, 0, 2, RDC_CLUT_ENTRIES + 1 },
	{ "step", st_step, 0, 1, 1 },
	{ "run-until", st_run_until, 0, 1, 1 },
	{ "wait-frame", st_wait_frame, 0, 0, 0 },
	{ "vsync", st_vsync, 0, 0, 0 },
	{ "finish", st_finish, 0, 0, 0 },
	{ "reset", st_reset, 0, 0, 0 },
	{ "screenshot", st_screenshot, 0, 1, 1 },
	{ "vram-load", rdl_st_vram_load, 0, 2, 2 },
	{ "encode", rdl_st_encode, 0, 6, 7 },
	{ "histogram-plot", rdl_st_histogram_plot, RDC_OP_FILL_RECT, 5, 5 },
	{ "vertices", rdl_st_vertices, 0, 1, RDL_ANY },
	{ "indices", rdl_st_indices, 0, 1, RDL_ANY },
	{ "spin", rdl_st_spin, 0, 1, 1 },
	{ "raster", rdl_st_raster, 0, 1, 1 },
	{ "raster-wait", rdl_st_raster_wait, 0, 1, 2 },
	{ "raster-reg", rdl_st_raster_reg, 0, 2, 2 },
	{ "raster-clut", rdl_st_raster_clut, 0, 2, RDC_CLUT_ENTRIES + 1 },
	{ "raster-end", rdl_st_raster_end, 0, 0, 0 },
};

const char *rdl_stmt_info(size_t i, uint32_t *min, uint32_t *max)
{
	if (i >= RDC_ARRAY_SIZE(rdl_stmts))
		return NULL;
	*min = rdl_stmts[i].min;
	*max = rdl_stmts[i].max == RDL_ANY ? UINT32_MAX : rdl_stmts[i].max;
	return rdl_stmts[i].name;
}

static int rdl_arg_count(struct rdl *r, const struct rdl_stmt *st,
			 uint32_t nargs)
{
	const char *pl = nargs == 1 ? "" : "s";

	if (st->min == st->max)
		return rdl_err(r, RDC_E_PARSE, "%s: %u argument%s (takes %u)",
			       st->name, nargs, pl, st->min);
	if (st->max == RDL_ANY)
		return rdl_err(r, RDC_E_PARSE,
			       "%s: %u argument%s (takes at least %u)",
			       st->name, nargs, pl, st->min);
	return rdl_err(r, RDC_E_PARSE, "%s: %u argument%s (takes %u to %u)",
		       st->name, nargs, pl, st->min, st->max);
}

/* Statements that act on the host at once cannot be kept in a list. */
static bool rdl_list_refused(const struct rdl_stmt *st)
{
	size_t i;

	if (st->fn == st_end || st->fn == st_list)
		return false;
	if (st->fn == st_readback || st->fn == st_raw)
		return true;
	for (i = 0; i < RDC_ARRAY_SIZE(rdl_stmts); i++)
		if (rdl_stmts[i].fn == st_list)
			break;
	return st >= rdl_stmts + i;
}

static int rdl_statement(struct rdl *r)
{
	const struct rdl_tok *kw = &r->tok[0];
	uint32_t nargs = (uint32_t)RDC_MIN(r->ntok - 1, (size_t)RDL_ANY - 1);

	if (kw->quoted)
		return rdl_err(r, RDC_E_PARSE,
			       "statement starts with a string");
	for (size_t i = 0; i < RDC_ARRAY_SIZE(rdl_stmts); i++) {
		const struct rdl_stmt *st = &rdl_stmts[i];

		if (strcmp(kw->s, st->name))
			continue;
		if (nargs < st->min || nargs > st->max)
			return rdl_arg_count(r, st, nargs);
		if (r->list_on && rdl_list_refused(st))
			return rdl_err(r, RDC_E_PARSE,
				       "%s: not allowed inside list (line %u)",
				       st->name, r->list_line);
		rdc_batch_reset(r->b);
		r->res->frame_ready = 0;
		r->dev->src_line = r->line;
		return st->fn(r, st->op);
	}
	return rdl_err(r, RDC_E_PARSE, "unknown statement '%.40s'", kw->s);
}

/* Copy the next logical line (joining "\\\n" continuations) into r->buf. */
static int rdl_next_line(struct rdl *r, const char **pos, const char *end,
			 uint32_t *phys)
{
	size_t n = 0;
	const char *p = *pos;

	r->line = *phys + 1;
	r->src = p;
	r->src_end = end;
	while (p < end) {
		const char *nl = memchr(p, '\n', (size_t)(end - p));
		size_t len = nl ? (size_t)(nl - p) : (size_t)(end - p);
		bool cont;

		(*phys)++;
		if (memchr(p, '\0', len))
			return rdl_err(r, RDC_E_PARSE, "NUL byte in line");
		if (len && p[len - 1] == '\r')
			len--; /* CRLF files */
		cont = len && p[len - 1] == '\\';
		if (cont)
			len--;
		if (n + len + 2 > RDL_MAX_LINE)
			return rdl_err(r, RDC_E_PARSE, "line too long");
		if (n + len + 2 > r->buf_cap) {
			size_t cap = RDC_MAX(r->buf_cap * 2, n + len + 2);
			char *b = realloc(r->buf, cap);

			if (!b)
				return rdl_err(r, RDC_E_NOMEM, "out of memory");
			r->buf = b;
			r->buf_cap = cap;
		}
		memcpy(r->buf + n, p, len);
		n += len;
		r->buf[n++] = ' ';
		p = nl ? nl + 1 : end;
		if (!cont)
			break;
	}
	*pos = p;
	r->buf[n] = 0; /* the loop ran at least once: buf exists */
	return 0;
}

static int script_run(rdc_dev *dev, const char *text, size_t len,
		      struct rdc_script_result *res)
{
	struct rdc_script_result local;
	struct rdl r = { .dev = dev };
	const char *pos = text, *end;
	uint32_t phys = 0;
	int ret = 0;

	if (!res)
		res = &local;
	memset(res, 0, sizeof(*res));
	r.res = res;
	if (!dev || (!text && len))
		return RDC_E_INVAL;
	if (!len)
		return 0;
	end = text + len;
	r.b = rdc_batch_new();
	if (!r.b)
		return rdl_err(&r, RDC_E_NOMEM, "out of memory");
	while (!ret && pos < end) {
		ret = rdl_next_line(&r, &pos, end, &phys);
		if (!ret)
			ret = rdl_tokenize(&r);
		if (!ret && r.ntok)
			ret = rdl_statement(&r);
	}
	if (!ret && r.list_on) {
		r.line = r.list_line;
		ret = rdl_err(&r, RDC_E_PARSE, "list without end");
	}
	free(r.list_w);
	rdc_batch_free(r.b);
	free(r.tok);
	free(r.buf);
	return ret;
}

int rdc_script_frame_wait(rdc_dev *dev, const struct rdc_script_result *res)
{
	if (!dev || !res)
		return RDC_E_INVAL;
	return res->frame_ready ? 0 : rdc_frame_wait(dev);
}

static int script_run_file(rdc_dev *dev, const char *path,
			   struct rdc_script_result *res)
{
	struct rdc_script_result local;
	char *text = NULL;
	size_t len = 0, cap = 0;
	FILE *f;
	int ret;

	if (!res)
		res = &local;
	memset(res, 0, sizeof(*res));
	if (!dev || !path)
		return RDC_E_INVAL;
	f = fopen(path, "rb");
	if (!f) {
		snprintf(res->error_msg, sizeof(res->error_msg),
			 "cannot open '%.100s': %s", path, strerror(errno));
		return RDC_E_FILE;
	}
	for (;;) {
		size_t got;

		if (len == cap) {
			char *t;

			if (cap >= RDL_MAX_FILE) {
				ret = RDC_E_FILE;
				snprintf(res->error_msg, sizeof(res->error_msg),
					 "'%.100s' is larger than %u bytes",
					 path, RDL_MAX_FILE);
				goto out;
			}
			cap = cap ? cap * 2 : 65536;
			t = realloc(text, cap);
			if (!t) {
				ret = RDC_E_NOMEM;
				goto out;
			}
			text = t;
		}
		got = fread(text + len, 1, cap - len, f);
		len += got;
		if (got == 0)
			break;
	}
	if (ferror(f)) {
		ret = RDC_E_FILE;
		snprintf(res->error_msg, sizeof(res->error_msg),
			 "cannot read '%.100s'", path);
		goto out;
	}
	ret = script_run(dev, text, len, res);
out:
	fclose(f);
	free(text);
	return ret;
}

/* The caller's result may be of another release (rdc.h): filled in full
 * here, then handed over. */
int rdc_script_run_sized(rdc_dev *dev, const char *text, size_t len,
			 struct rdc_script_result *res)
{
	struct rdc_script_result full;
	int ret = script_run(dev, text, len, &full);

	if (res)
		rdc_struct_out(res, &full, sizeof(full));
	return ret;
}

int rdc_script_run_file_sized(rdc_dev *dev, const char *path,
			      struct rdc_script_result *res)
{
	struct rdc_script_result full;
	int ret = script_run_file(dev, path, &full);

	if (res)
		rdc_struct_out(res, &full, sizeof(full));
	return ret;
}
