#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Build gpio-sim out of tree from Debian's linux-source-SERIES (6.1 for
# 6.1.0-57-amd64, 6.12 for 6.12.95+deb12-amd64) against the headers of
# kernel $1, in $2; print the .ko's path.
#
# Debian's kernel leaves CONFIG_GPIO_SIM (and the IRQ_SIM it selects)
# out.  The module is gpio-sim.c and irq_sim.c linked as one, plus
# gpiolib.h, the private gpiolib header gpio-sim.c includes (the headers
# package does not carry drivers/).  One change: irq_sim.c calls
# handle_simple_irq(irq_to_desc(irq)), and irq_to_desc is not exported
# to modules; generic_handle_irq(irq) (exported) looks the descriptor up
# and runs the same flow handler.
set -e
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES O
kver=$1
out=$2
ko=$out/src/gpio-sim.ko
series=$(echo "$kver" | sed -n "s/^\([0-9]*\.[0-9]*\).*/\1/p")
tarball=/usr/src/linux-source-$series.tar.xz
if [ -f "$ko" ] && [ "$ko" -nt "/lib/modules/$kver/build/Module.symvers" ] &&
	[ "$ko" -nt "$0" ]; then
	echo "$ko"
	exit 0
fi
[ -r "$tarball" ] || { echo "$tarball missing (apt-get install linux-source-$series)" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out/src"
cd "$out"
# Only the three files: the whole tree is over a gigabyte unpacked.
tar -xJf "$tarball" --wildcards --strip-components=1 -C "$out" \
	'*/drivers/gpio/gpio-sim.c' '*/drivers/gpio/gpiolib.h' \
	'*/kernel/irq/irq_sim.c'
cp drivers/gpio/gpio-sim.c drivers/gpio/gpiolib.h src/
cp kernel/irq/irq_sim.c src/
grep -q 'handle_simple_irq(irq_to_desc(irqnum));' src/irq_sim.c ||
	{ echo "irq_sim.c: the irq_to_desc call is not where it was" >&2; exit 1; }
sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/if (irqnum)\n\t\t\tgeneric_handle_irq(irqnum);/' \
	src/irq_sim.c
cat >src/Kbuild <<'EOF'
obj-m := gpio-sim.o
gpio-sim-y := gpio-sim-main.o irq_sim.o
EOF
# The module is named gpio-sim, so the driver's object gets another name.
mv src/gpio-sim.c src/gpio-sim-main.c
make -C "/lib/modules/$kver/build" M="$out/src" modules >build.log 2>&1 ||
	{ tail -n 20 build.log >&2; exit 1; }
echo "$ko"
