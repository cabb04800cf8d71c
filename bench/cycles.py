#!/usr/bin/env python3
"""Figure: texrender side by side with real Cycles on the atrium (issues 22 and 24).

    python3 bench/cycles.py [--quick] [--build build] [--reps N] [--spp 1,16] [--size 512x512]

The measurement is texcc_tools.bench.cycles (python/texcc_tools/bench/cycles.py); bench/run
runs it as the figure "cycles"."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.cycles import run

if __name__ == "__main__":
    run()
