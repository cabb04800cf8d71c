#!/usr/bin/env python3
"""Writes random texture DAGs over random_nodes.cl for the equivalence tests.

Each graph has up to --max-nodes nodes (the last graph exactly that many) and --materials
materials; a node's arguments are drawn from earlier nodes (shared children; a float node
feeding a vector parameter is a broadcast), attributes (AO broadcast to vectors too), or
constants of every parameter kind (float, int, float2..4, arrays of float..float4 and int,
images). Some nodes are exact duplicates of earlier ones (the merge pass folds them). Every
material is its own DAG (the nodes it reaches), so --count 20 --materials 10 gives 200 DAGs.
With --twins K, K materials get a twin: a copy of the nodes they reach with new float constants,
so that shape mode's bodies are shared; with --bake F, a fraction F of the int arguments are
written {"value": v, "bake": true}. Both draw from their own random stream: the base graphs stay
those of the seed.

usage: random_graphs.py --out DIR [--count 20] [--materials 10] [--max-nodes 64] [--seed 1]
                        [--twins K] [--bake F]
Prints the paths of the graphs written, one per line.
"""
import argparse
import json
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))

# name -> (return type, [(param, type)]); "T[]" is __global const T*, "#name" an int that
# gives the length of array parameter `name`.
FUNCTIONS = {
    "rnd_blend": ("float", [("a", "float"), ("b", "float"), ("k", "float")]),
    "rnd_swirl": ("float2", [("uv", "float2"), ("s", "float"), ("n", "int")]),
    "rnd_mix3": ("float3", [("p", "float3"), ("q", "float3"), ("w", "float")]),
    "rnd_shade": ("float4", [("c", "float4"), ("uv", "float2"), ("t", "float")]),
    "rnd_len": ("float", [("p", "float3"), ("c", "float4")]),
    "rnd_weights": ("float", [("t", "float"), ("w", "float4[]"), ("n", "#w")]),
    "rnd_points": ("float3", [("p", "float3"), ("pts", "float3[]"), ("n", "#pts")]),
    "rnd_curve": ("float2", [("x", "float"), ("pts", "float2[]"), ("gains", "float[]"),
                             ("n", "#pts")]),
    "rnd_pick": ("float", [("x", "float"), ("table", "int[]"), ("n", "#table")]),
    "rnd_surface": ("float", [("a", "float"), ("dir", "float3")]),
    "rnd_image": ("float4", [("img", "sam2D"), ("uv", "float2")]),
}
ATTRIBUTES = {
    "float": ["AO"],
    "float2": ["TexCoord0"],
    "float3": ["WorldPos", "ObjectPos", "Normal", "GeomNormal", "Tangent", "ViewDir"],
}
WIDTH = {"float": 1, "float2": 2, "float3": 3, "float4": 4, "int": 1}


def constant(rng, ty):
    if ty == "int":
        return rng.randint(0, 4)
    if ty == "float":
        return round(rng.uniform(-1, 1), 4)
    return [round(rng.uniform(-1, 1), 4) for _ in range(WIDTH[ty])]


def array(rng, elem, count):
    if elem == "int":
        return [rng.randint(-4, 4) for _ in range(count)]
    if elem == "float":
        return [round(rng.uniform(-1, 1), 4) for _ in range(count)]
    return [[round(rng.uniform(-1, 1), 4) for _ in range(WIDTH[elem])] for _ in range(count)]


def argument(rng, ty, nodes, images):
    """A value for a float..float4 parameter: a node, an attribute or a constant."""
    r = rng.random()
    if r < 0.55:
        same = [n["id"] for n in nodes if n["ret"] == ty]
        bcast = [n["id"] for n in nodes if n["ret"] == "float"] if ty != "float" else []
        pool = same + bcast
        if pool:
            # Prefer recent nodes (deep chains) but reach back too (shared children).
            pick = pool[-1 - min(int(rng.expovariate(0.4)), len(pool) - 1)]
            return {"node": pick}
    if r < 0.75:
        return {"attr": rng.choice(ATTRIBUTES.get(ty, []) + ["AO"] if ty != "float" else ["AO"])}
    return constant(rng, ty)


def make_node(rng, index, nodes, images):
    fn = rng.choice([f for f in FUNCTIONS if images or f != "rnd_image"])
    ret, params = FUNCTIONS[fn]
    args, lengths = {}, {}
    for name, ty in params:
        if ty.endswith("[]"):
            count = lengths.setdefault("arrays", rng.randint(1, 5))
            args[name] = array(rng, ty[:-2], count)
            lengths[name] = count
        elif ty.startswith("#"):
            args[name] = lengths[ty[1:]]
        elif ty == "sam2D":
            args[name] = {"image": rng.choice(images)}
        elif ty == "int":
            args[name] = constant(rng, "int")
        else:
            args[name] = argument(rng, ty, nodes, images)
    return {"id": "n%d" % index, "fn": fn, "args": args, "ret": ret}


def bsdf(rng, nodes, unused, depth=0):
    def pick(types):
        # Nodes no material reads yet first, so that most of the graph is live.
        fresh = [n["id"] for n in nodes if n["ret"] in types and n["id"] in unused]
        pool = fresh or [n["id"] for n in nodes if n["ret"] in types]
        if pool and rng.random() < 0.85:
            pick = rng.choice(pool)
            unused.discard(pick)
            return {"node": pick}
        return None

    kind = rng.choice(["diffuse", "glossy", "emission", "blend"] if depth < 2 else ["diffuse"])
    color = pick(["float", "float3", "float4"]) or [0.5, 0.5, 0.5]
    if kind == "diffuse":
        return {"bsdf": "diffuse", "color": color}
    if kind == "glossy":
        return {"bsdf": "glossy", "color": color, "roughness": pick(["float"]) or 0.3}
    if kind == "emission":
        return {"bsdf": "emission", "color": color, "strength": pick(["float"]) or 1.0}
    return {"bsdf": "blend", "mask": pick(["float"]) or 0.5,
            "a": bsdf(rng, nodes, unused, depth + 1), "b": bsdf(rng, nodes, unused, depth + 1)}


def make_graph(rng, num_nodes, num_materials):
    images = ["img0", "img1"] if rng.random() < 0.5 else []
    nodes = []
    for i in range(num_nodes):
        if nodes and rng.random() < 0.08:
            twin = dict(rng.choice(nodes))
            twin["id"] = "n%d" % i
            nodes.append(twin)
        else:
            nodes.append(make_node(rng, i, nodes, images))
    unused = set(n["id"] for n in nodes)
    for n in nodes:
        for value in n["args"].values():
            if isinstance(value, dict) and "node" in value:
                unused.discard(value["node"])
    materials = {"m%d" % m: bsdf(rng, nodes, unused) for m in range(num_materials)}
    graph = {"texcc": 1, "sources": [os.path.join(HERE, "random_nodes.cl")]}
    if images:
        graph["images"] = {name: name + ".png" for name in images}
    graph["nodes"] = [{"id": n["id"], "fn": n["fn"], "args": n["args"]} for n in nodes]
    graph["materials"] = materials
    return graph


def reached(graph, material):
    """The ids of the nodes a material's BSDF tree reaches."""
    by_id = {n["id"]: n for n in graph["nodes"]}
    work, seen = [], set()

    def refs(value):
        if isinstance(value, dict):
            if "node" in value:
                work.append(value["node"])
            for v in value.values():
                refs(v)

    refs(material)
    while work:
        i = work.pop()
        if i not in seen:
            seen.add(i)
            refs(by_id[i]["args"])
    return seen


def add_twins(rng, graph, count):
    """Twins of `count` materials over renamed copies of their nodes, float constants redrawn
    (int constants, baked or not, are kept)."""
    for name in sorted(graph["materials"])[:count]:
        ids = reached(graph, graph["materials"][name])
        rename = lambda v: {"node": "%s_%s" % (name, v["node"])} if "node" in v else v

        def twin_value(v):
            if isinstance(v, dict):
                return rename(v)
            if isinstance(v, float):
                return round(rng.uniform(-1, 1), 4)
            if isinstance(v, list):
                return [twin_value(e) for e in v]
            return v

        for n in [n for n in graph["nodes"] if n["id"] in ids]:
            args = {k: twin_value(v) for k, v in n["args"].items()}
            graph["nodes"].append({"id": "%s_%s" % (name, n["id"]), "fn": n["fn"], "args": args})
        text = json.dumps(graph["materials"][name])
        for i in sorted(ids, key=len, reverse=True):
            text = text.replace('"node": "%s"' % i, '"node": "%s_%s"' % (name, i))
        graph["materials"][name + "_twin"] = json.loads(text)


def bake_ints(rng, graph, fraction):
    for n in graph["nodes"]:
        for k, v in n["args"].items():
            if isinstance(v, int) and rng.random() < fraction:
                n["args"][k] = {"value": v, "bake": True}


def main():
    ap = argparse.ArgumentParser(description="random texture DAGs for the equivalence tests")
    ap.add_argument("--out", required=True)
    ap.add_argument("--count", type=int, default=20)
    ap.add_argument("--materials", type=int, default=10)
    ap.add_argument("--max-nodes", type=int, default=64)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--twins", type=int, default=0)
    ap.add_argument("--bake", type=float, default=0.0)
    args = ap.parse_args()
    extra = random.Random(args.seed + 7919)
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(args.seed)
    for g in range(args.count):
        last = g == args.count - 1
        n = args.max_nodes if last else rng.randint(4, args.max_nodes)
        path = os.path.join(args.out, "random_%02d.json" % g)
        graph = make_graph(rng, n, args.materials)
        bake_ints(extra, graph, args.bake)
        add_twins(extra, graph, args.twins)
        with open(path, "w") as f:
            json.dump(graph, f, indent=1)
        print(path)


if __name__ == "__main__":
    main()
