#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# A trace of drm: (rdcctl --record, librdc's client-side recorder): a
# scene drawn through rdcdrm.ko's card, with command words through SUBMIT
# and a display list written through the VRAM ioctl, is recorded; the trace
# replays on sim: to the frame the scene makes on sim: and on the device;
# rdcctl diff finds no divergence between the trace and the scene run on
# sim: (and says the untimed trace's timing is not compared), and finds
# the changed statement of another scene at its write.
# vm-module: rdcdrm clock=stepped
. "$RDC_TREE/tests/vm/lib.sh"

# the console would draw on the device between the client's operations
fbcon_unbind
FB=""
for c in /dev/dri/card*; do
	[ -c "$c" ] || continue
	"$RDCCTL" --connect "drm:$c" regs >/dev/null 2>&1 && { FB=drm:$c; break; }
done
[ -n "$FB" ] || { echo "no card of rdcdrm.ko in /dev/dri"; exit 1; }

cat >"$T/a.rdl" <<'SCENE'
mode 320x200 xrgb8888
host-blit 0 0 320 200 pattern noise 11
list 0x80000
fg #2040ff
fill-rect 20 20 80 40
ret
end
call 0x80000
fg #ffffff
text 8 180 "rdc record"
SCENE
sed 's/rdc record/rdc recorD/' "$T/a.rdl" >"$T/b.rdl"

crc_of() {
	awk '$1 == "crc32" { print $2 }' "$1"
}

record() {
	rm -f "$T/s.trace"
	"$RDCCTL" --connect $FB --record "$T/s.trace" run "$T/a.rdl" \
		>"$T/dev.out" || return 1
	"$RDCCTL" run "$T/a.rdl" >"$T/sim.out" || return 1
	echo "device $(crc_of "$T/dev.out"), sim: $(crc_of "$T/sim.out")"
	[ -s "$T/s.trace" ] && [ -n "$(crc_of "$T/sim.out")" ] &&
		[ "$(crc_of "$T/dev.out")" = "$(crc_of "$T/sim.out")" ]
}
check "rdcctl --record on $FB writes a trace; the device draws as sim:" \
	record

replay() {
	"$RDCCTL" replay "$T/s.trace" >"$T/replay.out"
	cat "$T/replay.out"
	[ "$(crc_of "$T/replay.out")" = "$(crc_of "$T/sim.out")" ] &&
		grep -q '^mismatches 0$' "$T/replay.out"
}
check "the trace replays on sim: to the scene's frame, every read the same" \
	replay

same() {
	"$RDCCTL" diff "$T/s.trace" "$T/a.rdl" >"$T/diff.out"
	r=$?
	cat "$T/diff.out"
	[ $r = 0 ] && grep -q '^VRAM writes: the same' "$T/diff.out" &&
		grep -q '^frame: the same' "$T/diff.out" &&
		grep -q '^timing: not compared' "$T/diff.out"
}
check "diff of the trace and its scene on sim:: no divergence" same

changed() {
	"$RDCCTL" diff "$T/s.trace" "$T/b.rdl" >"$T/diff.out"
	r=$?
	cat "$T/diff.out"
	[ $r = 3 ] && grep -q '^first divergence' "$T/diff.out" &&
		grep -q "B: .*b.rdl:10 text" "$T/diff.out"
}
check "diff of the trace and a changed scene finds the text" changed

finish
