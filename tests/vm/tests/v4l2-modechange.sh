#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# A mode change mid-stream (320x200@70 to 640x480@60): the writer
# renegotiates the format and the interval and keeps streaming; a reader
# that follows it gets both pictures exactly.
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

writer_start --script "$SCENES/stream_a.rdl" --at 100 "$SCENES/stream_b.rdl" \
	--format yuyv
check "reader sees 320x200 then 640x480, every frame exact" \
	"$READ" --device "$DEV" --expect "$SCENES/stream_a.rdl" \
	--expect "$SCENES/stream_b.rdl" --each 30 --frames 60 \
	--stall-ms 400 --timeout 120
check "writer still running" writer_alive
writer_stop
grep -q 'renegotiations [2-9]' $T/writer.log
check "writer renegotiated" [ $? -eq 0 ]
finish
