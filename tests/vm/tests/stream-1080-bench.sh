#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Figures, not conditions: bench/stream_bench.c with --v4l2, i.e. rdcctl
# stream's pipeline with the demo at 1920x1080 into a real v4l2loopback
# device, paced to 60 Hz and unpaced: frames a second, CPU share, frames
# written and dropped.  QEMU under TCG runs the simulator far slower than
# the host, so these are the guest's figures; the host's are make bench's.
# Printed as the check's output; only "it ran" is checked.  `make
# bench-stream-vm` runs this test alone; the suite leaves it out unless
# RDC_VM_TESTS names it.
# vm-bench
# vm-module: v4l2loopback devices=1 exclusive_caps=1 video_nr=0 card_label=rdc
. "$RDC_TREE/tests/vm/lib.sh"

BENCH=$B/stream-bench
[ -x "$BENCH" ] || { echo "$BENCH is not built"; exit 77; }

# from the tree: the demo is examples/demo.rdl
check "stream-bench --v4l2 $DEV --frames 60 (paced, unpaced)" \
	sh -c 'cd "$1" && exec "$2" --v4l2 "$3" --frames 60' sh \
	"$RDC_TREE" "$BENCH" "$DEV"
finish
