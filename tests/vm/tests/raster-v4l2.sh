#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The raster list's palette split in every frame a sink gets:
# examples/demo.rdl (8 bpp indexed, its sky ramp turned to sunset from
# line 240 on by the CRTC's raster list, no host write after the script)
# streamed by `rdcctl stream` into v4l2loopback.  Frames 0, 1 and 100 of
# one capture (read(2) on one open, a frame a read) are each sim:'s
# picture of the script, byte for byte (our reader, --raw), and each
# shows the list's colours either side of the split: at line 239 the
# upper palette's, at line 240 the lower's, as `rdcctl why` names them
# (the list entry and the line it runs at).
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

DEMO=$RDC_TREE/examples/demo.rdl
W=640
FRAME=$((W * 480 * 4)) # bgr32
X=5                    # a column of the sky, nothing drawn over it

# colour X Y LINE: the colour (6 hex digits) rdcctl why says pixel X,Y of
# the demo shows, which must come from a raster-list entry run at LINE
colour() {
	"$RDCCTL" why "$1" "$2" "$DEMO" | tail -n 1 |
		sed -n "s/.* = 0x\([0-9a-f]\{6\}\): raster-list entry [0-9]* (VRAM 0x[0-9a-f]*) at line $3, column 0 this frame$/\1/p"
}

# px FILE N X Y: pixel X,Y of frame N of FILE (bgr32) as 6 hex digits
px() {
	od -A n -t x1 -j $((FRAME * $2 + ($4 * W + $3) * 4)) -N 3 "$1" |
		awk '{ print $3 $2 $1 }'
}

UPPER=$(colour $X 239 0)
LOWER=$(colour $X 240 240)
check "rdcctl why: line 239 from the list's top ($UPPER), 240 from its WAIT 240 ($LOWER)" \
	test -n "$UPPER" -a -n "$LOWER" -a "$UPPER" != "$LOWER"

writer_start --script "$DEMO" --format bgr32
check "the device gets a format" wait_device 60

# frames 0 and 1, 98 more, then frame 100, all from one open
capture() {
	rm -f $T/f.raw
	exec 3<"$DEV" || return 1
	dd bs=$FRAME count=2 <&3 >$T/f.raw 2>/dev/null &&
		dd bs=$FRAME count=98 <&3 >/dev/null 2>/dev/null &&
		dd bs=$FRAME count=1 <&3 >>$T/f.raw 2>/dev/null
	rc=$?
	exec 3<&-
	[ $rc = 0 ] && [ "$(wc -c <$T/f.raw)" -eq $((3 * FRAME)) ]
}
check "frames 0, 1 and 100 read" capture
check "each is sim:'s picture of demo.rdl (our reader)" \
	"$READ" --raw $T/f.raw --format bgr32 --expect "$DEMO" --frames 3
for i in 0 1 2; do
	f=$i # lib.sh counts its checks in n
	[ $i = 2 ] && f=100
	check "frame $f: line 239 the upper palette's $UPPER" \
		test "$(px $T/f.raw $i $X 239)" = "$UPPER"
	check "frame $f: line 240 the lower palette's $LOWER" \
		test "$(px $T/f.raw $i $X 240)" = "$LOWER"
	check "frame $f: the split holds across the line (x 630)" \
		test "$(px $T/f.raw $i 630 239)$(px $T/f.raw $i 630 240)" = \
		"$UPPER$LOWER"
done
check "writer still running" writer_alive
finish
