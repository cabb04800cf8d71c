"""Farm figures (docs/farm.md, BENCHMARKS.md "Farm"): what a Ray task costs over a texrender run.

One frame of the box scene with AO (testsuite/Inputs/runtime/box, const-tex/graph-ao.json) is
rendered by texrender alone, then through scripts/farm.py's task (render_tile: texrender
--region on the shipped bundle) on a local Ray cluster of 1 and of 2 workers, with tiles of
16x16, 32x32, 64x64 and the whole image. Every stitched frame is checked equal to the single
render bit for bit. Per tile size: wall seconds from submitting the frame's tasks to having all
results, the tasks' own texrender seconds, and from them
  - the per-task overhead: with 1 worker the tasks run one after another and share the same
    work (the image), so the slope of wall seconds against the number of tasks N is what each
    task adds (texrender's start-up, scene load, BVH, kernel-cache load, and Ray);
  - Ray's share of it: (wall - sum of the tasks' texrender seconds) / N with 1 worker;
  - the speed-up of 2 workers over 1.
Transfer sizes: the bundle (shipped once per node through the object store) and the mean EXR
bytes a task returns. Results: bench/results/farm.json; the load average is recorded with them.

  .venv/bin/python bench/farm.py [--size 128x128] [--spp 16] [--reps 2]   (.venv's Python: numpy,
  and Ray, which farm.import_ray installs on first use)
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from texcc_tools import exr, farm
from texcc_tools.paths import BENCH, INPUTS, default_build_dir

SCENE = os.path.join(INPUTS, "runtime", "box", "scene.json")
GRAPH = os.path.join(INPUTS, "runtime", "const-tex", "graph-ao.json")
BIN = os.path.join(default_build_dir(), "bin")


def timed_tile(*args):
    t0 = time.perf_counter()
    images = farm.render_tile(*args)
    return images, time.perf_counter() - t0


def slope(xs, ys):
    mx, my = statistics.mean(xs), statistics.mean(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--size", default="128x128")
    p.add_argument("--spp", default="16")
    p.add_argument("--reps", type=int, default=2)
    p.add_argument("-o", default=os.path.join(BENCH, "results", "farm.json"))
    a = p.parse_args()
    ray = farm.import_ray()
    import numpy as np
    from ray import cloudpickle
    for module in (farm, exr):  # a worker of another cluster need not have the package
        cloudpickle.register_pickle_by_value(module)

    width, height = (int(v) for v in a.size.split("x"))
    work = tempfile.mkdtemp(prefix="farm-bench-")
    tex = os.path.join(work, "tex")
    subprocess.run([os.path.join(BIN, "texcc"), "--graph", GRAPH, "-o", tex], check=True)
    texrender = os.path.join(BIN, "texrender")
    options = ["--size", a.size, "--spp", a.spp]
    whole_path = os.path.join(work, "whole.exr")
    singles = []
    for _ in range(a.reps + 1):  # the first run also fills the kernel cache
        t0 = time.perf_counter()
        subprocess.run([texrender, SCENE, "--textures", tex, "--quiet", "-o", whole_path] + options,
                       check=True)
        singles.append(time.perf_counter() - t0)
    single = statistics.median(singles[1:])
    whole = exr.read_exr(farm.read_bytes(whole_path))
    files = farm.make_bundle(SCENE, tex)
    digest = farm.bundle_digest(files)
    result = {"scene": "testsuite/Inputs/runtime/box + const-tex/graph-ao.json", "size": a.size,
              "spp": int(a.spp), "cpus": os.cpu_count(), "loadAverageBefore": os.getloadavg(),
              "singleTexrenderSeconds": single, "bundleBytes": sum(map(len, files.values())),
              "runs": []}
    for workers in (1, 2):
        ray.init(num_cpus=workers, include_dashboard=False, logging_level="ERROR",
                 log_to_driver=False)
        task = ray.remote(num_cpus=1, max_retries=0)(timed_tile)
        ref = ray.put(files)
        ray.get([task.remote(texrender, ref, digest, options, 0, (0, 0, 16, 16), None, "")
                 for _ in range(workers)])  # warm: worker processes, bundle unpacked
        for tile in (16, 32, 64, width):
            tiles = farm.tiles_of(width, height, max(1, width // tile), max(1, height // tile))
            walls, task_seconds, out_bytes = [], [], 0
            for _ in range(a.reps):
                t0 = time.perf_counter()
                got = ray.get([task.remote(texrender, ref, digest, options, 0, t, None, "")
                               for t in tiles])
                walls.append(time.perf_counter() - t0)
                task_seconds.append(sum(s for _, s in got))
                out_bytes = statistics.mean(len(images[0]) for images, _ in got)
                image = np.zeros_like(whole)
                for (x, y, w, h), (images, _) in zip(tiles, got):
                    image[y:y + h, x:x + w] = exr.read_exr(images[0])
                if not np.array_equal(image, whole):
                    sys.exit("bench/farm.py: %d workers, %dx%d tiles: the stitched frame differs "
                             "from texrender's" % (workers, tile, tile))
            wall, tasks_s = statistics.median(walls), statistics.median(task_seconds)
            run = {"workers": workers, "tile": tile, "tasks": len(tiles), "wallSeconds": wall,
                   "taskTexrenderSeconds": tasks_s, "rayOverheadPerTask": (wall - tasks_s) / len(tiles),
                   "meanResultBytes": out_bytes, "identical": True}
            result["runs"].append(run)
            print("%d worker(s), %3dx%-3d tiles, %3d tasks: %6.2f s wall, tasks' texrender %6.2f s"
                  % (workers, tile, tile, len(tiles), wall, tasks_s), flush=True)
        ray.shutdown()
    one = [r for r in result["runs"] if r["workers"] == 1]
    result["perTaskOverheadSeconds"] = slope([r["tasks"] for r in one], [r["wallSeconds"] for r in one])
    for r in one:
        two = next(t for t in result["runs"] if t["workers"] == 2 and t["tile"] == r["tile"])
        r["speedupOf2Workers"] = r["wallSeconds"] / two["wallSeconds"]
    result["loadAverageAfter"] = os.getloadavg()
    with open(a.o, "w") as f:
        json.dump(result, f, indent=1)
    print("single texrender %.2f s; per-task overhead (slope, 1 worker) %.3f s; bundle %d bytes"
          % (single, result["perTaskOverheadSeconds"], result["bundleBytes"]))
    for r in one:
        print("tile %3d: speed-up of 2 workers %.2f, Ray's overhead per task %.3f s"
              % (r["tile"], r["speedupOf2Workers"], r["rayOverheadPerTask"]))
    print("load average before %s, after %s" % (result["loadAverageBefore"], result["loadAverageAfter"]))


if __name__ == "__main__":
    main()
