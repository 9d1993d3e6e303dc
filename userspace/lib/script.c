// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The .rdl script interpreter (the format is documented in docs/rdl.md).
 * rdc_script_run (at the end) reads a logical line, script_lex.c splits it
 * into tokens, and the statement's handler (by the table below) reads its
 * values, encodes its commands and hands the batch to script_run.c, which
 * runs it and charges its cycles.  This file holds the table, the loop
 * over lines and the host-side statements (mode, reg, step, screenshot,
 * list ...); the other statements are in script_cmd.c and script_draw.c
 * (the 2D commands), script_img.c, script_3d.c and script_raster.c.
 * script_names.c holds the names of opcodes, registers, ROPs and formats.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "script.h"
#include "script_3d.h"
#include "script_cmd.h"
#include "script_draw.h"
#include "script_img.h"

/* Statement handlers get the tokens after the keyword at index 1. */
typedef int (*rdl_fn)(struct rdl *r, uint32_t op);

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
	{ "nop", rdl_st_nop, RDC_OP_NOP, 0, 1 },
	{ "fence", rdl_st_words, RDC_OP_FENCE, 1, 1 },
	{ "wait-vblank", rdl_st_words, RDC_OP_WAIT_VBLANK, 0, 0 },
	{ "wait-line", rdl_st_words, RDC_OP_WAIT_LINE, 1, 1 },
	{ "cmd-reg", rdl_st_cmd_reg, RDC_OP_REG_WRITE, 2, 2 },
	{ "load-clut", rdl_st_load_clut, RDC_OP_LOAD_CLUT, 2, RDL_ANY },
	{ "call", rdl_st_words, RDC_OP_CALL, 1, 1 },
	{ "ret", rdl_st_words, RDC_OP_RET, 0, 0 },
	{ "jump", rdl_st_words, RDC_OP_JUMP, 1, 1 },
	{ "fg", rdl_st_colour, RDC_OP_SET_FG, 1, 1 },
	{ "bg", rdl_st_colour, RDC_OP_SET_BG, 1, 1 },
	{ "rop", rdl_st_rop, RDC_OP_SET_ROP, 1, 1 },
	{ "clip", rdl_st_clip, RDC_OP_SET_CLIP, 1, 4 },
	{ "dst", rdl_st_surface, RDC_OP_SET_DST, 1, 5 },
	{ "src", rdl_st_surface, RDC_OP_SET_SRC, 1, 5 },
	{ "pixel", rdl_st_points, RDC_OP_PIXEL, 2, 2 },
	{ "line", rdl_st_points, RDC_OP_LINE, 4, 4 },
	{ "polyline", rdl_st_points, RDC_OP_POLYLINE, 4, RDL_ANY },
	{ "rect", rdl_st_shape, RDC_OP_RECT, 4, 4 },
	{ "fill-rect", rdl_st_shape, RDC_OP_FILL_RECT, 4, 4 },
	{ "fill", rdl_st_shape, RDC_OP_FILL_RECT, 4, 4 },
	{ "circle", rdl_st_shape, RDC_OP_CIRCLE, 3, 3 },
	{ "fill-circle", rdl_st_shape, RDC_OP_FILL_CIRCLE, 3, 3 },
	{ "ellipse", rdl_st_shape, RDC_OP_ELLIPSE, 4, 4 },
	{ "fill-ellipse", rdl_st_shape, RDC_OP_FILL_ELLIPSE, 4, 4 },
	{ "pen", rdl_st_pen, RDC_OP_SET_PEN, 1, 3 },
	{ "dash", rdl_st_dash, RDC_OP_SET_DASH, 1, 3 },
	{ "polygon", rdl_st_points, RDC_OP_POLYGON, 4, RDL_ANY },
	{ "arc", rdl_st_arc, RDC_OP_ARC, 6, 7 },
	{ "bezier", rdl_st_curve, RDC_OP_BEZIER, 8, 10 },
	{ "hermite", rdl_st_curve, RDC_OP_HERMITE, 8, 10 },
	{ "bspline", rdl_st_curve, RDC_OP_BSPLINE, 8, RDL_ANY },
	{ "transform", rdl_st_transform, RDC_OP_SET_TRANSFORM, 1, 9 },
	{ "viewport", rdl_st_viewport, RDC_OP_SET_VIEWPORT, 8, 8 },
	{ "fill-polygon", rdl_st_fill_polygon, RDC_OP_FILL_POLYGON, 6,
	  RDL_ANY },
	{ "flood", rdl_st_flood, RDC_OP_FLOOD_FILL, 2, 5 },
	{ "pattern", rdl_st_pattern, RDC_OP_SET_PATTERN, 1, 65 },
	{ "triangle", rdl_st_triangle, RDC_OP_TRIANGLE, 12, 13 },
	{ "zbuf", rdl_st_zbuf, RDC_OP_SET_ZBUF, 1, 4 },
	{ "clear-z", rdl_st_clear_z, RDC_OP_CLEAR_Z, 1, 1 },
	{ "aa-line", rdl_st_points, RDC_OP_AA_LINE, 4, 4 },
	{ "aa-circle", rdl_st_shape, RDC_OP_AA_CIRCLE, 3, 3 },
	{ "aa-ellipse", rdl_st_shape, RDC_OP_AA_ELLIPSE, 4, 4 },
	{ "aa-ramp", rdl_st_words, RDC_OP_SET_AA_RAMP, 1, 1 },
	{ "alpha", rdl_st_words, RDC_OP_SET_ALPHA, 1, 1 },
	{ "colorkey", rdl_st_colorkey, RDC_OP_SET_COLORKEY, 1, 1 },
	{ "blit", rdl_st_blit, RDC_OP_BLIT, 6, 6 },
	{ "host-blit", rdl_st_host_blit, RDC_OP_HOST_BLIT, 6, RDL_ANY },
	{ "readback", rdl_st_readback, RDC_OP_READBACK, 4, 5 },
	{ "mono", rdl_st_mono, RDC_OP_MONO, 4, RDL_ANY },
	{ "text", rdl_st_text, RDC_OP_TEXT, 3, 4 },
	{ "cmd", rdl_st_cmd, RDC_OP_NOP, 1, RDC_CMD_MAX_ARGS + 1 },
	{ "raw", rdl_st_raw, RDC_OP_NOP, 1, RDL_ANY },
	{ "decode", rdl_st_decode, RDC_OP_DECODE, 3, 4 },
	{ "histogram", rdl_st_histogram, RDC_OP_HISTOGRAM, 5, 7 },
	{ "map-build", rdl_st_map_build, RDC_OP_MAP_BUILD, 3, 4 },
	{ "map-apply", rdl_st_map_apply, RDC_OP_MAP_APPLY, 5, 5 },
	{ "map-clut", rdl_st_words, RDC_OP_MAP_CLUT, 1, 1 },
	{ "convolve", rdl_st_convolve, RDC_OP_CONVOLVE, 7, 19 },
	{ "threshold", rdl_st_threshold, RDC_OP_THRESHOLD, 5, 6 },
	{ "matrix", rdl_st_matrix, RDC_OP_MATRIX_LOAD, 1, 12 },
	{ "matrix-mult", rdl_st_matrix, RDC_OP_MATRIX_MULT, 12, 12 },
	{ "translate", rdl_st_vec3, RDC_OP_TRANSLATE, 3, 3 },
	{ "scale", rdl_st_vec3, RDC_OP_SCALE, 1, 3 },
	{ "rotate", rdl_st_rotate, RDC_OP_ROTATE, 2, 2 },
	{ "push", rdl_st_words, RDC_OP_PUSH_MATRIX, 0, 0 },
	{ "pop", rdl_st_words, RDC_OP_POP_MATRIX, 0, 0 },
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
	{ "encode", rdl_st_encode, 0, 6, 9 },
	{ "histogram-plot", rdl_st_histogram_plot, RDC_OP_FILL_RECT, 5, 5 },
	{ "vertices", rdl_st_vertices, 0, 1, RDL_ANY },
	{ "indices", rdl_st_indices, 0, 1, RDL_ANY },
	{ "spin", rdl_st_spin, 0, 1, 1 },
	{ "raster", rdl_st_raster, 0, 1, 1 },
	{ "raster-wait", rdl_st_raster_wait, 0, 1, 2 },
	{ "raster-reg", rdl_st_raster_reg, 0, 2, 2 },
	{ "raster-clut", rdl_st_raster_clut, 0, 2, RDC_CLUT_ENTRIES + 1 },
	{ "raster-end", rdl_st_raster_end, 0, 0, 0 },
	{ "lpen", rdl_st_lpen, 0, 1, 3 },
	{ "lpen-expect", rdl_st_lpen_expect, 0, 1, 2 },
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
	if (st->fn == rdl_st_readback || st->fn == rdl_st_raw)
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
