#!/usr/bin/env python3
"""Issue 39 items 1-2: the texture kernel's cost per sample in every texrender mode beside a C
reference, the same texture source compiled by clang-15 -O3 as native code
(bench/cpp_reference/README.md), on one thread.

The code is texcc_tools.bench.texture_speed (python/texcc_tools/bench/texture_speed.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.texture_speed import main

if __name__ == "__main__":
    common.run_main(main, "bench/texture_speed.py")
