// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The 3D statements of .rdl (script_3d.c), for script.c's table.
 */
#ifndef RDC_SCRIPT_3D_H
#define RDC_SCRIPT_3D_H

#include "script.h"

int rdl_st_matrix(struct rdl *r, uint32_t op);
int rdl_st_vec3(struct rdl *r, uint32_t op);
int rdl_st_rotate(struct rdl *r, uint32_t op);
int rdl_st_view(struct rdl *r, uint32_t op);
int rdl_st_viewport3(struct rdl *r, uint32_t op);
int rdl_st_light(struct rdl *r, uint32_t op);
int rdl_st_ambient(struct rdl *r, uint32_t op);
int rdl_st_material(struct rdl *r, uint32_t op);
int rdl_st_mesh(struct rdl *r, uint32_t op);
int rdl_st_patch(struct rdl *r, uint32_t op);
int rdl_st_bezier3(struct rdl *r, uint32_t op);
int rdl_st_bspline3(struct rdl *r, uint32_t op);
/* host statements: vertex and index data into VRAM */
int rdl_st_vertices(struct rdl *r, uint32_t op);
int rdl_st_indices(struct rdl *r, uint32_t op);
int rdl_st_spin(struct rdl *r, uint32_t op);

#endif /* RDC_SCRIPT_3D_H */
