// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * .rdl statements of the image commands (DECODE, HISTOGRAM, MAP_*,
 * CONVOLVE, THRESHOLD) and the host statements that feed and show them:
 * vram-load, encode, histogram-plot.  docs/rdl.md describes them.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "script.h"
#include "script_img.h"

#define RDL_VRAM_FILE_MAX (256u << 20)

static int rdl_chan(struct rdl *r, size_t i, uint32_t *sel)
{
	static const char *const names[] = { "luma", "red", "green", "blue" };

	for (uint32_t k = 0; k < RDC_ARRAY_SIZE(names); k++) {
		if (rdl_word(r, i, names[k])) {
			*sel = k;
			return 0;
		}
	}
	return rdl_err(r, RDC_E_PARSE,
		       "%s: '%.40s' is not luma, red, green "
		       "or blue",
		       r->tok[0].s, r->tok[i].s);
}

/* X Y W H from token `first` on, as a point and a size word. */
static int rdl_rect(struct rdl *r, size_t first, uint32_t *xy, uint32_t *wh)
{
	int c[2];
	uint32_t w, h;
	int ret = rdl_coords(r, first, 2, c);

	if (!ret)
		ret = rdl_size(r, first + 2, &w);
	if (!ret)
		ret = rdl_size(r, first + 3, &h);
	if (ret)
		return ret;
	*xy = RDC_XY(c[0], c[1]);
	*wh = RDC_WH(w, h);
	return 0;
}

/* decode ADDR X Y [SIZE]: SIZE defaults to the rest of VRAM. */
int rdl_st_decode(struct rdl *r, uint32_t op)
{
	uint32_t a[3], vram;
	int c[2];
	int ret = rdl_u32(r, 1, &a[0]);

	if (!ret)
		ret = rdl_coords(r, 2, 2, c);
	if (ret)
		return ret;
	if (r->ntok > 4) {
		ret = rdl_u32(r, 4, &a[1]);
	} else {
		ret = rdc_reg_read(r->dev, RDC_REG_VRAM_SIZE, &vram);
		if (ret)
			return rdl_fail(r, "decode", ret);
		a[1] = a[0] < vram ? vram - a[0] : 0;
	}
	if (ret)
		return ret;
	a[2] = RDC_XY(c[0], c[1]);
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, a, 3));
}

/* histogram X Y W H TABLE [luma|red|green|blue] [accum] */
int rdl_st_histogram(struct rdl *r, uint32_t op)
{
	uint32_t a[3], fl = 0, sel;
	int ret = rdl_rect(r, 1, &a[0], &a[1]);

	if (!ret)
		ret = rdl_u32(r, 5, &a[2]);
	for (size_t i = 6; !ret && i < r->ntok; i++) {
		if (rdl_word(r, i, "accum")) {
			fl |= RDC_HIST_ACCUM;
			continue;
		}
		ret = rdl_chan(r, i, &sel);
		fl |= sel;
	}
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, fl, a, 3));
}

/*
 * map-build stretch LO HI MAP | stretch-auto HIST MAP [MIN] |
 * equalize HIST MAP
 */
int rdl_st_map_build(struct rdl *r, uint32_t op)
{
	uint32_t a[3] = { 0, 0, 0 }, mode, lo, hi;
	int ret;

	if (rdl_word(r, 1, "stretch")) {
		mode = RDC_MAP_STRETCH;
		if (r->ntok != 5)
			return rdl_err(r, RDC_E_PARSE,
				       "map-build stretch LO HI MAP");
		ret = rdl_u32(r, 2, &lo);
		if (!ret)
			ret = rdl_u32(r, 3, &hi);
		if (!ret)
			ret = rdl_u32(r, 4, &a[1]);
		if (!ret && (lo > 255 || hi > 255))
			ret = rdl_err(r, RDC_E_PARSE,
				      "map-build: levels are 0..255");
		a[2] = lo | hi << 8;
	} else if (rdl_word(r, 1, "stretch-auto") ||
		   rdl_word(r, 1, "equalize")) {
		mode = rdl_word(r, 1, "equalize") ? RDC_MAP_EQUALIZE :
						    RDC_MAP_STRETCH_AUTO;
		if (r->ntok < 4 ||
		    r->ntok > (mode == RDC_MAP_EQUALIZE ? 4u : 5u))
			return rdl_err(r, RDC_E_PARSE,
				       "map-build %s HIST MAP%s", r->tok[1].s,
				       mode == RDC_MAP_EQUALIZE ? "" :
								  " [MIN]");
		ret = rdl_u32(r, 2, &a[0]);
		if (!ret)
			ret = rdl_u32(r, 3, &a[1]);
		if (!ret && r->ntok == 5)
			ret = rdl_u32(r, 4, &a[2]);
	} else {
		return rdl_err(r, RDC_E_PARSE,
			       "map-build: '%.40s' is not "
			       "stretch, stretch-auto or equalize",
			       r->tok[1].s);
	}
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, mode, a, 3));
}

/* map-apply X Y W H MAP */
int rdl_st_map_apply(struct rdl *r, uint32_t op)
{
	uint32_t a[3];
	int ret = rdl_rect(r, 1, &a[0], &a[1]);

	if (!ret)
		ret = rdl_u32(r, 5, &a[2]);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, a, 3));
}

/* threshold X Y W H LEVEL [luma|red|green|blue] */
int rdl_st_threshold(struct rdl *r, uint32_t op)
{
	uint32_t a[3], sel = 0;
	int ret = rdl_rect(r, 1, &a[0], &a[1]);

	if (!ret)
		ret = rdl_u32(r, 5, &a[2]);
	if (!ret && r->ntok > 6)
		ret = rdl_chan(r, 6, &sel);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, sel, a, 3));
}

static const struct {
	const char *name;
	int8_t k[9];
	uint16_t div;
	int16_t bias;
	uint8_t flags;
} rdl_kernels[] = {
	{ "box", { 1, 1, 1, 1, 1, 1, 1, 1, 1 }, 9, 0, 0 },
	{ "gauss", { 1, 2, 1, 2, 4, 2, 1, 2, 1 }, 16, 0, 0 },
	{ "sharpen", { 0, -1, 0, -1, 5, -1, 0, -1, 0 }, 1, 0, 0 },
	{ "laplace", { 0, 1, 0, 1, -4, 1, 0, 1, 0 }, 1, 0, RDC_CONV_ABS },
	{ "emboss", { -2, -1, 0, -1, 1, 1, 0, 1, 2 }, 1, 0, 0 },
	{ "sobel", { 0 }, 1, 0, RDC_CONV_SOBEL },
};

static uint32_t krow(const int32_t *k)
{
	return (uint8_t)k[0] | (uint32_t)(uint8_t)k[1] << 8 |
	       (uint32_t)(uint8_t)k[2] << 16;
}

/*
 * convolve SX SY DX DY W H NAME [DIV [BIAS]]
 * convolve SX SY DX DY W H K0 .. K8 DIV [BIAS] [abs]
 */
int rdl_st_convolve(struct rdl *r, uint32_t op)
{
	int c[4];
	int32_t k[9];
	int64_t v;
	uint32_t a[7], w, h, fl = 0, div = 1, n;
	int32_t bias = 0;
	size_t i = 7, end = r->ntok;
	int ret = rdl_coords(r, 1, 4, c);

	if (!ret)
		ret = rdl_size(r, 5, &w);
	if (!ret)
		ret = rdl_size(r, 6, &h);
	if (ret)
		return ret;
	if (end > 7 && rdl_word(r, end - 1, "abs")) {
		fl |= RDC_CONV_ABS;
		end--;
	}
	for (n = 0; n < RDC_ARRAY_SIZE(rdl_kernels); n++)
		if (rdl_word(r, 7, rdl_kernels[n].name))
			break;
	if (n < RDC_ARRAY_SIZE(rdl_kernels)) {
		for (int t = 0; t < 9; t++)
			k[t] = rdl_kernels[n].k[t];
		div = rdl_kernels[n].div;
		bias = rdl_kernels[n].bias;
		fl |= rdl_kernels[n].flags;
		i = 8;
	} else {
		if (end < 16) /* the keyword, 6 numbers, 9 coefficients */
			return rdl_err(r, RDC_E_PARSE,
				       "convolve: a kernel name "
				       "(box gauss sharpen laplace emboss "
				       "sobel) or 9 coefficients");
		for (int t = 0; t < 9; t++, i++) {
			ret = rdl_int(r, i, -128, 127, &v);
			if (ret)
				return ret;
			k[t] = (int32_t)v;
		}
	}
	if (i < end) {
		ret = rdl_int(r, i++, 1, 65535, &v);
		div = (uint32_t)v;
	}
	if (!ret && i < end) {
		ret = rdl_int(r, i++, -32768, 32767, &v);
		bias = (int32_t)v;
	}
	if (ret)
		return ret;
	if (i < end)
		return rdl_err(r, RDC_E_PARSE, "convolve: too many arguments");
	if ((fl & RDC_CONV_SOBEL) && (fl & RDC_CONV_ABS))
		return rdl_err(r, RDC_E_PARSE, "convolve: sobel takes no abs");
	a[0] = RDC_XY(c[0], c[1]);
	a[1] = RDC_XY(c[2], c[3]);
	a[2] = RDC_WH(w, h);
	n = 3;
	if ((fl & RDC_CONV_MODE) == RDC_CONV_KERNEL) {
		a[n++] = krow(k);
		a[n++] = krow(k + 3);
		a[n++] = krow(k + 6);
	}
	a[n++] = div | (uint32_t)(uint16_t)bias << 16;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, fl, a, n));
}

/* vram-load ADDR FILE: the file's bytes into VRAM at ADDR. */
int rdl_st_vram_load(struct rdl *r, uint32_t op)
{
	uint32_t addr;
	FILE *f;
	uint8_t *buf;
	long n;
	int ret = rdl_u32(r, 1, &addr);

	(void)op;
	if (ret)
		return ret;
	f = fopen(r->tok[2].s, "rb");
	if (!f)
		return rdl_err(r, RDC_E_FILE, "vram-load: cannot open '%.80s'",
			       r->tok[2].s);
	if (fseek(f, 0, SEEK_END) || (n = ftell(f)) < 0 ||
	    (unsigned long)n > RDL_VRAM_FILE_MAX || fseek(f, 0, SEEK_SET)) {
		fclose(f);
		return rdl_err(r, RDC_E_FILE,
			       "vram-load: '%.80s': not a "
			       "readable file of at most 256 MiB",
			       r->tok[2].s);
	}
	buf = malloc((size_t)n + 1);
	if (!buf) {
		fclose(f);
		return rdl_err(r, RDC_E_NOMEM, "vram-load: out of memory");
	}
	if (fread(buf, 1, (size_t)n, f) != (size_t)n) {
		free(buf);
		fclose(f);
		return rdl_err(r, RDC_E_FILE, "vram-load: cannot read '%.80s'",
			       r->tok[2].s);
	}
	fclose(f);
	ret = n ? rdc_vram_write(r->dev, addr, buf, (size_t)n) : 0;
	free(buf);
	return ret ? rdl_fail(r, "vram-load", ret) : 0;
}

/*
 * After encode's rectangle: [grey] and, for the lossy codecs, [step N]
 * (DPCMQ's quantiser step, 1..255) or [quality N] (DCT's quality, 1..100:
 * its quantisation table scaled); *level 0 when none is given.
 */
static int encode_opts(struct rdl *r, uint32_t codec, uint32_t *ch,
		       uint32_t *level)
{
	const char *key = codec == RDC_IMG_DPCMQ ? "step" :
			  codec == RDC_IMG_DCT	 ? "quality" :
						   NULL;
	uint32_t max = codec == RDC_IMG_DPCMQ ? 255 : 100;
	size_t i = 7;
	int ret;

	if (i < r->ntok && (rdl_word(r, i, "grey") || rdl_word(r, i, "gray"))) {
		*ch = 1;
		i++;
	}
	if (i < r->ntok && key && rdl_word(r, i, key) && i + 1 < r->ntok) {
		ret = rdl_u32(r, i + 1, level);
		if (ret)
			return ret;
		if (!*level || *level > max)
			return rdl_err(r, RDC_E_PARSE,
				       "encode: %s %u is not 1..%u", key,
				       *level, max);
		i += 2;
	}
	if (i < r->ntok)
		return rdl_err(r, RDC_E_PARSE,
			       "encode: '%.40s' is not grey%s%s", r->tok[i].s,
			       key ? " or " : "", key ? key : "");
	return 0;
}

/*
 * encode rle|dpcm|btc|huff|dpcmq|dct ADDR X Y W H [grey] [step|quality
 * N]: the rectangle of the picture on screen (the next complete frame),
 * encoded on the host and written to VRAM at ADDR.
 */
int rdl_st_encode(struct rdl *r, uint32_t op)
{
	static const char *const codecs[] = { "rle",  "dpcm",  "btc",
					      "huff", "dpcmq", "dct" };
	uint32_t codec = 0, addr, xy, wh, fw, fh, w, h, ch = 3, *pix = NULL;
	uint32_t level = 0;
	uint8_t *smp = NULL, *out = NULL;
	size_t cap, len;
	int32_t x, y;
	int ret;

	(void)op;
	for (uint32_t k = 0; k < RDC_ARRAY_SIZE(codecs); k++)
		if (rdl_word(r, 1, codecs[k]))
			codec = RDC_IMG_RLE + k;
	if (!codec)
		return rdl_err(r, RDC_E_PARSE,
			       "encode: '%.40s' is not rle, "
			       "dpcm, btc, huff, dpcmq or dct",
			       r->tok[1].s);
	ret = rdl_u32(r, 2, &addr);
	if (!ret)
		ret = rdl_rect(r, 3, &xy, &wh);
	if (ret)
		return ret;
	ret = encode_opts(r, codec, &ch, &level);
	if (ret)
		return ret;
	x = RDC_X(xy);
	y = RDC_Y(xy);
	w = RDC_W(wh);
	h = RDC_H(wh);
	ret = rdc_frame_wait(r->dev);
	if (!ret)
		ret = rdc_frame_alloc(r->dev, &pix, &fw, &fh);
	if (ret)
		return rdl_fail(r, "encode", ret);
	if (x < 0 || y < 0 || !w || !h || (uint64_t)x + w > fw ||
	    (uint64_t)y + h > fh) {
		free(pix);
		return rdl_err(r, RDC_E_RANGE,
			       "encode: the rectangle leaves "
			       "the %ux%u screen",
			       fw, fh);
	}
	cap = rdc_image_bound(codec, w, h, ch);
	smp = malloc((size_t)w * h * ch);
	out = cap ? malloc(cap) : NULL;
	if (!smp || !out)
		ret = cap ? RDC_E_NOMEM : RDC_E_RANGE;
	if (!ret)
		ret = rdc_image_samples(pix + (size_t)y * fw + x, w, h, fw, ch,
					smp);
	if (!ret)
		ret = level ? rdc_image_encode_lossy(codec, level, smp, w, h,
						     ch, (size_t)w * ch, out,
						     cap, &len) :
			      rdc_image_encode(codec, smp, w, h, ch,
					       (size_t)w * ch, out, cap, &len);
	if (!ret)
		ret = rdc_vram_write(r->dev, addr, out, len);
	free(pix);
	free(smp);
	free(out);
	return ret ? rdl_fail(r, "encode", ret) : 0;
}

/*
 * histogram-plot TABLE X Y W H: the 256 bins at TABLE as W columns of
 * bars in FG (FILL_RECT), column c the sum of bins c * 256 / W up to
 * (c + 1) * 256 / W (at least one), the tallest H pixels high.
 */
int rdl_st_histogram_plot(struct rdl *r, uint32_t op)
{
	uint32_t table, xy, wh, w, h, b0, b1, c, i;
	uint64_t col, max = 0, *cols;
	uint8_t raw[1024];
	int ret = rdl_u32(r, 1, &table);

	if (!ret)
		ret = rdl_rect(r, 2, &xy, &wh);
	if (ret)
		return ret;
	w = RDC_W(wh);
	h = RDC_H(wh);
	ret = rdc_vram_read(r->dev, table, raw, sizeof(raw));
	if (ret)
		return rdl_fail(r, "histogram-plot", ret);
	cols = calloc(w ? w : 1, sizeof(*cols));
	if (!cols)
		return rdl_err(r, RDC_E_NOMEM, "histogram-plot: out of memory");
	for (c = 0; c < w; c++) {
		b0 = (uint32_t)((uint64_t)c * 256 / w);
		b1 = (uint32_t)((uint64_t)(c + 1) * 256 / w);
		b1 = b1 > b0 ? b1 : b0 + 1;
		for (col = 0, i = b0; i < b1; i++)
			col += rdc_ld32(raw + 4 * i);
		cols[c] = col;
		max = col > max ? col : max;
	}
	for (c = 0; !ret && c < w; c++) {
		uint32_t bh = max ? (uint32_t)(cols[c] * h / max) : 0;

		if (bh)
			ret = rdc_batch_fill_rect(r->b, RDC_X(xy) + (int32_t)c,
						  RDC_Y(xy) + (int32_t)(h - bh),
						  1, bh);
	}
	free(cols);
	return rdl_encoded(r, op, ret);
}
