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
#  - the installed rdcctl and rdcd use librdc.so, and rdcd's sources do
#    not include librdc's or the chip's private headers;
#  - `make uninstall` leaves no file behind.
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
vars="O=$O DESTDIR=$dest PREFIX=$prefix LIBDIR=$libdir"

# shellcheck disable=SC2086 # $vars is a list of words
if $MAKE -s --no-print-directory $vars install >"$tmp/install.log" 2>&1; then
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
leak=$(grep -E '^(rdc_port_|rdc_dp_|rdc_backend_|rdc_client_|rdc_err_detail|rdc_fifo_feed|rdc_bus_|rdl_|dp_)' "$tmp/exports")
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

# The installed tools run on the installed library.
for t in rdcctl rdcd; do
	if readelf -d "$dest$prefix/bin/$t" | grep -q 'NEEDED.*\[librdc\.so\.1\]'; then
		ok "$t uses librdc.so.1"
	else
		bad "$t does not use librdc.so.1"
	fi
done
got=$(LD_LIBRARY_PATH="$dest$libdir" "$dest$prefix/bin/rdcctl" run \
	tests/install/scene.rdl | sed -n 's/^crc32 //p')
if [ -n "$want" ] && [ "$got" = "$want" ]; then
	ok "installed rdcctl: crc32 $got"
else
	bad "installed rdcctl: crc32 '$got', the build's '$want'"
fi
priv=$(grep -l '#include "\(rdc_priv\|rdc_client\|hw\|hw_priv\|dp\)\.h"' userspace/rdcd/*.[ch])
if [ -z "$priv" ]; then
	ok "rdcd's sources include no private header of librdc or the chip"
else
	bad "private headers included by: $priv"
fi

# shellcheck disable=SC2086
if $MAKE -s --no-print-directory $vars uninstall >"$tmp/uninstall.log" 2>&1; then
	left=$(find "$dest" ! -type d)
	if [ -z "$left" ]; then
		ok "make uninstall removed every file"
	else
		bad "make uninstall left: $(echo "$left" | head -n 5 | tr '\n' ' ')"
	fi
else
	cat "$tmp/uninstall.log"
	bad "make uninstall"
fi

echo "install: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
