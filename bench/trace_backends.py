#!/usr/bin/env python3
"""Frame time of the atrium with each trace backend (issue 24): 512x512, maxDepth 4, diffuse
(no texture, no AO) and rust (texture + 8 AO rays per hit), 1 and 16 spp, --trace=opencl and
--trace=embree interleaved (every repetition renders every configuration in turn); medians of
the frame time (renderSeconds) and of each stage's time, the BVH build times, and the 1-minute
load average at each render. Writes bench/trace_backends.json and prints a Markdown table.

The code is texcc_tools.bench.trace_backends (python/texcc_tools/bench/trace_backends.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.trace_backends import main

if __name__ == "__main__":
    main()
