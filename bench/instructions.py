#!/usr/bin/env python3
"""Figure 2d: instructions the texture kernel executes per textured hit on PoCL, counted by
callgrind (no machine noise): where interp and shape lose to inline.

The code is texcc_tools.bench.instructions (python/texcc_tools/bench/instructions.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.instructions import main

if __name__ == "__main__":
    common.run_main(main, "bench/instructions.py")
