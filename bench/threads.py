#!/usr/bin/env python3
"""Figure: texrender's frame alone and beside a competing niced CPU load, per --threads, with
Cycles under the same loads (issue 39 item 4).

The code is texcc_tools.bench.threads (python/texcc_tools/bench/threads.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.threads import main

if __name__ == "__main__":
    common.run_main(main, "threads")
