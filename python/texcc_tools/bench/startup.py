"""texrender's fixed start-up cost (bench/startup.md): the CPU time (user + system, every
thread) and wall time of a 16x16, 1 spp render of the atrium (bench/accuracy.py --peer's
fixed-part measurement), for one or more texrender builds, interleaved: each repetition runs
every build once, in an order that rotates with the repetition, so that the shared machine's
load drifts over all of them alike. Medians over the repetitions; the 1-minute load average
before each run is recorded.

usage: python3 bench/startup.py [--scene diffuse|rust-model] [--reps N] [--trace embree|opencl]
                                NAME=BIN_DIR ...   (BIN_DIR holds texrender; kernels/ beside it)
A build's kernels are those beside its bin/ folder (texrender finds them next to itself); the
texcc output is made once by the first build's texcc."""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

from texcc_tools.paths import ROOT
SCENES = {"diffuse": ("bench/inputs/diffuse/graph.json", "examples/atrium/scene-diffuse.json"),
          "rust-model": ("examples/rust/graph.json", "examples/atrium/scene.json")}


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_once(binary, scene, tex, work, cache, extra):
    cmd = [os.path.join(binary, "texrender"), scene, "--textures", tex, "-o",
           os.path.join(work, "fixed.exr"), "--stats", os.path.join(work, "fixed.json"),
           "--quiet", "--size", "16x16", "--spp", "1", "--seed", "1", "--cache-dir", cache] + extra
    c0, w0 = children_cpu(), time.monotonic()
    subprocess.run(cmd, check=True)
    wall, cpu = time.monotonic() - w0, children_cpu() - c0
    with open(os.path.join(work, "fixed.json")) as f:
        stats = json.load(f)
    return {"cpu": cpu, "wall": wall, "bvh": stats.get("bvhBuildSeconds")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("builds", nargs="+", help="NAME=BIN_DIR")
    ap.add_argument("--scene", default="diffuse", choices=sorted(SCENES))
    ap.add_argument("--reps", type=int, default=7)
    ap.add_argument("--trace", default=None, help="texrender --trace (default: its auto)")
    ap.add_argument("--json", help="write the samples and medians here")
    a = ap.parse_args()
    builds = [b.split("=", 1) for b in a.builds]
    graph, scene = (os.path.join(ROOT, p) for p in SCENES[a.scene])
    extra = ["--trace=" + a.trace] if a.trace else []
    with tempfile.TemporaryDirectory(prefix="texrender-startup-") as work:
        tex, cache = os.path.join(work, "tex"), os.path.join(work, "cache")
        subprocess.run([os.path.join(builds[0][1], "texcc"), "--mode=interp", "--graph", graph,
                        "-o", tex], check=True, stdout=subprocess.DEVNULL)
        for name, b in builds:  # warm the program caches (not measured)
            run_once(b, scene, tex, work, cache, extra)
        samples = {name: [] for name, _ in builds}
        loads = []
        for rep in range(a.reps):
            k = rep % len(builds)
            for name, b in builds[k:] + builds[:k]:
                loads.append(os.getloadavg()[0])
                samples[name].append(run_once(b, scene, tex, work, cache, extra))
    out = {"scene": a.scene, "reps": a.reps, "trace": a.trace or "auto",
           "load": [min(loads), statistics.median(loads), max(loads)], "builds": {}}
    print("%s, %d repetitions, load %.1f-%.1f (median %.1f)" % (
        a.scene, a.reps, out["load"][0], out["load"][2], out["load"][1]))
    for name, _ in builds:
        s = samples[name]
        med = {k: statistics.median(x[k] for x in s) for k in ("cpu", "wall")}
        out["builds"][name] = {"median": med, "samples": s}
        print("  %-12s CPU s median %.3f [%s]  wall s median %.3f" % (
            name, med["cpu"], " ".join("%.2f" % x["cpu"] for x in s), med["wall"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
