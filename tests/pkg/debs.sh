#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The Debian packages, built and tried as a user of them would:
#  - `dpkg-buildpackage -us -uc -b` in a copy of the tree (every file git
#    tracks or would track, as it is now) in BUILD_DIR-debs, so the source
#    tree gets none of debhelper's files (and BUILD_DIR none of its
#    directories, which the Makefile would read as dependency files):
#    librdc1, librdc-dev, rdc-tools, python3-rdc and rdcfb-dkms, nothing
#    else;
#  - lintian over them: no error (its warnings are printed);
#  - each package unpacked (dpkg -x) into one scratch root, which must
#    then hold what each is for (the library and its SONAME link; headers,
#    rdc.pc, librdc.a; the programs with their manual pages, completion,
#    units and udev rule; the module's sources with dkms.conf);
#  - the unpacked rdcctl, on the unpacked librdc.so.1, runs
#    examples/demo.rdl and prints the CRC tests/golden/golden.txt holds;
#    the unpacked rdcd serves a client (the unpacked rdcctl) the same
#    frame; examples/hello.c builds with the unpacked rdc.pc alone and
#    prints the CRC the build's rdcctl gives tests/install/scene.rdl;
#    the unpacked python3-rdc, imported by Debian's python3 on the
#    unpacked library, gives examples/demo.rdl the same CRC, and offers
#    pytest its plugin through its entry point.
# Whether the module loads from the dkms package is the VM's to test:
# make check hands the package to rdcfb-dkms (tests/vm/dkms.sh).
# Closes with "debs: N passed, M failed".
#
#   tests/pkg/debs.sh BUILD_DIR        (from the source root; make debs)
set -u
O=${1:-build}
CC=${CC:-cc}
PKG_CONFIG=${PKG_CONFIG:-pkg-config}
pass=0
fail=0
ok() {
	pass=$((pass + 1))
	echo "debs: ok: $*"
}
bad() {
	fail=$((fail + 1))
	echo "debs: FAILED: $*"
}
finish() {
	echo "debs: $pass passed, $fail failed"
	[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
	exit $?
}
for t in dpkg-buildpackage dh dh_dkms lintian; do
	command -v $t >/dev/null 2>&1 || {
		echo "debs: $t is missing (scripts/deps.sh --debs installs it)"
		bad "tools"
		finish
	}
done
top=$PWD
case $O in
/*) work=${O%/}-debs ;;
*) work=$top/${O%/}-debs ;;
esac
rm -rf "$work"
mkdir -p "$work/src" "$work/root"

# The tree as it is, without build directories and ignored files.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
	git ls-files --cached --others --exclude-standard |
		while read -r f; do [ -e "$f" ] && printf '%s\n' "$f"; done |
		tar -cf - -T - | tar -xf - -C "$work/src"
else
	tar --exclude="./${O%/}*" --exclude='./build*' -cf - . |
		tar -xf - -C "$work/src"
fi
[ -f "$work/src/debian/control" ] || { bad "no debian/ in the copy"; finish; }

echo "debs: dpkg-buildpackage -us -uc -b (log: $work/build.log)"
if (cd "$work/src" && dpkg-buildpackage -us -uc -b -j2) >"$work/build.log" 2>&1; then
	ok "dpkg-buildpackage -us -uc -b"
else
	tail -n 60 "$work/build.log"
	bad "dpkg-buildpackage"
	finish
fi
# debhelper's automatic -dbgsym packages aside
debs=$(cd "$work" && ls ./*.deb | sed 's|^\./||' | grep -v -- '-dbgsym_' |
	sort | tr '\n' ' ')
names=$(for d in $debs; do echo "${d%%_*}"; done | sort | tr '\n' ' ')
if [ "$names" = "librdc-dev librdc1 python3-rdc rdc-tools rdcfb-dkms " ]; then
	ok "packages: $debs"
else
	bad "packages: '$names', want librdc-dev librdc1 python3-rdc rdc-tools rdcfb-dkms"
fi

changes=$(ls "$work"/*.changes | head -n 1)
lintian --no-tag-display-limit "$changes" >"$work/lintian.log" 2>&1
errors=$(grep -c '^E: ' "$work/lintian.log")
warnings=$(grep -c '^W: ' "$work/lintian.log")
grep '^[EW]: ' "$work/lintian.log" | sed 's/^/debs: lintian: /'
if [ "$errors" -eq 0 ]; then
	ok "lintian: no error ($warnings warnings)"
else
	bad "lintian: $errors errors"
fi

# Each package's dependencies are its own: dkms for the module's alone.
depbad=0
for d in $debs; do
	dep=$(dpkg-deb -f "$work/$d" Depends)
	case "${d%%_*}:$dep" in
	rdcfb-dkms:*dkms*) ;;
	rdcfb-dkms:*)
		bad "rdcfb-dkms does not depend on dkms: $dep"
		depbad=1
		;;
	*:*dkms*)
		bad "${d%%_*} depends on dkms: $dep"
		depbad=1
		;;
	esac
done
# The user units are left for users to enable: the postinst enables a
# unit again (an upgrade) only where it was installed and enabled before
# (dh_installsystemduser --no-enable's debian-installed guard).
pi=$work/tools-control/postinst
if ! dpkg-deb -e "$work"/rdc-tools_*.deb "$work/tools-control" ||
	{ grep -qs -- '--user enable' "$pi" &&
		! grep -qs -- '--user debian-installed' "$pi"; }; then
	bad "rdc-tools enables rdcd's user units at installation"
elif [ $depbad -eq 0 ]; then
	ok "dependencies as each package needs; the user units are not enabled at installation"
fi

root=$work/root
for d in $debs; do
	dpkg -x "$work/$d" "$root" || bad "dpkg -x $d"
done
ma=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
missing=
for f in usr/lib/$ma/librdc.so.1 usr/lib/$ma/librdc.so usr/lib/$ma/librdc.a \
	usr/lib/$ma/pkgconfig/rdc.pc usr/include/rdc/rdc.h \
	usr/bin/rdcctl usr/bin/rdcd usr/share/man/man1/rdcctl.1.gz \
	usr/share/man/man8/rdcd.8.gz usr/share/man/man5/rdl.5.gz \
	usr/share/man/man3/librdc.3.gz \
	usr/share/bash-completion/completions/rdcctl \
	usr/lib/systemd/user/rdcd.service usr/lib/systemd/user/rdcd.socket \
	usr/lib/udev/rules.d/70-rdc.rules; do
	[ -e "$root/$f" ] || missing="$missing /$f"
done
src=$(ls -d "$root"/usr/src/rdcfb-* 2>/dev/null | head -n 1)
if [ -z "$src" ]; then
	missing="$missing /usr/src/rdcfb-*"
else
	for f in dkms.conf Kbuild driver/rdcfb_main.c hw-sim/rdc_regs.h \
		firmware-model/dp.c; do
		[ -e "$src/$f" ] || missing="$missing ${src#"$root"}/$f"
	done
fi
if [ -z "$missing" ]; then
	ok "the packages hold the library, headers, rdc.pc, programs, manual pages, completion, units, udev rule and ${src#"$root"}"
else
	bad "missing from the packages:$missing"
fi

# The unpacked programs on the unpacked library.
LD_LIBRARY_PATH=$root/usr/lib/$ma
export LD_LIBRARY_PATH
lib=$(ldd "$root/usr/bin/rdcctl" | sed -n 's/.*librdc\.so\.1 => \([^ ]*\).*/\1/p')
case "$lib" in
"$root"/*) ok "rdcctl uses the packaged librdc.so.1" ;;
*) bad "rdcctl's librdc.so.1 is '$lib', not the packaged one" ;;
esac
want=$(awk '$1 == "example_demo" { print $2 }' tests/golden/golden.txt)
got=$("$root/usr/bin/rdcctl" run examples/demo.rdl | sed -n 's/^crc32 //p')
if [ -n "$want" ] && [ "$got" = "$want" ]; then
	ok "packaged rdcctl run examples/demo.rdl: crc32 $got, as golden.txt"
else
	bad "packaged rdcctl: crc32 '$got', golden.txt '$want'"
fi

sock=$work/rdc.sock
"$root/usr/bin/rdcd" --stepped --listen "unix:$sock" \
	--ready-file "$work/ready" >"$work/rdcd.log" 2>&1 &
pid=$!
i=0
while [ ! -f "$work/ready" ] && [ $i -lt 200 ] && kill -0 $pid 2>/dev/null; do
	sleep 0.1
	i=$((i + 1))
done
got=$("$root/usr/bin/rdcctl" --connect "unix:$sock" run examples/demo.rdl |
	sed -n 's/^crc32 //p')
kill $pid 2>/dev/null
wait $pid
st=$?
if [ -n "$want" ] && [ "$got" = "$want" ] && [ $st -eq 0 ]; then
	ok "packaged rdcd served the packaged rdcctl: crc32 $got, clean exit"
else
	cat "$work/rdcd.log"
	bad "packaged rdcd: crc32 '$got' (want '$want'), exit $st"
fi

# python3-rdc on the unpacked library, with nothing from the tree.
pysite=$root/usr/lib/python3/dist-packages
want=$(awk '$1 == "example_demo" { print $2 }' tests/golden/golden.txt)
got=$(cd "$work" && PYTHONPATH=$pysite PYTHONDONTWRITEBYTECODE=1 \
	/usr/bin/python3 -c '
import importlib.metadata as md, os, sys, rdc
assert rdc.library().startswith(sys.argv[2]), rdc.library()
eps = [e.value for e in md.entry_points(group="pytest11")]
assert "rdc.pytest_plugin" in eps, eps
with rdc.open() as d:
    r = d.script_run_file(sys.argv[1])
    d.script_frame_wait(r)
    print("%08x" % d.frame_crc())' "$top/examples/demo.rdl" "$root/" 2>&1)
if [ -n "$want" ] && [ "$got" = "$want" ]; then
	ok "python3-rdc on the packaged librdc.so.1: demo crc32 $got, pytest plugin registered"
else
	bad "python3-rdc: '$got', want crc32 '$want'"
fi

# A program of one's own against librdc-dev, through its rdc.pc alone.
syspc=$($PKG_CONFIG --variable pc_path pkg-config)
want=$("$root/usr/bin/rdcctl" run tests/install/scene.rdl |
	sed -n 's/^crc32 //p')
if cflags=$(PKG_CONFIG_SYSROOT_DIR=$root \
	PKG_CONFIG_LIBDIR=$root/usr/lib/$ma/pkgconfig:$syspc \
	$PKG_CONFIG --cflags --libs rdc) &&
	# shellcheck disable=SC2086 # a list of words
	$CC -Wall -Werror examples/hello.c $cflags -o "$work/hello" \
		2>"$work/hello.err"; then
	got=$("$work/hello" | sed -n 's/^crc32 //p')
	if [ -n "$got" ] && [ "$got" = "$want" ]; then
		ok "examples/hello.c with the packaged rdc.pc: crc32 $got"
	else
		bad "hello: crc32 '$got', rdcctl '$want'"
	fi
else
	cat "$work/hello.err" 2>/dev/null
	bad "examples/hello.c does not build with the packaged rdc.pc"
fi
finish
