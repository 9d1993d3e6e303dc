#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Figures only (docs/usb.md, "Tests and figures"): the DisplayLink
# personality driven by Linux's udl through dummy_hcd, rdcd paced.  For
# 640x480 and 1024x768: full-screen updates and 64x64 updates in a row
# (drm_pattern --bench), each set ending with the frame checked exactly;
# updates a second, bytes on the bus and the RDC-1's DP busy and
# simulated cycles per update, as TAP comments.
#   RDC_VM_TESTS=udl-bench tests/vm/run.sh BUILD
# vm-bench
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
# vm-module: udl
. "$RDC_TREE/tests/vm/lib.sh"

usb_require
udl_vars
[ -x "$DRMP" ] || { echo "drm_pattern is not built (no libdrm-dev?)"; exit 77; }
N=10

udl_ready() {
	udl_up && udl_card 60
}
check "the gadget enumerates and udl's connector is connected" udl_ready
for m in 640x480 1024x768; do
	check "$m: $N full-screen and $((10 * N)) 64x64 updates, the last exact" \
		"$DRMP" --uri "$OBS" --mode $m --bench "$N"
	grep '^# bench' "$T/check.out"
done
check "the gadget goes down cleanly" usb_gadget_down
finish
