// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc: the .rdl statements of the 3D stage on a sim: device.  Each
 * statement must send the words docs/commands.md gives (compared with a
 * batch built by rdc_batch_cmd from the documented encoding), the host
 * statements must put the documented bytes into VRAM, and malformed
 * statements must fail at their line with nothing sent.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "script_fx.h"
#include "rdc_regs.h"

#define SCREEN_BYTES (320 * 200 * 4)

static uint32_t reg(rdc_dev *dev, uint32_t r)
{
	uint32_t v = 0;

	assert_int_equal(rdc_reg_read(dev, r, &v), 0);
	return v;
}

static uint32_t fnv(const uint8_t *p, size_t n)
{
	uint32_t h = 2166136261u;

	for (size_t i = 0; i < n; i++)
		h = (h ^ p[i]) * 16777619u;
	return h;
}

static uint32_t screen_hash(rdc_dev *dev)
{
	static uint8_t buf[SCREEN_BYTES];

	assert_int_equal(rdc_vram_read(dev, 0, buf, sizeof(buf)), 0);
	return fnv(buf, sizeof(buf));
}

#define FX(v) ((uint32_t)(int32_t)((v)*65536))

static const char scene_setup[] = "mode 320x200 xrgb8888\n"
				  "fg #000000\n"
				  "fill 0 0 320 200\n"
				  "zbuf 0x100000 640 test write\n"
				  "clear-z 0xffff\n";

/* The statements, then the same commands as words: the same picture. */
static void test_statements_encode(void **state)
{
	rdc_dev *dev = *state;
	rdc_batch *b;
	uint32_t h1, h2, w[49];
	static const uint32_t cube_v[] = {
		FX(-1), FX(-1), FX(1), FX(1), FX(-1),
		FX(1),	FX(0),	FX(1), FX(0),
	};

	assert_int_equal(run(dev, scene_setup), 0);
	assert_int_equal(run(dev,
			     "view perspective vrp 0 0 0 vpn 0 0 1 vup 0 1 0 "
			     "prp 0.5 0 6 "
			     "window -2 2 -1.25 1.25 front 3 back -4\n"
			     "viewport3 0 0 319 199\n"
			     "ambient #101010\n"
			     "light 0 #ffffff 0 0 1\n"
			     "light 1 #ff0000 1 0 0.5\n"
			     "light 1 off\n"
			     "material #808080 #c0c0c0 #ffffff 12\n"
			     "matrix identity\n"
			     "push\n"
			     "rotate y 30\n"
			     "translate 0.25 0 0\n"
			     "scale 1.5\n"
			     "vertices 0x180000 -1 -1 1 1 -1 1 0 1 0\n"
			     "indices 0x181000 0 1 2\n"
			     "mesh 0x180000 3 0x181000 1 lit two-sided\n"
			     "pop\n"
			     "fg #ffff00\n"
			     "bezier3 -1 -1 0 -1 1 0 1 1 0 1 -1 0 steps 12\n"
			     "bspline3 -1 0 0 -0.5 0.5 1 0.5 -0.5 -1 1 0 0 "
			     "1.5 1 0.5\n"),
			 0);
	assert_int_equal(reg(dev, RDC_REG_ERR_CODE), 0);
	h1 = screen_hash(dev);
	/* the same from words */
	assert_int_equal(run(dev, scene_setup), 0);
	b = rdc_batch_new();
	assert_non_null(b);
	{
		const uint32_t view[18] = {
			0,	0,     0,	  0,	    0,	   FX(1),
			0,	FX(1), 0,	  FX(0.5),  0,	   FX(6),
			FX(-2), FX(2), FX(-1.25), FX(1.25), FX(3), FX(-4),
		};
		const uint32_t vp[2] = { RDC_XY(0, 0), RDC_XY(319, 199) };
		const uint32_t amb = 0x101010,
			       l0[4] = { 0xffffff, 0, 0, FX(1) };
		const uint32_t l1[4] = { 0xff0000, FX(1), 0, FX(0.5) };
		const uint32_t mat[4] = { 0x808080, 0xc0c0c0, 0xffffff, 12 };
		const uint32_t rot = 5461; /* 30 degrees: 5461.33, rounded */
		const uint32_t tr[3] = { FX(0.25), 0, 0 };
		const uint32_t sc[3] = { FX(1.5), FX(1.5), FX(1.5) };
		const uint32_t mesh[4] = { 0x180000, 3, 0x181000, 1 };
		const uint32_t fg = 0xffff00;

		assert_int_equal(rdc_batch_cmd(b, RDC_OP_SET_VIEW,
					       RDC_VIEW_PERSPECTIVE, view, 18),
				 0);
		assert_int_equal(
			rdc_batch_cmd(b, RDC_OP_SET_VIEWPORT3, 0, vp, 2), 0);
		assert_int_equal(
			rdc_batch_cmd(b, RDC_OP_SET_AMBIENT, 0, &amb, 1), 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_SET_LIGHT, 0, l0, 4),
				 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_SET_LIGHT, 1, l1, 4),
				 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_SET_LIGHT, 1, NULL, 0),
				 0);
		assert_int_equal(
			rdc_batch_cmd(b, RDC_OP_SET_MATERIAL, 0, mat, 4), 0);
		assert_int_equal(
			rdc_batch_cmd(b, RDC_OP_MATRIX_LOAD, 0, NULL, 0), 0);
		assert_int_equal(
			rdc_batch_cmd(b, RDC_OP_PUSH_MATRIX, 0, NULL, 0), 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_ROTATE, RDC_AXIS_Y,
					       &rot, 1),
				 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_TRANSLATE, 0, tr, 3),
				 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_SCALE, 0, sc, 3), 0);
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_MESH,
					       RDC_MESH_LIT |
						       RDC_MESH_TWO_SIDED,
					       mesh, 4),
				 0);
		assert_int_equal(
			rdc_batch_cmd(b, RDC_OP_POP_MATRIX, 0, NULL, 0), 0);
		assert_int_equal(rdc_batch_fg(b, fg), 0);
		for (int i = 0; i < 12; i++)
			w[i] = (uint32_t[]){ FX(-1), FX(-1), 0,	     FX(-1),
					     FX(1),  0,	     FX(1),  FX(1),
					     0,	     FX(1),  FX(-1), 0 }[i];
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_BEZIER3, 12, w, 12),
				 0);
		for (int i = 0; i < 15; i++)
			w[i] = (uint32_t[]){ FX(-1),  0,     0,	      FX(-0.5),
					     FX(0.5), FX(1), FX(0.5), FX(-0.5),
					     FX(-1),  FX(1), 0,	      0,
					     FX(1.5), FX(1), FX(0.5) }[i];
		assert_int_equal(rdc_batch_cmd(b, RDC_OP_BSPLINE3, 0, w, 15),
				 0);
	}
	/* the vertex and index bytes as documented: little-endian */
	{
		uint8_t v[sizeof(cube_v)], ix[6];

		for (size_t i = 0; i < RDC_ARRAY_SIZE(cube_v); i++)
			for (int k = 0; k < 4; k++)
				v[4 * i + k] = (uint8_t)(cube_v[i] >> (8 * k));
		ix[0] = 0, ix[1] = 0, ix[2] = 1, ix[3] = 0, ix[4] = 2,
		ix[5] = 0;
		assert_int_equal(rdc_vram_write(dev, 0x180000, v, sizeof(v)),
				 0);
		assert_int_equal(rdc_vram_write(dev, 0x181000, ix, sizeof(ix)),
				 0);
	}
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_idle_wait(dev), 0);
	rdc_batch_free(b);
	assert_int_equal(reg(dev, RDC_REG_ERR_CODE), 0);
	h2 = screen_hash(dev);
	assert_int_equal(h1, h2);
	/* and something was drawn */
	assert_int_equal(run(dev, scene_setup), 0);
	assert_int_not_equal(screen_hash(dev), h1);
}

/* The host statements write exactly the documented bytes. */
static void test_vertices_indices(void **state)
{
	rdc_dev *dev = *state;
	uint8_t got[16];
	static const uint8_t want_v[12] = {
		0x00, 0x80, 0x00, 0x00, /* 0.5 */
		0x00, 0x00, 0xfe, 0xff, /* -2 */
		0x01, 0x00, 0x00, 0x00, /* 1/65536 */
	};
	static const uint8_t want_i[6] = { 1, 0, 0xff, 0xff, 0x34, 0x12 };

	assert_int_equal(run(dev, "vertices 0x200000 0.5 -2 0.0000153\n"
				  "indices 0x200100 1 65535 0x1234\n"),
			 0);
	assert_int_equal(rdc_vram_read(dev, 0x200000, got, 12), 0);
	assert_memory_equal(got, want_v, 12);
	assert_int_equal(rdc_vram_read(dev, 0x200100, got, 6), 0);
	assert_memory_equal(got, want_i, 6);
}

/* Malformed statements: a parse error at the right line, nothing sent. */
static void test_statement_errors(void **state)
{
	rdc_dev *dev = *state;
	static const char *const bad[] = {
		"view oblique vrp 0 0 0 vpn 0 0 1 vup 0 1 0 prp 0 0 1 "
		"window -1 1 -1 1 front 1 back -1\n",
		"view parallel vrp 0 0 0 vpn 0 0 1 vup 0 1 0 prp 0 0 1 "
		"window -1 1 -1 1 back -1 front 1\n",
		"rotate w 10\n",
		"matrix 1 2 3\n",
		"light 4 #ffffff 0 0 1\n",
		"light 0 #ffffff 0 0\n",
		"material #ffffff #ffffff #ffffff 0\n",
		"mesh 0 3 0 1 shiny\n",
		"patch 33 lit 0 0 0\n",
		"patch 4 lit 0 0 0\n",
		"bezier3 0 0 0 1 1 1 2 2 2 3 3 3 steps 0\n",
		"bspline3 0 0 0 1 1 1 2 2 2\n",
		"bspline3 0 0 0 1 1 1 2 2 2 3 3 3 4\n",
		"bspline3 0 0 0 1 1 1 2 2 2 3 3 3 steps 256\n",
		"translate 1 2\n",
		"indices 0 65536\n",
		"vertices 0 40000\n",
	};
	uint32_t cmds = reg(dev, RDC_REG_PERF_CMDS);

	for (size_t i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
		char text[512];

		snprintf(text, sizeof(text), "# line 1\n%s", bad[i]);
		assert_int_equal(run(dev, text), RDC_E_PARSE);
		assert_int_equal(res.error_line, 2);
	}
	assert_int_equal(reg(dev, RDC_REG_PERF_CMDS), cmds);
}

/* Device errors of the 3D commands come back as script errors. */
static void test_device_errors(void **state)
{
	rdc_dev *dev = *state;

	assert_int_not_equal(run(dev, "mode 320x200 xrgb8888\n"
				      "pop\n"),
			     0);
	assert_int_equal(res.error_line, 2);
	assert_int_not_equal(run(dev, "view perspective vrp 0 0 0 vpn 0 0 0 "
				      "vup 0 1 0 prp 0 0 1 window -1 1 -1 1 "
				      "front 0.5 back -1\n"),
			     0);
	assert_int_equal(res.error_line, 1);
}

/*
 * mesh ... scanline bounds: the box before the vertices, the scan-line
 * mode giving the depth buffer's picture, and a box outside culled.
 */
static void test_mesh_scanline_bounds(void **state)
{
	rdc_dev *dev = *state;
	static const char model[] =
		"view parallel vrp 0 0 0 vpn 0 0 1 vup 0 1 0 prp 0 0 5 "
		"window -2 2 -1.25 1.25 front 2 back -2\n"
		"viewport3 0 0 319 199\n"
		"matrix identity\n"
		"vertices 0x180000 -1.5 -1 -1 1.5 1 1 "
		"-1.5 -1 0  1 -0.5 0  0 1 0 "
		"-1 0.8 1  1.5 -1 -1  0.5 1 -1\n"
		"indices 0x181000 0 1 2 3 4 5\n"
		"fg #ffffff\n";
	uint32_t empty, hz, hs, hc;

	assert_int_equal(run(dev, scene_setup), 0);
	empty = screen_hash(dev);
	assert_int_equal(run(dev, model), 0);
	assert_int_equal(run(dev, "mesh 0x180018 6 0x181000 2\n"), 0);
	hz = screen_hash(dev);
	assert_int_not_equal(hz, empty);
	assert_int_equal(run(dev, scene_setup), 0);
	assert_int_equal(run(dev, model), 0);
	assert_int_equal(run(dev,
			     "zbuf off\n"
			     "mesh 0x180000 6 0x181000 2 scanline bounds\n"),
			 0);
	assert_int_equal(reg(dev, RDC_REG_ERR_CODE), 0);
	hs = screen_hash(dev);
	assert_int_equal(hs, hz);
	assert_int_equal(run(dev, scene_setup), 0);
	assert_int_equal(run(dev, model), 0);
	assert_int_equal(run(dev, "translate 9 0 0\n"
				  "mesh 0x180000 6 0x181000 2 bounds\n"),
			 0);
	assert_int_equal(reg(dev, RDC_REG_ERR_CODE), 0);
	hc = screen_hash(dev);
	assert_int_equal(hc, empty);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_statements_encode,
						dev_setup, dev_teardown),
		cmocka_unit_test_setup_teardown(test_vertices_indices,
						dev_setup, dev_teardown),
		cmocka_unit_test_setup_teardown(test_statement_errors,
						dev_setup, dev_teardown),
		cmocka_unit_test_setup_teardown(test_device_errors, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_mesh_scanline_bounds,
						dev_setup, dev_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
