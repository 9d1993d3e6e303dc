#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The Python example suite (examples/python, docs/python.md) run as its
# users would against the kernel's RDC-1s instead of the simulator:
# pytest --rdc-uri fbdev:/dev/fbN on rdcfb.ko and --rdc-uri
# drm:/dev/dri/cardN on rdcdrm.ko, both on their stepped clocks: every
# test passes but the one that needs the simulator's exact edge times,
# which skips.  The present on TE among them: a GPIO-line wait is for
# the next edge after the call, not one the lines' queue held before it.
# Skipped without python3 and pytest (Debian: python3-pytest).
# vm-module: rdcfb clock=stepped
# vm-module: rdcdrm clock=stepped
. "$RDC_TREE/tests/vm/lib.sh"

PY=/usr/bin/python3
if [ ! -x "$PY" ] || ! "$PY" -c 'import pytest' 2>/dev/null; then
	echo "python3 with pytest not installed (Debian: python3-pytest)"
	exit 77
fi
# the console would draw on the devices between the tests' operations
fbcon_unbind

FB=""
for f in /dev/fb*; do
	[ -c "$f" ] || continue
	"$RDCCTL" --connect "fbdev:$f" regs >/dev/null 2>&1 && { FB=$f; break; }
done
CARD=""
for c in /dev/dri/card*; do
	[ -c "$c" ] || continue
	"$RDCCTL" --connect "drm:$c" regs >/dev/null 2>&1 && { CARD=$c; break; }
done

# suite URI: the example suite on URI; all but one pass (above)
suite() {
	(cd "$T" && PYTHONPATH=$RDC_TREE/python RDC_LIBRARY=$B/librdc.so.1 \
		PYTHONDONTWRITEBYTECODE=1 "$PY" -m pytest -p no:cacheprovider \
		--basetemp="$T/pytest" -rs "$RDC_TREE/examples/python" \
		--rdc-uri "$1") >"$T/pytest.out" 2>&1
	rc=$?
	cat "$T/pytest.out"
	[ $rc -eq 0 ] && grep -Eq ' [0-9]+ passed, 1 skipped in ' \
		"$T/pytest.out"
}
if [ -n "$FB" ]; then
	check "examples/python through fbdev:$FB (rdcfb.ko)" suite "fbdev:$FB"
else
	check "rdcfb.ko's framebuffer found" false
fi
if [ -n "$CARD" ]; then
	check "examples/python through drm:$CARD (rdcdrm.ko)" suite "drm:$CARD"
else
	check "rdcdrm.ko's card found" false
fi
finish
