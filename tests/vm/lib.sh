# SPDX-License-Identifier: GPL-2.0-only
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
wait_device() {
	i=0
	while [ $i -lt $(($1 * 10)) ]; do
		v4l2-ctl -d "$DEV" --get-fmt-video >/dev/null 2>&1 && return 0
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
