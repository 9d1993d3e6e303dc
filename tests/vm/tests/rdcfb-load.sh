#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Every preset size at 8, 16 and 32 bpp and a mode of its own timings
# set through FBIOPUT_VSCREENINFO show in the frames; FBIOPUTCMAP writes
# the CLUT, FBIOPAN_DISPLAY flips pages, FBIOBLANK stops the frames.
# rdcfb.ko loaded, used (a rectangle drawn by the DP through SUBMIT, a
# stripe written through the mapping, both read back in a scanned-out
# frame) and unloaded 100 times, across its module parameters, with no
# VRAM or frame memory left behind and no warning in dmesg.  The module
# refuses to unload while a client holds /dev/fb0 open or only mapped
# (fb_open pins it); unbinding the device under an open, mapped client is
# clean: its ioctls answer ENODEV and the memory goes when it lets go.
# vm-module: rdcfb
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$B/rdcfb_tool
KO=$RDC_VM_DIR/build-rdcfb/rdcfb.ko
LOOPS=${RDCFB_LOOPS:-100}


vmalloc_kb() {
	sed -n 's/^VmallocUsed: *\([0-9]*\).*/\1/p' /proc/meminfo
}

# wait_held FILE: the holder printed "held" (at most 20 s)
wait_held() {
	i=0
	while [ $i -lt 200 ]; do
		grep -q held "$1" 2>/dev/null && return 0
		sleep 0.1
		i=$((i + 1))
	done
	return 1
}

dmesg -C
fbcon_unbind
check "modes, CLUT, pan and blank through the standard ioctls" \
	"$TOOL" modes /dev/fb0
check "the harness's module unloads" rmmod rdcfb
base=$(vmalloc_kb)

# load, use, unload; every fourth run with two devices, every fourth with
# the stepped clock, every fourth at 800x600 8 bpp then set back by use
loop() {
	i=0
	while [ $i -lt "$LOOPS" ]; do
		case $((i % 4)) in
		1) args="devices=2" ;;
		2) args="clock=stepped" ;;
		3) args="vram=8M" ;;
		*) args="" ;;
		esac
		insmod "$KO" $args || { echo "run $i: insmod $args failed"; return 1; }
		[ -c /dev/fb0 ] || { echo "run $i: no /dev/fb0"; return 1; }
		if [ "$args" = devices=2 ] && [ ! -c /dev/fb1 ]; then
			echo "run $i: no /dev/fb1"
			return 1
		fi
		"$TOOL" use /dev/fb0 >"$T/use.log" 2>&1 ||
			{ echo "run $i ($args): use failed"; cat "$T/use.log"; return 1; }
		fbcon_unbind
		rmmod rdcfb || { echo "run $i: rmmod failed"; return 1; }
		i=$((i + 1))
	done
	echo "$LOOPS runs; last: $(cat "$T/use.log")"
}
check "load, use, unload $LOOPS times" loop

after=$(vmalloc_kb)
check "no vmalloc memory left behind (before ${base} kB, after ${after} kB)" \
	test $((after - base)) -lt 4096

insmod "$KO"
"$TOOL" hold /dev/fb0 open >"$T/hold.out" 2>&1 &
pid=$!
check "a client holds /dev/fb0 open" wait_held "$T/hold.out"
fbcon_unbind
check "unload refused while it is open" sh -c '! rmmod rdcfb'
kill "$pid"
wait "$pid"
check "unload once it is closed" rmmod rdcfb

insmod "$KO"
"$TOOL" hold /dev/fb0 map >"$T/hold.out" 2>&1 &
pid=$!
check "a client holds /dev/fb0 mapped, fd closed" wait_held "$T/hold.out"
fbcon_unbind
check "unload refused while it is mapped" sh -c '! rmmod rdcfb'
kill "$pid"
wait "$pid"
check "unload once it is unmapped" rmmod rdcfb

insmod "$KO"
check "unbind the device under an open, mapped client" \
	"$TOOL" unbind /dev/fb0 rdcfb.0
check "unload after that" rmmod rdcfb
check "VRAM freed after all that (${base} kB before)" \
	sh -c "test \$((\$(sed -n 's/^VmallocUsed: *\([0-9]*\).*/\1/p' /proc/meminfo) - $base)) -lt 4096"

dmesg >"$T/dmesg.log"
check "no WARN, BUG or oops in dmesg" \
	sh -c "! grep -E 'WARNING|BUG|Oops|general protection|Call Trace|refcount|corruption|leak' '$T/dmesg.log'"
grep -c rdcfb "$T/dmesg.log" | sed 's/^/# rdcfb lines in dmesg: /'

# leave it loaded and fbcon unbound, for the harness to unload
insmod "$KO"
fbcon_unbind
finish
