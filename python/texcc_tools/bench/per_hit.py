"""Figure 2e: per-hit texture cost of every mode side by side on PoCL, on the two textures of the
paper's Table 1 (examples/rust and examples/scratches), with shape mode's hoisting
(docs/frontend.md, "Hoisting") on and off.

Configurations: inline (first: the ratios are to it), interp (its value
stack a private array; the local-memory stack was removed in 2026-12, bench/refactor-20.md),
interp-unhoisted (interp --no-hoist),
interp-unquickened (interp --max-quickened=0), wavefront,
shape, shape --no-hoist (every declaration of the user's functions computed per hit), and
shape+bake (every constant int argument baked, --bake: the "mode" arguments, as in section 3), and
inline, interp and shape with --no-checks (the loop budget compiled out: "checkCost" is the
checked configuration's median time per hit over the unchecked one's, minus 1). One
`texcc-eval --time R` process per texture builds every configuration's kernel and runs all of
them over the same random hits (texcc-eval's grid: positions, normals, AO and UVs drawn as in
the equivalence tests) in R rounds, each round launching every configuration once in an order
that rotates with the round (docs/cli.md, texcc-eval). The cost is the texture kernels' device
time (OpenCL profiling) per textured hit; shape's texcc_uniforms runs once before the rounds,
as it runs once per upload in the renderer. The ratio to inline is taken within each round and
the median reported: on the shared 2-core machine whole renders of one configuration varied by
15% or more between processes (an earlier version of this figure timed renders), while rounds
of one process see the same load. PoCL runs one thread (POCL_MAX_PTHREAD_COUNT=1).

With --nodes it measures instead single Blender nodes (NODE_GRAPHS: Noise 3D fBM Detail 8,
Voronoi 3D F1 Euclidean, and the old fbm3 with 9 octaves) in inline and interp, all six in one
process (bench/results/per_hit-blender.json).

usage: bench/per_hit.py [--build DIR] [--rounds N] [--grid N] [--only rust,scratches,marble,wood]
                        [--nodes] [--out FILE]
"""
import argparse
import json
import os
import sys

from texcc_tools import manifest
from texcc_tools.bench import common
from texcc_tools.bench import resources

CONFIGS = (("inline", "inline", []),
           ("interp", "interp", []),
           ("interp-unhoisted", "interp", ["--no-hoist"]),
           ("interp-unquickened", "interp", ["--max-quickened=0"]),
           ("wavefront", "wavefront", []),
           ("shape", "shape", []),
           ("shape-unhoisted", "shape", ["--no-hoist"]),
           ("inline-unchecked", "inline", ["--no-checks"]),
           ("interp-unchecked", "interp", ["--no-checks"]),
           ("shape-unchecked", "shape", ["--no-checks"]))
GRAPHS = {"rust": os.path.join("examples", "rust", "graph.json"),
          "scratches": os.path.join("examples", "scratches", "graph.json"),
          "marble": os.path.join("examples", "marble", "graph.json"),
          "wood": os.path.join("examples", "wood", "graph.json")}
# Blender nodes of textures/blender/ (issue 21), one node each, in inline and interp only: a
# Noise Texture 3D fBM of Detail 8 and a Voronoi Texture 3D F1 Euclidean, beside the old
# library's fbm3 (9 octaves, as Detail 8 sums) that the noise replaces. Not part of bench/run's
# figure.
NODE_PATH = os.path.join("testsuite", "Inputs", "blender", "perhit")
NODE_GRAPHS = {"blender-noise-detail8": os.path.join(NODE_PATH, "noise-detail8.json"),
               "blender-voronoi-f1": os.path.join(NODE_PATH, "voronoi-f1.json"),
               "fbm3-octaves9": os.path.join(NODE_PATH, "fbm3-old.json")}
NODE_CONFIGS = (("inline", "inline", []), ("interp", "interp", []))


def hoisted_values(folder):
    """{function: [hoisted value names]} of a texcc output folder's layout.json."""
    layout = manifest.load(folder)
    return {fn["name"]: [v["name"] for v in fn["hoisted"]["values"]]
            for fn in layout["functions"] if "hoisted" in fn}


def time_folders(tools, folders, rounds, grid):
    """One texcc-eval --time process over the folders (rounds rotate their order)."""
    tool = os.path.join(tools.build, "bin", "texcc-eval")
    cmd = [tool] + folders + ["--time", str(rounds), "--grid", str(grid)]
    env = dict(os.environ, POCL_MAX_PTHREAD_COUNT="1")
    r = common.subprocess.run(cmd, stdout=common.subprocess.PIPE, stderr=common.subprocess.PIPE,
                              text=True, env=env)
    if r.returncode != 0:
        raise common.BenchError("%s failed: %s" % (" ".join(cmd), r.stderr[-1000:]))
    return cmd, json.loads(r.stdout)


def measure_nodes(tools, names, rounds, grid):
    """The Blender node rows: every (node graph, inline/interp) in one texcc-eval process, so
    that the nodes are compared within the same rounds; ratios are to the first folder (the
    first graph's inline)."""
    folders, keys = [], []
    for name in names:
        graph = os.path.join(common.ROOT, NODE_GRAPHS[name])
        for cfg, mode, extra in NODE_CONFIGS:
            folder = os.path.join(tools.work, "perhit-%s-%s" % (name, cfg))
            common.texcc(tools, graph, folder, mode, extra)
            folders.append(folder)
            keys.append((name, cfg))
    cmd, out = time_folders(tools, folders, rounds, grid)
    rows = {name: {"graph": NODE_GRAPHS[name], "device": out["device"],
                   "texturedHits": out["texturedHits"], "configs": {}} for name in names}
    for (name, cfg), f in zip(keys, out["folders"]):
        rows[name]["configs"][cfg] = {"medianNsPerHit": f["medianNsPerHit"],
                                      "minNsPerHit": f["minNsPerHit"],
                                      "medianRatioToFirst": f["medianRatioToFirst"]}
    common.log("nodes: ns per textured hit (median) %s; median ratios to %s inline %s" % (
        {"%s/%s" % k: round(f["medianNsPerHit"], 1) for k, f in zip(keys, out["folders"])},
        names[0], {"%s/%s" % k: round(f["medianRatioToFirst"], 3)
                   for k, f in zip(keys, out["folders"])}))
    return {"command": " ".join(os.path.relpath(c, tools.work) if c.startswith(tools.work)
                                else c for c in cmd), "ratiosTo": "%s inline" % names[0],
            "textures": rows}


def measure_texture(tools, name, rounds, grid):
    graph = os.path.join(common.ROOT, GRAPHS[name])
    probe = os.path.join(tools.work, "perhit-%s-probe" % name)
    common.texcc(tools, graph, probe, "shape")
    bake = ["--bake=" + a for a in resources.int_arguments(os.path.join(probe, "layout.json"))]
    configs = CONFIGS + (("shape+bake", "shape", bake),)
    folders = []
    for cfg, mode, extra in configs:
        folder = os.path.join(tools.work, "perhit-%s-%s" % (name, cfg))
        common.texcc(tools, graph, folder, mode, extra)
        folders.append(folder)
    cmd, out = time_folders(tools, folders, rounds, grid)
    row = {"graph": GRAPHS[name], "device": out["device"], "texturedHits": out["texturedHits"],
           "hoisted": hoisted_values(folders[CONFIGS.index(("shape", "shape", []))]),
           "command": " ".join(os.path.relpath(c, tools.work) if c.startswith(tools.work) else c
                               for c in cmd),
           "configs": {}}
    for (cfg, _, extra), f in zip(configs, out["folders"]):
        row["configs"][cfg] = {"texccOptions": extra, "nsPerHit": f["nsPerHit"],
                               "medianNsPerHit": f["medianNsPerHit"],
                               "minNsPerHit": f["minNsPerHit"],
                               "medianRatioToInline": f["medianRatioToFirst"]}
    row["checkCost"] = {m: row["configs"][m]["medianNsPerHit"] /
                        row["configs"][m + "-unchecked"]["medianNsPerHit"] - 1.0
                        for m in ("inline", "interp", "shape")}
    common.log("%s: loop budget's cost per hit %s" % (
        name, {m: "%+.1f%%" % (100 * c) for m, c in row["checkCost"].items()}))
    common.log("%s: ns per textured hit (median) %s; median ratios to inline %s" % (
        name, {c: round(v["medianNsPerHit"], 1) for c, v in row["configs"].items()},
        {c: round(v["medianRatioToInline"], 3) for c, v in row["configs"].items()}))
    return row


def measure(tools, quick):
    """bench/run's figure: both textures, one PoCL thread; 21 rounds over 1024 hits quick, 101
    rounds over 4096 full (a round of all five configurations takes about 0.1 s)."""
    rounds, grid = (21, 1024) if quick else (101, 4096)
    return {"rounds": rounds, "grid": grid, "poclMaxPthreadCount": "1",
            "textures": {name: measure_texture(tools, name, rounds, grid) for name in GRAPHS}}


def main():
    ap = argparse.ArgumentParser()
    common.add_build_argument(ap)
    ap.add_argument("--work", default=None)
    ap.add_argument("--rounds", type=int, default=101)
    ap.add_argument("--grid", type=int, default=4096)
    ap.add_argument("--only", default="rust,scratches")
    ap.add_argument("--nodes", action="store_true",
                    help="the Blender node rows (NODE_GRAPHS) instead, in one process")
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "per_hit.json"))
    args = ap.parse_args()
    work = args.work or os.path.join(args.build, "bench-per-hit")
    os.makedirs(work, exist_ok=True)
    tools = common.Tools(args.build, work)
    load_before = os.getloadavg()
    data = {"machine": common.machine(), "git": common.git_head(), "rounds": args.rounds,
            "grid": args.grid, "poclMaxPthreadCount": "1"}
    if args.nodes:
        data.update(measure_nodes(tools, list(NODE_GRAPHS), args.rounds, args.grid))
    else:
        data["textures"] = {name: measure_texture(tools, name, args.rounds, args.grid)
                            for name in args.only.split(",")}
    data["loadAverage"] = {"before": list(load_before), "after": list(os.getloadavg())}
    common.save(None, data, args.out)


if __name__ == "__main__":
    common.run_main(main, "bench/per_hit.py")
