#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Figures, not conditions: bench/net_bench --uri against one rdcd --fast
# in this guest, over its UNIX socket and over USB (dummy_hcd): small
# commands submitted per second, register-read round trip, 1024x768
# frames per second received in each encoding, and the bytes a frame
# takes in each encoding with the rate USB 2.0 high speed (35-40 MB/s in
# practice) would carry.  Printed as TAP comments; only "it ran" is
# checked.  `make bench-usb` runs this test alone; the suite leaves it
# out unless RDC_VM_TESTS names it.
# vm-bench
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
. "$RDC_TREE/tests/vm/lib.sh"

BENCH=$B/net_bench
usb_require
"$RDCCTL" --connect usb:fffe:fffd regs 2>&1 | grep -q "not supported" &&
	{ echo "librdc is built without libusb-1.0: no usb: backend"; exit 77; }
[ -x "$BENCH" ] || { echo "$BENCH is not built"; exit 77; }

check "the gadget enumerates (rdcd --fast on ffs: and unix:)" \
	usb_gadget_up --fast
for uri in "unix:$USB_SOCK" usb:; do
	check "net_bench --uri ${uri%%:*}:" "$BENCH" --uri "$uri"
	sed 's/^/# /' "$T/check.out"
done
check "rdcd and the gadget go down cleanly (rdcd exits 0)" usb_gadget_down
finish
