"""Issue 39 items 1-2: the texture kernel's cost per sample in every texrender mode beside a C
reference, the same texture source compiled by clang-15 -O3 as native code
(bench/cpp_reference/README.md), on one thread.

Graphs (bench/cpp_reference/graphs/): Blender's Noise Texture (blNoise3DColor, 3D fBM, Detail 7,
Color) and a user's fBM of PCG-hashed value noise (bench/cpp_reference/userfbm.cl, 8 octaves,
colour). Per graph it measures, in ns per sample:

- texrender's modes inline, interp and shape on PoCL (texcc-eval --time: one process, the modes
  in rounds whose order rotates, POCL_MAX_PTHREAD_COUNT=1, device time per textured hit);
- ref: the texture function itself over an array of points (ref.c), with the parameters as
  run-time values ("runtime") and as literals ("folded");
- native: texcc's generated proctex.cl of inline and interp mode (the loop budget, the guards,
  the interp dispatch included) compiled by the same clang-15 -O3 and run work-item after
  work-item (proctex_host.c): what texcc's code costs without PoCL's build of it.

The processes alternate (ref, native, PoCL) --reps times; the figures are medians over all rounds
of all repetitions, with the load average recorded. Every reference output is compared with
texrender's inline mode at the same points (texcc-eval --points): "maxAbsDiff" must be 0.

--callgrind adds instruction counts per sample of the reference and the native builds (valgrind
--tool=callgrind, which has no AVX-512: both built for -march=haswell): deterministic where the
wall times of the shared machine are not. PoCL's kernels are not counted here: on this AVX-512
machine PoCL builds them with AVX-512 whatever POCL_LLVM_CPU_NAME says, and under valgrind it
sees another CPU and builds again (minutes per Noise kernel); bench/texture-speed.md has the
counts taken that way. The figures without --callgrind are saved before the counting starts.

--nodes measures instead the single Blender nodes of bench/per_node_cycles.py (Noise 3D Color
fBM and Ridged Multifractal, Voronoi 3D F1, Wave; its NODES) in every mode, and with
--baseline REV the same nodes built from REV's textures/blender/ beside them: each node's
baseline and current folders in one texcc-eval --time process (rounds interleave them), --reps
processes, medians, the ratio of each current mode to the baseline's same mode, and whether the
two give the same values at every grid point ("identical", texcc-eval's %.9g output compared).

usage: bench/texture_speed.py [--build DIR] [--work DIR] [--rounds R] [--reps K] [--grid N]
                              [--callgrind] [--modes inline,interp,shape] [--out FILE]
       bench/texture_speed.py --nodes [--baseline REV] [--rounds R] [--reps K] [--grid N]
                              [--out FILE]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import types

from texcc_tools.bench import common

REF_DIR = os.path.join(common.BENCH, "cpp_reference")
GRAPHS = {"noise3d-color-detail7": os.path.join(REF_DIR, "graphs", "noise3d-color-detail7.json"),
          "userfbm": os.path.join(REF_DIR, "graphs", "userfbm.json")}
# ref.c's variant names per graph; its --dump-values columns 0-2 are the noise, 3-5 the fBM.
REF_VARIANTS = {"noise3d-color-detail7": ("noise3d-color-detail7/runtime",
                                          "noise3d-color-detail7/folded"),
                "userfbm": ("userfbm/runtime", "userfbm/folded")}
REF_COLUMNS = {"noise3d-color-detail7": slice(0, 3), "userfbm": slice(3, 6)}
REF_FUNCTIONS = {"noise3d-color-detail7/runtime": "refNoiseRuntime",
                 "noise3d-color-detail7/folded": "refNoiseFolded",
                 "userfbm/runtime": "refFbmRuntime", "userfbm/folded": "refFbmFolded"}
NATIVE_MODES = ("inline", "interp")
CLANG = "clang-15"
# The reference inlines every texture function into its loop, as PoCL's kernel compiler does:
# at clang's default threshold blVoronoiOctaveRows stayed a call (perf), so Voronoi's colour and
# position were computed and F1 kept its second distance (286 against 68 ns folded; the values
# are the same either way).
REF_INLINE = ["-mllvm", "-inline-threshold=100000"]
CL_FLAGS = ["-x", "cl", "-cl-std=CL1.2", "-Xclang", "-finclude-default-header",
            "--target=x86_64-linux-gnu", "-O3", "-ffp-contract=off"]


def bench_tools(build, work):
    """What common.Tools(build, work) gives (texcc, texrender, build, work, cache), made here:
    texcc_tools' Tools at 4949609 fails to construct (its loop variable `tool` shadows the
    function of that name)."""
    t = types.SimpleNamespace(texcc=os.path.join(build, "bin", "texcc"),
                              texrender=os.path.join(build, "bin", "texrender"), build=build,
                              work=work, cache=os.path.join(work, "cache"), device="0")
    for path in (t.texcc, t.texrender):
        if not os.access(path, os.X_OK):
            raise common.BenchError("%s: not built (ninja -C %s texcc texrender)" % (path, build))
    os.makedirs(t.cache, exist_ok=True)
    return t


def sh(cmd, env=None, cwd=None):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                       cwd=cwd)
    if r.returncode != 0:
        raise common.BenchError("%s failed (exit %d): %s" % (" ".join(cmd), r.returncode,
                                                             r.stderr.strip()[-1500:]))
    return r.stdout, r.stderr


def build_ref(work, march):
    """ref (ref.c + ref_textures.cl + ref_voronoi.cl) for -march=MARCH; returns the binary's
    path. ref_voronoi.cl is a translation unit of its own (voronoi.cl and noise.cl both define
    hash.h's functions): only its two entry points stay global (objcopy), so that the two
    objects' copies of the library do not clash at the link."""
    obj = os.path.join(work, "ref_textures.%s.o" % march)
    sh([CLANG] + CL_FLAGS + REF_INLINE + ["-march=" + march, "-c",
                                          os.path.join(REF_DIR, "ref_textures.cl"), "-o", obj])
    vor = os.path.join(work, "ref_voronoi.%s.o" % march)
    sh([CLANG] + CL_FLAGS + REF_INLINE + ["-march=" + march, "-c",
                                          os.path.join(REF_DIR, "ref_voronoi.cl"), "-o",
                                          vor + ".tmp"])
    sh(["objcopy", "--keep-global-symbol=refVoronoiRuntime",
        "--keep-global-symbol=refVoronoiFolded", vor + ".tmp", vor])
    exe = os.path.join(work, "ref.%s" % march)
    sh([CLANG, "-O3", "-march=" + march, os.path.join(REF_DIR, "ref.c"), obj, vor, "-lm", "-o",
        exe])
    return exe


def build_native(work, folder, march):
    """proctex_host over FOLDER's proctex.cl for -march=MARCH; returns the binary's path."""
    name = os.path.basename(folder.rstrip("/"))
    obj = os.path.join(work, "%s.%s.o" % (name, march))
    sh([CLANG] + CL_FLAGS + ["-march=" + march, "-I", os.path.join(common.ROOT, "kernels", "common"),
                             "-include", os.path.join(REF_DIR, "cl_compat.h"), "-w", "-c",
                             os.path.join(folder, "proctex.cl"), "-o", obj])
    exe = os.path.join(work, "%s.%s" % (name, march))
    sh([CLANG, "-O3", "-march=" + march, os.path.join(REF_DIR, "proctex_host.c"), obj, "-lm",
        "-o", exe])
    return exe


def max_outputs(folder):
    with open(os.path.join(folder, "proctex.cl")) as f:
        m = re.search(r"#define TEXCC_MAX_OUTPUTS (\d+)", f.read())
    return int(m.group(1)) if m else 1


def read_rows(path, cols=slice(None)):
    with open(path) as f:
        return [[float(v) for v in line.split()][cols] for line in f if line.strip()]


def max_abs_diff(a, b):
    if len(a) != len(b):
        raise common.BenchError("value dumps of different lengths: %d, %d" % (len(a), len(b)))
    return max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))


def callgrind_ir(cmd, toggle, env=None):
    """Instructions executed inside the functions matching toggle (callgrind)."""
    out = cmd[0] + ".callgrind.out"
    _, err = sh(["valgrind", "--tool=callgrind", "--toggle-collect=" + toggle,
                 "--callgrind-out-file=" + out] + cmd, env=env)
    os.remove(out)
    m = re.search(r"Collected : (\d+)", err)
    if not m:
        raise common.BenchError("no callgrind total in: %s" % err[-500:])
    return int(m.group(1))


def measure(args):
    work = args.work
    os.makedirs(work, exist_ok=True)
    tools = bench_tools(args.build, work)
    eval_tool = os.path.join(args.build, "bin", "texcc-eval")
    modes = args.modes.split(",")
    folders = {}
    for g, graph in GRAPHS.items():
        for mode in modes:
            folder = os.path.join(work, "%s-%s" % (g, mode))
            common.texcc(tools, graph, folder, mode)
            folders[(g, mode)] = folder
    ref = build_ref(work, "native")
    natives = {(g, m): build_native(work, folders[(g, m)], "native")
               for g in GRAPHS for m in NATIVE_MODES if m in modes}

    # Values: the reference at its points against texrender's inline mode (PoCL) there.
    points = os.path.join(work, "points.txt")
    ref_values = os.path.join(work, "ref-values.txt")
    sh([ref, "--points", str(args.grid), "--rounds", "1", "--dump-points", points,
        "--dump-values", ref_values])
    env1 = dict(os.environ, POCL_MAX_PTHREAD_COUNT="1")
    values = {}
    for g in GRAPHS:
        out, _ = sh([eval_tool, folders[(g, modes[0])], "--points", points], env=env1)
        pocl = [[float(v) for v in line.split()[3:6]] for line in out.splitlines() if line.strip()]
        d = {"texrender-" + modes[0]: max_abs_diff(read_rows(ref_values, REF_COLUMNS[g]), pocl)}
        for m in NATIVE_MODES:
            if (g, m) in natives:
                dump = os.path.join(work, "%s-%s.native-values.txt" % (g, m))
                sh([natives[(g, m)], os.path.join(folders[(g, m)], "args.bin"), "--points",
                    str(args.grid), "--rounds", "1", "--outputs", str(max_outputs(folders[(g, m)])),
                    "--dump-values", dump])
                d["native-" + m] = max_abs_diff(read_rows(ref_values, REF_COLUMNS[g]),
                                                read_rows(dump))
        values[g] = d
        common.log("%s: max abs difference of the reference to %s" % (g, d))

    samples = {g: {} for g in GRAPHS}
    loads = []

    def add(g, key, xs):
        samples[g].setdefault(key, []).extend(xs)

    for rep in range(args.reps):
        loads.append(os.getloadavg()[0])
        out, _ = sh([ref, "--points", str(args.grid), "--rounds", str(args.rounds)])
        r = json.loads(out)["variants"]
        for g, (rt, folded) in REF_VARIANTS.items():
            add(g, "ref-runtime", r[rt]["nsPerSample"])
            add(g, "ref-folded", r[folded]["nsPerSample"])
        for (g, m), exe in natives.items():
            out, _ = sh([exe, os.path.join(folders[(g, m)], "args.bin"), "--points", str(args.grid),
                         "--rounds", str(args.rounds), "--outputs",
                         str(max_outputs(folders[(g, m)]))])
            add(g, "native-" + m, json.loads(out)["nsPerSample"])
        for g in GRAPHS:
            out, _ = sh([eval_tool] + [folders[(g, m)] for m in modes] +
                        ["--time", str(args.rounds), "--grid", str(args.grid)], env=env1)
            for m, f in zip(modes, json.loads(out)["folders"]):
                add(g, "texrender-" + m, f["nsPerHit"])
        common.log("repetition %d of %d done (load %.1f)" % (rep + 1, args.reps, loads[-1]))
    loads.append(os.getloadavg()[0])

    rows = {}
    for g in GRAPHS:
        row = {k: {"medianNsPerSample": statistics.median(v), "minNsPerSample": min(v),
                   "samples": len(v)} for k, v in samples[g].items()}
        base = row["ref-folded"]["medianNsPerSample"]
        for k in row:
            row[k]["ratioToRefFolded"] = row[k]["medianNsPerSample"] / base
        rows[g] = {"configs": row, "maxAbsDiff": values[g]}
        common.log("%s: median ns/sample %s" % (g, {k: round(v["medianNsPerSample"], 1)
                                                    for k, v in row.items()}))

    data = {"machine": common.machine(), "git": common.git_head(), "grid": args.grid,
            "rounds": args.rounds, "reps": args.reps, "poclMaxPthreadCount": "1",
            "loadAverage1min": loads, "graphs": rows}
    common.save(None, data, args.out)
    if args.callgrind:
        cwork = os.path.join(work, "callgrind")
        os.makedirs(cwork, exist_ok=True)
        n = args.callgrind_points
        ref_h = build_ref(cwork, "haswell")
        for g, variants in REF_VARIANTS.items():
            for v, key in zip(variants, ("ref-runtime", "ref-folded")):
                # ref runs every variant once untimed and once per round: 2 runs of n points.
                ir = callgrind_ir([ref_h, "--points", str(n), "--rounds", "1"], REF_FUNCTIONS[v])
                rows[g]["configs"][key]["irPerSample"] = ir / (2.0 * n)
        for g in GRAPHS:
            for m in NATIVE_MODES:
                if m not in modes:
                    continue
                exe = build_native(cwork, folders[(g, m)], "haswell")
                ir = callgrind_ir([exe, os.path.join(folders[(g, m)], "args.bin"), "--points",
                                   str(n), "--rounds", "1", "--outputs",
                                   str(max_outputs(folders[(g, m)]))], "texcc_proctex")
                rows[g]["configs"]["native-" + m]["irPerSample"] = ir / (2.0 * n)
            common.log("%s: instructions per sample %s" % (g, {
                k: round(v["irPerSample"], 1) for k, v in rows[g]["configs"].items()
                if "irPerSample" in v}))
        common.save(None, data, args.out)
    return data


def measure_nodes(args):
    """Per-node ns per sample of the current textures/blender/ (and of --baseline REV's)."""
    from texcc_tools.bench import per_node_cycles
    work = args.work
    os.makedirs(work, exist_ok=True)
    tools = bench_tools(args.build, work)
    eval_tool = os.path.join(args.build, "bin", "texcc-eval")
    modes = args.modes.split(",")
    roots = {"current": os.path.join(common.ROOT, "textures", "blender")}
    if args.baseline:
        base = os.path.join(work, "baseline-src")
        os.makedirs(base, exist_ok=True)
        out, _ = sh(["git", "-C", common.ROOT, "ls-tree", "--name-only", args.baseline,
                     "textures/blender/"])
        for path in out.split():
            text, _ = sh(["git", "-C", common.ROOT, "show", "%s:%s" % (args.baseline, path)])
            with open(os.path.join(base, os.path.basename(path)), "w") as f:
                f.write(text)
        roots = {"baseline": base, "current": roots["current"]}
    folders = {}
    for name, (_, _, _, _, node) in per_node_cycles.NODES.items():
        for version, root in roots.items():
            graph = {"texcc": 1, "sources": [os.path.join(root, node["src"])],
                     "nodes": [{"id": "n", "fn": node["fn"], "args": node["args"]}],
                     "materials": {"m": {"bsdf": "diffuse", "color": {"node": "n"}}}}
            path = os.path.join(work, "%s-%s.json" % (name, version))
            with open(path, "w") as f:
                json.dump(graph, f)
            for mode in modes:
                folder = os.path.join(work, "%s-%s-%s" % (name, version, mode))
                common.texcc(tools, path, folder, mode)
                folders[(name, version, mode)] = folder
    env1 = dict(os.environ, POCL_MAX_PTHREAD_COUNT="1")
    identical = {}
    for name in per_node_cycles.NODES:
        dumps = {key: sh([eval_tool, folder, "--grid", str(args.grid)], env=env1)[0]
                 for key, folder in folders.items() if key[0] == name}
        first = dumps[(name, "current", modes[0])]
        identical[name] = all(d == first for d in dumps.values())
        common.log("%s: every version and mode gives the same values: %s" % (name, identical[name]))
    samples, loads = {}, []
    for rep in range(args.reps):
        loads.append(os.getloadavg()[0])
        for name in per_node_cycles.NODES:
            keys = [(name, v, m) for v in roots for m in modes]
            out, _ = sh([eval_tool] + [folders[k] for k in keys] +
                        ["--time", str(args.rounds), "--grid", str(args.grid)], env=env1)
            for k, f in zip(keys, json.loads(out)["folders"]):
                samples.setdefault(k, []).extend(f["nsPerHit"])
        common.log("repetition %d of %d done (load %.1f)" % (rep + 1, args.reps, loads[-1]))
    loads.append(os.getloadavg()[0])
    rows = {}
    for name in per_node_cycles.NODES:
        row = {}
        for version in roots:
            for mode in modes:
                xs = samples[(name, version, mode)]
                row.setdefault(version, {})[mode] = {"medianNsPerSample": statistics.median(xs),
                                                     "minNsPerSample": min(xs),
                                                     "samples": len(xs)}
        if "baseline" in roots:
            for mode in modes:
                row["current"][mode]["ratioToBaseline"] = (
                    row["current"][mode]["medianNsPerSample"] /
                    row["baseline"][mode]["medianNsPerSample"])
        rows[name] = {"versions": row, "identical": identical[name]}
        common.log("%s: median ns/sample %s" % (name, {
            "%s %s" % (v, m): round(row[v][m]["medianNsPerSample"], 1)
            for v in roots for m in modes}))
    data = {"machine": common.machine(), "git": common.git_head(), "baseline": args.baseline,
            "grid": args.grid, "rounds": args.rounds, "reps": args.reps,
            "poclMaxPthreadCount": "1", "loadAverage1min": loads, "nodes": rows}
    common.save(None, data, args.out)
    return data


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--grid", type=int, default=4096)
    ap.add_argument("--modes", default="inline,interp,shape")
    ap.add_argument("--callgrind", action="store_true")
    ap.add_argument("--callgrind-points", type=int, default=4096)
    ap.add_argument("--out", default=None)
    ap.add_argument("--nodes", action="store_true")
    ap.add_argument("--baseline", default=None)
    args = ap.parse_args()
    if args.nodes:
        args.work = args.work or os.path.join(args.build, "bench-texture-speed-nodes")
        args.out = args.out or os.path.join(common.RESULTS, "texture_speed_nodes.json")
        measure_nodes(args)
        return
    if args.baseline:
        raise common.BenchError("--baseline needs --nodes")
    args.work = args.work or os.path.join(args.build, "bench-texture-speed")
    args.out = args.out or os.path.join(common.RESULTS, "texture_speed.json")
    measure(args)
