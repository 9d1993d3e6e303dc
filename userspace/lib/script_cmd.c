// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * .rdl statements of the device's first commands: NOP, FENCE and the
 * other plain-word commands, register writes and CLUT loads from the
 * FIFO, colours and ROP, clip and surfaces, points and shapes, blits
 * (host-blit with its generated patterns), readback with its CRC, mono,
 * text, and `raw` and `cmd` for any words.  docs/rdl.md describes them.
 */
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "script.h"
#include "script_cmd.h"

int rdl_st_nop(struct rdl *r, uint32_t op)
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
int rdl_st_words(struct rdl *r, uint32_t op)
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

int rdl_st_cmd_reg(struct rdl *r, uint32_t op)
{
	uint32_t reg, val;
	int ret = rdl_reg(r, 1, &reg);

	if (!ret)
		ret = rdl_u32(r, 2, &val);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_reg_write(r->b, reg, val));
}

int rdl_st_load_clut(struct rdl *r, uint32_t op)
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

int rdl_st_colour(struct rdl *r, uint32_t op)
{
	uint32_t c;
	int ret = rdl_colour(r, 1, rdl_dst_format(r), &c);

	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, &c, 1));
}

int rdl_st_rop(struct rdl *r, uint32_t op)
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

int rdl_st_clip(struct rdl *r, uint32_t op)
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

int rdl_st_surface(struct rdl *r, uint32_t op)
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

int rdl_st_points(struct rdl *r, uint32_t op)
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
int rdl_st_shape(struct rdl *r, uint32_t op)
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

int rdl_st_blit(struct rdl *r, uint32_t op)
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

int rdl_st_host_blit(struct rdl *r, uint32_t op)
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
int rdl_st_readback(struct rdl *r, uint32_t op)
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

int rdl_st_mono(struct rdl *r, uint32_t op)
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

int rdl_st_text(struct rdl *r, uint32_t op)
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
int rdl_st_raw(struct rdl *r, uint32_t op)
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
int rdl_st_cmd(struct rdl *r, uint32_t op)
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
