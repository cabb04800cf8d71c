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
        if "RGB" in channels:
            return np.array(channels["RGB"].pixels, dtype=np.float32)[:, :, :3]
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
