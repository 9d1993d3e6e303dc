// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcctl image encode --format rle|dpcm|btc [--grey] IN.png OUT: a PNG
 * encoded as an RDC-1 image stream (hw-sim/rdc_image.h) for the DP's
 * DECODE; .rdl loads it with `vram-load ADDR OUT` and draws it with
 * `decode ADDR X Y`.  Prints the sizes and the compression ratio.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "report.h"

const char rdcctl_image_usage[] =
	"  image encode --format rle|dpcm|btc [--grey] IN.png OUT\n"
	"                             encode a PNG as an image stream for\n"
	"                             the DP's DECODE (RGB, or the luma\n"
	"                             with --grey); print the sizes and\n"
	"                             the ratio to the raw samples\n";

static const char *const image_codecs[] = { "rle", "dpcm", "btc" };

static int image_encode(int argc, char **argv)
{
	const char *in = NULL, *out = NULL;
	uint32_t codec = 0, ch = 3, w, h, *pix = NULL;
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
		for (uint32_t k = 0; k < 3; k++)
			if (!strcmp(v, image_codecs[k]))
				codec = RDC_IMG_RLE + k;
		if (!codec) {
			fprintf(stderr,
				"rdcctl: image encode: format '%s' is not "
				"rle, dpcm or btc\n",
				v);
			return 2;
		}
	}
	if (!codec || !in || !out) {
		fprintf(stderr, "usage: rdcctl image encode --format "
				"rle|dpcm|btc [--grey] IN.png OUT\n");
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
	if (!ret)
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
	fprintf(stderr, "usage: rdcctl image encode --format rle|dpcm|btc "
			"[--grey] IN.png OUT\n");
	return 2;
}
