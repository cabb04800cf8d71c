"""Issue 20's before/after (bench/refactor-20.md): callgrind instructions per textured hit of
every example in every mode, counted as bench/instructions.py counts them (texcc-eval on PoCL's
CPU device, POCL_LLVM_CPU_NAME=haswell, inclusive Ir of the work-group functions), for one or
more builds, and interp's mechanisms under review (the local-memory value stack, quickened
opcodes) against the kernel without them.

  bench/refactor20.py --build before=/tmp/c-base/build --build after=build \\
      --configs interp,inline,wavefront,shape --out bench/results/refactor20.json

A count does not depend on the machine's load (only on the code PoCL generates), so builds and
configurations need no interleaving. The rows are appended to --out when it exists (one file for
runs made at different times), keyed by build label, example and configuration."""
import argparse
import json
import os

from texcc_tools.bench import common
from texcc_tools.bench import instructions

EXAMPLES = {"rust": "examples/rust/graph.json", "scratches": "examples/scratches/graph.json",
            "marble": "examples/marble/graph.json", "wood": "examples/wood/graph.json"}
# label -> (mode, texcc options)
CONFIGS = {
    "interp": ("interp", []),
    "inline": ("inline", []),
    "wavefront": ("wavefront", []),
    "shape": ("shape", []),
    "interp-private": ("interp", ["--local-stack-limit=0"]),
    "interp-unquickened": ("interp", ["--max-quickened=0"]),
}


class BuildTools:
    """What common.texcc and instructions.count need of a build folder: texcc, texcc-eval."""

    def __init__(self, build, work):
        self.build = build
        self.work = work
        self.texcc = os.path.join(build, "bin", "texcc")
        for tool in ("texcc", "texcc-eval"):
            if not os.access(os.path.join(build, "bin", tool), os.X_OK):
                raise common.BenchError("%s/bin/%s: not built" % (build, tool))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", action="append", required=True, metavar="LABEL=DIR")
    ap.add_argument("--configs", default="interp,inline,wavefront,shape")
    ap.add_argument("--only", default=",".join(EXAMPLES))
    ap.add_argument("--work", default="/tmp/refactor20-work")
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "refactor20.json"))
    args = ap.parse_args()
    data = {"rows": []}
    if os.path.exists(args.out):
        with open(args.out) as f:
            data = json.load(f)
    data["grid"] = instructions.GRID
    data["pocl"] = instructions.POCL_ENV
    for spec in args.build:
        label, build = spec.split("=", 1)
        work = os.path.join(args.work, label)
        os.makedirs(work, exist_ok=True)
        tools = BuildTools(os.path.abspath(build), work)
        for tex in args.only.split(","):
            graph = os.path.join(common.ROOT, EXAMPLES[tex])
            for config in args.configs.split(","):
                mode, extra = CONFIGS[config]
                folder = os.path.join(work, "%s-%s" % (tex, config))
                common.run(["rm", "-rf", folder])
                common.texcc(tools, graph, folder, mode, extra)
                ir = instructions.count(tools, folder, instructions.GRID)
                hits = instructions.textured_hits(folder, instructions.GRID)
                common.log("%s %s %s: %.1f instructions per textured hit"
                           % (label, tex, config, ir / hits))
                data["rows"] = [r for r in data["rows"]
                                if (r["build"], r["texture"], r["config"]) != (label, tex, config)]
                data["rows"].append({"build": label, "buildDir": build, "texture": tex,
                                     "config": config, "mode": mode, "texccOptions": extra,
                                     "instructions": ir, "texturedHits": hits,
                                     "perHit": ir / hits, "load": os.getloadavg()[0]})
                with open(args.out, "w") as f:
                    json.dump(data, f, indent=1)
                    f.write("\n")


if __name__ == "__main__":
    common.run_main(main, "bench/refactor20.py")
