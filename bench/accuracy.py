"""Figure 4: speed against accuracy on the atrium with rust. A converged reference (interp,
many samples per pixel and AO rays) is rendered once; then, per mode, a sweep over samples per
pixel and AO rays per hit records the frame time (texrender renderSeconds, median over the
repetitions) and the error against the reference: RMSE of linear radiance and mean FLIP (HDR,
flip-evaluator) when it is installed."""
import os

import numpy as np

import common

GRAPH = os.path.join(common.ROOT, "examples", "rust", "graph.json")
SCENE = os.path.join(common.ROOT, "examples", "atrium", "scene.json")


def read_exr(path):
    """Linear RGB of texrender's EXR (OpenEXR's Python bindings, bench/requirements.txt)."""
    import OpenEXR
    with OpenEXR.File(path) as f:
        channels = f.channels()
        for name in ("RGB", "RGBA"):  # texrender's; Blender's
            if name in channels:
                return np.array(channels[name].pixels, dtype=np.float32)[:, :, :3]
        return np.stack([np.array(channels[c].pixels, dtype=np.float32) for c in "RGB"], axis=-1)


def flip_error(ref, img):
    try:
        import flip_evaluator
    except ImportError:
        return None
    _, mean, _ = flip_evaluator.evaluate(ref, img, "HDR", applyMagma=False)
    return float(mean)


def settings(quick):
    if quick:
        return {"size": "64x64", "refSpp": 64, "refAo": 16, "spp": (1, 4, 16), "ao": (2, 8),
                "reps": 2}
    return {"size": "128x128", "refSpp": 1024, "refAo": 64, "spp": (1, 2, 4, 8, 16, 32, 64),
            "ao": (1, 2, 4, 8, 16), "reps": 3}


def measure(tools, quick):
    cfg = settings(quick)
    folders = {}
    for mode in common.MODES:
        folders[mode] = os.path.join(tools.work, "acc-%s" % mode)
        common.texcc(tools, GRAPH, folders[mode], mode)
    common.log("accuracy reference %s spp, %s AO rays" % (cfg["refSpp"], cfg["refAo"]))
    ref_stats, ref_path, _ = common.texrender(
        tools, SCENE, folders["interp"], "acc-ref",
        ["--size", cfg["size"], "--spp", str(cfg["refSpp"]), "--ao-samples", str(cfg["refAo"]),
         "--seed", "7"], image="exr")
    ref = read_exr(ref_path)
    points = []
    for spp in cfg["spp"]:
        for ao in cfg["ao"]:
            for mode in common.MODES:
                points.append(one_point(tools, cfg, folders[mode], mode, spp, ao, ref))
    try:
        import flip_evaluator  # noqa: F401
        flip_note = "flip-evaluator installed"
    except ImportError:
        flip_note = "flip-evaluator is not installed: FLIP not measured"
    return {"size": cfg["size"], "reference": {"spp": cfg["refSpp"], "aoSamples": cfg["refAo"],
                                               "renderSeconds": ref_stats["renderSeconds"]},
            "repetitions": cfg["reps"], "points": points, "flip": flip_note}


def one_point(tools, cfg, folder, mode, spp, ao, ref):
    common.log("accuracy %s spp=%d ao=%d" % (mode, spp, ao))
    times, img = [], None
    for rep in range(cfg["reps"]):
        stats, path, _ = common.texrender(
            tools, SCENE, folder, "acc-%s-%d-%d" % (mode, spp, ao),
            ["--size", cfg["size"], "--spp", str(spp), "--ao-samples", str(ao), "--seed", "1"],
            image="exr")
        times.append(stats["renderSeconds"])
        if img is None:
            img = read_exr(path)
    rmse = float(np.sqrt(np.mean((img - ref) ** 2)))
    return {"mode": mode, "spp": spp, "aoSamples": ao, "renderSeconds": common.median(times),
            "rmse": rmse, "flip": flip_error(ref, img)}


# --- The peer (issue 26): texrender's default mode against Cycles at equal spp and equal time ---

PEER_SCENES = {"diffuse": ("bench/inputs/diffuse/graph.json", "examples/atrium/scene-diffuse.json"),
               "rust-model": ("examples/rust/graph.json", "examples/atrium/scene.json")}


def peer_settings(quick):
    if quick:
        return {"size": "32x32", "refSpp": 256, "spp": (1, 4, 16), "reps": 1,
                "scenes": ("diffuse",)}
    return {"size": "128x128", "refSpp": 4096, "spp": (1, 4, 16, 64, 256), "reps": 2,
            "scenes": tuple(PEER_SCENES)}


def sampler_kernels(work, sampler):
    """kernels/ as it is (sampler "sobol"), or with RT_SAMPLER_PCG (the PCG stream of before
    issue 26) put in front of rt_sampling.h; a spec BASE:NAME=VALUE[+NAME=VALUE] also puts
    those bench-only defines in front of shade.cl (sampling.sampler_defines)."""
    import sampling
    base, defines = sampling.sampler_defines(sampler)
    prepend = {"shade.cl": defines} if defines else {}
    if base == "pcg":
        prepend["common/rt_sampling.h"] = "#define RT_SAMPLER_PCG 1\n"
    return common.kernel_variant(work, sampler.replace(":", "-").replace("=", "").replace(
        "+", "-"), prepend)


def reference(path, make):
    """The converged reference at `path` (an EXR outside git), made by make() when missing."""
    if not os.path.exists(path):
        make()
    return read_exr(path)


def measure_peer(tools, quick, refs=None, samplers=("sobol", "pcg"), checkpoint=None,
                 overrides=None):
    """RMSE and HDR-FLIP against a converged reference as a function of spp and of frame time:
    texrender's default mode (interp, Embree on CPU) with its sampler and with the PCG sampler
    of before issue 26, and Cycles (bpy, .venv) on the same scene. Each renderer is measured
    against its own converged image (refSpp samples, seed 1000), so the figures are noise, not
    the small difference between the renderers (reported apart: referenceDifference). The
    repetitions rotate the order of the renderers; seeds 1.. per repetition."""
    import cycles
    cfg = peer_settings(quick)
    cfg.update({k: v for k, v in (overrides or {}).items() if v is not None})
    refs = refs or os.path.join(tools.work, "refs")
    os.makedirs(refs, exist_ok=True)
    w, h = (int(x) for x in cfg["size"].split("x"))
    cyc = cycles.Cycles()
    out = {"size": cfg["size"], "refSpp": cfg["refSpp"], "references": refs,
           "cyclesVersion": cyc.version, "scenes": {}, "loads": []}
    kernels = {s: sampler_kernels(tools.work, s) for s in samplers}
    if "sobol" not in kernels:  # the references: the kernels as they are
        kernels["sobol"] = sampler_kernels(tools.work, "sobol")
    try:
        for scene_name in cfg["scenes"]:
            graph, scene = PEER_SCENES[scene_name]
            scene = os.path.join(common.ROOT, scene)
            tex = os.path.join(tools.work, "peer-tex-" + scene_name)
            common.texcc(tools, os.path.join(common.ROOT, graph), tex, "interp")
            blend = os.path.join(tools.work, "peer-%s.blend" % scene_name)
            common.run([cycles.VENV_PYTHON, cycles.MAKE_SCENE, blend, "--variant", scene_name])

            def tr(sampler, spp, seed, name):
                stats, path, _ = common.texrender(
                    tools, scene, tex, name,
                    ["--size", cfg["size"], "--spp", str(spp), "--seed", str(seed),
                     "--kernels", kernels[sampler]], image="exr",
                    cache=os.path.join(tools.work, "cache-" + sampler))
                return stats["renderSeconds"], path

            def cy(spp, seed, exr):
                return cyc.call(op="render", blend=blend, size=[w, h], spp=spp, seed=seed,
                                exr=exr)["seconds"]

            ref_paths = {"texrender": os.path.join(refs, "ref-%s-texrender-%s-%d.exr" % (
                             scene_name, cfg["size"], cfg["refSpp"])),
                         "cycles": os.path.join(refs, "ref-%s-cycles-%s-%d.exr" % (
                             scene_name, cfg["size"], cfg["refSpp"]))}
            common.log("peer %s: references (%d spp) in %s" % (scene_name, cfg["refSpp"], refs))

            def make_tr_ref():
                _, p = tr("sobol", cfg["refSpp"], 1000, "peer-ref")
                os.replace(p, ref_paths["texrender"])
            ref = {"texrender": reference(ref_paths["texrender"], make_tr_ref),
                   "cycles": reference(ref_paths["cycles"], lambda: cy(
                       cfg["refSpp"], 1000, ref_paths["cycles"]))}
            # Cycles' fixed part (scene sync + BVH): a 16x16, 1 spp render of the same file
            cy(1, 1, None)
            fixed = common.median([cyc.call(op="render", blend=blend, size=[16, 16], spp=1,
                                            seed=1)["seconds"] for _ in range(3)])
            for s in samplers:  # warm kernel caches
                tr(s, 1, 1, "peer-warm-" + s.replace(":", "-"))
            configs = ["texrender-" + s for s in samplers] + ["cycles"]
            points = []
            for spp in cfg["spp"]:
                for rep in range(cfg["reps"]):
                    k = rep % len(configs)
                    for c in configs[k:] + configs[:k]:
                        common.log("peer %s %s spp=%d rep %d" % (scene_name, c, spp, rep + 1))
                        out["loads"].append(os.getloadavg()[0])
                        seed = rep + 1
                        if c == "cycles":
                            exr = os.path.join(tools.work, "peer-cycles.exr")
                            sec = cy(spp, seed, exr)
                            img, r = read_exr(exr), ref["cycles"]
                            sec_frame = sec - fixed
                        else:
                            sec, p = tr(c.split("-", 1)[1], spp, seed,
                                        "peer-" + c.replace(":", "-"))
                            img, r = read_exr(p), ref["texrender"]
                            sec_frame = sec
                        points.append({"renderer": c, "spp": spp, "rep": rep,
                                       "seconds": sec_frame, "rawSeconds": sec,
                                       "rmse": float(np.sqrt(np.mean((img - r) ** 2))),
                                       "flip": flip_error(r, img)})
                    if checkpoint:
                        checkpoint(out)
            diff = float(np.sqrt(np.mean((ref["texrender"] - ref["cycles"]) ** 2)))
            out["scenes"][scene_name] = {
                "cyclesFixedSeconds": fixed, "points": points, "summary": summarize_peer(points),
                "referenceDifference": {"rmse": diff, "flip": flip_error(ref["cycles"],
                                                                         ref["texrender"]),
                                        "meanTexrender": float(ref["texrender"].mean()),
                                        "meanCycles": float(ref["cycles"].mean())}}
            if checkpoint:
                checkpoint(out)
    finally:
        cyc.close()
    return out


def summarize_peer(points):
    """Per renderer and spp: median seconds and the RMS of the RMSE and the mean FLIP over the
    repetitions (independent seeds)."""
    rows = []
    for c in sorted({p["renderer"] for p in points}):
        for spp in sorted({p["spp"] for p in points}):
            ps = [p for p in points if p["renderer"] == c and p["spp"] == spp]
            if not ps:
                continue
            flips = [p["flip"] for p in ps if p["flip"] is not None]
            rows.append({"renderer": c, "spp": spp,
                         "seconds": common.median([p["seconds"] for p in ps]),
                         "rmse": float(np.sqrt(np.mean([p["rmse"] ** 2 for p in ps]))),
                         "flip": float(np.mean(flips)) if flips else None, "n": len(ps)})
    return rows


def main():
    import argparse
    import json
    import sys
    ap = argparse.ArgumentParser(description="bench/accuracy.py --peer: texrender against "
                                 "Cycles, error against a converged reference")
    ap.add_argument("--peer", action="store_true", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--work", default="/tmp/texcc-accuracy-peer")
    ap.add_argument("--refs", default=None, help="folder of the reference EXRs (kept, reused)")
    ap.add_argument("--samplers", default="sobol,pcg",
                    help="texrender's samplers: sobol, pcg, or BASE:NAME=VALUE[+...] with "
                    "bench-only shade.cl defines")
    ap.add_argument("--size", help="film size (default 128x128)")
    ap.add_argument("--ref-spp", type=int, help="the references' spp (default 4096)")
    ap.add_argument("--spp", help="comma-separated spp of the sweep (default 1,4,16,64,256)")
    ap.add_argument("--reps", type=int, help="repetitions (seeds 1..) per point (default 2)")
    ap.add_argument("--scenes", help="comma-separated, of: " + ",".join(PEER_SCENES))
    ap.add_argument("--json", default=os.path.join(common.ROOT, "bench", "results",
                                                   "accuracy_peer.json"))
    args = ap.parse_args()
    tools = common.Tools(args.build, args.work)

    def save(obj):
        with open(args.json, "w") as f:
            json.dump(obj, f, indent=1)
    overrides = {"size": args.size, "refSpp": args.ref_spp, "reps": args.reps,
                 "spp": tuple(int(x) for x in args.spp.split(",")) if args.spp else None,
                 "scenes": tuple(args.scenes.split(",")) if args.scenes else None}
    result = measure_peer(tools, args.quick, args.refs, tuple(args.samplers.split(",")), save,
                          overrides)
    result["machine"] = common.machine()
    save(result)
    for name, s in result["scenes"].items():
        for row in s["summary"]:
            print("%-10s %-16s spp %4d  %7.3f s  RMSE %.5f  FLIP %s" % (
                name, row["renderer"], row["spp"], row["seconds"], row["rmse"],
                common.fmt(row["flip"])), file=sys.stdout)


if __name__ == "__main__":
    main()
