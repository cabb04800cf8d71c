#!/usr/bin/env python3
"""Issue 37's "real material" figure: texrender against Cycles 5.0.1 (bpy) on a PBR-textured
object under an HDR world and an area lamp (bench/inputs/real_material_blend.py: albedo,
roughness and normal maps made by the script, Non-Color where due; cases "real" and
"real-metal"), and on the three-lamp interior (testsuite/Inputs/blender-export/
make_lamp_blend.py's "interior"). Each .blend is exported by scripts/blender_export.py and
rendered by both at SIZE and SPP for every seed; the seed means are compared as bench/cycles.py's
lamp figures are (cycles_lamps.lamp_figure): whole-image means per channel, 16x16 blocks within 1%,
each block's difference against its standard error, frame times.

The code is texcc_tools.bench.real_material (python/texcc_tools/bench/real_material.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.real_material import main

if __name__ == "__main__":
    common.run_main(main, "bench/real_material.py")
