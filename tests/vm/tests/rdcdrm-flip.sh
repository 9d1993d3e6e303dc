#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Page flips on rdcdrm.ko's stepped clock, where wall time plays no part
# and each commit runs the chip to the vblank that latches it: 300
# legacy, 300 atomic and 300 damage-clipped atomic flips with events, each
# at the vblank after the one before (0 missed), no frame torn, one flip
# latched an event, DRM's vblank count and the chip's frame counter
# moving together; then the primary plane off with the CRTC on (a black
# screen, frames going on) and on again.  The paced clock's flips are in
# rdcdrm-kms, where missed vblanks are a figure of this machine's speed.
# vm-module: rdcdrm clock=stepped
. "$RDC_TREE/tests/vm/lib.sh"

KC=$B/kms_conform
[ -x "$KC" ] || { echo "kms_conform is not built (no libdrm?)"; exit 77; }
# the console would draw on the card between the subtests' commits
fbcon_unbind
[ -n "$(ls /dev/dri/card* 2>/dev/null)" ] ||
	{ echo "no /dev/dri/card*"; exit 1; }
for t in flip-legacy flip-atomic flip-damage primary-off; do
	check "kms_conform $t (stepped clock)" "$KC" "$t"
done
finish
