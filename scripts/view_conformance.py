#!/usr/bin/env python3
"""view_conformance.py: texrender's PNG against Blender's PNG of the same EXR, through the same
Color Management (view transform, look, exposure, gamma; display sRGB).

The code is texcc_tools.scripts.view_conformance (python/texcc_tools/scripts/view_conformance.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.view_conformance import main

if __name__ == "__main__":
    sys.exit(main())
