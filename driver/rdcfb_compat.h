/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * What differs between the kernels rdcfb builds on, in one place: Debian
 * 12's 6.1 up to Debian 13's 6.12 (docs/driver.md lists them).  The rest
 * of the driver is written against the kernel API they share; the
 * fb_info flags leave out FBINFO_DEFAULT, which was 0 and went in 6.6.
 */
#ifndef RDCFB_COMPAT_H
#define RDCFB_COMPAT_H

#include <linux/platform_device.h>
#include <linux/version.h>

/*
 * RDCFB_PLATFORM_REMOVE(name, fn) defines name, the platform driver's
 * .remove, calling void fn(struct platform_device *).  From 6.11 .remove
 * returns void; before, it returns an int that the driver core ignores
 * (6.3 to 6.10 also had .remove_new, which returns void).
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0)
#define RDCFB_PLATFORM_REMOVE(name, fn) \
	static void name(struct platform_device *pdev) \
	{ \
		fn(pdev); \
	}
#else
#define RDCFB_PLATFORM_REMOVE(name, fn) \
	static int name(struct platform_device *pdev) \
	{ \
		fn(pdev); \
		return 0; \
	}
#endif

#endif /* RDCFB_COMPAT_H */
