// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * MESH's bounding-box culling: RDC_MESH_BOUNDS must cull a mesh whose box
 * lies outside the view volume before reading a vertex or an index
 * (counted, for the box's read and eight corner transforms), and never
 * one that could draw.
 */
#include "test_dp_common.h"

#define SW     640
#define SH     480
#define STRIDE (SW * 4)
#define ZBASE  0x200000u
#define VBASE  0x300000u
#define IBASE  0x380000u
#define NTRI   24
#define ZSIZE  (SW * 2 * SH)

static const struct rdc_surface screen = { 0, STRIDE, SW, SH,
					   RDC_FMT_XRGB8888 };

static int32_t fxi(int32_t num, int32_t den)
{
	return (int32_t)((int64_t)num * 65536 / den);
}

/* a view of the box [-2, 2] x [-1.5, 1.5] x [2, -6], z towards the eye */
static void send_view(struct tdp *t, bool persp, int32_t vx0, int32_t vy0)
{
	const uint32_t a[18] = { 0,
				 0,
				 0,
				 0,
				 0,
				 65536,
				 0,
				 65536,
				 0,
				 0,
				 0,
				 4 * 65536,
				 (uint32_t)(-2 * 65536),
				 2 * 65536,
				 (uint32_t)fxi(-3, 2),
				 (uint32_t)fxi(3, 2),
				 2 * 65536,
				 (uint32_t)(-6 * 65536) };

	tdp_cmd(t, RDC_OP_SET_VIEW, persp ? RDC_VIEW_PERSPECTIVE : 0, 18, a);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT3, RDC_XY(vx0, vy0),
		RDC_XY(SW - 1 - vx0, SH - 1 - vy0));
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
}

static void zbuf_on(struct tdp *t)
{
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST | RDC_Z_WRITE, 2,
		(const uint32_t[]){ ZBASE, SW * 2 });
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
}

/* fl: RDC_MESH_* flags, and RDC_MESH_BOUNDS for the vcount word's bit */
static void mesh(struct tdp *t, uint32_t fl, uint32_t vbase, uint32_t nv,
		 uint32_t nt)
{
	tdp_cmd(t, RDC_OP_MESH, fl & ~RDC_MESH_BOUNDS, 4,
		(const uint32_t[]){ vbase, nv | (fl & RDC_MESH_BOUNDS), IBASE,
				    nt });
}

static uint64_t last_cycles(struct tdp *t)
{
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	return rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
}

static uint64_t fetch_cost(uint32_t args)
{
	return (1 + args) * RDC_T_FIFO_WORD + RDC_T_DECODE;
}

static uint32_t culled(struct tdp *t)
{
	struct rdc_dp_view v;

	assert_true(rdc_dp_view_get(&t->hw, &v));
	return v.meshes_culled;
}

static uint32_t screen_hash(struct tdp *t)
{
	return tdp_fnv(2166136261u, t->vram, STRIDE * SH);
}

/*
 * nt triangles at vbase, triangle i in the depth slab around
 * z = 1.6 - 0.3 k (k a permutation of i, so the mesh order is not the
 * depth order), its vertices anywhere in x, y over a range wider than the
 * window (many cross the volume's sides and are clipped); vertices with
 * normals, each triangle 0 1 2, 3 4 5, ... in the index buffer.
 */
static void rand_scene(struct tdp *t, uint32_t *seed, uint32_t vbase,
		       uint32_t nt)
{
	uint32_t perm[NTRI], i, k, c;

	for (i = 0; i < nt; i++)
		perm[i] = i;
	for (i = nt; i-- > 1;) {
		uint32_t j = tdp_rand(seed) % (i + 1), s = perm[i];

		perm[i] = perm[j];
		perm[j] = s;
	}
	for (i = 0; i < nt; i++) {
		int32_t zc = fxi(16, 10) - (int32_t)perm[i] * fxi(3, 10);

		for (k = 0; k < 3; k++) {
			uint32_t v = 3 * i + k;
			int32_t p[6] = {
				tdp_range(seed, -3 * 65536, 3 * 65536),
				tdp_range(seed, -2 * 65536, 2 * 65536),
				zc + tdp_range(seed, -fxi(1, 10), fxi(1, 10)),
				tdp_range(seed, -65536, 65536),
				tdp_range(seed, -65536, 65536),
				65536,
			};

			for (c = 0; c < 6; c++)
				rdc_st32(t->vram + vbase + (6 * v + c) * 4,
					 (uint32_t)p[c]);
			rdc_st16(t->vram + IBASE + 2 * v, (uint16_t)v);
		}
	}
}

/* ---- RDC_MESH_BOUNDS ---------------------------------------------------- */

static void put_box(struct tdp *t, uint32_t at, const int32_t *b)
{
	for (int i = 0; i < 6; i++)
		rdc_st32(t->vram + at + 4 * i, (uint32_t)b[i]);
}

/*
 * A box outside the volume: culled (counted), for its fetch, the box's
 * read and eight corner transforms; its indices are not read (they are
 * out of range here), nothing is drawn.  A box inside: the mesh is drawn
 * as without BOUNDS.
 */
static void test_bounds_cull(void **state)
{
	struct tdp *t = *state;
	const int32_t out[6] = { 3 * 65536, -65536, -65536,
				 5 * 65536, 65536,  65536 };
	const int32_t in[6] = { -3 * 65536, -2 * 65536, -2 * 65536,
				3 * 65536,  2 * 65536,	2 * 65536 };
	uint32_t seed = 0xb0c5, open, n0, h0, h1;
	uint64_t want;

	tdp_set_surface(t, RDC_OP_SET_DST, &screen);
	TDP_CMD(t, RDC_OP_SET_FG, 0xffffff);
	send_view(t, true, 0, 0);
	zbuf_on(t);
	rand_scene(t, &seed, VBASE + 24, 8);
	memset(t->vram, 0, STRIDE * SH);
	h0 = screen_hash(t);
	n0 = culled(t);

	/* outside: the indices say 0xffff, a RANGE error were they read */
	for (uint32_t i = 0; i < 24; i++)
		rdc_st16(t->vram + IBASE + 2 * i, 0xffff);
	put_box(t, VBASE, out);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = fetch_cost(4) + tdp_bus_span(&open, VBASE, 24, TDP_BUS_READ) +
	       8 * RDC_T_VERTEX3;
	mesh(t, RDC_MESH_NORMALS | RDC_MESH_BOUNDS, VBASE, 24, 8);
	assert_int_equal(last_cycles(t), want);
	assert_int_equal(culled(t), n0 + 1);
	assert_int_equal(screen_hash(t), h0);
	/* without BOUNDS the bad indices are read */
	mesh(t, RDC_MESH_NORMALS, VBASE + 24, 24, 8);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	tdp_clear_err(t);

	/* inside: drawn as without the box */
	for (uint32_t i = 0; i < 24; i++)
		rdc_st16(t->vram + IBASE + 2 * i, (uint16_t)i);
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
	mesh(t, RDC_MESH_NORMALS, VBASE + 24, 24, 8);
	tdp_drain(t);
	h1 = screen_hash(t);
	assert_int_not_equal(h1, h0);
	memset(t->vram, 0, STRIDE * SH);
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
	put_box(t, VBASE, in);
	mesh(t, RDC_MESH_NORMALS | RDC_MESH_BOUNDS, VBASE, 24, 8);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(screen_hash(t), h1);
	assert_int_equal(culled(t), n0 + 1);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
	tdp_drain(t);
}

/*
 * Random small meshes in their exact boxes under random transforms: a
 * culled mesh is one that draws nothing without BOUNDS, and most of the
 * meshes outside the volume are culled.
 */
static void test_bounds_conservative(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0xc0115, n0, ncull = 0, nempty = 0;

	tdp_set_surface(t, RDC_OP_SET_DST, &screen);
	TDP_CMD(t, RDC_OP_SET_FG, 0xffffff);
	for (int it = 0; it < 200; it++) {
		int32_t b[6] = { INT32_MAX, INT32_MAX, INT32_MAX,
				 INT32_MIN, INT32_MIN, INT32_MIN };
		uint32_t h, i;
		bool cull;

		send_view(t, it & 1, 0, 0);
		tdp_cmd(t, RDC_OP_TRANSLATE, 0, 3,
			(const uint32_t[]){
				(uint32_t)tdp_range(&seed, -8 * 65536,
						    8 * 65536),
				(uint32_t)tdp_range(&seed, -6 * 65536,
						    6 * 65536),
				(uint32_t)tdp_range(&seed, -9 * 65536,
						    3 * 65536) });
		tdp_cmd(t, RDC_OP_ROTATE, RDC_AXIS_Y, 1,
			(const uint32_t[]){ tdp_rand(&seed) & 0xffff });
		rand_scene(t, &seed, VBASE + 24, 4);
		for (i = 0; i < 12; i++)
			for (int k = 0; k < 3; k++) {
				int32_t c = (int32_t)rdc_ld32(
					t->vram + VBASE + 24 + (6 * i + k) * 4);

				b[k] = c < b[k] ? c : b[k];
				b[k + 3] = c > b[k + 3] ? c : b[k + 3];
			}
		put_box(t, VBASE, b);
		memset(t->vram, 0, STRIDE * SH);
		n0 = culled(t);
		mesh(t, RDC_MESH_NORMALS | RDC_MESH_BOUNDS, VBASE, 12, 4);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		cull = culled(t) != n0;
		mesh(t, RDC_MESH_NORMALS, VBASE + 24, 12, 4);
		tdp_drain(t);
		h = screen_hash(t);
		memset(t->vram, 0, STRIDE * SH);
		if (h == screen_hash(t))
			nempty++;
		else
			assert_false(cull);
		ncull += cull;
	}
	assert_true(ncull > 20);
	assert_true(ncull <= nempty);
	print_message("%u of 200 culled, %u drew nothing\n", ncull, nempty);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_bounds_cull),
		TDP_TEST(test_bounds_conservative),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
