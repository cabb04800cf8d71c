"""Figure 2b: a 20-edit session replayed in every mode, and the per-hit texture cost per mode.

bench/inputs/edit/session.txt (14 argument edits, 5 rewirings over the kernel's functions, 1
rewiring onto a dead node whose function no live node calls: only the interp kernels, which have
a case for every node's function, have it) runs through one `texrender
--edit-script` process per configuration on the atrium with rust (graph-session.json):
interp, inline, wavefront, shape with --tier=shape (every shape change waits for its build)
and shape with --tier=auto (tiered: the interp fallback renders while the shape kernel builds
on a background thread). Each frame's edit-to-frame latency is texrender's editSeconds +
renderSeconds (wall clock); a frame "waits for a build" when texrender counts a foreground
kernel build or build seconds (buildWaitSeconds) before it. PoCL's kernel cache is off
(POCL_KERNEL_CACHE=0) and texrender's program cache starts with only the fixed kernels, so
every texture-kernel build is a real one.

The per-hit cost renders the unedited graph per configuration (no edits; 3 alternating
repetitions quick, 5 full; minimum and median) and divides the texture kernels' device time
(OpenCL profiling, stats.json) by the work-items of the texture stage (hit_attributes'
work-items: every active path of every bounce, misses and untextured hits included, which
return at once). shape runs its shape kernel (--tier=shape); "shape (interp fallback)" runs
the same folder's proctex.interp.cl (--tier=interp)."""
import os
import shutil

from texcc_tools.bench import common

EDIT_DIR = os.path.join(common.BENCH, "inputs", "edit")
SCENE = os.path.join(common.ROOT, "examples", "atrium", "scene.json")
GRAPH = os.path.join(EDIT_DIR, "graph-session.json")
SESSION = os.path.join(EDIT_DIR, "session.txt")
# (name, texcc mode, texrender options)
CONFIGS = (("interp", "interp", []), ("inline", "inline", []), ("wavefront", "wavefront", []),
           ("shape", "shape", ["--tier=shape"]), ("shape+tiered", "shape", ["--tier=auto"]))


def fixed_kernel_cache(tools, opts):
    """A program cache holding the fixed kernels only (a diffuse render fills it)."""
    cache = os.path.join(tools.work, "cache-fixed")
    if not os.path.isdir(cache):
        folder = os.path.join(tools.work, "session-diffuse")
        common.texcc(tools, os.path.join(common.BENCH, "inputs", "diffuse", "graph.json"),
                     folder, "interp")
        common.texrender(tools, os.path.join(common.ROOT, "examples", "atrium",
                                             "scene-diffuse.json"),
                         folder, "session-diffuse", opts, cache=cache)
    return cache


def fresh_cache(tools, name, opts):
    cache = os.path.join(tools.work, "cache-" + name.replace("+", "-"))
    shutil.rmtree(cache, ignore_errors=True)
    shutil.copytree(fixed_kernel_cache(tools, opts), cache)
    return cache


def session(tools, name, mode, extra, opts):
    folder = os.path.join(tools.work, "session-" + name.replace("+", "-"))
    common.texcc(tools, GRAPH, folder, mode)
    stats, _, wall = common.texrender(tools, SCENE, folder, "session-" + name.replace("+", "-"),
                                      opts + extra + ["--edit-script", SESSION],
                                      cache=fresh_cache(tools, name, opts))
    frames = stats["frames"]
    if len(frames) != 21:
        raise common.BenchError("%s: expected 21 frames, got %d" % (name, len(frames)))
    edits = frames[1:]
    latency = [f["editToFrameSeconds"] for f in edits]
    waited = [f["index"] for f in edits if f["kernelBuilds"] or f["buildWaitSeconds"] > 0]
    worst = max(range(len(edits)), key=lambda i: latency[i])
    return {"mode": name, "totalSeconds": sum(latency), "worstSeconds": latency[worst],
            "worstEdit": edits[worst]["edit"], "medianSeconds": common.median(latency),
            "framesWaiting": waited, "foregroundBuilds": sum(f["kernelBuilds"] for f in edits),
            "backgroundBuilds": stats.get("backgroundKernelBuilds", 0),
            "tiers": [f["tier"] for f in edits], "processSeconds": wall,
            "frames": [{k: f[k] for k in ("index", "edit", "tier", "kernelBuilds",
                                          "backgroundBuilds", "buildWaitSeconds", "editSeconds",
                                          "renderSeconds", "editToFrameSeconds", "rebuilt",
                                          "backgroundRebuild")} for f in edits],
            "textureBuilds": stats.get("textureBuilds", [])}


def per_hit(tools, name, mode, extra, opts, rep):
    folder = os.path.join(tools.work, "perhit-" + name.replace("+", "-").replace(" ", "-"))
    if rep == 0:
        common.texcc(tools, os.path.join(EDIT_DIR, "graph.json"), folder, mode)
    stats, _, _ = common.texrender(tools, SCENE, folder, "perhit-%d" % rep, opts + extra)
    hits = stats["kernels"]["hit_attributes"]["workItems"]
    return {"mode": name, "tier": stats["frames"][0]["tier"], "hits": hits,
            "textureSeconds": common.texture_kernel_seconds(stats)}


def per_hit_rows(tools, quick):
    """Alternating repetitions (the shared machine's load varies); the minimum is the
    least-disturbed figure, the median is shown beside it."""
    size = "256x256" if quick else "512x512"
    opts = ["--size", size, "--spp", "2" if quick else "8"]
    configs = CONFIGS[:4] + (("shape (interp fallback)", "shape", ["--tier=interp"]),)
    samples = {name: [] for name, _, _ in configs}
    for rep in range(3 if quick else 5):
        for name, mode, extra in configs:
            common.log("per-hit cost rep %d: %s" % (rep + 1, name))
            samples[name].append(per_hit(tools, name, mode, extra, opts, rep))
    rows = []
    for name, runs in samples.items():
        ms = [1e3 * r["textureSeconds"] / r["hits"] * 1e6 for r in runs]
        rows.append({"mode": name, "tier": runs[0]["tier"], "hits": runs[0]["hits"],
                     "msPerMillionHits": min(ms), "medianMsPerMillionHits": common.median(ms),
                     "samples": ms})
    return rows, int(opts[-1])


def measure(tools, quick):
    size = "256x256" if quick else "512x512"
    opts = ["--size", size, "--spp", "1"]
    rows = []
    with common.no_pocl_cache():
        for name, mode, extra in CONFIGS:
            common.log("edit session: %s" % name)
            rows.append(session(tools, name, mode, extra, opts))
    # The program cache of the session runs is warm: these runs measure kernels, not builds.
    hits, hit_spp = per_hit_rows(tools, quick)
    return {"size": size, "spp": 1, "edits": 20, "rows": rows, "perHit": hits,
            "perHitSpp": hit_spp, "poclKernelCache": False}
