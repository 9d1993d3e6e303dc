// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * What every part of rdc-bench shares (parts.h): the workloads' names,
 * the peers built in, and dying on an error.
 */
#include <stdio.h>
#include <stdlib.h>

#include "parts.h"

const char *const kind_name[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = "fill",
	[BENCH_BLIT] = "blit",
	[BENCH_BLIT_XOR] = "blit_xor",
	[BENCH_LINE] = "line",
	[BENCH_AALINE] = "aaline",
	[BENCH_CIRCLE] = "circle",
	[BENCH_FILL_CIRCLE] = "fill_circle",
	[BENCH_POLYGON] = "polygon",
	[BENCH_TEXT] = "text",
	[BENCH_SCANOUT] = "scanout",
	[BENCH_REALTIME] = "realtime",
	[BENCH_REALTIME_1080] = "realtime1080",
	[BENCH_TEAPOT3D] = "teapot3d",
	[BENCH_GROWTH] = "growth",
};

const struct bench_peer *const peers[NPEERS + 1] = {
#ifdef BENCH_HAVE_PIXMAN
	&bench_peer_pixman,
#endif
#ifdef BENCH_HAVE_CAIRO
	&bench_peer_cairo,
#endif
#ifdef BENCH_HAVE_SDL2_GFX
	&bench_peer_sdl2_gfx,
#endif
	NULL,
};

void bench_die(const char *what, int err)
{
	fprintf(stderr, "rdc-bench: %s: %s\n", what, rdc_strerror(err));
	exit(1);
}

void *bench_xcalloc(size_t n, size_t size)
{
	void *p = calloc(n, size);

	if (!p)
		bench_die("memory", RDC_E_NOMEM);
	return p;
}
