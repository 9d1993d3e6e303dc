# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Helpers for the desktop-* VM tests: real compositors (Debian's weston,
# Xorg with the modesetting driver, cage on wlroots) started on the
# card of the DRM driver named $DESKTOP_DRIVER (rdc: rdcdrm.ko), with no
# input devices, software rendering and the guest's tmpfs for their
# runtime files; sourced after lib.sh.

DESKTOP_DRIVER=${DESKTOP_DRIVER:-rdc}
FRAME_CHECK=$B/frame_check
DESKTOP_PID=""

# The card of the device whose driver is $DESKTOP_DRIVER* (rdcdrm's
# platform driver), e.g. /dev/dri/card0.
desktop_card() {
	for c in /sys/class/drm/card[0-9]*; do
		case $c in *-*) continue ;; esac
		d=$(basename "$(readlink -f "$c/device/driver")")
		case $d in "$DESKTOP_DRIVER"*)
			echo "/dev/dri/$(basename "$c")"
			return 0
			;;
		esac
	done
	return 1
}

# wait_for SECONDS COMMAND...: until the command succeeds.
wait_for() {
	secs=$1
	shift
	i=0
	while [ $i -lt $((secs * 10)) ]; do
		"$@" >/dev/null 2>&1 && return 0
		sleep 0.1
		i=$((i + 1))
	done
	return 1
}

# /run is the host's, read-only: seatd and the compositors get a tmpfs.
# Shared memory (POSIX shm, as grim's buffers) needs /dev/shm, which the
# guest's devtmpfs lacks.  X servers (Xorg, cage's Xwayland) put their
# lock files and sockets in /tmp, which is the host's, read-only, when
# the tree lives under /tmp (the tests' scratch is /run then): a
# writable overlay goes over it, the tree still showing through.
DESKTOP_MOUNTS=""
desktop_run_tmpfs() {
	if [ "$T" = /run ]; then
		mkdir -p /run/rdc-tmp-upper /run/rdc-tmp-work
		chmod 1777 /run/rdc-tmp-upper
		if mount -t overlay overlay -o lowerdir=/tmp,upperdir=/run/rdc-tmp-upper,workdir=/run/rdc-tmp-work /tmp; then
			DESKTOP_MOUNTS="/tmp $DESKTOP_MOUNTS"
		else
			echo "# /tmp stays read-only: X servers may not start"
		fi
	else
		mount -t tmpfs run /run && DESKTOP_MOUNTS="/run $DESKTOP_MOUNTS"
	fi
	mkdir -p /dev/shm
	if ! mountpoint -q /dev/shm; then
		mount -t tmpfs -o mode=1777 shm /dev/shm &&
			DESKTOP_MOUNTS="/dev/shm $DESKTOP_MOUNTS"
	fi
}

# What desktop_run_tmpfs mounted goes, for the tests after this one, and
# the consoles a compositor may have left in graphics mode (killed, it
# cannot restore them) are text consoles again, the first one in front:
# fbcon draws nothing on a console in graphics mode.
desktop_cleanup() {
	for m in $DESKTOP_MOUNTS; do
		umount "$m" || umount -l "$m"
	done
	DESKTOP_MOUNTS=""
	/usr/bin/python3 -c '
import fcntl, os
KDSETMODE, KD_TEXT = 0x4B3A, 0
for n in (1, 2, 3):
    try:
        fd = os.open("/dev/tty%d" % n, os.O_RDWR | os.O_NOCTTY)
    except OSError:
        continue
    try:
        fcntl.ioctl(fd, KDSETMODE, KD_TEXT)
    except OSError:
        pass
    os.close(fd)
' 2>/dev/null
	busybox chvt 1 2>/dev/null || chvt 1 2>/dev/null
}

# Weston on the card, pixman renderer, direct launcher on a VT, the
# screenshooter allowed (--debug); clients reach it at $WAYLAND_DISPLAY.
# The panel shows no clock: a minute turning between a screenshot and
# the chip's frame would tell them apart.
weston_start() {
	export XDG_RUNTIME_DIR=$T/xdg
	mkdir -p -m 700 "$XDG_RUNTIME_DIR"
	export WAYLAND_DISPLAY=wl-rdc
	printf '[shell]\nclock-format=none\n' >$T/weston.ini
	weston --tty=2 --debug --backend=drm-backend.so --use-pixman \
		--config=$T/weston.ini --drm-device="$(basename "$CARD")" \
		--continue-without-input --idle-time=0 --socket=$WAYLAND_DISPLAY \
		--log=$T/weston.log "$@" >$T/weston.out 2>&1 &
	DESKTOP_PID=$!
	wait_for 60 test -S "$XDG_RUNTIME_DIR/$WAYLAND_DISPLAY"
}

# Stop the compositor started last and report how it ended: 0 when it
# exited cleanly.  It is asked to with SIGTERM, or, with an argument, by
# ending that process (cage ends with its client).
desktop_stop() {
	[ -n "$DESKTOP_PID" ] || return 0
	if [ -n "${1:-}" ]; then
		pkill -TERM -x "$1"
	else
		kill -TERM "$DESKTOP_PID" 2>/dev/null
	fi
	i=0
	while kill -0 "$DESKTOP_PID" 2>/dev/null && [ $i -lt 200 ]; do
		sleep 0.1
		i=$((i + 1))
	done
	if kill -0 "$DESKTOP_PID" 2>/dev/null; then
		echo "the compositor did not exit in 20 s"
		kill -KILL "$DESKTOP_PID"
		wait "$DESKTOP_PID"
		DESKTOP_PID=""
		return 1
	fi
	wait "$DESKTOP_PID"
	rc=$?
	DESKTOP_PID=""
	echo "the compositor exited with status $rc"
	# A signal's own status (128 + SIGTERM) is a clean exit for a
	# compositor that does not catch it.
	[ $rc = 0 ] || [ $rc = 143 ]
}

# The chip's frame counter (FRAME_COUNT) through librdc's drm: backend.
chip_frames() {
	"$RDCCTL" --connect "drm:$CARD" regs |
		awk '$2 == "FRAME_COUNT" { print $4 }'
}

# Xorg with the modesetting driver on the card: no glamor, a shadow
# framebuffer, no input devices needed; the display is :1.
xorg_start() {
	cat >$T/xorg.conf <<XEOF
Section "ServerFlags"
	Option "AutoAddDevices" "false"
	Option "AutoAddGPU" "false"
	Option "AllowEmptyInput" "true"
EndSection
Section "Device"
	Identifier "rdc"
	Driver "modesetting"
	Option "kmsdev" "$CARD"
	Option "AccelMethod" "none"
	Option "ShadowFB" "true"
EndSection
XEOF
	export DISPLAY=:1
	Xorg :1 -config $T/xorg.conf -logfile $T/xorg.log -nolisten tcp \
		-noreset vt3 "$@" >$T/xorg.out 2>&1 &
	DESKTOP_PID=$!
	wait_for 60 xdpyinfo -display :1
}

# cage on the card as user nobody (it refuses to run as root), with a
# seatd of its own; pixman renderer.  Arguments: the client.
cage_start() {
	seatd -u nobody -g nogroup -l error >$T/seatd.out 2>&1 &
	SEATD_PID=$!
	wait_for 10 test -S /run/seatd.sock
	export XDG_RUNTIME_DIR=$T/xdg-nobody
	mkdir -p -m 700 "$XDG_RUNTIME_DIR"
	chown nobody:nogroup "$XDG_RUNTIME_DIR"
	setpriv --reuid=nobody --regid=nogroup --clear-groups \
		env XDG_RUNTIME_DIR="$XDG_RUNTIME_DIR" LIBSEAT_BACKEND=seatd \
		WLR_RENDERER=pixman WLR_LIBINPUT_NO_DEVICES=1 \
		WLR_DRM_DEVICES="$CARD" cage -- "$@" >$T/cage.out 2>&1 &
	DESKTOP_PID=$!
	export WAYLAND_DISPLAY=wayland-0
	wait_for 60 test -S "$XDG_RUNTIME_DIR/wayland-0"
}

# As the user cage runs as.
as_nobody() {
	setpriv --reuid=nobody --regid=nogroup --clear-groups \
		env XDG_RUNTIME_DIR="$XDG_RUNTIME_DIR" \
		WAYLAND_DISPLAY="$WAYLAND_DISPLAY" "$@"
}

seatd_stop() {
	[ -n "${SEATD_PID:-}" ] || return 0
	kill "$SEATD_PID" 2>/dev/null
	wait "$SEATD_PID" 2>/dev/null
	SEATD_PID=""
}

# The logs of what ran, for a failure's diagnosis.
desktop_logs() {
	for f in weston.log weston.out xorg.log xorg.out cage.out seatd.out; do
		[ -s "$T/$f" ] || continue
		echo "--- $f (last lines)"
		tail -n 15 "$T/$f"
	done
}
