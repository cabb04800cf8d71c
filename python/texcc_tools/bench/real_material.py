"""Issue 37's "real material" figure: texrender against Cycles 5.0.1 (bpy) on a PBR-textured
object under an HDR world and an area lamp (bench/inputs/real_material_blend.py: albedo,
roughness and normal maps made by the script, Non-Color where due; cases "real" and
"real-metal"), and on the three-lamp interior (testsuite/Inputs/blender-export/
make_lamp_blend.py's "interior"). Each .blend is exported by scripts/blender_export.py and
rendered by both at SIZE and SPP for every seed; the seed means are compared as bench/cycles.py's
lamp figures are (cycles_lamps.lamp_figure): whole-image means per channel, 16x16 blocks within 1%,
each block's difference against its standard error, frame times.

usage: bench/real_material.py [--build DIR] [--size WxH] [--spp N] [--seeds 1-4]
                              [--cases real,real-metal,interior] [--out FILE]
"""
import argparse
import os

from texcc_tools.bench import common
from texcc_tools.bench import cycles, cycles_lamps

REAL_BLEND = os.path.join(common.BENCH, "inputs", "real_material_blend.py")
REAL_CASES = ("real", "real-metal")
LAMP_CASES = ("interior",)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    common.add_build_argument(ap)
    ap.add_argument("--work", default=None)
    ap.add_argument("--size", default="128x96")
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--seeds", type=cycles.seed_list, default=[1, 2, 3, 4])
    ap.add_argument("--cases", default=",".join(REAL_CASES + LAMP_CASES))
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "real_material.json"))
    args = ap.parse_args()
    cycles.ensure_bpy()
    work = args.work or os.path.join(args.build, "bench-real-material")
    os.makedirs(work, exist_ok=True)
    tools = common.Tools(args.build, work)
    cases = args.cases.split(",")
    unknown = [c for c in cases if c not in REAL_CASES + LAMP_CASES]
    if unknown:
        raise common.BenchError("unknown case(s) %s (cases: %s)" % (
            ", ".join(unknown), ", ".join(REAL_CASES + LAMP_CASES)))
    load = [os.getloadavg()[0]]
    out = {}
    real = [c for c in cases if c in REAL_CASES]
    if real:
        out.update(cycles_lamps.lamp_figure(tools, args.size, args.spp, args.seeds, real,
                                      maker=REAL_BLEND, prefix="real"))
    lamps = [c for c in cases if c in LAMP_CASES]
    if lamps:
        out.update(cycles_lamps.lamp_figure(tools, args.size, args.spp, args.seeds, lamps))
    load.append(os.getloadavg()[0])
    common.save(None, {"machine": common.machine(), "git": common.git_head(),
                       "size": args.size, "spp": args.spp, "seeds": args.seeds,
                       "loadAverage1min": load, "cases": out}, args.out)


if __name__ == "__main__":
    common.run_main(main, "bench/real_material.py")
