#!/usr/bin/env python3
"""Ray throughput of texrender (rays per second by kind) with each trace backend (--trace=opencl:
OpenCL profiling events of the trace kernels; --trace=embree: wall time of the Embree stages) on
the Cornell box (plain, and with a texture that reads AO) and on the atrium with the rust texture.
The two backends run one after the other per scene. Writes bench/throughput.json and
bench/throughput.md.

The code is texcc_tools.bench.throughput (python/texcc_tools/bench/throughput.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.throughput import main

if __name__ == "__main__":
    main()
