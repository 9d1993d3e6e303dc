#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Weston (Debian's, DRM backend, pixman renderer) runs on rdcdrm's card
# unchanged: a client shows, Weston's own screenshot equals the chip's
# scanned-out frame pixel for pixel, its repaint loop runs on the chip's
# vblank events (each presentation a later vblank, stamped a frame period
# per vblank after the one before, most often exactly,
# no more vblanks than the chip scanned out),
# and it exits cleanly, after which rdcdrm unloads.
# vm-module: rdcdrm
. "$RDC_TREE/tests/vm/lib.sh"
. "$RDC_TREE/tests/vm/desktop.sh"

CARD=$(desktop_card) || { echo "# no card of rdcdrm's"; exit 1; }
desktop_run_tmpfs
check "weston starts on $CARD" weston_start
weston-flower >$T/flower.out 2>&1 &
CLIENT=$!
sleep 5
check "weston-flower is still showing" kill -0 $CLIENT
# Weston fades its desktop in: a picture is taken once two screenshots
# a second apart are the same (at most 20 tries).
shot() {
	mkdir -p $T/shots
	rm -f $T/shots/* $T/still.png
	i=0
	while [ $i -lt 20 ]; do
		(cd $T/shots && weston-screenshooter) || return 1
		set -- $T/shots/wayland-screenshot-*.png
		[ $# = 2 ] && cmp -s "$1" "$2" && { mv "$2" $T/still.png; return 0; }
		[ $# = 2 ] && rm "$1"
		sleep 1
		i=$((i + 1))
	done
	echo "the screen never stood still"
	return 1
}
check "weston-screenshooter takes weston's picture" shot
check "weston's screenshot equals the chip's frame" \
	"$FRAME_CHECK" --uri "drm:$CARD" $T/still.png
kill $CLIENT 2>/dev/null

# Repaint on vblank: weston-presentation-shm's feedback gives each
# frame's vblank sequence (MSC) and presentation time.
present() {
	f0=$(chip_frames)
	# stdout alone: its lines are buffered, and the client's "exiting"
	# on stderr, written at the SIGINT, could land inside one
	timeout -s INT 6 weston-presentation-shm -f >$T/present.out \
		2>$T/present.err
	f1=$(chip_frames)
	awk -v f0="$f0" -v f1="$f1" -v us="$PERIOD_US" '
		/ seq [0-9]+$/ {
			seq = $NF + 0; n++
			if (n > 1 && seq <= last) { bad = "seq " seq " after " last }
			if (n > 1 && us > 0) {
				for (i = 1; i <= NF; i++) if ($i == "p2p") p2p = $(i + 1)
				d = p2p - (seq - last) * us
				gaps++
				if (d >= -2 && d <= 2) on++
				else if (!off) off = "p2p " p2p " us for " seq - last " vblanks"
				if (d < -2) early = "p2p " p2p " us for " seq - last " vblanks: sooner than the beam"
			}
			last = seq
			if (!first) first = seq
		}
		END {
			printf "%d frames presented, vblanks %d..%d; the chip scanned out %d frames\n", n, first, last, f1 - f0
			if (gaps) printf "%d of %d intervals are whole frame periods of %.3f us%s\n", on, gaps, us, off ? " (first other: " off ")" : ""
			if (bad) { print bad; exit 1 }
			# a slip also packs the frames it catches up on into less
			# wall time, so a stamp may come sooner: said, not failed
			if (early) print early
			# A paced chip that falls behind wall time slips its clock,
			# and the timestamps after it come later than the count
			# says, never sooner: on a loaded host, a few times a run.
			if (gaps && on * 2 < gaps) { print "timestamps do not follow the beam"; exit 1 }
			if (n < 10) { print "too few frames presented"; exit 1 }
			if (last - first + 1 > f1 - f0) { print "more vblanks than chip frames"; exit 1 }
		}' $T/present.out
}
# The frame period in microseconds, from the chip's CRTC registers.
PERIOD_US=$("$RDCCTL" --connect "drm:$CARD" regs | awk '
	$2 == "H_TOTAL" { h = $4 } $2 == "V_TOTAL" { v = $4 }
	$2 == "PIXCLK_KHZ" { k = $4 }
	END { if (k) printf "%.3f\n", h * v * 1000 / k; else print 0 }')
check "weston repaints on the chip's vblanks" present
check "weston exits cleanly" desktop_stop
check "rdcdrm unloads afterwards" rmmod rdcdrm
[ $failed -eq 0 ] || desktop_logs
desktop_cleanup
finish
