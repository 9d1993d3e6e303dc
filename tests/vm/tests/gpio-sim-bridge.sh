#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# rdcd --gpio-sim bridges the RDC-1's pins to a gpio-sim chip, and
# libgpiod's own tools use them as a GPIO-wired panel controller's: they
# find the lines by name, gpiomon sees one TE rising edge a frame (counted
# exactly on a stepped daemon; the rate of a paced one is only reported),
# gpioset BL_EN=0 darkens the frames and RESET_N low holds the chip in
# reset, after which a scene draws as sim: draws it.  Recording, the
# trace replays what the lines did, and a power cycle's new chip gets the
# levels the lines still drive.  rdcd takes its chip down when it exits.
# vm-module: gpio-sim
. "$RDC_TREE/tests/vm/lib.sh"

RDCD=$B/rdcd
NAME=rdcpins
CFS=/sys/kernel/config/gpio-sim
SOCK=unix:$T/pins.sock
scene=$SCENES/stream_a.rdl
if ! [ -x "$RDCD" ] || ! "$RDCD" --help | grep -q -- --gpio-sim; then
	echo "rdcd is not built, or has no --gpio-sim"
	exit 77
fi
if ! gpiomon --version 2>/dev/null | grep -q 'v2'; then
	echo "libgpiod v2 tools (gpiomon, gpioset) are not installed"
	exit 77
fi
MOUNTED=""
if ! grep -q " /sys/kernel/config " /proc/mounts; then
	mount -t configfs configfs /sys/kernel/config && MOUNTED=1
fi

RDCD_PID=""
rdcd_start() {
	rm -f "$T/ready"
	"$RDCD" --listen "$SOCK" --ready-file "$T/ready" --gpio-sim "$NAME" \
		-q "$@" >>"$T/rdcd.log" 2>&1 &
	RDCD_PID=$!
	i=0
	while ! [ -s "$T/ready" ] && [ $i -lt 300 ]; do
		sleep 0.1
		i=$((i + 1))
	done
	test -s "$T/ready"
}

rdcd_stop() {
	kill "$RDCD_PID"
	wait "$RDCD_PID"
	rc=$?
	RDCD_PID=""
	return $rc
}

ctl() {
	"$RDCCTL" --connect "$SOCK" "$@"
}

# reg NAME: a register's value (decimal) as rdcctl regs prints it
reg() {
	ctl regs | awk -v n="$1" '$2 == n { print $4 }'
}

# crc SCRIPT [URI]: the CRC-32 rdcctl run prints for the frame after it
crc() {
	"$RDCCTL" --connect "${2:-$SOCK}" run "$1" | awk '$1 == "crc32" { print $2 }'
}

# wait_pins PATTERN: until rdcctl pins' line matches (2 s)
wait_pins() {
	i=0
	while [ $i -lt 40 ]; do
		ctl pins | grep -q "$1" && return 0
		sleep 0.05
		i=$((i + 1))
	done
	ctl pins
	return 1
}

# ---- a stepped daemon: exact counts, darkness, reset ----------------------
check "rdcd --stepped --gpio-sim $NAME starts" rdcd_start --stepped
CHIP=$(cat "$CFS/$NAME/bank0/chip_name" 2>/dev/null)
echo "# chip $CHIP"
check "gpiodetect lists the chip by its label" \
	sh -c "gpiodetect | tee /dev/stderr | grep -q '^$CHIP \[$NAME\] (4 lines)'"
check "gpioinfo names the four lines" sh -c "gpioinfo -c $CHIP | tee $T/info &&
	for l in TE IRQ RESET_N BL_EN; do grep -q \"\\\"\$l\\\"\" $T/info || exit 1; done"

# gpiomon first, then ten frames of simulated time
rm -f "$T/mon"
gpiomon --banner -c "$CHIP" -e rising --idle-timeout 3s -F '%S %E %l' TE \
	>"$T/mon" 2>&1 &
MON=$!
i=0
while ! grep -q -i monitor "$T/mon" 2>/dev/null && [ $i -lt 50 ]; do
	sleep 0.1
	i=$((i + 1))
done
f0=$(reg FRAME_COUNT)
check "a client moves time through 10 frames" \
	ctl pins --watch --pin TE --edges rising --count 10
f1=$(reg FRAME_COUNT)
wait $MON
edges=$(grep -c 'rising TE' "$T/mon")
echo "# frames $f0 -> $f1, gpiomon saw $edges rising edges on TE"
check "gpiomon sees exactly one TE rising edge a frame (10)" \
	test "$edges" = 10 -a $((f1 - f0)) = 10

black=$(printf 'mode 320x200 xrgb8888\n' >"$T/black.rdl" && crc "$T/black.rdl" sim:)
want=$(crc "$scene" sim:)
printf '# nothing\n' >"$T/none.rdl"
check "a client draws the scene" test "$(crc "$scene")" = "$want"
gpioset -c "$CHIP" BL_EN=0 &
SET=$!
check "gpioset BL_EN=0 reaches the chip" wait_pins "BL_EN=0"
dark=$(crc "$T/none.rdl")
echo "# lit $want, dark $dark, black $black"
check "BL_EN low: the frames are black" test "$dark" = "$black"
kill $SET
wait $SET 2>/dev/null
check "gpioset gone: BL_EN pulled high again" wait_pins "BL_EN=1"
check "BL_EN high: the picture is back" test "$(crc "$T/none.rdl")" = "$want"

gpioset -c "$CHIP" RESET_N=0 &
SET=$!
check "gpioset RESET_N=0 reaches the chip" wait_pins "RESET_N=0"
check "held in reset: registers at their reset values" \
	test "$(reg H_DISPLAY)" = 640 -a "$(reg IRQ_ENABLE)" = 0
st=$(reg STATUS)
check "held in reset: the DP idle, its FIFO empty" \
	test $((st & 7)) = 0 -a $((st & 8)) = 8
kill $SET
wait $SET 2>/dev/null
check "RESET_N released" wait_pins "RESET_N=1"
check "after the reset the scene draws as on sim:" \
	test "$(crc "$scene")" = "$want"
check "rdcd exits cleanly" rdcd_stop
check "rdcd took its gpio-sim chip down" test ! -e "$CFS/$NAME"

# ---- recording: the bridge's pin changes replay; a power cycle keeps them --
# power_cycle PORT: RESET kind 1 as the controller, over the raw protocol
# (HELLO wanting control, then RESET); 0 if both replies came back OK.
power_cycle() {
	# HELLO: len 20, type 1, seq 1; "RDC1", version 1, caps 0, flags 1,
	# no token.  RESET: len 4, type 12, seq 2; kind 1 (power).
	(printf '\024\0\0\0\001\0\0\0\001\0\0\0\0\0\0\0RDC1\001\0\0\0\0\0\0\0\001\0\0\0\0\0\0\0'
	 printf '\004\0\0\0\014\0\0\0\002\0\0\0\0\0\0\0\001\0\0\0'
	 sleep 1) | busybox nc 127.0.0.1 "$1" >"$T/power.out"
	# the HELLO reply (16 + 28 bytes), then RESET's: status at 56..59
	test "$(wc -c <"$T/power.out")" = 60 &&
		test "$(od -An -tx1 -j 56 -N 4 "$T/power.out" | tr -d ' ')" = 00000000
}

# the guest's loopback starts down; the power cycle goes over TCP
ip link set lo up 2>/dev/null || busybox ip link set lo up 2>/dev/null
# new_chip_held: a new chip (time 0: stepped, nothing has moved it since)
# already held in reset, as the level went to it before the RESET reply
new_chip_held() {
	t=$(reg TIME_LO)
	echo "TIME_LO $t"
	ctl pins | tee /dev/stderr | grep -q RESET_N=0 && test "$t" = 0
}

if ! busybox nc --help 2>&1 | grep -q 'IPADDR PORT'; then
	echo "# busybox nc missing: the recording part is skipped"
elif check "rdcd --stepped --record --gpio-sim starts" \
	rdcd_start --stepped --record "$T/trace" --listen tcp:127.0.0.1:0; then
	CHIP=$(cat "$CFS/$NAME/bank0/chip_name")
	PORT=$(sed -n 's/^tcp:127\.0\.0\.1:\([0-9]*\)$/\1/p' "$T/ready")
	check "a client draws the scene" test "$(crc "$scene")" = "$want"
	gpioset -c "$CHIP" BL_EN=0 &
	SET=$!
	check "recording: gpioset BL_EN=0 reaches the chip" wait_pins "BL_EN=0"
	check "recording: BL_EN low, the frames are black" \
		test "$(crc "$T/none.rdl")" = "$black"
	kill $SET
	wait $SET 2>/dev/null
	check "recording: BL_EN pulled high again" wait_pins "BL_EN=1"
	gpioset -c "$CHIP" RESET_N=0 &
	SET=$!
	check "recording: gpioset RESET_N=0 reaches the chip" wait_pins "RESET_N=0"
	check "a power cycle over the protocol (port $PORT)" power_cycle "$PORT"
	check "the new chip is held in reset by the line still driven low" \
		new_chip_held
	kill $SET
	wait $SET 2>/dev/null
	check "recording: RESET_N released" wait_pins "RESET_N=1"
	live=$(crc "$scene")
	check "after the power cycle the scene draws as on sim:" \
		test "$live" = "$want"
	check "rdcd exits cleanly" rdcd_stop
	"$RDCCTL" replay "$T/trace" >"$T/replay" 2>&1
	sed 's/^/    replay: /' "$T/replay"
	check "the trace replays without a mismatch" \
		grep -q '^mismatches 0$' "$T/replay"
	check "the replay ends on the frame the client saw last" \
		grep -q "^crc32 $live\$" "$T/replay"
fi

# ---- a paced daemon: the rate, reported only --------------------------------
if rdcd_start; then
	CHIP=$(cat "$CFS/$NAME/bank0/chip_name")
	gpiomon -c "$CHIP" -e rising -n 31 --idle-timeout 5s -F '%S' TE \
		>"$T/paced" 2>&1
	awk 'NR == 1 { a = $1 } { b = $1; n = NR }
	     END { if (n > 1) printf "# paced: %d TE edges, %.3f ms apart on average (60 Hz mode: 16.683)\n", n, (b - a) * 1000 / (n - 1) }' \
		"$T/paced"
	check "paced rdcd exits cleanly" rdcd_stop
fi
sed 's/^/    rdcd: /' "$T/rdcd.log"
# configfs pins gpio-sim.ko: let the module go after the test
[ -z "$MOUNTED" ] || umount /sys/kernel/config
finish
