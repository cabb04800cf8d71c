#!/usr/bin/env python3
"""Farm figures (docs/farm.md, BENCHMARKS.md "Farm"): what a Ray task costs over a texrender run.

The code is texcc_tools.bench.farm (python/texcc_tools/bench/farm.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.farm import main

if __name__ == "__main__":
    main()
