/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Golden scenes as the firmware image carries them, and the replay that
 * runs them on the portable core (hw-sim/, firmware-model/).
 *
 * A scene is what its .rdl script did to a simulated RDC-1, operation by
 * operation: register writes and reads, VRAM writes, waits, steps, pin
 * changes, each with the simulated time it happened at.  At build time
 * mcu/gen_scenes.c runs the script through librdc's sim: backend with
 * the trace recorder (userspace/lib/record.c) attached and turns the
 * trace into the words below; the firmware (mcu/main.c) and its host twin
 * (mcu/host_main.c) replay them with mcu_replay() and print one line per
 * scene, so the two outputs can be compared line for line.
 *
 * This file and mcu/replay.c are freestanding like the core: no libc, no
 * floating point, no allocation.
 */
#ifndef RDC_MCU_SCENE_H
#define RDC_MCU_SCENE_H

#define RDC_CORE_INTERNAL /* the MCU image holds the chip in static memory: hw.h, dp.h */
#include "rdc_base.h"
#include "dp.h"
#include "hw.h"

/*
 * The largest VRAM and frame a scene may use: the firmware's buffers are
 * this size (mcu/mps2.ld places them in the board's 16 MiB PSRAM), and
 * gen_scenes refuses a scene that needs more.  A chip made with a smaller
 * frame capacity refuses larger modes, so the cap is the same on both
 * sides of a comparison (host_main.c uses it too).
 */
#define MCU_VRAM_CAP  (8u << 20)
#define MCU_FRAME_CAP (800u * 600u)

/*
 * An operation is a header word (MCU_OP_* | argument words << 8), the
 * simulated time the host did it at (low word, high word), then its
 * arguments:
 *   POWER       a fresh chip: VRAM zeroed, rdc_hw_init, rdc_dp_init
 *   REG_WRITE   reg, value...: rdc_hw_write of each value in turn
 *   REG_READ    reg, value the host read
 *   VRAM_WRITE  addr, len, offset of the bytes in the scene's data
 *   WAIT        2 x (test, reg, mask, value), needs_dp, budget low,
 *               budget high, result (enum rdc_hw_wait_result, MORE and
 *               TIMEOUT both as TIMEOUT)
 *   STEP        cycles low, cycles high: rdc_hw_run_until(now + cycles)
 *   PINS        mask, levels: the input pins in mask driven to levels
 *   MARK        the script's last statement has finished (its `total`)
 *   END         the recording ended: time runs on to the header's time
 * A replay counts a mismatch for every time, register value or wait
 * result that differs from the recording.
 */
enum mcu_op {
	MCU_OP_POWER = 1,
	MCU_OP_REG_WRITE = 2,
	MCU_OP_REG_READ = 3,
	MCU_OP_VRAM_WRITE = 4,
	MCU_OP_WAIT = 5,
	MCU_OP_STEP = 6,
	MCU_OP_PINS = 7,
	MCU_OP_MARK = 8,
	MCU_OP_END = 9,
};

#define MCU_OP_HEAD	 3u /* header, time low, time high */
#define MCU_OP_WAIT_ARGS (4u * RDC_WAIT_TEST_TERMS + 4u)

struct mcu_scene {
	const char *name;
	uint32_t vram_size;
	const uint32_t *ops;
	uint32_t nwords;
	const uint8_t *data; /* VRAM_WRITE bytes */
	uint32_t ndata;
};

/* The scenes gen_scenes compiled in (mcu_scenes.c, generated). */
extern const struct mcu_scene mcu_scenes[];
extern const uint32_t mcu_nscenes;

/* The chip a replay runs on: the caller's memory, as rdc_hw_init wants. */
struct mcu_chip {
	struct rdc_hw hw;
	struct rdc_dp dp;
	uint8_t *vram;	    /* MCU_VRAM_CAP bytes */
	uint32_t *frame[2]; /* MCU_FRAME_CAP pixels each */
};

struct mcu_result {
	uint64_t total; /* simulated time at MARK */
	uint64_t time;	/* at the end */
	uint32_t crc;	/* CRC-32 (zlib) of the last frame, XRGB8888 LE */
	uint32_t width, height; /* 0 x 0: no frame */
	uint32_t ops;		/* operations replayed */
	uint32_t mismatches;
	struct rdc_perf perf; /* the chip's counters at the end */
	/* 0, or why the scene's words could not be replayed */
	const char *error;
};

/* Replay scene s on c from a fresh chip; r gets the figures. */
void mcu_replay(struct mcu_chip *c, const struct mcu_scene *s,
		struct mcu_result *r);

/* CRC-32 (zlib's) of n XRGB8888 pixels as little-endian bytes. */
uint32_t mcu_crc32_xrgb(const uint32_t *px, uint32_t n);

/*
 * The scene's line into buf (NUL-terminated, cut at cap):
 *   scene NAME vram N ops N total T time T frame WxH crc32 X busy N
 *   stall N pixels N cmds N mismatches N
 * or "scene NAME error WHY".
 */
#define MCU_LINE_MAX 256u
void mcu_format(char *buf, uint32_t cap, const struct mcu_scene *s,
		const struct mcu_result *r);

#endif /* RDC_MCU_SCENE_H */
