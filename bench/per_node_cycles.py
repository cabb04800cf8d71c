#!/usr/bin/env python3
"""Issue 39 item 5: single Blender nodes' cost per sample in Cycles (SVM and OSL, through bpy),
in texrender per mode and in the C reference, one thread each, measured in interleaved rounds.

The code is texcc_tools.bench.per_node_cycles (python/texcc_tools/bench/per_node_cycles.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.per_node_cycles import main

if __name__ == "__main__":
    common.run_main(main, "bench/per_node_cycles.py")
