"""Issue 39 item 5: single Blender nodes' cost per sample in Cycles (SVM and OSL, through bpy),
in texrender per mode and in the C reference, one thread each, measured in interleaved rounds.

Nodes (NODES): Noise 3D Color Detail 7 fBM and Ridged Multifractal, Voronoi 3D F1, Wave Bands X
Sine Distortion 1 Detail 7, and a user's fBM (bench/cpp_reference/userfbm.cl; in Cycles as OSL,
bench/cpp_reference/userfbm.osl in a Script node: no SVM form).

Cycles: a plane that fills an orthographic view (its Object coordinates span [-1, 1] in x and
y), the node's output into an Emission shader, no lights, black world, Cycles on the CPU with
one thread, SIZE x SIZE pixels at SPP samples, adaptive sampling and denoising off. Two bpy
processes stay up for the whole run, one with the SVM shading system and one with OSL
(scene.cycles.shading_system: Blender's own nodes then run as Cycles' OSL shaders); each
renders, when asked, every node's material and a constant Emission once. A node's cost per
sample in a round is its render's CPU time (the bpy process's, time.process_time) minus the
constant's of the same process and round, over SIZE^2 x SPP samples (CPU time because wall time
on a shared machine spreads with the load; wall time is kept beside it).

texrender: texcc-eval --time over each node as a texcc graph (inline, interp and shape,
POCL_MAX_PTHREAD_COUNT=1, kernel time per textured hit, points uniform in [-1, 1]^3), all
folders in one process per round (--inner rounds; their median is the round's figure).

C reference: bench/cpp_reference/ref (the same texture source compiled by clang-15 -O3 over an
array of points, run-time and folded parameters; thread CPU time), --inner rounds per round.
Its values are compared with texrender's inline mode at its points ("maxAbsDiff", must be 0).

Each round runs the four (Cycles SVM, Cycles OSL, texrender, reference) once, in an order that
rotates with the round; the figures are medians over the rounds, with the 1-minute load average
recorded per round, and the median over rounds of each round's ratio of texrender's inline mode
to Cycles' figure in the same round.

usage: bench/per_node_cycles.py [--build DIR] [--size N] [--spp N] [--reps K] [--inner R]
                                [--no-osl] [--out FILE]
"""
import argparse
import json
import os
import statistics
import subprocess

from texcc_tools.bench import common, texture_speed

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

# The C reference's variant names (bench/cpp_reference/ref.c) and its --dump-values columns per
# node; the user fBM's texcc graph.
REF = {"noise-3d-color-detail7": ("noise3d-color-detail7", 0),
       "noise-3d-ridged-detail7": ("noise3d-ridged-detail7", 6),
       "voronoi-3d-f1": ("voronoi3d-f1", 9),
       "wave-bands-x-distortion1-detail7": ("wave-bands-x-distortion1-detail7", 12),
       "userfbm": ("userfbm", 3)}
USERFBM_GRAPH = os.path.join(common.BENCH, "cpp_reference", "graphs", "userfbm.json")
USERFBM_OSL = os.path.join(common.BENCH, "cpp_reference", "userfbm.osl")
MODES = ("inline", "interp", "shape")

WORKER = r"""
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


def render_all():
    wall, cpu = {}, {}
    for name, m in materials.items():
        plane.data.materials.clear()
        plane.data.materials.append(m)
        t0, c0 = time.perf_counter(), time.process_time()
        bpy.ops.render.render()
        wall[name] = time.perf_counter() - t0
        cpu[name] = time.process_time() - c0
    return {"wall": wall, "cpu": cpu}


render_all()  # warms up (kernel loading, OSL shader compilation), not counted
print("PER_NODE_READY", flush=True)
for line in sys.stdin:
    if line.strip() != "round":
        break
    print("PER_NODE_ROUND " + json.dumps(render_all()), flush=True)
"""


class CyclesWorker:
    """One bpy process (SVM or OSL) that renders every material once per round()."""

    def __init__(self, work, size, spp, nodes, osl):
        self.name = "osl" if osl else "svm"
        self.script = os.path.join(work, "per_node_worker.py")
        with open(self.script, "w") as f:
            f.write(WORKER)
        self.log = open(os.path.join(work, "cycles-%s.log" % self.name), "w")
        req = json.dumps({"size": size, "spp": spp, "nodes": nodes, "osl": osl})
        self.proc = subprocess.Popen([VENV_PYTHON, self.script, req], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=self.log, text=True)
        self._read("PER_NODE_READY")

    def _read(self, prefix):
        for line in self.proc.stdout:
            if line.startswith(prefix):
                return line[len(prefix):].strip()
        self.proc.wait()
        raise common.BenchError("the Cycles %s worker failed (exit %s): see %s" % (
            self.name, self.proc.returncode, self.log.name))

    def round(self):
        self.proc.stdin.write("round\n")
        self.proc.stdin.flush()
        return json.loads(self._read("PER_NODE_ROUND "))

    def close(self):
        if self.proc.poll() is None:
            self.proc.stdin.close()
            self.proc.wait()
        self.log.close()


def cycles_nodes(osl):
    """The materials of one worker: a constant, the Blender nodes, and under OSL the user fBM."""
    nodes = {"constant": None}
    for name, (kind, output, inputs, props, _) in NODES.items():
        nodes[name] = (kind, output, inputs, props)
    if osl:
        nodes["userfbm"] = ["SCRIPT", USERFBM_OSL, "Color"]
    return nodes


def texrender_folders(tools):
    """{(node, mode): texcc output folder} of every node, the user fBM included."""
    folders = {}
    for name, (_, _, _, _, node) in NODES.items():
        graph = {"texcc": 1,
                 "sources": [os.path.join(common.ROOT, "textures", "blender", node["src"])],
                 "nodes": [{"id": "n", "fn": node["fn"], "args": node["args"]}],
                 "materials": {"m": {"bsdf": "diffuse", "color": {"node": "n"}}}}
        path = os.path.join(tools.work, "%s.json" % name)
        with open(path, "w") as f:
            json.dump(graph, f)
        for mode in MODES:
            folder = os.path.join(tools.work, "%s-%s" % (name, mode))
            common.texcc(tools, path, folder, mode)
            folders[(name, mode)] = folder
    for mode in MODES:
        folder = os.path.join(tools.work, "userfbm-%s" % mode)
        common.texcc(tools, USERFBM_GRAPH, folder, mode)
        folders[("userfbm", mode)] = folder
    return folders


def texrender_round(eval_tool, folders, inner, grid):
    """One texcc-eval --time process over every folder: {(node, mode): median ns per hit}."""
    keys = list(folders)
    r = subprocess.run([eval_tool] + [folders[k] for k in keys] +
                       ["--time", str(inner), "--grid", str(grid)],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                       env=dict(os.environ, POCL_MAX_PTHREAD_COUNT="1"))
    if r.returncode != 0:
        raise common.BenchError("texcc-eval failed: %s" % r.stderr[-1500:])
    return {k: f["medianNsPerHit"] for k, f in zip(keys, json.loads(r.stdout)["folders"])}


def ref_round(ref, inner, grid):
    """One run of the C reference: {variant: median ns per sample}."""
    out, _ = texture_speed.sh([ref, "--points", str(grid), "--rounds", str(inner)])
    return {k: v["medianNsPerSample"] for k, v in json.loads(out)["variants"].items()}


def ref_values_check(tools, ref, folders, grid):
    """Max abs difference per node between the reference and texrender's inline mode at the
    reference's points (both must give the same floats: 0)."""
    points = os.path.join(tools.work, "ref-points.txt")
    values = os.path.join(tools.work, "ref-values.txt")
    texture_speed.sh([ref, "--points", str(grid), "--rounds", "1", "--dump-points", points,
                      "--dump-values", values])
    env = dict(os.environ, POCL_MAX_PTHREAD_COUNT="1")
    diffs = {}
    for name, (_, col) in REF.items():
        out, _ = texture_speed.sh([os.path.join(tools.build, "bin", "texcc-eval"),
                                   folders[(name, "inline")], "--points", points], env=env)
        tex = [[float(v) for v in line.split()[3:6]] for line in out.splitlines() if line.strip()]
        diffs[name] = texture_speed.max_abs_diff(
            texture_speed.read_rows(values, slice(col, col + 3)), tex)
    return diffs


def med(xs):
    return statistics.median(xs) if xs else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--reps", type=int, default=7, help="interleaved rounds")
    ap.add_argument("--inner", type=int, default=7,
                    help="texcc-eval and reference rounds inside each round")
    ap.add_argument("--grid", type=int, default=4096)
    ap.add_argument("--no-osl", action="store_true", help="no Cycles OSL column")
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "per_node_cycles.json"))
    args = ap.parse_args()
    work = args.work or os.path.join(args.build, "bench-per-node-cycles")
    os.makedirs(work, exist_ok=True)
    tools = texture_speed.bench_tools(args.build, work)
    eval_tool = os.path.join(args.build, "bin", "texcc-eval")
    folders = texrender_folders(tools)
    ref = texture_speed.build_ref(work, "native")
    diffs = ref_values_check(tools, ref, folders, args.grid)
    common.log("reference against texrender inline, max abs difference: %s" % diffs)
    workers = {"svm": CyclesWorker(work, args.size, args.spp, cycles_nodes(False), False)}
    if not args.no_osl:
        workers["osl"] = CyclesWorker(work, args.size, args.spp, cycles_nodes(True), True)
    samples = args.size * args.size * args.spp
    parts = list(workers) + ["texrender", "ref"]
    rounds, loads = [], []
    try:
        for r in range(args.reps):
            loads.append(os.getloadavg()[0])
            got = {}
            for j in range(len(parts)):
                part = parts[(j + r) % len(parts)]
                if part in workers:
                    got[part] = workers[part].round()
                elif part == "texrender":
                    got[part] = texrender_round(eval_tool, folders, args.inner, args.grid)
                else:
                    got[part] = ref_round(ref, args.inner, args.grid)
            rounds.append(got)
            common.log("round %d of %d done (load %.1f)" % (r + 1, args.reps, loads[-1]))
    finally:
        for w in workers.values():
            w.close()
    loads.append(os.getloadavg()[0])

    def cycles_cost(kind, name, clock="cpu"):
        """Per round: (node render - constant render) in ns per sample."""
        if kind not in workers:
            return []
        out = []
        for g in rounds:
            c = g[kind][clock]
            if name in c:
                out.append((c[name] - c["constant"]) * 1e9 / samples)
        return out

    rows = {}
    for name in list(NODES) + ["userfbm"]:
        row = {}
        for kind in ("svm", "osl"):
            xs = cycles_cost(kind, name)
            if xs:
                row["cycles" + kind.capitalize()] = {
                    "medianNsPerSample": med(xs), "rounds": xs,
                    "wallMedianNsPerSample": med(cycles_cost(kind, name, "wall"))}
        for mode in MODES:
            xs = [g["texrender"][(name, mode)] for g in rounds]
            row["texrender-" + mode] = {"medianNsPerSample": med(xs), "rounds": xs}
        variant = REF[name][0]
        for v in ("folded", "runtime"):
            xs = [g["ref"]["%s/%s" % (variant, v)] for g in rounds]
            row["ref-" + v] = {"medianNsPerSample": med(xs), "rounds": xs}
        row["refMaxAbsDiff"] = diffs[name]
        # ratios of medians, and the median of the rounds' own ratios (texrender inline)
        for kind in ("Svm", "Osl"):
            c = row.get("cycles" + kind)
            if not c:
                continue
            row["ratioToCycles" + kind] = {m: row["texrender-" + m]["medianNsPerSample"] /
                                           c["medianNsPerSample"] for m in MODES}
            row["ratioToCycles" + kind]["ref-folded"] = (row["ref-folded"]["medianNsPerSample"] /
                                                         c["medianNsPerSample"])
            row["roundRatioToCycles" + kind] = med([
                t / cc for t, cc in zip(row["texrender-inline"]["rounds"], c["rounds"]) if cc > 0])
        row["ratioToRefFolded"] = {m: row["texrender-" + m]["medianNsPerSample"] /
                                   row["ref-folded"]["medianNsPerSample"] for m in MODES}
        rows[name] = row
        common.log("%s: %s" % (name, ", ".join(
            "%s %.1f" % (k, v["medianNsPerSample"]) for k, v in row.items()
            if isinstance(v, dict) and "medianNsPerSample" in v)))
    common.save(None, {"machine": common.machine(), "git": common.git_head(), "size": args.size,
                       "spp": args.spp, "reps": args.reps, "inner": args.inner,
                       "grid": args.grid, "threads": 1, "clock": "cpu",
                       "loadAverage1min": loads, "interleaved": True,
                       "cyclesConstantSeconds": {k: [g[k]["cpu"]["constant"] for g in rounds]
                                                 for k in workers},
                       "nodes": rows}, args.out)
