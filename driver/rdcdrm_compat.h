/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * What differs between the kernels rdcdrm builds on, in one place: Debian
 * 12's 6.1 up to Debian 13's 6.12 (docs/driver.md lists them).  The rest
 * of the driver is written against the API they share.
 */
#ifndef RDCDRM_COMPAT_H
#define RDCDRM_COMPAT_H

#include <drm/drm_gem.h>
#include <drm/drm_gem_shmem_helper.h>
#include <linux/dma-resv.h>
#include <linux/platform_device.h>
#include <linux/version.h>

#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0)
#include <drm/drm_fbdev_shmem.h>
#else
#include <drm/drm_fb_helper.h>
#endif

/* rdcdrm_drv.c: takes the device down */
void rdcdrm_remove(struct platform_device *pdev);

/* The platform driver's .remove: void from 6.11, an int before. */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0)
static inline void rdcdrm_platform_remove(struct platform_device *pdev)
{
	rdcdrm_remove(pdev);
}
#else
static inline int rdcdrm_platform_remove(struct platform_device *pdev)
{
	rdcdrm_remove(pdev);
	return 0;
}
#endif

/*
 * fbdev emulation on GEM shmem: drm_fbdev_generic_setup() until 6.10,
 * drm_fbdev_shmem_setup() from 6.11.
 */
static inline void rdcdrm_fbdev_setup(struct drm_device *drm, u32 bpp)
{
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0)
	drm_fbdev_shmem_setup(drm, bpp);
#else
	drm_fbdev_generic_setup(drm, bpp);
#endif
}

/*
 * A kernel mapping of a shmem GEM object: 6.12's drm_gem_shmem_vmap()
 * wants the reservation lock held, 6.1's takes its own (and is as happy
 * with the reservation lock held around it).
 */
static inline int rdcdrm_gem_vmap(struct drm_gem_object *obj,
				  struct iosys_map *map)
{
	int ret;

	dma_resv_lock(obj->resv, NULL);
	ret = drm_gem_shmem_vmap(to_drm_gem_shmem_obj(obj), map);
	dma_resv_unlock(obj->resv);
	return ret;
}

static inline void rdcdrm_gem_vunmap(struct drm_gem_object *obj,
				     struct iosys_map *map)
{
	dma_resv_lock(obj->resv, NULL);
	drm_gem_shmem_vunmap(to_drm_gem_shmem_obj(obj), map);
	dma_resv_unlock(obj->resv);
}

#endif /* RDCDRM_COMPAT_H */
