"""Shared helpers of the benchmarks: running texcc and texrender, reading stats.json, medians,
the machine description. Every helper raises BenchError on a failed measurement so that
bench/run exits non-zero."""
import argparse
import contextlib
import json
import os
import platform
import statistics
import subprocess
import sys

from texcc_tools import process
from texcc_tools.paths import BENCH, CHARTS, KERNELS, RESULTS, ROOT, default_build_dir, tool

# ROOT, BENCH, RESULTS, CHARTS: texcc_tools.paths's, kept here for the commands that use them.
__all__ = ["ROOT", "BENCH", "RESULTS", "CHARTS", "BUILD", "MODES", "FIXED_KERNELS", "BenchError",
           "run_main", "Tools", "run", "texcc", "texrender", "no_pocl_cache",
           "texture_kernel_seconds", "per_hit_samples", "with_one_pocl_thread", "ao_seconds",
           "median", "machine", "git_head", "save", "load", "log", "fmt", "pct", "kernel_variant",
           "add_build_argument"]
BUILD = default_build_dir()
MODES = ("interp", "inline", "wavefront", "shape")

# Kernels of texrender that are not the texture kernel (docs/runtime.md).
FIXED_KERNELS = {"raygen", "closest_hit_primary", "closest_hit_bounce", "hit_attributes",
                 "ao_trace", "ao_reduce", "shade", "shadow", "compact", "accumulate"}


class BenchError(Exception):
    pass


def add_build_argument(parser):
    """--build, default $TEXCC_BUILD_DIR else build/ (texcc_tools.paths)."""
    from texcc_tools.paths import add_build_argument as add
    add(parser)


def run_main(main, name):
    """A benchmark script's entry point: runs main(); a failed measurement (BenchError) ends the
    script with "NAME: error: WHY" on stderr and exit status 1."""
    try:
        main()
    except BenchError as e:
        print("%s: error: %s" % (name, e), file=sys.stderr)
        sys.exit(1)


class Tools:
    """The binaries of one build folder and the work folder of this run."""

    def __init__(self, build, work, device="0"):
        self.texcc = tool("texcc", build)
        self.texrender = tool("texrender", build)
        for binary in (self.texcc, self.texrender):
            if not os.access(binary, os.X_OK):
                raise BenchError("%s: not built (ninja -C %s texcc texrender)" % (binary, build))
        self.build = build
        self.work = work
        self.device = device
        self.cache = os.path.join(work, "cache")
        os.makedirs(self.cache, exist_ok=True)


def run(cmd, timeout=None, cwd=None):
    """Runs cmd; returns (wall seconds, stdout). Raises BenchError on failure or timeout."""
    try:
        wall, r = process.timed(cmd, timeout=timeout, cwd=cwd)
    except process.RunError as e:
        raise BenchError(str(e)) from None
    return wall, r.stdout


def texcc(tools, graph, out, mode, extra=(), timeout=None):
    """Compiles graph into out with the given mode; returns texcc's wall seconds."""
    cmd = [tools.texcc, "--mode=" + mode, "--graph", graph, "-o", out] + list(extra)
    wall, _ = run(cmd, timeout=timeout)
    return wall


def texrender(tools, scene, textures, name, opts=(), timeout=None, image="png", cache=None):
    """Renders scene; returns (stats dict, image path, wall seconds)."""
    out = os.path.join(tools.work, name)
    stats = out + ".stats.json"
    img = out + "." + image
    cmd = [tools.texrender, scene, "--textures", textures, "-o", img, "--stats", stats,
           "--quiet", "--device", tools.device, "--cache-dir", cache or tools.cache] + list(opts)
    wall, _ = run(cmd, timeout=timeout)
    with open(stats) as f:
        return json.load(f), img, wall


@contextlib.contextmanager
def no_pocl_cache():
    """PoCL keeps its own cache of compiled kernels (~/.cache/pocl), keyed by source: a
    kernel built by an earlier run would cost nothing. Build-time measurements turn it off."""
    old = os.environ.get("POCL_KERNEL_CACHE")
    os.environ["POCL_KERNEL_CACHE"] = "0"
    try:
        yield
    finally:
        if old is None:
            del os.environ["POCL_KERNEL_CACHE"]
        else:
            os.environ["POCL_KERNEL_CACHE"] = old


def texture_kernel_seconds(stats):
    """Device seconds of the texture kernel(s): every kernel that is not a fixed one."""
    return sum(k["seconds"] for name, k in stats["kernels"].items()
               if name not in FIXED_KERNELS)


def per_hit_samples(tools, label, graph, scene, configs, reps, opts):
    """Per-hit texture cost of each configuration (name, mode, texcc options) of one graph on
    one scene: texcc once per configuration, a first unmeasured render (it builds every
    kernel), then reps repetitions that render every configuration back to back, in an order
    that rotates with the repetition (the shared machine's load drifts), each in its own
    texrender process. The cost is the texture kernels' device time (OpenCL profiling,
    stats.json: every kernel that is not a fixed one) in ns over the texture stage's
    work-items (hit_attributes' workItems: every active path of every bounce), i.e. ms per
    million hits. Returns ({name: [samples]}, hits, {name: texcc output folder})."""
    folders = {}
    for cfg, mode, extra in configs:
        folder = os.path.join(tools.work, "%s-%s" % (label, cfg))
        texcc(tools, graph, folder, mode, extra)
        folders[cfg] = folder
        texrender(tools, scene, folder, "%s-%s-warm" % (label, cfg), opts)
    samples = {cfg: [] for cfg, _, _ in configs}
    hits = 0
    for rep in range(reps):
        k = rep % len(configs)
        for cfg, _, _ in configs[k:] + configs[:k]:
            log("%s rep %d: %s" % (label, rep + 1, cfg))
            stats, _, _ = texrender(tools, scene, folders[cfg], "%s-%s-%d" % (label, cfg, rep), opts)
            hits = stats["kernels"]["hit_attributes"]["workItems"]
            samples[cfg].append(1e9 * texture_kernel_seconds(stats) / hits)
    return samples, hits, folders


def with_one_pocl_thread(fn):
    """fn() with POCL_MAX_PTHREAD_COUNT=1 (per-hit timings: on the shared 2-core machine a
    kernel spread over both cores varies threefold between runs), the variable restored after."""
    saved = os.environ.get("POCL_MAX_PTHREAD_COUNT")
    os.environ["POCL_MAX_PTHREAD_COUNT"] = "1"
    try:
        return fn()
    finally:
        if saved is None:
            del os.environ["POCL_MAX_PTHREAD_COUNT"]
        else:
            os.environ["POCL_MAX_PTHREAD_COUNT"] = saved


def ao_seconds(stats):
    k = stats["kernels"]
    return sum(k[name]["seconds"] for name in ("ao_trace", "ao_reduce") if name in k)


def median(values):
    return statistics.median(values)


def machine():
    """The CPU model and core count (lscpu), the OpenCL device is recorded per result."""
    info = {"platform": platform.platform(), "python": platform.python_version()}
    try:
        out = subprocess.run(["lscpu"], stdout=subprocess.PIPE, text=True).stdout
        for line in out.splitlines():
            key, _, value = line.partition(":")
            if key.strip() in ("Model name", "CPU(s)", "Thread(s) per core", "Architecture"):
                info[key.strip()] = value.strip()
    except OSError:
        info["Model name"] = "unknown (lscpu missing)"
    return info


def git_head():
    """HEAD's short hash, with "+dirty" when the working tree differs from it."""
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                          stdout=subprocess.PIPE, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                           stdout=subprocess.PIPE, text=True).stdout.strip()
    return head + ("+dirty" if dirty else "")


def save(name, data, path=None):
    """Writes data to path, by default bench/results/<name>.json; returns the path."""
    path = path or os.path.join(RESULTS, name + ".json")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(data, f, indent=1, sort_keys=True)
        f.write("\n")
    log("wrote " + path)
    return path


# argparse types of the figure scripts' options: a bad value ends the script with argparse's
# "NAME: error: argument --OPT: ..." before anything runs.
def positive_int(text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError("expected a positive integer, got %r" % text)
    return value


def positive_numbers(text):
    """A comma list of positive numbers."""
    try:
        values = [float(x) for x in text.split(",") if x]
    except ValueError:
        values = []
    if not values or min(values) <= 0:
        raise argparse.ArgumentTypeError("expected positive numbers separated by commas, got %r"
                                         % text)
    return values


def positive_number(text):
    try:
        value = float(text)
    except ValueError:
        value = 0.0
    if not value > 0:
        raise argparse.ArgumentTypeError("expected a positive number, got %r" % text)
    return value


def film_size(text):
    """WxH with positive integers, kept as the text texrender's --size takes."""
    parts = text.split("x")
    if len(parts) != 2 or not all(x.isdigit() and int(x) > 0 for x in parts):
        raise argparse.ArgumentTypeError("expected WxH (positive integers), got %r" % text)
    return text


def print_report(name, argv, report):
    """`bench/NAME.py --report [FILE]`: prints report(the result) of FILE, by default
    bench/results/NAME.json; BenchError naming the file if it cannot be read or is not one."""
    path = argv[0] if argv else os.path.join(RESULTS, name + ".json")
    try:
        with open(path) as f:
            text = report(json.load(f))
    except (OSError, ValueError, KeyError) as e:
        raise BenchError("%s: not a bench/%s.py result (%s)" % (path, name, e))
    print(text)


def load(name):
    path = os.path.join(RESULTS, name + ".json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def log(msg):
    print("bench: " + msg, flush=True)


# Number formats of the report (texcc_tools.bench.report, report_peers).
def fmt(x, digits=3):
    if x is None:
        return "n/a"
    return ("%%.%dg" % digits) % x


def pct(x):
    return ("%+.1f%%" if abs(x) < 10 else "%+.0f%%") % x


def kernel_variant(work, name, prepend):
    """A copy of kernels/ in work/kernels-NAME with text put in front of some of its files:
    prepend maps a path inside kernels/ to the lines (bench-only defines) to insert."""
    import shutil
    out = os.path.join(work, "kernels-" + name)
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(KERNELS, out)
    for rel, text in prepend.items():
        path = os.path.join(out, rel)
        with open(path) as f:
            src = f.read()
        with open(path, "w") as f:
            f.write(text + src)
    return out
