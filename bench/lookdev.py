#!/usr/bin/env python3
"""Figure: live look-development on the atrium with rust at a 256x256 preview (issue 23).

The code is texcc_tools.bench.lookdev (python/texcc_tools/bench/lookdev.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.lookdev import main

if __name__ == "__main__":
    try:
        main()
    except common.BenchError as e:
        sys.stderr.write("lookdev: error: %s\n" % e)
        sys.exit(1)
