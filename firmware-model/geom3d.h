/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The 3D geometry stage's state and scratch, kept in struct rdc_dp (dp.h
 * includes this header).  Number formats:
 *
 *   15.16   matrices, vertices, world coordinates, view parameters
 *           (65536 is 1.0); matrix entries are limited to |m| < 2^14,
 *           world coordinates to |w| < 2^15 (checked, RDC_ERR_RANGE)
 *   2.30    unit vectors: normals, light directions, the view basis
 *   7.24    the viewing transformation's linear part (|l| < 2^5)
 *   clip    homogeneous clip coordinates in 1/65536 units, |c| < 2^31
 */
#ifndef RDC_GEOM3D_H
#define RDC_GEOM3D_H

#include "../hw-sim/rdc_regs.h"

struct rdc_dp_light {
	uint32_t on;
	uint32_t rgb;	/* 0x00RRGGBB */
	int32_t dir[3]; /* unit, 2.30, towards the light, world */
};

struct rdc_dp_3d {
	/* current transformation matrix (rows 0..2 of the 4x4), 15.16 */
	int32_t ctm[3][4];
	int32_t stack[RDC_MATRIX_STACK_DEPTH][3][4];
	uint32_t sp;
	/*
	 * The view: world (15.16) to clip coordinates, clip = lin * world
	 * / 2^24 + tr; persp selects the projection.  eye: perspective, the
	 * centre of projection in world coordinates (15.16); parallel, the
	 * unit vector (2.30) from the scene towards the viewer.
	 */
	int32_t lin[4][3];
	int64_t tr[4];
	int32_t eye[3];
	bool persp;
	/* SET_VIEWPORT3's corner pixels */
	int32_t vx0, vy0, vx1, vy1;
	/* illumination */
	uint32_t ambient;
	struct rdc_dp_light light[RDC_LIGHTS];
	uint32_t mat_amb, mat_diff, mat_spec, mat_shine;
};

/* One vertex through the pipeline (the post-transform cache). */
struct rdc_dp_v3 {
	int32_t c[4];	/* clip X, Y, Z, W */
	int32_t w[3];	/* world position, 15.16 */
	int32_t n[3];	/* world normal, unit 2.30 (0: none) */
	int32_t sx, sy; /* screen pixel, valid when out == 0 */
	uint32_t z;	/* depth 0..65535, valid when out == 0 */
	uint32_t rgb;	/* lit colour 0x00RRGGBB */
	uint8_t out;	/* outcode: bit k set when outside clip plane k */
};

#endif /* RDC_GEOM3D_H */
