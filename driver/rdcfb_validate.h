/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * SUBMIT's check of a command buffer (rdcfb_validate.c).  Kept apart from
 * rdcfb.h so that the unit tests build it in user space too.
 */
#ifndef RDCFB_VALIDATE_H
#define RDCFB_VALIDATE_H

#include "rdc_regs.h"

/*
 * 0 if the `n` words at `w` are whole, well-formed commands for a chip of
 * `vram_size` bytes; else -EPROTO with *bad_word the index of the first
 * offending word (a header, when the count or opcode is what is wrong).
 */
int rdcfb_validate(const u32 *w, u32 n, u32 vram_size, u32 *bad_word);

#endif /* RDCFB_VALIDATE_H */
