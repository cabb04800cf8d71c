"""Ray throughput of texrender (rays per second by kind) with each trace backend (--trace=opencl:
OpenCL profiling events of the trace kernels; --trace=embree: wall time of the Embree stages) on
the Cornell box (plain, and with a texture that reads AO) and on the atrium with the rust texture.
The two backends run one after the other per scene. Writes bench/throughput.json and
bench/throughput.md.

usage: bench/throughput.py [--build build] [--device N] [--trace opencl,embree]
Needs texcc and texrender in BUILD/bin; the atrium is skipped when examples/atrium/generated
(scripts/make_scenes.py) is missing.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from texcc_tools import process
from texcc_tools.paths import ROOT, add_build_argument

CASES = [
    # name, scene, graph, texcc sources, texrender options
    ("cornell", "examples/cornell/scene.json", "examples/cornell/graph.json", [],
     ["--size", "256x256", "--spp", "64", "--max-depth", "8"]),
    ("cornell+AO", "testsuite/Inputs/runtime/box/scene.json",
     "testsuite/Inputs/runtime/const-tex/graph-ao.json", [],
     ["--size", "256x256", "--spp", "16", "--max-depth", "8", "--ao-samples", "8"]),
    ("atrium (rust)", "examples/atrium/scene.json", "examples/rust/graph.json", [],
     ["--size", "512x512", "--spp", "4", "--max-depth", "4"]),
]


def run(cmd):
    try:
        process.run(cmd)
    except process.RunError as e:
        sys.exit("throughput.py: %s" % e)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_build_argument(ap)
    ap.add_argument("--device", default="0")
    ap.add_argument("--trace", default="opencl,embree", help="backends, comma-separated")
    args = ap.parse_args()
    texcc = os.path.join(args.build, "bin", "texcc")
    texrender = os.path.join(args.build, "bin", "texrender")
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, scene, graph, sources, opts in CASES:
            if name.startswith("atrium") and not os.path.exists(
                    os.path.join(ROOT, "examples/atrium/generated/atrium.obj")):
                print("throughput.py: skipping %s (run scripts/make_scenes.py)" % name)
                continue
            out = os.path.join(tmp, name.split()[0])
            run([texcc] + sources + ["--graph", os.path.join(ROOT, graph), "-o", out])
            stats = os.path.join(tmp, "stats.json")
            for trace in args.trace.split(","):
                cmd = [texrender, os.path.join(ROOT, scene), "--textures", out, "--quiet",
                       "--device", args.device, "--trace=" + trace,
                       "-o", os.path.join(tmp, "img.exr"), "--stats", stats]
                run(cmd + opts)  # warm the program cache
                run(cmd + opts)
                with open(stats) as f:
                    s = json.load(f)
                load = os.getloadavg()[0]
                results.append({"scene": name, "options": " ".join(opts), "device": s["device"],
                                "trace": s["trace"], "bvhBuildSeconds": s["bvhBuildSeconds"],
                                "cpus": os.cpu_count(), "loadAverage": round(load, 1),
                                "triangles": s["triangles"], "renderSeconds": s["renderSeconds"],
                                "rays": s["rays"]})
                print("%-14s %-6s %s" % (name, s["trace"], {
                    k: round(v["perSecond"] / 1e6, 2) for k, v in s["rays"].items()}))
    with open(os.path.join(ROOT, "bench", "throughput.json"), "w") as f:
        json.dump(results, f, indent=2)
        f.write("\n")
    lines = ["# texrender ray throughput", "",
             "Rays per second by kind and trace backend: the time of the stage that traces "
             "them (`closest_hit_primary`, `closest_hit_bounce`, `shadow`, `ao_trace`; "
             "opencl: OpenCL profiling events of the kernel; embree: wall time of the Embree "
             "stage, map and unmap included; docs/runtime.md). Regenerate: "
             "`bench/throughput.py` (raw numbers: `bench/throughput.json`). On a CPU device the "
             "numbers depend on what else runs: the load average (1 min) at the end of each "
             "run is listed.", "",
             "| scene | triangles | options | device | trace | primary Mray/s | bounce Mray/s | "
             "shadow Mray/s | AO Mray/s | render s | CPUs, load |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        ray = lambda k: ("%.2f" % (r["rays"][k]["perSecond"] / 1e6)) if r["rays"][k]["count"] else "-"
        lines.append("| %s | %d | `%s` | %s | %s | %s | %s | %s | %s | %.2f | %d, %.1f |" % (
            r["scene"], r["triangles"], r["options"], r["device"], r["trace"], ray("primary"),
            ray("bounce"), ray("shadow"), ray("ao"), r["renderSeconds"], r["cpus"],
            r["loadAverage"]))
    with open(os.path.join(ROOT, "bench", "throughput.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
