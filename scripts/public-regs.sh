#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The register map as librdc installs it: hw-sim/rdc_regs.h (the one copy)
# with the field helpers under RDC_ names, so that a program including
# <rdc.h> gets no unprefixed macro (BIT, GENMASK, FIELD_PREP, FIELD_GET).
# The helpers are defined here the way hw-sim/rdc_bits.h defines them
# outside the kernel; the portable core's base header is not installed.
#
#   scripts/public-regs.sh hw-sim/rdc_regs.h > include/rdc/rdc_regs.h
set -eu
src=${1:?usage: public-regs.sh hw-sim/rdc_regs.h}
grep -q '^#include "rdc_bits.h"$' "$src" || {
	echo "public-regs.sh: $src does not include rdc_bits.h as expected" >&2
	exit 1
}
sed -e '/^#include "rdc_bits.h"$/{
r /dev/stdin
d
}' \
    -e 's/\(^\|[^A-Za-z0-9_]\)BIT(/\1RDC_BIT(/g' \
    -e 's/\(^\|[^A-Za-z0-9_]\)GENMASK(/\1RDC_GENMASK(/g' \
    -e 's/\(^\|[^A-Za-z0-9_]\)FIELD_PREP(/\1RDC_FIELD_PREP(/g' \
    -e 's/\(^\|[^A-Za-z0-9_]\)FIELD_GET(/\1RDC_FIELD_GET(/g' \
    "$src" <<'HELPERS'
/*
 * Installed form (scripts/public-regs.sh): the field helpers of
 * hw-sim/rdc_bits.h under RDC_ names.
 */
#include <stdint.h>

#define RDC_BIT(n) (1u << (n))
/* Bits h..l set, h >= l, for 32-bit registers. */
#define RDC_GENMASK(h, l) ((~0u >> (31 - (h))) & (~0u << (l)))
#define RDC_FIELD_PREP(mask, val) \
	(((uint32_t)(val) << __builtin_ctz(mask)) & (mask))
#define RDC_FIELD_GET(mask, reg) \
	(((uint32_t)(reg) & (mask)) >> __builtin_ctz(mask))
HELPERS
