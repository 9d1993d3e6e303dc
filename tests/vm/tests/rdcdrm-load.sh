#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# rdcdrm.ko, the RDC-1 as a DRM/KMS device (driver "rdc"): modetest lists
# the chip's presets; fbcon runs on the emulated fbdev; a mode set from a
# dumb buffer with modetest's plain pattern, and rdcdrm_tool's own mode
# sets, damage, flips, vblank counts, formats, gamma and cursor give chip
# frames (the FRAME ioctl) equal to what was drawn; the debugfs CRCs are
# the frames'; bad ioctl input gets clean errors, random input too.  Load
# and unload with both clocks; unload refused while a client holds the
# card; unbind under an open, mapped client; no memory left behind and
# dmesg clean.
# vm-module: rdcdrm
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$B/rdcdrm_tool
KO=$RDC_VM_DIR/build-rdcdrm/rdcdrm.ko
CARD=/dev/dri/card0
LOOPS=${RDCDRM_LOOPS:-6}
DEBUGFS=/sys/kernel/debug/dri/0

[ -x "$TOOL" ] || { echo "rdcdrm_tool is not built (no libdrm?)"; exit 77; }

vmalloc_kb() {
	sed -n 's/^VmallocUsed: *\([0-9]*\).*/\1/p' /proc/meminfo
}

# (its counter is its own: loop's $i stays loop's)
wait_held() {
	w=0
	while [ $w -lt 300 ]; do
		grep -q held "$1" 2>/dev/null && return 0
		sleep 0.1
		w=$((w + 1))
	done
	return 1
}

# every preset, by name, in modetest's list of the connector's modes
presets_listed() {
	modetest -M rdc -c >"$T/modetest-c.txt" 2>&1 || return 1
	for m in 320x200 640x480 800x600 1024x768 1280x720 1920x1080; do
		grep -q "$m" "$T/modetest-c.txt" ||
			{ echo "$m not listed"; cat "$T/modetest-c.txt"; return 1; }
	done
	grep -E "connected|#0 " "$T/modetest-c.txt" | head -n 4
}

fbcon_on_rdcdrm() {
	grep -i rdc /proc/fb || return 1
	v=$(fbcon_vt) || { echo "no fbcon"; return 1; }
	echo "$v bind=$(cat "$v/bind")"
	[ "$(cat "$v/bind")" = 1 ]
}

# modetest sets 1024x768 XRGB8888 from a dumb buffer filled with its plain
# pattern (0x77 bytes) and waits on its stdin; the frame shows it.
modetest_plain() {
	conn=$(awk '$3 == "connected" { print $1; exit }' "$T/modetest-c.txt")
	[ -n "$conn" ] || { echo "no connected connector"; return 1; }
	mkfifo "$T/mt.in"
	modetest -M rdc -s "$conn:1024x768@XR24" -F plain <"$T/mt.in" \
		>"$T/mt.out" 2>&1 &
	mt=$!
	exec 3>"$T/mt.in"
	# modetest opens the card first, as its master
	sleep 3
	"$TOOL" frame "$CARD" 777777
	ret=$?
	exec 3>&-
	wait "$mt"
	rm -f "$T/mt.in"
	sed 's/^/modetest: /' "$T/mt.out" | head -n 5
	return $ret
}

dmesg -C
check "the harness's module made $CARD" test -c "$CARD"
check "modetest -M rdc lists the chip's presets" presets_listed
check "fbcon is bound to the emulated fbdev" fbcon_on_rdcdrm
check "the console's frame is scanned out" "$TOOL" frame "$CARD"
fbcon_unbind
check "modetest's plain pattern from a dumb buffer is the chip's frame" \
	modetest_plain
check "mode sets, damage, flips, vblank and the private ioctls" \
	"$TOOL" kms "$CARD"
check "XRGB8888, ARGB8888, RGB888, RGB565, C8 and a gamma LUT" \
	"$TOOL" formats "$CARD"
if grep -q RDC_REG_CURSOR_CTRL "$RDC_TREE/hw-sim/rdc_regs.h"; then
	check "the ARGB cursor equals software compositing" \
		"$TOOL" cursor "$CARD"
fi
mount -t debugfs none /sys/kernel/debug 2>/dev/null
"$TOOL" hold "$CARD" >"$T/hold.out" 2>&1 &
pid=$!
wait_held "$T/hold.out"
check "debugfs CRCs (source auto) are the scanned-out frames'" \
	"$TOOL" crc "$CARD" "$DEBUGFS"
kill "$pid"
wait "$pid"
check "1000 random private ioctls answer 0 or their errno; the card draws after" \
	"$TOOL" fuzz "$CARD" 1000

check "the harness's module unloads" rmmod rdcdrm
base=$(vmalloc_kb)

loop() {
	i=0
	while [ $i -lt "$LOOPS" ]; do
		case $((i % 3)) in
		1) args="clock=stepped" ;;
		2) args="devices=2 vram=18M" ;;
		*) args="" ;;
		esac
		insmod "$KO" $args || { echo "run $i: insmod $args failed"; return 1; }
		[ -c $CARD ] || { echo "run $i: no $CARD"; return 1; }
		if [ "$args" = "devices=2 vram=18M" ] && [ ! -c /dev/dri/card1 ]; then
			echo "run $i: no card1"
			return 1
		fi
		fbcon_unbind
		: >"$T/hold.out"
		"$TOOL" hold "$CARD" >"$T/hold.out" 2>&1 &
		pid=$!
		wait_held "$T/hold.out" ||
			{ echo "run $i ($args): no mode set"; cat "$T/hold.out"; return 1; }
		"$TOOL" frame "$CARD" >"$T/frame.out" 2>&1 ||
			{ echo "run $i ($args): frame"; cat "$T/frame.out"; return 1; }
		kill "$pid"
		wait "$pid"
		rmmod rdcdrm || { echo "run $i: rmmod failed"; return 1; }
		i=$((i + 1))
	done
	echo "$LOOPS runs; last frame: $(cat "$T/frame.out")"
}
check "load, use, unload $LOOPS times" loop

# bad module parameters: refused (the kernel chip host's one check, which
# rdcfb takes too), each named in the log, nothing loaded
bad_params() {
	for args in vram=4K vram=1G vram=16Q clock=fast scanout=lazy \
		cpu_budget=0 cpu_budget=101 devices=0 devices=9; do
		dmesg -C
		if insmod "$KO" $args 2>/dev/null; then
			echo "$args: loaded"
			rmmod rdcdrm
			return 1
		fi
		dmesg | grep -q "rdcdrm: ${args%%=*}=" ||
			{ echo "$args: not named in dmesg"; dmesg | tail -3; return 1; }
		[ ! -d /sys/module/rdcdrm ] || { echo "$args: module left"; return 1; }
	done
}
check "bad vram, clock, scanout, cpu_budget and devices parameters are refused and named" bad_params

# the stepped clock without fbdev emulation (whose console draws when it
# will): the same commits give the same cycles and frame on every load
stepped_run() {
	insmod "$KO" clock=stepped fbdev=0 || return 1
	"$TOOL" stepped "$CARD" >"$T/stepped.$1" 2>&1
	ret=$?
	rmmod rdcdrm || return 1
	cat "$T/stepped.$1"
	return $ret
}
stepped_same() {
	stepped_run 1 && stepped_run 2 && cmp -s "$T/stepped.1" "$T/stepped.2"
}
check "stepped clock: a mode set, damage and a flip are the same twice" \
	stepped_same

insmod "$KO"
fbcon_unbind
: >"$T/hold.out"
"$TOOL" hold "$CARD" >"$T/hold.out" 2>&1 &
pid=$!
check "a client holds $CARD with a mode set" wait_held "$T/hold.out"
check "unload refused while it is open" sh -c '! rmmod rdcdrm'
kill "$pid"
wait "$pid"
check "unload once it is closed" rmmod rdcdrm

insmod "$KO"
fbcon_unbind
check "unbind the device under an open, mapped client" \
	"$TOOL" unbind "$CARD" rdcdrm.0
check "unload after that" rmmod rdcdrm
after=$(vmalloc_kb)
check "VRAM freed after all that (before ${base} kB, after ${after} kB)" \
	test $((after - base)) -lt 4096

dmesg >"$T/dmesg.log"
check "no WARN, BUG or oops in dmesg" \
	sh -c "! grep -E 'WARNING|BUG|Oops|general protection|Call Trace|refcount|corruption|leak' '$T/dmesg.log'"
grep -E 'rdc|drm' "$T/dmesg.log" | tail -n 5 | sed 's/^/# /'

# leave it loaded, for the harness to unload
insmod "$KO"
fbcon_unbind
finish
