// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * A self-benchmark in debugfs (rdcfb/fbN/bench; reading it runs it): the
 * console's two workloads, a line of text (imageblit of an 80-column
 * glyph row) and a scroll (copyarea of the screen less one text row),
 * through this driver's fb_ops (display-processor commands, run to
 * completion) and through the kernel's own sys_imageblit / sys_copyarea on
 * a system-memory fb_info of the same mode, timed with ktime_get in one
 * run.  Besides the wall-time ratio it gives the DP's simulated cycles:
 * what the chip would take at its core clock.  Beside it, irqs_off: the
 * driver's interrupts-off sections by length.
 */
#include <linux/debugfs.h>
#include <linux/ktime.h>
#include <linux/math64.h>
#include <linux/seq_file.h>
#include <linux/slab.h>
#include <linux/vmalloc.h>

#include "rdcfb.h"

#define RDCFB_BENCH_LINES   200u /* text rows drawn */
#define RDCFB_BENCH_SCROLLS 20u	 /* screens scrolled */
#define RDCFB_GLYPH_W	    8u
#define RDCFB_GLYPH_H	    16u
#define RDCFB_TEXT_COLS	    80u
#define RDCFB_PERCENT	    100u

static struct dentry *rdcfb_debugfs_root;

/* The system-memory twin's: sys_* helpers call fbops->fb_sync. */
static const struct fb_ops rdcfb_bench_sys_ops = {
	.owner = THIS_MODULE,
};

struct rdcfb_bench_run {
	u64 dp_ns, sys_ns, busy;
};

static u64 rdcfb_busy(struct rdc_kchip *chip)
{
	struct rdc_kchip_counters c;

	rdc_kchip_counters(chip, &c);
	return c.busy;
}

/* The glyph row fbcon would hand over for one line of text. */
static void rdcfb_text_row(u8 *data, u32 cols)
{
	static const char text[] =
		"The quick brown fox jumps over the lazy dog 0123456789 ";
	u32 c, y;

	for (y = 0; y < RDCFB_GLYPH_H; y++)
		for (c = 0; c < cols; c++)
			data[y * cols + c] =
				rdc_font8x16[(u8)text[c % (sizeof(text) - 1)] *
						     RDCFB_GLYPH_H +
					     y];
}

static void rdcfb_bench_blit(struct fb_info *info, struct fb_info *sys,
			     const struct fb_image *img, u32 rows,
			     struct rdcfb_bench_run *r)
{
	struct rdcfb_par *par = info->par;
	struct fb_image im = *img;
	ktime_t t0;
	u64 b0;
	u32 i;

	rdcfb_sync(info);
	b0 = rdcfb_busy(par->chip);
	t0 = ktime_get();
	for (i = 0; i < RDCFB_BENCH_LINES; i++) {
		im.dy = (i % rows) * RDCFB_GLYPH_H;
		rdcfb_blit(info, &im);
	}
	rdcfb_sync(info);
	r->dp_ns = ktime_to_ns(ktime_sub(ktime_get(), t0));
	r->busy = rdcfb_busy(par->chip) - b0;
	t0 = ktime_get();
	for (i = 0; i < RDCFB_BENCH_LINES; i++) {
		im.dy = (i % rows) * RDCFB_GLYPH_H;
		sys_imageblit(sys, &im);
	}
	r->sys_ns = ktime_to_ns(ktime_sub(ktime_get(), t0));
}

static void rdcfb_bench_scroll(struct fb_info *info, struct fb_info *sys,
			       struct rdcfb_bench_run *r)
{
	struct rdcfb_par *par = info->par;
	struct fb_copyarea a = {
		.sx = 0,
		.sy = RDCFB_GLYPH_H,
		.dx = 0,
		.dy = 0,
		.width = info->var.xres,
		.height = info->var.yres - RDCFB_GLYPH_H,
	};
	ktime_t t0;
	u64 b0;
	u32 i;

	rdcfb_sync(info);
	b0 = rdcfb_busy(par->chip);
	t0 = ktime_get();
	for (i = 0; i < RDCFB_BENCH_SCROLLS; i++)
		rdcfb_copy(info, &a);
	rdcfb_sync(info);
	r->dp_ns = ktime_to_ns(ktime_sub(ktime_get(), t0));
	r->busy = rdcfb_busy(par->chip) - b0;
	t0 = ktime_get();
	for (i = 0; i < RDCFB_BENCH_SCROLLS; i++)
		sys_copyarea(sys, &a);
	r->sys_ns = ktime_to_ns(ktime_sub(ktime_get(), t0));
}

static void rdcfb_bench_print(struct seq_file *m, struct rdc_kchip *chip,
			      const char *what, u32 ops,
			      const struct rdcfb_bench_run *r)
{
	u64 chip_ns = mul_u64_u32_div(r->busy, NSEC_PER_SEC,
				      rdc_hw_core_hz(chip->hw));
	u64 sys = max_t(u64, r->sys_ns, 1);
	u64 wall_x100 = div64_u64(r->dp_ns * RDCFB_PERCENT, sys);
	u64 chip_x100 = div64_u64(chip_ns * RDCFB_PERCENT, sys);

	seq_printf(m, "%s: %u ops\n", what, ops);
	seq_printf(
		m,
		"  through the DP: %llu ns/op wall, %llu DP cycles/op (%llu ns/op at the core clock)\n",
		div_u64(r->dp_ns, ops), div_u64(r->busy, ops),
		div_u64(chip_ns, ops));
	seq_printf(m, "  sys helper: %llu ns/op\n", div_u64(r->sys_ns, ops));
	seq_printf(
		m,
		"  ratio dp/sys: wall %llu.%02llu, at the core clock %llu.%02llu\n",
		wall_x100 / RDCFB_PERCENT, wall_x100 % RDCFB_PERCENT,
		chip_x100 / RDCFB_PERCENT, chip_x100 % RDCFB_PERCENT);
}

static int rdcfb_bench_show(struct seq_file *m, void *unused)
{
	struct fb_info *info = m->private;
	struct rdcfb_par *par = info->par;
	u32 cols = min(info->var.xres / RDCFB_GLYPH_W, RDCFB_TEXT_COLS);
	u32 rows = info->var.yres / RDCFB_GLYPH_H;
	struct rdcfb_bench_run r;
	struct fb_image img = { 0 };
	struct fb_info *sys;
	u8 *glyphs;
	int ret = -ENOMEM;

	if (!cols || rows < 2)
		return -EINVAL;
	sys = framebuffer_alloc(0, NULL);
	glyphs = kmalloc_array(cols, RDCFB_GLYPH_H, GFP_KERNEL);
	if (!sys || !glyphs)
		goto out;
	sys->fbops = &rdcfb_bench_sys_ops;
	sys->var = info->var;
	sys->fix = info->fix;
	sys->pseudo_palette = par->pseudo_palette;
	sys->flags = FBINFO_VIRTFB;
	sys->screen_size = (size_t)info->fix.line_length * info->var.yres;
	sys->screen_buffer = vzalloc(sys->screen_size);
	if (!sys->screen_buffer)
		goto out;
	rdcfb_text_row(glyphs, cols);
	img.width = cols * RDCFB_GLYPH_W;
	img.height = RDCFB_GLYPH_H;
	img.depth = 1;
	img.fg_color = 7;
	img.bg_color = 0;
	img.data = (const char *)glyphs;

	seq_printf(m, "mode %ux%u-%u, fb%d\n", info->var.xres, info->var.yres,
		   info->var.bits_per_pixel, info->node);
	rdcfb_bench_blit(info, sys, &img, rows - 1, &r);
	rdcfb_bench_print(m, par->chip, "imageblit (80-column text row)",
			  RDCFB_BENCH_LINES, &r);
	rdcfb_bench_scroll(info, sys, &r);
	rdcfb_bench_print(m, par->chip, "copyarea (scroll one text row)",
			  RDCFB_BENCH_SCROLLS, &r);
	ret = 0;
out:
	if (sys)
		vfree(sys->screen_buffer);
	kfree(glyphs);
	framebuffer_release(sys);
	return ret;
}
DEFINE_SHOW_ATTRIBUTE(rdcfb_bench);

/* The interrupts-off sections by length: "<1us N", "2-4us N", ... */
static int rdcfb_irqoff_show(struct seq_file *m, void *unused)
{
	struct fb_info *info = m->private;
	struct rdcfb_par *par = info->par;
	struct rdc_kchip_irqoff *st = &par->chip->irqoff;
	unsigned int k;
	s64 n;

	for (k = 0; k < RDC_KCHIP_IRQOFF_BUCKETS; k++) {
		n = atomic64_read(&st->hist[k]);
		if (!n)
			continue;
		if (!k)
			seq_puts(m, "<1us");
		else if (k == RDC_KCHIP_IRQOFF_BUCKETS - 1)
			seq_printf(m, ">=%uus", 1u << (k - 1));
		else
			seq_printf(m, "%u-%uus", 1u << (k - 1), 1u << k);
		seq_printf(m, " %lld\n", (long long)n);
	}
	return 0;
}
DEFINE_SHOW_ATTRIBUTE(rdcfb_irqoff);

void rdcfb_bench_init(struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	char name[16];

	snprintf(name, sizeof(name), "fb%d", info->node);
	par->debugfs = debugfs_create_dir(name, rdcfb_debugfs_root);
	debugfs_create_file("bench", 0400, par->debugfs, info,
			    &rdcfb_bench_fops);
	debugfs_create_file("irqs_off", 0400, par->debugfs, info,
			    &rdcfb_irqoff_fops);
}

void rdcfb_bench_exit(struct fb_info *info)
{
	struct rdcfb_par *par = info->par;

	debugfs_remove_recursive(par->debugfs);
	par->debugfs = NULL;
}

void rdcfb_bench_module_init(void)
{
	rdcfb_debugfs_root = debugfs_create_dir(RDCFB_NAME, NULL);
}

void rdcfb_bench_module_exit(void)
{
	debugfs_remove_recursive(rdcfb_debugfs_root);
}
