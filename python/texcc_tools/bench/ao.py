"""Figure 6: parallel AO against a per-hit loop (the paper's claim that tracing every AO ray of
every hit in one launch beats looping over a hit's AO rays inside one work-item).

The atrium with rust (which reads AO) is rendered with texrender's default parallel AO and with
`--ao-method=loop` (`ao_loop`, one OpenCL work-item per hit looping over its rays), for each trace
backend: `--trace=embree` (the CPU default: `ao_rays` makes every AO ray of every hit, Embree traces
each hit's rays as one packet, `ao_reduce` averages; the loop variant keeps Embree for closest hit and
shadow rays) and `--trace=opencl` (`ao_trace`, one work-item per AO ray, then `ao_reduce`).
Both methods trace the same rays, so the images must be identical: the figure checks it with
`texrender-compare --exact`. Each repetition renders both, alternating which goes first; AO time
is ao_rays + ao_trace + ao_reduce against ao_loop (stats.json: OpenCL profiling, the Embree
stage's wall time); the ratio of each repetition is taken, and medians are reported. Swept over
AO rays per hit. (This replaces bench/ao_embree.py, its short Embree-only version.)

    python3 bench/ao.py [--build build] [--size 512x512] [--reps 5] [--samples 1,8,32]
        [--trace embree,opencl] [--out FILE]   # standalone; bench/run runs it as figure "ao"
"""
import os
import sys

from texcc_tools.bench import common

SCENE = "examples/atrium/scene.json"
GRAPH = "examples/rust/graph.json"
METHODS = ("parallel", "loop")
AO_STAGES = ("ao_rays", "ao_trace", "ao_reduce", "ao_loop")


def ao_kernel_seconds(stats):
    k = stats["kernels"]
    return sum(k[n]["seconds"] for n in AO_STAGES if n in k)


def render(tools, textures, method, samples, size, rep, trace):
    name = "ao-%s-%s-%d-%d" % (trace, method, samples, rep)
    opts = ["--size", size, "--spp", "1", "--ao-samples", str(samples), "--ao-method", method,
            "--trace=" + trace]
    stats, img, _ = common.texrender(tools, os.path.join(common.ROOT, SCENE), textures, name,
                                     opts, image="exr")
    return {"aoSeconds": ao_kernel_seconds(stats), "renderSeconds": stats["renderSeconds"],
            "aoRays": stats["rays"]["ao"]["count"], "device": stats["device"],
            "trace": stats.get("trace", trace), "load": os.getloadavg()[0]}, img


def identical(tools, a, b):
    compare = os.path.join(tools.build, "bin", "texrender-compare")
    _, out = common.run([compare, "--exact", a, b])  # exits non-zero unless identical
    return out.strip().splitlines()[0]


def measure(tools, quick, size=None, reps=None, sweep=None, traces=("embree", "opencl")):
    size = size or ("128x128" if quick else "512x512")
    reps = reps or (3 if quick else 7)
    sweep = sweep or ((2, 8, 32) if quick else (1, 2, 4, 8, 16, 32, 64))
    textures = os.path.join(tools.work, "ao-rust")
    common.texcc(tools, os.path.join(common.ROOT, GRAPH), textures, "interp")
    rows = []
    for trace in traces:
        for method in METHODS:  # warm: kernels built, caches filled
            render(tools, textures, method, 1, size, -1, trace)
        for samples in sweep:
            runs = {m: [] for m in METHODS}
            ratios, images = [], {}
            for rep in range(reps):
                order = METHODS if rep % 2 == 0 else METHODS[::-1]
                for method in order:
                    common.log("ao %s %s, %d rays, rep %d/%d" % (trace, method, samples,
                                                                rep + 1, reps))
                    r, images[method] = render(tools, textures, method, samples, size, rep,
                                               trace)
                    runs[method].append(r)
                ratios.append(runs["loop"][-1]["aoSeconds"] / runs["parallel"][-1]["aoSeconds"])
            loads = [r["load"] for m in METHODS for r in runs[m]]
            rows.append({"trace": trace, "aoSamples": samples,
                         "ratioLoopOverParallel": common.median(ratios),
                         "exact": identical(tools, images["parallel"], images["loop"]),
                         "aoRays": runs["parallel"][0]["aoRays"],
                         "loadRange": [min(loads), max(loads)],
                         **{m + "AoSeconds": common.median([r["aoSeconds"] for r in runs[m]])
                            for m in METHODS},
                         **{m + "RenderSeconds": common.median([r["renderSeconds"]
                                                                for r in runs[m]])
                            for m in METHODS}})
    return {"size": size, "repetitions": reps, "rows": rows, "traces": list(traces),
            "device": runs["parallel"][0]["device"]}


def main():
    import argparse
    import tempfile
    import time
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    common.add_build_argument(ap)
    ap.add_argument("--size", default="512x512")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--samples", default="1,8,32")
    ap.add_argument("--trace", default="embree,opencl")
    ap.add_argument("--out", help="result file (default bench/results/ao.json)")
    args = ap.parse_args()
    tools = common.Tools(os.path.abspath(args.build), tempfile.mkdtemp(prefix="texcc-ao-"))
    t0 = time.perf_counter()
    data = measure(tools, False, args.size, args.reps,
                   [int(s) for s in args.samples.split(",")], args.trace.split(","))
    data.update({"quick": False, "complete": True, "seconds": time.perf_counter() - t0,
                 "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                 "machine": common.machine(), "git": common.git_head(),
                 "loadAverage": os.getloadavg()[1],
                 "build": os.path.relpath(tools.build, common.ROOT),
                 "command": "python3 bench/ao.py " + " ".join(sys.argv[1:])})
    common.save("ao", data, args.out)


if __name__ == "__main__":
    common.run_main(main, "bench/ao.py")
