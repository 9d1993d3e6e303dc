// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The 3D geometry stage against an independent double-precision model of
 * the course's pipeline, written here from Foley & van Dam ch. 6 and 16:
 * the matrices T(-VRP), R, SH_par, T_par / T(-PRP), S_par / S_per and Mper
 * multiplied out in doubles, homogeneous clipping by Sutherland-Hodgman,
 * the viewport mapping, and the illumination equation.  Nothing here
 * calls the DP's code; the DP is driven through the FIFO only.
 *
 * Tolerances: the DP rounds each projected vertex to a pixel, so a pixel
 * it fills has its centre within 0.75 pixel (Euclidean) of the exact
 * projected polygon, and every pixel whose centre lies 0.75 pixel or more
 * inside it is filled.  Colours agree within 2 of 255 per channel.
 */
#include <math.h>
#include <stdio.h>

#include "test_dp_common.h"

#define SW	640
#define SH	480
#define STRIDE	(SW * 4)
#define ZBASE	0x200000u
#define VBASE	0x300000u
#define IBASE	0x380000u
#define COV_TOL 0.75
#define COL_TOL 2

static int32_t fx(double d)
{
	return (int32_t)lround(d * 65536.0);
}

/* ---- the reference pipeline -------------------------------------------- */

struct ref_view {
	double vrp[3], vpn[3], vup[3], prp[3];
	double umin, umax, vmin, vmax, F, B;
	bool persp;
	int vx0, vy0, vx1, vy1;
};

typedef double mat4[4][4];

static void m_ident(mat4 m)
{
	memset(m, 0, sizeof(mat4));
	for (int i = 0; i < 4; i++)
		m[i][i] = 1;
}

/* a = a * b */
static void m_mul(mat4 a, mat4 b)
{
	mat4 c;

	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++) {
			c[i][j] = 0;
			for (int k = 0; k < 4; k++)
				c[i][j] += a[i][k] * b[k][j];
		}
	memcpy(a, c, sizeof(mat4));
}

static void m_trans(mat4 a, double x, double y, double z)
{
	mat4 t;

	m_ident(t);
	t[0][3] = x;
	t[1][3] = y;
	t[2][3] = z;
	m_mul(a, t);
}

static void m_scale(mat4 a, double x, double y, double z)
{
	mat4 t;

	m_ident(t);
	t[0][0] = x;
	t[1][1] = y;
	t[2][2] = z;
	m_mul(a, t);
}

static void m_rot(mat4 a, int axis, double ang)
{
	mat4 t;
	int r = (axis + 1) % 3, k = (axis + 2) % 3;

	m_ident(t);
	t[r][r] = cos(ang);
	t[r][k] = -sin(ang);
	t[k][r] = sin(ang);
	t[k][k] = cos(ang);
	m_mul(a, t);
}

static void v_norm(double *v)
{
	double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);

	for (int i = 0; i < 3; i++)
		v[i] /= l;
}

static void v_cross(const double *a, const double *b, double *o)
{
	o[0] = a[1] * b[2] - a[2] * b[1];
	o[1] = a[2] * b[0] - a[0] * b[2];
	o[2] = a[0] * b[1] - a[1] * b[0];
}

static double v_dot(const double *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Foley's N_par, or M_per N_per: world to the parallel canonical volume */
static void ref_view_matrix(const struct ref_view *v, mat4 N)
{
	double n[3], u[3], vv[3], cu = (v->umax + v->umin) / 2;
	double cv = (v->vmax + v->vmin) / 2, dop[3], shx, shy;
	mat4 t;

	memcpy(n, v->vpn, sizeof(n));
	v_norm(n);
	v_cross(v->vup, n, u);
	v_norm(u);
	v_cross(n, u, vv);
	dop[0] = cu - v->prp[0];
	dop[1] = cv - v->prp[1];
	dop[2] = -v->prp[2];
	shx = -dop[0] / dop[2];
	shy = -dop[1] / dop[2];
	m_ident(N);
	if (!v->persp) {
		m_scale(N, 2 / (v->umax - v->umin), 2 / (v->vmax - v->vmin),
			1 / (v->F - v->B));
		m_trans(N, -cu, -cv, -v->F);
	} else {
		double vz = -v->prp[2];
		double zmin = -(vz + v->F) / (vz + v->B);

		m_ident(t);
		t[2][2] = 1 / (1 + zmin);
		t[2][3] = -zmin / (1 + zmin);
		t[3][2] = -1;
		t[3][3] = 0;
		m_mul(N, t);
		m_scale(N, 2 * vz / ((v->umax - v->umin) * (vz + v->B)),
			2 * vz / ((v->vmax - v->vmin) * (vz + v->B)),
			-1 / (vz + v->B));
	}
	m_ident(t);
	t[0][2] = shx;
	t[1][2] = shy;
	m_mul(N, t);
	if (v->persp)
		m_trans(N, -v->prp[0], -v->prp[1], -v->prp[2]);
	m_ident(t);
	for (int j = 0; j < 3; j++) {
		t[0][j] = u[j];
		t[1][j] = vv[j];
		t[2][j] = n[j];
	}
	m_mul(N, t);
	m_trans(N, -v->vrp[0], -v->vrp[1], -v->vrp[2]);
}

static void m_apply(mat4 m, const double *p, double *o)
{
	for (int i = 0; i < 4; i++)
		o[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] +
		       m[i][3];
}

struct hv {
	double c[4];
};

/*
 * The canonical view volume as the course states it: a box on the
 * divided coordinates, x/w and y/w in [-1, 1] and z/w in [-1, 0] (0 the
 * front plane), for W > 0.  Kept as the box's faces, tested on x/w, y/w
 * and z/w, and not as the plane distances the display processor clips
 * with, so that the two are not one formula written twice.
 */
static const struct ref_face {
	int axis;     /* 0: x, 1: y, 2: z */
	double bound; /* of the divided coordinate */
	bool at_most; /* inside: <= bound (else >= bound) */
} ref_box[6] = {
	{ 0, -1, false }, { 0, 1, true }, { 1, -1, false },
	{ 1, 1, true },	  { 2, 0, true }, { 2, -1, false },
};

/* No point of the box has W <= 0: the clip first keeps W >= this. */
#define REF_W_MIN 1e-9

/* Is c on the inside of face k (W > 0), or of W >= REF_W_MIN (k < 0)? */
static bool ref_inside(const double *c, int k)
{
	const struct ref_face *f = &ref_box[k < 0 ? 0 : k];
	double q;

	if (k < 0)
		return c[3] >= REF_W_MIN;
	q = c[f->axis] / c[3];
	return f->at_most ? q <= f->bound : q >= f->bound;
}

static void ref_lerp(const struct hv *a, const struct hv *b, double t,
		     struct hv *o)
{
	for (int j = 0; j < 4; j++)
		o->c[j] = a->c[j] + t * (b->c[j] - a->c[j]);
}

/*
 * Where the edge from in (inside) to out (outside) leaves the half-space
 * k.  W >= REF_W_MIN: where W is REF_W_MIN.  A face: by bisection on
 * the divided coordinate, which is monotonic along an edge whose W stays
 * positive (both ends passed the W clip), to well under 1e-12 of the edge.
 */
static void ref_cross(const struct hv *in, const struct hv *out, int k,
		      struct hv *o)
{
	double lo = 0, hi = 1;

	if (k < 0) {
		ref_lerp(in, out,
			 (in->c[3] - REF_W_MIN) / (in->c[3] - out->c[3]), o);
		return;
	}
	for (int i = 0; i < 48; i++) {
		double mid = (lo + hi) / 2;

		ref_lerp(in, out, mid, o);
		if (ref_inside(o->c, k))
			lo = mid;
		else
			hi = mid;
	}
	ref_lerp(in, out, lo, o);
}

/*
 * Sutherland-Hodgman against W >= REF_W_MIN, then the box's six faces;
 * returns the count.  Every vertex it keeps or makes is in the box.
 */
static int ref_clip(struct hv *p, int n)
{
	struct hv o[16];

	for (int k = -1; k < 6 && n; k++) {
		int m = 0;

		for (int i = 0; i < n; i++) {
			struct hv *a = &p[i], *b = &p[(i + 1) % n];
			bool ia = ref_inside(a->c, k), ib = ref_inside(b->c, k);

			if (ia)
				o[m++] = *a;
			if (ia != ib)
				ref_cross(ia ? a : b, ia ? b : a, k, &o[m++]);
		}
		memcpy(p, o, sizeof(struct hv) * m);
		n = m;
	}
	return n;
}

static void ref_screen(const struct ref_view *v, const double *c, double *s)
{
	s[0] = v->vx0 + (c[0] / c[3] + 1) / 2 * (v->vx1 - v->vx0);
	s[1] = v->vy1 - (c[1] / c[3] + 1) / 2 * (v->vy1 - v->vy0);
	s[2] = -c[2] / c[3] * 65535;
}

/* Signed distance of (x, y) to the convex polygon: > 0 inside. */
static double poly_sdist(const double (*s)[3], int n, double x, double y)
{
	double best = 1e30, area = 0;
	bool inside = true;

	for (int i = 0; i < n; i++) {
		const double *a = s[i], *b = s[(i + 1) % n];

		area += a[0] * b[1] - b[0] * a[1];
	}
	for (int i = 0; i < n; i++) {
		const double *a = s[i], *b = s[(i + 1) % n];
		double ex = b[0] - a[0], ey = b[1] - a[1];
		double l2 = ex * ex + ey * ey, t, dx, dy, cr;

		t = l2 > 0 ? ((x - a[0]) * ex + (y - a[1]) * ey) / l2 : 0;
		t = t < 0 ? 0 : t > 1 ? 1 : t;
		dx = x - (a[0] + t * ex);
		dy = y - (a[1] + t * ey);
		best = fmin(best, sqrt(dx * dx + dy * dy));
		cr = ex * (y - a[1]) - ey * (x - a[0]);
		if ((area > 0 && cr < 0) || (area < 0 && cr > 0))
			inside = false;
	}
	if (area == 0)
		inside = false;
	return inside ? best : -best;
}

/* ---- driving the DP ------------------------------------------------------ */

static void send_view(struct tdp *t, const struct ref_view *v)
{
	uint32_t a[18];
	int i;

	for (i = 0; i < 3; i++) {
		a[i] = (uint32_t)fx(v->vrp[i]);
		a[3 + i] = (uint32_t)fx(v->vpn[i]);
		a[6 + i] = (uint32_t)fx(v->vup[i]);
		a[9 + i] = (uint32_t)fx(v->prp[i]);
	}
	a[12] = (uint32_t)fx(v->umin);
	a[13] = (uint32_t)fx(v->umax);
	a[14] = (uint32_t)fx(v->vmin);
	a[15] = (uint32_t)fx(v->vmax);
	a[16] = (uint32_t)fx(v->F);
	a[17] = (uint32_t)fx(v->B);
	tdp_cmd(t, RDC_OP_SET_VIEW, v->persp ? RDC_VIEW_PERSPECTIVE : 0, 18, a);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT3, RDC_XY(v->vx0, v->vy0),
		RDC_XY(v->vx1, v->vy1));
}

static void put_mesh(struct tdp *t, const double (*p)[3],
		     const double (*nrm)[3], uint32_t nv, const uint16_t *idx,
		     uint32_t nt)
{
	uint32_t words = nrm ? 6 : 3;

	for (uint32_t i = 0; i < nv; i++) {
		for (int k = 0; k < 3; k++) {
			rdc_st32(t->vram + VBASE + (i * words + k) * 4,
				 (uint32_t)fx(p[i][k]));
			if (nrm)
				rdc_st32(t->vram + VBASE +
						 (i * words + 3 + k) * 4,
					 (uint32_t)fx(nrm[i][k]));
		}
	}
	for (uint32_t i = 0; i < 3 * nt; i++)
		rdc_st16(t->vram + IBASE + 2 * i, idx[i]);
}

static void mesh(struct tdp *t, uint32_t fl, uint32_t nv, uint32_t nt)
{
	tdp_cmd(t, RDC_OP_MESH, fl, 4,
		(const uint32_t[]){ VBASE, nv, IBASE, nt });
}

static uint32_t px(struct tdp *t, int x, int y)
{
	return rdc_ld32(t->vram + (uint32_t)y * STRIDE + (uint32_t)x * 4) &
	       0xffffffu;
}

static void clear_screen(struct tdp *t)
{
	memset(t->vram, 0, STRIDE * SH);
}

static struct ref_view std_view(bool persp)
{
	struct ref_view v = {
		.vrp = { 0, 0, 0 },
		.vpn = { 0, 0, 1 },
		.vup = { 0, 1, 0 },
		.prp = { 0, 0, 4 },
		.umin = -2,
		.umax = 2,
		.vmin = -1.5,
		.vmax = 1.5,
		.F = 2,
		.B = -6,
		.persp = persp,
		.vx0 = 0,
		.vy0 = 0,
		.vx1 = SW - 1,
		.vy1 = SH - 1,
	};
	return v;
}

static double frand(uint32_t *s, double lo, double hi)
{
	return lo + (hi - lo) * (tdp_rand(s) / 4294967296.0);
}

static void rand_view(uint32_t *s, struct ref_view *v)
{
	do {
		for (int i = 0; i < 3; i++) {
			v->vrp[i] = frand(s, -3, 3);
			v->vpn[i] = frand(s, -1, 1);
			v->vup[i] = frand(s, -1, 1);
		}
		double c[3];

		v_cross(v->vup, v->vpn, c);
		if (sqrt(v_dot(c, c)) > 0.3 &&
		    sqrt(v_dot(v->vpn, v->vpn)) > 0.3)
			break;
	} while (1);
	v->persp = tdp_rand(s) & 1;
	v->umin = frand(s, -4, -1);
	v->umax = frand(s, 1, 4);
	v->vmin = frand(s, -3, -1);
	v->vmax = frand(s, 1, 3);
	v->prp[0] = frand(s, -1, 1);
	v->prp[1] = frand(s, -1, 1);
	v->prp[2] = frand(s, 4, 12);
	v->F = frand(s, 0.5, 3);
	v->B = frand(s, -20, -5);
	v->vx0 = (int)frand(s, 0, 100);
	v->vy0 = (int)frand(s, 0, 100);
	v->vx1 = (int)frand(s, 400, SW - 1);
	v->vy1 = (int)frand(s, 300, SH - 1);
}

/*
 * Draw triangle p (world = model, CTM identity) with FG white, no culling,
 * and compare against the reference clipped polygon.
 */
static void check_tri(struct tdp *t, const struct ref_view *v,
		      const double (*p)[3], unsigned long *exact_in,
		      unsigned long *checked)
{
	static const uint16_t idx[3] = { 0, 1, 2 };
	struct hv h[16];
	double s[16][3];
	mat4 N;
	int n;

	ref_view_matrix(v, N);
	for (int i = 0; i < 3; i++)
		m_apply(N, p[i], h[i].c);
	n = ref_clip(h, 3);
	for (int i = 0; i < n; i++)
		ref_screen(v, h[i].c, s[i]);
	clear_screen(t);
	put_mesh(t, p, NULL, 3, idx, 1);
	mesh(t, 0, 3, 1);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	for (int y = 0; y < SH; y++) {
		for (int x = 0; x < SW; x++) {
			bool on = px(t, x, y) != 0;
			double d = n >= 3 ? poly_sdist((const double(*)[3])s, n,
						       x + 0.5, y + 0.5) :
					    -1e9;

			if (on) {
				if (d < -COV_TOL)
					fail_msg("pixel %d,%d drawn, %.3f "
						 "outside",
						 x, y, -d);
				if (x < v->vx0 || x > v->vx1 || y < v->vy0 ||
				    y > v->vy1)
					fail_msg("pixel %d,%d outside the "
						 "viewport",
						 x, y);
			} else if (d >= COV_TOL) {
				fail_msg("pixel %d,%d not drawn, %.3f inside",
					 x, y, d);
			}
			if (d >= COV_TOL)
				(*exact_in)++;
			(*checked)++;
		}
	}
}

/* Random triangles under random views, most of them clipped. */
static void test_coverage_random(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0x3d3d1234;
	unsigned long in = 0, all = 0;

	for (int it = 0; it < 60; it++) {
		struct ref_view v;
		double p[3][3];

		rand_view(&seed, &v);
		send_view(t, &v);
		for (int i = 0; i < 3; i++)
			for (int k = 0; k < 3; k++)
				p[i][k] = v.vrp[k] + frand(&seed, -6, 6);
		check_tri(t, &v, (const double(*)[3])p, &in, &all);
	}
	printf("coverage: %lu pixels well inside checked of %lu\n", in, all);
	assert_true(in > 10000); /* the triangles were not all off screen */
}

/* Known points to known pixels, both projections. */
static void test_known_points(void **state)
{
	struct tdp *t = *state;
	/* centre, window corners, a point half-way back in perspective */
	static const struct {
		bool persp;
		double p[3];
		int x, y;
	} k[] = {
		{ false, { 0, 0, 0 }, 320, 240 },
		{ false, { 1.5, 0.75, 0 }, 560, 120 },
		{ false, { -1, -0.75, -3 }, 160, 360 },
		{ false, { 1, 0, 1 }, 480, 240 },
		{ true, { 0, 0, 0 }, 320, 240 },
		{ true, { 1.5, 0.75, 0 }, 560, 120 },
		/* z = -4: twice as far from the eye, half the offset */
		{ true, { 2, 0, -4 }, 480, 240 },
		{ true, { -2, 1.5, -4 }, 160, 120 },
	};

	for (size_t i = 0; i < RDC_ARRAY_SIZE(k); i++) {
		struct ref_view v = std_view(k[i].persp);
		uint32_t a[12];
		int found = 0;

		v.vx1 = 640;
		v.vy1 = 480;
		send_view(t, &v);
		clear_screen(t);
		for (int j = 0; j < 4; j++)
			for (int c = 0; c < 3; c++)
				a[3 * j + c] = (uint32_t)fx(k[i].p[c]);
		tdp_cmd(t, RDC_OP_BEZIER3, 1, 12, a);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		for (int y = 0; y < SH; y++)
			for (int x = 0; x < SW; x++)
				if (px(t, x, y)) {
					assert_int_equal(x, k[i].x);
					assert_int_equal(y, k[i].y);
					found++;
				}
		if (found != 1)
			fail_msg("point %zu: %d pixels", i, found);
	}
}

/* ---- closed meshes --------------------------------------------------- */

#define SPH_R 8
#define SPH_S 12

static uint32_t sphere(double (*p)[3], double (*nrm)[3], uint16_t *idx,
		       uint32_t *nt)
{
	uint32_t nv = 0, t = 0;

	/* poles and rings, counter-clockwise seen from outside */
	p[nv][0] = 0, p[nv][1] = 1, p[nv][2] = 0, nv++;
	for (int r = 1; r < SPH_R; r++) {
		double th = M_PI * r / SPH_R;

		for (int s = 0; s < SPH_S; s++) {
			double ph = 2 * M_PI * s / SPH_S;

			p[nv][0] = sin(th) * cos(ph);
			p[nv][1] = cos(th);
			p[nv][2] = -sin(th) * sin(ph);
			nv++;
		}
	}
	p[nv][0] = 0, p[nv][1] = -1, p[nv][2] = 0, nv++;
	for (uint32_t i = 0; i < nv; i++)
		memcpy(nrm[i], p[i], sizeof(p[i]));
	for (int s = 0; s < SPH_S; s++) {
		int s1 = (s + 1) % SPH_S;

		idx[t++] = 0, idx[t++] = (uint16_t)(1 + s),
		idx[t++] = (uint16_t)(1 + s1);
		for (int r = 0; r + 1 < SPH_R - 1; r++) {
			uint16_t a = (uint16_t)(1 + r * SPH_S + s);
			uint16_t b = (uint16_t)(1 + r * SPH_S + s1);
			uint16_t c = (uint16_t)(a + SPH_S),
				 d = (uint16_t)(b + SPH_S);

			idx[t++] = a, idx[t++] = c, idx[t++] = d;
			idx[t++] = a, idx[t++] = d, idx[t++] = b;
		}
		idx[t++] = (uint16_t)(nv - 1);
		idx[t++] = (uint16_t)(1 + (SPH_R - 2) * SPH_S + s1);
		idx[t++] = (uint16_t)(1 + (SPH_R - 2) * SPH_S + s);
	}
	*nt = t / 3;
	return nv;
}

/*
 * A closed sphere under XOR: with culling every pixel inside the
 * silhouette is covered exactly once (twice would cancel); without it,
 * front and back faces cover each such pixel twice (all cancel).
 */
static void test_closed_mesh_once(void **state)
{
	struct tdp *t = *state;
	static double p[200][3], nrm[200][3];
	static uint16_t idx[600];
	static double fs[200][16][3];
	static int fn[200];
	static bool ffront[200];
	uint32_t nt, nv = sphere(p, nrm, idx, &nt), seed = 99;

	put_mesh(t, (const double(*)[3])p, NULL, nv, idx, nt);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	for (int it = 0; it < 4; it++) {
		struct ref_view v = std_view(it & 1);
		uint32_t qx = tdp_rand(&seed) & 0xffff,
			 qy = tdp_rand(&seed) & 0xffff;
		double ax = qx * 2 * M_PI / 65536, ay = qy * 2 * M_PI / 65536;
		mat4 M, N;
		long once = 0, twice = 0;

		send_view(t, &v);
		m_ident(M);
		m_rot(M, 0, ax);
		m_rot(M, 1, ay);
		/* CTM = Rx(ax) Ry(ay) through ROTATE, angles as the DP has them
		 */
		tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
		tdp_cmd(t, RDC_OP_ROTATE, RDC_AXIS_X, 1, &qx);
		tdp_cmd(t, RDC_OP_ROTATE, RDC_AXIS_Y, 1, &qy);
		ref_view_matrix(&v, N);
		m_mul(N, M);
		for (uint32_t f = 0; f < nt; f++) {
			struct hv h[16];
			double area = 0;

			for (int i = 0; i < 3; i++)
				m_apply(N, p[idx[3 * f + i]], h[i].c);
			fn[f] = ref_clip(h, 3);
			for (int i = 0; i < fn[f]; i++)
				ref_screen(&v, h[i].c, fs[f][i]);
			for (int i = 0; i < fn[f]; i++) {
				const double *a = fs[f][i];
				const double *b = fs[f][(i + 1) % fn[f]];

				area += a[0] * b[1] - b[0] * a[1];
			}
			ffront[f] = area < 0;
		}
		for (int pass = 0; pass < 2; pass++) {
			clear_screen(t);
			mesh(t, pass ? 0 : RDC_MESH_CULL, nv, nt);
			tdp_drain(t);
			assert_int_equal(tdp_err(t), 0);
			for (int y = 0; y < SH; y++) {
				for (int x = 0; x < SW; x++) {
					double bf = -1e9, bb = -1e9;

					for (uint32_t f = 0; f < nt; f++) {
						double d;

						if (fn[f] < 3)
							continue;
						d = poly_sdist(
							(const double(*)[3])
								fs[f],
							fn[f], x + 0.5,
							y + 0.5);
						if (ffront[f])
							bf = fmax(bf, d);
						else
							bb = fmax(bb, d);
					}
					/*
					 * well inside a front face: one front
					 * face covers it (and one back face,
					 * checked where it is well inside one)
					 */
					if (bf < COV_TOL)
						continue;
					if (pass == 0) {
						assert_int_equal(px(t, x, y),
								 0xffffff);
						once++;
					} else if (bb >= COV_TOL) {
						assert_int_equal(px(t, x, y),
								 0);
						twice++;
					}
				}
			}
			if (pass == 0)
				assert_true(once > 1000);
			else
				assert_true(twice > 1000);
		}
	}
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
}

/* ---- illumination ----------------------------------------------------- */

struct ref_light {
	double amb[3], mat_a[3], mat_d[3], mat_s[3];
	int shine;
	int nl;
	double col[4][3], dir[4][3];
};

static void ref_shade(const struct ref_light *L, const double *nin,
		      const double *V, double *out)
{
	double n[3];

	memcpy(n, nin, sizeof(n));
	v_norm(n);
	for (int c = 0; c < 3; c++)
		out[c] = L->amb[c] * L->mat_a[c];
	for (int i = 0; i < L->nl; i++) {
		double l[3], r[3], nl, rv;

		memcpy(l, L->dir[i], sizeof(l));
		v_norm(l);
		nl = v_dot(n, l);
		if (nl <= 0)
			continue;
		for (int k = 0; k < 3; k++)
			r[k] = 2 * nl * n[k] - l[k];
		rv = v_dot(r, V);
		for (int c = 0; c < 3; c++)
			out[c] += L->col[i][c] *
				  (L->mat_d[c] * nl +
				   (rv > 0 ? L->mat_s[c] * pow(rv, L->shine) :
					     0));
	}
	for (int c = 0; c < 3; c++)
		out[c] = fmin(255, out[c] * 255);
}

static uint32_t rgb_of(const double *c)
{
	return (uint32_t)lround(c[0] * 255) << 16 |
	       (uint32_t)lround(c[1] * 255) << 8 | (uint32_t)lround(c[2] * 255);
}

static void check_col(uint32_t got, const double *want)
{
	for (int c = 0; c < 3; c++) {
		int g = (int)(got >> (16 - 8 * c) & 0xff);

		if (fabs(g - want[c]) > COL_TOL)
			fail_msg("channel %d: %d, reference %.2f (pixel %06x)",
				 c, g, want[c], got);
	}
}

/*
 * A triangle facing the viewer, lit flat (face normal) and Gouraud
 * (vertex normals all n), parallel view: every pixel is the reference
 * colour for normal n.  Then flat under perspective, where V runs from
 * the face's centroid to the eye.  Random lights, materials and normals.
 */
static void test_lighting_ref(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 7777;
	struct ref_view v = std_view(false);
	double V[3] = { 0, 0, 1 };

	send_view(t, &v);
	for (int it = 0; it < 40; it++) {
		struct ref_light L = { .nl = 1 + (int)(tdp_rand(&seed) % 3) };
		double n[3], p[3][3], nr[3][3], a[3], b[3], want[3];
		uint32_t m[4];
		static const uint16_t idx[3] = { 0, 1, 2 };

		for (int c = 0; c < 3; c++) {
			L.amb[c] = (tdp_rand(&seed) & 0xff) / 255.0;
			L.mat_a[c] = (tdp_rand(&seed) & 0xff) / 255.0;
			L.mat_d[c] = (tdp_rand(&seed) & 0xff) / 255.0;
			L.mat_s[c] = (tdp_rand(&seed) & 0xff) / 255.0;
		}
		L.shine = 1 + (int)(tdp_rand(&seed) % 60);
		tdp_cmd(t, RDC_OP_SET_AMBIENT, 0, 1,
			(const uint32_t[]){ rgb_of(L.amb) });
		m[0] = rgb_of(L.mat_a);
		m[1] = rgb_of(L.mat_d);
		m[2] = rgb_of(L.mat_s);
		m[3] = (uint32_t)L.shine;
		tdp_cmd(t, RDC_OP_SET_MATERIAL, 0, 4, m);
		for (int i = 0; i < 4; i++) {
			if (i >= L.nl) {
				tdp_cmd(t, RDC_OP_SET_LIGHT, (uint32_t)i, 0,
					NULL);
				continue;
			}
			for (int c = 0; c < 3; c++) {
				L.col[i][c] = (tdp_rand(&seed) & 0xff) / 255.0;
				L.dir[i][c] = frand(&seed, -1, 1);
			}
			L.dir[i][2] = frand(&seed, 0.2, 1);
			tdp_cmd(t, RDC_OP_SET_LIGHT, (uint32_t)i, 4,
				(const uint32_t[]){
					rgb_of(L.col[i]),
					(uint32_t)fx(L.dir[i][0]),
					(uint32_t)fx(L.dir[i][1]),
					(uint32_t)fx(L.dir[i][2]) });
		}
		/* the reference takes the quantised inputs */
		for (int c = 0; c < 3; c++) {
			L.amb[c] = lround(L.amb[c] * 255) / 255.0;
			L.mat_a[c] = lround(L.mat_a[c] * 255) / 255.0;
			L.mat_d[c] = lround(L.mat_d[c] * 255) / 255.0;
			L.mat_s[c] = lround(L.mat_s[c] * 255) / 255.0;
			for (int i = 0; i < L.nl; i++)
				L.col[i][c] = lround(L.col[i][c] * 255) / 255.0;
		}
		/* a triangle in the plane through the origin with normal n */
		n[0] = frand(&seed, -0.7, 0.7);
		n[1] = frand(&seed, -0.7, 0.7);
		n[2] = 1;
		v_norm(n);
		a[0] = 1, a[1] = 0, a[2] = -n[0] / n[2];
		v_norm(a);
		v_cross(n, a, b);
		for (int c = 0; c < 3; c++) {
			p[0][c] = -0.8 * a[c] - 0.6 * b[c];
			p[1][c] = 0.9 * a[c] - 0.5 * b[c];
			p[2][c] = 0.1 * a[c] + 0.9 * b[c];
			for (int i = 0; i < 3; i++)
				nr[i][c] = n[c];
		}
		ref_shade(&L, n, V, want);
		for (int mode = 0; mode < 2; mode++) {
			clear_screen(t);
			put_mesh(t, (const double(*)[3])p,
				 (const double(*)[3])nr, 3, idx, 1);
			mesh(t,
			     RDC_MESH_NORMALS | RDC_MESH_LIT |
				     (mode ? RDC_MESH_GOURAUD : 0),
			     3, 1);
			tdp_drain(t);
			assert_int_equal(tdp_err(t), 0);
			/* the centroid's pixel */
			check_col(px(t, 320, 240 - 8), want);
		}
		/*
		 * perspective, flat: the face lit at its centroid, V from
		 * there to the centre of projection (0, 0, 4)
		 */
		{
			struct ref_view pv = std_view(true);
			double c[3], vp[3];

			for (int k = 0; k < 3; k++) {
				c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
				vp[k] = pv.prp[k] - c[k];
			}
			v_norm(vp);
			ref_shade(&L, n, vp, want);
			send_view(t, &pv);
			clear_screen(t);
			mesh(t, RDC_MESH_NORMALS | RDC_MESH_LIT, 3, 1);
			tdp_drain(t);
			assert_int_equal(tdp_err(t), 0);
			check_col(px(t, 320, 240 - 8), want);
			send_view(t, &v);
		}
	}
}

/*
 * The lit colour in each DST format: RGB565 rounded per channel, RGB888
 * as is, indexed through the AA ramp from FG.  A face lit by the ambient
 * term alone (no lights) has the colour ambient * reflectance.
 */
static void test_lit_formats(void **state)
{
	struct tdp *t = *state;
	static const double p[3][3] = { { -1, -1, 0 },
					{ 1, -1, 0 },
					{ 0, 1, 0 } };
	static const uint16_t idx[3] = { 0, 1, 2 };
	struct ref_view v = std_view(false);
	const uint32_t base = 0x100000; /* below the mesh buffers */
	uint32_t seed = 4242;

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	for (uint32_t l = 0; l < RDC_LIGHTS; l++)
		tdp_cmd(t, RDC_OP_SET_LIGHT, l, 0, NULL);
	put_mesh(t, p, NULL, 3, idx, 1);
	for (int it = 0; it < 30; it++) {
		uint32_t fmt = (uint32_t[]){ RDC_FMT_RGB565, RDC_FMT_RGB888,
					     RDC_FMT_I8 }[it % 3];
		uint32_t amb = tdp_rand(&seed) & 0xffffff;
		uint32_t mat = tdp_rand(&seed) & 0xffffff;
		uint32_t ramp = 2 + tdp_rand(&seed) % 30, fg = 40, want, got;
		uint32_t c[3], bpp = tdp_bpp(fmt);
		struct rdc_surface s = { base, SW * 4, SW, SH, fmt };

		for (int k = 0; k < 3; k++) {
			uint32_t a = amb >> (16 - 8 * k) & 0xff;
			uint32_t m = mat >> (16 - 8 * k) & 0xff;

			/* the reference: a m / 255 rounded */
			c[k] = (uint32_t)lround(a * m / 255.0);
		}
		if (fmt == RDC_FMT_RGB565)
			want = (uint32_t)lround(c[0] * 31 / 255.0) << 11 |
			       (uint32_t)lround(c[1] * 63 / 255.0) << 5 |
			       (uint32_t)lround(c[2] * 31 / 255.0);
		else if (fmt == RDC_FMT_RGB888)
			want = c[0] << 16 | c[1] << 8 | c[2];
		else
			want = fg +
			       (uint32_t)lround((255 - lround((77.0 * c[0] +
							       150.0 * c[1] +
							       29.0 * c[2]) /
							      256.0)) *
						(ramp - 1) / 255.0);
		tdp_set_surface(t, RDC_OP_SET_DST, &s);
		TDP_CMD(t, RDC_OP_SET_FG, fg);
		TDP_CMD(t, RDC_OP_SET_AA_RAMP, ramp);
		TDP_CMD(t, RDC_OP_SET_AMBIENT, amb);
		TDP_CMD(t, RDC_OP_SET_MATERIAL, mat, 0xffffff, 0, 1);
		memset(t->vram + base, 0, SW * 4 * SH);
		mesh(t, RDC_MESH_LIT, 3, 1);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		got = tdp_get(t->vram, &s, 320, 240);
		/* rounding of halves may differ by one step */
		if (fmt == RDC_FMT_RGB888) {
			for (int k = 0; k < 3; k++)
				assert_true(
					abs((int)(got >> (16 - 8 * k) & 0xff) -
					    (int)c[k]) <= 1);
		} else if (fmt == RDC_FMT_RGB565) {
			assert_true(abs((int)(got >> 11) - (int)(want >> 11)) <=
				    1);
			assert_true(abs((int)(got >> 5 & 63) -
					(int)(want >> 5 & 63)) <= 1);
			assert_true(abs((int)(got & 31) - (int)(want & 31)) <=
				    1);
		} else {
			assert_true(abs((int)got - (int)want) <= 1);
			assert_true(got >= fg && got < fg + ramp);
		}
		(void)bpp;
	}
	tdp_set_surface(t, RDC_OP_SET_DST,
			&(struct rdc_surface){ 0, SW * 4, SW, SH,
					       RDC_FMT_XRGB8888 });
}

/* ---- the matrix stack and display lists ---------------------------- */

/*
 * A display list draws a small triangle; the FIFO calls it twice under
 * PUSH / TRANSLATE / POP.  The same triangles placed by hand must give
 * the same frame, and the CTM after the last POP is the one before.
 */
static void test_stack_lists(void **state)
{
	struct tdp *t = *state;
	static const double p[3][3] = { { 0, 0, 0 },
					{ 0.5, 0, 0 },
					{ 0, 0.5, 0 } };
	static const uint16_t idx[3] = { 0, 1, 2 };
	const uint32_t list = 0x3c0000u;
	uint32_t crc1, crc2;
	struct ref_view v = std_view(true);

	send_view(t, &v);
	put_mesh(t, p, NULL, 3, idx, 1);
	rdc_st32(t->vram + list, RDC_CMD(RDC_OP_MESH, 0, 4));
	rdc_st32(t->vram + list + 4, VBASE);
	rdc_st32(t->vram + list + 8, 3);
	rdc_st32(t->vram + list + 12, IBASE);
	rdc_st32(t->vram + list + 16, 1);
	rdc_st32(t->vram + list + 20, RDC_CMD(RDC_OP_RET, 0, 0));
	clear_screen(t);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	tdp_cmd(t, RDC_OP_ROTATE, RDC_AXIS_Z, 1, (const uint32_t[]){ 4096 });
	for (int i = 0; i < 2; i++) {
		tdp_cmd(t, RDC_OP_PUSH_MATRIX, 0, 0, NULL);
		TDP_CMD(t, RDC_OP_TRANSLATE, (uint32_t)fx(i ? -1 : 1),
			(uint32_t)fx(0.25), (uint32_t)fx(-1));
		TDP_CMD(t, RDC_OP_CALL, list);
		tdp_cmd(t, RDC_OP_POP_MATRIX, 0, 0, NULL);
	}
	/* after the POPs the rotation alone: draw at the origin */
	mesh(t, 0, 3, 1);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	crc1 = tdp_fnv(2166136261u, t->vram, STRIDE * SH);
	/* by hand: Rz(22.5 deg) T(...) as one matrix per placement */
	clear_screen(t);
	for (int i = 0; i < 3; i++) {
		double c = cos(M_PI / 8), s = sin(M_PI / 8);
		double tx = i == 2 ? 0 : i ? -1 : 1, ty = i == 2 ? 0 : 0.25;
		double tz = i == 2 ? 0 : -1;

		TDP_CMD(t, RDC_OP_MATRIX_LOAD, (uint32_t)fx(c),
			(uint32_t)fx(-s), 0, (uint32_t)fx(c * tx - s * ty),
			(uint32_t)fx(s), (uint32_t)fx(c), 0,
			(uint32_t)fx(s * tx + c * ty), 0, 0, (uint32_t)fx(1),
			(uint32_t)fx(tz));
		mesh(t, 0, 3, 1);
	}
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	crc2 = tdp_fnv(2166136261u, t->vram, STRIDE * SH);
	assert_int_equal(crc1, crc2);
}

/*
 * Facing: a triangle counter-clockwise as the viewer sees it (its normal
 * towards the eye) is drawn with RDC_MESH_CULL, the same one wound the
 * other way is not; without culling both are.
 */
static void test_cull_facing(void **state)
{
	struct tdp *t = *state;
	static const double p[3][3] = { { -1, -1, 0 },
					{ 1, -1, 0 },
					{ 0, 1, 0 } };
	static const uint16_t ccw[3] = { 0, 1, 2 }, cw[3] = { 0, 2, 1 };
	struct ref_view v = std_view(true);

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	for (int k = 0; k < 4; k++) {
		clear_screen(t);
		put_mesh(t, p, NULL, 3, k & 1 ? cw : ccw, 1);
		mesh(t, k & 2 ? 0 : RDC_MESH_CULL, 3, 1);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		assert_int_equal(px(t, 320, 240) != 0, k != 1);
	}
}

/*
 * Painter's order: a near triangle listed before a far one that it
 * hides, told apart by their normals (one faces a red light, the other a
 * blue one).  Without the depth buffer, mesh order lets the far one
 * overwrite the near one; RDC_MESH_SORT draws the far one first.
 */
static void test_painter_sort(void **state)
{
	struct tdp *t = *state;
	static const double p[6][3] = {
		{ -1, -1, 1 },	    { 1, -1, 1 },      { 0, 1, 1 },
		{ -1.5, -1.2, -2 }, { 1.5, -1.2, -2 }, { 0, 1.5, -2 },
	};
	static const double nr[6][3] = {
		{ 1, 0, 0.2 },	{ 1, 0, 0.2 },	{ 1, 0, 0.2 },
		{ -1, 0, 0.2 }, { -1, 0, 0.2 }, { -1, 0, 0.2 },
	};
	static const uint16_t idx[6] = { 0, 1, 2, 3, 4, 5 };
	struct ref_view v = std_view(true);

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_SET_AMBIENT, 0);
	TDP_CMD(t, RDC_OP_SET_MATERIAL, 0, 0xffffff, 0, 1);
	tdp_cmd(t, RDC_OP_SET_LIGHT, 0, 4,
		(const uint32_t[]){ 0xff0000, (uint32_t)fx(1), 0, 0 });
	tdp_cmd(t, RDC_OP_SET_LIGHT, 1, 4,
		(const uint32_t[]){ 0x0000ff, (uint32_t)fx(-1), 0, 0 });
	put_mesh(t, p, nr, 6, idx, 2);
	for (int k = 0; k < 2; k++) {
		uint32_t c;

		clear_screen(t);
		mesh(t,
		     RDC_MESH_NORMALS | RDC_MESH_LIT | RDC_MESH_GOURAUD |
			     (k ? RDC_MESH_SORT : 0),
		     6, 2);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		c = px(t, 320, 240);
		if (k)
			assert_true((c >> 16) > 0x80 && (c & 0xff) == 0);
		else
			assert_true((c & 0xff) > 0x80 && (c >> 16) == 0);
	}
	tdp_cmd(t, RDC_OP_SET_LIGHT, 1, 0, NULL);
}

/* ---- wireframe ------------------------------------------------------ */

/*
 * Two triangles sharing an edge under XOR: the shared edge drawn twice
 * would vanish.  The frame must equal XOR-drawn LINEs of the five edges
 * between the exact (integer) vertex pixels.
 */
static void test_wire_edges_once(void **state)
{
	struct tdp *t = *state;
	/* parallel view, window 640 x 480 units: one unit a pixel */
	struct ref_view v = std_view(false);
	static const double p[4][3] = { { -200, -100, 0 },
					{ 150, -120, 0 },
					{ 180, 90, 0 },
					{ -170, 130, 0 } };
	static const uint16_t idx[6] = { 0, 1, 2, 0, 2, 3 };
	static const int e[5][2] = {
		{ 0, 1 }, { 1, 2 }, { 2, 0 }, { 2, 3 }, { 3, 0 }
	};
	uint32_t crc1, crc2;

	v.umin = -320, v.umax = 320, v.vmin = -240, v.vmax = 240;
	v.vx1 = 640;
	v.vy1 = 480;
	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	clear_screen(t);
	put_mesh(t, p, NULL, 4, idx, 2);
	mesh(t, RDC_MESH_WIRE, 4, 2);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	crc1 = tdp_fnv(2166136261u, t->vram, STRIDE * SH);
	clear_screen(t);
	for (int i = 0; i < 5; i++) {
		const double *a = p[e[i][0]], *b = p[e[i][1]];

		TDP_CMD(t, RDC_OP_LINE,
			RDC_XY((int)lround(a[0] + 320),
			       (int)lround(240 - a[1])),
			RDC_XY((int)lround(b[0] + 320),
			       (int)lround(240 - b[1])));
	}
	tdp_drain(t);
	crc2 = tdp_fnv(2166136261u, t->vram, STRIDE * SH);
	assert_int_equal(crc1, crc2);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
}

/* ---- depth ------------------------------------------------------------ */

/*
 * Two interpenetrating triangles with the depth buffer: where both cover
 * a pixel well inside, the one nearer in the reference wins (pixels
 * whose two depths differ by less than 1/500 of the range are skipped).
 */
static void test_zbuffer_ref(void **state)
{
	struct tdp *t = *state;
	struct ref_view v = std_view(true);
	static const double p[6][3] = {
		{ -1.5, -1, -2 }, { 1.5, -1, 1 },   { 0, 1.2, -0.5 },
		{ -1.5, 0.8, 1 }, { 1.2, 1, -2.5 }, { 0, -1.2, -0.5 },
	};
	static const uint16_t idx[6] = { 0, 1, 2, 3, 4, 5 };
	mat4 N;
	double s[2][3][3];
	long checked = 0;

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	ref_view_matrix(&v, N);
	for (int f = 0; f < 2; f++)
		for (int i = 0; i < 3; i++) {
			struct hv h;

			m_apply(N, p[3 * f + i], h.c);
			ref_screen(&v, h.c, s[f][i]);
		}
	clear_screen(t);
	put_mesh(t, p, NULL, 6, idx, 2);
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST | RDC_Z_WRITE, 2,
		(const uint32_t[]){ ZBASE, SW * 2 });
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
	TDP_CMD(t, RDC_OP_SET_FG, 0xff0000);
	tdp_cmd(t, RDC_OP_MESH, 0, 4, (const uint32_t[]){ VBASE, 3, IBASE, 1 });
	TDP_CMD(t, RDC_OP_SET_FG, 0x0000ff);
	tdp_cmd(t, RDC_OP_MESH, 0, 4,
		(const uint32_t[]){ VBASE + 36, 3, IBASE, 1 });
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	for (int y = 0; y < SH; y++) {
		for (int x = 0; x < SW; x++) {
			double z[2];
			bool in = true;

			for (int f = 0; f < 2; f++) {
				const double(*q)[3] = (const double(*)[3])s[f];
				double d = poly_sdist(q, 3, x + 0.5, y + 0.5);
				/* depth on the screen plane through the
				 * vertices */
				double ax = q[1][0] - q[0][0],
				       ay = q[1][1] - q[0][1];
				double bx = q[2][0] - q[0][0],
				       by = q[2][1] - q[0][1];
				double det = ax * by - ay * bx;
				double px0 = x + 0.5 - q[0][0],
				       py0 = y + 0.5 - q[0][1];
				double l1 = (px0 * by - py0 * bx) / det;
				double l2 = (ax * py0 - ay * px0) / det;

				if (d < 1.5)
					in = false;
				z[f] = q[0][2] + l1 * (q[1][2] - q[0][2]) +
				       l2 * (q[2][2] - q[0][2]);
			}
			if (!in || fabs(z[0] - z[1]) < 130)
				continue;
			assert_int_equal(px(t, x, y),
					 z[0] < z[1] ? 0xff0000u : 0x0000ffu);
			checked++;
		}
	}
	assert_true(checked > 2000);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
	TDP_CMD(t, RDC_OP_SET_FG, 0xffffff);
}

/* ---- bad input -------------------------------------------------------- */

static void expect_err(struct tdp *t, uint32_t code)
{
	tdp_drain(t);
	assert_int_equal(tdp_err(t), code);
	tdp_clear_err(t);
}

static void test_bad_input(void **state)
{
	struct tdp *t = *state;
	static const double p[3][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
	static const uint16_t idx[3] = { 0, 1, 2 };
	static const uint16_t bad[3] = { 0, 1, 3 };
	struct ref_view v = std_view(true);
	uint32_t h0, a[18], i;

	send_view(t, &v);
	clear_screen(t);
	put_mesh(t, p, NULL, 3, idx, 1);
	h0 = tdp_fnv(2166136261u, t->vram, STRIDE * SH);
	/* indices past the vertex count: nothing drawn */
	rdc_st16(t->vram + IBASE + 4, bad[2]);
	mesh(t, 0, 3, 1);
	expect_err(t, RDC_ERR_RANGE);
	assert_int_equal(tdp_fnv(2166136261u, t->vram, STRIDE * SH), h0);
	rdc_st16(t->vram + IBASE + 4, idx[2]);
	/* huge meshes, buffers leaving VRAM, misaligned vertices */
	mesh(t, 0, RDC_MESH_MAX_VERTS + 1, 1);
	expect_err(t, RDC_ERR_RANGE);
	mesh(t, 0, 3, RDC_MESH_MAX_TRIS + 1);
	expect_err(t, RDC_ERR_RANGE);
	tdp_cmd(t, RDC_OP_MESH, 0, 4,
		(const uint32_t[]){ TDP_VRAM_SIZE - 24, 3, IBASE, 1 });
	expect_err(t, RDC_ERR_RANGE);
	tdp_cmd(t, RDC_OP_MESH, 0, 4,
		(const uint32_t[]){ VBASE, 3, TDP_VRAM_SIZE - 4, 1 });
	expect_err(t, RDC_ERR_RANGE);
	tdp_cmd(t, RDC_OP_MESH, 0, 4,
		(const uint32_t[]){ 0xfffffff0u, 3, 0xfffffff0u, 0xffff });
	expect_err(t, RDC_ERR_RANGE);
	tdp_cmd(t, RDC_OP_MESH, 0, 4,
		(const uint32_t[]){ VBASE + 2, 3, IBASE, 1 });
	expect_err(t, RDC_ERR_RANGE);
	/* lit Gouraud without normals; the scan-line mode in a wireframe */
	mesh(t, RDC_MESH_LIT | RDC_MESH_GOURAUD, 3, 1);
	expect_err(t, RDC_ERR_ARG);
	mesh(t, RDC_MESH_SCANLINE | RDC_MESH_WIRE, 3, 1);
	expect_err(t, RDC_ERR_ARG);
	/* a buffer exactly at the end of VRAM is fine */
	memcpy(t->vram + TDP_VRAM_SIZE - 36, t->vram + VBASE, 36);
	tdp_cmd(t, RDC_OP_MESH, 0, 4,
		(const uint32_t[]){ TDP_VRAM_SIZE - 36, 3, IBASE, 1 });
	expect_err(t, 0);
	/* the stack: 16 pushes fit, the 17th and an empty pop do not */
	for (i = 0; i < RDC_MATRIX_STACK_DEPTH; i++)
		tdp_cmd(t, RDC_OP_PUSH_MATRIX, 0, 0, NULL);
	expect_err(t, 0);
	tdp_cmd(t, RDC_OP_PUSH_MATRIX, 0, 0, NULL);
	expect_err(t, RDC_ERR_STACK);
	for (i = 0; i < RDC_MATRIX_STACK_DEPTH; i++)
		tdp_cmd(t, RDC_OP_POP_MATRIX, 0, 0, NULL);
	expect_err(t, 0);
	tdp_cmd(t, RDC_OP_POP_MATRIX, 0, 0, NULL);
	expect_err(t, RDC_ERR_STACK);
	/* matrices out of range, products overflowing, bad axis */
	TDP_CMD(t, RDC_OP_SCALE, (uint32_t)fx(20000), 65536, 65536);
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_SCALE, (uint32_t)fx(10000), 65536, 65536);
	expect_err(t, 0);
	TDP_CMD(t, RDC_OP_SCALE, (uint32_t)fx(10), 65536, 65536);
	expect_err(t, RDC_ERR_RANGE);
	tdp_cmd(t, RDC_OP_ROTATE, 3, 1, (const uint32_t[]){ 0 });
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_MATRIX_LOAD, 1, 2, 3);
	expect_err(t, RDC_ERR_LENGTH);
	/* a degenerate (singular) CTM: everything on one line, no crash */
	TDP_CMD(t, RDC_OP_MATRIX_LOAD, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
	mesh(t, RDC_MESH_LIT, 3, 1);
	expect_err(t, 0);
	mesh(t, RDC_MESH_WIRE, 3, 1);
	expect_err(t, 0);
	/* bad views: zero VPN, VUP along VPN, eye inside the front plane */
	for (int k = 0; k < 3; k++) {
		struct ref_view b = std_view(true);

		if (k == 0)
			b.vpn[2] = 0;
		if (k == 1)
			b.vup[1] = 0, b.vup[2] = 1;
		if (k == 2)
			b.F = 5;
		for (i = 0; i < 3; i++) {
			a[i] = (uint32_t)fx(b.vrp[i]);
			a[3 + i] = (uint32_t)fx(b.vpn[i]);
			a[6 + i] = (uint32_t)fx(b.vup[i]);
			a[9 + i] = (uint32_t)fx(b.prp[i]);
		}
		a[12] = (uint32_t)fx(b.umin);
		a[13] = (uint32_t)fx(b.umax);
		a[14] = (uint32_t)fx(b.vmin);
		a[15] = (uint32_t)fx(b.vmax);
		a[16] = (uint32_t)fx(b.F);
		a[17] = (uint32_t)fx(b.B);
		tdp_cmd(t, RDC_OP_SET_VIEW, RDC_VIEW_PERSPECTIVE, 18, a);
		expect_err(t, RDC_ERR_ARG);
	}
	/* points at the eye and behind it: clipped, nothing behind drawn */
	{
		static const double q[3][3] = { { 0, 0, 4 },
						{ 1, 0, 8 },
						{ 0, 1, 6 } };

		tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
		clear_screen(t);
		put_mesh(t, q, NULL, 3, idx, 1);
		mesh(t, 0, 3, 1);
		expect_err(t, 0);
		for (int y = 0; y < SH; y++)
			for (int x = 0; x < SW; x++)
				assert_int_equal(px(t, x, y), 0);
	}
	/* a far vertex: clip coordinates out of range */
	{
		static const double q[3][3] = { { 0, 0, 0 },
						{ 30000, 0, 0 },
						{ 0, 1, 0 } };

		put_mesh(t, q, NULL, 3, idx, 1);
		TDP_CMD(t, RDC_OP_SCALE, (uint32_t)fx(1000), (uint32_t)fx(1000),
			(uint32_t)fx(1000));
		mesh(t, 0, 3, 1);
		expect_err(t, RDC_ERR_RANGE);
	}
	/* a patch with bad steps, lights, materials */
	{
		uint32_t pa[49] = { 0 };

		pa[0] = 33u << 8;
		tdp_cmd(t, RDC_OP_PATCH, 0, 49, pa);
		expect_err(t, RDC_ERR_RANGE);
		pa[0] = 4u << 8 | 0x80;
		tdp_cmd(t, RDC_OP_PATCH, 0, 49, pa);
		expect_err(t, RDC_ERR_ARG);
		tdp_cmd(t, RDC_OP_SET_LIGHT, RDC_LIGHTS, 0, NULL);
		expect_err(t, RDC_ERR_ARG);
		TDP_CMD(t, RDC_OP_SET_LIGHT, 0, 0, 0, 0);
		expect_err(t, RDC_ERR_ARG);
		TDP_CMD(t, RDC_OP_SET_MATERIAL, 0, 0, 0, 0);
		expect_err(t, RDC_ERR_RANGE);
	}
	/* and the DP still draws */
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	send_view(t, &v);
	clear_screen(t);
	put_mesh(t, p, NULL, 3, idx, 1);
	mesh(t, 0, 3, 1);
	expect_err(t, 0);
	assert_int_not_equal(tdp_fnv(2166136261u, t->vram, STRIDE * SH), h0);
}

/* ---- patches ---------------------------------------------------------- */

/*
 * A flat bicubic patch (control points on a plane, a bilinear grid) is
 * the plane's quad: its coverage against the reference quad, and every
 * step count from 1 to 32 gives the same coverage within tolerance.
 */
static void test_patch_flat(void **state)
{
	struct tdp *t = *state;
	struct ref_view v = std_view(true);
	uint32_t a[49];
	/* a planar quad: z = -1 + (y + 1) / 2.1 */
	double q[4][3] = { { -1.5, -1, -1 },
			   { 1.5, -1, -1 },
			   { 1.2, 1.1, 0 },
			   { -1.3, 1, -1 + 2 / 2.1 } };
	mat4 N;
	double s[4][3];

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	ref_view_matrix(&v, N);
	for (int i = 0; i < 4; i++) {
		struct hv h;

		m_apply(N, q[i], h.c);
		ref_screen(&v, h.c, s[i]);
	}
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++) {
			double u = j / 3.0, w = i / 3.0;

			for (int c = 0; c < 3; c++) {
				/* bilinear: its Bezier points are the grid */
				double bot = q[0][c] + u * (q[1][c] - q[0][c]);
				double top = q[3][c] + u * (q[2][c] - q[3][c]);

				a[1 + 3 * (4 * i + j) + c] =
					(uint32_t)fx(bot + w * (top - bot));
			}
		}
	for (uint32_t n = 1; n <= RDC_PATCH_MAX_STEPS; n += 7) {
		a[0] = n << 8;
		clear_screen(t);
		tdp_cmd(t, RDC_OP_PATCH, 0, 49, a);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		for (int y = 0; y < SH; y++)
			for (int x = 0; x < SW; x++) {
				bool on = px(t, x, y) != 0;
				/* the quad is planar but not a parallelogram */
				double d = poly_sdist((const double(*)[3])s, 4,
						      x + 0.5, y + 0.5);

				if (on && d < -COV_TOL - 0.5)
					fail_msg("n %u: %d,%d outside", n, x,
						 y);
				if (!on && d > COV_TOL + 0.5)
					fail_msg("n %u: %d,%d missing", n, x,
						 y);
			}
	}
}

/* ---- 3D B-spline curves -------------------------------------------------- */

static void bspline3(struct tdp *t, uint32_t steps, const int32_t *q,
		     uint32_t np)
{
	tdp_cmd(t, RDC_OP_BSPLINE3, steps, 3 * np, (const uint32_t *)q);
}

static uint32_t screen_hash(struct tdp *t)
{
	return tdp_fnv(2166136261u, t->vram, STRIDE * SH);
}

/*
 * BSPLINE3, the uniform cubic B-spline: evenly spaced collinear control
 * points trace their line from q1 to q(n-2) (the ends (q0 + 4 q1 + q2) / 6
 * and so on), every pixel within a pixel of the reference projection of
 * that segment; a segment is the Bezier curve of the basis change (b0 =
 * (q0 + 4 q1 + q2) / 6, b1 = (2 q1 + q2) / 3, b2 = (q1 + 2 q2) / 3, b3 =
 * (q1 + 4 q2 + q3) / 6, exact for control points in multiples of 6
 * units), pixel for pixel BEZIER3's; one command of n points draws what
 * the n - 3 commands of its four-point windows draw.
 */
static void test_bspline3(void **state)
{
	struct tdp *t = *state;
	struct ref_view v = std_view(true);
	static const double P[3] = { 0.2, 0.3, -1 }, D[3] = { 0.5, 0.2, -0.3 };
	uint32_t seed = 0x5b1e, h0, trial;
	int32_t q[3 * 8], b[12];
	mat4 N;

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	ref_view_matrix(&v, N);
	clear_screen(t);
	h0 = screen_hash(t);

	/* collinear, evenly spaced: a straight line from q1 to q(np - 2) */
	for (uint32_t np = 4; np <= 8; np += 2) {
		double s[2][3], ends[2][3];
		unsigned long drawn = 0;

		for (uint32_t i = 0; i < np; i++)
			for (int c = 0; c < 3; c++)
				q[3 * i + c] = fx(P[c] + (i - 1.5) * D[c]);
		for (int c = 0; c < 3; c++) {
			ends[0][c] = P[c] - 0.5 * D[c];
			ends[1][c] = P[c] + (np - 3.5) * D[c];
		}
		for (int e = 0; e < 2; e++) {
			double h[4];

			m_apply(N, ends[e], h);
			ref_screen(&v, h, s[e]);
		}
		clear_screen(t);
		bspline3(t, 7, q, np);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		for (int y = 0; y < SH; y++)
			for (int x = 0; x < SW; x++) {
				double ex = s[1][0] - s[0][0],
				       ey = s[1][1] - s[0][1];
				double l2 = ex * ex + ey * ey, u, dx, dy;

				if (!px(t, x, y))
					continue;
				drawn++;
				u = ((x - s[0][0]) * ex + (y - s[0][1]) * ey) /
				    l2;
				u = u < 0 ? 0 : u > 1 ? 1 : u;
				dx = x - (s[0][0] + u * ex);
				dy = y - (s[0][1] + u * ey);
				if (dx * dx + dy * dy > 1.0)
					fail_msg("%u points: %d,%d off the "
						 "line",
						 np, x, y);
			}
		if (drawn + 1 <
		    fmax(fabs(s[1][0] - s[0][0]), fabs(s[1][1] - s[0][1])))
			fail_msg("%u points: %lu pixels", np, drawn);
	}

	for (trial = 0; trial < 24; trial++) {
		uint32_t steps = 1 + tdp_rand(&seed) % 40, np, h1;

		/* a segment against BEZIER3 of the same cubic */
		for (int i = 0; i < 12; i++)
			q[i] = 6 * (int32_t)tdp_range(&seed, -16384, 16384);
		for (int c = 0; c < 3; c++) {
			b[c] = (q[c] + 4 * q[3 + c] + q[6 + c]) / 6;
			b[3 + c] = (2 * q[3 + c] + q[6 + c]) / 3;
			b[6 + c] = (q[3 + c] + 2 * q[6 + c]) / 3;
			b[9 + c] = (q[3 + c] + 4 * q[6 + c] + q[9 + c]) / 6;
		}
		clear_screen(t);
		bspline3(t, steps, q, 4);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		h1 = screen_hash(t);
		assert_int_not_equal(h1, h0);
		clear_screen(t);
		tdp_cmd(t, RDC_OP_BEZIER3, steps, 12, (const uint32_t *)b);
		tdp_drain(t);
		assert_int_equal(screen_hash(t), h1);

		/* a longer curve against its windows, one by one */
		np = 4 + tdp_rand(&seed) % 5;
		for (uint32_t i = 0; i < 3 * np; i++)
			q[i] = (int32_t)tdp_range(&seed, -2 * 65536, 2 * 65536);
		clear_screen(t);
		bspline3(t, steps, q, np);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		h1 = screen_hash(t);
		clear_screen(t);
		for (uint32_t w = 0; w + 3 < np; w++)
			bspline3(t, steps, q + 3 * w, 4);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		if (screen_hash(t) != h1)
			fail_msg("trial %u: %u points, %u steps: the windows "
				 "differ",
				 trial, np, steps);
	}
}

/*
 * BSPLINE3's bad input: a length not 3 words a point or under 4 points
 * (LENGTH), more curve points than the vertex cache holds or a point out
 * of range (RANGE); nothing drawn, and the DP draws on.
 */
static void test_bspline3_errors(void **state)
{
	struct tdp *t = *state;
	struct ref_view v = std_view(true);
	int32_t q[3 * 12];
	uint32_t h0;

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	for (int i = 0; i < 3 * 12; i++)
		q[i] = (int32_t)((i % 3 == 2 ? 0 : i % 7) * 8192);
	clear_screen(t);
	tdp_drain(t);
	h0 = screen_hash(t);
	tdp_cmd(t, RDC_OP_BSPLINE3, 0, 11, (const uint32_t *)q);
	expect_err(t, RDC_ERR_LENGTH);
	tdp_cmd(t, RDC_OP_BSPLINE3, 0, 9, (const uint32_t *)q);
	expect_err(t, RDC_ERR_LENGTH);
	tdp_cmd(t, RDC_OP_BSPLINE3, 0, 13, (const uint32_t *)q);
	expect_err(t, RDC_ERR_LENGTH);
	tdp_cmd(t, RDC_OP_BSPLINE3, 0, 0, NULL);
	expect_err(t, RDC_ERR_LENGTH);
	/* 9 segments of 255 steps: 2296 points, the cache holds 2048 */
	bspline3(t, 255, q, 12);
	expect_err(t, RDC_ERR_RANGE);
	/* 8 segments of 255: 2041 points fit */
	bspline3(t, 255, q, 11);
	expect_err(t, 0);
	assert_int_not_equal(screen_hash(t), h0);
	clear_screen(t);
	/* the last segment leaving 15.16 once scaled; the good ones before
	 * it are not drawn either */
	q[3 * 8] = q[3 * 9] = q[3 * 10] = 100 * 65536;
	TDP_CMD(t, RDC_OP_SCALE, (uint32_t)fx(400), (uint32_t)fx(400),
		(uint32_t)fx(400));
	bspline3(t, 16, q, 11);
	expect_err(t, RDC_ERR_RANGE);
	assert_int_equal(screen_hash(t), h0);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	bspline3(t, 16, q, 6);
	expect_err(t, 0);
	assert_int_not_equal(screen_hash(t), h0);
}

/* ---- the cost model ------------------------------------------------------ */

/* The cycles of the last command, and *open the DRAM row it left open. */
static uint64_t last_cycles(struct tdp *t)
{
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	return rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
}

/* fetch (header and args through the FIFO) and decode */
static uint64_t fetch_cost(uint32_t args)
{
	return (1 + args) * RDC_T_FIFO_WORD + RDC_T_DECODE;
}

/*
 * docs/hardware.md's 3D formulas on work whose pixels cost nothing (all
 * rejected, culled or clipped away), so every cycle is the geometry
 * engine's steps and the buffer reads: the state commands cost their
 * fetch alone; MESH reads its indices, then its vertices, and charges
 * T_VERTEX3 a vertex, the lighting of each vertex (Gouraud), T_SORT3 per
 * triangle and halving with SORT, T_TRI3 a triangle set up and T_CLIP3 a
 * vertex clipping makes; PATCH and BEZIER3 T_TESS3 + T_VERTEX3 a point.
 */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	struct ref_view v = std_view(true);
	/* a square in z = 0 drawn clockwise (back faces), and a far one */
	static const double sq[4][3] = {
		{ -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 }
	};
	static const double far[3][3] = { { -100, 0, 0 },
					  { -90, 1, 0 },
					  { -95, 2, 0 } };
	/* a back face reaching past the left plane: two vertices made */
	static const double cut[3][3] = { { -5, 0, 0 },
					  { 0, 1, 0 },
					  { 1, 0, 0 } };
	static const double up[4][3] = {
		{ 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 }
	};
	static const uint16_t back[15] = { 2, 1, 0, 3, 1, 0, 3, 2,
					   0, 3, 2, 1, 1, 0, 2 };
	static const uint16_t one[3] = { 0, 1, 2 };
	uint32_t open, h0, a[49], n, lights;
	uint64_t want;

	send_view(t, &v);
	tdp_cmd(t, RDC_OP_MATRIX_LOAD, 0, 0, NULL);
	clear_screen(t);
	h0 = tdp_fnv(2166136261u, t->vram, STRIDE * SH);

	/* state commands: fetch and decode only */
	send_view(t, &v);
	tdp_drain(t);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT3, RDC_XY(0, 0), RDC_XY(SW - 1, SH - 1));
	assert_int_equal(last_cycles(t), fetch_cost(2));
	TDP_CMD(t, RDC_OP_TRANSLATE, 0, 0, 0);
	assert_int_equal(last_cycles(t), fetch_cost(3));
	tdp_cmd(t, RDC_OP_ROTATE, RDC_AXIS_Z, 1, (const uint32_t[]){ 0 });
	assert_int_equal(last_cycles(t), fetch_cost(1));
	tdp_cmd(t, RDC_OP_PUSH_MATRIX, 0, 0, NULL);
	assert_int_equal(last_cycles(t), fetch_cost(0));
	tdp_cmd(t, RDC_OP_POP_MATRIX, 0, 0, NULL);
	assert_int_equal(last_cycles(t), fetch_cost(0));
	TDP_CMD(t, RDC_OP_SET_LIGHT, 0xffffff, 0, 0, 65536);
	assert_int_equal(last_cycles(t), fetch_cost(4));
	tdp_cmd(t, RDC_OP_SET_LIGHT, 1, 4,
		(const uint32_t[]){ 0x808080, 65536, 0, 65536 });
	assert_int_equal(last_cycles(t), fetch_cost(4));
	lights = 2;
	TDP_CMD(t, RDC_OP_SET_AMBIENT, 0x101010);
	assert_int_equal(last_cycles(t), fetch_cost(1));
	TDP_CMD(t, RDC_OP_SET_MATERIAL, 0x404040, 0x808080, 0xffffff, 8);
	assert_int_equal(last_cycles(t), fetch_cost(4));
	{
		uint32_t view[18];

		for (int i = 0; i < 18; i++)
			view[i] = 0;
		/* the reset view again */
		view[5] = 65536;
		view[7] = 65536;
		view[11] = 65536;
		view[12] = (uint32_t)-65536;
		view[13] = 65536;
		view[14] = (uint32_t)-65536;
		view[15] = 65536;
		view[16] = 65536;
		view[17] = (uint32_t)-65536;
		tdp_cmd(t, RDC_OP_SET_VIEW, 0, 18, view);
		assert_int_equal(last_cycles(t), fetch_cost(18));
	}
	send_view(t, &v);
	tdp_drain(t);

	/* MESH with its extent outside the volume: reads and vertices */
	put_mesh(t, far, NULL, 3, one, 1);
	open = t->hw.bus.open_row;
	want = fetch_cost(4) + tdp_bus_span(&open, IBASE, 6, TDP_BUS_READ) +
	       tdp_bus_span(&open, VBASE, 3 * 12, TDP_BUS_READ) +
	       3 * RDC_T_VERTEX3;
	mesh(t, 0, 3, 1);
	assert_int_equal(last_cycles(t), want);

	/* five back faces, lit per vertex by two lights, sorted, culled */
	put_mesh(t, sq, up, 4, back, 5);
	open = t->hw.bus.open_row;
	want = fetch_cost(4) + tdp_bus_span(&open, IBASE, 5 * 6, TDP_BUS_READ) +
	       tdp_bus_span(&open, VBASE, 4 * 24, TDP_BUS_READ) +
	       4 * (RDC_T_VERTEX3 + RDC_T_LIGHT3 + lights * RDC_T_LIGHT3_EACH) +
	       5 * 3 * RDC_T_SORT3 /* ceil(log2 5) = 3 */ + 5 * RDC_T_TRI3;
	mesh(t,
	     RDC_MESH_NORMALS | RDC_MESH_LIT | RDC_MESH_GOURAUD |
		     RDC_MESH_CULL | RDC_MESH_SORT,
	     4, 5);
	assert_int_equal(last_cycles(t), want);

	/* a back face crossing the left plane: clipped (two new vertices),
	 * then culled */
	put_mesh(t, cut, NULL, 3, one, 1);
	open = t->hw.bus.open_row;
	want = fetch_cost(4) + tdp_bus_span(&open, IBASE, 6, TDP_BUS_READ) +
	       tdp_bus_span(&open, VBASE, 3 * 12, TDP_BUS_READ) +
	       3 * RDC_T_VERTEX3 + RDC_T_TRI3 + 2 * RDC_T_CLIP3;
	mesh(t, RDC_MESH_CULL, 3, 1);
	assert_int_equal(last_cycles(t), want);

	/* a flat patch facing away, lit per vertex, culled: n = 4 */
	n = 4;
	a[0] = n << 8 | RDC_MESH_LIT | RDC_MESH_GOURAUD | RDC_MESH_CULL;
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++) {
			/* u (j) to the left, v (i) up: the normal away */
			a[1 + 3 * (4 * i + j)] = (uint32_t)fx(1 - j * 2 / 3.0);
			a[2 + 3 * (4 * i + j)] = (uint32_t)fx(i * 2 / 3.0 - 1);
			a[3 + 3 * (4 * i + j)] = 0;
		}
	want = fetch_cost(49) +
	       (n + 1) * (n + 1) *
		       (RDC_T_TESS3 + RDC_T_VERTEX3 + RDC_T_LIGHT3 +
			lights * RDC_T_LIGHT3_EACH) +
	       2 * n * n * RDC_T_TRI3;
	tdp_cmd(t, RDC_OP_PATCH, 0, 49, a);
	assert_int_equal(last_cycles(t), want);

	/* a Bezier curve outside the volume, 8 steps */
	for (int i = 0; i < 4; i++) {
		a[3 * i] = (uint32_t)fx(-100 - i);
		a[3 * i + 1] = (uint32_t)fx(i);
		a[3 * i + 2] = 0;
	}
	tdp_cmd(t, RDC_OP_BEZIER3, 8, 12, a);
	assert_int_equal(last_cycles(t),
			 fetch_cost(12) + 9 * (RDC_T_TESS3 + RDC_T_VERTEX3));
	tdp_cmd(t, RDC_OP_BEZIER3, 0, 12, a);
	assert_int_equal(last_cycles(t),
			 fetch_cost(12) + (RDC_BEZIER3_STEPS +
					   1) * (RDC_T_TESS3 + RDC_T_VERTEX3));

	/* a B-spline outside the volume: 5 points, 2 segments of 6 steps */
	for (int i = 0; i < 5; i++) {
		a[3 * i] = (uint32_t)fx(-100 - i);
		a[3 * i + 1] = (uint32_t)fx(i);
		a[3 * i + 2] = 0;
	}
	tdp_cmd(t, RDC_OP_BSPLINE3, 6, 15, a);
	assert_int_equal(last_cycles(t),
			 fetch_cost(15) +
				 (2 * 6 + 1) * (RDC_T_TESS3 + RDC_T_VERTEX3));

	/* none of it drew a pixel */
	assert_int_equal(tdp_fnv(2166136261u, t->vram, STRIDE * SH), h0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_known_points),	 TDP_TEST(test_coverage_random),
		TDP_TEST(test_closed_mesh_once), TDP_TEST(test_lighting_ref),
		TDP_TEST(test_stack_lists),	 TDP_TEST(test_cull_facing),
		TDP_TEST(test_painter_sort),	 TDP_TEST(test_wire_edges_once),
		TDP_TEST(test_zbuffer_ref),	 TDP_TEST(test_bad_input),
		TDP_TEST(test_patch_flat),	 TDP_TEST(test_lit_formats),
		TDP_TEST(test_cycles),		 TDP_TEST(test_bspline3),
		TDP_TEST(test_bspline3_errors),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
