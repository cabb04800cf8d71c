#!/usr/bin/env bash
# Configures (once) and builds texcc and texrender into build/ with Ninja. Incremental.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TEXCC_BUILD_DIR:-$root/build}"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${TEXCC_BUILD_TYPE:-RelWithDebInfo}" \
    -DTEXCC_LIT="$root/.venv/bin/lit" >&2
fi
jobs="${TEXCC_JOBS:-$(nproc)}"
ninja -C "$build" -j "$jobs" >&2
if [ -z "${TEXCC_NO_PREBUILD:-}" ]; then "$root/scripts/prebuild-kernels.sh" "$build" >&2; fi
