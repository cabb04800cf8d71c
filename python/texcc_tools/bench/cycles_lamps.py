"""Blender's lamps and HDR worlds against Cycles (bench/cycles.py --lamps, --env;
bench/real_material.py): per case, Cycles and texrender's render of the exported scene at each
seed, the seed means compared per channel and per 16x16 block (bench/cycles.md)."""
import os

from texcc_tools import exr
from texcc_tools.bench import common
from texcc_tools.bench.cycles import exported
from texcc_tools.paths import INPUTS, VENV_PYTHON

# --- Lamps (issue 37 item 2): Blender's point, spot and area lamps against Cycles -------------

LAMP_BLEND = os.path.join(INPUTS, "blender-export", "make_lamp_blend.py")
LAMP_CASES = ("point", "spot", "area-rect", "area-disk", "three-point", "sphere", "interior")
# Renders a .blend with Cycles at a size, spp and seed (CPU, the make_lamp_blend.py settings:
# no denoising, no adaptive sampling, box filter 1 px); prints the render's seconds.
LAMP_CYCLES = """
import sys, time
import bpy
from texcc_tools.testing.cycles_render import render_npy
blend, w, h, spp, seed, npy = sys.argv[-6:]
bpy.ops.wm.open_mainfile(filepath=blend)
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = int(w), int(h)
scene.cycles.seed = int(seed)
t0 = time.perf_counter()
render_npy(scene, int(spp), npy + ".exr", npy)
print("CYCLESSECONDS %f" % (time.perf_counter() - t0))
"""


# --- The HDR world (issue 37 item 2): an Environment Texture against Cycles ----------------

WORLD_BLEND = os.path.join(os.path.dirname(LAMP_BLEND), "make_world_blend.py")
WORLD_CASES = ("env", "env-rotated")


def lamp_figure(tools, size, spp, seeds, cases, block=16, tol=0.01, maker=LAMP_BLEND,
                prefix="lamp"):
    """Per case of `maker` (make_lamp_blend.py's lamps, or make_world_blend.py's HDR worlds
    with prefix "world"): Cycles and texrender (the exporter's scene) at `spp` and each seed; the mean
    images over the seeds compared: whole-image means per channel, and the 16x16 blocks within
    `tol` (of max(Cycles' block mean, 5% of Cycles' image mean), every channel); each block's
    difference against its standard error from both renderers' seed-to-seed spread; frame
    times (Cycles' render call, which includes its scene sync and BVH build; texrender's
    renderSeconds)."""
    import numpy as np
    w, h = (int(x) for x in size.split("x"))
    out = {}
    for case in cases:
        blend = os.path.join(tools.work, "%s-%s.blend" % (prefix, case))
        common.run([VENV_PYTHON, maker, blend, case])
        scene, textures = exported(tools, blend, "%s-%s" % (prefix, case))
        cyc, tex, cyc_t, tex_t = [], [], [], []
        for seed in seeds:
            npy = os.path.join(tools.work, "%s-%s-cycles-%d.npy" % (prefix, case, seed))
            _, text = common.run([VENV_PYTHON, "-c", LAMP_CYCLES, os.path.abspath(blend), str(w),
                                  str(h), str(spp), str(seed), os.path.abspath(npy)])
            cyc_t.append(float(text.split("CYCLESSECONDS")[1].split()[0]))
            cyc.append(np.load(npy)[..., :3].astype(np.float64))
            stats, img, _ = common.texrender(tools, scene, textures, "%s-%s-%d" % (prefix, case, seed),
                                             ["--size", size, "--spp", str(spp), "--seed",
                                              str(seed)], image="exr")
            tex_t.append(stats["renderSeconds"])
            tex.append(np.asarray(exr.read_file(img), np.float64)[..., :3])
        a, b = np.mean(cyc, axis=0), np.mean(tex, axis=0)

        def tiles(x):
            return x.reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))

        ta, tb = tiles(a), tiles(b)
        floor = 0.05 * a.mean()
        rel = np.abs(tb - ta) / np.maximum(ta, floor)
        within = (rel <= tol).all(axis=-1)
        n = len(seeds)
        if n > 1:  # the standard error of each renderer's seed mean, per block and channel
            se2 = sum(np.var([tiles(x) for x in xs], axis=0, ddof=1) / n for xs in (cyc, tex))
            z = (tb - ta) / np.sqrt(np.maximum(se2, 1e-30))
        else:
            z = None
        out[case] = {
            "meanCycles": a.mean(axis=(0, 1)).tolist(), "meanTexrender": b.mean(axis=(0, 1)).tolist(),
            "meanRelDiffPercent": (100 * (b.mean(axis=(0, 1)) / a.mean(axis=(0, 1)) - 1)).tolist(),
            "blocks": int(within.size), "blocksWithin": int(within.sum()),
            "blocksWithinPercent": 100.0 * within.mean(),
            "worstBlockRelDiffPercent": 100 * float(rel.max()),
            "blockZ": None if z is None else {
                "rms": float(np.sqrt((z * z).mean())), "maxAbs": float(np.abs(z).max()),
                "over3": int((np.abs(z) > 3).sum()), "values": int(z.size)},
            "cyclesSeconds": cyc_t, "texrenderSeconds": tex_t,
            "frameTimeRatio": float(np.mean(cyc_t) / np.mean(tex_t))}
        r = out[case]
        print("%-12s means %+.2f/%+.2f/%+.2f%%  blocks within %.0f%%: %d/%d  worst %.2f%%  "
              "z rms %s  Cycles %.2f s  texrender %.2f s" % (
                  case, *r["meanRelDiffPercent"], 100 * tol, r["blocksWithin"], r["blocks"],
                  r["worstBlockRelDiffPercent"],
                  "%.2f" % r["blockZ"]["rms"] if r["blockZ"] else "-",
                  np.mean(cyc_t), np.mean(tex_t)), flush=True)
    return out
