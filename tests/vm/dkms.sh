#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# For a VM test's "# vm-dkms: NAME" line (run.sh): `dkms add`, `dkms
# build` and `dkms install` NAME (rdcfb: the layout scripts/dkms-source.sh
# makes) for kernel $2, here, as a user would, with everything dkms
# writes kept in $3:
#
#   tests/vm/dkms.sh NAME KVER OUTDIR
#
# The source is the tree's (scripts/dkms-source.sh), or with
# RDC_DKMS_DEB=PATH the files of that rdcfb-dkms package (make debs).
#
# dkms runs in a mount namespace of its own where /usr/src, /var/lib/dkms
# and /lib/modules/KVER are overlays with their upper layers in
# OUTDIR/upper/{src,dkms,modules}, so this machine's own trees are never
# written.  The guest lays the same upper layers over its view of those
# trees (tests/vm/tests/rdcfb-dkms.sh), so its modprobe finds the module
# where `dkms install` put it and `dkms status` reads dkms's own state.
# The build is the slow part, done here at full speed rather than in the
# emulated guest.  OUTDIR/dkms.log keeps dkms's output.
set -e
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES O
name=$1
kver=$2
out=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
[ "$name" = rdcfb ] || { echo "dkms.sh: no dkms source for $name" >&2; exit 1; }
[ "$(id -u)" = 0 ] || { echo "dkms.sh: dkms needs root" >&2; exit 1; }
command -v dkms >/dev/null || { echo "dkms.sh: dkms is not installed" >&2; exit 1; }

# Done before, and nothing it was made from has changed since?
stamp=$out/installed
if [ -f "$stamp" ] && [ "$stamp" -nt "/lib/modules/$kver/build/Module.symvers" ] &&
	[ -z "$(find "$root/Kbuild" "$root/driver" "$root/hw-sim" \
		"$root/firmware-model" "$root/scripts/dkms-source.sh" "$0" \
		${RDC_DKMS_DEB:+"$RDC_DKMS_DEB"} \
		-newer "$stamp" -print 2>/dev/null | head -n 1)" ] &&
	[ "$(cat "$out/from" 2>/dev/null)" = "${RDC_DKMS_DEB:-tree}" ]; then
	exit 0
fi
rm -rf "$out"
mkdir -p "$out"
if [ -n "${RDC_DKMS_DEB:-}" ]; then
	# the rdcfb-dkms package's own files (make debs), as its postinst
	# hands them to dkms
	dpkg-deb -x "$RDC_DKMS_DEB" "$out/deb"
	src=$(ls -d "$out"/deb/usr/src/rdcfb-* | head -n 1)
	[ -f "$src/dkms.conf" ] ||
		{ echo "dkms.sh: $RDC_DKMS_DEB holds no dkms.conf" >&2; exit 1; }
	echo "dkms.sh: source from $RDC_DKMS_DEB"
else
	src=$(sh "$root/scripts/dkms-source.sh" "$out/source")
fi
ver=${src##*/rdcfb-}
printf '%s\n' "$ver" >"$out/version"

unshare -m sh -e -c '
	out=$1
	kver=$2
	src=$3
	ver=$4
	# dkms'"'"'s own trees, as its configuration names them (these are
	# its defaults); they must exist already: nothing is created on
	# this machine outside the namespace'"'"'s overlays
	source_tree=/usr/src
	dkms_tree=/var/lib/dkms
	install_tree=/lib/modules
	[ ! -r /etc/dkms/framework.conf ] || . /etc/dkms/framework.conf
	mount --make-rprivate /
	for m in "src:$source_tree" "dkms:$dkms_tree" "modules:$install_tree/$kver"; do
		n=${m%%:*}
		d=${m#*:}
		[ -d "$d" ] || { echo "dkms.sh: $d does not exist" >&2; exit 1; }
		mkdir -p "$out/upper/$n" "$out/scratch/$n"
		mount -t overlay overlay \
			-o "lowerdir=$d,upperdir=$out/upper/$n,workdir=$out/scratch/$n" "$d"
	done
	dkms add "$src"
	dkms build -m rdcfb -v "$ver" -k "$kver" -j 2
	dkms install -m rdcfb -v "$ver" -k "$kver"
	dkms status -m rdcfb -v "$ver" -k "$kver"
' dkms "$out" "$kver" "$src" "$ver" >"$out/dkms.log" 2>&1 ||
	{ tail -n 30 "$out/dkms.log" >&2; exit 1; }
# overlayfs's scratch directories (workdir=), not to be shared
rm -rf "$out/scratch"
printf '%s\n' "${RDC_DKMS_DEB:-tree}" >"$out/from"
touch "$stamp"
