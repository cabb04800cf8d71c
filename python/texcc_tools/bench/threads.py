"""Figure: texrender's frame alone and beside a competing niced CPU load, per --threads, with
Cycles under the same loads (issue 39 item 4).

The scene is the atrium with rust everywhere (bench/cycles.py's "rust-all": examples/atrium
with every mesh given examples/rust's material; Cycles renders the .blend that
examples/blender/make_scene.py builds for it, Blender's own rust nodes, so the two compare the
same kind of work, not the same pixels). Loads:

- quiet: nothing added (the machine is shared: other work runs; its load average is recorded
  before every render);
- nice: `nice -n 10 stress-ng --cpu K` started by this script, in its session (the renderers'
  autogroup), before the render and stopped after it;
- nice-setsid: the same, started with setsid(): a session and so an autogroup of its own.
  With CONFIG_SCHED_AUTOGROUP on (/proc/sys/kernel/sched_autogroup_enabled), the scheduler
  first shares the CPU between autogroups, and nice only weighs threads within one: a niced
  load in another session takes as much as a load at nice 0 would.

Each round renders every (load, renderer) pair once, in an order that rotates with the round;
the figures are medians over the rounds. texrender's frame is stats.json's renderSeconds (no
BVH or kernel build; kernels are cached by a warm-up render); Cycles' is the time of
bpy.ops.render.render() in one warm bpy process, less its fixed part (scene sync and BVH: the
median of three 16x16 1 spp renders) as bench/cycles.py does; its raw time is kept too. The
stressor's CPU seconds (wait4) and texrender's are recorded per render.

--profile samples the states of texrender's threads (/proc/PID/task/*/stat) every 2 ms during
one quiet render per --threads value: how many are runnable at once, i.e. how many threads
the frame's critical path keeps busy (PoCL's pool and the trace backend's take turns).

    python3 bench/threads.py [--rounds 3] [--size 256x256] [--spp 8] [--threads 0,1,2,4]
        [--stress 2] [--loads quiet,nice,nice-setsid] [--cycles] [--profile] [--out FILE]

--baseline-build DIR adds texrender from another build (without --threads) to every round:
a change and the build before it, interleaved. --waits records per render the seconds
texrender's threads were runnable but waiting for a CPU (/proc/PID/task/*/schedstat).

--threads 0 is texrender without --threads (every core). Results: bench/results/threads.json;
bench/threads.md reports them (`python3 bench/threads.py --report [FILE]` prints its tables).
"""
import argparse
import collections
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

from texcc_tools.bench import common, cycles, texture_speed


def autogroup(pid):
    try:
        with open("/proc/%d/autogroup" % pid) as f:
            return f.read().split()[0]
    except OSError:
        return None


class Stressor:
    """`nice -n 10 stress-ng --cpu K`, in this session or (setsid) in one of its own."""

    def __init__(self, kind, workers):
        self.kind = kind
        self.p = None
        if kind == "quiet":
            return
        self.p = subprocess.Popen(["nice", "-n", "10", "stress-ng", "--cpu", str(workers),
                                   "--timeout", "0", "--quiet"],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                  start_new_session=(kind == "nice-setsid"))
        # Its workers are forked at once; wait until they exist (not a timing window: the
        # children are read back from /proc).
        deadline = time.time() + 10
        while time.time() < deadline and len(self.children()) < workers:
            time.sleep(0.01)
        self.group = autogroup(self.p.pid)

    def children(self):
        try:
            with open("/proc/%d/task/%d/children" % (self.p.pid, self.p.pid)) as f:
                return f.read().split()
        except OSError:
            return []

    def stop(self):
        """Stops it; returns its CPU seconds (user + sys, its workers included)."""
        if not self.p:
            return 0.0
        self.p.send_signal(signal.SIGTERM)
        _, _, ru = os.wait4(self.p.pid, 0)
        self.p.returncode = 0
        return ru.ru_utime + ru.ru_stime


def command(tools, scene, textures, size, spp, threads, name):
    """(output path without extension, texrender's command line) of one render."""
    out = os.path.join(tools.work, name)
    return out, [tools.texrender, scene, "--textures", textures, "-o", out + ".png", "--stats",
                 out + ".json", "--quiet", "--cache-dir", tools.cache, "--size", size, "--spp",
                 str(spp)] + (["--threads", str(threads)] if threads else [])


def finished(cmd, returncode, err, out):
    """The stats.json of a render that ended; BenchError if it failed."""
    if returncode != 0:
        raise common.BenchError("texrender failed (exit %d): %s\n%s" % (
            returncode, " ".join(cmd), err.decode()[-2000:]))
    with open(out + ".json") as f:
        return json.load(f)


def texrender(tools, scene, textures, size, spp, threads, name, profile=False):
    out, cmd = command(tools, scene, textures, size, spp, threads, name)
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    samples = collections.Counter() if profile else None
    if profile:
        while p.poll() is None:
            samples[runnable(p.pid)] += 1
            time.sleep(0.002)
    out_, err = p.communicate()
    wall = time.perf_counter() - t0
    stats = finished(cmd, p.returncode, err, out)
    r = {"frame": stats["renderSeconds"], "total": stats["totalSeconds"], "wall": wall,
         "threads": stats["threads"]}
    if profile:
        r["runnableSamples"] = {str(k): v for k, v in sorted(samples.items())}
    return r


def schedstat(pid, last):
    """Reads /proc/PID/task/*/schedstat into last[tid] = (seconds on a CPU, seconds runnable
    but waiting for one): the scheduler's own accounting (Documentation/scheduler/sched-stats)."""
    try:
        tids = os.listdir("/proc/%d/task" % pid)
    except OSError:
        return
    for tid in tids:
        try:
            with open("/proc/%d/task/%s/schedstat" % (pid, tid)) as f:
                run, wait = f.read().split()[:2]
        except (OSError, ValueError):
            continue
        last[tid] = (int(run) / 1e9, int(wait) / 1e9)


def texrender_cpu(tools, scene, textures, size, spp, threads, name, waits=False):
    """texrender() with its CPU seconds (wait4: user + sys of the process). waits: also the
    seconds its threads were runnable but not running (schedstat, read every 5 ms: a thread's
    last 5 ms before it ends are missed)."""
    out, cmd = command(tools, scene, textures, size, spp, threads, name)
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    last = {}
    status = ru = None
    while waits:
        pid, status, ru = os.wait4(p.pid, os.WNOHANG)
        if pid:
            break
        schedstat(p.pid, last)
        time.sleep(0.005)
    err = p.stderr.read()
    if ru is None:
        _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - t0
    stats = finished(cmd, p.returncode, err, out)
    # kernelSeconds: the stages' own times (OpenCL profiling start to end, the Embree stages'
    # wall time); the rest of renderSeconds is the host between them: launches, maps, and the
    # hand-offs (a pool's workers woken, the host thread woken when they finish).
    return {"frame": stats["renderSeconds"], "total": stats["totalSeconds"], "wall": wall,
            "cpu": ru.ru_utime + ru.ru_stime, "threads": stats["threads"],
            "kernelSeconds": stats["kernelSeconds"],
            **({"runQueueWait": sum(w for _, w in last.values())} if waits else {})}


def runnable(pid):
    """How many threads of pid are running or runnable (state R)."""
    n = 0
    try:
        for t in os.listdir("/proc/%d/task" % pid):
            try:
                with open("/proc/%d/task/%s/stat" % (pid, t)) as f:
                    stat = f.read()
            except OSError:
                continue
            if stat[stat.rindex(")") + 2] == "R":
                n += 1
    except OSError:
        pass
    return n


def inputs(tools):
    """(scene, textures) of texrender's rust everywhere, and the Cycles .blend (or None)."""
    graph, scene, everywhere = cycles.TEXRENDER["rust-all"]
    textures = os.path.join(tools.work, "tex-rust")
    common.run([tools.texcc, "--graph", os.path.join(common.ROOT, graph), "-o", textures])
    path = os.path.join(common.ROOT, scene)
    with open(path) as f:
        s = json.load(f)
    for mesh in s["meshes"]:
        mesh["material"] = everywhere
        mesh["obj"] = os.path.join(os.path.dirname(path), mesh["obj"])
    out = os.path.join(tools.work, "atrium-rust-all.json")
    with open(out, "w") as f:
        json.dump(s, f, indent=1)
    return out, textures


def measure(args, tools, save):
    scene, textures = inputs(tools)
    threads = [int(t) for t in args.threads.split(",")]
    renderers = ["texrender-%s" % (t or "default") for t in threads]
    builds = {r: tools for r in renderers}
    if args.baseline_build:
        renderers.append("texrender-baseline")
        builds["texrender-baseline"] = texture_speed.bench_tools(args.baseline_build, tools.work)
    cyc = blend = None
    fixed = []
    w, h = (int(x) for x in args.size.split("x"))
    if args.cycles:
        blend = args.blend or cycles.make_blends(tools, ("rust-all",))["rust-all"]
        cyc = cycles.Cycles()
        renderers.append("cycles")
        cyc.call(op="render", blend=blend, size=[w, h], spp=1)  # warm
        for _ in range(3):
            fixed.append(cyc.call(op="render", blend=blend, size=[16, 16], spp=1)["seconds"])
    # Kernels into the cache, at the measured spp: PoCL compiles a second work-group function
    # for launches of 65536 work-items or more (ClContext.h), which 1 spp at 256x256 misses.
    for b in {id(t): t for t in builds.values()}.values():
        texrender(b, scene, textures, args.size, args.spp, 0, "warm")
    loads = args.loads.split(",")
    configs = [(l, r) for l in loads for r in renderers]
    runs = {"%s/%s" % c: [] for c in configs}
    data = {"size": args.size, "spp": args.spp, "stressWorkers": args.stress,
            "cyclesFixed": fixed, "runs": runs, "autogroupEnabled": open(
                "/proc/sys/kernel/sched_autogroup_enabled").read().strip(),
            "driverAutogroup": autogroup(os.getpid())}
    for rnd in range(args.rounds):
        k = rnd % len(configs)
        for load, r in configs[k:] + configs[:k]:
            common.log("threads figure: round %d/%d %s %s" % (rnd + 1, args.rounds, load, r))
            before = os.getloadavg()
            st = Stressor(load, args.stress)
            try:
                if r == "cycles":
                    c0 = cpu_seconds(cyc.p.pid)
                    s = cyc.call(op="render", blend=blend, size=[w, h], spp=args.spp)
                    sample = {"raw": s["seconds"], "frame": s["seconds"] - common.median(fixed),
                              "cpu": cpu_seconds(cyc.p.pid) - c0}
                else:
                    t = r.split("-")[1]
                    sample = texrender_cpu(builds[r], scene, textures, args.size, args.spp,
                                           0 if t in ("default", "baseline") else int(t), "r",
                                           waits=args.waits)
            finally:
                sample_stress = st.stop()
            sample.update({"round": rnd, "load1Before": before[0],
                           "load1After": os.getloadavg()[0], "stressCpu": sample_stress,
                           "stressAutogroup": getattr(st, "group", None)})
            runs["%s/%s" % (load, r)].append(sample)
        save(data)
    data["medians"] = {c: {"frame": common.median([s["frame"] for s in v])}
                       for c, v in runs.items() if v}
    if args.profile:
        data["profile"] = {}
        for t in threads:
            common.log("threads figure: profile --threads %s" % (t or "default"))
            data["profile"][str(t or "default")] = texrender(
                tools, scene, textures, args.size, args.spp, t, "profile", profile=True)
    if cyc:
        cyc.close()
    return data


BUSY = "import time\nend = time.time() + %f\nwhile time.time() < end: pass\n"


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def autogroup_check(seconds=4.0, cpu=None):
    """Two busy loops on one CPU, their CPU seconds read halfway through `seconds`: A at nice 0
    in this session, B at nice 10 in this session, in a session of its own (setsid), and in
    its own session with its autogroup niced to 10 (/proc/PID/autogroup). Returns each case's
    CPU seconds of A and B: how much a niced competitor takes from a thread of this session in
    each arrangement."""
    cpu = cpu if cpu is not None else max(os.sched_getaffinity(0))
    out = {}
    for case in ("same-session", "setsid", "setsid+autogroup-nice"):
        cmd = [sys.executable, "-c", BUSY % seconds]
        a = subprocess.Popen(["taskset", "-c", str(cpu)] + cmd)
        b = subprocess.Popen(["taskset", "-c", str(cpu), "nice", "-n", "10"] + cmd,
                             start_new_session=(case != "same-session"))
        if case == "setsid+autogroup-nice":
            with open("/proc/%d/autogroup" % b.pid, "w") as f:
                f.write("10")
        time.sleep(seconds / 2)
        a_cpu, b_cpu = cpu_seconds(a.pid), cpu_seconds(b.pid)
        a.wait(), b.wait()
        out[case] = {"A": a_cpu, "B": b_cpu, "B share": b_cpu / max(a_cpu + b_cpu, 1e-9),
                     "load1": os.getloadavg()[0]}
        common.log("autogroup check %s: A %.2f s, B %.2f s of CPU in %.1f s" % (
            case, a_cpu, b_cpu, seconds / 2))
    return out


# The scheduler's weights of nice 0 and nice 10 (sched_prio_to_weight): a thread of the renderer
# sharing a core with one niced stressor thread runs 1024 / (1024 + 110) of the time.
WEIGHT_NICE0, WEIGHT_NICE10 = 1024, 110


def cores_busy(s):
    """CPU seconds over wall seconds of one render: texrender's whole process (wall), Cycles'
    render call (raw: its frame with its fixed part); None where not recorded."""
    wall = s.get("wall", s.get("raw"))
    return s["cpu"] / wall if "cpu" in s and wall else None


def decomposition(runs, loads, renderers):
    """A frame's growth beside the load, split per round into what the renderer had to do
    (CPU factor: its CPU seconds beside the load over the same round's quiet ones) and how much
    of the machine it got (share factor: cores busy quiet over cores busy beside the load);
    growth = CPU factor x share factor, the fixed parts aside. Beside a niced stressor with a
    thread per core, a renderer that keeps every core busy gets at best 1024 / (1024 + 110) of
    each: share factor 1 + 110 / 1024 = 1.107 (the fair-share floor)."""
    med = common.median
    out = ["", "| renderer | load | cores busy, quiet | cores busy, load | share factor "
           "(floor %.3f) | CPU factor | product |" % (1 + WEIGHT_NICE10 / WEIGHT_NICE0),
           "|---|---|---|---|---|---|---|"]
    rows = 0
    for r in renderers:
        quiet = {s["round"]: s for s in runs.get("quiet/" + r, [])}
        for l in loads:
            if l == "quiet":
                continue
            pairs = [(quiet[s["round"]], s) for s in runs.get("%s/%s" % (l, r), [])
                     if s["round"] in quiet and cores_busy(s) and cores_busy(quiet[s["round"]])]
            if not pairs:
                continue
            share = med([cores_busy(q) / cores_busy(s) for q, s in pairs])
            cpu = med([s["cpu"] / q["cpu"] for q, s in pairs])
            out.append("| %s | %s | %.2f | %.2f | %.3f | %.3f | %.3f |" % (
                r, l, med([cores_busy(q) for q, _ in pairs]),
                med([cores_busy(s) for _, s in pairs]), share, cpu, share * cpu))
            rows += 1
    return out if rows else []


def report(data):
    """The markdown tables of bench/threads.md from a result file."""
    if "autogroupCheck" in data:  # --autogroup-check's file
        return "\n".join(["| case | A's CPU s | B's CPU s | B's share |", "|---|---|---|---|"] + [
            "| %s | %.2f | %.2f | %.0f%% |" % (c, v["A"], v["B"], 100 * v["B share"])
            for c, v in data["autogroupCheck"].items()])
    runs = data["runs"]
    loads = sorted({c.split("/")[0] for c in runs}, key=["quiet", "nice", "nice-setsid"].index)
    renderers = sorted({c.split("/")[1] for c in runs})
    med = common.median
    lines = ["| renderer | " + " | ".join(loads) + " | " + " | ".join(
        "%s growth (paired)" % l for l in loads if l != "quiet") + " |",
        "|---" * (1 + 2 * len(loads) - 1) + "|"]
    for r in renderers:
        cells = []
        for l in loads:
            v = runs.get("%s/%s" % (l, r), [])
            cells.append("%.2f s (%s)" % (med([s["frame"] for s in v]), ", ".join(
                "%.2f" % s["frame"] for s in v)) if v else "-")
        quiet = {s["round"]: s["frame"] for s in runs.get("quiet/" + r, [])}
        for l in loads:
            if l == "quiet":
                continue
            v = runs.get("%s/%s" % (l, r), [])
            ratios = [s["frame"] / quiet[s["round"]] - 1 for s in v if s["round"] in quiet]
            allq = [s["frame"] for s in runs.get("quiet/" + r, [])]
            cells.append("%+.0f%% (%+.0f%%)" % (
                100 * (med([s["frame"] for s in v]) / med(allq) - 1), 100 * med(ratios))
                if v and ratios else "-")
        lines.append("| %s | %s |" % (r, " | ".join(cells)))
    lines.append("")
    lines.append("| renderer | " + " | ".join(
        "%s: CPU s per render (user + sys), median | %s: the stressor's CPU s" % (l, l)
        for l in loads) + " |")
    lines.append("|---" * (1 + 2 * len(loads)) + "|")
    for r in renderers:
        cells = []
        for l in loads:
            v = runs.get("%s/%s" % (l, r), [])
            t = [s["cpu"] for s in v if "cpu" in s]
            cells.append("%.2f" % med(t) if t else "-")
            cells.append("%.2f" % med([s["stressCpu"] for s in v]) if v else "-")
        lines.append("| %s | %s |" % (r, " | ".join(cells)))
    every = [s for vs in runs.values() for s in vs]
    lines.append("")
    lines.append("Load average (1 min) before the renders: %.1f-%.1f (median %.1f)." % (
        min(s["load1Before"] for s in every), max(s["load1Before"] for s in every),
        med([s["load1Before"] for s in every])))
    if any("runQueueWait" in s for v in runs.values() for s in v):
        lines.append("")
        lines.append("| renderer | " + " | ".join(
            "%s: run-queue wait s, median" % l for l in loads) + " |")
        lines.append("|---" * (1 + len(loads)) + "|")
        for r in renderers:
            cells = []
            for l in loads:
                w = [s["runQueueWait"] for s in runs.get("%s/%s" % (l, r), [])
                     if "runQueueWait" in s]
                cells.append("%.2f" % med(w) if w else "-")
            lines.append("| %s | %s |" % (r, " | ".join(cells)))
    lines += decomposition(runs, loads, renderers)
    prof = data.get("profile")
    if prof:
        lines.append("")
        lines.append("| --threads | samples | runnable threads of texrender (share of samples) |")
        lines.append("|---|---|---|")
        for t, p in prof.items():
            n = sum(p["runnableSamples"].values())
            lines.append("| %s | %d | %s |" % (t, n, ", ".join(
                "%s: %.0f%%" % (k, 100.0 * c / n) for k, c in sorted(
                    p["runnableSamples"].items(), key=lambda kv: int(kv[0])))))
    return "\n".join(lines)


def main():
    if sys.argv[1:2] == ["--report"]:
        common.print_report("threads", sys.argv[2:3], report)
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(common.ROOT, "build"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", default="256x256")
    ap.add_argument("--spp", type=int, default=8)
    ap.add_argument("--threads", default="0,1,2,4",
                    help="texrender --threads values, 0: without the option")
    ap.add_argument("--stress", type=int, default=2, help="stress-ng --cpu workers")
    ap.add_argument("--loads", default="quiet,nice,nice-setsid")
    ap.add_argument("--cycles", action="store_true", help="Cycles (bpy) under the same loads")
    ap.add_argument("--blend", help="the rust-all .blend (default: made by make_scene.py)")
    ap.add_argument("--profile", action="store_true")
    ap.add_argument("--baseline-build",
                    help="another build folder (bin/texrender), rendered as texrender-baseline "
                         "(without --threads) in every round beside this build's")
    ap.add_argument("--waits", action="store_true",
                    help="record texrender's run-queue wait per render (schedstat)")
    ap.add_argument("--autogroup-check", action="store_true",
                    help="only: how much CPU a niced busy loop takes from one of this session, "
                         "in this session, under setsid, and with its autogroup niced "
                         "(bench/results/threads-autogroup.json)")
    ap.add_argument("--out", help="result file (default bench/results/threads.json)")
    args = ap.parse_args()
    if args.autogroup_check:
        data = {"autogroupCheck": autogroup_check(), "autogroupEnabled": open(
            "/proc/sys/kernel/sched_autogroup_enabled").read().strip(),
            "command": "python3 bench/threads.py " + " ".join(sys.argv[1:]),
            "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())}
        common.save("threads-autogroup", data, args.out)
        return
    if args.cycles:
        cycles.ensure_bpy()
    work = tempfile.mkdtemp(prefix="texcc-threads-")
    tools = texture_speed.bench_tools(args.build, work)
    t0 = time.perf_counter()
    run = {"command": "python3 bench/threads.py " + " ".join(sys.argv[1:]),
           "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "git": common.git_head(),
           "machine": common.machine()}

    def save(data, complete=False):
        data.update(run, complete=complete, seconds=time.perf_counter() - t0)
        common.save("threads", data, args.out)

    save(measure(args, tools, save), True)
