// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * .rdl statements that build the CRTC's raster list (docs/hardware.md,
 * "Raster list") in VRAM and turn it on: `raster ADDR`, the entries
 * `raster-wait`, `raster-reg`, `raster-clut`, then `raster-end`.  Each
 * entry is written to VRAM as it is read, so a list a script rewrites
 * changes as the beam passes, as the chip's would.
 */
#include <string.h>

#include "script.h"

/* One entry at the list's next address. */
static int rl_put(struct rdl *r, const char *what, uint32_t op, uint32_t arg,
		  uint32_t val)
{
	uint32_t w0 = FIELD_PREP(RDC_RL_OP, op) | FIELD_PREP(RDC_RL_ARG, arg);
	uint8_t b[RDC_RASTER_ENTRY_BYTES];
	int ret;

	if (!r->raster_on)
		return rdl_err(r, RDC_E_PARSE, "%s outside `raster ADDR`",
			       what);
	if (r->raster_n >= RDC_RASTER_MAX_ENTRIES)
		return rdl_err(r, RDC_E_PARSE, "%s: more than %u entries", what,
			       RDC_RASTER_MAX_ENTRIES);
	for (int k = 0; k < 4; k++) {
		b[k] = (uint8_t)(w0 >> (8 * k));
		b[4 + k] = (uint8_t)(val >> (8 * k));
	}
	ret = rdc_vram_write(r->dev, r->raster_addr, b, sizeof(b));
	if (ret)
		return rdl_fail(r, what, ret);
	r->raster_addr += RDC_RASTER_ENTRY_BYTES;
	r->raster_n++;
	return 0;
}

/* raster ADDR: begin a list at ADDR (8-aligned); raster off: turn it off */
int rdl_st_raster(struct rdl *r, uint32_t op)
{
	uint32_t addr;
	int ret;

	(void)op;
	if (!strcmp(r->tok[1].s, "off")) {
		r->raster_on = false;
		ret = rdc_reg_write(r->dev, RDC_REG_RASTER_CTRL, 0);
		return ret ? rdl_fail(r, "raster", ret) : 0;
	}
	ret = rdl_u32(r, 1, &addr);
	if (ret)
		return ret;
	if (addr & ~RDC_RASTER_BASE_MASK)
		return rdl_err(r, RDC_E_PARSE,
			       "raster: address 0x%x is not 8-aligned", addr);
	r->raster_on = true;
	r->raster_base = r->raster_addr = addr;
	r->raster_n = 0;
	return 0;
}

/* raster-wait LINE [COLUMN] */
int rdl_st_raster_wait(struct rdl *r, uint32_t op)
{
	int64_t y, x = 0;
	int ret = rdl_int(r, 1, 0, 0xffff, &y);

	(void)op;
	if (!ret && r->ntok > 2)
		ret = rdl_int(r, 2, 0, 0xffff, &x);
	if (ret)
		return ret;
	return rl_put(r, "raster-wait", RDC_RL_WAIT, 0,
		      FIELD_PREP(RDC_RL_Y, (uint32_t)y) |
			      FIELD_PREP(RDC_RL_X, (uint32_t)x));
}

/* raster-reg REG VALUE: the chip refuses registers off its list */
int rdl_st_raster_reg(struct rdl *r, uint32_t op)
{
	uint32_t reg, val;
	int ret = rdl_reg(r, 1, &reg);

	(void)op;
	if (!ret)
		ret = rdl_u32(r, 2, &val);
	if (ret)
		return ret;
	return rl_put(r, "raster-reg", RDC_RL_REG, reg, val);
}

/* raster-clut FIRST RGB...: an entry for each colour, FIRST on */
int rdl_st_raster_clut(struct rdl *r, uint32_t op)
{
	uint32_t first, rgb;
	int ret = rdl_u32(r, 1, &first);

	(void)op;
	if (ret)
		return ret;
	if (first + (r->ntok - 2) > RDC_CLUT_ENTRIES)
		return rdl_err(r, RDC_E_PARSE, "raster-clut past entry 255");
	for (size_t i = 2; i < r->ntok && !ret; i++) {
		ret = rdl_rgb(r, i, &rgb);
		if (!ret)
			ret = rl_put(r, "raster-clut", RDC_RL_CLUT,
				     first + (uint32_t)(i - 2), rgb);
	}
	return ret;
}

/*
 * raster-end: END, then RASTER_BASE and RASTER_CTRL.EN: the list runs
 * from the next frame on (the registers are latched at vblank)
 */
int rdl_st_raster_end(struct rdl *r, uint32_t op)
{
	int ret = rl_put(r, "raster-end", RDC_RL_END, 0, 0);

	(void)op;
	if (ret)
		return ret;
	r->raster_on = false;
	ret = rdc_reg_write(r->dev, RDC_REG_RASTER_BASE, r->raster_base);
	if (!ret)
		ret = rdc_reg_write(r->dev, RDC_REG_RASTER_CTRL,
				    RDC_RASTER_CTRL_EN);
	return ret ? rdl_fail(r, "raster-end", ret) : 0;
}
