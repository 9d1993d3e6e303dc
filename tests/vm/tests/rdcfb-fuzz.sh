#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# 10,000 random and malformed SUBMIT buffers, and bad REG/WAIT/STEP/FRAME
# requests, on rdcfb's private ioctls (rdcfb_fuzz): each refused with its
# errno, a refused buffer queues nothing, and afterwards a known scene
# drawn through fbdev: equals the same scene on an in-process sim:.  No
# oops, BUG or warning in dmesg, and the device keeps working.
# vm-module: rdcfb clock=stepped
. "$RDC_TREE/tests/vm/lib.sh"

FUZZ=$B/rdcfb_fuzz
FB=/dev/fb0
SCENE=$RDC_TREE/tests/golden/scenes/example_repertoire.rdl


fbcon_unbind
[ -c $FB ] || { echo "no $FB"; exit 1; }
dmesg -C
check "rdcfb_fuzz: 10000 submits (TAP below)" \
	"$FUZZ" --device $FB --scene "$SCENE" --iterations 10000
dmesg >"$T/dmesg.log"
check "no oops, BUG or WARN in dmesg" \
	sh -c "! grep -E 'WARNING|BUG|Oops|general protection|Call Trace|UBSAN|KASAN' '$T/dmesg.log'"
grep rdcfb "$T/dmesg.log" | tail -n 5 | sed 's/^/# dmesg: /'
check "the device still draws: the scene again through rdcctl" \
	"$RDCCTL" --connect "fbdev:$FB" run "$SCENE"
finish
