#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# librdc's usb: backend against rdcd --stepped behind a USB gadget on
# dummy_hcd: `rdcctl list` finds the device (bus/port path, IDs, serial)
# and every URI form reaches it; then the conformance suite of
# tests/unit/test_net_conform.c, built as a VM program and given
# RDC_CONFORM_URI=usb:, sees over USB exactly what it sees on sim: (the
# API scenario: frames, cycle counts, counters, registers, errors; and
# every golden scene: frame CRC, cycles per command class, readback CRC,
# simulated time).  rdcctl list also finds rdcd's socket where it looks by
# default.
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
. "$RDC_TREE/tests/vm/lib.sh"

CONFORM=$B/test_net_conform
usb_require
"$RDCCTL" --connect usb:fffe:fffd regs 2>&1 | grep -q "not supported" &&
	{ echo "librdc is built without libusb-1.0: no usb: backend"; exit 77; }
[ -x "$CONFORM" ] || { echo "$CONFORM is not built"; exit 77; }

check "the gadget enumerates (rdcd --stepped on ffs:)" usb_gadget_up
# The API scenario wants the chip as rdcd starts it: first thing.
cd "$RDC_TREE" || exit 1
check "conformance: API scenario over usb: = sim:" \
	env RDC_CONFORM_URI=usb: "$CONFORM" test_conform_api
"$RDCCTL" list >"$T/list.txt" 2>&1
path=$(sed -n 's/^usb:\([0-9][-0-9.]*\) .*/\1/p' "$T/list.txt" | head -n 1)
check "rdcctl list: usb:BUS-PORT with 1209:0001 and the serial" sh -c '
	cat "$1"; grep -Eq "^usb:$2 +USB 1209:0001 .*serial $3\$" "$1"' \
	sh "$T/list.txt" "${path:-none}" "$USB_SERIAL"
# rdcd's socket seen where rdcctl looks by default
mkdir -p "$T/xdg/rdc" && ln -sf "$USB_SOCK" "$T/xdg/rdc/rdc.sock"
check "rdcctl list: an rdcd socket in the default directory" sh -c '
	XDG_RUNTIME_DIR=$2 "$1" list | grep -E "^unix:$2/rdc/rdc.sock +rdcd socket, stepped"' \
	sh "$RDCCTL" "$T/xdg"
for uri in "usb:$path" "usb:1209:0001" "usb:serial=$USB_SERIAL"; do
	check "rdcctl --connect $uri regs" sh -c \
		'"$1" --connect "$2" regs | grep -E "VRAM_SIZE +0x01000000"' \
		sh "$RDCCTL" "$uri"
done
check "a wrong serial is not taken" sh -c \
	'! "$1" --connect usb:serial=no-such-serial regs' sh "$RDCCTL"
check "conformance: every golden scene over usb: = sim:" \
	env RDC_CONFORM_URI=usb: "$CONFORM" test_conform_scenes
check "rdcd still running" usb_rdcd_alive
check "rdcd and the gadget go down cleanly (rdcd exits 0)" usb_gadget_down
finish
