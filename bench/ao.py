#!/usr/bin/env python3
"""Figure 6: parallel AO against a per-hit loop (the paper's claim that tracing every AO ray of
every hit in one launch beats looping over a hit's AO rays inside one work-item).

The code is texcc_tools.bench.ao (python/texcc_tools/bench/ao.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.ao import main

if __name__ == "__main__":
    common.run_main(main, "bench/ao.py")
