#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Unplugging an RDC-1 on USB: the gadget's UDC is unbound during a long
# submit and during a frame subscription through usb:.  The host side gets
# RDC_E_GONE ("device gone"), then at once for every later call, within a
# bound (no hang: the program is killed if it overstays); rdcd keeps
# serving its socket clients; binding the UDC again lets a new usb: open
# work.  The tool is the ASan+UBSan build: a leak or a memory error on
# the way out of a vanished device fails it.
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$RDC_BUILD/san/usb_tool
BOUND=60 # seconds a host call may take to notice the device left
usb_require
"$RDCCTL" --connect usb:fffe:fffd regs 2>&1 | grep -q "not supported" &&
	{ echo "librdc is built without libusb-1.0: no usb: backend"; exit 77; }
[ -x "$TOOL" ] || { echo "$TOOL is not built"; exit 77; }

# wait_line FILE PATTERN SECONDS
wait_line() {
	i=0
	while ! grep -q "$2" "$1" 2>/dev/null; do
		[ $i -ge $(($3 * 10)) ] && return 1
		sleep 0.1
		i=$((i + 1))
	done
}

# unplug_during MODE READY: run usb_tool MODE usb:, unplug once it printed
# READY, and expect it to end with RDC_E_GONE within $BOUND seconds.
unplug_during() {
	"$TOOL" "$1" usb: >"$T/tool.out" 2>&1 &
	tool=$!
	if ! wait_line "$T/tool.out" "$2" 120; then
		echo "never got to: $2"
		kill $tool 2>/dev/null
		wait $tool
		cat "$T/tool.out"
		return 1
	fi
	sleep 1
	t0=$(date +%s)
	usb_unplug || echo "(the bus did not report the device gone)"
	i=0
	while kill -0 $tool 2>/dev/null && [ $i -lt $((BOUND * 10)) ]; do
		sleep 0.1
		i=$((i + 1))
	done
	if kill -0 $tool 2>/dev/null; then
		echo "still waiting $BOUND s after the unplug: killed"
		kill -9 $tool
	fi
	wait $tool
	rc=$?
	echo "# usb $1: the program ended $(($(date +%s) - t0)) s after the unplug began"
	cat "$T/tool.out"
	[ $rc -eq 0 ] && grep -q 'device gone' "$T/tool.out"
}

unix_serves() {
	"$RDCCTL" --connect "unix:$USB_SOCK" regs | grep VRAM_SIZE
}

check "the gadget enumerates (rdcd --stepped on ffs:)" usb_gadget_up
check "unplugged during a long submit: device gone" \
	unplug_during submit submitting
check "rdcd still running" usb_rdcd_alive
check "rdcd still serves its socket" unix_serves
check "the UDC bound again: the device is back" usb_replug
check "a new usb: open works" sh -c '"$1" --connect usb: regs | grep VRAM_SIZE' \
	sh "$RDCCTL"
check "unplugged during a frame subscription: device gone" \
	unplug_during frames "frames flowing"
check "rdcd still running" usb_rdcd_alive
check "rdcd still serves its socket" unix_serves
check "the UDC bound again: the device is back" usb_replug
check "a new usb: open works" sh -c '"$1" --connect usb: regs | grep VRAM_SIZE' \
	sh "$RDCCTL"
check "rdcd and the gadget go down cleanly (rdcd exits 0)" usb_gadget_down
finish
