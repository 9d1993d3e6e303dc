#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The Python bindings (python/rdc) and their pytest plugin, from the
# source tree without installing: tests/python (the bindings against
# librdc and rdcctl, every golden scene, the plugin's fixtures through
# pytester) and the example suite examples/python, with Debian's python3
# on BUILD_DIR/rel/librdc.so.1, rdcctl and rdcd.  Closes with
# "python: N passed, M failed, K skipped"; without python3, pytest or the
# shared library it says why and counts one skip.
#
#   tests/python/run.sh [BUILD_DIR]    (from the source root; make
#                                       python-check, tests/run.sh)
set -u
O=${1:-build}
# Debian's interpreter, whose dist-packages hold python3-pytest and
# python3-numpy: not whatever python3 comes first in PATH
py=${RDC_PYTHON:-/usr/bin/python3}
skip() {
	echo "python: skipped: $*"
	echo "python: 0 passed, 0 failed, 1 skipped"
	exit 0
}
if [ ! -f "$py" ] || [ ! -x "$py" ]; then
	skip "$py not found (Debian: python3)"
fi
"$py" -c 'import pytest' 2>/dev/null ||
	skip "pytest not importable by $py (Debian: python3-pytest)"
[ -e "$O/rel/librdc.so.1" ] ||
	skip "$O/rel/librdc.so.1 not built (make O=$O shared)"
"$py" -c 'import numpy' 2>/dev/null ||
	echo "python: numpy not importable by $py: frames as bytes only, the numpy tests skip (Debian: python3-numpy)"

# absolute: pytester runs tests in directories of their own
top=$PWD
O=$(cd "$O" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
PYTHONPATH=$top/python${PYTHONPATH:+:$PYTHONPATH}
RDC_LIBRARY=$O/rel/librdc.so.1
RDC_RDCCTL=$O/rel/rdcctl
RDC_RDCD=$O/rel/rdcd
PYTHONDONTWRITEBYTECODE=1
export PYTHONPATH RDC_LIBRARY RDC_RDCCTL RDC_RDCD PYTHONDONTWRITEBYTECODE
# the plugin's own --rdc-uri default: these tests are the simulator's
unset RDC_URI
"$py" -m pytest -p no:cacheprovider -rs --basetemp="$tmp/pytest" \
	--junitxml="$tmp/junit.xml" tests/python examples/python
rc=$?
counts=$("$py" - "$tmp/junit.xml" <<'EOF'
import sys
import xml.etree.ElementTree as ET

try:
    root = ET.parse(sys.argv[1]).getroot()
except (OSError, ET.ParseError):
    print("0 0 0")
    sys.exit()
suites = [root] if root.tag == "testsuite" else root.findall("testsuite")
n = {k: sum(int(s.get(k, 0)) for s in suites)
     for k in ("tests", "failures", "errors", "skipped")}
failed = n["failures"] + n["errors"]
print(n["tests"] - failed - n["skipped"], failed, n["skipped"])
EOF
)
# shellcheck disable=SC2086 # three numbers
set -- $counts
pass=$1 fail=$2 skipped=$3
# pytest failing without a failed test (a usage or collection error)
[ "$rc" -ne 0 ] && [ "$fail" -eq 0 ] && fail=1
echo "python: $pass passed, $fail failed, $skipped skipped"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
