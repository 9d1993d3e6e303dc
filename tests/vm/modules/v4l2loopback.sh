#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Build v4l2loopback out of tree from Debian's v4l2loopback-dkms source
# against the headers of kernel $1, in $2; print the .ko's path.  The
# .deb is unpacked, never installed, so dkms builds nothing for the
# running kernel.  A kernel from a backports suite takes the source from
# the same suite (bookworm's 0.12.7 does not build on 6.12; bookworm-
# backports' 0.13 does).
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
pkg=v4l2loopback-dkms
bpo=$(dpkg-query -W -f='${Version}' "linux-image-$kver" 2>/dev/null |
	sed -n 's/.*~bpo\([0-9]*\)+.*/\1/p')
if [ -n "$bpo" ]; then
	codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
	[ -z "$codename" ] || pkg=$pkg/$codename-backports
fi
# one apt at a time: the kernels' parts run side by side (run.sh)
flock "${APT_LOCK:-/tmp/rdc-vm-apt.lock}" sh -c "apt-get download '$pkg' >/dev/null 2>&1 ||
	{ apt-get update >/dev/null 2>&1 && apt-get download '$pkg' >/dev/null; }"
dpkg-deb -x v4l2loopback-dkms_*.deb pkg
mv pkg/usr/src/v4l2loopback-* src
make -C "/lib/modules/$kver/build" M="$out/src" modules >build.log 2>&1 ||
	{ tail -n 20 build.log >&2; exit 1; }
echo "$ko"
