// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Random 3D command streams: the opcodes 0x40..0x52 (and their neighbours
 * that are not commands) with random lengths and arguments drawn from a
 * mix of ordinary 15.16 values, zeros and the extremes of int32; MESH
 * buffers anywhere in VRAM, against its end, full of random bytes; views
 * that are valid, degenerate and absurd.  Under ASan and UBSan any
 * out-of-bounds access or signed overflow aborts the program.  Nothing
 * may be written outside the destination surface and the depth surface,
 * and afterwards the DP must still draw a known mesh the same way as a
 * fresh chip does.
 */
#include <stdio.h>

#include "test_dp_common.h"

#define F_W	 320u
#define F_H	 200u
#define F_STRIDE (F_W * 4u)
#define F_ZBASE	 0x100000u
#define F_BUFS	 0x200000u /* random vertex and index data from here */
#define F_IDX	 0x380000u /* indices below 16 from here */
#define F_CMDS	 6000u

static const uint8_t ops[] = {
	RDC_OP_MATRIX_LOAD,
	RDC_OP_MATRIX_MULT,
	RDC_OP_TRANSLATE,
	RDC_OP_SCALE,
	RDC_OP_ROTATE,
	RDC_OP_PUSH_MATRIX,
	RDC_OP_POP_MATRIX,
	RDC_OP_SET_VIEW,
	RDC_OP_SET_VIEWPORT3,
	RDC_OP_SET_LIGHT,
	RDC_OP_SET_AMBIENT,
	RDC_OP_SET_MATERIAL,
	RDC_OP_MESH,
	RDC_OP_MESH,
	RDC_OP_MESH,
	RDC_OP_PATCH,
	RDC_OP_BEZIER3,
	RDC_OP_BSPLINE3,
	0x47,
	0x4d,
	0x54,
};

/* Mostly modest 15.16 numbers, sometimes 0 or an extreme. */
static uint32_t rnd_fix(uint32_t *rng)
{
	switch (tdp_rand(rng) % 16) {
	case 0:
		return 0;
	case 1:
		return tdp_rand(rng);
	case 2:
		return 0x7fffffffu - tdp_rand(rng) % 4;
	case 3:
		return 0x80000000u + tdp_rand(rng) % 4;
	default:
		return (uint32_t)tdp_range(rng, -6 * 65536, 6 << 16);
	}
}

/* A view that is usually sensible, sometimes degenerate. */
static void rnd_view(uint32_t *rng, uint32_t *a)
{
	for (int i = 0; i < 18; i++)
		a[i] = (uint32_t)tdp_range(rng, -3 * 65536, 3 << 16);
	a[11] = (uint32_t)tdp_range(rng, 4 << 16, 12 << 16); /* prp n */
	a[12] = (uint32_t)tdp_range(rng, -3 * 65536, -1 * 65536);
	a[13] = (uint32_t)tdp_range(rng, 1 << 16, 3 << 16);
	a[14] = (uint32_t)tdp_range(rng, -3 * 65536, -1 * 65536);
	a[15] = (uint32_t)tdp_range(rng, 1 << 16, 3 << 16);
	a[16] = (uint32_t)tdp_range(rng, 0, 3 << 16);
	a[17] = (uint32_t)tdp_range(rng, -20 * 65536, -1 * 65536);
	if (tdp_rand(rng) % 4 == 0)
		a[tdp_rand(rng) % 18] = rnd_fix(rng);
}

static uint32_t rnd_addr(uint32_t *rng)
{
	switch (tdp_rand(rng) % 4) {
	case 0:
		return TDP_VRAM_SIZE - (tdp_rand(rng) % 64);
	case 1:
		return tdp_rand(rng);
	default:
		return F_BUFS + (tdp_rand(rng) % 0x40000) * 4;
	}
}

static void fuzz_cmd(struct tdp *t, uint32_t *rng)
{
	uint32_t op = ops[tdp_rand(rng) % sizeof(ops)], a[64], n, fl = 0;
	int fixed = rdc_cmd_args(op);

	n = fixed >= 0 ? (uint32_t)fixed : tdp_rand(rng) % 2 ? 12 : 0;
	if (op == RDC_OP_SET_LIGHT)
		n = tdp_rand(rng) % 3 ? 4 : 0;
	for (uint32_t i = 0; i < RDC_ARRAY_SIZE(a); i++)
		a[i] = rnd_fix(rng);
	switch (op) {
	case RDC_OP_SET_VIEW:
		rnd_view(rng, a);
		fl = tdp_rand(rng) % 2;
		break;
	case RDC_OP_SET_VIEWPORT3:
		a[0] = RDC_XY(tdp_range(rng, -50, 200),
			      tdp_range(rng, -50, 150));
		a[1] = RDC_XY(tdp_range(rng, 0, 400), tdp_range(rng, 0, 300));
		break;
	case RDC_OP_ROTATE:
		fl = tdp_rand(rng) % 4;
		break;
	case RDC_OP_SET_LIGHT:
		fl = tdp_rand(rng) % 5;
		a[0] &= 0xffffff;
		break;
	case RDC_OP_SET_AMBIENT:
		a[0] &= 0xffffff;
		break;
	case RDC_OP_SET_MATERIAL:
		a[0] &= 0xffffff;
		a[1] &= 0xffffff;
		a[2] &= 0xffffff;
		a[3] = tdp_rand(rng) % 260;
		break;
	case RDC_OP_MESH:
		if (tdp_rand(rng) % 4) {
			/* indices that fit 16 vertices: mostly drawn */
			a[0] = F_BUFS + (tdp_rand(rng) % 0x10000) * 4;
			a[1] = 16 + tdp_rand(rng) % 48;
			a[2] = F_IDX + (tdp_rand(rng) % 0x8000) * 2;
			a[3] = tdp_rand(rng) % 300;
			fl = tdp_rand(rng) & 0x7f;
			break;
		}
		a[0] = rnd_addr(rng);
		a[1] = tdp_rand(rng) % 8 ?
			       tdp_rand(rng) % 64 :
			       tdp_rand(rng) % (RDC_MESH_MAX_VERTS + 2);
		a[2] = rnd_addr(rng);
		a[3] = tdp_rand(rng) % 8 ?
			       tdp_rand(rng) % 64 :
			       tdp_rand(rng) % (RDC_MESH_MAX_TRIS + 2);
		fl = tdp_rand(rng) % 8 ? tdp_rand(rng) & 0x7f :
					 tdp_rand(rng) & 0xff;
		break;
	case RDC_OP_PATCH:
		a[0] = (tdp_rand(rng) & 0x7f) | (tdp_rand(rng) % 12) << 8;
		if (tdp_rand(rng) % 16 == 0)
			a[0] = tdp_rand(rng);
		break;
	case RDC_OP_BEZIER3:
		fl = tdp_rand(rng) % 40;
		break;
	case RDC_OP_BSPLINE3:
		fl = tdp_rand(rng) % 40;
		n = 3 * (4 + tdp_rand(rng) % 18); /* 4..21 points */
		break;
	default:
		break;
	}
	if (tdp_rand(rng) % 32 == 0)
		n = tdp_rand(rng) % 60; /* a wrong length */
	tdp_cmd(t, op, fl, n, a);
}

/* A small lit, culled, depth-buffered sphere-like octahedron. */
static void known_scene(struct tdp *t)
{
	static const int32_t v[6][3] = {
		{ 1, 0, 0 },  { -1, 0, 0 }, { 0, 1, 0 },
		{ 0, -1, 0 }, { 0, 0, 1 },  { 0, 0, -1 },
	};
	static const uint16_t ix[24] = {
		0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
		2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
	};
	const uint32_t base = 0x3f0000, ibase = 0x3f1000;

	for (int i = 0; i < 6; i++)
		for (int k = 0; k < 3; k++) {
			rdc_st32(t->vram + base + (6 * i + k) * 4,
				 (uint32_t)(v[i][k] * 65536));
			rdc_st32(t->vram + base + (6 * i + 3 + k) * 4,
				 (uint32_t)(v[i][k] * 65536));
		}
	for (int i = 0; i < 24; i++)
		rdc_st16(t->vram + ibase + 2 * i, ix[i]);
	memset(t->vram, 0, F_STRIDE * F_H);
	TDP_CMD(t, RDC_OP_SET_DST, 0, F_STRIDE, RDC_WH(F_W, F_H),
		RDC_FMT_XRGB8888);
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST | RDC_Z_WRITE, 2,
		(const uint32_t[]){ F_ZBASE, F_W * 2 });
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT3, RDC_XY(0, 0),
		RDC_XY(F_W - 1, F_H - 1));
	tdp_cmd(t, RDC_OP_SET_VIEW, RDC_VIEW_PERSPECTIVE, 18,
		(const uint32_t[]){ 0, 0, 0, 1 << 16, 1 << 16, 2 << 16, 0,
				    1 << 16, 0, 0, 0, 6 << 16,
				    (uint32_t)(-2 * 65536), 2 << 16,
				    (uint32_t)(-5 * 32768), 5 << 15, 3 << 16,
				    (uint32_t)(-3 * 65536) });
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_SET_AMBIENT, 0x202020);
	TDP_CMD(t, RDC_OP_SET_MATERIAL, 0xff8040, 0xff8040, 0xffffff, 20);
	TDP_CMD(t, RDC_OP_SET_LIGHT, 0xffffff, 1 << 16, 2 << 16, 3 << 16);
	for (uint32_t l = 1; l < RDC_LIGHTS; l++)
		tdp_cmd(t, RDC_OP_SET_LIGHT, l, 0, NULL);
	tdp_cmd(t, RDC_OP_MESH,
		RDC_MESH_NORMALS | RDC_MESH_CULL | RDC_MESH_LIT |
			RDC_MESH_GOURAUD,
		4, (const uint32_t[]){ base, 6, ibase, 8 });
	tdp_drain(t);
}

static void test_fuzz_3d(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 0x3df0022u, h_fresh, h_after, errors = 0;
	uint8_t *shadow = malloc(TDP_VRAM_SIZE);

	assert_non_null(shadow);
	/* the reference picture from a fresh chip */
	known_scene(t);
	assert_int_equal(tdp_err(t), 0);
	h_fresh = tdp_fnv(2166136261u, t->vram, F_STRIDE * F_H);
	/* random buffers */
	for (uint32_t i = F_BUFS; i < F_IDX; i += 4)
		rdc_st32(t->vram + i,
			 tdp_rand(&rng) % 4 ? rnd_fix(&rng) : tdp_rand(&rng));
	for (uint32_t i = F_IDX; i < TDP_VRAM_SIZE; i += 2)
		rdc_st16(t->vram + i, tdp_rand(&rng) % 16);
	TDP_CMD(t, RDC_OP_SET_DST, 0, F_STRIDE, RDC_WH(F_W, F_H),
		RDC_FMT_XRGB8888);
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST | RDC_Z_WRITE, 2,
		(const uint32_t[]){ F_ZBASE, F_W * 2 });
	tdp_drain(t);
	memcpy(shadow, t->vram, TDP_VRAM_SIZE);
	for (uint32_t i = 0; i < F_CMDS; i++) {
		fuzz_cmd(t, &rng);
		if (i % 64 == 63) {
			tdp_drain(t);
			if (tdp_err(t))
				errors++;
			tdp_clear_err(t);
		}
	}
	tdp_drain(t);
	assert_int_not_equal(tdp_fnv(2166136261u, t->vram, F_STRIDE * F_H),
			     tdp_fnv(2166136261u, shadow, F_STRIDE * F_H));
	/* only DST and the depth surface may have changed */
	for (uint32_t i = 0; i < TDP_VRAM_SIZE; i++) {
		bool dst = i < F_STRIDE * F_H;
		bool z = i >= F_ZBASE && i < F_ZBASE + F_W * 2 * F_H;

		if (!dst && !z && t->vram[i] != shadow[i])
			fail_msg("VRAM byte 0x%x changed outside the surfaces",
				 i);
	}
	free(shadow);
	printf("3d fuzz: %u commands, errors seen in %u of %u batches, "
	       "%llu DP cycles\n",
	       F_CMDS, errors, F_CMDS / 64,
	       (unsigned long long)t->hw.perf.busy);
	assert_true(errors > 0); /* the stream did hit the checks */
	/* a soft reset, then the known picture again */
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	tdp_clear_err(t);
	known_scene(t);
	assert_int_equal(tdp_err(t), 0);
	h_after = tdp_fnv(2166136261u, t->vram, F_STRIDE * F_H);
	assert_int_equal(h_after, h_fresh);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_fuzz_3d),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
