// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The 3D geometry stage: modelling transforms and their stack, the view
 * as the course sets it up (VRP, VPN, VUP, PRP, window, front and back
 * planes; Foley & van Dam, ch. 6), the vertex pipeline and homogeneous
 * clipping against the canonical view volume.
 *
 * Modelling.  The CTM is the top three rows of a 4x4 whose bottom row is
 * 0 0 0 1, in 15.16; each MATRIX_MULT, TRANSLATE, SCALE and ROTATE
 * post-multiplies it (the new transform applies to the vertices first), so
 * a display list that PUSHes, transforms, CALLs a sub-list and POPs draws
 * the sub-list's model under its own placement.  Products are exact 64-bit
 * sums rounded once to 15.16; an entry of the linear part at or above
 * 2^14 (16384.0) in size, or a translation leaving int32, fails the
 * command with RDC_ERR_RANGE and leaves the CTM alone.
 *
 * Viewing.  q = R (p - VRP) are view reference coordinates: R's rows are
 * u = VUP x n / |VUP x n|, v = n x u, n = VPN / |VPN|.  With the window's
 * centre CW = (cu, cv, 0), the shear sh = (CW - PRP)_uv / prp_n that
 * takes the direction of projection to the n axis, then Npar or Nper and
 * (perspective) Foley's Mper, the canonical volume to clip against is
 *
 *     -W <= X <= W,  -W <= Y <= W,  -W <= Z <= 0      (W > 0)
 *
 * which the DP reaches with these homogeneous coordinates, the course's
 * normalised ones multiplied by a positive factor chosen to keep every
 * coefficient a ratio of the view's own lengths (so the same fixed-point
 * precision serves a model a metre wide and one a kilometre wide):
 *
 *   parallel:     X = qu + shu qn - cu          Y = (Wd/Ht) (qv + shv qn - cv)
 *                 Z = (Wd/2) (qn - F) / (F - B) W = Wd / 2
 *   perspective:  X, Y the same
 *                 Z = aw e (qn - F) / (F - B)   W = aw (prp_n - qn)
 *                 aw = Wd / (2 prp_n),  e = prp_n - B
 *
 * Wd and Ht are the window's width and height.  X / W, Y / W are the
 * course's x and y in [-1, 1] and Z / W its z in [-1, 0] (0 the front
 * plane).  Perspective needs prp_n > F > B: everything in front of the
 * front plane, the eye included, has Z > 0 and is clipped, so nothing
 * behind the eye is drawn.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "geom3d_int.h"
#include "../hw-sim/bus.h"

#define G3_LIN_MAX  ((int64_t)1 << 30) /* |CTM linear entry| < 2^14 */
#define G3_COEF_MAX ((int64_t)1 << 28) /* view coefficient < 16.0 */
/* the view's ratios before the common scaling: < 2^14 */
#define G3_FACTOR_MAX ((int64_t)1 << 38)
#define G3_S32_MAX    ((int64_t)0x7fffffff)
#define G3_CLIP_MAX   G3_S32_MAX
#define G3_Z_MAX      65535
#define G3_T_SHIFT    30 /* clip parameter t in 2.30 */
#define G3_LIN_ONE    ((int64_t)1 << G3_LIN_SHIFT)

int64_t g3_div_round(int64_t n, int64_t d)
{
	int64_t q = n / d, r = n % d;

	if (r < 0) {
		q--;
		r += d;
	}
	if (2 * r >= d)
		q++;
	return q;
}

static int64_t g3_abs(int64_t v)
{
	return v < 0 ? -v : v;
}

static bool s32_ok(int64_t v)
{
	return v >= -G3_S32_MAX - 1 && v <= G3_S32_MAX;
}

bool g3_normalize(const int64_t *v, int32_t *out)
{
	int64_t m = RDC_MAX(RDC_MAX(g3_abs(v[0]), g3_abs(v[1])), g3_abs(v[2]));
	int64_t s[3], len;
	int sh = 0, i;

	if (!m)
		return false;
	/* bring the largest component to [2^29, 2^30): precise, no overflow */
	while ((m >> sh) >= ((int64_t)1 << 30))
		sh++;
	for (i = 0; i < 3; i++)
		s[i] = v[i] >> sh;
	m >>= sh;
	while (m < ((int64_t)1 << 29)) {
		for (i = 0; i < 3; i++)
			s[i] *= 2;
		m *= 2;
	}
	len = (int64_t)dp_isqrt(
		(uint64_t)(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
	if (!len)
		return false;
	for (i = 0; i < 3; i++)
		out[i] = (int32_t)g3_div_round(s[i] * ((int64_t)1 << 30), len);
	return true;
}

/* ---- modelling --------------------------------------------------------- */

static void mat_identity(int32_t m[3][4])
{
	rdc_memset(m, 0, sizeof(int32_t) * 12);
	m[0][0] = G3_ONE;
	m[1][1] = G3_ONE;
	m[2][2] = G3_ONE;
}

static bool mat_ok(const int32_t m[3][4])
{
	int r, c;

	for (r = 0; r < 3; r++)
		for (c = 0; c < 3; c++)
			if (g3_abs(m[r][c]) >= G3_LIN_MAX)
				return false;
	return true;
}

/* CTM = CTM * b; false (CTM unchanged) when the product leaves the range. */
static bool ctm_mult(struct rdc_dp *dp, const int32_t b[3][4])
{
	int32_t(*a)[4] = dp->g3.ctm;
	int32_t c[3][4];
	int r, k, j;

	if (!mat_ok(b))
		return false;
	for (r = 0; r < 3; r++) {
		for (j = 0; j < 4; j++) {
			int64_t s = j == 3 ? (int64_t)a[r][3] * G3_ONE : 0, v;

			for (k = 0; k < 3; k++)
				s += (int64_t)a[r][k] * b[k][j];
			v = g3_div_round(s, G3_ONE);
			if (j < 3 ? g3_abs(v) >= G3_LIN_MAX : !s32_ok(v))
				return false;
			c[r][j] = (int32_t)v;
		}
	}
	rdc_memcpy(a, c, sizeof(c));
	return true;
}

static uint32_t cmd_matrix(struct rdc_dp *dp, uint32_t op, uint32_t fl,
			   uint32_t len, const uint32_t *a)
{
	struct rdc_dp_3d *g = &dp->g3;
	int32_t m[3][4];
	int32_t c, s;
	int r, k;

	mat_identity(m);
	switch (op) {
	case RDC_OP_MATRIX_LOAD:
	case RDC_OP_MATRIX_MULT:
		if (op == RDC_OP_MATRIX_LOAD && len == 0) {
			mat_identity(g->ctm);
			return RDC_ERR_NONE;
		}
		if (len != 12)
			return RDC_ERR_LENGTH;
		for (r = 0; r < 3; r++)
			for (k = 0; k < 4; k++)
				m[r][k] = (int32_t)a[r * 4 + k];
		if (!mat_ok(m))
			return RDC_ERR_RANGE;
		if (op == RDC_OP_MATRIX_LOAD) {
			rdc_memcpy(g->ctm, m, sizeof(m));
			return RDC_ERR_NONE;
		}
		break;
	case RDC_OP_TRANSLATE:
		for (r = 0; r < 3; r++)
			m[r][3] = (int32_t)a[r];
		break;
	case RDC_OP_SCALE:
		for (r = 0; r < 3; r++)
			m[r][r] = (int32_t)a[r];
		break;
	case RDC_OP_ROTATE:
		if (fl > RDC_AXIS_Z)
			return RDC_ERR_ARG;
		c = dp_cos(a[0] & 0xffffu);
		s = dp_sin(a[0] & 0xffffu);
		/* the two axes after `fl`, in cyclic order x -> y -> z -> x */
		r = (int)(fl + 1) % 3;
		k = (int)(fl + 2) % 3;
		m[r][r] = c;
		m[r][k] = -s;
		m[k][r] = s;
		m[k][k] = c;
		break;
	default:
		return RDC_ERR_OPCODE;
	}
	return ctm_mult(dp, m) ? RDC_ERR_NONE : RDC_ERR_RANGE;
}

/* ---- viewing ----------------------------------------------------------- */

/*
 * Build the view from SET_VIEW's 18 words (or the reset view).  All
 * checks come first; the state changes only on success.
 */
static uint32_t view_set(struct rdc_dp *dp, bool persp, const int32_t *p)
{
	struct rdc_dp_3d *g = &dp->g3;
	const int32_t *vrp = p, *vpn = p + 3, *vup = p + 6, *prp = p + 9;
	int64_t umin = p[12], umax = p[13], vmin = p[14], vmax = p[15];
	int64_t F = p[16], B = p[17];
	int64_t wd = umax - umin, ht = vmax - vmin, t[3], c[4][3], k[4];
	int64_t shu, shv, ay, aw, az, e, cu2 = umax + umin, cv2 = vmax + vmin;
	int64_t m;
	int sh;
	int32_t R[3][3], lin[4][3], eye[3];
	int64_t tr[4];
	int i, j;

	if (wd <= 0 || ht <= 0 || F <= B || prp[2] <= 0 ||
	    (persp && prp[2] <= F))
		return RDC_ERR_ARG;
	for (i = 0; i < 3; i++)
		t[i] = vpn[i];
	if (!g3_normalize(t, R[2]))
		return RDC_ERR_ARG;
	/* u = VUP x n */
	t[0] = (int64_t)vup[1] * R[2][2] - (int64_t)vup[2] * R[2][1];
	t[1] = (int64_t)vup[2] * R[2][0] - (int64_t)vup[0] * R[2][2];
	t[2] = (int64_t)vup[0] * R[2][1] - (int64_t)vup[1] * R[2][0];
	if (!g3_normalize(t, R[0]))
		return RDC_ERR_ARG;
	/* v = n x u */
	t[0] = (int64_t)R[2][1] * R[0][2] - (int64_t)R[2][2] * R[0][1];
	t[1] = (int64_t)R[2][2] * R[0][0] - (int64_t)R[2][0] * R[0][2];
	t[2] = (int64_t)R[2][0] * R[0][1] - (int64_t)R[2][1] * R[0][0];
	if (!g3_normalize(t, R[1]))
		return RDC_ERR_ARG;

	shu = g3_div_round((cu2 - 2 * (int64_t)prp[0]) * G3_LIN_ONE,
			   2 * (int64_t)prp[2]);
	shv = g3_div_round((cv2 - 2 * (int64_t)prp[1]) * G3_LIN_ONE,
			   2 * (int64_t)prp[2]);
	ay = g3_div_round(wd * G3_LIN_ONE, ht);
	if (g3_abs(shu) >= G3_COEF_MAX || g3_abs(shv) >= G3_COEF_MAX ||
	    ay >= G3_COEF_MAX)
		return RDC_ERR_RANGE;
	rdc_memset(c, 0, sizeof(c));
	c[0][0] = G3_LIN_ONE;
	c[0][2] = shu;
	c[1][1] = ay;
	c[1][2] = g3_div_round(ay * shv, G3_LIN_ONE);
	if (!persp) {
		az = g3_div_round(wd * (G3_LIN_ONE / 2), F - B);
		aw = 0;
	} else {
		aw = g3_div_round(wd * G3_LIN_ONE, 2 * (int64_t)prp[2]);
		e = g3_div_round(((int64_t)prp[2] - B) * G3_LIN_ONE, F - B);
		/* aw * e must fit: each below 2^38, their product below 2^62 */
		if (aw <= 0 || aw >= G3_FACTOR_MAX || e >= G3_FACTOR_MAX ||
		    e > ((int64_t)1 << 62) / aw)
			return RDC_ERR_RANGE;
		az = g3_div_round(aw * e, G3_LIN_ONE);
	}
	if (az >= G3_FACTOR_MAX)
		return RDC_ERR_RANGE;
	c[2][2] = az;
	c[3][2] = -aw;
	/*
	 * One power of two over every coefficient (homogeneous coordinates
	 * do not mind) brings the largest below G3_COEF_MAX.
	 */
	m = 0;
	for (i = 0; i < 4; i++)
		for (j = 0; j < 3; j++)
			m = RDC_MAX(m, g3_abs(c[i][j]));
	sh = 0;
	while ((m >> sh) >= G3_COEF_MAX)
		sh++;
	for (i = 0; i < 4; i++)
		for (j = 0; j < 3; j++)
			c[i][j] = g3_div_round(c[i][j], (int64_t)1 << sh);
	/* the constant terms, in clip units, from the scaled coefficients */
	k[0] = -g3_div_round(cu2, (int64_t)2 << sh);
	k[1] = -g3_div_round(c[1][1] * cv2, 2 * G3_LIN_ONE);
	k[2] = -g3_div_round(c[2][2] * F, G3_LIN_ONE);
	if (!persp)
		k[3] = g3_div_round(wd, (int64_t)2 << sh);
	else
		k[3] = g3_div_round(-c[3][2] * prp[2], G3_LIN_ONE);
	/* lin = c R (7.24); tr = k - lin VRP (clip units) */
	for (i = 0; i < 4; i++) {
		int64_t s;

		for (j = 0; j < 3; j++) {
			s = c[i][0] * R[0][j] + c[i][1] * R[1][j] +
			    c[i][2] * R[2][j];
			lin[i][j] = (int32_t)g3_div_round(
				s, (int64_t)1 << G3_UNIT_SHIFT);
		}
		s = (int64_t)lin[i][0] * vrp[0] + (int64_t)lin[i][1] * vrp[1] +
		    (int64_t)lin[i][2] * vrp[2];
		tr[i] = k[i] - g3_div_round(s, (int64_t)1 << G3_LIN_SHIFT);
		if (g3_abs(tr[i]) > ((int64_t)1 << 40))
			return RDC_ERR_RANGE;
	}
	/* the eye: the COP, or the direction towards the viewer */
	if (persp) {
		for (j = 0; j < 3; j++) {
			int64_t s = (int64_t)R[0][j] * prp[0] +
				    (int64_t)R[1][j] * prp[1] +
				    (int64_t)R[2][j] * prp[2];
			int64_t v =
				vrp[j] +
				g3_div_round(s, (int64_t)1 << G3_UNIT_SHIFT);

			if (!s32_ok(v))
				return RDC_ERR_RANGE;
			eye[j] = (int32_t)v;
		}
	} else {
		int64_t d[3] = { 2 * (int64_t)prp[0] - cu2,
				 2 * (int64_t)prp[1] - cv2,
				 2 * (int64_t)prp[2] };

		for (j = 0; j < 3; j++)
			t[j] = R[0][j] * (d[0] >> 4) + R[1][j] * (d[1] >> 4) +
			       R[2][j] * (d[2] >> 4);
		if (!g3_normalize(t, eye))
			return RDC_ERR_ARG;
	}
	rdc_memcpy(g->lin, lin, sizeof(lin));
	rdc_memcpy(g->tr, tr, sizeof(tr));
	rdc_memcpy(g->eye, eye, sizeof(eye));
	g->persp = persp;
	return RDC_ERR_NONE;
}

/* ---- the vertex pipeline ------------------------------------------------ */

void g3_normal_matrix(const struct rdc_dp *dp, struct g3_nmat *nm)
{
	const int32_t(*a)[4] = dp->g3.ctm;
	int64_t m = 0, det;
	int r, c, sh = 0;

	for (r = 0; r < 3; r++) {
		for (c = 0; c < 3; c++) {
			int r1 = (r + 1) % 3, r2 = (r + 2) % 3;
			int c1 = (c + 1) % 3, c2 = (c + 2) % 3;

			nm->m[r][c] = (int64_t)a[r1][c1] * a[r2][c2] -
				      (int64_t)a[r1][c2] * a[r2][c1];
			m = RDC_MAX(m, g3_abs(nm->m[r][c]));
		}
	}
	while ((m >> sh) >= ((int64_t)1 << 30))
		sh++;
	for (r = 0; r < 3; r++)
		for (c = 0; c < 3; c++)
			nm->m[r][c] >>= sh;
	det = a[0][0] * nm->m[0][0] + a[0][1] * nm->m[0][1] +
	      a[0][2] * nm->m[0][2];
	if (det < 0)
		for (r = 0; r < 3; r++)
			for (c = 0; c < 3; c++)
				nm->m[r][c] = -nm->m[r][c];
}

static uint8_t outcode(const int64_t *c)
{
	uint8_t o = 0;

	if (c[3] + c[0] < 0)
		o |= 1;
	if (c[3] - c[0] < 0)
		o |= 2;
	if (c[3] + c[1] < 0)
		o |= 4;
	if (c[3] - c[1] < 0)
		o |= 8;
	if (c[2] > 0)
		o |= 16;
	if (c[3] + c[2] < 0)
		o |= 32;
	return o;
}

void g3_project(const struct rdc_dp *dp, const int64_t *c, int32_t *sx,
		int32_t *sy, uint32_t *z)
{
	const struct rdc_dp_3d *g = &dp->g3;
	int64_t w = c[3], x, y, d;

	/* inside the volume w > 0; a degenerate w = 0 is the point (0, 0) */
	if (w <= 0) {
		*sx = g->vx0;
		*sy = g->vy1;
		*z = 0;
		return;
	}
	x = g->vx0 + g3_div_round((c[0] + w) * (g->vx1 - g->vx0), 2 * w);
	y = g->vy1 - g3_div_round((c[1] + w) * (g->vy1 - g->vy0), 2 * w);
	d = g3_div_round(-c[2] * G3_Z_MAX, w);
	*sx = (int32_t)RDC_MIN(RDC_MAX(x, (int64_t)g->vx0), (int64_t)g->vx1);
	*sy = (int32_t)RDC_MIN(RDC_MAX(y, (int64_t)g->vy0), (int64_t)g->vy1);
	*z = (uint32_t)RDC_MIN(RDC_MAX(d, (int64_t)0), (int64_t)G3_Z_MAX);
}

bool g3_vertex(struct rdc_dp *dp, const int32_t *pos, const int32_t *nrm,
	       const struct g3_nmat *nm, bool lit, bool two_sided,
	       struct rdc_dp_v3 *v)
{
	const struct rdc_dp_3d *g = &dp->g3;
	int64_t c[4], t[3];
	int i;

	for (i = 0; i < 3; i++) {
		int64_t s = (int64_t)g->ctm[i][0] * pos[0] +
			    (int64_t)g->ctm[i][1] * pos[1] +
			    (int64_t)g->ctm[i][2] * pos[2] +
			    (int64_t)g->ctm[i][3] * G3_ONE;

		s = g3_div_round(s, G3_ONE);
		if (!s32_ok(s))
			return false;
		v->w[i] = (int32_t)s;
	}
	for (i = 0; i < 4; i++) {
		int64_t s = (int64_t)g->lin[i][0] * v->w[0] +
			    (int64_t)g->lin[i][1] * v->w[1] +
			    (int64_t)g->lin[i][2] * v->w[2];

		c[i] = g3_div_round(s, (int64_t)1 << G3_LIN_SHIFT) + g->tr[i];
		if (g3_abs(c[i]) > G3_CLIP_MAX)
			return false;
		v->c[i] = (int32_t)c[i];
	}
	v->out = outcode(c);
	v->sx = 0;
	v->sy = 0;
	v->z = 0;
	if (!v->out)
		g3_project(dp, c, &v->sx, &v->sy, &v->z);
	v->n[0] = v->n[1] = v->n[2] = 0;
	if (nrm) {
		for (i = 0; i < 3; i++)
			t[i] = nm->m[i][0] * nrm[0] + nm->m[i][1] * nrm[1] +
			       nm->m[i][2] * nrm[2];
		g3_normalize(t, v->n);
	}
	v->rgb = 0;
	if (lit)
		v->rgb = g3_light(dp, v->w, v->n, two_sided);
	return true;
}

/* ---- clipping ----------------------------------------------------------- */

/* Signed distance of c inside clip plane k (>= 0: inside). */
static int64_t plane_dist(const int64_t *c, unsigned int k)
{
	switch (k) {
	case 0:
		return c[3] + c[0];
	case 1:
		return c[3] - c[0];
	case 2:
		return c[3] + c[1];
	case 3:
		return c[3] - c[1];
	case 4:
		return -c[2];
	default:
		return c[3] + c[2];
	}
}

/*
 * The point where the edge from inside vertex a (da >= 0) to outside
 * vertex b (db < 0) meets plane k, put exactly on the plane.  Always
 * computed from the inside end, so the two triangles sharing an edge
 * clip it to the same point.
 */
static void plane_cut(const struct g3_pv *a, const struct g3_pv *b, int64_t da,
		      int64_t db, unsigned int k, struct g3_pv *o)
{
	int64_t t = g3_div_round(da << G3_T_SHIFT, da - db);
	int i;

	for (i = 0; i < 4; i++)
		o->c[i] = a->c[i] + ((b->c[i] - a->c[i]) * t >> G3_T_SHIFT);
	for (i = 0; i < 3; i++)
		o->col[i] = a->col[i] +
			    (int32_t)(((int64_t)(b->col[i] - a->col[i]) * t +
				       ((int64_t)1 << (G3_T_SHIFT - 1))) >>
				      G3_T_SHIFT);
	switch (k) {
	case 0:
		o->c[0] = -o->c[3];
		break;
	case 1:
		o->c[0] = o->c[3];
		break;
	case 2:
		o->c[1] = -o->c[3];
		break;
	case 3:
		o->c[1] = o->c[3];
		break;
	case 4:
		o->c[2] = 0;
		break;
	default:
		o->c[2] = -o->c[3];
		break;
	}
}

uint32_t g3_clip_poly(struct rdc_dp *dp, struct g3_pv *p, uint32_t n,
		      struct g3_pv *tmp)
{
	unsigned int k;
	uint32_t i, m, made = 0;

	for (k = 0; k < G3_PLANES && n; k++) {
		m = 0;
		for (i = 0; i < n; i++) {
			const struct g3_pv *a = &p[i], *b = &p[(i + 1) % n];
			int64_t da = plane_dist(a->c, k),
				db = plane_dist(b->c, k);

			if (da >= 0)
				tmp[m++] = *a;
			if ((da >= 0) != (db >= 0) && m < G3_POLY_MAX) {
				if (da >= 0)
					plane_cut(a, b, da, db, k, &tmp[m]);
				else
					plane_cut(b, a, db, da, k, &tmp[m]);
				m++;
				made++;
			}
		}
		for (i = 0; i < m; i++)
			p[i] = tmp[i];
		n = m;
	}
	if (made)
		rdc_port_compute(dp->hw, made * RDC_T_CLIP3);
	return n < 3 ? 0 : n;
}

bool g3_clip_line(struct g3_pv *a, struct g3_pv *b)
{
	unsigned int k;

	for (k = 0; k < G3_PLANES; k++) {
		int64_t da = plane_dist(a->c, k), db = plane_dist(b->c, k);
		struct g3_pv o;

		if (da < 0 && db < 0)
			return false;
		if (da >= 0 && db >= 0)
			continue;
		if (da >= 0) {
			plane_cut(a, b, da, db, k, &o);
			*b = o;
		} else {
			plane_cut(b, a, db, da, k, &o);
			*a = o;
		}
	}
	return true;
}

/* ---- commands ----------------------------------------------------------- */

static const int32_t view_reset[18] = {
	0,	 0,	  0,		   /* VRP */
	0,	 0,	  G3_ONE,	   /* VPN */
	0,	 G3_ONE,  0,		   /* VUP */
	0,	 0,	  G3_ONE,	   /* PRP */
	-G3_ONE, G3_ONE,  -G3_ONE, G3_ONE, /* window */
	G3_ONE,	 -G3_ONE,		   /* F, B */
};

void dp_3d_reset(struct rdc_dp *dp)
{
	struct rdc_dp_3d *g = &dp->g3;
	struct rdc_timing tm = { 0 };
	int i;

	mat_identity(g->ctm);
	g->sp = 0;
	view_set(dp, false, view_reset);
	rdc_preset_timing(RDC_PRESET_640x480_60, &tm);
	g->vx0 = 0;
	g->vy0 = 0;
	g->vx1 = (int32_t)tm.h_display - 1;
	g->vy1 = (int32_t)tm.v_display - 1;
	g->ambient = 0x202020;
	for (i = 0; i < RDC_LIGHTS; i++)
		g->light[i].on = 0;
	g->mat_amb = 0xffffff;
	g->mat_diff = 0xffffff;
	g->mat_spec = 0;
	g->mat_shine = 1;
}

static bool coord_ok(int32_t v)
{
	return v >= RDC_COORD_MIN && v <= RDC_COORD_MAX;
}

static uint32_t cmd_light(struct rdc_dp *dp, uint32_t fl, uint32_t len,
			  const uint32_t *a)
{
	struct rdc_dp_light *l;
	int64_t d[3];
	int32_t u[3];
	int i;

	if (fl >= RDC_LIGHTS)
		return RDC_ERR_ARG;
	l = &dp->g3.light[fl];
	if (len == 0) {
		l->on = 0;
		return RDC_ERR_NONE;
	}
	if (len != 4)
		return RDC_ERR_LENGTH;
	if (a[0] > 0xffffffu)
		return RDC_ERR_RANGE;
	for (i = 0; i < 3; i++)
		d[i] = (int32_t)a[1 + i];
	if (!g3_normalize(d, u))
		return RDC_ERR_ARG;
	l->on = 1;
	l->rgb = a[0];
	rdc_memcpy(l->dir, u, sizeof(u));
	return RDC_ERR_NONE;
}

uint32_t dp_cmd_3d(struct rdc_dp *dp, uint32_t op, uint32_t fl, uint32_t len,
		   const uint32_t *a)
{
	struct rdc_dp_3d *g = &dp->g3;
	int32_t p[18];
	int i;

	switch (op) {
	case RDC_OP_MATRIX_LOAD:
	case RDC_OP_MATRIX_MULT:
	case RDC_OP_TRANSLATE:
	case RDC_OP_SCALE:
	case RDC_OP_ROTATE:
		return cmd_matrix(dp, op, fl, len, a);
	case RDC_OP_PUSH_MATRIX:
		if (g->sp >= RDC_MATRIX_STACK_DEPTH)
			return RDC_ERR_STACK;
		rdc_memcpy(g->stack[g->sp++], g->ctm, sizeof(g->ctm));
		return RDC_ERR_NONE;
	case RDC_OP_POP_MATRIX:
		if (!g->sp)
			return RDC_ERR_STACK;
		rdc_memcpy(g->ctm, g->stack[--g->sp], sizeof(g->ctm));
		return RDC_ERR_NONE;
	case RDC_OP_SET_VIEW:
		if (fl & ~RDC_VIEW_PERSPECTIVE)
			return RDC_ERR_ARG;
		for (i = 0; i < 18; i++)
			p[i] = (int32_t)a[i];
		return view_set(dp, fl & RDC_VIEW_PERSPECTIVE, p);
	case RDC_OP_SET_VIEWPORT3:
		if (!coord_ok(RDC_X(a[0])) || !coord_ok(RDC_Y(a[0])) ||
		    !coord_ok(RDC_X(a[1])) || !coord_ok(RDC_Y(a[1])))
			return RDC_ERR_RANGE;
		if (RDC_X(a[0]) >= RDC_X(a[1]) || RDC_Y(a[0]) >= RDC_Y(a[1]))
			return RDC_ERR_ARG;
		g->vx0 = RDC_X(a[0]);
		g->vy0 = RDC_Y(a[0]);
		g->vx1 = RDC_X(a[1]);
		g->vy1 = RDC_Y(a[1]);
		return RDC_ERR_NONE;
	case RDC_OP_SET_LIGHT:
		return cmd_light(dp, fl, len, a);
	case RDC_OP_SET_AMBIENT:
		if (a[0] > 0xffffffu)
			return RDC_ERR_RANGE;
		g->ambient = a[0];
		return RDC_ERR_NONE;
	case RDC_OP_SET_MATERIAL:
		if (a[0] > 0xffffffu || a[1] > 0xffffffu || a[2] > 0xffffffu)
			return RDC_ERR_RANGE;
		if (a[3] < 1 || a[3] > 255)
			return RDC_ERR_RANGE;
		g->mat_amb = a[0];
		g->mat_diff = a[1];
		g->mat_spec = a[2];
		g->mat_shine = a[3];
		return RDC_ERR_NONE;
	case RDC_OP_MESH:
		return g3_cmd_mesh(dp, fl, a);
	case RDC_OP_PATCH:
		return g3_cmd_patch(dp, a);
	case RDC_OP_BEZIER3:
		return g3_cmd_bezier3(dp, fl, a);
	case RDC_OP_BSPLINE3:
		return g3_cmd_bspline3(dp, fl, len, a);
	default:
		return RDC_ERR_OPCODE;
	}
}
