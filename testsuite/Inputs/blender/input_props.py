#!/usr/bin/env python3
"""input_props.py: the input nodes that no Cycles fixture covers (textures/blender/input.cl reads
attributes that texcc-eval draws at random), checked against what they must compute from the
same hit's attributes: Texture Coordinate's Normal is the normalised shading normal through the
object's axes (the identity and a 90-degree turn about Z), UV is (TexCoord0, 0), Generated is
ObjectPos in the bounding box's 0..1 space, the Ambient Occlusion node's Color is its input
times AO and AO is in [0, 1], Geometry's normals and Incoming are unit vectors.

    input_props.py --texcc T --eval E --src ROOT --work DIR [--host] [--grid N]

Prints one line per check and exits 1 if any fails.
"""
import argparse
import json
import math
import os
import subprocess
import sys

from texcc_tools import manifest

TOL = 1e-5
TURN = {"axisX": [0, 1, 0], "axisY": [-1, 0, 0], "axisZ": [0, 0, 1]}
AO_COLOR = [0.5, 1.0, 2.0]
BOX = {"bboxMin": [-1.0, -2.0, 0.5], "bboxMax": [1.0, 2.0, 0.5]}  # z flat: spans -1..1

NODES = [
    ("normal", "blGeometryNormal", {}),
    ("true_normal", "blGeometryTrueNormal", {}),
    ("incoming", "blGeometryIncoming", {}),
    ("tex_normal", "blTexCoordNormal", {"axisX": [1, 0, 0], "axisY": [0, 1, 0],
                                        "axisZ": [0, 0, 1]}),
    ("tex_normal_turned", "blTexCoordNormal", TURN),
    ("uv", "blTexCoordUV", {}),
    ("object", "blTexCoordObject", {}),
    ("generated", "blTexCoordGenerated", BOX),
    ("ao", "blAmbientOcclusionAO", {}),
    ("ao_color", "blAmbientOcclusionColor", {"color": AO_COLOR}),
]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def main():
    ap = argparse.ArgumentParser()
    for a in ("--texcc", "--eval", "--src", "--work"):
        ap.add_argument(a, required=True)
    ap.add_argument("--host", action="store_true")
    ap.add_argument("--grid", type=int, default=256)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    graph = {"texcc": 1, "sources": [os.path.join(args.src, "textures", "blender", "input.cl")],
             "nodes": [{"id": i, "fn": fn, "args": a} for i, fn, a in NODES],
             "materials": {"m_" + i: {"bsdf": "diffuse", "color": {"node": i}}
                           for i, _, _ in NODES}}
    path = os.path.join(args.work, "graph.json")
    with open(path, "w") as f:
        json.dump(graph, f)
    out = os.path.join(args.work, "out")
    subprocess.run([args.texcc, "--graph", path, "-o", out] +
                   (["--target=host"] if args.host else []), check=True)
    index = {m["name"]: m["index"] for m in manifest.load(out)["materials"]}
    text = subprocess.run([args.eval, out, "--grid", str(args.grid)] +
                          (["--host"] if args.host else []), check=True,
                          stdout=subprocess.PIPE, text=True).stdout
    hits = {}
    for line in text.splitlines():
        hit, mat, k, x, y, z, w = line.split()
        if k == "0":
            hits.setdefault(int(hit), {})[int(mat)] = [float(x), float(y), float(z)]
    v = {i: [hits[h][index["m_" + i]] for h in sorted(hits)] for i, _, _ in NODES}
    n = len(hits)

    def close(a, b):
        return all(abs(p - q) <= TOL * max(1.0, abs(q)) for p, q in zip(a, b))

    half = [(hi - lo) / 2 or 1.0 for lo, hi in zip(BOX["bboxMin"], BOX["bboxMax"])]
    centre = [(lo + hi) / 2 for lo, hi in zip(BOX["bboxMin"], BOX["bboxMax"])]
    checks = [
        ("Texture Coordinate Normal = normalize(Normal), identity axes",
         lambda h: close(v["tex_normal"][h], unit(v["normal"][h]))),
        ("Texture Coordinate Normal through axes turned 90 degrees about Z = (n.y, -n.x, n.z)",
         lambda h: close(v["tex_normal_turned"][h],
                         unit([v["normal"][h][1], -v["normal"][h][0], v["normal"][h][2]]))),
        ("UV = (u, v, 0), u and v in TexCoord0's range",
         lambda h: v["uv"][h][2] == 0.0 and all(-0.5 <= c <= 1.5 for c in v["uv"][h][:2])),
        ("Generated = (Object - (centre - half)) / (2 half), a flat axis spanning -1..1",
         lambda h: close(v["generated"][h], [(p - (c - s)) / (2 * s) for p, c, s in
                                              zip(v["object"][h], centre, half)])),
        ("AO in [0, 1]", lambda h: 0.0 <= v["ao"][h][0] <= 1.0),
        ("AO Color = color * AO",
         lambda h: close(v["ao_color"][h], [c * v["ao"][h][0] for c in AO_COLOR])),
        ("Geometry Normal, True Normal, Incoming are unit vectors",
         lambda h: all(abs(math.sqrt(sum(c * c for c in v[k][h])) - 1.0) <= TOL
                       for k in ("normal", "true_normal", "incoming"))),
    ]
    failed = 0
    for name, ok in checks:
        bad = [h for h in range(n) if not ok(h)]
        failed += bool(bad)
        print("%s: %s (%d of %d hits)%s" % ("FAIL" if bad else "OK", name, n - len(bad), n,
                                            "; first bad hit %d" % bad[0] if bad else ""))
    print("input nodes: %d of %d checks pass" % (len(checks) - failed, len(checks)))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
