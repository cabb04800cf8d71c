"""Figure 6: parallel AO against a per-hit loop (the paper's claim that tracing every AO ray of
every hit in one launch beats looping over a hit's AO rays inside one work-item).

The atrium with rust (which reads AO) is rendered with texrender's default `ao_trace` +
`ao_reduce` (one work-item per AO ray) and with `--ao-method=loop` (`ao_loop`, one work-item per
hit). Both trace the same rays, so the images must be identical: the figure checks it with
`texrender-compare --exact`. Each repetition renders both, alternating which goes first; the
ratio of each repetition is taken, and medians are reported. Swept over AO rays per hit."""
import os

import common

SCENE = "examples/atrium/scene.json"
GRAPH = "examples/rust/graph.json"
METHODS = ("parallel", "loop")


def ao_kernel_seconds(stats):
    k = stats["kernels"]
    return sum(k[n]["seconds"] for n in ("ao_trace", "ao_reduce", "ao_loop") if n in k)


def render(tools, textures, method, samples, size, rep):
    name = "ao-%s-%d-%d" % (method, samples, rep)
    opts = ["--size", size, "--spp", "1", "--ao-samples", str(samples), "--ao-method", method]
    stats, img, _ = common.texrender(tools, os.path.join(common.ROOT, SCENE), textures, name,
                                     opts, image="exr")
    return {"aoSeconds": ao_kernel_seconds(stats), "renderSeconds": stats["renderSeconds"],
            "aoRays": stats["rays"]["ao"]["count"], "device": stats["device"]}, img


def identical(tools, a, b):
    compare = os.path.join(tools.build, "bin", "texrender-compare")
    _, out = common.run([compare, "--exact", a, b])  # exits non-zero unless identical
    return out.strip().splitlines()[0]


def measure(tools, quick):
    size = "128x128" if quick else "512x512"
    reps = 3 if quick else 7
    sweep = (2, 8, 32) if quick else (1, 2, 4, 8, 16, 32, 64)
    textures = os.path.join(tools.work, "ao-rust")
    common.texcc(tools, os.path.join(common.ROOT, GRAPH), textures, "interp")
    rows = []
    for samples in sweep:
        runs = {m: [] for m in METHODS}
        ratios, images = [], {}
        for rep in range(reps):
            order = METHODS if rep % 2 == 0 else METHODS[::-1]
            for method in order:
                common.log("ao %s, %d rays, rep %d/%d" % (method, samples, rep + 1, reps))
                r, images[method] = render(tools, textures, method, samples, size, rep)
                runs[method].append(r)
            ratios.append(runs["loop"][-1]["aoSeconds"] / runs["parallel"][-1]["aoSeconds"])
        rows.append({"aoSamples": samples, "ratioLoopOverParallel": common.median(ratios),
                     "exact": identical(tools, images["parallel"], images["loop"]),
                     "aoRays": runs["parallel"][0]["aoRays"],
                     **{m + "AoSeconds": common.median([r["aoSeconds"] for r in runs[m]])
                        for m in METHODS},
                     **{m + "RenderSeconds": common.median([r["renderSeconds"] for r in runs[m]])
                        for m in METHODS}})
    return {"size": size, "repetitions": reps, "rows": rows,
            "device": runs["parallel"][0]["device"]}
