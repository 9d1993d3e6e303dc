// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The workloads' pixel counts (bench/README.md, "pixels") from a geometry
 * of their own, independent of the display processor's: the midpoint
 * circle's distinct points and rows, and a polygon's pixel centres by the
 * even-odd rule.  A figure's Mpix/s is these pixels over its time.
 */
#include "parts.h"

/*
 * The classic incremental midpoint circle, octant x <= y from (0, r).
 * Outline: the distinct points of the eight reflections inside the
 * surface (reflections coincide only on the axes and the diagonal).
 * Filled: each row's span out to the farthest point on it, clipped.
 */
uint64_t circle_pixels(int cx, int cy, int r, bool filled)
{
	int half[BENCH_W];
	int x = 0, y = r, d = 1 - r, k;
	uint64_t n = 0;

	for (k = 0; k <= r; k++)
		half[k] = -1;
	while (x <= y) {
		int pt[8][2] = {
			{ x, y }, { -x, y }, { x, -y }, { -x, -y },
			{ y, x }, { -y, x }, { y, -x }, { -y, -x },
		};
		int i, j;

		if (half[y] < x)
			half[y] = x;
		if (half[x] < y)
			half[x] = y;
		for (i = 0; !filled && i < 8; i++) {
			int px = cx + pt[i][0], py = cy + pt[i][1];

			for (j = 0; j < i; j++)
				if (pt[j][0] == pt[i][0] &&
				    pt[j][1] == pt[i][1])
					break;
			if (j == i && px >= 0 && px < BENCH_W && py >= 0 &&
			    py < BENCH_H)
				n++;
		}
		if (d < 0) {
			d += 2 * x + 3;
		} else {
			d += 2 * (x - y) + 5;
			y--;
		}
		x++;
	}
	for (k = -r; filled && k <= r; k++) {
		int h = half[k < 0 ? -k : k], py = cy + k;
		int x0 = cx - h < 0 ? 0 : cx - h;
		int x1 = cx + h >= BENCH_W ? BENCH_W - 1 : cx + h;

		if (py >= 0 && py < BENCH_H && x1 >= x0)
			n += (uint64_t)(x1 - x0 + 1);
	}
	return n;
}

/* ceil(p / q) for q > 0 */
static long ceil_div(long p, long q)
{
	return p >= 0 ? (p + q - 1) / q : -(-p / q);
}

/*
 * Even-odd pixel-centre count: a row's centre line y + 1/2 crosses the
 * edges with min(y0, y1) <= y < max(y0, y1) (never at a vertex: centres
 * are half-integers); pixel x is inside when its centre x + 1/2 lies in
 * [left, right) of a pair of crossings, so a crossing at c starts or ends
 * the run at pixel ceil(c - 1/2), computed exactly in integers:
 * c = a0 + (2y + 1 - 2 a1) (b0 - a0) / (2 (b1 - a1)).
 */
uint64_t polygon_pixels(const int *xy, uint32_t n)
{
	int ymin = xy[1], ymax = xy[1], y;
	long cross[BENCH_POLY_MAX];
	uint64_t cnt = 0;
	uint32_t i;

	for (i = 1; i < n; i++) {
		ymin = xy[2 * i + 1] < ymin ? xy[2 * i + 1] : ymin;
		ymax = xy[2 * i + 1] > ymax ? xy[2 * i + 1] : ymax;
	}
	for (y = ymin; y < ymax; y++) {
		uint32_t m = 0, k;

		for (i = 0; i < n; i++) {
			const int *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
			long dy = b[1] - a[1], num;

			if (y < (dy > 0 ? a[1] : b[1]) ||
			    y >= (dy > 0 ? b[1] : a[1]))
				continue;
			/* c - 1/2 = num / (2 dy) */
			num = 2L * a[0] * dy +
			      (2L * y + 1 - 2L * a[1]) * (b[0] - a[0]) - dy;
			cross[m++] = dy > 0 ? ceil_div(num, 2 * dy) :
					      ceil_div(-num, -2 * dy);
		}
		for (k = 1; k < m; k++) { /* a handful: insertion sort */
			long v = cross[k];
			uint32_t j = k;

			for (; j > 0 && cross[j - 1] > v; j--)
				cross[j] = cross[j - 1];
			cross[j] = v;
		}
		for (k = 0; k + 1 < m; k += 2)
			cnt += (uint64_t)(cross[k + 1] - cross[k]);
	}
	return cnt;
}
