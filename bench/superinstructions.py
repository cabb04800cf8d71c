#!/usr/bin/env python3
"""interp's superinstructions (docs/modes.md) against interp --no-superinstructions and inline:
per-hit texture cost on PoCL, and gfx90a registers of the interp kernel.

Workloads: the depth chain of bench/stability.py (mathColor multiply-adds) at 64 and 256
nodes on bench/inputs/sweep/scene.json, and examples/rust and examples/scratches on the atrium
(examples/atrium/scene.json, scene-scratched.json; generate it first with
`python3 scripts/make_scenes.py --only atrium`). Per workload, every repetition renders the
three configurations back to back, in an order that rotates with the repetition (the shared
machine's load drifts), each in its own texrender process with a warm program cache (a first,
unmeasured render builds every kernel). The per-hit cost is the texture kernel's device time
(OpenCL profiling, stats.json) over the texture stage's work-items (hit_attributes'
workItems: every active path of every bounce, misses and untextured hits included). Ratios
are taken per repetition, then the median, and between the minima. PoCL runs one thread (POCL_MAX_PTHREAD_COUNT=1,
--pocl-threads): on a shared 2-core machine the device time of a kernel spread over both cores
swings with every other process (rust: 14 to 51 ms per million hits in seven runs), on one
core it varies by about 10%. Registers: clang-15 -> gfx90a with libclc,
-Rpass-analysis=kernel-resource-usage (bench/resources.py), texcc_proctex of each interp kernel.

usage: bench/superinstructions.py [--build DIR] [--reps N] [--size WxH] [--spp N]
                                  [--pocl-threads N] [--only chain64,chain256,rust,scratches]
                                  [--out FILE]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import resources  # noqa: E402
import stability  # noqa: E402

CONFIGS = (("interp", "interp", []),
           ("interp-unfused", "interp", ["--no-superinstructions"]),
           ("inline", "inline", []))
ATRIUM = os.path.join(common.ROOT, "examples", "atrium")
WORKLOADS = {
    "chain64": (None, stability.SCENE, 64),
    "chain256": (None, stability.SCENE, 256),
    "rust": (os.path.join(common.ROOT, "examples", "rust", "graph.json"),
             os.path.join(ATRIUM, "scene.json"), None),
    "scratches": (os.path.join(common.ROOT, "examples", "scratches", "graph.json"),
                  os.path.join(ATRIUM, "scene-scratched.json"), None),
}


def graph_of(tools, name):
    graph, _, depth = WORKLOADS[name]
    if graph:
        return graph
    path = os.path.join(tools.work, "%s.json" % name)
    with open(path, "w") as f:
        json.dump(stability.chain_graph(depth), f)
    return path


def fused_pairs(folder):
    sys.path.insert(0, os.path.join(common.ROOT, "testsuite", "Inputs", "codegen"))
    import equivalence  # noqa: E402
    return equivalence.fused_count(folder)


RATIOS = (("interp/inline", "interp", "inline"), ("unfused/inline", "interp-unfused", "inline"),
          ("interp/unfused", "interp", "interp-unfused"))


def summarize(samples):
    """Per configuration: the samples, their minimum and median; per ratio: the per-repetition
    ratios, their median, and the ratio of the minima. A run that shared its core with another
    process takes about three times as long (the machine is shared): the minimum is the
    least-disturbed figure, the median of the ratios the typical one."""
    ratios = {name: [x / y for x, y in zip(samples[a], samples[b])] for name, a, b in RATIOS}
    return {"msPerMillionHits": samples,
            "minMsPerMillionHits": {k: min(v) for k, v in samples.items()},
            "medianMsPerMillionHits": {k: common.median(v) for k, v in samples.items()},
            "ratios": ratios, "medianRatios": {k: common.median(v) for k, v in ratios.items()},
            "minRatios": {name: min(samples[a]) / min(samples[b]) for name, a, b in RATIOS}}


def measure_workloads(tools, names, reps, opts):
    results = {}
    for name in names:
        _, scene, _ = WORKLOADS[name]
        samples, hits, folders = common.per_hit_samples(tools, name, graph_of(tools, name), scene,
                                                        CONFIGS, reps, opts)
        table, fused = fused_pairs(folders["interp"])
        row = {"scene": os.path.relpath(scene, common.ROOT), "hits": hits,
               "superinstructions": table, "fusedPairs": fused}
        row.update(summarize(samples))
        if name in ("rust", "scratches"):
            row["gfx90a"] = {}
            for cfg in ("interp", "interp-unfused"):
                src = os.path.join(folders[cfg], "proctex.cl")
                row["gfx90a"][cfg] = resources.amdgpu(src, folders[cfg],
                                                      {"texcc_proctex"})["kernels"]["texcc_proctex"]
        results[name] = row
        common.log("%s: ms per 1M hits min %s, median %s; median ratios %s, ratios of minima %s"
                   % (name, {k: round(v, 3) for k, v in row["minMsPerMillionHits"].items()},
                      {k: round(v, 3) for k, v in row["medianMsPerMillionHits"].items()},
                      {k: round(v, 3) for k, v in row["medianRatios"].items()},
                      {k: round(v, 3) for k, v in row["minRatios"].items()}))
    return results


def measure(tools, quick):
    """bench/run's figure: every workload, 128x128, 1 spp, one PoCL thread; 3 repetitions
    quick, 9 full."""
    reps = 3 if quick else 9
    workloads = common.with_one_pocl_thread(lambda: measure_workloads(
        tools, list(WORKLOADS), reps, ["--size", "128x128", "--spp", "1"]))
    return {"reps": reps, "size": "128x128", "spp": 1, "poclMaxPthreadCount": "1",
            "workloads": workloads}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--reps", type=int, default=9)
    ap.add_argument("--size", default="128x128")
    ap.add_argument("--spp", default="1")
    ap.add_argument("--pocl-threads", default="1")
    ap.add_argument("--only", default=",".join(WORKLOADS))
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "superinstructions.json"))
    args = ap.parse_args()
    work = args.work or os.path.join(args.build, "bench-superinstructions")
    os.makedirs(work, exist_ok=True)
    tools = common.Tools(args.build, work)
    if args.pocl_threads != "0":
        os.environ["POCL_MAX_PTHREAD_COUNT"] = args.pocl_threads
    opts = ["--size", args.size, "--spp", args.spp]
    names = args.only.split(",")
    data = {"machine": common.machine(), "git": common.git_head(), "reps": args.reps,
            "size": args.size, "spp": int(args.spp),
            "poclMaxPthreadCount": os.environ.get("POCL_MAX_PTHREAD_COUNT"),
            "workloads": measure_workloads(tools, names, args.reps, opts)}
    common.save(None, data, args.out)


if __name__ == "__main__":
    try:
        main()
    except common.BenchError as e:
        print("bench/superinstructions.py: error: %s" % e, file=sys.stderr)
        sys.exit(1)
