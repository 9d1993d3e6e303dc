#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Every golden scene (tests/golden/scenes) and examples/demo.rdl, run by
# rdcctl through fbdev:/dev/fb0 on rdcfb.ko's stepped clock, gives what
# the same scene gives through sim: in this guest: the same frame CRC, the
# same cycles per command class, the same readback CRC and the same
# simulated time.  Before each scene the kernel's chip is put in a fresh
# sim:'s state (soft reset, VRAM zeroed); its clock is not reset, so the
# time compared is the time since that reset.
# vm-module: rdcfb clock=stepped
. "$RDC_TREE/tests/vm/lib.sh"

IOCTL=$B/fbdev_ioctl
FB=/dev/fb0


# total cycles on rdcctl run's "total N cycles ..." line, minus $2
total_since() {
	t=$(sed -n 's/^total \([0-9]*\) cycles.*/\1/p' "$1")
	[ -n "$t" ] && echo $((t - $2))
}

# same_run SCENE: fbdev: and sim: agree on everything rdcctl run prints
same_run() {
	prep=$("$IOCTL" --device $FB --prepare) || { echo "prepare failed"; return 1; }
	t0=$(echo "$prep" | sed -n 's/^time \([0-9]*\) .*/\1/p')
	vram=$(echo "$prep" | sed -n 's/.* vram \([0-9]*\)$/\1/p')
	"$RDCCTL" --connect "fbdev:$FB" run "$1" >"$T/fb.out" 2>&1
	rf=$?
	"$RDCCTL" --connect "sim:vram=$vram" run "$1" >"$T/sim.out" 2>&1
	rs=$?
	tf=$(total_since "$T/fb.out" "$t0")
	ts=$(total_since "$T/sim.out" 0)
	grep -v '^total ' "$T/fb.out" >"$T/fb.rest"
	grep -v '^total ' "$T/sim.out" >"$T/sim.rest"
	if [ $rf -eq $rs ] && [ "$tf" = "$ts" ] &&
		cmp -s "$T/fb.rest" "$T/sim.rest"; then
		echo "$(grep '^crc32' "$T/sim.out"), $ts cycles, exit $rs"
		return 0
	fi
	echo "fbdev: (exit $rf, $tf cycles since reset at $t0):"
	sed 's/^/  /' "$T/fb.out"
	echo "sim: (exit $rs, $ts cycles):"
	sed 's/^/  /' "$T/sim.out"
	return 1
}

fbcon_unbind
[ -c $FB ] || { echo "no $FB"; exit 1; }
cd "$T" || exit 1
for s in "$RDC_TREE"/tests/golden/scenes/*.rdl "$RDC_TREE"/examples/demo.rdl; do
	check "$(basename "$s" .rdl): fbdev: = sim:" same_run "$s"
done
finish
