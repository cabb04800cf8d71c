"""bench/run's driver: runs the figures (in the paper's priority order), saves
bench/results/<figure>.json and regenerates the charts and BENCHMARKS.md.

usage: bench/run [--quick] [--build DIR] [--device N] [--only FIGURE ...] [--report-only]
"""
import argparse
import os
import sys
import tempfile
import time

from texcc_tools.bench import (accuracy, ao, common, cycles, edit_session, edits, instructions,
                               lookdev, per_hit, report, resources, stability, table1,
                               value_stack)

# The stability sweep is last: its full run takes hours, and it saves its points as it goes.
FIGURES = [("table1", table1), ("edits", edits), ("edit_session", edit_session),
           ("instructions", instructions),
           ("per_hit", per_hit),
           ("resources", resources),
           ("value_stack", value_stack), ("accuracy", accuracy), ("ao", ao),
           ("cycles", cycles), ("lookdev", lookdev), ("stability", stability)]


def main():
    ap = argparse.ArgumentParser(description="texcc benchmarks")
    ap.add_argument("--quick", action="store_true", help="small sizes (under 15 minutes)")
    common.add_build_argument(ap)
    ap.add_argument("--device", default="0")
    ap.add_argument("--only", nargs="*", choices=[n for n, _ in FIGURES])
    ap.add_argument("--report-only", action="store_true", help="only regenerate the report")
    ap.add_argument("--note", help="a sentence on the binaries used, kept in bench/results/note.json")
    args = ap.parse_args()
    if args.note is not None:
        common.save("note", {"note": args.note})
    if not args.report_only:
        run_figures(args)
    report.write(args)
    return 0


def ensure_scenes():
    """The atrium's meshes are generated (git-ignored): make them when missing."""
    if not os.path.exists(os.path.join(common.ROOT, "examples", "atrium", "generated",
                                       "atrium.obj")):
        common.log("generating the atrium (scripts/make_scenes.py --only atrium)")
        common.run([sys.executable, os.path.join(common.ROOT, "scripts", "make_scenes.py"),
                    "--only", "atrium"])


def run_figures(args):
    ensure_scenes()
    tools = common.Tools(os.path.abspath(args.build), tempfile.mkdtemp(prefix="texcc-bench-"),
                         args.device)
    start = time.perf_counter()
    for name, module in FIGURES:
        if args.only and name not in args.only:
            continue
        t0 = time.perf_counter()

        def save(data, complete=True, name=name, t0=t0):
            data["complete"] = complete
            data["quick"] = args.quick
            data["seconds"] = time.perf_counter() - t0
            data["date"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
            data["build"] = (os.path.relpath(tools.build, common.ROOT)
                             if tools.build.startswith(common.ROOT + os.sep) else tools.build)
            data["loadAverage"] = os.getloadavg()[1]
            data["command"] = "bench/run" + (" --quick" if args.quick else "") + \
                (" --only " + name if args.only else "")
            data["machine"] = common.machine()
            data["git"] = common.git_head()
            common.save(name, data)

        if getattr(module, "CHECKPOINTS", False):
            # Saved after every point, marked incomplete, so that a run cut short keeps them.
            data = module.measure(tools, args.quick, lambda d: save(d, complete=False))
        else:
            data = module.measure(tools, args.quick)
        save(data)
        common.log("%s done in %.0f s" % (name, data["seconds"]))
    common.log("all figures in %.0f s" % (time.perf_counter() - start))

