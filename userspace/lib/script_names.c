// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The .rdl names of opcodes, registers, ROPs and pixel formats, and the
 * public look-ups by them.
 */
#include <string.h>
#include <strings.h>

#include "script.h"

static const char *const rdl_op_names[RDC_OP_COUNT] = {
	[RDC_OP_NOP] = "nop",
	[RDC_OP_FENCE] = "fence",
	[RDC_OP_WAIT_VBLANK] = "wait-vblank",
	[RDC_OP_WAIT_LINE] = "wait-line",
	[RDC_OP_REG_WRITE] = "cmd-reg",
	[RDC_OP_LOAD_CLUT] = "load-clut",
	[RDC_OP_CALL] = "call",
	[RDC_OP_RET] = "ret",
	[RDC_OP_JUMP] = "jump",
	[RDC_OP_SET_FG] = "fg",
	[RDC_OP_SET_BG] = "bg",
	[RDC_OP_SET_ROP] = "rop",
	[RDC_OP_SET_CLIP] = "clip",
	[RDC_OP_SET_DST] = "dst",
	[RDC_OP_SET_SRC] = "src",
	[RDC_OP_PIXEL] = "pixel",
	[RDC_OP_LINE] = "line",
	[RDC_OP_POLYLINE] = "polyline",
	[RDC_OP_RECT] = "rect",
	[RDC_OP_FILL_RECT] = "fill-rect",
	[RDC_OP_CIRCLE] = "circle",
	[RDC_OP_FILL_CIRCLE] = "fill-circle",
	[RDC_OP_ELLIPSE] = "ellipse",
	[RDC_OP_FILL_ELLIPSE] = "fill-ellipse",
	[RDC_OP_SET_PEN] = "pen",
	[RDC_OP_SET_DASH] = "dash",
	[RDC_OP_SET_TRANSFORM] = "transform",
	[RDC_OP_SET_VIEWPORT] = "viewport",
	[RDC_OP_POLYGON] = "polygon",
	[RDC_OP_ARC] = "arc",
	[RDC_OP_BEZIER] = "bezier",
	[RDC_OP_HERMITE] = "hermite",
	[RDC_OP_BSPLINE] = "bspline",
	[RDC_OP_BLIT] = "blit",
	[RDC_OP_HOST_BLIT] = "host-blit",
	[RDC_OP_READBACK] = "readback",
	[RDC_OP_MONO] = "mono",
	[RDC_OP_TEXT] = "text",
	[RDC_OP_FILL_POLYGON] = "fill-polygon",
	[RDC_OP_FLOOD_FILL] = "flood",
	[RDC_OP_SET_PATTERN] = "pattern",
	[RDC_OP_TRIANGLE] = "triangle",
	[RDC_OP_MATRIX_LOAD] = "matrix",
	[RDC_OP_MATRIX_MULT] = "matrix-mult",
	[RDC_OP_TRANSLATE] = "translate",
	[RDC_OP_SCALE] = "scale",
	[RDC_OP_ROTATE] = "rotate",
	[RDC_OP_PUSH_MATRIX] = "push",
	[RDC_OP_POP_MATRIX] = "pop",
	[RDC_OP_SET_VIEW] = "view",
	[RDC_OP_SET_VIEWPORT3] = "viewport3",
	[RDC_OP_SET_LIGHT] = "light",
	[RDC_OP_SET_AMBIENT] = "ambient",
	[RDC_OP_SET_MATERIAL] = "material",
	[RDC_OP_MESH] = "mesh",
	[RDC_OP_PATCH] = "patch",
	[RDC_OP_BEZIER3] = "bezier3",
	[RDC_OP_BSPLINE3] = "bspline3",
	[RDC_OP_DECODE] = "decode",
	[RDC_OP_HISTOGRAM] = "histogram",
	[RDC_OP_MAP_BUILD] = "map-build",
	[RDC_OP_MAP_APPLY] = "map-apply",
	[RDC_OP_MAP_CLUT] = "map-clut",
	[RDC_OP_CONVOLVE] = "convolve",
	[RDC_OP_THRESHOLD] = "threshold",
	[RDC_OP_SET_ZBUF] = "zbuf",
	[RDC_OP_CLEAR_Z] = "clear-z",
	[RDC_OP_AA_LINE] = "aa-line",
	[RDC_OP_AA_CIRCLE] = "aa-circle",
	[RDC_OP_AA_ELLIPSE] = "aa-ellipse",
	[RDC_OP_SET_AA_RAMP] = "aa-ramp",
	[RDC_OP_SET_ALPHA] = "alpha",
	[RDC_OP_SET_COLORKEY] = "colorkey",
};

const char *rdc_op_name(uint32_t op)
{
	return op < RDC_OP_COUNT ? rdl_op_names[op] : NULL;
}

/* clang-format off */
#define RDL_REG(n) { #n, RDC_REG_##n }
/* clang-format on */
static const struct {
	const char *name;
	uint32_t reg;
} rdl_regs[] = {
	RDL_REG(ID),
	RDL_REG(VERSION),
	RDL_REG(VRAM_SIZE),
	RDL_REG(CORE_KHZ),
	RDL_REG(CONTROL),
	RDL_REG(STATUS),
	RDL_REG(IRQ_STATUS),
	RDL_REG(IRQ_ENABLE),
	RDL_REG(ERR_CODE),
	RDL_REG(ERR_INFO),
	RDL_REG(PINS),
	RDL_REG(H_TOTAL),
	RDL_REG(H_DISPLAY),
	RDL_REG(H_SYNC_START),
	RDL_REG(H_SYNC_END),
	RDL_REG(V_TOTAL),
	RDL_REG(V_DISPLAY),
	RDL_REG(V_SYNC_START),
	RDL_REG(V_SYNC_END),
	RDL_REG(PIXCLK_KHZ),
	RDL_REG(CRTC_FLAGS),
	RDL_REG(FB_BASE),
	RDL_REG(FB_STRIDE),
	RDL_REG(FB_FORMAT),
	RDL_REG(LINE_COMPARE),
	RDL_REG(BEAM),
	RDL_REG(FRAME_COUNT),
	RDL_REG(MODE_PRESET),
	RDL_REG(RASTER_BASE),
	RDL_REG(RASTER_CTRL),
	RDL_REG(RASTER_STATUS),
	RDL_REG(LPEN_POS),
	RDL_REG(LPEN_CTRL),
	RDL_REG(LPEN_LATCH),
	RDL_REG(CLUT_INDEX),
	RDL_REG(CLUT_DATA),
	RDL_REG(CURSOR_BASE),
	RDL_REG(CURSOR_POS),
	RDL_REG(CURSOR_FG),
	RDL_REG(CURSOR_BG),
	RDL_REG(CURSOR_CTRL),
	RDL_REG(FIFO_DATA),
	RDL_REG(FIFO_FREE),
	RDL_REG(FIFO_LOWWATER),
	RDL_REG(RING_BASE),
	RDL_REG(RING_SIZE),
	RDL_REG(RING_HEAD),
	RDL_REG(RING_TAIL),
	RDL_REG(FENCE),
	RDL_REG(RDATA),
	RDL_REG(RDATA_COUNT),
	RDL_REG(TIME_LO),
	RDL_REG(TIME_HI),
	RDL_REG(PERF_BUSY_LO),
	RDL_REG(PERF_BUSY_HI),
	RDL_REG(PERF_STALL_LO),
	RDL_REG(PERF_STALL_HI),
	RDL_REG(PERF_PIXELS_LO),
	RDL_REG(PERF_PIXELS_HI),
	RDL_REG(PERF_CMDS),
	RDL_REG(PERF_LAST_CYCLES),
	RDL_REG(PERF_LAST_OPCODE),
	RDL_REG(PERF_CTRL),
	RDL_REG(PERF_CULLED),
};

size_t rdc_reg_count(void)
{
	return RDC_ARRAY_SIZE(rdl_regs);
}

const char *rdc_reg_info(size_t i, uint32_t *reg)
{
	if (i >= RDC_ARRAY_SIZE(rdl_regs))
		return NULL;
	if (reg)
		*reg = rdl_regs[i].reg;
	return rdl_regs[i].name;
}

/* Register by name (case-insensitive, optional "RDC_REG_" prefix). */
int rdc_reg_by_name(const char *name, uint32_t *reg)
{
	if (!strncasecmp(name, "RDC_REG_", 8))
		name += 8;
	for (size_t i = 0; i < RDC_ARRAY_SIZE(rdl_regs); i++) {
		if (!strcasecmp(name, rdl_regs[i].name)) {
			*reg = rdl_regs[i].reg;
			return 0;
		}
	}
	return RDC_E_INVAL;
}

static const char *const rdl_rop_names[RDC_ROP_COUNT] = {
	"clear",	 "and",		"and-reverse", "copy",
	"and-inverted",	 "noop",	"xor",	       "or",
	"nor",		 "equiv",	"invert",      "or-reverse",
	"copy-inverted", "or-inverted", "nand",	       "set",
};

/* "copy", "GXcopy", "and-reverse", "GXandReverse", "and_reverse" */
int rdl_rop_by_name(const char *s)
{
	char want[32], have[32];
	size_t n = 0;

	if (!strncasecmp(s, "gx", 2))
		s += 2;
	for (; *s && n + 1 < sizeof(want); s++)
		if (*s != '-' && *s != '_')
			want[n++] = (char)(*s | 0x20);
	want[n] = 0;
	for (int i = 0; i < RDC_ROP_COUNT; i++) {
		const char *p = rdl_rop_names[i];

		n = 0;
		for (; *p; p++)
			if (*p != '-')
				have[n++] = *p;
		have[n] = 0;
		if (!strcmp(want, have))
			return i;
	}
	return -1;
}

const char *const rdl_fmt_names[RDC_FMT_COUNT] = {
	"i1", "i2", "i4", "i8", "rgb565", "rgb888", "xrgb8888",
};
