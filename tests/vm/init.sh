#!/bin/busybox sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# /init of the VM tests' initramfs (tests/vm/run.sh builds it): mount the
# host's root read-only over 9p at /host, then for each test load the
# modules its "# vm-module:" lines name, run it chrooted into the host
# root, unload every module loaded since it began (see leftovers), and
# report on the console:
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

# new_mods: the modules loaded since /tmp/mods.before, one name a line.
new_mods() {
	cut -d' ' -f1 /proc/modules | grep -vxF -f /tmp/mods.before
}

# leftovers: unload the modules loaded since /tmp/mods.before was taken
# (those the test's "# vm-module:" lines named, their dependencies, and
# any loaded while it ran), newest first as
# /proc/modules lists them, so that a module goes before those it uses.
# A module that stays loaded is a reference the test left behind (a
# process still running, a file or mount still open, a device still
# bound, a configfs directory not removed): print a "not ok" line naming
# it, its reference count and holders, and what may hold it, then take
# that down (takedown) and unload again; false then.
# /proc/modules decides, not modprobe's status: busybox's modprobe -r
# NAME unloads NAME and then its dependencies, and exits 1 when one of
# those is still used by a module loaded beside it (modprobe -r usb_f_fs
# unloads usb_f_fs, libcomposite and configfs, and fails on udc_core,
# which dummy_hcd uses).
unload_new() {
	new_mods >/tmp/mods.new
	# a reference can go a moment after its last holder exits (a
	# work item, a deferred close): a few tries before blaming the test
	i=0
	while [ -s /tmp/mods.new ] && [ $i -lt 30 ]; do
		[ $i = 0 ] || sleep 0.1
		for m in $(cat /tmp/mods.new); do
			grep -q "^$m " /proc/modules || continue
			# rmmod for one outside the initramfs's modules.dep
			modprobe -r "$m" 2>/dev/null || rmmod "$m" 2>/dev/null
		done
		cut -d' ' -f1 /proc/modules | grep -xF -f /tmp/mods.new >/tmp/mods.left
		mv /tmp/mods.left /tmp/mods.new
		i=$((i + 1))
	done
	[ ! -s /tmp/mods.new ]
}

# The gadgets in configfs: under /host too, where a test running in
# the chroot mounts it.
GADGETS="/sys/kernel/config/usb_gadget /host/sys/kernel/config/usb_gadget"

# gadgets: the gadget directories in configfs, one a line.
gadgets() {
	for d in $GADGETS; do ls -d "$d"/* 2>/dev/null; done
}

# mounts_of TYPE...: the lines of /proc/mounts of those file system types.
mounts_of() {
	grep -E " ($(echo "$@" | tr ' ' '|')) " /proc/mounts
}

# procs: the processes running, "PID COMMAND LINE" a line: not this
# shell, nor a kernel thread (no command line).  Called with its output
# to a file, in this shell: a pipe would make it a process of its own.
procs() {
	for p in /proc/[0-9]*; do
		cmd=$(tr '\0' ' ' <"$p/cmdline" 2>/dev/null)
		[ "${p#/proc/}" != 1 ] && [ -n "$cmd" ] || continue
		echo "${p#/proc/} $cmd"
	done
}

# takedown: what a test that failed or was stopped may have left: its
# processes killed, its USB gadgets unbound and removed the way configfs
# wants (function links first, then strings, configs, functions, the
# gadget), the framebuffer console unbound, FunctionFS and configfs
# unmounted; so that the next test starts clean.
takedown() {
	[ -z "$1" ] || kill -KILL $1 2>/dev/null
	sleep 0.2
	for g in $(gadgets); do
		echo "    gadget $(basename "$g"): taken down"
		echo "" >"$g/UDC" 2>/dev/null
		for l in "$g"/configs/*/* "$g"/os_desc/*; do
			[ -L "$l" ] && rm -f "$l"
		done
		rmdir "$g"/configs/*/strings/* "$g"/configs/* \
			"$g"/functions/* "$g"/strings/* "$g" 2>/dev/null
	done
	# the framebuffer console on a device whose driver must unload
	for v in /sys/class/vtconsole/vtcon*; do
		grep -q "frame buffer" "$v/name" 2>/dev/null &&
			echo 0 >"$v/bind" 2>/dev/null
	done
	mounts_of functionfs configfs | cut -d' ' -f2 |
		sort -r | while read -r mnt; do
		umount "$mnt" 2>/dev/null || umount -l "$mnt" 2>/dev/null
	done
}

leftovers() {
	unload_new && return 0
	for m in $(cat /tmp/mods.new); do
		h=$(echo $(ls /sys/module/$m/holders 2>/dev/null))
		echo "not ok - module $m left loaded: refcnt" \
			"$(cat /sys/module/$m/refcnt 2>/dev/null), holders: ${h:-none}"
	done
	# what may hold them: processes and the device files they hold
	# open, mounts, gadgets, consoles
	left=""
	procs >/tmp/procs
	while read -r p cmd; do
		echo "    process $p: $cmd"
		ls -l "/proc/$p/fd" 2>/dev/null | sed -n 's|.* -> \(.*/dev/.*\)|      fd \1|p'
		left="$left $p"
	done </tmp/procs
	mounts_of functionfs configfs usbfs debugfs | sed 's/^/    mount: /'
	gadgets | sed 's/^/    gadget: /'
	for v in /sys/class/vtconsole/vtcon*; do
		echo "    $(basename "$v"): $(cat "$v/name") bind $(cat "$v/bind")"
	done 2>/dev/null
	# the next test starts without this one's leftovers
	takedown "$left"
	unload_new ||
		echo "    still loaded after the takedown:" $(cat /tmp/mods.new)
	return 1
}

# remains: what a takedown must not leave: modules loaded since the test
# began, gadgets, FunctionFS and configfs mounts, processes (as
# leftovers finds them); one line each, none when clean.
remains() {
	new_mods | sed 's/^/module /'
	gadgets | sed 's/^/gadget /'
	mounts_of functionfs configfs | sed 's/^/mount /'
	procs >/tmp/procs
	sed 's/^/process /' /tmp/procs
}

# stopped NAME STATUS: the verdict on a test with a "# vm-stop:" line,
# which hangs on purpose to try the net below: stopped (STATUS 124, or
# 137 when SIGTERM was not enough), found holding something, and nothing
# left after the takedown.  (Its verdict has a name no other function
# here uses: shell variables are global.)
stopped() {
	verdict=0
	case $2 in
	124 | 137) echo "ok - $1: stopped after $tmo s, as it asks" ;;
	*)
		echo "not ok - $1: exit $2 within its $tmo s: not stopped"
		verdict=1
		;;
	esac
	if leftovers; then
		echo "not ok - $1: held nothing when stopped"
		verdict=1
	fi
	remains >/tmp/remains
	if [ -s /tmp/remains ]; then
		echo "not ok - $1: left after the takedown:"
		sed 's/^/    /' /tmp/remains
		verdict=1
	else
		echo "ok - $1: nothing left after the takedown"
	fi
	return $verdict
}

for t in $RDC_TESTS; do
	f=/host$RDC_TREE/tests/vm/tests/$t.sh
	rc=0
	t0=$(date +%s)
	echo "RDC-VM-BEGIN $t"
	cut -d' ' -f1 /proc/modules >/tmp/mods.before
	sed -n 's/^# vm-module: *//p' "$f" >/tmp/mods
	# "# vm-stop: N": the test hangs on purpose, stopped after N s
	stop=$(sed -n 's/^# vm-stop: *\([0-9][0-9]*\) *$/\1/p' "$f")
	tmo=${stop:-$RDC_TEST_TIMEOUT}
	while read -r name args; do
		if ! modprobe "$name" $args; then
			echo "modprobe $name failed"
			rc=1
		fi
	done </tmp/mods
	if [ $rc = 0 ]; then
		# a test that hangs costs its own time, not the boot's
		chroot /host /usr/bin/timeout -k 10 "$tmo" \
			/usr/bin/env -i \
			PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
			HOME=$scratch TMPDIR=$scratch RDC_TREE="$RDC_TREE" \
			RDC_BUILD="$RDC_BUILD" RDC_VM_DIR="$RDC_VM_DIR" \
			/bin/sh "$RDC_TREE/tests/vm/tests/$t.sh" \
			</dev/null 2>&1
		rc=$?
		case $rc in
		124 | 137)
			[ -n "$stop" ] ||
				echo "not ok - $t: stopped after $tmo s" \
					"(RDC_VM_TEST_TIMEOUT)"
			;;
		esac
	fi
	if [ -n "$stop" ] && [ $rc != 77 ]; then
		stopped "$t" $rc
		rc=$?
	else
		leftovers || rc=1
	fi
	echo "RDC-VM-RESULT $t $rc $(($(date +%s) - t0))"
done
echo RDC-VM-DONE
poweroff -f
