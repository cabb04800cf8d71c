#!/usr/bin/env python3
"""Parallel AO with the Embree trace backend against the per-hit loop (issue 24 point 4, a short
version of bench/ao.py): the atrium with rust (its mask reads AO), 1 spp, AO rays per hit swept;
per repetition `--trace=embree` (every AO ray of every hit: ao_rays makes them, one Embree
stream traces them, ao_reduce averages) and `--trace=embree --ao-method=loop` (the OpenCL
ao_loop, one work-item per hit; closest hit and shadow rays still Embree), alternating which
goes first. AO time: ao_rays + ao_trace + ao_reduce against ao_loop (stats.json; the Embree
stage is wall time). Prints medians and the per-repetition ratio loop / parallel.

usage: bench/ao_embree.py [--build build] [--size 512x512] [--reps 3] [--samples 1,8,32]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("ao_embree.py: %s failed:\n%s" % (" ".join(cmd), r.stderr))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--size", default="512x512")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--samples", default="1,8,32")
    args = ap.parse_args()
    bin_ = os.path.join(args.build, "bin")
    with tempfile.TemporaryDirectory() as tmp:
        tex = os.path.join(tmp, "rust")
        run([os.path.join(bin_, "texcc"), "--graph", os.path.join(ROOT, "examples/rust/graph.json"),
             "-o", tex])

        def render(samples, method):
            stats = os.path.join(tmp, "s.json")
            run([os.path.join(bin_, "texrender"), os.path.join(ROOT, "examples/atrium/scene.json"),
                 "--textures", tex, "--size", args.size, "--spp", "1", "--quiet", "--trace=embree",
                 "--ao-samples", str(samples), "--ao-method=" + method,
                 "-o", os.path.join(tmp, "i.exr"), "--stats", stats])
            with open(stats) as f:
                s = json.load(f)
            k = s["kernels"]
            ao = sum(k[n]["seconds"] for n in ("ao_rays", "ao_trace", "ao_reduce", "ao_loop") if n in k)
            return {"ao": ao, "frame": s["renderSeconds"], "aoRays": s["rays"]["ao"]["count"],
                    "load": os.getloadavg()[0]}

        render(1, "parallel"), render(1, "loop")  # warm the caches
        print("| AO rays per hit | AO rays | parallel (Embree stream): AO | loop (ao_loop): AO "
              "| loop / parallel (median of per-rep ratios) | frame parallel | frame loop | load |")
        print("|---|---|---|---|---|---|---|---|")
        for samples in map(int, args.samples.split(",")):
            par, loop = [], []
            for rep in range(args.reps):
                order = ["parallel", "loop"] if rep % 2 == 0 else ["loop", "parallel"]
                for m in order:
                    (par if m == "parallel" else loop).append(render(samples, m))
            med = lambda rs, f: statistics.median(f(r) for r in rs)
            ratio = statistics.median(l["ao"] / p["ao"] for p, l in zip(par, loop))
            loads = [r["load"] for r in par + loop]
            print("| %d | %d | %.3f s | %.3f s | %.2fx | %.2f s | %.2f s | %.1f-%.1f |" % (
                samples, par[0]["aoRays"], med(par, lambda r: r["ao"]), med(loop, lambda r: r["ao"]),
                ratio, med(par, lambda r: r["frame"]), med(loop, lambda r: r["frame"]),
                min(loads), max(loads)), flush=True)


if __name__ == "__main__":
    main()
