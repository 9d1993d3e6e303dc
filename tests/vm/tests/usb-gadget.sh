#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The RDC-1 as a USB device: rdcd --listen ffs: behind a configfs gadget on
# dummy_hcd enumerates on the guest's own bus with rdc_usb.h's identity
# (lsusb -v: class, endpoints, strings, serial); usb_raw, written against
# libusb alone, talks the protocol over bulk OUT/IN, gets an interrupt
# event on the interrupt endpoint, uses the INFO and RESET requests, and
# measures round trips (figures as comments, not conditions).  rdcd exits
# cleanly on SIGTERM with its bridge threads.
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
. "$RDC_TREE/tests/vm/lib.sh"

RAW=$B/usb_raw
usb_require
[ -x "$RAW" ] || { echo "usb_raw is not built (no libusb-1.0?)"; exit 77; }
command -v lsusb >/dev/null || { echo "lsusb missing (usbutils)"; exit 77; }
RAW="$RAW --serial $USB_SERIAL"

check "the gadget enumerates (rdcd on ffs:, bound to the first UDC)" \
	usb_gadget_up --mode 640x480
lsusb -v -d $USB_VID:$USB_PID >"$T/lsusb.txt" 2>&1
# lsusb_has PATTERN: the verbose listing has a line matching PATTERN
lsusb_has() {
	grep -Eq "$1" "$T/lsusb.txt" || { echo "no line matching: $1"; false; }
}
check "lsusb: interface class 255/0x52/1" sh -c '
	grep -Eq "bInterfaceClass +255" "$1" &&
	grep -Eq "bInterfaceSubClass +82" "$1" &&
	grep -Eq "bInterfaceProtocol +1" "$1" &&
	grep -Eq "bNumEndpoints +3" "$1"' sh "$T/lsusb.txt"
check "lsusb: bulk OUT and bulk IN of 512 bytes (high speed)" sh -c '
	awk "/bEndpointAddress/ { a = \$2 \" \" \$5 }
	     /Transfer Type/ { t = \$3 }
	     /wMaxPacketSize/ { print a, t, \$2 }" "$1" >"$1.eps"
	cat "$1.eps"
	grep -Eq "^0x0[1-9a-f] OUT Bulk 0x0200" "$1.eps" &&
	grep -Eq "^0x8[1-9a-f] IN Bulk 0x0200" "$1.eps"' sh "$T/lsusb.txt"
check "lsusb: interrupt IN of 64 bytes, every 1 ms" sh -c '
	grep -Eq "^0x8[1-9a-f] IN Interrupt 0x0040" "$1.eps" &&
	grep -Eq "bInterval +4" "$1"' sh "$T/lsusb.txt"
check "lsusb: strings and serial" sh -c '
	grep -Eq "idVendor +0x1209" "$1" && grep -Eq "idProduct +0x0001" "$1" &&
	grep -Eq "iProduct +[0-9]+ RDC-1" "$1" &&
	grep -Eq "iInterface +[0-9]+ RDC-1 display controller" "$1" &&
	grep -Eq "iSerial +[0-9]+ $2\$" "$1"' sh "$T/lsusb.txt" "$USB_SERIAL"
check "usb_raw: descriptors" $RAW descriptors
check "usb_raw: INFO, RESET, HELLO, PING, REG_READ, REG_WRITE" $RAW basic
check "usb_raw: an interrupt event on the interrupt endpoint" $RAW irq
check "usb_raw: RESET drops a half request, unknown requests stall" $RAW reset
check "usb_raw: replies of whole packets still end the host's read" $RAW zlp
check "usb_raw: round trips (figures below)" $RAW bench 300
grep '^# usb' "$T/check.out"
check "rdcd still running" usb_rdcd_alive

# SIGTERM while a host streams frames: the bridge threads stop mid-transfer
$RAW hostile frames 60 >"$T/frames.log" 2>&1 &
raw=$!
check "a host steps the clock and reads frames" \
	usb_wait_log "$T/frames.log" stepping 20
sleep 1
check "SIGTERM to rdcd mid-stream: it exits 0" usb_rdcd_stop
check "the device leaves the bus with it" usb_wait gone 10
check "the host program sees it go" wait $raw
sed 's/^/    /' "$T/frames.log"
check "the gadget goes down cleanly" usb_gadget_down
check "no functionfs mount is left" sh -c '! grep functionfs /proc/mounts'

# A question about the kernel, not rdcd (docs/usb.md): does a 0-byte
# write() to a FunctionFS endpoint send a zero-length packet?
check "a probe gadget (0x1209:0x0002) with a device side of usb_raw's own" \
	"$GADGET" up --name zlp --dir /dev/ffs-zlp --pid 0x0002 --serial zlp
"$B/usb_raw" ffs-zlp /dev/ffs-zlp >"$T/zlpdev.log" 2>&1 &
zdev=$!
check "  ... bound" "$GADGET" bind --name zlp
check "  ... read by the host" "$B/usb_raw" --pid 0002 zlp-probe
grep '^# finding' "$T/check.out"
check "  ... the device side wrote 512, 0 and 100 bytes" wait $zdev
sed 's/^/    /' "$T/zlpdev.log"
check "  ... removed" "$GADGET" down --name zlp

# docs/usb.md's recipe: rdc-gadget.sh starting rdcd itself, and stopping it
USB_SERIAL=recipe
check "rdc-gadget.sh up --rdcd: rdcd started, gadget bound" \
	"$GADGET" up --name recipe --serial recipe --rdcd "$B/rdcd" -- --stepped
check "  ... the host sees it" usb_wait present 20
check "  ... and talks to it" $B/usb_raw --serial recipe basic
check "  ... status" "$GADGET" status --name recipe
check "  ... down: unbound, rdcd stopped, nothing left" \
	"$GADGET" down --name recipe
check "  ... the device is gone" usb_wait gone 10
check "  ... and no rdcd runs on it" \
	sh -c '! grep -qs "ffs:/dev/ffs-recip[e]" /proc/[0-9]*/cmdline'
[ -z "${USB_CONFIGFS:-}" ] || umount /sys/kernel/config 2>/dev/null
finish
