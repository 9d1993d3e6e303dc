#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# A scripted scene streamed into v4l2loopback in each sink format: our own
# reader and ffmpeg (-f v4l2) both get frames equal, CRC for CRC, to the
# simulator's own, with the mode's frame interval.
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

scene=$SCENES/stream_a.rdl
for fmt in bgr32 xrgb32 rgb24 yuyv; do
	writer_start --script "$scene" --format "$fmt"
	check "$fmt: the device gets a format" wait_device 60
	check "$fmt: own reader, 30 frames exact, mode's interval" \
		"$READ" --device "$DEV" --expect "$scene" --frames 30 \
		--check-rate --timeout 60
	check "$fmt: ffmpeg -f v4l2, 10 frames exact" \
		ffmpeg_frames "$fmt" "$scene" 10
	check "$fmt: writer still running" writer_alive
	writer_stop
done
finish
