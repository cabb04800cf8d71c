"""Figure 2d: instructions the texture kernel executes per textured hit on PoCL, counted by
callgrind (no machine noise): where interp and shape lose to inline.

Per texture (examples/rust, examples/scratches) and configuration, texcc writes the kernel and
`texcc-eval OUT --grid N` evaluates it on PoCL's CPU device over N random hits per material
(bench/resources.py's graphs; texcc-eval is the equivalence tests' evaluator), compiled by
PoCL for `POCL_LLVM_CPU_NAME=haswell` (AVX2: valgrind runs no AVX-512). The count is
callgrind's inclusive Ir of PoCL's work-group functions (`--toggle-collect=_pocl_kernel_*`:
the kernel and every library call it makes, no runtime, no compilation; a first, uncounted run
fills PoCL's kernel cache), over the textured hits (N times the materials with outputs).
Configurations: interp (hoisting on: texcc_uniforms counted as for shape), interp --no-hoist, interp --max-quickened=0, inline, wavefront
(its per-node kernels and the output copy), shape (with its hoisting, texcc_uniforms counted once
per run: over N hits it is an upper bound of a frame's share), shape --no-hoist, shape+bake (every int argument baked, as in
section 3), shape with every constant baked (what inline sees, through shape's code), and for
each node, shape with only that node's constants baked: the instructions that baking saves,
node by node, say which constants inline's constant folding pays off on."""
import json
import os
import re
import shutil

from texcc_tools import manifest
from texcc_tools.bench import common
from texcc_tools.bench import resources

# Hits per material, quick and full alike: a count does not vary between runs, and at --grid 256
# the counted runs built their kernels again under valgrind (about a minute each; the native
# run's cache entries were not found), at 64 they find them.
GRID = 64
# PoCL compiles for the host CPU it detects, and under valgrind it detects another one (no
# AVX-512), so a kernel cached by a native run would be compiled again under valgrind (a minute
# each). Naming the CPU makes both runs the same target: the native run fills the cache and the
# counted run finds it. Haswell (AVX2, FMA) is what valgrind can execute.
POCL_ENV = {"POCL_MAX_PTHREAD_COUNT": "1", "POCL_LLVM_CPU_NAME": "haswell"}


def eval_tool(tools):
    path = os.path.join(tools.build, "bin", "texcc-eval")
    if not os.path.exists(path):
        raise common.BenchError("texcc-eval not found in %s (build it: scripts/build.sh)"
                                % os.path.dirname(path))
    return path


def count(tools, folder, grid):
    """Inclusive instructions of the texture kernels over one texcc-eval run of folder."""
    if not shutil.which("valgrind"):
        raise common.BenchError("valgrind not found (apt-get install valgrind)")
    env = dict(os.environ, **POCL_ENV)
    cmd = [eval_tool(tools), folder, "--grid", str(grid)]
    r = common.subprocess.run(cmd, stdout=common.subprocess.DEVNULL,
                              stderr=common.subprocess.PIPE, text=True, env=env)
    if r.returncode != 0:
        raise common.BenchError("%s failed: %s" % (" ".join(cmd), r.stderr[-1000:]))
    out = os.path.join(folder, "callgrind.out")
    vg = ["valgrind", "--tool=callgrind", "--toggle-collect=_pocl_kernel_*",
          "--callgrind-out-file=" + out] + cmd
    r = common.subprocess.run(vg, stdout=common.subprocess.DEVNULL,
                              stderr=common.subprocess.PIPE, text=True, env=env)
    if r.returncode != 0:
        raise common.BenchError("%s failed: %s" % (" ".join(vg), r.stderr[-1000:]))
    m = re.search(r"Collected : (\d+)", r.stderr)
    if not m:
        raise common.BenchError("callgrind printed no count for %s" % folder)
    return int(m.group(1))


def textured_hits(folder, grid):
    layout = manifest.load(folder)
    return grid * sum(1 for m in layout["materials"] if m.get("outputs"))


def constant_args(graph_path):
    """{node id: [arg, ...]} of the arguments given as a number or a flat list of numbers."""
    with open(graph_path) as f:
        graph = json.load(f)
    out = {}
    for node in graph["nodes"]:
        names = [a for a, v in node.get("args", {}).items()
                 if isinstance(v, (int, float)) or
                 (isinstance(v, list) and v and all(isinstance(x, (int, float)) for x in v))]
        if names:
            out[node["id"]] = names
    return out


def bake_flags(args):
    return ["--bake=%s.%s" % (n, a) for n, names in args.items() for a in names]


def measure(tools, quick):
    grid = GRID
    rows = []
    for tex, graph in resources.GRAPHS.items():
        graph_path = os.path.join(common.ROOT, graph)
        consts = constant_args(graph_path)
        folder0 = os.path.join(tools.work, "ins-%s-probe" % tex)
        common.texcc(tools, graph_path, folder0, "shape")
        ints = resources.int_arguments(os.path.join(folder0, "layout.json"))
        configs = [("interp", "interp", []),
                   ("interp --no-hoist", "interp", ["--no-hoist"]),
                   ("interp --max-quickened=0", "interp", ["--max-quickened=0"]),
                   ("inline", "inline", []), ("wavefront", "wavefront", []),
                   ("shape", "shape", []),
                   ("shape --no-hoist", "shape", ["--no-hoist"]),
                   ("shape+bake", "shape", ["--bake=" + a for a in ints]),
                   ("shape, every constant baked", "shape", bake_flags(consts))]
        configs += [("shape, %s baked" % node, "shape", bake_flags({node: names}))
                    for node, names in consts.items()]
        for label, mode, extra in configs:
            folder = os.path.join(tools.work, "ins-%s-%d" % (tex, len(rows)))
            common.texcc(tools, graph_path, folder, mode, extra)
            ir = count(tools, folder, grid)
            hits = textured_hits(folder, grid)
            common.log("instructions %s %s: %.0f per textured hit" % (tex, label, ir / hits))
            rows.append({"texture": tex, "config": label, "mode": mode, "texccOptions": extra,
                         "instructions": ir, "texturedHits": hits,
                         "perHit": ir / hits})
    return {"grid": grid, "pocl": POCL_ENV, "rows": rows}


# The examples whose loops and array reads the checks guard (bench/per_hit.py's GRAPHS).
CHECK_GRAPHS = {"rust": "examples/rust/graph.json", "scratches": "examples/scratches/graph.json",
                "marble": "examples/marble/graph.json", "wood": "examples/wood/graph.json"}
CHECK_MODES = ("inline", "interp", "shape")


def measure_checks(tools, names, grid):
    """The cost of the loop budget and the bounds checks in instructions (bench/loop-budget.md):
    per example and mode, the kernel as texcc compiles it against `texcc --no-checks`, counted
    as above; the ratio minus 1 is the checks' cost per hit, free of the machine's load."""
    rows = []
    for tex in names:
        graph_path = os.path.join(common.ROOT, CHECK_GRAPHS[tex])
        for mode in CHECK_MODES:
            counts = {}
            for label, extra in (("checked", []), ("unchecked", ["--no-checks"])):
                folder = os.path.join(tools.work, "checks-%s-%s-%s" % (tex, mode, label))
                common.texcc(tools, graph_path, folder, mode, extra)
                counts[label] = count(tools, folder, grid) / textured_hits(folder, grid)
            cost = counts["checked"] / counts["unchecked"] - 1.0
            common.log("checks %s %s: %.1f instructions per hit checked, %.1f unchecked: %+.2f%%"
                       % (tex, mode, counts["checked"], counts["unchecked"], 100 * cost))
            rows.append({"texture": tex, "mode": mode, "checkedPerHit": counts["checked"],
                         "uncheckedPerHit": counts["unchecked"], "cost": cost})
    return {"grid": grid, "pocl": POCL_ENV, "rows": rows}


def main():
    import argparse
    ap = argparse.ArgumentParser(description="--checks: the checks' cost in instructions per hit")
    common.add_build_argument(ap)
    ap.add_argument("--work", default=None)
    ap.add_argument("--checks", action="store_true", required=True)
    ap.add_argument("--only", default=",".join(CHECK_GRAPHS))
    ap.add_argument("--out", default=os.path.join(common.RESULTS, "instructions-checks.json"))
    args = ap.parse_args()
    work = args.work or os.path.join(args.build, "bench-instructions")
    os.makedirs(work, exist_ok=True)
    tools = common.Tools(args.build, work)
    data = {"machine": common.machine(), "git": common.git_head()}
    data.update(measure_checks(tools, args.only.split(","), GRID))
    common.save(None, data, args.out)


if __name__ == "__main__":
    common.run_main(main, "bench/instructions.py")
