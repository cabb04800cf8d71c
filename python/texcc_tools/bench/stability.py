"""Figure 5: stability under growing graphs. Two families of generated graphs over
textures/math.cl's mathColor (float3 a, float3 b, int op), rendered on a one-quad scene
(bench/inputs/sweep/scene.json): "nodes", a balanced binary tree of additions with N nodes whose
leaves read ObjectPos; "depth", a chain of D multiply-adds. Per point and mode: texcc time,
kernel build time (the wall time of a first texrender process whose texture kernel is not
cached minus that of a second one that finds it in the program cache), texture-kernel device time, device memory and layout.json's
stack slots. A mode stops at its first failure (the error is kept) or when one point exceeds
the time cap. PoCL's own kernel cache is off (POCL_KERNEL_CACHE=0). The full run goes past the issue's 4096 nodes and depth 1024 (to 262143 nodes and
depth 65536) so that every mode meets its limit."""
import json
import os
import shutil
import time

from texcc_tools import manifest
from texcc_tools.bench import common

MATH = os.path.join(common.ROOT, "textures", "math.cl")
SCENE = os.path.join(common.BENCH, "inputs", "sweep", "scene.json")


def node(nid, a, b, op):
    return {"id": nid, "fn": "mathColor", "args": {"a": a, "b": b, "op": op}}


def tree_graph(count):
    """A balanced binary tree of count nodes (count odd or 1) summing ObjectPos leaves."""
    leaves = (count + 1) // 2
    nodes, level = [], []
    for i in range(leaves):
        nodes.append(node("l%d" % i, {"attr": "ObjectPos"}, [0.001 * i, 0.002, 0.003], 0))
        level.append("l%d" % i)
    k = 0
    while len(level) > 1:
        nxt = []
        for i in range(0, len(level) - 1, 2):
            nodes.append(node("s%d" % k, {"node": level[i]}, {"node": level[i + 1]}, 0))
            nxt.append("s%d" % k)
            k += 1
        if len(level) % 2:
            nxt.append(level[-1])
        level = nxt
    return graph(nodes, level[0])


def chain_graph(depth):
    nodes = [node("c0", {"attr": "ObjectPos"}, [0.5, 0.25, 0.125], 2)]
    for i in range(1, depth):
        op = 2 if i % 2 else 0
        nodes.append(node("c%d" % i, {"node": "c%d" % (i - 1)}, [0.999, 0.001, 0.5], op))
    return graph(nodes, nodes[-1]["id"])


def graph(nodes, out):
    return {"texcc": 1, "sources": [MATH], "nodes": nodes,
            "materials": {"m": {"bsdf": "diffuse", "color": {"node": out}}}}


def sizes(family, quick):
    if family == "nodes":
        return [1, 63] if quick else [4 ** k - 1 if k else 1 for k in range(10)]
    return [1, 64] if quick else [4 ** k for k in range(9)]


def point(tools, family, size, mode, cap):
    tag = "st-%s-%d-%s" % (family, size, mode)
    path = os.path.join(tools.work, tag + ".json")
    with open(path, "w") as f:
        json.dump(tree_graph(size) if family == "nodes" else chain_graph(size), f)
    folder = os.path.join(tools.work, tag)
    start = time.perf_counter()
    texcc_s = common.texcc(tools, path, folder, mode, timeout=cap)
    layout = manifest.load(folder)
    cache = os.path.join(tools.work, "cache-" + tag)
    shutil.rmtree(cache, ignore_errors=True)
    shutil.copytree(tools.sweep_cache, cache)
    left = max(cap - (time.perf_counter() - start), 1)
    cold, _, cold_wall = common.texrender(tools, SCENE, folder, tag, timeout=left, cache=cache)
    warm, _, warm_wall = common.texrender(tools, SCENE, folder, tag, timeout=cap, cache=cache)
    shutil.rmtree(cache, ignore_errors=True)
    return {"family": family, "size": size, "mode": mode, "texccSeconds": texcc_s,
            "buildSeconds": cold_wall - warm_wall,
            "kernelBuilds": cold["kernelBuilds"],
            "kernelSeconds": common.texture_kernel_seconds(warm),
            "memoryBytes": warm["memoryBytes"], "stackSlots": layout.get("stackSlots"),
            "spill": layout.get("spill"), "scratchFloat4PerHit": layout.get("scratchFloat4PerHit"),
            "wallSeconds": time.perf_counter() - start}


def warm_fixed_kernels(tools):
    """A program cache holding texrender's fixed kernels for the sweep scene."""
    tools.sweep_cache = os.path.join(tools.work, "cache-sweep")
    folder = os.path.join(tools.work, "st-warmup")
    path = folder + ".json"
    with open(path, "w") as f:
        json.dump(chain_graph(1), f)
    common.texcc(tools, path, folder, "interp")
    common.texrender(tools, SCENE, folder, "st-warmup", cache=tools.sweep_cache)


CHECKPOINTS = True  # bench.py passes a checkpoint callback


def measure(tools, quick, checkpoint=None):
    with common.no_pocl_cache():
        return sweep(tools, quick, checkpoint or (lambda data: None))


def sweep(tools, quick, checkpoint):
    cap = 120 if quick else 600
    warm_fixed_kernels(tools)
    points, failures = [], []

    def result():
        return {"capSeconds": cap, "points": points, "stopped": failures,
                "sizes": {f: sizes(f, quick) for f in ("nodes", "depth")}}

    for family in ("nodes", "depth"):
        for mode in common.MODES:
            for size in sizes(family, quick):
                common.log("stability %s=%d %s" % (family, size, mode))
                try:
                    p = point(tools, family, size, mode, cap)
                except common.BenchError as e:
                    failures.append({"family": family, "size": size, "mode": mode,
                                     "error": str(e).splitlines()[0][:300],
                                     "log": str(e)[-1500:]})
                    break
                points.append(p)
                if p["wallSeconds"] > cap:
                    failures.append({"family": family, "size": size, "mode": mode,
                                     "error": "passed the %d s cap (%.0f s)" % (cap, p["wallSeconds"])})
                    break
                checkpoint(result())
            checkpoint(result())
    return result()
