#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# cage (Debian's, on wlroots, pixman renderer) runs one client full
# screen on rdcdrm's card unchanged: grim's screenshot (wlroots'
# screencopy) equals the chip's scanned-out frame pixel for pixel, and
# cage exits cleanly, after which rdcdrm unloads.
# vm-module: rdcdrm
# vm-module: overlay
. "$RDC_TREE/tests/vm/lib.sh"
. "$RDC_TREE/tests/vm/desktop.sh"

CARD=$(desktop_card) || { echo "# no card of rdcdrm's"; exit 1; }
desktop_run_tmpfs
check "cage starts on $CARD with weston-flower" cage_start weston-flower
sleep 5
check "cage is still running" kill -0 $DESKTOP_PID
check "grim takes cage's picture" as_nobody grim $T/cage.png
check "grim's screenshot equals the chip's frame" \
	"$FRAME_CHECK" --uri "drm:$CARD" $T/cage.png
check "cage exits cleanly with its client" desktop_stop weston-flower
seatd_stop
check "rdcdrm unloads afterwards" rmmod rdcdrm
[ $failed -eq 0 ] || desktop_logs
desktop_cleanup
finish
