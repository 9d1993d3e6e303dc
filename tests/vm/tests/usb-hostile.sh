#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# A hostile or careless USB host against rdcd's ffs: listener, while a
# UNIX-socket client of the same rdcd asks PING and REG_READ all along:
# truncated requests, a 4 GiB length, random bytes on bulk OUT, frames
# subscribed with bulk IN never read, a host gone mid-message, an unplug
# (UDC unbound) during a 1 MiB SUBMIT and during a frame subscription.
# After each, a new USB session (RESET, HELLO, ...) works; rdcd stays up,
# the socket client gets every answer right, and rdcd exits 0 on SIGTERM
# while a host streams frames (under ASan and UBSan when the build has
# san/rdcd: no leak, no bad access in the bridge threads).
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
[ -x "$RDC_BUILD/san/rdcd" ] && USB_RDCD=$RDC_BUILD/san/rdcd
. "$RDC_TREE/tests/vm/lib.sh"

RAW=$B/usb_raw
usb_require
[ -x "$RAW" ] || { echo "usb_raw is not built (no libusb-1.0?)"; exit 77; }
echo "# rdcd: $USB_RDCD"
RAWS="$RAW --serial $USB_SERIAL"

then_new_session() {
	check "  ... then a new USB session works" $RAWS basic
}

check "the gadget enumerates" usb_gadget_up --mode 640x480
rm -f "$T/stop-watch"
"$RAW" watch "$USB_SOCK" "$T/stop-watch" >"$T/watch.log" 2>&1 &
watch=$!
check "a USB session works" $RAWS basic

check "a truncated request: no reply, nothing else happens" \
	$RAWS hostile truncated
then_new_session
check "a 4 GiB length: TOOBIG, then the session stalls" \
	$RAWS hostile oversize
then_new_session
check "64 KiB of random bytes on bulk OUT" $RAWS hostile random
then_new_session
check "frames subscribed, 30 frames made, bulk IN never read" \
	$RAWS hostile stall-frames 2
then_new_session
check "the host goes away in the middle of a request" \
	$RAWS hostile exit-mid-message
then_new_session

$RAWS hostile long-submit 60 >"$T/submit.log" 2>&1 &
raw=$!
check "a 1 MiB SUBMIT under way" usb_wait_log "$T/submit.log" submitting 20
sleep 1
check "unplugged during the SUBMIT" usb_unplug
check "  ... the host program sees the device go" wait $raw
sed 's/^/    /' "$T/submit.log"
check "  ... replugged" usb_replug
then_new_session

$RAWS hostile frames 60 >"$T/frames.log" 2>&1 &
raw=$!
check "a frame subscription under way" usb_wait_log "$T/frames.log" stepping 20
sleep 2
check "unplugged during the subscription" usb_unplug
wait $raw
sed 's/^/    /' "$T/frames.log"
check "  ... replugged" usb_replug
then_new_session

touch "$T/stop-watch"
check "the socket client got every answer right throughout" wait $watch
sed 's/^/    /' "$T/watch.log"
check "rdcd still running" usb_rdcd_alive

$RAWS hostile frames 60 >"$T/frames2.log" 2>&1 &
raw=$!
check "a host streams frames again" usb_wait_log "$T/frames2.log" stepping 20
sleep 1
check "SIGTERM mid-stream: rdcd exits 0, its threads stopped mid-transfer" \
	usb_rdcd_stop
wait $raw
check "the gadget goes down cleanly" usb_gadget_down
finish
