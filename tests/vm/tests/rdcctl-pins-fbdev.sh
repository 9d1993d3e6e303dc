#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# librdc's fbdev: pins, which go through rdcfb.ko's GPIO chip with
# libgpiod: rdcctl pins reads the four levels, --watch on the stepped
# clock moves time itself and sees TE's edges alternate, one rising edge a
# frame; --set BL_EN=0 makes the frames black and =1 brings the picture
# back; --set RESET_N=0 holds the chip at its reset values and, released,
# a scene draws as sim: draws it; no line stays requested afterwards.
# vm-module: rdcfb clock=stepped mode=320x200-32
. "$RDC_TREE/tests/vm/lib.sh"

FB=fbdev:/dev/fb0
scene=$SCENES/stream_a.rdl
# the console would draw on the device, and it holds the module
fbcon_unbind

if ! "$RDCCTL" --connect $FB pins >"$T/pins" 2>&1; then
	cat "$T/pins"
	if grep -q "not supported" "$T/pins"; then
		echo "no GPIO lines: librdc without libgpiod, or rdcfb.ko without its gpio_chip"
		exit 77
	fi
fi

ctl() {
	"$RDCCTL" --connect $FB "$@"
}

reg() {
	ctl regs | awk -v n="$1" '$2 == n { print $4 }'
}

crc() {
	"$RDCCTL" --connect "${2:-$FB}" run "$1" | awk '$1 == "crc32" { print $2 }'
}

check "rdcctl pins reads the levels" \
	sh -c "cat $T/pins; grep -q 'RESET_N=1 BL_EN=1' $T/pins"

watch_te() {
	f0=$(reg FRAME_COUNT)
	ctl pins --watch --pin TE --count 8 >"$T/watch" || return 1
	f1=$(reg FRAME_COUNT)
	cat "$T/watch"
	r=$(grep -c rising "$T/watch")
	f=$(grep -c falling "$T/watch")
	echo "frames $f0 -> $f1: $r rising, $f falling"
	cut -f2 "$T/watch" | tr '\n' ' ' | grep -q 'rising rising\|falling falling' &&
		{ echo "two edges of one kind in a row"; return 1; }
	[ "$r" = 4 ] && [ "$f" = 4 ] && [ $((f1 - f0)) = 4 ]
}
check "--watch moves the stepped clock: TE alternates, a rising edge a frame" \
	watch_te

printf 'mode 320x200 xrgb8888\n' >"$T/black.rdl"
printf '# nothing\n' >"$T/none.rdl"
black=$(crc "$T/black.rdl" sim:)
want=$(crc "$scene" sim:)
check "the scene draws through fbdev: as on sim:" test "$(crc "$scene")" = "$want"
set_and_show() {
	ctl pins --set "$1" && ctl pins | tee /dev/stderr | grep -q "$1"
}
check "--set BL_EN=0" set_and_show BL_EN=0
dark=$(crc "$T/none.rdl")
echo "# lit $want, dark $dark, black $black"
check "BL_EN low: the frames are black" test "$dark" = "$black"
check "--set BL_EN=1" set_and_show BL_EN=1
check "BL_EN high: the picture is back" test "$(crc "$T/none.rdl")" = "$want"

check "--set RESET_N=0" set_and_show RESET_N=0
check "held in reset: registers at their reset values" \
	test "$(reg H_DISPLAY)" = 640 -a "$(reg IRQ_ENABLE)" = 0
check "--set RESET_N=1" set_and_show RESET_N=1
check "after the reset the scene draws as on sim:" \
	test "$(crc "$scene")" = "$want"
chip=$(gpiodetect | sed -n 's/^\(gpiochip[0-9]*\) \[rdcfb\.0-pins\].*/\1/p')
check "no line stays requested by librdc" \
	sh -c "gpioinfo -c $chip; ! gpioinfo -c $chip | grep -q librdc"
finish
