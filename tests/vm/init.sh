#!/bin/busybox sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# /init of the VM tests' initramfs (tests/vm/run.sh builds it): mount the
# host's root read-only over 9p at /host, then for each test load the
# modules its "# vm-module:" lines name, run it chrooted into the host
# root, unload them, and report on the console:
#   RDC-VM-BEGIN NAME
#   (what the test printed)
#   RDC-VM-RESULT NAME STATUS SECONDS
/bin/busybox --install -s /bin
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
ln -s /proc/self/fd /dev/fd # as udev makes it: <(...) in bash, dkms
mount -t tmpfs tmp /tmp

if grep -q rdc.probe=1 /proc/cmdline; then
	echo RDC-VM-PROBE-OK
	poweroff -f
fi

. /vm.conf
echo # the firmware leaves escape sequences on the line
for m in virtio_pci 9pnet_virtio 9p; do
	modprobe "$m"
done
mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose hostroot /host ||
	echo "cannot mount the host's root"
mount --bind /proc /host/proc
mount --bind /sys /host/sys
mount --bind /dev /host/dev
# Scratch space for the tests: a tmpfs over /tmp, or over /run when the
# tree itself lives under /tmp (it would be hidden).
case "$RDC_TREE/ $RDC_BUILD/" in
/tmp/* | *" /tmp/"*) scratch=/run ;;
*) scratch=/tmp ;;
esac
mount -t tmpfs tmp "/host$scratch"

for t in $RDC_TESTS; do
	f=/host$RDC_TREE/tests/vm/tests/$t.sh
	loaded=""
	rc=0
	t0=$(date +%s)
	echo "RDC-VM-BEGIN $t"
	sed -n 's/^# vm-module: *//p' "$f" >/tmp/mods
	while read -r name args; do
		if modprobe "$name" $args; then
			loaded="$name $loaded"
		else
			echo "modprobe $name failed"
			rc=1
		fi
	done </tmp/mods
	if [ $rc = 0 ]; then
		chroot /host /usr/bin/env -i \
			PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
			HOME=$scratch TMPDIR=$scratch RDC_TREE="$RDC_TREE" \
			RDC_BUILD="$RDC_BUILD" RDC_VM_DIR="$RDC_VM_DIR" \
			/bin/sh "$RDC_TREE/tests/vm/tests/$t.sh" \
			</dev/null 2>&1
		rc=$?
	fi
	for m in $loaded; do
		modprobe -r "$m" || echo "cannot unload $m"
	done
	echo "RDC-VM-RESULT $t $rc $(($(date +%s) - t0))"
done
echo RDC-VM-DONE
poweroff -f
