#!/usr/bin/env bash
# README's main job: set up, build, compile examples/rust with texcc, render it with texrender
# to out/rust.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TEXCC_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
ex="$root/examples/rust"
for need in "$build/bin/texcc" "$build/bin/texrender" "$ex/graph.json" "$ex/scene.json"; do
  if [ ! -e "$need" ]; then
    echo "main: cannot render examples/rust yet: '${need#$root/}' does not exist (that part is not built yet)" >&2
    exit 1
  fi
done
mkdir -p "$root/out"
# The example's scene geometry is generated (deterministic, a few seconds), its sources come from
# graph.json's "sources".
"$root/.venv/bin/python" "$root/scripts/make_scenes.py" --only rust
"$build/bin/texcc" --graph "$ex/graph.json" -o "$root/out/rust"
"$build/bin/texrender" "$ex/scene.json" --textures "$root/out/rust" -o "$root/out/rust.png" \
  --stats "$root/out/rust-stats.json"
echo "main: wrote out/rust.png" >&2
