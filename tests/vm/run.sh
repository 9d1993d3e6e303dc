#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# The VM test harness: boot Debian's own kernel under QEMU with a small
# initramfs, share this machine's root file system with the guest over
# virtio-9p (read-only), and run every tests/vm/tests/*.sh there against
# real kernel modules.  Prints TAP and closes with
# "vm: N passed, M failed, K skipped" (a test skips, exit 77, saying why).
#
#   tests/vm/run.sh [--auto] [BUILD_DIR]
#
# It installs the Debian packages it needs (as root), builds the
# out-of-tree modules the tests ask for (tests/vm/modules/NAME.sh), and
# reads the kernel version from the installed linux-image-amd64 package.
# With --auto (what `make check` uses) a machine that cannot run it (not
# root with packages missing, not x86_64, RDC_NO_VM set) is skipped with a
# message and exit status 0; without it, that is a failure.
# RDC_VM_TESTS="name ..." runs a subset; RDC_VM_TIMEOUT bounds the boot
# (seconds, default 900); RDC_VM_ACCEL=tcg|kvm overrides the probe.
set -u
# Run from make: its variables (O=, -j) must not reach Kbuild's make.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES

auto=0
if [ "${1:-}" = --auto ]; then
	auto=1
	shift
fi
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
O=${1:-build}
case $O in /*) ;; *) O=$ROOT/$O ;; esac
VMDIR=$O/vm
HERE=$ROOT/tests/vm

skip() {
	echo "vm: skipped: $*"
	[ $auto = 1 ] && exit 0
	exit 1
}

[ -z "${RDC_NO_VM:-}" ] || skip "RDC_NO_VM is set"
[ "$(uname -m)" = x86_64 ] || skip "not an x86_64 machine"
command -v dpkg-query >/dev/null 2>&1 || skip "not a Debian system"

PKGS="qemu-system-x86 linux-image-amd64 linux-headers-amd64 busybox-static
kmod cpio gzip make gcc ffmpeg v4l-utils fbset linux-source-6.1
usbutils libusb-1.0-0 libdrm-tests"
missing=""
for p in $PKGS; do
	dpkg-query -W -f='${Status}' "$p" 2>/dev/null |
		grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
	[ "$(id -u)" = 0 ] ||
		skip "missing Debian packages; as root: apt-get install -y$missing"
	echo "vm: installing$missing"
	export DEBIAN_FRONTEND=noninteractive
	apt-get install -y --no-install-recommends $missing >/dev/null 2>&1 ||
		{ apt-get update >/dev/null 2>&1 &&
		  apt-get install -y --no-install-recommends $missing >/dev/null; } ||
		{ echo "vm: apt-get install failed"; exit 1; }
fi

# The kernel linux-image-amd64 points at, e.g. "6.1.0-56-amd64".
KVER=$(dpkg-query -W -f='${Depends}' linux-image-amd64 |
	sed -n 's/^linux-image-\([^ ,]*\).*/\1/p')
KERNEL=/boot/vmlinuz-$KVER
[ -n "$KVER" ] && [ -d "/lib/modules/$KVER" ] ||
	{ echo "vm: cannot tell the kernel version from linux-image-amd64"; exit 1; }
[ -r "$KERNEL" ] || skip "$KERNEL is not readable (run as root)"

mkdir -p "$VMDIR"
LOG=$VMDIR/console.log

# ---- Which tests, and the modules they declare ------------------------------
TESTS=""
for t in "$HERE"/tests/*.sh; do
	n=$(basename "$t" .sh)
	if [ -n "${RDC_VM_TESTS:-}" ]; then
		case " $RDC_VM_TESTS " in *" $n "*) ;; *) continue ;; esac
	elif grep -q '^# vm-bench' "$t"; then
		continue # figures only: run when named (make bench-usb)
	fi
	TESTS="$TESTS $n"
done
[ -n "$TESTS" ] || { echo "vm: no tests"; exit 1; }
MODS="virtio_pci 9pnet_virtio 9p"
for n in $TESTS; do
	MODS="$MODS $(sed -n 's/^# vm-module: *\([^ ]*\).*/\1/p' "$HERE/tests/$n.sh")"
done

# ---- Initramfs ----------------------------------------------------------------
R=$VMDIR/initramfs
rm -rf "$R"
mkdir -p "$R/bin" "$R/proc" "$R/sys" "$R/dev" "$R/tmp" "$R/host" \
	"$R/lib/modules/$KVER/extra"
cp /bin/busybox "$R/bin/busybox"
for m in $(printf '%s\n' $MODS | sort -u); do
	if [ -f "$HERE/modules/$m.sh" ]; then
		# Out of tree: its script builds it and prints the .ko path.
		ko=$(sh "$HERE/modules/$m.sh" "$KVER" "$VMDIR/build-$m") ||
			{ echo "vm: building module $m failed"; exit 1; }
		cp "$ko" "$R/lib/modules/$KVER/extra/"
		deps=$(modinfo -F depends "$ko" | tr , ' ')
	else
		deps=$m
	fi
	for d in $deps; do
		modprobe -S "$KVER" --show-depends "$d" 2>/dev/null |
			awk '$1 == "insmod" { print $2 }' |
			while read -r f; do
				mkdir -p "$R$(dirname "$f")"
				cp "$f" "$R$f"
			done
	done
done
for f in modules.order modules.builtin modules.builtin.modinfo; do
	[ -f "/lib/modules/$KVER/$f" ] && cp "/lib/modules/$KVER/$f" "$R/lib/modules/$KVER/"
done
depmod -b "$R" "$KVER" || { echo "vm: depmod failed"; exit 1; }
cp "$HERE/init.sh" "$R/init"
chmod +x "$R/init"
{
	echo "RDC_TREE='$ROOT'"
	echo "RDC_BUILD='$O'"
	echo "RDC_TESTS='$TESTS'"
} >"$R/vm.conf"
(cd "$R" && find . | cpio -o -H newc 2>/dev/null | gzip -1) >"$VMDIR/initrd.gz"

# ---- Boot ---------------------------------------------------------------------
qemu() {
	accel=$1
	tmo=$2
	shift 2
	timeout "$tmo" qemu-system-x86_64 -accel "$accel" -m 1024 -smp 1 \
		-nographic -no-reboot -kernel "$KERNEL" -initrd "$VMDIR/initrd.gz" \
		-virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
		-append "console=ttyS0 quiet loglevel=1 panic=-1 $*" </dev/null
}

# KVM only when it really boots this kernel here (it may exist and hang).
ACCEL=${RDC_VM_ACCEL:-}
if [ -z "$ACCEL" ]; then
	ACCEL=tcg
	if [ -r "$VMDIR/accel.$KVER" ]; then
		ACCEL=$(cat "$VMDIR/accel.$KVER")
	elif [ -w /dev/kvm ]; then
		if qemu kvm 30 rdc.probe=1 2>/dev/null | grep -q RDC-VM-PROBE-OK; then
			ACCEL=kvm
		fi
		echo "$ACCEL" >"$VMDIR/accel.$KVER"
	fi
fi

echo "vm: kernel $KVER, accel $ACCEL, tests:$TESTS"
start=$(date +%s)
qemu "$ACCEL" "${RDC_VM_TIMEOUT:-900}" >"$LOG" 2>&1
qrc=$?
echo "vm: guest ran $(($(date +%s) - start)) s (console: $LOG)"

# ---- Results: TAP -------------------------------------------------------------
pass=0
fail=0
skipped=0
i=0
set -- $TESTS
echo "1..$#"
for n in $TESTS; do
	i=$((i + 1))
	res=$(tr -d '\r' <"$LOG" | sed -n "s/.*RDC-VM-RESULT $n \([0-9]*\).*/\1/p" | tail -n 1)
	case $res in
	0) echo "ok $i - $n"; pass=$((pass + 1)) ;;
	77) # the reason: the last line the test printed
		why=$(tr -d '\r' <"$LOG" | awk -v b="RDC-VM-BEGIN $n" -v r="RDC-VM-RESULT $n " '
			index($0, r) { on = 0 }
			on && NF { last = $0 }
			index($0, b) && index($0, b) == length($0) - length(b) + 1 { on = 1 }
			END { print last }' | sed 's/^# *//')
		echo "ok $i - $n # SKIP${why:+ $why}"; skipped=$((skipped + 1)) ;;
	"") echo "not ok $i - $n (no result: guest died? qemu status $qrc)"; fail=$((fail + 1)) ;;
	*) echo "not ok $i - $n (exit $res)"; fail=$((fail + 1)) ;;
	esac
	# What the test printed, as TAP diagnostics.
	tr -d '\r' <"$LOG" | awk -v b="RDC-VM-BEGIN $n" -v r="RDC-VM-RESULT $n " '
		index($0, r) { on = 0 }
		on { print "    " $0 }
		index($0, b) && index($0, b) == length($0) - length(b) + 1 { on = 1 }'
done
if [ $fail -ne 0 ]; then
	echo "# last console lines:"
	grep -v '^RDC-VM' "$LOG" | tail -n 20 | sed 's/^/# /'
fi
echo "vm: $pass passed, $fail failed, $skipped skipped"
[ $fail -eq 0 ]
