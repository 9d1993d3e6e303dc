#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# KMS conformance of rdcdrm.ko's card: each subtest of kms_conform
# (tests/vm/kms_conform.c, libdrm) is one line here, its own checks
# below it: TEST_ONLY commits accepted and refused as the KMS uAPI
# documents; 300 legacy, 300 atomic and 300 damage-clipped atomic page
# flips with an event each, no frame torn, one flip latched an event and
# DRM's vblank count moving with the chip's frames (the vblanks missed
# are a figure: on the paced clock they depend on this machine's speed);
# vblank waits and
# CRTC sequences; the ARGB cursor composited as the chip documents it;
# gamma ramps, GAMMA_LUT and C8 through the CLUT; debugfs CRCs against the
# FRAME ioctl's; damage clips cheaper than full updates; bad input refused
# with the card working after.  Every frame compared is the chip's own.
# vm-module: rdcdrm
. "$RDC_TREE/tests/vm/lib.sh"

KC=$B/kms_conform
[ -x "$KC" ] || { echo "kms_conform is not built (no libdrm?)"; exit 77; }
# the console would draw on the card between the subtests' commits
fbcon_unbind
grep -q debugfs /proc/mounts ||
	mount -t debugfs debugfs /sys/kernel/debug 2>/dev/null
[ -n "$(ls /dev/dri/card* 2>/dev/null)" ] ||
	{ echo "no /dev/dri/card*"; exit 1; }
for t in $("$KC" --list); do
	check "kms_conform $t" "$KC" "$t"
done
finish
