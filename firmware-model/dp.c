// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The display processor's command decoder and drawing state.
 *
 * A command is fetched whole (header, then its argument words, from the
 * source the header came from) before it runs, so a command never sees a
 * half-written argument list; the source running dry mid-command parks the
 * decoder in RDC_DP_FETCH.  Only WAIT_VBLANK/WAIT_LINE (waiting for the
 * beam) and READBACK (waiting for RDATA space) suspend after they start.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"
#include "rdc_dp_host.h"
#include "../hw-sim/bus.h"

/* dp->src of a command fetched from a display list in VRAM */
#define DP_SRC_LIST 2u

/*
 * DST and SRC start as the chip's power-on screen: the 640x480 preset in
 * XRGB8888 at VRAM 0, unpadded.
 */
static void dp_reset_surface(struct rdc_surface *s)
{
	struct rdc_timing tm = { 0 };

	rdc_preset_timing(RDC_PRESET_640x480_60, &tm);
	s->base = 0;
	s->format = RDC_FMT_XRGB8888;
	s->width = tm.h_display;
	s->height = tm.v_display;
	s->stride = rdc_format_row_bytes(s->format, s->width);
}

static void dp_reset_state(struct rdc_dp *dp)
{
	struct rdc_dp_state *st = &dp->st;

	st->fg = 0xffffffffu;
	st->bg = 0;
	st->rop = RDC_ROP_COPY;
	st->clip.x0 = RDC_COORD_MIN;
	st->clip.y0 = RDC_COORD_MIN;
	st->clip.x1 = RDC_COORD_MAX + 1;
	st->clip.y1 = RDC_COORD_MAX + 1;
	dp_reset_surface(&st->dst);
	st->src = st->dst;
	st->alpha = RDC_ALPHA_OPAQUE;
	st->colorkey = 0;
	st->colorkey_on = 0;
	st->aa_ramp = RDC_AA_RAMP_RESET;
	dp_xform_reset(st);
	dp_pen_reset(st);
	st->pat_mode = RDC_PAT_NONE;
	st->z_base = 0;
	st->z_stride = 0;
	st->z_flags = 0;
	dp_3d_reset(dp);
}

static void dp_reset(void *opaque)
{
	struct rdc_dp *dp = opaque;

	dp_reset_state(dp);
	dp->phase = RDC_DP_IDLE;
	dp->list_depth = 0;
	dp->list_pc = 0;
	dp->meshes_culled = 0;
	dp->cmd_len = 0;
	dp->cmd_have = 0;
	dp->rb_pos = 0;
	dp->rb_len = 0;
	dp->hw->dp_status = 0;
	dp->hw->dp_resume = 0;
}

static bool coord_ok(int32_t v)
{
	return v >= RDC_COORD_MIN && v <= RDC_COORD_MAX;
}

static bool xy_ok(uint32_t w)
{
	return coord_ok(RDC_X(w)) && coord_ok(RDC_Y(w));
}

static bool wh_ok(uint32_t w)
{
	return RDC_W(w) <= RDC_SIZE_MAX && RDC_H(w) <= RDC_SIZE_MAX;
}

/*
 * The command is over: account for it and return to idle.  Inline: every
 * command that runs ends here.
 */
static rdc_always_inline void cmd_done(struct rdc_dp *dp)
{
	struct rdc_hw *hw = dp->hw;
	uint64_t cycles = hw->now - dp->cmd_start;

	hw->perf.cmds++;
	hw->perf.last_cycles = (uint32_t)RDC_MIN(cycles, (uint64_t)0xffffffffu);
	hw->perf.last_opcode = RDC_CMD_OP(dp->cmd[0]);
	hw->perf.busy += cycles;
	if (dp->phase != RDC_DP_HALTED)
		dp->phase = RDC_DP_IDLE;
}

/*
 * Reject the command: record the error, then skip it or halt.  An error
 * inside a display list abandons every list: the next command comes from
 * the FIFO or the ring.
 */
static void cmd_fail_info(struct rdc_dp *dp, uint32_t code, uint32_t info)
{
	struct rdc_hw *hw = dp->hw;

	rdc_port_error(hw, code, info);
	dp->list_depth = 0;
	if (hw->control & RDC_CONTROL_HALT_ON_ERR) {
		dp->phase = RDC_DP_HALTED;
		hw->dp_resume = 0;
	}
	cmd_done(dp);
}

static void cmd_fail(struct rdc_dp *dp, uint32_t code)
{
	cmd_fail_info(dp, code, dp->cmd[0]);
}

/* Does a SET_DST/SET_SRC argument list describe a surface inside VRAM? */
static bool surface_parse(const struct rdc_hw *hw, const uint32_t *a,
			  struct rdc_surface *s)
{
	uint32_t fmt = a[3], w = RDC_W(a[2]), h = RDC_H(a[2]), row;

	if (fmt >= RDC_FMT_COUNT || w < 1 || h < 1 || w > RDC_SIZE_MAX ||
	    h > RDC_SIZE_MAX)
		return false;
	row = rdc_format_row_bytes(fmt, w);
	if (a[1] < row)
		return false;
	if ((uint64_t)a[0] + (uint64_t)(h - 1) * a[1] + row > hw->vram_size)
		return false;
	s->base = a[0];
	s->stride = a[1];
	s->width = w;
	s->height = h;
	s->format = fmt;
	return true;
}

/* The bits of a colour the destination's pixel holds. */
static uint32_t dp_colour_mask(const struct rdc_dp *dp)
{
	unsigned int bpp = rdc_format_bpp(dp->st.dst.format);

	return bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
}

/* Run a command that may wait: WAIT_* or READBACK.  true when complete. */
static bool readback_step(struct rdc_dp *dp)
{
	struct rdc_hw *hw = dp->hw;
	const uint32_t *a = dp->cmd + 1;
	uint32_t w = RDC_W(a[1]), h = RDC_H(a[1]);

	for (;;) {
		uint32_t pushed;

		if (dp->rb_pos == dp->rb_len) {
			uint32_t n;

			if (dp->rb_row >= h || !dp->rb_words_per_row)
				return true;
			n = RDC_MIN(RDC_DP_RB_CHUNK,
				    dp->rb_words_per_row - dp->rb_word);
			rdc_dp_readback_pack(dp, RDC_X(a[0]), RDC_Y(a[0]), w,
					     dp->rb_row, dp->rb_word, n,
					     dp->rb_buf);
			dp->rb_pos = 0;
			dp->rb_len = n;
			dp->rb_word += n;
			if (dp->rb_word == dp->rb_words_per_row) {
				dp->rb_word = 0;
				dp->rb_row++;
			}
		}
		if (!rdc_port_rdata_space(hw))
			return false;
		pushed = rdc_port_rdata_push(hw, dp->rb_buf + dp->rb_pos,
					     dp->rb_len - dp->rb_pos);
		if (!pushed)
			return false;
		dp->rb_pos += pushed;
	}
}

/*
 * Check and draw a primitive; the colours in dp->st are already masked.
 * Returns RDC_ERR_NONE or the error; nothing is drawn on error.
 */
static uint32_t exec_draw(struct rdc_dp *dp, uint32_t op, uint32_t fl,
			  uint32_t len, const uint32_t *a)
{
	bool tr = fl & RDC_MONO_TRANSPARENT;
	int32_t x = RDC_X(a[0]), y = RDC_Y(a[0]);
	uint32_t w, h, fmt;

	switch (op) {
	/*
	 * The geometric primitives go through the transform unit: vertices
	 * and anchors (RECT's corner, the centres) are mapped by dp_xform,
	 * sizes and radii scaled by |m00| and |m11| (dp_xform_size).  A
	 * result out of range fails the command with RDC_ERR_RANGE.
	 */
	case RDC_OP_PIXEL:
		if (!dp_xform(dp, &x, &y))
			return RDC_ERR_RANGE;
		rdc_dp_pixel(dp, x, y);
		return RDC_ERR_NONE;
	case RDC_OP_LINE:
	case RDC_OP_POLYLINE:
	case RDC_OP_POLYGON:
		/*
		 * Polyline segments after the first leave out their first
		 * pixel (the previous segment's last); a closed polyline
		 * also leaves out its closing pixel, so XOR outlines stay
		 * whole.  The stroker keeps that rule.
		 */
		return dp_cmd_stroke(dp, op, len, a);
	case RDC_OP_RECT:
	case RDC_OP_FILL_RECT:
		w = RDC_W(a[1]);
		h = RDC_H(a[1]);
		if (!dp_xform(dp, &x, &y) || !dp_xform_size(dp, &w, &h))
			return RDC_ERR_RANGE;
		if (op == RDC_OP_RECT && !dp_pen_plain(dp))
			dp_stroke_rect(dp, x, y, w, h);
		else
			rdc_dp_rect(dp, x, y, w, h, op == RDC_OP_FILL_RECT);
		return RDC_ERR_NONE;
	case RDC_OP_CIRCLE:
	case RDC_OP_FILL_CIRCLE:
		w = a[1];
		h = a[1];
		if (a[1] > RDC_SIZE_MAX || !dp_xform(dp, &x, &y) ||
		    !dp_xform_size(dp, &w, &h))
			return RDC_ERR_RANGE;
		/* unequal scales turn the circle into an ellipse */
		if (w == h)
			rdc_dp_circle(dp, x, y, w, op == RDC_OP_FILL_CIRCLE);
		else
			rdc_dp_ellipse(dp, x, y, w, h,
				       op == RDC_OP_FILL_CIRCLE);
		return RDC_ERR_NONE;
	case RDC_OP_ELLIPSE:
	case RDC_OP_FILL_ELLIPSE:
		w = RDC_W(a[1]);
		h = RDC_H(a[1]);
		if (!wh_ok(a[1]) || !dp_xform(dp, &x, &y) ||
		    !dp_xform_size(dp, &w, &h))
			return RDC_ERR_RANGE;
		rdc_dp_ellipse(dp, x, y, w, h, op == RDC_OP_FILL_ELLIPSE);
		return RDC_ERR_NONE;
	case RDC_OP_ARC:
		return dp_cmd_arc(dp, fl, a);
	case RDC_OP_FILL_POLYGON:
		return dp_cmd_fill_polygon(dp, fl, len, a);
	case RDC_OP_FLOOD_FILL:
		return dp_cmd_flood(dp, fl, len, a);
	case RDC_OP_TRIANGLE:
		return dp_cmd_triangle(dp, fl, a);
	case RDC_OP_BEZIER:
	case RDC_OP_HERMITE:
	case RDC_OP_BSPLINE:
		return dp_cmd_curve(dp, op, fl, len, a);
	case RDC_OP_BLIT:
		if (!xy_ok(a[0]) || !xy_ok(a[1]) || !wh_ok(a[2]))
			return RDC_ERR_RANGE;
		if (rdc_format_bpp(dp->st.src.format) !=
		    rdc_format_bpp(dp->st.dst.format))
			return RDC_ERR_ARG;
		rdc_dp_blit(dp, RDC_X(a[0]), RDC_Y(a[0]), RDC_X(a[1]),
			    RDC_Y(a[1]), RDC_W(a[2]), RDC_H(a[2]));
		return RDC_ERR_NONE;
	case RDC_OP_HOST_BLIT:
	case RDC_OP_MONO:
		if (len < 2)
			return RDC_ERR_LENGTH;
		if (!xy_ok(a[0]) || !wh_ok(a[1]))
			return RDC_ERR_RANGE;
		fmt = op == RDC_OP_MONO ? RDC_FMT_I1 : dp->st.dst.format;
		/* the rows, after MONO's colours (cmd_exec's), exactly */
		w = rdc_cmd_data_at(op, fl);
		if (len !=
		    w + (uint64_t)RDC_H(a[1]) *
				    rdc_dp_words_per_row(fmt, RDC_W(a[1])))
			return RDC_ERR_LENGTH;
		if (op == RDC_OP_MONO)
			rdc_dp_mono(dp, RDC_X(a[0]), RDC_Y(a[0]), RDC_W(a[1]),
				    RDC_H(a[1]), a + w, tr);
		else
			rdc_dp_host_blit(dp, RDC_X(a[0]), RDC_Y(a[0]),
					 RDC_W(a[1]), RDC_H(a[1]), a + w);
		return RDC_ERR_NONE;
	case RDC_OP_TEXT:
		if (len < 2)
			return RDC_ERR_LENGTH;
		if (!xy_ok(a[0]))
			return RDC_ERR_RANGE;
		if (len != 2 + ((uint64_t)a[1] + 3) / 4)
			return RDC_ERR_LENGTH;
		rdc_dp_text(dp, RDC_X(a[0]), RDC_Y(a[0]), a[1], a + 2, tr);
		return RDC_ERR_NONE;
	case RDC_OP_AA_LINE:
	case RDC_OP_AA_CIRCLE:
	case RDC_OP_AA_ELLIPSE:
		return rdc_dp_aa_cmd(dp, op, a);
	case RDC_OP_DECODE:
	case RDC_OP_HISTOGRAM:
	case RDC_OP_MAP_BUILD:
	case RDC_OP_MAP_APPLY:
	case RDC_OP_MAP_CLUT:
	case RDC_OP_CONVOLVE:
	case RDC_OP_THRESHOLD:
		return dp_cmd_image(dp, op, fl, len, a);
	case RDC_OP_MATRIX_LOAD:
	case RDC_OP_MATRIX_MULT:
	case RDC_OP_TRANSLATE:
	case RDC_OP_SCALE:
	case RDC_OP_ROTATE:
	case RDC_OP_PUSH_MATRIX:
	case RDC_OP_POP_MATRIX:
	case RDC_OP_SET_VIEW:
	case RDC_OP_SET_VIEWPORT3:
	case RDC_OP_SET_LIGHT:
	case RDC_OP_SET_AMBIENT:
	case RDC_OP_SET_MATERIAL:
	case RDC_OP_MESH:
	case RDC_OP_PATCH:
	case RDC_OP_BEZIER3:
	case RDC_OP_BSPLINE3:
		return dp_cmd_3d(dp, op, fl, len, a);
	case RDC_OP_READBACK:
		if (!xy_ok(a[0]) || !wh_ok(a[1]))
			return RDC_ERR_RANGE;
		dp->rb_row = 0;
		dp->rb_word = 0;
		dp->rb_pos = 0;
		dp->rb_len = 0;
		dp->rb_words_per_row =
			RDC_H(a[1]) ? rdc_dp_words_per_row(dp->st.src.format,
							   RDC_W(a[1])) :
				      0;
		if (!readback_step(dp))
			dp->phase = RDC_DP_READBACK;
		return RDC_ERR_NONE;
	default:
		return RDC_ERR_OPCODE;
	}
}

/*
 * Display lists.  list_depth counts the lists entered; list_ret[d - 1]
 * holds the address to resume the list at depth d when the list it called
 * returns (the outermost list returns to the FIFO or ring, which need no
 * address).
 */
static bool list_addr_ok(const struct rdc_dp *dp, uint32_t addr)
{
	return addr % sizeof(uint32_t) == 0 &&
	       (uint64_t)addr + sizeof(uint32_t) <= dp->hw->vram_size;
}

/* CALL, and JUMP: from the FIFO or ring a JUMP enters a list as CALL does. */
static uint32_t list_enter(struct rdc_dp *dp, uint32_t op, uint32_t addr)
{
	if (!list_addr_ok(dp, addr))
		return RDC_ERR_RANGE;
	if (op == RDC_OP_JUMP && dp->list_depth) {
		dp->list_pc = addr;
		return RDC_ERR_NONE;
	}
	if (dp->list_depth >= RDC_CALL_DEPTH)
		return RDC_ERR_STACK;
	if (dp->list_depth)
		dp->list_ret[dp->list_depth - 1] = dp->list_pc;
	dp->list_depth++;
	dp->list_pc = addr;
	return RDC_ERR_NONE;
}

static uint32_t list_return(struct rdc_dp *dp)
{
	if (!dp->list_depth)
		return RDC_ERR_STACK;
	dp->list_depth--;
	if (dp->list_depth)
		dp->list_pc = dp->list_ret[dp->list_depth - 1];
	return RDC_ERR_NONE;
}

/*
 * Fetch the next command of the current list from VRAM: the header as one
 * 4-byte read, then its argument words as one read span, both charged by
 * the bus model.  A list word outside VRAM (the list ran off its end, or
 * a RET returned into a bad address) is RDC_ERR_RANGE with ERR_INFO = that
 * word's address, and the lists are abandoned.
 */
static void list_begin(struct rdc_dp *dp)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t pc = dp->list_pc, len, i;
	const uint8_t *p;

	dp->cmd_start = hw->now;
	dp->src = DP_SRC_LIST;
	dp->cmd[0] = RDC_CMD(RDC_OP_NOP, 0, 0);
	p = list_addr_ok(dp, pc) ?
		    rdc_port_span(hw, pc, sizeof(uint32_t), RDC_BUS_READ) :
		    NULL;
	if (!p) {
		rdc_port_compute(hw, RDC_T_DECODE);
		cmd_fail_info(dp, RDC_ERR_RANGE, pc);
		return;
	}
	dp->cmd[0] = rdc_ld32(p);
	pc += sizeof(uint32_t);
	dp->list_pc = pc;
	len = RDC_CMD_LEN(dp->cmd[0]);
	if (len > RDC_CMD_MAX_ARGS) {
		/* as from the FIFO: only the header is consumed */
		rdc_port_compute(hw, RDC_T_DECODE);
		cmd_fail(dp, RDC_ERR_LENGTH);
		return;
	}
	if (len) {
		p = (uint64_t)pc + (uint64_t)len * sizeof(uint32_t) <=
				    hw->vram_size ?
			    rdc_port_span(hw, pc, len * sizeof(uint32_t),
					  RDC_BUS_READ) :
			    NULL;
		if (!p) {
			rdc_port_compute(hw, RDC_T_DECODE);
			cmd_fail_info(dp, RDC_ERR_RANGE, pc);
			return;
		}
		for (i = 0; i < len; i++)
			dp->cmd[1 + i] = rdc_ld32(p + i * sizeof(uint32_t));
		dp->list_pc = pc + len * (uint32_t)sizeof(uint32_t);
	}
	dp->cmd_len = 1 + len;
	dp->cmd_have = dp->cmd_len;
	dp->phase = RDC_DP_FETCH;
}

/*
 * Execute the fetched command in dp->cmd.  Returns RDC_ERR_NONE, or the
 * error to report.  Commands that suspend set dp->phase and return
 * RDC_ERR_NONE; the caller then leaves them in progress.
 */
static uint32_t cmd_exec(struct rdc_dp *dp)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t hdr = dp->cmd[0], op = RDC_CMD_OP(hdr);
	uint32_t len = RDC_CMD_LEN(hdr), fl = RDC_CMD_FL(hdr), i, err, save_fg,
		 save_bg, m;
	const uint32_t *a = dp->cmd + 1;
	int fixed = rdc_cmd_args(op);
	struct rdc_surface s;
	uint64_t t;

	/*
	 * Colours carried in the command: written as the SET_FG (and
	 * SET_BG) before it would write them, whatever becomes of it.
	 */
	if ((fl & RDC_DRAW_FG) && rdc_cmd_takes_fg(op)) {
		if (!len)
			return RDC_ERR_LENGTH;
		dp->st.fg = *a++;
		len--;
		fl &= ~RDC_DRAW_FG;
	} else if (op == RDC_OP_MONO && (fl & RDC_MONO_COLORS) &&
		   len >= rdc_cmd_data_at(op, fl)) {
		dp->st.fg = a[2];
		dp->st.bg = a[3];
	}
	if (fixed >= 0 && len != (uint32_t)fixed)
		return RDC_ERR_LENGTH;

	switch (op) {
	case RDC_OP_NOP:
		return RDC_ERR_NONE;
	case RDC_OP_FENCE:
		rdc_port_fence(hw, a[0]);
		return RDC_ERR_NONE;
	case RDC_OP_WAIT_VBLANK:
	case RDC_OP_WAIT_LINE:
		t = op == RDC_OP_WAIT_VBLANK ? rdc_port_next_vblank(hw) :
					       rdc_port_next_line(hw, a[0]);
		if (t != RDC_NEVER && t > hw->now) {
			dp->wait_time = t;
			dp->phase = RDC_DP_WAIT;
		}
		return RDC_ERR_NONE;
	case RDC_OP_REG_WRITE:
		return rdc_port_reg_write(hw, a[0], a[1]) ? RDC_ERR_REG :
							    RDC_ERR_NONE;
	case RDC_OP_LOAD_CLUT:
		if (len < 2 || len > RDC_CLUT_ENTRIES + 1)
			return RDC_ERR_LENGTH;
		if ((uint64_t)a[0] + (len - 1) > RDC_CLUT_ENTRIES)
			return RDC_ERR_RANGE;
		for (i = 1; i < len; i++)
			rdc_port_clut_write(hw, a[0] + i - 1, a[i]);
		return RDC_ERR_NONE;

	case RDC_OP_SET_FG:
		dp->st.fg = a[0];
		return RDC_ERR_NONE;
	case RDC_OP_SET_BG:
		dp->st.bg = a[0];
		return RDC_ERR_NONE;
	case RDC_OP_SET_ROP:
		if (a[0] >= RDC_ROP_COUNT)
			return RDC_ERR_ARG;
		dp->st.rop = a[0];
		return RDC_ERR_NONE;
	case RDC_OP_SET_CLIP:
		/* x1/y1 are exclusive, so they may reach RDC_COORD_MAX + 1. */
		if (RDC_X(a[0]) < RDC_COORD_MIN ||
		    RDC_Y(a[0]) < RDC_COORD_MIN ||
		    RDC_X(a[1]) > RDC_COORD_MAX + 1 ||
		    RDC_Y(a[1]) > RDC_COORD_MAX + 1 ||
		    RDC_X(a[0]) > RDC_X(a[1]) || RDC_Y(a[0]) > RDC_Y(a[1]))
			return RDC_ERR_RANGE;
		dp->st.clip.x0 = RDC_X(a[0]);
		dp->st.clip.y0 = RDC_Y(a[0]);
		dp->st.clip.x1 = RDC_X(a[1]);
		dp->st.clip.y1 = RDC_Y(a[1]);
		return RDC_ERR_NONE;
	case RDC_OP_SET_DST:
	case RDC_OP_SET_SRC:
		if (!surface_parse(hw, a, &s))
			return RDC_ERR_SURFACE;
		if (op == RDC_OP_SET_DST)
			dp->st.dst = s;
		else
			dp->st.src = s;
		return RDC_ERR_NONE;
	case RDC_OP_SET_TRANSFORM:
		return dp_cmd_set_transform(dp, len, a);
	case RDC_OP_SET_VIEWPORT:
		return dp_cmd_set_viewport(dp, len, a);
	case RDC_OP_SET_PEN:
		return dp_cmd_set_pen(dp, a[0]);
	case RDC_OP_SET_DASH:
		return dp_cmd_set_dash(dp, a[0], a[1]);
	case RDC_OP_SET_PATTERN:
		return dp_cmd_set_pattern(dp, RDC_CMD_FL(hdr), len, a);
	case RDC_OP_SET_ZBUF:
		return dp_cmd_set_zbuf(dp, RDC_CMD_FL(hdr), len, a);
	case RDC_OP_CLEAR_Z:
		return dp_cmd_clear_z(dp, a);
	case RDC_OP_SET_ALPHA:
		if (a[0] > RDC_ALPHA_OPAQUE)
			return RDC_ERR_RANGE;
		dp->st.alpha = a[0];
		return RDC_ERR_NONE;
	case RDC_OP_SET_COLORKEY:
		if (RDC_CMD_FL(hdr) & ~RDC_COLORKEY_ENABLE)
			return RDC_ERR_ARG;
		dp->st.colorkey = a[0];
		dp->st.colorkey_on = RDC_CMD_FL(hdr) & RDC_COLORKEY_ENABLE;
		return RDC_ERR_NONE;
	case RDC_OP_SET_AA_RAMP:
		if (a[0] < RDC_AA_RAMP_MIN || a[0] > RDC_AA_RAMP_MAX)
			return RDC_ERR_RANGE;
		dp->st.aa_ramp = a[0];
		return RDC_ERR_NONE;
	case RDC_OP_CALL:
	case RDC_OP_JUMP:
		return list_enter(dp, op, a[0]);
	case RDC_OP_RET:
		return list_return(dp);
	default:
		break;
	}

	/*
	 * Draw with colours masked to DST; the registers keep all bits.
	 * Drawing leaves the colours alone, so a 32-bit DST, which masks
	 * nothing, needs no copy: and the copy's read of both colours in
	 * one load, just after a command's own colour was stored alone,
	 * would wait for that store to retire.
	 */
	m = dp_colour_mask(dp);
	save_fg = save_bg = 0;
	if (m != 0xffffffffu) {
		save_fg = dp->st.fg;
		save_bg = dp->st.bg;
		dp->st.fg &= m;
		dp->st.bg &= m;
	}
	err = exec_draw(dp, op, fl, len, a);
	if (m != 0xffffffffu) {
		dp->st.fg = save_fg;
		dp->st.bg = save_bg;
	}
	return err;
}

static void dp_status_update(struct rdc_dp *dp)
{
	static const uint32_t bits[] = {
		[RDC_DP_IDLE] = 0,
		[RDC_DP_FETCH] = RDC_STATUS_DP_BUSY | RDC_STATUS_DP_WAIT,
		[RDC_DP_READBACK] = RDC_STATUS_DP_BUSY | RDC_STATUS_DP_WAIT,
		[RDC_DP_WAIT] = RDC_STATUS_DP_BUSY | RDC_STATUS_DP_WAIT,
		[RDC_DP_HALTED] = RDC_STATUS_DP_HALTED,
	};

	dp->hw->dp_status = bits[dp->phase];
	/* between the commands of a display list the DP is still busy */
	if (dp->list_depth && dp->phase == RDC_DP_IDLE)
		dp->hw->dp_status |= RDC_STATUS_DP_BUSY;
}

/* The fetched command in dp->cmd: decode it and run it. */
static void cmd_run(struct rdc_dp *dp)
{
	uint32_t err;

	rdc_port_compute(dp->hw, RDC_T_DECODE);
	dp->phase = RDC_DP_IDLE;
	err = cmd_exec(dp);
	if (err)
		cmd_fail(dp, err);
	else if (dp->phase == RDC_DP_IDLE)
		cmd_done(dp);
}

/*
 * Most commands are in the FIFO whole: one pop, not two, and no need to
 * ask first whether a source has words (the pop says).  A list runs to
 * its end before the queues are looked at.
 */
static bool cmd_pop_whole(struct rdc_dp *dp)
{
	struct rdc_hw *hw = dp->hw;
	uint64_t start;
	uint32_t got;

	if (dp->list_depth)
		return false;
	start = hw->now;
	got = rdc_port_cmd_pop_whole(hw, dp->cmd, RDC_CMD_MAX_ARGS);
	if (!got)
		return false;
	dp->cmd_start = start;
	dp->src = RDC_SRC_FIFO;
	dp->cmd_have = dp->cmd_len = got;
	return true;
}

/* Start a command from the first source with words waiting. */
static bool cmd_begin(struct rdc_dp *dp)
{
	struct rdc_hw *hw = dp->hw;
	unsigned int src;

	if (dp->list_depth) {
		list_begin(dp);
		return true;
	}
	if (rdc_port_cmd_avail(hw, RDC_SRC_FIFO))
		src = RDC_SRC_FIFO;
	else if (rdc_port_cmd_avail(hw, RDC_SRC_RING))
		src = RDC_SRC_RING;
	else
		return false;
	dp->cmd_start = hw->now;
	if (rdc_port_cmd_pop(hw, src, dp->cmd, 1) != 1)
		return false;
	dp->src = src;
	dp->cmd_have = 1;
	if (RDC_CMD_LEN(dp->cmd[0]) > RDC_CMD_MAX_ARGS) {
		/* Too long to buffer: drop the header alone. */
		rdc_port_compute(hw, RDC_T_DECODE);
		cmd_fail(dp, RDC_ERR_LENGTH);
		return true;
	}
	dp->cmd_len = 1 + RDC_CMD_LEN(dp->cmd[0]);
	dp->phase = RDC_DP_FETCH;
	return true;
}

static uint64_t dp_run(void *opaque, uint64_t until)
{
	struct rdc_dp *dp = opaque;
	struct rdc_hw *hw = dp->hw;
	uint64_t ret = RDC_NEVER;

	if (!(hw->control & RDC_CONTROL_DP_EN)) {
		dp_status_update(dp);
		return RDC_NEVER;
	}
	for (;;) {
		uint32_t got;

		switch (dp->phase) {
		case RDC_DP_HALTED:
			if (!hw->dp_resume)
				goto out;
			hw->dp_resume = 0;
			dp->phase = RDC_DP_IDLE;
			continue;
		case RDC_DP_IDLE:
			if (hw->now >= until) {
				if (dp->list_depth ||
				    rdc_port_cmd_avail(hw, RDC_SRC_FIFO) ||
				    rdc_port_cmd_avail(hw, RDC_SRC_RING))
					ret = hw->now;
				goto out;
			}
			/* whole: run now, not after another turn of the loop */
			if (cmd_pop_whole(dp))
				cmd_run(dp);
			else if (!cmd_begin(dp))
				goto out;
			continue;
		case RDC_DP_FETCH:
			/* (a list command arrives whole: nothing to pop) */
			if (dp->cmd_have < dp->cmd_len) {
				got = rdc_port_cmd_pop(
					hw, dp->src, dp->cmd + dp->cmd_have,
					dp->cmd_len - dp->cmd_have);
				dp->cmd_have += got;
			}
			if (dp->cmd_have < dp->cmd_len)
				goto out; /* the host owes us words */
			cmd_run(dp);
			continue;
		case RDC_DP_WAIT:
			if (dp->wait_time > until) {
				ret = dp->wait_time;
				goto out;
			}
			if (dp->wait_time > hw->now)
				rdc_port_idle_until(hw, dp->wait_time);
			cmd_done(dp);
			continue;
		case RDC_DP_READBACK:
			if (!readback_step(dp))
				goto out;
			cmd_done(dp);
			continue;
		}
	}
out:
	dp_status_update(dp);
	return ret;
}

static const struct rdc_dp_ops rdc_dp_ops = {
	.reset = dp_reset,
	.run = dp_run,
};

size_t rdc_dp_size(void)
{
	return sizeof(struct rdc_dp);
}

bool rdc_dp_view_get(const struct rdc_hw *hw, struct rdc_dp_view *s)
{
	const struct rdc_dp *dp = hw->dp;
	uint32_t d;

	rdc_memset(s, 0, sizeof(*s));
	if (!dp)
		return false;
	s->opcode = RDC_CMD_OP(dp->cmd[0]);
	s->rop = dp->st.rop;
	s->alpha = dp->st.alpha;
	s->colorkey = dp->st.colorkey;
	s->colorkey_on = dp->st.colorkey_on;
	s->pattern = dp->st.pat_mode;
	s->fg = dp->st.fg;
	s->bg = dp->st.bg;
	s->meshes_culled = dp->meshes_culled;
	s->depth = RDC_MIN(dp->list_depth, (uint32_t)RDC_CALL_DEPTH);
	if (s->depth) {
		s->src = RDC_DP_SRC_LIST;
		s->cmd_addr = dp->list_pc - dp->cmd_len * 4u;
		for (d = 0; d + 1 < s->depth; d++)
			s->calls[d] = dp->list_ret[d];
	} else {
		s->src = dp->src == RDC_SRC_RING ? RDC_DP_SRC_RING :
						   RDC_DP_SRC_FIFO;
	}
	return true;
}

void rdc_dp_init(struct rdc_dp *dp, struct rdc_hw *hw)
{
	rdc_memset(dp, 0, sizeof(*dp));
	dp->hw = hw;
	dp_reset(dp);
	rdc_hw_set_dp(hw, &rdc_dp_ops, dp);
}
