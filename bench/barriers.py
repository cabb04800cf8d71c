#!/usr/bin/env python3
"""Figure: what a stage barrier costs a two-thread program beside a niced CPU load (issue 39
item 4).

The code is texcc_tools.bench.barriers (python/texcc_tools/bench/barriers.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.barriers import main

if __name__ == "__main__":
    common.run_main(main, "barriers")
