/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Field helpers in the style of the kernel's <linux/bits.h> and
 * <linux/bitfield.h>.  In the kernel the real ones are used; elsewhere this
 * is their small twin, so rdc_regs.h reads the same in every build.
 */
#ifndef RDC_BITS_H
#define RDC_BITS_H

#include "rdc_base.h"

#ifndef __KERNEL__
#ifndef BIT
#define BIT(n) (1u << (n))
#endif
#ifndef GENMASK
/* Bits h..l set, h >= l, for 32-bit registers. */
#define GENMASK(h, l) ((~0u >> (31 - (h))) & (~0u << (l)))
#endif
#ifndef FIELD_PREP
#define FIELD_PREP(mask, val) \
	(((uint32_t)(val) << __builtin_ctz(mask)) & (mask))
#endif
#ifndef FIELD_GET
#define FIELD_GET(mask, reg) (((uint32_t)(reg) & (mask)) >> __builtin_ctz(mask))
#endif
#endif

#endif /* RDC_BITS_H */
