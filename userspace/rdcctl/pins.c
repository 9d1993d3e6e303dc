// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcctl pins: the RDC-1's pins on any librdc device: show the levels,
 * drive RESET_N and BL_EN, and watch TE and IRQ edges as gpiomon shows a
 * GPIO line's.
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pins.h"
#include "rdc.h"
#include "report.h"

#define PINS_MAX_SET 8
/* One wait of --watch, so a signal is noticed (microseconds). */
#define PINS_WATCH_SLICE_US 1000000u

const char rdcctl_pins_usage[] =
	"  pins [OPTIONS]             show the pins TE, IRQ, RESET_N, BL_EN\n"
	"    --set PIN=0|1            drive RESET_N or BL_EN (repeatable)\n"
	"    --watch                  print TE and IRQ edges until --count\n"
	"                             or a signal: wall time, edge, pin,\n"
	"                             simulated cycle (when known)\n"
	"    --pin TE|IRQ             watch only this pin\n"
	"    --edges rising|falling|both  (default both)\n"
	"    --count N                stop after N edges\n";

static const struct {
	const char *name;
	uint32_t bit;
} pins_names[] = {
	{ "TE", RDC_PIN_TE },
	{ "IRQ", RDC_PIN_IRQ },
	{ "RESET_N", RDC_PIN_RESET_N },
	{ "BL_EN", RDC_PIN_BL_EN },
};

#define PINS_N (sizeof(pins_names) / sizeof(pins_names[0]))

struct pins_opts {
	const char *uri;
	uint32_t set_mask, set_levels;
	bool watch;
	uint32_t watch_pins, edges;
	uint64_t count;
};

static volatile sig_atomic_t pins_stop;

static void pins_on_signal(int sig)
{
	(void)sig;
	pins_stop = 1;
}

static uint32_t pins_by_name(const char *s, size_t len)
{
	for (size_t i = 0; i < PINS_N; i++)
		if (strlen(pins_names[i].name) == len &&
		    !strncasecmp(s, pins_names[i].name, len))
			return pins_names[i].bit;
	return 0;
}

static const char *pins_name(uint32_t bit)
{
	for (size_t i = 0; i < PINS_N; i++)
		if (pins_names[i].bit == bit)
			return pins_names[i].name;
	return "?";
}

static int pins_parse(int argc, char **argv, struct pins_opts *o)
{
	for (int i = 0; i < argc; i++) {
		const char *a = argv[i];
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;

		if (!strcmp(a, "--watch")) {
			o->watch = true;
			continue;
		}
		if (!v) {
			fprintf(stderr, "rdcctl: pins: %s needs a value\n", a);
			return -1;
		}
		i++;
		if (!strcmp(a, "--set")) {
			const char *eq = strchr(v, '=');
			uint32_t bit = eq ? pins_by_name(v, (size_t)(eq - v)) :
					    0;

			if (!(bit & RDC_PINS_IN) ||
			    (strcmp(eq + 1, "0") && strcmp(eq + 1, "1"))) {
				fprintf(stderr,
					"rdcctl: pins: --set wants RESET_N=0|1 "
					"or BL_EN=0|1, not '%s'\n",
					v);
				return -1;
			}
			o->set_mask |= bit;
			o->set_levels = (o->set_levels & ~bit) |
					(eq[1] == '1' ? bit : 0);
		} else if (!strcmp(a, "--pin")) {
			uint32_t bit = pins_by_name(v, strlen(v));

			if (!(bit & RDC_PINS_OUT)) {
				fprintf(stderr, "rdcctl: pins: --pin wants TE "
						"or IRQ\n");
				return -1;
			}
			o->watch_pins |= bit;
		} else if (!strcmp(a, "--edges")) {
			if (!strcmp(v, "rising"))
				o->edges = RDC_EDGE_RISING;
			else if (!strcmp(v, "falling"))
				o->edges = RDC_EDGE_FALLING;
			else if (!strcmp(v, "both"))
				o->edges = RDC_EDGE_BOTH;
			else {
				fprintf(stderr, "rdcctl: pins: bad --edges\n");
				return -1;
			}
		} else if (!strcmp(a, "--count")) {
			char *end;

			errno = 0;
			o->count = strtoull(v, &end, 10);
			if (errno || *end || v[0] < '0' || v[0] > '9') {
				fprintf(stderr, "rdcctl: pins: bad --count\n");
				return -1;
			}
		} else {
			fprintf(stderr, "rdcctl: pins: unknown option '%s'\n",
				a);
			return -1;
		}
	}
	if (!o->watch_pins)
		o->watch_pins = RDC_PINS_OUT;
	if (!o->edges)
		o->edges = RDC_EDGE_BOTH;
	return 0;
}

static void pins_print(uint32_t levels)
{
	for (size_t i = 0; i < PINS_N; i++)
		printf("%s%s=%u", i ? " " : "", pins_names[i].name,
		       levels & pins_names[i].bit ? 1u : 0u);
	putchar('\n');
}

/* One line per edge, gpiomon's way: time, edge, line; then the cycle. */
static void pins_print_edge(const struct rdc_pin_edge *ev)
{
	for (size_t i = 0; i < PINS_N; i++) {
		uint32_t bit = pins_names[i].bit;

		if (!(ev->pins & bit))
			continue;
		printf("%llu.%09llu\t%s\t%s",
		       (unsigned long long)(ev->wall_ns / 1000000000u),
		       (unsigned long long)(ev->wall_ns % 1000000000u),
		       ev->levels & bit ? "rising" : "falling", pins_name(bit));
		if (ev->time != RDC_PIN_TIME_NONE)
			printf("\t%llu", (unsigned long long)ev->time);
		putchar('\n');
	}
	fflush(stdout);
}

static int pins_watch(rdc_dev *dev, const struct pins_opts *o)
{
	uint64_t seen = 0;

	while (!pins_stop && (!o->count || seen < o->count)) {
		struct rdc_pin_edge ev;
		/* every edge, as gpiomon: those queued between waits too */
		int ret = rdc_pins_wait_edge(dev, o->watch_pins,
					     o->edges | RDC_EDGE_QUEUED,
					     PINS_WATCH_SLICE_US, &ev);

		if (ret == RDC_E_TIMEOUT)
			continue;
		if (ret) {
			fprintf(stderr, "rdcctl: pins: wait: %s\n",
				rdc_strerror(ret));
			return ret;
		}
		pins_print_edge(&ev);
		for (uint32_t p = ev.pins; p; p &= p - 1)
			seen++;
	}
	return 0;
}

int rdcctl_pins_main(int argc, char **argv)
{
	struct pins_opts o = { .uri = "sim:" };
	struct sigaction sa;
	uint32_t levels;
	rdc_dev *dev;
	int i, ret;

	i = rdcctl_command_at(argc, argv, "pins", &o.uri);
	if (i < 0)
		return -1;
	if (pins_parse(argc - i - 1, argv + i + 1, &o))
		return 2;
	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = pins_on_signal;
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);

	ret = rdcctl_open(o.uri, &dev);
	if (ret)
		return 1;
	if (o.set_mask) {
		ret = rdc_pins_set(dev, o.set_mask, o.set_levels);
		if (ret) {
			fprintf(stderr, "rdcctl: pins: set: %s\n",
				rdc_strerror(ret));
			goto out;
		}
	}
	if (o.watch) {
		ret = pins_watch(dev, &o);
		goto out;
	}
	ret = rdc_pins_get(dev, &levels);
	if (ret)
		fprintf(stderr, "rdcctl: pins: %s\n", rdc_strerror(ret));
	else
		pins_print(levels);
out:
	rdc_close(dev);
	return ret ? 1 : 0;
}
