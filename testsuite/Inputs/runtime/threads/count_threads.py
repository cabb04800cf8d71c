"""Counts the threads of a texrender process after its first frame (threads-pool.test).

    count_threads.py LABEL [ENV=VALUE ...] -- texrender ... --interactive ...
    count_threads.py --compare COUNTS


Starts the command with the environment changes given, sends one edit on standard input and
waits for texrender's "frame 1:" line (the frame after the edit: every pool has worked by then),
counts the entries of /proc/PID/task while texrender waits for its next edit, then sends 'quit'.
ENV=VALUE CPU=first runs texrender on the first CPU this process may run on, alone. Prints
"LABEL: N threads, mask MASK, pinned CPUS": MASK, the CPUs texrender was allowed, CPUS, sorted,
the CPU of each thread whose affinity is that one CPU alone, narrower than MASK ("-" for none). Nothing is timed: it waits for texrender's own
lines.

--pinned LABEL COUNTS STATS: checks the pinning of LABEL's run against the rule (docs/cli.md,
texrender --threads): the pools are pinned, PoCL's worker I on CPU I, exactly when the pool
has N >= 2 threads and this process may run on CPUs 0..N-1 and no other; stats.json's
threads.pinned says whether they were.

--compare reads those lines for the labels one (--threads 1), four (--threads 4) and pocl1
(no --threads, POCL_MAX_PTHREAD_COUNT=1 in the environment) and checks that the pools follow
--threads: four has at least 3 threads more than one (PoCL's pool: one worker per thread), and,
where this process may run on 2 cores or more, one has fewer threads than pocl1 (the same PoCL
pool; Embree's, sized to every core without --threads, starts a worker thread building the
scene's BVH that --threads 1 does not).
"""
import json
import os
import subprocess
import sys


def compare(path):
    counts = {}
    with open(path) as f:
        for line in f:
            label, _, rest = line.partition(": ")
            counts[label] = int(rest.split()[0])
    ok = True
    grow = counts["four"] - counts["one"]
    print("--threads 4 over --threads 1: %+d threads (at least +3: %s)"
          % (grow, "ok" if grow >= 3 else "FAILED"))
    ok &= grow >= 3
    if len(os.sched_getaffinity(0)) >= 2:
        fewer = counts["one"] < counts["pocl1"]
        print("--threads 1 under POCL_MAX_PTHREAD_COUNT=1 alone: %d < %d threads (Embree's "
              "pool): %s" % (counts["one"], counts["pocl1"], "ok" if fewer else "FAILED"))
        ok &= fewer
    else:
        print("--threads 1 under POCL_MAX_PTHREAD_COUNT=1 alone: not checked on one core")
    sys.exit(0 if ok else 1)


def pinned_cpus(pid, mask):
    """The CPU of each thread of pid whose affinity is one CPU alone, narrower than the mask
    the process was started with, sorted."""
    cpus = []
    for tid in os.listdir("/proc/%d/task" % pid):
        try:
            own = os.sched_getaffinity(int(tid))
        except OSError:
            continue
        if len(own) == 1 and own != mask:
            cpus.append(next(iter(own)))
    return sorted(cpus)


def check_pinned(label, counts_path, stats_path):
    with open(counts_path) as f:
        lines = dict(l.rstrip("\n").split(": ", 1) for l in f if l.strip())
    seen = lines[label].split("pinned ")[1]
    mask = set(int(c) for c in lines[label].split("mask ")[1].split(",")[0].split())
    with open(stats_path) as f:
        threads = json.load(f)["threads"]
    n = threads["pool"]
    expect = n >= 2 and mask == set(range(n))
    want = " ".join(str(c) for c in range(n)) if expect else "-"
    ok = seen == want and threads["pinned"] == expect
    print("%s: pool %d, this process on CPUs %s: pinned %s (expected %s), stats.json pinned "
          "%s: %s" % (label, n, sorted(mask), seen, want, threads["pinned"],
                      "ok" if ok else "FAILED"))
    sys.exit(0 if ok else 1)


def main():
    if sys.argv[1] == "--compare":
        compare(sys.argv[2])
        return
    if sys.argv[1] == "--pinned":
        check_pinned(*sys.argv[2:5])
        return
    label = sys.argv[1]
    sep = sys.argv.index("--")
    env = dict(os.environ)
    mask = os.sched_getaffinity(0)
    for item in sys.argv[2:sep]:
        key, _, value = item.partition("=")
        if key == "CPU" and value == "first":  # the first CPU this process may run on, alone
            mask = {min(mask)}
        else:
            env[key] = value
    p = subprocess.Popen(sys.argv[sep + 1:], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         text=True, env=env, preexec_fn=lambda: os.sched_setaffinity(0, mask))
    p.stdin.write("set out.gain=0.5\n")
    p.stdin.flush()
    line = p.stdout.readline()
    if not line.startswith("frame 1:"):
        p.kill()
        sys.exit("%s: expected texrender's 'frame 1:' line, got %r (exit %s)"
                 % (label, line, p.wait()))
    threads = len(os.listdir("/proc/%d/task" % p.pid))
    pinned = " ".join(str(c) for c in pinned_cpus(p.pid, mask)) or "-"
    p.stdin.write("quit\n")
    p.stdin.close()
    rest = p.stdout.read()
    if p.wait() != 0:
        sys.exit("%s: texrender exited %d: %s" % (label, p.returncode, rest))
    print("%s: %d threads, mask %s, pinned %s"
          % (label, threads, " ".join(str(c) for c in sorted(mask)), pinned))


if __name__ == "__main__":
    main()
