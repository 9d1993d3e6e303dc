#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The DisplayLink personality's whole loop and life cycle (docs/usb.md),
# beside udl-drm (which checks binding, modes and exact frames):
# - fbcon on udl's fbdev emulation: text written to the console shows in
#   the RDC-1's frame, inside the text's character cells and nowhere else;
# - kernel DRM -> USB -> RDC-1 -> `rdcctl stream` (rdcd's observer) ->
#   v4l2loopback -> ffmpeg: the frames ffmpeg reads are drm_pattern's
#   pattern through RGB565 and rgb24, exactly; DRM offers 640x480 twice
#   (the preset, and the CTA-861 twin it adds at 25.2 MHz): udl-drm's
#   640x480 check takes the first, this one the other, and each frame
#   check reads the CRTC's pixel clock back (the mode's);
# - unplug (unbind the UDC) while a client draws full frames: udl lets go
#   (the client gets ENODEV), no oops or warning in dmesg, rdcd stays up;
#   binding again brings a connected card back and a pattern draws exactly.
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
# vm-module: udl
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"
# where the guest's time goes (a figure, not a condition)
up() {
	echo "# guest uptime $(cut -d' ' -f1 /proc/uptime) s: $*"
}
up start

usb_require
udl_vars
[ -x "$DRMP" ] || { echo "drm_pattern is not built (no libdrm-dev?)"; exit 77; }
command -v modetest >/dev/null || { echo "modetest missing (libdrm-tests)"; exit 77; }
command -v stty >/dev/null || { echo "stty missing"; exit 77; }

udl_ready() {
	udl_up && udl_card 60
}
dmesg -c >/dev/null 2>&1
check "the gadget enumerates and udl's connector is connected" udl_ready

up fbcon
# ---- fbcon ---------------------------------------------------------------------
fbdev_udl() {
	for f in /sys/class/graphics/fb[0-9]*; do
		grep -q udl "$f/name" 2>/dev/null &&
			{ echo "$(basename "$f"): $(cat "$f/name")"; return 0; }
	done
	return 1
}
check "the fbdev emulation gives /dev/fbN (udl's)" fbdev_udl
fbcon_bound() {
	v=$(fbcon_vt) && cat "$v/name" && [ "$(cat "$v/bind")" = 1 ]
}
check "fbcon is bound" fbcon_bound
TTY=/dev/tty1
# no blinking cursor: the frame changes only with the text
echo 0 >/sys/class/graphics/fbcon/cursor_blink 2>/dev/null
printf '\033[?25l\033[2J\033[H' >$TTY
check "the cleared console: the RDC-1's frame is black" \
	"$DRMP" --ink "$OBS" 0,0,0,0
crc0=$("$DRMP" --crc "$OBS")
# the character cell: the frame's size (the fbdev emulation takes the
# preferred mode, rdcd's --mode 1024x768 in udl_up) over the console's
# rows and columns
set -- $(stty -F $TTY size) 0 0
rows=$1
cols=$2
text="RDC-1 udl fbcon"
printf '\033[5;10H%s' "$text" >$TTY
fw=$((1024 / (cols ? cols : 1)))
fh=$((768 / (rows ? rows : 1)))
echo "# console $cols x $rows, cells ${fw}x$fh"
check "console text: lit pixels in its cells (row 5, column 10) only" \
	"$DRMP" --ink "$OBS" $((9 * fw)),$((4 * fh)),$((${#text} * fw)),$fh
crc1=$("$DRMP" --crc "$OBS")
check "the frame's CRC changed with the text" sh -c \
	'echo "CRC $1 -> $2"; [ -n "$1" ] && [ -n "$2" ] && [ "$1" != "$2" ]' \
	sh "$crc0" "$crc1"

up the loop to ffmpeg
# ---- DRM -> USB -> RDC-1 -> v4l2loopback -> ffmpeg ------------------------------
# drm_pattern holds the mode while this runs, then compares what ffmpeg
# wrote with its pattern
cat >"$T/v4l2-loop.sh" <<'EOF'
. "$RDC_TREE/tests/vm/lib.sh"
writer_start --from "$1" --format rgb24
wait_device 60 || { echo "no format on $DEV"; writer_stop; exit 1; }
rm -f "$T/ff.raw"
ffmpeg -nostdin -hide_banner -loglevel error -f v4l2 -i "$DEV" \
	-frames:v 3 -c:v rawvideo -f rawvideo -y "$T/ff.raw"
rc=$?
writer_stop
exit $rc
EOF
modetest -M udl -c >"$T/modetest.txt" 2>&1
# "#1 640x480 59.94 640 656 752 800 480 490 492 525 25175 flags: ..."
awk '$1 ~ /^#[0-9]+$/ && $2 == "640x480"' "$T/modetest.txt" | sed 's/^ */# /'
clocks=$(awk '$1 ~ /^#[0-9]+$/ && $2 == "640x480" && $12 ~ /^[0-9]+$/ {
	print $12 }' "$T/modetest.txt")
check "DRM offers 640x480 twice (the preset and its CTA-861 twin)" \
	test "$(echo $clocks | wc -w)" = 2
# the loop at the last: udl-drm's 640x480 check takes the first
set -- $clocks
eval c=\${$#}
check "640x480 at $c kHz: ffmpeg reads the pattern via v4l2loopback" \
	"$DRMP" --uri "$OBS" --mode 640x480 --clock "$c" \
	--exec "sh $T/v4l2-loop.sh '$OBS'" --raw "$T/ff.raw" rgb24

up unplug
# ---- unplug while drawing, and back ---------------------------------------------
"$DRMP" --mode 1024x768 --loop >"$T/loop.log" 2>&1 &
loop=$!
# and the connector probed over and over (each probe reads the EDID, a
# control request a byte on 6.1), so that the unplug lands in the middle
# of a control transfer as well as of a bulk one
(while echo detect >"$CONN/status" 2>/dev/null; do :; done) &
prober=$!
sleep 1
dmesg -c >/dev/null 2>&1
check "unplug (unbind the UDC) while a client draws and the host reads the EDID" \
	usb_unplug
up unplugged
check "the drawing client sees the card go and exits" sh -c '
	i=0
	while kill -0 $1 2>/dev/null && [ $i -lt 300 ]; do
		sleep 0.1
		i=$((i + 1))
	done
	! kill -0 $1 2>/dev/null' sh $loop
up the client has exited
kill $loop $prober 2>/dev/null
wait $loop
st=$?
wait $prober 2>/dev/null
echo "# the drawing client's exit status $st: $(tr '\n' ' ' <"$T/loop.log")"
dmesg >"$T/dmesg.txt" 2>&1
# udl logs a URB it could not submit once the device has gone (-ENODEV),
# and the EDID byte whose control request the unplug cut short (-EPROTO,
# -ESHUTDOWN, -ENODEV or a timeout: docs/usb.md): those, and no oops, BUG,
# warning or other error
check "dmesg after the unplug: no oops, BUG, warning or other error" sh -c '
	grep -Ei "udl|drm|usb" "$1" | sed "s/^/    /"
	! grep -Ei "oops|bug:|warn|call trace|error|fail" "$1" |
	  grep -v "udl_submit_urb.*usb_submit_urb error ffffffed" |
	  grep -Ev "Read EDID byte [0-9]+ failed err (ffffffb9|ffffff94|ffffffed|ffffff92)$"' \
	sh "$T/dmesg.txt"
check "rdcd still runs" usb_rdcd_alive
check "rdcd's control endpoint outlived the unplug (no ep0 error)" sh -c '
	! grep -E "error: .*ep0" "$1"' sh "$USB_RDCD_LOG"
replug() {
	usb_replug && udl_card 60
}
up bind again
check "binding again brings a connected card back" replug
up the card is back
check "and a pattern draws exactly again (800x600)" \
	"$DRMP" --uri "$OBS" --mode 800x600
up down
check "the gadget goes down cleanly" usb_gadget_down
up end
finish
