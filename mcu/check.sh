#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The firmware test (`make mcu-test`, part of `make check`): boot the
# Cortex-M image under QEMU and check, for every golden scene in it, that
#  - the firmware's line (frame CRC-32, the script's total cycles, the
#    final time, busy/stall cycles, pixels, commands) is the line the same
#    replay prints built for the host (mcu-host), and reports no mismatch
#    against the recorded register reads, wait results and times;
#  - its CRC-32 and total cycles are what `rdcctl run` prints for the
#    scene on a sim: chip with the same VRAM.
#
#   mcu/check.sh ELF MCU_HOST RDCCTL SCENES_TXT SCENE_DIR OUTDIR
set -u
elf=$1 host=$2 rdcctl=$3 list=$4 scenes=$5 out=$6
qemu=${MCU_QEMU:-qemu-system-arm}
mkdir -p "$out"
fail=0
bad() {
	echo "mcu: FAIL: $*"
	fail=1
}

# semihosting carries the output (to a file) and the exit status; 120 s
# is a hang
rm -f "$out/mcu.txt"
timeout 120 "$qemu" -M mps2-an385 -cpu cortex-m3 -nographic -monitor none \
	-serial none -chardev file,id=semihost,path="$out/mcu.txt" \
	-semihosting-config enable=on,target=native,chardev=semihost \
	-kernel "$elf" >"$out/qemu.err" 2>&1
rc=$?
[ $rc -eq 0 ] || bad "the firmware exited with status $rc" \
	"($(head -c 300 "$out/qemu.err"))"
"$host" >"$out/host.txt" || bad "mcu-host exited with status $?"

grep '^scene ' "$out/mcu.txt" >"$out/mcu-scenes.txt"
grep '^scene ' "$out/host.txt" >"$out/host-scenes.txt"
n=$(wc -l <"$out/host-scenes.txt")
want=$(wc -l <"$list")
[ "$n" -eq "$want" ] || bad "mcu-host printed $n scenes, the image holds $want"
if ! cmp -s "$out/mcu-scenes.txt" "$out/host-scenes.txt"; then
	bad "the Cortex-M and the host differ (< Cortex-M, > host):"
	diff "$out/mcu-scenes.txt" "$out/host-scenes.txt" | head -n 20
fi
grep -v ' mismatches 0$' "$out/mcu-scenes.txt" | while read -r line; do
	echo "mcu: FAIL: $line"
done
grep -qv ' mismatches 0$' "$out/mcu-scenes.txt" && fail=1

# the same scenes through the script interpreter, on the host
while read -r name vram; do
	res=$("$rdcctl" run --uri "sim:vram=$vram" "$scenes/$name.rdl") || {
		bad "$name: rdcctl run failed"
		continue
	}
	crc=$(printf '%s\n' "$res" | awk '$1 == "crc32" { print $2 }')
	total=$(printf '%s\n' "$res" | awk '$1 == "total" { print $2 }')
	got=$(awk -v n="$name" '$2 == n {
		for (i = 3; i < NF; i++) {
			if ($i == "crc32") c = $(i + 1)
			if ($i == "total") t = $(i + 1)
		}
		print c, t }' "$out/mcu-scenes.txt")
	[ "$got" = "$crc $total" ] ||
		bad "$name: Cortex-M crc32/total '$got', rdcctl run '$crc $total'"
done <"$list"

grep '^mcu ' "$out/mcu.txt"
if [ $fail -ne 0 ]; then
	echo "mcu: FAIL (outputs in $out)"
	exit 1
fi
echo "mcu: $n scenes: frame CRC-32, cycles and counters equal on the" \
	"Cortex-M3 (QEMU mps2-an385), on the host and in rdcctl run"
