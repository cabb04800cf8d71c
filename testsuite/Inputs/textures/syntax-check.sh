#!/usr/bin/env bash
# syntax-check.sh CLANG FILE.cl: plain clang syntax check of a texture file, with shim.h
# standing in for texcc's prelude (see shim.h for why readAttr/readSetting go through sed).
set -euo pipefail
clang="$1"
file="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp --suffix=.cl)"
trap 'rm -f "$tmp"' EXIT
# Keep the line numbers: the rewrite never adds or removes a line.
printf '#line 1 "%s"\n' "$file" > "$tmp"
sed -E 's/read(Attr|Setting)\("([A-Za-z0-9_]+)"\)/tex_shim_\1_\2()/g' "$file" >> "$tmp"
"$clang" -x cl -cl-std=CL1.2 -Xclang -finclude-default-header -fsyntax-only -Wall -Werror \
  -include "$here/shim.h" "$tmp"
