#!/usr/bin/env python3
"""Figure 2e: per-hit texture cost of every mode side by side on PoCL, on the two textures of the
paper's Table 1 (examples/rust and examples/scratches on the atrium), with shape mode's hoisting
(docs/frontend.md, "Hoisting") on and off.

Configurations: interp (superinstructions on), inline, wavefront, shape, and shape --no-hoist
(every declaration of the user's functions computed per hit). Per workload, every repetition
renders all of them back to back in a rotating order, each in its own texrender process with a
warm program cache (common.per_hit_samples); shape renders with --tier=shape (texrender's
default for a single render), and its cost includes texcc_uniforms, which runs once per frame.
The cost is the texture kernels' device time over the texture stage's work-items, in ms per
million hits. PoCL runs one thread (POCL_MAX_PTHREAD_COUNT=1): on the shared 2-core machine a
kernel spread over both cores varies threefold between runs. Ratios to inline are taken per
repetition, then the median, and between the minima.

usage: bench/per_hit.py [--build DIR] [--reps N] [--size WxH] [--spp N] [--only rust,scratches]
                        [--out FILE]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import superinstructions  # noqa: E402

CONFIGS = (("interp", "interp", []),
           ("inline", "inline", []),
           ("wavefront", "wavefront", []),
           ("shape", "shape", []),
           ("shape-unhoisted", "shape", ["--no-hoist"]))
WORKLOADS = ("rust", "scratches")


def summarize(samples):
    """Per configuration: the samples, their minimum and median; per configuration other than
    inline: the per-repetition ratios to inline, their median, and the ratio of the minima."""
    ratios = {cfg: [x / y for x, y in zip(v, samples["inline"])]
              for cfg, v in samples.items() if cfg != "inline"}
    return {"msPerMillionHits": samples,
            "minMsPerMillionHits": {k: min(v) for k, v in samples.items()},
            "medianMsPerMillionHits": {k: common.median(v) for k, v in samples.items()},
            "ratiosToInline": ratios,
            "medianRatiosToInline": {k: common.median(v) for k, v in ratios.items()},
            "minRatiosToInline": {k: min(samples[k]) / min(samples["inline"]) for k in ratios}}


def hoisted_values(folder):
    """{function: [hoisted value names]} of a texcc output folder's layout.json."""
    with open(os.path.join(folder, "layout.json")) as f:
        layout = json.load(f)
    return {fn["name"]: [v["name"] for v in fn["hoisted"]["values"]]
            for fn in layout["functions"] if "hoisted" in fn}


def measure_workloads(tools, names, reps, opts):
    results = {}
    for name in names:
        graph, scene, _ = superinstructions.WORKLOADS[name]
        samples, hits, folders = common.per_hit_samples(tools, name, graph, scene, CONFIGS,
                                                        reps, opts)
        row = {"scene": os.path.relpath(scene, common.ROOT), "hits": hits,
               "hoisted": hoisted_values(folders["shape"])}
        row.update(summarize(samples))
        results[name] = row
        common.log("%s: ms per 1M hits min %s; median ratios to inline %s, ratios of minima %s"
                   % (name, {k: round(v, 2) for k, v in row["minMsPerMillionHits"].items()},
                      {k: round(v, 3) for k, v in row["medianRatiosToInline"].items()},
                      {k: round(v, 3) for k, v in row["minRatiosToInline"].items()}))
    return results


def measure(tools, quick):
    """bench/run's figure: both textures, 1 spp, one PoCL thread; 128x128 and 3 repetitions
    quick, 256x256 and 9 full (at 128x128 a frame's texture work is about 1.5 ms, and seven
    repetitions on the shared machine varied by 15% or more)."""
    reps, size = (3, "128x128") if quick else (9, "256x256")
    opts = ["--size", size, "--spp", "1"]
    workloads = common.with_one_pocl_thread(lambda: measure_workloads(tools, WORKLOADS, reps, opts))
    return {"reps": reps, "size": size, "spp": 1, "poclMaxPthreadCount": "1",
            "workloads": workloads}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--reps", type=int, default=9)
    ap.add_argument("--size", default="256x256")
    ap.add_argument("--spp", default="1")
    ap.add_argument("--only", default=",".join(WORKLOADS))
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "per_hit.json"))
    args = ap.parse_args()
    work = args.work or os.path.join(args.build, "bench-per-hit")
    os.makedirs(work, exist_ok=True)
    tools = common.Tools(args.build, work)
    opts = ["--size", args.size, "--spp", args.spp]
    names = args.only.split(",")
    data = {"machine": common.machine(), "git": common.git_head(), "reps": args.reps,
            "size": args.size, "spp": int(args.spp), "poclMaxPthreadCount": "1",
            "workloads": common.with_one_pocl_thread(
                lambda: measure_workloads(tools, names, args.reps, opts))}
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        json.dump(data, f, indent=1, sort_keys=True)
        f.write("\n")
    common.log("wrote " + args.out)


if __name__ == "__main__":
    try:
        main()
    except common.BenchError as e:
        print("bench/per_hit.py: error: %s" % e, file=sys.stderr)
        sys.exit(1)
