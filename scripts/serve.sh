#!/usr/bin/env bash
# The browser preview (docs/live.md, "Browser preview"); texrender --serve execs this.
#   scripts/serve.sh [--port P] [--listen ADDR] --texrender PATH -- SCENE --textures DIR [...]
#   scripts/serve.sh --install     only installs the preview's Python packages
# On first use installs aiohttp (scripts/requirements-serve.txt, pinned) into the project's
# .venv/, then runs scripts/serve.py with it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$root/.venv"
req="$root/scripts/requirements-serve.txt"
stamp="$venv/.requirements-serve.stamp"
if [ ! -x "$venv/bin/python" ]; then
  /usr/bin/python3 -m venv "$venv"
fi
if [ ! -f "$stamp" ] || ! cmp -s "$req" "$stamp" || ! "$venv/bin/python" -c "import aiohttp" 2>/dev/null; then
  echo "serve: installing the preview's Python packages into .venv" >&2
  "$venv/bin/python" -m pip install -q --disable-pip-version-check -r "$req" >&2
  cp "$req" "$stamp"
fi
if [ "${1:-}" = "--install" ]; then
  exit 0
fi
exec "$venv/bin/python" "$root/scripts/serve.py" "$@"
