"""cycles_reference.py: regenerates the Cycles block means the exported scenes are tested against.

    .venv/bin/python testsuite/Inputs/blender-export/cycles_reference.py [--spp 4096]

For each case (make_blend.py's "scene", "texture-only" and "ao-spread"): builds the .blend,
renders it with Cycles (bpy 5.0.1, CPU, no denoising, no adaptive sampling, box pixel filter of
1 px, a transparent film for texture-only and ao-spread so that alpha is the coverage) and
writes the block means into cycles-means.json / cycles-texture-only.json /
cycles-ao-spread.json (region_means.py --write; texture-only and ao-spread also mark the
silhouette blocks). Then re-export the committed scenes with scripts/blender_export.py.
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = {"scene": ("cycles-means.json", []), "texture-only": ("cycles-texture-only.json",
                                                              ["--edges"]),
         "ao-spread": ("cycles-ao-spread.json", ["--edges"])}


def render(blend, exr, spp, transparent):
    import bpy
    from texcc_tools.testing.cycles_render import render_npy
    bpy.ops.wm.open_mainfile(filepath=blend)
    render_npy(bpy.context.scene, spp, exr, exr + ".npy", transparent)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--spp", type=int, default=4096)
    args = ap.parse_args()
    work = tempfile.mkdtemp()
    for case, (expected, flags) in CASES.items():
        blend = os.path.join(work, case + ".blend")
        subprocess.check_call([sys.executable, os.path.join(HERE, "make_blend.py"), blend, case])
        subprocess.check_call([sys.executable, __file__, "--render", blend, str(args.spp),
                               "1" if flags else "0"])
        subprocess.check_call([sys.executable, os.path.join(HERE, "region_means.py"),
                               blend + ".exr.npy", os.path.join(HERE, expected), "--write"] +
                              flags)
        print("cycles_reference: %s: %s (%d spp)" % (case, expected, args.spp))


if __name__ == "__main__":
    if sys.argv[1:2] == ["--render"]:
        render(sys.argv[2], sys.argv[2] + ".exr", int(sys.argv[3]), sys.argv[4] == "1")
    else:
        main()
