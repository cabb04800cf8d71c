#!/usr/bin/env python3
"""Figure 2e: per-hit texture cost of every mode side by side on PoCL, on the two textures of the
paper's Table 1 (examples/rust and examples/scratches), with shape mode's hoisting
(docs/frontend.md, "Hoisting") on and off.

The code is texcc_tools.bench.per_hit (python/texcc_tools/bench/per_hit.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.per_hit import main

if __name__ == "__main__":
    common.run_main(main, "bench/per_hit.py")
