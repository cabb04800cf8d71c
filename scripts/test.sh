#!/usr/bin/env bash
# README's test command: set up, build, run every test (lit suite and GoogleTest unit tests,
# both through lit), print a summary line, exit non-zero on any failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TEXCC_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
xml="$build/test-results.xml"
rc=0
"$root/.venv/bin/lit" -sv --xunit-xml-output "$xml" "$build/testsuite" "$build/testsuite/Unit" "$@" || rc=$?
"$root/.venv/bin/python" "$root/scripts/summarize_tests.py" "$xml" || rc=1
exit $rc
