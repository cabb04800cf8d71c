#!/usr/bin/env python3
"""Where texrender's variance comes from (issue 26): the per-pixel variance of the image split by
light (sun, sky, emissive meshes) and by path length, for texrender and for Cycles on the same
scene (the atrium, examples/blender/make_scene.py).

The code is texcc_tools.bench.sampling (python/texcc_tools/bench/sampling.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.sampling import main

if __name__ == "__main__":
    main()
