#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The kernel chip may not starve its host.  rdcfb.ko with two devices
# paced at 1920x1080, every frame converted (scanout=always), asks more of
# the guest's one CPU than a guest under TCG has.  Without a budget the
# pacing work (high-priority kworkers) runs back to back and user space
# gets next to nothing, as when rdcfb-irqoff once hung on 6.12: this
# test fails on the module from before the budget: the chips took 97%
# of the CPU and the loop 1% (92 s where it takes 0.8 s unloaded).  With the budget (cpu_budget, 75% by default, the
# module's for all its devices together) the chips' time falls behind
# wall time instead.
# The checks, on shares of the guest's CPU measured over a shell loop's
# run (host load slows the guest as a whole, so shares hold where times
# do not): the chips' share (host_busy_ns over host_up_ns, both devices)
# stays within the default budget (5 points over for the work's own
# edges), and the loop gets at least a tenth of the CPU (its user +
# system time over its wall time).  The times are TAP comments.
# vm-module: rdcfb mode=1920x1080-32 devices=2 scanout=always
. "$RDC_TREE/tests/vm/lib.sh"

KO=$RDC_VM_DIR/build-rdcfb/rdcfb.ko
SYS0=/sys/bus/platform/devices/rdcfb.0
SYS1=/sys/bus/platform/devices/rdcfb.1
BUDGET=75 # cpu_budget's default
PAR=/sys/module/rdcfb/parameters
LOOPS=25000

now_ms() {
	echo $(($(date +%s%N) / 1000000))
}

# A fixed piece of user-space work in a shell of its own: prints the
# milliseconds of CPU it took (its `times`).
work_cpu_ms() {
	sh -c "i=0; while [ \$i -lt $LOOPS ]; do i=\$((i + 1)); done; times" |
		awk 'NR == 1 {
			split($1, u, /[ms]/); split($2, s, /[ms]/)
			print int((u[1] * 60 + u[2] + s[1] * 60 + s[2]) * 1000)
		}'
}

busy() {
	echo $(($(cat $SYS0/host_busy_ns) + $(cat $SYS1/host_busy_ns)))
}

# the parameters the harness loaded it with (the vm-module line); a
# module without cpu_budget (from before it) runs as it is
params=""
for p in mode devices scanout cpu_budget; do
	[ -r $PAR/$p ] && params="$params $p=$(cat $PAR/$p)"
done
params=${params# }
fbcon_unbind
check "rdcfb unloads" rmmod rdcfb
t0=$(now_ms)
base_cpu=$(work_cpu_ms)
base=$(($(now_ms) - t0))
check "rdcfb loads with $params" insmod "$KO" $params
# settled: the pacing work runs (fbcon bound and drawn, then let go)
sleep 2
fbcon_unbind
busy0=$(busy)
up0=$(cat $SYS0/host_up_ns)
t0=$(now_ms)
cpu=$(work_cpu_ms)
wall=$(($(now_ms) - t0))
busy1=$(busy)
up1=$(cat $SYS0/host_up_ns)
chip=$(((busy1 - busy0) * 100 / (up1 - up0 + 1)))
mine=$((cpu * 100 / (wall + 1)))
echo "# the loop: ${base} ms (${base_cpu} ms CPU) unloaded, ${wall} ms" \
	"(${cpu} ms CPU) beside the paced chips; throttled" \
	"$(cat $SYS0/pace_throttled) and $(cat $SYS1/pace_throttled) times"
check "the chips took ${chip}% of the CPU: at most the budget, $BUDGET%" \
	test "$chip" -le $((BUDGET + 5))
check "user space ran beside them: the loop got ${mine}% of the CPU" \
	test "$mine" -ge 10
finish
