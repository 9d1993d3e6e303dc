#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The standard fbdev ioctls on rdcfb's /dev/fb0 as fbdev clients use them
# (every preset in 8 bpp indexed, RGB565 and XRGB8888; colour map, pan,
# vsync, blank, the mapping), checked against the chip's registers and
# its frames by fbdev_ioctl; then Debian's fbset reads the mode and sets
# others, and FBIOGET_VSCREENINFO shows them.
# vm-module: rdcfb clock=stepped
. "$RDC_TREE/tests/vm/lib.sh"

IOCTL=$B/fbdev_ioctl
FB=/dev/fb0


# fbset -i shows the geometry FBIOGET_VSCREENINFO has
fbset_reads() {
	cur=$("$IOCTL" --device $FB --get) || return 1
	fbset -fb $FB -i >"$T/fbset.out" 2>&1 || { cat "$T/fbset.out"; return 1; }
	cat "$T/fbset.out"
	x=${cur%%x*}
	rest=${cur#*x}
	y=${rest%-*}
	bpp=${cur##*-}
	echo "FBIOGET_VSCREENINFO: $cur"
	grep -Eq "geometry $x $y [0-9]+ [0-9]+ $bpp\$" "$T/fbset.out" &&
		grep -q "Name *: rdcfb" "$T/fbset.out"
}

# fbset_mode PRESET BPP WxH-BPP: fbset sets the preset's mode from a mode
# file; FBIOGET_VSCREENINFO then shows it
fbset_mode() {
	"$IOCTL" --fbset-mode "$1" "$2" >"$T/rdc.modes" || return 1
	cat "$T/rdc.modes"
	fbset -fb $FB -db "$T/rdc.modes" rdc || return 1
	got=$("$IOCTL" --device $FB --get)
	echo "FBIOGET_VSCREENINFO: $got"
	[ "$got" = "$3" ]
}

# fbset_depth BPP WxH-BPP: only the depth changes
fbset_depth() {
	fbset -fb $FB -depth "$1" || return 1
	got=$("$IOCTL" --device $FB --get)
	echo "FBIOGET_VSCREENINFO: $got"
	[ "$got" = "$2" ]
}

fbcon_unbind
[ -c $FB ] || { echo "no $FB"; exit 1; }
check "fbdev_ioctl: the standard ioctls (TAP below)" "$IOCTL" --device $FB
check "fbset -i reads the mode" fbset_reads
check "fbset sets 800x600 RGB565 from a mode file" fbset_mode 2 16 800x600-16
check "fbset -depth 32 keeps 800x600" fbset_depth 32 800x600-32
check "fbset sets 640x480 8 bpp from a mode file" fbset_mode 1 8 640x480-8
check "fbset -i reads that" fbset_reads
check "fbset sets 1024x768 XRGB8888" fbset_mode 3 32 1024x768-32
finish
