// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Conformance: the same test functions run over sim:, unix: and tcp:
 * (rdcd --stepped) and must see identical frames, cycle counts, counters
 * and register values.  sim: is the reference: the socket backends are
 * correct exactly when nothing tells them apart.
 *
 * With RDC_CONFORM_URI set, the same suite runs against that device
 * instead of rdcd instances of its own (tests/vm/tests/usb-conform.sh
 * gives it usb:, an rdcd --stepped behind a USB gadget).  The API
 * scenario then expects a device as rdcd --stepped starts (time 0); for
 * each scene the device is first put in a fresh sim:'s state (conf_prepare:
 * VRAM zeroed, soft reset) and its times are counted from that reset, and
 * sim: gets the device's VRAM size, as tests/vm/tests/rdcfb-conformance.sh
 * does for fbdev:.
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "test_net_common.h"

#define CONF_SCENE_DIR	"tests/golden/scenes"
#define CONF_MAX_SCENES 64

/* Everything a run observes; runs on different backends must be equal. */
struct conf_out {
	uint64_t t_mode, t_draw, t_blit, t_vblank, t_step, t_end;
	uint32_t frame_crc, w, h;
	uint32_t readback_crc, readback_len;
	uint8_t vram[256];
	struct rdc_stats stats;
	uint32_t fence, status, frame_count, beam;
	int err_range, err_halt;
};

static uint32_t conf_crc(const void *p, size_t n)
{
	const uint8_t *b = p;
	uint32_t c = ~0u;

	for (size_t i = 0; i < n; i++) {
		c ^= b[i];
		for (int k = 0; k < 8; k++)
			c = (c >> 1) ^ (0xedb88320u & -(c & 1));
	}
	return ~c;
}

/* A bit of everything the backend table carries. */
static int conf_scenario(rdc_dev *dev, struct conf_out *o)
{
	static uint32_t pix[32 * 24], rb[64 * 64];
	rdc_batch *b = rdc_batch_new();
	uint8_t v[256];
	int ret;

	memset(o, 0, sizeof(*o));
	if (!b)
		return RDC_E_NOMEM;
	ret = rdc_mode_set(dev, RDC_PRESET_320x200_70, RDC_FMT_XRGB8888, 0);
	if (!ret)
		ret = rdc_finish(dev);
	if (!ret)
		ret = rdc_sim_time(dev, &o->t_mode);
	/* many small commands: the FIFO fills, submits wait for room */
	for (int i = 0; !ret && i < 300; i++) {
		ret = rdc_batch_fg(b, 0x10203u * (uint32_t)i);
		if (!ret)
			ret = rdc_batch_fill_rect(b, i % 300, i % 190, 9, 7);
		if (!ret && i % 7 == 0)
			ret = rdc_batch_line(b, 0, i % 200, 319, 199 - i % 200);
		if (!ret && i % 11 == 0)
			ret = rdc_batch_circle(b, 160, 100, (uint32_t)(i % 90));
	}
	if (!ret)
		ret = rdc_batch_text(b, 8, 8, "conformance", 11, 1);
	if (!ret)
		ret = rdc_batch_submit(dev, b);
	if (!ret)
		ret = rdc_finish(dev);
	if (!ret)
		ret = rdc_sim_time(dev, &o->t_draw);
	/* host aperture and host blits */
	for (size_t i = 0; i < sizeof(v); i++)
		v[i] = (uint8_t)(i * 7 + 3);
	if (!ret)
		ret = rdc_vram_write(dev, 300000, v, sizeof(v));
	if (!ret)
		ret = rdc_vram_read(dev, 300000 - 16, o->vram, sizeof(o->vram));
	for (size_t i = 0; i < RDC_ARRAY_SIZE(pix); i++)
		pix[i] = 0x00a5a5a5u ^ (uint32_t)(i * 2654435761u);
	if (!ret)
		ret = rdc_host_blit(dev, 40, 50, 32, 24, pix, 32 * 4);
	if (!ret)
		ret = rdc_finish(dev);
	if (!ret) {
		ret = rdc_readback(dev, 30, 40, 64, 40, rb, sizeof(rb));
		if (ret > 0) {
			o->readback_len = (uint32_t)ret;
			o->readback_crc = conf_crc(rb, (size_t)ret);
			ret = 0;
		}
	}
	if (!ret)
		ret = rdc_sim_time(dev, &o->t_blit);
	if (!ret)
		ret = rdc_vblank_wait(dev);
	if (!ret)
		ret = rdc_sim_time(dev, &o->t_vblank);
	if (!ret)
		ret = rdc_sim_step(dev, 12345);
	if (!ret)
		ret = rdc_sim_time(dev, &o->t_step);
	if (!ret)
		ret = rdc_frame_wait(dev);
	if (!ret)
		ret = rdc_frame_crc(dev, &o->frame_crc);
	if (!ret)
		ret = rdc_frame_grab(dev, NULL, 0, &o->w, &o->h) ==
				      RDC_E_RANGE ?
			      0 :
			      RDC_E_INVAL;
	if (!ret)
		ret = rdc_stats_get(dev, &o->stats);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_FENCE, &o->fence);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_STATUS, &o->status);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &o->frame_count);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_BEAM, &o->beam);
	/* errors travel too */
	if (!ret)
		o->err_range = rdc_vram_read(dev, 0xfffffff0u, v, 64);
	if (!ret) {
		uint32_t bad = RDC_CMD(0x7f, 0, 0);

		ret = rdc_reg_write(dev, RDC_REG_CONTROL,
				    RDC_CONTROL_SOFT_RESET);
		if (!ret)
			ret = rdc_submit(dev, &bad, 1);
		if (!ret)
			o->err_halt = rdc_finish(dev);
	}
	if (!ret)
		ret = rdc_sim_time(dev, &o->t_end);
	rdc_batch_free(b);
	return ret;
}

static void conf_expect_equal(const struct conf_out *a,
			      const struct conf_out *b, const char *what)
{
	if (memcmp(a, b, sizeof(*a))) {
		print_error("%s differs from sim: t %llu/%llu draw %llu/%llu "
			    "end %llu/%llu crc %08x/%08x\n",
			    what, (unsigned long long)a->t_mode,
			    (unsigned long long)b->t_mode,
			    (unsigned long long)a->t_draw,
			    (unsigned long long)b->t_draw,
			    (unsigned long long)a->t_end,
			    (unsigned long long)b->t_end, a->frame_crc,
			    b->frame_crc);
	}
	assert_memory_equal(a, b, sizeof(*a));
}

static const char *const conf_stepped[] = { "--stepped", "-q", NULL };

/* RDC_CONFORM_URI, or NULL: start rdcd for each run */
static const char *conf_uri;

/* Rows of VRAM zeroed per fill in conf_prepare (within RDC_COORD_MAX). */
#define CONF_CLEAR_STRIDE 16384u
#define CONF_CLEAR_ROWS	  4096u

/*
 * Put the device at `uri` in a fresh sim:'s state, as far as a client
 * can: VRAM zeroed by the DP (fills over the whole of it, then the bytes
 * past the last full row), then a soft reset; *t0 is the time after it,
 * *vram the VRAM size.
 */
static int conf_prepare(const char *uri, uint64_t *t0, uint32_t *vram)
{
	static const uint8_t zero[CONF_CLEAR_STRIDE];
	rdc_dev *dev = NULL;
	rdc_batch *b = rdc_batch_new();
	uint32_t rows = 0;
	int ret = b ? rdc_open(uri, &dev) : RDC_E_NOMEM;

	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_VRAM_SIZE, vram);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_CONTROL,
				    RDC_CONTROL_SOFT_RESET);
	if (!ret)
		rows = *vram / CONF_CLEAR_STRIDE;
	for (uint32_t y = 0; !ret && y < rows; y += CONF_CLEAR_ROWS) {
		uint32_t h = RDC_MIN(CONF_CLEAR_ROWS, rows - y);

		ret = rdc_batch_dst(b, y * CONF_CLEAR_STRIDE, CONF_CLEAR_STRIDE,
				    CONF_CLEAR_STRIDE / 4, h, RDC_FMT_XRGB8888);
		if (!ret)
			ret = rdc_batch_clip(b, 0, 0, CONF_CLEAR_STRIDE / 4,
					     (int)h);
		if (!ret)
			ret = rdc_batch_rop(b, RDC_ROP_COPY);
		if (!ret)
			ret = rdc_batch_fg(b, 0);
		if (!ret)
			ret = rdc_batch_fill_rect(b, 0, 0,
						  CONF_CLEAR_STRIDE / 4, h);
		if (!ret)
			ret = rdc_batch_submit(dev, b);
	}
	if (!ret)
		ret = rdc_finish(dev);
	if (!ret && *vram % CONF_CLEAR_STRIDE)
		ret = rdc_vram_write(dev, rows * CONF_CLEAR_STRIDE, zero,
				     *vram % CONF_CLEAR_STRIDE);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_CONTROL,
				    RDC_CONTROL_SOFT_RESET);
	if (!ret)
		ret = rdc_sim_time(dev, t0);
	rdc_close(dev);
	rdc_batch_free(b);
	return ret;
}

static void run_on(const char *uri, struct conf_out *o, struct netd *d)
{
	rdc_dev *dev = NULL;
	int ret = rdc_open(uri, &dev);

	if (!ret)
		ret = conf_scenario(dev, o);
	rdc_close(dev);
	if (ret && d) {
		print_error("%s: %s; daemon log:\n", uri, rdc_strerror(ret));
		netd_dump_log(d);
	}
	assert_int_equal(ret, 0);
}

static void test_conform_api(void **state)
{
	static struct conf_out ref, u, t;
	struct netd d;

	(void)state;
	run_on("sim:", &ref, NULL);
	/* the scenario really did something */
	assert_true(ref.t_draw > ref.t_mode);
	assert_true(ref.stats.cmds > 300);
	assert_int_equal(ref.w, 320);
	assert_int_equal(ref.readback_len, 64 * 40 * 4);
	assert_int_equal(ref.err_range, RDC_E_RANGE);
	assert_true(ref.err_halt == RDC_E_HALTED ||
		    ref.err_halt == RDC_E_DEVICE);
	/* the aperture bytes written are read back 16 bytes in */
	assert_int_equal(ref.vram[16], 3);
	assert_int_equal(ref.vram[17], 10);

	if (conf_uri) {
		run_on(conf_uri, &u, NULL);
		conf_expect_equal(&ref, &u, conf_uri);
		return;
	}

	assert_int_equal(netd_start(&d, conf_stepped), 0);
	run_on(d.unix_uri, &u, &d);
	assert_int_equal(netd_stop(&d), 0);
	conf_expect_equal(&ref, &u, "unix:");

	assert_int_equal(netd_start(&d, conf_stepped), 0);
	run_on(d.tcp_uri, &t, &d);
	assert_int_equal(netd_stop(&d), 0);
	conf_expect_equal(&ref, &t, "tcp:");
}

/* What rdcctl run and the golden tests measure, for one scene. */
struct conf_scene {
	int ret;
	uint64_t t_script, t_frame;
	uint32_t crc;
	uint64_t op_cycles[256];
	uint32_t readback_crc;
};

/* Times are counted from t0 (conf_prepare's reset; 0 on a fresh device). */
static void scene_run(const char *uri, const char *path, struct conf_scene *s,
		      uint64_t t0)
{
	static struct rdc_script_result res;
	rdc_dev *dev = NULL;

	memset(s, 0, sizeof(*s));
	memset(&res, 0, sizeof(res));
	s->ret = rdc_open(uri, &dev);
	if (s->ret)
		return;
	s->ret = rdc_script_run_file(dev, path, &res);
	if (!s->ret)
		s->ret = rdc_sim_time(dev, &s->t_script);
	if (!s->ret)
		s->ret = rdc_script_frame_wait(dev, &res);
	if (!s->ret)
		s->ret = rdc_frame_crc(dev, &s->crc);
	if (!s->ret)
		s->ret = rdc_sim_time(dev, &s->t_frame);
	s->t_script -= t0;
	s->t_frame -= t0;
	memcpy(s->op_cycles, res.op_cycles, sizeof(s->op_cycles));
	s->readback_crc = res.readback_crc;
	rdc_close(dev);
}

static int scene_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every golden scene, as scripts: the whole drawing vocabulary. */
static void test_conform_scenes(void **state)
{
	static struct conf_scene ref, got;
	static char names[CONF_MAX_SCENES][300];
	char *list[CONF_MAX_SCENES];
	const char *scenes = getenv("RDC_CONFORM_SCENES");
	DIR *dir;

	if (!scenes)
		scenes = CONF_SCENE_DIR;
	dir = opendir(scenes);
	struct dirent *e;
	size_t n = 0, failed = 0, compared = 0;

	(void)state;
	assert_non_null(dir);
	while ((e = readdir(dir)) && n < CONF_MAX_SCENES) {
		size_t len = strlen(e->d_name);

		if (len > 4 && !strcmp(e->d_name + len - 4, ".rdl")) {
			snprintf(names[n], sizeof(names[n]), "%s/%s", scenes,
				 e->d_name);
			list[n] = names[n];
			n++;
		}
	}
	closedir(dir);
	assert_true(n > 0);
	qsort(list, n, sizeof(*list), scene_cmp);
	for (size_t i = 0; i < n; i++) {
		struct netd d;

		if (conf_uri) {
			char sim[40];
			uint64_t t0 = 0;
			uint32_t vram = 0;

			assert_int_equal(conf_prepare(conf_uri, &t0, &vram), 0);
			snprintf(sim, sizeof(sim), "sim:vram=%u", vram);
			scene_run(sim, list[i], &ref, 0);
			if (ref.ret)
				continue;
			compared++;
			scene_run(conf_uri, list[i], &got, t0);
			if (memcmp(&ref, &got, sizeof(ref))) {
				print_error("%s over %s: ret %d crc %08x/%08x "
					    "t %llu/%llu\n",
					    list[i], conf_uri, got.ret, got.crc,
					    ref.crc,
					    (unsigned long long)got.t_frame,
					    (unsigned long long)ref.t_frame);
				failed++;
			} else {
				print_message("%s: crc %08x, %llu cycles\n",
					      list[i], got.crc,
					      (unsigned long long)got.t_frame);
			}
			continue;
		}
		scene_run("sim:", list[i], &ref, 0);
		if (ref.ret) /* fails on sim: too: test_golden's business */
			continue;
		compared++;
		for (int tcp = 0; tcp < 2; tcp++) {
			assert_int_equal(netd_start(&d, conf_stepped), 0);
			scene_run(tcp ? d.tcp_uri : d.unix_uri, list[i], &got,
				  0);
			assert_int_equal(netd_stop(&d), 0);
			if (memcmp(&ref, &got, sizeof(ref))) {
				print_error("%s over %s: ret %d crc %08x/%08x "
					    "t %llu/%llu\n",
					    list[i], tcp ? "tcp" : "unix",
					    got.ret, got.crc, ref.crc,
					    (unsigned long long)got.t_frame,
					    (unsigned long long)ref.t_frame);
				failed++;
			}
		}
	}
	assert_int_equal(failed, 0);
	assert_true(compared > n / 2);
}

/* An argument names the one test to run (the VM test runs them apart). */
int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_conform_api),
		cmocka_unit_test(test_conform_scenes),
	};

	if (argc > 1)
		cmocka_set_test_filter(argv[1]);
	conf_uri = getenv("RDC_CONFORM_URI");
	if (conf_uri && !*conf_uri)
		conf_uri = NULL;
	return cmocka_run_group_tests(tests, NULL, NULL);
}
