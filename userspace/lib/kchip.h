/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * What librdc's two backends of an RDC-1 simulated in the kernel share:
 * fbdev: (rdcfb.ko, /dev/fbN) and drm: (rdcdrm.ko, /dev/dri/cardN).  Both
 * modules run the same kernel chip host behind private ioctls of the same
 * meaning (driver/rdcfb_ioctl.h, driver/rdcdrm_ioctl.h), and both register
 * the chip's pins as one gpio_chip per device, labelled after the device
 * node's sysfs device ("rdcfb.N-pins", "rdcdrm.N-pins") with the lines
 * "TE", "IRQ", "RESET_N", "BL_EN".
 */
#ifndef RDC_KCHIP_H
#define RDC_KCHIP_H

#include <stddef.h>
#include <stdint.h>

#include "rdc_priv.h"

/*
 * The one place an errno from either module becomes a library error (the
 * meanings of the two ioctl headers' lists).
 */
int rdc_kchip_error(int err);

/*
 * The modules' STATE ioctl answer (driver/rdc_state_uapi.h, the same for
 * rdcfb and rdcdrm) as the core's rdc_hw_resume, for a trace's start.
 */
struct rdc_chip_state;
void rdc_kchip_state_resume(const struct rdc_chip_state *st,
			    struct rdc_hw_resume *s);

/*
 * Words of `w` (n of them) up to the last command boundary at or before
 * `max`: the modules check a buffer command by command, so a command
 * must not be split between two SUBMITs.
 */
size_t rdc_kchip_piece(const uint32_t *w, size_t n, size_t max);

/*
 * The pins as GPIO lines (libgpiod v2), opened on the first call that
 * needs them: `fd` is the device node whose sysfs device names the
 * gpio_chip.  Stepped or paced is asked of the device itself (a STEP of
 * nothing through dev's backend is refused on a paced clock); PINS is
 * read through dev's backend too.  Without libgpiod every call answers
 * RDC_E_NOSYS.
 */
struct rdc_kchip_pins;

void rdc_kchip_pins_free(struct rdc_kchip_pins *p);
int rdc_kchip_pins_get(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
		       uint32_t *levels);
int rdc_kchip_pins_set(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
		       uint32_t mask, uint32_t levels);
int rdc_kchip_pins_wait(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
			uint32_t pins, uint32_t edges, uint64_t budget_cycles,
			uint64_t timeout_us, struct rdc_pin_edge *ev);

#endif /* RDC_KCHIP_H */
