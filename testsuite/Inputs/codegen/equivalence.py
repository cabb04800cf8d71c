#!/usr/bin/env python3
"""Equivalence of the evaluation modes on one graph: compiles it with texcc for the host target
(the oracle) and for interp, inline, wavefront and shape, evaluates each with texcc-eval over the
same grid of hits, and compares every mode with the host (compare.py, max abs diff <= --tol).
Shape mode must also agree bit for bit (--tol 0) with its interp fallback, proctex.interp.cl,
which the tiered runtime swaps in while a new shape's kernel builds. An interp kernel that
hoists values (layout.json kernel.uniforms) interp --no-hoist, and one with quickened opcodes
interp --max-quickened=0. Every mode after interp
must equal interp bit for bit too: every kernel has FP_CONTRACT OFF, so the modes differ only in
how the same user code is called, never in its arithmetic.

usage: equivalence.py --texcc TEXCC --eval TEXCC_EVAL --work DIR --grid N GRAPH [GRAPH ...]
                      [--tol 1e-5] [--modes interp,inline,wavefront,shape]
                      [-- extra texcc options]
Exit 0 when every mode of every graph agrees, 1 otherwise (each failure is printed).
"""
import argparse
import os
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

from texcc_tools import manifest

HERE = os.path.dirname(os.path.abspath(__file__))


def run(cmd, lines, out_path=None):
    with open(out_path, "w") if out_path else open(os.devnull, "w") as out:
        r = subprocess.run(cmd, stdout=out, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        lines.append("command failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr))
        return False
    return True


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    ap = argparse.ArgumentParser()
    ap.add_argument("--texcc", required=True)
    ap.add_argument("--eval", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--grid", type=int, default=32)
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--modes", default="interp,inline,wavefront,shape")
    ap.add_argument("graphs", nargs="+")
    args = ap.parse_args(argv)
    os.makedirs(args.work, exist_ok=True)
    modes = args.modes.split(",")
    jobs = [(g, graph, args, modes, extra) for g, graph in enumerate(args.graphs)]
    with ThreadPoolExecutor(max_workers=max(1, min(4, os.cpu_count() or 1))) as pool:
        results = list(pool.map(lambda job: check_graph(*job), jobs))
    failures = 0
    for lines, failed in results:
        for line in lines:
            print(line)
        failures += failed
    total = len(args.graphs) * len(modes)
    print("equivalence: %d of %d (graph, mode) pairs agree with the host target"
          % (total - failures, total))
    return 1 if failures else 0


def compare(ref, dump, tol, label, lines):
    r = subprocess.run([sys.executable, os.path.join(HERE, "compare.py"), ref, dump,
                        "--tol", str(tol), "--label", label], stdout=subprocess.PIPE, text=True)
    lines.append(r.stdout.strip())
    return r.returncode == 0


def check_fallback(out, dump, graph, args, lines):
    """Evaluates shape mode's proctex.interp.cl (same layout.json and args.bin) and requires the
    shape kernel's values bit for bit (%.9g round-trips a float)."""
    fallback = out + "-fallback"
    os.makedirs(fallback, exist_ok=True)
    shutil.copyfile(os.path.join(out, "args.bin"), os.path.join(fallback, "args.bin"))
    # The interp tier ignores the hoisted values in args.bin and has no texcc_uniforms kernel
    # to compute them (the runtime runs it for the shape tier only).
    layout = manifest.load(out)
    layout["kernel"].pop("uniforms", None)
    manifest.save(fallback, layout)
    shutil.copyfile(os.path.join(out, "proctex.interp.cl"), os.path.join(fallback, "proctex.cl"))
    fallback_dump = fallback + ".txt"
    return (run([args.eval, fallback, "--grid", str(args.grid)], lines, fallback_dump)
            and compare(dump, fallback_dump, 0.0, "%s shape = its interp fallback" % graph,
                        lines))


def check_unhoisted(out, dump, graph, args, extra, lines):
    """interp whose kernel hoists (layout.json kernel.uniforms) against interp --no-hoist, bit
    for bit; true without a check when nothing is hoisted."""
    layout = manifest.load(out)
    if not layout["kernel"].get("uniforms"):
        return True
    hoisted = sum(len(fn["hoisted"]["values"]) for fn in layout["functions"] if "hoisted" in fn)
    plain = out + "-unhoisted"
    plain_dump = plain + ".txt"
    if not (run([args.texcc, "--mode=interp", "--no-hoist", "--graph", graph, "-o", plain] +
                extra, lines)
            and run([args.eval, plain, "--grid", str(args.grid)], lines, plain_dump)):
        return False
    return compare(dump, plain_dump, 0.0, "%s interp = interp --no-hoist (hoisted values %d)"
                   % (graph, hoisted), lines)


def check_unquickened(out, dump, graph, args, extra, lines):
    """interp with quickened opcodes (layout.json "quickened") against --max-quickened=0, bit
    for bit; true without a check when the table is empty."""
    quickened = manifest.load(out).get("quickened", [])
    if not quickened:
        return True
    plain = out + "-unquickened"
    plain_dump = plain + ".txt"
    if not (run([args.texcc, "--mode=interp", "--graph", graph, "-o", plain] + extra +
                ["--max-quickened=0"], lines)
            and run([args.eval, plain, "--grid", str(args.grid)], lines, plain_dump)):
        return False
    return compare(dump, plain_dump, 0.0, "%s interp = interp --max-quickened=0 (quickened %d)"
                   % (graph, len(quickened)), lines)


def check_graph(g, graph, args, modes, extra):
    """Compiles and evaluates one graph for the host and every mode; (report lines, failures)."""
    lines, failures = [], 0
    interp_dump = None
    base = os.path.join(args.work, "%d-%s" % (g, os.path.splitext(os.path.basename(graph))[0]))
    host_out = base + "-host"
    ref = host_out + ".txt"
    if not (run([args.texcc, "--target=host", "--graph", graph, "-o", host_out] + extra, lines)
            and run([args.eval, host_out, "--grid", str(args.grid), "--host"], lines, ref)):
        return lines, len(modes)
    for mode in modes:
        out = base + "-" + mode
        dump = out + ".txt"
        ok = (run([args.texcc, "--mode=" + mode, "--graph", graph, "-o", out] + extra, lines)
              and run([args.eval, out, "--grid", str(args.grid)], lines, dump))
        ok = ok and compare(ref, dump, args.tol, "%s %s" % (graph, mode), lines)
        if ok and mode == "shape":
            ok = check_fallback(out, dump, graph, args, lines)
        if ok and mode == "interp":
            ok = check_unhoisted(out, dump, graph, args, extra, lines)
            ok = ok and check_unquickened(out, dump, graph, args, extra, lines)
            interp_dump = dump
        elif ok and interp_dump:
            ok = compare(interp_dump, dump, 0.0, "%s %s = interp" % (graph, mode), lines)
        failures += 0 if ok else 1
    return lines, failures


if __name__ == "__main__":
    sys.exit(main())
