#!/usr/bin/env bash
# README's test command: set up, build, run the tests (lit suite and GoogleTest unit tests, both
# through lit), print a summary, exit non-zero on any failure.
#   scripts/test.sh [--slow] [LIT OPTION...]
# Without --slow it runs the default tier: the tests marked `REQUIRES: slow-tier` are reported
# UNSUPPORTED ("slow tier: run scripts/test.sh --slow"). --slow runs both tiers (CI does:
# .ci/run). Other arguments go to lit (e.g. --filter REGEX). docs/testing.md.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TEXCC_BUILD_DIR:-$root/build}"
lit_args=()
for arg in "$@"; do
  case "$arg" in
    --slow) lit_args+=(--param slow-tier=1) ;;
    -h|--help)
      echo "usage: scripts/test.sh [--slow] [LIT OPTION...]"
      echo "  --slow   run the slow tier too (tests marked REQUIRES: slow-tier; docs/testing.md)"
      echo "Set-up, build, then lit on the suite and the unit tests; other options go to lit:"
      exec "$root/.venv/bin/lit" --help ;;
    *) lit_args+=("$arg") ;;
  esac
done
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
xml="$build/test-results.xml"
rc=0
"$root/.venv/bin/lit" -sv --xunit-xml-output "$xml" "$build/testsuite" "$build/testsuite/Unit" \
  ${lit_args[@]+"${lit_args[@]}"} || rc=$?
"$root/.venv/bin/python" "$root/scripts/summarize_tests.py" "$xml" || rc=1
exit $rc
