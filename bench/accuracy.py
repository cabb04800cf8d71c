#!/usr/bin/env python3
"""Figure 4: speed against accuracy on the atrium with rust. A converged reference (interp,
many samples per pixel and AO rays) is rendered once; then, per mode, a sweep over samples per
pixel and AO rays per hit records the frame time (texrender renderSeconds, median over the
repetitions) and the error against the reference: RMSE of linear radiance and mean FLIP (HDR,
flip-evaluator) when it is installed.

The measurement is texcc_tools.bench.accuracy (python/texcc_tools/bench/accuracy.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.accuracy import main

if __name__ == "__main__":
    main()
