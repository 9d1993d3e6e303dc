// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * SDL2_gfx as a peer: the classic midpoint and Bresenham primitives on
 * SDL2's software renderer drawing into an ARGB8888 SDL_Surface (no
 * window, no video driver).  line, aaline, circle, fill_circle and polygon
 * (filledPolygon: pairs of crossings, i.e. even-odd).  No CRC to match:
 * its rounding differs from rdc's.
 */
#include <stdlib.h>

#include <SDL.h>
#include <SDL2_gfxPrimitives.h>

#include "bench.h"

#define SDL_ALPHA 0xff

static int sdl_has(enum bench_kind kind)
{
	return kind == BENCH_LINE || kind == BENCH_AALINE ||
	       kind == BENCH_CIRCLE || kind == BENCH_FILL_CIRCLE ||
	       kind == BENCH_POLYGON;
}

#define R8(c) ((Uint8)((c) >> 16))
#define G8(c) ((Uint8)((c) >> 8))
#define B8(c) ((Uint8)(c))

static void sdl_draw(SDL_Renderer *rn, const struct bench_input *in,
		     uint32_t ops)
{
	const uint32_t *a = in->arg;
	Sint16 vx[BENCH_POLY_MAX], vy[BENCH_POLY_MAX];
	uint32_t i, k;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		switch (in->kind) {
		case BENCH_LINE:
			lineRGBA(rn, (Sint16)a[0], (Sint16)a[1], (Sint16)a[2],
				 (Sint16)a[3], R8(a[4]), G8(a[4]), B8(a[4]),
				 SDL_ALPHA);
			break;
		case BENCH_AALINE:
			aalineRGBA(rn, (Sint16)a[0], (Sint16)a[1], (Sint16)a[2],
				   (Sint16)a[3], R8(a[4]), G8(a[4]), B8(a[4]),
				   SDL_ALPHA);
			break;
		case BENCH_CIRCLE:
			circleRGBA(rn, (Sint16)a[0], (Sint16)a[1], (Sint16)a[2],
				   R8(a[3]), G8(a[3]), B8(a[3]), SDL_ALPHA);
			break;
		case BENCH_FILL_CIRCLE:
			filledCircleRGBA(rn, (Sint16)a[0], (Sint16)a[1],
					 (Sint16)a[2], R8(a[3]), G8(a[3]),
					 B8(a[3]), SDL_ALPHA);
			break;
		case BENCH_POLYGON: {
			const int *xy = in->xy + 2 * a[1];

			for (k = 0; k < a[0] && k < BENCH_POLY_MAX; k++) {
				vx[k] = (Sint16)xy[2 * k];
				vy[k] = (Sint16)xy[2 * k + 1];
			}
			filledPolygonRGBA(rn, vx, vy, (int)k, R8(a[2]),
					  G8(a[2]), B8(a[2]), SDL_ALPHA);
			break;
		}
		default:
			return;
		}
	}
}

static double sdl_run(const struct bench_input *in, uint32_t ops, uint32_t *crc)
{
	SDL_Surface *surf;
	SDL_Renderer *rn;
	double t0, t;

	if (!sdl_has(in->kind))
		return -1;
	surf = SDL_CreateRGBSurfaceWithFormat(0, BENCH_W, BENCH_H, 32,
					      SDL_PIXELFORMAT_ARGB8888);
	if (!surf)
		return -1;
	SDL_FillRect(surf, NULL, 0);
	rn = SDL_CreateSoftwareRenderer(surf);
	if (!rn) {
		SDL_FreeSurface(surf);
		return -1;
	}
	t0 = bench_tic();
	sdl_draw(rn, in, ops);
	SDL_RenderPresent(rn);
	t = bench_toc(t0);
	*crc = bench_surface_crc(surf->pixels, (size_t)surf->pitch);
	SDL_DestroyRenderer(rn);
	SDL_FreeSurface(surf);
	return t;
}

const struct bench_peer bench_peer_sdl2_gfx = {
	.name = "SDL2_gfx",
	.has = sdl_has,
	.run = sdl_run,
};
