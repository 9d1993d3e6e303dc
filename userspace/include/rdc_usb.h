/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The RDC-1 as a USB device: identifiers, the interface layout and the
 * vendor control requests, shared by the device side (rdcd's FunctionFS
 * listener, userspace/rdcd/ffs.c) and the host side (librdc's usb:
 * backend on libusb, userspace/lib/usb.c).  docs/usb.md describes the
 * framing in prose; this header is the definition.
 *
 * One vendor-specific interface (class 0xff) with three endpoints:
 *
 *   bulk OUT       requests: the byte stream of rdc_proto.h messages, as
 *                  on a socket.  The host may split and join messages
 *                  across transfers freely; a transfer whose length is a
 *                  multiple of wMaxPacketSize ends with a zero-length
 *                  packet, so the device's read completes.
 *   bulk IN        replies and frame events: the same byte stream.  The
 *                  device never ends a write on a full packet (it sends
 *                  the last byte of such a chunk as a write of its own), so
 *                  every host transfer of any size completes on a short
 *                  packet and no reply waits for more data.
 *   interrupt IN   interrupt events: each RDC_MSG_EV_IRQ message (header
 *                  and payload, RDC_USB_EVENT_SIZE bytes) in one transfer.
 *                  They never appear on bulk IN.
 *
 * When the daemon ends the conversation itself (a fatal protocol error,
 * answered as on a socket), the device halts both bulk endpoints after
 * its last reply; the host recovers with RDC_USB_REQ_RESET.
 */
#ifndef RDC_USB_H
#define RDC_USB_H

#include <stdint.h>

/*
 * pid.codes (https://pid.codes), the open-source VID pool: 0x1209 with a
 * test PID, for development and testing only.  Both sides take others
 * (rdc-gadget.sh --vid/--pid, usb:VID:PID).
 */
#define RDC_USB_VID 0x1209u
#define RDC_USB_PID 0x0001u

#define RDC_USB_CLASS	 0xffu /* vendor specific */
#define RDC_USB_SUBCLASS 0x52u /* 'R' */
#define RDC_USB_PROTOCOL 0x01u /* this framing, over rdc_proto.h v1 */

/* Max packet sizes the device declares. */
#define RDC_USB_BULK_FS		 64u
#define RDC_USB_BULK_HS		 512u
#define RDC_USB_INTR_MAXP	 64u
#define RDC_USB_INTR_INTERVAL_FS 1u /* frames (1 ms) */
#define RDC_USB_INTR_INTERVAL_HS 4u /* 2^(4-1) microframes = 1 ms */

/* An RDC_MSG_EV_IRQ message: 16-byte header, u32 status bits, u64 time. */
#define RDC_USB_EVENT_SIZE 28u

/*
 * Vendor requests: bmRequestType vendor, recipient interface (0x41 OUT /
 * 0xc1 IN), wIndex the interface number.  The device answers them with
 * recipient device (0x40 OUT / 0xc0 IN, wIndex ignored) as well.  Other
 * requests to the interface stall.
 */
enum rdc_usb_request {
	/*
	 * OUT, no data: end the session.  The device drops what it holds of
	 * the current connection (a half-received request, queued replies
	 * and events, control of the device) and starts a new one; the host
	 * then clears its halts, drains the IN endpoints and sends HELLO
	 * again.  How a host resynchronises after a stall or a timeout.
	 */
	RDC_USB_REQ_RESET = 0x01,
	/* IN, RDC_USB_INFO_SIZE bytes: struct rdc_usb_info, little-endian. */
	RDC_USB_REQ_INFO = 0x02,
};

/*
 * The answer to RDC_USB_REQ_INFO: u32 magic (RDC_PROTO_MAGIC), u32 the
 * protocol version, u32 the largest request payload the device accepts,
 * u32 the device's session number (bumped by every RESET and every new
 * configuration).
 */
#define RDC_USB_INFO_SIZE 16u

#endif /* RDC_USB_H */
