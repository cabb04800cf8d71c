#!/usr/bin/env python3
"""Issue 39 item 5, first part: single Blender nodes' cost per sample in Cycles (SVM, through
bpy) beside texrender's per mode, one thread each.

Cycles: a plane that fills an orthographic view (its Object coordinates span [-1, 1] in x and
y), the node's output into an Emission shader, no lights, black world, Cycles on the CPU with
one thread, SIZE x SIZE pixels at SPP samples, adaptive sampling and denoising off. A node's cost
per sample is its render's CPU time (the bpy process's, time.process_time) minus a constant
Emission's, over SIZE^2 x SPP samples (CPU time, because wall time on a shared machine spreads
with the load; wall time is recorded beside it); the renders of every node and of the constant
alternate in rounds (--reps), and the median of each node's per-round differences is reported.

texrender: texcc-eval --time over the same node as a texcc graph (inline, interp and shape in
one process, POCL_MAX_PTHREAD_COUNT=1, kernel time per textured hit, points uniform in
[-1, 1]^3).

The user fBM (bench/cpp_reference/userfbm.cl) runs in Cycles as OSL
(bench/cpp_reference/userfbm.osl, the same arithmetic, in a Script node) with the shading system
set to OSL for it and for its own constant Emission. The two sides are not the same measurement
(Cycles' difference of whole renders includes its SVM or OSL set-up for the node; texrender's
is the texture kernel alone).

usage: bench/per_node_cycles.py [--build DIR] [--size N] [--spp N] [--reps K] [--rounds R]
                                [--out FILE]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
VENV_PYTHON = os.path.join(common.ROOT, ".venv", "bin", "python")

# Node name -> (Blender node type, output, {input: value}, {property: value}, texcc graph node).
NODES = {
    "noise-3d-color-detail7": (
        "ShaderNodeTexNoise", "Color",
        {"Scale": 5.0, "Detail": 7.0, "Roughness": 0.5, "Lacunarity": 2.0, "Distortion": 0.0},
        {"noise_dimensions": "3D", "noise_type": "FBM", "normalize": True},
        {"fn": "blNoise3DColor", "src": "noise.cl",
         "args": {"vector": {"attr": "ObjectPos"}, "scale": 5.0, "detail": 7.0, "roughness": 0.5,
                  "lacunarity": 2.0, "offset": 0.0, "gain": 1.0, "distortion": 0.0, "type": 1,
                  "normalize": 1}}),
    "noise-3d-ridged-detail7": (
        "ShaderNodeTexNoise", "Color",
        {"Scale": 5.0, "Detail": 7.0, "Roughness": 0.5, "Lacunarity": 2.0, "Offset": 1.0,
         "Gain": 2.0, "Distortion": 0.0},
        {"noise_dimensions": "3D", "noise_type": "RIDGED_MULTIFRACTAL", "normalize": True},
        {"fn": "blNoise3DColor", "src": "noise.cl",
         "args": {"vector": {"attr": "ObjectPos"}, "scale": 5.0, "detail": 7.0, "roughness": 0.5,
                  "lacunarity": 2.0, "offset": 1.0, "gain": 2.0, "distortion": 0.0, "type": 3,
                  "normalize": 1}}),
    "voronoi-3d-f1": (
        "ShaderNodeTexVoronoi", "Distance",
        {"Scale": 5.0, "Randomness": 1.0},
        {"voronoi_dimensions": "3D", "feature": "F1", "distance": "EUCLIDEAN"},
        {"fn": "blVoronoi3DDistance", "src": "voronoi.cl",
         "args": {"vector": {"attr": "ObjectPos"}, "scale": 5.0, "detail": 0.0, "roughness": 0.5,
                  "lacunarity": 2.0, "smoothness": 1.0, "exponent": 0.5, "randomness": 1.0,
                  "feature": 0, "metric": 0, "normalize": 0}}),
    "wave-bands-x-distortion1-detail7": (
        "ShaderNodeTexWave", "Color",
        {"Scale": 5.0, "Distortion": 1.0, "Detail": 7.0, "Detail Scale": 1.0,
         "Detail Roughness": 0.5, "Phase Offset": 0.0},
        {"wave_type": "BANDS", "bands_direction": "X", "wave_profile": "SIN"},
        {"fn": "blWaveColor", "src": "noise.cl",
         "args": {"vector": {"attr": "ObjectPos"}, "scale": 5.0, "distortion": 1.0, "detail": 7.0,
                  "detailScale": 1.0, "detailRoughness": 0.5, "phaseOffset": 0.0, "waveType": 0,
                  "direction": 0, "profile": 0}}),
}

WORKER = r'''
import json, os, sys, time
import bpy
req = json.loads(sys.argv[-1])
# The Script node's socket query (oslquery) is in the bpy wheel's own site-packages.
sys.path.append(os.path.join(os.path.dirname(bpy.__file__), "..", "..", "..", "python", "lib",
                             "python3.11", "site-packages"))
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.shading_system = bool(req.get("osl"))
scene.render.threads_mode = "FIXED"
scene.render.threads = 1
scene.cycles.samples = req["spp"]
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.max_bounces = 0
scene.render.resolution_x = scene.render.resolution_y = req["size"]
scene.render.resolution_percentage = 100
world = bpy.data.worlds.new("w")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world
bpy.ops.mesh.primitive_plane_add(size=2.0)
plane = bpy.context.active_object
cam_data = bpy.data.cameras.new("c")
cam_data.type = "ORTHO"
cam_data.ortho_scale = 2.0
cam = bpy.data.objects.new("c", cam_data)
cam.location = (0.0, 0.0, 1.0)
scene.collection.objects.link(cam)
scene.camera = cam
materials = {}
for name, spec in req["nodes"].items():
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    o = t.nodes.new("ShaderNodeOutputMaterial")
    e = t.nodes.new("ShaderNodeEmission")
    t.links.new(e.outputs[0], o.inputs["Surface"])
    if spec is not None and spec[0] == "SCRIPT":
        txt = bpy.data.texts.new(name + ".osl")
        with open(spec[1]) as f:
            txt.write(f.read())
        n = t.nodes.new("ShaderNodeScript")
        n.mode = "INTERNAL"
        n.script = txt
        t.links.new(n.outputs[spec[2]], e.inputs["Color"])
    elif spec is not None:
        kind, output, inputs, props = spec
        tc = t.nodes.new("ShaderNodeTexCoord")
        n = t.nodes.new(kind)
        for k, v in props.items():
            setattr(n, k, v)
        for k, v in inputs.items():
            n.inputs[k].default_value = v
        t.links.new(tc.outputs["Object"], n.inputs["Vector"])
        t.links.new(n.outputs[output], e.inputs["Color"])
    materials[name] = m
times = {name: [] for name in materials}
cpu = {name: [] for name in materials}
for r in range(req["reps"] + 1):  # the first round warms up (kernel loading), not counted
    for name, m in materials.items():
        plane.data.materials.clear()
        plane.data.materials.append(m)
        t0, c0 = time.perf_counter(), time.process_time()
        bpy.ops.render.render()
        if r > 0:
            times[name].append(time.perf_counter() - t0)
            cpu[name].append(time.process_time() - c0)
print("PER_NODE_CYCLES " + json.dumps({"wall": times, "cpu": cpu}), flush=True)
'''


def cycles_times(size, spp, reps, osl=False):
    if osl:
        nodes = {"constant": None,
                 "userfbm": ["SCRIPT", os.path.join(common.BENCH, "cpp_reference", "userfbm.osl"),
                             "Color"]}
    else:
        nodes = {"constant": None}
        for name, (kind, output, inputs, props, _) in NODES.items():
            nodes[name] = (kind, output, inputs, props)
    req = json.dumps({"size": size, "spp": spp, "reps": reps, "nodes": nodes, "osl": osl})
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as f:
        f.write(WORKER)
    try:
        r = subprocess.run([VENV_PYTHON, f.name, req], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
    finally:
        os.remove(f.name)
    for line in r.stdout.splitlines():
        if line.startswith("PER_NODE_CYCLES "):
            return json.loads(line[len("PER_NODE_CYCLES "):])
    raise common.BenchError("the Cycles worker failed (exit %d): %s" % (r.returncode,
                                                                        r.stderr[-1500:]))


def texrender_times(tools, rounds, grid):
    eval_tool = os.path.join(tools.build, "bin", "texcc-eval")
    folders, keys = [], []
    for name, (_, _, _, _, node) in NODES.items():
        graph = {"texcc": 1,
                 "sources": [os.path.join(common.ROOT, "textures", "blender", node["src"])],
                 "nodes": [{"id": "n", "fn": node["fn"], "args": node["args"]}],
                 "materials": {"m": {"bsdf": "diffuse", "color": {"node": "n"}}}}
        path = os.path.join(tools.work, "%s.json" % name)
        with open(path, "w") as f:
            json.dump(graph, f)
        for mode in ("inline", "interp", "shape"):
            folder = os.path.join(tools.work, "%s-%s" % (name, mode))
            common.texcc(tools, path, folder, mode)
            folders.append(folder)
            keys.append((name, mode))
    for mode in ("inline", "interp", "shape"):
        folder = os.path.join(tools.work, "userfbm-%s" % mode)
        common.texcc(tools, os.path.join(common.BENCH, "cpp_reference", "graphs", "userfbm.json"),
                     folder, mode)
        folders.append(folder)
        keys.append(("userfbm", mode))
    r = subprocess.run([eval_tool] + folders + ["--time", str(rounds), "--grid", str(grid)],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                       env=dict(os.environ, POCL_MAX_PTHREAD_COUNT="1"))
    if r.returncode != 0:
        raise common.BenchError("texcc-eval failed: %s" % r.stderr[-1500:])
    out = json.loads(r.stdout)
    res = {}
    for (name, mode), f in zip(keys, out["folders"]):
        res.setdefault(name, {})[mode] = f["medianNsPerHit"]
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=21)
    ap.add_argument("--grid", type=int, default=4096)
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "per_node_cycles.json"))
    args = ap.parse_args()
    work = args.work or os.path.join(args.build, "bench-per-node-cycles")
    os.makedirs(work, exist_ok=True)
    tools = common.Tools(args.build, work)
    load = [os.getloadavg()[0]]
    cyc = cycles_times(args.size, args.spp, args.reps)
    load.append(os.getloadavg()[0])
    osl = cycles_times(args.size, args.spp, args.reps, osl=True)
    load.append(os.getloadavg()[0])
    tex = texrender_times(tools, args.rounds, args.grid)
    load.append(os.getloadavg()[0])
    samples = args.size * args.size * args.spp

    def per_sample(runs, name, constant="constant"):
        """Median over rounds of (node render - constant render) per sample, in ns, by the
        worker's CPU time (what the render thread spent, whatever the machine's load) and by
        wall time; and the CPU-time rounds themselves."""
        out = {}
        for clock in ("cpu", "wall"):
            diffs = [(a - b) * 1e9 / samples
                     for a, b in zip(runs[clock][name], runs[clock][constant])]
            out[clock] = (statistics.median(diffs), diffs)
        return out

    rows = {}
    for name in NODES:
        c = per_sample(cyc, name)
        svm = c["cpu"][0]
        rows[name] = {"cyclesSvmNsPerSample": svm, "cyclesSvmRounds": c["cpu"][1],
                      "cyclesSvmWallNsPerSample": c["wall"][0],
                      "texrenderNsPerSample": tex[name],
                      "ratioToCyclesSvm": {m: v / svm for m, v in tex[name].items()}}
        common.log("%s: Cycles SVM %.1f ns/sample CPU (%.1f wall); texrender %s" % (
            name, svm, c["wall"][0],
            {m: "%.1f (%.2fx)" % (v, v / svm) for m, v in tex[name].items()}))
    c = per_sample(osl, "userfbm")
    o = c["cpu"][0]
    rows["userfbm"] = {"cyclesOslNsPerSample": o, "cyclesOslRounds": c["cpu"][1],
                       "cyclesOslWallNsPerSample": c["wall"][0],
                       "texrenderNsPerSample": tex["userfbm"],
                       "ratioToCyclesOsl": {m: v / o for m, v in tex["userfbm"].items()}}
    common.log("userfbm: Cycles OSL %.1f ns/sample CPU (%.1f wall); texrender %s" % (
        o, c["wall"][0], {m: "%.1f (%.2fx)" % (v, v / o) for m, v in tex["userfbm"].items()}))
    common.save(None, {"machine": common.machine(), "git": common.git_head(), "size": args.size,
                       "spp": args.spp, "reps": args.reps, "rounds": args.rounds,
                       "grid": args.grid, "threads": 1, "clock": "cpu", "loadAverage1min": load,
                       "cyclesConstantSeconds": cyc["cpu"]["constant"],
                       "cyclesOslConstantSeconds": osl["cpu"]["constant"], "nodes": rows},
                args.out)


if __name__ == "__main__":
    common.run_main(main, "bench/per_node_cycles.py")
