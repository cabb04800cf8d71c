"""Figure 2: edit-to-frame latency per mode on the atrium with rust (bench/inputs/edit).

An argument edit and a rewiring over existing functions go through texrender's edit mode
(--edit-script bench/inputs/edit/edits.txt); stats.json gives, per frame, editSeconds (the
whole edit: re-encode and upload, or texcc + kernel build + upload), kernelBuilds and the
frame's renderSeconds. texrender does not split editSeconds, so texcc's share is measured by a
separate run of texcc on the same edited graph, and "build + upload" is editSeconds minus it.

A new user function cannot go through the edit mode: its live editor knows only the
signatures in layout.json, which lists the functions of the graph's nodes (dead ones' too). It is measured as
texcc on bench/inputs/edit/graph-new-function.json and a fresh texrender whose texture kernel
is not cached; its kernel build time is that process's wall time minus a second one's that
finds the kernel in the program cache. PoCL's own kernel cache is off (POCL_KERNEL_CACHE=0)
so that every build is a real one."""
import copy
import json
import os
import shutil

from texcc_tools.bench import common

EDIT_DIR = os.path.join(common.BENCH, "inputs", "edit")
SCENE = os.path.join(common.ROOT, "examples", "atrium", "scene.json")


def edited_graphs(work):
    """The graphs after each edit of edits.txt, for the separate texcc timing."""
    with open(os.path.join(EDIT_DIR, "graph.json")) as f:
        g = json.load(f)
    nodes = {n["id"]: n for n in g["nodes"]}
    nodes["patches"]["args"]["scale"] = 2.6
    arg = copy.deepcopy(g)
    nodes["mask"]["args"]["noise"] = {"node": "tone"}
    rewire = copy.deepcopy(g)
    out = {}
    for name, graph in (("argument", arg), ("rewire", rewire)):
        graph["sources"] = [os.path.normpath(os.path.join(EDIT_DIR, s)) for s in graph["sources"]]
        path = os.path.join(work, "edit-%s.json" % name)
        with open(path, "w") as f:
            json.dump(graph, f)
        out[name] = path
    return out


def live_edits(tools, mode, opts, rep):
    folder = os.path.join(tools.work, "edit-%s" % mode)
    common.texcc(tools, os.path.join(EDIT_DIR, "graph.json"), folder, mode)
    stats, _, _ = common.texrender(tools, SCENE, folder, "edit-%s-%d" % (mode, rep),
                                   opts + ["--edit-script", os.path.join(EDIT_DIR, "edits.txt")])
    frames = stats["frames"]
    if len(frames) != 3:
        raise common.BenchError("edit mode: expected 3 frames, got %d" % len(frames))
    return {"argument": frames[1], "rewire": frames[2], "firstFrame": frames[0]}


def new_function(tools, mode, opts, rep):
    folder = os.path.join(tools.work, "newfn-%s-%d" % (mode, rep))
    texcc_s = common.texcc(tools, os.path.join(EDIT_DIR, "graph-new-function.json"), folder, mode)
    cache = os.path.join(tools.work, "cache-newfn-%s-%d" % (mode, rep))
    shutil.rmtree(cache, ignore_errors=True)
    shutil.copytree(tools.cache, cache)
    cold, _, cold_wall = common.texrender(tools, SCENE, folder, "newfn-cold", opts, cache=cache)
    warm, _, warm_wall = common.texrender(tools, SCENE, folder, "newfn-warm", opts, cache=cache)
    if cold["kernelBuilds"] < 1 or warm["kernelBuilds"] != 0:
        raise common.BenchError("new function: expected a build then a cache hit, got %d and %d"
                                % (cold["kernelBuilds"], warm["kernelBuilds"]))
    return {"texccSeconds": texcc_s, "kernelBuilds": cold["kernelBuilds"],
            "buildSeconds": cold_wall - warm_wall,
            "frameSeconds": cold["renderSeconds"], "processSeconds": cold["totalSeconds"]}


def measure(tools, quick):
    size = "256x256" if quick else "512x512"
    reps = 2 if quick else 5
    opts = ["--size", size, "--spp", "1"]
    graphs = edited_graphs(tools.work)
    samples = {m: {"argument": [], "rewire": [], "new": [], "texcc": {"argument": [],
                                                                     "rewire": []}}
               for m in common.MODES}
    with common.no_pocl_cache():
        run_reps(tools, reps, opts, graphs, samples)
    return {"size": size, "spp": 1, "repetitions": reps, "rows": summarize(samples),
            "samples": samples, "poclKernelCache": False}


def run_reps(tools, reps, opts, graphs, samples):
    for rep in range(reps):
        for mode in common.MODES:
            common.log("edits rep %d/%d %s" % (rep + 1, reps, mode))
            live = live_edits(tools, mode, opts, rep)
            for kind in ("argument", "rewire"):
                samples[mode][kind].append(live[kind])
                samples[mode]["texcc"][kind].append(common.texcc(
                    tools, graphs[kind], os.path.join(tools.work, "edit-texcc"), mode))
            samples[mode]["new"].append(new_function(tools, mode, opts, rep))


def summarize(samples):
    rows = []
    for mode, s in samples.items():
        for kind in ("argument", "rewire"):
            frames = s[kind]
            edit = common.median([f["editSeconds"] for f in frames])
            texcc_s = common.median(s["texcc"][kind])
            builds = max(f["kernelBuilds"] for f in frames)
            rows.append({"mode": mode, "edit": kind, "kernelBuilds": builds,
                         "texccSeconds": texcc_s if builds else 0.0,
                         "editSeconds": edit,
                         "buildUploadSeconds": max(edit - texcc_s, 0.0) if builds else edit,
                         "frameSeconds": common.median([f["renderSeconds"] for f in frames]),
                         "editToFrameSeconds": common.median(
                             [f["editToFrameSeconds"] for f in frames])})
        new = s["new"]
        texcc_s = common.median([n["texccSeconds"] for n in new])
        build = common.median([n["buildSeconds"] for n in new])
        frame = common.median([n["frameSeconds"] for n in new])
        rows.append({"mode": mode, "edit": "new function", "kernelBuilds": new[0]["kernelBuilds"],
                     "texccSeconds": texcc_s, "editSeconds": None,
                     "buildUploadSeconds": build, "frameSeconds": frame,
                     "editToFrameSeconds": texcc_s + build + frame})
    return rows
