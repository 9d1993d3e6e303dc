// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcdrm: a simulated RDC-1 raster display controller as a DRM/KMS device
 * (driver name "rdc"), as vkms simulates its display.  The chip (hw-sim/)
 * and its display processor's firmware (firmware-model/) are compiled in
 * unchanged and run on the kernel chip host that rdcfb.ko uses too
 * (rdc_kchip.c).  This file holds the module parameters, the platform
 * devices and driver, and the DRM driver; rdcdrm_kms.c the display
 * pipeline, rdcdrm_uapi.c the private ioctls.
 *
 * Lifetime: the drm_device owns the chip.  Unbinding unplugs the device
 * (ioctls answer ENODEV), shuts the pipeline down and stops the chip's
 * clock; its memory goes with the drm_device when the last client lets
 * go.  The module cannot go while a client holds the device open.
 */
#include <drm/drm_atomic_helper.h>
#include <drm/drm_drv.h>
#include <drm/drm_file.h>
#include <drm/drm_gem_shmem_helper.h>
#include <drm/drm_ioctl.h>
#include <drm/drm_managed.h>
#include <linux/dma-mapping.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/slab.h>
#include <linux/string.h>

#include "rdcdrm.h"
#include "rdcdrm_compat.h"

static char *vram = "32M";
module_param(vram, charp, 0444);
MODULE_PARM_DESC(vram, "VRAM size per device, e.g. 32M (18M..256M)");

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

static bool fbdev = true;
module_param(fbdev, bool, 0444);
MODULE_PARM_DESC(fbdev, "Emulate an fbdev device on the DRM device (1)");

static struct rdc_kchip_params rdcdrm_params;
static struct platform_device *rdcdrm_pdev[RDCDRM_MAX_DEVICES];

static const struct drm_ioctl_desc rdcdrm_ioctls[] = {
	DRM_IOCTL_DEF_DRV(RDC_REG_READ, rdcdrm_ioctl_reg_read,
			  DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_REG_WRITE, rdcdrm_ioctl_reg_write,
			  DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_SUBMIT, rdcdrm_ioctl_submit, DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_WAIT, rdcdrm_ioctl_wait, DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_STEP, rdcdrm_ioctl_step, DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_COUNTERS, rdcdrm_ioctl_counters,
			  DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_FRAME, rdcdrm_ioctl_frame, DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_VRAM, rdcdrm_ioctl_vram, DRM_RENDER_ALLOW),
	DRM_IOCTL_DEF_DRV(RDC_STATE, rdcdrm_ioctl_state, DRM_RENDER_ALLOW),
};

DEFINE_DRM_GEM_FOPS(rdcdrm_fops);

static const struct drm_driver rdcdrm_driver = {
	.driver_features = DRIVER_MODESET | DRIVER_GEM | DRIVER_ATOMIC,
	.fops = &rdcdrm_fops,
	DRM_GEM_SHMEM_DRIVER_OPS,
	.ioctls = rdcdrm_ioctls,
	.num_ioctls = ARRAY_SIZE(rdcdrm_ioctls),
	.name = DRM_RDC_DRIVER_NAME,
	.desc = "Simulated RDC-1 raster display controller",
	.date = "20261205",
	.major = 1,
	.minor = 0,
};

/*
 * sysfs of the platform device: the wall time the host spent holding the
 * chip (simulating, uploading, answering ioctls) and the time since the
 * chip was made; their ratio over an interval is the chip's CPU share.
 */
#define RDCDRM_HOST_ATTR(name) \
	static ssize_t name##_show(struct device *dev, \
				   struct device_attribute *attr, char *buf) \
	{ \
		struct rdcdrm_device *rd = dev_get_drvdata(dev); \
		struct rdc_kchip_counters c; \
\
		if (!rd) \
			return -ENODEV; \
		rdc_kchip_counters(&rd->chip, &c); \
		return sysfs_emit(buf, "%llu\n", (unsigned long long)c.name); \
	} \
	static DEVICE_ATTR_RO(name)

RDCDRM_HOST_ATTR(host_busy_ns);
RDCDRM_HOST_ATTR(host_up_ns);
RDCDRM_HOST_ATTR(throttled);

static ssize_t scanout_show(struct device *dev, struct device_attribute *attr,
			    char *buf)
{
	struct rdcdrm_device *rd = dev_get_drvdata(dev);

	return rd ? rdc_kchip_scanout_show(&rd->chip, buf) : -ENODEV;
}
static DEVICE_ATTR_RO(scanout);

static struct attribute *rdcdrm_attrs[] = {
	&dev_attr_host_busy_ns.attr,
	&dev_attr_host_up_ns.attr,
	&dev_attr_throttled.attr,
	&dev_attr_scanout.attr,
	NULL,
};
ATTRIBUTE_GROUPS(rdcdrm);

/* The last reference to the drm_device is gone: so is every user. */
static void rdcdrm_release(struct drm_device *drm, void *data)
{
	struct rdcdrm_device *rd = data;

	rdc_kchip_free(&rd->chip);
}

static int rdcdrm_probe(struct platform_device *pdev)
{
	struct rdcdrm_device *rd;
	struct drm_device *drm;
	int ret;

	ret = dma_coerce_mask_and_coherent(&pdev->dev, DMA_BIT_MASK(64));
	if (ret)
		return ret;
	rd = devm_drm_dev_alloc(&pdev->dev, &rdcdrm_driver,
				struct rdcdrm_device, drm);
	if (IS_ERR(rd))
		return PTR_ERR(rd);
	drm = &rd->drm;
	rd->pdev = pdev;
	spin_lock_init(&rd->vbl_lock);
	rd->stage = drmm_kmalloc_array(drm, RDCDRM_STAGE_WORDS, sizeof(u32),
				       GFP_KERNEL);
	if (!rd->stage)
		return -ENOMEM;
	rd->chip.hooks = &rdcdrm_hooks;
	ret = rdc_kchip_init(&rd->chip, &pdev->dev, &rdcdrm_params);
	if (ret)
		return ret;
	ret = drmm_add_action_or_reset(drm, rdcdrm_release, rd);
	if (ret)
		return ret;
	ret = rdcdrm_kms_init(rd);
	if (ret)
		return ret;
	platform_set_drvdata(pdev, rd);
	rdc_kchip_start(&rd->chip);
	ret = drm_dev_register(drm, 0);
	if (ret)
		goto err_stop;
	/* a device without its pins as GPIO lines is still one */
	ret = rdc_kgpio_register(&rd->chip, &pdev->dev);
	if (ret)
		dev_warn(&pdev->dev, "no GPIO lines for the pins: %d\n", ret);
	if (fbdev)
		rdcdrm_fbdev_setup(drm, 32);
	drm_info(drm, "%s: %u KiB VRAM, %s clock, scanout %s\n",
		 dev_name(&pdev->dev), rdcdrm_params.vram_bytes >> 10,
		 rdcdrm_params.stepped ? "stepped" : "paced",
		 rdcdrm_params.on_demand ? "on demand" : "always");
	return 0;

err_stop:
	rdc_kchip_stop(&rd->chip);
	return ret;
}

void rdcdrm_remove(struct platform_device *pdev)
{
	struct rdcdrm_device *rd = platform_get_drvdata(pdev);

	drm_dev_unplug(&rd->drm);
	drm_atomic_helper_shutdown(&rd->drm);
	rdc_kchip_stop(&rd->chip);
	rdc_kgpio_unregister(&rd->chip);
}

static void rdcdrm_shutdown(struct platform_device *pdev)
{
	struct rdcdrm_device *rd = platform_get_drvdata(pdev);

	drm_atomic_helper_shutdown(&rd->drm);
}

static struct platform_driver rdcdrm_platform_driver = {
	.probe = rdcdrm_probe,
	.remove = rdcdrm_platform_remove,
	.shutdown = rdcdrm_shutdown,
	.driver = {
		.name = RDCDRM_NAME,
		.dev_groups = rdcdrm_groups,
	},
};

static void rdcdrm_unregister_devices(void)
{
	int i;

	for (i = RDCDRM_MAX_DEVICES - 1; i >= 0; i--) {
		if (rdcdrm_pdev[i])
			platform_device_unregister(rdcdrm_pdev[i]);
		rdcdrm_pdev[i] = NULL;
	}
}

static int __init rdcdrm_init(void)
{
	unsigned int i;
	int ret;

	ret = rdc_kchip_params_parse("rdcdrm", vram, RDCDRM_VRAM_MIN,
				     RDCDRM_VRAM_MAX, clock, scanout,
				     cpu_budget, devices, RDCDRM_MAX_DEVICES,
				     &rdcdrm_params);
	if (ret)
		return ret;
	ret = platform_driver_register(&rdcdrm_platform_driver);
	if (ret)
		return ret;
	for (i = 0; i < devices; i++) {
		rdcdrm_pdev[i] = platform_device_register_simple(RDCDRM_NAME, i,
								 NULL, 0);
		if (IS_ERR(rdcdrm_pdev[i])) {
			ret = PTR_ERR(rdcdrm_pdev[i]);
			rdcdrm_pdev[i] = NULL;
			rdcdrm_unregister_devices();
			platform_driver_unregister(&rdcdrm_platform_driver);
			return ret;
		}
	}
	return 0;
}

static void __exit rdcdrm_exit(void)
{
	rdcdrm_unregister_devices();
	platform_driver_unregister(&rdcdrm_platform_driver);
	rdc_kgpio_module_exit();
}

module_init(rdcdrm_init);
module_exit(rdcdrm_exit);

MODULE_DESCRIPTION("Simulated RDC-1 raster display controller, DRM/KMS");
MODULE_LICENSE("GPL");
