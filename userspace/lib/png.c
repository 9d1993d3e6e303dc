// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* PNG output of XRGB8888 frames through libpng. */
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rdc_priv.h"

#define PNG_RGB_BYTES 3

int rdc_png_write(const char *path, const uint32_t *xrgb, uint32_t w,
		  uint32_t h, size_t pitch)
{
	png_structp png = NULL;
	png_infop info = NULL;
	uint8_t *row = NULL;
	FILE *f;
	volatile int ret = RDC_E_FILE;

	if (!path || !xrgb || !w || !h || pitch < w || w > RDC_CRTC_MAX_TOTAL ||
	    h > RDC_CRTC_MAX_TOTAL)
		return RDC_E_INVAL;
	row = malloc((size_t)w * PNG_RGB_BYTES);
	if (!row)
		return RDC_E_NOMEM;
	f = fopen(path, "wb");
	if (!f) {
		free(row);
		return rdc_err_detail(RDC_E_FILE, "%s: %s", path,
				      strerror(errno));
	}
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	if (png)
		info = png_create_info_struct(png);
	if (!png || !info) {
		ret = RDC_E_NOMEM;
		goto out;
	}
	/* libpng reports errors by longjmp: land here with ret unset. */
	if (setjmp(png_jmpbuf(png))) {
		rdc_err_detail(RDC_E_FILE, "%s: %s", path,
			       errno ? strerror(errno) : "libpng failed");
		goto out;
	}
	errno = 0;
	png_init_io(png, f);
	png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
		     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (uint32_t y = 0; y < h; y++) {
		const uint32_t *src = xrgb + (size_t)y * pitch;

		for (uint32_t x = 0; x < w; x++) {
			row[PNG_RGB_BYTES * x + 0] = (uint8_t)(src[x] >> 16);
			row[PNG_RGB_BYTES * x + 1] = (uint8_t)(src[x] >> 8);
			row[PNG_RGB_BYTES * x + 2] = (uint8_t)src[x];
		}
		png_write_row(png, row);
	}
	png_write_end(png, NULL);
	ret = 0;
out:
	png_destroy_write_struct(&png, &info);
	if (fclose(f) && !ret)
		ret = rdc_err_detail(RDC_E_FILE, "%s: %s", path,
				     strerror(errno));
	free(row);
	return ret;
}
