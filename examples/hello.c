// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * A first librdc program: draw a small scene on an RDC-1 and print the
 * frame's CRC-32.  Against an installed librdc:
 *
 *   cc hello.c $(pkg-config --cflags --libs rdc) -o hello
 *   ./hello                 # the simulated chip in this process (sim:)
 *   ./hello unix:/tmp/rdc.sock   # or the one rdcd serves
 *
 * tests/install/scene.rdl is the same scene as an .rdl script: `rdcctl run`
 * prints the same crc32 for it.
 */
#include <stdio.h>

#include <rdc.h>

static int fail(const char *what, int err)
{
	fprintf(stderr, "hello: %s: %s %s\n", what, rdc_strerror(err),
		rdc_last_error_detail(err));
	return 1;
}

int main(int argc, char **argv)
{
	static const int star[] = { 320, 60,  355, 160, 460, 160, 375,
				    220, 405, 320, 320, 260, 235, 320,
				    265, 220, 180, 160, 285, 160 };
	const char *uri = argc > 1 ? argv[1] : "sim:";
	uint32_t version = rdc_version(), crc;
	rdc_batch *b;
	rdc_dev *dev;
	int err;

	/* the header this was built with and the library it runs with */
	if (RDC_VERSION_GET_MAJOR(version) != RDC_VERSION_MAJOR) {
		fprintf(stderr, "hello: built for librdc %d, running with %u\n",
			RDC_VERSION_MAJOR, RDC_VERSION_GET_MAJOR(version));
		return 1;
	}
	printf("librdc %u.%u.%u\n", RDC_VERSION_GET_MAJOR(version),
	       RDC_VERSION_GET_MINOR(version), RDC_VERSION_GET_PATCH(version));

	err = rdc_open(uri, &dev);
	if (err)
		return fail(uri, err);
	b = rdc_batch_new();
	if (!b) {
		rdc_close(dev);
		return fail("batch", RDC_E_NOMEM);
	}
	err = rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_XRGB8888, 0);
	if (err)
		goto out;

	rdc_batch_fg(b, 0x102040);
	rdc_batch_fill_rect(b, 0, 0, 640, 480);
	rdc_batch_fg(b, 0xff8000);
	rdc_batch_fill_circle(b, 320, 240, 100);
	rdc_batch_fg(b, 0xffffff);
	rdc_batch_fill_polygon(b, star, 10, 0);
	rdc_batch_fg(b, 0x40c040);
	rdc_batch_line(b, 0, 479, 639, 0);
	rdc_batch_aa_circle(b, 320, 240, 180);
	rdc_batch_fg(b, 0xffff00);
	rdc_batch_text(b, 16, 16, "hello, RDC-1", 12, 1);
	err = rdc_batch_submit(dev, b);
	if (!err)
		err = rdc_finish(dev); /* the DP has drawn it all */
	if (!err)
		err = rdc_frame_wait(dev); /* a frame scanned out after it */
	if (!err)
		err = rdc_frame_crc(dev, &crc);
	if (!err)
		printf("crc32 %08x\n", crc);
out:
	rdc_batch_free(b);
	rdc_close(dev);
	return err ? fail("draw", err) : 0;
}
