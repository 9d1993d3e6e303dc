// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Where does the light pen point?  The way 1980s light-pen software found
 * out: light half of what is left of the screen, watch a frame, keep the
 * half the pen saw, until one pixel is left (9 + 8 frames on 320x200).
 *
 *   cc lpen.c $(pkg-config --cflags --libs rdc) -o lpen
 *   ./lpen                       # sim:, the pen held at (211, 137)
 *   rdcctl --connect unix:/tmp/rdc.sock pen 40 30
 *   ./lpen unix:/tmp/rdc.sock    # find where rdcctl put it
 */
#include <stdio.h>

#include <rdc.h>

static int fail(const char *what, int err)
{
	fprintf(stderr, "lpen: %s: %s %s\n", what, rdc_strerror(err),
		rdc_last_error_detail(err));
	return 1;
}

/*
 * [x0, x1) x [y0, y1) white, the rest black; then from a clear of IRQ
 * LPEN to the second vblank: one whole frame.  1 if the pen saw light, 0
 * if not, or a negative error.
 */
static int flash(rdc_dev *dev, rdc_batch *b, uint32_t w, uint32_t h, int x0,
		 int y0, int x1, int y1)
{
	uint32_t st;
	int ret;

	rdc_batch_fg(b, 0);
	rdc_batch_fill_rect(b, 0, 0, w, h);
	rdc_batch_fg(b, 0xffffff);
	rdc_batch_fill_rect(b, x0, y0, (uint32_t)(x1 - x0),
			    (uint32_t)(y1 - y0));
	ret = rdc_batch_submit(dev, b);
	if (!ret)
		ret = rdc_finish(dev);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_IRQ_STATUS, RDC_IRQ_LPEN);
	if (!ret)
		ret = rdc_vblank_wait(dev);
	if (!ret)
		ret = rdc_vblank_wait(dev);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_IRQ_STATUS, &st);
	return ret ? ret : (st & RDC_IRQ_LPEN) != 0;
}

int main(int argc, char **argv)
{
	const char *uri = argc > 1 ? argv[1] : "sim:";
	int x0 = 0, y0 = 0, x1, y1, lit = 0, ret;
	uint32_t w, h;
	rdc_batch *b;
	rdc_dev *dev;

	ret = rdc_open(uri, &dev);
	if (ret)
		return fail(uri, ret);
	b = rdc_batch_new();
	if (!b)
		return fail("batch", RDC_E_NOMEM);
	ret = rdc_mode_set(dev, RDC_PRESET_320x200_70, RDC_FMT_XRGB8888, 0);
	if (!ret)
		ret = rdc_preset_size(RDC_PRESET_320x200_70, &w, &h);
	/* on sim: nobody else holds the pen: hold it somewhere */
	if (!ret && argc < 2)
		ret = rdc_reg_write(dev, RDC_REG_LPEN_POS, 137u << 16 | 211);
	if (!ret && argc < 2)
		ret = rdc_reg_write(dev, RDC_REG_LPEN_CTRL, RDC_LPEN_CTRL_EN);
	if (ret)
		return fail("mode", ret);
	x1 = (int)w;
	y1 = (int)h;
	while (x1 - x0 > 1 && lit >= 0) {
		int mid = x0 + (x1 - x0) / 2;

		lit = flash(dev, b, w, h, x0, 0, mid, (int)h);
		if (lit > 0)
			x1 = mid;
		else
			x0 = mid;
	}
	while (y1 - y0 > 1 && lit >= 0) {
		int mid = y0 + (y1 - y0) / 2;

		lit = flash(dev, b, w, h, 0, y0, (int)w, mid);
		if (lit > 0)
			y1 = mid;
		else
			y0 = mid;
	}
	if (lit >= 0)
		lit = flash(dev, b, w, h, x0, y0, x0 + 1, y0 + 1);
	if (lit < 0)
		return fail("flash", lit);
	if (lit)
		printf("the pen points at %d,%d\n", x0, y0);
	else
		printf("no pen on the screen\n");
	rdc_batch_free(b);
	rdc_close(dev);
	return lit ? 0 : 1;
}
