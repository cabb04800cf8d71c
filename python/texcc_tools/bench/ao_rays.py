"""The Embree AO stages of builds side by side (issue 24, point 3): the atrium with rust
(examples/atrium/scene.json, 8 AO rays per hit), 512x512, maxDepth 4, --trace=embree, with each
build in turn in every repetition (the first one rotating); per build the medians of the
`ao_rays` (OpenCL kernel that makes the AO rays) and `ao_trace` (Embree stream) stage times and
of the frame, and per repetition the ratio of each build's `ao_rays` to the first build's.
A build is a folder with bin/texrender, bin/texcc and kernels/ (e.g. a copy of build/ taken
before a change). Writes the raw runs to --out.

usage: bench/ao_rays.py --builds NAME=DIR,NAME=DIR[,...] [--spp 1] [--reps 5] [--out FILE]
Needs examples/atrium/generated (scripts/make_scenes.py --only atrium rust).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from texcc_tools.paths import ROOT


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--builds", required=True)
    ap.add_argument("--spp", default="1")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "ao_rays.json"))
    args = ap.parse_args()
    builds = dict(b.split("=", 1) for b in args.builds.split(","))
    names = list(builds)
    res = {k: [] for k in names}
    with tempfile.TemporaryDirectory() as tmp:
        tex = {}
        for k, b in builds.items():
            tex[k] = os.path.join(tmp, "tex-%d" % len(tex))
            subprocess.run([os.path.join(b, "bin", "texcc"), "--graph",
                            os.path.join(ROOT, "examples", "rust", "graph.json"), "-o", tex[k]],
                           check=True)
        for rep in range(-1, args.reps):  # rep -1 warms the program caches
            r0 = rep % len(names)
            for k in names[r0:] + names[:r0]:
                b = builds[k]
                stats = os.path.join(tmp, "stats.json")
                cmd = [os.path.join(b, "bin", "texrender"),
                       os.path.join(ROOT, "examples", "atrium", "scene.json"), "--textures", tex[k],
                       "--kernels", os.path.join(b, "kernels"), "--size", "512x512", "--spp",
                       args.spp, "--max-depth", "4", "--quiet", "--trace=embree",
                       "-o", os.path.join(tmp, "img.exr"), "--stats", stats]
                if subprocess.run(cmd).returncode != 0:
                    sys.exit("ao_rays.py: %s failed" % " ".join(cmd))
                with open(stats) as f:
                    s = json.load(f)
                r = {"rep": rep, "ao_rays": s["kernels"]["ao_rays"]["seconds"],
                     "ao_trace": s["kernels"]["ao_trace"]["seconds"], "frame": s["renderSeconds"],
                     "aoRays": s["rays"]["ao"]["count"], "load": os.getloadavg()[0]}
                print(k, r, flush=True)
                if rep >= 0:
                    res[k].append(r)
    with open(args.out, "w") as f:
        json.dump({"spp": args.spp, "builds": builds, "runs": res}, f, indent=1)
        f.write("\n")
    first = res[names[0]]
    for k in names:
        rs = res[k]
        med = {f: round(statistics.median(r[f] for r in rs), 3) for f in ("ao_rays", "ao_trace", "frame")}
        ratios = [round(y["ao_rays"] / x["ao_rays"], 2) for x, y in zip(first, rs)]
        print("%s: medians %s; ao_rays all %s; ao_rays / %s per rep %s (median %.2f); load %s" % (
            k, med, [round(r["ao_rays"], 3) for r in rs], names[0], ratios,
            statistics.median(ratios), [round(r["load"], 1) for r in rs]))


if __name__ == "__main__":
    main()
