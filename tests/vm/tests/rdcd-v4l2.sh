#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# rdcd feeds its frames to v4l2loopback (--v4l2) while a client draws a
# scene over its socket: our reader and ffmpeg get the simulator's frames
# exactly, at the mode's interval.
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

RDCD=$B/rdcd
if ! [ -x "$RDCD" ] || ! "$RDCD" --help | grep -q -- --v4l2; then
	echo "rdcd is not built, or has no --v4l2"
	exit 77
fi
scene=$SCENES/stream_a.rdl
# the scratch directory outlives a test: no earlier test's ready file
rm -f "$T/ready" "$T/rdc.sock"
"$RDCD" --listen "unix:$T/rdc.sock" --ready-file "$T/ready" --v4l2 "$DEV" \
	>"$T/rdcd.log" 2>&1 &
rdcd=$!
i=0
while ! [ -s "$T/ready" ] && [ $i -lt 300 ]; do
	sleep 0.1
	i=$((i + 1))
done
check "rdcd listens" test -s "$T/ready"
check "a client draws the scene through rdcd" \
	"$RDCCTL" --connect "unix:$T/rdc.sock" run "$scene"
check "own reader: 30 exact frames, mode's interval" \
	"$READ" --device "$DEV" --expect "$scene" --frames 30 --settle \
	--check-rate --timeout 60
check "ffmpeg -f v4l2: 10 exact frames" ffmpeg_frames bgr32 "$scene" 10
check "rdcd still running" kill -0 $rdcd
kill $rdcd
wait $rdcd
sed 's/^/    rdcd: /' "$T/rdcd.log"
finish
