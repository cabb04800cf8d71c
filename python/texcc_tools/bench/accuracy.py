"""Figure 4: speed against accuracy on the atrium with rust. A converged reference (interp,
many samples per pixel and AO rays) is rendered once; then, per mode, a sweep over samples per
pixel and AO rays per hit records the frame time (texrender renderSeconds, median over the
repetitions) and the error against the reference: RMSE of linear radiance and mean FLIP (HDR,
flip-evaluator) when it is installed."""
import os

import numpy as np

from texcc_tools import exr
from texcc_tools.bench import common

GRAPH = os.path.join(common.ROOT, "examples", "rust", "graph.json")
SCENE = os.path.join(common.ROOT, "examples", "atrium", "scene.json")


def read_exr(path):
    """Linear RGB of texrender's EXR, or Blender's (texcc_tools.exr)."""
    return exr.read_file(path)


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
    from texcc_tools.bench import sampling
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


def children_cpu():
    """User + system CPU seconds of this process's finished children (every thread)."""
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def process_cpu(pid):
    """User + system CPU seconds so far of a live process, all its threads (/proc/PID/stat):
    the warm bpy worker, which renders with Cycles' threads in its own process."""
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def reps_at(cfg, spp):
    """Repetitions at spp: cfg["repsAt"] {spp: n} where given, else cfg["reps"]."""
    return (cfg.get("repsAt") or {}).get(spp, cfg["reps"])


def fixed_parts(tr, cy, samplers, reps=3):
    """Each renderer's fixed part: the median (of reps) CPU and wall time of a 16x16, 1 spp
    render of the scene, after a warm-up render (Cycles: the scene's .blend loaded; texrender:
    its program caches filled). tr and cy are measure_peer's render functions. With reps > 1
    the renderers take turns, the order rotating with the repetition. Returns {config: {cpu,
    wall, seconds}} (medians) with the samples under "samples"."""
    configs = ["texrender-" + s for s in samplers] + ["cycles"]
    cy(1, 1, None)
    for s in samplers:
        tr(s, 1, 1, "peer-warm-" + s.replace(":", "-"))
    runs = {c: [] for c in configs}
    for rep in range(reps):
        k = rep % len(configs)
        for c in configs[k:] + configs[:k]:
            runs[c].append(cy(1, 1, None, [16, 16]) if c == "cycles" else
                           tr(c.split("-", 1)[1], 1, 1, "peer-fixed", "16x16")[0])
    fixed = {}
    for c, fs in runs.items():
        fixed[c] = {k: common.median([f[k] for f in fs]) for k in fs[0]}
        fixed[c]["samples"] = fs
    return fixed


def measure_peer(tools, quick, refs=None, samplers=("sobol", "pcg"), checkpoint=None,
                 overrides=None, fixed_only=0):
    """RMSE and HDR-FLIP against a converged reference as a function of spp and of frame time:
    texrender's default mode (interp, Embree on CPU) with its sampler and with the PCG sampler
    of before issue 26, and Cycles (bpy, .venv) on the same scene. Each renderer is measured
    against its own converged image (refSpp samples, seed 1000), so the figures are noise, not
    the small difference between the renderers (reported apart: referenceDifference). The
    repetitions rotate the order of the renderers; seeds 1.. per repetition.

    The time axis is CPU time (user + system, all threads) of the renderer's process, which
    depends far less on the shared machine's load than wall time: texrender's from
    getrusage(RUSAGE_CHILDREN) around its process (warm texcc and PoCL kernel caches), Cycles'
    from /proc of the warm bpy worker around bpy.ops.render.render(). Each renderer's fixed
    part (texrender: process start, OpenCL set-up, kernels from the cache, BVH; Cycles: scene
    sync and BVH) is the median CPU time of three 16x16, 1 spp renders of the same scene and is
    subtracted: "cpu" is the frame's CPU time, "cpuTotal" the whole. Wall times are kept
    beside (texrender's renderSeconds and process wall, Cycles' render call)."""
    from texcc_tools.bench import cycles
    cfg = peer_settings(quick)
    cfg.update({k: v for k, v in (overrides or {}).items() if v is not None})
    refs = refs or os.path.join(tools.work, "refs")
    os.makedirs(refs, exist_ok=True)
    w, h = (int(x) for x in cfg["size"].split("x"))
    cyc = cycles.Cycles()
    out = {"size": cfg["size"], "refSpp": cfg["refSpp"], "references": refs,
           "timeAxis": "CPU time per frame (s)",
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

            def tr(sampler, spp, seed, name, size=None):
                c0 = children_cpu()
                stats, path, wall = common.texrender(
                    tools, scene, tex, name,
                    ["--size", size or cfg["size"], "--spp", str(spp), "--seed", str(seed),
                     "--kernels", kernels[sampler]], image="exr",
                    cache=os.path.join(tools.work, "cache-" + sampler))
                return {"seconds": stats["renderSeconds"], "wall": wall,
                        "cpu": children_cpu() - c0}, path

            def cy(spp, seed, exr, size=None):
                c0 = process_cpu(cyc.p.pid)
                r = cyc.call(op="render", blend=blend, size=size or [w, h], spp=spp, seed=seed,
                             exr=exr)
                return {"seconds": r["seconds"], "wall": r["seconds"],
                        "cpu": process_cpu(cyc.p.pid) - c0}

            if fixed_only:  # --fixed-only N: the fixed parts alone, N repetitions
                out["scenes"][scene_name] = {"fixed": fixed_parts(tr, cy, samplers, fixed_only)}
                if checkpoint:
                    checkpoint(out)
                continue
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
            fixed = fixed_parts(tr, cy, samplers)
            configs = ["texrender-" + s for s in samplers] + ["cycles"]
            points = []
            for spp in cfg["spp"]:
                for rep in range(reps_at(cfg, spp)):
                    k = rep % len(configs)
                    for c in configs[k:] + configs[:k]:
                        common.log("peer %s %s spp=%d rep %d" % (scene_name, c, spp, rep + 1))
                        load = os.getloadavg()[0]
                        out["loads"].append(load)
                        seed = rep + 1
                        if c == "cycles":
                            exr = os.path.join(tools.work, "peer-cycles.exr")
                            t = cy(spp, seed, exr)
                            img, r = read_exr(exr), ref["cycles"]
                        else:
                            t, p = tr(c.split("-", 1)[1], spp, seed,
                                      "peer-" + c.replace(":", "-"))
                            img, r = read_exr(p), ref["texrender"]
                        points.append({"renderer": c, "spp": spp, "rep": rep, "load": load,
                                       "cpu": t["cpu"] - fixed[c]["cpu"],
                                       "cpuTotal": t["cpu"],
                                       "seconds": t["seconds"], "wall": t["wall"],
                                       "rmse": float(np.sqrt(np.mean((img - r) ** 2))),
                                       "flip": flip_error(r, img)})
                    if checkpoint:
                        checkpoint(out)
            diff = float(np.sqrt(np.mean((ref["texrender"] - ref["cycles"]) ** 2)))
            summary, ratios = summarize_peer(points), peer_ratios(points)
            fitted_seconds(summary, ratios)
            out["scenes"][scene_name] = {
                "fixed": fixed, "points": points, "summary": summary, "ratios": ratios,
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
    """Per renderer and spp: the median times (cpu: the frame's CPU seconds, the time axis;
    cpuTotal; wall: renderSeconds / the render call) and the RMS of the RMSE and the mean FLIP
    over the repetitions (independent seeds). "seconds" is the frame's CPU time (the charts'
    time axis)."""
    rows = []
    for c in sorted({p["renderer"] for p in points}):
        for spp in sorted({p["spp"] for p in points}):
            ps = [p for p in points if p["renderer"] == c and p["spp"] == spp]
            if not ps:
                continue
            flips = [p["flip"] for p in ps if p["flip"] is not None]
            med = {k: common.median([p[k] for p in ps]) for k in ("cpu", "cpuTotal", "wall")}
            rows.append({"renderer": c, "spp": spp, "seconds": med["cpu"], "cpu": med["cpu"],
                         "cpuTotal": med["cpuTotal"], "wallSeconds": med["wall"],
                         "renderSeconds": common.median([p["seconds"] for p in ps]),
                         "rmse": float(np.sqrt(np.mean([p["rmse"] ** 2 for p in ps]))),
                         "flip": float(np.mean(flips)) if flips else None, "n": len(ps)})
    return rows


def fitted_seconds(summary, ratios):
    """Each summary row's "seconds" (the charts' time axis) becomes the fitted frame CPU time,
    perSample * spp (time_model): below about 16 spp the measured frame time (cpu: the
    process's CPU time less the fixed part) is smaller than the fixed part's noise."""
    model = ratios.get("timeModel", {})
    for row in summary:
        if row["renderer"] in model and model[row["renderer"]][1] > 0:
            row["seconds"] = model[row["renderer"]][1] * row["spp"]


def rmse_at(curve, spp):
    """RMSE at a (fractional) spp on a renderer's curve [(spp, rmse)]: straight between
    neighbouring points in log-log, and beyond the ends along RMSE ~ spp^-1/2."""
    if spp <= curve[0][0]:
        return curve[0][1] * (curve[0][0] / spp) ** 0.5
    if spp >= curve[-1][0]:
        return curve[-1][1] * (curve[-1][0] / spp) ** 0.5
    for (s0, e0), (s1, e1) in zip(curve, curve[1:]):
        if s0 <= spp <= s1:
            f = np.log(spp / s0) / np.log(s1 / s0)
            return float(np.exp(np.log(e0) + f * (np.log(e1) - np.log(e0))))
    return None


def time_model(groups, c, spps):
    """A renderer's CPU time as fixed + perSample * spp: least squares over the median
    cpuTotal at each spp (a render's work grows linearly with spp; the fit smooths the
    load's noise)."""
    x = np.array([s for s in spps if (c, s) in groups], float)
    y = np.array([np.median(groups[c, s]["t"]) for s in x.astype(int)])
    per, fixed = np.polyfit(x, y, 1)
    return float(fixed), float(per)


def _ratios(groups, spps, mine, peer):
    rms = {k: float(np.sqrt(np.mean(np.square(g["e"])))) for k, g in groups.items()}
    curve = sorted((s, rms[mine, s]) for s in spps if (mine, s) in groups)
    (fm, pm), (fp, pp) = time_model(groups, mine, spps), time_model(groups, peer, spps)
    out = {"timeModel": {mine: [fm, pm], peer: [fp, pp]}}
    for s in spps:
        if (mine, s) not in groups or (peer, s) not in groups:
            continue
        row = {"equalSpp": rms[mine, s] / rms[peer, s]}
        if pm <= 0 or pp <= 0:  # too few or too noisy points for a time model
            out[s] = row
            continue
        # equal frame time: texrender's spp in the CPU time Cycles spends on s samples
        row["equalTime-cpu"] = rmse_at(curve, s * pp / pm) / rms[peer, s]
        # equal whole-process time, fixed parts included (None: texrender's fixed part alone
        # is longer than Cycles' whole render, it has no image by then)
        s2 = (fp + pp * s - fm) / pm
        row["equalTime-cpuTotal"] = rmse_at(curve, s2) / rms[peer, s] if s2 >= 1 else None
        out[s] = row
    return out


def peer_ratios(points, mine="texrender-sobol", peer="cycles", boot=2000):
    """texrender's RMSE over Cycles' at each spp (equal samples) and at the CPU time Cycles
    spends on that spp (equal time). Each renderer's CPU time is fitted as fixed + perSample *
    spp (time_model); at equal frame time ("equalTime-cpu", fixed parts left out) texrender
    renders s * perSample(Cycles) / perSample(texrender) samples, at equal whole-process time
    ("equalTime-cpuTotal") (fixed + perSample * s of Cycles less texrender's fixed) /
    texrender's perSample; its RMSE there is read off its own RMSE-against-spp curve in log-log
    (rmse_at, which is the RMSE-against-time curve with the fitted time). Each ratio has a 95%
    percentile-bootstrap interval: the repetitions of every (renderer, spp) resampled with
    replacement, the whole computation redone (fixed generator seed)."""
    spps = sorted({p["spp"] for p in points})
    groups = {}
    for p in points:
        g = groups.setdefault((p["renderer"], p["spp"]), {"e": [], "t": []})
        g["e"].append(p["rmse"])
        g["t"].append(p["cpuTotal"])
    if not any(k[0] == mine for k in groups) or not any(k[0] == peer for k in groups):
        return {}
    point = _ratios(groups, spps, mine, peer)
    rng = np.random.default_rng(0)
    samples = {}
    for _ in range(boot):
        g2 = {}
        for k, g in groups.items():
            idx = rng.integers(0, len(g["e"]), len(g["e"]))
            g2[k] = {"e": [g["e"][i] for i in idx], "t": [g["t"][i] for i in idx]}
        for s, row in _ratios(g2, spps, mine, peer).items():
            if s == "timeModel":
                continue
            for k, v in row.items():
                if v is not None:
                    samples.setdefault((s, k), []).append(v)
    out = {"timeModel": point.pop("timeModel")}
    for s, row in point.items():
        out[str(s)] = {}
        for k, v in row.items():
            vs = samples.get((s, k), [])
            out[str(s)][k] = {"ratio": v, "ci95": [float(np.percentile(vs, 2.5)),
                                                   float(np.percentile(vs, 97.5))]
                              if vs and v is not None else None}
    return out


def main():
    import argparse
    import json
    import sys
    ap = argparse.ArgumentParser(description="bench/accuracy.py --peer: texrender against "
                                 "Cycles, error against a converged reference")
    ap.add_argument("--peer", action="store_true", required=True)
    ap.add_argument("--quick", action="store_true")
    common.add_build_argument(ap)
    ap.add_argument("--work", default="/tmp/texcc-accuracy-peer")
    ap.add_argument("--refs", default=None, help="folder of the reference EXRs (kept, reused)")
    ap.add_argument("--samplers", default="sobol,pcg",
                    help="texrender's samplers: sobol, pcg, or BASE:NAME=VALUE[+...] with "
                    "bench-only shade.cl defines")
    ap.add_argument("--size", help="film size (default 128x128)")
    ap.add_argument("--ref-spp", type=int, help="the references' spp (default 4096)")
    ap.add_argument("--spp", help="comma-separated spp of the sweep (default 1,4,16,64,256)")
    ap.add_argument("--reps", type=int, help="repetitions (seeds 1..) per point (default 2)")
    ap.add_argument("--reps-at", help="repetitions by spp, SPP:N,... (e.g. 1:16,4:8): "
                    "overrides --reps at those spp")
    ap.add_argument("--scenes", help="comma-separated, of: " + ",".join(PEER_SCENES))
    ap.add_argument("--fixed-only", type=int, default=0, metavar="N",
                    help="measure only each renderer's fixed part (16x16, 1 spp), N "
                    "repetitions in turns (no references, no sweep; bench/startup.md)")
    ap.add_argument("--json", default=os.path.join(common.ROOT, "bench", "results",
                                                   "accuracy_peer.json"))
    args = ap.parse_args()
    tools = common.Tools(args.build, args.work)

    def save(obj):
        with open(args.json, "w") as f:
            json.dump(obj, f, indent=1)
    overrides = {"size": args.size, "refSpp": args.ref_spp, "reps": args.reps,
                 "repsAt": {int(a): int(b) for a, b in (x.split(":") for x in
                                                         args.reps_at.split(","))}
                 if args.reps_at else None,
                 "spp": tuple(int(x) for x in args.spp.split(",")) if args.spp else None,
                 "scenes": tuple(args.scenes.split(",")) if args.scenes else None}
    import time
    started = (time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime()), os.getloadavg())
    if args.fixed_only and args.json == ap.get_default("json"):
        save = lambda obj: None  # never over the sweep's results file unless asked to
    result = measure_peer(tools, args.quick, args.refs, tuple(args.samplers.split(",")), save,
                          overrides, args.fixed_only)
    result["machine"] = common.machine()
    result["run"] = {"command": " ".join(sys.argv), "started": started[0],
                     "loadAtStart": started[1],
                     "finished": time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime()),
                     "loadAtEnd": os.getloadavg()}
    save(result)
    for name, s in result["scenes"].items():
        for c, f in s["fixed"].items():
            print("%-10s fixed part %-16s CPU s median %.3f [%s]  wall s median %.3f" % (
                name, c, f["cpu"], " ".join("%.2f" % x["cpu"] for x in f["samples"]), f["wall"]))
        for row in s.get("summary", []):
            print("%-10s %-16s spp %4d  cpu %7.3f s (total %7.3f, wall %7.3f)  RMSE %.5f  "
                  "FLIP %s" % (name, row["renderer"], row["spp"], row["cpu"], row["cpuTotal"],
                               row["wallSeconds"], row["rmse"], common.fmt(row["flip"])))
        for spp, row in s.get("ratios", {}).items():
            if spp == "timeModel":
                print("%-10s CPU s = fixed + per sample * spp: %s" % (name, row))
                continue
            print("%-10s texrender/Cycles spp %4s  %s" % (name, spp, "  ".join(
                "%s %.3f [%.3f, %.3f]" % ((k, v["ratio"]) + tuple(v["ci95"])) if v["ci95"]
                else "%s -" % k for k, v in row.items())))


if __name__ == "__main__":
    main()
