#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# rdcfb installed through dkms as a user installs it: the source laid out
# by scripts/dkms-source.sh with driver/dkms.conf (or the rdcfb-dkms
# package's files, RDC_DKMS_DEB: tests/vm/dkms.sh), then `dkms add`, `dkms
# build` and `dkms install` for this guest's kernel (run on the host by
# tests/vm/dkms.sh, where the build is fast, into overlays kept in the
# build directory).  Here those overlays are laid over the guest's
# /usr/src, /var/lib/dkms and /lib/modules/KVER: `dkms status` says
# installed, modprobe finds rdcfb.ko where dkms installed it
# (updates/dkms/) and loads it, /dev/fb0 is rdcfb's and draws a rectangle
# read back in a frame, the module unloads, dmesg holds no warning.
# vm-dkms: rdcfb
# vm-module: overlay
. "$RDC_TREE/tests/vm/lib.sh"

TOOL=$B/rdcfb_tool
K=$(uname -r)
D=$RDC_VM_DIR/dkms-rdcfb
if ! [ -f "$D/installed" ]; then
	echo "no dkms install of rdcfb for $K in $D (tests/vm/dkms.sh)"
	exit 1
fi
VER=$(cat "$D/version")

MOUNTED=""
unmount() {
	for d in $MOUNTED; do
		umount "$d"
	done
	MOUNTED=""
}
trap unmount EXIT
# dkms's upper layers over the guest's trees (read-only overlays)
lay_dkms_trees() {
	for m in src:/usr/src dkms:/var/lib/dkms modules:/lib/modules/$K; do
		mount -t overlay overlay \
			-o "lowerdir=$D/upper/${m%%:*}:${m#*:}" "${m#*:}" ||
			return 1
		MOUNTED="${m#*:} $MOUNTED"
	done
}
check "dkms's trees laid over /usr/src, /var/lib/dkms, /lib/modules/$K" \
	lay_dkms_trees

# shows PATTERN CMD...: CMD's output, shown, has a line matching PATTERN
shows() {
	pat=$1
	shift
	out=$("$@") || return 1
	printf '%s\n' "$out"
	printf '%s\n' "$out" | grep -q "$pat"
}

dmesg -C
check "dkms status: rdcfb/$VER installed for $K" \
	shows ': installed' dkms status -m rdcfb -v "$VER" -k "$K"
check "modprobe finds rdcfb.ko under updates/dkms/" \
	shows "^/lib/modules/$K/updates/dkms/rdcfb\.ko" modinfo -n rdcfb
check "modinfo: version magic of $K" \
	shows "^$K " modinfo -F vermagic rdcfb
check "rdcdrm.ko, built beside it, is under updates/dkms/ too" \
	shows "^/lib/modules/$K/updates/dkms/rdcdrm\.ko" modinfo -n rdcdrm
check "modprobe rdcfb loads it" modprobe rdcfb clock=stepped
check "the loaded module is dkms's build (srcversion)" \
	test "$(cat /sys/module/rdcfb/srcversion 2>/dev/null)" = \
	"$(modinfo -F srcversion rdcfb)"
fbcon_unbind
check "/dev/fb0 draws: a rectangle through SUBMIT read back in a frame" \
	"$TOOL" use /dev/fb0
fbcon_unbind
check "modprobe -r rdcfb unloads it" modprobe -r rdcfb
check "no rdcfb left loaded" test ! -d /sys/module/rdcfb
dmesg >"$T/dmesg.log"
check "no WARN, BUG or oops in dmesg" \
	sh -c "! grep -E 'WARNING|BUG|Oops|general protection|Call Trace' '$T/dmesg.log'"
unmount
finish
