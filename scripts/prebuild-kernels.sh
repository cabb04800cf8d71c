#!/usr/bin/env bash
# Prebuilds texrender's fixed kernels (raygen, closest_hit, shade, ...) for this machine's
# OpenCL device into BUILD/programs, where texrender looks after its program cache
# (docs/runtime.md, "Cold start"): a first render with empty caches then builds only its texture
# kernel. Each binary is stored after launches of both grid classes, so it carries PoCL's
# compiled work-group functions. Run by scripts/build.sh; a machine without an OpenCL device
# skips it (texrender builds the kernels on first use, as before).
set -euo pipefail
build="${1:?usage: prebuild-kernels.sh BUILD_DIR}"
texrender="$build/bin/texrender" texcc="$build/bin/texcc"
[ -x "$texrender" ] && [ -x "$texcc" ] || exit 0
"$build/bin/texcc-cl-probe" >/dev/null 2>&1 || { echo "prebuild-kernels: no OpenCL device; skipped" >&2; exit 0; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/flat.cl" <<'CL'
/* flat() -> float3: a constant grey. */
float3 flat() { return (float3)(0.5f); }
CL
cat > "$tmp/graph.json" <<'JSON'
{ "texcc": 1, "sources": ["flat.cl"], "nodes": [ { "id": "f", "fn": "flat", "args": {} } ],
  "materials": { "m": { "bsdf": "diffuse", "color": { "node": "f" } } } }
JSON
printf 'v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1 2 3\n' > "$tmp/tri.obj"
cat > "$tmp/scene.json" <<'JSON'
{ "texrender": 1, "camera": { "position": [0, 0, 3], "target": [0, 0, 0], "fov": 45 },
  "film": { "width": 8, "height": 8 }, "render": { "spp": 1, "maxDepth": 2, "seed": 1 },
  "lights": [ { "type": "sky", "radiance": [1, 1, 1] } ],
  "meshes": [ { "obj": "tri.obj", "material": "m" } ] }
JSON
"$texcc" --graph "$tmp/graph.json" -o "$tmp/tex"
# The cache folder BUILD: binaries go to BUILD/programs/<key>.bin; present ones are loaded.
TEXRENDER_CACHE_DIR="$build" TEXRENDER_PREBUILT_DIR="" TEXRENDER_FIRST_BUILD=optimised \
  "$texrender" "$tmp/scene.json" --textures "$tmp/tex" --quiet -o "$tmp/out.png"
