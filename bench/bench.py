#!/usr/bin/env python3
"""bench/run's driver: runs the figures (in the paper's priority order), saves
bench/results/<figure>.json and regenerates the charts and BENCHMARKS.md.

usage: bench/run [--quick] [--build DIR] [--device N] [--only FIGURE ...] [--report-only]

The code is texcc_tools.bench.bench (python/texcc_tools/bench/bench.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.bench import main

if __name__ == "__main__":
    try:
        sys.exit(main())
    except common.BenchError as e:
        sys.stderr.write("bench: error: %s\n" % e)
        sys.exit(1)
