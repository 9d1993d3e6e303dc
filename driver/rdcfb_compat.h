/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
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

/* rdcfb_main.c: takes the device down */
void rdcfb_remove(struct platform_device *pdev);

/*
 * The platform driver's .remove: from 6.11 it returns void; before, an
 * int that the driver core ignores (6.3 to 6.10 also had .remove_new,
 * which returns void).
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0)
static inline void rdcfb_platform_remove(struct platform_device *pdev)
{
	rdcfb_remove(pdev);
}
#else
static inline int rdcfb_platform_remove(struct platform_device *pdev)
{
	rdcfb_remove(pdev);
	return 0;
}
#endif

#endif /* RDCFB_COMPAT_H */
