// SPDX-License-Identifier: GPL-2.0-only
/* The release of librdc, for programs to compare with the header's. */
#include "rdc.h"

uint32_t rdc_version(void)
{
	return RDC_VERSION_NUMBER;
}
