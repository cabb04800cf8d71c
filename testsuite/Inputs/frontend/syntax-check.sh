#!/bin/sh
# syntax-check.sh CLANG RENDERED: pastes texcc-fe's rendered user code (up to its
# "// texcc-fe signatures:" line) after the kernel's device headers, as proctex.cl does, and
# checks the result with `CLANG -x cl -cl-std=CL1.2 -fsyntax-only`.
set -e
clang="$1"
rendered="$2"
src="${TEXCC_SRC:?TEXCC_SRC is not set}"
out="$rendered.kernel.cl"
{
  cat "$src/kernels/common/texcc_abi.h" "$src/kernels/common/texcc_device.h"
  sed '/^\/\/ texcc-fe signatures:/,$d' "$rendered"
} > "$out"
# An OpenCL runtime defines __OPENCL_VERSION__ (texcc_abi.h tests it); clang alone does not.
exec "$clang" -x cl -cl-std=CL1.2 -fsyntax-only -D__OPENCL_VERSION__=120 "$out"
