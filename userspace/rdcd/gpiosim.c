// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd --gpio-sim NAME: the chip's pins as the lines of a gpio-sim chip
 * (the kernel's GPIO simulator, CONFIG_GPIO_SIM), so that a program
 * written with libgpiod for a GPIO-wired panel controller runs unchanged
 * against this daemon.
 *
 * rdcd makes the simulated chip itself through configfs and takes it
 * down on exit:
 *   /sys/kernel/config/gpio-sim/NAME/bank0   num_lines 4, label NAME,
 *                                            line0..3/name TE IRQ RESET_N
 *                                            BL_EN
 *   /sys/kernel/config/gpio-sim/NAME/live    1
 * and then talks to it through the simulator's sysfs lines,
 * /sys/devices/platform/<dev_name>/<chip_name>/sim_gpioN/{pull,value}:
 *
 *  - TE and IRQ are the chip's outputs: rdcd writes their `pull` at every
 *    RDC_TRACE_PINS change, from inside the simulation, so a consumer
 *    that requested them as inputs gets an edge event for each.  Paced,
 *    edges come in real time (within the loop's millisecond tick); fast,
 *    as quickly as the simulation makes them, far ahead of the wall
 *    clock; stepped, only while a client's wait moves time.
 *  - RESET_N and BL_EN are the chip's inputs: pulled up, so they read
 *    high until a consumer requests them as outputs and drives them; the
 *    line's `value` is then what it drives.  rdcd reads them once per
 *    turn of its loop and at least every RDCD_GPIOSIM_POLL_MS, and hands
 *    a change to the chip (rdc_pins_set) as a protocol client's PINS_SET
 *    would: a consumer's change reaches the chip within a loop turn
 *    (about a millisecond paced, less fast, RDCD_GPIOSIM_POLL_MS at
 *    most stepped).  Only changes are forwarded, so a protocol client
 *    may drive the pins too; the last change wins.  A power cycle makes
 *    a chip whose inputs are high whatever the lines say: rdcd tells the
 *    bridge (rdcd_gpiosim_new_chip), which forwards the levels the
 *    consumer still drives at once, before time moves on the new chip.
 *    (The chip's address cannot tell: the new one may reuse the old
 *    one's memory.)
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rdcd.h"

#define GPIOSIM_CONFIGFS "/sys/kernel/config/gpio-sim"
#define GPIOSIM_NLINES	 4u
#define GPIOSIM_NAME_MAX 32u

/* Lines in RDC_PIN_* bit order: line N is pin 1 << N. */
static const char *const gpiosim_line[GPIOSIM_NLINES] = {
	"TE",
	"IRQ",
	"RESET_N",
	"BL_EN",
};

_Static_assert(RDC_PIN_TE == 1u && RDC_PIN_IRQ == 2u && RDC_PIN_RESET_N == 4u &&
		       RDC_PIN_BL_EN == 8u,
	       "gpiosim_line is in RDC_PIN_* bit order");

struct rdcd_gpiosim {
	struct rdcd *d;
	char dir[160];	  /* configfs: GPIOSIM_CONFIGFS/NAME */
	char sysdir[200]; /* sysfs: /sys/devices/platform/DEV/CHIP */
	char chip[32];	  /* gpiochipN */
	int pull_fd[GPIOSIM_NLINES], value_fd[GPIOSIM_NLINES];
	uint32_t pulled; /* TE, IRQ as last written */
	uint32_t seen;	 /* RESET_N, BL_EN as last forwarded (or the chip's) */
	bool live, made[GPIOSIM_NLINES], bank, top;
	bool write_failed, set_failed;
};

static int gpiosim_write_file(const char *path, const char *s)
{
	int fd = open(path, O_WRONLY | O_CLOEXEC);
	ssize_t k;

	if (fd < 0)
		return -1;
	k = write(fd, s, strlen(s));
	close(fd);
	return k == (ssize_t)strlen(s) ? 0 : -1;
}

/* The first line of a file, newline cut; 0 or -1. */
static int gpiosim_read_file(const char *path, char *buf, size_t cap)
{
	int fd = open(path, O_RDONLY | O_CLOEXEC);
	ssize_t k;

	if (fd < 0)
		return -1;
	k = read(fd, buf, cap - 1);
	close(fd);
	if (k <= 0)
		return -1;
	buf[k] = 0;
	buf[strcspn(buf, "\n")] = 0;
	return buf[0] ? 0 : -1;
}

static int gpiosim_attr(const struct rdcd_gpiosim *g, const char *rel,
			const char *val)
{
	char path[300];

	snprintf(path, sizeof(path), "%s/%s", g->dir, rel);
	return gpiosim_write_file(path, val);
}

static bool gpiosim_name_ok(const char *name)
{
	size_t n = strlen(name);

	if (!n || n > GPIOSIM_NAME_MAX || name[0] == '.')
		return false;
	for (size_t i = 0; i < n; i++)
		if (!((name[i] >= 'a' && name[i] <= 'z') ||
		      (name[i] >= 'A' && name[i] <= 'Z') ||
		      (name[i] >= '0' && name[i] <= '9') || name[i] == '-' ||
		      name[i] == '_' || name[i] == '.'))
			return false;
	return true;
}

/* Undo what open made, in the reverse order; safe on a partial one. */
static void gpiosim_teardown(struct rdcd_gpiosim *g)
{
	char path[300];

	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++) {
		if (g->pull_fd[i] >= 0)
			close(g->pull_fd[i]);
		if (g->value_fd[i] >= 0)
			close(g->value_fd[i]);
		g->pull_fd[i] = g->value_fd[i] = -1;
	}
	if (g->live && gpiosim_attr(g, "live", "0"))
		rdcd_log(g->d, RDCD_LOG_WARN, "gpio-sim: %s/live: %s", g->dir,
			 strerror(errno));
	g->live = false;
	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++) {
		if (!g->made[i])
			continue;
		snprintf(path, sizeof(path), "%s/bank0/line%u", g->dir, i);
		rmdir(path);
		g->made[i] = false;
	}
	if (g->bank) {
		snprintf(path, sizeof(path), "%s/bank0", g->dir);
		rmdir(path);
		g->bank = false;
	}
	if (g->top && rmdir(g->dir))
		rdcd_log(g->d, RDCD_LOG_WARN, "gpio-sim: rmdir %s: %s", g->dir,
			 strerror(errno));
	g->top = false;
}

static void gpiosim_pull(struct rdcd_gpiosim *g, unsigned int line, bool high)
{
	static const char up[] = "pull-up", down[] = "pull-down";
	const char *s = high ? up : down;

	if (pwrite(g->pull_fd[line], s, strlen(s), 0) == (ssize_t)strlen(s))
		return;
	if (!g->write_failed)
		rdcd_log(g->d, RDCD_LOG_WARN,
			 "gpio-sim: %s/sim_gpio%u/pull: %s", g->sysdir, line,
			 strerror(errno));
	g->write_failed = true;
}

/* TE and IRQ to `levels`, writing only the lines that change. */
static void gpiosim_drive(struct rdcd_gpiosim *g, uint32_t levels)
{
	uint32_t diff = (levels ^ g->pulled) & RDC_PINS_OUT;

	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++)
		if (diff & (1u << i))
			gpiosim_pull(g, i, levels & (1u << i));
	g->pulled = (g->pulled & ~diff) | (levels & diff);
}

/* The chip reports each pin change at its simulated time: pass it on. */
static void gpiosim_trace(void *ctx, uint64_t time, unsigned int event,
			  uint32_t a, uint32_t b)
{
	struct rdcd_gpiosim *g = ctx;

	(void)time;
	if (event == RDC_TRACE_PINS && (b & RDC_PINS_OUT))
		gpiosim_drive(g, a);
}

/* RESET_N and BL_EN as the sim lines read: 1 unless a consumer drives 0. */
static int gpiosim_inputs(struct rdcd_gpiosim *g, uint32_t *levels)
{
	*levels = 0;
	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++) {
		char b[8];
		ssize_t k;

		if (!(RDC_PINS_IN & (1u << i)))
			continue;
		k = pread(g->value_fd[i], b, sizeof(b) - 1, 0);
		if (k <= 0)
			return -1;
		if (b[0] == '1')
			*levels |= 1u << i;
	}
	return 0;
}

static int gpiosim_open_lines(struct rdcd_gpiosim *g)
{
	char path[320], dev[64];

	snprintf(path, sizeof(path), "%s/dev_name", g->dir);
	if (gpiosim_read_file(path, dev, sizeof(dev)))
		return -1;
	snprintf(path, sizeof(path), "%s/bank0/chip_name", g->dir);
	if (gpiosim_read_file(path, g->chip, sizeof(g->chip)))
		return -1;
	snprintf(g->sysdir, sizeof(g->sysdir), "/sys/devices/platform/%s/%s",
		 dev, g->chip);
	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++) {
		snprintf(path, sizeof(path), "%s/sim_gpio%u/pull", g->sysdir,
			 i);
		g->pull_fd[i] = open(path, O_WRONLY | O_CLOEXEC);
		snprintf(path, sizeof(path), "%s/sim_gpio%u/value", g->sysdir,
			 i);
		g->value_fd[i] = open(path, O_RDONLY | O_CLOEXEC);
		if (g->pull_fd[i] < 0 || g->value_fd[i] < 0)
			return -1;
	}
	return 0;
}

/* Pulls from the chip's levels now (at start, and on a new chip). */
static void gpiosim_sync(struct rdcd_gpiosim *g)
{
	uint32_t levels = rdc_hw_pins(g->d->hw);

	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++)
		if (RDC_PINS_OUT & (1u << i))
			gpiosim_pull(g, i, levels & (1u << i));
	g->pulled = levels & RDC_PINS_OUT;
}

int rdcd_gpiosim_open(struct rdcd *d, const char *name)
{
	struct rdcd_gpiosim *g;
	char path[300], n[4];
	const char *what = "";
	struct stat st;

	if (!gpiosim_name_ok(name)) {
		rdcd_log(d, RDCD_LOG_ERR,
			 "--gpio-sim %s: want 1-%u letters, digits, '-', '_' "
			 "or '.'",
			 name, GPIOSIM_NAME_MAX);
		return -1;
	}
	if (stat(GPIOSIM_CONFIGFS, &st) || !S_ISDIR(st.st_mode)) {
		rdcd_log(d, RDCD_LOG_ERR,
			 "--gpio-sim: %s missing (modprobe gpio-sim; configfs "
			 "mounted on /sys/kernel/config?)",
			 GPIOSIM_CONFIGFS);
		return -1;
	}
	g = calloc(1, sizeof(*g));
	if (!g)
		return -1;
	g->d = d;
	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++)
		g->pull_fd[i] = g->value_fd[i] = -1;
	snprintf(g->dir, sizeof(g->dir), "%s/%s", GPIOSIM_CONFIGFS, name);
	/* someone else's chip, or one a killed daemon left: not ours */
	what = "mkdir";
	if (mkdir(g->dir, 0755))
		goto fail;
	g->top = true;
	snprintf(path, sizeof(path), "%s/bank0", g->dir);
	if (mkdir(path, 0755))
		goto fail;
	g->bank = true;
	what = "bank0";
	snprintf(n, sizeof(n), "%u", GPIOSIM_NLINES);
	if (gpiosim_attr(g, "bank0/num_lines", n) ||
	    gpiosim_attr(g, "bank0/label", name))
		goto fail;
	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++) {
		char rel[40];

		snprintf(path, sizeof(path), "%s/bank0/line%u", g->dir, i);
		what = "lines";
		if (mkdir(path, 0755))
			goto fail;
		g->made[i] = true;
		snprintf(rel, sizeof(rel), "bank0/line%u/name", i);
		if (gpiosim_attr(g, rel, gpiosim_line[i]))
			goto fail;
	}
	what = "live";
	if (gpiosim_attr(g, "live", "1"))
		goto fail;
	g->live = true;
	what = "sim_gpio lines";
	if (gpiosim_open_lines(g))
		goto fail;
	/* the inputs idle high, as RESET_N and BL_EN must */
	for (unsigned int i = 0; i < GPIOSIM_NLINES; i++)
		if (RDC_PINS_IN & (1u << i))
			gpiosim_pull(g, i, true);
	gpiosim_sync(g);
	if (g->write_failed || gpiosim_inputs(g, &g->seen)) {
		what = "sim_gpio pull/value";
		goto fail;
	}
	if (rdcd_trace_add(d, gpiosim_trace, g)) {
		what = "trace hook";
		goto fail;
	}
	d->gpiosim = g;
	rdcd_log(d, RDCD_LOG_INFO, "gpio-sim: pins on %s (/dev/%s)", name,
		 g->chip);
	return 0;
fail:
	rdcd_log(d, RDCD_LOG_ERR, "--gpio-sim %s: %s: %s", name, what,
		 errno ? strerror(errno) : "failed");
	gpiosim_teardown(g);
	free(g);
	return -1;
}

/* Hand the chip what the input lines say, where it differs from seen. */
static void gpiosim_forward(struct rdcd_gpiosim *g)
{
	struct rdcd *d = g->d;
	uint32_t in, diff;
	int ret;

	if (gpiosim_inputs(g, &in)) {
		if (!g->write_failed)
			rdcd_log(d, RDCD_LOG_WARN, "gpio-sim: reading %s: %s",
				 g->sysdir, strerror(errno));
		g->write_failed = true;
		return;
	}
	diff = in ^ g->seen;
	if (!diff)
		return;
	g->seen = in;
	ret = rdc_pins_set(d->dev, diff, in);
	if (ret) {
		if (!g->set_failed)
			rdcd_log(d, RDCD_LOG_WARN,
				 "gpio-sim: driving the chip's pins: %s",
				 rdc_strerror(ret));
		g->set_failed = true;
		return;
	}
	/* TE and IRQ followed already: a reset reports its pin changes */
	rdcd_log(d, RDCD_LOG_DEBUG, "gpio-sim: RESET_N=%u BL_EN=%u",
		 !!(in & RDC_PIN_RESET_N), !!(in & RDC_PIN_BL_EN));
}

void rdcd_gpiosim_poll(struct rdcd *d)
{
	if (d->gpiosim)
		gpiosim_forward(d->gpiosim);
}

void rdcd_gpiosim_new_chip(struct rdcd *d)
{
	struct rdcd_gpiosim *g = d->gpiosim;

	if (!g)
		return;
	gpiosim_sync(g);
	/* what the new chip has: the consumer's levels differ from these */
	g->seen = rdc_hw_pins(d->hw) & RDC_PINS_IN;
	gpiosim_forward(g);
}

void rdcd_gpiosim_close(struct rdcd *d)
{
	struct rdcd_gpiosim *g = d->gpiosim;

	if (!g)
		return;
	rdcd_trace_remove(d, gpiosim_trace, g);
	gpiosim_teardown(g);
	free(g);
	d->gpiosim = NULL;
}
