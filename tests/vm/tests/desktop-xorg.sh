#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Xorg's modesetting driver (Debian's xserver-xorg-core; glamor off, a
# shadow framebuffer) runs on rdcdrm's card unchanged: an X client draws,
# `xwd -root` equals the chip's scanned-out frame pixel for pixel with
# the chip's hardware cursor laid over it, the cursor X sets (a 16x16
# red square, hot spot at its corner) is where X put the pointer (the
# screen's centre) and shows in red in the frame, and the server exits
# cleanly, after which rdcdrm unloads.
# vm-module: rdcdrm
# vm-module: overlay
. "$RDC_TREE/tests/vm/lib.sh"
. "$RDC_TREE/tests/vm/desktop.sh"

CARD=$(desktop_card) || { echo "# no card of rdcdrm's"; exit 1; }
desktop_run_tmpfs
check "Xorg starts on $CARD" xorg_start
# A root window pattern and a cursor of our own, both known.
printf '#define c_width 16\n#define c_height 16\n#define c_x_hot 0\n#define c_y_hot 0\nstatic unsigned char c_bits[] = {\n%s};\n' \
	"$(i=0; while [ $i -lt 32 ]; do printf '0xff, '; i=$((i + 1)); done)" \
	>$T/cursor.xbm
check "xsetroot draws the root window and sets the cursor" \
	xsetroot -mod 4 4 -fg '#2060c0' -bg '#f0d040' \
	-cursor $T/cursor.xbm $T/cursor.xbm
check "xsetroot sets the cursor colours" \
	xsetroot -cursor $T/cursor.xbm $T/cursor.xbm -fg red -bg blue
xeyes -geometry 200x150+40+40 >$T/xeyes.out 2>&1 &
CLIENT=$!
sleep 4
check "xeyes is still showing" kill -0 $CLIENT
SIZE=$(xdpyinfo | sed -n 's/^ *dimensions: *\([0-9]*\)x\([0-9]*\) pixels.*/\1 \2/p')
set -- $SIZE
W=$1
H=$2
echo "# screen ${W}x$H"
check "xwd -root dumps the screen" sh -c "xwd -root -silent >$T/root.xwd"
check "the screen with the chip's cursor over it equals the chip's frame" \
	"$FRAME_CHECK" --uri "drm:$CARD" --cursor-at $((W / 2)),$((H / 2)) \
	$T/root.xwd
check "the cursor shows in red where X put it" \
	"$FRAME_CHECK" --uri "drm:$CARD" --expect-rect \
	$((W / 2)),$((H / 2)),16,16,ff0000
kill $CLIENT 2>/dev/null
check "Xorg exits cleanly" desktop_stop
check "rdcdrm unloads afterwards" rmmod rdcdrm
[ $failed -eq 0 ] || desktop_logs
desktop_cleanup
finish
