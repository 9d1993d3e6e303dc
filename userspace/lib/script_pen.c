// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * .rdl statements of the CRTC's light pen (docs/hardware.md, "Light
 * pen"): `lpen X Y [THRESHOLD]` holds it at a pixel, `lpen off` lifts it,
 * `lpen-expect X Y` and `lpen-expect dark` watch a whole frame and check
 * the latch, as `rdcctl pen` does.
 */
#include <string.h>

#include "script.h"

/* lpen X Y [THRESHOLD] | lpen off (`pen` is the line pen's SET_PEN) */
int rdl_st_lpen(struct rdl *r, uint32_t op)
{
	uint32_t x, y, th = 0;
	int ret;

	(void)op;
	if (rdl_word(r, 1, "off")) {
		if (r->ntok > 2)
			return rdl_err(r, RDC_E_PARSE,
				       "lpen off takes nothing more");
		ret = rdc_reg_write(r->dev, RDC_REG_LPEN_CTRL, 0);
		return ret ? rdl_fail(r, "lpen", ret) : 0;
	}
	if (r->ntok < 3)
		return rdl_err(r, RDC_E_PARSE, "lpen wants X Y or off");
	ret = rdl_u32(r, 1, &x);
	if (!ret)
		ret = rdl_u32(r, 2, &y);
	if (!ret && r->ntok > 3)
		ret = rdl_u32(r, 3, &th);
	if (ret)
		return ret;
	if (x > 0xffff || y > 0xffff)
		return rdl_err(r, RDC_E_PARSE, "lpen: X and Y are 0..65535");
	if (th > 255)
		return rdl_err(r, RDC_E_PARSE, "lpen: THRESHOLD is 0..255");
	/* the write of LPEN_CTRL clears STATUS.LPEN; IRQ_STATUS is W1C */
	ret = rdc_reg_write(r->dev, RDC_REG_LPEN_POS,
			    FIELD_PREP(RDC_LPEN_Y, y) |
				    FIELD_PREP(RDC_LPEN_X, x));
	if (!ret)
		ret = rdc_reg_write(r->dev, RDC_REG_LPEN_CTRL,
				    RDC_LPEN_CTRL_EN |
					    FIELD_PREP(RDC_LPEN_CTRL_THRESHOLD,
						       th));
	if (!ret)
		ret = rdc_reg_write(r->dev, RDC_REG_IRQ_STATUS, RDC_IRQ_LPEN);
	return ret ? rdl_fail(r, "lpen", ret) : 0;
}

/*
 * lpen-expect X Y | lpen-expect dark: IRQ_STATUS.LPEN cleared, then to the
 * second vblank, so that one whole frame passes the pen; then it and
 * LPEN_LATCH must say it latched at (X, Y), or that it saw no light.
 */
int rdl_st_lpen_expect(struct rdl *r, uint32_t op)
{
	uint32_t x = 0, y = 0, irq, latch, lx, ly;
	bool dark = rdl_word(r, 1, "dark");
	int ret = 0;

	(void)op;
	if (dark && r->ntok > 2)
		return rdl_err(r, RDC_E_PARSE,
			       "lpen-expect dark takes nothing more");
	if (!dark && r->ntok < 3)
		return rdl_err(r, RDC_E_PARSE, "lpen-expect wants X Y or dark");
	if (!dark)
		ret = rdl_u32(r, 1, &x);
	if (!ret && !dark)
		ret = rdl_u32(r, 2, &y);
	if (ret)
		return ret;
	ret = rdc_reg_write(r->dev, RDC_REG_IRQ_STATUS, RDC_IRQ_LPEN);
	if (!ret)
		ret = rdc_vblank_wait(r->dev);
	if (!ret)
		ret = rdc_vblank_wait(r->dev);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_IRQ_STATUS, &irq);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_LPEN_LATCH, &latch);
	if (ret)
		return rdl_fail(r, "lpen-expect", ret);
	r->res->frame_ready = 1;
	lx = FIELD_GET(RDC_LPEN_X, latch);
	ly = FIELD_GET(RDC_LPEN_Y, latch);
	if (!(irq & RDC_IRQ_LPEN))
		return dark ? 0 :
			      rdl_err(r, RDC_E_DEVICE,
				      "lpen-expect: the pen saw no light, "
				      "expected a latch at %u,%u",
				      x, y);
	if (dark)
		return rdl_err(r, RDC_E_DEVICE,
			       "lpen-expect: the pen latched at %u,%u, "
			       "expected no light",
			       lx, ly);
	if (lx != x || ly != y)
		return rdl_err(r, RDC_E_DEVICE,
			       "lpen-expect: the pen latched at %u,%u, "
			       "expected %u,%u",
			       lx, ly, x, y);
	return 0;
}
