#!/usr/bin/env python3
"""make_scenes.py: generate the examples' geometry (Wavefront OBJ) deterministically.

The code is texcc_tools.scripts.make_scenes (python/texcc_tools/scripts/make_scenes.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.make_scenes import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
