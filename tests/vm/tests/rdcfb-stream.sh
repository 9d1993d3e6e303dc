#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The kernel device streamed to v4l2loopback in the same guest:
# `rdcctl stream --from fbdev:/dev/fb0 --v4l2 /dev/video0` while scenes are
# drawn through fbdev: by another client; our reader gets each scene's
# picture exactly (CRC for CRC against the simulator's own frame), and
# follows a second scene with a mode change drawn while streaming.
# vm-module: rdcfb
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

FB=/dev/fb0


fbcon_unbind
[ -c $FB ] || { echo "no $FB"; exit 1; }
[ -c "$DEV" ] || { echo "no $DEV"; exit 1; }
a=$SCENES/stream_a.rdl
b=$SCENES/stream_b.rdl
check "scene a drawn through fbdev:" "$RDCCTL" --connect "fbdev:$FB" run "$a"
writer_start --from "fbdev:$FB" --format bgr32
check "the stream from fbdev: gives the device a format" wait_device 60
check "own reader: 30 frames of scene a, exact" \
	"$READ" --device "$DEV" --expect "$a" --frames 30 --settle --timeout 60
check "ffmpeg -f v4l2: 10 frames of scene a, exact" \
	ffmpeg_frames bgr32 "$a" 10
check "scene b (640x480) drawn through fbdev: while streaming" \
	"$RDCCTL" --connect "fbdev:$FB" run "$b"
check "own reader follows: 30 frames of scene b, exact" \
	"$READ" --device "$DEV" --expect "$b" --frames 30 --settle --timeout 90
check "the stream is still running" writer_alive
finish
