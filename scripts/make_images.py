#!/usr/bin/env python3
"""make_images.py: the two small images of examples/image-multiply, made deterministically.

The code is texcc_tools.scripts.make_images (python/texcc_tools/scripts/make_images.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.make_images import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
