// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The command statements of .rdl (script_cmd.c), for script.c's table.
 */
#ifndef RDC_SCRIPT_CMD_H
#define RDC_SCRIPT_CMD_H

#include "script.h"

int rdl_st_nop(struct rdl *r, uint32_t op);
int rdl_st_words(struct rdl *r, uint32_t op);
int rdl_st_cmd_reg(struct rdl *r, uint32_t op);
int rdl_st_load_clut(struct rdl *r, uint32_t op);
int rdl_st_colour(struct rdl *r, uint32_t op);
int rdl_st_rop(struct rdl *r, uint32_t op);
int rdl_st_clip(struct rdl *r, uint32_t op);
int rdl_st_surface(struct rdl *r, uint32_t op);
int rdl_st_points(struct rdl *r, uint32_t op);
int rdl_st_shape(struct rdl *r, uint32_t op);
int rdl_st_blit(struct rdl *r, uint32_t op);
int rdl_st_host_blit(struct rdl *r, uint32_t op);
int rdl_st_readback(struct rdl *r, uint32_t op);
int rdl_st_mono(struct rdl *r, uint32_t op);
int rdl_st_text(struct rdl *r, uint32_t op);
int rdl_st_raw(struct rdl *r, uint32_t op);
int rdl_st_cmd(struct rdl *r, uint32_t op);

#endif /* RDC_SCRIPT_CMD_H */
