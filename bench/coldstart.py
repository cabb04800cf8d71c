#!/usr/bin/env python3
"""Time to the first image, cold and warm (issue 36), beside Cycles' time to its first sample.

The code is texcc_tools.bench.coldstart (python/texcc_tools/bench/coldstart.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.coldstart import main

if __name__ == "__main__":
    common.run_main(main, "coldstart")
