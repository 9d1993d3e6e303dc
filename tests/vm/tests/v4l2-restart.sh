#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Killing a reader leaves the writer streaming to the next one; killing
# and restarting the writer while a reader waits leaves the reader
# receiving again.
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

scene=$SCENES/stream_a.rdl
writer_start --script "$scene"
check "the device gets a format" wait_device 60

"$READ" --device "$DEV" --expect "$scene" --frames 1000000 --timeout 60 \
	>/dev/null 2>&1 &
reader=$!
sleep 2
kill -9 $reader
wait $reader 2>/dev/null
check "writer survives its reader's death" writer_alive
check "a new reader gets 20 exact frames" \
	"$READ" --device "$DEV" --expect "$scene" --frames 20 --timeout 60

"$READ" --device "$DEV" --expect "$scene" --frames 80 --stall-ms 3000 \
	--timeout 90 >$T/reader.log 2>&1 &
reader=$!
sleep 1
writer_stop
writer_start --script "$scene"
wait $reader
check "a reader across a writer restart gets 80 exact frames" [ $? -eq 0 ]
sed 's/^/    reader: /' $T/reader.log
check "restarted writer streams" writer_alive
finish
