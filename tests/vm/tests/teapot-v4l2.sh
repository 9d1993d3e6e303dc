#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The turning teapot (examples/teapot.rdl, then examples/teapot-spin.rdl:
# the display processor draws every frame itself from display lists in
# VRAM, double-buffered, flipping at vertical blanking) streamed by
# `rdcctl stream` into v4l2loopback, paced to the mode's 60 Hz: our reader
# gets the frames the simulator makes, frame for frame (each one's CRC-32
# that of sim:'s frame of the same number, in order, so each a new turn),
# with the mode's frame interval.  The rates the writer and the reader
# reach are figures (TAP comments), never judged: under emulation they are
# far below 60.  (ffmpeg is left to v4l2-stream and rdcd-v4l2: in the
# guest it takes some 20 s to start, and here its mmap reads of
# v4l2loopback 0.12.7 got one frame eight times over while the writer was
# slower than the reader, so it cannot follow a turning picture frame by
# frame.)
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

EX=$RDC_TREE/examples
SCRIPTS="--expect $EX/teapot.rdl --expect $EX/teapot-spin.rdl"
# frames after the two scripts' pictures that the reader's references
# cover; the writer stops there, so it never sends a frame the reader
# cannot know
SEQ=30
READ_N=16

now() { date +%s.%N; }

# writer_run ARGS: rdcctl stream of the teapot, paced
writer_run() {
	writer_start --script "$EX/teapot.rdl" --at 1 "$EX/teapot-spin.rdl" "$@"
	W_T0=$(now)
}

# writer_end WHO: stop the writer; its frames a second as a TAP comment
writer_end() {
	t1=$(now)
	writer_stop >$T/writer.out
	W_SENT=$(sed -n 's/^v4l2: frames \([0-9]*\).*/\1/p' $T/writer.log)
	awk -v n="${W_SENT:-0}" -v a="$W_T0" -v b="$t1" -v w="$1" 'BEGIN {
		printf "# %s: rdcctl stream sent %d frames in %.1f s: " \
		    "%.1f fps (the mode: 60)\n", w, n, b - a, n / (b - a) }'
}

reader_wait() {
	wait $reader
	rc=$?
	cat $T/read.out
	return $rc
}

# our reader makes its references first (sim:, the same scripts, then
# a frame at each vertical blanking as rdcctl stream sends them); then the
# writer starts
rm -f $T/read.out
# shellcheck disable=SC2086
"$READ" --device "$DEV" $SCRIPTS --sequence $SEQ --format bgr32 \
	--in-order --frames $READ_N --timeout 120 >$T/read.out 2>&1 &
reader=$!
i=0
while ! grep -q '^expected:' $T/read.out 2>/dev/null &&
	kill -0 $reader 2>/dev/null && [ $i -lt 1800 ]; do
	sleep 0.1
	i=$((i + 1))
done
writer_run --frames $((SEQ + 2))
check "own reader: $READ_N frames in order, each sim:'s frame of its number, the mode's interval" \
	reader_wait
writer_end "own reader's writer"
sed -n 's/^session: \([0-9]*\) frames, \([0-9.]*\) ms apart.*/\1 \2/p' \
	$T/read.out | awk '{ printf "# own reader: %d frames %.1f ms " \
	    "apart: %.1f fps\n", $1, $2, 1000 / $2 }'
sed 's/^/    /' $T/writer.out

finish
