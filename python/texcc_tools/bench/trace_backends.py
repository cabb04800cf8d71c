"""Frame time of the atrium with each trace backend (issue 24): 512x512, maxDepth 4, diffuse
(no texture, no AO) and rust (texture + 8 AO rays per hit), 1 and 16 spp, --trace=opencl and
--trace=embree interleaved (every repetition renders every configuration in turn); medians of
the frame time (renderSeconds) and of each stage's time, the BVH build times, and the 1-minute
load average at each render. Writes bench/trace_backends.json and prints a Markdown table.

usage: bench/trace_backends.py [--build build] [--reps 1spp,16spp] [--size 512x512]
                               [--configs diffuse,rust] [--traces opencl,embree] [--before DIR]
                               [--out bench/trace_backends.json]
--before DIR: also render with an older build (DIR/bin/texrender, DIR/bin/texcc and
DIR/kernels, e.g. a copy of build/ taken before a change) as trace "opencl-before"
(--trace=opencl), interleaved with the others: the before/after of an OpenCL traversal change.
Needs examples/atrium/generated (scripts/make_scenes.py --only atrium rust).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from texcc_tools import process
from texcc_tools.paths import ROOT, add_build_argument
CONFIGS = {"diffuse": ("examples/atrium/scene-diffuse.json", "bench/inputs/diffuse/graph.json"),
           "rust": ("examples/atrium/scene.json", "examples/rust/graph.json")}
TRACES = ["opencl", "embree"]
STAGES = ["closest_hit_primary", "closest_hit_bounce", "shadow", "ao_rays", "ao_trace", "shade",
          "hit_attributes", "proctex"]


def run(cmd):
    try:
        process.run(cmd)
    except process.RunError as e:
        sys.exit("trace_backends.py: %s" % e)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_build_argument(ap)
    ap.add_argument("--reps", default="5,3", help="repetitions at 1 spp and at 16 spp")
    ap.add_argument("--size", default="512x512")
    ap.add_argument("--configs", default=",".join(CONFIGS))
    ap.add_argument("--traces", default=",".join(TRACES))
    ap.add_argument("--before", help="an older build (bin/, kernels/): adds opencl-before")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "trace_backends.json"))
    args = ap.parse_args()
    reps = dict(zip([1, 16], map(int, args.reps.split(","))))
    configs = args.configs.split(",")
    traces = args.traces.split(",") + (["opencl-before"] if args.before else [])
    builds = {"": args.build}
    if args.before:
        builds["-before"] = args.before
    raw = []
    with tempfile.TemporaryDirectory() as tmp:
        tex = {}
        for suffix, build in builds.items():
            for name in configs:
                tex[name + suffix] = os.path.join(tmp, name + suffix)
                run([os.path.join(build, "bin", "texcc"), "--graph",
                     os.path.join(ROOT, CONFIGS[name][1]), "-o", tex[name + suffix]])

        def render(name, spp, trace, rep):
            stats = os.path.join(tmp, "stats.json")
            suffix = "-before" if trace.endswith("-before") else ""
            build = builds[suffix]
            cmd = [os.path.join(build, "bin", "texrender"), os.path.join(ROOT, CONFIGS[name][0]),
                   "--textures", tex[name + suffix], "--kernels", os.path.join(build, "kernels"),
                   "--size", args.size, "--spp", str(spp), "--max-depth", "4", "--quiet",
                   "--trace=" + trace[:len(trace) - len(suffix)], "-o",
                   os.path.join(tmp, "img.exr"), "--stats", stats]
            run(cmd)
            with open(stats) as f:
                s = json.load(f)
            r = {"config": name, "spp": spp, "trace": trace, "rep": rep,
                 "renderSeconds": s["renderSeconds"], "bvhBuildSeconds": s["bvhBuildSeconds"],
                 "loadAverage": os.getloadavg()[0], "device": s["device"],
                 "stages": {k: v["seconds"] for k, v in s["kernels"].items()},
                 "rays": s["rays"], "bvhNodes": s["bvhNodes"]}
            print("%-7s %2d spp %-6s rep %d: %.3f s (load %.1f)" % (
                name, spp, trace, rep, r["renderSeconds"], r["loadAverage"]), flush=True)
            return r

        for name in configs:  # warm the program caches
            for trace in traces:
                render(name, 1, trace, -1)
        for spp in (1, 16):
            for rep in range(reps[spp]):
                for name in configs:
                    # Rotate which configuration goes first in each repetition.
                    for trace in traces[rep % len(traces):] + traces[:rep % len(traces)]:
                        raw.append(render(name, spp, trace, rep))
    summary = []
    for spp in (1, 16):
        for name in configs:
            for trace in traces:
                rs = [r for r in raw if r["config"] == name and r["spp"] == spp and r["trace"] == trace]
                if not rs:
                    continue
                med = lambda f: statistics.median(f(r) for r in rs)
                summary.append({
                    "config": name, "spp": spp, "trace": trace, "n": len(rs),
                    "renderSeconds": med(lambda r: r["renderSeconds"]),
                    "renderSecondsAll": [round(r["renderSeconds"], 3) for r in rs],
                    "stages": {k: med(lambda r: r["stages"].get(k, 0.0)) for k in STAGES},
                    # "wide" (Embree's builder, the OpenCL traversal's BVH), "embree" (Embree's
                    # scene BVH, embree only), "sah" (the binary SAH builder of older builds).
                    "bvhBuildSeconds": {k: (med(lambda r: r["bvhBuildSeconds"][k])
                                            if rs[0]["bvhBuildSeconds"][k] is not None else None)
                                        for k in rs[0]["bvhBuildSeconds"]},
                    "bvhNodes": rs[0]["bvhNodes"],
                    "raysPerSecond": {k: med(lambda r: r["rays"][k]["perSecond"])
                                      for k in ("primary", "bounce", "shadow", "ao")},
                    "loadAverage": [round(r["loadAverage"], 1) for r in rs]})
    out = {"size": args.size, "maxDepth": 4, "cpus": os.cpu_count(), "summary": summary, "raw": raw}
    with open(args.out, "w") as f:
        json.dump(out, f, indent=2)
        f.write("\n")
    print("\n| config | spp | trace | frame s (median) | frames s | "
          + " | ".join(STAGES) + " | load |")
    print("|---|---|---|---|---|" + "---|" * len(STAGES) + "---|")
    for s in summary:
        print("| %s | %d | %s | %.3f | %s | %s | %s |" % (
            s["config"], s["spp"], s["trace"], s["renderSeconds"],
            ", ".join("%.2f" % x for x in s["renderSecondsAll"]),
            " | ".join("%.3f" % s["stages"][k] for k in STAGES),
            "-".join("%.1f" % x for x in (min(s["loadAverage"]), max(s["loadAverage"])))))


if __name__ == "__main__":
    main()
