#!/usr/bin/env python3
"""texrender's fixed start-up cost (bench/startup.md): the CPU time (user + system, every
thread) and wall time of a 16x16, 1 spp render of the atrium (bench/accuracy.py --peer's
fixed-part measurement), for one or more texrender builds, interleaved: each repetition runs
every build once, in an order that rotates with the repetition, so that the shared machine's
load drifts over all of them alike. Medians over the repetitions; the 1-minute load average
before each run is recorded.

The code is texcc_tools.bench.startup (python/texcc_tools/bench/startup.py)."""
import sys

import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.startup import main

if __name__ == "__main__":
    sys.exit(main())
