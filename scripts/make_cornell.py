#!/usr/bin/env python3
"""Writes examples/cornell/ (OBJ files, scene.json, graph.json) from Mitsuba 3's Cornell box
numbers in ../shared/scenes/cornell_box_mitsuba.json (read from beside the repository, never
copied into it).

The code is texcc_tools.scripts.make_cornell (python/texcc_tools/scripts/make_cornell.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.make_cornell import main

if __name__ == "__main__":
    main()
