// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * FLOOD_FILL against a breadth-first search written here over a copy of
 * the image taken before the fill: random closed outlines and noise, both
 * modes, 4- and 8-connected, clipped; full-screen mazes (which overflow
 * the span stack and take the rescan path); patterns; bad arguments;
 * cycle count of a minimal fill.
 */
#include "tdp_poly.h"

struct bfs {
	const struct rdc_surface *s;
	const uint8_t *img; /* the VRAM copy, at s->base */
	struct rdc_rect c;
	bool boundary, eight;
	uint32_t key, fill;
	uint8_t *mark;
	int32_t *queue;
};

static uint32_t bfs_px(const struct bfs *b, int32_t x, int32_t y)
{
	struct rdc_surface s0 = *b->s;

	s0.base = 0;
	return tdp_get(b->img, &s0, x, y);
}

static bool bfs_in(const struct bfs *b, int32_t x, int32_t y)
{
	uint32_t p;

	if (x < b->c.x0 || x >= b->c.x1 || y < b->c.y0 || y >= b->c.y1)
		return false;
	p = bfs_px(b, x, y);
	return b->boundary ? p != b->key && p != b->fill : p == b->key;
}

/* Mark the seed's region; returns its size. */
static uint32_t bfs_run(struct bfs *b, int32_t sx, int32_t sy)
{
	int32_t w = (int32_t)b->s->width;
	uint32_t head = 0, tail = 0;

	if (!b->boundary)
		b->key = bfs_px(b, sx, sy);
	if (!b->boundary && b->key == b->fill)
		return 0;
	if (!bfs_in(b, sx, sy))
		return 0;
	b->mark[sy * w + sx] = 1;
	b->queue[tail++] = sy * w + sx;
	while (head < tail) {
		int32_t p = b->queue[head++], x = p % w, y = p / w, dx, dy;

		for (dy = -1; dy <= 1; dy++)
			for (dx = -1; dx <= 1; dx++) {
				int32_t nx = x + dx, ny = y + dy;

				if ((!dx && !dy) || (!b->eight && dx && dy))
					continue;
				if (!bfs_in(b, nx, ny) || b->mark[ny * w + nx])
					continue;
				b->mark[ny * w + nx] = 1;
				b->queue[tail++] = ny * w + nx;
			}
	}
	return tail;
}

/*
 * Flood from (sx, sy) with solid fill `fill` and compare every pixel with
 * the image the BFS predicts.  Returns the region size.
 */
static uint32_t flood_check(struct tdp *t, const struct rdc_surface *s,
			    const struct rdc_rect *c, int32_t sx, int32_t sy,
			    uint32_t flags, uint32_t key, uint32_t fill)
{
	size_t bytes = (size_t)s->stride * s->height, npx;
	struct bfs b = { .s = s,
			 .c = *c,
			 .boundary = flags & RDC_FLOOD_BOUNDARY,
			 .eight = flags & RDC_FLOOD_8,
			 .key = key,
			 .fill = fill };
	uint8_t *img = malloc(bytes);
	uint32_t a[2] = { RDC_XY(sx, sy), key }, size;
	int32_t x, y;

	npx = (size_t)s->width * s->height;
	b.mark = calloc(npx, 1);
	b.queue = malloc(npx * sizeof(*b.queue));
	assert_non_null(img);
	assert_non_null(b.mark);
	assert_non_null(b.queue);
	memcpy(img, t->vram + s->base, bytes);
	b.img = img;
	b.c.x0 = RDC_MAX(b.c.x0, 0);
	b.c.y0 = RDC_MAX(b.c.y0, 0);
	b.c.x1 = RDC_MIN(b.c.x1, (int32_t)s->width);
	b.c.y1 = RDC_MIN(b.c.y1, (int32_t)s->height);
	size = bfs_run(&b, sx, sy);

	TDP_CMD(t, RDC_OP_SET_FG, fill);
	tdp_cmd(t, RDC_OP_FLOOD_FILL, flags, b.boundary ? 2 : 1, a);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	for (y = 0; y < (int32_t)s->height; y++)
		for (x = 0; x < (int32_t)s->width; x++) {
			uint32_t want = b.mark[y * (int32_t)s->width + x] ?
						fill :
						bfs_px(&b, x, y);

			if (tdp_get(t->vram, s, x, y) != want)
				fail_msg(
					"flags %u seed (%d,%d): (%d,%d) is %x, "
					"want %x",
					flags, sx, sy, x, y,
					tdp_get(t->vram, s, x, y), want);
		}
	free(b.queue);
	free(b.mark);
	free(img);
	return size;
}

/* Closed outlines (polygon outlines, circles, rectangles) over noise. */
static void test_random_outlines(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 0xc0ffee, iter;

	for (iter = 0; iter < 160; iter++) {
		uint32_t fmt =
			iter % 2 ?
				RDC_FMT_I8 :
				(uint32_t)tdp_range(&rng, 0, RDC_FMT_COUNT - 1);
		int32_t w = tdp_range(&rng, 20, 120),
			h = tdp_range(&rng, 20, 90);
		struct rdc_surface s =
			tpp_surface(fmt, (uint32_t)w, (uint32_t)h);
		uint32_t m = tdp_mask(fmt), wall = 1 & m, fill = 2 & m;
		uint32_t flags = tdp_rand(&rng) % 4, k, n, a[12];
		struct rdc_rect c = { RDC_COORD_MIN, RDC_COORD_MIN,
				      RDC_COORD_MAX + 1, RDC_COORD_MAX + 1 };
		int32_t x, y;

		if (m == 1) /* 1 bpp: wall 1, fill 0 (interior fills 1s) */
			fill = 0;
		tpp_dst(t, &s);
		/* sparse noise of every colour */
		for (y = 0; y < h; y++)
			for (x = 0; x < w; x++)
				if (tdp_rand(&rng) % 23 == 0)
					tdp_put(t->vram, &s, x, y,
						tdp_rand(&rng));
		TDP_CMD(t, RDC_OP_SET_FG, wall);
		for (k = 0; k < 3; k++) {
			switch (tdp_rand(&rng) % 3) {
			case 0:
				n = (uint32_t)tdp_range(&rng, 3, 12);
				for (uint32_t i = 0; i < n; i++)
					a[i] = RDC_XY(
						tdp_range(&rng, -5, w + 5),
						tdp_range(&rng, -5, h + 5));
				tdp_cmd(t, RDC_OP_POLYGON, 0, n, a);
				break;
			case 1:
				TDP_CMD(t, RDC_OP_CIRCLE,
					RDC_XY(tdp_range(&rng, 0, w),
					       tdp_range(&rng, 0, h)),
					(uint32_t)tdp_range(&rng, 2, 40));
				break;
			default:
				TDP_CMD(t, RDC_OP_RECT,
					RDC_XY(tdp_range(&rng, -3, w),
					       tdp_range(&rng, -3, h)),
					RDC_WH(tdp_range(&rng, 2, w),
					       tdp_range(&rng, 2, h)));
				break;
			}
		}
		tdp_drain(t);
		if (tdp_rand(&rng) % 3 == 0) {
			c.x0 = tdp_range(&rng, -3, w / 2);
			c.y0 = tdp_range(&rng, -3, h / 2);
			c.x1 = tdp_range(&rng, c.x0 + 1, w + 3);
			c.y1 = tdp_range(&rng, c.y0 + 1, h + 3);
			TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(c.x0, c.y0),
				RDC_XY(c.x1, c.y1));
		}
		flood_check(t, &s, &c, tdp_range(&rng, 0, w - 1),
			    tdp_range(&rng, 0, h - 1), flags, wall, fill);
	}
}

/* A perfect maze of 1-pixel corridors over the whole surface, with some
 * extra openings so that corridors meet diagonally and loop. */
static void make_maze(struct tdp *t, const struct rdc_surface *s, uint32_t seed)
{
	int32_t cw = (int32_t)(s->width - 1) / 2,
		ch = (int32_t)(s->height - 1) / 2;
	int32_t *stack = malloc((size_t)cw * ch * sizeof(*stack));
	uint8_t *seen = calloc((size_t)cw * ch, 1);
	uint32_t rng = seed, sp = 0, k;
	int32_t x, y;

	assert_non_null(stack);
	assert_non_null(seen);
	for (y = 0; y < (int32_t)s->height; y++)
		for (x = 0; x < (int32_t)s->width; x++)
			tdp_put(t->vram, s, x, y, 1);
	stack[sp++] = 0;
	seen[0] = 1;
	tdp_put(t->vram, s, 1, 1, 0);
	while (sp) {
		int32_t c = stack[sp - 1], cx = c % cw, cy = c / cw;
		int32_t nb[4], nn = 0, d;
		static const int32_t dx[4] = { 1, -1, 0, 0 },
				     dy[4] = { 0, 0, 1, -1 };

		for (d = 0; d < 4; d++) {
			int32_t nx = cx + dx[d], ny = cy + dy[d];

			if (nx >= 0 && nx < cw && ny >= 0 && ny < ch &&
			    !seen[ny * cw + nx])
				nb[nn++] = d;
		}
		if (!nn) {
			sp--;
			continue;
		}
		d = nb[tdp_rand(&rng) % (uint32_t)nn];
		tdp_put(t->vram, s, 1 + 2 * cx + dx[d], 1 + 2 * cy + dy[d], 0);
		cx += dx[d];
		cy += dy[d];
		tdp_put(t->vram, s, 1 + 2 * cx, 1 + 2 * cy, 0);
		seen[cy * cw + cx] = 1;
		stack[sp++] = cy * cw + cx;
	}
	for (k = 0; k < s->width * s->height / 64; k++)
		tdp_put(t->vram, s, tdp_range(&rng, 1, (int32_t)s->width - 2),
			tdp_range(&rng, 1, (int32_t)s->height - 2), 0);
	/* and a closed-off pocket the fill must not reach */
	for (x = 0; x < 9; x++)
		for (y = 0; y < 9; y++)
			tdp_put(t->vram, s, (int32_t)s->width - 12 + x,
				(int32_t)s->height - 12 + y,
				x == 0 || y == 0 || x == 8 || y == 8);
	free(seen);
	free(stack);
}

static void test_maze(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, 1024, 768);
	struct rdc_rect c = { 0, 0, 1024, 768 };
	uint32_t flags;

	for (flags = 0; flags <= RDC_FLOOD_8; flags++) {
		uint32_t size;

		tpp_dst(t, &s);
		make_maze(t, &s, 17 + flags);
		size = flood_check(t, &s, &c, 1, 1, flags, 0, 2);
		/* most of the screen is corridor */
		assert_true(size > 1024u * 768u / 3);
		/* boundary mode over the same maze */
		tpp_dst(t, &s);
		make_maze(t, &s, 99 + flags);
		flood_check(t, &s, &c, 1, 1, flags | RDC_FLOOD_BOUNDARY, 1, 2);
	}
}

/* A patterned flood: region from the BFS, values from the pattern. */
static void test_pattern_flood(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, 64, 48);
	const uint32_t pat[2] = { 0x3c7effc3, 0x1f2f4f8f };
	struct bfs b = { .s = &s, .c = { 0, 0, 64, 48 }, .fill = 0xff };
	size_t bytes = (size_t)s.stride * s.height;
	uint8_t *img = malloc(bytes);
	int32_t x, y;

	b.mark = calloc(64 * 48, 1);
	b.queue = malloc(64 * 48 * sizeof(*b.queue));
	assert_non_null(img);
	tpp_dst(t, &s);
	TDP_CMD(t, RDC_OP_SET_FG, 7);
	TDP_CMD(t, RDC_OP_CIRCLE, RDC_XY(30, 24), 20);
	TDP_CMD(t, RDC_OP_LINE, RDC_XY(10, 24), RDC_XY(50, 24));
	tdp_drain(t);
	memcpy(img, t->vram + s.base, bytes);
	b.img = img;
	bfs_run(&b, 30, 10);
	TDP_CMD(t, RDC_OP_SET_FG, 5);
	TDP_CMD(t, RDC_OP_SET_BG, 6);
	tdp_cmd(t, RDC_OP_SET_PATTERN, RDC_PAT_MONO, 2, pat);
	TDP_CMD(t, RDC_OP_FLOOD_FILL, RDC_XY(30, 10));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	for (y = 0; y < 48; y++)
		for (x = 0; x < 64; x++) {
			uint32_t row = (pat[(y & 7) / 4] >> (8 * (y & 3))) &
				       0xff;
			uint32_t want =
				b.mark[y * 64 + x] ?
					((row >> (7 - (x & 7))) & 1 ? 5 : 6) :
					bfs_px(&b, x, y);

			assert_int_equal(tdp_get(t->vram, &s, x, y), want);
		}
	free(b.queue);
	free(b.mark);
	free(img);
}

static void test_bad_args(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, 64, 48);
	const uint32_t seed[2] = { RDC_XY(5, 5), 1 };
	const uint32_t far[2] = { RDC_XY(-16385, 5), 1 };
	const struct {
		uint32_t flags, n;
		const uint32_t *a;
		uint32_t err;
	} bad[] = {
		{ 4, 1, seed, RDC_ERR_ARG },
		{ 0, 2, seed, RDC_ERR_LENGTH },
		{ 0, 0, seed, RDC_ERR_LENGTH },
		{ RDC_FLOOD_BOUNDARY, 1, seed, RDC_ERR_LENGTH },
		{ RDC_FLOOD_8, 1, far, RDC_ERR_RANGE },
	};
	uint32_t i, h0;

	tpp_dst(t, &s);
	h0 = tpp_hash(t, &s);
	for (i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
		tdp_clear_err(t);
		tdp_cmd(t, RDC_OP_FLOOD_FILL, bad[i].flags, bad[i].n, bad[i].a);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), bad[i].err);
	}
	/* boundary mode with a ROP that reads DST */
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	tdp_cmd(t, RDC_OP_FLOOD_FILL, RDC_FLOOD_BOUNDARY, 2, seed);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	assert_int_equal(tpp_hash(t, &s), h0);
	/* ... but interior mode with XOR is fine: the region is XORed */
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_SET_FG, 0x11);
	tdp_cmd(t, RDC_OP_FLOOD_FILL, 0, 1, seed);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(tdp_get(t->vram, &s, 63, 47), 0x11);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
	/* seed outside the clip, or fill colour == seed colour: nothing */
	tpp_clear(t, &s);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(10, 10), RDC_XY(20, 20));
	tdp_cmd(t, RDC_OP_FLOOD_FILL, 0, 1, seed);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(64, 48));
	TDP_CMD(t, RDC_OP_SET_FG, 0);
	tdp_cmd(t, RDC_OP_FLOOD_FILL, RDC_FLOOD_8, 1, seed);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(tpp_hash(t, &s), h0);
}

/*
 * A one-pixel region (4-connected, clip 3x3 around it) costs: fetch and
 * decode; reading the seed (a span from the seed rightwards to the clip
 * edge), the row again from its left neighbour (extending the run left),
 * writing the pixel, then reading the row above and the row below from
 * the seed column rightwards (the stack pops the upper row first).
 */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, 64, 48);
	uint32_t open;
	uint64_t want;
	int32_t x, y;

	tpp_dst(t, &s);
	for (y = 9; y <= 11; y++)
		for (x = 19; x <= 21; x++)
			if (x != 20 || y != 10)
				tdp_put(t->vram, &s, x, y, 3);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(19, 9), RDC_XY(22, 12));
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 2 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	want += tpp_row_cost(&open, &s, 20, 10, 2, TDP_BUS_READ);
	want += tpp_row_cost(&open, &s, 19, 10, 3, TDP_BUS_READ);
	want += tpp_row_cost(&open, &s, 20, 10, 1, TDP_BUS_WRITE);
	want += tpp_row_cost(&open, &s, 20, 9, 2, TDP_BUS_READ);
	want += tpp_row_cost(&open, &s, 20, 11, 2, TDP_BUS_READ);
	TDP_CMD(t, RDC_OP_FLOOD_FILL, RDC_XY(20, 10));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(tdp_get(t->vram, &s, 20, 10), 0xffffffffu);
	assert_int_equal(tdp_get(t->vram, &s, 21, 10), 3);
	assert_int_equal(tpp_last_cycles(t), want);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_random_outlines), TDP_TEST(test_maze),
		TDP_TEST(test_pattern_flood),	TDP_TEST(test_bad_args),
		TDP_TEST(test_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
