/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The trace file's format: its magic, versions, header flags and record
 * types, for the recorder and replay (record.c, which describes the
 * layout) and for what else reads traces (mcu/gen_scenes.c).  The table
 * of it: docs/protocol.md, "Traces".
 */
#ifndef RDC_RECORD_H
#define RDC_RECORD_H

#define REC_MAGIC	  "RDCTRACE"
#define REC_MAGIC_LEN	  8u
#define REC_VERSION	  2u /* a timed trace */
#define REC_VERSION_FLAGS 3u /* the flags word and SUBMIT */
#define REC_VERSION_STATE 4u /* STATE: where the chip was at the start */
#define REC_VERSION_MIN	  1u /* no PINS records */
#define REC_VERSION_MAX	  REC_VERSION_STATE
/* The header up to version 2: magic, u32 version, u32 VRAM size. */
#define REC_HEAD_LEN (REC_MAGIC_LEN + 8u)
/* Every record starts with u8 op, u64 time. */
#define REC_RECORD_HEAD 9u

/* Header flags (version 3 on). */
#define REC_F_UNTIMED 0x1u /* no time: every record's is 0 */
#define REC_F_KNOWN   REC_F_UNTIMED

enum rec_op {
	REC_REG_WRITE = 1,
	REC_REG_READ = 2,
	REC_VRAM_WRITE = 3,
	REC_WAIT = 4,
	REC_STEP = 5,
	REC_POWER = 6,
	REC_END = 7,
	REC_PINS = 8,
	REC_SUBMIT = 9,
	REC_STATE = 10,
};

/* STATE's `what` (version 4 on) */
#define REC_STATE_CORE	0x1u /* the core section: rdc_hw_resume's */
#define REC_STATE_KNOWN REC_STATE_CORE
/* its core section's flags */
#define REC_STATE_SCANNING	 0x1u
#define REC_STATE_DP_ACTIVE	 0x2u
#define REC_STATE_GAMMA		 0x4u /* CONTROL.GAMMA_EN in force */
#define REC_STATE_CORE_FLAGS_ALL 0x7u
/* the core section's bytes: 6 u64, 8 u32, u32 flags, 17 u32 in force,
 * u32 PERF_CULLED */
#define REC_STATE_CORE_LEN (6u * 8u + 8u * 4u + 4u + 17u * 4u + 4u)

#endif /* RDC_RECORD_H */
