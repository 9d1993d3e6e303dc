#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The DisplayLink personality (docs/usb.md): rdcd --listen udl: behind a
# gadget with DisplayLink's IDs on dummy_hcd, driven by Linux's own udl
# DRM driver.  udl binds, reads the EDID (the RDC-1's presets, 1024x768
# first), and its card offers exactly those modes (sysfs, modetest);
# drm_pattern sets 640x480, 800x600 and 1024x768 with a known pattern and
# rdcd's frame (read by an observer) equals it in RGB565 exactly; a
# damaged rectangle changes only itself, for far fewer bytes; the
# full-screen and 64x64 update rates as figures.  (Kept short for CI:
# unplug under load is usb-unplug's and usb-hostile's, on the same
# FunctionFS plumbing.)
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
# vm-module: udl
. "$RDC_TREE/tests/vm/lib.sh"
echo "# guest uptime at the start: $(cut -d' ' -f1 /proc/uptime) s"

usb_require
udl_vars
[ -x "$DRMP" ] || { echo "drm_pattern is not built (no libdrm-dev?)"; exit 77; }
command -v modetest >/dev/null || { echo "modetest missing (libdrm-tests)"; exit 77; }
# the presets udl can use (docs/usb.md: not 320x200)
PRESETS="640x480 800x600 1024x768 1280x720 1920x1080"

# udlfb claims the same IDs: it must not be the one that binds
check "udlfb is not loaded (udl, not udlfb, drives the device)" \
	sh -c '! grep -q "^udlfb " /proc/modules'

dmesg -c >/dev/null 2>&1
check "the gadget (DisplayLink IDs) enumerates" udl_up
lsusb -v -d $USB_VID:$USB_PID >"$T/lsusb.txt" 2>&1
check "lsusb: vendor interface 255/0/0, bulk OUT endpoint 0x01" sh -c '
	grep -Eq "bInterfaceClass +255" "$1" &&
	grep -Eq "bInterfaceSubClass +0" "$1" &&
	grep -Eq "bInterfaceProtocol +0" "$1" &&
	grep -Eq "bEndpointAddress +0x01 +EP 1 OUT" "$1" ||
	{ grep -E "bEndpointAddress|Interface" "$1"; false; }' sh "$T/lsusb.txt"
check "udl binds and its connector is connected" udl_card 60
check "the card has a node in /dev/dri" test -c "/dev/dri/$(basename "$CARD")"
modetest -M udl -c >"$T/modetest.txt" 2>&1
# mode names as modetest lists them ("  #0 1024x768 60.00 ..."), in order
awk '$1 ~ /^#[0-9]+$/ && $2 ~ /^[0-9]+x[0-9]+$/ { print $2 }' \
	"$T/modetest.txt" >"$T/modes.txt"
check "modetest -M udl -c: connected, the RDC-1's presets, 1024x768 first" sh -c '
	grep -E "[[:space:]]connected[[:space:]]" "$1" || exit 1
	tr "\n" " " <"$2"; echo
	[ "$(head -n 1 "$2")" = 1024x768 ] &&
	[ "$(sort -u "$2" | tr "\n" " ")" = "$(printf "%s\n" $3 | sort | tr "\n" " ")" ]' \
	sh "$T/modetest.txt" "$T/modes.txt" "$PRESETS"
# what 6.1's udl logs when the vendor descriptor is stalled (docs/usb.md)
dmesg >"$T/dmesg1.txt" 2>&1
check "dmesg: nothing but the documented vendor-descriptor lines" sh -c '
	grep -Ei "udl|drm|usb" "$1" | sed "s/^/    /"
	! grep -Ei "error|warn|oops|bug|call trace|fail" "$1" |
	  grep -Ev "Unrecognized vendor firmware descriptor|vendor descriptor length"' \
	sh "$T/dmesg1.txt"

# 640x480 (the first of the two DRM offers, docs/usb.md; udl-loop takes the
# other) also gives the figures: full-screen and 64x64 update rates
check "drm_pattern 640x480: the RDC-1's frame is the pattern in RGB565" \
	"$DRMP" --uri "$OBS" --mode 640x480 --bench 2
grep '^# bench' "$T/check.out"
check "drm_pattern 800x600: the RDC-1's frame is the pattern in RGB565" \
	"$DRMP" --uri "$OBS" --mode 800x600
check "drm_pattern 1024x768, then a 40x30 rectangle: exact, few bytes" \
	"$DRMP" --uri "$OBS" --mode 1024x768 --rect 300,200,40,30
grep '^#' "$T/check.out"

check "the gadget goes down cleanly" usb_gadget_down
echo "# guest uptime at the end: $(cut -d' ' -f1 /proc/uptime) s"
finish
