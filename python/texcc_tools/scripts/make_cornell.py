"""Writes examples/cornell/ (OBJ files, scene.json, graph.json) from Mitsuba 3's Cornell box
numbers in ../shared/scenes/cornell_box_mitsuba.json (read from beside the repository, never
copied into it).

Materials white/red/green are constant diffuse BSDFs; the light is the `light` mesh with
scene.json "emission" (one-sided, emitting along its normal, downwards) over a white diffuse
BSDF, exactly as Mitsuba's `cornell_box()` (an area emitter on a white rectangle).

usage: scripts/make_cornell.py [--numbers PATH] [--out DIR]
"""
import argparse
import json
import os
import sys

from texcc_tools.paths import ROOT


def write_obj(path, shape):
    lines = ["# %s (%s) from Mitsuba 3's cornell_box(), written by scripts/make_cornell.py"
             % (shape["name"], shape["source_type"])]
    for v in shape["vertices"]:
        lines.append("v %r %r %r" % tuple(v))
    normal = shape.get("normal")
    if normal:
        lines.append("vn %r %r %r" % tuple(float(c) + 0.0 for c in normal))
    for tri in shape["triangles"]:
        if normal:
            lines.append("f " + " ".join("%d//1" % (i + 1) for i in tri))
        else:
            lines.append("f " + " ".join("%d" % (i + 1) for i in tri))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--numbers", default=os.path.join(ROOT, "..", "shared", "scenes",
                                                      "cornell_box_mitsuba.json"))
    ap.add_argument("--out", default=os.path.join(ROOT, "examples", "cornell"))
    args = ap.parse_args()
    if not os.path.exists(args.numbers):
        sys.exit("make_cornell.py: %s not found (it lives in ../shared/scenes)" % args.numbers)
    with open(args.numbers) as f:
        src = json.load(f)
    os.makedirs(args.out, exist_ok=True)

    cam = src["camera"]
    meshes = []
    for shape in src["shapes"]:
        name = shape["name"]
        write_obj(os.path.join(args.out, name + ".obj"), shape)
        mesh = {"obj": name + ".obj", "material": shape["material"]}
        emitter = shape.get("emitter")
        if emitter:
            mesh["emission"] = emitter["radiance_rgb"]
        meshes.append(mesh)

    scene = {
        "texrender": 1,
        "textures": "../../out/cornell",
        "camera": {"position": cam["origin"], "target": cam["target"], "up": cam["up"],
                   "fov": cam["fov_deg"], "fovAxis": cam["fov_axis"]},
        "film": {"width": cam["width"], "height": cam["height"]},
        "render": {"spp": 64, "maxDepth": src["integrator"]["max_depth"], "aoSamples": 8,
                   "aoDistance": 0.5, "seed": 1},
        "lights": [],
        "meshes": meshes,
    }
    with open(os.path.join(args.out, "scene.json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")

    graph = {
        "texcc": 1,
        "sources": [],
        "nodes": [],
        "materials": {name: {"bsdf": "diffuse", "color": m["albedo_rgb"]}
                      for name, m in src["materials"].items()},
    }
    with open(os.path.join(args.out, "graph.json"), "w") as f:
        json.dump(graph, f, indent=2)
        f.write("\n")
    print("make_cornell.py: wrote %d meshes, scene.json and graph.json to %s"
          % (len(meshes), os.path.relpath(args.out, ROOT)))


if __name__ == "__main__":
    main()
