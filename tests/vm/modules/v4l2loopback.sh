#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# Build v4l2loopback out of tree from Debian's v4l2loopback-dkms source
# against the headers of kernel $1, in $2; print the .ko's path.  The
# .deb is unpacked, never installed, so dkms builds nothing for the
# running kernel.
set -e
# Not the outer make's variables (O=, -j...): they mean other things to
# Kbuild.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES O
kver=$1
out=$2
ko=$out/src/v4l2loopback.ko
if [ -f "$ko" ] && [ "$ko" -nt "/lib/modules/$kver/build/Module.symvers" ]; then
	echo "$ko"
	exit 0
fi
rm -rf "$out"
mkdir -p "$out"
cd "$out"
apt-get download v4l2loopback-dkms >/dev/null 2>&1 ||
	{ apt-get update >/dev/null 2>&1 && apt-get download v4l2loopback-dkms >/dev/null; }
dpkg-deb -x v4l2loopback-dkms_*.deb pkg
mv pkg/usr/src/v4l2loopback-* src
make -C "/lib/modules/$kver/build" M="$out/src" modules >build.log 2>&1 ||
	{ tail -n 20 build.log >&2; exit 1; }
echo "$ko"
