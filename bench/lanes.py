#!/usr/bin/env python3
"""Figure: a frame whole or as two one-thread lanes, quiet and beside a niced load (issue 39
item 4).

The code is texcc_tools.bench.lanes (python/texcc_tools/bench/lanes.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.lanes import main

if __name__ == "__main__":
    common.run_main(main, "lanes")
