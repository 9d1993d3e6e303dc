#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Build rdcdrm.ko (driver/ with hw-sim/ and firmware-model/, through the
# top-level Kbuild) against the headers of kernel $1, in $2; print the
# .ko's path (the Kbuild builds rdcfb.ko beside it).  Kbuild runs in a
# tree of links to the sources, so nothing is written beside them.  The
# harness copies the DRM modules it depends on (drm, drm_kms_helper,
# drm_shmem_helper...) into the initramfs from its modinfo.
set -e
# Not the outer make's variables (O=, -j...): they mean other things to
# Kbuild.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES O
kver=$1
out=$2
root=$(cd "$(dirname "$0")/../../.." && pwd)
for d in hw-sim firmware-model driver; do
	mkdir -p "$out/$d"
	ln -sf "$root/$d"/*.[ch] "$out/$d/"
done
find "$out" -xtype l -delete
ln -sf "$root/Kbuild" "$out/Kbuild"
make -C "/lib/modules/$kver/build" M="$out" modules >"$out/build.log" 2>&1 ||
	{ tail -n 20 "$out/build.log" >&2; exit 1; }
echo "$out/rdcdrm.ko"
