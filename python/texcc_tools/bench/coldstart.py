"""Time to the first image, cold and warm (issue 36), beside Cycles' time to its first sample.

Scenes (--scenes, default all four):
  rust             examples/rust (texcc graph with the user's rust.cl); Cycles renders
                   make_scene.py's Blender version of the same scene (--scene examples/rust/
                   scene.json --variant rust-model: the rust node tree on the model)
  custom-node      examples/custom-node (the tutorial's dots.cl); Cycles renders the same scene
                   with grey materials (make_scene.py --variant diffuse: there is no Blender
                   version of a user's OpenCL function)
  atrium-blender   examples/blender/make_scene.py --variant rust-model (the atrium), exported by
                   scripts/blender_export.py; Cycles renders that .blend
  principled-bump  bench/inputs/principled_bump_blend.py (a 10-node Principled material with
                   Bump on a sphere), exported; Cycles renders that .blend

For each repetition the scenes are measured in turn, and for each scene: texrender cold (empty
PoCL and texrender program caches: fresh POCL_CACHE_DIR and TEXRENDER_CACHE_DIR), texrender warm
(the caches the cold run left), Cycles (a fresh bpy process: open the .blend, render 1 sample
at the scene's size). texrender's time to the first image: from starting texcc on graph.json to
the first "frame" event of `texrender SCENE --watch --control` (the first image written, as
the live preview shows it), texcc included. Cycles' time to its first sample: open_mainfile +
render() of 1 sample, measured inside the bpy process (bpy's import not included; it is
recorded). The 1-minute load average is recorded with every measurement: the machine is shared.
Every texrender line that announces a slow step ("texrender: ...: N s ...") is kept.

  bench/coldstart.py [--reps 3] [--scenes rust,atrium-blender] [--json FILE] [--no-cycles]

Writes bench/results/coldstart.json (or --json) and prints the medians; texcc_tools.bench.report
puts them in BENCHMARKS.md.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

from texcc_tools.bench import common

VENV_PYTHON = os.path.join(common.ROOT, ".venv", "bin", "python")
MAKE_SCENE = os.path.join(common.ROOT, "examples", "blender", "make_scene.py")
EXPORT = os.path.join(common.ROOT, "scripts", "blender_export.py")
PRINCIPLED = os.path.join(common.ROOT, "bench", "inputs", "principled_bump_blend.py")
SCENES = ("rust", "custom-node", "atrium-blender", "principled-bump")

CYCLES_WORKER = r"""
import json, sys, time
t0 = time.perf_counter()
import bpy
t1 = time.perf_counter()
bpy.ops.wm.open_mainfile(filepath=sys.argv[1])
s = bpy.context.scene
s.cycles.samples = 1
s.cycles.device = "CPU"
s.render.filepath = sys.argv[2]
bpy.ops.render.render(write_still=True)
t2 = time.perf_counter()
print("CYCLES " + json.dumps({"importSeconds": t1 - t0, "firstSampleSeconds": t2 - t1,
                              "size": [s.render.resolution_x, s.render.resolution_y]}))
"""


def load1():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def prepare(work, names):
    """Each scene's graph.json, scene.json and .blend (None: Cycles renders a stand-in)."""
    out = {}
    if {"rust", "custom-node", "atrium-blender"} & set(names):
        common.run([sys.executable, os.path.join(common.ROOT, "scripts", "make_scenes.py"),
                    "--only", "atrium", "rust", "custom-node"])
    for name in names:
        d = os.path.join(work, name)
        os.makedirs(d, exist_ok=True)
        blend = os.path.join(d, name + ".blend")
        if name in ("rust", "custom-node"):
            ex = os.path.join(common.ROOT, "examples", name)
            common.run([VENV_PYTHON, MAKE_SCENE, blend, "--scene", os.path.join(ex, "scene.json"),
                        "--variant", "rust-model" if name == "rust" else "diffuse"])
            out[name] = {"graph": os.path.join(ex, "graph.json"),
                         "scene": os.path.join(ex, "scene.json"), "blend": blend,
                         "cycles": "make_scene.py --variant " +
                                   ("rust-model" if name == "rust" else "diffuse")}
            continue
        if name == "atrium-blender":
            common.run([VENV_PYTHON, MAKE_SCENE, blend, "--variant", "rust-model"])
        else:
            common.run([VENV_PYTHON, PRINCIPLED, blend])
        exp = os.path.join(d, "export")
        common.run([VENV_PYTHON, EXPORT, blend, "-o", exp])
        out[name] = {"graph": os.path.join(exp, "graph.json"),
                     "scene": os.path.join(exp, "scene.json"), "blend": blend,
                     "cycles": "the same .blend"}
    return out


def first_image(tools, scene, caches, run_dir, timeout):
    """texcc + texrender --watch --control until the first frame event: (seconds, lines)."""
    env = dict(os.environ, POCL_CACHE_DIR=caches["pocl"], TEXRENDER_CACHE_DIR=caches["texrender"])
    for var in ("TEXRENDER_FIRST_BUILD", "TEXRENDER_PREBUILT_DIR", "TEXRENDER_ANNOUNCE_AFTER"):
        env.pop(var, None)  # the default configuration
    tex = os.path.join(run_dir, "tex")
    shutil.rmtree(tex, ignore_errors=True)
    t0 = time.perf_counter()
    r = subprocess.run([tools.texcc, "--graph", scene["graph"], "-o", tex], env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode:
        raise common.BenchError("texcc %s: %s" % (scene["graph"], r.stderr.strip()[-300:]))
    texcc_s = time.perf_counter() - t0
    p = subprocess.Popen([tools.texrender, scene["scene"], "--textures", tex, "--watch",
                          "--control", "-o", os.path.join(run_dir, "out.png")], env=env,
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, start_new_session=True)
    lines = []

    def drain():
        for line in p.stderr:
            lines.append((time.perf_counter() - t0, line.rstrip("\n")))
    th = threading.Thread(target=drain, daemon=True)
    th.start()
    seconds, frame = None, None
    deadline = t0 + timeout
    try:
        for line in p.stdout:
            if '"event":"frame"' in line:
                seconds = time.perf_counter() - t0
                frame = json.loads(line)
                break
            if time.perf_counter() > deadline:
                break
    finally:
        # Not quit: a cold session would first finish its optimised build in the background.
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
        th.join(timeout=5)
    if seconds is None:
        raise common.BenchError("texrender %s: no frame within %d s: %s" %
                                (scene["scene"], timeout, [l for _, l in lines][-5:]))
    slow = [l for _, l in lines if re.search(r": [0-9]+ s \.\.\.$|: done in ", l)]
    return {"seconds": seconds, "texccSeconds": texcc_s, "frame": frame, "slowSteps": slow}


def cycles(blend, run_dir):
    r = subprocess.run([VENV_PYTHON, "-c", CYCLES_WORKER, blend, os.path.join(run_dir, "c.png")],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    m = re.search(r"^CYCLES (.*)$", r.stdout, re.M)
    if r.returncode or not m:
        raise common.BenchError("Cycles on %s: %s" % (blend, (r.stderr or r.stdout)[-300:]))
    return json.loads(m.group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--scenes", default=",".join(SCENES))
    common.add_build_argument(ap)
    ap.add_argument("--work", default=None)
    ap.add_argument("--json", default=os.path.join(common.RESULTS, "coldstart.json"))
    ap.add_argument("--timeout", type=int, default=600)
    ap.add_argument("--no-cycles", action="store_true")
    a = ap.parse_args()
    names = [n for n in a.scenes.split(",") if n]
    for n in names:
        if n not in SCENES:
            raise common.BenchError("--scenes: unknown scene %r (have %s)" % (n, ", ".join(SCENES)))
    work = a.work or tempfile.mkdtemp(prefix="coldstart-")
    tools = common.Tools(a.build, work)
    scenes = prepare(work, names)
    samples = {n: {"cold": [], "warm": [], "cycles": []} for n in names}
    for rep in range(a.reps):
        for n in names:
            run_dir = os.path.join(work, n, "run")
            caches = {"pocl": os.path.join(run_dir, "pocl"), "texrender": os.path.join(run_dir, "tc")}
            for c in caches.values():
                shutil.rmtree(c, ignore_errors=True)
                os.makedirs(c)
            for kind in ("cold", "warm"):
                load = load1()
                r = first_image(tools, scenes[n], caches, run_dir, a.timeout)
                r["load"] = load
                samples[n][kind].append(r)
                common.log("rep %d %s %s: %.2f s (load %.1f)%s" % (
                    rep + 1, n, kind, r["seconds"], load,
                    "".join("\n    " + s for s in r["slowSteps"])))
            if not a.no_cycles:
                load = load1()
                c = cycles(scenes[n]["blend"], run_dir)
                c["load"] = load
                samples[n]["cycles"].append(c)
                common.log("rep %d %s cycles: %.2f s (load %.1f)" % (
                    rep + 1, n, c["firstSampleSeconds"], load))
    rows = []
    for n in names:
        s = samples[n]
        row = {"scene": n, "cycles": scenes[n]["cycles"],
               "coldMedian": common.median([x["seconds"] for x in s["cold"]]),
               "warmMedian": common.median([x["seconds"] for x in s["warm"]]),
               "cold": [round(x["seconds"], 3) for x in s["cold"]],
               "warm": [round(x["seconds"], 3) for x in s["warm"]],
               "load": [x["load"] for x in s["cold"] + s["warm"] + s["cycles"]],
               "slowSteps": s["cold"][0]["slowSteps"] if s["cold"] else []}
        if s["cycles"]:
            row["cyclesMedian"] = common.median([x["firstSampleSeconds"] for x in s["cycles"]])
            row["cyclesSamples"] = [round(x["firstSampleSeconds"], 3) for x in s["cycles"]]
            row["bpyImportMedian"] = common.median([x["importSeconds"] for x in s["cycles"]])
        rows.append(row)
        print("%-16s cold %6.2f s  warm %5.2f s  Cycles %s   (load %.1f-%.1f)" % (
            n, row["coldMedian"], row["warmMedian"],
            "%.2f s" % row["cyclesMedian"] if "cyclesMedian" in row else "-",
            min(row["load"]), max(row["load"])))
    data = {"machine": common.machine(), "commit": common.git_head(), "reps": a.reps,
            "when": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "rows": rows}
    os.makedirs(os.path.dirname(os.path.abspath(a.json)), exist_ok=True)
    with open(a.json, "w") as f:
        json.dump(data, f, indent=1)
    print("wrote %s" % a.json)


if __name__ == "__main__":
    common.run_main(main, "coldstart")
