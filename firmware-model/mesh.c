// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Polygon meshes: a vertex buffer and an index buffer in VRAM, every
 * vertex through the pipeline once (the post-transform cache dp->v3),
 * then each triangle rejected by its outcodes, clipped in homogeneous
 * coordinates when it crosses the volume, culled by the orientation of
 * its projection, and filled by TRIANGLE's rasteriser (flat or Gouraud,
 * with the depth buffer of SET_ZBUF) or drawn as each edge once.
 *
 * Facing is decided after clipping, from the exact signed area of the
 * projected polygon's integer vertices, the same vertices the rasteriser
 * fills: a triangle counter-clockwise on the screen (y up) is a front
 * face.  Clipped vertices are computed from the inside end of each edge,
 * so triangles sharing an edge meet on the same pixels.
 *
 * RDC_MESH_SCANLINE fills without a depth buffer (Foley, van Dam et al.,
 * 15.6): the projected triangles go into an edge table by first row;
 * each row keeps the active triangles, takes each one's span from its
 * two edges crossing the row (the split points B of poly.c, so the
 * coverage is TRIANGLE's), and resolves the row in an on-chip row of
 * depths, a triangle's depth interpolated along its span exactly as
 * TRIANGLE does, the nearest winning and the first drawn on a tie, as a
 * depth buffer cleared to 0xffff with TEST and WRITE would.  Each pixel
 * is then written once, a run of covered pixels a span.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "geom3d_int.h"
#include "../hw-sim/bus.h"

#define IDX_BYTES      2u
#define SORT_DEPTH_MAX ((1u << 20) - 1)
#define SORT_TRI       0xfffu /* RDC_MESH_MAX_TRIS - 1 */

static void pv_from(struct g3_pv *p, const struct rdc_dp_v3 *v)
{
	int i;

	for (i = 0; i < 4; i++)
		p->c[i] = v->c[i];
	p->col[0] = (int32_t)(v->rgb >> 16 & 0xff);
	p->col[1] = (int32_t)(v->rgb >> 8 & 0xff);
	p->col[2] = (int32_t)(v->rgb & 0xff);
}

static uint32_t pv_rgb(const struct g3_pv *p)
{
	uint32_t out = 0;
	int k;

	for (k = 0; k < 3; k++)
		out |= (uint32_t)RDC_MIN(RDC_MAX(p->col[k], 0), 255)
		       << (16 - 8 * k);
	return out;
}

/* The flat colour of triangle a, b, c: its face normal, lit at the centroid */
static uint32_t face_rgb(struct rdc_dp *dp, const struct rdc_dp_v3 *a,
			 const struct rdc_dp_v3 *b, const struct rdc_dp_v3 *c,
			 bool two_sided)
{
	int64_t e1[3], e2[3], n[3], m = 0;
	int32_t un[3], pc[3];
	int i, sh = 0;

	for (i = 0; i < 3; i++) {
		e1[i] = (int64_t)b->w[i] - a->w[i];
		e2[i] = (int64_t)c->w[i] - a->w[i];
		m = RDC_MAX(m, RDC_MAX(e1[i] < 0 ? -e1[i] : e1[i],
				       e2[i] < 0 ? -e2[i] : e2[i]));
		pc[i] = (int32_t)(((int64_t)a->w[i] + b->w[i] + c->w[i]) / 3);
	}
	while ((m >> sh) >= ((int64_t)1 << 30))
		sh++;
	for (i = 0; i < 3; i++) {
		e1[i] >>= sh;
		e2[i] >>= sh;
	}
	n[0] = e1[1] * e2[2] - e1[2] * e2[1];
	n[1] = e1[2] * e2[0] - e1[0] * e2[2];
	n[2] = e1[0] * e2[1] - e1[1] * e2[0];
	if (!g3_normalize(n, un))
		return 0;
	rdc_port_compute(dp->hw, g3_light_cycles(dp));
	return g3_light(dp, pc, un, two_sided);
}

/*
 * Triangle i0, i1, i2 clipped and projected into x, y, z, rgb (at most
 * G3_POLY_MAX vertices); returns the count (0: nothing visible) and
 * *area2, twice the signed area on the screen with y down (negative for
 * a front face).
 */
static uint32_t tri_project(struct rdc_dp *dp, const struct rdc_dp_v3 *v[3],
			    int32_t *x, int32_t *y, uint32_t *z, uint32_t *rgb,
			    int64_t *area2)
{
	struct g3_pv p[G3_POLY_MAX], tmp[G3_POLY_MAX];
	uint32_t n = 3, i;
	int64_t a = 0;

	if (v[0]->out & v[1]->out & v[2]->out)
		return 0;
	if (!(v[0]->out | v[1]->out | v[2]->out)) {
		for (i = 0; i < 3; i++) {
			x[i] = v[i]->sx;
			y[i] = v[i]->sy;
			z[i] = v[i]->z;
			rgb[i] = v[i]->rgb;
		}
	} else {
		for (i = 0; i < 3; i++)
			pv_from(&p[i], v[i]);
		n = g3_clip_poly(dp, p, 3, tmp);
		for (i = 0; i < n; i++) {
			g3_project(dp, p[i].c, &x[i], &y[i], &z[i]);
			rgb[i] = pv_rgb(&p[i]);
		}
	}
	for (i = 0; i < n; i++) {
		uint32_t j = (i + 1) % n;

		a += (int64_t)x[i] * y[j] - (int64_t)x[j] * y[i];
	}
	*area2 = a;
	return n;
}

/* Sift-down heapsort of the edge keys: no scratch, O(n log n). */
static void edge_sort(uint32_t *e, uint32_t n)
{
	uint32_t start = n / 2, end = n, root, child, t;

	while (end > 1) {
		if (start > 0) {
			start--;
		} else {
			end--;
			t = e[end];
			e[end] = e[0];
			e[0] = t;
		}
		root = start;
		while ((child = 2 * root + 1) < end) {
			if (child + 1 < end && e[child] < e[child + 1])
				child++;
			if (e[root] >= e[child])
				break;
			t = e[root];
			e[root] = e[child];
			e[child] = t;
			root = child;
		}
	}
}

void g3_draw_segment(struct rdc_dp *dp, const struct rdc_dp_v3 *a,
		     const struct rdc_dp_v3 *b, bool skip_first)
{
	struct g3_pv pa, pb;
	int32_t x0, y0, x1, y1;
	uint32_t z;

	if (a->out & b->out)
		return;
	pv_from(&pa, a);
	pv_from(&pb, b);
	if ((a->out | b->out) && !g3_clip_line(&pa, &pb))
		return;
	if (a->out | b->out)
		rdc_port_compute(dp->hw, RDC_T_CLIP3);
	g3_project(dp, pa.c, &x0, &y0, &z);
	g3_project(dp, pb.c, &x1, &y1, &z);
	rdc_dp_line(dp, x0, y0, x1, y1, skip_first && !a->out, false);
}

/*
 * Extents: false when every vertex the triangles use lies outside one
 * and the same clip plane (the mesh's box is outside the volume).
 */
static bool g3_any_inside(const struct rdc_dp *dp, uint32_t ntri)
{
	uint8_t all = 0xff;
	uint32_t i;

	for (i = 0; i < 3 * ntri && all; i++)
		all &= dp->v3[dp->v3_idx[i]].out;
	return !all;
}

/* Depth of a clip-space vertex for the painter's sort: -z / w in 0..2^20. */
static uint32_t sort_depth(const struct rdc_dp_v3 *v)
{
	int64_t w = v->c[3], z = -(int64_t)v->c[2], d;

	if (w <= 0)
		return 0; /* at or behind the eye: clipped anyway */
	d = z <= 0 ? 0 : z >= w ? SORT_DEPTH_MAX : (z << 20) / w;
	return (uint32_t)RDC_MIN(d, (int64_t)SORT_DEPTH_MAX);
}

/*
 * Painter's order: dp->v3_edge[k] = (far key << 12 | triangle), sorted so
 * the farthest triangle (by its farthest vertex) comes first, ties in
 * their order in the mesh.
 */
static void depth_sort(struct rdc_dp *dp, uint32_t ntri)
{
	uint32_t t, i, levels = 0;

	for (t = 0; t < ntri; t++) {
		uint32_t d = 0;

		for (i = 0; i < 3; i++)
			d = RDC_MAX(d,
				    sort_depth(&dp->v3[dp->v3_idx[3 * t + i]]));
		dp->v3_edge[t] = (SORT_DEPTH_MAX - d) << 12 | t;
	}
	edge_sort(dp->v3_edge, ntri);
	while ((1u << levels) < ntri)
		levels++;
	rdc_port_compute(dp->hw, ntri * levels * RDC_T_SORT3);
}

#define SCAN_NONE 0xffffu
#define SCAN_BACK 0xffffu /* the depth a pixel must be nearer than */

/* Add one fan triangle to the scan-line set; false when it is full. */
static bool scan_add(struct rdc_dp *dp, uint32_t *ns, const int32_t *x,
		     const int32_t *y, const uint32_t *col, const uint32_t *z)
{
	struct rdc_dp_stri *s;
	int i;

	if (*ns >= RDC_MESH_SCAN_MAX_TRIS)
		return false;
	s = &dp->v3_scan[(*ns)++];
	for (i = 0; i < 3; i++) {
		s->x[i] = x[i];
		s->y[i] = y[i];
		s->col[i] = col[i];
		s->z[i] = (uint16_t)z[i];
	}
	return true;
}

/*
 * Pixels [*xa, *xb] of row py the triangle covers: TRIANGLE's rule, the
 * split B(py) of each of the two edges crossing the row (poly.c); false
 * when none.
 */
static bool scan_span(const struct rdc_dp_stri *s, int32_t py, int32_t *xa,
		      int32_t *xb)
{
	int64_t b[2] = { 0, 0 };
	int i, n = 0;

	for (i = 0; i < 3 && n < 2; i++) {
		int64_t x0 = s->x[i], y0 = s->y[i];
		int64_t x1 = s->x[(i + 1) % 3], y1 = s->y[(i + 1) % 3], t;

		if (y0 > y1) {
			t = x0, x0 = x1, x1 = t;
			t = y0, y0 = y1, y1 = t;
		}
		if (py < y0 || py >= y1)
			continue;
		b[n++] = dp_div_floor((2 * py + 1 - 2 * y0) * (x1 - x0) +
					      (2 * x0 - 1) * (y1 - y0) +
					      2 * (y1 - y0) - 1,
				      2 * (y1 - y0));
	}
	if (n < 2 || b[0] == b[1])
		return false;
	*xa = (int32_t)RDC_MIN(b[0], b[1]);
	*xb = (int32_t)RDC_MAX(b[0], b[1]) - 1;
	return true;
}

/*
 * Resolve row y, columns [cx0, cx1) (at most RDC_DP_CHUNK), among the
 * na active triangles, and write its covered runs.
 */
static void scan_row(struct rdc_dp *dp, bool gouraud, int32_t y, int32_t cx0,
		     int32_t cx1, uint32_t na)
{
	uint32_t *rz = dp->flood_row[1], *rid = dp->flood_row[2];
	uint32_t n = (uint32_t)(cx1 - cx0), i, k;
	struct dp_tri t;
	int32_t x, xa, xb;

	for (i = 0; i < n; i++) {
		rz[i] = SCAN_BACK;
		rid[i] = SCAN_NONE;
	}
	for (k = 0; k < na; k++) {
		uint32_t id = dp->v3_act[k];
		const struct rdc_dp_stri *s = &dp->v3_scan[id];
		uint32_t z3[3] = { s->z[0], s->z[1], s->z[2] };

		if (!scan_span(s, y, &xa, &xb))
			continue;
		xa = RDC_MAX(xa, cx0);
		xb = RDC_MIN(xb, cx1 - 1);
		if (xa > xb ||
		    !dp_tri_setup(dp, s->x, s->y, s->col, z3, gouraud, &t))
			continue;
		for (x = xa; x <= xb; x++) {
			uint32_t z = dp_tri_depth(&t, x, y),
				 j = (uint32_t)(x - cx0);

			if (z < rz[j] || (z == rz[j] && id < rid[j])) {
				rz[j] = z;
				rid[j] = id;
			}
		}
	}
	/* each maximal run of covered pixels is one DST span */
	for (i = 0; i < n;) {
		uint32_t r = i, last = SCAN_NONE;

		if (rid[i] == SCAN_NONE) {
			i++;
			continue;
		}
		while (r < n && rid[r] != SCAN_NONE) {
			if (rid[r] != last) {
				const struct rdc_dp_stri *s =
					&dp->v3_scan[rid[r]];
				uint32_t z3[3] = { s->z[0], s->z[1], s->z[2] };

				last = rid[r];
				dp_tri_setup(dp, s->x, s->y, s->col, z3,
					     gouraud, &t);
			}
			dp->px[r - i] = dp_tri_pixel(&t, cx0 + (int32_t)r, y);
			r++;
		}
		rdc_dp_span_px(dp, y, cx0 + (int32_t)i, r - i, 0, dp->px, NULL);
		i = r;
	}
}

/* Draw the ns gathered triangles a scan line at a time. */
static void scan_draw(struct rdc_dp *dp, bool gouraud, uint32_t ns)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	uint32_t i, k, j, na = 0;
	int32_t y, cx;

	if (c.x0 >= c.x1 || c.y0 >= c.y1 || !ns)
		return;
	for (i = 0; i < (uint32_t)(c.y1 - c.y0); i++)
		dp->poly_et[i] = SCAN_NONE;
	/* the edge table: each triangle in the bucket of its first row */
	for (k = ns; k-- > 0;) {
		struct rdc_dp_stri *s = &dp->v3_scan[k];
		int32_t top = RDC_MIN(RDC_MIN(s->y[0], s->y[1]), s->y[2]);

		s->yend = RDC_MAX(RDC_MAX(s->y[0], s->y[1]), s->y[2]);
		top = RDC_MAX(top, c.y0);
		if (top >= RDC_MIN(s->yend, c.y1))
			continue;
		s->next = dp->poly_et[top - c.y0];
		dp->poly_et[top - c.y0] = (uint16_t)k;
	}
	for (y = c.y0; y < c.y1; y++) {
		/* new triangles in, finished ones out */
		for (k = dp->poly_et[y - c.y0]; k != SCAN_NONE;
		     k = dp->v3_scan[k].next)
			dp->v3_act[na++] = (uint16_t)k;
		for (k = 0, j = 0; k < na; k++)
			if (dp->v3_scan[dp->v3_act[k]].yend > y)
				dp->v3_act[j++] = dp->v3_act[k];
		na = j;
		if (!na)
			continue;
		for (cx = c.x0; cx < c.x1; cx += (int32_t)RDC_DP_CHUNK)
			scan_row(dp, gouraud, y, cx,
				 (int32_t)RDC_MIN((int64_t)cx + RDC_DP_CHUNK,
						  (int64_t)c.x1),
				 na);
	}
}

uint32_t g3_draw_tris(struct rdc_dp *dp, uint32_t fl, uint32_t ntri)
{
	bool wire = fl & RDC_MESH_WIRE, cull = fl & RDC_MESH_CULL;
	bool scan = !wire && (fl & RDC_MESH_SCANLINE);
	bool lit = fl & RDC_MESH_LIT, gouraud = lit && (fl & RDC_MESH_GOURAUD);
	bool two = fl & RDC_MESH_TWO_SIDED;
	int32_t x[G3_POLY_MAX], y[G3_POLY_MAX];
	uint32_t z[G3_POLY_MAX], rgb[G3_POLY_MAX], col[G3_POLY_MAX];
	bool sort = !wire && (fl & RDC_MESH_SORT);
	uint32_t k, t, i, n, nedge = 0, ns = 0;

	/* every vertex outside one clip plane: nothing to set up */
	if (!g3_any_inside(dp, ntri))
		return RDC_ERR_NONE;
	if (sort)
		depth_sort(dp, ntri);
	for (k = 0; k < ntri; k++) {
		const uint16_t *ix;
		const struct rdc_dp_v3 *v[3];
		int64_t area2;

		t = sort ? dp->v3_edge[k] & SORT_TRI : k;
		ix = dp->v3_idx + 3 * t;
		v[0] = &dp->v3[ix[0]];
		v[1] = &dp->v3[ix[1]];
		v[2] = &dp->v3[ix[2]];
		rdc_port_compute(dp->hw, RDC_T_TRI3);
		n = tri_project(dp, v, x, y, z, rgb, &area2);
		if (!n || (cull && area2 >= 0))
			continue;
		if (wire) {
			for (i = 0; i < 3; i++) {
				uint32_t a = ix[i], b = ix[(i + 1) % 3];

				dp->v3_edge[nedge++] = RDC_MIN(a, b) << 16 |
						       RDC_MAX(a, b);
			}
			continue;
		}
		if (!area2)
			continue; /* no pixel centre inside */
		if (gouraud) {
			for (i = 0; i < n; i++)
				col[i] = g3_pixel(dp, rgb[i]);
		} else {
			uint32_t c = lit ? g3_pixel(dp, face_rgb(dp, v[0], v[1],
								 v[2], two)) :
					   dp->st.fg;

			for (i = 0; i < n; i++)
				col[i] = c;
		}
		/* a fan over the clipped polygon */
		for (i = 1; i + 1 < n; i++) {
			int32_t tx[3] = { x[0], x[i], x[i + 1] };
			int32_t ty[3] = { y[0], y[i], y[i + 1] };
			uint32_t tz[3] = { z[0], z[i], z[i + 1] };
			uint32_t tc[3] = { col[0], col[i], col[i + 1] };

			if (!scan)
				dp_tri_draw(dp, tx, ty, tc, tz, gouraud);
			else if (!scan_add(dp, &ns, tx, ty, tc, tz))
				return RDC_ERR_RANGE;
		}
	}
	if (scan)
		scan_draw(dp, gouraud, ns);
	if (!wire)
		return RDC_ERR_NONE;
	edge_sort(dp->v3_edge, nedge);
	for (i = 0; i < nedge; i++) {
		uint32_t e = dp->v3_edge[i];

		if (i && e == dp->v3_edge[i - 1])
			continue;
		g3_draw_segment(dp, &dp->v3[e >> 16], &dp->v3[e & 0xffffu],
				false);
	}
	return RDC_ERR_NONE;
}

/*
 * RDC_MESH_BOUNDS: true when the model box's eight corners, through the
 * CTM and the view, all lie outside one clip plane.  The clip planes are
 * linear in homogeneous coordinates and the corners' images span the
 * image of the box, so the whole mesh is then outside.
 */
static uint32_t bounds_cull(struct rdc_dp *dp, const uint8_t *p, bool *out)
{
	int32_t b[RDC_MESH_BOUNDS_WORDS], pos[3];
	struct rdc_dp_v3 v;
	uint8_t all = 0xff;
	uint32_t i, k;

	for (i = 0; i < RDC_MESH_BOUNDS_WORDS; i++)
		b[i] = (int32_t)rdc_ld32(p + i * sizeof(uint32_t));
	rdc_port_compute(dp->hw, 8 * RDC_T_VERTEX3);
	for (i = 0; i < 8; i++) {
		for (k = 0; k < 3; k++)
			pos[k] = b[k + (i >> k & 1 ? 3 : 0)];
		if (!g3_vertex(dp, pos, NULL, NULL, false, false, &v))
			return RDC_ERR_RANGE;
		all &= v.out;
	}
	*out = all != 0;
	return RDC_ERR_NONE;
}

uint32_t g3_cmd_mesh(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t vbase = a[0], vcount = a[1] & ~RDC_MESH_BOUNDS, ibase = a[2];
	uint32_t tcount = a[3];
	uint32_t words = fl & RDC_MESH_NORMALS ? 6 : 3, i, j;
	bool lit = fl & RDC_MESH_LIT;
	bool vlit = lit && (fl & RDC_MESH_GOURAUD);
	struct g3_nmat nm;
	const uint8_t *p;

	uint32_t vskip = a[1] & RDC_MESH_BOUNDS ?
				 RDC_MESH_BOUNDS_WORDS * sizeof(uint32_t) :
				 0;

	if (fl & ~RDC_MESH_CMD_FLAGS ||
	    (fl & RDC_MESH_SCANLINE && fl & RDC_MESH_WIRE))
		return RDC_ERR_ARG;
	/* lighting per vertex needs the vertices' normals */
	if (vlit && !(fl & RDC_MESH_NORMALS))
		return RDC_ERR_ARG;
	if (vcount < 1 || vcount > RDC_MESH_MAX_VERTS ||
	    tcount > RDC_MESH_MAX_TRIS || vbase % sizeof(uint32_t) ||
	    (uint64_t)vbase + vskip +
			    (uint64_t)vcount * words * sizeof(uint32_t) >
		    hw->vram_size ||
	    (uint64_t)ibase + (uint64_t)tcount * 3 * IDX_BYTES > hw->vram_size)
		return RDC_ERR_RANGE;
	if (!(fl & (RDC_MESH_WIRE | RDC_MESH_SCANLINE)) && !dp_zbuf_ready(dp))
		return RDC_ERR_SURFACE;
	if (vskip) {
		uint32_t err;
		bool out;

		p = rdc_port_span(hw, vbase, vskip, RDC_BUS_READ);
		if (!p)
			return RDC_ERR_RANGE;
		err = bounds_cull(dp, p, &out);
		if (err != RDC_ERR_NONE)
			return err;
		if (out) {
			dp->meshes_culled++;
			hw->perf.culled++; /* PERF_CULLED */
			return RDC_ERR_NONE;
		}
		vbase += vskip;
	}
	/* the indices, all checked before anything is drawn */
	if (tcount) {
		p = rdc_port_span(hw, ibase, tcount * 3 * IDX_BYTES,
				  RDC_BUS_READ);
		if (!p)
			return RDC_ERR_RANGE;
		for (i = 0; i < 3 * tcount; i++) {
			dp->v3_idx[i] = rdc_ld16(p + i * IDX_BYTES);
			if (dp->v3_idx[i] >= vcount)
				return RDC_ERR_RANGE;
		}
	}
	p = rdc_port_span(hw, vbase,
			  vcount * words * (uint32_t)sizeof(uint32_t),
			  RDC_BUS_READ);
	if (!p)
		return RDC_ERR_RANGE;
	g3_normal_matrix(dp, &nm);
	for (i = 0; i < vcount; i++) {
		const uint8_t *q = p + i * words * sizeof(uint32_t);
		int32_t v[6];

		for (j = 0; j < words; j++)
			v[j] = (int32_t)rdc_ld32(q + j * sizeof(uint32_t));
		if (!g3_vertex(dp, v, words == 6 ? v + 3 : NULL, &nm, vlit,
			       fl & RDC_MESH_TWO_SIDED, &dp->v3[i]))
			return RDC_ERR_RANGE;
	}
	rdc_port_compute(hw, vcount * (RDC_T_VERTEX3 +
				       (vlit ? g3_light_cycles(dp) : 0)));
	return g3_draw_tris(dp, fl, tcount);
}
