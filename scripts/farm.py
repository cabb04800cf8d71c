#!/usr/bin/env python3
"""farm.py: renders frames and tiles of a texrender scene on a Ray cluster (docs/farm.md).

  farm.py render scene.json --textures T [--frames 1-48] [--tiles 4x4] -o out/frame.####.exr
  farm.py stitch --size WxH -o OUT.exr TILE.exr@X,Y ...

The farm is texcc_tools.farm (python/texcc_tools/farm.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.farm import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
