#!/usr/bin/env python3
"""Principled BSDF conformance against Cycles (issue 37 item 5).

The code is texcc_tools.scripts.principled_conformance (python/texcc_tools/scripts/principled_conformance.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.principled_conformance import main

if __name__ == "__main__":
    main()
