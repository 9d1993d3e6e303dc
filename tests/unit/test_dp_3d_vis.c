// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * MESH's scan-line visible-surface mode and its bounding-box culling.
 *
 * RDC_MESH_SCANLINE must give the pixels of the depth-buffered path (a
 * depth buffer cleared to 0xffff, TEST and WRITE) on seeded random scenes
 * of triangles that do not intersect (each in a slab of depth of its
 * own), flat, lit flat and lit Gouraud, culled or not, many of them
 * clipped, under random parallel and perspective views, without touching
 * the depth surface; its cost is held to the cycle on a small scene: the
 * geometry, then each row's covered run written once.  RDC_MESH_BOUNDS
 * must cull a mesh whose box lies outside the view volume before reading
 * a vertex or an index (counted), and never one that could draw.
 */
#include <math.h>
#include <stdio.h>

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

/* Meshes culled: PERF_CULLED, which the DP's own count must equal. */
static uint32_t culled(struct tdp *t)
{
	struct rdc_dp_view v;
	uint32_t perf = rdc_hw_read(&t->hw, RDC_REG_PERF_CULLED);

	assert_true(rdc_dp_view_get(&t->hw, &v));
	assert_int_equal(perf, v.meshes_culled);
	return perf;
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

static void lights(struct tdp *t)
{
	TDP_CMD(t, RDC_OP_SET_AMBIENT, 0x202020);
	TDP_CMD(t, RDC_OP_SET_MATERIAL, 0x4080ff, 0xc0a060, 0xffffff, 12);
	TDP_CMD(t, RDC_OP_SET_LIGHT, 0xffffff, fxi(1, 2), fxi(4, 5), 65536);
}

/*
 * Random scenes: the scan-line mode against the depth buffer, pixel for
 * pixel; the depth surface is left alone by the scan-line mode.
 */
static void test_scan_equals_zbuf(void **state)
{
	static const uint32_t modes[4] = { 0, RDC_MESH_LIT,
					   RDC_MESH_LIT | RDC_MESH_GOURAUD,
					   RDC_MESH_LIT | RDC_MESH_GOURAUD |
						   RDC_MESH_TWO_SIDED };
	struct tdp *t = *state;
	uint32_t seed = 0x5ca71e, hz, hs, zh;
	unsigned long drawn = 0;

	tdp_set_surface(t, RDC_OP_SET_DST, &screen);
	TDP_CMD(t, RDC_OP_SET_FG, 0x80c040);
	lights(t);
	for (int it = 0; it < 48; it++) {
		uint32_t nt = 2 + tdp_rand(&seed) % (NTRI - 1);
		uint32_t fl = RDC_MESH_NORMALS | modes[it % 4] |
			      (it & 4 ? RDC_MESH_CULL : 0) |
			      (it & 8 ? RDC_MESH_SORT : 0);

		send_view(t, it & 1, (int32_t)(tdp_rand(&seed) % 64),
			  (int32_t)(tdp_rand(&seed) % 48));
		rand_scene(t, &seed, VBASE, nt);

		memset(t->vram, 0, STRIDE * SH);
		zbuf_on(t);
		mesh(t, fl, VBASE, 3 * nt, nt);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		hz = screen_hash(t);
		for (uint32_t i = 0; i < SW * SH; i++)
			drawn += rdc_ld32(t->vram + 4 * i) != 0;

		memset(t->vram, 0, STRIDE * SH);
		memset(t->vram + ZBASE, 0x5a, ZSIZE);
		zh = tdp_fnv(2166136261u, t->vram + ZBASE, ZSIZE);
		mesh(t, fl | RDC_MESH_SCANLINE, VBASE, 3 * nt, nt);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		hs = screen_hash(t);
		if (hs != hz)
			fail_msg(
				"scene %d (%u triangles, flags %#x): scan-line "
				"%08x, depth buffer %08x",
				it, nt, fl, hs, hz);
		assert_int_equal(tdp_fnv(2166136261u, t->vram + ZBASE, ZSIZE),
				 zh);
	}
	/* the scenes drew something: not a comparison of empty frames */
	assert_true(drawn > 48ul * 20000);
	tdp_cmd(t, RDC_OP_SET_LIGHT, 0, 0, NULL);
}

/*
 * Two overlapping triangles, unlit, under a parallel view of one unit a
 * pixel: MESH with SCANLINE costs its fetch, the index and vertex reads,
 * T_VERTEX3 a vertex and T_TRI3 a triangle, then one DST write span per
 * row's covered run, top to bottom; nothing else.
 */
static void test_scan_cycles(void **state)
{
	struct tdp *t = *state;
	static const int32_t p[6][3] = {
		{ -200, -150, 0 }, { 100, -120, 0 }, { -50, 160, 0 },
		{ -20, -100, 1 },  { 250, -40, 1 },  { 60, 180, 1 },
	};
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
				 (uint32_t)(-320 * 65536),
				 320 * 65536,
				 (uint32_t)(-240 * 65536),
				 240 * 65536,
				 2 * 65536,
				 (uint32_t)(-2 * 65536) };
	uint32_t open, rows = 0, i, k;

	uint64_t want, zcost;

	tdp_set_surface(t, RDC_OP_SET_DST, &screen);
	tdp_cmd(t, RDC_OP_SET_VIEW, 0, 18, a);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT3, RDC_XY(0, 0), RDC_XY(SW - 1, SH - 1));
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_SET_FG, 0xffffff);
	for (i = 0; i < 6; i++) {
		for (k = 0; k < 3; k++)
			rdc_st32(t->vram + VBASE + (3 * i + k) * 4,
				 (uint32_t)(p[i][k] * 65536));
		rdc_st16(t->vram + IBASE + 2 * i, (uint16_t)i);
	}
	memset(t->vram, 0, STRIDE * SH);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	mesh(t, RDC_MESH_SCANLINE, VBASE, 6, 2);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	want = fetch_cost(4) + tdp_bus_span(&open, IBASE, 12, TDP_BUS_READ) +
	       tdp_bus_span(&open, VBASE, 6 * 12, TDP_BUS_READ) +
	       6 * RDC_T_VERTEX3 + 2 * RDC_T_TRI3;
	/* each run of covered pixels of a row, as the frame shows them */
	for (int y = 0; y < SH; y++) {
		bool counted = false;

		for (int x = 0; x < SW;) {
			int x1 = x;

			while (x1 < SW &&
			       rdc_ld32(t->vram + (uint32_t)y * STRIDE +
					4u * x1))
				x1++;
			if (x1 == x) {
				x++;
				continue;
			}
			want += tdp_bus_span(&open,
					     (uint64_t)y * STRIDE + 4u * x,
					     4u * (x1 - x), TDP_BUS_WRITE);
			rows += !counted;
			counted = true;
			x = x1;
		}
	}
	assert_true(rows > 300);
	assert_int_equal(last_cycles(t), want);

	/* the depth-buffered path: more (the depth traffic, overdraw) */
	zbuf_on(t);
	memset(t->vram, 0, STRIDE * SH);
	tdp_drain(t);
	mesh(t, 0, VBASE, 6, 2);
	zcost = last_cycles(t);
	assert_int_equal(want, 40752);
	assert_int_equal(zcost, 94420);
	print_message("scan-line %llu cycles, depth buffer %llu\n",
		      (unsigned long long)want, (unsigned long long)zcost);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
}

/*
 * The cap: RDC_MESH_SCAN_MAX_TRIS triangles draw; a mesh whose clipped
 * triangles make more fan triangles than that is RANGE, nothing drawn.
 */
static void test_scan_errors(void **state)
{
	struct tdp *t = *state;
	/* inside the window [-2, 2] x [-1.5, 1.5]; then cut by x = +-2 */
	static const int32_t q[2][3][2] = {
		{ { -1, -1 }, { 1, -1 }, { 0, 1 } },
		{ { -3, -1 }, { 3, -1 }, { 0, 1 } }
	};
	uint32_t h0;

	tdp_set_surface(t, RDC_OP_SET_DST, &screen);
	send_view(t, false, 0, 0);
	for (uint32_t i = 0; i < 3 * RDC_MESH_MAX_TRIS; i++)
		rdc_st16(t->vram + IBASE + 2 * i, (uint16_t)(i % 3));
	for (int k = 0; k < 2; k++) {
		for (uint32_t i = 0; i < 3; i++) {
			rdc_st32(t->vram + VBASE + 12 * i,
				 (uint32_t)(q[k][i][0] * 65536));
			rdc_st32(t->vram + VBASE + 12 * i + 4,
				 (uint32_t)(q[k][i][1] * 65536));
			rdc_st32(t->vram + VBASE + 12 * i + 8, 0);
		}
		memset(t->vram, 0, STRIDE * SH);
		h0 = screen_hash(t);
		mesh(t, RDC_MESH_SCANLINE, VBASE, 3, RDC_MESH_MAX_TRIS);
		tdp_drain(t);
		if (!k) {
			assert_int_equal(tdp_err(t), 0);
			assert_int_not_equal(screen_hash(t), 0);
		} else {
			assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
			tdp_clear_err(t);
			assert_int_equal(screen_hash(t), h0);
		}
	}
	/* SCANLINE with WIRE: ARG */
	mesh(t, RDC_MESH_SCANLINE | RDC_MESH_WIRE, VBASE, 3, 1);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	tdp_clear_err(t);
	/* no depth surface needed */
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST, 2,
		(const uint32_t[]){ ZBASE, SW * 2 });
	tdp_drain(t);
	t->dp.st.z_base = TDP_VRAM_SIZE; /* no longer fits DST */
	mesh(t, 0, VBASE, 3, 1);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_SURFACE);
	tdp_clear_err(t);
	mesh(t, RDC_MESH_SCANLINE, VBASE, 3, 1);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
	tdp_drain(t);
}

/* ---- the teapot as one mesh ---------------------------------------------- */

#define TP_PATCHES 32
#define TP_N	   7 /* 32 (7 + 1)^2 = 2048 vertices: the vertex cache */
#define TP_NV	   (TP_PATCHES * (TP_N + 1) * (TP_N + 1))
#define TP_NT	   (TP_PATCHES * 2 * TP_N * TP_N)

static int32_t fxd(double d)
{
	return (int32_t)lround(d * 65536.0);
}

/* examples/teapot.rdl's 32 patches: 48 numbers after each "patch ..." */
static int read_patches(double (*cp)[48])
{
	FILE *f = fopen("examples/teapot.rdl", "r");
	char tok[64];
	int np = -1, k = 48;

	assert_non_null(f);
	while (fscanf(f, "%63s", tok) == 1) {
		char *end;
		double d = strtod(tok, &end);

		if (!strcmp(tok, "patch") && np + 1 < TP_PATCHES) {
			np++;
			k = -1; /* the steps next */
		} else if (np >= 0 && k < 48 && *end == 0 && end != tok) {
			if (k >= 0)
				cp[np][k] = d;
			k++;
		}
	}
	fclose(f);
	return np + 1;
}

static double bern(int i, double t)
{
	static const double c[4] = { 1, 3, 3, 1 };

	return c[i] * pow(t, i) * pow(1 - t, 3 - i);
}

static double dbern(int i, double t)
{
	switch (i) {
	case 0:
		return -3 * (1 - t) * (1 - t);
	case 1:
		return 3 * (1 - t) * (1 - t) - 6 * t * (1 - t);
	case 2:
		return 6 * t * (1 - t) - 3 * t * t;
	default:
		return 3 * t * t;
	}
}

/* P(u, v) and its normal dP/du x dP/dv, nudged inwards where it vanishes */
static void tp_eval(const double *cp, double u, double v, double *p, double *n)
{
	for (int tries = 0; tries < 3; tries++) {
		double du[3] = { 0, 0, 0 }, dv[3] = { 0, 0, 0 };

		for (int k = 0; k < 3; k++)
			p[k] = 0;
		for (int i = 0; i < 4; i++)
			for (int j = 0; j < 4; j++)
				for (int k = 0; k < 3; k++) {
					double c = cp[3 * (4 * i + j) + k];

					if (!tries)
						p[k] += bern(i, v) *
							bern(j, u) * c;
					du[k] += bern(i, v) * dbern(j, u) * c;
					dv[k] += dbern(i, v) * bern(j, u) * c;
				}
		n[0] = du[1] * dv[2] - du[2] * dv[1];
		n[1] = du[2] * dv[0] - du[0] * dv[2];
		n[2] = du[0] * dv[1] - du[1] * dv[0];
		if (sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) > 1e-6)
			return;
		u = u < 0.5 ? u + 1e-3 : u - 1e-3;
		v = v < 0.5 ? v + 1e-3 : v - 1e-3;
	}
}

/*
 * examples/teapot.rdl's scene (view, lights, material) with its 32
 * patches tessellated on the host into one mesh of 2048 vertices and 3136
 * triangles, lit Gouraud, two-sided: the scan-line mode against the depth
 * buffer, pixel for pixel, and their cycles (docs/commands.md quotes
 * them; the spout and handle pierce the body, which the per-pixel depth
 * resolution handles as the depth buffer does).
 */
static void test_scan_teapot(void **state)
{
	static double cp[TP_PATCHES][48];
	struct tdp *t = *state;
	const uint32_t view[18] = { (uint32_t)fxd(0.2),
				    0,
				    (uint32_t)fxd(1.4),
				    (uint32_t)fxd(1),
				    (uint32_t)fxd(-1.6),
				    (uint32_t)fxd(0.9),
				    0,
				    0,
				    65536,
				    0,
				    0,
				    (uint32_t)fxd(14),
				    (uint32_t)fxd(-3.6),
				    (uint32_t)fxd(3.6),
				    (uint32_t)fxd(-2.7),
				    (uint32_t)fxd(2.7),
				    (uint32_t)fxd(6),
				    (uint32_t)fxd(-6) };
	const uint32_t fl = RDC_MESH_NORMALS | RDC_MESH_LIT | RDC_MESH_GOURAUD |
			    RDC_MESH_TWO_SIDED;
	uint32_t v = 0, k = 0, hz, hs;
	uint64_t cz, cs, pz, ps;

	assert_int_equal(read_patches(cp), TP_PATCHES);
	for (int q = 0; q < TP_PATCHES; q++) {
		uint32_t v0 = v;

		for (int i = 0; i <= TP_N; i++)
			for (int j = 0; j <= TP_N; j++, v++) {
				double p[3], n[3];

				tp_eval(cp[q], (double)j / TP_N,
					(double)i / TP_N, p, n);
				for (int c = 0; c < 3; c++) {
					rdc_st32(t->vram + VBASE +
							 (6 * v + c) * 4,
						 (uint32_t)fxd(p[c]));
					rdc_st32(t->vram + VBASE +
							 (6 * v + 3 + c) * 4,
						 (uint32_t)fxd(n[c]));
				}
			}
		for (int i = 0; i < TP_N; i++)
			for (int j = 0; j < TP_N; j++) {
				uint16_t k00 =
					(uint16_t)(v0 + i * (TP_N + 1) + j);
				uint16_t q4[6] = { k00,
						   (uint16_t)(k00 + 1),
						   (uint16_t)(k00 + TP_N + 2),
						   k00,
						   (uint16_t)(k00 + TP_N + 2),
						   (uint16_t)(k00 + TP_N + 1) };

				for (int e = 0; e < 6; e++)
					rdc_st16(t->vram + IBASE + 2 * k++,
						 q4[e]);
			}
	}
	assert_int_equal(v, TP_NV);
	assert_int_equal(k, 3 * TP_NT);

	tdp_set_surface(t, RDC_OP_SET_DST, &screen);
	tdp_cmd(t, RDC_OP_SET_VIEW, RDC_VIEW_PERSPECTIVE, 18, view);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT3, RDC_XY(0, 0), RDC_XY(SW - 1, SH - 1));
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_SET_AMBIENT, 0x303038);
	TDP_CMD(t, RDC_OP_SET_LIGHT, 0xfff4e0, fxd(1), fxd(-1.2), fxd(1.6));
	tdp_cmd(t, RDC_OP_SET_LIGHT, 1, 4,
		(const uint32_t[]){ 0x4060a0, (uint32_t)fxd(-1.5),
				    (uint32_t)fxd(0.5), (uint32_t)fxd(0.3) });
	TDP_CMD(t, RDC_OP_SET_MATERIAL, 0xc06030, 0xd07840, 0xffffff, 24);

	memset(t->vram, 0, STRIDE * SH);
	zbuf_on(t);
	tdp_drain(t);
	pz = rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO);
	mesh(t, fl, VBASE, TP_NV, TP_NT);
	cz = last_cycles(t);
	pz = rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO) - pz;
	hz = screen_hash(t);

	memset(t->vram, 0, STRIDE * SH);
	tdp_drain(t);
	ps = rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO);
	mesh(t, fl | RDC_MESH_SCANLINE, VBASE, TP_NV, TP_NT);
	cs = last_cycles(t);
	ps = rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO) - ps;
	hs = screen_hash(t);
	print_message("teapot mesh: depth buffer %llu cycles %llu pixels, "
		      "scan-line %llu cycles %llu pixels\n",
		      (unsigned long long)cz, (unsigned long long)pz,
		      (unsigned long long)cs, (unsigned long long)ps);
	assert_int_equal(hs, hz);
	/* docs/commands.md's figures */
	assert_int_equal(cz, 904851);
	assert_int_equal(cs, 299176);
	assert_int_equal(pz, 123175);
	assert_int_equal(ps, 96746);
	tdp_cmd(t, RDC_OP_SET_LIGHT, 1, 0, NULL);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
	tdp_drain(t);
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
	/* the same with the scan-line mode */
	open = t->hw.bus.open_row;
	want = fetch_cost(4) + tdp_bus_span(&open, VBASE, 24, TDP_BUS_READ) +
	       8 * RDC_T_VERTEX3;
	mesh(t, RDC_MESH_NORMALS | RDC_MESH_BOUNDS | RDC_MESH_SCANLINE, VBASE,
	     24, 8);
	assert_int_equal(last_cycles(t), want);
	assert_int_equal(culled(t), n0 + 2);
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
	assert_int_equal(culled(t), n0 + 2);
	/* PERF_CTRL zeroes PERF_CULLED, read-only: a write is error REG */
	rdc_hw_write(&t->hw, RDC_REG_PERF_CTRL, RDC_PERF_CTRL_CLEAR);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CULLED), 0);
	put_box(t, VBASE, out);
	mesh(t, RDC_MESH_NORMALS | RDC_MESH_BOUNDS, VBASE, 24, 8);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CULLED), 1);
	rdc_hw_write(&t->hw, RDC_REG_PERF_CULLED, 7);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CULLED), 1);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_CODE), RDC_ERR_REG);
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
		TDP_TEST(test_scan_equals_zbuf),    TDP_TEST(test_scan_cycles),
		TDP_TEST(test_scan_errors),	    TDP_TEST(test_bounds_cull),
		TDP_TEST(test_bounds_conservative), TDP_TEST(test_scan_teapot),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
