"""Counts the threads of a texrender process after its first frame (threads-pool.test).

    count_threads.py LABEL [ENV=VALUE ...] -- texrender ... --interactive ...
    count_threads.py --compare COUNTS


Starts the command with the environment changes given, sends one edit on standard input and
waits for texrender's "frame 1:" line (the frame after the edit: every pool has worked by then),
counts the entries of /proc/PID/task while texrender waits for its next edit, then sends 'quit'.
Prints "LABEL: N threads". Nothing is timed: it waits for texrender's own lines.

--compare reads those lines for the labels one (--threads 1), four (--threads 4) and pocl1
(no --threads, POCL_MAX_PTHREAD_COUNT=1 in the environment) and checks that the pools follow
--threads: four has at least 3 threads more than one (PoCL's pool: one worker per thread), and,
where this process may run on 2 cores or more, one has fewer threads than pocl1 (the same PoCL
pool; Embree's, sized to every core without --threads, starts a worker thread building the
scene's BVH that --threads 1 does not).
"""
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


def main():
    if sys.argv[1] == "--compare":
        compare(sys.argv[2])
        return
    label = sys.argv[1]
    sep = sys.argv.index("--")
    env = dict(os.environ)
    for item in sys.argv[2:sep]:
        key, _, value = item.partition("=")
        env[key] = value
    p = subprocess.Popen(sys.argv[sep + 1:], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         text=True, env=env)
    p.stdin.write("set out.gain=0.5\n")
    p.stdin.flush()
    line = p.stdout.readline()
    if not line.startswith("frame 1:"):
        p.kill()
        sys.exit("%s: expected texrender's 'frame 1:' line, got %r (exit %s)"
                 % (label, line, p.wait()))
    threads = len(os.listdir("/proc/%d/task" % p.pid))
    p.stdin.write("quit\n")
    p.stdin.close()
    rest = p.stdout.read()
    if p.wait() != 0:
        sys.exit("%s: texrender exited %d: %s" % (label, p.returncode, rest))
    print("%s: %d threads" % (label, threads))


if __name__ == "__main__":
    main()
