#!/usr/bin/env bash
# Installs what texcc needs on Debian 12, and nothing that is already there.
# Idempotent: when everything is present it only checks (a second or two).
#   Debian packages: installed with apt-get when run as root, otherwise listed.
#   Python tools (lit, pinned): a project-local virtual environment in .venv/, and the
#   project's own package texcc_tools (pyproject.toml, python/texcc_tools/), editable.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

packages=(
  g++ cmake ninja-build python3-venv
  clang-15 libclang-15-dev llvm-15-dev llvm-15-tools libclc-15
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers
  libglm-dev libstb-dev nlohmann-json3-dev libtinyobjloader-dev libtinyexr-dev libgtest-dev
  zlib1g-dev libembree-dev libopencolorio-dev pkg-config
)
# Extra packages a caller may ask for (e.g. TEXCC_EXTRA_PACKAGES="valgrind").
read -r -a extra <<<"${TEXCC_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: missing Debian packages: ${missing[*]}" >&2
    echo "setup: run as root, or: sudo apt-get install ${missing[*]}" >&2
    exit 1
  fi
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >&2
  apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
fi

# Python tools, pinned, in a project-local venv (never the system's site-packages).
venv="$root/.venv"
pyreq="$root/scripts/requirements.txt"
stamp="$venv/.requirements.stamp"
if [ ! -x "$venv/bin/python" ]; then
  /usr/bin/python3 -m venv "$venv"
fi
if [ ! -f "$stamp" ] || ! cmp -s "$pyreq" "$stamp"; then
  echo "setup: installing Python requirements into .venv" >&2
  "$venv/bin/python" -m pip install -q --disable-pip-version-check -r "$pyreq" >&2
  cp "$pyreq" "$stamp"
fi
# The project's package (python/texcc_tools/), editable: an edit of its modules needs no
# reinstall; pyproject.toml's stamp (or a clone moved elsewhere) installs it again.
pkgstamp="$venv/.pyproject.stamp"
if [ ! -f "$pkgstamp" ] || ! cmp -s "$root/pyproject.toml" "$pkgstamp" ||
   ! "$venv/bin/python" -c "import texcc_tools.paths as p, sys; sys.exit(p.ROOT != '$root')" 2>/dev/null; then
  echo "setup: installing the texcc_tools package into .venv" >&2
  "$venv/bin/python" -m pip install -q --disable-pip-version-check \
    --no-deps -e "$root" >&2
  cp "$root/pyproject.toml" "$pkgstamp"
fi
