# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Helpers for tests/vm/tests/*.sh, which run in the guest chrooted into
# the host's root with RDC_TREE (source tree) and RDC_BUILD (build dir)
# set.  A test prints TAP lines through check() and ends with finish; its
# exit status is its result (0 pass, 77 skip, else fail).

B=$RDC_BUILD/rel
RDCCTL=$B/rdcctl
READ=$B/v4l2_read
SCENES=$RDC_TREE/tests/vm/scenes
DEV=/dev/video0
T=${TMPDIR:-/tmp}
n=0
failed=0
WRITER=""

# check DESCRIPTION COMMAND...: one TAP line, the command's output below.
check() {
	desc=$1
	shift
	n=$((n + 1))
	if "$@" >$T/check.out 2>&1; then
		echo "ok $n - $desc"
	else
		echo "not ok $n - $desc"
		failed=$((failed + 1))
	fi
	sed 's/^/    /' $T/check.out
}

# The frame source writing into $DEV; arguments are rdcctl stream's.
writer_start() {
	"$RDCCTL" stream --v4l2 "$DEV" "$@" >$T/writer.log 2>&1 &
	WRITER=$!
}

writer_alive() {
	[ -n "$WRITER" ] && kill -0 "$WRITER" 2>/dev/null
}

writer_stop() {
	[ -n "$WRITER" ] || return 0
	kill "$WRITER" 2>/dev/null
	wait "$WRITER"
	sed 's/^/    writer: /' $T/writer.log
	WRITER=""
}

# Wait until the device has a format (a writer wrote), at most $1 s.
# v4l2loopback's sysfs "format" is empty until then; G_FMT is not a sign
# (0.13 answers it with a default before any writer).
wait_device() {
	i=0
	while [ $i -lt $(($1 * 10)) ]; do
		[ -n "$(cat "/sys/class/video4linux/${DEV#/dev/}/format" \
			2>/dev/null)" ] && return 0
		sleep 0.1
		i=$((i + 1))
	done
	return 1
}

# ffmpeg_frames FORMAT SCENE N: ffmpeg -f v4l2 captures N frames from $DEV,
# each must be SCENE's picture in FORMAT, byte for byte.
ffmpeg_frames() {
	rm -f "$T/ff.raw"
	ffmpeg -nostdin -hide_banner -loglevel error -f v4l2 -i "$DEV" \
		-frames:v "$3" -c:v rawvideo -f rawvideo -y "$T/ff.raw" &&
		"$READ" --raw "$T/ff.raw" --format "$1" --expect "$2" --frames "$3"
}

# The virtual terminal fbcon runs on (its sysfs directory).
fbcon_vt() {
	for v in /sys/class/vtconsole/vtcon*; do
		if grep -q "frame buffer" "$v/name" 2>/dev/null; then
			echo "$v"
			return 0
		fi
	done
	return 1
}

# Take fbcon off the framebuffer: a console drawing on the device changes
# its frames, and holds the module while bound (as for any fb driver).
fbcon_unbind() {
	v=$(fbcon_vt) && echo 0 >"$v/bind"
	return 0
}

finish() {
	writer_stop
	echo "1..$n"
	[ $failed -eq 0 ]
}

# ---- USB: the RDC-1 as a USB device on the guest's own bus (docs/usb.md) ----
# rdcd serves FunctionFS (--listen ffs:) behind a configfs gadget
# (scripts/rdc-gadget.sh) bound to dummy_hcd's UDC, so the guest is both
# the device and the host.  Tests declare:
#   # vm-module: dummy_hcd
#   # vm-module: libcomposite
#   # vm-module: usb_f_fs
# usb_require exits 77 (skip) saying why when that cannot work here.
# From usb_require on, a test that exits before taking its gadgets down
# (a skip, a failure) has them taken down on its way out (usb_atexit):
# the harness unloads the modules after each test and fails one that
# leaves a module it loaded behind (tests/vm/README.md).
GADGET=$RDC_TREE/scripts/rdc-gadget.sh
USB_RDCD=${USB_RDCD:-$B/rdcd} # rdcd to run (a test may pick san/rdcd)
USB_VID=1209
USB_PID=0001
USB_SERIAL=rdcvm$$
USB_FFS=/dev/ffs-rdc
USB_SOCK=$T/rdc.sock       # rdcd's UNIX socket beside the gadget
USB_RDCD_LOG=$T/rdcd.log
USB_RDCD_PID=""
USB_SYSFS=""               # /sys/bus/usb/devices/B-P once enumerated
USB_BUSNUM=""
USB_DEVNUM=""
export RDC_GADGET_STATE=$T/gadget

usb_require() {
	trap usb_atexit EXIT
	if ! [ -x "$USB_RDCD" ] || ! "$USB_RDCD" --help | grep -q 'ffs:'; then
		echo "rdcd is not built, or has no ffs: listener"
		exit 77
	fi
	if ! grep -q configfs /proc/mounts &&
		mount -t configfs none /sys/kernel/config 2>/dev/null; then
		USB_CONFIGFS=1 # unmounted by usb_gadget_down: modules unload
	fi
	if ! [ -d /sys/kernel/config/usb_gadget ]; then
		echo "no configfs usb_gadget (libcomposite not loaded?)"
		exit 77
	fi
	if [ -z "$(ls /sys/class/udc 2>/dev/null)" ]; then
		echo "no UDC (dummy_hcd not loaded?)"
		exit 77
	fi
}

# usb_atexit: the EXIT trap: stop what the test left running (rdcd, a
# writer), take down every gadget rdc-gadget.sh still keeps state for,
# and unmount configfs if usb_require mounted it; the exit status stays.
# A skip's reason is the last line it printed: quiet then.
usb_atexit() {
	arc=$?
	trap - EXIT
	if [ $arc = 77 ]; then
		usb_takedown >/dev/null 2>&1
	else
		usb_takedown
	fi
	exit $arc
}

usb_takedown() {
	writer_stop
	if [ -n "$USB_RDCD_PID" ]; then
		echo "# on exit: rdcd $USB_RDCD_PID still runs: stopped"
		timeout 30 "$GADGET" unbind >/dev/null 2>&1
		usb_rdcd_stop
	fi
	for s in "$RDC_GADGET_STATE"/*; do
		[ -d "$s" ] || continue
		echo "# on exit: gadget $(basename "$s") still up: taken down"
		"$GADGET" down --name "$(basename "$s")"
	done
	[ -z "${USB_CONFIGFS:-}" ] || ! grep -q " /sys/kernel/config configfs " \
		/proc/mounts || umount /sys/kernel/config
}

# usb_find: set USB_SYSFS, USB_BUSNUM, USB_DEVNUM for our device (by
# VID:PID and serial); false if it is not on the bus.
usb_find() {
	for u in /sys/bus/usb/devices/*; do
		[ -r "$u/idVendor" ] && [ -r "$u/serial" ] || continue
		[ "$(cat "$u/idVendor" 2>/dev/null)" = $USB_VID ] &&
			[ "$(cat "$u/idProduct" 2>/dev/null)" = $USB_PID ] &&
			[ "$(cat "$u/serial" 2>/dev/null)" = "$USB_SERIAL" ] ||
			continue
		# configured, and its interface bound or at least listed
		[ "$(cat "$u/bConfigurationValue" 2>/dev/null)" = 1 ] || continue
		USB_SYSFS=$u
		USB_BUSNUM=$(cat "$u/busnum" 2>/dev/null)
		USB_DEVNUM=$(cat "$u/devnum" 2>/dev/null)
		return 0
	done
	USB_SYSFS=""
	return 1
}

# usb_wait present|gone SECONDS
usb_wait() {
	i=0
	while [ $i -lt $(($2 * 10)) ]; do
		if usb_find; then
			[ "$1" = present ] && return 0
		else
			[ "$1" = gone ] && return 0
		fi
		sleep 0.1
		i=$((i + 1))
	done
	echo "usb: device $USB_VID:$USB_PID serial $USB_SERIAL not $1 after $2 s"
	return 1
}

# usb_gadget_up [RDCD_ARGS...]: rdcd --stepped --listen ffs:$USB_FFS
# --listen unix:$USB_SOCK ARGS (pid $USB_RDCD_PID, log $USB_RDCD_LOG), the
# gadget bound to the first UDC; returns once the host side has it
# configured (USB_SYSFS, USB_BUSNUM, USB_DEVNUM set).
usb_gadget_up() {
	"$GADGET" up --dir "$USB_FFS" --serial "$USB_SERIAL" \
		>"$T/gadget.log" 2>&1 || { cat "$T/gadget.log"; return 1; }
	rm -f "$USB_SOCK" "$T/rdcd.ready"
	"$USB_RDCD" --stepped --listen "ffs:$USB_FFS" --listen "unix:$USB_SOCK" \
		--ready-file "$T/rdcd.ready" "$@" >"$USB_RDCD_LOG" 2>&1 &
	USB_RDCD_PID=$!
	i=0
	while ! [ -s "$T/rdcd.ready" ]; do
		if [ $i -ge 300 ] || ! kill -0 $USB_RDCD_PID 2>/dev/null; then
			echo "usb: rdcd did not start"
			sed 's/^/    rdcd: /' "$USB_RDCD_LOG"
			return 1
		fi
		sleep 0.1
		i=$((i + 1))
	done
	"$GADGET" bind >>"$T/gadget.log" 2>&1 ||
		{ cat "$T/gadget.log"; return 1; }
	usb_wait present 30
}

# usb_rdcd_stop: SIGTERM to rdcd, its exit status (after 30 s: its
# threads' kernel stacks are shown and it is killed); its log is shown.
usb_rdcd_stop() {
	[ -n "$USB_RDCD_PID" ] || return 0
	kill -TERM $USB_RDCD_PID 2>/dev/null
	i=0
	while usb_running $USB_RDCD_PID && [ $i -lt 300 ]; do
		sleep 0.1
		i=$((i + 1))
	done
	if usb_running $USB_RDCD_PID; then
		echo "usb: rdcd still runs 30 s after SIGTERM; its threads:"
		for t in /proc/$USB_RDCD_PID/task/*; do
			echo "  $(cat $t/comm) in $(cat $t/wchan)"
			sed 's/^/    /' $t/stack 2>/dev/null
		done
		kill -KILL $USB_RDCD_PID
	fi
	wait $USB_RDCD_PID
	rc=$?
	USB_RDCD_PID=""
	sed 's/^/    rdcd: /' "$USB_RDCD_LOG"
	return $rc
}

# usb_gadget_down: unplug, stop rdcd, remove the gadget; returns rdcd's
# exit status (or failure if the gadget could not be removed).
usb_gadget_down() {
	drc=0
	timeout 30 "$GADGET" unbind >/dev/null 2>&1 ||
		{ echo "usb: unbinding the gadget failed or hung"; drc=1; }
	usb_rdcd_stop || drc=$?
	"$GADGET" down || drc=1
	[ -z "${USB_CONFIGFS:-}" ] || umount /sys/kernel/config 2>/dev/null
	return $drc
}

# usb_wait_log FILE PATTERN SECONDS: until FILE has a line with PATTERN
usb_wait_log() {
	i=0
	while ! grep -q "$2" "$1" 2>/dev/null; do
		[ $i -lt $(($3 * 10)) ] || { echo "no '$2' in $1"; return 1; }
		sleep 0.1
		i=$((i + 1))
	done
}

# usb_running PID: a process that has not exited (zombies have)
usb_running() {
	[ -r /proc/$1/stat ] &&
		! sed 's/^.*) //' /proc/$1/stat 2>/dev/null | grep -q '^Z'
}

# usb_unplug / usb_replug: unbind the gadget from its UDC (the host sees a
# disconnect) and bind it again; each waits for the host side to agree.
usb_unplug() {
	"$GADGET" unbind && usb_wait gone 20
}

usb_replug() {
	"$GADGET" bind && usb_wait present 20
}

usb_rdcd_alive() {
	[ -n "$USB_RDCD_PID" ] && usb_running $USB_RDCD_PID
}

# ---- The DisplayLink personality (docs/usb.md): udl-*.sh ----------------------
# udl_vars: the gadget's IDs and FunctionFS directory, rdcd's socket as an
# observer (OBS) and the DRM client (DRMP); call after usb_require.
udl_vars() {
	USB_VID=17e9
	USB_PID=5244
	USB_FFS=/dev/ffs-udl
	OBS="unix:$USB_SOCK?observe"
	DRMP=$B/drm_pattern
}

# udl_up: the gadget with DisplayLink's IDs, rdcd --listen udl: (paced,
# 1024x768 its preferred mode) and --listen unix:$USB_SOCK, bound to the
# UDC; returns once the host has it configured.
udl_up() {
	"$GADGET" up --personality udl --dir "$USB_FFS" \
		--serial "$USB_SERIAL" >"$T/gadget.log" 2>&1 ||
		{ cat "$T/gadget.log"; return 1; }
	rm -f "$USB_SOCK" "$T/rdcd.ready"
	"$USB_RDCD" --listen "udl:$USB_FFS" --listen "unix:$USB_SOCK" \
		--ready-file "$T/rdcd.ready" --mode 1024x768 -v \
		>"$USB_RDCD_LOG" 2>&1 &
	USB_RDCD_PID=$!
	i=0
	while ! [ -s "$T/rdcd.ready" ]; do
		[ $i -lt 300 ] && kill -0 $USB_RDCD_PID 2>/dev/null ||
			{ cat "$USB_RDCD_LOG"; return 1; }
		sleep 0.1
		i=$((i + 1))
	done
	"$GADGET" bind >>"$T/gadget.log" 2>&1 || { cat "$T/gadget.log"; return 1; }
	usb_wait present 30
}

# udl_card: the sysfs directory of the udl card, once its connector is
# connected (the EDID read), at most $1 s
udl_card() {
	i=0
	while [ $i -lt $(($1 * 10)) ]; do
		for c in /sys/class/drm/card[0-9]*; do
			case $c in *-*) continue ;; esac
			[ "$(basename "$(readlink -f "$c/device/driver")")" = udl ] ||
				continue
			for k in "$c"/"$(basename "$c")"-*; do
				[ "$(cat "$k/status" 2>/dev/null)" = connected ] &&
					{ CARD=$c; CONN=$k; return 0; }
			done
		done
		sleep 0.1
		i=$((i + 1))
	done
	echo "no udl card with a connected connector after $1 s"
	ls -l /sys/class/drm/ 2>&1
	return 1
}
