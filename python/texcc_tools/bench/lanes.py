"""Figure: the frame of bench/threads.py (the atrium with rust everywhere) rendered by one
texrender whole (`whole`: `--lanes off`, the stages shared by both cores, a barrier at each
stage's end), by one texrender in lanes (`texrender-lanes`: its default, one lane per core,
docs/cli.md) and as two lanes in two processes (`lanes`: two `texrender --threads 1` processes
at once, each rendering half of the film with `--region`, the top and bottom halves; stitched,
the halves equal the whole bit for bit, docs/runtime.md), so that no stage waits for a thread on
the other core. --configs picks them (default: all three). Quiet and beside
`nice -n 10 stress-ng --cpu 2` in this session (bench/threads.py's Stressor); each round runs
every (load, configuration) pair once, in an order rotating with the round. The time of the
lanes is the wall time until both have ended; `frame` is the longer of their renderSeconds
(issue 39 item 4, bench/threads.md). --cycles adds Cycles (bpy) rendering the same scene's
.blend in the same rounds, measured as bench/threads.py measures it: its wall time is that of
bpy.ops.render.render() in a warm bpy process, its frame that less the fixed part.

    python3 bench/lanes.py [--build DIR] [--rounds 5] [--size 512x512] [--spp 16]
        [--configs whole,texrender-lanes,lanes] [--cycles [--blend B]] [--out FILE]
    python3 bench/lanes.py --report [FILE]

Results: bench/results/lanes.json.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

from texcc_tools.bench import common, cycles, texture_speed
from texcc_tools.bench import threads as th

CONFIGS = ("whole", "texrender-lanes", "lanes", "cycles")


def render(tools, scene, textures, size, spp, config):
    """(wall seconds, frame seconds) of the frame in configuration config (not cycles)."""
    w, h = (int(x) for x in size.split("x"))
    jobs = [["--lanes", "off"]] if config == "whole" else [[]] if config == "texrender-lanes" else [
        ["--threads", "1", "--region", "0,0,%d,%d" % (w, h // 2)],
        ["--threads", "1", "--region", "0,%d,%d,%d" % (h // 2, w, h - h // 2)]]
    outs = [os.path.join(tools.work, "lane%d" % i) for i in range(len(jobs))]
    t0 = time.perf_counter()
    procs = []
    for out, extra in zip(outs, jobs):
        cmd = th.command(tools, scene, textures, size, spp, 0, os.path.basename(out))[1] + extra
        procs.append((cmd, out, subprocess.Popen(cmd, stdout=subprocess.DEVNULL,
                                                 stderr=subprocess.PIPE)))
    frames = []
    for cmd, out, p in procs:
        _, err = p.communicate()
        frames.append(th.finished(cmd, p.returncode, err, out)["renderSeconds"])
    return time.perf_counter() - t0, max(frames)


def configs(text):
    """--configs: a comma-separated list of texrender's configurations."""
    out = text.split(",")
    bad = [c for c in out if c not in CONFIGS[:-1]]
    if bad or not text:
        raise argparse.ArgumentTypeError("expected some of %s, got %r" % (",".join(CONFIGS[:-1]), text))
    return out


def measure(args, tools):
    scene, textures = th.inputs(tools)
    render(tools, scene, textures, args.size, args.spp, "whole")  # warm: kernels cached
    runs = {}
    w, h = (int(x) for x in args.size.split("x"))
    cyc, fixed = None, []
    if args.cycles:
        blend = args.blend or cycles.make_blends(tools, ("rust-all",))["rust-all"]
        cyc = cycles.Cycles()
        cyc.call(op="render", blend=blend, size=[w, h], spp=1)  # warm
        fixed = [cyc.call(op="render", blend=blend, size=[16, 16], spp=1)["seconds"]
                 for _ in range(3)]

    def one(c):
        if c != "cycles":
            return render(tools, scene, textures, args.size, args.spp, c)
        raw = cyc.call(op="render", blend=blend, size=[w, h], spp=args.spp)["seconds"]
        return raw, raw - common.median(fixed)

    keys = [(load, c) for load in ("quiet", "nice") for c in args.configs + (["cycles"] if cyc else [])]
    for r in range(args.rounds):
        k = r % len(keys)
        for load, c in keys[k:] + keys[:k]:
            before = os.getloadavg()[0]
            stressor = th.Stressor(load, 2)
            try:
                wall, frame = one(c)
            finally:
                stress = stressor.stop()
            runs.setdefault("%s/%s" % (load, c), []).append(
                {"round": r, "wall": wall, "frame": frame, "stressCpu": stress,
                 "load1Before": before})
            common.log("round %d/%d %s %s: %.2f s" % (r + 1, args.rounds, load, c, wall))
    if cyc:
        cyc.close()
    return {"runs": runs, "cyclesFixed": fixed}


def report(data):
    med = common.median
    runs = data["runs"]
    lines = ["| configuration | quiet (wall) | nice (wall) | growth (paired) | frame quiet / nice "
             "| the stressor's CPU s |", "|---|---|---|---|---|---|"]
    for c in (c for c in CONFIGS if "quiet/" + c in runs):
        q, n = runs["quiet/" + c], runs["nice/" + c]
        quiet = {s["round"]: s["wall"] for s in q}
        paired = [s["wall"] / quiet[s["round"]] - 1 for s in n if s["round"] in quiet]
        row = "| %s | %.2f s (%s) | %.2f s (%s) | %+.1f%% (%+.1f%%) | %.2f / %.2f s | %.2f |"
        lines.append(row % (
            c, med([s["wall"] for s in q]), ", ".join("%.2f" % s["wall"] for s in q),
            med([s["wall"] for s in n]), ", ".join("%.2f" % s["wall"] for s in n),
            100 * (med([s["wall"] for s in n]) / med([s["wall"] for s in q]) - 1),
            100 * med(paired), med([s["frame"] for s in q]), med([s["frame"] for s in n]),
            med([s["stressCpu"] for s in n])))
    every = [s for v in runs.values() for s in v]
    lines.append("")
    lines.append("Load average (1 min) before the renders: %.1f-%.1f." % (
        min(s["load1Before"] for s in every), max(s["load1Before"] for s in every)))
    return "\n".join(lines)


def main():
    if sys.argv[1:2] == ["--report"]:
        common.print_report("lanes", sys.argv[2:3], report)
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--rounds", type=common.positive_int, default=5)
    ap.add_argument("--size", type=common.film_size, default="512x512")
    ap.add_argument("--spp", type=common.positive_int, default=16)
    ap.add_argument("--configs", type=configs, default="whole,texrender-lanes,lanes",
                    help="texrender's configurations, of " + ", ".join(CONFIGS[:-1]))
    ap.add_argument("--cycles", action="store_true", help="Cycles (bpy) in the same rounds")
    ap.add_argument("--blend", help="the rust-all .blend (default: made by make_scene.py)")
    ap.add_argument("--out", help="result file (default bench/results/lanes.json)")
    args = ap.parse_args()
    if args.cycles:
        cycles.ensure_bpy()
    t0 = time.perf_counter()
    tools = texture_speed.bench_tools(args.build, tempfile.mkdtemp(prefix="texcc-lanes-"))
    data = measure(args, tools)
    data.update(command="python3 bench/lanes.py " + " ".join(sys.argv[1:]),
                date=time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), git=common.git_head(),
                machine=common.machine(), seconds=time.perf_counter() - t0, complete=True)
    common.save("lanes", data, args.out)
    print(report(data))
