/* SPDX-License-Identifier: GPL-2.0-only WITH Linux-syscall-note */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The chip's state as both modules' STATE ioctls give it: one struct for
 * rdcfb_ioctl.h and rdcdrm_ioctl.h, filled by the kernel chip host
 * (rdc_kchip_state_get) and read by librdc (rdc_kchip_state_resume).
 */
#ifndef RDC_STATE_UAPI_H
#define RDC_STATE_UAPI_H

#include <linux/types.h>

/*
 * Where the chip's run has got to beyond what its registers read back
 * (read-only; rdcfb's RDCFB_IOC_STATE, rdcdrm's DRM_IOCTL_RDC_STATE): a trace recorded from here on (librdc's rdc_record_start)
 * starts its replay's fresh chip at the same time, frame phase and
 * counters.  `reserved` must be 0 in.
 */
#define RDC_CHIP_STATE_SCANNING (1u << 0) /* a mode is in force, scanning */
#define RDC_CHIP_STATE_DP_ACTIVE \
	(1u << 1)		       /* the DP has work queued or running */
#define RDC_CHIP_STATE_GAMMA (1u << 2) /* CONTROL.GAMMA_EN in force */

struct rdc_chip_state {
	__u64 now;	   /* simulated time, core cycles */
	__u64 frame_start; /* line 0 of the frame being scanned (now: none) */
	__u64 frame_count; /* RDC_REG_FRAME_COUNT, all 64 bits */
	__u64 busy;	   /* RDC_REG_PERF_* */
	__u64 stall;
	__u64 pixels;
	__u32 cmds;
	__u32 last_cycles;
	__u32 last_opcode;
	__u32 culled;
	__u32 fence;	  /* RDC_REG_FENCE */
	__u32 irq_status; /* RDC_REG_IRQ_STATUS */
	__u32 err_code;	  /* RDC_REG_ERR_CODE */
	__u32 err_info;	  /* RDC_REG_ERR_INFO */
	__u32 open_row;	  /* the DRAM row the bus has open */
	/*
	 * What the CRTC has in force, latched at the last vblank: the
	 * registers read what was written for the next one.
	 */
	__u32 h_total;
	__u32 h_display;
	__u32 h_sync_start;
	__u32 h_sync_end;
	__u32 v_total;
	__u32 v_display;
	__u32 v_sync_start;
	__u32 v_sync_end;
	__u32 pixclk_khz;
	__u32 crtc_flags;
	__u32 fb_base;
	__u32 fb_stride;
	__u32 fb_format;
	__u32 cursor_ctrl;
	__u32 cursor_base;
	__u32 raster_base;
	__u32 raster_ctrl;
	__u32 flags;	/* out: RDC_CHIP_STATE_* */
	__u32 reserved; /* 0 */
};

#endif /* RDC_STATE_UAPI_H */
