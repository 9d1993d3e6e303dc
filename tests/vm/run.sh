#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The VM test harness: boot one of Debian's kernels under QEMU with a small
# initramfs, share this machine's root file system with the guest over
# virtio-9p (read-only), and run every tests/vm/tests/*.sh there against
# real kernel modules.  Prints TAP and closes with
# "vm: N passed, M failed, K skipped" (a test skips, exit 77, saying why).
#
#   tests/vm/run.sh [--auto] [--all-kernels] [BUILD_DIR]
#
# It installs the Debian packages it needs (as root), builds the
# out-of-tree modules the tests ask for (tests/vm/modules/NAME.sh) for
# the kernel it boots, and reads kernel versions from Debian's packages.
#
# RDC_VM_KERNEL=VERSION boots that kernel (e.g. 6.12.95+deb12-amd64; its
# linux-image, linux-headers and linux-source packages are installed when
# missing), RDC_VM_KERNEL=newest the newest Debian offers this release
# (on Debian 12: bookworm-backports' linux-image-amd64, Debian 13's
# series).  The default is the kernel linux-image-amd64 points at (on
# Debian 12, 6.1).
# --all-kernels (what `make check` uses): every test on the default
# kernel and on the newest, the two booted side by side: the kernels
# differ in more than what is built per kernel (v4l2loopback is 0.12.7
# on 6.1 and 0.13 on 6.12, the USB gadget and udl stacks are the
# kernel's own).  With one kernel only, or with RDC_VM_KERNEL set, once.
# With --auto a machine that cannot run it (not root with packages
# missing, not x86_64, RDC_NO_VM set) is skipped with a message and exit
# status 0; without it, that is a failure.
# RDC_VM_TESTS="name ..." runs a subset; RDC_VM_TIMEOUT bounds the boot
# (seconds, default 1800: the whole suite takes about 600 on a quiet
# machine; on a loaded one, load average 6 on two cores, 1716 on 6.1 and
# 1441 on 6.12), RDC_VM_TEST_TIMEOUT each test (seconds of guest time,
# default 400; a test stopped there fails and the next one runs);
# RDC_VM_ACCEL=tcg|kvm overrides the probe.
set -u
# Run from make: its variables (O=, -j) must not reach Kbuild's make.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES

auto=0
autoflag=""
all=0
while :; do
	case ${1:-} in
	--auto) auto=1 autoflag=--auto ;;
	--all-kernels) all=1 ;;
	*) break ;;
	esac
	shift
done
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
O=${1:-build}
case $O in /*) ;; *) O=$ROOT/$O ;; esac
HERE=$ROOT/tests/vm

skip() {
	echo "vm: skipped: $*"
	[ $auto = 1 ] && exit 0
	exit 1
}

[ -z "${RDC_NO_VM:-}" ] || skip "RDC_NO_VM is set"
[ "$(uname -m)" = x86_64 ] || skip "not an x86_64 machine"
command -v dpkg-query >/dev/null 2>&1 || skip "not a Debian system"

# ---- Which tests ----------------------------------------------------------------
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
TEST_TMO=${RDC_VM_TEST_TIMEOUT:-400}
case $TEST_TMO in '' | *[!0-9]*) echo "vm: RDC_VM_TEST_TIMEOUT: not a number of seconds"; exit 1 ;; esac

# ---- Packages ---------------------------------------------------------------------
is_installed() {
	dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"
}

# install PKG...: what is missing of them (PKG may be NAME=VERSION).  The
# kernels' parts run at once: one apt at a time, through APT_LOCK.
APT_LOCK=${TMPDIR:-/tmp}/rdc-vm-apt.lock
# and dpkg's own lock, held by any other apt: wait for it too
LOCK_WAIT="-o DPkg::Lock::Timeout=600"
export APT_LOCK
install() {
	missing=""
	for p in "$@"; do
		is_installed "${p%%=*}" || missing="$missing $p"
	done
	[ -n "$missing" ] || return 0
	[ "$(id -u)" = 0 ] ||
		skip "missing Debian packages; as root: apt-get install -y$missing"
	echo "vm: installing$missing"
	export DEBIAN_FRONTEND=noninteractive
	flock "$APT_LOCK" sh -c "apt-get $LOCK_WAIT install -y --no-install-recommends $missing >/dev/null 2>&1 ||
		{ apt-get $LOCK_WAIT update >/dev/null 2>&1 &&
		  apt-get $LOCK_WAIT install -y --no-install-recommends $missing >/dev/null; }" ||
		{ echo "vm: apt-get install$missing failed"; exit 1; }
}

# The kernel a linux-image-amd64 package points at, e.g. "6.1.0-57-amd64",
# from its Depends (read from dpkg's status, or apt-cache's for "/RELEASE").
meta_kernel() {
	case $1 in
	*/*) apt-cache show "$1" 2>/dev/null | sed -n 's/^Depends: //p' | head -n 1 ;;
	*) dpkg-query -W -f='${Depends}' "$1" 2>/dev/null ;;
	esac | sed -n 's/^linux-image-\([^ ,]*\).*/\1/p'
}

# The newest kernel series Debian offers this release: on Debian 12,
# bookworm-backports' (enabled as scripts/deps.sh does for libgpiod).
newest_kernel() {
	codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
	if [ "$codename" = bookworm ]; then
		if ! grep -rqs bookworm-backports /etc/apt/sources.list /etc/apt/sources.list.d; then
			[ "$(id -u)" = 0 ] || {
				echo "vm: the newest kernel needs bookworm-backports in apt's sources" >&2
				return
			}
			echo "vm: enabling bookworm-backports for its kernel"
			printf '%s\n' "Types: deb" "URIs: http://deb.debian.org/debian" \
				"Suites: bookworm-backports" "Components: main" \
				"Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" \
				>/etc/apt/sources.list.d/rdc-backports.sources
		fi
		k=$(meta_kernel linux-image-amd64/bookworm-backports)
		if [ -z "$k" ] && [ "$(id -u)" = 0 ]; then
			apt-get update >/dev/null 2>&1
			k=$(meta_kernel linux-image-amd64/bookworm-backports)
		fi
		[ -n "$k" ] && { echo "$k"; return; }
	fi
	meta_kernel linux-image-amd64
}

BASE_PKGS="qemu-system-x86 linux-image-amd64 linux-headers-amd64
busybox-static kmod cpio gzip xz-utils make gcc dkms ffmpeg v4l-utils fbset
usbutils libusb-1.0-0 libdrm-tests"

# ---- Both kernels: this script once per kernel, then the totals --------------------
if [ $all = 1 ] && [ -z "${RDC_VM_KERNEL:-}" ]; then
	install $BASE_PKGS
	old=$(meta_kernel linux-image-amd64)
	[ -n "$old" ] || { echo "vm: cannot tell the kernel version from linux-image-amd64"; exit 1; }
	new=$(newest_kernel)
	kernels=$old
	if [ -z "$new" ]; then
		echo "vm: only $old: the newest kernel is not to be had here"
	elif [ "$new" != "$old" ]; then
		kernels="$old $new"
	fi
	pass=0
	fail=0
	skipped=0
	mkdir -p "$O"
	# The kernels boot side by side: QEMU under TCG keeps one core busy,
	# and the machines these run on have two.  Each part's output is
	# shown whole when it is done; apt and dpkg are taken in turn
	# (flock in install()).
	pids=""
	for k in $kernels; do
		set -- $TESTS
		echo "vm: booting $k for:" "$@"
		RDC_VM_KERNEL=$k RDC_VM_TESTS="$*" RDC_VM_PART=1 \
			sh "$0" $autoflag "$O" >"$O/vm-$k.out" 2>&1 &
		pids="$pids $!"
	done
	for p in $pids; do
		wait "$p"
	done
	for k in $kernels; do
		cat "$O/vm-$k.out"
		line=$(sed -n 's/^vm: \([0-9]*\) passed, \([0-9]*\) failed, \([0-9]*\) skipped on .*/\1 \2 \3/p' "$O/vm-$k.out")
		if [ -n "$line" ]; then
			set -- $line
			pass=$((pass + $1))
			fail=$((fail + $2))
			skipped=$((skipped + $3))
		elif [ $auto = 0 ] || ! grep -q '^vm: skipped: ' "$O/vm-$k.out"; then
			fail=$((fail + 1)) # it could not run its tests
		fi
		rm -f "$O/vm-$k.out"
	done
	echo "vm: $pass passed, $fail failed, $skipped skipped"
	[ $fail -eq 0 ]
	exit
fi

install $BASE_PKGS
# The desktop-* tests run Debian's compositors and X server on rdcdrm.ko:
# weston, Xorg's modesetting driver and cage (wlroots, which also wants
# Xwayland), seatd for cage's seat, the screenshot tools (grim, xwd) and
# X clients (xsetroot, xdpyinfo, xeyes).
DESKTOP_PKGS="weston seatd xserver-xorg-core xwayland cage grim x11-apps
x11-utils x11-xserver-utils"
case " $TESTS " in *" desktop-"*) install $DESKTOP_PKGS ;; esac
case ${RDC_VM_KERNEL:-} in
"") KVER=$(meta_kernel linux-image-amd64) ;;
newest) KVER=$(newest_kernel) ;;
*) KVER=$RDC_VM_KERNEL ;;
esac
[ -n "$KVER" ] || { echo "vm: cannot tell the kernel version from linux-image-amd64"; exit 1; }
# The image, the headers the modules build against, and the source of
# the same series (gpio-sim is built from it), of the image's version.
install linux-image-$KVER linux-headers-$KVER
SERIES=$(echo "$KVER" | sed -n 's/^\([0-9]*\.[0-9]*\).*/\1/p')
if ! is_installed linux-source-$SERIES; then
	v=$(dpkg-query -W -f='${Version}' "linux-image-$KVER")
	if apt-cache show "linux-source-$SERIES=$v" >/dev/null 2>&1; then
		install "linux-source-$SERIES=$v"
	else
		install "linux-source-$SERIES"
	fi
fi
KERNEL=/boot/vmlinuz-$KVER
[ -d "/lib/modules/$KVER" ] || { echo "vm: /lib/modules/$KVER is missing"; exit 1; }
[ -r "$KERNEL" ] || skip "$KERNEL is not readable (run as root)"

VMDIR=$O/vm/$KVER
mkdir -p "$VMDIR"
# One run at a time per kernel and build directory: the initramfs and the
# console log below are the run's own.
exec 9>"$VMDIR/lock"
flock 9
LOG=$VMDIR/console.log

# ---- The modules the tests declare ------------------------------------------------
MODS="virtio_pci 9pnet_virtio 9p"
DKMS=""
for n in $TESTS; do
	MODS="$MODS $(sed -n 's/^# vm-module: *\([^ ]*\).*/\1/p' "$HERE/tests/$n.sh")"
	DKMS="$DKMS $(sed -n 's/^# vm-dkms: *\([^ ]*\).*/\1/p' "$HERE/tests/$n.sh")"
done

# A test's "# vm-dkms: NAME": dkms adds, builds and installs NAME here for
# the guest's kernel (tests/vm/dkms.sh), without touching this machine.
for m in $(printf '%s\n' $DKMS | sort -u); do
	sh "$HERE/dkms.sh" "$m" "$KVER" "$VMDIR/dkms-$m" ||
		{ echo "vm: dkms for $m on $KVER failed"; exit 1; }
done

# ---- Initramfs ----------------------------------------------------------------
# copy_module FILE: into the initramfs at its own path, uncompressed
# (busybox's modprobe may not read .xz or .zst).
copy_module() {
	mkdir -p "$R$(dirname "$1")"
	case $1 in
	*.xz) xz -dc "$1" >"$R${1%.xz}" ;;
	*.zst) zstd -qdc "$1" >"$R${1%.zst}" ;;
	*) cp "$1" "$R$1" ;;
	esac
}
R=$VMDIR/initramfs
rm -rf "$R"
mkdir -p "$R/bin" "$R/proc" "$R/sys" "$R/dev" "$R/tmp" "$R/host" \
	"$R/lib/modules/$KVER/extra"
cp /bin/busybox "$R/bin/busybox"
for m in $(printf '%s\n' $MODS | sort -u); do
	if [ -f "$HERE/modules/$m.sh" ]; then
		# Out of tree: its script builds it and prints the .ko path.
		ko=$(sh "$HERE/modules/$m.sh" "$KVER" "$VMDIR/build-$m") ||
			{ echo "vm: building module $m for $KVER failed"; exit 1; }
		cp "$ko" "$R/lib/modules/$KVER/extra/"
		deps=$(modinfo -F depends "$ko" | tr , ' ')
	else
		deps=$m
	fi
	for d in $deps; do
		modprobe -S "$KVER" --show-depends "$d" 2>/dev/null |
			awk '$1 == "insmod" { print $2 }' |
			while read -r f; do
				copy_module "$f"
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
	echo "RDC_VM_DIR='$VMDIR'"
	echo "RDC_TESTS='$TESTS'"
	echo "RDC_TEST_TIMEOUT='$TEST_TMO'"
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
	if [ -r "$VMDIR/accel" ]; then
		ACCEL=$(cat "$VMDIR/accel")
	elif [ -w /dev/kvm ]; then
		if qemu kvm 30 rdc.probe=1 2>/dev/null | grep -q RDC-VM-PROBE-OK; then
			ACCEL=kvm
		fi
		echo "$ACCEL" >"$VMDIR/accel"
	fi
fi

echo "vm: kernel $KVER, accel $ACCEL, tests:$TESTS"
start=$(date +%s)
qemu "$ACCEL" "${RDC_VM_TIMEOUT:-1800}" >"$LOG" 2>&1
qrc=$?
echo "vm: guest ran $(($(date +%s) - start)) s on $KVER (console: $LOG)"

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
	secs=$(tr -d '\r' <"$LOG" | sed -n "s/.*RDC-VM-RESULT $n [0-9]* \([0-9]*\).*/\1/p" | tail -n 1)
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
	[ -z "$secs" ] || echo "    # $n: $secs s of guest time on $KVER"
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
# One closing line for the run; --all-kernels adds up its parts.
if [ -n "${RDC_VM_PART:-}" ]; then
	echo "vm: $pass passed, $fail failed, $skipped skipped on $KVER"
else
	echo "vm: $pass passed, $fail failed, $skipped skipped"
fi
[ $fail -eq 0 ]
