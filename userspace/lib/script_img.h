// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The image statements of .rdl (script_img.c), for script.c's table.
 */
#ifndef RDC_SCRIPT_IMG_H
#define RDC_SCRIPT_IMG_H

#include "script.h"

int rdl_st_decode(struct rdl *r, uint32_t op);
int rdl_st_histogram(struct rdl *r, uint32_t op);
int rdl_st_map_build(struct rdl *r, uint32_t op);
int rdl_st_map_apply(struct rdl *r, uint32_t op);
int rdl_st_threshold(struct rdl *r, uint32_t op);
int rdl_st_convolve(struct rdl *r, uint32_t op);
/* host statements */
int rdl_st_vram_load(struct rdl *r, uint32_t op);
int rdl_st_encode(struct rdl *r, uint32_t op);
int rdl_st_histogram_plot(struct rdl *r, uint32_t op);

#endif /* RDC_SCRIPT_IMG_H */
