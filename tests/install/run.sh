#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# librdc as a program outside the tree meets it: `make install` into a
# scratch DESTDIR (PREFIX and LIBDIR not the defaults), then, with nothing
# but what pkg-config says about the installed rdc.pc:
#  - the installed headers compile alone (-Wall -Wextra -Werror -Wundef,
#    C99 -pedantic) and define no macro outside RDC_* / rdc_* (the check
#    is first shown to catch hw-sim's own rdc_regs.h, which defines BIT);
#  - librdc.so has its SONAME and exports rdc_* functions only, the public
#    ones under RDC_<major>, none of the internals;
#  - examples/hello.c, built shared and static, draws its scene and prints
#    the same frame CRC as the build's own rdcctl running
#    tests/install/scene.rdl; so does the installed rdcctl;
#  - the installed rdcctl and rdcd use librdc.so, through a RUNPATH
#    naming LIBDIR (/opt/rdc/lib64: not where the loader looks), and
#    rdcd's sources do not include librdc's or the chip's private headers;
#  - a DESTDIR install does not run ldconfig;
#  - the Python package lands where python3 finds it for PREFIX, and
#    imported from there runs the scene on the installed librdc.so.1;
#  - `make uninstall` leaves no file and no directory behind;
#  - $O/rel/rdc.pc (PKG_CONFIG_PATH=$O/rel) builds examples/hello.c from
#    the tree, and it draws the same frame;
#  - installed into a scratch PREFIX on the live system (no DESTDIR),
#    rdcctl runs on the system's loader alone (no LD_LIBRARY_PATH);
#  - as root, with unshare: `make install` with the default PREFIX into
#    the live system, seen only in a private mount namespace (an empty
#    /usr/local, a copy of /etc for ldconfig's cache): the installed
#    rdcctl and examples/hello.c built with pkg-config run on the
#    system's loader, through the ldconfig make install ran, and make
#    uninstall empties /usr/local again.
# Closes with "install: N passed, M failed".
#
#   tests/install/run.sh BUILD_DIR     (from the source root; make
#                                       install-check builds first)
set -u
O=${1:-build}
MAKE=${MAKE:-make}
CC=${CC:-cc}
PKG_CONFIG=${PKG_CONFIG:-pkg-config}
pass=0
fail=0
ok() {
	pass=$((pass + 1))
	echo "install: ok: $*"
}
bad() {
	fail=$((fail + 1))
	echo "install: FAILED: $*"
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
dest=$tmp/root
prefix=/opt/rdc
libdir=$prefix/lib64
# the directories make install creates are logged here, not in $O
vars="O=$O DESTDIR=$dest PREFIX=$prefix LIBDIR=$libdir RDC_INSTALL_DIRS=$tmp/dirs"

# shellcheck disable=SC2086 # $vars is a list of words
# (LDCONFIG=false: a DESTDIR install that ran ldconfig would fail)
if $MAKE -s --no-print-directory $vars LDCONFIG=false install \
	>"$tmp/install.log" 2>&1; then
	ok "make install"
else
	cat "$tmp/install.log"
	bad "make install"
	echo "install: $pass passed, $fail failed"
	exit 1
fi
for f in bin/rdcctl bin/rdcd lib64/librdc.a lib64/librdc.so \
	lib64/librdc.so.1 lib64/pkgconfig/rdc.pc include/rdc/rdc.h \
	include/rdc/rdc_regs.h include/rdc/rdc_sink.h include/rdc/rdc_proto.h; do
	[ -e "$dest$prefix/$f" ] || bad "installed: $prefix/$f missing"
done
lib=$(readlink -f "$dest$libdir/librdc.so")
soname=$(readelf -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
if [ "$soname" = librdc.so.1 ] && [ "$(readlink "$dest$libdir/librdc.so.1")" = "$(basename "$lib")" ]; then
	ok "$(basename "$lib"): SONAME $soname, links librdc.so.1 and librdc.so"
else
	bad "SONAME '$soname' or the links of $(basename "$lib")"
fi

# Exports: rdc_* functions only, versioned; none of the internals.
nm -D --defined-only "$lib" | awk '{ print $3 }' >"$tmp/exports"
grep -v '^RDC_' "$tmp/exports" | grep -v '^rdc_[a-z0-9_]*@@\?RDC_' >"$tmp/foreign"
n=$(grep -c '^rdc_' "$tmp/exports")
if [ -s "$tmp/foreign" ]; then
	bad "librdc.so exports more than rdc_* functions: $(head -n 5 "$tmp/foreign" | tr '\n' ' ')"
elif ! grep -q '^rdc_open@@RDC_1$' "$tmp/exports"; then
	bad "librdc.so: rdc_open@@RDC_1 is not exported"
else
	ok "librdc.so exports $n rdc_* functions and nothing else"
fi
# hw-sim's DP port, the backends, the script interpreter's insides and
# librdc's private helpers stay inside
leak=$(grep -E '^(rdc_port_|rdc_dp_|rdc_backend_|rdc_client_|rdc_err_detail|rdc_fifo_feed@|rdc_bus_|rdl_|dp_)' "$tmp/exports")
if [ -n "$leak" ]; then
	bad "internal symbols exported: $(echo "$leak" | head -n 5 | tr '\n' ' ')"
else
	ok "no internal symbol exported"
fi

# The installed rdc.pc first; the system's for the libraries it requires.
syspc=$($PKG_CONFIG --variable pc_path pkg-config)
PKG_CONFIG_SYSROOT_DIR="$dest"
PKG_CONFIG_LIBDIR="$dest$libdir/pkgconfig:$syspc"
export PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_LIBDIR
if cflags=$($PKG_CONFIG --cflags rdc) && libs=$($PKG_CONFIG --libs rdc) &&
	slibs=$($PKG_CONFIG --static --libs rdc); then
	ok "pkg-config rdc $($PKG_CONFIG --modversion rdc): $cflags $libs"
else
	bad "pkg-config cannot read the installed rdc.pc"
fi
case " $cflags $libs " in
*"$PWD"*) bad "pkg-config points into the source tree: $cflags $libs" ;;
esac

# Every installed header alone, and the macros it brings.
printf '#include <stddef.h>\n#include <stdint.h>\n#include <stdbool.h>\n' >"$tmp/base.c"
$CC -dM -E "$tmp/base.c" | awk '{ sub(/\(.*/, "", $2); print $2 }' |
	sort -u >"$tmp/base.macros"
# foreign_macros FILE CFLAGS...: macros FILE defines outside RDC_*/rdc_*
foreign_macros() {
	h=$1
	shift
	echo "#include \"$h\"" >"$tmp/one.c"
	# shellcheck disable=SC2068 # the flags are words
	$CC $@ -dM -E "$tmp/one.c" | awk '{ sub(/\(.*/, "", $2); print $2 }' |
		sort -u | comm -23 - "$tmp/base.macros" | grep -v '^RDC_\|^rdc_'
}
if foreign_macros "$PWD/hw-sim/rdc_regs.h" -I"$PWD/hw-sim" | grep -q '^BIT$'; then
	ok "the macro check sees hw-sim/rdc_regs.h's BIT"
else
	bad "the macro check does not see hw-sim/rdc_regs.h's BIT"
fi
hdrs=0
for h in "$dest$prefix"/include/rdc/*.h; do
	b=$(basename "$h")
	echo "#include <$b>" >"$tmp/alone.c"
	# shellcheck disable=SC2086 # $cflags is a list of words
	if ! $CC -std=c99 -pedantic -Wall -Wextra -Werror -Wundef $cflags \
		-c "$tmp/alone.c" -o "$tmp/alone.o" 2>"$tmp/alone.err"; then
		cat "$tmp/alone.err"
		bad "<$b> does not compile alone"
		continue
	fi
	# shellcheck disable=SC2086
	m=$(foreign_macros "$b" $cflags)
	if [ -n "$m" ]; then
		bad "<$b> defines macros outside RDC_*/rdc_*: $(echo "$m" | tr '\n' ' ')"
		continue
	fi
	hdrs=$((hdrs + 1))
done
[ "$hdrs" -gt 0 ] && ok "$hdrs installed headers compile alone and define RDC_*/rdc_* macros only"

# The scene's CRC as the build's rdcctl computes it, from the script.
want=$("$O/rel/rdcctl" run tests/install/scene.rdl | sed -n 's/^crc32 //p')
[ -n "$want" ] || bad "$O/rel/rdcctl run tests/install/scene.rdl gave no crc32"

# The Python package where PYTHON (Debian's python3) finds it for this
# PREFIX, importable from there alone and drawing on the installed
# librdc.so.1 what rdcctl draws.
py=${PYTHON:-/usr/bin/python3}
if [ ! -x "$py" ]; then
	echo "install: skipped: the Python package ($py not found)"
else
	site=$dest$("$py" scripts/python-sitedir.py "$prefix")
	for f in rdc/__init__.py rdc/_lib.py rdc/pytest_plugin.py \
		rdc/_constants.py rdc-*.dist-info/entry_points.txt; do
		# shellcheck disable=SC2086 # the dist-info's name is a pattern
		[ -e "$(echo $site/$f)" ] || bad "installed: $site/$f missing"
	done
	got=$(env -u RDC_LIBRARY PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 \
		LD_LIBRARY_PATH="$dest$libdir" "$py" -c '
import os, sys, rdc
assert rdc._headers.source_tree() is None, "the tree, not the install"
with rdc.open() as d:
    r = d.script_run_file(sys.argv[1])
    d.script_frame_wait(r)
    print(os.path.realpath(rdc.library()), "%08x" % d.frame_crc())' \
		tests/install/scene.rdl 2>&1)
	lib1=$(readlink -f "$dest$libdir/librdc.so.1")
	if [ "$got" = "$lib1 $want" ]; then
		ok "python3 imports the installed rdc on the installed librdc.so.1: crc32 $want"
	else
		bad "the installed Python package: '$got', want '$lib1 $want'"
	fi
fi

cp examples/hello.c "$tmp/hello.c"
cd "$tmp" || exit 1
# shellcheck disable=SC2086
if $CC -Wall -Werror $cflags hello.c $libs -o hello-shared 2>build.err; then
	need=$(readelf -d hello-shared | grep -c 'NEEDED.*\[librdc\.so\.1\]')
	got=$(LD_LIBRARY_PATH="$dest$libdir" ./hello-shared | sed -n 's/^crc32 //p')
	if [ "$need" = 1 ] && [ -n "$want" ] && [ "$got" = "$want" ]; then
		ok "hello (shared, librdc.so.1): crc32 $got as rdcctl's"
	else
		bad "hello (shared): crc32 '$got', rdcctl '$want', NEEDED librdc.so.1 $need"
	fi
else
	cat build.err
	bad "hello (shared) does not build"
fi
# static: the same pkg-config line with --static, librdc.a for -lrdc
slibs=$(echo " $slibs " | sed 's/ -lrdc / -l:librdc.a /')
# shellcheck disable=SC2086
if $CC -Wall -Werror $cflags hello.c $slibs -o hello-static 2>build.err; then
	need=$(readelf -d hello-static | grep -c 'NEEDED.*librdc')
	got=$(./hello-static | sed -n 's/^crc32 //p')
	if [ "$need" = 0 ] && [ -n "$want" ] && [ "$got" = "$want" ]; then
		ok "hello (static librdc.a): crc32 $got as rdcctl's"
	else
		bad "hello (static): crc32 '$got', rdcctl '$want', NEEDED librdc $need"
	fi
else
	cat build.err
	bad "hello (static) does not build"
fi
cd - >/dev/null || exit 1

# The installed tools run on the installed library, which LIBDIR, not a
# directory the loader searches, holds: their RUNPATH names it.
for t in rdcctl rdcd; do
	rp=$(readelf -d "$dest$prefix/bin/$t" | sed -n 's/.*(RUNPATH).*\[\(.*\)\]/\1/p')
	if readelf -d "$dest$prefix/bin/$t" | grep -q 'NEEDED.*\[librdc\.so\.1\]' &&
		[ "$rp" = "$libdir" ]; then
		ok "$t uses librdc.so.1, RUNPATH $rp"
	else
		bad "$t: NEEDED librdc.so.1 and RUNPATH $libdir wanted, RUNPATH '$rp'"
	fi
done

# In the tree, as installed: $O/rel/rdc.pc names librdc.a and the
# headers make install lays out.
if tflags=$(env -u PKG_CONFIG_SYSROOT_DIR -u PKG_CONFIG_LIBDIR \
	PKG_CONFIG_PATH="$O/rel" $PKG_CONFIG --cflags --libs rdc) &&
	# shellcheck disable=SC2086 # the flags are words
	$CC -Wall -Werror examples/hello.c $tflags -o "$tmp/hello-tree" \
		2>"$tmp/tree.err"; then
	got=$("$tmp/hello-tree" | sed -n 's/^crc32 //p')
	if [ -n "$want" ] && [ "$got" = "$want" ]; then
		ok "hello (PKG_CONFIG_PATH=$O/rel): crc32 $got"
	else
		bad "hello (PKG_CONFIG_PATH=$O/rel): crc32 '$got', rdcctl '$want'"
	fi
else
	cat "$tmp/tree.err" 2>/dev/null
	bad "PKG_CONFIG_PATH=$O/rel pkg-config --cflags --libs rdc does not build examples/hello.c"
fi

# Into the live system under a scratch PREFIX (not a directory the loader
# searches): the installed rdcctl runs on the system's loader alone.
live=$tmp/live
if $MAKE -s --no-print-directory O="$O" PREFIX="$live" \
	RDC_INSTALL_DIRS="$tmp/live-dirs" LDCONFIG=false install \
	>"$tmp/live.log" 2>&1; then
	got=$(env -u LD_LIBRARY_PATH "$live/bin/rdcctl" run \
		tests/install/scene.rdl 2>"$tmp/live.err" | sed -n 's/^crc32 //p')
	if [ -n "$want" ] && [ "$got" = "$want" ]; then
		ok "rdcctl installed in $live runs on the system's loader: crc32 $got"
	else
		cat "$tmp/live.err"
		bad "rdcctl installed in $live: crc32 '$got', the build's '$want'"
	fi
	$MAKE -s --no-print-directory O="$O" PREFIX="$live" \
		RDC_INSTALL_DIRS="$tmp/live-dirs" uninstall >>"$tmp/live.log" 2>&1
	if [ -e "$live" ]; then
		bad "make uninstall left $(find "$live" | head -n 5 | tr '\n' ' ')"
	fi
else
	cat "$tmp/live.log"
	bad "make install PREFIX=$live"
fi
priv=$(grep -l '#include "\(rdc_priv\|rdc_client\|hw\|hw_priv\|dp\)\.h"' userspace/rdcd/*.[ch])
if [ -z "$priv" ]; then
	ok "rdcd's sources include no private header of librdc or the chip"
else
	bad "private headers included by: $priv"
fi

# shellcheck disable=SC2086
if $MAKE -s --no-print-directory $vars uninstall >"$tmp/uninstall.log" 2>&1; then
	left=$(find "$dest" 2>/dev/null)
	if [ -z "$left" ]; then
		ok "make uninstall removed every file and directory it made"
	else
		bad "make uninstall left: $(echo "$left" | head -n 5 | tr '\n' ' ')"
	fi
else
	cat "$tmp/uninstall.log"
	bad "make uninstall"
fi

# The default PREFIX in the live system, as a new user installs, in a
# mount namespace of its own: an empty /usr/local and a copy of /etc,
# whose ld.so.cache the ldconfig of make install rewrites.
if [ "$(id -u)" != 0 ] || ! unshare -m true 2>/dev/null; then
	echo "install: skipped: make install into /usr/local in a mount namespace (needs root and unshare)"
elif ! cp -a /etc "$tmp/etc" 2>"$tmp/etc.err"; then
	cat "$tmp/etc.err"
	bad "cannot copy /etc for the mount namespace"
else
	cat >"$tmp/ns.sh" <<EOF
mount -t tmpfs rdc-install /usr/local && mount --bind "$tmp/etc" /etc || exit 1
unset LD_LIBRARY_PATH PKG_CONFIG_PATH PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR
$MAKE -s --no-print-directory O="$O" RDC_INSTALL_DIRS="$tmp/ns-dirs" install \\
	>"$tmp/ns.log" 2>&1 || { cat "$tmp/ns.log"; echo "ns: make install failed"; exit 1; }
grep -q 'ldconfig\$' "$tmp/ns.log" && echo "ns: ldconfig ran"
readelf -d /usr/local/bin/rdcctl | grep -q RUNPATH && echo "ns: rdcctl has a RUNPATH"
echo "ns: rdcctl \$(/usr/local/bin/rdcctl run tests/install/scene.rdl 2>&1 | sed -n 's/^crc32 //p;/error/p')"
$CC -Wall -Werror examples/hello.c \$(pkg-config --cflags --libs rdc) \\
	-o "$tmp/hello-ns" && echo "ns: hello \$("$tmp/hello-ns" 2>&1 | sed -n 's/^crc32 //p;/error/p')"
$MAKE -s --no-print-directory O="$O" RDC_INSTALL_DIRS="$tmp/ns-dirs" uninstall \\
	>>"$tmp/ns.log" 2>&1 || echo "ns: make uninstall failed"
echo "ns: left \$(find /usr/local -mindepth 1 | head -n 5 | tr '\n' ' ')"
EOF
	unshare -m sh "$tmp/ns.sh" >"$tmp/ns.out" 2>&1
	cat "$tmp/ns.out"
	if grep -q '^ns: ldconfig ran$' "$tmp/ns.out" &&
		! grep -q '^ns: rdcctl has a RUNPATH' "$tmp/ns.out"; then
		ok "make install into /usr/local ran ldconfig, and linked no RUNPATH"
	else
		bad "make install into /usr/local: no ldconfig, or a RUNPATH"
	fi
	if [ -n "$want" ] && grep -qx "ns: rdcctl $want" "$tmp/ns.out" &&
		grep -qx "ns: hello $want" "$tmp/ns.out"; then
		ok "/usr/local/bin/rdcctl and hello built with pkg-config run on the system's loader: crc32 $want"
	else
		bad "/usr/local/bin/rdcctl or hello built with pkg-config: not crc32 '$want'"
	fi
	if grep -qx 'ns: left ' "$tmp/ns.out"; then
		ok "make uninstall left /usr/local empty, as it was"
	else
		bad "make uninstall in /usr/local: $(grep '^ns: left' "$tmp/ns.out")"
	fi
fi

echo "install: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
