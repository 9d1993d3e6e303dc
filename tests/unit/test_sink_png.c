// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* The png sink: every Nth frame and on demand, numbered by sequence. */
#include <dirent.h>
#include <png.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <setjmp.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc_sink.h"

#define PW 24
#define PH 10

static char tdir[64];

static int setup(void **state)
{
	(void)state;
	strcpy(tdir, "/tmp/rdc_sink_png_XXXXXX");
	return mkdtemp(tdir) ? 0 : -1;
}

static int teardown(void **state)
{
	DIR *d = opendir(tdir);
	struct dirent *e;

	(void)state;
	while (d && (e = readdir(d))) {
		char p[320];

		if (e->d_name[0] == '.')
			continue;
		snprintf(p, sizeof(p), "%s/%s", tdir, e->d_name);
		unlink(p);
	}
	if (d)
		closedir(d);
	return rmdir(tdir);
}

/* The sorted file names in tdir, joined by spaces. */
static void listing(char *out, size_t cap)
{
	struct dirent **ents;
	int n = scandir(tdir, &ents, NULL, alphasort);

	assert_true(n >= 0);
	out[0] = '\0';
	for (int i = 0; i < n; i++) {
		if (ents[i]->d_name[0] != '.') {
			if (out[0])
				strncat(out, " ", cap - strlen(out) - 1);
			strncat(out, ents[i]->d_name, cap - strlen(out) - 1);
		}
		free(ents[i]);
	}
	free(ents);
}

static void frame_fill(uint32_t *px, uint64_t seq)
{
	for (uint32_t i = 0; i < PW * PH; i++)
		px[i] = (uint32_t)(seq * 0x010203u + i * 0x0a0b0cu) & 0xffffff;
}

static void test_png_every_n(void **state)
{
	uint32_t px[PW * PH];
	struct rdc_frame f = {
		.xrgb = px, .width = PW, .height = PH, .stride = PW
	};
	struct rdc_sink_stats st;
	char spec[128], names[512];
	rdc_sink *s;

	(void)state;
	snprintf(spec, sizeof(spec), "png:%s,every=3", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), 0);
	for (uint64_t seq = 10; seq < 17; seq++) {
		f.seq = seq;
		frame_fill(px, seq);
		assert_int_equal(rdc_sink_frame(s, &f), 0);
	}
	/* Handed frames 1, 4 and 7 (seq 10, 13, 16) are due. */
	listing(names, sizeof(names));
	assert_string_equal(names, "frame-00000010.png frame-00000013.png "
				   "frame-00000016.png");
	assert_int_equal(rdc_sink_stats_get(s, &st), 0);
	assert_int_equal(st.frames, 7);
	assert_int_equal(st.written, 3);
	rdc_sink_close(s);
}

static void test_png_on_demand_and_pixels(void **state)
{
	uint32_t px[PW * PH];
	struct rdc_frame f = {
		.xrgb = px, .width = PW, .height = PH, .stride = PW
	};
	char spec[128], names[512], path[256];
	png_image img;
	uint8_t rgb[PW * PH * 3];
	rdc_sink *s;

	(void)state;
	snprintf(spec, sizeof(spec), "png:%s,prefix=shot", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), 0);
	f.seq = 1;
	frame_fill(px, 1);
	assert_int_equal(rdc_sink_frame(s, &f), 0); /* not asked for */
	assert_int_equal(rdc_sink_snapshot(s), 0);
	f.seq = 2;
	frame_fill(px, 2);
	assert_int_equal(rdc_sink_frame(s, &f), 0);
	f.seq = 3;
	assert_int_equal(rdc_sink_frame(s, &f), 0); /* one shot only */
	listing(names, sizeof(names));
	assert_string_equal(names, "shot-00000002.png");

	snprintf(path, sizeof(path), "%s/shot-00000002.png", tdir);
	memset(&img, 0, sizeof(img));
	img.version = PNG_IMAGE_VERSION;
	assert_true(png_image_begin_read_from_file(&img, path));
	assert_int_equal(img.width, PW);
	assert_int_equal(img.height, PH);
	img.format = PNG_FORMAT_RGB;
	assert_true(png_image_finish_read(&img, NULL, rgb, 0, NULL));
	frame_fill(px, 2);
	for (uint32_t i = 0; i < PW * PH; i++) {
		assert_int_equal(rgb[3 * i], (px[i] >> 16) & 0xff);
		assert_int_equal(rgb[3 * i + 1], (px[i] >> 8) & 0xff);
		assert_int_equal(rgb[3 * i + 2], px[i] & 0xff);
	}
	rdc_sink_close(s);
}

static void test_png_bad_specs(void **state)
{
	char spec[128];
	rdc_sink *s = NULL;

	(void)state;
	assert_int_equal(rdc_sink_open("png:", &s), RDC_E_URI);
	snprintf(spec, sizeof(spec), "png:%s,every=x", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_URI);
	snprintf(spec, sizeof(spec), "png:%s,every=-1", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_URI);
	snprintf(spec, sizeof(spec), "png:%s,prefix=../up", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_URI);
	snprintf(spec, sizeof(spec), "png:%s,speed", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_URI);
	assert_null(s);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_URI), "speed"));
}

/*
 * A directory that is not there is made, parents too (mkdir -p); one that
 * cannot be made fails the open with its name and the reason; one that
 * goes away later fails the frame the same way, never silently.
 */
static void test_png_directories(void **state)
{
	char spec[160], path[160], file[200];
	rdc_sink *s = NULL;
	uint32_t px[4] = { 0 };
	struct rdc_frame f = {
		.xrgb = px, .width = 2, .height = 2, .stride = 2
	};
	FILE *fp;

	(void)state;
	snprintf(spec, sizeof(spec), "png:%s/a/b/,every=1", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), 0);
	assert_int_equal(rdc_sink_frame(s, &f), 0);
	snprintf(file, sizeof(file), "%s/a/b/frame-00000000.png", tdir);
	assert_int_equal(access(file, R_OK), 0);
	/* the directory goes away under the sink */
	assert_int_equal(unlink(file), 0);
	snprintf(path, sizeof(path), "%s/a/b", tdir);
	assert_int_equal(rmdir(path), 0);
	f.seq = 1;
	assert_int_equal(rdc_sink_frame(s, &f), RDC_E_FILE);
	snprintf(file, sizeof(file), "%s/a/b//frame-00000001.png", tdir);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), file));
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "No such file or directory"));
	rdc_sink_close(s);
	snprintf(path, sizeof(path), "%s/a", tdir);
	assert_int_equal(rmdir(path), 0);

	/* under a regular file: refused at open */
	snprintf(path, sizeof(path), "%s/plain", tdir);
	fp = fopen(path, "w");
	assert_non_null(fp);
	fclose(fp);
	snprintf(spec, sizeof(spec), "png:%s/plain/shots,every=1", tdir);
	s = NULL;
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_FILE);
	assert_null(s);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), path));
	assert_non_null(
		strstr(rdc_last_error_detail(RDC_E_FILE), "Not a directory"));
	snprintf(spec, sizeof(spec), "png:%s/plain,every=1", tdir);
	assert_int_equal(rdc_sink_open(spec, &s), RDC_E_FILE);
	assert_non_null(
		strstr(rdc_last_error_detail(RDC_E_FILE), "not a directory"));
	unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_png_every_n, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_png_on_demand_and_pixels,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_png_bad_specs, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_png_directories, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
