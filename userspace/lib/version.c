// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The release of librdc, for programs to compare with the header's, and
 * the copy through which a structure reaches a caller built against
 * another release (rdc.h, "Structures that grow").
 */
#include <string.h>

#include "rdc_priv.h"

uint32_t rdc_version(void)
{
	return RDC_VERSION_NUMBER;
}

void rdc_struct_out(void *out, const void *full, size_t n)
{
	uint32_t size;

	memcpy(&size, out, sizeof(size));
	if (size <= sizeof(size) || n <= sizeof(size))
		return;
	memcpy((uint8_t *)out + sizeof(size),
	       (const uint8_t *)full + sizeof(size),
	       (size < n ? size : n) - sizeof(size));
	if (size > n)
		memset((uint8_t *)out + n, 0, size - n);
}
