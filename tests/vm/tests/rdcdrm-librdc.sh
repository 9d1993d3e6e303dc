#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# librdc's drm: backend on rdcdrm.ko's card: rdcctl list names it; regs
# and stats read the chip; a scene that sets its own mode and surface
# draws to sim:'s frame CRC through drm:/dev/dri/cardN and through drm:
# alone (rdcdrm-record records and replays one); the pins through the
# module's GPIO lines (levels, TE's edges, BL_EN driven); rdcctl stream
# --from drm: feeds v4l2loopback while another client draws, and our
# reader and ffmpeg get the scene exactly, as rdcfb-stream does for
# fbdev:.  bochs (QEMU's VGA) is loaded first, so the guest has a DRM
# card of another driver before rdcdrm.ko's: rdc_list leaves it out,
# drm: alone passes it by, and drm: on it is refused, naming its driver;
# /dev/null and a missing card are refused too.  (The two share DRM's
# helper modules, so the harness's `modprobe -r rdcdrm` afterwards
# reports the helpers bochs still uses as "cannot unload rdcdrm".)
# vm-module: bochs
# vm-module: rdcdrm
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

# the console would draw on the card between the client's operations
fbcon_unbind
CARD=""
for c in /dev/dri/card*; do
	[ -c "$c" ] || continue
	"$RDCCTL" --connect "drm:$c" regs >/dev/null 2>&1 && { CARD=$c; break; }
done
[ -n "$CARD" ] || { echo "no card of rdcdrm.ko in /dev/dri"; ls -l /dev/dri; exit 1; }
DRM=drm:$CARD
a=$SCENES/stream_a.rdl

crc_of() {
	awk '$1 == "crc32" { print $2 }' "$1"
}

listed() {
	"$RDCCTL" list | tee "$T/list.out"
	grep -q "^$DRM " "$T/list.out"
}
check "rdcctl list names $DRM" listed
only_rdc() {
	cnt=$(grep -c "^drm:" "$T/list.out")
	echo "$cnt drm: line(s)"
	[ "$cnt" = 1 ]
}
check "rdcctl list names no other DRM card" only_rdc

regs() {
	"$RDCCTL" --connect "$DRM" regs >"$T/regs.out" || return 1
	head -n 4 "$T/regs.out"
	grep -q '^0x000 ID  *0x31434452 ' "$T/regs.out"
}
check "rdcctl regs on $DRM: the chip's ID (RDC1)" regs
check "rdcctl stats on $DRM" "$RDCCTL" --connect "$DRM" stats

same_crc() {
	"$RDCCTL" --connect "$1" run "$a" >"$T/dev.out" || return 1
	"$RDCCTL" run "$a" >"$T/sim.out" || return 1
	echo "$1 $(crc_of "$T/dev.out"), sim: $(crc_of "$T/sim.out")"
	[ -n "$(crc_of "$T/sim.out")" ] &&
		[ "$(crc_of "$T/dev.out")" = "$(crc_of "$T/sim.out")" ]
}
check "a scene through $DRM gives sim:'s frame CRC" same_crc "$DRM"
check "the same through drm: (the first rdc card)" same_crc drm:

pins() {
	"$RDCCTL" --connect "$DRM" pins >"$T/pins.out" 2>&1
	r=$?
	cat "$T/pins.out"
	[ $r = 0 ] && grep -q RESET_N "$T/pins.out"
}
watch_te() {
	timeout 60 "$RDCCTL" --connect "$DRM" pins --watch --pin TE \
		--count 8 >"$T/watch" || return 1
	cat "$T/watch"
	r=$(grep -c rising "$T/watch")
	f=$(grep -c falling "$T/watch")
	echo "$r rising, $f falling"
	cut -f2 "$T/watch" | tr '\n' ' ' | grep -q 'rising rising\|falling falling' &&
		{ echo "two edges of one kind in a row"; return 1; }
	[ "$r" = 4 ] && [ "$f" = 4 ]
}
set_and_show() {
	"$RDCCTL" --connect "$DRM" pins --set "$1" &&
		"$RDCCTL" --connect "$DRM" pins | tee /dev/stderr | grep -q "$1"
}
if "$RDCCTL" --connect "$DRM" pins 2>&1 | grep -q 'not supported'; then
	echo "# pins: this build has no libgpiod"
else
	check "rdcctl pins on $DRM reads the module's GPIO lines" pins
	check "pins --watch: TE's edges alternate, as the paced clock makes them" \
		watch_te
	check "pins --set BL_EN=0 drives the line; the chip keeps it" \
		set_and_show BL_EN=0
	check "pins --set BL_EN=1" set_and_show BL_EN=1
fi

refused() {
	out=$("$RDCCTL" --connect "drm:$1" regs 2>&1)
	r=$?
	echo "$out"
	[ $r != 0 ] && echo "$out" | grep -q "$2"
}
OTHER=""
for c in /dev/dri/card*; do
	[ -c "$c" ] && [ "drm:$c" != "$DRM" ] && { OTHER=$c; break; }
done
if [ -n "$OTHER" ]; then
	check "$OTHER (another driver's card) is refused, naming its driver" \
		refused "$OTHER" "is a DRM card of driver '.*', not rdcdrm.ko's"
else
	echo "# no DRM card of another driver here (bochs did not bind)"
fi
check "drm:/dev/null is refused as no DRM device" \
	refused /dev/null "not a DRM device"
check "a missing card names rdcdrm.ko and how to load it" \
	refused /dev/dri/card63 "modprobe rdcdrm"

[ -c "$DEV" ] || { echo "no $DEV"; finish; exit 1; }
# The stream holds the card open while another client draws: when the
# card's last client closes it, DRM hands the display back to its fbdev
# emulation, which sets its own picture.
writer_start --from "$DRM" --format bgr32
check "the stream from drm: gives the device a format" wait_device 60
check "scene a drawn through $DRM while streaming" \
	"$RDCCTL" --connect "$DRM" run "$a"
check "own reader: 30 frames of scene a, exact" \
	"$READ" --device "$DEV" --expect "$a" --frames 30 --settle --timeout 60
check "ffmpeg -f v4l2: 10 frames of scene a, exact" \
	ffmpeg_frames bgr32 "$a" 10
check "the stream is still running" writer_alive
finish
