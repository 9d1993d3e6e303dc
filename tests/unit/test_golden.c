// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Golden frames: every scene in tests/golden/scenes through librdc, checked
 * against the CRC-32 and cycle count in tests/golden/golden.txt (written
 * by tests/golden/regen.sh from what rdcctl run prints).  Also: the same
 * script on two devices gives identical pictures and cycle counts.
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"

#define GOLDEN_DIR	"tests/golden"
#define GOLDEN_LIST	GOLDEN_DIR "/golden.txt"
#define SCENE_DIR	GOLDEN_DIR "/scenes"
#define GOLDEN_MAX	256
#define GOLDEN_NAME_MAX 64

struct golden {
	char name[GOLDEN_NAME_MAX];
	uint32_t crc;
	unsigned long long cycles;
};

static struct golden goldens[GOLDEN_MAX];
static size_t ngoldens;

static int golden_load(void)
{
	FILE *f = fopen(GOLDEN_LIST, "r");
	char line[256];

	if (!f)
		return -1;
	ngoldens = 0;
	while (fgets(line, sizeof(line), f) && ngoldens < GOLDEN_MAX) {
		struct golden *g = &goldens[ngoldens];
		unsigned int crc;

		if (line[0] == '#' || line[0] == '\n')
			continue;
		if (sscanf(line, "%63s %x %llu", g->name, &crc, &g->cycles) !=
		    3)
			continue;
		g->crc = crc;
		ngoldens++;
	}
	fclose(f);
	return 0;
}

/* What rdcctl run measures: time at the script's end, then the picture. */
static int golden_run(const char *path, uint32_t *crc,
		      unsigned long long *cycles, struct rdc_script_result *res,
		      uint32_t **pix, uint32_t *w, uint32_t *h)
{
	rdc_dev *dev;
	uint64_t t;
	int ret;

	ret = rdc_open("sim:", &dev);
	if (ret)
		return ret;
	ret = rdc_script_run_file(dev, path, res);
	if (ret) {
		print_error("%s:%u: %s\n", path, res->error_line,
			    res->error_msg);
		goto out;
	}
	ret = rdc_sim_time(dev, &t);
	if (!ret)
		ret = rdc_script_frame_wait(dev, res);
	if (!ret)
		ret = rdc_frame_crc(dev, crc);
	if (!ret && pix) {
		ret = rdc_frame_grab(dev, NULL, 0, w, h);
		if (ret == RDC_E_RANGE) {
			*pix = malloc((size_t)*w * *h * sizeof(**pix));
			ret = *pix ? rdc_frame_grab(dev, *pix, (size_t)*w * *h,
						    w, h) :
				     RDC_E_NOMEM;
		}
	}
	*cycles = t;
out:
	rdc_close(dev);
	return ret;
}

static void test_golden_scenes(void **state)
{
	static struct rdc_script_result res;
	size_t failed = 0;

	(void)state;
	assert_int_equal(golden_load(), 0);
	assert_true(ngoldens > 0);
	for (size_t i = 0; i < ngoldens; i++) {
		const struct golden *g = &goldens[i];
		char path[256];
		uint32_t crc = 0;
		unsigned long long cycles = 0;
		int ret;

		snprintf(path, sizeof(path), SCENE_DIR "/%s.rdl", g->name);
		ret = golden_run(path, &crc, &cycles, &res, NULL, NULL, NULL);
		if (ret) {
			print_error("golden %s: %s\n", g->name,
				    rdc_strerror(ret));
			failed++;
			continue;
		}
		if (crc != g->crc || cycles != g->cycles) {
			print_error(
				"golden %s: crc32 %08x cycles %llu, "
				"expected crc32 %08x cycles %llu "
				"(make golden regenerates; look at the PNGs)\n",
				g->name, crc, cycles, g->crc, g->cycles);
			failed++;
		}
	}
	assert_int_equal(failed, 0);
}

/* Every scene file has a golden line: a new scene is not silently skipped. */
static void test_golden_every_scene_listed(void **state)
{
	DIR *d;
	struct dirent *e;
	size_t scenes = 0, missing = 0;

	(void)state;
	assert_int_equal(golden_load(), 0);
	d = opendir(SCENE_DIR);
	assert_non_null(d);
	while ((e = readdir(d))) {
		size_t len = strlen(e->d_name);
		bool found = false;

		if (len < 5 || strcmp(e->d_name + len - 4, ".rdl"))
			continue;
		scenes++;
		for (size_t i = 0; i < ngoldens; i++)
			if (strlen(goldens[i].name) == len - 4 &&
			    !strncmp(goldens[i].name, e->d_name, len - 4))
				found = true;
		if (!found) {
			print_error("scene %s has no line in " GOLDEN_LIST "\n",
				    e->d_name);
			missing++;
		}
	}
	closedir(d);
	assert_int_equal(scenes, ngoldens);
	assert_int_equal(missing, 0);
}

static void test_golden_determinism(void **state)
{
	static const char *const scenes[] = {
		SCENE_DIR "/rops.rdl",
		SCENE_DIR "/palette_midframe.rdl",
		SCENE_DIR "/blit_overlap.rdl",
	};
	static struct rdc_script_result r1, r2;

	(void)state;
	for (size_t s = 0; s < sizeof(scenes) / sizeof(*scenes); s++) {
		uint32_t *p1 = NULL, *p2 = NULL, w1 = 0, h1 = 0, w2 = 0, h2 = 0;
		uint32_t c1 = 0, c2 = 0;
		unsigned long long t1 = 0, t2 = 0;

		assert_int_equal(
			golden_run(scenes[s], &c1, &t1, &r1, &p1, &w1, &h1), 0);
		assert_int_equal(
			golden_run(scenes[s], &c2, &t2, &r2, &p2, &w2, &h2), 0);
		assert_non_null(p1);
		assert_non_null(p2);
		assert_int_equal(w1, w2);
		assert_int_equal(h1, h2);
		assert_memory_equal(p1, p2, (size_t)w1 * h1 * sizeof(*p1));
		assert_int_equal(c1, c2);
		assert_int_equal(t1, t2);
		assert_memory_equal(r1.op_cycles, r2.op_cycles,
				    sizeof(r1.op_cycles));
		assert_memory_equal(r1.op_count, r2.op_count,
				    sizeof(r1.op_count));
		free(p1);
		free(p2);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_golden_scenes),
		cmocka_unit_test(test_golden_every_scene_listed),
		cmocka_unit_test(test_golden_determinism),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
