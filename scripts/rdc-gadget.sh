#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The RDC-1 as a USB device (docs/usb.md): a configfs gadget through
# libcomposite with one FunctionFS function, whose device side is rdcd
# (`rdcd --listen ffs:DIR`).
#
#   rdc-gadget.sh up [OPTIONS] [-- RDCD_ARGS...]
#       create the gadget, mount functionfs at DIR; with --rdcd also start
#       rdcd on it and bind the gadget to a UDC once rdcd has written its
#       descriptors; without --rdcd, start rdcd yourself, then `bind`
#   rdc-gadget.sh bind [--udc NAME]   plug in (waits for the descriptors)
#   rdc-gadget.sh unbind              unplug: the host sees it go
#   rdc-gadget.sh down                unbind, stop the rdcd `up` started,
#                                     umount, remove the configfs tree
#   rdc-gadget.sh status
#
# Options: --personality rdc|udl (rdc: rdc_usb.h's interface, the default;
# udl: DisplayLink's command set for Linux's udl DRM driver, IDs
# 0x17e9/0x5244, rdcd --listen udl:DIR), --name NAME (gadget and function
# instance, default rdc),
# --dir DIR (functionfs mount, default /dev/ffs-NAME), --vid/--pid (default
# rdc_usb.h's 0x1209/0x0001), --serial S (default generated), --udc NAME
# (default the first in /sys/class/udc), --rdcd PATH, --log FILE (rdcd's
# stderr, default STATE/rdcd.log).  State (what `down` undoes) is kept in
# $RDC_GADGET_STATE (default /run/rdc-gadget, else $TMPDIR/rdc-gadget).
set -u

NAME=rdc
DIR=""
PERSONALITY=rdc
VID=""
PID=""
SERIAL=""
UDC=""
RDCD=""
LOG=""
CFG=/sys/kernel/config

die() {
	echo "rdc-gadget: $*" >&2
	exit 1
}

usage() {
	sed -n '3,25s/^# \{0,1\}//p' "$0"
	exit "${1:-0}"
}

[ $# -ge 1 ] || usage 2
CMD=$1
shift
while [ $# -gt 0 ]; do
	case $1 in
	--name | --dir | --vid | --pid | --serial | --udc | --rdcd | --log | \
		--personality)
		[ $# -ge 2 ] || die "$1 needs a value"
		case $1 in
		--personality) PERSONALITY=$2 ;;
		--name) NAME=$2 ;;
		--dir) DIR=$2 ;;
		--vid) VID=$2 ;;
		--pid) PID=$2 ;;
		--serial) SERIAL=$2 ;;
		--udc) UDC=$2 ;;
		--rdcd) RDCD=$2 ;;
		--log) LOG=$2 ;;
		esac
		shift 2
		;;
	--) shift; break ;;
	-h | --help) usage 0 ;;
	*) die "unknown argument '$1' (--help)" ;;
	esac
done
case $NAME in *[!A-Za-z0-9_-]* | "") die "bad --name '$NAME'" ;; esac
# udl matches DisplayLink's vendor ID and the interface class alone; the
# product ID is this simulation's, no DisplayLink product's.
case $PERSONALITY in
rdc) VID=${VID:-0x1209} PID=${PID:-0x0001} ;;
udl) VID=${VID:-0x17e9} PID=${PID:-0x5244} ;;
*) die "bad --personality '$PERSONALITY' (rdc or udl)" ;;
esac
G=$CFG/usb_gadget/$NAME
F=functions/ffs.$NAME

STATE=${RDC_GADGET_STATE:-/run/rdc-gadget}
mkdir -p "$STATE" 2>/dev/null || STATE=${TMPDIR:-/tmp}/rdc-gadget
STATE=$STATE/$NAME

# A process that exists and is not a zombie.
alive() {
	[ -n "$1" ] && [ -r "/proc/$1/stat" ] &&
		! sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null | grep -q '^Z'
}

descriptors_written() {
	[ -e "$1/ep1" ]
}

# ---- up ----------------------------------------------------------------------
gadget_create() {
	if ! [ -d "$CFG/usb_gadget" ]; then
		modprobe libcomposite 2>/dev/null
		grep -q " $CFG configfs" /proc/mounts ||
			mount -t configfs none "$CFG" 2>/dev/null
	fi
	[ -d "$CFG/usb_gadget" ] ||
		die "no $CFG/usb_gadget (configfs and libcomposite loaded?)"
	[ -e "$G" ] && die "gadget $NAME exists already ('down' first)"
	[ -n "$SERIAL" ] ||
		SERIAL=rdc-$(head -c 8 /proc/sys/kernel/random/uuid)
	mkdir "$G" || die "cannot create $G"
	echo "$VID" >"$G/idVendor"
	echo "$PID" >"$G/idProduct"
	echo 0x0100 >"$G/bcdDevice" # RDC-1 revision 1.00
	echo 0x0200 >"$G/bcdUSB"
	# full- and high-speed descriptors only: keep SuperSpeed UDCs at high
	echo high-speed >"$G/max_speed" 2>/dev/null
	mkdir "$G/strings/0x409"
	echo "rdc project" >"$G/strings/0x409/manufacturer"
	if [ "$PERSONALITY" = udl ]; then
		echo "RDC-1 raster display controller (simulated, DisplayLink command set)"
	else
		echo "RDC-1 raster display controller (simulated)"
	fi >"$G/strings/0x409/product"
	echo "$SERIAL" >"$G/strings/0x409/serialnumber"
	mkdir "$G/configs/c.1" "$G/configs/c.1/strings/0x409"
	echo "RDC-1" >"$G/configs/c.1/strings/0x409/configuration"
	echo 100 >"$G/configs/c.1/MaxPower"
	mkdir "$G/$F" || { gadget_remove; die "cannot create $F (usb_f_fs?)"; }
	ln -s "$G/$F" "$G/configs/c.1/"
	mkdir -p "$DIR" || { gadget_remove; die "cannot create $DIR"; }
	mount -t functionfs "$NAME" "$DIR" ||
		{ gadget_remove; die "cannot mount functionfs at $DIR"; }
	mkdir -p "$STATE"
	echo "$DIR" >"$STATE/dir"
	echo "$SERIAL" >"$STATE/serial"
	echo "$PERSONALITY" >"$STATE/personality"
}

gadget_remove() {
	[ -d "$G" ] || return 0
	rm -f "$G/configs/c.1/ffs.$NAME"
	rmdir "$G/configs/c.1/strings/0x409" "$G/configs/c.1" 2>/dev/null
	rmdir "$G/$F" 2>/dev/null
	rmdir "$G/strings/0x409" 2>/dev/null
	rmdir "$G" || echo "rdc-gadget: cannot remove $G" >&2
}

rdcd_start() {
	[ -x "$RDCD" ] || die "--rdcd $RDCD is not executable"
	[ -n "$LOG" ] || LOG=$STATE/rdcd.log
	if [ "$PERSONALITY" = udl ]; then lis=udl; else lis=ffs; fi
	"$RDCD" --listen "$lis:$DIR" "$@" >"$LOG" 2>&1 </dev/null &
	echo $! >"$STATE/rdcd.pid"
}

# ---- bind / unbind -------------------------------------------------------------
do_bind() {
	[ -d "$G" ] || die "gadget $NAME is not up"
	[ -n "$DIR" ] || DIR=$(cat "$STATE/dir" 2>/dev/null)
	if [ -z "$UDC" ]; then
		UDC=$(cat "$STATE/udc" 2>/dev/null)
		[ -n "$UDC" ] || UDC=$(ls /sys/class/udc 2>/dev/null | head -n 1)
	fi
	[ -n "$UDC" ] || die "no UDC in /sys/class/udc (dummy_hcd loaded?)"
	# The function is ready once its descriptors are written.
	i=0
	while ! descriptors_written "$DIR"; do
		[ $i -lt 100 ] || die "no descriptors in $DIR after 10 s (is rdcd --listen ffs:$DIR running?)"
		pid=$(cat "$STATE/rdcd.pid" 2>/dev/null)
		[ -z "$pid" ] || alive "$pid" || die "rdcd exited (log: ${LOG:-$STATE/rdcd.log})"
		sleep 0.1
		i=$((i + 1))
	done
	[ -z "$(cat "$G/UDC")" ] || return 0
	echo "$UDC" >"$G/UDC" || die "cannot bind to $UDC"
	echo "$UDC" >"$STATE/udc"
}

do_unbind() {
	[ -d "$G" ] || die "gadget $NAME is not up"
	[ -z "$(cat "$G/UDC")" ] || echo "" >"$G/UDC"
}

# ---- down ----------------------------------------------------------------------
do_down() {
	[ -n "$DIR" ] || DIR=$(cat "$STATE/dir" 2>/dev/null)
	[ -d "$G" ] && [ -n "$(cat "$G/UDC" 2>/dev/null)" ] && echo "" >"$G/UDC"
	pid=$(cat "$STATE/rdcd.pid" 2>/dev/null)
	if [ -n "$pid" ] && alive "$pid"; then
		kill -TERM "$pid"
		i=0
		while alive "$pid" && [ $i -lt 100 ]; do
			sleep 0.1
			i=$((i + 1))
		done
		alive "$pid" && { echo "rdc-gadget: rdcd $pid ignores SIGTERM: killed" >&2; kill -KILL "$pid"; }
	fi
	if [ -n "$DIR" ] && grep -q " $DIR functionfs " /proc/mounts; then
		i=0
		until umount "$DIR" 2>/dev/null; do
			[ $i -lt 50 ] || { echo "rdc-gadget: $DIR stays busy (who holds it open?)" >&2; break; }
			sleep 0.1
			i=$((i + 1))
		done
		rmdir "$DIR" 2>/dev/null
	fi
	gadget_remove
	rm -rf "$STATE"
	# anything left is a failure
	! [ -e "$G" ] && ! { [ -n "$DIR" ] &&
		grep -q " $DIR functionfs " /proc/mounts; }
}

case $CMD in
up)
	[ -n "$DIR" ] || DIR=/dev/ffs-$NAME
	gadget_create
	if [ -n "$RDCD" ]; then
		rdcd_start "$@"
		do_bind
		echo "rdc-gadget: $NAME up on $UDC, serial $SERIAL, rdcd $(cat "$STATE/rdcd.pid")"
	else
		echo "rdc-gadget: $NAME created, functionfs at $DIR, serial $SERIAL;"
		[ "$PERSONALITY" = udl ] && lis=udl || lis=ffs
		echo "  now: rdcd --listen $lis:$DIR ... and then: $0 bind --name $NAME"
	fi
	;;
bind) do_bind ;;
unbind) do_unbind ;;
down) do_down ;;
status)
	if [ -d "$G" ]; then
		echo "gadget $NAME: $(cat "$G/idVendor"):$(cat "$G/idProduct")," \
			"serial $(cat "$G/strings/0x409/serialnumber")," \
			"udc '$(cat "$G/UDC")', functionfs $(cat "$STATE/dir" 2>/dev/null)"
	else
		echo "gadget $NAME: not up"
		exit 1
	fi
	;;
*) usage 2 ;;
esac
