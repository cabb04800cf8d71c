#!/usr/bin/env python3
"""swatches.py: a small rendered swatch per node function, and the node reference.

The code is texcc_tools.scripts.swatches (python/texcc_tools/scripts/swatches.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.swatches import main

if __name__ == "__main__":
    main()
