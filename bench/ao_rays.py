#!/usr/bin/env python3
"""The Embree AO stages of builds side by side (issue 24, point 3): the atrium with rust
(examples/atrium/scene.json, 8 AO rays per hit), 512x512, maxDepth 4, --trace=embree, with each
build in turn in every repetition (the first one rotating); per build the medians of the
`ao_rays` (OpenCL kernel that makes the AO rays) and `ao_trace` (Embree stream) stage times and
of the frame, and per repetition the ratio of each build's `ao_rays` to the first build's.
A build is a folder with bin/texrender, bin/texcc and kernels/ (e.g. a copy of build/ taken
before a change). Writes the raw runs to --out.

The code is texcc_tools.bench.ao_rays (python/texcc_tools/bench/ao_rays.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.ao_rays import main

if __name__ == "__main__":
    main()
