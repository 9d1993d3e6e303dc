// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcctl image encode --format rle|dpcm|btc|huff|dpcmq|dct [--level N]
 * [--grey] [--measure] IN.png OUT: a PNG encoded as an RDC-1 image
 * stream (hw-sim/rdc_image.h) for the DP's DECODE; .rdl loads it with
 * `vram-load ADDR OUT` and draws it with `decode ADDR X Y`.  Prints the
 * sizes and the compression ratio; --level sets DPCMQ's step or DCT's
 * quality; --measure also decodes the stream on an RDC-1 simulated in
 * this process and prints the PSNR of the result against the samples
 * and the DP's cycles per pixel for the DECODE.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "report.h"

const char rdcctl_image_usage[] =
	"  image encode --format rle|dpcm|btc|huff|dpcmq|dct [--level N]\n"
	"               [--grey] [--measure] IN.png OUT\n"
	"                             encode a PNG as an image stream for\n"
	"                             the DP's DECODE (RGB, or the luma\n"
	"                             with --grey; --level: DPCMQ's step\n"
	"                             1..255 or DCT's quality 1..100);\n"
	"                             print the sizes and the ratio to the\n"
	"                             raw samples; with --measure the PSNR\n"
	"                             and DP cycles a pixel of its\n"
	"                             decoding on sim:\n";

static const char *const image_codecs[] = { "rle",  "dpcm",  "btc",
					    "huff", "dpcmq", "dct" };

#define IMAGE_NCODECS (sizeof(image_codecs) / sizeof(image_codecs[0]))

/* 10 log10(x) for x >= 1, without libm: x = m 2^e, ln m by atanh's series */
static double image_db(double x)
{
	double m = x, z, z2, t, ln = 0;
	int e = 0;

	while (m >= 2) {
		m /= 2;
		e++;
	}
	z = (m - 1) / (m + 1);
	z2 = z * z;
	t = z;
	for (int k = 1; k < 60; k += 2) {
		ln += t / k;
		t *= z2;
	}
	ln = 2 * ln + e * 0.69314718055994530942;
	return 10 * ln / 2.30258509299404568402;
}

static int image_reg64(rdc_dev *dev, uint32_t lo, uint64_t *v)
{
	uint32_t l, h;
	int ret = rdc_reg_read(dev, lo, &l);

	if (!ret)
		ret = rdc_reg_read(dev, lo + 4, &h);
	*v = (uint64_t)h << 32 | l;
	return ret;
}

/*
 * DECODE of the stream into an XRGB8888 surface at VRAM 0 on sim:, the
 * scanout off (the bare cost, as the unit tests count it): the PSNR of
 * the picture against smp (*psnr < 0: identical) and the DP's cycles.
 */
static int image_measure(const uint8_t *st, size_t len, const uint8_t *smp,
			 uint32_t w, uint32_t h, uint32_t ch, double *psnr,
			 uint64_t *cycles)
{
	uint32_t stride = w * 4, at, args[4], err;
	uint64_t busy0, busy1, n = (uint64_t)w * h * ch;
	double se = 0;
	uint32_t *px = NULL;
	rdc_batch *b = NULL;
	rdc_dev *dev = NULL;
	int ret;

	at = (uint32_t)(((uint64_t)stride * h + 4095) & ~4095ull);
	ret = rdc_open("sim:vram=32M", &dev);
	if (ret)
		return ret;
	b = rdc_batch_new();
	px = malloc((size_t)stride * h);
	if (!b || !px) {
		ret = RDC_E_NOMEM;
		goto out;
	}
	args[0] = 0;
	args[1] = stride;
	args[2] = RDC_WH(w, h);
	args[3] = RDC_FMT_XRGB8888;
	ret = rdc_reg_write(dev, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	if (!ret)
		ret = rdc_vram_write(dev, at, st, len);
	if (!ret)
		ret = rdc_batch_cmd(b, RDC_OP_SET_DST, 0, args, 4);
	if (!ret)
		ret = rdc_batch_submit(dev, b);
	if (!ret)
		ret = rdc_finish(dev);
	if (!ret)
		ret = image_reg64(dev, RDC_REG_PERF_BUSY_LO, &busy0);
	args[0] = at;
	args[1] = (uint32_t)len;
	args[2] = RDC_XY(0, 0);
	if (!ret)
		ret = rdc_batch_cmd(b, RDC_OP_DECODE, 0, args, 3);
	if (!ret)
		ret = rdc_batch_submit(dev, b);
	if (!ret)
		ret = rdc_idle_wait(dev);
	if (!ret)
		ret = image_reg64(dev, RDC_REG_PERF_BUSY_LO, &busy1);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_ERR_CODE, &err);
	if (!ret && err) {
		fprintf(stderr, "rdcctl: image encode: DECODE failed (%u)\n",
			err);
		ret = RDC_E_IO;
	}
	if (!ret)
		ret = rdc_vram_read(dev, 0, px, (size_t)stride * h);
	if (ret)
		goto out;
	for (uint64_t i = 0; i < n; i++) {
		uint32_t p = px[i / ch], c = ch == 1 ? 2 : i % ch;
		int d = (int)(p >> (16 - 8 * c) & 0xff) - smp[i];

		se += (double)d * d;
	}
	*psnr = se ? image_db(255.0 * 255.0 * (double)n / se) : -1;
	*cycles = busy1 - busy0;
out:
	free(px);
	rdc_batch_free(b);
	rdc_close(dev);
	return ret;
}

static int image_encode(int argc, char **argv)
{
	const char *in = NULL, *out = NULL;
	uint32_t codec = 0, ch = 3, w, h, *pix = NULL;
	int measure = 0;
	unsigned long level = 0;
	char *end;
	uint64_t cycles = 0;
	double psnr = 0;
	uint8_t *smp = NULL, *st = NULL;
	size_t cap, len = 0, raw;
	FILE *f;
	int ret;

	for (int i = 0; i < argc; i++) {
		const char *a = argv[i], *v = NULL;

		if (!strncmp(a, "--format=", 9)) {
			v = a + 9;
		} else if (!strcmp(a, "--format")) {
			if (i + 1 >= argc) {
				fprintf(stderr,
					"rdcctl: --format needs a value\n");
				return 2;
			}
			v = argv[++i];
		} else if (!strcmp(a, "--grey") || !strcmp(a, "--gray")) {
			ch = 1;
			continue;
		} else if (!strcmp(a, "--measure")) {
			measure = 1;
			continue;
		} else if (!strncmp(a, "--level", 7) &&
			   (a[7] == '=' || !a[7])) {
			const char *l = a[7] ? a + 8 : NULL;

			if (!l && i + 1 < argc)
				l = argv[++i];
			level = l ? strtoul(l, &end, 10) : 0;
			if (!l || !*l || *end || !level || level > 255) {
				fprintf(stderr,
					"rdcctl: --level needs a "
					"number 1..255 (dct: 1..100)\n");
				return 2;
			}
			continue;
		} else if (a[0] == '-' && a[1]) {
			fprintf(stderr,
				"rdcctl: image encode: unknown option '%s'\n",
				a);
			return 2;
		} else if (!in) {
			in = a;
			continue;
		} else if (!out) {
			out = a;
			continue;
		} else {
			fprintf(stderr,
				"rdcctl: image encode: unexpected argument "
				"'%s'\n",
				a);
			return 2;
		}
		codec = 0;
		for (uint32_t k = 0; k < IMAGE_NCODECS; k++)
			if (!strcmp(v, image_codecs[k]))
				codec = RDC_IMG_RLE + k;
		if (!codec) {
			fprintf(stderr,
				"rdcctl: image encode: format '%s' is not "
				"rle, dpcm, btc, huff, dpcmq or dct\n",
				v);
			return 2;
		}
	}
	if (!codec || !in || !out) {
		fprintf(stderr,
			"usage: rdcctl image encode --format "
			"rle|dpcm|btc|huff|dpcmq|dct [--level N] [--grey] "
			"[--measure] IN.png OUT\n");
		return 2;
	}
	ret = rdc_image_png_read(in, &pix, &w, &h);
	if (ret) {
		rdcctl_error(in, ret);
		return 1;
	}
	raw = (size_t)w * h * ch;
	cap = rdc_image_bound(codec, w, h, ch);
	smp = malloc(raw);
	st = malloc(cap);
	ret = smp && st ? 0 : RDC_E_NOMEM;
	if (!ret)
		ret = rdc_image_samples(pix, w, h, w, ch, smp);
	if (!ret && level)
		ret = rdc_image_encode_lossy(codec, (uint32_t)level, smp, w, h,
					     ch, (size_t)w * ch, st, cap, &len);
	else if (!ret)
		ret = rdc_image_encode(codec, smp, w, h, ch, (size_t)w * ch, st,
				       cap, &len);
	if (ret) {
		rdcctl_error("image encode", ret);
		goto out;
	}
	f = fopen(out, "wb");
	if (!f || fwrite(st, 1, len, f) != len) {
		fprintf(stderr, "rdcctl: cannot write '%s'\n", out);
		if (f)
			fclose(f);
		ret = RDC_E_FILE;
		goto out;
	}
	if (fclose(f)) {
		fprintf(stderr, "rdcctl: cannot write '%s'\n", out);
		ret = RDC_E_FILE;
		goto out;
	}
	printf("%s: %ux%u, %u channel%s, %zu bytes of samples\n", in, w, h, ch,
	       ch == 1 ? "" : "s", raw);
	printf("%s: %s, %zu bytes (header %u), ratio %.2f:1, %.3f bits a "
	       "pixel\n",
	       out, image_codecs[codec - RDC_IMG_RLE], len, RDC_IMG_HDR_BYTES,
	       (double)raw / (double)len, 8.0 * (double)len / ((double)w * h));
	if (measure) {
		ret = image_measure(st, len, smp, w, h, ch, &psnr, &cycles);
		if (ret) {
			rdcctl_error("image encode --measure", ret);
			goto out;
		}
		if (psnr < 0)
			printf("%s: DECODE on sim: identical to the samples, "
			       "%llu DP cycles, %.3f a pixel\n",
			       out, (unsigned long long)cycles,
			       (double)cycles / ((double)w * h));
		else
			printf("%s: DECODE on sim: PSNR %.2f dB, %llu DP "
			       "cycles, %.3f a pixel\n",
			       out, psnr, (unsigned long long)cycles,
			       (double)cycles / ((double)w * h));
	}
out:
	free(pix);
	free(smp);
	free(st);
	return ret ? 1 : 0;
}

int rdcctl_image_main(int argc, char **argv)
{
	int i = 1;

	/* leading --uri/--connect options are rdcctl's; image needs none */
	while (i < argc && (!strncmp(argv[i], "--uri", 5) ||
			    !strncmp(argv[i], "--connect", 9)))
		i += strchr(argv[i], '=') ? 1 : 2;
	if (i >= argc || strcmp(argv[i], "image"))
		return -1;
	if (i + 1 < argc && !strcmp(argv[i + 1], "encode"))
		return image_encode(argc - i - 2, argv + i + 2);
	fprintf(stderr, "usage: rdcctl image encode --format "
			"rle|dpcm|btc|huff|dpcmq|dct [--level N] [--grey] "
			"[--measure] IN.png OUT\n");
	return 2;
}
