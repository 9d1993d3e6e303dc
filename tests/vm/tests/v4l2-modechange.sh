#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# A mode change mid-stream (320x200@70 to 640x480@60): the writer
# renegotiates the format and the interval and keeps streaming; a reader
# that follows it gets both pictures exactly.  How the change goes
# depends on v4l2loopback (docs/v4l2.md): 0.13 takes the new format on
# the writer's own descriptor (STREAMOFF, S_FMT, STREAMON) while a read()
# reader holds the device; 0.12.7 keeps the old one until every opener
# has closed, so the writer lets go and opens it again.
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

# 0.13 gives its version in sysfs, 0.12.7 none
ver=$(cat /sys/module/v4l2loopback/version 2>/dev/null)
echo "# v4l2loopback ${ver:-0.12 (no version in sysfs)}"
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
case $ver in
"" | 0.12.*)
	grep -q 'reopens [1-9]' $T/writer.log
	check "0.12: the writer let go and opened the device again" [ $? -eq 0 ]
	;;
*)
	grep -q 'reopens 0$' $T/writer.log
	check "$ver: the new format taken on the writer's own descriptor" \
		[ $? -eq 0 ]
	;;
esac
finish
