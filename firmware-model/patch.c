// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Bicubic Bezier patches and 3D Bezier and uniform B-spline curves by
 * forward differencing (Foley & van Dam 11.2-11.3).
 *
 * A patch P(u, v) = sum_i sum_j B_i(v) B_j(u) P_ij (P_ij control point 4 i
 * + j) with n steps each way: the four column curves C_j(v) and their
 * derivatives are stepped down v; at each row their values are the
 * control points of the row's curve in u, stepped across with its
 * u-derivative and the v-derivative's curve.  The (n + 1)^2 points and
 * normals dP/du x dP/dv go through the vertex pipeline into the
 * post-transform cache and 2 n^2 triangles, counter-clockwise about the
 * normal, go to the mesh path.  Values are kept with 16 more fractional
 * bits than 15.16, the differences rounded once at the start (the error
 * after n steps is below n^3 / 2 units of the extra bits: far below a
 * 15.16 unit at the step cap).  Where the normal vanishes (a patch edge
 * collapsed to a point, as at the poles of a lid) the nearest row's
 * normal at the same u is used.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "geom3d_int.h"
#include "../hw-sim/bus.h"

#define FD_SHIFT  16
#define FD_ONE	  ((int64_t)1 << FD_SHIFT)
#define PATCH_PTS 16

struct fd {
	int64_t f, d1, d2, d3;
};

/* Forward differences of a t^3 + b t^2 + c t + d over n steps. */
static void fd_init(struct fd *s, int64_t a, int64_t b, int64_t c, int64_t d,
		    int64_t n)
{
	int64_t a3 = g3_div_round(a, n * n * n), b2 = g3_div_round(b, n * n);
	int64_t c1 = g3_div_round(c, n);

	s->f = d;
	s->d1 = a3 + b2 + c1;
	s->d2 = 6 * a3 + 2 * b2;
	s->d3 = 6 * a3;
}

static void fd_step(struct fd *s)
{
	s->f += s->d1;
	s->d1 += s->d2;
	s->d2 += s->d3;
}

/* The cubic through Bezier values p0..p3, and its derivative. */
static void fd_bezier(struct fd *s, struct fd *ds, const int64_t *p, int64_t n)
{
	int64_t a = -p[0] + 3 * p[1] - 3 * p[2] + p[3];
	int64_t b = 3 * p[0] - 6 * p[1] + 3 * p[2];
	int64_t c = -3 * p[0] + 3 * p[1];

	fd_init(s, a, b, c, p[0], n);
	if (ds)
		fd_init(ds, 0, 3 * a, 2 * b, c, n);
}

static int32_t fd_raw(int64_t v)
{
	int64_t r = (v + ((int64_t)1 << (FD_SHIFT - 1))) >> FD_SHIFT;

	return (int32_t)RDC_MIN(RDC_MAX(r, (int64_t)-0x7fffffff - 1),
				(int64_t)0x7fffffff);
}

/* unit normal (2.30) of du x dv, zero when they are parallel */
static void cross_unit(const int64_t *du, const int64_t *dv, int32_t *out)
{
	int64_t u[3], v[3], n[3], m = 0;
	int i, sh = 0;

	for (i = 0; i < 3; i++) {
		m = RDC_MAX(m, RDC_MAX(du[i] < 0 ? -du[i] : du[i],
				       dv[i] < 0 ? -dv[i] : dv[i]));
	}
	while ((m >> sh) >= ((int64_t)1 << 30))
		sh++;
	for (i = 0; i < 3; i++) {
		u[i] = du[i] >> sh;
		v[i] = dv[i] >> sh;
	}
	n[0] = u[1] * v[2] - u[2] * v[1];
	n[1] = u[2] * v[0] - u[0] * v[2];
	n[2] = u[0] * v[1] - u[1] * v[0];
	if (!g3_normalize(n, out))
		out[0] = out[1] = out[2] = 0;
}

static bool zero3(const int32_t *v)
{
	return !v[0] && !v[1] && !v[2];
}

uint32_t g3_cmd_patch(struct rdc_dp *dp, const uint32_t *a)
{
	uint32_t mode = a[0], fl = mode & RDC_MESH_FLAGS;
	uint32_t n = (mode & RDC_PATCH_STEPS) >> 8, s, j, k, i, nv, r;
	bool vlit = (fl & RDC_MESH_LIT) && (fl & RDC_MESH_GOURAUD);
	struct fd col[4][3], dcol[4][3];
	struct g3_nmat nm;
	int64_t p[4];

	if (mode & ~(RDC_MESH_FLAGS | RDC_PATCH_STEPS))
		return RDC_ERR_ARG;
	if (n < 1 || n > RDC_PATCH_MAX_STEPS)
		return RDC_ERR_RANGE;
	if (!(fl & RDC_MESH_WIRE) && !dp_zbuf_ready(dp))
		return RDC_ERR_SURFACE;
	nv = (n + 1) * (n + 1);
	/* the column curves C_j(v), j = 0..3, per coordinate */
	for (j = 0; j < 4; j++) {
		for (k = 0; k < 3; k++) {
			for (i = 0; i < 4; i++)
				p[i] = (int64_t)(int32_t)
					       a[1 + 3 * (4 * i + j) + k] *
				       FD_ONE;
			fd_bezier(&col[j][k], &dcol[j][k], p, n);
		}
	}
	/* model positions and normals into the cache first */
	for (s = 0; s <= n; s++) {
		struct fd row[3], du[3], dv[3];
		int64_t q[4], d[4];

		for (k = 0; k < 3; k++) {
			for (j = 0; j < 4; j++) {
				q[j] = col[j][k].f;
				d[j] = dcol[j][k].f;
			}
			fd_bezier(&row[k], &du[k], q, n);
			fd_bezier(&dv[k], NULL, d, n);
		}
		for (j = 0; j <= n; j++) {
			struct rdc_dp_v3 *v = &dp->v3[s * (n + 1) + j];
			int64_t eu[3], ev[3];

			for (k = 0; k < 3; k++) {
				v->w[k] = fd_raw(row[k].f);
				eu[k] = du[k].f;
				ev[k] = dv[k].f;
				fd_step(&row[k]);
				fd_step(&du[k]);
				fd_step(&dv[k]);
			}
			cross_unit(eu, ev, v->n);
		}
		for (j = 0; j < 4; j++)
			for (k = 0; k < 3; k++) {
				fd_step(&col[j][k]);
				fd_step(&dcol[j][k]);
			}
	}
	/* a vanished normal takes the nearest row's at the same u */
	for (i = 0; i < nv; i++) {
		struct rdc_dp_v3 *v = &dp->v3[i];

		s = i / (n + 1);
		j = i % (n + 1);
		for (r = 1; zero3(v->n) && r <= n; r++) {
			if (s + r <= n &&
			    !zero3(dp->v3[(s + r) * (n + 1) + j].n))
				rdc_memcpy(v->n,
					   dp->v3[(s + r) * (n + 1) + j].n,
					   sizeof(v->n));
			else if (s >= r &&
				 !zero3(dp->v3[(s - r) * (n + 1) + j].n))
				rdc_memcpy(v->n,
					   dp->v3[(s - r) * (n + 1) + j].n,
					   sizeof(v->n));
		}
	}
	g3_normal_matrix(dp, &nm);
	for (i = 0; i < nv; i++) {
		int32_t pos[3], nrm[3];

		rdc_memcpy(pos, dp->v3[i].w, sizeof(pos));
		rdc_memcpy(nrm, dp->v3[i].n, sizeof(nrm));
		if (!g3_vertex(dp, pos, nrm, &nm, vlit, fl & RDC_MESH_TWO_SIDED,
			       &dp->v3[i]))
			return RDC_ERR_RANGE;
	}
	rdc_port_compute(dp->hw, nv * (RDC_T_TESS3 + RDC_T_VERTEX3 +
				       (vlit ? g3_light_cycles(dp) : 0)));
	k = 0;
	for (s = 0; s < n; s++) {
		for (j = 0; j < n; j++) {
			uint16_t k00 = (uint16_t)(s * (n + 1) + j);
			uint16_t k01 = (uint16_t)(k00 + 1);
			uint16_t k10 = (uint16_t)(k00 + n + 1);
			uint16_t k11 = (uint16_t)(k10 + 1);

			dp->v3_idx[k++] = k00;
			dp->v3_idx[k++] = k01;
			dp->v3_idx[k++] = k11;
			dp->v3_idx[k++] = k00;
			dp->v3_idx[k++] = k11;
			dp->v3_idx[k++] = k10;
		}
	}
	return g3_draw_tris(dp, fl | RDC_MESH_NORMALS, 2 * n * n);
}

uint32_t g3_cmd_bezier3(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	uint32_t n = fl ? fl : RDC_BEZIER3_STEPS, i, k;
	struct fd c[3];
	struct g3_nmat nm;
	int64_t p[4];

	for (k = 0; k < 3; k++) {
		for (i = 0; i < 4; i++)
			p[i] = (int64_t)(int32_t)a[3 * i + k] * FD_ONE;
		fd_bezier(&c[k], NULL, p, n);
	}
	g3_normal_matrix(dp, &nm);
	for (i = 0; i <= n; i++) {
		int32_t pos[3];

		for (k = 0; k < 3; k++) {
			/* the last point exactly on p3 */
			pos[k] = i == n ? (int32_t)a[9 + k] : fd_raw(c[k].f);
			fd_step(&c[k]);
		}
		if (!g3_vertex(dp, pos, NULL, &nm, false, false, &dp->v3[i]))
			return RDC_ERR_RANGE;
	}
	rdc_port_compute(dp->hw, (n + 1) * (RDC_T_TESS3 + RDC_T_VERTEX3));
	for (i = 0; i < n; i++)
		g3_draw_segment(dp, &dp->v3[i], &dp->v3[i + 1], i > 0);
	return RDC_ERR_NONE;
}

/*
 * A uniform cubic B-spline segment of control values q0..q3: the cubic
 * (-q0 + 3 q1 - 3 q2 + q3) t^3 + (3 q0 - 6 q1 + 3 q2) t^2 + (-3 q0 +
 * 3 q2) t + (q0 + 4 q1 + q2), all over 6, forward differenced.
 */
static void fd_bspline(struct fd *s, const int64_t *q, int64_t n)
{
	fd_init(s, g3_div_round(-q[0] + 3 * q[1] - 3 * q[2] + q[3], 6),
		g3_div_round(3 * q[0] - 6 * q[1] + 3 * q[2], 6),
		g3_div_round(-3 * q[0] + 3 * q[2], 6),
		g3_div_round(q[0] + 4 * q[1] + q[2], 6), n);
}

/*
 * (q0 + 4 q1 + q2) / 6 of coordinate k of the points from w: where the
 * segment of the window at w starts, and the one before it ends
 */
static int32_t bspline_joint(const uint32_t *w, uint32_t k)
{
	return (int32_t)g3_div_round((int64_t)(int32_t)w[k] +
					     4 * (int64_t)(int32_t)w[3 + k] +
					     (int32_t)w[6 + k],
				     6);
}

/*
 * Every point of the curve goes into the vertex cache (so the whole
 * command is checked before anything is drawn), each segment's first
 * point being the end of the one before it, then the polyline is drawn.
 */
uint32_t g3_cmd_bspline3(struct rdc_dp *dp, uint32_t fl, uint32_t len,
			 const uint32_t *a)
{
	uint32_t n = fl ? fl : RDC_BEZIER3_STEPS, np = len / 3, nv, s, i, k;
	struct g3_nmat nm;
	struct fd c[3];
	int64_t q[4];

	if (len % 3 || np < 4 || np > RDC_BSPLINE3_MAX_POINTS)
		return RDC_ERR_LENGTH;
	nv = (np - 3) * n + 1;
	if (nv > RDC_MESH_MAX_VERTS)
		return RDC_ERR_RANGE;
	g3_normal_matrix(dp, &nm);
	for (s = 0; s + 3 < np; s++) {
		const uint32_t *w = a + 3 * s;

		for (k = 0; k < 3; k++) {
			for (i = 0; i < 4; i++)
				q[i] = (int64_t)(int32_t)w[3 * i + k] * FD_ONE;
			fd_bspline(&c[k], q, n);
		}
		for (i = 0; i <= n; i++) {
			int32_t pos[3];

			/* the ends exactly, the same in every window */
			for (k = 0; k < 3; k++) {
				pos[k] = i == 0 ? bspline_joint(w, k) :
					 i == n ? bspline_joint(w + 3, k) :
						  fd_raw(c[k].f);
				fd_step(&c[k]);
			}
			if (s && !i)
				continue; /* the previous segment's end */
			if (!g3_vertex(dp, pos, NULL, &nm, false, false,
				       &dp->v3[s * n + i]))
				return RDC_ERR_RANGE;
		}
	}
	rdc_port_compute(dp->hw, nv * (RDC_T_TESS3 + RDC_T_VERTEX3));
	for (i = 0; i + 1 < nv; i++)
		g3_draw_segment(dp, &dp->v3[i], &dp->v3[i + 1], i > 0);
	return RDC_ERR_NONE;
}
