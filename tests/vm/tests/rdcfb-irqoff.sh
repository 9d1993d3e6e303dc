#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# How long rdcfb.ko keeps interrupts off, under load: fbcon scrolling text
# on fb0 (tty writes and kernel messages, which the console draws with
# interrupts off), golden scenes drawn through fbdev: on the paced clock
# on fb1 (a client's commands and fbcon's would interleave on one
# device: docs/driver.md), and frame snapshots of both through sysfs
# (frame_crc) and the FRAME ioctl, all at once.  The checks are that every part of the load ran and dmesg
# stayed clean; the longest interrupts-off section the driver measured
# (sysfs irqs_off_max_ns, irqs_off_max_at) and all of them by length
# (debugfs rdcfb/fbN/irqs_off) are printed as TAP comments, not judged:
# timing is no pass/fail matter.
# vm-module: rdcfb mode=1024x768-32 devices=2
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$B/rdcfb_tool
SYS=/sys/bus/platform/devices/rdcfb.0
SYS1=/sys/bus/platform/devices/rdcfb.1
TTY=/dev/tty1
FB=/dev/fb1

fbcon_bound() {
	v=$(fbcon_vt) && [ "$(cat "$v/bind")" = 1 ] && grep -q "^0 rdcfb" /proc/fb
}

# 300 lines written to the console: every one scrolls it
scroll_tty() {
	i=0
	while [ $i -lt 300 ]; do
		echo "tty line $i: the quick brown fox jumps over the lazy dog"
		i=$((i + 1))
	done >"$TTY"
}

# 100 kernel messages at a level the console prints (printk draws them
# with interrupts off)
scroll_kmsg() {
	i=0
	while [ $i -lt 100 ]; do
		echo "<3>console load $i: the quick brown fox" >/dev/kmsg ||
			return 1
		i=$((i + 1))
	done
}

# every golden scene through fbdev: on the paced clock, from a reset chip
# and zeroed VRAM, ending as it does on sim: (a scene rdcctl refuses is
# refused on both)
scenes() {
	for s in "$RDC_TREE"/tests/golden/scenes/*.rdl; do
		prep=$("$B/fbdev_ioctl" --device $FB --prepare) ||
			{ echo "prepare failed"; return 1; }
		vram=${prep##* vram }
		"$RDCCTL" --connect "sim:vram=$vram" run "$s" >"$T/sim.out" 2>&1
		rs=$?
		"$RDCCTL" --connect "fbdev:$FB" run "$s" -o "$T/scene.png" \
			>"$T/scene.out" 2>&1
		rf=$?
		[ $rf -eq $rs ] && continue
		echo "$(basename "$s"): fbdev: exit $rf, sim: exit $rs"
		cat "$T/scene.out"
		return 1
	done
}

# frames through sysfs and the FRAME ioctl, alternately
# A read answers EAGAIN while a device has no frame yet: fb1's scenes
# each begin with a reset, which starts the frames over.  Such a read
# (through sysfs or the ioctl) is tried again, up to 5 s; any other
# error fails at once.
again() {
	k=0
	until "$@" >/dev/null 2>"$T/again.err"; do
		grep -q 'temporarily unavailable' "$T/again.err" &&
			[ $k -lt 100 ] || { cat "$T/again.err"; return 1; }
		k=$((k + 1))
		sleep 0.05
	done
}

snapshots() {
	i=0
	while [ $i -lt 60 ]; do
		again cat "$SYS/frame_crc" || return 1
		again cat "$SYS1/frame_crc" || return 1
		again "$TOOL" frame /dev/fb0 "$T/frame.raw" || return 1
		again "$TOOL" frame $FB "$T/frame.raw" || return 1
		i=$((i + 1))
	done
}

check "fbcon is bound to /dev/fb0 (rdcfb)" fbcon_bound
check "fb1 is rdcfb's second device" sh -c "grep '^1 rdcfb' /proc/fb"
check "irqs_off_max_ns resets" sh -c \
	"echo 0 >$SYS/irqs_off_max_ns && echo 0 >$SYS1/irqs_off_max_ns"
dmesg -C
cd "$T" || exit 1
scroll_tty >"$T/tty.log" 2>&1 &
p_tty=$!
scroll_kmsg >"$T/kmsg.log" 2>&1 &
p_kmsg=$!
scenes >"$T/scenes.log" 2>&1 &
p_scenes=$!
snapshots >"$T/snap.log" 2>&1 &
p_snap=$!
wait $p_tty
r_tty=$?
wait $p_kmsg
r_kmsg=$?
wait $p_scenes
r_scenes=$?
wait $p_snap
r_snap=$?
check "300 lines scrolled through the console" sh -c \
	"cat $T/tty.log; exit $r_tty"
check "100 kernel messages printed on the console" sh -c \
	"cat $T/kmsg.log; exit $r_kmsg"
check "every golden scene drawn through fbdev: on fb1 (paced), as on sim:" sh -c \
	"cat $T/scenes.log; exit $r_scenes"
check "60 frames of each device through sysfs and FRAME" sh -c \
	"cat $T/snap.log; exit $r_snap"
check "the longest interrupts-off sections are readable" sh -c \
	"grep -E '^[0-9]+$' $SYS/irqs_off_max_ns $SYS1/irqs_off_max_ns"
mount -t debugfs none /sys/kernel/debug 2>/dev/null
for d in "$SYS" "$SYS1"; do
	echo "# irqs off, ${d##*/}: longest $(cat "$d/irqs_off_max_ns") ns," \
		"ended at $(cat "$d/irqs_off_max_at")"
	[ -r "$d/fb_dropped" ] &&
		echo "# ${d##*/}: fb_ops records dropped at a full queue: $(cat "$d/fb_dropped")"
	fb=$(ls "$d/graphics" 2>/dev/null)
	[ -r "/sys/kernel/debug/rdcfb/$fb/irqs_off" ] &&
		tr '\n' ' ' <"/sys/kernel/debug/rdcfb/$fb/irqs_off" |
		sed "s/^/# irqs off, ${d##*/}, sections by length: /; s/ *\$//" &&
		echo
done
dmesg >"$T/dmesg.log"
check "no oops, BUG or WARN in dmesg" \
	sh -c "! grep -E 'WARNING|BUG|Oops|general protection|Call Trace|UBSAN' '$T/dmesg.log'"
fbcon_unbind
finish
