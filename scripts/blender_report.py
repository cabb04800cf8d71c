#!/usr/bin/env python3
"""blender_report.py: writes bench/blender-nodes-table.md, texcc's Blender nodes against Cycles.

The code is texcc_tools.scripts.blender_report (python/texcc_tools/scripts/blender_report.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.blender_report import main

if __name__ == "__main__":
    main()
