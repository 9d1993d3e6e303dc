// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The drawing statements of .rdl (script_draw.c), for script.c's table.
 */
#ifndef RDC_SCRIPT_DRAW_H
#define RDC_SCRIPT_DRAW_H

#include "script.h"

int rdl_st_pen(struct rdl *r, uint32_t op);
int rdl_st_dash(struct rdl *r, uint32_t op);
int rdl_st_arc(struct rdl *r, uint32_t op);
int rdl_st_curve(struct rdl *r, uint32_t op);
int rdl_st_transform(struct rdl *r, uint32_t op);
int rdl_st_viewport(struct rdl *r, uint32_t op);
int rdl_st_fill_polygon(struct rdl *r, uint32_t op);
int rdl_st_flood(struct rdl *r, uint32_t op);
int rdl_st_pattern(struct rdl *r, uint32_t op);
int rdl_st_triangle(struct rdl *r, uint32_t op);
int rdl_st_zbuf(struct rdl *r, uint32_t op);
int rdl_st_clear_z(struct rdl *r, uint32_t op);
int rdl_st_colorkey(struct rdl *r, uint32_t op);

#endif /* RDC_SCRIPT_DRAW_H */
