#!/usr/bin/env bash
# The sanitizer run (docs/fuzzing.md): builds the `asan` preset (build-asan/, GCC's
# AddressSanitizer + UndefinedBehaviorSanitizer, Debug) and runs every test under it: the lit
# suite and the GoogleTest unit tests, as scripts/test.sh does for build/. Extra arguments go
# to lit. Exit status: lit's (any sanitizer report fails the test that caused it).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-asan"
"$root/scripts/setup.sh"
cd "$root"
[ -f "$build/build.ninja" ] || cmake --preset asan
# TEXCC_ASAN_TARGETS: build only these targets (e.g. the tools, for `--filter reliability/`:
# "texcc texrender texcc-eval texcc-cl-probe texcc-fe texcc-graph texrender-compare"), not the
# unit tests too; CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs.
read -r -a targets <<<"${TEXCC_ASAN_TARGETS:-}"
cmake --build --preset asan ${targets[@]:+--target "${targets[@]}"}

# Every report is fatal: UBSan in GCC's default (recovering) mode would only print and go on.
# LeakSanitizer stays on for our code; scripts/lsan.supp lists the leaks that belong to the
# OpenCL stack (PoCL, the ICD loader, the LLVM inside PoCL) and why.
# strict_string_checks: the C strings we pass to libc are checked up to their terminator.
# use_sigaltstack=0: ASan unmaps a thread's alternate signal stack when the thread ends, taking
# whatever stack is installed for its own; texrender's background build threads end after the
# OpenCL stack has installed a heap-allocated one there (73728 bytes, not page-aligned; most
# likely the LLVM inside PoCL, whose signal handling mallocs one), and
# ASan then aborts with "unable to unmap" (live/watch-source-quick*.test, 2026-12-05).
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:use_sigaltstack=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
exec "$root/.venv/bin/lit" -s "$build/testsuite" "$build/testsuite/Unit" "$@"
