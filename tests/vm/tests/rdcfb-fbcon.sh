#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# fbcon binds to rdcfb's /dev/fb0 and text written to the console is drawn
# by the display processor (its command counter rises) as the console font's
# glyphs in the scanned-out frame, pixel for pixel; `ffmpeg -f fbdev`
# reads a frame equal to the device's own (FRAME ioctl CRC).  Then the
# self-benchmark: the console's imageblit and scroll through the DP
# against the kernel's sys_imageblit/sys_copyarea, as TAP comments.
# vm-module: rdcfb
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$B/rdcfb_tool
SYS=/sys/bus/platform/devices/rdcfb.0
TTY=/dev/tty1
# The expected picture comes from the font the console itself draws with
# (read back through KDFONTOP), not from the RDC-1's own.
TEXT="The quick brown fox jumps over 13 lazy dogs!"

fbcon_bound() {
	v=$(fbcon_vt) && [ "$(cat "$v/bind")" = 1 ] && grep -q "^0 rdcfb" /proc/fb
}

# the frame shows TEXT on the top line (retried while frames come in)
text_shown() {
	i=0
	while [ $i -lt 40 ]; do
		"$TOOL" text /dev/fb0 "$TTY" 0 0 "$TEXT" >"$T/text.out" 2>&1 &&
			{ cat "$T/text.out"; return 0; }
		sleep 0.25
		i=$((i + 1))
	done
	cat "$T/text.out"
	return 1
}

# ffmpeg's frame from /dev/fb0 has the CRC of the device's own frame
ffmpeg_matches() {
	k=0
	while [ $k -lt 5 ]; do
		rm -f "$T/ff.raw"
		ffmpeg -nostdin -hide_banner -loglevel error -f fbdev \
			-i /dev/fb0 -frames:v 1 -c:v rawvideo -f rawvideo \
			-y "$T/ff.raw" || return 1
		ff=$("$TOOL" rawcrc "$T/ff.raw")
		dev=$("$TOOL" frame /dev/fb0 "$T/dev.raw") || return 1
		echo "ffmpeg $ff, device $dev ($(wc -c <"$T/ff.raw") bytes)"
		[ "$ff" = "${dev##* }" ] && return 0
		k=$((k + 1))
		sleep 0.5
	done
	return 1
}

check "fbcon is bound to /dev/fb0 (rdcfb)" fbcon_bound
# a still console: no blinking cursor to race the frame grabs
echo 0 >/sys/class/graphics/fbcon/cursor_blink 2>/dev/null
printf '\033[?25l\033[2J\033[H' >"$TTY"
sleep 1
c0=$(cat "$SYS/cmds")
p0=$(cat "$SYS/pixels")
printf '%s' "$TEXT" >"$TTY"
check "the console's text is in the scanned-out frame, glyph for glyph" \
	text_shown
c1=$(cat "$SYS/cmds")
p1=$(cat "$SYS/pixels")
area=$((${#TEXT} * 8 * 16))
check "the DP drew it: commands $c0 -> $c1, pixels $p0 -> $p1 (text: $area)" \
	test "$c1" -gt "$c0" -a $((p1 - p0)) -ge "$area"
check "ffmpeg -f fbdev reads the device's frame" ffmpeg_matches
# EAGAIN while no whole frame is kept (scanout on demand: nobody looked
# while fbcon drew); the failed look keeps the next ones
frame_crc() {
	i=0
	until c=$(cat "$SYS/frame_crc" 2>/dev/null); do
		i=$((i + 1))
		[ $i -lt 40 ] || return 1
		sleep 0.05
	done
	echo "$c" | grep -E '^[0-9a-f]{8} '
}
check "frame_crc in sysfs" frame_crc

mount -t debugfs none /sys/kernel/debug 2>/dev/null
if [ -r /sys/kernel/debug/rdcfb/fb0/bench ]; then
	check "self-benchmark runs" cp /sys/kernel/debug/rdcfb/fb0/bench "$T/bench"
	sed 's/^/# bench: /' "$T/bench"
fi

# let the harness unload the module: fbcon holds it while bound
fbcon_unbind
finish
