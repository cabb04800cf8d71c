"""Figure: what a stage barrier costs a two-thread program beside a niced CPU load (issue 39
item 4, bench/threads.md).

bench/stage_barriers.c does the same CPU work on two threads pinned to CPUs 0 and 1, either
straight through ("steady", as Cycles' render threads work) or in stages of a given length
with a barrier between them (the threads that run out of chunks sleep until the host thread
starts the next stage, as PoCL's pthread workers do at the end of each command), and with
--spin-us, polling for the next stage for up to that long before they sleep; with --halves,
also each stage split into two independent halves (two chains of stages, each half as wide: a
thread whose chain waits at a barrier takes chunks of the other). Each round
runs every (load, configuration) pair once, in an order rotating with the round: quiet
(nothing added) and nice (`nice -n 10 stress-ng --cpu 2` in this session, bench/threads.py's
Stressor). The chunk's cost is calibrated once, quiet, before the rounds, so that every
configuration does the same work; the stage lengths are nominal (quiet).

    python3 bench/barriers.py [--rounds 4] [--seconds 2] [--stages-ms 1,5,10,20,40]
        [--spin-us 200,1000] [--halves] [--out FILE]
    python3 bench/barriers.py --report [FILE]

Results: bench/results/barriers.json.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

from texcc_tools.bench import common
from texcc_tools.bench.threads import Stressor

SOURCE = os.path.join(common.BENCH, "stage_barriers.c")


def build(work):
    exe = os.path.join(work, "stage_barriers")
    common.run(["cc", "-O2", "-pthread", SOURCE, "-o", exe])
    return exe


def wall(exe, argv):
    out = subprocess.run([exe] + argv, check=True, capture_output=True, text=True).stdout
    return float(out)


def configurations(exe, seconds, stages_ms, spins_us=(), halves=False):
    """{name: argv} of the steady run and staged runs per stage length (sleeping at once, then
    polling for each of spins_us first), each `seconds` of work on two threads (quiet), from a
    quiet calibration of one chunk's cost."""
    calib = 2000
    chunk = wall(exe, ["steady", "1", str(calib)]) * 2 / calib  # CPU seconds per chunk
    total = int(seconds * 2 / chunk)
    cfgs = {"steady": ["steady", "1", str(total)]}
    for ms in stages_ms:
        per = max(1, int(ms / 1000.0 * 2 / chunk))
        cfgs["stages %g ms" % ms] = ["stages", str(max(1, total // per)), str(per)]
        for us in spins_us:
            cfgs["stages %g ms, polling %g us" % (ms, us)] = cfgs["stages %g ms" % ms] + [
                str(int(us))]
        if halves:
            cfgs["stages %g ms in two halves" % ms] = ["halves"] + cfgs["stages %g ms" % ms][1:]
    return cfgs, chunk


def measure(args, exe):
    cfgs, chunk = configurations(exe, args.seconds, args.stages_ms, args.spin_us, args.halves)
    common.log("chunk %.1f us; %s" % (chunk * 1e6, cfgs))
    runs = {}
    keys = [(load, c) for load in ("quiet", "nice") for c in cfgs]
    for r in range(args.rounds):
        k = r % len(keys)
        for load, c in keys[k:] + keys[:k]:
            stressor = Stressor(load, 2)
            before = os.getloadavg()[0]
            try:
                w = wall(exe, cfgs[c])
            finally:
                stress = stressor.stop()
            runs.setdefault("%s/%s" % (load, c), []).append(
                {"round": r, "wall": w, "stressCpu": stress, "load1Before": before})
            common.log("round %d/%d %s %s: %.3f s" % (r + 1, args.rounds, load, c, w))
    return {"runs": runs, "configurations": cfgs, "chunkSeconds": chunk}


def report(data):
    med = common.median
    runs = data["runs"]
    lines = ["| configuration | quiet | nice | growth (paired) | the stressor's CPU s |",
             "|---|---|---|---|---|"]
    order = sorted(data["configurations"], key=lambda c: (c != "steady", float(
        c.split()[1]) if c != "steady" else 0.0, c))  # saved files sort their keys
    for c in order:
        q, n = runs["quiet/" + c], runs["nice/" + c]
        quiet = {s["round"]: s["wall"] for s in q}
        paired = [s["wall"] / quiet[s["round"]] - 1 for s in n if s["round"] in quiet]
        lines.append("| %s | %.2f s | %.2f s | %+.1f%% (%+.1f%%) | %.2f |" % (
            c, med([s["wall"] for s in q]), med([s["wall"] for s in n]),
            100 * (med([s["wall"] for s in n]) / med([s["wall"] for s in q]) - 1),
            100 * med(paired), med([s["stressCpu"] for s in n])))
    every = [s for v in runs.values() for s in v]
    lines.append("")
    lines.append("Load average (1 min) before the runs: %.1f-%.1f." % (
        min(s["load1Before"] for s in every), max(s["load1Before"] for s in every)))
    return "\n".join(lines)


def main():
    if sys.argv[1:2] == ["--report"]:
        common.print_report("barriers", sys.argv[2:3], report)
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=common.positive_int, default=4)
    ap.add_argument("--seconds", type=common.positive_number, default=2.0,
                    help="work per run, quiet")
    ap.add_argument("--stages-ms", type=common.positive_numbers, default=[1, 5, 10, 20, 40])
    ap.add_argument("--spin-us", type=common.positive_numbers, default=[],
                    help="also each stage length with its threads "
                    "polling for the next stage this long before they sleep (comma list)")
    ap.add_argument("--halves", action="store_true",
                    help="also each stage length split into two independent halves")
    ap.add_argument("--out", help="result file (default bench/results/barriers.json)")
    args = ap.parse_args()
    if len(os.sched_getaffinity(0)) < 2:
        raise common.BenchError("needs CPUs 0 and 1")
    t0 = time.perf_counter()
    data = measure(args, build(tempfile.mkdtemp(prefix="texcc-barriers-")))
    data.update(command="python3 bench/barriers.py " + " ".join(sys.argv[1:]),
                date=time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), git=common.git_head(),
                machine=common.machine(), seconds=time.perf_counter() - t0, complete=True,
                autogroupEnabled=open("/proc/sys/kernel/sched_autogroup_enabled").read().strip())
    common.save("barriers", data, args.out)
    print(report(data))
