#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Lay out the source of rdcfb.ko and rdcdrm.ko as dkms wants it:
#
#   scripts/dkms-source.sh DIR [VERSION]
#
# makes DIR/rdcfb-VERSION/ holding dkms.conf (driver/dkms.conf with its
# version filled in), Kbuild, COPYING and the .c and .h files of driver/,
# hw-sim/ and firmware-model/, and prints that directory.  VERSION is
# the release, rdc.h's RDC_VERSION_MAJOR.MINOR.PATCH unless given.  Then,
# as root: dkms add DIR/rdcfb-VERSION && dkms install rdcfb/VERSION
# (docs/driver.md).  `make dkms-source` runs it into $(O)/dkms.
set -e
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: $0 DIR [VERSION]" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
ver=${2:-$(awk '/^#define[ \t]+RDC_VERSION_(MAJOR|MINOR|PATCH)[ \t]/ {
	v = v (v == "" ? "" : ".") $3 } END { print v }' \
	"$root/userspace/include/rdc.h")}
case $ver in
[0-9]*.[0-9]*.[0-9]*) ;;
*) echo "$0: no version (rdc.h's RDC_VERSION_*?): '$ver'" >&2; exit 1 ;;
esac
dst=$1/rdcfb-$ver
rm -rf "$dst"
mkdir -p "$dst"
cp "$root/Kbuild" "$root/COPYING" "$dst/"
for d in driver hw-sim firmware-model; do
	mkdir -p "$dst/$d"
	cp "$root/$d"/*.[ch] "$dst/$d/"
done
sed "s/#MODULE_VERSION#/$ver/" "$root/driver/dkms.conf" >"$dst/dkms.conf"
echo "$dst"
