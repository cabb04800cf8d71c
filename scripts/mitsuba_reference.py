#!/usr/bin/env python3
"""Renders the Cornell-box reference with Mitsuba 3 (scalar_rgb): mi.cornell_box() -- the scene
scripts/make_cornell.py exports to examples/cornell -- with the `path` integrator (max_depth 8),
a box pixel filter, 128x128. The image is the mean of --passes independent renders (seeds
0..passes-1) of --spp samples each; the per-pixel variance of that mean (from the spread of
the passes) is written beside it, for the statistical comparison
(runtime/tool/texrender_compare.cpp).

The code is texcc_tools.scripts.mitsuba_reference (python/texcc_tools/scripts/mitsuba_reference.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.scripts.mitsuba_reference import main

if __name__ == "__main__":
    main()
