// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcfb: a simulated RDC-1 raster display controller as a Linux
 * framebuffer device, as vkms simulates its display.  The chip (hw-sim/)
 * and its display processor's firmware (firmware-model/) are compiled in
 * unchanged; this file holds the module parameters, the platform devices
 * and driver, and the counters in sysfs.
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/slab.h>
#include <linux/string.h>

#include "rdcfb.h"
#include "rdcfb_compat.h"

#define RDCFB_VRAM_MIN (1u << 20) /* holds 640x480 at 8 bpp, and more */
#define RDCFB_VRAM_MAX (256u << 20)

static char *vram = "16M";
module_param(vram, charp, 0444);
MODULE_PARM_DESC(vram, "VRAM size per device, e.g. 16M (1M..256M)");

static char *mode = "640x480-32";
module_param(mode, charp, 0444);
MODULE_PARM_DESC(
	mode,
	"Initial mode WxH[-bpp]: a preset size, 8/16/32 bpp (640x480-32)");

static unsigned int devices = 1;
module_param(devices, uint, 0444);
MODULE_PARM_DESC(devices, "Number of devices (1..8)");

static char *clock = "paced";
module_param(clock, charp, 0444);
MODULE_PARM_DESC(clock,
		 "paced (follows wall time) or stepped (moves only in waits)");

static char *scanout = "auto";
module_param(scanout, charp, 0444);
MODULE_PARM_DESC(scanout, "demand, always, or auto: demand when paced");

static unsigned int cpu_budget = 75;
module_param(cpu_budget, uint, 0444);
MODULE_PARM_DESC(cpu_budget,
		 "Per cent of a CPU all devices' paced clocks may take (75)");

static struct rdc_kchip_params rdcfb_params;
static struct platform_device *rdcfb_pdev[RDCFB_MAX_DEVICES];

/* ---- sysfs: the counters ------------------------------------------------- */

static struct rdc_kchip *rdc_kchip_of(struct device *dev)
{
	struct fb_info *info = dev_get_drvdata(dev);

	return ((struct rdcfb_par *)info->par)->chip;
}

#define RDCFB_COUNTER_ATTR(name, expr) \
	static ssize_t name##_show(struct device *dev, \
				   struct device_attribute *attr, char *buf) \
	{ \
		struct rdc_kchip_counters c; \
\
		rdc_kchip_counters(rdc_kchip_of(dev), &c); \
		return sysfs_emit(buf, "%llu\n", (unsigned long long)(expr)); \
	} \
	static DEVICE_ATTR_RO(name)

RDCFB_COUNTER_ATTR(busy_cycles, c.busy);
RDCFB_COUNTER_ATTR(stall_cycles, c.stall);
RDCFB_COUNTER_ATTR(pixels, c.pixels);
RDCFB_COUNTER_ATTR(cmds, c.cmds);
RDCFB_COUNTER_ATTR(frames, c.frames);
RDCFB_COUNTER_ATTR(now, c.now);
RDCFB_COUNTER_ATTR(host_busy_ns, c.host_busy_ns);
RDCFB_COUNTER_ATTR(host_up_ns, c.host_up_ns);
RDCFB_COUNTER_ATTR(pace_throttled, c.throttled);

#define RDCFB_PIN_ATTR(name, field) \
	static ssize_t name##_show(struct device *dev, \
				   struct device_attribute *attr, char *buf) \
	{ \
		struct rdc_kchip *chip = rdc_kchip_of(dev); \
		struct rdc_kchip_pin_stats s; \
\
		rdc_kgpio_stats(READ_ONCE(chip->gpio), &s); \
		return sysfs_emit(buf, "%llu\n", (unsigned long long)s.field); \
	} \
	static DEVICE_ATTR_RO(name)

RDCFB_PIN_ATTR(pin_edges, edges);
RDCFB_PIN_ATTR(pin_lost, lost);
RDCFB_PIN_ATTR(pin_late_max_ns, late_max_ns);
RDCFB_PIN_ATTR(pin_late_avg_ns, late_avg_ns);

static ssize_t frame_crc_show(struct device *dev, struct device_attribute *attr,
			      char *buf)
{
	struct rdc_kchip *chip = rdc_kchip_of(dev);
	ssize_t ret;

	mutex_lock(&chip->snap_lock);
	ret = rdc_kchip_snapshot(chip);
	if (!ret)
		ret = sysfs_emit(buf, "%08x %u %ux%u\n", chip->snap_crc,
				 (u32)chip->snap_seq, chip->snap_w,
				 chip->snap_h);
	mutex_unlock(&chip->snap_lock);
	return ret;
}
static DEVICE_ATTR_RO(frame_crc);

/* The longest interrupts-off section so far; writing anything starts afresh. */
static ssize_t irqs_off_max_ns_show(struct device *dev,
				    struct device_attribute *attr, char *buf)
{
	struct rdc_kchip *chip = rdc_kchip_of(dev);

	return sysfs_emit(buf, "%lld\n",
			  (long long)atomic64_read(&chip->irqoff.max_ns));
}

static ssize_t irqs_off_max_ns_store(struct device *dev,
				     struct device_attribute *attr,
				     const char *buf, size_t count)
{
	struct rdc_kchip *chip = rdc_kchip_of(dev);

	rdc_kchip_irqoff_reset(&chip->irqoff);
	return count;
}
static DEVICE_ATTR_RW(irqs_off_max_ns);

static ssize_t irqs_off_max_at_show(struct device *dev,
				    struct device_attribute *attr, char *buf)
{
	struct rdc_kchip *chip = rdc_kchip_of(dev);

	return sysfs_emit(buf, "%pS\n", (void *)READ_ONCE(chip->irqoff.max_at));
}
static DEVICE_ATTR_RO(irqs_off_max_at);

/* fb_ops' records dropped at a full queue, in atomic context. */
static ssize_t fb_dropped_show(struct device *dev,
			       struct device_attribute *attr, char *buf)
{
	return sysfs_emit(
		buf, "%llu\n",
		(unsigned long long)rdcfb_ops_dropped(rdc_kchip_of(dev)));
}
static DEVICE_ATTR_RO(fb_dropped);

static ssize_t scanout_show(struct device *dev, struct device_attribute *attr,
			    char *buf)
{
	return rdc_kchip_scanout_show(rdc_kchip_of(dev), buf);
}
static DEVICE_ATTR_RO(scanout);

static struct attribute *rdcfb_attrs[] = {
	&dev_attr_busy_cycles.attr,
	&dev_attr_stall_cycles.attr,
	&dev_attr_pixels.attr,
	&dev_attr_cmds.attr,
	&dev_attr_frames.attr,
	&dev_attr_now.attr,
	&dev_attr_host_busy_ns.attr,
	&dev_attr_host_up_ns.attr,
	&dev_attr_pace_throttled.attr,
	&dev_attr_frame_crc.attr,
	&dev_attr_pin_edges.attr,
	&dev_attr_pin_lost.attr,
	&dev_attr_pin_late_max_ns.attr,
	&dev_attr_pin_late_avg_ns.attr,
	&dev_attr_irqs_off_max_ns.attr,
	&dev_attr_irqs_off_max_at.attr,
	&dev_attr_fb_dropped.attr,
	&dev_attr_scanout.attr,
	NULL,
};
ATTRIBUTE_GROUPS(rdcfb);

/* ---- platform driver ----------------------------------------------------- */

static int rdcfb_probe(struct platform_device *pdev)
{
	struct rdcfb_dev *rd;
	struct rdc_kchip *chip;
	struct rdcfb_par *par;
	struct fb_info *info;
	int ret;

	rd = kzalloc(sizeof(*rd), GFP_KERNEL);
	if (!rd)
		return -ENOMEM;
	chip = &rd->chip;
	chip->hooks = &rdcfb_hooks;
	ret = rdcfb_opq_init(rd);
	if (ret)
		goto err_chip;
	ret = rdc_kchip_init(chip, &pdev->dev, &rdcfb_params);
	if (ret)
		goto err_opq;
	info = framebuffer_alloc(sizeof(*par), &pdev->dev);
	if (!info) {
		ret = -ENOMEM;
		goto err_free;
	}
	par = info->par;
	par->chip = chip;
	par->pdev = pdev;
	ret = rdcfb_fb_setup(info, mode);
	if (ret) {
		dev_err(&pdev->dev, "mode \"%s\" refused: %d\n", mode, ret);
		goto err_info;
	}
	platform_set_drvdata(pdev, info);
	rdc_kchip_start(chip);
	/* from here on info owns chip: fb_destroy frees both */
	ret = register_framebuffer(info);
	if (ret)
		goto err_stop;
	rdcfb_bench_init(info);
	/* a framebuffer without its pins as GPIO lines is still one */
	ret = rdc_kgpio_register(chip, &pdev->dev);
	if (ret)
		dev_warn(&pdev->dev, "no GPIO lines for the pins: %d\n", ret);
	fb_info(info, "%s: %ux%u, %u KiB VRAM, %s clock, scanout %s\n",
		info->fix.id, info->var.xres, info->var.yres,
		rdcfb_params.vram_bytes >> 10,
		rdcfb_params.stepped ? "stepped" : "paced",
		rdcfb_params.on_demand ? "on demand" : "always");
	return 0;

err_stop:
	rdc_kchip_stop(chip);
	fb_dealloc_cmap(&info->cmap);
err_info:
	framebuffer_release(info);
err_free:
	rdc_kchip_free(chip);
err_opq:
	rdcfb_opq_free(rd);
err_chip:
	kfree(rd);
	return ret;
}

/*
 * Clients may still hold /dev/fbN open or mapped: unregister_framebuffer
 * only drops the registration's reference, and fb_destroy frees the chip
 * and VRAM when the last client lets go (mapped VRAM pages hold their own
 * references).  Their ioctls meanwhile answer -ENODEV.  The module itself
 * cannot go while a client holds the device: fb_open pins it.
 */
void rdcfb_remove(struct platform_device *pdev)
{
	struct fb_info *info = platform_get_drvdata(pdev);
	struct rdcfb_par *par = info->par;

	rdcfb_bench_exit(info);
	rdc_kchip_stop(par->chip);
	rdc_kgpio_unregister(par->chip);
	unregister_framebuffer(info);
}

static struct platform_driver rdcfb_driver = {
	.probe = rdcfb_probe,
	.remove = rdcfb_platform_remove,
	.driver = {
		.name = RDCFB_NAME,
		.dev_groups = rdcfb_groups,
	},
};

static void rdcfb_unregister_devices(void)
{
	int i;

	for (i = RDCFB_MAX_DEVICES - 1; i >= 0; i--) {
		if (rdcfb_pdev[i])
			platform_device_unregister(rdcfb_pdev[i]);
		rdcfb_pdev[i] = NULL;
	}
}

static int __init rdcfb_init(void)
{
	unsigned int i;
	int ret;

	ret = rdc_kchip_params_parse("rdcfb", vram, RDCFB_VRAM_MIN,
				     RDCFB_VRAM_MAX, clock, scanout, cpu_budget,
				     devices, RDCFB_MAX_DEVICES, &rdcfb_params);
	if (ret)
		return ret;
	rdcfb_bench_module_init();
	ret = platform_driver_register(&rdcfb_driver);
	if (ret) {
		rdcfb_bench_module_exit();
		return ret;
	}
	for (i = 0; i < devices; i++) {
		rdcfb_pdev[i] =
			platform_device_register_simple(RDCFB_NAME, i, NULL, 0);
		if (IS_ERR(rdcfb_pdev[i])) {
			ret = PTR_ERR(rdcfb_pdev[i]);
			rdcfb_pdev[i] = NULL;
			rdcfb_unregister_devices();
			platform_driver_unregister(&rdcfb_driver);
			rdcfb_bench_module_exit();
			return ret;
		}
	}
	return 0;
}

static void __exit rdcfb_exit(void)
{
	rdcfb_unregister_devices();
	platform_driver_unregister(&rdcfb_driver);
	rdc_kgpio_module_exit();
	rdcfb_bench_module_exit();
}

module_init(rdcfb_init);
module_exit(rdcfb_exit);

MODULE_DESCRIPTION("Simulated RDC-1 raster display controller framebuffer");
MODULE_LICENSE("GPL");
