"""Figure: texrender side by side with real Cycles on the atrium (issues 22 and 24).

The atrium is rebuilt in Blender by examples/blender/make_scene.py (same OBJs, camera, sun as
irradiance R 2 pi (1 - cos r), sky as the world colour, Cycles on the CPU with both threads, no
denoising, no adaptive sampling, box filter 1 px, no clamping, light tree and path guiding off;
max_bounces = maxDepth - 2, since texrender's maxDepth has Mitsuba's meaning, 2 = direct light
only). Four variants: diffuse, rust on the model, rust everywhere, scratches on the model.

Frame times: every repetition renders every (variant, renderer) once, in an order that rotates
with the repetition; renderers: Cycles (one warm bpy process, `bpy.ops.render.render()` timed:
Cycles makes a new session per render, so the time includes its scene sync and BVH build; that
fixed part is measured apart as a 16x16, 1 spp render of the same file), texrender
`--trace=auto` (Embree on this CPU) and `--trace=opencl`, texcc's default mode (interp), one
process per render; texrender's frame is stats.json's renderSeconds (without the BVH build and
kernel builds, which are reported apart: bvhBuildSeconds). texrender's rust and scratches are
the examples' texcc graphs (examples/rust, examples/scratches), which are not Blender's nodes:
their frame times compare the same work, not the same pixels.

Image agreement (diffuse only: the only variant whose materials are the same in both
renderers): each renderer at high spp, the mean linear RGB over the model's pixels and over the
rest (regions from a Cycles emission mask; pixels on the model's edge excluded) and HDR-FLIP
(flip-evaluator) between the two images.

    python3 bench/cycles.py [--quick] [--build build] [--reps N] [--spp 1,16] [--size 512x512]
        [--agree-size 256x256 --agree-spp 256] [--no-agree]

bench/run runs it as the figure "cycles"; results in bench/results/cycles.json.
"""
import json
import os
import subprocess
import sys
import time

from texcc_tools import exr
from texcc_tools.bench import common
from texcc_tools.paths import EXAMPLES, VENV_PYTHON

MAKE_SCENE = os.path.join(EXAMPLES, "blender", "make_scene.py")
VARIANTS = ("diffuse", "rust-model", "rust-all", "scratches-model")
RENDERERS = ("cycles", "texrender-auto", "texrender-opencl")
TAG = "CYCLESJSON "

# texrender's side of each variant: (graph, scene, material of every mesh or None: the scene's)
TEXRENDER = {"diffuse": ("bench/inputs/diffuse/graph.json", "examples/atrium/scene-diffuse.json",
                         None),
             "rust-model": ("examples/rust/graph.json", "examples/atrium/scene.json", None),
             "rust-all": ("examples/rust/graph.json", "examples/atrium/scene.json", "rusty"),
             "scratches-model": ("examples/scratches/graph.json",
                                 "examples/atrium/scene-scratched.json", None)}


# --- The bpy worker (runs under .venv's Python) --------------------------------------------------

def worker():
    # Replies go to the original stdout; everything bpy and Cycles print goes to stderr.
    channel = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)
    # Run as `python -P -m texcc_tools.bench.cycles --worker`: no folder holding a cycles.py
    # is on the module path to shadow Blender's own "cycles" add-on.
    import bpy
    import numpy as np

    def reply(obj):
        channel.write(TAG + json.dumps(obj) + "\n")
        channel.flush()

    def setup(req):
        bpy.ops.wm.open_mainfile(filepath=req["blend"])
        scene = bpy.context.scene
        scene.render.resolution_x, scene.render.resolution_y = req["size"]
        scene.cycles.samples = req["spp"]
        scene.cycles.seed = req.get("seed", 1)
        if req.get("pattern"):  # Cycles' sampling pattern (default: the .blend's, Tabulated Sobol)
            scene.cycles.sampling_pattern = req["pattern"]
        return scene

    read_exr = exr.read_file

    def render(req):
        scene = setup(req)
        if req.get("exr"):
            scene.render.image_settings.file_format = "OPEN_EXR"
            scene.render.image_settings.color_depth = "32"
            scene.render.filepath = req["exr"]
        t0 = time.perf_counter()
        bpy.ops.render.render(write_still=bool(req.get("exr")))
        return {"seconds": time.perf_counter() - t0}

    def mask(req):
        """1 on the model, 0 elsewhere: the model white emission, everything else black."""
        scene = setup(req)
        for obj in scene.objects:
            if obj.type == "LIGHT":
                obj.hide_render = True
        scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
        for obj in scene.objects:
            if obj.type != "MESH":
                continue
            m = bpy.data.materials.new("mask-" + obj.name)
            m.use_nodes = True
            t = m.node_tree
            t.nodes.clear()
            out = t.nodes.new("ShaderNodeOutputMaterial")
            em = t.nodes.new("ShaderNodeEmission")
            em.inputs["Strength"].default_value = 1.0 if obj.name == "model" else 0.0
            t.links.new(em.outputs[0], out.inputs["Surface"])
            obj.data.materials.clear()
            obj.data.materials.append(m)
        scene.render.image_settings.file_format = "OPEN_EXR"
        scene.render.image_settings.color_depth = "32"
        scene.render.filepath = req["exr"]
        bpy.ops.render.render(write_still=True)
        return {}

    def analyze(req):
        """a = Cycles, b = texrender: an image each, or a list of images at different seeds and
        equal spp, whose mean (the image at their summed spp) is compared."""
        a, b = (np.mean([read_exr(p) for p in ([x] if isinstance(x, str) else x)], axis=0)
                for x in (req["a"], req["b"]))
        m = read_exr(req["mask"])[:, :, 0]
        regions = {"model": m >= 0.999, "rest": m <= 0.001, "all": np.ones_like(m, bool)}
        out = {"regions": {}}
        for name, sel in regions.items():
            ma, mb = a[sel].mean(axis=0), b[sel].mean(axis=0)
            out["regions"][name] = {"pixels": int(sel.sum()), "a": ma.tolist(), "b": mb.tolist(),
                                    "relDiffPercent": (100 * (mb / ma - 1)).tolist()}
        try:
            import flip_evaluator
            _, mean, _ = flip_evaluator.evaluate(np.ascontiguousarray(a), np.ascontiguousarray(b),
                                                 "HDR", applyMagma=False)
            out["flip"] = float(mean)
        except ImportError:
            out["flip"] = None
        return out

    def seeds(req):
        """Seed-to-seed spread: RMSE of linear RGB between every pair of images, and the mean
        per-pixel variance across them (unbiased), for each group of images."""
        out = {}
        for name, paths in req["groups"].items():
            imgs = np.stack([read_exr(p) for p in paths])
            pairs = [float(np.sqrt(((imgs[i] - imgs[j]) ** 2).mean()))
                     for i in range(len(imgs)) for j in range(i + 1, len(imgs))]
            out[name] = {"pairRmse": pairs, "meanPairRmse": float(np.mean(pairs)),
                         "meanPixelVariance": float(imgs.var(axis=0, ddof=1).mean()),
                         "mean": imgs.mean(axis=(0, 1, 2)).tolist()}
        return out

    def blocks(req):
        """Issue 22's texture-only check: a = Cycles, b = texrender, both the material's colour
        through Emission with no lights. Per block of req["block"] pixels: the relative
        difference of the block means, |b / a - 1| per channel (the largest channel is the
        block's figure). Blocks compared: those whose every pixel is on the model (mask);
        "smooth" ones are those of them not on a discontinuity of the texture: in neither image
        does the luminance within the block span more than req["edgeRange"] times the block's
        mean luminance (a scratch line or a mask edge inside the block)."""
        a, b = read_exr(req["a"]), read_exr(req["b"])
        m = read_exr(req["mask"])[:, :, 0]
        n = req["block"]
        h, w = (m.shape[0] // n) * n, (m.shape[1] // n) * n

        def tiles(x):
            return x[:h, :w].reshape(h // n, n, w // n, n, -1).swapaxes(1, 2).reshape(
                h // n, w // n, n * n, -1)

        ta, tb, tm = tiles(a), tiles(b), tiles(m[:, :, None])[..., 0]
        on_model = (tm >= 0.999).all(axis=2)
        weights = np.array([0.2126, 0.7152, 0.0722])
        edge = np.zeros_like(on_model)
        for t in (ta, tb):
            lum = t @ weights
            span = lum.max(axis=2) - lum.min(axis=2)
            edge |= span > req["edgeRange"] * np.maximum(lum.mean(axis=2), 1e-6)
        ma, mb = ta.mean(axis=2), tb.mean(axis=2)
        rel = np.abs(mb / np.maximum(ma, 1e-9) - 1).max(axis=2)
        signed = mb / np.maximum(ma, 1e-9) - 1
        out = {"blockPixels": n, "edgeRange": req["edgeRange"],
               "blocks": int(on_model.size), "onModel": int(on_model.sum())}
        for name, sel in (("model", on_model), ("smooth", on_model & ~edge)):
            r = rel[sel]
            if not r.size:
                out[name] = {"blocks": 0}
                continue
            out[name] = {
                "blocks": int(r.size), "maxRelPercent": float(100 * r.max()),
                "p50RelPercent": float(100 * np.percentile(r, 50)),
                "p90RelPercent": float(100 * np.percentile(r, 90)),
                "p99RelPercent": float(100 * np.percentile(r, 99)),
                "fractionWithin1Percent": float((r <= 0.01).mean()),
                "meanSignedPercent": (100 * signed[sel].mean(axis=0)).tolist(),
                "meanA": ma[sel].mean(axis=0).tolist(), "meanB": mb[sel].mean(axis=0).tolist()}
        sel = m >= 0.999
        ma, mb = a[sel].mean(axis=0), b[sel].mean(axis=0)
        out["modelPixels"] = {"pixels": int(sel.sum()), "a": ma.tolist(), "b": mb.tolist(),
                              "relDiffPercent": (100 * (mb / ma - 1)).tolist()}
        if req.get("dump"):
            np.savez(req["dump"], rel=rel, onModel=on_model, edge=edge, ma=ma, mb=mb)
        return out

    def noise(req):
        """Noise against bias per 8x8 block (issue 22, rust's texture-only view): a = Cycles'
        images and b = texrender's at the same N >= 2 seeds (a[i] and b[i] one seed), same spp.
        Per block wholly on the model and smooth in every image (as blocks()): the difference of
        the two renderers' seed-pooled means, d = mean(b) / mean(a) - 1, and its standard error
        se, the spread of the per-seed differences b[i] / a[i] - 1 (ddof 1) over sqrt(N); per
        channel, the block's figure its largest |d| channel. Also each renderer's seed-to-seed
        spread |x[0] / x[1] - 1| (first two seeds)."""
        imgs = {r: [read_exr(p) for p in req[r]] for r in ("a", "b")}
        if len(imgs["a"]) != len(imgs["b"]) or len(imgs["a"]) < 2:
            raise ValueError("noise: a and b need the same number of images, at least 2")
        m = read_exr(req["mask"])[:, :, 0]
        n = req["block"]
        h, w = (m.shape[0] // n) * n, (m.shape[1] // n) * n

        def tiles(x):
            return x[:h, :w].reshape(h // n, n, w // n, n, -1).swapaxes(1, 2).reshape(
                h // n, w // n, n * n, -1)

        t = {r: [tiles(v[:, :, :3]) for v in xs] for r, xs in imgs.items()}
        on_model = (tiles(m[:, :, None])[..., 0] >= 0.999).all(axis=2)
        weights = np.array([0.2126, 0.7152, 0.0722])
        edge = np.zeros_like(on_model)
        for x in t["a"] + t["b"]:
            lum = x @ weights
            edge |= (lum.max(axis=2) - lum.min(axis=2)) > req["edgeRange"] * np.maximum(
                lum.mean(axis=2), 1e-6)
        mm = {r: np.stack([x.mean(axis=2) for x in xs]) for r, xs in t.items()}
        ma = np.maximum(mm["a"], 1e-9)
        d = mm["b"].mean(axis=0) / ma.mean(axis=0) - 1
        per_seed = mm["b"] / ma - 1
        e = per_seed.std(axis=0, ddof=1) / np.sqrt(len(per_seed))
        ch = np.abs(d).argmax(axis=2)
        pick = (lambda x: np.take_along_axis(x, ch[..., None], axis=2)[..., 0])
        dd, ee = pick(d), pick(e)
        out = {"blockPixels": n, "edgeRange": req["edgeRange"], "seedCount": len(per_seed)}
        for name, sel in (("model", on_model), ("smooth", on_model & ~edge)):
            ad, ae = np.abs(dd[sel]), ee[sel]
            seed = {r: np.abs(mm[r][0] / np.maximum(mm[r][1], 1e-9) - 1).max(axis=2)[sel]
                    for r in ("a", "b")}
            rows = np.argwhere(sel)
            worst = np.argsort(-ad)[:12]
            out[name] = {
                "blocks": int(ad.size),
                "diffMaxPercent": float(100 * ad.max()),
                "diffP50Percent": float(100 * np.percentile(ad, 50)),
                "diffP90Percent": float(100 * np.percentile(ad, 90)),
                "within1Percent": float((ad <= 0.01).mean()),
                "noiseP50Percent": float(100 * np.percentile(ae, 50)),
                "noiseP90Percent": float(100 * np.percentile(ae, 90)),
                "noiseMaxPercent": float(100 * ae.max()),
                "beyond3Sigma": int((ad > 3 * ae).sum()),
                "beyond1PercentAnd3Sigma": int(((ad > 0.01) & (ad > 3 * ae)).sum()),
                "cyclesSeedToSeedP50Percent": float(100 * np.percentile(seed["a"], 50)),
                "cyclesSeedToSeedMaxPercent": float(100 * seed["a"].max()),
                "texrenderSeedToSeedP50Percent": float(100 * np.percentile(seed["b"], 50)),
                "texrenderSeedToSeedMaxPercent": float(100 * seed["b"].max()),
                "worst": [{"block": [int(rows[i][0]), int(rows[i][1])],
                           "diffPercent": float(100 * dd[sel][i]),
                           "noisePercent": float(100 * ae[i]),
                           "cyclesMean": mm["a"].mean(axis=0)[tuple(rows[i])].tolist()}
                          for i in worst]}
        return out

    ops = {"render": render, "mask": mask, "analyze": analyze, "seeds": seeds, "blocks": blocks,
           "noise": noise}
    reply({"ready": bpy.app.version_string})
    for line in sys.stdin:
        req = json.loads(line)
        try:
            reply(ops[req["op"]](req))
        except Exception as e:  # reported to the driver, which raises BenchError
            reply({"error": "%s: %s" % (type(e).__name__, e)})


class Cycles:
    """The driver's handle on one warm bpy process."""

    def __init__(self):
        if not os.path.exists(VENV_PYTHON):
            raise common.BenchError("%s missing: python3 -m venv .venv && .venv/bin/pip install "
                                    "-r scripts/requirements-blender.txt" % VENV_PYTHON)
        self.p = subprocess.Popen([VENV_PYTHON, "-P", "-m", "texcc_tools.bench.cycles",
                                   "--worker"],
                                  stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        self.version = self._read()["ready"]

    def _read(self):
        for line in self.p.stdout:
            if line.startswith(TAG):
                r = json.loads(line[len(TAG):])
                if "error" in r:
                    raise common.BenchError("cycles worker: " + r["error"])
                return r
        raise common.BenchError("cycles worker exited (exit %s)" % self.p.wait())

    def call(self, **req):
        self.p.stdin.write(json.dumps(req) + "\n")
        self.p.stdin.flush()
        return self._read()

    def close(self):
        self.p.stdin.close()
        self.p.wait()


# --- The driver ----------------------------------------------------------------------------------

def ensure_bpy():
    """bpy (scripts/requirements-blender.txt, the one pin) and flip-evaluator in .venv."""
    from texcc_tools.bpy_env import REQUIREMENTS
    r = subprocess.run([VENV_PYTHON, "-c", "import bpy, flip_evaluator"], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE) if os.path.exists(VENV_PYTHON) else None
    if r is None or r.returncode != 0:
        common.log("installing %s and flip-evaluator into .venv (about 370 MB)" % REQUIREMENTS)
        if not os.path.exists(VENV_PYTHON):
            common.run([sys.executable, "-m", "venv", os.path.join(common.ROOT, ".venv")])
        common.run([VENV_PYTHON, "-m", "pip", "install", "-r", REQUIREMENTS, "-r",
                    os.path.join(common.ROOT, "bench", "requirements.txt")])


def make_blends(tools, variants=VARIANTS, extra=(), tag=""):
    out = {}
    for v in variants:
        out[v] = os.path.join(tools.work, "atrium-%s%s.blend" % (v, tag))
        common.run([VENV_PYTHON, MAKE_SCENE, out[v], "--variant", v] + list(extra))
    return out


def texrender_inputs(tools):
    """{variant: (scene path, textures folder)}: texcc once per graph (default mode)."""
    out, folders = {}, {}
    for v, (graph, scene, everywhere) in TEXRENDER.items():
        if graph not in folders:
            folders[graph] = os.path.join(tools.work, "tex-" + os.path.basename(os.path.dirname(graph)))
            common.run([tools.texcc, "--graph", os.path.join(common.ROOT, graph), "-o",
                        folders[graph]])
        path = os.path.join(common.ROOT, scene)
        if everywhere:
            with open(path) as f:
                s = json.load(f)
            for mesh in s["meshes"]:
                mesh["material"] = everywhere
                mesh["obj"] = os.path.join(os.path.dirname(path), mesh["obj"])
            path = os.path.join(tools.work, "atrium-%s.json" % v)
            with open(path, "w") as f:
                json.dump(s, f, indent=1)
        out[v] = (path, folders[graph])
    return out


def texrender_once(tools, inputs, variant, trace, size, spp, name, exr=False, seed=None):
    scene, textures = inputs[variant]
    opts = ["--size", size, "--spp", str(spp), "--trace=" + trace]
    if seed is not None:
        opts += ["--seed", str(seed)]
    stats, img, wall = common.texrender(tools, scene, textures, name, opts,
                                        image="exr" if exr else "png")
    k = stats["kernels"]
    return {"frame": stats["renderSeconds"], "total": stats["totalSeconds"], "wall": wall,
            "trace": stats["trace"], "bvhBuildSeconds": stats["bvhBuildSeconds"],
            "stages": {n: k[n]["seconds"] for n in k},
            "textureSeconds": common.texture_kernel_seconds(stats)}, img


def frame_times(tools, cyc, blends, inputs, size, spps, reps, checkpoint, variants, renderers):
    w, h = (int(x) for x in size.split("x"))
    configs = [(v, r) for v in variants for r in renderers]
    runs = {str(spp): {"%s/%s" % c: [] for c in configs} for spp in spps}
    loads = []
    fixed = {v: [] for v in variants}
    for v in variants:  # warm: kernels built, caches filled; Cycles' fixed part (sync + BVH)
        for r in renderers:
            if r == "cycles":
                continue
            texrender_once(tools, inputs, v, r.split("-")[1], size, 1, "warm")
        cyc.call(op="render", blend=blends[v], size=[w, h], spp=1)
        for _ in range(3):
            fixed[v].append(cyc.call(op="render", blend=blends[v], size=[16, 16],
                                     spp=1)["seconds"])
    fixed = {v: common.median(f) for v, f in fixed.items()}
    for spp in spps:
        for rep in range(reps):
            k = rep % len(configs)
            for v, r in configs[k:] + configs[:k]:
                common.log("cycles figure: %d spp rep %d/%d %s %s" % (spp, rep + 1, reps, v, r))
                loads.append(os.getloadavg()[0])
                if r == "cycles":
                    s = cyc.call(op="render", blend=blends[v], size=[w, h], spp=spp)
                    sample = {"render": s["seconds"]}
                else:
                    sample, _ = texrender_once(tools, inputs, v, r.split("-")[1], size, spp,
                                               "cy-%s-%s" % (v, r))
                runs[str(spp)]["%s/%s" % (v, r)].append(sample)
            done = {k2: v2 for k2, v2 in runs.items() if all(v2.values())}
            checkpoint(done, fixed, loads)
    return runs, fixed, loads


def summarize(runs, fixed):
    table = []
    if not runs:
        return table
    for spp, cfgs in runs.items():
        for r in RENDERERS:
            if "diffuse/" + r not in cfgs:
                continue
            key = "render" if r == "cycles" else "frame"
            base = [s[key] for s in cfgs["diffuse/" + r]]
            for v in VARIANTS:
                if "%s/%s" % (v, r) not in cfgs:
                    continue
                times = [s[key] for s in cfgs["%s/%s" % (v, r)]]
                row = {"spp": int(spp), "renderer": r, "variant": v,
                       "median": common.median(times), "raw": times,
                       "overheadPercent": 100 * (common.median(
                           [t / b for t, b in zip(times, base)]) - 1)}
                if r == "cycles":
                    row["fixedSeconds"] = fixed[v]
                    row["medianWithoutFixed"] = row["median"] - fixed[v]
                else:
                    samples = cfgs["%s/%s" % (v, r)]
                    row["medianTotal"] = common.median([s["total"] for s in samples])
                    row["trace"] = samples[0]["trace"]
                    row["bvhBuildSeconds"] = samples[0]["bvhBuildSeconds"]
                    stages = samples[0]["stages"].keys()
                    row["stages"] = {n: common.median([s["stages"][n] for s in samples])
                                     for n in stages}
                table.append(row)
    # texrender over Cycles, ratio of medians (frame against render() less the fixed part, and
    # texrender's whole process against Cycles' whole render())
    for row in table:
        if row["renderer"] == "cycles":
            continue
        c = next(x for x in table if x["renderer"] == "cycles" and x["spp"] == row["spp"]
                 and x["variant"] == row["variant"])
        row["overCyclesFrame"] = row["median"] / c["medianWithoutFixed"]
        row["overCyclesRender"] = row["median"] / c["median"]
    return table


def exported(tools, blend, name):
    """texrender's side of a Blender variant through engineer E's exporter: (scene, textures)."""
    out = os.path.join(tools.work, "export-" + name)
    common.run([VENV_PYTHON, os.path.join(common.ROOT, "scripts", "blender_export.py"), blend,
                "-o", out])
    common.run([tools.texcc, "--graph", os.path.join(out, "graph.json"), "-o", out + "-tex"])
    return os.path.join(out, "scene.json"), out + "-tex"


def agreement(tools, cyc, blends, inputs, size, spp, which=("diffuse",), seeds=(1,)):
    """which: variants; diffuse uses texrender's own scene, the others the scene and graph the
    exporter (scripts/blender_export.py) makes from the same .blend Cycles renders. seeds: each
    renderer renders each seed at spp, and the mean of its images is compared (a converged image
    at len(seeds) x spp, made of independent runs)."""
    w, h = (int(x) for x in size.split("x"))
    mask = os.path.join(tools.work, "agree-mask.exr")
    cyc.call(op="mask", blend=blends["diffuse"], size=[w, h], spp=16, exr=mask)
    out = {}
    for v in which:
        ca, tb, ct, tt = [], [], [], []
        try:
            own = dict(inputs)
            if v != "diffuse":
                own[v] = exported(tools, blends[v], v)
            for seed in seeds:
                ca.append(os.path.join(tools.work, "agree-cycles-%s-%d.exr" % (v, seed)))
                ct.append(cyc.call(op="render", blend=blends[v], size=[w, h], spp=spp,
                                   seed=seed, exr=ca[-1])["seconds"])
                r, texr = texrender_once(tools, own, v, "auto", size, spp,
                                         "agree-%s-%d" % (v, seed), exr=True, seed=seed)
                tb.append(texr)
                tt.append(r["frame"])
                common.log("agreement %s: seed %d done" % (v, seed))
        except common.BenchError as e:  # e.g. a node texcc does not have yet: say so, go on
            out[v] = {"error": str(e).strip().splitlines()[-1][-300:]}
            common.log("agreement %s: %s" % (v, out[v]["error"]))
            continue
        res = cyc.call(op="analyze", a=ca, b=tb, mask=mask)
        res.update({"cyclesSeconds": sum(ct), "texrenderSeconds": sum(tt), "size": size,
                    "spp": spp * len(seeds), "seeds": list(seeds),
                    "texrenderInput": "texrender's own scene" if v == "diffuse"
                    else "exported by scripts/blender_export.py"})
        out[v] = res
    return out


def seed_list(text):
    """--noise-seed's value: "2", "2,3,4" or "2-16"."""
    out = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        if int(hi or lo) < int(lo):
            raise ValueError("empty range %s" % part)
        out += range(int(lo), int(hi or lo) + 1)
    if len(set(out)) != len(out):
        raise ValueError("a seed twice in %s" % text)
    return out


def seed_spread(tools, cyc, blends, inputs, size, spp, n):
    """Issue 26: n seeds of the diffuse atrium per renderer at equal spp; RMSE between seeds."""
    w, h = (int(x) for x in size.split("x"))
    groups = {"cycles": [], "texrender-auto": []}
    times = {"cycles": [], "texrender-auto": []}
    for seed in range(1, n + 1):
        exr = os.path.join(tools.work, "seed-cycles-%d.exr" % seed)
        times["cycles"].append(cyc.call(op="render", blend=blends["diffuse"], size=[w, h],
                                        spp=spp, seed=seed, exr=exr)["seconds"])
        groups["cycles"].append(exr)
        r, img = texrender_once(tools, inputs, "diffuse", "auto", size, spp,
                                "seed-tr-%d" % seed, exr=True, seed=seed)
        times["texrender-auto"].append(r["frame"])
        groups["texrender-auto"].append(img)
        common.log("seeds: %d/%d" % (seed, n))
    res = cyc.call(op="seeds", groups=groups)
    for k in res:
        res[k]["seconds"] = times[k]
    return {"size": size, "spp": spp, "seeds": n, "results": res,
            "varianceRatioTexrenderOverCycles": res["texrender-auto"]["meanPixelVariance"] /
            res["cycles"]["meanPixelVariance"], "loadAverage": os.getloadavg()}


CHECKPOINTS = True  # bench.py passes a checkpoint callback


def measure(tools, quick, save=None, size=None, spps=None, reps=None, agree_size=None,
            agree_spp=None, agree=True, variants=VARIANTS, renderers=RENDERERS,
            agree_variants=("diffuse",), seeds=None, agree_seeds=(1,)):
    """save(data) is called after every repetition with what is measured so far."""
    ensure_bpy()
    size = size or ("128x128" if quick else "512x512")
    spps = spps or ([1, 4] if quick else [1, 16])
    reps = (2 if quick else 5) if reps is None else reps
    blends = make_blends(tools, [v for v in VARIANTS if v in variants or v == "diffuse" or
                                 (agree and v in agree_variants)])
    inputs = texrender_inputs(tools)
    cyc = Cycles()
    data = {"size": size, "spps": spps, "repetitions": reps, "cyclesVersion": cyc.version,
            "maxDepth": 4, "cyclesMaxBounces": 2, "loadAverageBefore": os.getloadavg()}
    try:
        if agree:
            asize = agree_size or ("64x64" if quick else "256x256")
            aspp = agree_spp or (16 if quick else 256)
            data["agreement"] = {"size": asize, "spp": aspp, "loadAverage": os.getloadavg(),
                                 "results": agreement(tools, cyc, blends, inputs, asize, aspp,
                                                      agree_variants, agree_seeds)}

        def checkpoint(runs, fixed, loads):
            data.update({"cyclesFixedSeconds": fixed, "rows": summarize(runs, fixed),
                         "runs": runs, "loadAverage1min": loads,
                         "loadAverageAfter": os.getloadavg()})
            if save:
                save(dict(data))

        if seeds:
            data["seedSpread"] = seed_spread(tools, cyc, blends, inputs, seeds[0], seeds[1],
                                             seeds[2])
        if reps > 0:
            runs, fixed, loads = frame_times(tools, cyc, blends, inputs, size, spps, reps,
                                             checkpoint, variants, renderers)
            checkpoint(runs, fixed, loads)
    finally:
        cyc.close()
    return data


def main():
    from texcc_tools.bench.cycles_lamps import LAMP_CASES, WORLD_BLEND, WORLD_CASES, lamp_figure
    from texcc_tools.bench.cycles_texture_only import TEXTURE_ONLY_VARIANTS, texture_only

    import argparse
    import tempfile
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true")
    common.add_build_argument(ap)
    ap.add_argument("--reps", type=int)
    ap.add_argument("--size")
    ap.add_argument("--spp", help="comma-separated, e.g. 1,16")
    ap.add_argument("--agree-size")
    ap.add_argument("--agree-spp", type=int)
    ap.add_argument("--no-agree", action="store_true")
    ap.add_argument("--seeds", help="SIZE,SPP,N: also the seed-to-seed spread of the diffuse "
                    "atrium (issue 26), e.g. 256x256,64,4; --reps 0 skips the frame times")
    ap.add_argument("--agree-seeds", type=seed_list, default=[1],
                    help="the image agreement at these seeds (N,M,... or N-M), each at "
                    "--agree-spp: each renderer's mean image is compared (default 1)")
    ap.add_argument("--agree-variants", default="diffuse",
                    help="variants of the image agreement; other than diffuse, texrender renders "
                    "what scripts/blender_export.py exports from the same .blend")
    ap.add_argument("--variants", default=",".join(VARIANTS),
                    help="subset of %s (diffuse is needed for the overheads)" % ",".join(VARIANTS))
    ap.add_argument("--renderers", default=",".join(RENDERERS))
    ap.add_argument("--merge", action="store_true",
                    help="add these rows to bench/results/cycles.json (replacing its rows of the "
                    "same spp, variant and renderer), e.g. a second run at another spp with a "
                    "subset")
    ap.add_argument("--out", help="result file (default bench/results/cycles.json)")
    ap.add_argument("--texture-only", action="store_true",
                    help="only issue 22's texture-only check (rust-model and scratches-model: "
                    "the material colour through Emission, no lights; 8x8-block agreement) at "
                    "--agree-size (default 256x256) and --agree-spp (default 128); "
                    "--agree-variants picks one of them, --merge replaces only its results; "
                    "results in bench/results/cycles_texture_only.json")
    ap.add_argument("--seed", type=int, default=1,
                    help="with --texture-only: both renderers' seed (default 1)")
    ap.add_argument("--noise-seed", type=seed_list, default=(),
                    help="with --texture-only: both renderers also at these seeds (N, N,M,... "
                    "or N-M); per block, the renderers' seed-pooled difference against its "
                    "standard error from the seed-to-seed spread (results' \"noise\")")
    ap.add_argument("--cycles-pattern", choices=("TABULATED_SOBOL", "BLUE_NOISE"),
                    help="with --texture-only: Cycles' sampling pattern (default: the .blend's, "
                    "Tabulated Sobol)")
    ap.add_argument("--texture-probe", choices=("ao", "ao-squared", "constant-ao"),
                    help="with --texture-only, rust-model: the AO node's output alone (ao), its "
                    "square (ao-squared) or the colour with AO replaced by a constant 0.5 (constant-ao); bisects issue 22's "
                    "rust blocks (make_scene.py --texture-probe)")
    ap.add_argument("--lamps", action="store_true",
                    help="only issue 37's lamp figure (testsuite/Inputs/blender-export/"
                    "make_lamp_blend.py's cases through the exporter) at --agree-size (default "
                    "128x96) and --agree-spp (default 256) over --agree-seeds; --lamp-cases "
                    "picks cases, --merge replaces only theirs; results in "
                    "bench/results/cycles_lamps.json (needs numpy: run it with .venv/bin/python)")
    ap.add_argument("--lamp-cases", default=",".join(LAMP_CASES))
    ap.add_argument("--env", action="store_true",
                    help="only issue 37's HDR world figure (testsuite/Inputs/blender-export/"
                    "make_world_blend.py's cases: an Environment Texture of a script-made EXR "
                    "with a sun and a gradient over a diffuse and a glossy object, and the same "
                    "rotated through a Mapping node) as --lamps measures its lamps; --env-cases "
                    "picks cases; results in bench/results/cycles_env.json")
    ap.add_argument("--env-cases", default=",".join(WORLD_CASES))
    args = ap.parse_args()
    if args.lamps or args.env:
        ensure_bpy()
        tools = common.Tools(os.path.abspath(args.build), tempfile.mkdtemp(prefix="texcc-lamps-"))
        t0, load0 = time.perf_counter(), os.getloadavg()
        data = {"size": args.agree_size or "128x96", "spp": args.agree_spp or 256,
                "seeds": list(args.agree_seeds)}
        if args.env:
            data["results"] = lamp_figure(tools, data["size"], data["spp"], data["seeds"],
                                          args.env_cases.split(","), maker=WORLD_BLEND,
                                          prefix="world")
        else:
            data["results"] = lamp_figure(tools, data["size"], data["spp"], data["seeds"],
                                          args.lamp_cases.split(","))
        data.update({"seconds": time.perf_counter() - t0, "git": common.git_head(),
                     "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                     "machine": common.machine(), "loadAverageBefore": load0,
                     "loadAverageAfter": os.getloadavg(),
                     "command": ".venv/bin/python bench/cycles.py " + " ".join(sys.argv[1:])})
        for r in data["results"].values():  # each case says which run measured it
            r["run"] = {k: data[k] for k in ("size", "spp", "seeds", "git", "date", "command",
                                             "loadAverageBefore", "loadAverageAfter")}
        name = "cycles_env" if args.env else "cycles_lamps"
        old = common.load(name) if args.merge else None
        if old:  # --merge: these cases replace theirs
            old["results"].update(data["results"])
            data = old
        common.save(name, data, args.out)
        return
    if args.seed in args.noise_seed:
        ap.error("--noise-seed must not repeat --seed (%d)" % args.seed)
    variants, renderers = args.variants.split(","), args.renderers.split(",")
    if "diffuse" not in variants or not set(variants) <= set(VARIANTS) or \
            not set(renderers) <= set(RENDERERS):
        ap.error("--variants must include diffuse; names from %s and %s" % (VARIANTS, RENDERERS))
    tools = common.Tools(os.path.abspath(args.build), tempfile.mkdtemp(prefix="texcc-cycles-"))
    t0 = time.perf_counter()
    if args.texture_only:
        ensure_bpy()
        which = [v for v in args.agree_variants.split(",") if v != "diffuse"] or \
            list(TEXTURE_ONLY_VARIANTS)
        data = texture_only(tools, args.agree_size or "256x256", args.agree_spp or 128, which,
                            seed=args.seed, noise_seeds=args.noise_seed,
                            probe=args.texture_probe, pattern=args.cycles_pattern)
        data.update({"seconds": time.perf_counter() - t0, "git": common.git_head(),
                     "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                     "machine": common.machine(), "build": os.path.relpath(tools.build,
                                                                           common.ROOT),
                     "command": "python3 bench/cycles.py " + " ".join(sys.argv[1:])})
        old = common.load("cycles_texture_only") if args.merge else None
        if old:  # --merge: these variants replace theirs, each with its own run's details
            for v in data["results"]:
                data["results"][v]["run"] = {k: data[k] for k in (
                    "size", "spp", "git", "date", "command", "loadAverageBefore",
                    "loadAverageAfter")}
            old["results"].update(data["results"])
            data = old
        common.save("cycles_texture_only", data, args.out)
        return
    base = common.load("cycles") if args.merge else None

    def save(data, complete=False):
        """Every row carries the run that measured it ("run"); with --merge, this run's rows
        replace only the base's rows of the same spp, variant and renderer."""
        run = {"command": "python3 bench/cycles.py " + " ".join(sys.argv[1:]),
               "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
               "git": common.git_head(), "complete": complete}
        run.update({k: data.get(k) for k in ("size", "repetitions", "loadAverage1min")})
        for r in data.get("rows", []):
            r["run"] = run
        for r in (data.get("agreement") or {}).get("results", {}).values():
            r["run"] = {k: run[k] for k in ("command", "date", "git")}
        if base:
            key = (lambda r: (r["spp"], r["variant"], r["renderer"]))
            new = {key(r) for r in data.get("rows", [])}
            merged = dict(base)
            merged["rows"] = [r for r in base["rows"] if key(r) not in new] + data.get("rows", [])
            br, dr = base.get("runs", {}), data.get("runs", {})
            merged["runs"] = {spp: dict(br.get(spp, {}), **dr.get(spp, {}))
                              for spp in set(br) | set(dr)}
            if data.get("agreement"):
                ag = dict(base.get("agreement") or {"results": {}})
                ag["results"] = dict(ag["results"], **data["agreement"]["results"])
                merged["agreement"] = ag
            if data.get("seedSpread"):
                merged["seedSpread"] = dict(data["seedSpread"], command=run["command"],
                                            date=run["date"])
            merged["spps"] = sorted({r["spp"] for r in merged["rows"]})
            merged.pop("parts", None)  # the rows' "run" says it now
            common.save("cycles", merged, args.out)
            return
        data.update({"complete": complete, "quick": args.quick,
                     "seconds": time.perf_counter() - t0, "date": run["date"],
                     "machine": common.machine(), "git": run["git"],
                     "loadAverage": os.getloadavg()[1], "build": os.path.relpath(
                         tools.build, common.ROOT), "command": run["command"]})
        common.save("cycles", data, args.out)

    data = measure(tools, args.quick, save, args.size,
                   [int(s) for s in args.spp.split(",")] if args.spp else None, args.reps,
                   args.agree_size, args.agree_spp, not args.no_agree, variants, renderers,
                   args.agree_variants.split(","),
                   (lambda a: (a[0], int(a[1]), int(a[2])))(args.seeds.split(","))
                   if args.seeds else None, args.agree_seeds)
    save(data, True)


def run():
    """bench/cycles.py's entry point; --worker is the bpy worker (python -P -m ...)."""
    if sys.argv[1:2] == ["--worker"]:
        worker()
    else:
        try:
            main()
        except common.BenchError as e:
            sys.exit("bench/cycles.py: error: %s" % e)


if __name__ == "__main__":
    run()
