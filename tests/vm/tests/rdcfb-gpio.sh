#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# rdcfb.ko's GPIO lines, through libgpiod v2's tools and gpio_te:
# gpiodetect and gpioinfo show the chip "rdcfb.0-pins" with TE, IRQ,
# RESET_N and BL_EN; on the stepped clock gpiomon sees exactly one rising
# and one falling TE edge per frame for 300 frames, in order, and the IRQ
# line's pulses; gpioset BL_EN=0 makes the frames black and =1 brings the
# picture back; RESET_N low holds the chip at its reset values, released
# it resets the chip, which then draws a golden scene as sim: does.  On
# the paced clock gpiomon sees 300 TE edges at the mode's rate, gpio_te
# reports TE's jitter and lost edges, and 120 full-screen fills presented
# on TE's rising edge never tear while the same fills at random moments
# do.  The module refuses to unload while a line is requested; dmesg
# stays clean.
# vm-module: rdcfb clock=stepped mode=320x200-32
. "$RDC_TREE/tests/vm/lib.sh"

GT=$B/gpio_te
IOCTL=$B/fbdev_ioctl
KO=$RDC_VM_DIR/build-rdcfb/rdcfb.ko
FB=/dev/fb0
LABEL=rdcfb.0-pins
SYS=/sys/bus/platform/devices/rdcfb.0
FRAMES=300

if [ ! -x "$GT" ]; then
	echo "gpio_te not built: libgpiod >= 2 (libgpiod-dev) was missing"
	exit 77
fi
if ! gpiodetect --version 2>/dev/null | grep -q 'v2\.'; then
	echo "libgpiod v2 tools (gpiodetect, gpioinfo, gpiomon, gpioset) missing"
	exit 77
fi

# the gpiochipN the label belongs to
chip_of() {
	gpiodetect | sed -n "s/^\(gpiochip[0-9]*\) \[$1\].*/\1/p"
}

# held LINE: a consumer has LINE requested (at most 10 s)
held() {
	i=0
	while [ $i -lt 100 ]; do
		gpioinfo "$1" 2>/dev/null | grep -q consumer && return 0
		sleep 0.1
		i=$((i + 1))
	done
	return 1
}

# drive LINE=VALUE with gpioset until it is requested, then let go (the
# kernel keeps an output's level after release)
drive() {
	gpioset -c "$CHIP" "$1" &
	p=$!
	held "${1%%=*}" || { kill $p; return 1; }
	kill $p
	wait $p 2>/dev/null
	return 0
}

lists_lines() {
	gpiodetect
	gpiodetect | grep -q "^$CHIP \[$LABEL\] (4 lines)" || return 1
	gpioinfo -c "$CHIP" >"$T/info" || return 1
	cat "$T/info"
	sp='[[:space:]]*'
	grep -q "line${sp}0:$sp\"TE\"${sp}input" "$T/info" &&
		grep -q "line${sp}1:$sp\"IRQ\"${sp}input" "$T/info" &&
		grep -q "line${sp}2:$sp\"RESET_N\"${sp}output" "$T/info" &&
		grep -q "line${sp}3:$sp\"BL_EN\"${sp}output" "$T/info"
}

by_name() {
	for l in TE IRQ RESET_N BL_EN; do
		gpioinfo "$l" || return 1
		gpioinfo "$l" | grep -q "^$CHIP " || return 1
	done
	gpioget -c "$CHIP" --as-is RESET_N BL_EN | tee "$T/get"
	grep -q '"RESET_N"=active "BL_EN"=active' "$T/get"
}

# lines_at_least FILE N: FILE has N lines (at most 10 s)
lines_at_least() {
	i=0
	while [ $i -lt 100 ]; do
		[ "$(wc -l <"$1")" -ge "$2" ] && return 0
		sleep 0.1
		i=$((i + 1))
	done
	return 1
}

# mon_start LINE: gpiomon watches both edges of LINE, a line per event
mon_start() {
	stdbuf -oL gpiomon -c "$CHIP" -e both --idle-timeout 3s -F '%E' "$1" \
		>"$T/mon" &
	mon=$!
	held "$1" || { kill $mon; return 1; }
}

# mon_end LINE N: gpiomon saw N rising and N falling edges, alternating
mon_end() {
	wait $mon
	r=$(grep -c rising "$T/mon")
	fa=$(grep -c falling "$T/mon")
	echo "$1: $r rising, $fa falling edges"
	tr '\n' ' ' <"$T/mon" | grep -q 'rising rising\|falling falling' &&
		{ echo "two edges of one kind in a row"; return 1; }
	[ "$r" = "$2" ] && [ "$fa" = "$2" ]
}

# The stepped clock runs TE_CHUNK frames at a time, and the next chunk
# waits until gpiomon has printed the last one's edges: the GPIO character
# device keeps 16 events per line for a consumer, and simulated time runs
# far faster than a consumer under TCG reads.
TE_CHUNK=5
te_frames() {
	# the mode the driver set at load is in force from the second frame
	"$GT" frames $FB 2 >/dev/null
	mon_start TE || return 1
	k=0
	first=""
	while [ $((k * TE_CHUNK)) -lt $FRAMES ]; do
		k=$((k + 1))
		"$GT" frames $FB $TE_CHUNK >"$T/step" || { kill $mon; return 1; }
		set -- $(sed -n 's/^FRAME_COUNT //p' "$T/step")
		[ -n "$first" ] || first=$1
		lines_at_least "$T/mon" $((2 * k * TE_CHUNK)) ||
			{ echo "chunk $k: $(wc -l <"$T/mon") edges"; kill $mon; return 1; }
	done
	echo "FRAME_COUNT $first..$2 in $k steps"
	mon_end TE $FRAMES && [ $(($2 - first)) = $FRAMES ]
}

irq_pulses() {
	mon_start IRQ || return 1
	for k in 1 2 3 4; do
		"$GT" irq $FB 5 || { kill $mon; return 1; }
		lines_at_least "$T/mon" $((10 * k)) || { kill $mon; return 1; }
	done
	mon_end IRQ 20
}

# same_run SCENE: fbdev: and sim: print the same (as rdcfb-conformance)
same_run() {
	prep=$("$IOCTL" --device $FB --prepare) || { echo "prepare failed"; return 1; }
	t0=$(echo "$prep" | sed -n 's/^time \([0-9]*\) .*/\1/p')
	vram=$(echo "$prep" | sed -n 's/.* vram \([0-9]*\)$/\1/p')
	"$RDCCTL" --connect "fbdev:$FB" run "$1" >"$T/fb.out" 2>&1 || return 1
	"$RDCCTL" --connect "sim:vram=$vram" run "$1" >"$T/sim.out" 2>&1 || return 1
	tf=$(sed -n 's/^total \([0-9]*\) cycles.*/\1/p' "$T/fb.out")
	ts=$(sed -n 's/^total \([0-9]*\) cycles.*/\1/p' "$T/sim.out")
	grep -v '^total ' "$T/fb.out" >"$T/fb.rest"
	grep -v '^total ' "$T/sim.out" >"$T/sim.rest"
	grep '^crc32' "$T/sim.out"
	[ $((tf - t0)) = "$ts" ] && cmp "$T/fb.rest" "$T/sim.rest"
}

dark_then_lit() {
	"$RDCCTL" --connect "fbdev:$FB" run "$RDC_TREE/tests/golden/scenes/circles.rdl" \
		>/dev/null || return 1
	"$GT" frames $FB 2 >/dev/null
	lit=$("$GT" crc $FB)
	"$GT" black $FB && { echo "the picture is black to begin with"; return 1; }
	drive BL_EN=0 || return 1
	"$GT" frames $FB 2 >/dev/null
	"$GT" black $FB || return 1
	drive BL_EN=1 || return 1
	"$GT" frames $FB 2 >/dev/null
	now=$("$GT" crc $FB)
	echo "picture $lit, after BL_EN=0 then 1: $now"
	[ "$now" = "$lit" ]
}

reset_hold() {
	"$GT" dirty $FB || return 1
	gpioset -c "$CHIP" RESET_N=0 &
	p=$!
	held RESET_N || { kill $p; return 1; }
	rc=0
	"$GT" reset $FB held || rc=1
	gpioget -c "$CHIP" TE | grep -q '"TE"=inactive' || { echo "TE high in reset"; rc=1; }
	"$GT" frames $FB 3 | tee "$T/frames"
	grep -q '^FRAME_COUNT 0 0$' "$T/frames" || rc=1
	kill $p
	wait $p 2>/dev/null
	drive RESET_N=1 || return 1
	"$GT" reset $FB released || rc=1
	return $rc
}

paced_gpiomon() {
	timeout 60 gpiomon -c "$CHIP" -e rising -n $FRAMES -F '%S' TE >"$T/mon" ||
		return 1
	got=$(wc -l <"$T/mon")
	# a missing edge would make the span one frame longer
	awk -v T="$("$GT" period $FB)" 'NR > 1 { d = $1 - p; s += d;
		if (!mn || d < mn) mn = d; if (d > mx) mx = d } { p = $1 }
		END { printf "# %d edges: mean period %.1f us (%.2f Hz; the mode: %.1f us), min %.1f us, max %.1f us; edges missing by the span: %d\n",
			NR, s / (NR - 1) * 1e6, (NR - 1) / s, T / 1e3, mn * 1e6,
			mx * 1e6, int(s * 1e9 / T + 0.5) - (NR - 1) }' "$T/mon"
	[ "$got" = $FRAMES ]
}

unload_refused() {
	gpiomon -c "$CHIP" TE >/dev/null &
	p=$!
	held TE || { kill $p; return 1; }
	rc=0
	rmmod rdcfb 2>&1 && { echo "rmmod went through with TE requested"; rc=1; }
	kill $p
	wait $p 2>/dev/null
	[ $rc = 0 ] && rmmod rdcfb
}

dmesg -C
fbcon_unbind
[ -c $FB ] || { echo "no $FB"; exit 1; }
CHIP=$(chip_of $LABEL)
[ -n "$CHIP" ] || { echo "no GPIO chip labelled $LABEL"; gpiodetect; exit 1; }

check "gpiodetect and gpioinfo show $LABEL and its four lines" lists_lines
check "gpioinfo and gpioget find the lines by name" by_name
check "stepped: gpiomon sees one rising and one falling TE edge per frame, $FRAMES frames" te_frames
check "stepped: the IRQ line pulses with the vblank IRQ, 20 times" irq_pulses
check "gpioset BL_EN=0 darkens the frames, =1 brings the picture back" dark_then_lit
check "RESET_N low holds the chip in reset (reset values, DP idle, no frames)" reset_hold
check "after RESET_N, circles.rdl through fbdev: = sim:" \
	same_run "$RDC_TREE/tests/golden/scenes/circles.rdl"

rmmod rdcfb || { echo "cannot unload the stepped module"; finish; exit 1; }
insmod "$KO" clock=paced mode=320x200-32 || { echo "insmod paced failed"; exit 1; }
fbcon_unbind
CHIP=$(chip_of $LABEL)
check "paced: gpiomon sees $FRAMES TE rising edges" paced_gpiomon
check "paced: TE jitter and lost edges over 600 frames (TAP below)" \
	"$GT" jitter $FB $LABEL 600
echo "# driver: $(cat $SYS/pin_edges) edges delivered, $(cat $SYS/pin_lost) lost," \
	"late by $(cat $SYS/pin_late_avg_ns) ns on average, $(cat $SYS/pin_late_max_ns) ns at most"
check "paced: 120 fills presented on TE never tear; at random moments they do" \
	"$GT" present $FB $LABEL 120
check "unload refused while gpiomon holds TE; clean once it lets go" unload_refused

dmesg >"$T/dmesg.log"
check "no WARN, BUG or oops in dmesg, no edge lost" \
	sh -c "! grep -E 'WARNING|BUG|Oops|general protection|Call Trace|edges lost|REMOVING' '$T/dmesg.log'"

# leave it loaded for the harness to unload
insmod "$KO"
fbcon_unbind
finish
