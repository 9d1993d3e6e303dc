/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Shared by the 3D files: geom3d.c (matrices, the view, the vertex
 * pipeline, clipping), mesh.c (MESH and the triangle/edge drawing),
 * light.c (illumination) and patch.c (PATCH, BEZIER3, BSPLINE3).
 */
#ifndef RDC_GEOM3D_INT_H
#define RDC_GEOM3D_INT_H

#include "dp_int.h"

#define G3_ONE	      (1 << 16) /* 1.0 in 15.16 */
#define G3_UNIT_SHIFT 30	/* unit vectors are 2.30 */
#define G3_LIN_SHIFT  24	/* the view's linear part is 7.24 */
#define G3_PLANES     6		/* clip planes */
/* Sutherland-Hodgman: a triangle gains at most one vertex a plane */
#define G3_POLY_MAX (3 + G3_PLANES)

/* n / d rounded to nearest, halves towards +infinity; d > 0. */
int64_t g3_div_round(int64_t n, int64_t d);
/*
 * Scale the vector v to a unit vector in 2.30; false (out untouched) for
 * the zero vector.
 */
bool g3_normalize(const int64_t *v, int32_t *out);

/*
 * The cofactor matrix of the CTM's linear part, scaled to entries below
 * 2^30 and signed so that it maps a model normal to a world normal (the
 * inverse transpose up to a positive factor).
 */
struct g3_nmat {
	int64_t m[3][3];
};

void g3_normal_matrix(const struct rdc_dp *dp, struct g3_nmat *nm);

/*
 * A model-space vertex (15.16) through the CTM and the view into *v:
 * world and clip coordinates, the outcode, and for an inside vertex the
 * screen pixel and depth.  nrm (may be NULL) is the model normal, taken
 * through nm and normalised into v->n (0 when NULL or zero).  With lit,
 * v->rgb is its lit colour.  false: a coordinate left the documented
 * range (RDC_ERR_RANGE).
 */
bool g3_vertex(struct rdc_dp *dp, const int32_t *pos, const int32_t *nrm,
	       const struct g3_nmat *nm, bool lit, bool two_sided,
	       struct rdc_dp_v3 *v);

/* Clip-space polygon vertex: coordinates and a colour per channel. */
struct g3_pv {
	int64_t c[4];
	int32_t col[3];
};

/*
 * Clip the polygon p[0..n) against the canonical volume; returns the new
 * vertex count (0: nothing left), each new vertex charged RDC_T_CLIP3.
 * tmp is scratch of G3_POLY_MAX vertices; the result is in p.
 */
uint32_t g3_clip_poly(struct rdc_dp *dp, struct g3_pv *p, uint32_t n,
		      struct g3_pv *tmp);
/*
 * Clip the segment a-b; false when nothing is left, else a and b are the
 * visible part.
 */
bool g3_clip_line(struct g3_pv *a, struct g3_pv *b);
/* Screen pixel and depth of a clip-space point inside the volume. */
void g3_project(const struct rdc_dp *dp, const int64_t *c, int32_t *sx,
		int32_t *sy, uint32_t *z);

/* Lit colour 0x00RRGGBB at world position pw with unit normal n (light.c) */
uint32_t g3_light(const struct rdc_dp *dp, const int32_t *pw, const int32_t *n,
		  bool two_sided);
/* A 0x00RRGGBB colour as a DST pixel value (light.c). */
uint32_t g3_pixel(const struct rdc_dp *dp, uint32_t rgb);
/* Cycles of lighting one vertex or face with the lights that are on. */
uint32_t g3_light_cycles(const struct rdc_dp *dp);

/*
 * Draw triangles dp->v3_idx[0 .. 3 * ntri) of the vertex cache
 * dp->v3[0 .. nvert) with the RDC_MESH_* flags fl (mesh.c); RDC_ERR_RANGE
 * (nothing drawn) when RDC_MESH_SCANLINE gathers more than
 * RDC_MESH_SCAN_MAX_TRIS triangles.
 */
uint32_t g3_draw_tris(struct rdc_dp *dp, uint32_t fl, uint32_t ntri);
/* The segment between two cached vertices in FG (mesh.c). */
void g3_draw_segment(struct rdc_dp *dp, const struct rdc_dp_v3 *a,
		     const struct rdc_dp_v3 *b, bool skip_first);

uint32_t g3_cmd_mesh(struct rdc_dp *dp, uint32_t fl, const uint32_t *a);
uint32_t g3_cmd_patch(struct rdc_dp *dp, const uint32_t *a);
uint32_t g3_cmd_bezier3(struct rdc_dp *dp, uint32_t fl, const uint32_t *a);
uint32_t g3_cmd_bspline3(struct rdc_dp *dp, uint32_t fl, uint32_t len,
			 const uint32_t *a);

#endif /* RDC_GEOM3D_INT_H */
