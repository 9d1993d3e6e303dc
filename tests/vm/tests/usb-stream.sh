#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Frames over USB: a scene drawn through usb: on rdcd behind a USB gadget,
# then `rdcctl --connect usb: stream --v4l2 /dev/video0` takes the frames
# over the bulk endpoints into v4l2loopback: our reader and ffmpeg get the
# simulator's frames exactly, at the mode's interval, as rdcd-v4l2.sh
# checks for rdcd's own sink.  Interrupt events come through the
# interrupt endpoint to rdc_event_next.
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$B/usb_tool
usb_require
"$RDCCTL" --connect usb:fffe:fffd regs 2>&1 | grep -q "not supported" &&
	{ echo "librdc is built without libusb-1.0: no usb: backend"; exit 77; }
[ -x "$TOOL" ] || { echo "$TOOL is not built"; exit 77; }
scene=$SCENES/stream_a.rdl

check "the gadget enumerates (rdcd --stepped on ffs:)" usb_gadget_up
check "interrupt events through the interrupt endpoint" "$TOOL" irq usb:
check "the scene drawn through usb:" "$RDCCTL" --connect usb: run "$scene"
writer_start --from usb:
check "the device gets a format" wait_device 60
check "own reader: 30 exact frames, mode's interval" \
	"$READ" --device "$DEV" --expect "$scene" --frames 30 --settle \
	--check-rate --timeout 120
check "ffmpeg -f v4l2: 10 exact frames" ffmpeg_frames bgr32 "$scene" 10
check "rdcctl stream over usb: still running" writer_alive
writer_stop
check "rdcd still running" usb_rdcd_alive
check "rdcd and the gadget go down cleanly (rdcd exits 0)" usb_gadget_down
finish
