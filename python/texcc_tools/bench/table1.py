"""Figure 1: the paper's Table 1 on the atrium. Render time of the atrium with the rust texture
(and its AO mask) and with the scratches texture, per mode, relative to the same scene with the
model in plain diffuse gray. Every repetition renders all configurations in turn (baseline
first), so each ratio compares renders of one repetition; the table gives medians."""
import os

from texcc_tools.bench import common

PAPER = {"rust": {"cycles": 46, "rtx": 33, "paper": 21},
         "scratches": {"cycles": 9, "rtx": 4, "paper": 15}}

TEXTURES = {"rust": ("examples/rust/graph.json", "examples/atrium/scene.json"),
            "scratches": ("examples/scratches/graph.json", "examples/atrium/scene-scratched.json")}
BASELINE_SCENE = "examples/atrium/scene-diffuse.json"
# Only the gray material: no texture kernel, no AO (the rust layout makes texrender read AO).
BASELINE_GRAPH = "bench/inputs/diffuse/graph.json"


def compile_all(tools):
    out = {}
    for tex, (graph, _) in TEXTURES.items():
        for mode in common.MODES:
            folder = os.path.join(tools.work, "t1-%s-%s" % (tex, mode))
            common.texcc(tools, os.path.join(common.ROOT, graph), folder, mode)
            out[(tex, mode)] = folder
    out["diffuse"] = os.path.join(tools.work, "t1-diffuse")
    common.texcc(tools, os.path.join(common.ROOT, BASELINE_GRAPH), out["diffuse"], "interp")
    return out


def one_render(tools, scene, textures, name, opts):
    stats, _, _ = common.texrender(tools, os.path.join(common.ROOT, scene), textures, name, opts)
    return {"renderSeconds": stats["renderSeconds"], "kernelSeconds": stats["kernelSeconds"],
            "textureSeconds": common.texture_kernel_seconds(stats),
            "aoSeconds": common.ao_seconds(stats), "aoEnabled": stats["aoEnabled"],
            "textureKernel": stats["textureKernel"], "device": stats["device"]}


def measure(tools, quick):
    size = "256x256" if quick else "512x512"
    reps = 5 if quick else 9
    opts = ["--size", size, "--spp", "1"]
    folders = compile_all(tools)
    configs = [("diffuse", None)] + [(tex, mode) for tex in TEXTURES for mode in common.MODES]
    runs = {("%s/%s" % c if c[1] else c[0]): [] for c in configs}
    for rep in range(reps):
        for tex, mode in configs:
            if mode is None:
                key, scene, textures = "diffuse", BASELINE_SCENE, folders["diffuse"]
            else:
                key, scene, textures = "%s/%s" % (tex, mode), TEXTURES[tex][1], folders[(tex, mode)]
            common.log("table1 rep %d/%d %s" % (rep + 1, reps, key))
            runs[key].append(one_render(tools, scene, textures, "t1-" + key.replace("/", "-"),
                                        opts))
    return summarize(runs, reps, size)


def summarize(runs, reps, size):
    rows = []
    base = runs["diffuse"]
    for key, samples in runs.items():
        if key == "diffuse":
            continue
        tex, mode = key.split("/")
        ratio = [s["renderSeconds"] / b["renderSeconds"] for s, b in zip(samples, base)]
        kratio = [s["kernelSeconds"] / b["kernelSeconds"] for s, b in zip(samples, base)]
        tex_share = [s["textureSeconds"] / b["kernelSeconds"] for s, b in zip(samples, base)]
        ao_share = [s["aoSeconds"] / b["kernelSeconds"] for s, b in zip(samples, base)]
        rows.append({"texture": tex, "mode": mode,
                     "renderSeconds": common.median([s["renderSeconds"] for s in samples]),
                     "increasePercent": 100 * (common.median(ratio) - 1),
                     "kernelIncreasePercent": 100 * (common.median(kratio) - 1),
                     "textureKernelPercent": 100 * common.median(tex_share),
                     "aoKernelPercent": 100 * common.median(ao_share),
                     "textureKernelSeconds": common.median([s["textureSeconds"] for s in samples]),
                     "aoEnabled": samples[0]["aoEnabled"], "paper": PAPER[tex]})
    return {"size": size, "spp": 1, "repetitions": reps, "device": base[0]["device"],
            "baseline": {"renderSeconds": common.median([b["renderSeconds"] for b in base]),
                         "kernelSeconds": common.median([b["kernelSeconds"] for b in base]),
                         "aoEnabled": base[0]["aoEnabled"],
                         "textureKernel": base[0]["textureKernel"]},
            "rows": rows, "runs": runs}
