"""Renders the Cornell-box reference with Mitsuba 3 (scalar_rgb): mi.cornell_box() -- the scene
scripts/make_cornell.py exports to examples/cornell -- with the `path` integrator (max_depth 8),
a box pixel filter, 128x128. The image is the mean of --passes independent renders (seeds
0..passes-1) of --spp samples each; the per-pixel variance of that mean (from the spread of
the passes) is written beside it, for the statistical comparison
(runtime/tool/texrender_compare.cpp).

Installs mitsuba (pinned) into the project's .venv when it is missing; nothing else needs it.

usage: scripts/mitsuba_reference.py [--spp 256] [--passes 32] [--size 128]
         [--out testsuite/Inputs/runtime/cornell_ref.exr]
  writes OUT (mean, float32) and OUT with _var before .exr (variance of the mean, float32)
"""
import argparse
import os
import subprocess
import sys
import time

from texcc_tools.paths import ROOT
MITSUBA = "mitsuba==3.9.1"


def ensure_mitsuba():
    try:
        import mitsuba  # noqa: F401
        return
    except ImportError:
        pass
    venv_python = os.path.join(ROOT, ".venv", "bin", "python")
    if os.path.realpath(sys.executable) != os.path.realpath(venv_python):
        if not os.path.exists(venv_python):
            sys.exit("mitsuba_reference.py: no .venv; run scripts/setup.sh first")
        os.execv(venv_python, [venv_python] + sys.argv)
    print("mitsuba_reference.py: installing %s into .venv" % MITSUBA, file=sys.stderr)
    subprocess.check_call([sys.executable, "-m", "pip", "install", "-q", MITSUBA, "numpy"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--spp", type=int, default=256, help="samples per pixel of each pass")
    ap.add_argument("--passes", type=int, default=32)
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--max-depth", type=int, default=8)
    ap.add_argument("--out", default=os.path.join(ROOT, "testsuite", "Inputs", "runtime",
                                                  "cornell_ref.exr"))
    args = ap.parse_args()
    ensure_mitsuba()
    import mitsuba as mi
    import numpy as np

    mi.set_variant("scalar_rgb")
    scene_dict = mi.cornell_box()
    sensor = scene_dict["sensor"]
    sensor["film"]["width"] = sensor["film"]["height"] = args.size
    sensor["film"]["rfilter"] = {"type": "box"}
    sensor["sampler"] = {"type": "independent", "sample_count": args.spp}
    scene_dict["integrator"] = {"type": "path", "max_depth": args.max_depth}
    scene = mi.load_dict(scene_dict)

    images = []
    t0 = time.time()
    for seed in range(args.passes):
        img = np.array(mi.render(scene, seed=seed, spp=args.spp), dtype=np.float64)[:, :, :3]
        images.append(img)
        print("mitsuba_reference.py: pass %d/%d (%.0f s)" % (seed + 1, args.passes,
                                                            time.time() - t0), file=sys.stderr)
    stack = np.stack(images)
    mean = stack.mean(axis=0)
    var_of_mean = stack.var(axis=0, ddof=1) / args.passes
    base, ext = os.path.splitext(args.out)
    mi.Bitmap(mean.astype(np.float32)).write(args.out)
    mi.Bitmap(var_of_mean.astype(np.float32)).write(base + "_var" + ext)
    print("mitsuba_reference.py: wrote %s (mean radiance %s, %d spp)"
          % (os.path.relpath(args.out, ROOT), np.round(mean.mean(axis=(0, 1)), 5),
             args.spp * args.passes))


if __name__ == "__main__":
    main()
