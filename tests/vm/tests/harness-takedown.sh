#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The harness's net for a test that hangs, tried on a test that hangs on
# purpose: it holds what a hung test can hold (rdcfb's /dev/fb0 open in
# a process that ignores SIGTERM, fbcon bound to rdcfb, a USB gadget
# bound to dummy_hcd with rdcd behind it, FunctionFS and configfs
# mounted) and waits.  Its "# vm-stop:" line has init.sh stop it after
# that many seconds, as RDC_VM_TEST_TIMEOUT stops a test that hangs, and
# pass it only if it was stopped, was found holding something, and its
# takedown left nothing: no module it loaded, no gadget, no FunctionFS
# or configfs mount, no process.
# vm-module: rdcfb
# vm-module: dummy_hcd
# vm-module: libcomposite
# vm-module: usb_f_fs
# vm-stop: 45
. "$RDC_TREE/tests/vm/lib.sh"

usb_require
# a hung test's exit trap never runs (SIGTERM ends its shell): nor this one
trap - EXIT
check "rdcfb's /dev/fb0 is there" test -c /dev/fb0
check "fbcon is bound to it" sh -c 'grep -q "^0 rdcfb" /proc/fb && v=$1 &&
	[ "$(cat "$v/bind")" = 1 ]' sh "$(fbcon_vt)"
sh -c 'trap "" TERM; exec sleep 100000' </dev/fb0 >/dev/null 2>&1 &
check "the gadget enumerates (rdcd on ffs:)" usb_gadget_up --mode 640x480
# a hold that failed would leave that part of the takedown untried: the
# test ends (and fails, not being stopped) instead of waiting
[ $failed -eq 0 ] || exit 1
echo "# held; this test waits for the harness to stop it"
while :; do
	sleep 1
done
