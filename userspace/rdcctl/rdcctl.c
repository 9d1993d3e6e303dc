// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcctl: run .rdl scripts against an RDC-1, dump its registers and
 * counters, save what it shows.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "history.h"
#include "pen.h"
#include "pins.h"
#include "image.h"
#include "rdc.h"
#include "report.h"
#include "stream.h"

#define RDCCTL_DEFAULT_URI "sim:"

static void usage(FILE *f)
{
	fprintf(f,
		"usage: rdcctl [--connect URI] [--record TRACE] COMMAND "
		"[ARGS]\n"
		"\n"
		"commands:\n"
		"  run FILE.rdl [-o OUT.png]  run a script, wait for the next\n"
		"                             complete frame, print cycles per\n"
		"                             command class, the simulated time\n"
		"                             and the frame's CRC-32; -o saves "
		"it\n"
		"      [--vcd OUT.vcd]        and the chip's signals as a Value\n"
		"                             Change Dump (sim: only)\n"
		"  regs [FILE.rdl]            print every register (after the\n"
		"                             script, if one is given)\n"
		"  stats [FILE.rdl]           print the performance counters\n"
		"  replay TRACE [-o OUT.png]  play an rdcd --record trace on a\n"
		"                             fresh sim: and print its time, frame\n"
		"                             count and last frame's CRC-32\n"
		"  list                       every RDC-1 this machine reaches\n"
		"                             (USB, rdcd's default socket\n"
		"                             directory, rdcfb.ko, rdcdrm.ko):\n"
		"                             one line each, the URI for\n"
		"                             --connect first\n"
		"%s%s%s%s%s"
		"\n"
		"options:\n"
		"  --connect URI  device to use (default " RDCCTL_DEFAULT_URI
		", e.g. sim:vram=4M,\n"
		"                 unix:/run/user/1000/rdc/rdc.sock, "
		"tcp:127.0.0.1:7000);\n"
		"                 --uri is the same\n"
		"  --record TRACE  record every operation rdcctl makes on the\n"
		"                 device (any URI) into a trace for replay,\n"
		"                 why and diff; untimed but on sim:\n"
		"  -h, --help  this text\n"
		"  --version   rdcctl's release and librdc's\n"
		"\n"
		"The script format is described in rdl(5), the commands in "
		"rdcctl(1).\n",
		rdcctl_stream_usage, rdcctl_pins_usage, rdcctl_pen_usage,
		rdcctl_image_usage, rdcctl_history_usage);
}

/* The release rdcctl was built as, and the librdc it runs on. */
static void version(void)
{
	uint32_t v = rdc_version();

	printf("rdcctl %u.%u.%u (librdc %u.%u.%u)\n", RDC_VERSION_MAJOR,
	       RDC_VERSION_MINOR, RDC_VERSION_PATCH, RDC_VERSION_GET_MAJOR(v),
	       RDC_VERSION_GET_MINOR(v), RDC_VERSION_GET_PATCH(v));
}

const char *rdcctl_record_path;

int rdcctl_open(const char *uri, rdc_dev **dev)
{
	int ret = rdc_open(uri, dev);

	if (ret) {
		rdcctl_open_error(uri, ret);
		return ret;
	}
	if (!rdcctl_record_path)
		return 0;
	ret = rdc_record_start(*dev, rdcctl_record_path);
	if (ret) {
		rdcctl_record_error(rdcctl_record_path, ret);
		rdc_close(*dev);
		*dev = NULL;
	}
	return ret;
}

/*
 * Take --record TRACE (--record=TRACE) out of argv, before or after the
 * command: every subcommand then sees only the options it knows.  -1 on
 * a missing value.
 */
static int take_record(int *argc, char **argv)
{
	int i = 1, j;

	while (i < *argc) {
		const char *a = argv[i];

		if (!strncmp(a, "--record=", 9)) {
			rdcctl_record_path = a + 9;
			j = 1;
		} else if (!strcmp(a, "--record")) {
			if (i + 1 >= *argc) {
				fprintf(stderr, "rdcctl: --record needs a "
						"value\n");
				return -1;
			}
			rdcctl_record_path = argv[i + 1];
			j = 2;
		} else {
			/* a URI is a value, whatever it looks like */
			i += !strcmp(a, "--uri") || !strcmp(a, "--connect") ?
				     2 :
				     1;
			continue;
		}
		memmove(argv + i, argv + i + j,
			(size_t)(*argc - i - j + 1) * sizeof(*argv));
		*argc -= j;
	}
	if (rdcctl_record_path && !*rdcctl_record_path) {
		fprintf(stderr, "rdcctl: --record needs a file name\n");
		return -1;
	}
	return 0;
}

/* Commands that open no device of --connect's have nothing to record. */
static int record_refused(int argc, char **argv)
{
	static const char *const none[] = { "diff", "replay", "list" };
	const char *uri;

	if (!rdcctl_record_path)
		return 0;
	for (size_t k = 0; k < sizeof(none) / sizeof(none[0]); k++)
		if (rdcctl_command_at(argc, argv, none[k], &uri) >= 0) {
			fprintf(stderr,
				"rdcctl: --record does not go with %s (it "
				"opens no device of --connect's to record)\n",
				none[k]);
			return 1;
		}
	return 0;
}

struct opts {
	const char *uri;
	const char *cmd;
	const char *script;
	const char *png;
	const char *vcd;
};

static int parse_args(int argc, char **argv, struct opts *o)
{
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];

		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			usage(stdout);
			exit(0);
		} else if (!strcmp(a, "--version")) {
			version();
			exit(0);
		} else if (!strcmp(a, "--uri") || !strcmp(a, "--connect") ||
			   !strcmp(a, "-o") || !strcmp(a, "--vcd")) {
			if (i + 1 >= argc) {
				fprintf(stderr, "rdcctl: %s needs a value\n",
					a);
				return -1;
			}
			if (a[1] == 'o')
				o->png = argv[++i];
			else if (!strcmp(a, "--vcd"))
				o->vcd = argv[++i];
			else
				o->uri = argv[++i];
		} else if (!strncmp(a, "--uri=", 6)) {
			o->uri = a + 6;
		} else if (!strncmp(a, "--connect=", 10)) {
			o->uri = a + 10;
		} else if (a[0] == '-' && a[1]) {
			fprintf(stderr, "rdcctl: unknown option '%s'\n", a);
			return -1;
		} else if (!o->cmd) {
			o->cmd = a;
		} else if (!o->script) {
			o->script = a;
		} else {
			fprintf(stderr, "rdcctl: unexpected argument '%s'\n",
				a);
			return -1;
		}
	}
	if (!o->cmd) {
		usage(stderr);
		return -1;
	}
	return 0;
}

static int run_script(rdc_dev *dev, const char *path,
		      struct rdc_script_result *res)
{
	int ret = rdc_script_run_file(dev, path, res);

	if (ret)
		rdcctl_script_error(path, ret, res);
	return ret;
}

static void print_classes(const struct rdc_script_result *res)
{
	printf("%-14s %10s %14s\n", "class", "commands", "cycles");
	for (uint32_t op = 0; op < 256; op++) {
		const char *name = rdc_op_name(op);
		char buf[16];

		if (!res->op_count[op] && !res->op_cycles[op])
			continue;
		if (!name) {
			snprintf(buf, sizeof(buf), "op-0x%02x", op);
			name = buf;
		}
		printf("%-14s %10llu %14llu\n", name,
		       (unsigned long long)res->op_count[op],
		       (unsigned long long)res->op_cycles[op]);
	}
}

static int cmd_run(rdc_dev *dev, const struct opts *o)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	uint32_t *pix = NULL, w = 0, h = 0, crc, hz = 0;
	rdc_vcd *vcd = NULL;
	uint64_t t = 0;
	int ret;

	if (!res)
		return RDC_E_NOMEM;
	if (o->vcd) {
		ret = rdc_vcd_open(dev, o->vcd, &vcd);
		if (ret == RDC_E_NOSYS)
			fprintf(stderr,
				"rdcctl: --vcd needs a sim: device (the "
				"signals are traced inside the simulator), "
				"not '%s'\n",
				o->uri);
		else if (ret)
			rdcctl_error(o->vcd, ret);
		if (ret)
			goto out;
	}
	ret = run_script(dev, o->script, res);
	if (ret)
		goto out;
	ret = rdc_sim_time(dev, &t);
	if (!ret)
		ret = rdc_sim_core_hz(dev, &hz);
	if (!ret)
		ret = rdc_script_frame_wait(dev, res);
	if (!ret)
		ret = rdc_frame_grab(dev, NULL, 0, &w, &h);
	if (ret == RDC_E_RANGE) {
		pix = malloc(((size_t)w * h + 1) * sizeof(*pix));
		ret = pix ? rdc_frame_grab(dev, pix, (size_t)w * h, &w, &h) :
			    RDC_E_NOMEM;
	}
	if (ret) {
		rdcctl_error("frame", ret);
		goto out;
	}
	ret = rdc_frame_crc(dev, &crc);
	if (ret) {
		rdcctl_error("crc", ret);
		goto out;
	}
	/* the PNG first: a run that fails prints no figures */
	if (o->png) {
		ret = rdc_png_write(o->png, pix, w, h, w);
		if (ret) {
			rdcctl_error(o->png, ret);
			goto out;
		}
	}
	print_classes(res);
	if (res->readbacks)
		printf("readback crc32 %08x (%u words)\n", res->readback_crc,
		       res->readback_words);
	printf("total %llu cycles (%.3f ms at %u Hz)\n", (unsigned long long)t,
	       hz ? (double)t * 1000.0 / hz : 0.0, hz);
	printf("frame %ux%u\n", w, h);
	printf("crc32 %08x\n", crc);
out:
	if (vcd) {
		int err = rdc_vcd_close(vcd);

		if (err)
			rdcctl_error(o->vcd, err);
		if (!ret)
			ret = err;
	}
	free(pix);
	free(res);
	return ret;
}

static int cmd_regs(rdc_dev *dev)
{
	for (size_t i = 0; i < rdc_reg_count(); i++) {
		uint32_t reg, v;
		const char *name = rdc_reg_info(i, &reg);
		int ret;

		/* Reading these pops or changes state; show them as such. */
		if (rdc_reg_read_has_effect(reg)) {
			printf("0x%03x %-18s (not read)\n", reg, name);
			continue;
		}
		ret = rdc_reg_read(dev, reg, &v);
		if (ret) {
			rdcctl_error(name, ret);
			return ret;
		}
		printf("0x%03x %-18s 0x%08x %u\n", reg, name, v, v);
	}
	return 0;
}

static int cmd_stats(rdc_dev *dev)
{
	struct rdc_stats st;
	uint32_t hz = 0;
	int ret = rdc_stats_get(dev, &st);

	if (!ret)
		ret = rdc_sim_core_hz(dev, &hz);
	if (ret) {
		rdcctl_error("stats", ret);
		return ret;
	}
	printf("time         %llu cycles (%.3f ms)\n",
	       (unsigned long long)st.time,
	       hz ? (double)st.time * 1000.0 / hz : 0.0);
	printf("busy         %llu\n", (unsigned long long)st.busy);
	printf("stall        %llu\n", (unsigned long long)st.stall);
	printf("pixels       %llu\n", (unsigned long long)st.pixels);
	printf("commands     %u\n", st.cmds);
	printf("last-cycles  %u\n", st.last_cycles);
	printf("last-opcode  0x%02x %s\n", st.last_opcode,
	       rdc_op_name(st.last_opcode) ? rdc_op_name(st.last_opcode) : "");
	printf("frames       %llu\n", (unsigned long long)st.frames);
	return 0;
}

/* A trace needs no device: it brings its own fresh one. */
static int cmd_replay(const struct opts *o)
{
	struct rdc_replay_result res;
	rdc_dev *dev = NULL;
	uint32_t *pix = NULL, w = 0, h = 0;
	int ret;

	if (!o->script) {
		fprintf(stderr, "rdcctl: replay needs a trace file\n");
		return 2;
	}
	ret = rdc_replay_file(o->script, &res, &dev);
	if (ret) {
		rdcctl_error(o->script, ret);
		return 1;
	}
	if (res.truncated)
		fprintf(stderr,
			"rdcctl: %s: truncated trace: it ends without its END "
			"record (rdcd is still recording, or was stopped "
			"without closing it); replayed up to its last complete "
			"record\n",
			o->script);
	printf("records %llu\n", (unsigned long long)res.records);
	printf("total %llu cycles\n", (unsigned long long)res.time);
	printf("frames %llu\n", (unsigned long long)res.frames);
	if (res.frames)
		printf("frame %ux%u\ncrc32 %08x\n", res.width, res.height,
		       res.frame_crc);
	printf("mismatches %llu\n", (unsigned long long)res.mismatches);
	if (o->png && res.frames) {
		ret = rdc_frame_grab(dev, NULL, 0, &w, &h);
		if (ret == RDC_E_RANGE) {
			pix = malloc(((size_t)w * h + 1) * sizeof(*pix));
			ret = pix ? rdc_frame_grab(dev, pix, (size_t)w * h, &w,
						   &h) :
				    RDC_E_NOMEM;
		}
		if (!ret)
			ret = rdc_png_write(o->png, pix, w, h, w);
		if (ret)
			rdcctl_error(o->png, ret);
		free(pix);
	}
	rdc_close(dev);
	if (ret)
		return 1;
	return res.mismatches ? RDCCTL_EXIT_DIFFERS : 0;
}

static void list_one(const struct rdc_found *f, void *arg)
{
	(void)arg;
	printf("%-40s %s\n", f->uri, f->info);
}

static int cmd_list(void)
{
	int n = rdc_list(list_one, NULL);

	if (n < 0) {
		rdcctl_error("list", n);
		return 1;
	}
	if (!n)
		fprintf(stderr, "rdcctl: no RDC-1 found\n");
	return 0;
}

int main(int argc, char **argv)
{
	struct opts o = { .uri = RDCCTL_DEFAULT_URI };
	rdc_dev *dev;
	int ret;

	if (take_record(&argc, argv) || record_refused(argc, argv))
		return 2;
	ret = rdcctl_stream_main(argc, argv);
	if (ret >= 0)
		return ret;
	ret = rdcctl_pins_main(argc, argv);
	if (ret >= 0)
		return ret;
	ret = rdcctl_pen_main(argc, argv);
	if (ret >= 0)
		return ret;
	ret = rdcctl_image_main(argc, argv);
	if (ret >= 0)
		return ret;
	ret = rdcctl_history_main(argc, argv);
	if (ret >= 0)
		return ret;
	if (parse_args(argc, argv, &o))
		return 2;
	if (!strcmp(o.cmd, "replay"))
		return cmd_replay(&o);
	if (!strcmp(o.cmd, "list")) {
		if (o.script) {
			fprintf(stderr, "rdcctl: list takes no argument\n");
			return 2;
		}
		return cmd_list();
	}
	if (strcmp(o.cmd, "run") && strcmp(o.cmd, "regs") &&
	    strcmp(o.cmd, "stats")) {
		fprintf(stderr, "rdcctl: unknown command '%s' (try --help)\n",
			o.cmd);
		return 2;
	}
	if (o.vcd && strcmp(o.cmd, "run")) {
		fprintf(stderr, "rdcctl: --vcd goes with run\n");
		return 2;
	}
	/* bad usage (2) is told before a device is opened */
	if (!strcmp(o.cmd, "run") && !o.script) {
		fprintf(stderr, "rdcctl: run needs a script\n");
		return 2;
	}
	ret = rdcctl_open(o.uri, &dev);
	if (ret)
		return 1;
	if (!strcmp(o.cmd, "run")) {
		ret = cmd_run(dev, &o);
	} else {
		struct rdc_script_result *res = calloc(1, sizeof(*res));

		ret = res ? 0 : RDC_E_NOMEM;
		if (!ret && o.script)
			ret = run_script(dev, o.script, res);
		free(res);
		if (!ret)
			ret = !strcmp(o.cmd, "regs") ? cmd_regs(dev) :
						       cmd_stats(dev);
	}
	if (rdcctl_record_path) {
		int err = rdc_record_stop(dev);

		if (err)
			rdcctl_record_error(rdcctl_record_path, err);
		ret = ret ? ret : err;
	}
	rdc_close(dev);
	return ret ? 1 : 0;
}
