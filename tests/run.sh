#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Run every cmocka test program in $1/tests, then the Python tests
# (tests/python/run.sh), from the source root and close with one summary
# line: "tests: N passed, M failed, K skipped" (cmocka's
# skip(): a test that cannot run here, e.g. a library this build lacks,
# says why in its output), after the names of the skipped tests.
set -u
dir=${1:-build/san}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
pass=0
fail=0
skipped=0
bad=""
skips=""
for t in "$dir"/tests/test_*; do
	[ -x "$t" ] || continue
	out=$("$t" 2>&1)
	rc=$?
	printf '%s\n' "$out"
	p=$(printf '%s\n' "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | tail -n 1)
	f=$(printf '%s\n' "$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | tail -n 1)
	# cmocka 1.1: "[  SKIPPED ] N test(s), listed below:", then a line
	# per skipped test
	s=$(printf '%s\n' "$out" | sed -n 's/^\[  SKIPPED \] \([0-9]*\) test(s), listed below:.*/\1/p' | tail -n 1)
	for n in $(printf '%s\n' "$out" | sed -n '/^\[  SKIPPED \] [0-9]* test(s), listed below:/,$ s/^\[  SKIPPED \] \([^ ]*\)$/\1/p'); do
		skips="$skips $(basename "$t"):$n"
	done
	pass=$((pass + ${p:-0}))
	skipped=$((skipped + ${s:-0}))
	if [ $rc -ne 0 ] && [ -z "$f" ]; then
		f=1 # crashed or sanitizer abort before cmocka's summary
	fi
	fail=$((fail + ${f:-0}))
	[ $rc -ne 0 ] && bad="$bad $(basename "$t")"
done
# The Python bindings and pytest plugin on $dir's sibling rel/ build
# (librdc.so.1), counted with the rest: tests/python/run.sh
out=$(tests/python/run.sh "$(dirname "$dir")" 2>&1)
printf '%s\n' "$out"
c=$(printf '%s\n' "$out" | sed -n 's/^python: \([0-9]*\) passed, \([0-9]*\) failed, \([0-9]*\) skipped$/\1 \2 \3/p' | tail -n 1)
# shellcheck disable=SC2086 # three numbers
set -- ${c:-0 1 0}
pass=$((pass + $1))
fail=$((fail + $2))
skipped=$((skipped + $3))
[ "$3" -gt 0 ] && skips="$skips python"
[ "$2" -gt 0 ] && bad="$bad python"
[ -n "$skips" ] && echo "skipped tests:$skips"
[ -n "$bad" ] && echo "failing programs:$bad"
echo "tests: $pass passed, $fail failed, $skipped skipped"
[ $fail -eq 0 ] && [ $pass -gt 0 ]
