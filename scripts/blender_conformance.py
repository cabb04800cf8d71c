#!/usr/bin/env python3
"""blender_conformance.py: golden values of Blender's shader nodes, computed by Cycles itself,
written to testsuite/Inputs/blender/ (texcc_tools.blender.conformance).

    scripts/blender_conformance.py [--only NAME ...] [--size N]"""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.blender.conformance import main

if __name__ == "__main__":
    main()
