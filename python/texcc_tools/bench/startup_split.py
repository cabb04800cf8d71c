"""The split of texrender's fixed start-up cost (bench/startup.md): classifies the CPU samples
of `perf record -e cpu-clock --call-graph dwarf` of one texrender run by phase.

A sample belongs to the first phase (in PHASES' order) with a function on its call chain; a
sample without one goes, in a thread with classified samples, with that thread's next
classified sample (a chain perf could not unwind), and otherwise (Embree's TBB workers, PoCL's
device threads) with the last classified sample before it of any thread, so that the worker
threads' share of a BVH build counts for that build.

usage: perf record -e cpu-clock -F 2000 --call-graph dwarf,32768 -o P texrender ...
       perf script -i P -F pid,tid,time,ip,sym > P.txt
       python3 bench/startup_split.py P.txt"""
import collections
import sys

# (phase, substrings of a function name), tried in this order on each call chain (outermost
# frame first) so that e.g. a page fault inside the OBJ reader counts as OBJ loading.
PHASES = [
    ("OBJ loading (read, parse, checks, normals)", ("texrender::loadObj", "texrender::readObj")),
    ("wide BVH (Embree's builder, flattening)", ("texrender::buildBvh",)),
    ("Embree scene BVH (trace backend)", ("texrender::makeEmbreeTrace", "texrender::makeTrace")),
    ("scene data (transforms, BVH reorder, lights)", ("texrender::buildSceneData",)),
    ("OpenCL context (platform, PoCL device)", ("texrender::ClContext::ClContext",)),
    ("fixed kernels (program cache loads)", ("texrender::Renderer::buildFixedKernels",)),
    ("buffers upload", ("texrender::Renderer::uploadScene",)),
    ("texture tiers (texture program)", ("texrender::TierManager", "uploadLayoutData")),
    ("render", ("texrender::Renderer::render",)),
    ("scene.json, layout, options", ("texrender::loadScene", "texrender::loadLayout")),
    ("process start (exec, dynamic loading)", ("_dl_start", "_dl_init", "_dl_relocate",
                                               "dl_main", "load_elf_binary", "_dl_map_object")),
    ("exit (destructors, unmapping)", ("__run_exit_handlers", "~Renderer", "_dl_fini")),
]


def samples(path):
    """(pid, tid, time, [frames, innermost first]) of each sample."""
    head, frames = None, []
    with open(path, errors="replace") as f:
        for line in f:
            if not line.strip():
                if head:
                    yield head + (frames,)
                head, frames = None, []
                continue
            if not line.startswith("\t"):
                ids, t = line.split()[:2]
                pid, tid = ids.split("/")
                head = (int(pid), int(tid), float(t.rstrip(":")))
            else:
                parts = line.strip().split(None, 1)
                frames.append(parts[1] if len(parts) > 1 else "")
    if head:
        yield head + (frames,)


def classify(frames):
    outer = list(reversed(frames))
    for phase, keys in PHASES:
        for fr in outer:
            if any(k in fr for k in keys):
                return phase
    return None


def split(path):
    """(samples, Counter of phase -> samples)."""
    rows = [(tid, classify(frames)) for pid, tid, t, frames in samples(path)]
    # A thread with classified samples (the one that runs texrender's work): an unclassified
    # sample of it (a call chain perf could not unwind to texrender's frames, mostly in the
    # kernel) goes with that thread's next classified one.
    following, nxt = [None] * len(rows), {}
    for i in range(len(rows) - 1, -1, -1):
        tid, p = rows[i]
        following[i] = nxt.get(tid)
        if p:
            nxt[tid] = p
    current = "other"
    counts = collections.Counter()
    for i, (tid, p) in enumerate(rows):
        if p:
            current = p
        counts[p or following[i] or current] += 1
    return len(rows), counts


def main():
    for path in sys.argv[1:]:
        total, counts = split(path)
        print("%s: %d samples" % (path, total))
        for phase, n in counts.most_common():
            print("  %5.1f%%  %s" % (100.0 * n / total, phase))


if __name__ == "__main__":
    main()
